"""The exported catenary FMU: valid FMI 2.0, equal to the Python law, robust.

Everything that runs the FMU's binary runs in a fresh Python process (a crash
in C fails the test instead of taking the test runner down): each ``_case_*``
function below is called in a subprocess by :func:`isolated`.
"""

import json
import math
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

from moorings.catenary import LineState, taut_distance
from moorings.fmu_export import export_catenary_fmu, find_compiler
from moorings.line import MooringLine
from conftest import requires_cc

HERE = Path(__file__).resolve().parent
pytestmark = requires_cc


def lines3d():
    """Six 3-D lines at different azimuths: inextensible and elastic, light and heavy."""
    out = []
    specs = [(150.0, 918.75, None, 50.0), (6.98, 1.036, None, 2.651), (20.0, 10.0, None, 0.0),
             (150.0, 918.75, 2e8, 50.0), (20.0, 10.0, 1e5, 12.0), (20.0, 10.0, 300.0, 25.0)]
    for i, (L, w, EA, h) in enumerate(specs):
        az = 2 * math.pi * i / len(specs)
        out.append(MooringLine((100 * math.cos(az), 100 * math.sin(az), -h), L, w, EA=EA, name=f"L{i}"))
    return out


def lines2d():
    return [MooringLine((-30.0, -8.0), 40.0, 50.0, name="port"),
            MooringLine((35.0, -10.0), 45.0, 60.0, EA=1e5, name="starboard")]


def trajectory(lines, n=80, reach=1.15):
    """Fairlead positions (2 n, n_lines, dim): each fairlead at a fixed height above its
    anchor, moving from straight above it outwards, beyond the taut point (elastic lines)
    or up to just short of it (inextensible ones), each line in its own direction; the
    second half of the samples is dense around lift-off and the taut point."""
    dim = lines[0].dim
    pos = np.empty((2 * n, len(lines), dim))
    for i, ln in enumerate(lines):
        h = [10.0, 2.651, 5.0, 50.0, 12.0, 25.0, 8.0, 12.0][i % 8]
        h = min(h, 0.9 * ln.length)
        xt = taut_distance(h, ln.length)
        xmax = reach * xt if not ln.inextensible else (1 - 1e-6) * xt
        X = np.concatenate([np.linspace(0.0, xmax, n), np.linspace(0.9 * xt, min(xmax, 1.05 * xt), n)])
        a = np.asarray(ln.anchor)
        if dim == 3:
            az = 0.7 + 1.3 * i
            pos[:, i] = a + np.stack([X * math.cos(az), X * math.sin(az), np.full(2 * n, h)], axis=1)
        else:
            sign = 1.0 if i % 2 == 0 else -1.0
            pos[:, i] = a + np.stack([sign * X, np.full(2 * n, h)], axis=1)
    return pos


@pytest.fixture(scope="module")
def fmus(tmp_path_factory):
    d = tmp_path_factory.mktemp("fmus")
    p3 = export_catenary_fmu(lines3d(), d / "cat3.fmu", reference_point=(1.0, -2.0, 3.0),
                             fairleads=trajectory(lines3d())[10])
    p2 = export_catenary_fmu(lines2d(), d / "cat2.fmu", model_identifier="cat2d", reference_point=(0.5, 1.0))
    return {"3d": p3, "2d": p2}


