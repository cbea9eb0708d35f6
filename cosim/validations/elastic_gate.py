"""Validation case ``elastic-gate`` (issue 17): the water column released through an
elastic rubber gate, Antoci, Gallati & Sibilla (2007), against their measured gate-tip
displacements (refdata ``elastic_gate_antoci2007``, SOURCE.txt)."""

from __future__ import annotations

import time

import numpy as np

from cosim.validations.registry import case

DATASET = "elastic_gate_antoci2007"

# the set-up as refdata SOURCE.txt gives it (Antoci et al. 2007)
COL_L, COL_H = 0.1, 0.14  #: water column width and height [m]
GATE_L, GATE_B = 0.079, 0.005  #: gate length (clamp to free end) and thickness [m]
RHO_S, E_S, NU_S = 1100.0, 12e6, 0.4  #: rubber density [kg/m^3], Young's modulus [Pa] (Antoci's), Poisson's ratio
TANK_L = 0.6  #: tank floor length [m]: SOURCE.txt's downstream side is "open/long"; 0.6 m keeps the
#: released water off the far wall until after the last measured frame (0.36 s)
WALL_TOP = 0.2  #: top of the rigid wall above the gate and of the tank walls [m]

#: the stated tolerance: RMS difference over the measured frames relative to the measured peak, per component
TOL_RMS_REL = 0.15
#: in phase: our peak within one of the experiment's frames (0.04 s) of the measured peak
TOL_PEAK_LAG_S = 0.04


def experiment() -> dict[str, np.ndarray]:
    """The measured free-end displacements, ``(n, 2)`` each: t [s], displacement [m]
    (x: horizontal, downstream positive; y: vertical, up positive)."""
    from cosim.refdata import path

    return {"x": np.loadtxt(path(DATASET, "ng_2020_elastic_dam_break_x_displacement_antoci_2007_experiment.csv"),
                            delimiter=","),
            "y": np.loadtxt(path(DATASET, "ng_2020_elastic_dam_break_y_displacement_antoci_2007_experiment.csv"),
                            delimiter=",")}


#: the published numerical solutions (refdata SOURCE.txt), key -> label; reported, not judged
NUMERICAL = {"khayyer_2018": "Khayyer et al. 2018 (ISPH-SPH)", "yang_2012": "Yang et al. 2012 (SPH-FEM)",
             "ng_2020": "Ng et al. 2020 (SPH-VCPM)"}


def numerical() -> dict[str, dict[str, np.ndarray]]:
    """The three published numerical solutions of the free end, by key of :data:`NUMERICAL`
    and component (``"x"``, ``"y"``): ``(n, 2)`` arrays, t [s], displacement [m]."""
    from cosim.refdata import path

    def _gate_curve(name):
        return np.loadtxt(path(DATASET, name), delimiter=",")

    return {"khayyer_2018": {"x": _gate_curve("ng_2020_elastic_dam_break_x_displacement_khayyer_2018_isph_sph.csv"),
                             "y": _gate_curve("ng_2020_elastic_dam_break_y_displacement_khayyer_2018_isph_sph.csv")},
            "yang_2012": {"x": _gate_curve("ng_2020_elastic_dam_break_x_displacement_yang_2012_sph_fem.csv"),
                          "y": _gate_curve("ng_2020_elastic_dam_break_y_displacement_yang_2012_sph_fem.csv")},
            "ng_2020": {"x": _gate_curve("ng_2020_elastic_dam_break_x_displacement_ng_2020_sph_vcpm_alpha_1.csv"),
                        "y": _gate_curve("ng_2020_elastic_dam_break_y_displacement_ng_2020_sph_vcpm_alpha_1.csv")}}


#: (dx [m], t_end [s], elements) of the full (False) and quick (True) variants: the quick one
#: the scene file's (one particle across the gate: the thin-wall treatment)
GATE_RUNS = {True: (0.005, 0.3, 8), False: (0.00125, 0.4, 16)}


