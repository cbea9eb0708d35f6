"""The SPH terms of fluid.terms, each against its equation or an invariant of it, and as the
CPU loops compile them (numba.njit, float64 and float32) against the plain functions. That
the GPU kernels, built from the same terms, give the CPU's rates: tests/test_fluid_cuda.py."""

import math

import numpy as np
import pytest

from fluid import terms

RHO0, C0, GAMMA = 1000.0, 20.0, 7.0
B = C0**2 * RHO0 / GAMMA


def test_tait_is_the_equation_of_state_and_its_inverse():
    """Barreiro et al. 2016, Eq. 8: P(rho0) = 0, c(rho0) = c0, P = B ((rho/rho0)^gamma - 1),
    c = c0 (rho/rho0)^3 for gamma = 7; tait_density inverts tait_pressure."""
    e = 0.5 * (GAMMA - 1.0)
    assert terms.cpu.tait(RHO0, RHO0, C0, GAMMA, B, e) == (0.0, C0)
    for rho in (990.0, 1003.0, 1021.5):
        p, c = terms.cpu.tait(rho, RHO0, C0, GAMMA, B, e)
        assert p == pytest.approx(B * ((rho / RHO0) ** 7 - 1), rel=1e-13)
        assert c == pytest.approx(C0 * (rho / RHO0) ** 3, rel=1e-13)
        # gamma = 7 by products, any other gamma by pow: the same law
        p7 = terms.cpu.tait_pressure(rho, RHO0, B, 7.0 + 1e-15)
        assert terms.cpu.tait_pressure(rho, RHO0, B, 7.0) == pytest.approx(p7, rel=1e-10)
        assert terms.cpu.tait_density(p, RHO0, B, 1.0 / GAMMA) == pytest.approx(rho, rel=1e-14)


@pytest.mark.parametrize("kernel", [terms.WENDLAND, terms.CUBIC])
def test_kernel_gradient_is_the_derivative_of_the_kernel(kernel):
    """grad_a W_ab = F r_ab, F = scale * shape = (dW/dr) / r (fluid.kernels docstring)."""
    h, ad = 0.02, 3.7
    for q in (0.3, 0.9, 1.4, 1.9):
        r, dr = q * h, 1e-7 * h
        dW = (terms.cpu.kernel_w(kernel, (r + dr) / h, ad) - terms.cpu.kernel_w(kernel, (r - dr) / h, ad)) / (2 * dr)
        F = terms.cpu.kernel_grad_scale(kernel, ad, h) * terms.cpu.kernel_grad_shape(kernel, q)
        assert F * r == pytest.approx(dW, rel=1e-6)
    assert terms.cpu.kernel_w(kernel, 2.0, ad) == 0.0 and terms.cpu.kernel_grad_shape(kernel, 2.5) == 0.0


def test_diffusion_vanishes_in_the_hydrostatic_state_for_both_corrections():
    """A density linear along gravity, rho = R + kappa g . r, kappa = rho / c^2: the
    Fourtakas et al. 2019 and the renormalised (Dinçer & Demir 2020, Eq. 2) rho^H_ba equal
    rho_b - rho_a, so the diffusion term (Eq. 1) is zero; Molteni's (rho^H = 0) is not."""
    g = np.array([0.3, -0.5, -9.81])
    kap = 1000.0 / C0**2
    rng = np.random.default_rng(1)
    for _ in range(5):
        ra, rb = rng.normal(0, 0.02, 3), rng.normal(0, 0.02, 3)
        rab = ra - rb
        rhoa, rhob = 1000.0 + kap * g @ ra, 1000.0 + kap * g @ rb
        hg = -0.5 * g
        four = terms.cpu.fourtakas_hydrostatic(*hg, *rab, kap, kap, True)
        ren = terms.cpu.renormalised_hydrostatic(*(kap * g), *(kap * g), *rab, True)
        r2 = rab @ rab
        for rhoH in (four, ren):
            assert rhoH == pytest.approx(rhob - rhoa, rel=1e-12)
        assert terms.cpu.density_diffusion(0.1, rhoa, rhob, 0.0, 1.0, r2, 1.0) != 0.0


