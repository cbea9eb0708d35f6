"""cosim study: metrics against closed forms, Richardson extrapolation recovering a known
order, a serial study of the moored box whose coupling step converges at second order,
its cache, a failed run as a row, the same study on a local Dask cluster, and every spec
checked before the first run (the series a scene records known from the scene alone)."""

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from cosim.errors import InputError
from cosim.scene import Scene
from cosim.study import _richardson, pareto_front, run_study
from cosim.study import metrics as M
from cosim.study import sweep
from cosim.scene.build import build
from cosim.scene.probes import groups, series_names

ROOT = Path(__file__).resolve().parents[1]
BOX = ROOT / "examples" / "moored_box.toml"


def test_metrics_of_a_sine():
    t = np.linspace(0.0, 10.0, 2001)
    x = 0.3 + 2.0 * np.sin(2 * np.pi * t / 1.25)
    assert M.value("peak", t, x) == pytest.approx(2.3, rel=1e-4)  # sampled off the crest
    assert M.value("amplitude", t, x) == pytest.approx(2.0, rel=1e-4)
    assert M.value("period", t, x) == pytest.approx(1.25, rel=5e-3)  # 4 periods in the last half
    assert M.value("mean", t, x) == pytest.approx(0.3, abs=2e-3)
    assert M.value("arrival", t, x) == pytest.approx(1.25 / 12, abs=0.01)  # 2 sin = 1 at a twelfth of a period
    assert M.value("rms", t, x, ref=(t, x)) == 0.0
    assert M.value("rms", t, 1.1 * x - 0.03, ref=(t, x)) == pytest.approx(0.1 * 2.0 / math.sqrt(2) / math.sqrt(2),
                                                                           rel=2e-2)
    with pytest.raises(InputError, match="unknown statistic 'median'"):
        M.parse("box.heave:median")


def test_the_period_of_a_decaying_tone_over_a_fraction_of_cycles():
    """5.5 free periods in the last half, damped, sampled 40 times a period (a sloshing
    record): the windowed, padded spectrum finds the period to 0.1 %; a plain FFT's bin
    there is 18 % of the frequency wide."""
    T = 1.18182
    t = np.arange(0.0, 11 * T, T / 40)
    x = np.exp(-0.05 * t) * np.sin(2 * np.pi * t / T + 0.4) + 0.01 * np.sin(2 * np.pi * t / 0.39)
    assert M.value("period", t, x) == pytest.approx(T, rel=1e-3)


def test_the_harmonic_amplitude_ignores_noise_that_sets_the_range():
    rng = np.random.default_rng(3)
    t = np.arange(0.0, 0.18, 0.03 / 40)  # 6 periods of 0.03 s, 40 samples each
    x = 7000.0 + 3400.0 * np.sin(2 * np.pi * t / 0.03) + 300.0 * rng.standard_normal(t.size)
    # 120 samples of noise 300: the fit's standard error is 300 sqrt(2/120) = 39 (1.1 %)
    assert M.value("harmonic", t, x) == pytest.approx(3400.0, rel=0.03)
    assert M.value("amplitude", t, x) > 3400.0 * 1.1  # the range carries the noise's extremes


def test_richardson_recovers_order_and_limit():
    m_star, p = _richardson([0.01, 0.02, 0.04], [1 + 3 * h**1.5 for h in (0.01, 0.02, 0.04)])
    assert m_star == pytest.approx(1.0, abs=1e-12) and p == pytest.approx(1.5, abs=1e-9)
    assert math.isnan(_richardson([1, 2, 3], [5.0, 5.0, 5.0])[1])
    with pytest.raises(InputError, match="monotonically"):
        _richardson([1, 2, 3], [1.0, 2.0, 1.5])


