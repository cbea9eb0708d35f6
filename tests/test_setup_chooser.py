"""The set-up chooser (``cosim.scene.setup``) is as good as the validation cases' hand-set
set-ups: the rule that tells impulsive wall pressures from sloshing, and every case with a
scene file run with the set-up the chooser picks for its scene
(``cosim.validations.case_scene.auto_setup``), judged against its own quick tolerances."""

import math

import pytest

from cosim import validation
from cosim.scene.setup import IMPULSIVE_PERIODS, choose
from cosim.validations import case_scene


def _first_period(length: float, depth: float, g: float = 9.81) -> float:
    """Linear theory's first sloshing period [s] of a rectangular tank (Ibrahim 2005, §1.2):
    w1^2 = g k tanh(k h), k = pi / L."""
    k = math.pi / length
    return 2 * math.pi / math.sqrt(g * k * math.tanh(k * depth))


def test_the_first_sloshing_period_decides_impulsive_or_sloshing():
    """The westergaard tank (3.0 m, water 1.0 m: T1 = 2.219 s) shaken at 0.03 s is impulsive;
    at a period just above a third of T1 it is sloshing, just below impulsive; the
    sloshing-frequency tank shaken at its own T1 is sloshing."""
    t1 = _first_period(3.0, 1.0)
    assert t1 == pytest.approx(2.2186, abs=1e-4)
    scene = case_scene.load("westergaard", ["fluid.setup=auto"])
    assert choose(scene).name == "impulsive" and "first sloshing period" in choose(scene).reason
    for factor, name in ((1.02, "sloshing"), (0.98, "impulsive")):
        period = case_scene.number(factor * IMPULSIVE_PERIODS * t1)
        assert choose(scene.with_values([f"base_motion.period={period}"])).name == name, factor
    assert choose(case_scene.load("sloshing-frequency")).name == "sloshing"


def test_the_long_period_tanks_slosh():
    """long-period's excitations (Sunara et al. 2021: T = 1.0 s in the 3 m tanks, 0.7 s in the
    cylinder; T / T1 = 0.45, 0.36, 0.42) get "sloshing", the set-up that case runs; the
    vertical-walled tanks shaken at the paper's short periods "impulsive", the inclined one
    "sloshing" still (its slope's pressure grows noisy at h = sqrt(2) dx)."""
    for case, period, fast in (("westergaard", 1.0, "impulsive"), ("inclined-wall", 1.0, "sloshing"),
                               ("cylinder-tank", 0.7, "impulsive")):
        scene = case_scene.chosen(case_scene.load(case))
        assert choose(scene).name == fast, case
        assert choose(scene.with_values([f"base_motion.period={period}"])).name == "sloshing", case


def test_a_record_keeps_the_sloshing_set_up():
    """A ground-motion record has no single period: the arch rib keeps "sloshing"."""
    scene = validation.cases()["arch-rib"].scene(True)
    assert scene.fluid.setup == "auto" and choose(scene).name == "sloshing"


def test_auto_setup_clears_the_hand_set_levers():
    """Under auto_setup a case's scene asks for "auto" with its hand-set walls cleared; a
    code-built case gets the chooser's levers (cylinder-tank: walls "adami", the solver's
    h), outside it its own."""
    assert case_scene.load("cylinder-tank").fluid.walls == "adami"
    assert case_scene.fluid_setup("cylinder-tank", {}) == {}
    with case_scene.auto_setup():
        scene = case_scene.load("cylinder-tank")
        assert scene.fluid.setup == "auto" and scene.fluid.walls is None
        assert case_scene.fluid_setup("cylinder-tank", {}) == {"walls": "adami"}
        assert case_scene.fluid_setup("sloshing-frequency", {})["h_coef"] == 2.0


#: the cases with a scene file whose quick variant runs the SPH fluid, run under auto_setup, by cost
QUICK = ["sinking-cylinder", "floating-box-draft", "sloshing-frequency", "sloshing-spheric10"]
#: the costlier ones, 20-35 CPU-s each: out of CI's time (docs/development.md)
LONG = ["inclined-wall", "floating-heave-period", "moored-body-sph"]
#: the 3-D ones, 2-5 CPU-minutes each under the chooser's set-up (h = 2 dx): out of CI's time
#: (as their quick variants with their own set-up, tests/test_tanks.py)
SLOW = ["cylinder-tank", "inclined-wall-3d"]
#: cases whose quick scene gets the same FluidConfig from "auto" as its own: their quick
#: validation run (``cosim validate NAME --quick``) is the chooser's, so not run again here
SAME = ["westergaard", "westergaard-3d", "hydrostatic", "arch-rib", "elastic-table2", "hydrostatic-3d",
        "nearfield-floating-box", "dambreak-2d", "dambreak-lobovsky", "elastic-plate",
        "nearfield-waves", "long-period", "wave-propagation", "elastic-gate", "momentum-exchange"]
