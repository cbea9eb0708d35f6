"""Every kind of domain, excitation and body a scene offers builds and runs a few steps at
a coarse spacing, and what it builds is what it says: the water volume of each domain,
the motion of a shaken tank's walls, a floating body's draft."""

import math
from pathlib import Path

import numpy as np
import pytest

from cosim.scene import (MJCF, SPH, Analytic, Block, Box, Cylinder, CylinderTank, Earthquake, Flap, Flume,
                         InclinedTank, NoFluid, OpenWater, PaddleRecord, Piston, PolygonTank, Probes, Roll, RollTable,
                         Scene, Shake, Sphere, TableMotion, Tank, World)
from cosim.scene.build import build

W2 = World(dim=2, duration=0.01, sample_every=0.005, snapshot_every=0)
W3 = World(dim=3, duration=0.005, sample_every=0.005, snapshot_every=0)


def _water_volume(built, dim):
    from fluid.particles import Kind

    ps = built.sph.ps
    return int((ps.kind == Kind.FLUID).sum()) * built.sph.config.dx ** dim


@pytest.mark.parametrize("domain, dim, volume, rel", [
    (Tank(length=0.6, height=0.4, depth=0.2), 2, 0.6 * 0.2, 1e-9),
    (Tank(length=0.6, height=0.4, water=[Block((0.0, 0.0), (0.2, 0.3))]), 2, 0.2 * 0.3, 1e-9),
    (Flume(length=1.0, depth=0.2, height=0.3), 2, 1.0 * 0.2, 1e-9),
    (InclinedTank(angle=30.0, length=0.5, depth=0.2, height=0.3), 2,
     0.5 * 0.2 + 0.5 * 0.2**2 * math.tan(math.radians(30)), 0.08),
    (PolygonTank(vertices=[(0.0, 0.0), (0.6, 0.0), (0.6, 0.4), (0.0, 0.4)], fill_level=0.2), 2, 0.6 * 0.2, 1e-9),
    (Tank(length=0.3, width=0.2, height=0.3, depth=0.15), 3, 0.3 * 0.2 * 0.15, 1e-9),
    (CylinderTank(diameter=0.4, depth=0.2, height=0.3), 3, math.pi * 0.2**2 * 0.2, 0.03),
], ids=["tank", "dam-break-block", "flume", "inclined", "polygon", "tank-3d", "cylinder-3d"])
def test_domains_hold_their_water_and_run(domain, dim, volume, rel, tmp_path):
    scene = Scene(world=W2 if dim == 2 else W3, fluid=SPH(dx=0.05 if dim == 2 else 0.05), domain=domain)
    b = build(scene, tmp_path)
    assert _water_volume(b, dim) == pytest.approx(volume, rel=rel)
    assert b.setup.name == ("impact" if domain.__class__ is Tank and domain.water else "still")
    r = scene.run(tmp_path / "run", progress=False)
    assert r.summary["t_reached_s"] == scene.world.duration


