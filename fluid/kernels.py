"""SPH smoothing kernels with support radius 2h, normalised in 2-D and 3-D.

Every kernel is written as ``W(r) = alpha_d * w(q)``, ``q = r / h``, and its gradient as
``grad_a W_ab = F(r) * r_ab`` with ``r_ab = r_a - r_b``, so that the pair loops never divide
by ``r`` and the self pair contributes exactly zero. Factors are clamped at the edge of the
support (no branch), which is what lets the pair loop vectorise.

* Wendland C2 (Wendland 1995; the DualSPHysics default, Barreiro et al. 2016, §2.2,
  and the cable kernel of Dinçer & Demir 2020):
  ``w = (1 - q/2)^4 (2q + 1)``, ``alpha_2 = 7 / (4 pi h^2)``, ``alpha_3 = 21 / (16 pi h^3)``;
  ``F = -5 alpha_d / h^2 (1 - q/2)^3``.
* Cubic spline (Monaghan & Lattanzio 1985; Sunara et al. 2021, Eq. 4, whose 3-D
  factor 1/(pi h^3) is used; the 2-D factor is 10 / (7 pi h^2)):
  ``w = 1 - 3/2 q^2 + 3/4 q^3`` (q < 1), ``(2 - q)^3 / 4`` (1 <= q < 2).

The smoothing length is ``h = h_coef * dx`` (``dx`` the particle spacing [m]).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from errors import InputError
from fluid import terms

#: kernel ids used inside the numba loops
WENDLAND = terms.WENDLAND
CUBIC = terms.CUBIC
KERNELS = {"wendland": WENDLAND, "cubic": CUBIC}

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")


def kernel_id(name: str) -> int:
    try:
        return KERNELS[name]
    except KeyError:
        raise InputError(f"unknown kernel {name!r}; choose one of {sorted(KERNELS)}") from None


@njit(**_OPTS)
def alpha_d(kernel: int, dim: int, h: float) -> float:
    """Normalisation factor alpha_d [1/m^dim] of ``kernel`` in ``dim`` dimensions."""
    if kernel == WENDLAND:
        if dim == 2:
            return 7.0 / (4.0 * math.pi * h * h)
        return 21.0 / (16.0 * math.pi * h * h * h)
    if dim == 2:
        return 10.0 / (7.0 * math.pi * h * h)
    return 1.0 / (math.pi * h * h * h)


#: the kernel of :mod:`fluid.terms` as the CPU loops call it: ``w_value(kernel, q, ad)``
#: [1/m^dim], ``grad_shape(kernel, q)`` [-] (the part of ``F`` that varies from pair to
#: pair) and ``grad_scale(kernel, ad, h)`` [1/m^(dim+2)], ``F = grad_scale * grad_shape``
w_value = terms.cpu.kernel_w
grad_shape = terms.cpu.kernel_grad_shape
grad_scale = terms.cpu.kernel_grad_scale


@njit(**_OPTS)
def grad_factor(kernel: int, q: float, ad: float, h: float) -> float:
    """``F`` [1/m^(dim+2)] with ``grad_a W_ab = F * (r_a - r_b)``; zero outside the support."""
    return grad_scale(kernel, ad, h) * grad_shape(kernel, q)


@njit(**_OPTS)
def _w_array(kernel, q, ad):
    out = np.empty_like(q)
    for i in range(q.size):
        out.flat[i] = w_value(kernel, q.flat[i], ad)
    return out


@njit(**_OPTS)
def _f_array(kernel, q, ad, h):
    out = np.empty_like(q)
    for i in range(q.size):
        out[i] = grad_factor(kernel, q[i], ad, h)
    return out


def W(r, h: float, dim: int, kernel: str = "wendland") -> np.ndarray:
    """Kernel value [1/m^dim] at distances ``r`` [m], smoothing length ``h`` [m]."""
    k = kernel_id(kernel)
    q = np.ascontiguousarray(np.asarray(r, np.float64) / h)
    return _w_array(k, q, alpha_d(k, dim, h))


def grad_W(rab, h: float, kernel: str = "wendland") -> np.ndarray:
    """``grad_a W_ab`` [1/m^(dim+1)] for separations ``rab = r_a - r_b`` [m] of shape (M, dim)."""
    k = kernel_id(kernel)
    rab = np.atleast_2d(np.asarray(rab, np.float64))
    q = np.ascontiguousarray(np.linalg.norm(rab, axis=1) / h)
    return _f_array(k, q, alpha_d(k, rab.shape[1], h), h)[:, None] * rab
