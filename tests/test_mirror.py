"""A symmetry plane's mirror images (fluid.mirror): the half domain y >= 0 with its images
has the whole domain's rates and follows the whole domain's motion, for a state symmetric
about the plane (the invariant the method rests on)."""

import math

import numpy as np
import pytest

from errors import InputError
from fluid.geometry import assemble, block, set_hydrostatic, tank_walls
from fluid.mirror import Mirror
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig

DX, L, W, D = 0.025, 0.3, 0.3, 0.15


def _symmetric_tank(seed=0):
    """A 3-D tank across y = -W/2 .. W/2 whose water is perturbed symmetrically about y = 0:
    positions jittered by up to 0.15 dx, velocities and densities random, each particle at
    y < 0 the mirror image of one at y > 0 (velocity's y reversed)."""
    lo, hi = np.array([0.0, -W / 2, 0.0]), np.array([L, W / 2, D + 0.1])
    walls = tank_walls(lo, hi, DX, 4)
    ps = assemble(3, DX, 1000.0, block(lo, np.array([L, W / 2, D]), DX), [(walls, Kind.FIXED_WALL, 0)]).particles
    set_hydrostatic(ps, D, 1000.0, 20.0, 7.0, 9.81)
    rng = np.random.default_rng(seed)
    fl = np.flatnonzero((ps.kind == Kind.FLUID) & (ps.pos[:, 1] > 0))
    key = {tuple(np.round(p, 9)): i for i, p in enumerate(ps.pos)}
    twin = np.array([key[(round(p[0], 9), round(-p[1], 9), round(p[2], 9))] for p in ps.pos[fl]])
    ps.pos[fl] += rng.uniform(-0.15, 0.15, (fl.size, 3)) * DX
    ps.vel[fl] = rng.normal(0.0, 0.05, (fl.size, 3))
    ps.rho[fl] *= 1.0 + rng.uniform(-2e-3, 2e-3, fl.size)
    ps.pos[twin], ps.vel[twin], ps.rho[twin] = ps.pos[fl], ps.vel[fl], ps.rho[fl]
    ps.pos[twin, 1] *= -1.0
    ps.vel[twin, 1] *= -1.0
    return ps


def _pair(ps, **config):
    """The whole tank's fluid and its half y >= 0 with a symmetry plane at y = 0."""
    base = dict(dim=3, dx=DX, c0=20.0, h_coef=2.0, walls="adami", alpha=0.02, g=(1.5, 0.0, -9.81)) | config
    whole = Fluid(FluidConfig(**base), ps)
    half = Fluid(FluidConfig(**base, symmetry_y=0.0), ps.select(ps.pos[:, 1] > 0))
    return whole, half


def _matched(whole, half, values_whole, values_half):
    """Values of the half's simulated rows and of the same particles in the whole tank."""
    real = np.flatnonzero(half.ps.ids >= 0)
    at = np.argsort(whole.ps.ids)[half.ps.ids[real]]  # the whole tank's ids are 0..N-1
    return values_whole[at], values_half[real]


@pytest.mark.parametrize("diffusion", ["fourtakas", pytest.param("antuono", marks=pytest.mark.long)])
def test_the_half_with_its_images_has_the_whole_tanks_rates(diffusion):
    """Continuity and momentum rates of every particle of the half (fluid and walls, the
    Adami wall densities, the renormalised density gradients of Antuono's diffusion) equal
    the whole tank's to round-off, on a jittered state with no lattice symmetry besides y."""
    whole, half = _pair(_symmetric_tank(), diffusion=diffusion)
    whole.initialize(0.0)
    half.initialize(0.0)
    assert half.mirror.rows.size > 0 and (half.ps.ids < 0).sum() == half.mirror.rows.size
    for a, b, scale in ((whole._drho, half._drho, np.abs(whole._drho).max()),
                        (whole._acc, half._acc, np.abs(whole._acc).max())):
        wa, ha = _matched(whole, half, a, b)
        np.testing.assert_allclose(ha, wa, rtol=0, atol=1e-10 * scale)
    assert half.max_dt() == pytest.approx(whole.max_dt(), rel=1e-9)


