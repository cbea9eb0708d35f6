"""The SPH terms, each written once: the kernel, the equation of state and the pair and
particle terms of the rates, as plain functions of scalars.

Each is compiled where it is used: ``numba.njit`` for the CPU loops (:mod:`fluid.kernels`,
:mod:`fluid.equations`, :mod:`fluid.mls`, :mod:`fluid.boundary_correction`) and
``numba.cuda.jit(device=True)`` for the GPU kernels (:mod:`fluid.cuda.kernels`), so that
the two paths evaluate the same expressions; :func:`float32_variant` gives the CPU's
float32 pair loop the same code with float32 literals. A term takes what the loops share
between terms (the kernel factor ``F_ab``, one division ``d = 1 / ((r^2 + eta^2)(rho_a +
rho_b))``) as arguments, so that a pair costs what it did when the terms were written out
in the loops; the pair loops and their notation: :mod:`fluid.equations`. Adding a term:
docs/fluid_equations.md, "The terms, written once". After editing a term, delete the numba
caches (``fluid/**/*.nbi``): a loop's cache is keyed on its own file, not on the terms it inlines.

* Kernels: Wendland C2 (Wendland 1995) and the cubic spline (Monaghan & Lattanzio 1985),
  ``W = alpha_d w(q)``, ``grad_a W_ab = F r_ab``: :mod:`fluid.kernels`.
* Tait equation of state, Barreiro et al. 2016, Eq. 8.
* Continuity, Barreiro et al. 2016, Eq. 7; density diffusion, Molteni & Colagrossi 2009,
  Fourtakas et al. 2019, Antuono et al. 2010 (Dinçer & Demir 2020, Eq. 1-4).
* Momentum, Barreiro et al. 2016, Eq. 6; artificial viscosity, Monaghan 1992 (Sunara
  et al. 2021, Eq. 6); laminar viscosity, Lo & Shao 2002; XSPH, Monaghan 1989.
* The viscous term of the time step, Sunara et al. 2021, Eq. 14.
* A boundary particle's force and moment on its body.
* The integrator's update of one particle: the symplectic predictor-corrector (Monaghan
  2005) and Verlet (Monaghan 1989), :mod:`fluid.integrator`.
* The wall pressure extrapolated from the fluid, Adami, Hu & Adams 2012, Eq. 27.
* Fickian particle shifting, Lind et al. 2012 (Skillen et al. 2013's coefficient), its
  free-surface region and normal from the renormalisation matrix (Marrone et al. 2010).
* Linear solves: the renormalised density gradient (Dinçer & Demir 2020, Eq. 3-4), the
  MLS density (Sunara et al. 2021, Eq. 9-12), the mDBC ghost-node system (English et
  al. 2022, Eq. 12-13).
"""

from __future__ import annotations

import math
import types

import numpy as np
from numba import njit

#: kernel ids (fluid.kernels.KERNELS)
WENDLAND = 0
CUBIC = 1
#: |det| of the renormalisation matrix of :func:`renormalised_gradient`, relative to the
#: cube (square in 2-D) of its mean diagonal, below which the hydrostatic gradient is
#: used instead (a particle at the free surface or with few fluid neighbours)
DET_MIN = 1e-3


def float32_variant(f):
    """``f`` with every float literal of its code a float32, so that numba types its
    arithmetic on float32 arguments as float32 (a float64 literal would promote it)."""
    code = f.__code__
    consts = tuple(np.float32(c) if type(c) is float else c for c in code.co_consts)
    g = types.FunctionType(code.replace(co_consts=consts, co_name=code.co_name + "_f32"), f.__globals__,
                           code.co_name + "_f32", f.__defaults__, f.__closure__)
    g.__qualname__ = f.__qualname__ + "_f32"
    g.__doc__ = f.__doc__
    return g


def rebind(f, **names):
    """``f`` with the global names given bound to other objects (a loop whose terms
    module, :func:`compiled`, is that of another precision)."""
    return types.FunctionType(f.__code__, {**f.__globals__, **names}, f.__name__, f.__defaults__, f.__closure__)


def compiled(jit, float32: bool = False, name: str = "cpu") -> types.ModuleType:
    """A module holding every term of :data:`TERMS` compiled by ``jit`` (``njit(...)``,
    ``cuda.jit(device=True)``), as :func:`float32_variant` if ``float32``: a loop calls
    ``module.term(...)`` and is built for a target or precision by the module it names; a
    term calling another calls the other's compiled form."""
    mod = types.ModuleType(f"{__name__}.{name}")
    for term in TERMS:
        f = globals()[term]
        f = float32_variant(f) if float32 else f
        setattr(mod, term, jit(rebind(f, **{t: getattr(mod, t) for t in TERMS if hasattr(mod, t)})))
    return mod