def test_a_tanks_inner_walls_are_wall_particles_and_keep_the_water_out(tmp_path):
    """A baffle (``domain.walls``) in a tank filled to a depth: its lattice is wall
    particles of the tank's group, the water laid to the depth leaves its volume out (and
    stays a lattice spacing from its first particles), and the water beside it stays out
    through a short run; a water block beside a wall keeps its own volume."""
    from fluid.particles import Kind

    baffle = Block((0.25, 0.0), (0.4, 0.3))  # 0.15 m = 3 layers of 0.05 m
    scene = Scene(world=W2.replace(duration=0.2), fluid=SPH(dx=0.05),
                  domain=Tank(length=0.6, height=0.4, depth=0.2, walls=[baffle]))
    b = build(scene, tmp_path)
    ps = b.sph.ps
    fluid, walls = ps.pos[ps.kind == Kind.FLUID], ps.pos[ps.kind != Kind.FLUID]
    assert _water_volume(b, 2) == pytest.approx((0.6 - 0.15) * 0.2, rel=1e-9)
    inner = walls[(walls[:, 0] > 0.25) & (walls[:, 0] < 0.4) & (walls[:, 1] > 0.0)]
    assert len(inner) == 3 * 6 and np.unique(ps.group[ps.kind != Kind.FLUID]).tolist() == [0]
    gap = np.min(np.linalg.norm(fluid[:, None, :] - inner[None, :, :], axis=2))
    assert gap == pytest.approx(0.05, rel=1e-9)
    b.coupler.run(0.2)
    x = b.sph.ps.pos[b.sph.ps.kind == Kind.FLUID][:, 0]
    assert not ((x > 0.25) & (x < 0.4)).any()
    column = Tank(length=0.6, height=0.4, water=[Block((0.0, 0.0), (0.25, 0.3))], walls=[baffle])
    b = build(Scene(world=W2, fluid=SPH(dx=0.05), domain=column), tmp_path / "column")
    assert _water_volume(b, 2) == pytest.approx(0.25 * 0.3, rel=1e-9)


def _table(path, t, v):
    np.savetxt(path, np.column_stack([t, v]))
    return str(path)


def _at2(path, dt=0.01, n=200):
    acc = 0.1 * np.sin(2 * np.pi * np.arange(n) * dt / 0.5)  # g
    head = ["TEST RECORD", "SYNTHETIC", "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS=  {n}, DT= {dt:.4f} SEC"]
    path.write_text("\n".join(head + [" ".join(f"{a:.6e}" for a in acc[i:i + 5]) for i in range(0, n, 5)]) + "\n")
    return str(path)


def _motions(tmp_path):
    t = np.linspace(0.0, 1.0, 21)
    return {
        "shake-amplitude": Shake(period=0.5, amplitude=0.01),
        "shake-acceleration": Shake(period=0.5, acceleration=2.0, ramp=0.1, stop=0.9),
        "roll": Roll(amplitude=2.0, period=1.0, point=(0.3, 0.0)),
        "roll-table": RollTable(file=_table(tmp_path / "r.txt", t, 2.0 * np.sin(2 * np.pi * t)), point=(0.3, 0.0)),
        "table": TableMotion(file=_table(tmp_path / "d.txt", t, 0.01 * np.sin(2 * np.pi * t))),
        "earthquake": Earthquake(file=_at2(tmp_path / "q.AT2"), scale=0.5),
    }


@pytest.mark.parametrize("kind", ["shake-amplitude", "shake-acceleration", "roll", "roll-table", "table", "earthquake"])
def test_base_motions_move_the_walls(kind, tmp_path):
    """The tank's walls follow the prescribed motion (their velocity at the end is the
    motion's), the water is dragged along."""
    from fluid.particles import Kind

    motion = _motions(tmp_path)[kind]
    scene = Scene(world=W2.replace(duration=0.2), fluid=SPH(dx=0.05), domain=Tank(length=0.6, height=0.4, depth=0.2),
                  base_motion=motion)
    b = build(scene, tmp_path)
    assert b.setup.name == "sloshing"
    b.coupler.run(0.2)
    ps = b.sph.ps
    walls = ps.kind == Kind.MOVING_WALL
    assert walls.any() and np.isfinite(ps.vel).all()
    assert np.abs(ps.vel[walls]).max() > 1e-4  # the walls move


