"""The elastic cantilever (bodies/elastic.py) coupled to the SPH fluid (cosim/sph_fluid.py,
``SPHFluid(elastic=[beam])``): boundary particles on the deformed plate, the fluid's
force on each split between the two links that carry it. Momentum is exchanged exactly,
as for rigid bodies (tests/test_sph_bodies.py, validation case momentum-exchange)."""

import numpy as np
import pytest

from bodies import builders
from bodies.elastic import elastic_beam
from bodies.mujoco_bodies import MujocoBodies
from cosim.coupler import Coupler
from cosim.errors import InputError, InstabilityError
from cosim.sph_fluid import SPHFluid
from fluid.geometry import block, tank_walls
from fluid.particles import Kind
from fluid.solver import FluidConfig

PLATE = dict(length=0.08, thickness=0.012, E=1e6, rho=2500.0, n_elements=8)  # Yang & Li 2020's plate


def blob_on_plate(dim, free_base=False, dx=0.004):
    """No gravity, no walls: a block of water moving at 1 m/s in +x hits the plate
    (clamped at x = 0.3 m, z = 0 to the world, or to a free 3 kg base)."""
    beam = elastic_beam("p", **PLATE, base=(0.3, 0.0, 0.0) if not free_base else (0.0, 0.0, 0.02),
                        width=1.0 if dim == 2 else 0.04)
    xml, names = beam.xml, beam.link_names
    if free_base:
        xml = ('<body name="base" pos="0.3 0 -0.02"><freejoint/><geom type="box" size="0.02 0.02 0.02" '
               'density="3000" contype="0" conaffinity="0"/>' + xml + '</body>')
        names = ["base", *names]
    bodies = MujocoBodies(builders.scene(xml, gravity=0.0), bodies=names)
    lo, hi = ([0.2, 0.0], [0.29, 0.06]) if dim == 2 else ([0.2, -0.02, 0.0], [0.29, 0.02, 0.06])
    cfg = FluidConfig(dim=dim, dx=dx, g=0.0, c0=20.0, domain_lo=(-1.0,) * dim, domain_hi=(2.0,) * dim)
    fluid = SPHFluid(cfg, block(np.array(lo), np.array(hi), dx), elastic=[beam])
    coupler = Coupler(bodies=bodies, fluid=fluid)
    coupler.initialize()
    ps = fluid.fluid.ps
    ps.vel[ps.kind == Kind.FLUID, 0] = 1.0
    fluid.fluid._rates()  # noqa: SLF001 - the rates of the new velocities
    return coupler, bodies, fluid


def fluid_momentum(fluid):
    """Linear momentum (3,) and angular momentum about the origin along y of the fluid."""
    ps = fluid.fluid.ps
    fl = ps.kind == Kind.FLUID
    m, x, v = ps.mass[fl], ps.pos[fl], ps.vel[fl]
    if fluid.config.dim == 2:
        x = np.stack([x[:, 0], 0 * x[:, 0], x[:, 1]], axis=1)
        v = np.stack([v[:, 0], 0 * v[:, 0], v[:, 1]], axis=1)
    return (m[:, None] * v).sum(axis=0), (m[:, None] * np.cross(x, v)).sum(axis=0)[1]