# ------------------------------------------------------------------ kernel
def kernel_w(kernel, q, ad):
    """Kernel value W [1/m^dim] at ``q = r/h`` with normalisation ``ad = alpha_d``: Wendland
    C2 ``(1 - q/2)^4 (2q + 1)`` (Wendland 1995), cubic spline ``((2-q)^3 - 4 (1-q)^3) / 4``
    (Monaghan & Lattanzio 1985); zero beyond q = 2 (clamped, no branch)."""
    if kernel == WENDLAND:
        t = max(1.0 - 0.5 * q, 0.0)
        return ad * t * t * t * t * (2.0 * q + 1.0)
    t2 = max(2.0 - q, 0.0)
    t1 = max(1.0 - q, 0.0)
    return ad * 0.25 * (t2 * t2 * t2 - 4.0 * t1 * t1 * t1)


def kernel_grad_shape(kernel, q):
    """``F / kernel_grad_scale`` [-] at ``q = r/h``, where ``grad_a W_ab = F r_ab``: the
    part of the kernel gradient that varies from pair to pair. Wendland C2: ``(1 -
    q/2)^3``; cubic spline: ``(-3/4 (2-q)^2 + 3 (1-q)^2) / q`` (``dW/dq / (q h^2)``)."""
    if kernel == WENDLAND:
        t = max(1.0 - 0.5 * q, 0.0)
        return t * t * t
    t2 = max(2.0 - q, 0.0)
    t1 = max(1.0 - q, 0.0)
    qs = max(q, 1e-12)
    return (-0.75 * t2 * t2 + 3.0 * t1 * t1) / qs


def kernel_grad_scale(kernel, ad, h):
    """``F / kernel_grad_shape`` [1/m^(dim+2)]: ``-5 alpha_d / h^2`` (Wendland), ``alpha_d /
    h^2`` (cubic spline); ``ad`` [1/m^dim], ``h`` [m]."""
    if kernel == WENDLAND:
        return -5.0 * ad / (h * h)
    return ad / (h * h)


# ------------------------------------------------------------------ equation of state
def tait(rho, rho0, c0, gamma, B, e):
    """Pressure [Pa] and sound speed [m/s] at density ``rho`` [kg/m^3]: ``P = B ((rho /
    rho0)^gamma - 1)``, ``c = c0 (rho/rho0)^e``, ``e = (gamma - 1)/2`` (Barreiro et al.
    2016, Eq. 8); for water (gamma = 7) the powers by multiplication (pow costs more than
    the rest of a particle's packing)."""
    x = rho / rho0
    if gamma == 7.0:
        x2 = x * x
        x3 = x2 * x
        return B * (x3 * x3 * x - 1.0), c0 * x3
    return B * (x ** gamma - 1.0), c0 * x ** e


def tait_pressure(rho, rho0, B, gamma):
    """The pressure [Pa] of :func:`tait` alone (Barreiro et al. 2016, Eq. 8)."""
    x = rho / rho0
    if gamma == 7.0:
        x2 = x * x
        x3 = x2 * x
        return B * (x3 * x3 * x - 1.0)
    return B * (x ** gamma - 1.0)


def tait_density(p, rho0, B, inv_gamma):
    """The density [kg/m^3] whose Tait pressure is ``p`` [Pa]: Barreiro et al. 2016, Eq. 8
    inverted, ``rho0 (1 + p / B)^(1/gamma)``."""
    return rho0 * (1.0 + p / B) ** inv_gamma


# ------------------------------------------------------------------ pair terms
# Notation (fluid.equations): ``r_ab = r_a - r_b``, ``v_ab = v_a - v_b``, ``vr = v_ab .
# r_ab``, ``grad_a W_ab = Fc Fs r_ab`` with ``Fc`` the kernel's constant and ``Fs`` its
# shape (the loops apply ``Fc`` once per particle), ``mbF = m_b Fs`` (0 for a pair of
# boundary particles, which do not interact).
def pair_division(r2, eta2, rs):
    """``(r^2 + eta^2, d, inv)`` with ``d = 1 / ((r^2 + eta^2) rs)``, ``inv = 1 / (r^2 +
    eta^2)``: one division for both denominators of a pair (``r2`` [m^2], ``eta2`` [m^2],
    ``rs = rho_a + rho_b`` [kg/m^3])."""
    e2 = r2 + eta2
    d = 1.0 / (e2 * rs)
    return e2, d, d * rs