@pytest.mark.parametrize("scale", [1.0, -1.0])
def test_a_recorded_roll_turns_the_tank_as_the_harmonic_roll_it_samples(scale, tmp_path):
    """A roll table sampling the harmonic roll 2 deg sin(2 pi t / 1 s) every 5 ms moves
    the tank's walls where the harmonic roll moves them, to the spline's error (the
    angle's fourth derivative times h^4 / 384: 2e-9 rad here); ``scale = -1`` turns the
    other way, about the same axis point."""
    t = np.arange(0.0, 1.0 + 1e-9, 0.005)
    table = RollTable(file=_table(tmp_path / "r.txt", t, 2.0 * np.sin(2 * np.pi * t)), point=(0.3, 0.0),
                      scale=scale)
    tank = Tank(length=0.6, height=0.4, depth=0.2)
    moved = {}
    for name, motion in (("table", table), ("harmonic", Roll(amplitude=2.0 * scale, period=1.0, point=(0.3, 0.0)))):
        b = build(Scene(world=W2, fluid=SPH(dx=0.05), domain=tank, base_motion=motion), tmp_path / name)
        corners = np.array([[0.0, 0.0], [0.6, 0.4], [0.3, 0.0]])
        moved[name] = [np.asarray(b.base_motion(s, corners)[0]) for s in (0.13, 0.41, 0.77)]
    for a, h in zip(moved["table"], moved["harmonic"]):
        assert np.abs(a - h).max() < 1e-8
        assert np.array_equal(a[2], [0.3, 0.0])  # the axis point stays
    # at t = 0.13 s the angle (1.46 deg) lifts the left corner for scale 1 (about +y: the right one down)
    assert np.sign(moved["table"][0][0][1]) == scale


def test_a_gzipped_table_is_the_table(tmp_path):
    """A table file ending in .gz is read gunzipped, by the checks and the build alike."""
    import gzip

    t = np.arange(0.0, 1.0 + 1e-9, 0.005)
    plain = _table(tmp_path / "r.txt", t, 2.0 * np.sin(2 * np.pi * t))
    with open(plain, "rb") as src, gzip.open(tmp_path / "r.txt.gz", "wb") as dst:
        dst.write(src.read())
    tank, pts = Tank(length=0.6, height=0.4, depth=0.2), np.array([[0.0, 0.4]])
    moved = [np.asarray(build(Scene(world=W2, fluid=SPH(dx=0.05), domain=tank,
                                    base_motion=RollTable(file=f, point=(0.3, 0.0))), tmp_path / Path(f).name)
                        .base_motion(0.3, pts)[0]) for f in (plain, str(tmp_path / "r.txt.gz"))]
    assert np.array_equal(moved[0], moved[1]) and moved[0][0, 1] != 0.4


@pytest.mark.parametrize("kind", ["piston", "flap", "record"])
def test_wavemakers_drive_the_paddle(kind, tmp_path):
    t = np.linspace(0.0, 2.0, 41)
    waves = {"piston": Piston(height=0.02, period=1.0), "flap": Flap(height=0.02, period=1.0),
             "record": PaddleRecord(paddle="piston", file=_table(tmp_path / "p.txt", t, 0.01 * np.sin(np.pi * t)))}
    scene = Scene(world=W2.replace(duration=0.2), fluid=SPH(dx=0.05), domain=Flume(length=1.5, depth=0.2, height=0.3),
                  waves=waves[kind], probes=Probes(gauges=[0.5]))
    r = scene.run(tmp_path / "run", progress=False)
    assert r.summary["setup"]["name"] == "waves" and np.isfinite(r["gauge1.eta"]).all()