def test_momentum_pair_terms_are_antisymmetric_and_viscosity_acts_on_approach_only():
    """m_a dv_a + m_b dv_b = 0 for every pair (Barreiro et al. 2016, Eq. 6 with a symmetric
    Pi_ab, Monaghan 1992): the pair exchanges momentum exactly; Pi_ab = 0 for separating pairs."""
    h, eta2 = 0.013, 0.01 * 0.013**2
    ma, mb, rhoa, rhob, ca, cb = 0.11, 0.09, 1002.0, 997.0, 20.3, 19.9
    pa, pb = 350.0 / rhoa**2, -20.0 / rhob**2
    rab = np.array([0.004, -0.002, 0.011])
    for vab in (np.array([-0.3, 0.1, -0.2]), np.array([0.3, -0.1, 0.2])):
        vr, r2 = vab @ rab, rab @ rab
        Fs = terms.cpu.kernel_grad_shape(terms.WENDLAND, math.sqrt(r2) / h)
        _, d, _ = terms.cpu.pair_division(r2, eta2, rhoa + rhob)
        Pi = terms.cpu.artificial_viscosity(-0.1 * h, ca, cb, vr, d)
        assert (Pi > 0) == (vr < 0) and (Pi == 0) == (vr > 0)
        # mu_ab = h vr / (r^2 + eta^2), Pi = -alpha cbar mu / rhobar
        assert Pi == pytest.approx(-0.1 * 0.5 * (ca + cb) * h * min(vr, 0) / (r2 + eta2) / (0.5 * (rhoa + rhob)))
        dva = -terms.cpu.momentum(mb * Fs, pa, pb, Pi) * rab
        dvb = -terms.cpu.momentum(ma * Fs, pb, pa, Pi) * -rab
        np.testing.assert_allclose(ma * dva + mb * dvb, 0.0, atol=1e-15 * np.abs(ma * dva).max())
        lam_a = terms.cpu.laminar_viscosity(mb * Fs, r2, d) * vab
        lam_b = terms.cpu.laminar_viscosity(ma * Fs, r2, d) * -vab
        np.testing.assert_allclose(ma * lam_a + mb * lam_b, 0.0, atol=1e-15 * np.abs(ma * lam_a).max())
        # the time step's viscous term of one pair: |mu_ab|
        _, _, inv = terms.cpu.pair_division(r2, eta2, rhoa + rhob)
        v8 = terms.cpu.viscous_bound(1.0, r2, 4 * h * h, vr, inv, 1.0)
        assert terms.cpu.viscous_speed(h, v8) == pytest.approx(h * abs(vr) / (r2 + eta2), rel=1e-14)


def test_surface_fade_and_continuity_rate():
    """The fade is 1 inside the fluid (s_a <= s0), 0 at the surface (s_a >= s1), linear
    between; boundary particles (fa = 0) take no diffusion."""
    s0, s1 = 0.02, 0.05
    assert terms.cpu.surface_fade(1.0, 1.0, 0.01, 0.0, 0.0, s0, s1) == 1.0
    assert terms.cpu.surface_fade(1.0, -1.0, 0.0, 0.06, 0.0, s0, s1) == 0.0
    assert terms.cpu.surface_fade(1.0, 1.0, 0.0, 0.0, 0.035, s0, s1) == pytest.approx(0.5)
    assert terms.cpu.continuity_rate(2.0, 3.0, 5.0, 0.0, 1.0, 7.0) == 6.0
    assert terms.cpu.continuity_rate(2.0, 3.0, 5.0, 1.0, 0.5, 7.0) == 2.0 * (3.0 - 17.5)