def continuity(mbF, vr):
    """Continuity, one pair (Barreiro et al. 2016, Eq. 7): ``m_b v_ab . grad_a W_ab / Fc``
    [kg/(m^3 s)] over ``Fc``."""
    return mbF * vr


def fourtakas_hydrostatic(hgx, hgy, hgz, rx, ry, rz, ka, kb, tilted):
    """``rho^H_ba`` [kg/m^3] of the Fourtakas et al. 2019 diffusion, linearised with the
    local density and sound speed: ``-(kappa_a + kappa_b) (g . r_ab) / 2``, ``kappa =
    rho / c^2``; ``hg = -g / 2`` [m/s^2] (times 0 or 1: the term on or off); ``tilted``
    False: gravity along -z, only ``hgz`` taken."""
    if tilted:
        return (hgx * rx + hgy * ry + hgz * rz) * (ka + kb)
    return hgz * (ka + kb) * rz


def renormalised_hydrostatic(gxa, gya, gza, gxb, gyb, gzb, rx, ry, rz, three):
    """``rho^H_ba`` [kg/m^3] of the renormalised diffusion (Antuono et al. 2010; Dinçer &
    Demir 2020, Eq. 2): ``-(<grad rho>_a + <grad rho>_b) . r_ab / 2`` from the gradients
    [kg/m^4] of :func:`renormalised_gradient`."""
    rhoH = -0.5 * ((gxa + gxb) * rx + (gza + gzb) * rz)
    if three:
        rhoH -= 0.5 * (gya + gyb) * ry
    return rhoH


def density_diffusion(volb, rhoa, rhob, rhoH, Fs, r2, inv):
    """Density diffusion, one pair, without its factor ``-delta h c0 Fc`` (Molteni &
    Colagrossi 2009; Dinçer & Demir 2020, Eq. 1): ``V_b (rho_b - rho_a - rho^H_ba) Fs
    r^2 / (r^2 + eta^2)``, ``V_b = m_b / rho_b`` [m^3] (0 for a boundary particle b)."""
    return volb * (rhob - rhoa - rhoH) * Fs * r2 * inv


def support_volume(volb, fb, mb, irho0):
    """The volume [m^3] particle b adds to ``sum_b V_b grad_a W_ab``, the free surface's
    cut of the support (the diffusion's fade): ``m_b / rho_b`` for fluid (``volb``,
    ``fb = 1``), ``m_b / rho0`` for boundary particles (``fb = 0``)."""
    return volb + (1.0 - fb) * mb * irho0


def artificial_viscosity(avh, ca, cb, vr, d):
    """Monaghan's artificial viscosity ``Pi_ab`` [m^2/s^2] (Monaghan 1992; Sunara et al.
    2021, Eq. 6): ``-alpha cbar_ab mu_ab / rhobar_ab`` for approaching pairs, ``mu_ab = h
    vr / (r^2 + eta^2)``; ``avh = -alpha h``, ``d`` from :func:`pair_division`."""
    return avh * (ca + cb) * min(vr, 0.0) * d


def wall_viscosity(awall, fa, fb):
    """The factor on ``Pi_ab``: 1 between fluid particles, ``alpha_wall`` between fluid and
    boundary (0: a free-slip wall)."""
    return awall + (1.0 - awall) * fa * fb


def momentum(mbF, pa, pb, Pi):
    """Momentum, one pair, over ``-Fc r_ab`` (Barreiro et al. 2016, Eq. 6): ``m_b (P_a /
    rho_a^2 + P_b / rho_b^2 + Pi_ab) Fs`` [m^2/s^2 per unit Fc]."""
    return mbF * (pa + pb + Pi)


def laminar_viscosity(mbF, r2, d):
    """Laminar viscosity, one pair, over ``4 nu Fc v_ab`` (Lo & Shao 2002; Barreiro et al.
    2016, §2.3): ``m_b Fs r^2 / ((rho_a + rho_b)(r^2 + eta^2))``."""
    return mbF * r2 * d


def viscous_bound(mask, r2, R2, vr, inv, scale):
    """``(scale mu_ab / h)^8`` for a pair within the support ``R2 = 4 h^2`` (``mask`` 0 for
    a pair of boundary particles): a term of the 8-norm that bounds ``max_b |mu_ab|`` of the
    time step (Sunara et al. 2021, Eq. 14; :func:`fluid.equations.interact`)."""
    m = (mask if r2 < R2 else 0.0) * vr * inv * scale
    m2 = m * m
    m4 = m2 * m2
    return m4 * m4