@pytest.mark.parametrize("paddle", ["piston", "flap"])
def test_a_paddle_record_started_later_starts_from_its_zero(paddle, tmp_path):
    """A record shifted to start 0.5 s in (``t_shift`` = -0.5) with its value there as the
    paddle's zero (``zero_at_start``) moves the paddle by the record less that value: the
    paddle starts where the flume builds it, and 0.1 s later has moved by s(0.6) - s(0.5)
    (a flap's top turned by that angle about the hinge)."""
    from cosim.scene.build import PADDLE
    from fluid.particles import Kind

    t = np.linspace(0.0, 2.0, 201)
    s = 0.05 + 0.02 * np.sin(np.pi * t)  # an offset record: 0.05 m (or rad) at the start
    rec = PaddleRecord(paddle=paddle, file=_table(tmp_path / "p.txt", t, s), t_shift=-0.5, zero_at_start=True)
    scene = Scene(world=W2.replace(duration=0.1), fluid=SPH(dx=0.05), domain=Flume(length=1.5, depth=0.2, height=0.3),
                  waves=rec)
    b = build(scene, tmp_path)
    f = b.sph
    paddle_ps = (f.ps.group == PADDLE) & (f.ps.kind != Kind.FLUID)
    ids = np.sort(f.ps.ids[paddle_ps])
    start = {i: p for i, p in zip(f.ps.ids, f.ps.pos.copy())}
    b.coupler.run(0.1)
    moved = {i: p for i, p in zip(f.ps.ids, f.ps.pos)}
    ds = float(np.interp(0.6, t, s) - np.interp(0.5, t, s))  # the spline's, to its interpolation error
    top = max(ids, key=lambda i: start[i][1])
    dx_top = moved[top][0] - start[top][0]
    expect = ds if paddle == "piston" else start[top][1] * math.sin(ds) + start[top][0] * (math.cos(ds) - 1)
    assert dx_top == pytest.approx(expect, rel=2e-3)
    assert abs(expect) < 0.01  # not the record's 0.05 offset


@pytest.mark.parametrize("body, dim", [
    (Cylinder("c", radius=0.05, density=500.0, pos=(0.3,), place="floating"), 2),
    (Box("b", size=(0.1, 0.1, 0.08), density=600.0, pos=(0.2, 0.15), place="floating"), 3),
    (Cylinder("c", radius=0.05, length=0.1, density=400.0, pos=(0.2, 0.15), place="floating"), 3),
    (Sphere("s", radius=0.05, density=300.0, pos=(0.2, 0.15), place="floating"), 3),
], ids=["cylinder-2d", "box-3d", "cylinder-3d", "sphere-3d"])
def test_floating_bodies_start_at_their_draft(body, dim, tmp_path):
    """On the analytic fluid a floating body starts in equilibrium: its buoyancy carries
    its weight and it stays where it is put."""
    scene = Scene(world=World(dim=dim, duration=0.2, sample_every=0.1), fluid=Analytic(level=0.5), bodies=[body])
    from cosim.scene.placement import volume_and_height

    r = scene.run(tmp_path, progress=False)
    weight = body.density * volume_and_height(body, dim)[0] * 9.81
    assert r[f"{body.name}.fluid_Fz"][-1] == pytest.approx(weight, rel=2e-3)
    assert np.abs(r[f"{body.name}.heave"]).max() < 1e-4


def test_mjcf_bodies(tmp_path):
    xml = tmp_path / "m.xml"
    xml.write_text('<mujoco><option gravity="0 0 -1"/><worldbody><body name="float" pos="0 0 0">'
                   '<freejoint/><geom type="box" size="0.5 0.5 0.5" density="500"/>'
                   '<site name="top" pos="0 0 0.5"/></body></worldbody></mujoco>')
    scene = Scene(world=World(dim=3, duration=0.5, sample_every=0.1), fluid=Analytic(level=0.0),
                  bodies=[MJCF(file=str(xml))])
    b = build(scene, tmp_path)
    assert tuple(b.bodies.model.opt.gravity) == (0.0, 0.0, -9.81)  # the world's gravity, not the file's
    r = scene.run(tmp_path / "run", progress=False)
    assert np.abs(r["float.heave"]).max() < 1e-6  # half its volume under water: afloat at rest