def isolated(case: str, *args):
    """Run ``case(*args)`` of this module in a fresh interpreter; its return value comes back as JSON."""
    code = (
        "import json, sys\n"
        f"sys.path.insert(0, {str(HERE)!r})\n"
        "import test_fmu_export as m\n"
        f"out = getattr(m, {case!r})(*json.loads(sys.argv[1]))\n"
        "print('RESULT ' + json.dumps(out))\n"
    )
    res = subprocess.run([sys.executable, "-c", code, json.dumps([str(a) for a in args])],
                         capture_output=True, text=True, timeout=120, cwd=HERE.parent)
    if res.returncode < 0:
        pytest.fail(f"{case}: the FMU crashed the process (signal {-res.returncode}):\n{res.stderr[-3000:]}")
    if res.returncode != 0:
        pytest.fail(f"{case} failed in its subprocess:\n{res.stderr[-5000:]}")
    line = [ln for ln in res.stdout.splitlines() if ln.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT "):])


# ---------------------------------------------------------------------------
# helpers used inside the subprocesses
# ---------------------------------------------------------------------------

class Host:
    """A minimal FMI 2.0 co-simulation host on fmpy that collects the log messages."""

    def __init__(self, path, instance_name="inst"):
        from ctypes import byref

        import fmpy
        from fmpy.fmi2 import FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE
        from fmpy.fmi2 import fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
        from fmpy.fmi1 import calloc, free
        from fmpy.logging import addLoggerProxy

        self.md = fmpy.read_model_description(path)
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.messages = []

        def logger(env, name, status, category, message):
            self.messages.append((status, category.decode(), message.decode()))

        cb = fmi2CallbackFunctions()
        self._pylogger = fmi2CallbackLoggerTYPE(logger)
        cb.logger = self._pylogger
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        addLoggerProxy(byref(cb))  # fmpy's proxy formats the message; it keeps ONE Python logger per process
        self._keep = (cb, logger)

        def arm():  # make this host's logger the process's one again
            a = fmi2CallbackFunctions()
            a.logger = self._pylogger
            addLoggerProxy(byref(a))

        self._arm = arm
        self.dir = fmpy.extract(path)
        self.fmu = FMU2Slave(guid=self.md.guid, unzipDirectory=self.dir,
                             modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName=instance_name)
        self.fmu.instantiate(callbacks=cb)
        self.fmu.setupExperiment(startTime=0.0)
        self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def vr(self, names):
        return [self.vars[n].valueReference for n in names]

    def set(self, names, values):
        self._arm()
        self.fmu.setReal(self.vr(names), [float(v) for v in values])

    def get(self, names):
        self._arm()
        return self.fmu.getReal(self.vr(names))

    def get_int(self, names):
        self._arm()
        return self.fmu.getInteger(self.vr(names))


def _axes(dim):
    return ("x", "z") if dim == 2 else ("x", "y", "z")


def _names(lines, key):
    return [f"{ln.name}.{key}.{a}" for ln in lines for a in _axes(ln.dim)]


def _compare_along(host, lines, traj, ref_point):
    """Max relative difference of every output to CatenaryMooring along a trajectory; states seen."""
    from moorings.catenary_mooring import CatenaryMooring

    dim = lines[0].dim
    py = CatenaryMooring(lines)
    worst, states = 0.0, set()
    mom_names = [f"moment.{a}" for a in (_axes(3) if dim == 3 else ("y",))]
    for pos in traj:
        host.set(_names(lines, "fairlead"), pos.ravel())
        got_f = np.reshape(host.get(_names(lines, "force")), (len(lines), dim))
        got_t = host.get([f"{ln.name}.tension" for ln in lines])
        got_hv = np.reshape(host.get([f"{ln.name}.{k}" for ln in lines for k in ("H", "V", "touchdown")]), (-1, 3))
        got_tot = host.get([f"force.{a}" for a in _axes(dim)])
        got_mom = host.get(mom_names)
        got_state = host.get_int([f"{ln.name}.state" for ln in lines])
        py.set_fairlead_motion(pos)
        f = py.fairlead_forces()
        T = py.fairlead_tensions()
        sol = py.solution
        tot, mom = py.total_wrench(ref_point)
        scale = np.maximum(T, 1e-300)
        worst = max(worst, float(np.max(np.abs(got_f - f) / scale[:, None])))
        worst = max(worst, float(np.max(np.abs(np.array(got_t) - T) / scale)))
        worst = max(worst, float(np.max(np.abs(got_hv[:, 0] - sol.H) / scale)))
        worst = max(worst, float(np.max(np.abs(got_hv[:, 1] - sol.V) / scale)))
        worst = max(worst, float(np.max(np.abs(got_hv[:, 2] - sol.touchdown) / py._L)))
        fs = np.sum(np.abs(f))
        worst = max(worst, float(np.max(np.abs(np.array(got_tot) - tot)) / fs))
        msc = np.sum(np.linalg.norm(py._pos - ref_point, axis=1) * np.linalg.norm(f, axis=1))
        worst = max(worst, float(np.max(np.abs(np.array(got_mom) - np.atleast_1d(mom))) / msc))
        assert list(got_state) == [int(s) for s in sol.state]
        for ln, s in zip(lines, sol.state):
            states.add((ln.inextensible, int(s)))
    return worst, sorted(states)


def _case_sweep(path3, path2):
    h3, h2 = Host(path3), Host(path2)
    w3, s3 = _compare_along(h3, lines3d(), trajectory(lines3d()), np.array([1.0, -2.0, 3.0]))
    w2, s2 = _compare_along(h2, lines2d(), trajectory(lines2d()), np.array([0.5, 1.0]))
    assert not h3.messages and not h2.messages, (h3.messages, h2.messages)
    return {"worst3": w3, "worst2": w2, "states": sorted(set(map(tuple, s3 + s2)))}


def _case_simulate(path):
    """fmpy.simulate_fmu drives the FMU with an input table; every row equals the Python law."""
    import fmpy
    from moorings.catenary_mooring import CatenaryMooring

    lines = lines3d()
    traj = trajectory(lines, n=21)[::2]
    names = _names(lines, "fairlead")
    t = np.linspace(0.0, 2.0, 21)
    inp = np.zeros(21, dtype=[("time", float)] + [(n, float) for n in names])
    inp["time"] = t
    for k, n in enumerate(names):
        inp[n] = traj.reshape(21, -1)[:, k]
    out_names = _names(lines, "force")
    # fmpy applies the inputs at the start of each step and records the outputs at its end,
    # before the next inputs: row k (k >= 1) shows the law at the inputs of row k - 1
    res = fmpy.simulate_fmu(path, start_time=0.0, stop_time=2.0, output_interval=0.1, input=inp,
                            output=out_names + [f"{ln.name}.state" for ln in lines], apply_default_start_values=True)
    py = CatenaryMooring(lines)
    worst = 0.0
    assert len(res) == 21 and np.allclose(res["time"], t)
    for k in range(21):
        py.set_fairlead_motion(traj[max(k - 1, 0)])
        f = py.fairlead_forces().ravel()
        got = np.array([res[n][k] for n in out_names])
        worst = max(worst, float(np.max(np.abs(got - f) / np.maximum(np.repeat(py.fairlead_tensions(), 3), 1e-300))))
    return {"rows": len(res), "worst": worst}


def _case_two_instances_reset_state(path):
    """Two instances in one process keep their own values; reset restores the start values
    and a re-run repeats the first; get/set and (de)serialised FMU states restore values and time."""
    lines = lines3d()
    traj = trajectory(lines)
    fair, force = _names(lines, "fairlead"), _names(lines, "force")
    a, b = Host(path, "a"), Host(path, "b")
    start_forces = a.get(force)

    def run(host, steps):
        out = []
        for k, pos in enumerate(steps):
            host.set(fair, pos.ravel())
            host.fmu.doStep(currentCommunicationPoint=0.1 * k, communicationStepSize=0.1)
            out.append(host.get(force))
        return out

    ra = run(a, traj[:20])
    rb = run(b, traj[40:60])
    assert a.get(force) == ra[-1] and b.get(force) == rb[-1]  # b's inputs did not leak into a
    assert ra[5] != rb[5]
    # FMU state: take it at step 20, move on, come back
    st = a.fmu.getFMUstate()
    t20 = a.fmu.getRealStatus(2)  # fmi2LastSuccessfulTime
    run(a, traj[60:70])
    a.set([f"{lines[3].name}.length"], [180.0])  # a tunable parameter changes too
    assert a.get(force) != ra[-1]
    a.fmu.setFMUstate(st)
    assert a.get(force) == ra[-1] and a.fmu.getRealStatus(2) == t20 == pytest.approx(2.0)
    blob = a.fmu.serializeFMUstate(st)
    a.fmu.freeFMUstate(st)
    run(a, traj[70:75])
    st2 = a.fmu.deSerializeFMUstate(blob)
    a.fmu.setFMUstate(st2)
    assert a.get(force) == ra[-1]
    a.fmu.freeFMUstate(st2)
    # reset: back to the start values; re-run repeats the first run exactly
    a.fmu.terminate()
    a.fmu.reset()
    assert a.get(force) == start_forces
    a.fmu.setupExperiment(startTime=0.0)
    a.fmu.enterInitializationMode()
    a.fmu.exitInitializationMode()
    assert run(a, traj[:20]) == ra
    a.fmu.terminate()
    a.fmu.freeInstance()
    b.fmu.terminate()
    b.fmu.freeInstance()
    return {"ok": True}


def _case_errors(path):
    """A taut inextensible line, a NaN input, a fairlead below the seabed and a bad
    parameter come back as fmi2Error with a message naming the line; the host lives on."""
    from fmpy.fmi1 import FMICallException

    lines = lines3d()
    fair = _names(lines, "fairlead")
    h = Host(path)
    good = trajectory(lines)[10]
    h.set(fair, good.ravel())
    ok_forces = h.get(_names(lines, "force"))
    out = {}
    # 1. taut inextensible line 1: fairlead beyond the taut point
    a = np.asarray(lines[1].anchor)
    taut_pos = a + np.array([lines[1].length, 0.0, 0.5])
    h.set(fair[3:6], taut_pos)
    with pytest.raises(FMICallException) as exc:
        h.get(_names(lines, "force"))
    out["taut_status"] = exc.value.status
    out["taut_msg"] = h.messages[-1]
    with pytest.raises(FMICallException):
        h.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.1)
    h.set(fair[3:6], good[1])
    assert h.get(_names(lines, "force")) == ok_forces  # recovered
    # 2. NaN input: refused, the previous value kept
    n_msgs = len(h.messages)
    with pytest.raises(FMICallException) as exc:
        h.set([fair[4]], [math.nan])
    out["nan_status"] = exc.value.status
    out["nan_msg"] = h.messages[n_msgs]
    assert h.get(fair[3:6]) == list(good[1])
    assert h.get(_names(lines, "force")) == ok_forces
    # 3. fairlead below the seabed through the anchor of line 4
    h.set([fair[14]], [lines[4].anchor[2] - 1.0])
    with pytest.raises(FMICallException):
        h.get(_names(lines, "force"))
    out["below_msg"] = h.messages[-1]
    h.set([fair[14]], [good[4, 2]])
    # 4. a negative length is reported before any step, at the end of initialisation
    h.fmu.terminate()
    h.fmu.reset()
    h.set([f"{lines[2].name}.length"], [-3.0])
    h.fmu.setupExperiment(startTime=0.0)
    h.fmu.enterInitializationMode()
    with pytest.raises(FMICallException):
        h.fmu.exitInitializationMode()
    out["param_msg"] = h.messages[-1]
    # 5. an output cannot be set
    with pytest.raises(FMICallException):
        h.set(["force.x"], [1.0])
    h.fmu.freeInstance()
    return out