def xsph_weight(mbm, d, e2, w):
    """XSPH weight of a pair over ``2 eps alpha_d`` (Monaghan 1989): ``m_b w(q) /
    (rho_a + rho_b)`` (``w`` the kernel's shape; ``d e2 = 1 / (rho_a + rho_b)``)."""
    return mbm * (d * e2) * w


def adami_pressure(pf, bx, by, bz, rx, ry, rz):
    """The pressure [Pa] fluid particle f carries to wall particle w in the wall-pressure
    extrapolation of Adami, Hu & Adams 2012, Eq. 27: ``p_f + rho0 (g - a_w) . r_wf``
    (``b = rho0 (g - a_w)`` [Pa/m], ``r_wf = r_w - r_f`` [m]; rho_f taken as rho0:
    :mod:`fluid.wall_density`), to be weighted by ``W_wf``."""
    return pf + bx * rx + by * ry + bz * rz


def fickian_weight(volb, w, iw_dx):
    """The volume [m^3] particle b adds to the concentration gradient of Fickian shifting,
    ``grad C_a = sum_b V_b (1 + R (W_ab / W(dx))^n) grad_a W_ab`` (Lind et al. 2012, with
    the tensile term of Monaghan 2000, R = 0.2, n = 4): ``V_b (1 + R (w_ab iw_dx)^4)``,
    ``w_ab`` the kernel's shape at the pair, ``iw_dx`` the inverse of its value at the
    spacing dx, ``V_b`` [m^3] the neighbour's volume (:mod:`fluid.shifting`: ``m_b / rho0``)."""
    x = w * iw_dx
    x2 = x * x
    return volb * (1.0 + 0.2 * x2 * x2)


# ------------------------------------------------------------------ particle terms
def symmetric_min_eigenvalue(bxx, bxy, bxz, byy, byz, bzz, three):
    """The smallest eigenvalue of the symmetric matrix ``B`` (``bxx ... bzz``; ``three``
    False: the x-z block only), in closed form: 2 x 2, ``(bxx + bzz)/2 - sqrt(((bxx -
    bzz)/2)^2 + bxz^2)``; 3 x 3, the trigonometric solution of its characteristic cubic
    (Smith 1961, Commun. ACM 4: 168)."""
    if not three:
        return 0.5 * (bxx + bzz) - math.sqrt(0.25 * (bxx - bzz) * (bxx - bzz) + bxz * bxz)
    q = (bxx + byy + bzz) / 3.0
    p1 = bxy * bxy + bxz * bxz + byz * byz
    p2 = (bxx - q) * (bxx - q) + (byy - q) * (byy - q) + (bzz - q) * (bzz - q) + 2.0 * p1
    p = math.sqrt(p2 / 6.0)
    if not p > 0.0:
        return q
    ip = 1.0 / p
    axx, ayy, azz = (bxx - q) * ip, (byy - q) * ip, (bzz - q) * ip
    axy, axz, ayz = bxy * ip, bxz * ip, byz * ip
    r = 0.5 * (axx * (ayy * azz - ayz * ayz) - axy * (axy * azz - ayz * axz) + axz * (axy * ayz - ayy * axz))
    phi = math.acos(min(max(r, -1.0), 1.0)) / 3.0
    return q + 2.0 * p * math.cos(phi + 2.0943951023931957)  # + 2 pi / 3