def test_adami_wall_pressure_is_exact_for_a_hydrostatic_field():
    """Adami et al. 2012, Eq. 27: in the pressure field p = rho0 (g - a_w) . (r - r_s) of a
    fluid of density rho0 accelerated by g - a_w, every fluid particle carries the wall's own
    pressure to it, so any weights give it; floored at p_floor; 0 with no fluid weight."""
    rho0 = 1000.0
    b = rho0 * (np.array([0.4, -0.2, -9.81]) - np.array([1.5, 0.0, 0.3]))  # rho0 (g - a_w)
    rng = np.random.default_rng(2)
    rs = np.array([0.0, 0.0, 0.5])
    rw = np.array([0.1, 0.05, 0.02])
    sp = sw = 0.0
    for _ in range(12):
        rf = rw + rng.normal(0, 0.01, 3)
        carried = terms.cpu.adami_pressure(b @ (rf - rs), *b, *(rw - rf))
        assert carried == pytest.approx(b @ (rw - rs), rel=1e-12)
        w = float(rng.uniform(0.1, 1.0))
        sw += w
        sp += w * carried
    assert terms.cpu.adami_wall_pressure(sp, sw, 1e-24, 0.0) == pytest.approx(b @ (rw - rs), rel=1e-12)
    assert terms.cpu.adami_wall_pressure(-sp, sw, 1e-24, 0.0) == 0.0
    assert terms.cpu.adami_wall_pressure(sp, 1e-30, 1e-24, 0.0) == 0.0


def _args(term, rng):
    """Arguments for a term: kernel ids and flags where the name says so, floats else."""
    names = terms.__dict__[term].__code__.co_varnames[:terms.__dict__[term].__code__.co_argcount]
    out = []
    for n in names:
        if n == "kernel":
            out.append(int(rng.integers(0, 2)))
        elif n in ("three", "tilted", "laminar"):
            out.append(bool(rng.integers(0, 2)))
        elif n == "gamma":
            out.append(7.0)
        elif n in ("q",):
            out.append(float(rng.uniform(0, 2.2)))
        elif n == "m":  # the MLS moments, a tuple (terms.MLS_ZERO)
            out.append(tuple(float(v) for v in rng.uniform(0.1, 2.0, len(terms.MLS_ZERO))))
        else:
            out.append(float(rng.uniform(0.1, 2.0)))
    return out


@pytest.mark.parametrize("term", [t for t in terms.TERMS if t not in ("solve_in_place", "mdbc_add_neighbour",
                                                                       "mdbc_extrapolate")])
def test_compiled_terms_are_the_plain_functions(term):
    """What the CPU loops call is the term as written: the njit compilation equals the
    Python function (to fastmath's reassociation), and the float32 variant computes in
    float32 what the float64 one does, to float32 round-off."""
    rng = np.random.default_rng(7)
    py = getattr(terms, term)
    for _ in range(3):
        args = _args(term, rng)
        want = np.atleast_1d(py(*args))
        np.testing.assert_allclose(np.atleast_1d(getattr(terms.cpu, term)(*args)), want, rtol=1e-13)
        a32 = [np.float32(a) if isinstance(a, float) else tuple(map(np.float32, a)) if isinstance(a, tuple) else a
               for a in args]
        got = getattr(terms.cpu_f32, term)(*a32)
        np.testing.assert_allclose(np.atleast_1d(got), want, rtol=3e-6, atol=1e-5)


def test_float32_variant_types_its_literals_as_float32():
    """A float64 literal would promote a float32 expression: the variant's are float32."""
    from numba import njit, types

    f = njit(terms.float32_variant(terms.kernel_grad_shape))
    f(terms.CUBIC, np.float32(0.7))
    assert f.nopython_signatures[0].return_type == types.float32
    g = njit(terms.kernel_grad_shape)
    g(terms.CUBIC, np.float32(0.7))
    assert g.nopython_signatures[0].return_type == types.float64


@pytest.mark.parametrize("three", [False, True])
def test_renormalised_gradient_is_exact_for_a_linear_density(three):
    """Dinçer & Demir 2020, Eq. 3-4: -M^-1 b reproduces the gradient of any linear field
    from any (non-degenerate) neighbours; a degenerate M gives the hydrostatic ka g."""
    rng = np.random.default_rng(3)
    grad = np.array([3.0, -1.5, 7.0]) if three else np.array([3.0, 0.0, 7.0])
    r = rng.normal(0, 0.01, (30, 3))
    if not three:
        r[:, 1] = 0.0
    w = rng.uniform(0.1, 1.0, 30)  # V_b Fs
    M = np.einsum("b,bi,bj->ij", w, r, r)
    bv = np.einsum("b,b,bi->i", w, -(r @ grad), r)  # rho_b - rho_a = -grad . r_ab
    args = (M[0, 0], M[0, 1], M[0, 2], M[1, 1], M[1, 2], M[2, 2], *bv, 2.5e-3, 0.0, 0.0, -9.81, three)
    np.testing.assert_allclose(terms.cpu.renormalised_gradient(*args), grad, rtol=1e-10, atol=1e-12)
    flat = (M[0, 0], 0.0, 0.0, 0.0, 0.0, 1e-12 * M[0, 0], *bv, 2.5e-3, 0.0, 0.0, -9.81, three)  # all on a line
    assert terms.cpu.renormalised_gradient(*flat) == (0.0, 0.0, 2.5e-3 * -9.81)


