"""Yang & Li 2020, §4 (Table 2) as one scene family:
its seven tests, the scene of each, how one is run and what is measured (the tables and
figures are drawn by ``benchmarks/elastic_table2.py``; the measured study is
``docs/studies/elastic_dambreak/README.md``).

Set-up (``scenes/elastic-table2.toml``, Test 1): a column L = 146 mm wide and hu high
collapses at t = 0 and strikes a structure b = 12 mm thick and 20 b / 3 = 80 mm high,
rho_s = 2500 kg/m^3, clamped to the floor with its left face a beyond the column (base x =
L + a + b / 2), in the 0.584 m tank of Walhorn et al. (walls 0.4 m high); 2-D (x-z, 1 m
deep); the structure an 8-element MuJoCo chain (:mod:`bodies.elastic`, no damping), the
fluid the scene's dam-break set-up (c0 = 10 sqrt(2 g hu), Yang & Li 2020, Eq. 6's rule). Table 2
(E in Pa: the table prints kPa, which the paper's sub-millimetre displacements rule out):
Test 1, hu = 292 mm, a = 146 mm, E = 3.0e7 Pa, is every group's base case; Tests 2, 3 vary
hu (252, 332 mm), Tests 4, 5 a (176, 206 mm), Tests 6, 7 E (1.5e7, 7.5e6 Pa).

Each test is a scene (:func:`scene_of`) run by :mod:`cosim.study.sweep` (:func:`run_cases`:
its own process, cached by scene and code, CPU time measured). Per test (:func:`metrics`,
from the probes ``plate.corner_x``, ``plate.fluid_Fx`` and ``plate.p0 .. p8``, sampled
every 1 ms):

- arrival: the first time the fluid's force on the structure passes 1 % of its peak, and
  the onset of motion (the corner past 1 % of its peak);
- the peak x displacement of the upper left corner and its time;
- the peak pressure at the foot: the net x force on the two lowest nodes' shares (z < 15
  mm) over their span, the largest value of its 5 ms running mean (and of one sample: one
  SPH step's force, spiky); the extreme pressure at each node (Fig. 8), 5 ms means;
- the frequency of the free vibration: the spectral peak
  (:func:`cosim.study.metrics.spectral_peak`, 0.5-2.5 f1) of the corner's motion after its
  peak, high-passed at 0.3 f1 (4th-order Butterworth, both ways: the load's slow part
  out), against the dry clamped-free Timoshenko f1 of the structure;
- the quasi-static check: the tip deflection the nodal loads (5 ms means) would give on a
  static cantilever (``sum_k F_k (z_k^2 (3 L - z_k) / (6 E I) + z_k / (kappa G A))``).

What was measured (the corner's peaks rise with hu, fall with a and go nearly as 1/E; ours
3.9-4.1 times the paper's, whose figures fit a structure 3-4 times stiffer in bending than
the one it prints): docs/studies/elastic_dambreak/README.md.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from cosim.validations.registry import case

SCENE = Path(__file__).with_name("scenes") / "elastic-table2.toml"  #: Test 1
L_COL, B, H_S, RHO_S = 0.146, 0.012, 0.08, 2500.0  #: column width, structure thickness and height [m], density
#: Yang & Li 2020, Table 2: test -> (hu [m], a [m], E [Pa])
TABLE2 = {1: (0.292, 0.146, 3.0e7), 2: (0.252, 0.146, 3.0e7), 3: (0.332, 0.146, 3.0e7), 4: (0.292, 0.176, 3.0e7),
          5: (0.292, 0.206, 3.0e7), 6: (0.292, 0.146, 1.5e7), 7: (0.292, 0.146, 7.5e6)}
#: the groups of §4.1-4.3, each in ascending order of its parameter: (name, column of TABLE2, unit scale, label)
GROUPS = {"hu": ((2, 1, 3), 0, 1e3, "hu [mm]"), "a": ((1, 4, 5), 1, 1e3, "a [mm]"),
          "E": ((7, 6, 1), 2, 1e-6, "E [MPa]")}
#: the paper's numbers (its text; the figures are not digitised): arrival, time of the peak
#: (Tests 1-3), the peak displacements of Tests 1, 4, 5, the frequency band of Tests 1-3
PAPER = {"arrival_s": 0.138, "peak_t_s": 0.186, "peak_mm": {1: 0.82, 4: 0.76, 5: 0.67}, "f_band_hz": (40.0, 50.0)}
#: §4.4's slopes (its text): d(x/xmax) and d(P/Pmax) per d(parameter/max): hu +0.3 -> x +0.4, P +0.5;
#: a +0.3 -> x -0.3; E +0.8 -> x -0.7, P +0.2
SLOPES = {"peak_mm": {"hu": 0.4 / 0.3, "a": -0.3 / 0.3, "E": -0.7 / 0.8},
          "foot_p_peak_kPa": {"hu": 0.5 / 0.3, "E": 0.2 / 0.8}}
N_FOOT = 2  #: nodes whose shares make the foot (z < 15 mm with 8 elements)
SMOOTH_S = 0.005  #: running mean [s] over the sampled loads (one sample is one SPH step's force: spiky)


def scene_of(test: int, dx: float | None = None):
    """The scene of a Table 2 test: :data:`SCENE` with hu (``domain.water``), a
    (``bodies[0].base`` at x = L + a + b / 2) and E set, and optionally dx."""
    from cosim.scene import Scene

    hu, a, E = TABLE2[test]
    vals = [f"domain.water=[{{lo = [0.0, 0.0], hi = [{L_COL}, {hu}]}}]",
            f"bodies[0].base=[{L_COL + a + B / 2:.6g}, 0.0]",
            f"bodies[0].E={E}"]
    if dx is not None:
        vals.append(f"fluid.dx={dx}")
    return Scene.from_toml(SCENE).with_values(vals)


def run_cases(tests, dxs, out: Path, report=None) -> list[tuple[int, float, dict, Path]]:
    """Run each (test, dx) serially through :mod:`cosim.study.sweep`; (test, dx, record,
    folder). ``report(case, record)`` is called after each run (the sweep's progress hook)."""
    from cosim.study import sweep

    version = sweep.code_version()
    plan = [(t, dx) for dx in dxs for t in tests]
    cs = [sweep.case(i, {"test": t, "fluid.dx": dx}, scene_of(t, dx), out, version) for i, (t, dx) in enumerate(plan)]
    recs = sweep.execute(cs, workers=1, threads=1, serial=True, version=version, report=report)
    return [(t, dx, r, c.folder) for (t, dx), r, c in zip(plan, recs, cs)]


def metrics(test: int, folder: Path) -> dict:
    """The measured quantities of one run of ``test`` in ``folder`` (module docstring);
    keys starting with ``_`` are series for the figures."""
    from scipy.signal import butter, filtfilt

    from bodies.elastic import elastic_beam
    from cosim.study import sweep
    from cosim.study.metrics import spectral_peak

    s = sweep.series(folder)
    t, x = s["plate.corner_x"]
    F = s["plate.fluid_Fx"][1]
    n_nodes = sum(1 for k in s if k.startswith("plate.p") and k[7:].isdigit())
    p = np.array([s[f"plate.p{k}"][1] for k in range(n_nodes)]).T  # (samples, nodes) [Pa]
    hu, a, E = TABLE2[test]
    beam = elastic_beam("p", H_S, B, E=E, rho=RHO_S, n_elements=n_nodes - 1, base=(0.0, 0.0, 0.0))
    span = np.diff(beam.link_bounds, axis=1)[:, 0]
    z = np.linspace(0.0, H_S, n_nodes)
    flex = z**2 * (3 * H_S - z) / (6 * beam.E * beam.I) + z / (beam.kappa * beam.G * beam.A)
    k = max(1, int(round(SMOOTH_S / (t[1] - t[0]))))
    mean = lambda y: np.convolve(y, np.ones(k) / k, mode="same")  # noqa: E731 - the 5 ms running mean
    quasi = mean((p * span) @ flex)
    i = int(np.argmax(x))
    after = t >= t[i]
    f1 = float(beam.natural_frequencies(1)[0])
    hp = filtfilt(*butter(4, 0.3 * f1, btype="high", fs=1.0 / (t[1] - t[0])), x)  # the load's slow part removed
    f_vib, freqs, spec = spectral_peak(t[after], hp[after], 0.5 * f1, 2.5 * f1)
    foot_raw = (p[:, :N_FOOT] * span[:N_FOOT]).sum(axis=1) / span[:N_FOOT].sum()
    foot = mean(foot_raw)
    return {"test": test, "hu_mm": 1e3 * hu, "a_mm": 1e3 * a, "E_Pa": E,
            "arrival_s": float(t[np.argmax(np.abs(F) > 0.01 * np.abs(F).max())]),
            "motion_onset_s": float(t[np.argmax(x > 0.01 * x.max())]),
            "peak_mm": 1e3 * float(x[i]), "peak_t_s": float(t[i]),
            "force_peak_N_per_m": float(mean(F).max()), "foot_p_peak_kPa": 1e-3 * float(foot.max()),
            "foot_p_peak_raw_kPa": 1e-3 * float(foot_raw.max()), "foot_p_peak_t_s": float(t[np.argmax(foot)]),
            "p_extreme_kPa": list(1e-3 * np.array([mean(c) for c in p.T]).max(axis=1)),
            "z_mm": list(1e3 * z), "f_vib_hz": f_vib, "f1_dry_hz": f1,
            "quasi_static_max_mm": 1e3 * float(quasi.max()), "quasi_static_at_peak_mm": 1e3 * float(quasi[i]),
            "_t": t, "_x": x, "_f": freqs, "_spec": spec, "_after": (t[after][0], t[after][-1])}


# ------------------------------------------------------------------ the validation case
#: §4.2's group: the distance a (Tests 1, 4, 5), the one group the paper gives numbers for
A_GROUP = (1, 4, 5)
TABLE2_TARGET = ("the peak x displacement of the structure's upper left corner falls with a in the paper's ratios "
                 "(0.76 / 0.82 = 0.927 and 0.67 / 0.82 = 0.817 for a = 176 and 206 mm against 146 mm, Tests 4, 5 "
                 "and 1) within 0.05 each, and the structure starts to move later as a grows; the paper's absolute "
                 "peaks (0.82 / 0.76 / 0.67 mm) within 15 % reported beside it")
#: what the full variant judges: the ratios within 0.05, the fall and the onsets in order
FULL_TOLERANCES = {"ratio_err.a176": 0.05, "ratio_err.a206": 0.05, "peak_falls_with_a": True,
                   "onset_later_with_a": True}


def _a_key(test: int) -> str:
    """A test's key in the case's metrics: its distance a, "a146" ... "a206"."""
    return f"a{TABLE2[test][1] * 1e3:.0f}"


def a_group_metrics(ms: dict) -> dict:
    """The case's metrics from :func:`metrics` of the tests run (Test 1 and any of 4, 5):
    peaks, onsets, the ratios to Test 1's against the paper's, whether the peak falls and
    the onset comes later with a, and each peak's error relative to the paper's."""
    tests = [t for t in A_GROUP if t in ms]
    a = {t: _a_key(t) for t in tests}
    peak = [ms[t]["peak_mm"] for t in tests]
    onset = [ms[t]["motion_onset_s"] for t in tests]
    ratio = {a[t]: ms[t]["peak_mm"] / ms[1]["peak_mm"] for t in tests[1:]}
    paper = {a[t]: PAPER["peak_mm"][t] / PAPER["peak_mm"][1] for t in tests[1:]}
    rel = {a[t]: ms[t]["peak_mm"] / PAPER["peak_mm"][t] - 1.0 for t in tests}
    return {"peak_mm": {a[t]: ms[t]["peak_mm"] for t in tests}, "peak_t_s": {a[t]: ms[t]["peak_t_s"] for t in tests},
            "motion_onset_s": {a[t]: ms[t]["motion_onset_s"] for t in tests},
            "arrival_s": {a[t]: ms[t]["arrival_s"] for t in tests},
            "ratio_to_a146": ratio, "paper_ratio_to_a146": paper,
            "ratio_err": {k: ratio[k] - paper[k] for k in ratio},
            "peak_falls_with_a": bool(all(p > q for p, q in zip(peak, peak[1:]))),
            "onset_later_with_a": bool(all(p < q for p, q in zip(onset, onset[1:]))),
            "paper_peak_mm": {a[t]: PAPER["peak_mm"][t] for t in tests},
            "peak_rel_err_vs_paper": rel,
            "paper_peaks_within_15pct": bool(all(abs(v) <= 0.15 for v in rel.values()))}


#: the tests each variant runs and their spacing [m] (quick: True)
A_RUNS = {True: ((1, 5), 0.005), False: (A_GROUP, 0.0025)}


@case("elastic-table2", "Yang & Li 2020, §4.2 (Table 2, Tests 1, 4, 5): a 2-D dam break on an elastic cantilever at "
      "a = 146 / 176 / 206 mm from the column, the structure's peak displacement against the paper's",
      target=TABLE2_TARGET,
      quick="Tests 1 and 5 (a = 146 and 206 mm) at dx = 5 mm: the peak at a = 206 mm at least 5 % below the one at "
            "146 mm (the paper: 18 % below) and its motion starting later; the ratio is reported, not judged "
            "(0.90 at this spacing against 0.78 at 2.5 mm: the fall needs the finer spacing)",
      scene=lambda quick: scene_of(A_RUNS[quick][0][0], A_RUNS[quick][1]))
def elastic_table2(quick: bool) -> dict:
    """The a group of Yang & Li 2020's Table 2 (Tests 1, 4, 5: hu = 292 mm, E = 3.0e7 Pa, a =
    146 / 176 / 206 mm), each a scene of :func:`scene_of` run by :func:`run_cases` in its own
    process (one thread) into a temporary folder, measured by :func:`metrics`. The paper's
    text gives the peak top displacements 0.82 / 0.76 / 0.67 mm (§4.2): our peaks are about 4
    times those (our load matches the momentum flux of Ritter's dam-break flow, and beam
    theory under it gives our peak: docs/studies/elastic_dambreak/README.md), so what is
    judged is the fall with a, its ratios, and the onset's order; the absolute peaks are
    reported beside it (``peak_rel_err_vs_paper``, ``paper_peaks_within_15pct``).

    Full variant (dx = 2.5 mm, the paper's spacing): passed (peaks 3.34 / 3.04 / 2.60 mm, ratios
    within 0.04 of the paper's), the paper's absolute peaks not met (about +300 %). Quick (dx =
    5 mm, Tests 1 and 5): passed, the ratio carrying about +-0.04 of the time step's noise
    against its 0.95 bound. The figures: docs/studies/elastic_dambreak/README.md.
    """
    tests, dx = A_RUNS[quick]
    with tempfile.TemporaryDirectory(prefix="elastic_table2_") as tmp:
        res = run_cases(tests, [dx], Path(tmp))
        errors = {t: rec["error"] for t, _, rec, _ in res if rec.get("error")}
        if errors:
            raise RuntimeError(f"elastic-table2: runs failed: {errors}")
        ms = {t: metrics(t, folder) for t, _, _, folder in res}
        particles = max(int(rec.get("particles") or 0) for _, _, rec, _ in res)
        steps = sum(int(rec.get("steps") or 0) for _, _, rec, _ in res)
        cpu = {_a_key(t): float(rec.get("cpu_s", float("nan"))) for t, _, rec, _ in res}
    m = a_group_metrics(ms)
    m.update({"dx_m": dx, "cpu_s": cpu})
    curves = {f"Test {t}, a = {TABLE2[t][1] * 1e3:.0f} mm (ours)": {"x": ms[t]["_t"], "y": ms[t]["_x"] * 1e3,
                                                                   "style": "-"} for t in tests}
    out = {"metrics": m, "particles": particles, "steps": steps,
           "series": {"upper left corner": {"xlabel": "t [s]", "ylabel": "x displacement [mm]", "curves": curves}}}
    if quick:
        out["tolerances"] = {"ratio_to_a146.a206": [None, 0.95], "onset_later_with_a": True}
        # the stated target's tolerances on the tests run (Test 4's ratio is not)
        out["stated_tolerances"] = {k: v for k, v in FULL_TOLERANCES.items()
                                    if not k.startswith("ratio_err.") or k[len("ratio_err."):] in m["ratio_err"]}
    else:
        out["tolerances"] = dict(FULL_TOLERANCES)
    return out