def fickian_shift(gx, gy, gz, bxx, bxy, bxz, byy, byz, bzz, D, lam_full, three):
    """Particle a's shift [m] of Fickian shifting, ``delta r_a = -D grad C_a`` (Lind et al.
    2012, Eq. 21-24; ``D = A h |v_a| dt`` [m^2], Skillen et al. 2013, Eq. 13), with the
    free-surface treatment of Lind et al. 2012 (no shift along the surface's normal near
    it: ``delta r_a = -D (I - n n) grad C_a``), the region and its normal found from the
    renormalisation matrix ``B_a = sum_b V_b r_ba (x) grad_a W_ab`` (the identity where the
    support is full; Marrone et al. 2010, as Sun et al. 2017 use it): a support cut by the
    free surface where ``B_a``'s smallest eigenvalue is below ``lam_full``, the normal along
    ``B_a^-1 grad C_a``. ``g`` = grad C_a [1/m], ``b`` = B_a (symmetric, [-]); no shift
    where ``B_a`` is singular (a particle with too few neighbours to say where the surface
    lies). Returns (x, y, z); y = 0 in 2-D (``three`` False)."""
    sx = -D * gx
    sy = -D * gy if three else 0.0
    sz = -D * gz
    if symmetric_min_eigenvalue(bxx, bxy, bxz, byy, byz, bzz, three) >= lam_full:
        return sx, sy, sz
    # the normal's direction: adj(B) grad C (its sign and length do not matter)
    if three:
        c00 = byy * bzz - byz * byz
        c01 = bxz * byz - bxy * bzz
        c02 = bxy * byz - bxz * byy
        det = bxx * c00 + bxy * c01 + bxz * c02
        nx = c00 * gx + c01 * gy + c02 * gz
        ny = c01 * gx + (bxx * bzz - bxz * bxz) * gy + (bxy * bxz - bxx * byz) * gz
        nz = c02 * gx + (bxy * bxz - bxx * byz) * gy + (bxx * byy - bxy * bxy) * gz
    else:
        det = bxx * bzz - bxz * bxz
        nx = bzz * gx - bxz * gz
        ny = 0.0
        nz = bxx * gz - bxz * gx
    nn = nx * nx + ny * ny + nz * nz
    if not (det > 0.0 and nn > 0.0):
        return 0.0, 0.0, 0.0
    p = (sx * nx + sy * ny + sz * nz) / nn
    return sx - p * nx, sy - p * ny, sz - p * nz


def surface_fade(h, Fc, gsx, gsy, gsz, s0, s1):
    """The diffusion's factor under the free surface [-]: 1 where ``s_a = h |sum_b V_b
    grad_a W_ab| <= s0``, 0 where ``s_a >= s1``, linear between (``gs`` the sum of
    :func:`support_volume` ``Fs r_ab`` over the neighbours; fluid.equations.SURFACE_FADE)."""
    sa = h * abs(Fc) * math.sqrt(gsx * gsx + gsy * gsy + gsz * gsz)
    return min(max((s1 - sa) / (s1 - s0), 0.0), 1.0)


def continuity_rate(Fc, sd, ddt, fa, fade, sdd):
    """``drho_a/dt`` [kg/(m^3 s)]: the continuity sum ``sd`` plus the diffusion ``sdd`` of
    a fluid particle (``fa`` 1; 0 for boundary particles), ``ddt = 2 delta h c0``, times
    ``fade`` (:func:`surface_fade`) (Barreiro et al. 2016, Eq. 7)."""
    return Fc * (sd - ddt * fa * fade * sdd)


def acceleration(Fc, s, nu4, lam, laminar, fa, g):
    """One component of ``dv_a/dt`` [m/s^2] (Barreiro et al. 2016, Eq. 6): the pressure
    and artificial viscosity sum ``s``, the laminar sum ``lam`` times ``4 nu`` if
    ``laminar``, and gravity ``g`` on fluid particles (``fa`` 1)."""
    if laminar:
        s += nu4 * lam
    return Fc * s + fa * g


def adami_wall_pressure(sp, sw, sw_min, p_floor):
    """The wall particle's pressure [Pa] of Adami et al. 2012, Eq. 27: ``sum_f W_wf
    adami_pressure / sum_f W_wf`` (``sp``, ``sw``), at least ``p_floor``; 0 where the kernel
    sum ``sw`` is not above ``sw_min`` (no fluid within 2h)."""
    return max(sp / sw, p_floor) if sw > sw_min else 0.0


def viscous_speed(scale, v8):
    """``scale`` times the eighth root of the 8-norm sum of :func:`viscous_bound` [m/s]:
    the viscous term of Sunara et al. 2021, Eq. 14 (roots by square roots: pow is slower)."""
    return scale * math.sqrt(math.sqrt(math.sqrt(v8)))


