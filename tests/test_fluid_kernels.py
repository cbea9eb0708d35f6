"""Kernels: normalisation, gradient, compact support (DESIGN.md, validation tier 1)."""

import numpy as np
import pytest

from fluid.kernels import W, grad_W


def lattice(dim, h, dx):
    n = int(np.ceil(2.2 * h / dx))
    ax = np.arange(-n, n + 1) * dx
    g = np.meshgrid(*([ax] * dim), indexing="ij")
    return np.stack([a.ravel() for a in g], axis=1)


@pytest.mark.parametrize("kernel", ["wendland", "cubic"])
@pytest.mark.parametrize("dim", [2, 3])
def test_integral_is_one(kernel, dim):
    h = 1.0
    dx = 0.04 if dim == 2 else 0.08
    r = lattice(dim, h, dx)
    # a lattice offset by an irrational fraction avoids a special alignment with the kernel
    r = r + 0.3183 * dx
    total = W(np.linalg.norm(r, axis=1), h, dim, kernel).sum() * dx**dim
    assert abs(total - 1.0) < 1e-3


@pytest.mark.parametrize("kernel", ["wendland", "cubic"])
@pytest.mark.parametrize("dim", [2, 3])
def test_gradient_matches_finite_difference_and_is_antisymmetric(kernel, dim):
    rng = np.random.default_rng(1)
    h = 0.7
    rab = rng.uniform(-1.5 * h, 1.5 * h, (200, dim))
    g = grad_W(rab, h, kernel)
    assert np.array_equal(g, -grad_W(-rab, h, kernel))
    eps = 1e-6
    for k in range(dim):
        e = np.zeros(dim)
        e[k] = eps
        fd = (W(np.linalg.norm(rab + e, axis=1), h, dim, kernel)
              - W(np.linalg.norm(rab - e, axis=1), h, dim, kernel)) / (2 * eps)
        np.testing.assert_allclose(g[:, k], fd, rtol=1e-5, atol=1e-6 / h ** (dim + 1))
    # the gradient points towards the neighbour: W decreases with distance
    assert (np.einsum("ij,ij->i", g, rab) <= 0).all()


@pytest.mark.parametrize("kernel", ["wendland", "cubic"])
@pytest.mark.parametrize("dim", [2, 3])
def test_compact_support(kernel, dim):
    h = 0.5
    r = np.array([2 * h, 2 * h + 1e-9, 3 * h, 10 * h])
    assert (W(r, h, dim, kernel) == 0).all()
    rab = np.zeros((4, dim))
    rab[:, 0] = r
    assert (grad_W(rab, h, kernel) == 0).all()
    assert W(np.array([2 * h - 1e-3 * h]), h, dim, kernel)[0] > 0
    # the self pair contributes nothing to a gradient
    assert (grad_W(np.zeros((1, dim)), h, kernel) == 0).all()