@pytest.mark.parametrize("dim,steps", [(2, 300), pytest.param(3, 20, marks=pytest.mark.long)])
def test_momentum_lost_by_the_fluid_is_what_the_links_receive_to_round_off(dim, steps):
    """Fixed clamp: the fluid's change of linear and angular momentum is minus the impulse
    the coupler booked on the links (the welded foot link's share goes into the clamp),
    to round-off: each particle's force is split between its two links with weights that
    sum to one, each part acting at the particle."""
    coupler, bodies, fluid = blob_on_plate(dim)
    P0, L0 = fluid_momentum(fluid)
    J, K = np.zeros(3), 0.0
    for _ in range(steps):
        kin0 = bodies.kinematics()
        dt = coupler.step(10.0).dt
        led = coupler.ledger.last()
        F, T = led["fluid_force"], led["fluid_torque"]
        J += dt * F.sum(axis=0)
        # MuJoCo applies F at the moving centre of mass: about the origin, over the step,
        # (c0 + V dt / 2) x F + T (the coupler's fluid-first torque is about the moving centre)
        K += dt * (np.cross(kin0.com + 0.5 * dt * kin0.velocity, F) + T).sum(axis=0)[1]
    P, L = fluid_momentum(fluid)
    assert J[0] > 0 and (bodies.kinematics().velocity[:, 0] > 0).any()  # the blow was struck, the plate moves
    # round-off of the fluid's own sums: relative to the momentum it holds
    assert np.abs(P - P0 + J).max() < 1e-13 * np.abs(P0).max()
    assert abs(L - L0 + K) < 1e-13 * abs(L0)
    if dim == 2:
        assert J[1] == 0.0


@pytest.mark.long
def test_clamped_to_a_free_base_fluid_and_structure_keep_their_momentum():
    """The clamp on a free base: its reaction is internal, and fluid + base + links keep
    their total linear momentum to MuJoCo's RK4 truncation (a chain's momentum is not
    linear in its joint velocities, so not to round-off: 5e-10 of the exchange)."""
    coupler, bodies, fluid = blob_on_plate(2, free_base=True)

    def total():
        k = bodies.kinematics()
        return fluid_momentum(fluid)[0], (bodies.masses()[:, None] * k.velocity).sum(axis=0)

    Pf0, Pb0 = total()
    for _ in range(400):
        coupler.step(10.0)
    Pf, Pb = total()
    exchanged = np.abs(Pf - Pf0).max()
    assert exchanged > 1.0
    assert np.abs(Pf + Pb - Pf0 - Pb0).max() < 1e-8 * exchanged


@pytest.mark.long
def test_elastic_plate_validation_quick():
    """The dam break on Yang & Li 2020's plate at dx = 5 mm over 0.3 s (cosim.validations.elastic):
    the corner's peak within 15 % of Idelsohn's 48.3 mm, inside 0.20-0.28 s."""
    from cosim import validation

    r = validation.run("elastic-plate", quick=True)
    assert r["passed"], r["outside_tolerance"]
    assert r["stated"]["met"]
    m = r["metrics"]
    assert 0.20 <= m["peak_t_s"] <= 0.28 and abs(m["peak_rel_err_vs_idelsohn"]) < 0.15
    assert set(m["rms_mm"]) == {"idelsohn_2008_pfem", "bogaers_2016_qn_ls", "liu_2013_sph", "sun_2019_mps_dem"}


def _side_of_plate(fluid, bodies, top_band):
    """For each fluid particle (by id): which side of the plate it is on (its nearest plate
    particle's outward x, as the plate is now) and whether it is free to change side there
    (near the plate's top, where water may go over, or far from the plate)."""
    from scipy.spatial import cKDTree

    e = fluid.elastic[0]
    ps = fluid.fluid.ps
    fl = ps.kind == Kind.FLUID
    kin = bodies.kinematics()
    p = e.place(kin)[0][:, [0, 2]]
    normal = e.rotate(np.tile([1.0, 0.0, 0.0], (e.n, 1)), kin)[:, [0, 2]]
    d, j = cKDTree(p).query(ps.pos[fl])
    right = np.einsum("ij,ij->i", ps.pos[fl] - p[j], normal[j]) > 0
    free = top_band[j] | (d > 3 * fluid.config.dx)
    return dict(zip(ps.ids[fl], right)), dict(zip(ps.ids[fl], free))