# ------------------------------------------------------------------ linear solves
def renormalised_gradient(mxx, mxy, mxz, myy, myz, mzz, bx, by, bz, ka, gx, gy, gz, three):
    """The renormalised density gradient [kg/m^4] (Dinçer & Demir 2020, Eq. 3-4): ``-M^-1
    b`` with ``M = sum_b V_b Fs r_ab (x) r_ab`` (symmetric: ``mxx ... mzz``) and ``b =
    sum_b V_b Fs (rho_b - rho_a) r_ab`` (the kernel's constant cancels; exact for a linear
    field); where |det M| is below :data:`DET_MIN` of its mean diagonal's power (a particle
    at the free surface, few fluid neighbours), the hydrostatic ``ka g`` (``ka = rho_a /
    c_a^2``). Returns (x, y, z); y = 0 in 2-D (``three`` False: the x-z block only)."""
    if three:
        c00 = myy * mzz - myz * myz
        c01 = mxz * myz - mxy * mzz
        c02 = mxy * myz - mxz * myy
        det = mxx * c00 + mxy * c01 + mxz * c02
        scale = (mxx + myy + mzz) / 3.0
        ok = abs(det) > DET_MIN * abs(scale) ** 3
    else:
        det = mxx * mzz - mxz * mxz
        scale = 0.5 * (mxx + mzz)
        ok = abs(det) > DET_MIN * scale * scale
    if not ok:
        return ka * gx, ka * gy, ka * gz
    if three:
        c11 = mxx * mzz - mxz * mxz
        c12 = mxy * mxz - mxx * myz
        c22 = mxx * myy - mxy * mxy
        return -(c00 * bx + c01 * by + c02 * bz) / det, -(c01 * bx + c11 * by + c12 * bz) / det, \
            -(c02 * bx + c12 * by + c22 * bz) / det
    return -(mzz * bx - mxz * bz) / det, 0.0, -(mxx * bz - mxz * bx) / det


def det4(m00, m01, m02, m03, m10, m11, m12, m13, m20, m21, m22, m23, m30, m31, m32, m33):
    """Determinant of a 4 x 4 matrix by 2 x 2 minors (Laplace expansion on two rows): the
    MLS density's Cramer's rule (Sunara et al. 2021, Eq. 9-12; :mod:`fluid.mls`)."""
    s0 = m00 * m11 - m10 * m01
    s1 = m00 * m12 - m10 * m02
    s2 = m00 * m13 - m10 * m03
    s3 = m01 * m12 - m11 * m02
    s4 = m01 * m13 - m11 * m03
    s5 = m02 * m13 - m12 * m03
    c5 = m22 * m33 - m32 * m23
    c4 = m21 * m33 - m31 * m23
    c3 = m21 * m32 - m31 * m22
    c2 = m20 * m33 - m30 * m23
    c1 = m20 * m32 - m30 * m22
    c0 = m20 * m31 - m30 * m21
    return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0


def solve_in_place(A, b, n):
    """Solve the n x n system ``A x = b`` in place (Gaussian elimination, partial
    pivoting): ``b`` becomes x; returns the determinant (0 if singular, ``b`` then holds
    garbage). The mDBC ghost-node system (English et al. 2022, Eq. 12-13)."""
    det = 1.0
    for k in range(n):
        p = k
        for r in range(k + 1, n):
            if abs(A[r, k]) > abs(A[p, k]):
                p = r
        if A[p, k] == 0.0:
            return 0.0
        if p != k:
            det = -det
            for c in range(n):
                t = A[k, c]
                A[k, c] = A[p, c]
                A[p, c] = t
            t = b[k]
            b[k] = b[p]
            b[p] = t
        det *= A[k, k]
        for r in range(k + 1, n):
            f = A[r, k] / A[k, k]
            for c in range(k, n):
                A[r, c] -= f * A[k, c]
            b[r] -= f * b[k]
    for k in range(n - 1, -1, -1):
        s = b[k]
        for c in range(k + 1, n):
            s -= A[k, c] * b[c]
        b[k] = s / A[k, k]
    return det


#: the MLS moments of no neighbour (:func:`mls_moments`)
MLS_ZERO = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


def mls_moments(m, vw, mw, rx, ry, rz):
    """The MLS moments ``m`` (Sunara et al. 2021, Eq. 9-12) with one neighbour b added:
    ``A += V_b W_ab (1, x) (x) (1, x)`` (its upper triangle ``a00, a01, a02, a03, a11,
    a12, a13, a22, a23, a33``) and ``s += m_b W_ab (1, x)`` (``s0 ... s3``), ``vw = V_b
    W_ab``, ``mw = m_b W_ab``, ``x = (rx, ry, rz) = r_ab / h``; a tuple in, a tuple out (no
    allocation: the loops keep it in registers). Start from :data:`MLS_ZERO`."""
    a00, a01, a02, a03, a11, a12, a13, a22, a23, a33, s0, s1, s2, s3 = m
    return (a00 + vw, a01 + vw * rx, a02 + vw * ry, a03 + vw * rz, a11 + vw * rx * rx, a12 + vw * rx * ry,
            a13 + vw * rx * rz, a22 + vw * ry * ry, a23 + vw * ry * rz, a33 + vw * rz * rz,
            s0 + mw, s1 + mw * rx, s2 + mw * ry, s3 + mw * rz)


