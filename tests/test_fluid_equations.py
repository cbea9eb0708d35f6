"""Rates of the WCSPH equations against analytic fields and pair invariants."""

import math

import numpy as np
import pytest

from fluid import equations as eq
from fluid.geometry import block
from fluid.kernels import alpha_d, kernel_id
from fluid.neighbours import Grid, sort_by_cell
from fluid.particles import Kind, ParticleSet
from fluid.solver import Fluid, FluidConfig

RHO0, C0, GAMMA = 1000.0, 20.0, 7.0


def rates(pos, vel, rho, kind=None, h_coef=math.sqrt(2), dx=0.01, g=(0.0, 0.0), diffusion="none",
          alpha=0.0, kernel="wendland", delta=0.1, c0=C0):
    """Evaluate continuity and momentum rates on a given particle set (caller's order)."""
    n, dim = pos.shape
    kind = np.zeros(n, np.int8) if kind is None else np.asarray(kind, np.int8)
    h = h_coef * dx
    grid = Grid.covering(pos.min(0) - 1e-9, pos.max(0) + 1e-9, 2 * h)
    perm, start, out = sort_by_cell(pos, grid)
    assert out == 0
    P, V, R, K = pos[perm], vel[perm], rho[perm], kind[perm]
    m = np.full(n, RHO0 * dx**dim)
    p = np.empty(n)
    k = kernel_id(kernel)
    prm = eq.params(h, alpha_d(k, dim, h), alpha, delta, diffusion, RHO0, c0, np.asarray(g, float))
    drho, acc, visc, cs, _ = eq.evaluate(P, V, R, m, K, start, grid, k, prm, RHO0, c0, GAMMA, p)
    inv = np.empty(n, np.int64)
    inv[perm] = np.arange(n)
    return drho[inv], acc[inv], visc[inv], p[inv]


def test_tait_equation_of_state():
    rho = np.array([RHO0, 1.01 * RHO0, 0.99 * RHO0])
    p, cs = np.empty(3), np.empty(3)
    eq.equation_of_state(rho, RHO0, C0, GAMMA, p, cs)
    S = np.empty((eq.N_ROWS, 3))
    p2 = np.empty(3)
    eq.pack(np.zeros((3, 2)), np.zeros((3, 2)), rho, np.ones(3), np.zeros(3, np.int8), RHO0, C0, GAMMA, p2, S)
    assert np.array_equal(p, p2) and np.array_equal(cs, S[eq.CS])
    B = C0**2 * RHO0 / GAMMA
    np.testing.assert_allclose(p, B * ((rho / RHO0) ** 7 - 1), rtol=1e-12, atol=1e-9)
    assert p[0] == 0.0 and cs[0] == C0
    # the hydrostatic density gives back rho0 g depth through the EOS
    depth = np.array([0.0, 0.1, 1.0])
    r = eq.hydrostatic_density(depth, RHO0, C0, GAMMA, 9.81)
    eq.equation_of_state(r, RHO0, C0, GAMMA, p, cs)
    np.testing.assert_allclose(p, RHO0 * 9.81 * depth, rtol=1e-10, atol=1e-9)


def interior(pos, lo, hi, margin):
    return np.all((pos > lo + margin) & (pos < hi - margin), axis=1)


@pytest.mark.parametrize("dim", [2, 3])
def test_uniform_motion_has_no_rates(dim):
    dx = 0.01
    pos = block(np.zeros(dim), np.full(dim, 0.1 if dim == 2 else 0.06), dx)
    vel = np.tile(np.arange(1.0, dim + 1), (len(pos), 1))
    drho, acc, visc, _ = rates(pos, vel, np.full(len(pos), RHO0), dx=dx, diffusion="fourtakas", alpha=0.1)
    assert np.abs(drho).max() < 1e-9 and np.abs(acc).max() < 1e-9 and np.abs(visc).max() < 1e-12


@pytest.mark.parametrize("kernel", ["wendland", "cubic"])
@pytest.mark.parametrize("dim", [2, 3])
def test_continuity_gives_divergence_of_a_linear_field(dim, kernel):
    """Eq. 7 for v = beta x: drho/dt = -rho div v = -dim beta rho in the interior, up to the
    lattice quadrature error of the kernel (< 2 % at h = 2 dx)."""
    dx, L = 0.01, (0.12 if dim == 2 else 0.1)
    pos = block(np.zeros(dim), np.full(dim, L), dx)
    beta = 0.3
    drho, *_ = rates(pos, beta * pos, np.full(len(pos), RHO0), dx=dx, h_coef=2.0, kernel=kernel)
    ins = interior(pos, 0, L, 2.0 * 2 * dx)
    assert ins.sum() > 4
    np.testing.assert_allclose(drho[ins], -dim * beta * RHO0, rtol=0.02)