# ---------------------------------------------------------------------------
# tests
# ---------------------------------------------------------------------------

def test_fmu_passes_fmpy_validation_and_ships_sources(fmus):
    from fmpy import read_model_description
    from fmpy.model_description import read_build_description
    from fmpy.validation import validate_fmu

    for p in fmus.values():
        assert validate_fmu(str(p)) == []
        names = set(zipfile.ZipFile(p).namelist())
        ident = read_model_description(str(p)).coSimulation.modelIdentifier
        assert f"binaries/linux64/{ident}.so" in names
        for f in ("catenary.c", "catenary.h", "fmi2_catenary.c", "model_config.h", "fmi2Functions.h",
                  "buildDescription.xml"):
            assert f"sources/{f}" in names
        (bc,) = read_build_description(str(p))  # validated against the FMI 3.0 / 2.0.4 schema
        assert bc.modelIdentifier == ident
        assert sorted(Path(f).name for f in bc.sourceFileSets[0].sourceFiles) == ["catenary.c", "fmi2_catenary.c"]
    md = read_model_description(str(fmus["3d"]))
    cs = md.coSimulation
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate and not cs.canBeInstantiatedOnlyOncePerProcess
    v = {x.name: x for x in md.modelVariables}
    assert v["L3.EA"].start == "200000000.0" and v["L0.EA"].start == "0.0"  # 0: inextensible
    assert v["L3.anchor.z"].causality == "parameter" and v["L3.anchor.z"].variability == "tunable"
    assert v["L3.fairlead.y"].causality == "input" and v["L3.force.y"].causality == "output"
    assert v["L5.state"].type == "Integer"
    assert len(md.outputs) == 6 * (3 + 4 + 1) + 6