def gate_scene(dx: float, t_end: float = 0.4, n_elements: int = 16, sample: float = 2e-3, E: float = E_S,
               thin_wall: bool | None = None, light_body: str = "auto", beta: float = 0.0, **overrides):
    """The scene ``scenes/elastic-gate.toml`` (the quick variant's) at spacing ``dx`` [m],
    ``t_end`` [s] long, sampled every ``sample`` [s], the gate of ``n_elements`` elements,
    Young's modulus ``E`` [Pa] and stiffness-proportional damping ``beta`` [s]; the rigid
    wall above the gate 3 dx thick (the walls' layers at h = sqrt(2) dx). Fewer than two
    particles across the gate (dx > 2.5 mm) get the thin-wall treatment (``thin_wall=None``:
    by dx). ``light_body`` is the coupler's remedy; ``overrides`` set the fluid's fields."""
    from cosim.validations import case_scene

    n = case_scene.number
    if thin_wall is None:
        thin_wall = round(GATE_B / dx) < 2
    wall = f"{{lo = [{n(COL_L)}, {n(GATE_L)}], hi = [{n(COL_L + 3 * dx)}, {n(WALL_TOP)}]}}"
    return case_scene.load("elastic-gate", [
        f"fluid.dx={n(dx)}", f"world.duration={n(t_end)}", f"world.sample_every={n(sample)}", f"domain.walls=[{wall}]",
        f"bodies[0].elements={int(n_elements)}", f"bodies[0].E={n(E)}", f"bodies[0].damping={n(beta)}",
        f"bodies[0].thin_wall={'true' if thin_wall else 'false'}", f'coupling.light_body="{light_body}"',
        *case_scene.settings("fluid", overrides)])


def run_elastic_gate(dx: float, t_end: float = 0.4, n_elements: int = 16, sample: float = 2e-3,
                     E: float = E_S, thin_wall: bool | None = None, light_body: str = "auto",
                     beta: float = 0.0, **overrides) -> dict:
    """The elastic gate (2-D, x-z; Antoci et al. 2007 as refdata SOURCE.txt gives it) of
    :func:`gate_scene` (its arguments), built as ``cosim run`` builds it: a water column
    ``COL_L`` x ``COL_H`` at rest against the left wall; at x = ``COL_L`` a rubber gate
    ``GATE_B`` thick and ``GATE_L`` long hangs from a rigid wall (from z = ``GATE_L`` up,
    3 dx thick), clamped at its top, its free end at the floor (no support: it only
    touches). At t = 0 the hydrostatic column pushes the gate open and flows out under it
    onto a floor ``TANK_L`` long.

    Fluid: a dam break's set-up (the solver's defaults: Wendland, h = sqrt(2) dx, alpha =
    0.01, Fourtakas delta = 0.1, CFL 0.2; c0 = 10 sqrt(2 g COL_H), Yang & Li 2020, Eq. 6's
    rule), tank and upper wall plain dynamic boundaries, the gate's particles mDBC; the
    column starts hydrostatic. Gate: the MuJoCo chain of :mod:`bodies.elastic` hanging
    from its clamp, Timoshenko elements, RK4, no damping unless ``beta``, E = 12 MPa
    (Antoci's), nu = 0.4 (only in the shear term), the narrow-beam E (not the plane-strain
    E / (1 - nu^2) = 14.3 MPa), MuJoCo steps of at most 0.1 ms.
    Returns the free end's x and y displacement every ``sample`` [s] up to ``t_end`` [s],
    and the CPU seconds the run took (``cpu_s``, :func:`time.process_time`, all threads)."""
    from cosim.validations import case_scene

    scene = gate_scene(dx, t_end, n_elements, sample, E, thin_wall, light_body, beta, **overrides)
    with case_scene.built(scene) as b:
        coupler, gate = b.coupler, b.fluid.elastic[0]
        c0, w0 = time.process_time(), time.perf_counter()
        ts, xs, ys = [0.0], [0.0], [0.0]
        for k in range(1, int(round(t_end / sample)) + 1):
            coupler.run(k * sample)
            gate.check()
            d = gate.displacement("tip")
            ts.append(coupler.t)
            xs.append(float(d[0]))
            ys.append(float(d[2]))
        body = scene.bodies[0]
        return {"t": np.array(ts), "x": np.array(xs), "y": np.array(ys), "particles": int(b.sph.ps.n),
                "steps": coupler.steps, "cpu_s": time.process_time() - c0, "wall_s": time.perf_counter() - w0,
                "c0": b.sph.config.speed_of_sound, "dx": dx, "n_elements": body.elements,
                "thin_wall": bool(body.thin_wall), "E": body.E, "beta": body.damping}