@pytest.mark.parametrize("dim", [2, 3])
def test_pressure_gradient_balances_gravity_in_hydrostatic_field(dim):
    """Eq. 6 with a hydrostatic density field: -grad p / rho + g ~ 0 in the interior, to the
    lattice quadrature error of the Wendland kernel at h = 2 dx (0.1 %). c0 is large here so
    that the compressibility terms of the symmetric form (of order p / (rho c0^2)) stay
    below 1e-3; at c0 = 20 m/s they reach 1 % at this depth."""
    c0 = 200.0
    dx, L = 0.01, (0.16 if dim == 2 else 0.1)
    g = np.zeros(dim)
    g[-1] = -9.81
    pos = block(np.zeros(dim), np.full(dim, L), dx)
    rho = eq.hydrostatic_density(L - pos[:, -1], RHO0, c0, GAMMA, 9.81)
    drho, acc, _, p = rates(pos, np.zeros_like(pos), rho, dx=dx, h_coef=2.0, g=g, diffusion="fourtakas", c0=c0)
    ins = interior(pos, 0, L, 2.0 * 2 * dx)
    assert np.abs(acc[ins]).max() < 0.002 * 9.81


def test_fourtakas_diffusion_vanishes_at_the_free_surface_where_molteni_does_not():
    """A fluid at rest in its hydrostatic state. (c0 is large so that the incompressible
    hydrostatic field used here, p = rho0 g depth, and the compressed one differ by < 1e-3.)"""
    dx, L, c0 = 0.01, 0.12, 200.0
    pos = block(np.zeros(2), np.full(2, L), dx)
    rho = eq.hydrostatic_density(L - pos[:, -1], RHO0, c0, GAMMA, 9.81)
    g = np.array([0.0, -9.81])
    d_f, *_ = rates(pos, np.zeros_like(pos), rho, dx=dx, g=g, diffusion="fourtakas", c0=c0)
    d_m, *_ = rates(pos, np.zeros_like(pos), rho, dx=dx, g=g, diffusion="molteni", c0=c0)
    top = pos[:, 1] > L - dx
    # Molteni-Colagrossi: a spurious rate at the surface (one-sided support) ...
    assert np.abs(d_m[top]).mean() > 0.1
    # ... which Fourtakas' hydrostatic correction removes to the linearisation error
    assert np.abs(d_f).max() < 1e-3 * np.abs(d_m[top]).mean()


@pytest.mark.parametrize("dim", [2, pytest.param(3, marks=pytest.mark.long)])
def test_antuono_diffusion_vanishes_for_any_linear_density_field_where_the_others_do_not(dim):
    """Dinçer & Demir 2020, Eq. 1-4 on a disordered set at rest under gravity, with a
    density field linear in every direction (not the hydrostatic one): the renormalised
    gradients are exact, so the diffusion vanishes to round-off wherever the
    renormalisation holds (here: every particle with a full support); Molteni's term
    does not, nor Fourtakas' (which removes only the hydrostatic gradient)."""
    rng = np.random.default_rng(7)
    dx = 0.01
    pos = block(np.zeros(dim), np.full(dim, 0.1), dx)
    pos = pos + rng.uniform(-0.2 * dx, 0.2 * dx, pos.shape)
    slope = np.array([3.0, -2.0, 5.0])[-dim:]  # [kg/m^4]
    rho = RHO0 + pos @ slope
    g = np.zeros(dim)
    g[-1] = -9.81
    kw = dict(dx=dx, h_coef=1.3 if dim == 3 else math.sqrt(2), delta=0.1, g=g)
    d = {k: rates(pos, np.zeros_like(pos), rho, diffusion=k, **kw)[0] for k in ("antuono", "molteni", "fourtakas")}
    inner = (np.abs(pos - pos.mean(0)) < np.ptp(pos, axis=0) / 2 - 3 * dx).all(axis=1)
    assert inner.sum() >= 8
    plain = min(np.abs(d["molteni"][inner]).mean(), np.abs(d["fourtakas"][inner]).mean())
    assert plain > 0.1  # [kg/m^3/s]
    assert np.abs(d["antuono"][inner]).max() < 1e-9 * plain