def test_solve_and_det4_against_numpy():
    """The mDBC system's elimination and the MLS determinant: numpy's solve and det."""
    rng = np.random.default_rng(5)
    for n in (3, 4):
        A = rng.normal(size=(n, n))
        b = rng.normal(size=n)
        x = b.copy()
        det = terms.cpu.solve_in_place(A.copy(), x, n)
        np.testing.assert_allclose(x, np.linalg.solve(A, b), rtol=1e-12)
        assert det == pytest.approx(np.linalg.det(A), rel=1e-12)
    A = rng.normal(size=(4, 4))
    assert terms.cpu.det4(*A.ravel()) == pytest.approx(np.linalg.det(A), rel=1e-12)
    assert terms.cpu.solve_in_place(np.zeros((2, 2)), np.ones(2), 2) == 0.0


@pytest.mark.parametrize("three", [False, True])
def test_fickian_shift_and_its_free_surface_projection(three):
    """Lind et al. 2012's shift -D grad C where B (the renormalisation matrix) is near the
    identity; below lam_full its component along n = B^-1 grad C removed (and B's smallest
    eigenvalue is numpy's); nothing for a singular B."""
    rng = np.random.default_rng(11)
    d = 3 if three else 2
    for _ in range(5):
        A = rng.normal(size=(d, d))
        B = A @ A.T + 0.1 * np.eye(d)
        g = rng.normal(size=d)
        b = (B[0, 0], B[0, 1], B[0, 2], B[1, 1], B[1, 2], B[2, 2]) if three else (B[0, 0], 0.0, B[0, 1], 0.0, 0.0,
                                                                                  B[1, 1])
        g3 = (g[0], g[1], g[2]) if three else (g[0], 0.0, g[1])
        lam = np.linalg.eigvalsh(B)[0]
        assert terms.cpu.symmetric_min_eigenvalue(*b, three) == pytest.approx(lam, rel=1e-10, abs=1e-12)
        full = np.array(terms.cpu.fickian_shift(*g3, *b, 0.5, lam - 1e-6, three))
        np.testing.assert_allclose(full[[0, 1, 2] if three else [0, 2]], -0.5 * g, rtol=1e-12)
        cut = np.array(terms.cpu.fickian_shift(*g3, *b, 0.5, lam + 1e-6, three))[[0, 1, 2] if three else [0, 2]]
        n = np.linalg.solve(B, g)
        assert abs(cut @ n) < 1e-12 * np.linalg.norm(g) * np.linalg.norm(n)
        np.testing.assert_allclose(cut, -0.5 * (g - (g @ n) / (n @ n) * n), rtol=1e-10, atol=1e-14)
    singular = (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)  # one neighbour: B of rank 1
    assert terms.cpu.fickian_shift(1.0, 0.0, 0.5, *singular, 0.5, 0.97, three) == (0.0, 0.0, 0.0)


def _particles(n=6, dim=2, seed=3):
    rng = np.random.default_rng(seed)
    pos, vel, acc = rng.normal(size=(n, dim)), rng.normal(size=(n, dim)), rng.normal(size=(n, dim))
    kind = np.zeros(n, np.int32)
    kind[-2:] = 1  # two boundary particles
    return pos, vel, acc, kind


