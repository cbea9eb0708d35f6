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
    with pytest.raises(InputError, match="beyond the symmetry plane"):
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
