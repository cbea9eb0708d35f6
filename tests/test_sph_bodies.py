"""The SPH fluid loading MuJoCo bodies (cosim.sph_fluid)."""

import math

import numpy as np
import pytest

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from cosim.errors import InputError
from cosim.sph_fluid import SPHFluid
from fluid.geometry import block, tank_walls
from fluid.particles import Kind
from fluid.solver import FluidConfig

G = 9.81


def submerged_box(dx=0.01, L=0.4, H=0.3, D=0.25, box=(0.1, 0.05), centre=(0.2, 0.105)):
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(G * D), c0_factor=20.0)
    walls = [(tank_walls(np.zeros(2), np.array([L, H]), dx, 3), Kind.FIXED_WALL, 0)]
    bodies = MujocoBodies(builders.scene(builders.box("b", box, (centre[0], 0.0, centre[1]), density=2000.0,
                                                      planar=True)))
    f = SPHFluid(cfg, block(np.zeros(2), np.array([L, D]), dx), walls, z_surface=D)
    f.attach_bodies(bodies)
    f.set_body_kinematics(bodies.kinematics())
    f.initialize(0.0)
    return f, bodies


def _held_wrenches(f, bodies, duration: float):
    """Step the fluid ``f`` at its own step for ``duration`` [s] round bodies that stay where
    they are; the first body's force and torque after each step, (steps, 3) each."""
    t, F, T = 0.0, [], []
    while t < duration:
        dt = f.max_dt()
        f.advance(t, dt)
        t += dt
        f.set_body_kinematics(bodies.kinematics())
        a, b = f.body_wrenches()
        F.append(a[0])
        T.append(b[0])
    return np.array(F), np.array(T)


@pytest.mark.long
def test_a_held_submerged_body_feels_archimedes():
    """A box held still under water: vertical force rho g A (per metre), no side
    force, no torque, over 0.1 s of SPH (lattice-aligned box, dx = 1 cm)."""
    f, bodies = submerged_box()
    assert f.removed_overlap == 50  # the 10 x 5 cells of the box, no fluid left inside
    assert f.displaced_volume == pytest.approx(0.1 * 0.05)
    F, T = _held_wrenches(f, bodies, 0.1)
    Fz, Fx, Ty = F[:, 2], F[:, 0], T[:, 1]
    exact = 1000.0 * G * 0.1 * 0.05
    assert np.mean(Fz) == pytest.approx(exact, rel=0.01)
    assert abs(np.mean(Fx)) < 1e-9 * exact and abs(np.mean(Ty)) < 1e-9 * exact


def test_fluid_loads_move_with_the_body_pose():
    """Placing the body's particles from a pose: the group follows the body."""
    f, bodies = submerged_box()
    bodies.data.qpos[0] = 0.05  # slide 5 cm in x
    bodies.initialize(0.0)
    f.set_body_kinematics(bodies.kinematics())
    ps = f.fluid.ps
    sel = ps.group == f._g0
    assert ps.pos[sel, 0].mean() == pytest.approx(0.25, abs=1e-12)
    assert (f.fluid.moment_points[f._g0] == bodies.kinematics().com[0, [0, 2]]).all()