@pytest.mark.long
@pytest.mark.parametrize("thickness", [0.01, 0.005])
def test_no_fluid_particle_crosses_a_plate_under_two_spacings_thick(thickness):
    """A dam-break column (0.15 x 0.3 m, dx = 10 mm) strikes a plate one spacing (and half a
    spacing) thick with the thin-wall treatment (two columns of particles, each taking its
    mDBC density from its own side): over 0.3 s no fluid particle passes through the plate
    (water that goes over its top is free to)."""
    dx, g, L = 0.01, 9.81, 0.25
    beam = elastic_beam("w", L, thickness, E=1e9, rho=2500.0, n_elements=8, base=(0.2, 0.0, 0.0), thin_wall=True)
    bodies = MujocoBodies(builders.scene(beam.xml, gravity=g, timestep=min(1e-4, 0.5 * beam.stable_dt())),
                          bodies=beam.link_names)
    walls = [(tank_walls([0.0, 0.0], [0.4, 0.4], dx, 3), Kind.FIXED_WALL, 0)]
    cfg = FluidConfig(dim=2, dx=dx, u_max=np.sqrt(2 * g * 0.3), domain_lo=(-0.05, -0.05), domain_hi=(0.45, 0.8))
    fluid = SPHFluid(cfg, block(np.array([0.0, 0.0]), np.array([0.15, 0.3]), dx), walls, z_surface=0.3,
                     elastic=[beam])
    coupler = Coupler(bodies=bodies, fluid=fluid)
    coupler.initialize()
    e = fluid.elastic[0]
    assert len(np.unique(e.plate[:, 0].round(9))) == 2  # two columns, at +-dx/2
    top = e.plate[:, 2] > L - 2 * dx
    before, _ = _side_of_plate(fluid, bodies, top)
    crossed, hits = set(), 0
    for k in range(1, 151):
        coupler.run(k * 0.002)
        now, free = _side_of_plate(fluid, bodies, top)
        crossed |= {i for i, r in now.items() if i in before and r != before[i] and not free[i]}
        before = now
        hits = max(hits, int(np.abs(coupler.ledger.last()["fluid_force"][:, 0]).sum() > 1.0))
    assert hits  # the flow struck the plate
    assert not crossed, f"{len(crossed)} fluid particles passed through the plate"


def test_a_plate_under_two_spacings_thick_is_refused_without_the_thin_wall_treatment():
    beam = elastic_beam("w", 0.25, 0.012, E=1e9, rho=2500.0, n_elements=8, base=(0.2, 0.0, 0.0))
    bodies = MujocoBodies(builders.scene(beam.xml, gravity=9.81), bodies=beam.link_names)
    cfg = FluidConfig(dim=2, dx=0.01, c0=20.0, domain_lo=(-1.0, -1.0), domain_hi=(1.0, 1.0))
    fluid = SPHFluid(cfg, block(np.array([0.0, 0.0]), np.array([0.1, 0.1]), 0.01), elastic=[beam])
    with pytest.raises(InputError, match=r"elastic plate 'w' is 0.012 m thick, 1 particle\(s\) across.*thin_wall=True"):
        Coupler(bodies=bodies, fluid=fluid).initialize()


def test_a_chain_stepped_beyond_its_stable_step_stops_the_run_naming_its_element():
    """A plate 10^4 times stiffer than Yang & Li 2020's, stepped at the fluid's step (40 times its
    stable RK4 step): MuJoCo resets a blown-up state to the initial pose by itself, which
    the run must not take for a plate at rest."""
    beam = elastic_beam("p", **{**PLATE, "E": 1e10}, base=(0.3, 0.0, 0.0))
    assert beam.stable_dt() < 1e-5
    bodies = MujocoBodies(builders.scene(beam.xml, gravity=0.0, timestep=1e-3), bodies=beam.link_names)
    cfg = FluidConfig(dim=2, dx=0.004, g=0.0, c0=20.0, domain_lo=(-1.0, -1.0), domain_hi=(2.0, 2.0))
    fluid = SPHFluid(cfg, block(np.array([0.2, 0.0]), np.array([0.29, 0.06]), 0.004), elastic=[beam])
    coupler = Coupler(bodies=bodies, fluid=fluid)
    coupler.initialize()
    ps = fluid.fluid.ps
    ps.vel[ps.kind == Kind.FLUID, 0] = 1.0
    fluid.fluid._rates()  # noqa: SLF001
    with pytest.raises(InstabilityError, match=r"body 'p_link\d'"):
        coupler.run(0.05)