def test_pareto_front():
    rows = [{"case": c, "wall_s": w, "max_error": e, "error": None} for c, w, e in
            (("a", 1, 0.5), ("b", 2, 0.1), ("c", 3, 0.2), ("d", 4, 0.01))]
    assert [r["case"] for r in pareto_front(rows)] == ["a", "b", "d"]
    # the CPU time ranks where it was measured: a run slowed down by its neighbours in a
    # sweep (wall 9 s for 2 s of CPU) is still the cheaper one
    rows[2].update(wall_s=9.0, cpu_s=1.5)
    assert [r["case"] for r in pareto_front(rows)] == ["a", "c", "b", "d"]


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    scene = Scene.from_toml(BOX).with_values(["world.duration=2.0"])
    out = tmp_path_factory.mktemp("study")
    res = run_study(scene, {"coupling.dt": [0.01, 0.005, 0.0025]}, ["box.surge:min", "box.left.tension:mean"], out,
                    reference="richardson", tol=1e-5, serial=True)
    return scene, out, res


@pytest.mark.long
def test_coupling_step_converges_at_second_order(study):
    """The predictor-corrector coupling (the analytic fluid's default scheme) is second
    order in the coupling step: the study's Richardson extrapolation observes p ~ 2."""
    _, out, res = study
    (order,) = [v["order"] for k, v in res.orders.items() if k.startswith("box.surge:min")]
    assert order == pytest.approx(2.0, abs=0.15)
    errors = [r["errors"]["box.surge:min"] for r in res.rows]
    assert errors[0] > errors[1] > errors[2]  # the error shrinks as dt does
    for name in ("study.csv", "study.md", "study.json", "pareto.png"):
        assert (out / name).stat().st_size > 0
    js = json.loads((out / "study.json").read_text())
    assert js["recommendation"]["tol"] == 1e-5 and len(js["rows"]) == 3


@pytest.mark.long
def test_repeated_study_costs_nothing(study):
    scene, out, first = study
    again = run_study(scene, {"coupling.dt": [0.01, 0.005, 0.0025]}, ["box.surge:min"], out,
                      reference="finest", serial=True)
    assert all(r["cached"] for r in again.rows)
    assert [r["metrics"]["box.surge:min"] for r in again.rows] == [r["metrics"]["box.surge:min"] for r in first.rows]


def test_a_failed_run_is_a_row(tmp_path):
    rec = tmp_path / "paddle.txt"
    np.savetxt(rec, np.column_stack([np.linspace(0, 2, 21), np.zeros(21)]))
    scene = Scene.from_toml(BOX).with_values(["world.duration=0.5"])
    cs = sweep.cases(scene, {"coupling.dt": [0.01]}, tmp_path, "v")
    cs[0].toml = cs[0].toml.replace('level = 0.0', 'level = "high"')  # refused by the run, not by the study
    (rec_,) = sweep.execute(cs, workers=1, threads=1, serial=True, version="v")
    assert rec_["returncode"] == 2 and "fluid.level" in rec_["error"]


def test_a_run_that_writes_more_than_a_pipe_holds_is_not_stalled(tmp_path):
    """A run's messages go to its folder's stderr.log: 1 MB of them (a pipe holds 64 KiB)
    and the run still ends, its exit code and messages kept."""
    code = "import sys; sys.stderr.write('particles left the domain\\n' * 40000); sys.exit(3)"
    rc, usage, text = sweep.run_logged([sys.executable, "-c", code], tmp_path / "stderr.log", {})
    assert rc == 3 and text.count("left the domain") == 40000 and usage.ru_utime >= 0.0
    assert (tmp_path / "stderr.log").read_text() == text


@pytest.mark.long
def test_unknown_metric_series_is_named(study):
    scene, out, _ = study
    with pytest.raises(InputError, match="no series 'box.roll'"):
        run_study(scene, {"coupling.dt": [0.01]}, ["box.roll:max"], out, serial=True)


