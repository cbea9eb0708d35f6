"""The inclined-wall tank of Sunara et al. 2021, §3.2: the exact impulsive pressure of the finite tank
(cosim.validations.tank_potential) against the closed forms and the refdata table, and the
validation case's quick run."""

import numpy as np
import pytest

from cosim import validation
from cosim.validations.sloshing import westergaard_series
from cosim.validations.tank_potential import impulsive_pressure, wall_profiles
from cosim.validations.tanks import ANGLES, chwang_profile, cylinder_series, petrov_moiseev


def test_the_vertical_tank_is_westergaards_finite_tank_series_converging_at_first_order():
    errs = []
    for nz in (30, 60, 120):
        w = wall_profiles(3.0, 1.0, 0.0, nz)
        exact = westergaard_series(1.0 - w["z"], 1.0, 3.0)
        errs.append(np.abs(w["left"] - exact).max())
        np.testing.assert_allclose(w["right"], w["left"], atol=1e-10)  # antisymmetric pressure, equal k_p
    assert errs[-1] < 1e-3
    rate = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all(rate > 0.9), rate  # the free-surface corner limits it to first order in the max norm


@pytest.mark.parametrize("beta", ANGLES)
def test_a_long_reservoir_reproduces_chwangs_table(beta):
    """L = 12 H is Chwang's semi-infinite reservoir (the far wall's modes decay as
    exp(-pi L / 2H)); 60 elements over the depth reproduce the table to 2e-4; the 3 m
    tank's face carries less (the far wall's pressure of opposite sign)."""
    y, cp = chwang_profile(beta)
    long = wall_profiles(12.0, 1.0, beta, 60)
    np.testing.assert_allclose(np.interp(y, long["z"], long["right"]), cp, atol=2.5e-4)
    tank = wall_profiles(3.0, 1.0, beta, 60)
    low = cp[0] - np.interp(0.0, tank["z"], tank["right"])
    assert 0.005 < low < 0.03


def test_the_pressure_is_harmonic_and_vanishes_at_the_surface():
    nodes, kp, nz, nx = impulsive_pressure(3.0, 1.0, 30.0, nz=40)
    top = nodes[:, 1] == 1.0
    assert np.all(kp[top] == 0.0) and top.sum() == nx + 1
    # discrete mean-value check away from the walls: the 5-point mean of a harmonic field on
    # a mapped grid row is its centre value to O(h^2)
    grid = kp.reshape(nz + 1, nx + 1)
    j, i = nz // 2, nx // 2
    mean = 0.25 * (grid[j - 1, i] + grid[j + 1, i] + grid[j, i - 1] + grid[j, i + 1])
    assert mean == pytest.approx(grid[j, i], abs=1e-3)
    with pytest.raises(ValueError):
        impulsive_pressure(3.0, 1.0, 90.0)


@pytest.mark.long
def test_inclined_wall_quick():
    r = validation.run("inclined-wall", quick=True)
    m = r["metrics"]
    assert r["passed"] and r["target"].startswith("quick: ")  # judged by its declared tolerances (0.06)
    assert r["stated"]["tolerances"] == {f"rms_right_vs_chwang_{b:g}": 0.04 for b in ANGLES}
    assert all(m[f"rms_right_vs_chwang_{b:g}"] < 0.06 for b in ANGLES)
    for b in ANGLES:
        assert m[f"kp_out_of_phase_max_{b:g}"] < 0.05  # the impulsive pressure follows the acceleration
        assert m[f"rms_left_vs_tank_{b:g}"] < 0.06  # the vertical side of the same tank
    # the steeper the face, the less it carries (Chwang; ours)
    assert m["kp_max_right_15"] > m["kp_max_right_30"] > m["kp_max_right_45"]


def test_the_cylinder_series_and_petrov_moiseev():
    """The exact series tends to Westergaard's for a wide tank, and on the paper's tank
    (R = 1 m, h = 0.6 m) Petrov-Moiseev's Ritz profile is 0.15 kPa RMS from it at 0.5 g
    (2.53 against 2.41 kPa at the bottom; docs/VALIDATION.md)."""
    z = np.linspace(0.0, 0.6, 61)
    np.testing.assert_allclose(cylinder_series(z, 0.6, 1e3), westergaard_series(0.6 - z, 0.6), atol=2e-4)
    scale = 1000.0 * 0.5 * 9.81 * 0.6
    assert scale * cylinder_series([0.0], 0.6, 1.0)[0] == pytest.approx(2423.3, abs=1.0)
    assert scale * petrov_moiseev([0.0], 0.6, 1.0)[0] == pytest.approx(2532.9, abs=1.0)
    assert petrov_moiseev([0.6], 0.6, 1.0)[0] == 0.0
    rms = np.sqrt(np.mean((cylinder_series(z, 0.6, 1.0) - petrov_moiseev(z, 0.6, 1.0)) ** 2)) * scale
    assert rms == pytest.approx(147.1, abs=1.0)
    # a narrower tank carries less (the water can flow round)
    assert cylinder_series([0.0], 0.6, 0.3)[0] < cylinder_series([0.0], 0.6, 1.0)[0]