def test_fmu_binary_exports_only_fmi_functions(fmus):
    import shutil

    nm = shutil.which("nm")
    if nm is None:
        pytest.skip("nm not available")
    with zipfile.ZipFile(fmus["2d"]) as zf:
        data = zf.read("binaries/linux64/cat2d.so")
    so = Path(fmus["2d"]).with_suffix(".so")
    so.write_bytes(data)
    out = subprocess.run([nm, "-D", "--defined-only", str(so)], capture_output=True, text=True, check=True).stdout
    syms = {ln.split()[-1] for ln in out.splitlines() if " T " in ln}
    assert "fmi2DoStep" in syms and "fmi2Instantiate" in syms
    assert all(s.startswith("fmi2") for s in syms), syms  # the law's symbols stay private
    needed = subprocess.run(["ldd", str(so)], capture_output=True, text=True).stdout
    assert "python" not in needed.lower()


def test_fmu_outputs_equal_python_law_over_all_states(fmus):
    r = isolated("_case_sweep", fmus["3d"], fmus["2d"])
    assert r["worst3"] <= 1e-12 and r["worst2"] <= 1e-12, r
    states = {tuple(s) for s in r["states"]}
    for s in (LineState.RESTING, LineState.PARTLY_LIFTED, LineState.FULLY_LIFTED):
        assert (True, s) in states  # inextensible (its TAUT state is an error: see the errors test)
    for s in LineState:
        assert (False, s) in states  # elastic


def test_fmu_simulates_with_fmpy_in_a_fresh_process(fmus):
    r = isolated("_case_simulate", fmus["3d"])
    assert r["rows"] == 21 and r["worst"] <= 1e-12