@pytest.mark.long
def test_cli_study_on_dask(tmp_path):
    """The command line, on a local Dask cluster of two workers; it leaves nothing in the
    temporary folder (Dask's scratch space, the runs' build folders and unpacked FMUs)."""
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    out = subprocess.run([sys.executable, "-m", "cosim.cli", "study", str(BOX), "--set", "world.duration=0.5",
                          "--vary", "moorings.model=catenary,fmu", "--metric", "box.left.tension:max", "--tol", "1%",
                          "--workers", "2", "--out", str(tmp_path / "study")], capture_output=True, text=True,
                         timeout=600, env=dict(os.environ, TMPDIR=str(tmp)))
    assert out.returncode == 0, out.stderr[-3000:]
    assert not list(tmp.iterdir())
    tmp_path = tmp_path / "study"
    js = json.loads((tmp_path / "study.json").read_text())
    a, b = (r["metrics"]["box.left.tension:max"] for r in js["rows"])
    assert a == pytest.approx(b, rel=1e-9)  # the FMU is the catenary law compiled
    assert js["recommendation"]["case"] is not None and "cheapest within 0.01" in out.stdout


# ------------------------------------------------------------------------ specs checked before any run
PLATE_PROBES = ["probes.gauges=[0.4]", "probes.energy=true",
                "probes.pressure=[{ name = \"wall\", centre = [0.584, 0.05], normal = [-1.0, 0.0], size = 0.01 }]"]
LINE_DYN = [f"moorings.lines[{i}].{k}={v}" for i in (0, 1)
            for k, v in (("EA", 1e7), ("mass_per_length", 5.803665), ("diameter", 0.03))]  # 50 N/m submerged


@pytest.mark.parametrize("base,changes", [
    ("analytic", []), ("analytic", ["moorings.model=moordyn"] + LINE_DYN),
    ("analytic", ["moorings.lines[0].EA=1e7", "moorings.lines[1].EA=1e7"]), ("analytic", ["moorings.model=fmu"]),
    ("analytic", ["moorings.lines[0].break_load=1e6"]), ("analytic", ['probes.motion=["buoy"]', "probes.loads=false"]),
    ("analytic", ["waves={ kind = \"linear\", height = 0.7, period = 20.0, depth = 20.0 }"]),
    ("mjcf", []), ("plate", PLATE_PROBES),
], ids=lambda v: v if isinstance(v, str) else ",".join(x.split("=")[0] for x in v) or "as given")
def test_series_names_are_what_a_run_records(base, changes, tmp_path):
    """The series a scene's run records, named from the scene alone (what ``cosim study``
    checks its metrics against), are the columns of the built scene's probe groups, in order."""
    from test_scene_errors import base_dict, folder

    with folder():
        scene = Scene.from_dict(base_dict(base)).with_values(changes)
        built = build(scene, tmp_path)
        assert series_names(scene) == [c for g in groups(scene, built) for c in g.columns]


@pytest.mark.parametrize("kwargs,says", [
    ({"workers": -1}, "--workers -1: give a whole number >= 1"),
    ({"workers": 0}, "--workers 0: give a whole number >= 1"),
    ({"threads": 0}, "--threads 0: give a whole number >= 1"),
    ({"specs": ["box.roll:max"]}, "--metric 'box.roll:max': the runs with {'coupling.dt': 0.01} record no series "
                                  "'box.roll'; they record box.surge, box.heave, box.pitch"),
    ({"specs": ["box.heave:median"]}, "unknown statistic 'median'"),
    ({"vary": {"coupling.dt": [0.01, 0.01]}}, "--vary coupling.dt: the value 0.01 is given twice"),
    ({"vary": {"coupling.dtt": [0.01]}}, "coupling.dtt: unknown key; did you mean 'dt'?"),
    ({"tol": -0.05}, "--tol -0.05: give a relative tolerance > 0"),
    ({"reference": "ref.json"}, "--reference ref.json: no reference value for box.heave:max"),
    ({"vary": {"fluid.model": ["analytic", "sph"]}}, "the run with {'fluid.model': 'sph'}: fluid.dx: is required: a "
                                                     "number [m] > 0 (particle spacing) (a field of this kind alone: "
                                                     "give it with --set fluid.dx=VALUE"),
    ({"vary": {"fluid.model": ["analytic", "potential"]}}, "the run with {'fluid.model': 'potential'}: world.dim: "
                                                           "linear potential flow about a body is 3-D"),
    ({"vary": {"coupling.dt": [0.01]}, "sets": ["fluid.dxx=0.1"]}, "fluid.dxx: unknown key"),
])
def test_every_spec_is_checked_before_the_first_run(kwargs, says, tmp_path, monkeypatch):
    """A bad spec is refused before anything runs or is written: the study's folder is not made."""
    monkeypatch.chdir(tmp_path)
    Path("ref.json").write_text('{"box.surge:min": 1.0}')
    args = dict(vary={"coupling.dt": [0.01, 0.005]}, specs=["box.heave:max"], workers=None, threads=1) | kwargs
    with pytest.raises(InputError) as e:
        run_study(Scene.from_toml(BOX), args.pop("vary"), args.pop("specs"), tmp_path / "study", serial=True, **args)
    assert says in str(e.value)
    assert not (tmp_path / "study").exists()