def test_the_cylinders_bottom_pressure_and_petrov_moiseevs_eq_21():
    """The bottom's exact pressure meets the wall's at the corner, tends near the wall of a
    wide tank to Westergaard's reservoir bottom, sum 2 (-1)^n / a_n^2 exp(-a_n s / h) at a
    distance s from the wall, and vanishes on the axis; Eq. 21 meets Eq. 20 at the corner."""
    from cosim.validations.tanks import cylinder_bottom_series, petrov_moiseev_bottom

    assert cylinder_bottom_series([1.0], 0.6, 1.0)[0] == pytest.approx(cylinder_series([0.0], 0.6, 1.0)[0], rel=1e-12)
    assert petrov_moiseev_bottom([1.0], 0.6, 1.0)[0] == pytest.approx(petrov_moiseev([0.0], 0.6, 1.0)[0], rel=1e-12)
    assert cylinder_bottom_series([0.0], 0.6, 1.0)[0] == 0.0 and petrov_moiseev_bottom([0.0], 0.6, 1.0)[0] == 0.0
    s = np.array([0.0, 0.3, 0.6, 1.2])
    a = (2 * np.arange(400) + 1) * np.pi / 2
    reservoir = (2 * (-1.0) ** np.arange(400) / a**2 * np.exp(-np.outer(s / 0.6, a))).sum(axis=1)
    np.testing.assert_allclose(cylinder_bottom_series(1e3 - s, 0.6, 1e3), reservoir, atol=3e-4)
    assert reservoir[0] == pytest.approx(0.742, abs=1e-3)  # Westergaard's k_p at the base


@pytest.mark.slow  # 3-D, 1-2 CPU-minutes: out of CI's time (docs/development.md); the 2-D inclined tank stays
def test_cylinder_tank_quick():
    r = validation.run("cylinder-tank", quick=True)
    m = r["metrics"]
    assert r["passed"] and r["target"].startswith("quick: ")
    # the stated target is against Petrov-Moiseev, itself 0.15 kPa RMS from the exact series: kept with its value
    assert r["stated"]["tolerances"] == {"rms_kpa_plane_vs_petrov_moiseev": 0.127} and r["stated"]["met"] is False
    assert r["departure"]["criterion"].startswith("the wall's hydrodynamic pressure on the x-z plane against the exact")
    assert m["rms_kpa_petrov_moiseev_vs_exact"] > 0.127
    # the bottom along x (Eq. 21's place): ours against the exact series (measured 0.024 kPa at dx = 0.1 m), and
    # Petrov-Moiseev's Eq. 21, 0.14 kPa from it
    assert m["rms_kpa_bottom_vs_exact"] < 0.1 < m["rms_kpa_petrov_moiseev_bottom_vs_exact"]
    assert abs(m["p_base_rel_err"]) < 0.06 and m["rms_kpa_plane_vs_exact"] < 0.35
    assert r["particles"] > 5000


@pytest.mark.slow  # 3-D, a minute of CPU: out of CI's time (docs/development.md); the 2-D tank stays
def test_inclined_wall_3d_quick():
    """The 45 deg tank as a 3-D slice (3 rows, dx = 0.1 m, c0 = 700 m/s, 1 + 1 periods):
    k_p up the inclined face within the stated 0.04 of Chwang and within 0.04 of the 2-D
    section run with the same settings (measured 0.020, 0.018; the section 0.007)."""
    r = validation.run("inclined-wall-3d", quick=True)
    m = r["metrics"]
    assert r["passed"] and r["target"].startswith("quick: ")
    assert r["stated"]["met"] is None  # 15 and 30 deg are the full variant's
    assert m["width_m"] == pytest.approx(0.3) and r["particles"] > 5000
    assert m["rms_right_vs_chwang_45"] < 0.04 and m["kp_right_vs_2d_max_45"] < 0.04
    assert m["kp_left_vs_2d_max_45"] < 0.04  # the vertical side of the same slice
    assert m["kp_out_of_phase_max_45"] < 0.05  # the impulsive pressure follows the acceleration