@pytest.mark.long
def test_an_mjcf_models_own_gravity_is_replaced_with_its_lines_too(tmp_path):
    """The world's gravity replaces the file's (docs/scenes.md), also once an inextensible
    line's tether has recompiled the model, and the build warns that it was replaced: the
    float on its line moves exactly as it does from a file that has the world's gravity."""
    from cosim.scene import Line, Moorings

    def run(g_file):
        xml = tmp_path / f"m{g_file}.xml"
        xml.write_text(f'<mujoco><option gravity="0 0 {g_file}"/><worldbody><body name="float" pos="0 0 0">'
                       '<freejoint/><geom type="box" size="0.5 0.5 0.5" density="500"/>'
                       '<site name="top" pos="0 0 0.5"/></body></worldbody></mujoco>')
        scene = Scene(world=World(dim=3, duration=0.5, sample_every=0.1), fluid=Analytic(level=0.0),
                      bodies=[MJCF(file=str(xml))],
                      moorings=Moorings(lines=[Line("float.top", anchor=(8.0, 0.0, -10.0), length=15.0, weight=5.0)]))
        b = build(scene, tmp_path)
        assert b.bodies.tethers  # the model was recompiled with the line's length constraint
        assert tuple(b.bodies.model.opt.gravity) == (0.0, 0.0, -9.81)
        return b.warnings, scene.run(tmp_path / f"run{g_file}", progress=False)

    warned, r = run(-5)
    assert any("own gravity [0.0, 0.0, -5.0] m/s^2 is replaced by the world's" in w for w in warned)
    assert any("is replaced by the world's" in w for w in r.summary["warnings"])
    same, ref = run(-9.81)
    assert not same
    np.testing.assert_array_equal(r["float.heave"], ref["float.heave"])
    assert np.abs(r["float.heave"]).max() > 1e-3  # the line's weight pulls it down: a test that can fail


@pytest.mark.long
def test_analytic_added_mass_slows_the_heave(tmp_path):
    """Added mass in the analytic fluid goes into the body's inertia: the heave period grows
    as sqrt((m + m_a) / m) (the hydrostatic stiffness is the same)."""
    from cosim.study.metrics import value

    def period(added):
        s = Scene(world=World(dim=2, duration=12.0, sample_every=0.02), fluid=Analytic(added_mass=added),
                  bodies=[Box("b", size=(1.0, 1.0), density=500.0, pos=(0.0, 0.1))])
        r = s.run(tmp_path / str(len(added)), progress=False)
        return value("period", r.t, r["b.heave"])

    assert period({"b": [0.0, 500.0, 0.0]}) / period({}) == pytest.approx(math.sqrt(2.0), rel=0.03)


@pytest.mark.parametrize("depth, short", [(0.11, 0.01), (0.1, 0.0), (0.118, 0.018)])
def test_a_depth_that_is_not_whole_rows_is_warned_of_with_the_level_the_water_gets(tmp_path, depth, short):
    """The water is laid in whole rows of dx from the floor: its top row's upper face (the
    still level it holds) lies ``short`` below a depth that is not a whole number of
    spacings, and the build says so, naming the level's shortfall and the depths that fit."""
    from fluid.particles import Kind

    dx = 0.02
    scene = Scene(world=World(dim=2, duration=0.01), fluid=SPH(dx=dx), domain=Tank(length=0.3, height=0.2, depth=depth))
    built = build(scene, tmp_path)
    ps = built.fluid.ps
    top = ps.pos[ps.kind == Kind.FLUID, 1].max() + 0.5 * dx
    assert top == pytest.approx(depth - short, abs=1e-9)
    said = [w for w in built.warnings if w.startswith("domain.depth")]
    if short:
        assert len(said) == 1 and f"lies {short:.4g} m below" in said[0] and f"{depth - short:.6g} or" in said[0]
    else:
        assert not said


