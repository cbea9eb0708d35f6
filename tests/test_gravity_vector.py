"""Gravity as a vector (``world.gravity``, ``FluidConfig(g=(gx, gz))``): one value for
every participant.

- SPH: a tank and its water turned by 30 degrees with gravity turned with them is the same
  tank at rest: the pressure rises along g at rho0 |g| (hydrostatics, p = rho0 |g| d with d
  the depth along g) and not across it, and the water stays still (the Fourtakas
  diffusion's hydrostatic part taken along g; taken along z alone the turned water flows).
- MuJoCo: a free body falls along g, x(t) = x0 + g t^2 / 2.
- What assumes gravity along -z is refused with a tilted one, naming the field.
"""

import math

import numpy as np
import pytest

from cosim.scene import Box, Scene, SceneError, World

G = 9.81


def turned_tank(angle_deg, t_end):
    """A 2-D tank 0.2 m long filled 0.1 m deep (dx = 0.01 m), turned by ``angle_deg`` about
    the origin (the walls, the water and gravity together), run for ``t_end`` [s]; the
    fluid's pressure, its positions and largest speed, and the unit vector along g."""
    from fluid.equations import hydrostatic_density
    from fluid.geometry import tank_with_water
    from fluid.particles import Kind
    from fluid.solver import Fluid, FluidConfig

    depth, a = 0.1, math.radians(angle_deg)
    rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    down = rot @ np.array([0.0, -1.0])
    cfg = FluidConfig(dim=2, dx=0.01, u_max=math.sqrt(G * depth), c0_factor=20.0, g=tuple(G * down))
    ps = tank_with_water(2, 0.01, 0.2, depth, 0.125, layers=3).particles
    ps.rho[:] = hydrostatic_density(depth - ps.pos[:, 1], cfg.rho0, cfg.speed_of_sound, cfg.gamma, G)
    ps.pos[:] = ps.pos @ rot.T
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    f.advance(0.0, t_end)
    fl = f.ps.kind == Kind.FLUID
    return f.ps.p[fl], f.ps.pos[fl], float(np.abs(f.ps.vel[fl]).max()), down


def fit(p, pos, down):
    """``(a, b)`` of p = p0 + a (r . e_g) + b (r . e_perp) [Pa/m] over the fluid more than
    3 spacings below the surface (away from the kernel it truncates)."""
    across = np.array([-down[1], down[0]])
    A = np.stack([np.ones(len(p)), pos @ down, pos @ across], axis=1)
    deep = (pos @ down) > (pos @ down).min() + 0.03
    (_, a, b), *_ = np.linalg.lstsq(A[deep], p[deep], rcond=None)
    return a, b


@pytest.mark.long
def test_a_turned_tank_under_turned_gravity_is_the_straight_tank_turned():
    """After 1 s (~5 sloshing periods) the straight tank's pressure rises along g at rho0 g
    within 2 % (the lattice's quadrature error, +1.2 %), and the tank turned by 30 degrees
    with its gravity is the straight one turned: the same gradient along g to 1e-9, none
    across it (below 1e-9 of it), still water (largest speed below 1e-3 sqrt(g H)).
    Measured with the Fourtakas term's hydrostatic part along z alone: a gradient 3 % low,
    1.7 % of it across g, speeds 3e-3 sqrt(g H)."""
    a0, b0 = fit(*turned_tank(0.0, 1.0)[:2], np.array([0.0, -1.0]))
    p, pos, vmax, down = turned_tank(30.0, 1.0)
    a, b = fit(p, pos, down)
    assert a0 == pytest.approx(1000.0 * G, rel=0.02) and abs(b0) < 1e-9 * a0
    assert a == pytest.approx(a0, rel=1e-9) and abs(b) < 1e-9 * a
    assert vmax < 1e-3 * math.sqrt(G * 0.1)