def test_momentum_exchange_validation_quick():
    """Linear and angular momentum of fluid + a free body to round-off with the
    fluid-first scheme; start-of-step loads are not exact."""
    from cosim.validation import run

    r = run("momentum-exchange", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert m["fluid_first"]["linear_drift"] < 1e-12 and m["fluid_first"]["angular_drift"] < 1e-12
    assert m["explicit"]["linear_drift"] > 1e-9
    vx, w = m["fluid_first"]["body_vx_m_s"], m["fluid_first"]["body_omega_rad_s"]
    # the box did exchange momentum with the water (without an exchange the drifts above would
    # be zero trivially): it lost more than a tenth of its speed and was spun. How much it
    # keeps depends on the body boundary (about half), which no reference fixes.
    assert vx[1] < 0.9 * vx[0] and abs(w[1]) > 0.1


def test_a_body_fewer_than_two_particles_across_is_refused_before_any_work():
    """A plate 1.2 cm thick at dx = 1 cm is one particle across (round(1.2) = 1): refused
    at attachment, naming the body, its thickness, dx and the fix, before the fluid is
    built; at 1.5 cm (two across, the minimum) and in 3-D likewise along the thin axis."""
    with pytest.raises(InputError, match=r"body 'b' geom 0 \(box\) is 0\.012 m across along its z axis, 1 "
                                         r"particle\(s\) at dx = 0\.01 m.*at least 2 particles across.*Refine dx "
                                         r"to 0\.006 m or less, or make the body at least 0\.02 m thick"):
        submerged_box(box=(0.1, 0.012))
    cfg = FluidConfig(dim=2, dx=0.01, u_max=1.0)
    f = SPHFluid(cfg, block(np.zeros(2), np.array([0.4, 0.25]), 0.01))
    with pytest.raises(InputError, match="body 'b'"):
        f.attach_bodies(MujocoBodies(builders.scene(builders.box("b", (0.1, 0.012), (0.2, 0, 0.1), density=2000.0,
                                                                 planar=True))))
    assert f.fluid is None  # nothing was built
    f.check_body_resolution(MujocoBodies(builders.scene(builders.box("b", (0.1, 0.015), (0.2, 0, 0.1),
                                                                     density=2000.0, planar=True))))  # 2 across
    f3 = SPHFluid(FluidConfig(dim=3, dx=0.01, u_max=1.0), np.zeros((0, 3)))
    plate = builders.scene(builders.box("plate", (0.1, 0.005, 0.1), (0, 0, 0), density=2000.0))
    with pytest.raises(InputError, match=r"body 'plate' geom 0 \(box\) is 0\.005 m across along its y axis"):
        f3.check_body_resolution(MujocoBodies(plate))
    wedge = ("0 0 0  0.1 0 0  0 0.1 0  0 0 0.005  0.1 0 0.005  0 0.1 0.005")  # a triangular plate, as a mesh
    with pytest.raises(InputError, match=r"body 'w' geom 0 \(mesh\) is 0\.005 m across along its . axis, 1 particle"):
        f3.check_body_resolution(MujocoBodies(f'<mujoco><asset><mesh name="m" vertex="{wedge}"/></asset><worldbody>'
                                              f'<body name="w"><freejoint/><geom type="mesh" mesh="m" mass="1"/>'
                                              f'</body></worldbody></mujoco>'))


def test_a_mesh_box_displaces_the_fluid_of_the_box_geom():
    """A box given as a mesh (MuJoCo's float32 vertices) on lattice planes takes the same
    fluid cells as the box geom (none beside its faces) and the same boundary particles."""
    verts = "0 -0.08 0  0.4 -0.08 0  0.4 0.08 0  0 0.08 0  0 -0.08 0.2  0.4 -0.08 0.2  0.4 0.08 0.2  0 0.08 0.2"
    geom = {"mesh": '<geom type="mesh" mesh="m" mass="1"/>',
            "box": '<geom type="box" size="0.2 0.08 0.1" pos="0.2 0 0.1" mass="1"/>'}
    got = {}
    for kind, g in geom.items():
        b = MujocoBodies(f'<mujoco><asset><mesh name="m" vertex="{verts}"/></asset><worldbody>'
                         f'<body name="b" pos="0.32 0 0.12"><freejoint/>{g}</body></worldbody></mujoco>')
        f = SPHFluid(FluidConfig(dim=3, dx=0.04, u_max=1.0),
                     block(np.array([0.0, -0.2, 0.0]), np.array([1.0, 0.2, 0.4]), 0.04), z_surface=0.4)
        f.attach_bodies(b)
        got[kind] = (f.removed_overlap, f._pb[np.lexsort(f._pb.T)])
    assert got["mesh"][0] == got["box"][0] == 10 * 4 * 5  # the box's 0.4 x 0.16 x 0.2 m in 4 cm cells
    np.testing.assert_allclose(got["mesh"][1], got["box"][1], atol=1e-6)


def _held_box_3d(half: bool, dx=0.025, L=0.3, W=0.3, D=0.2, box=(0.1, 0.1, 0.05), centre=(0.15, 0.0, 0.1),
                 **config):
    """A box held under still water in a 3-D tank across y = -W/2 .. W/2, or (``half``) the
    half y >= 0 of the same particles with a symmetry plane at y = 0 (fluid.mirror);
    ``config``: more FluidConfig fields."""
    cfg = FluidConfig(dim=3, dx=dx, u_max=math.sqrt(G * D), c0_factor=20.0, walls="adami", alpha_wall=0.0,
                      symmetry_y=0.0 if half else None, **config)
    lo, hi = np.array([0.0, -0.5 * W, 0.0]), np.array([L, 0.5 * W, D + 0.1])
    walls, water = tank_walls(lo, hi, dx, 4), block(lo, np.array([L, 0.5 * W, D]), dx)
    if half:
        walls, water = walls[walls[:, 1] > 0], water[water[:, 1] > 0]
    bodies = MujocoBodies(builders.scene(builders.box("b", box, centre, density=2000.0)))
    f = SPHFluid(cfg, water, [(walls, Kind.FIXED_WALL, 0)], z_surface=D)
    f.attach_bodies(bodies)
    f.set_body_kinematics(bodies.kinematics())
    f.initialize(0.0)
    return f, bodies


@pytest.mark.long
def test_a_symmetry_plane_gives_the_whole_body_its_mirrored_half_load():
    """Held under water in 3-D for 0.05 s: the load on the half body (y >= 0, its mirror
    images across y = 0) mirrored across the plane is the whole tank's at every step (the
    same physics, to rounding), with no side force and no roll or yaw moment, near the
    Archimedes force rho g V; on half the fluid particles."""
    runs = {}
    for half in (False, True):
        f, bodies = _held_box_3d(half)
        F, T = _held_wrenches(f, bodies, 0.05)
        runs[half] = (F, T, int((f.fluid.simulated().kind == Kind.FLUID).sum()))
    exact = 1000.0 * G * 0.1 * 0.1 * 0.05
    (Ff, Tf, nf), (Fh, Th, nh) = runs[False], runs[True]
    assert Fh.shape == Ff.shape
    np.testing.assert_allclose(Fh, Ff, rtol=0, atol=1e-6 * exact)
    np.testing.assert_allclose(Th, Tf, rtol=0, atol=1e-6 * exact * 0.1)
    assert (Fh[:, 1] == 0.0).all() and (Th[:, 0] == 0.0).all() and (Th[:, 2] == 0.0).all()
    assert Fh[:, 2].mean() == pytest.approx(exact, rel=0.02)
    assert 2 * nh == nf
    with pytest.raises(InputError, match="symmetry plane"):
        SPHFluid(FluidConfig(dim=3, dx=0.01, u_max=1.0, symmetry_y=0.5), np.zeros((0, 3)))


@pytest.mark.parametrize("half", [False, True])
def test_a_bodys_particle_forces_add_up_to_its_load(half):
    """SPHFluid.body_particle_forces: the force on each of the body's particles, counted as
    often as its load counts it (twice off a symmetry plane, the image's share), sums to
    body_wrenches' force, with the tank's loads off (the body's rows are computed either
    way); the rows are the body's own, inside its box. An odd number across y: the middle
    row lies on the plane, where the pose's round-off must not put it beyond."""
    f, bodies = _held_box_3d(half, box=(0.1, 0.115, 0.05), wall_loads=False)
    _held_wrenches(f, bodies, 0.003)
    x, F, shares = f.body_particle_forces(0)
    want = f.body_wrenches()[0][0]
    got = (shares[:, None] * F).sum(axis=0)
    assert want[2] > 0.5 * 1000.0 * G * 0.1 * 0.1 * 0.05 and np.isfinite(F).all()
    np.testing.assert_allclose(got[[0, 2]], want[[0, 2]], rtol=0, atol=1e-9 * want[2])
    assert sorted(set(shares)) == ([1.0, 2.0] if half else [1.0])
    assert (np.abs(x - [0.15, 0.0, 0.1]) <= [0.1, 0.115, 0.05]).all()
    assert len(x) == (f.fluid.simulated().kind == Kind.BODY).sum()
    with pytest.raises(InputError, match="no rigid body 1"):
        f.body_particle_forces(1)
