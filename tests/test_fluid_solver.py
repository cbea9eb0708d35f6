"""The Fluid participant: configuration checks, time stepping, guards, state round trip."""

import math

import numpy as np
import pytest

from cosim.errors import InputError, InstabilityError
from cosim.protocol import Participant, check_participant
from fluid import equations as eq
from fluid.geometry import set_hydrostatic, tank_with_water
from fluid.integrator import first_non_finite, stable_dt
from fluid.particles import Kind, ParticleSet
from fluid.solver import Fluid, FluidConfig


@pytest.mark.parametrize("bad, word", [
    (dict(cfl=0.6), "cfl"),
    (dict(cfl=0.0), "cfl"),
    (dict(c0=30.0, u_max=1.0), "exactly one"),
    (dict(c0=None, u_max=None), "exactly one"),
    (dict(c0=None, u_max=1.0, c0_factor=5.0), "c0_factor"),
    (dict(dx=-0.01), "dx"),
    (dict(dim=4), "dim"),
    (dict(kernel="gauss"), "kernel"),
    (dict(diffusion="adami"), "diffusion"),
    (dict(alpha=-0.1), "alpha"),
    (dict(alpha_wall=1.5), "alpha_wall"),
    (dict(diffusion_at_surface="no"), "diffusion_at_surface"),
    (dict(integrator="euler"), "integrator"),
    (dict(domain_lo=(0.0, 0.0)), "domain"),
    (dict(precision="float16"), "precision"),
])
def test_bad_configuration_is_refused_with_the_reason(bad, word):
    args = dict(c0=30.0)
    args.update(bad)
    with pytest.raises(InputError, match=word):
        FluidConfig(**args)


def test_c0_from_expected_speed():
    assert FluidConfig(u_max=2.0).speed_of_sound == 20.0
    assert FluidConfig(u_max=2.0, c0_factor=15).speed_of_sound == 30.0


def one_particle(dim=2, vel=None):
    pos = np.zeros((1, dim))
    return ParticleSet.create(pos, 1000.0, 0.1, vel=vel)


def test_is_a_participant():
    f = Fluid(FluidConfig(c0=30.0), one_particle())
    check_participant(f, Participant)
    assert isinstance(f, Participant) and f.name == "fluid"


@pytest.mark.parametrize("integrator", ["symplectic", "verlet"])
@pytest.mark.parametrize("dim", [2, 3])
def test_free_fall_is_exact_and_time_is_reached_exactly(dim, integrator):
    """A lone particle has no neighbours: both schemes integrate constant gravity exactly,
    whatever the sub-steps."""
    v0 = np.zeros(dim)
    v0[0] = 0.5
    cfg = FluidConfig(dim=dim, c0=30.0, domain_lo=(-1.0,) * dim, domain_hi=(1.0,) * dim,
                      integrator=integrator, verlet_reset=7)
    f = Fluid(cfg, one_particle(dim, v0))
    f.initialize(0.0)
    assert f.limit.limiter == "courant_viscous"
    np.testing.assert_allclose(f.max_dt(), 0.2 * cfg.h / 30.0, rtol=1e-12)
    t = 0.0
    # Verlet's leap-frog velocity update is exact only for equal steps: give it whole
    # multiples of its (here constant) stable step; the symplectic scheme takes any
    steps = (0.01, 0.037, 0.003) if integrator == "symplectic" else tuple(k * f.max_dt() for k in (9, 40, 3))
    for dt in steps:
        f.advance(t, dt)
        t += dt
    assert f.t == t
    assert f.counters.steps > 3
    z = f.ps.pos[0, -1]
    np.testing.assert_allclose(z, -0.5 * 9.81 * t * t, rtol=1e-12)
    np.testing.assert_allclose(f.ps.pos[0, 0], 0.5 * t, rtol=1e-12)
    np.testing.assert_allclose(f.ps.vel[0, -1], -9.81 * t, rtol=1e-12)