def test_two_instances_reset_and_fmu_state(fmus):
    assert isolated("_case_two_instances_reset_state", fmus["3d"]) == {"ok": True}


def test_errors_come_back_through_status_and_logger(fmus):
    r = isolated("_case_errors", fmus["3d"])
    assert r["taut_status"] == 3  # fmi2Error
    status, category, msg = r["taut_msg"]
    assert status == 3 and category == "logStatusError" and "'L1'" in msg and "taut" in msg
    assert r["nan_status"] == 3 and "'L1'" in r["nan_msg"][2] and "NaN" in r["nan_msg"][2]
    assert "'L4'" in r["below_msg"][2] and "below the seabed" in r["below_msg"][2]
    assert "'L2'" in r["param_msg"][2] and "length" in r["param_msg"][2]


def test_two_different_fmus_in_one_process(fmus):
    assert isolated("_case_two_fmus", fmus["3d"], fmus["2d"]) == {"ok": True}


def _case_two_fmus(path3, path2):
    from moorings.catenary_mooring import CatenaryMooring

    h3, h2 = Host(path3), Host(path2)
    for lines, host in ((lines3d(), h3), (lines2d(), h2)):
        pos = trajectory(lines)[30]
        host.set(_names(lines, "fairlead"), pos.ravel())
        py = CatenaryMooring(lines, fairleads=pos)
        assert np.array_equal(np.reshape(host.get(_names(lines, "force")), pos.shape), py.fairlead_forces())
    return {"ok": True}


def test_export_rejects_bad_arguments_before_writing(tmp_path):
    from cosim.errors import InputError

    lines = lines2d()
    with pytest.raises(InputError, match=r"\.fmu"):
        export_catenary_fmu(lines, tmp_path / "x.zip")
    with pytest.raises(InputError, match="does not exist"):
        export_catenary_fmu(lines, tmp_path / "nope" / "x.fmu")
    with pytest.raises(InputError, match="C identifier"):
        export_catenary_fmu(lines, tmp_path / "x.fmu", model_identifier="a-b")
    with pytest.raises(InputError, match="shape"):
        export_catenary_fmu(lines, tmp_path / "x.fmu", fairleads=[[0, 0]])
    with pytest.raises(InputError, match="no C compiler"):
        export_catenary_fmu(lines, tmp_path / "x.fmu", cc="no-such-compiler-xyz")
    assert list(tmp_path.iterdir()) == []


def test_sources_only_export_and_same_guid(tmp_path):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    p = export_catenary_fmu(lines2d(), tmp_path / "src.fmu", compile_binary=False)
    assert not any(n.startswith("binaries/") for n in zipfile.ZipFile(p).namelist())
    assert validate_fmu(str(p)) == []
    q = export_catenary_fmu(lines2d(), tmp_path / "again.fmu", compile_binary=False)
    assert read_model_description(str(p)).guid == read_model_description(str(q)).guid


def test_cli_export_fmu(tmp_path, capsys):
    from fmpy import read_model_description

    from cosim.cli import main

    spec = tmp_path / "lines.toml"
    spec.write_text(
        '[[line]]\nname = "port"\nanchor = [-30.0, -8.0]\nlength = 40.0\nweight = 50.0\nfairlead = [-2.0, 1.0]\n\n'
        '[[line]]\nname = "starboard"\nanchor = [35.0, -10.0]\nlength = 45.0\nweight = 60.0\nEA = 1e5\n'
        'fairlead = [2.0, 1.0]\n'
    )
    out = tmp_path / "m.fmu"
    assert main(["export-fmu", str(out), "--lines", str(spec), "--model-identifier", "twolines",
                 "--reference", "0.5", "1.0"]) == 0
    text = capsys.readouterr().out
    assert "2 line(s), 2-D" in text and "fmpy.validate_fmu: passed" in text
    v = {x.name: x for x in read_model_description(str(out)).modelVariables}
    assert float(v["starboard.EA"].start) == 1e5 and float(v["port.EA"].start) == 0.0
    assert float(v["port.fairlead.x"].start) == -2.0 and float(v["reference.z"].start) == 1.0
    assert "binaries/linux64/twolines.so" in zipfile.ZipFile(out).namelist()
    # --body-pose: the same file's fairleads are body-frame parameters, the pose is the input
    posed = tmp_path / "p.fmu"
    assert main(["export-fmu", str(posed), "--lines", str(spec), "--body-pose"]) == 0
    capsys.readouterr()
    v = {x.name: x for x in read_model_description(str(posed)).modelVariables}
    assert v["body.theta"].causality == "input" and v["port.fairlead.x"].causality == "output"
    assert float(v["starboard.fairlead_body.z"].start) == 1.0
    # a bad file is a clear error, exit status 2, nothing written
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"line": [{"anchor": [0, 0], "length": 10}]}))
    assert main(["export-fmu", str(tmp_path / "n.fmu"), "--lines", str(bad)]) == 2
    assert "missing ['weight']" in capsys.readouterr().err
    assert not (tmp_path / "n.fmu").exists()