@pytest.mark.parametrize("dim, length, built", [(2, 0.314, 0.32), (2, 0.306, 0.3), (2, 0.3, 0.3), (3, 0.1, 0.1)])
def test_a_length_that_is_not_whole_spacings_is_built_rounded_and_warned_of(tmp_path, dim, length, built):
    """A tank filled to a depth lays its walls and water on one lattice: its length (and, in
    3-D, its width, 0.15 m = 7.5 spacings here, rounded down) is built as the nearest whole
    number of spacings, the water reaching half a spacing short of the far wall's face; the
    build says so, naming the built size and the sizes that fit."""
    from fluid.particles import Kind

    dx = 0.02
    domain = Tank(length=length, height=0.2, depth=0.1, width=0.15 if dim == 3 else None)
    built_scene = build(Scene(world=World(dim=dim, duration=0.01), fluid=SPH(dx=dx), domain=domain), tmp_path)
    ps = built_scene.fluid.ps
    assert ps.pos[ps.kind == Kind.FLUID, 0].max() + 0.5 * dx == pytest.approx(built, abs=1e-9)
    said = [w for w in built_scene.warnings if w.startswith("domain.length")]
    if abs(built - length) > 1e-9:
        assert len(said) == 1 and f"built {built:.6g} m" in said[0] and "or" in said[0]
    else:
        assert not said
    if dim == 3:
        assert ps.pos[ps.kind == Kind.FLUID, 1].max() + 0.5 * dx == pytest.approx(0.14, abs=1e-9)
        assert any(w.startswith("domain.width: 0.15 m") and "built 0.14 m" in w for w in built_scene.warnings)


@pytest.mark.parametrize("length, built, gap", [(0.314, 0.32, 0.02), (0.306, 0.3, 0.0)])
def test_a_water_block_to_a_far_wall_not_whole_spacings_away_is_warned_of_its_empty_column(tmp_path, length,
                                                                                          built, gap):
    """A tank filled by a water block up to its far wall: the walls are built at the
    nearest whole number of spacings (as a tank filled to a depth), the block in whole
    columns from its own corner; where the length rounds up the block stops a spacing
    short of the wall's face, and the warning says so beside the built length."""
    from cosim.scene.spec import Block
    from fluid.particles import Kind

    dx = 0.02
    domain = Tank(length=length, height=0.2, water=(Block(lo=(0.0, 0.0), hi=(length, 0.1)),))
    b = build(Scene(world=World(dim=2, duration=0.01), fluid=SPH(dx=dx), domain=domain), tmp_path)
    ps = b.fluid.ps
    far_wall = (ps.kind != Kind.FLUID) & (ps.pos[:, 1] > 0.0) & (ps.pos[:, 0] > 0.5 * length)
    wall_face = ps.pos[far_wall, 0].min() - 0.5 * dx
    water_face = ps.pos[ps.kind == Kind.FLUID, 0].max() + 0.5 * dx
    assert wall_face == pytest.approx(built, abs=1e-9) and built - water_face == pytest.approx(gap, abs=1e-9)
    said = [w for w in b.warnings if w.startswith("domain.length")]
    assert len(said) == 1 and f"built {built:.6g} m" in said[0]
    assert ("empty column" in said[0]) == (gap > 0)


def test_open_water_without_gravity_stays_at_rest_and_loses_what_leaves_its_box(tmp_path):
    """Open water (no walls, no floor) without gravity: two blocks at rest carry no
    pressure (no hydrostatics in free fall) and nothing moves them, so after 40 steps every
    particle stands where it was laid to round-off; the fluid's box is the scene's, and a
    particle put outside it is removed."""
    from fluid.particles import Kind

    blocks = [Block((0.0, 0.0), (0.2, 0.1)), Block((0.3, 0.0), (0.4, 0.1))]
    scene = Scene(world=World(dim=2, gravity=0.0, duration=0.01, snapshot_every=0), fluid=SPH(dx=0.02, c0=10.0),
                  domain=OpenWater(lo=(-0.5, -0.5), hi=(1.0, 0.5), water=blocks))
    b = build(scene, tmp_path)
    f = b.sph
    assert b.setup.name == "impact" and f.config.domain_lo == (-0.5, -0.5) and f.config.domain_hi == (1.0, 0.5)
    assert not (f.ps.kind != Kind.FLUID).any() and _water_volume(b, 2) == pytest.approx(0.2 * 0.1 + 0.1 * 0.1)
    assert np.all(f.ps.rho == f.config.rho0)
    start = f.ps.pos[np.argsort(f.ps.ids)].copy()
    t = 0.0
    for _ in range(40):
        dt = f.max_dt()
        f.advance(t, dt)
        t += dt
    assert np.abs(f.ps.pos[np.argsort(f.ps.ids)] - start).max() < 1e-12
    f.ps.pos[0] = (1.5, 0.0)  # beyond hi along x
    f.advance(t, f.max_dt())
    assert f.ps.n == len(start) - 1