def test_world_gravity_reads_as_a_number_or_a_vector():
    w = World(dim=2, gravity=(0.0, -9.81))  # along -z: kept as the number
    assert w.gravity == 9.81 and not w.tilted and w.g_vector == (0.0, 0.0, -9.81)
    w = World(dim=2, gravity=(3.0, -4.0))
    assert w.tilted and w.g == pytest.approx(5.0) and w.g_down == 4.0 and w.g_vector == (3.0, 0.0, -4.0)
    assert w.tilt_deg == pytest.approx(math.degrees(math.atan2(3.0, 4.0)))
    assert World(dim=3, gravity=(0.0, 1.0, 0.0)).g_vector == (0.0, 1.0, 0.0)
    with pytest.raises(SceneError, match=r"World\.gravity: .*3 components; a 2-D scene's gravity is \(gx, gz\)"):
        World(dim=2, gravity=(0.0, 0.0, -9.81))
    with pytest.raises(SceneError, match=r"World\.gravity: .*beyond 980\.665"):
        World(dim=2, gravity=(1000.0, 0.0))


@pytest.mark.parametrize("g", [(3.0, -4.0), (3.0, 2.0, -4.0)])
def test_a_body_falls_along_g(g, tmp_path):
    """No fluid: a free box under g is at x0 + g t^2 / 2 after 0.5 s (2-D: g = (gx, gz))."""
    from cosim.scene.build import build

    dim = len(g)
    scene = Scene(world=World(dim=dim, duration=0.5, gravity=g),
                  bodies=[Box("b", size=(0.1,) * dim, density=500.0, pos=(0.0,) * (dim - 1) + (1.0,))])
    built = build(scene, tmp_path)
    built.coupler.run(0.5)
    g3 = (g[0], 0.0, g[1]) if dim == 2 else g
    np.testing.assert_allclose(built.bodies.kinematics().com[0], np.array([0.0, 0.0, 1.0]) + 0.125 * np.array(g3),
                               rtol=0, atol=1e-9)


def test_the_sph_fluid_takes_a_vector_of_its_dimension():
    from cosim.errors import InputError
    from fluid.solver import FluidConfig

    c = FluidConfig(dim=3, dx=0.01, c0=10.0, g=[1, 2, -9])
    assert c.g == (1.0, 2.0, -9.0) and c.g_down == 9.0 and c.g_magnitude == pytest.approx(math.sqrt(86.0))
    assert FluidConfig(dim=2, dx=0.01, c0=10.0).gravity3.tolist() == [0.0, 0.0, -9.81]
    with pytest.raises(InputError, match=r"give gravity as 2 finite components"):
        FluidConfig(dim=2, dx=0.01, c0=10.0, g=(0.0, 0.0, -9.81))


def test_the_coupler_refuses_a_fluid_and_bodies_that_fall_different_ways():
    """One gravity for every participant: an SPH fluid under (1, -9.81) and MuJoCo bodies
    under 9.81 along -z are refused when coupled, each vector named."""
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler
    from cosim.errors import ConfigurationError
    from cosim.sph_fluid import SPHFluid
    from fluid.geometry import block
    from fluid.solver import FluidConfig

    cfg = FluidConfig(dim=2, dx=0.02, c0=20.0, g=(1.0, -9.81), domain_lo=(-1.0, -1.0), domain_hi=(2.0, 2.0))
    fluid = SPHFluid(cfg, block(np.zeros(2), np.array([0.2, 0.1]), 0.02))
    box = builders.box("b", (0.1, 0.1), (1.0, 0.0, 1.0), planar=True, density=500.0)
    for g, ok in (((1.0, 0.0, -9.81), True), (9.81, False)):
        coupler = Coupler(bodies=MujocoBodies(builders.scene(box, gravity=g)), fluid=fluid)
        if ok:
            coupler.initialize()
            continue
        with pytest.raises(ConfigurationError, match=r"fluid 'fluid' has gravity \[1\.0, -9\.81\] m/s\^2, bodies .* "
                           r"\[0\.0, 0\.0, -9\.81\]"):
            coupler.initialize()