# ------------------------------------------------------------------------ one study over the fluids
TURBINE = ROOT / "examples" / "wind_turbine_base.toml"


def test_a_fluid_swap_carries_density_and_drag_and_says_what_it_dropped():
    from cosim.scene.toml_io import with_values

    base = Scene.from_toml(TURBINE)
    notes = []
    pot = with_values(base, ["fluid.model=potential"], notes)
    assert pot.fluid.rho == 1025.0 and pot.fluid.quadratic_drag == base.fluid.quadratic_damping
    assert notes == ["fluid.model = 'potential': its quadratic_damping taken as quadratic_drag; dropped added_mass, "
                     "linear_damping (not fields of Potential)"]
    back = with_values(pot, ["fluid.model=analytic"])  # no added mass or linear damping to come back
    assert back.fluid.quadratic_damping == base.fluid.quadratic_damping and not back.fluid.added_mass
    sph = with_values(base, ["fluid.model=sph", "fluid.dx=2.0"])
    assert sph.fluid.rho0 == 1025.0 and sph.fluid.dx == 2.0


def test_a_field_of_one_kind_is_set_on_the_runs_of_that_kind_alone(tmp_path):
    sets = ["fluid.dx=2.0", "fluid.panel_size=0.75", "world.duration=10.0"]
    cs = sweep.cases(Scene.from_toml(TURBINE), {"fluid.model": ["analytic", "potential", "sph"]}, tmp_path, "v",
                     sets)
    ana, pot, sph = (c.scene for c in cs)
    assert (type(ana.fluid).__name__, pot.fluid.panel_size, sph.fluid.dx) == ("Analytic", 0.75, 2.0)
    assert ana.world.duration == pot.world.duration == sph.world.duration == 10.0
    assert "--set fluid.dx=2.0 not applied (Potential has no such field)" in cs[1].notes
    assert "--set fluid.panel_size=0.75 not applied (SPH has no such field)" in cs[2].notes
    assert not any("duration" in n for c in cs for n in c.notes)


@pytest.mark.long
def test_cli_sets_a_field_of_one_kind_on_the_runs_of_that_kind(tmp_path):
    """``cosim study`` on an SPH scene turned analytic by --set, varying back to SPH: the SPH
    run takes the --set spacing, the analytic one says it did not."""
    scene = ROOT / "examples" / "moored_box_waves.toml"
    out = subprocess.run([sys.executable, "-m", "cosim.cli", "study", str(scene), "--set", "fluid.model=analytic",
                          "--set", "fluid.dx=0.05", "--set", "world.duration=0.2", "--set", "world.plot_at=[]",
                          "--vary", "fluid.model=analytic,sph", "--metric", "box.heave:max", "--serial",
                          "--out", str(tmp_path / "s")], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    rows = json.loads((tmp_path / "s" / "study.json").read_text())["rows"]
    assert [r["error"] for r in rows] == [None, None] and rows[1]["particles"] > 0
    assert rows[0]["notes"] == ["--set fluid.dx=0.05 not applied (Analytic has no such field)"]
    assert "SPH" in (tmp_path / "s" / "study.md").read_text()