def compare(t, x, y, t_max: float) -> dict:
    """Our free-end displacements ``x``, ``y`` [m] at times ``t`` [s] against the measured
    ones at the experiment's frames up to ``t_max`` [s] (ours interpolated there). Per
    component: the RMS difference over the frames relative to the measured peak
    (``rms_rel_x``, judged), each frame's difference relative to that peak (``err_rel_x``,
    reported, with the frame times ``t_frames_x``), the peaks and their times, the lag of
    our peak behind the measured one (``peak_lag_s_x``, judged: in phase), and the
    correlation of ours with the measured samples. Against each published numerical
    solution (reported, not judged): the RMS difference over its points up to ``t_max``
    relative to its own peak (``rms_rel_vs_numerical``), and the experiment's own RMS
    difference to it at the frames, relative to the measured peak
    (``experiment_rms_rel_vs_numerical``: how far the published methods lie from the
    measurement)."""
    out = {"rms_rel_vs_numerical": {}, "experiment_rms_rel_vs_numerical": {}}
    for key, ours in (("x", x), ("y", y)):
        ref = experiment()[key]
        ref = ref[ref[:, 0] <= t_max + 1e-9]
        ref_t = np.clip(ref[:, 0], 0.0, None)
        o = np.interp(ref_t, t, ours)
        peak = float(ref[:, 1].max())
        d = (o - ref[:, 1]) / peak
        i, j = int(np.argmax(ours)), int(np.argmax(ref[:, 1]))
        out.update({
            f"rms_rel_{key}": float(np.sqrt(np.mean(d**2))),
            f"err_rel_{key}": [round(float(v), 4) for v in d],
            f"t_frames_{key}": [round(float(v), 4) for v in ref[:, 0]],
            f"peak_mm_{key}": 1e3 * float(ours[i]), f"peak_t_s_{key}": float(t[i]),
            f"peak_ref_mm_{key}": 1e3 * peak, f"peak_ref_t_s_{key}": float(ref[j, 0]),
            f"peak_rel_err_{key}": float(ours[i] / peak - 1.0),
            f"peak_lag_s_{key}": float(t[i] - ref[j, 0]),
            f"correlation_{key}": float(np.corrcoef(o, ref[:, 1])[0, 1]),
        })
        for name, curves in numerical().items():
            c = curves[key]
            c = c[(c[:, 0] >= 0.0) & (c[:, 0] <= t_max + 1e-9)]
            d = np.interp(c[:, 0], t, ours) - c[:, 1]
            out["rms_rel_vs_numerical"][f"{name}.{key}"] = float(np.sqrt(np.mean(d**2)) / c[:, 1].max())
            e = ref[:, 1] - np.interp(ref_t, c[:, 0], c[:, 1])
            out["experiment_rms_rel_vs_numerical"][f"{name}.{key}"] = float(np.sqrt(np.mean(e**2)) / peak)
    return out


def series_plot(t, x, y) -> dict:
    """The report's plots: the free end's x and y displacement, ours against the experiment
    and the three published numerical solutions."""
    ref, num = experiment(), numerical()
    out = {}
    for key, ours, what in (("x", x, "horizontal"), ("y", y, "vertical")):
        curves = {"Antoci et al. 2007 (experiment)": {"x": ref[key][:, 0], "y": 1e3 * ref[key][:, 1], "style": "o"}}
        for name, label in NUMERICAL.items():
            curves[label] = {"x": num[name][key][:, 0], "y": 1e3 * num[name][key][:, 1], "style": "--"}
        curves["SPH + MuJoCo chain (ours)"] = {"x": t, "y": 1e3 * ours, "style": "-"}
        out[f"free end {key}"] = {"xlabel": "t [s]", "ylabel": f"{what} displacement [mm]", "curves": curves}
    return out


GATE_TARGET = ("the gate's free-end x and y displacement against Antoci et al. 2007's measurement at its frames "
               "(0.04 ... 0.36 s): per component the RMS difference relative to the measured peak within 15 %, "
               "and in phase: our peak within one frame (0.04 s) of the measured one; each frame's difference "
               "relative to the peak reported")