def test_step_limit_reports_its_condition():
    h, cfl = 0.014, 0.2
    kind = np.zeros(3, np.int8)
    cs = np.full(3, 30.0)
    acc = np.zeros((3, 2))
    visc = np.array([0.0, 2.0, 1.0])
    lim = stable_dt(acc, visc, cs, kind, h, cfl)
    assert lim.limiter == "courant_viscous"
    np.testing.assert_allclose(lim.dt, cfl * h / 32.0, rtol=1e-14)
    acc[1] = (0.0, 1e6)
    lim = stable_dt(acc, visc, cs, kind, h, cfl)
    assert lim.limiter == "force"
    np.testing.assert_allclose(lim.dt, cfl * math.sqrt(h / 1e6), rtol=1e-14)
    assert stable_dt(acc, visc, cs, kind, h, cfl, dt_max=1e-7).limiter == "dt_max"


def test_coupling_step_shorter_than_stable_step_is_reported():
    f = Fluid(FluidConfig(c0=30.0, domain_lo=(-1, -1), domain_hi=(1, 1)), one_particle())
    f.initialize(0.0)
    f.advance(0.0, 0.1 * f.max_dt())
    assert f.limiter == "coupling" and f.counters.steps == 1
    f.advance(f.t, 3.5 * f.max_dt())
    assert f.limiter == "courant_viscous" and f.counters.steps == 5