def test_the_3d_slice_refuses_an_even_row_count():
    from cosim.validations.tanks import run_inclined

    with pytest.raises(ValueError, match="rows"):
        run_inclined(45.0, 0.1, dim=3, rows=2)


@pytest.mark.parametrize("beta", ANGLES)
def test_the_3d_slices_patch_lies_on_the_slope_and_its_section_is_the_same_tank(beta):
    """inclined-wall-3d's scene at each angle: the slope patch centred on the inclined face
    (x = L + z tan(beta)) with its normal into the water, perpendicular to the face; its
    2-D section the same tank, shaking and fluid in the x-z plane, the patch taken to it."""
    import math

    from cosim.validations.case_scene import section
    from cosim.validations.tanks import inclined_3d_scene

    for quick in (True, False):
        scene = inclined_3d_scene(quick, beta)
        d, (p,) = scene.domain, scene.probes.pressure
        b = math.radians(beta)
        assert d.angle == beta and d.width == pytest.approx(3 * scene.fluid.dx)
        x, y, z = p.centre
        assert x == pytest.approx(d.length + z * math.tan(b), abs=1e-11) and y == pytest.approx(0.5 * d.width)
        n = np.array(p.normal)
        assert np.linalg.norm(n) == pytest.approx(1.0, abs=1e-11) and n[0] < 0 < n[2]
        assert n @ [math.sin(b), 0.0, math.cos(b)] == pytest.approx(0.0, abs=1e-11)  # along the face: none
        sec = section(scene)
        assert sec.world.dim == 2 and sec.domain.width is None
        assert (sec.domain.angle, sec.domain.length, sec.domain.depth, sec.domain.height) == \
            (d.angle, d.length, d.depth, d.height)
        assert sec.base_motion.direction == (1.0, 0.0) and sec.fluid == scene.fluid
        assert sec.probes.pressure[0].centre == (x, z) and sec.probes.pressure[0].normal == (n[0], n[2])


@pytest.mark.slow
def test_inclined_wall_3d_full():
    """dx = 0.05 m, a 0.15 m slice, c0 = 1430 m/s, 1 + 1 periods, at 15, 30, 45 deg: the
    stated target (RMS < 0.04 against Chwang) at each angle (measured 2026-11-25: 0.038 /
    0.025 / 0.0078; see the case's docstring)."""
    r = validation.run("inclined-wall-3d")
    m = r["metrics"]
    assert r["passed"] and all(m[f"rms_right_vs_chwang_{b:g}"] < 0.04 for b in ANGLES)
    assert m["kp_max_right_15"] > m["kp_max_right_30"] > m["kp_max_right_45"]


@pytest.mark.parametrize("name", ["westergaard-3d", "cylinder-tank"])
def test_the_packaged_scenes_are_the_full_variants_set_ups(name):
    """``cosim/validations/scenes/{westergaard-3d,cylinder-tank}.toml`` (``cosim run``-able)
    carry the full variants' tank, shaking, resolution, speed of sound, walls and periods:
    the defaults of :func:`run_westergaard` / :func:`run_cylinder` and the cases' own
    arguments (dx = 0.05 m; 1 + 1 and 2 + 3 periods; 40 samples a period)."""
    import inspect

    from cosim.scene.toml_io import read_toml
    from cosim.validations.sloshing import run_westergaard
    from cosim.validations.tanks import run_cylinder
    from cosim.validations.trade import SCENES

    sc = read_toml(SCENES / f"{name}.toml")
    fn, periods = (run_westergaard, 2) if name == "westergaard-3d" else (run_cylinder, 5)
    d = {k: p.default for k, p in inspect.signature(fn).parameters.items()}
    if name == "westergaard-3d":
        dims = (sc.domain.length, sc.domain.width, sc.domain.height, sc.domain.depth)
        assert dims == (d["length"], d["width"], d["height"], d["H"])
    else:
        assert (sc.domain.diameter, sc.domain.height, sc.domain.depth) == (d["diameter"], d["height"], d["depth"])
    assert sc.world.dim == 3 and sc.fluid.dx == 0.05 and sc.fluid.c0 == d["c0"] and sc.fluid.walls == "adami"
    assert sc.base_motion.acceleration == pytest.approx(d["a0"], rel=1e-3) and sc.base_motion.period == d["Tp"]
    assert sc.world.duration == pytest.approx(periods * d["Tp"])
    assert sc.world.sample_every == pytest.approx(d["Tp"] / d["samples_per_period"])