@pytest.mark.parametrize("dim", [2, 3])
def test_diffusion_fades_under_the_free_surface_only(dim):
    """diffusion_at_surface=False (fluid.equations docstring): in a walled tank on the
    lattice, the two rows under the free surface take no diffusion (in 3-D the row's four
    corner particles, s = 0.049 with the walls above the water, keep 4 % of it); every
    other fluid particle, those beside the walls included (walls count as support), takes
    all of it."""
    from fluid.geometry import tank_with_water

    dx, L, H = 0.01, 0.08, 0.07
    ps = tank_with_water(dim, dx, L, H, H + 2 * dx, width=0.06).particles
    rng = np.random.default_rng(3)
    rho = RHO0 * (1 + 1e-3 * rng.uniform(-1, 1, ps.n))  # a density field the diffusion acts on
    fluid = ps.kind == Kind.FLUID

    def drho(diffusion="molteni", at_surface=True):
        n = ps.n
        h = math.sqrt(2) * dx
        grid = Grid.covering(ps.pos.min(0) - 1e-9, ps.pos.max(0) + 1e-9, 2 * h)
        perm, start, _ = sort_by_cell(ps.pos, grid)
        k = kernel_id("wendland")
        prm = eq.params(h, alpha_d(k, dim, h), 0.0, 0.1, diffusion, RHO0, C0, np.zeros(dim),
                        diffusion_at_surface=at_surface)
        r = eq.evaluate(ps.pos[perm], np.zeros((n, dim)), rho[perm], ps.mass[perm], ps.kind[perm], start,
                        grid, k, prm, RHO0, C0, GAMMA, np.empty(n)).drho
        out = np.empty(n)
        out[perm] = r
        return out

    faded, full, none = drho(at_surface=False), drho(), drho("none")
    top = fluid & (ps.pos[:, -1] > H - 2 * dx)
    rest = fluid & ~top
    scale = np.abs(full - none)[fluid].mean()
    assert scale > 1.0  # [kg/m^3/s]
    assert (np.abs(faded - none)[top] <= 0.05 * np.abs(full - none)[top] + 1e-9 * scale).all()
    assert (faded[top] == none[top]).mean() > (0.9 if dim == 2 else 0.8)
    np.testing.assert_allclose(faded[rest], full[rest], rtol=0, atol=1e-9 * scale)
    beside = rest & ((ps.pos[:, 0] < dx) | (ps.pos[:, 0] > L - dx))  # beside a wall
    assert beside.sum() >= 4 and np.abs(full - none)[beside].min() > 1e-3 * scale


def test_artificial_viscosity_acts_only_on_approaching_pairs():
    dx = 0.01
    pos = np.array([[0.0, 0.0], [0.012, 0.0]])
    rho = np.full(2, RHO0)
    for sign, expect in ((-1, True), (1, False)):
        vel = np.array([[-sign * 0.5, 0.0], [sign * 0.5, 0.0]])  # sign -1: approaching
        _, acc, visc, _ = rates(pos, vel, rho, dx=dx, alpha=0.1)
        if expect:
            assert acc[0, 0] < 0 and acc[1, 0] > 0  # pushed apart
            np.testing.assert_allclose(acc[0], -acc[1], rtol=1e-14)
        else:
            assert np.abs(acc).max() == 0
        h = math.sqrt(2) * dx
        np.testing.assert_allclose(visc, h * 1.0 * 0.012 / (0.012**2 + 0.01 * h * h), rtol=1e-12)


def random_scene(dim, seed=0):
    """A fluid blob with random velocities and densities next to two wall groups."""
    rng = np.random.default_rng(seed)
    dx = 0.01
    L = 0.1 if dim == 2 else 0.05
    fl = block(np.zeros(dim), np.full(dim, L), dx) + rng.normal(0, 0.05 * dx, (1, dim))
    fl = fl + rng.normal(0, 0.1 * dx, fl.shape)
    lo = np.zeros(dim)
    lo[-1] = -0.03
    hi = np.full(dim, L)
    hi[-1] = 0.0
    floor = block(lo, hi, dx)
    lo2 = np.zeros(dim)
    lo2[0] = L
    hi2 = np.full(dim, L)
    hi2[0] = L + 0.03
    side = block(lo2, hi2, dx)
    pos = np.concatenate([fl, floor, side])
    kind = np.r_[np.zeros(len(fl)), np.full(len(floor), Kind.FIXED_WALL), np.full(len(side), Kind.BODY)]
    group = np.r_[np.full(len(fl), -1), np.zeros(len(floor)), np.ones(len(side))]
    vel = np.zeros_like(pos)
    vel[: len(fl)] = rng.normal(0, 0.3, (len(fl), dim))
    vel[len(fl) + len(floor):, 0] = -0.2  # the body moves
    rho = RHO0 * (1 + rng.uniform(-0.005, 0.01, len(pos)))
    ps = ParticleSet.create(pos, rho, RHO0 * dx**dim, kind=kind, group=group, vel=vel)
    return ps, dx


