"""The vectorised pair loop (fluid.equations.interact) against a plain O(N^2) evaluation of
the same equations (fluid.equations module docstring, written out here pair by pair with
numpy), on small random sets with fluid, fixed walls and a moving body."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid import equations as eq
from fluid.geometry import block
from fluid.kernels import alpha_d, kernel_id
from fluid.neighbours import Grid, fluid_near_cells, sort_by_cell
from fluid.particles import Kind

RHO0, C0, GAMMA = 1000.0, 20.0, 7.0


def kernel_terms(kernel, q, ad, h):
    """(W, F) with grad_a W_ab = F r_ab (fluid.kernels docstring), zero beyond q = 2."""
    if kernel == "wendland":
        t = np.clip(1 - q / 2, 0, None)
        return ad * t**4 * (2 * q + 1), -5 * ad / h**2 * t**3
    t2, t1 = np.clip(2 - q, 0, None), np.clip(1 - q, 0, None)
    with np.errstate(divide="ignore", invalid="ignore"):
        F = np.where(q > 0, ad / h**2 * (-0.75 * t2**2 + 3 * t1**2) / np.where(q > 0, q, 1), 0.0)
    return ad * 0.25 * (t2**3 - 4 * t1**3), F


def brute_force(pos, vel, rho, mass, kind, h, kernel, alpha, delta, diffusion, g, nu, eps, alpha_wall=1.0,
                at_surface=True):
    """drho (N,), acc (N, dim), visc (N,), xsph (N, dim) summed over every pair."""
    n, dim = pos.shape
    ad = alpha_d(kernel_id(kernel), dim, h)
    B = C0**2 * RHO0 / GAMMA
    p = B * ((rho / RHO0) ** GAMMA - 1)
    c = C0 * (rho / RHO0) ** ((GAMMA - 1) / 2)
    r = pos[:, None, :] - pos[None, :, :]  # r_ab
    v = vel[:, None, :] - vel[None, :, :]  # v_ab
    r2 = (r * r).sum(-1)
    Wab, F = kernel_terms(kernel, np.sqrt(r2) / h, ad, h)
    fl = (kind == Kind.FLUID).astype(float)
    mask = np.maximum(fl[:, None], fl[None, :])  # no boundary-boundary pairs
    mb = mass[None, :] * mask
    eta2 = 0.01 * h * h
    vr = (v * r).sum(-1)
    # continuity (Barreiro et al. 2016, Eq. 7) and density diffusion between fluid particles
    drho = (mb * vr * F).sum(1)
    if diffusion != "none":
        rhoH = 0.0
        if diffusion == "fourtakas":
            kap = rho / c**2
            rhoH = 0.5 * (kap[:, None] + kap[None, :]) * (-(r @ g))  # rhobar/c^2 g.(r_b - r_a)
        if diffusion == "antuono":  # Dinçer & Demir 2020, Eq. 2-4: renormalised gradients over fluid neighbours
            w = (mass / rho * fl)[None, :] * F  # V_b F_ab
            M = np.einsum("ab,abi,abj->aij", w, r, r)
            bv = np.einsum("ab,ab,abi->ai", w, rho[None, :] - rho[:, None], r)
            det = np.linalg.det(M)
            scale = np.trace(M, axis1=1, axis2=2) / dim
            ok = np.abs(det) > 1e-3 * np.abs(scale) ** dim
            G = np.where(ok[:, None], -np.linalg.solve(np.where(ok[:, None, None], M, np.eye(dim)), bv[..., None])[..., 0],
                         (rho / c**2)[:, None] * g)
            G *= fl[:, None]
            rhoH = -0.5 * ((G[:, None, :] + G[None, :, :]) * r).sum(-1)
        psi_gradW = 2 * (rho[None, :] - rho[:, None] - rhoH) * (-F) * r2 / (r2 + eta2)
        D = delta * h * C0 * ((mass / rho)[None, :] * fl[:, None] * fl[None, :] * psi_gradW).sum(1)
        if not at_surface:  # faded by the support's cut (fluid.equations docstring)
            V = np.where(fl > 0, mass / rho, mass / RHO0)
            s = h * np.linalg.norm(((V[None, :] * F)[..., None] * r).sum(1), axis=1)
            s0, s1 = eq.SURFACE_FADE
            D = D * np.clip((s1 - s) / (s1 - s0), 0, 1)
        drho = drho + D
    # momentum (Barreiro et al. 2016, Eq. 6) with Monaghan's artificial viscosity (Sunara et al. 2021, Eq. 6)
    mu = h * np.minimum(vr, 0) / (r2 + eta2)
    Pi = -alpha * 0.5 * (c[:, None] + c[None, :]) * mu / (0.5 * (rho[:, None] + rho[None, :]))
    Pi = Pi * np.where(fl[:, None] * fl[None, :] > 0, 1.0, alpha_wall)  # fluid-boundary pairs
    coef = -mb * ((p / rho**2)[:, None] + (p / rho**2)[None, :] + Pi) * F
    acc = (coef[..., None] * r).sum(1)
    # laminar viscosity (Lo & Shao 2002)
    lam = mb * 4 * nu * F * r2 / ((rho[:, None] + rho[None, :]) * (r2 + eta2))
    acc += (lam[..., None] * v).sum(1)
    acc += fl[:, None] * g
    # 8-norm of the viscous term of Sunara et al. 2021, Eq. 14 over the support (fluid.equations.interact)
    visc = ((mask * (r2 < 4 * h * h) * h * vr / (r2 + eta2)) ** 8).sum(1) ** 0.125
    # XSPH: eps sum_b m_b / rhobar_ab v_ba W_ab, fluid particles only
    xs = eps * fl[:, None] * ((mb / (0.5 * (rho[:, None] + rho[None, :])) * Wab)[..., None] * (-v)).sum(1)
    return drho, acc, visc, xs


def scene(dim, seed, jitter=0.15, mass_spread=0.1):
    rng = np.random.default_rng(seed)
    dx = 0.01
    L = 0.12 if dim == 2 else 0.05
    fl = block(np.zeros(dim), np.full(dim, L), dx)
    fl = fl + rng.normal(0, jitter * dx, fl.shape)
    lo, hi = np.full(dim, -0.02), np.full(dim, L + 0.02)
    hi[-1] = 0.0
    floor = block(lo, hi, dx) - np.r_[np.zeros(dim - 1), 0.005]
    lo2, hi2 = np.zeros(dim), np.full(dim, L)
    lo2[0], hi2[0] = L + 0.005, L + 0.025
    side = block(lo2, hi2, dx)
    pos = np.concatenate([fl, floor, side])
    kind = np.r_[np.zeros(len(fl)), np.full(len(floor), Kind.FIXED_WALL), np.full(len(side), Kind.BODY)]
    vel = rng.normal(0, 0.3, pos.shape)
    vel[len(fl):len(fl) + len(floor)] = 0.0
    vel[len(fl) + len(floor):] = [-0.2] + [0.05] * (dim - 1)
    rho = RHO0 * (1 + rng.uniform(-0.005, 0.01, len(pos)))
    mass = RHO0 * dx**dim * (1 + rng.uniform(-mass_spread, mass_spread, len(pos)))
    return pos, vel, rho, mass, kind.astype(np.int8), dx


# every kernel and dimension, and the optional terms with each dimension (each variant
# costs a few seconds of compilation on a cold cache: the fast tier keeps the variants its
# other tests compile anyway, the long tier the ones no other test uses)
@pytest.mark.parametrize("dim, kernel, nu, xsph, alpha_wall", [
    (2, "wendland", 0.0, 0.0, 1.0), (3, "wendland", 0.0, 0.0, 1.0), (2, "cubic", 0.0, 0.0, 1.0),
    (3, "cubic", 0.0, 0.0, 1.0), (2, "wendland", 1e-3, 0.3, 1.0), (3, "wendland", 1e-3, 0.3, 1.0),
    pytest.param(2, "wendland", 0.0, 0.0, 0.25, marks=pytest.mark.long), (2, "wendland", 0.0, 0.0, "antuono"),
    pytest.param(3, "cubic", 0.0, 0.0, "antuono", marks=pytest.mark.long),
    (2, "wendland", 0.0, 0.0, "fade"), (3, "wendland", 0.0, 0.0, "fade"), (3, "wendland", 0.0, 0.0, "tilted")])
def test_pair_loop_equals_brute_force(dim, kernel, nu, xsph, alpha_wall):
    check_pair_loop(dim, kernel, nu, xsph, alpha_wall, "float64")


#: how close the float32 pair loop comes to the float64 sums, relative to each field's
#: largest value (measured 1e-7 ... 6e-7 on these sets; float32's epsilon is 6e-8)
F32_TOL = 3e-6


# the float32 loop (FluidConfig(precision="float32")) in both dimensions, with each optional
# term once (the fast tier: the variant without optional terms, which the solver's float32
# tests compile anyway)
@pytest.mark.parametrize("dim, kernel, nu, xsph, alpha_wall", [
    (2, "wendland", 0.0, 0.0, 1.0), pytest.param(2, "wendland", 0.0, 0.0, 0.25, marks=pytest.mark.long),
    pytest.param(3, "cubic", 1e-3, 0.3, 1.0, marks=pytest.mark.long),
    pytest.param(3, "wendland", 0.0, 0.0, "fade", marks=pytest.mark.long),
    pytest.param(2, "cubic", 0.0, 0.0, "antuono", marks=pytest.mark.long)])
def test_float32_pair_loop_equals_brute_force_to_float32_round_off(dim, kernel, nu, xsph, alpha_wall):
    check_pair_loop(dim, kernel, nu, xsph, alpha_wall, "float32")


def check_pair_loop(dim, kernel, nu, xsph, alpha_wall, precision):
    at_surface = alpha_wall != "fade"  # diffusion_at_surface=False
    # the fade, on a set as ordered as a flow's bulk (equal masses), so that it is partial
    pos, vel, rho, mass, kind, dx = scene(dim, seed=dim) if at_surface else scene(dim, dim, 0.02, 0.0)
    h = math.sqrt(2) * dx if dim == 2 else 1.3 * dx
    g = np.zeros(dim)
    g[-1] = -9.81
    if alpha_wall == "tilted":  # the Fourtakas rho^H along g . r_ab, not g_z z_ab (the loop's "tilted" variant)
        alpha_wall, g[:-1] = 1.0, (2.0, -1.0)[:dim - 1]
    alpha, delta, diffusion = 0.1, 0.1, "fourtakas"
    if alpha_wall == "antuono":  # the renormalised diffusion (its own gradient loop)
        alpha_wall, diffusion = 1.0, "antuono"
    if not at_surface:
        alpha_wall = 1.0
    # a grid barely larger than the set, so that rounded-up ranges reach the row ends
    grid = Grid.covering(pos.min(0) - 1e-9, pos.max(0) + 1e-9, 2 * h)
    perm, start, out = sort_by_cell(pos, grid)
    assert out == 0
    k = kernel_id(kernel)
    prm = eq.params(h, alpha_d(k, dim, h), alpha, delta, diffusion, RHO0, C0, g, nu=nu, xsph=xsph,
                    alpha_wall=alpha_wall, diffusion_at_surface=at_surface, precision=precision)
    tol = 1e-11 if precision == "float64" else F32_TOL
    p = np.empty(len(pos))
    r = eq.evaluate(pos[perm], vel[perm], rho[perm], mass[perm], kind[perm], start, grid, k, prm,
                    RHO0, C0, GAMMA, p)
    drho, acc, visc, xs = brute_force(pos[perm], vel[perm], rho[perm], mass[perm], kind[perm], h, kernel,
                                      alpha, delta, diffusion, g, nu, xsph, alpha_wall, at_surface)
    assert np.abs(drho).max() > 1.0 and np.abs(acc - g * (kind[perm] == 0)[:, None]).max() > 1.0
    np.testing.assert_allclose(r.drho, drho, rtol=0, atol=tol * np.abs(drho).max())
    if precision == "float32":  # float32 it is: its round-off shows
        assert np.abs(r.drho - drho).max() > 1e-9 * np.abs(drho).max()
    if not at_surface:  # the fade takes diffusion from the particles by the surface, not from all
        args = pos[perm], vel[perm], rho[perm], mass[perm], kind[perm], h, kernel, alpha, delta
        fl = kind[perm] == Kind.FLUID
        # (the 3-D block is 5 particles across: nearly all of it is within two rows of a surface)
        for other, least in ((brute_force(*args, diffusion, g, nu, xsph)[0], 0.3),
                             (brute_force(*args, "none", g, nu, xsph)[0], 0.03)):
            assert (np.abs(drho - other)[fl] > 1e-6 * np.abs(other).max()).mean() > least
    np.testing.assert_allclose(r.acc, acc, rtol=0, atol=tol * np.abs(acc).max())
    np.testing.assert_allclose(r.visc, visc, rtol=tol, atol=0)
    if xsph:
        assert np.abs(xs).max() > 1e-2
        np.testing.assert_allclose(r.xsph, xs, rtol=0, atol=tol * np.abs(xs).max())
    else:
        assert r.xsph is None


def test_laminar_viscosity_conserves_momentum_and_damps_relative_motion():
    """The laminar term of the pair loop is antisymmetric in the pair (sum m_a a_a = 0)
    and removes kinetic energy (sum m_a v_a . a_a < 0)."""
    pos, vel, rho, mass, kind, dx = scene(2, seed=5)
    fl = kind == Kind.FLUID
    pos, vel, rho, mass, kind = pos[fl], vel[fl], rho[fl], mass[fl], kind[fl]
    h = math.sqrt(2) * dx
    grid = Grid.covering(pos.min(0) - 1e-9, pos.max(0) + 1e-9, 2 * h)
    perm, start, _ = sort_by_cell(pos, grid)
    acc = {}
    for nu in (0.0, 1e-2):
        prm = eq.params(h, alpha_d(0, 2, h), 0.0, 0.0, "none", RHO0, C0, np.zeros(2), nu=nu)
        acc[nu] = eq.evaluate(pos[perm], vel[perm], rho[perm], mass[perm], kind[perm], start, grid, 0, prm,
                              RHO0, C0, GAMMA, np.empty(len(pos))).acc
    a = acc[1e-2] - acc[0.0]
    m, v = mass[perm, None], vel[perm]
    assert np.abs((m * a).sum(0)).max() < 1e-12 * (m * np.abs(a)).sum()
    assert (m * v * a).sum() < -1e-3 * (m * np.abs(v * a)).sum()


def test_rows_marked_to_skip_get_zero_rates_and_leave_the_others_exact():
    """``skip`` (a symmetry plane's mirror images: neighbours whose own rates nobody reads):
    the marked rows get zero rates without a pass, every other row the rates of the full
    pass, bit for bit, the marked rows still taking part as neighbours. (With the
    renormalised diffusion the marked rows get no density gradient either: the mirror
    gives its images their sources', ``Mirror.reflect_rows``, as tests/test_mirror.py
    checks through the rates.)"""
    pos, vel, rho, mass, kind, dx = scene(3, seed=7)
    h = 1.3 * dx
    g = np.array([0.0, 0.0, -9.81])
    grid = Grid.covering(pos.min(0) - 1e-9, pos.max(0) + 1e-9, 2 * h)
    perm, start, _ = sort_by_cell(pos, grid)
    args = (pos[perm], vel[perm], rho[perm], mass[perm], kind[perm], start, grid, 0,
            eq.params(h, alpha_d(0, 3, h), 0.1, 0.1, "fourtakas", RHO0, C0, g, nu=1e-3, xsph=0.3), RHO0, C0, GAMMA)
    skip = pos[perm, 1] < 2 * h  # a band as thick as an image band
    assert 0.1 * len(pos) < skip.sum() < 0.9 * len(pos)
    full = eq.evaluate(*args, np.empty(len(pos)))
    full = [a.copy() for a in (full.drho, full.acc, full.visc, full.xsph)]
    part = eq.evaluate(*args, np.empty(len(pos)), skip=skip)
    for a, b in zip(full, (part.drho, part.acc, part.visc, part.xsph)):
        assert np.array_equal(a[~skip], b[~skip]) and not b[skip].any()
        assert np.abs(a[skip]).max() > 0  # what the full pass gave them


@pytest.mark.parametrize("dim", [2, 3])
def test_boundary_particles_far_from_the_fluid_are_skipped_exactly(dim):
    """With the cells near the fluid given (fluid_near_cells, as the solver does), the
    boundary particles of the other cells get zero rates without a pass over their
    neighbours: every rate equals the full pass's, bit for bit."""
    pos, vel, rho, mass, kind, dx = scene(dim, seed=5)
    h = math.sqrt(2) * dx if dim == 2 else 1.3 * dx
    lo, hi = pos.min(0), pos.max(0)
    hi[-1] = lo[-1] + 6 * dx
    far = block(lo + np.r_[np.zeros(dim - 1), 0.2], hi + np.r_[np.zeros(dim - 1), 0.2], dx)  # a dry lid
    pos = np.concatenate([pos, far])
    kind = np.r_[kind, np.full(len(far), Kind.FIXED_WALL, np.int8)]
    vel = np.concatenate([vel, np.zeros_like(far)])
    rho, mass = np.r_[rho, np.full(len(far), RHO0)], np.r_[mass, np.full(len(far), mass[-1])]
    g = np.zeros(dim)
    g[-1] = -9.81
    grid = Grid.covering(pos.min(0) - 1e-9, pos.max(0) + 1e-9, 2 * h)
    perm, start, out = sort_by_cell(pos, grid)
    args = (pos[perm], vel[perm], rho[perm], mass[perm], kind[perm], start, grid, 0,
            eq.params(h, alpha_d(0, dim, h), 0.1, 0.1, "fourtakas", RHO0, C0, g, nu=1e-3, xsph=0.3), RHO0, C0, GAMMA)
    near = fluid_near_cells(kind[perm], start, grid)
    cell_of = np.searchsorted(start, np.arange(len(pos)), side="right") - 1
    skipped = near[cell_of] == 0
    assert skipped.sum() >= len(far) // 2 and (kind[perm][skipped] != Kind.FLUID).all()
    full = eq.evaluate(*args, np.empty(len(pos)))
    full = [a.copy() for a in (full.drho, full.acc, full.visc, full.xsph)]
    part = eq.evaluate(*args, np.empty(len(pos)), near=near)
    for a, b in zip(full, (part.drho, part.acc, part.visc, part.xsph)):
        assert np.array_equal(a, b)
    assert (np.abs(full[0][~skipped]) > 0).sum() > 100
    with pytest.raises(InputError, match="kind"):  # the walls are picked by kind
        eq.interact(np.zeros((eq.N_ROWS, 1)), start, np.zeros(1, np.uint16), np.zeros(3), 1.0, 1, 1, 1, 0,
                    args[8], np.zeros((2, 1)), np.zeros((1, dim)), np.zeros((0, dim)), np.zeros((3, 0)),
                    walls=eq.WALLS_CONTINUITY)