PLATE_SCENE = """
[world]
dim = 2
duration = 0.02
sample_every = 0.005
snapshot_every = 0.0

[fluid]
model = "sph"
dx = 0.01

[domain]
kind = "tank"
length = 0.584
height = 0.32
water = [{ lo = [0.0, 0.0], hi = [0.146, 0.292] }]

[[bodies]]
shape = "elastic-plate"
name = "plate"
length = 0.08
thickness = 0.02
E = 1e6
density = 2500.0
base = [0.298, 0.0]
"""


@pytest.mark.long
def test_an_elastic_plate_is_a_scene_body_with_corner_and_tip_probes(tmp_path):
    from cosim.scene import ElasticPlate, Scene

    scene = Scene.from_dict(__import__("tomllib").loads(PLATE_SCENE))
    plate = scene.bodies[0]
    assert isinstance(plate, ElasticPlate) and plate.elements == 8 and plate.pos == (0.298, 0.04)
    assert Scene.from_dict(__import__("tomllib").loads(scene.to_toml())) == scene
    r = scene.run(tmp_path / "out")
    for q in ("corner_x", "corner_z", "tip_x", "tip_z"):
        assert r.units[f"plate.{q}"] == "m" and len(r[f"plate.{q}"]) == 5
    assert "plate.fluid_Fx" in r and not any(n.startswith("plate_link") for n in r.names)
    spans = np.array([0.005] + [0.01] * 7 + [0.005])  # node shares of the 8-element plate [m], width 1 m
    p = np.array([r[f"plate.p{k}"] for k in range(9)])
    assert r.units["plate.p0"] == "Pa" and np.allclose(spans @ p, r["plate.fluid_Fx"], rtol=1e-12, atol=1e-12)
    assert np.abs(r["plate.corner_x"]).max() < 1e-6  # the water has not arrived yet


def test_a_3d_elastic_plate_scene_builds_with_the_plate_across_its_width(tmp_path):
    from cosim.scene import Scene
    from cosim.scene.build import build
    from cosim.scene.probes import groups

    data = __import__("tomllib").loads(PLATE_SCENE)
    data["world"]["dim"] = 3
    data["domain"]["width"] = 0.06
    data["domain"]["water"] = [{"lo": [0.0, 0.0, 0.0], "hi": [0.146, 0.06, 0.292]}]
    data["bodies"][0].update(base=[0.298, 0.03, 0.0], width=0.04)
    scene = Scene.from_dict(data)
    built = build(scene, tmp_path)
    e = built.fluid.elastic[0]
    assert e.dim == 3 and np.ptp(e.plate[:, 1]) == pytest.approx(0.04 - 0.01)  # cell-centred across y
    motion = next(g for g in groups(scene, built) if g.name == "motion")
    assert motion.columns == [f"plate.{s}_{c}" for s in ("corner", "tip") for c in "xyz"]
    assert np.abs(motion.sample()).max() == 0.0


def test_a_hanging_elastic_plate_scene_passes_its_direction_to_the_chain(tmp_path):
    """``direction = "down"``: the chain is clamped at ``base`` (its top) and its boundary
    particles lie between the free end, ``length`` below, and the clamp."""
    from cosim.scene import Scene
    from cosim.scene.build import build

    data = __import__("tomllib").loads(PLATE_SCENE)
    data["bodies"][0].update(base=[0.298, 0.15], direction="down")
    built = build(Scene.from_dict(data), tmp_path)
    assert built.plates["plate"].direction == "down"
    z = built.fluid.elastic[0].place()[0][:, 2]
    assert (z.min(), z.max()) == pytest.approx((0.07 + 0.005, 0.15 - 0.005))  # cell-centred, dx = 0.01 m