#: SPH cases whose scene sets a lever the chooser does not, and why; not run here
OWN = {"wind-turbine-sph": "h = sqrt(2) dx, the kernel width that holds the base's static draft within 2 % at dx = "
                           "0.5 m, where the chooser's near field takes 2 dx for waves that cross a box several "
                           "wavelengths long; c0 = 5 sqrt(g d), half the steps, measured to hold surge, heave and "
                           "tensions at dx = 1.0 m; its quick variant costs about 20 CPU-minutes",
       "nearfield-radiation": "alpha = 0 and a laminar nu = 0.005 m^2/s: the reference is inviscid potential flow, "
                              "and the near field's alpha = 0.002 read as 12 % more damping (4 % with the laminar "
                              "term); the chooser's run, the session-45 record, met the quick tolerances (B33 "
                              "+12.1 %) (docs/validation/nearfield.md, 'The viscosity round the body')",
       "floating-box-waves": "the reference's set-up (Hadzic et al. 2005 as DualSPHysics runs it): h = 1.70 dx, its "
                             "kinematic artificial viscosity, none against the walls, each measured against the "
                             "defaults in docs/validation/floating-box-waves_history.md; the chooser's wave set-up "
                             "is not measured on this packet"}
#: the cases with a scene file whose quick variant runs another fluid, or none
OTHER_FLUID = {"wind-turbine-moorings", "potential-hemisphere", "moored-body", "potential-irregular",
               "potential-cylinder-rao", "shaken-cantilever", "catenary-johanning-2007", "catenary-johanning-2006",
               "catenary-two-lines", "cable-vs-catenary", "cable-exp2-static", "cable-exp2-shake", "cable-case1",
               "cable-free-fall", "catenary-limits"}


def _run_auto(name: str):
    with case_scene.auto_setup():
        rec = validation.run(name, quick=True)
    assert rec["passed"], (name, rec["outside_tolerance"], {k: rec["metrics"].get(k) for k in rec["tolerances"]})


@pytest.mark.long
@pytest.mark.parametrize("name", QUICK)
def test_auto_setup_meets_the_quick_tolerance(name):
    _run_auto(name)


@pytest.mark.slow  # out of CI's time (docs/development.md)
@pytest.mark.parametrize("name", LONG)
def test_auto_setup_meets_the_quick_tolerance_long(name):
    _run_auto(name)


@pytest.mark.slow
@pytest.mark.parametrize("name", SLOW)
def test_auto_setup_meets_the_quick_tolerance_slow(name):
    _run_auto(name)


@pytest.mark.parametrize("name", SAME)
def test_the_quick_scene_already_runs_the_choosers_set_up(name):
    """The chooser gives the quick scene, asked for "auto" with its levers cleared, the
    FluidConfig settings the scene has (hydrostatic-3d asks for "still" by name)."""
    scene = validation.cases()[name].scene(True)
    assert choose(case_scene.chosen(scene)).config == choose(scene).config


def test_every_sph_case_with_a_scene_file_is_checked():
    files = {n for n, p in validation.case_scenes().items() if p is not None}
    assert files == set(QUICK) | set(LONG) | set(SLOW) | set(SAME) | set(OWN) | OTHER_FLUID
    assert all(validation.cases()[n].scene(True).fluid.model != "sph" for n in OTHER_FLUID)
    for name in OWN:
        scene = validation.cases()[name].scene(True)
        assert choose(case_scene.chosen(scene)).config != choose(scene).config, name


def test_a_flume_at_twenty_rows_or_more_takes_the_wider_kernel():
    """Waves in a flume (the nearfield-floating-box case's, 0.3 m deep) take h = 2.5 dx from
    20 particle rows over the depth (fluid.solver.travelling_waves: the decay per wavelength
    halves from 10 to 20 rows), h = 2 dx below; a near field keeps h = 2 dx at any spacing
    (a wave crosses its box in a wavelength or two); a scene's own h_coef overrides both."""
    from fluid.solver import FINE_WAVES, TRAVELLING_WAVES

    flume = case_scene.load("nearfield-floating-box")
    for dx, want in ((0.02, TRAVELLING_WAVES), (0.015, FINE_WAVES), (0.01, FINE_WAVES)):
        s = choose(flume.with_values([f"fluid.dx={dx}"]))
        assert s.name == "waves" and all(s.config[k] == v for k, v in want.items()), dx
        assert ("h = 2.5 dx" in s.reason) == (want is FINE_WAVES)
    near = flume.with_values(["fluid.dx=0.01", "domain.kind=nearfield", "waves.kind=regular", "waves.depth=0.3"])
    assert choose(near).config["h_coef"] == 2.0
    assert choose(flume.with_values(["fluid.dx=0.01", "fluid.h_coef=1.8"])).config["h_coef"] == 1.8