def pose_lines():
    az = [0.3, 1.9, 3.5, 5.0]
    lines = [MooringLine((100 * math.cos(a), 100 * math.sin(a), -50.0), 130.0, 900.0,
                         EA=None if i % 2 else 1e8, name=f"m{i}") for i, a in enumerate(az)]
    fb = np.array([[6 * math.cos(a), 6 * math.sin(a), 2.0] for a in az])
    return lines, fb


def _quat_matrix(q):
    w, x, y, z = np.asarray(q) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def _case_body_pose(path3, path2):
    from moorings.catenary_mooring import CatenaryMooring

    rng = np.random.default_rng(6)
    worst = 0.0
    # 3-D: position and a (deliberately not normalised) quaternion
    lines, fb = pose_lines()
    h = Host(path3)
    ref_b = np.array([0.5, -0.2, 1.0])
    for _ in range(40):
        p = rng.uniform(-5, 5, 3)
        q = np.concatenate([[1.0], rng.uniform(-0.15, 0.15, 3)]) * rng.uniform(0.5, 2.0)
        h.set(["body.x", "body.y", "body.z", "body.qw", "body.qx", "body.qy", "body.qz"], [*p, *q])
        R = _quat_matrix(q)
        fl = p + fb @ R.T
        got_fl = np.reshape(h.get(_names(lines, "fairlead")), fl.shape)
        worst = max(worst, float(np.max(np.abs(got_fl - fl)) / 100.0))
        py = CatenaryMooring(lines, fairleads=got_fl)  # the law at the FMU's own fairlead positions
        f = py.fairlead_forces()
        got_f = np.reshape(h.get(_names(lines, "force")), f.shape)
        worst = max(worst, float(np.max(np.abs(got_f - f)) / np.max(np.abs(f))))
        tot, mom = py.total_wrench(p + R @ ref_b)
        got_m = np.array(h.get(["moment.x", "moment.y", "moment.z"]))
        worst = max(worst, float(np.max(np.abs(got_m - mom)) / (100 * np.max(np.abs(f)))))
    # 2-D: x, z and the pitch angle
    lines2, fb2 = lines2d(), np.array([[-2.0, 1.0], [2.0, 1.5]])
    h2 = Host(path2)
    for _ in range(40):
        x, z, th = rng.uniform(-3, 3), rng.uniform(0, 2), rng.uniform(-0.2, 0.2)
        h2.set(["body.x", "body.z", "body.theta"], [x, z, th])
        c, s = math.cos(th), math.sin(th)
        fl = np.array([x, z]) + fb2 @ np.array([[c, s], [-s, c]]).T
        got_fl = np.reshape(h2.get(_names(lines2, "fairlead")), fl.shape)
        worst = max(worst, float(np.max(np.abs(got_fl - fl)) / 30.0))
        py = CatenaryMooring(lines2, fairleads=got_fl)
        f = py.fairlead_forces()
        worst = max(worst, float(np.max(np.abs(np.reshape(h2.get(_names(lines2, "force")), f.shape) - f))
                                 / np.max(np.abs(f))))
    # a zero quaternion is an error, not a crash
    from fmpy.fmi1 import FMICallException

    h.set(["body.qw", "body.qx", "body.qy", "body.qz"], [0.0, 0.0, 0.0, 0.0])
    with pytest.raises(FMICallException):
        h.get(["force.x"])
    return {"worst": worst, "msg": h.messages[-1][2]}


@pytest.mark.long
def test_body_pose_moves_the_fairleads(tmp_path):
    from fmpy.validation import validate_fmu

    lines, fb = pose_lines()
    p3 = export_catenary_fmu(lines, tmp_path / "pose3.fmu", fairleads=fb, body_pose=True,
                             reference_point=(0.5, -0.2, 1.0), model_identifier="pose3")
    p2 = export_catenary_fmu(lines2d(), tmp_path / "pose2.fmu", fairleads=[[-2.0, 1.0], [2.0, 1.5]],
                             body_pose=True, pose=(0.0, 1.0, 0.0), model_identifier="pose2")
    assert validate_fmu(str(p3)) == [] and validate_fmu(str(p2)) == []
    r = isolated("_case_body_pose", p3, p2)
    assert r["worst"] <= 1e-12, r
    assert "quaternion" in r["msg"]
    from cosim.errors import InputError

    with pytest.raises(InputError, match="needs fairleads"):
        export_catenary_fmu(lines, tmp_path / "x.fmu", body_pose=True)
    with pytest.raises(InputError, match="quaternion"):
        export_catenary_fmu(lines, tmp_path / "x.fmu", fairleads=fb, body_pose=True, pose=(0, 0, 0, 0, 0, 0, 0))