@pytest.mark.long
@pytest.mark.parametrize("integrator", ["symplectic", "verlet"])
def test_the_half_follows_the_whole_tank(integrator):
    """0.1 s of sloshing under a tilted gravity, the density re-initialised every 20 steps:
    the half's particles stay where the whole tank's go (to 1e-9 m; rounding alone parts
    them), none crosses the plane, and the half holds half the fluid particles."""
    whole, half = _pair(_symmetric_tank(1), integrator=integrator, mls_every=20)
    for f in (whole, half):
        f.initialize(0.0)
        t = 0.0
        for _ in range(10):
            f.advance(t, 0.01)
            t += 0.01
    assert whole.counters.steps == half.counters.steps > 100
    wp, hp = _matched(whole, half, whole.ps.pos, half.ps.pos)
    np.testing.assert_allclose(hp, wp, rtol=0, atol=1e-9)
    start = _symmetric_tank(1).pos  # row i is id i
    assert np.abs(whole.ps.pos - start[whole.ps.ids]).max() > 0.1 * DX  # the water did slosh
    real = half.ps.ids >= 0
    assert (half.ps.pos[real, 1] >= 0).all() and (half.ps.pos[~real, 1] < 0).all()
    n_fluid = lambda f: int((f.simulated().kind == Kind.FLUID).sum())
    assert 2 * n_fluid(half) == n_fluid(whole)
    assert half.kinetic_energy() == pytest.approx(0.5 * whole.kinetic_energy(), rel=1e-9)
    assert half.simulated().n == int(real.sum())


def test_a_particle_that_crosses_the_plane_is_reflected_back():
    from fluid.particles import ParticleSet
    ps = ParticleSet.create(np.array([[0.0, -0.002, 0.0], [0.1, 0.01, 0.0]]), 1000.0, 1.0,
                            vel=np.array([[0.0, -0.5, 0.0], [0.0, 0.0, 0.0]]))
    aux = {"pos": ps.pos.copy(), "vel": ps.vel.copy()}
    Mirror(0.0, 0.05, 0.01).reflect_crossing(ps, aux)
    np.testing.assert_allclose(ps.pos[0], [0.0, 0.002, 0.0])
    np.testing.assert_allclose(ps.vel[0], [0.0, 0.5, 0.0])
    np.testing.assert_allclose(aux["pos"][0], [0.0, 0.002, 0.0])
    np.testing.assert_allclose(ps.pos[1], [0.1, 0.01, 0.0])


def test_a_symmetry_plane_is_refused_where_it_cannot_hold():
    with pytest.raises(InputError, match="symmetry_y"):
        FluidConfig(dim=2, dx=0.01, c0=10.0, symmetry_y=0.0)
    with pytest.raises(InputError, match="symmetry_y"):
        FluidConfig(dim=3, dx=0.01, c0=10.0, symmetry_y=math.nan)
    ps = _symmetric_tank()
    with pytest.raises(InputError, match="beyond the symmetry plane y = 0 m: give only the half y >= it"):
        Fluid(FluidConfig(dim=3, dx=DX, c0=20.0, symmetry_y=0.0), ps)


def test_a_saved_state_with_images_continues_bit_for_bit():
    _, half = _pair(_symmetric_tank(2))
    half.initialize(0.0)
    half.advance(0.0, 0.005)
    state = half.save_state()
    half.advance(0.005, 0.005)
    first = half.ps.pos.copy(), half.mirror.rows.copy()
    half.load_state(state)
    half.advance(0.005, 0.005)
    np.testing.assert_array_equal(half.ps.pos, first[0])
    np.testing.assert_array_equal(half.mirror.rows, first[1])


WS = 6 * DX  #: the slice's width between its two planes: more than the kernel's support 2h = 4 dx