def test_integrators_are_exact_under_a_constant_acceleration():
    """Both schemes (fluid.integrator, built from the integration terms) carry a fluid
    particle under a constant acceleration along x0 + v0 t + a t^2 / 2 and v0 + a t exactly
    (to round-off): the predictor-corrector at every step, Verlet from an Euler start
    (its leap-frog then keeps the exact parabola); boundary particles move with their
    velocity and keep it."""
    from fluid.integrator import corrector, predictor, verlet

    pos0, vel0, acc, kind = _particles()
    n, dt, steps = len(kind), 0.01, 20
    rho, drho = np.full(n, 1000.0), np.zeros(n)
    f = kind == 0
    t = dt * steps
    exact_x = pos0 + np.where(f[:, None], vel0 * t + 0.5 * acc * t * t, vel0 * t)
    exact_v = np.where(f[:, None], vel0 + acc * t, vel0)
    none = np.empty((0, 2))

    pos, vel = pos0.copy(), vel0.copy()
    pn, vn, rn = np.empty_like(pos), np.empty_like(vel), np.empty(n)
    for _ in range(steps):
        predictor(pos, vel, rho, drho, acc, kind, 1000.0, dt, pn, vn, rn, none)
        corrector(pos, vel, rho, drho, acc, kind, 1000.0, dt, pn, vn, rn, none)
    np.testing.assert_allclose(pos, exact_x, rtol=0, atol=1e-13)
    np.testing.assert_allclose(vel, exact_v, rtol=0, atol=1e-13)

    pos, vel = pos0.copy(), vel0.copy()
    vm1, rm1 = vel.copy(), rho.copy()
    for s in range(steps):
        verlet(pos, vel, rho, drho, acc, kind, 1000.0, dt, vm1, rm1, s == 0, none)
    # from an Euler step, v^n = v0 + a t_n exactly, and r^{n+1} = r^n + dt v^n + dt^2 a / 2 is the parabola's
    np.testing.assert_allclose(vel, exact_v, rtol=0, atol=1e-13)
    np.testing.assert_allclose(pos, exact_x, rtol=0, atol=1e-12)


def test_symplectic_density_update_is_the_pade_step_and_walls_stay_above_rho0():
    """The corrector's density, rho^n (2 - eps) / (2 + eps) with eps = -(drho / rho) dt
    (Monaghan 2005), is the (1, 1) Padé approximant of exp(-k dt) for drho = -k rho: within
    (k dt)^3 / 12 of the exact decay per step; a boundary particle's density never falls
    below rho0 (the predictor, the corrector and Verlet alike) and a fluid one's may."""
    from fluid.integrator import corrector, predictor, verlet

    k, dt = 50.0, 2e-3
    rho = np.array([1010.0, 1010.0])
    kind = np.array([0, 1], np.int32)
    pos, vel, acc = np.zeros((2, 2)), np.zeros((2, 2)), np.zeros((2, 2))
    pn, vn, rn, none = np.empty((2, 2)), np.empty((2, 2)), np.empty(2), np.empty((0, 2))
    start = rho.copy()
    predictor(pos, vel, rho, -k * rho, acc, kind, 1000.0, dt, pn, vn, rn, none)
    corrector(pos, vel, rho, -k * rho, acc, kind, 1000.0, dt, pn, vn, rn, none)
    z = k * dt
    assert rho[0] == pytest.approx(start[0] * (2 - z) / (2 + z), rel=1e-14)
    assert abs(rho[0] / start[0] - np.exp(-z)) < z ** 3 / 12
    assert rho[1] == 1000.0  # 1010 e^-0.1 = 914 for fluid: the wall is clamped at rho0
    rho = np.array([1000.5, 1000.5])
    rm1 = rho.copy()
    verlet(pos, vel, rho, np.array([-1e3, -1e3]), acc, kind, 1000.0, dt, vn, rm1, True, none)
    assert rho[0] == pytest.approx(1000.5 - 2.0) and rho[1] == 1000.0


def test_particle_load_is_the_force_and_its_moment():
    """A boundary particle's load (fluid.terms.particle_load): ``m a`` and ``r x m a``; in
    2-D (no y parts) the moment about +y alone, positive for a force along +x above the point."""
    rng = np.random.default_rng(5)
    for _ in range(5):
        m, a, r = rng.uniform(0.1, 2.0), rng.normal(size=3), rng.normal(size=3)
        got = terms.cpu.particle_load(m, *a, *r)
        np.testing.assert_allclose(got[:3], m * a, rtol=1e-14)
        np.testing.assert_allclose(got[3:], np.cross(r, m * a), rtol=1e-13, atol=1e-15)
    assert terms.cpu.particle_load(2.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.5) == (6.0, 0.0, 0.0, 0.0, 3.0, 0.0)