C_HOST = r"""
/* A minimal FMI 2.0 co-simulation host in C: no Python anywhere in the process. */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include "fmi2Functions.h"

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    va_list ap;
    (void)env; (void)name; (void)category;
    va_start(ap, message);
    fprintf(stderr, "[%d] ", (int)status);
    vfprintf(stderr, message, ap);
    fputc('\n', stderr);
    va_end(ap);
}

#define LOAD(f) f##TYPE *f = (f##TYPE *)dlsym(lib, #f); if (!f) { fprintf(stderr, "no %s\n", #f); return 2; }

int main(int argc, char **argv)
{
    /* argv: library, GUID; stdin: n_in vr_in... n_out vr_out... n_rows, then rows of n_in values */
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    unsigned n_in, n_out, rows, i, k;
    fmi2ValueReference vin[64], vout[64];
    fmi2Real x[64], y[64];
    fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    fmi2Component c;
    (void)argc;
    if (!lib) { fprintf(stderr, "%s\n", dlerror()); return 2; }
    LOAD(fmi2Instantiate) LOAD(fmi2SetupExperiment) LOAD(fmi2EnterInitializationMode)
    LOAD(fmi2ExitInitializationMode) LOAD(fmi2SetReal) LOAD(fmi2GetReal) LOAD(fmi2DoStep)
    LOAD(fmi2Terminate) LOAD(fmi2FreeInstance)
    if (scanf("%u", &n_in) != 1) return 3;
    for (i = 0; i < n_in; i++) if (scanf("%u", &vin[i]) != 1) return 3;
    if (scanf("%u", &n_out) != 1) return 3;
    for (i = 0; i < n_out; i++) if (scanf("%u", &vout[i]) != 1) return 3;
    if (scanf("%u", &rows) != 1) return 3;
    c = fmi2Instantiate("c_host", fmi2CoSimulation, argv[2], "", &cb, fmi2False, fmi2False);
    if (!c) return 4;
    if (fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) || fmi2EnterInitializationMode(c)
        || fmi2ExitInitializationMode(c)) return 5;
    for (k = 0; k < rows; k++) {
        for (i = 0; i < n_in; i++) if (scanf("%lf", &x[i]) != 1) return 3;
        if (fmi2SetReal(c, vin, n_in, x) || fmi2DoStep(c, 0.1 * k, 0.1, fmi2True)
            || fmi2GetReal(c, vout, n_out, y)) return 6;
        for (i = 0; i < n_out; i++) printf("%.17g%c", y[i], i + 1 < n_out ? ' ' : '\n');
    }
    fmi2Terminate(c);
    fmi2FreeInstance(c);
    return 0;
}
"""


def test_fmu_builds_from_its_sources_and_runs_in_a_c_host(tmp_path):
    """The shipped sources are complete (built here from sources/ alone, as buildDescription.xml
    says), and the binary runs in a plain C program without Python; outputs equal the Python law."""
    from fmpy import read_model_description

    from moorings.catenary_mooring import CatenaryMooring

    cc = find_compiler()
    lines = lines3d()
    fmu = export_catenary_fmu(lines, tmp_path / "src.fmu", compile_binary=False, model_identifier="srcbuilt")
    src = tmp_path / "unz"
    zipfile.ZipFile(fmu).extractall(src)
    lib = tmp_path / "srcbuilt.so"
    subprocess.run([cc, "-std=c99", "-O2", "-ffp-contract=off", "-fPIC", "-shared", "-I", str(src / "sources"),
                    str(src / "sources" / "catenary.c"), str(src / "sources" / "fmi2_catenary.c"), "-o", str(lib),
                    "-lm"], check=True, capture_output=True)
    (tmp_path / "host.c").write_text(C_HOST)
    exe = tmp_path / "host"
    subprocess.run([cc, "-std=c99", "-O2", "-I", str(src / "sources"), str(tmp_path / "host.c"), "-o", str(exe),
                    "-ldl"], check=True, capture_output=True)
    md = read_model_description(str(fmu))
    v = {x.name: x.valueReference for x in md.modelVariables}
    fin, fout = _names(lines, "fairlead"), _names(lines, "force")
    traj = trajectory(lines, n=30)
    stdin = " ".join([str(len(fin)), *(str(v[n]) for n in fin), str(len(fout)), *(str(v[n]) for n in fout),
                      str(len(traj))]) + "\n"
    stdin += "\n".join(" ".join(repr(float(c)) for c in row.ravel()) for row in traj) + "\n"
    env = {"PATH": "/usr/bin:/bin"}  # nothing of Python's environment
    res = subprocess.run([str(exe), str(lib), md.guid], input=stdin, capture_output=True, text=True, env=env,
                         timeout=60)
    assert res.returncode == 0, res.stderr
    got = np.array([[float(t) for t in ln.split()] for ln in res.stdout.splitlines()])
    assert got.shape == (len(traj), len(fout))
    py = CatenaryMooring(lines)
    worst = 0.0
    for row, pos in zip(got, traj):
        py.set_fairlead_motion(pos)
        f = py.fairlead_forces()
        worst = max(worst, float(np.max(np.abs(row.reshape(f.shape) - f) / py.fairlead_tensions()[:, None])))
    assert worst <= 1e-12, worst