def _slice_and_copies(seed=3):
    """A jittered 3-D slice y = 0 .. WS (floor and end walls across it only, no side walls)
    and the same slice with its mirror copies across y = 0 and y = WS laid out explicitly
    (y = -WS .. 2 WS): (slice's particles, copies' particles)."""
    t = 4 * DX
    walls = np.concatenate([block((-t, 0.0, -t), (L + t, WS, 0.0), DX),  # floor, under the end walls too
                            block((-t, 0.0, 0.0), (0.0, WS, D + 0.1), DX),
                            block((L, 0.0, 0.0), (L + t, WS, D + 0.1), DX)])
    ps = assemble(3, DX, 1000.0, block((0.0, 0.0, 0.0), (L, WS, D), DX), [(walls, Kind.FIXED_WALL, 0)]).particles
    set_hydrostatic(ps, D, 1000.0, 20.0, 7.0, 9.81)
    rng = np.random.default_rng(seed)
    fl = np.flatnonzero(ps.kind == Kind.FLUID)
    ps.pos[fl] += rng.uniform(-0.15, 0.15, (fl.size, 3)) * DX
    ps.pos[fl, 1] = np.clip(ps.pos[fl, 1], 1e-3 * DX, WS - 1e-3 * DX)
    ps.vel[fl] = rng.normal(0.0, 0.05, (fl.size, 3))
    ps.rho[fl] *= 1.0 + rng.uniform(-2e-3, 2e-3, fl.size)
    from fluid.particles import ParticleSet
    parts = []
    for plane in (None, 0.0, WS):  # the slice first: its rows keep ids 0..N-1
        pos, vel = ps.pos.copy(), ps.vel.copy()
        if plane is not None:
            pos[:, 1] = 2.0 * plane - pos[:, 1]
            vel[:, 1] *= -1.0
        parts.append((pos, vel))
    whole = ParticleSet.create(np.concatenate([p for p, _ in parts]), np.tile(ps.rho, 3), np.tile(ps.mass, 3),
                               kind=np.tile(ps.kind, 3), group=np.tile(ps.group, 3),
                               vel=np.concatenate([v for _, v in parts]))
    return ps, whole


def test_a_slice_between_two_planes_has_the_rates_of_its_mirrored_copies():
    """The slice y = 0 .. WS with symmetry planes at both sides (symmetry_y, symmetry_y_hi)
    gives every one of its particles (fluid and walls) the continuity and momentum rates
    that the same particles have beside their mirror copies laid out explicitly, to
    round-off: what a flow symmetric about both planes (uniform across y) has."""
    ps, whole_ps = _slice_and_copies()
    base = dict(dim=3, dx=DX, c0=20.0, h_coef=2.0, walls="adami", alpha=0.02, g=(1.5, 0.0, -9.81))
    whole = Fluid(FluidConfig(**base), whole_ps)
    part = Fluid(FluidConfig(**base, symmetry_y=0.0, symmetry_y_hi=WS), ps)
    whole.initialize(0.0)
    part.initialize(0.0)
    images = part.ps.pos[part.ps.ids < 0, 1]
    assert (images < 0).any() and (images > WS).any()  # both planes made images
    n = ps.n
    for a, b in ((whole._drho, part._drho), (whole._acc, part._acc)):
        real = np.flatnonzero(part.ps.ids >= 0)
        at = np.argsort(whole.ps.ids)[part.ps.ids[real]]  # the copies' ids follow the slice's
        assert (whole.ps.ids[at] < n).all()
        np.testing.assert_allclose(b[real], a[at], rtol=0, atol=1e-10 * np.abs(a[at]).max())


def test_a_particle_that_crosses_the_upper_plane_is_reflected_back():
    from fluid.particles import ParticleSet
    ps = ParticleSet.create(np.array([[0.0, 0.107, 0.0], [0.1, 0.05, 0.0]]), 1000.0, 1.0,
                            vel=np.array([[0.0, 0.5, 0.0], [0.0, 0.0, 0.0]]))
    aux = {"pos": ps.pos.copy(), "vel": ps.vel.copy()}
    Mirror(0.0, 0.05, 0.01, 0.1).reflect_crossing(ps, aux)
    np.testing.assert_allclose(ps.pos[0], [0.0, 0.093, 0.0])
    np.testing.assert_allclose(ps.vel[0], [0.0, -0.5, 0.0])
    np.testing.assert_allclose(aux["pos"][0], [0.0, 0.093, 0.0])
    np.testing.assert_allclose(ps.pos[1], [0.1, 0.05, 0.0])


def test_a_slice_between_two_planes_is_refused_where_it_cannot_hold():
    with pytest.raises(InputError, match="symmetry_y_hi=0.2 m without symmetry_y"):
        FluidConfig(dim=3, dx=0.01, c0=10.0, symmetry_y_hi=0.2)
    with pytest.raises(InputError, match=r"symmetry_y_hi=0.03 m.*at least the kernel's support 2h = 0.04 m"):
        FluidConfig(dim=3, dx=0.01, c0=10.0, h_coef=2.0, symmetry_y=0.0, symmetry_y_hi=0.03)
    ps, _ = _slice_and_copies()
    with pytest.raises(InputError,
                       match=r"beyond the symmetry plane y = 0.1 m: give only the slice between the planes "
                             r"\(symmetry_y_hi\)"):
        Fluid(FluidConfig(dim=3, dx=DX, c0=20.0, symmetry_y=0.0, symmetry_y_hi=0.1), ps)
