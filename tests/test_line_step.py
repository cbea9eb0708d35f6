"""The coupling step the bodies can follow their mooring lines at (cosim.line_step): the
derived bound against the measured instability threshold on a body on one stiff line and
on Barreiro et al. 2016's wind-turbine base, the coupler choosing it when no step is given, and a
given step above it refused."""

import math
from pathlib import Path

import numpy as np
import pytest

from cosim.errors import InstabilityError
from cosim.scene import Analytic, Box, Coupling, Line, Moorings, Probes, Scene, SceneError, World

WT = Path(__file__).resolve().parents[1] / "examples" / "wind_turbine_base.toml"
RHO, G = 1025.0, 9.81
EA, MPL, D = 1.4e9, 10.0, 0.05  # a stiff line: 1.4e9 N, 10 kg/m, 5 cm


def tension_leg(dt=None, duration=3.0, lines="explicit"):
    """A 2 x 4 m box (7.2 t, 7.2 t added mass in heave) held 0.3 m deeper than it floats by
    one vertical line 6.8 m long (EA / L = 2.1e8 N/m, pretension 3.8 kN): a body on a
    spring, omega = sqrt(k / M) = 120 rad/s (the hydrostatic 2e4 N/m is 0.01 % of it).
    ``lines``: the coupler's exchange with the line (the bound is derived for "explicit")."""
    w = (MPL - RHO * math.pi / 4 * D * D) * G
    M, sub, chord = 7200.0, 3.7, 6.8
    pre = (RHO * 2.0 * sub - M) * G
    L = chord / (1 + (pre + 0.5 * w * chord) / EA)
    return Scene(name="tension_leg", world=World(dim=2, duration=duration, sample_every=5 * dt if dt else 0.05),
                 fluid=Analytic(rho=RHO, added_mass={"box": [0.0, 7200.0, 0.0]}),
                 bodies=[Box("box", size=(2.0, 4.0), pos=(0.0, -1.7), density=900.0, fairleads={"f": (0.0, -2.0)})],
                 moorings=Moorings(model="moordyn", segments=10,
                                   lines=[Line("box.f", anchor=(0.0, -10.5), length=L, weight=w, EA=EA,
                                               mass_per_length=MPL, diameter=D)]),
                 probes=Probes(loads=False), coupling=Coupling(dt=dt, body_timestep=1e-3, lines=lines))


def _swing(res, after):
    """Largest departure of the line's tension from its mean after ``after`` [s], over the mean."""
    t = res["box.f.tension"][res.t >= after]
    return float(np.abs(t - t.mean()).max() / t.mean())


@pytest.mark.long
def test_the_spring_bound_is_within_a_factor_two_of_where_a_body_on_a_stiff_line_goes_unstable(tmp_path,
                                                                                                monkeypatch):
    """The bound 2 / omega (omega from MuJoCo's mass matrix, the added mass and EA / L) and the
    coupler's step, half of it: at that step the run is steady (tension within 1e-6 of its
    mean), at 2 / omega the body and the line swing (the threshold measured by a sweep, see
    cosim.line_step: 0.0125-0.013 s against 2 / omega = 0.0167 s), so the bound lies within a
    factor 2 of the threshold, above it, and the chosen step below it."""
    pytest.importorskip("moordyn")
    import cosim.line_step as ls
    from cosim.scene.build import build

    lim = build(tension_leg(), tmp_path / "b").coupler.line_limit
    k, M = EA / 6.8, 14400.0
    assert lim.term == "spring" and lim.omega == pytest.approx(math.sqrt(k / M), rel=0.01)
    assert lim.dt == pytest.approx(0.5 * 2 / lim.omega, rel=1e-12)
    chosen = tension_leg(duration=3.0).run(tmp_path / "auto")
    assert chosen.summary["steps"] >= 3.0 / lim.dt and _swing(chosen, 1.0) < 1e-6
    monkeypatch.setitem(ls.SAFETY, "spring", 1.0)  # let a step at the bound itself through
    at_bound = tension_leg(dt=2 / lim.omega).run(tmp_path / "bound")
    assert _swing(at_bound, 2.0) > 0.1  # unstable: growing swings of more than 10 % of the pretension