def test_an_sph_tank_under_a_tilted_gravity_gives_every_participant_the_vector(tmp_path):
    """A 2-D tank, 0.1 m of water, g = (1, -9.81) m/s^2, a box at rest in the air above the
    water: the water starts at rest under the tilted gravity (the level fill's particles, its
    surface turned normal to g: rising 1 / 9.81 m per metre along x), the fluid and the
    bodies take the same vector (the coupler checks it), and over the first 0.05 s the box
    falls along g (x = g_x t^2 / 2 to 1e-6, before it reaches the water) while the water
    keeps its place (its mean speed along x under a fifth of g_x t; started level, as before,
    it ran at 0.76 g_x t; what moves is the surface's lattice steps, one row every ten
    columns, settling)."""
    from cosim.scene import SPH, Tank
    from cosim.scene.build import build, domain_points
    from fluid.particles import Kind

    scene = Scene(world=World(dim=2, duration=0.05, gravity=(1.0, -9.81)), fluid=SPH(dx=0.02),
                  domain=Tank(length=0.6, height=0.4, depth=0.1),
                  bodies=[Box("b", size=(0.1, 0.05), density=500.0, pos=(0.3, 0.3))])
    built = build(scene, tmp_path)
    assert not any("not at rest" in w for w in built.warnings)
    fluid = built.fluid.fluid
    np.testing.assert_array_equal(fluid.config.gravity, [1.0, -9.81])
    np.testing.assert_array_equal(built.bodies.model.opt.gravity, [1.0, 0.0, -9.81])
    fl = fluid.ps.kind == Kind.FLUID
    level = Scene(world=World(dim=2, duration=0.05), fluid=SPH(dx=0.02), domain=Tank(length=0.6, height=0.4, depth=0.1))
    assert fl.sum() == len(domain_points(level, fluid.config)[0])  # the same water
    pos = fluid.ps.pos[fl]
    cols = np.round(pos[:, 0] / 0.02).astype(int)
    tops = np.array([[pos[cols == c, 0].mean(), pos[cols == c, 1].max()] for c in np.unique(cols)])
    slope = np.polyfit(tops[:, 0], tops[:, 1], 1)[0]
    assert slope == pytest.approx(1.0 / 9.81, rel=0.15)
    built.coupler.run(0.05)
    x = built.bodies.kinematics().com[0]
    assert x[0] - 0.3 == pytest.approx(0.5 * 1.0 * 0.05**2, rel=1e-6)
    assert x[2] - 0.3 == pytest.approx(-0.5 * 9.81 * 0.05**2, rel=1e-6)
    assert abs(fluid.ps.vel[fl, 0].mean()) < 0.2 * 1.0 * 0.05


def test_tilted_water_blocks_are_warned_of_and_a_tank_too_low_for_the_tilt_refused(tmp_path):
    """Explicit water blocks start as given (level) under a tilted gravity, with a warning;
    a tank whose water, turned normal to the tilted gravity, would stand over its walls is
    refused when the scene is made, naming world.gravity and the fields that fix it."""
    from cosim.errors import InputError
    from cosim.scene import SPH, Block, Tank
    from cosim.scene.build import build

    blocks = Scene(world=World(dim=2, duration=0.01, gravity=(1.0, -9.81)), fluid=SPH(dx=0.02),
                   domain=Tank(length=0.6, height=0.4, water=[Block(lo=(0.0, 0.0), hi=(0.2, 0.1))]))
    assert any("water blocks start as given" in w and "not at rest" in w for w in build(blocks, tmp_path / "b").warnings)
    with pytest.raises(InputError, match=r"world.gravity: .*stands 0.2529 m high at the tank's wall.*domain.height"):
        Scene(world=World(dim=2, duration=0.01, gravity=(5.0, -9.81)), fluid=SPH(dx=0.02),
              domain=Tank(length=0.6, height=0.2, depth=0.1))