def mls_solve(m, three, min_det):
    """``(rho_a, 1)``: the MLS density [kg/m^3] (Sunara et al. 2021, Eq. 9-12), ``e_1 . A^-1
    s`` by Cramer's rule, from the moments ``m`` of a particle's neighbours
    (:func:`mls_moments`, coordinates ``x = r_ab / h``): ``A = sum_b V_b W_ab (1, x) (x)
    (1, x)`` (symmetric 4 x 4: ``a00 ... a33``) and ``s = sum_b m_b W_ab (1, x)``; in 2-D
    (``three`` False) the y row and column are the identity. ``(s0 / a00, 0)``, the Shepard
    filter, where ``det A`` is not above ``min_det`` times the product of its diagonal (too
    few or one-sided neighbours)."""
    a00, a01, a02, a03, a11, a12, a13, a22, a23, a33, s0, s1, s2, s3 = m
    if not three:
        a22 = 1.0
    scale = a00 * a11 * a22 * a33
    det = det4(a00, a01, a02, a03, a01, a11, a12, a13, a02, a12, a22, a23, a03, a13, a23, a33)
    if scale > 0.0 and det / scale > min_det:
        return det4(s0, a01, a02, a03, s1, a11, a12, a13, s2, a12, a22, a23, s3, a13, a23, a33) / det, 1
    return s0 / a00, 0


def mdbc_add_neighbour(A, bv, row, col, m, V, w, VF, rx, ry, rz, rhoj, three):
    """Add fluid particle j to the ghost node's first-order system (English et al. 2022,
    Eq. 12-13): ``A += row (x) col``, ``b += row rho_j`` with ``row = V_j (W, grad W)`` and
    ``col = (1, r_jg)`` in the solver's order (x, z or x, y, z; ``m`` = dim + 1); ``V`` =
    m_j / rho_j [m^3], ``w`` = W [1/m^dim], ``VF = -V F`` (``grad_g W = -F r_jg``), ``r_jg``
    [m]; ``col[0]`` holds 1."""
    d = 3 if three else 2
    row[0] = V * w
    col[1] = rx
    row[1] = VF * rx
    col[d] = rz
    row[d] = VF * rz
    if three:
        col[2] = ry
        row[2] = VF * ry
    for a in range(m):
        for k in range(m):
            A[a, k] += row[a] * col[k]
        bv[a] += row[a] * rhoj


def mdbc_extrapolate(A, bv, m, o, dim, det_min, rho0):
    """``(rho_b, low)``: the boundary particle's density [kg/m^3] from its ghost node's system
    (English et al. 2022, Eq. 12-13, :func:`mdbc_add_neighbour`), ``rho_g + (r_b - r_g) .
    grad rho_g`` (``o = r_g - r_b`` [m]); where ``|det A|`` is below ``det_min`` the Shepard
    value, rho0 with no fluid near (``low`` 1); at least rho0. Overwrites ``A``, ``bv``."""
    s0 = A[0, 0]
    sb = bv[0]
    if abs(solve_in_place(A, bv, m)) >= det_min:
        val = bv[0]
        for k in range(dim):
            val -= o[k] * bv[k + 1]
        return max(val, rho0), 0
    return (max(sb / s0, rho0) if s0 > 0.0 else rho0), 1


# ------------------------------------------------------------------ loads on the bodies
def particle_load(mass, ax, ay, az, rx, ry, rz):
    """``(F, M)`` of one boundary particle, six scalars: the force ``mass a`` [N] it takes
    from the fluid (``a`` [m/s^2] its rate of momentum exchange per unit mass) and its moment
    ``r x mass a`` [N m] about its group's point (``r`` [m] from it); in 2-D (``ay = ry = 0``)
    the moment about +y, ``rz fx - rx fz``, is the fifth."""
    fx, fy, fz = mass * ax, mass * ay, mass * az
    return fx, fy, fz, ry * fz - rz * fy, rz * fx - rx * fz, rx * fy - ry * fx