@case("elastic-gate", "2-D water column released through an elastic rubber gate (Antoci et al. 2007): the gate's "
      "free end against the measured x and y displacements", target=GATE_TARGET,
      quick="dx = 5 mm (one particle across the gate: the thin-wall treatment), 0.3 s, N = 8: the same criteria "
            "over the frames up to 0.3 s", scene=lambda quick: gate_scene(*GATE_RUNS[quick]))
def elastic_gate(quick: bool) -> dict:
    """See :func:`run_elastic_gate` and :func:`compare`. Full: dx = 1.25 mm (4 particles
    across the gate), N = 16, 0.4 s; quick: dx = 5 mm (thin wall), N = 8, 0.3 s.

    Result: the case does not meet its target, and neither do the published numerical
    solutions. The opening (frames up to 0.08 s) is within 8 % of the measured peak at every
    resolution, but our free end peaks at 39.5 mm at 0.108 s against the measured 46.4 mm at
    0.161 s, then settles near 28-30 mm where the experiment stays at 37-44 mm. The three
    published solutions in refdata do the same (x peaks 42.7 / 39.3 / 39.0 mm at 0.115 /
    0.120 / 0.116 s for Khayyer 2018 / Yang 2012 / Ng 2020, about 28-30 mm at 0.36 s). Judged
    by this case's criterion, each of them fails it too: RMS over the frames 17.8 / 22.6 /
    23.4 % of the measured peak in x and 25.6 / 31.2 / 28.8 % in y, peaks 0.041-0.046 s early.
    Ours lies close to them: RMS relative to each one's peak 5.6 / 1.8 / 2.3 % in x and 10.6 /
    3.3 / 6.4 % in y (full variant; 3.4-5.8 % and 4.3-6.5 % in the quick one). The
    resolution is converged: 1.25 and 2.5 mm peak within 0.3 % of each other. The chain's
    static tip deflection meets Timoshenko within 0.5 % at N = 16 (tests/test_elastic_beam.py,
    the hanging gate); the linear static tip deflection under the initial hydrostatic load is
    45.4 mm. The SPH force on the gate at rest is 72.2 N/m at dx = 2.5 mm against the hydrostatic 77.9
    N/m (-7.3 %, the kernel's truncation at the free surface and in the floor corner). A
    softer gate, E = 10 MPa (dx 2.5 mm), peaks at 41.7 mm at 0.112 s (RMS 15.7 / 23.4 %): the
    early peak is not a matter of E. Nor of the rubber's damping: stiffness-proportional
    damping of the gate's first mode at ratios zeta = 0 / 0.2 / 0.5 / 1.0 (dx 5 mm, N = 8,
    0.4 s; ``python benchmarks/elastic_gate.py --dx 0.005 --elements 8 --zeta 0,0.2,0.5,1``)
    peaks at 41.9 / 42.2 / 39.6 / 38.2 mm at 0.120 / 0.114 / 0.126 / 0.196 s (RMS x 0.198 /
    0.185 / 0.174 / 0.143): only a critically damped gate, far beyond a rubber's loss factor,
    reaches the measured time, and then 18 % low. What the models lack against the
    experiment is open: the clamp, the release of the gate, flow past its sides in the real
    tank.

    The measured table (``python benchmarks/elastic_gate.py --dx 0.0025,0.00125``; the full
    variant is the 1.25 mm row): docs/validation/elastic-gate_history.md.
    """
    dx, t_end, n_el = GATE_RUNS[quick]
    r = run_elastic_gate(dx, t_end, n_elements=n_el)
    m = compare(r["t"], r["x"], r["y"], t_end)
    m.update({"dx_m": dx, "n_elements": n_el, "thin_wall": r["thin_wall"], "E_Pa": r["E"], "c0_m_s": r["c0"],
              "simulated_s": t_end, "run_cpu_s": r["cpu_s"], "cpu_s_per_simulated_s": r["cpu_s"] / t_end})
    tol = {"rms_rel_x": TOL_RMS_REL, "rms_rel_y": TOL_RMS_REL,
           "peak_lag_s_x": TOL_PEAK_LAG_S, "peak_lag_s_y": TOL_PEAK_LAG_S}
    return {"metrics": m, "tolerances": tol, "particles": r["particles"], "steps": r["steps"],
            "series": series_plot(r["t"], r["x"], r["y"])}