def test_c_sources_compile_without_warnings(tmp_path):
    """The shipped C (law + FMI wrapper, both layouts) is clean under -Wall -Wextra -pedantic -Werror."""
    cc = find_compiler()
    for body_pose in (False, True):
        lines, fb = pose_lines()
        fmu = export_catenary_fmu(lines, tmp_path / f"w{int(body_pose)}.fmu", fairleads=fb, body_pose=body_pose,
                                  compile_binary=False)
        src = tmp_path / f"w{int(body_pose)}"
        zipfile.ZipFile(fmu).extractall(src)
        res = subprocess.run([cc, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-ffp-contract=off",
                              "-fPIC", "-shared", "-I", str(src / "sources"), str(src / "sources" / "catenary.c"),
                              str(src / "sources" / "fmi2_catenary.c"), "-o", str(src / "x.so"), "-lm"],
                             capture_output=True, text=True)
        assert res.returncode == 0, res.stderr


def test_cli_export_fmu_of_a_scene(tmp_path, capsys):
    """``cosim export-fmu SCENE.toml``: the scene's own lines, no file of lines to retype;
    the fairleads start where the run starts them (the floating box's computed height), and
    the FMU's forces there are the catenary law's."""
    from fmpy import read_model_description

    from cosim.cli import main
    from cosim.scene import Scene
    from cosim.scene.build import mooring_lines
    from cosim.scene.placement import floating_height
    from moorings.catenary_mooring import CatenaryMooring
    from moorings.fmu_export import catenary_fmu_variable_map, fmu_line_names
    from moorings.fmu_mooring import FMUMooring

    example = Path(__file__).resolve().parents[1] / "examples" / "moored_box_waves.toml"
    scene = Scene.from_toml(example)
    out = tmp_path / "m.fmu"
    assert main(["export-fmu", str(example), "--out", str(out)]) == 0
    assert "2 line(s), 2-D" in capsys.readouterr().out
    lines = mooring_lines(scene)
    left, right = fmu_line_names(lines)
    v = {x.name: x for x in read_model_description(str(out)).modelVariables}
    assert float(v[f"{right}.anchor.x"].start) == 1.9 and float(v[f"{left}.length"].start) == 0.825
    assert float(v[f"{left}.weight"].start) == 10.0 and float(v[f"{left}.EA"].start) == 1e5
    z = floating_height(scene.bodies[0], 2, 0.3, 1000.0, 9.81, scene.moorings.lines) - 0.05
    fl = np.array([[float(v[f"{n}.fairlead.{a}"].start) for a in "xz"] for n in (left, right)])
    np.testing.assert_allclose(fl, [[1.1, z], [1.3, z]], atol=1e-9)
    fmu = FMUMooring(out, lines, catenary_fmu_variable_map(lines), fairleads=fl)
    fmu.initialize(0.0)
    np.testing.assert_allclose(fmu.fairlead_forces(), CatenaryMooring(lines, fairleads=fl).fairlead_forces(),
                               rtol=1e-12, atol=1e-12)
    fmu.close()
    # the box's pose in: its fairleads in the body frame, its start pose the scene's
    posed = tmp_path / "p.fmu"
    assert main(["export-fmu", str(example), "--out", str(posed), "--body-pose"]) == 0
    v = {x.name: x for x in read_model_description(str(posed)).modelVariables}
    assert float(v["body.x"].start) == pytest.approx(1.2) and float(v["body.z"].start) == pytest.approx(z + 0.05)
    assert float(v[f"{left}.fairlead_body.x"].start) == -0.1
    # a scene without lines is a clear error
    assert main(["export-fmu", str(example.with_name("sloshing_tank.toml")), "--out", str(tmp_path / "n.fmu")]) == 2
    assert "has no mooring lines" in capsys.readouterr().err and not (tmp_path / "n.fmu").exists()