# ------------------------------------------------------------------ integration, one particle
# The integrator's updates (fluid.integrator: the symplectic predictor-corrector, Monaghan
# 2005, and Verlet, Monaghan 1989; as DualSPHysics integrates) of one particle: its density
# and one component of its position and velocity. ``fluid`` is True for a fluid particle; a
# boundary particle's density is clamped below at ``rho0`` (a wall never pulls fluid in, as
# DualSPHysics does) and it moves with its prescribed velocity. ``xs`` [m/s]: the XSPH
# correction of that component (0.0 when XSPH is off).
def wall_clamped(rn, fluid, rho0):
    """The new density [kg/m^3] ``rn`` of a fluid particle; of a boundary one, at least ``rho0``."""
    return rn if fluid else max(rn, rho0)


def predictor_density(r, drho, dt, fluid, rho0):
    """``rho^{n+1/2} = rho^n + dt/2 drho^n`` [kg/m^3] (Monaghan 2005)."""
    return wall_clamped(r + 0.5 * dt * drho, fluid, rho0)


def predictor_component(p, v, a, xs, dt, fluid):
    """``(r^{n+1/2}, v^{n+1/2})``: ``r^n + dt/2 (v^n + xs)``, ``v^n + dt/2 a^n`` (a boundary
    particle keeps its velocity)."""
    half = 0.5 * dt
    return p + half * (v + xs), (v + half * a if fluid else v)


def corrector_density(r_n, drho, r, dt, fluid, rho0):
    """``rho^{n+1} = rho^n (2 - eps) / (2 + eps)``, ``eps = -(drho^{n+1/2} / rho^{n+1/2}) dt``
    [kg/m^3] (Monaghan 2005; the symplectic update that keeps the density positive)."""
    eps = -drho / r * dt
    return wall_clamped(r_n * (2.0 - eps) / (2.0 + eps), fluid, rho0)


def corrector_component(p_n, v_n, a, xs, dt, fluid):
    """``(r^{n+1}, v^{n+1})``: ``v^n + dt a^{n+1/2}``, ``r^n + dt ((v^n + v^{n+1}) / 2 + xs)``."""
    v1 = v_n + dt * a if fluid else v_n
    return p_n + 0.5 * dt * (v_n + v1) + dt * xs, v1


def verlet_density(r, r_m1, drho, dt, euler, fluid, rho0):
    """``rho^{n+1} = rho^{n-1} + 2 dt drho^n`` [kg/m^3] (Monaghan 1989); ``euler``: the
    forward-Euler ``rho^n + dt drho^n`` that decouples odd and even steps."""
    if euler:
        return wall_clamped(r + dt * drho, fluid, rho0)
    return wall_clamped(r_m1 + 2.0 * dt * drho, fluid, rho0)


def verlet_component(p, v, v_m1, a, xs, dt, euler, fluid):
    """``(r^{n+1}, v^{n+1})``: ``r^n + dt (v^n + xs) + dt^2/2 a^n``, ``v^{n-1} + 2 dt a^n``
    (``euler``: ``v^n + dt a^n``) for a fluid particle; a boundary one ``r^n + dt v^n`` and its
    velocity kept (Monaghan 1989)."""
    if not fluid:
        return p + dt * v, v
    p1 = p + (dt * (v + xs) + 0.5 * dt * dt * a)
    if euler:
        return p1, v + dt * a
    return p1, v_m1 + 2.0 * dt * a


#: the terms :func:`compiled` compiles
TERMS = ("kernel_w", "kernel_grad_shape", "kernel_grad_scale", "tait", "tait_pressure", "tait_density",
         "pair_division", "continuity", "fourtakas_hydrostatic", "renormalised_hydrostatic", "density_diffusion",
         "support_volume", "artificial_viscosity", "wall_viscosity", "momentum", "laminar_viscosity",
         "viscous_bound", "xsph_weight", "adami_pressure", "surface_fade", "adami_wall_pressure", "continuity_rate",
         "acceleration", "viscous_speed", "fickian_weight", "symmetric_min_eigenvalue", "fickian_shift",
         "renormalised_gradient", "det4", "solve_in_place", "mls_moments", "mls_solve",
         "mdbc_add_neighbour", "mdbc_extrapolate", "wall_clamped", "predictor_density", "predictor_component",
         "corrector_density", "corrector_component", "verlet_density", "verlet_component", "particle_load")
_OPTS = dict(fastmath=True, cache=True, error_model="numpy")
#: the terms compiled for the CPU loops (numba.njit; LLVM inlines them), and for the
#: float32 pair loop (float32 literals; not cached: the same code as ``cpu``'s, typed apart)
cpu = compiled(njit(**_OPTS))
cpu_f32 = compiled(njit(**{**_OPTS, "cache": False}), float32=True, name="cpu_f32")