@pytest.mark.parametrize("dim", [2, 3])
def test_a_body_given_a_velocity_flies_as_a_projectile(dim, tmp_path):
    """A free box given a ``velocity`` and no fluid moves as a projectile under gravity,
    without spin: x = x0 + vx t, z = z0 + vz t - g t^2 / 2, to round-off."""
    g, T = 9.81, 0.5
    v = (1.5, 2.0) if dim == 2 else (1.5, -0.5, 2.0)
    pos = (0.0, 1.0) if dim == 2 else (0.0, 0.0, 1.0)
    box = Box(name="b", size=(0.1,) * dim, pos=pos, density=500.0, velocity=v)
    scene = Scene(world=World(dim=dim, gravity=g, duration=T, snapshot_every=0), fluid=NoFluid(), bodies=[box])
    b = build(scene, tmp_path)
    k = b.bodies.kinematics()
    v3 = np.array([v[0], 0.0, v[1]] if dim == 2 else v)
    np.testing.assert_allclose(k.velocity[0], v3, atol=1e-15)
    b.coupler.run(T)
    k = b.bodies.kinematics()
    p0 = np.array([pos[0], 0.0, pos[1]] if dim == 2 else pos)
    expect = p0 + v3 * T + np.array([0.0, 0.0, -0.5 * g * T * T])
    np.testing.assert_allclose(k.com[0], expect, atol=1e-12)
    np.testing.assert_allclose(k.velocity[0], v3 + np.array([0.0, 0.0, -g * T]), atol=1e-9)
    assert np.abs(k.omega[0]).max() < 1e-12


def test_a_flume_between_symmetry_planes_keeps_its_waves_uniform_across_it(tmp_path):
    """``domain.sides = "symmetry"``: a 3-D flume with no side walls, its floor, paddle and
    far wall across y = 0 .. width, the fluid's symmetry planes at both sides (each particle
    near one has a mirror image); the particle count is the cost estimate's. Its columns
    across y are alike, so a paddle's wave stays uniform across the slice: no particle
    moves along y (a walled slice's water moves along y by its side walls)."""
    from cosim.scene import cost
    from fluid.particles import Kind

    dx, width = 0.03, 0.15
    flume = Flume(length=0.9, depth=0.15, height=0.25, width=width, sides="symmetry")
    scene = Scene(world=W3.replace(duration=0.4, sample_every=0.1), fluid=SPH(dx=dx), domain=flume,
                  waves=Piston(height=0.02, period=0.8))
    b = build(scene, tmp_path)
    ps = b.sph.ps
    real = ps.ids >= 0
    assert (ps.pos[real, 1] > 0.0).all() and (ps.pos[real, 1] < width).all()
    assert (b.sph.config.symmetry_y, b.sph.config.symmetry_y_hi) == (0.0, width)
    water, walls, _ = cost.sph_particles(scene)
    assert int((ps.kind[real] == Kind.FLUID).sum()) == pytest.approx(water, rel=0.02)
    assert int((ps.kind[real] != Kind.FLUID).sum()) == pytest.approx(walls, rel=0.1)
    b.coupler.run(0.4)
    ps = b.sph.ps
    fl = (ps.kind == Kind.FLUID) & (ps.ids >= 0)
    u = np.abs(ps.vel[fl][:, [0, 2]]).max()
    assert u > 0.02  # the paddle's wave
    assert np.abs(ps.vel[fl, 1]).max() < 1e-9 * u