def small_tank(dx=0.02):
    b = tank_with_water(2, dx, 0.2, 0.1, 0.14)
    cfg = FluidConfig(dx=dx, u_max=1.0, c0_factor=20)
    set_hydrostatic(b.particles, 0.1, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    return cfg, b.particles


def test_nan_stops_the_run_naming_the_particle():
    cfg, ps = small_tank()
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    i = int(np.flatnonzero(f.ps.kind == Kind.FLUID)[7])
    pid = int(f.ps.ids[i])
    f.ps.vel[i, 0] = np.nan
    with pytest.raises(InstabilityError, match=rf"step \d+, t=.*particle id {pid} \(kind FLUID\) at \[") as e:
        f.advance(0.0, 0.01)
    assert "Remedies" in str(e.value)


def test_the_nan_check_finds_the_lowest_bad_row():
    """The run's message names the first bad particle (the CUDA path's kernel finds the same)."""
    rng = np.random.default_rng(3)
    pos, vel, rho = rng.random((20_001, 3)), rng.random((20_001, 3)), rng.random(20_001)
    assert first_non_finite(pos, vel, rho) == -1
    vel[15_000, 2] = np.inf
    rho[12_345] = np.nan
    pos[19_999, 0] = -np.inf
    assert first_non_finite(pos, vel, rho) == 12_345


def test_removals_are_counted_and_told_when_the_total_doubles(caplog):
    """One splash particle a step for 100 steps: 100 counted, 7 warnings (totals 1, 2, 4,
    ..., 64), not 100; then 29 at once pass 128: the eighth."""
    from fluid.solver import _Counters

    c = _Counters()
    with caplog.at_level("WARNING", logger="fluid.solver"):
        for k in range(100):
            c.count_removed(np.array([int(Kind.FLUID)]), 0.001 * k)
        c.count_removed(np.array([int(Kind.FLUID)] * 28 + [int(Kind.FIXED_WALL)]), 0.2)
    assert c.removed["FLUID"] == 128 and c.removed["FIXED_WALL"] == 1
    told = [r.getMessage() for r in caplog.records if "left the domain" in r.getMessage()]
    assert len(told) == 8 and "'FLUID': 64," in told[6] and "29 particles" in told[7] and "'FLUID': 128," in told[7]


def test_particles_leaving_the_domain_are_removed_and_counted():
    cfg, ps = small_tank()
    # a droplet well above the surface, thrown upwards out of the domain
    drop = ParticleSet.create([[0.1, 0.2]], 1000.0, ps.mass[0], vel=[[0.0, 5.0]])
    ps = ParticleSet.concatenate([ps, drop])
    f = Fluid(FluidConfig(dx=cfg.dx, c0=30.0, domain_lo=(-0.1, -0.1), domain_hi=(0.3, 0.25)), ps)
    f.initialize(0.0)
    n0 = f.ps.n
    f.advance(0.0, 0.03)
    assert f.counters.removed["FLUID"] == 1 and f.ps.n == n0 - 1
    assert ps.n - 1 not in f.ps.ids
    f.advance(0.03, 0.01)  # and the run goes on


@pytest.mark.parametrize("integrator", ["symplectic", "verlet"])
def test_save_and_load_state_repeat_a_run_exactly(integrator):
    cfg, ps = small_tank()
    f = Fluid(FluidConfig(dx=cfg.dx, u_max=1.0, c0_factor=20, integrator=integrator), ps)
    f.initialize(0.0)
    f.advance(0.0, 0.01)
    s = f.save_state()
    f.advance(0.01, 0.01)
    a = f.ps.copy()
    f.load_state(s)
    assert f.t == 0.01
    f.advance(0.01, 0.01)
    o1, o2 = np.argsort(a.ids), np.argsort(f.ps.ids)
    assert np.array_equal(a.pos[o1], f.ps.pos[o2]) and np.array_equal(a.rho[o1], f.ps.rho[o2])


def test_wall_load_of_fluid_at_rest_is_its_weight():
    """The time-averaged force of the fluid on its tank equals the fluid's weight (2 %,
    the short run still carries the start-up pressure waves)."""
    cfg, ps = small_tank()
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    t, F = 0.0, []
    for _ in range(10):
        f.advance(t, 0.02)
        t += 0.02
        F.append(f.group_loads()[0][0])
    F = np.mean(F, axis=0)
    weight = f.ps.mass[f.ps.kind == Kind.FLUID].sum() * cfg.g
    assert abs(F[0]) < 1e-9 * weight
    np.testing.assert_allclose(F[1], -weight, rtol=0.02)


def test_wall_pressure_is_the_inverse_distance_average_of_the_fluid():
    """Sunara et al. 2021, Eq. 15 on a hand-made set: one wall particle, two fluid particles at distances
    d1, d2 with pressures p1, p2 -> (p1/d1 + p2/d2) / (1/d1 + 1/d2); fluid keep their own."""
    from fluid import equations as eq

    dx = 0.01
    pos = np.array([[0.0, 0.0], [0.01, 0.0], [0.0, 0.02], [0.5, 0.5]])
    kind = np.array([Kind.FIXED_WALL, Kind.FLUID, Kind.FLUID, Kind.FIXED_WALL])
    rho = np.array([1000.0, 1001.0, 1003.0, 1000.0])
    ps = ParticleSet.create(pos, rho, 0.1, kind=kind, group=[0, -1, -1, 0])
    f = Fluid(FluidConfig(dx=dx, c0=30.0, domain_lo=(-0.1, -0.1), domain_hi=(1.0, 1.0)), ps)
    f.initialize(0.0)
    pw = f.wall_pressure()
    p = f.ps.p
    o = np.argsort(f.ps.ids)
    p, pw = p[o], pw[o]
    assert pw[1] == p[1] and pw[2] == p[2]
    np.testing.assert_allclose(pw[0], (p[1] / 0.01 + p[2] / 0.02) / (1 / 0.01 + 1 / 0.02), rtol=1e-12)
    assert pw[3] == 0.0  # no fluid near it
    assert eq.DIFFUSION[0] == "fourtakas"  # the documented default


def test_moving_wall_follows_its_prescribed_velocity_and_pushes_the_fluid():
    dx = 0.02
    b = tank_with_water(2, dx, 0.4, 0.1, 0.14)
    ps = b.particles
    # a piston: two columns of particles inside the tank at x = 0.1 ... 0.12, no fluid there
    from fluid.geometry import block

    piston = block([0.06, 0.0], [0.1, 0.14], dx)
    fl = ps.kind == Kind.FLUID
    keep = ~(fl & (ps.pos[:, 0] < 0.12))
    ps = ps.select(keep)
    pis = ParticleSet.create(piston, 1000.0, ps.mass[0], kind=Kind.MOVING_WALL, group=1)
    ps = ParticleSet.concatenate([ps, pis])
    f = Fluid(FluidConfig(dx=dx, u_max=1.0, c0_factor=20), ps)
    f.initialize(0.0)
    with pytest.raises(InputError, match="FIXED_WALL"):
        f.set_group_velocity(0, (0.1, 0.0))
    f.set_group_velocity(1, (0.2, 0.0))
    x0 = {int(i): p.copy() for i, p in zip(f.ps.ids, f.ps.pos)}
    f.advance(0.0, 0.05)
    moved = np.array([f.ps.pos[k] - x0[int(i)] for k, i in enumerate(f.ps.ids)])
    g1 = f.ps.group == 1
    np.testing.assert_allclose(moved[g1], np.tile([0.01, 0.0], (g1.sum(), 1)), atol=1e-14)
    assert np.abs(moved[f.ps.group == 0]).max() == 0.0
    # the fluid in front of the piston is pushed along +x, and pushes back on it
    F, _ = f.group_loads()
    assert F[1, 0] < 0
    front = (f.ps.kind == Kind.FLUID) & (f.ps.pos[:, 0] < 0.16)
    assert f.ps.vel[front, 0].mean() > 0.05


def test_float32_pair_terms_follow_the_float64_run():
    """FluidConfig(precision="float32") (float32 pair terms, float64 state): a small tank
    of sheared water steps like the float64 run, within float32's round-off grown over
    36 steps (measured 6e-7 of the largest speed, 1.4e-6 kg/m^3), and not equal to it."""
    cfg, ps = small_tank()
    ps.vel[ps.kind == Kind.FLUID, 0] = 0.3 * ps.pos[ps.kind == Kind.FLUID, 1]  # a shear, so that every term acts
    runs = {}
    for precision in ("float64", "float32"):
        f = Fluid(FluidConfig(dx=cfg.dx, u_max=1.0, c0_factor=20, precision=precision), ps)
        f.initialize(0.0)
        f.advance(0.0, 0.01)
        o = np.argsort(f.ps.ids)
        runs[precision] = f.ps.vel[o], f.ps.rho[o], f.counters.steps
    (v64, r64, n64), (v32, r32, n32) = runs["float64"], runs["float32"]
    assert n64 == n32 > 5
    dv = np.abs(v32 - v64).max() / np.abs(v64).max()
    assert 0.0 < dv < 1e-5
    assert np.abs(r32 - r64).max() < 1e-5 * cfg.rho0


@pytest.mark.parametrize("integrator", ["symplectic", "verlet"])
def test_adami_walls_loads_leave_the_fluid_as_it_is(integrator):
    """Adami walls' densities are Eq. 27's alone, whether their loads are computed or
    not: a sloshing tank with the MLS re-initialisation (which reads the walls' densities)
    every 3 steps runs bit for bit the same with ``wall_loads`` on and off."""
    from dataclasses import replace

    cfg, ps = small_tank()
    fl = ps.kind == Kind.FLUID
    ps.vel[fl, 0] = 0.3 * ps.pos[fl, 1]
    runs = {}
    for loads in (True, False):
        f = Fluid(replace(cfg, walls="adami", wall_loads=loads, mls_every=3, integrator=integrator), ps.copy())
        f.initialize(0.0)
        f.advance(0.0, 0.01)
        o = np.argsort(f.ps.ids)
        runs[loads] = f.ps.pos[o], f.ps.vel[o], f.ps.rho[o], f.counters.steps
    (p1, v1, r1, n1), (p0, v0, r0, n0) = runs[True], runs[False]
    assert n1 == n0 >= 6
    np.testing.assert_array_equal(p1, p0)
    np.testing.assert_array_equal(v1, v0)
    np.testing.assert_array_equal(r1, r0)


@pytest.mark.parametrize("walls", ["dbc", "adami"])
def test_without_wall_loads_the_fluid_and_the_bodies_get_the_same_rates(walls):
    """FluidConfig(wall_loads=False): the fluid's rates, the walls' continuity rates (plain
    dynamic boundaries) and a body's load are those of the full pass; the walls' own
    accelerations are not computed, so their groups' loads and their rows of
    boundary_forces_now read NaN (the body's rows as with loads), and the readers of wall
    loads refuse with the reason."""
    from dataclasses import replace

    from fluid.geometry import block
    from fluid.probes import GroupLoad

    cfg, ps = small_tank()
    body = ParticleSet.create(block([0.08, 0.06], [0.12, 0.1], 0.02), 1000.0, ps.mass[0], kind=Kind.BODY, group=2)
    ps = ps.select(~((ps.kind == Kind.FLUID) & (np.abs(ps.pos[:, 0] - 0.09) < 0.03) & (ps.pos[:, 1] > 0.05)))
    ps = ParticleSet.concatenate([ps, body])
    fl = ps.kind == Kind.FLUID
    ps.vel[fl, 0] = 0.3 * ps.pos[fl, 1]
    ps.vel[ps.kind == Kind.BODY] = [0.05, -0.02]
    runs = {}
    for loads in (True, False):
        f = Fluid(replace(cfg, walls=walls, wall_loads=loads), ps.copy())
        f.initialize(0.0)
        runs[loads] = f
    full, lite = runs[True], runs[False]
    assert np.array_equal(full.ps.ids, lite.ps.ids)
    fl = full.ps.kind == Kind.FLUID
    wall = full.ps.kind == Kind.FIXED_WALL
    np.testing.assert_array_equal(lite._acc[fl], full._acc[fl])
    np.testing.assert_array_equal(lite._drho[fl], full._drho[fl])
    assert (lite._acc[wall] == 0).all() and np.abs(full._acc[wall]).max() > 1.0
    # the walls' viscous terms still bound the step
    ev = dict(zip(("full", "lite"), (eq.evaluate(f.ps.pos, f.ps.vel, f.ps.rho, f.ps.mass, f.ps.kind, f._start, f._grid,
                                                 f._kernel, f._prm, cfg.rho0, cfg.speed_of_sound, cfg.gamma, f.ps.p,
                                                 None, f._xbins, f.near_fluid, f._walls_rates).visc.copy()
                                     for f in (full, lite))))
    assert (ev["full"][wall] > 1e-3).sum() > 20  # the wetted walls' terms
    np.testing.assert_allclose(ev["lite"], ev["full"], rtol=1e-14, atol=0)  # the same terms, fused differently
    np.testing.assert_allclose(lite._limit.dt, full._limit.dt, rtol=1e-14)
    if walls == "dbc":  # their densities move with it
        assert np.abs(full._drho[wall]).max() > 1.0
        np.testing.assert_allclose(lite._drho[wall], full._drho[wall], rtol=0, atol=1e-12 * np.abs(full._drho).max())
    else:  # theirs come from the fluid's pressure, with or without loads
        assert (lite._drho[wall] == 0).all() and (full._drho[wall] == 0).all()
        np.testing.assert_array_equal(lite.ps.rho, full.ps.rho)
    F_full, M_full = full.group_forces_now()
    F, M = lite.group_forces_now()
    assert np.isnan(F[0]).all() and np.isnan(M[0]).all()
    np.testing.assert_array_equal(F[2], F_full[2])
    np.testing.assert_array_equal(M[2], M_full[2])
    assert np.abs(F_full[2]).max() > 0.1
    per_row = lite.boundary_forces_now()  # the walls' rows not computed, the body's as with loads
    assert np.isnan(per_row[lite.ps.kind == Kind.FIXED_WALL]).all()
    on_body = lite.ps.kind == Kind.BODY
    np.testing.assert_array_equal(per_row[on_body], full.boundary_forces_now()[on_body])
    from fluid.probes import wall_patch_pressure

    with pytest.raises(InputError, match="wall_loads"):
        wall_patch_pressure(lite, [0.0, 0.02], [1.0, 0.0], 0.02)
    with pytest.raises(InputError, match="wall_loads"):
        GroupLoad(0).sample(lite)
    assert GroupLoad(2).sample(lite)["F"][1] == F_full[2][1]
    with pytest.raises(InputError, match="wall_loads"):
        FluidConfig(dx=0.02, c0=30.0, wall_loads="no")