@pytest.mark.parametrize("dim", [2, 3])
def test_group_forces_are_the_exact_reaction_of_the_fluid(dim):
    """Pair antisymmetry: what the walls exert on the fluid is minus what the fluid exerts
    on the walls, summed over groups, to round-off."""
    ps, dx = random_scene(dim)
    f = Fluid(FluidConfig(dim=dim, dx=dx, c0=C0, alpha=0.1), ps)
    f.initialize(0.0)
    F, M = f.group_forces_now()
    on_fluid = f.fluid_force_from_groups()
    assert np.abs(F).max() > 1e-3  # a real load, not a trivial zero
    scale = np.abs(F).max()
    np.testing.assert_allclose(F.sum(axis=0), -on_fluid, rtol=0, atol=1e-11 * scale)
    # pair forces are central, so the moments cancel too, about any point
    c = np.array([0.3, -0.2, 0.1][:dim])
    f.moment_points[:] = c
    F, M = f.group_forces_now()
    fl = f.ps.kind == Kind.FLUID
    fa = f.ps.mass[fl, None] * (f._acc[fl] - f.config.gravity)
    r = f.ps.pos[fl] - c
    m_fluid = (r[:, 1] * fa[:, 0] - r[:, 0] * fa[:, 1]).sum() if dim == 2 else np.cross(r, fa).sum(axis=0)
    assert np.abs(M).max() > 1e-4
    np.testing.assert_allclose(M.sum(axis=0), -np.atleast_1d(m_fluid), rtol=0, atol=1e-11 * np.abs(M).max())


@pytest.mark.parametrize("dim", [2, 3])
def test_the_boundarys_power_less_its_compression_work_is_what_the_fluid_gains(dim):
    """Energy of the pair terms without viscosity or density diffusion: the fluid's kinetic
    and internal energy (de_a/dt = p_a / rho_a^2 drho_a/dt) gain the power the boundary
    particles put in (-F_b . v_b) less boundary_compression_power_now, to round-off; the
    fluid's own pairs exchange energy without loss."""
    ps, dx = random_scene(dim)
    ps.vel[ps.kind == Kind.FIXED_WALL, -1] = 0.1  # the walls move too: every boundary row does work
    f = Fluid(FluidConfig(dim=dim, dx=dx, c0=C0, alpha=0.0, delta=0.0, g=0.0), ps)
    f.initialize(0.0)
    fl = f.ps.kind == Kind.FLUID
    m, v, rho, p = f.ps.mass, f.ps.vel, f.ps.rho, f.ps.p
    gained = (m[fl] * (v[fl] * f._acc[fl]).sum(axis=1)).sum() + (m[fl] * p[fl] / rho[fl] ** 2 * f._drho[fl]).sum()
    put_in = -(f.boundary_forces_now()[~fl] * v[~fl]).sum()
    leak = f.boundary_compression_power_now()
    assert (leak[fl] == 0).all()
    assert abs(leak.sum()) > 1e-3 * abs(put_in)  # a real term, not a zero
    scale = (m[fl] * np.abs(v[fl] * f._acc[fl]).sum(axis=1)).sum()
    assert gained == pytest.approx(put_in - leak.sum(), abs=1e-10 * scale)


def test_fluid_momentum_is_conserved_without_walls():
    """Without walls and gravity the pair forces cancel: the fluid's momentum rate is zero."""
    ps, dx = random_scene(2, seed=3)
    fl = ps.select(ps.kind == Kind.FLUID)
    f = Fluid(FluidConfig(dim=2, dx=dx, c0=C0, alpha=0.1, g=0.0), fl)
    f.initialize(0.0)
    rate = (f.ps.mass[:, None] * f._acc).sum(axis=0)
    scale = (f.ps.mass[:, None] * np.abs(f._acc)).sum()
    assert scale > 1e-3
    assert np.abs(rate).max() < 1e-13 * scale