@pytest.mark.long
def test_the_sub_iterated_exchange_holds_a_body_on_a_stiff_line_at_one_and_a_half_times_the_bound(tmp_path,
                                                                                                   monkeypatch):
    """The same box, the line advanced with the body until its mean force over each step is
    the force the body was given (lines="subiterate"): the trapezoid rule on the line's
    force, which neither adds nor takes energy, so the start's 5 micrometre ringing of the
    19 Hz mode on the line (a tenth of the pretension) decays only by the line's own damping
    (to 0.25 in 6 s at 0.004 s), at every step; at 1.5 x the explicit exchange's bound 2 /
    omega (0.025 s, where that exchange grows beyond a tenth of the pretension) it does not
    grow either: the swing over the last second is below the one over the first."""
    pytest.importorskip("moordyn")
    import cosim.line_step as ls

    monkeypatch.setitem(ls.SAFETY, "spring", 100.0)  # let a step above the bound through
    res = tension_leg(dt=1.5 * 2 / 119.57, lines="subiterate").run(tmp_path / "sub")
    early, late = (res["box.f.tension"][(res.t >= a) & (res.t < a + 1.0)] for a in (0.5, 2.0))
    assert np.ptp(late) < np.ptp(early) and np.ptp(late) < 0.3 * late.mean()


