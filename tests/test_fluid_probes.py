"""fluid.probes on tanks at rest (hydrostatic densities, the state a run starts from):
pressures against rho g d, gauges against the water depth, energies against m g H / 2."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.geometry import assemble, block, set_hydrostatic, tank_walls, tank_with_water
from fluid.particles import Kind
from fluid.probes import (Energy, GroupLoad, PatchPressureProbe, PressureProbe, WaveGauge, fluid_energies,
                          pressure_at, surface_elevation, wall_patch_pressure)
from fluid.solver import Fluid, FluidConfig

G, RHO0 = 9.81, 1000.0


def _tank(dim=2, dx=0.01, depth=0.2, length=0.3, width=0.06):
    b = tank_with_water(dim, dx, length, depth, 1.25 * depth, width=width)
    cfg = FluidConfig(dim=dim, dx=dx, u_max=math.sqrt(G * depth), c0_factor=20.0, threads=1)
    set_hydrostatic(b.particles, depth, RHO0, cfg.speed_of_sound, cfg.gamma, G)
    f = Fluid(cfg, b.particles)
    f.initialize(0.0)
    return f


@pytest.fixture(scope="module")
def tank2d():
    return _tank()


def test_pressure_at_wall_points_is_rho_g_depth(tank2d):
    depth = np.array([0.03, 0.05, 0.1, 0.15])
    pts = np.stack([np.zeros_like(depth), 0.2 - depth], axis=1)  # on the left wall's face
    p = PressureProbe(pts).sample(tank2d)["p"]
    np.testing.assert_allclose(p, RHO0 * G * depth, rtol=0.01)
    # the same points on the right wall, and a dry point above the water: 0
    right = pts.copy()
    right[:, 0] = 0.3
    np.testing.assert_allclose(pressure_at(tank2d, right), p, rtol=1e-9)
    assert pressure_at(tank2d, [0.15, 0.23])[0] == 0.0


def test_pressure_at_a_boundary_particle_is_what_the_fluid_reports_there(tank2d):
    ps = tank2d.ps
    wall = np.flatnonzero((ps.kind == Kind.FIXED_WALL) & (ps.pos[:, 1] < 0.19))
    np.testing.assert_allclose(pressure_at(tank2d, ps.pos[wall]), tank2d.wall_pressure()[wall],
                               rtol=1e-9, atol=1e-9)


def test_gauges_find_the_water_depth(tank2d):
    eta = WaveGauge([0.02, 0.15, 0.28]).sample(tank2d)["eta"]
    assert np.abs(eta - 0.2).max() < 0.005  # dx / 2
    # a gauge through the wall reads its top: a dry gauge reads the solid under it
    top = tank2d.ps.pos[tank2d.ps.kind == Kind.FIXED_WALL, 1].max()
    assert surface_elevation(tank2d, [-0.02])[0] == pytest.approx(top + 0.005, abs=1e-12)


def test_the_surface_is_where_the_fluid_fraction_is_one_half(tank2d):
    """The height a gauge reads is solved to 1e-9 of the march's step (dx / 4): there the
    kernel-interpolated fluid fraction of the particles within 2h of its line is 0.5 to
    within its slope times that."""
    from fluid.kernels import alpha_d
    from fluid.probes import _fraction

    f, c = tank2d, tank2d.config
    ps = f.ps
    x = 0.13
    eta = surface_elevation(f, [x])[0]
    near = (ps.kind == Kind.FLUID) & (np.abs(ps.pos[:, 0] - x) < 2.0 * c.h)
    args = ((ps.pos[near, 0] - x) ** 2, ps.pos[near, 1].copy(), ps.mass[near] / ps.rho[near], f._kernel, c.h,
            alpha_d(f._kernel, 2, c.h))
    slope = (_fraction(eta - 1e-4, *args) - _fraction(eta + 1e-4, *args)) / 2e-4
    assert abs(eta - 0.2) < 0.005  # dx / 2 of the water's depth
    assert abs(_fraction(eta, *args) - 0.5) < slope * 1e-9 * c.dx / 4 + 1e-13


@pytest.mark.parametrize("dim", [2, 3])
def test_a_gauge_over_the_dry_floor_reads_the_floor(dim):
    """Water held in the left third of a tank (a dam break at t = 0): a gauge over the dry
    floor reads the floor's face (z = 0, a water depth of zero), one in the water its
    surface."""
    dx, length, width = 0.01, 0.3, 0.06
    lo = np.zeros(dim)
    hi = np.array([length, 0.25] if dim == 2 else [length, width, 0.25])
    top = hi.copy()
    top[0], top[-1] = 0.1, 0.2
    water = block(lo, top, dx)
    b = assemble(dim, dx, RHO0, water, [(tank_walls(lo, hi, dx), Kind.FIXED_WALL, 0)])
    f = Fluid(FluidConfig(dim=dim, dx=dx, c0=20.0, threads=1), b.particles)
    f.initialize(0.0)
    x = np.array([0.05, 0.15, 0.25])
    eta = surface_elevation(f, x if dim == 2 else np.stack([x, np.full(3, 0.5 * width)], 1))
    assert abs(eta[0] - 0.2) < dx / 2
    np.testing.assert_allclose(eta[1:], 0.0, atol=1e-12)


def test_tilted_surface_gives_the_slope_between_gauges():
    dx, slope = 0.01, 0.25
    lo, hi = np.zeros(2), np.array([0.4, 0.3])
    pts = block(lo, [0.4, 0.3], dx)
    pts = pts[pts[:, 1] < 0.1 + slope * pts[:, 0]]
    b = assemble(2, dx, RHO0, pts, [(tank_walls(lo, hi, dx), Kind.FIXED_WALL, 0)])
    f = Fluid(FluidConfig(dim=2, dx=dx, c0=20.0, threads=1), b.particles)
    f.initialize(0.0)
    x = np.array([0.1, 0.2, 0.3])
    eta = surface_elevation(f, x)
    # the staircase of the lattice smooths into the plane z = 0.1 + slope x
    np.testing.assert_allclose(np.diff(eta), slope * np.diff(x), atol=dx / 4)
    assert np.abs(eta - (0.1 + slope * x)).max() < dx / 2


def test_energies_of_a_column_at_rest(tank2d):
    ps = tank2d.ps
    fl = ps.kind == Kind.FLUID
    m = ps.mass[fl].sum()
    ke, pe = fluid_energies(tank2d)
    assert ke == 0.0
    np.testing.assert_allclose(pe, m * G * 0.2 / 2, rtol=1e-12)  # lattice rows symmetric about H/2
    e = Energy(z_ref=0.2).sample(tank2d)
    np.testing.assert_allclose(e["potential"], -m * G * 0.2 / 2, rtol=1e-12)
    v = ps.vel.copy()
    ps.vel[fl] = [0.3, -0.4]
    try:
        np.testing.assert_allclose(fluid_energies(tank2d)[0], 0.5 * m * 0.25, rtol=1e-12)
    finally:
        ps.vel[:] = v


def test_energies_do_not_depend_on_the_thread_count():
    """The sums are the same to the last bit on 1 thread and on all (a resumed run must
    reproduce the uninterrupted one's probes), and equal a plain sum to rounding."""
    import numba

    from fluid.probes import _energies

    rng = np.random.default_rng(3)
    n = 50_000
    pos, vel, mass = rng.random((n, 3)), rng.normal(size=(n, 3)), rng.random(n)
    kind = np.where(rng.random(n) < 0.8, int(Kind.FLUID), int(Kind.FIXED_WALL)).astype(np.int8)
    saved = numba.get_num_threads()
    try:
        got = []
        for k in sorted({1, numba.config.NUMBA_NUM_THREADS}):
            numba.set_num_threads(k)
            got.append(_energies(pos, vel, mass, kind, np.array([0.0, 0.0, -G]), 0.1))
    finally:
        numba.set_num_threads(saved)
    assert all(g == got[0] for g in got)
    fl = kind == int(Kind.FLUID)
    np.testing.assert_allclose(got[0][0], 0.5 * (mass[fl] * (vel[fl] ** 2).sum(axis=1)).sum(), rtol=1e-12)
    np.testing.assert_allclose(got[0][1], (mass[fl] * G * (pos[fl, 2] - 0.1)).sum(), rtol=1e-12)
    g = np.array([3.0, -1.0, -G])  # a tilted gravity: -m g . (r - z_ref e_z)
    _, pe = _energies(pos, vel, mass, kind, g, 0.1)
    np.testing.assert_allclose(pe, -(mass[fl] * ((pos[fl] - [0.0, 0.0, 0.1]) @ g)).sum(), rtol=1e-12)


def test_group_load_carries_the_water_weight_and_moves_its_moment(tank2d):
    F, M = tank2d.group_forces_now()
    s = GroupLoad(0).sample(tank2d)
    np.testing.assert_array_equal(s["F"], F[0])
    np.testing.assert_array_equal(s["M"], M[0])
    ps = tank2d.ps
    weight = ps.mass[ps.kind == Kind.FLUID].sum() * G
    assert abs(s["F"][1] / weight + 1.0) < 0.02 and abs(s["F"][0]) < 1e-6 * weight
    # moment about another point: M_c = M_0 + (r0 - c) x F, here about the origin
    c = np.array([0.5, -0.3])
    m_c = GroupLoad(0, about=c).sample(tank2d)["M"][0]
    d = tank2d.moment_points[0] - c
    assert m_c == pytest.approx(M[0, 0] + d[1] * F[0, 0] - d[0] * F[0, 1], rel=1e-12)
    with pytest.raises(InputError, match="no boundary group"):
        GroupLoad(3).sample(tank2d)


def test_wall_patch_reads_the_mean_pressure_on_its_face(tank2d):
    h = tank2d.config.h
    # under water: rho g d on either side wall, to the ~1 % the lattice's wall force has
    for d in (0.05, 0.1):
        for x, n in ((0.0, [1.0, 0.0]), (0.3, [-1.0, 0.0])):
            assert wall_patch_pressure(tank2d, [x, 0.2 - d], n, 4 * h) == pytest.approx(RHO0 * G * d, rel=0.015)
    probe = PatchPressureProbe([0.0, 0.1], [1.0, 0.0], 4 * h, group=0)
    assert probe.sample(tank2d)["p"] == wall_patch_pressure(tank2d, [0.0, 0.1], [1.0, 0.0], 4 * h)
    # a patch half under water reads the mean over its whole face, rho g a / 4 for
    # half-length a (an average of the fluid near its centre would not see the dry half)
    a = 0.04
    assert wall_patch_pressure(tank2d, [0.0, 0.2], [1.0, 0.0], 2 * a) == pytest.approx(RHO0 * G * a / 4, rel=0.01)


def test_wall_patch_reads_a_lone_particle_by_its_force_not_its_pressure():
    dx = 0.01
    lo, hi = np.zeros(2), np.array([0.3, 0.3])
    b = assemble(2, dx, RHO0, np.array([[0.15, 0.5 * dx]]), [(tank_walls(lo, hi, dx), Kind.FIXED_WALL, 0)])
    f = Fluid(FluidConfig(dim=2, dx=dx, c0=20.0, threads=1), b.particles)
    ps = f.ps
    ps.rho[ps.kind == Kind.FLUID] = 1010.0  # a droplet squeezed against the bottom: ~4 kPa
    f.initialize(0.0)
    p_drop = pressure_at(f, [[0.15, 0.0]])[0]
    assert p_drop > 4000.0
    # a patch wide enough to take the droplet's whole push: its force over the patch area;
    # the push is what the wall gives back to the droplet (pair antisymmetry)
    size = 0.1
    push = f.fluid_force_from_groups()[1]
    assert wall_patch_pressure(f, [0.15, 0.0], [0.0, 1.0], size) == pytest.approx(push / size, rel=1e-9)
    assert push / size < 0.1 * p_drop


def test_wall_patch_refuses_bad_input(tank2d):
    with pytest.raises(InputError, match="nonzero"):
        wall_patch_pressure(tank2d, [0.0, 0.1], [0.0, 0.0], 0.05)
    with pytest.raises(InputError, match="particle spacing"):
        wall_patch_pressure(tank2d, [0.0, 0.1], [1.0, 0.0], 0.001)
    with pytest.raises(InputError, match="wall's face"):
        wall_patch_pressure(tank2d, [0.15, 0.1], [1.0, 0.0], 0.05)  # mid-tank: no wall there
    with pytest.raises(InputError, match="finite"):
        PatchPressureProbe([0.0, 0.1], [1.0, 0.0, 0.0], 0.05)
    with pytest.raises(InputError, match="size"):
        PatchPressureProbe([0.0, 0.1], [1.0, 0.0], -0.05)


def test_3d_tank_pressure_and_gauges():
    f = _tank(dim=3, dx=0.02, depth=0.16, length=0.16, width=0.12)
    depth = np.array([0.06, 0.1])
    pts = np.stack([np.zeros(2), np.full(2, 0.06), 0.16 - depth], axis=1)
    np.testing.assert_allclose(pressure_at(f, pts), RHO0 * G * depth, rtol=0.01)
    eta = surface_elevation(f, [[0.05, 0.05], [0.11, 0.07]])
    assert np.abs(eta - 0.16).max() < 0.01  # dx / 2
    # a disc on the left wall, 4 dx across, 0.08 m deep
    assert wall_patch_pressure(f, [0.0, 0.06, 0.08], [1.0, 0.0, 0.0], 0.08) == pytest.approx(RHO0 * G * 0.08,
                                                                                        rel=0.02)


def test_bad_probe_input_is_refused(tank2d):
    with pytest.raises(InputError, match=r"\(M, 2\)"):
        pressure_at(tank2d, np.zeros((2, 3)))
    with pytest.raises(InputError, match="outside"):
        pressure_at(tank2d, [[5.0, 0.1]])
    with pytest.raises(InputError, match=r"shape \(M,\)"):
        surface_elevation(tank2d, np.zeros((2, 2)))
    with pytest.raises(InputError, match="not initialised"):
        _uninitialised = Fluid(tank2d.config, tank2d.ps)
        pressure_at(_uninitialised, [[0.1, 0.1]])


def _read_cosine(dim, dx, depth, a, wavelength, rows_wide, x):
    """The gauges at ``x`` (on the mid-line in 3-D) over a lattice whose columns are stretched
    to eta = a cos(k x), their particles' volumes with them (h = 2 dx): the least-squares
    cosine's (cos, sin, mean) coefficients [m]."""
    k = 2.0 * math.pi / wavelength
    lo = np.zeros(dim)
    height = depth + 0.2
    hi = np.array([2.0 * wavelength, height] if dim == 2 else [2.0 * wavelength, rows_wide * dx, height])
    top = hi.copy()
    top[-1] = depth
    pts = block(lo, top, dx)
    stretch = 1.0 + a * np.cos(k * pts[:, 0]) / depth
    pts[:, -1] *= stretch
    b = assemble(dim, dx, RHO0, pts, [(tank_walls(lo, hi, dx), Kind.FIXED_WALL, 0)])
    b.particles.mass[b.particles.kind == Kind.FLUID] *= stretch  # the block's particles, in its order
    f = Fluid(FluidConfig(dim=dim, dx=dx, c0=20.0, h_coef=2.0, threads=1), b.particles)
    f.initialize(0.0)
    eta = surface_elevation(f, x if dim == 2 else np.stack([x, np.full(x.size, 0.5 * rows_wide * dx)], 1))
    return np.linalg.lstsq(np.column_stack([np.cos(k * x), np.sin(k * x), np.ones_like(x)]), eta, rcond=None)[0]


@pytest.mark.parametrize("dim", [2, 3])
def test_gauges_read_a_cosine_surface_in_2d_and_3d(dim):
    """Columns of a lattice stretched to eta = a cos(k x) (their particles' volumes with
    them): the gauges' least-squares cosine has the surface's amplitude within 1.5 % and its
    mean level within dx / 10, in 3-D as in 2-D (a wave's height read in a 3-D flume is the
    water's, not the gauge's)."""
    dx, depth, a, wavelength = 0.03, 0.3, 0.02, 1.373
    c = _read_cosine(dim, dx, depth, a, wavelength, 5, np.linspace(0.25, 1.75, 31) * wavelength)
    assert math.hypot(c[0], c[1]) / a == pytest.approx(1.0, abs=0.015)
    assert abs(c[1]) < 0.02 * a and abs(c[2] - depth) < dx / 10


@pytest.mark.parametrize("dim", [2, 3])
def test_gauges_beside_a_wall_and_over_shallow_water_read_the_water(dim):
    """Still water at rest in a tank (h = 2 dx): gauges on the first six particle columns
    from a wall (in 3-D on the diagonal from the corner of two walls) read the still level
    within dx / 10, the columns beside a wall as the middle does, over water 10 and 3 rows
    deep (the latter shallower than the kernel's support: the floor in it). Counting
    the fluid alone, the wall's share of the kernel read as missing water: the column beside
    a wall 0.6 dx low, the corner's column dry (10 dx low)."""
    dx = 0.01
    for depth in (0.1, 0.03):
        b = tank_with_water(dim, dx, 0.12, depth, depth + 0.1, width=0.08)
        cfg = FluidConfig(dim=dim, dx=dx, u_max=1.0, h_coef=2.0, threads=1)
        f = Fluid(cfg, b.particles)
        f.initialize(0.0)
        x = (np.arange(6) + 0.5) * dx  # from the left wall's face inwards
        eta = surface_elevation(f, x if dim == 2 else np.stack([x, (np.arange(6) + 0.5) * dx], 1))
        np.testing.assert_allclose(eta, depth, atol=dx / 10, err_msg=f"depth {depth}")


@pytest.mark.parametrize("dim", [2, 3])
def test_a_gauge_reads_a_short_wave_by_its_response(dim):
    """Lattices stretched to a cosine surface (the particles' own amplitude a = dx / 2) at
    wavelengths 10, 15, 20 and 40 dx, h = 2 dx: the gauges' least-squares amplitude is
    fluid.probes.gauge_response of the wavenumber within 0.004 (0.80 at 10 dx: the kernel's
    profile across the surface averages the wave), and the response falls with k, from 1."""
    from fluid.probes import gauge_response

    dx = 0.02
    read = []
    for lam in (10, 15, 20, 40):
        wavelength, a = lam * dx, 0.5 * dx
        c = _read_cosine(dim, dx, 0.2, a, wavelength, 3, np.linspace(0.5, 1.5, 21) * wavelength)
        read.append(math.hypot(c[0], c[1]) / a)
        assert read[-1] == pytest.approx(float(gauge_response(2.0 * math.pi / wavelength, 2.0 * dx, dim)),
                                         abs=0.004), lam
    assert read[0] < 0.82 and np.all(np.diff(read) > 0)
    assert gauge_response(0.0, 2.0 * dx, dim) == pytest.approx(1.0)