@pytest.mark.long
@pytest.mark.parametrize("model", ["moordyn", "sph-cable"])
def test_the_wind_turbine_base_takes_the_lines_step_and_goes_unstable_at_twice_it(model, tmp_path, monkeypatch):
    """Barreiro et al. 2016's chain (EA 1.9e9 N, 442 kg/m) on the 16 t base, the lines' force held over
    each step (lines="explicit", the exchange the bound is derived for): the three lines'
    axial impedance sqrt(EA m) (plus the model's own axial damping) against the base's roll
    and pitch inertia sets the bound 2 / rate (dashpot). The scene runs with no coupling.dt
    at 0.8 of it, where MoorDyn's motion does not grow (the SPH cable's grows into a limit
    cycle: the sub-iterated exchange settles it, below); at twice the bound it grows a
    hundredfold or stops the run within 2 s."""
    pytest.importorskip("moordyn") if model == "moordyn" else None
    import cosim.line_step as ls

    from cosim.scene.build import build

    base = Scene.from_toml(WT).with_values([f"moorings.model={model}", "waves.height=0.01", "coupling.lines=explicit"])
    b = build(base, tmp_path / "auto")
    lim = b.coupler.line_limit
    assert lim.term == "dashpot" and lim.body == "base" and lim.dt < 0.0065
    spin = []  # the base's largest angular speed [rad/s] after each step

    def watch(built):
        return lambda info: spin.append(float(np.abs(built.bodies.kinematics().omega).max()))

    def run(built) -> tuple[int, float, float]:
        """Steps taken, the base's largest angular speed [rad/s] over the first and the second second."""
        spin.clear()
        n = built.coupler.run(2.0, watch(built))
        return n, max(spin[:len(spin) // 2]), max(spin[len(spin) // 2:])

    n, early, late = run(b)
    assert n >= 0.99 * 2.0 / lim.dt  # the coupler took the lines' step (which moves a little with them)
    if model == "moordyn":  # not growing: 8e-7 rad/s both (the SPH cable grows into a limit cycle, which the
        # sub-iterated exchange settles: below)
        assert late < 1.2 * early
    monkeypatch.setattr(ls, "SAFETY", {"spring": 100.0, "dashpot": 100.0})  # let twice the bound through
    dt = f"{2 * 2 / lim.rate:.6g}"  # a step that lands on the samples (cosim.scene.timing)
    fast = build(base.with_values([f"coupling.dt={dt}", f"world.sample_every={dt}"]), tmp_path / "2x")
    try:
        assert max(run(fast)[1:]) > 100 * max(early, late)  # MoorDyn: 0.15 rad/s
    except InstabilityError:  # the coupler's watch saw the base's acceleration grow (the SPH cable)
        pass


@pytest.mark.long
@pytest.mark.parametrize("model", ["sph-cable", "moordyn"])
def test_the_base_on_dynamic_lines_settles_at_the_derived_step(model, tmp_path):
    """Barreiro et al. 2016's base on three dynamic lines (20 nodes / segments), waves 0.01 m, the lines
    advanced with the base until their mean force over each step is the force the base was
    given (the coupler's default, lines="subiterate"): at the step the coupler derives, the
    base's largest angular speed over the fourth second is that of a settled base, below
    1e-3 rad/s (measured 6.7e-7 SPH cable, 1.9e-6 MoorDyn; with the force held over the step
    the SPH cable holds a 0.03 rad/s limit cycle, benchmarks/line_step_sweep.py), in at most
    a few advances of the lines per step."""
    pytest.importorskip("moordyn") if model == "moordyn" else None
    from cosim.scene.build import build

    b = build(Scene.from_toml(WT).with_values([f"moorings.model={model}", "waves.height=0.01"]), tmp_path)
    spin, tries = [], []
    b.coupler.run(3.0)
    b.coupler.run(4.0, lambda info: (spin.append(float(np.abs(b.bodies.kinematics().omega).max())),
                                     tries.append(b.coupler.line_iterations)))
    assert max(spin) < 1e-3
    assert 1 <= min(tries) and max(tries) <= 4


def test_a_given_step_above_the_lines_limit_is_refused_naming_the_line_the_limit_and_the_fix(tmp_path):
    pytest.importorskip("moordyn")
    scene = Scene.from_toml(WT).with_values(["moorings.model=moordyn", "coupling.dt=0.01"])
    says = (r"coupling step dt = 0.01 s is above 0.00499 s, the largest step at which the bodies follow mooring "
            r"'moordyn', line 'front_(port|starboard)': its axial impedance on body 'base'.*Leave dt unset \(a "
            r"scene: remove coupling.dt\).*or set dt <= 0.00499 s")
    with pytest.raises(SceneError, match=says) as e:  # named by the scene's key
        scene.run(tmp_path / "out")
    assert e.value.path == "coupling.dt"
    assert not (tmp_path / "out" / "summary.json").exists()


def test_each_model_reports_its_fairlead_stiffness(tmp_path):
    """The catenary's tangent stiffness by differences against its closed form at a point
    of the law (the vertical stiffness of a line resting on the seabed, w: V = w h), and a
    dynamic line's axial spring EA / L_s and impedance (1 + damping) sqrt(EA m) along its
    last segment (moorings.fairlead_stiffness)."""
    from moorings import CatenaryMooring, MooringLine
    from moorings.fairlead_stiffness import axial

    line = MooringLine((0.0, 0.0), 30.0, 100.0)
    m = CatenaryMooring([line], fairleads=[(5.0, 10.0)])  # X = 5 <= L - h = 20: resting, V = w h
    k = m.fairlead_stiffness().k[0]
    assert k[1, 1] == pytest.approx(100.0, rel=1e-6) and abs(k[0, 0]) < 1e-6  # dV/dh = w; H = 0 whatever X
    nodes = np.array([[0.0, 0.0], [4.0, 0.0], [8.0, 0.0], [11.0, 4.0]])  # two on the seabed, then up
    kk, cc = axial(nodes, np.array([0.0, 4.0, 8.0, 13.0]), 1e8, 5.0, 0.0, 1e-3, damping=0.5)
    e = np.array([0.6, 0.8])
    assert kk == pytest.approx(1e8 / 5.0 * np.outer(e, e))
    assert cc == pytest.approx(1.5 * math.sqrt(5e8) * np.outer(e, e))
