"""Validation case ``dambreak-lobovsky`` (issue 17; Yang & Li 2020, Appendix A,
Yang & Li 2020, Figures A1-A2): the 2-D dam break of Lobovsky et al. (2014),
H = 0.3 m, water levels at the gauges H1-H4 against the measured ones (refdata
``dambreak_lobovsky2014``, SOURCE.txt), plotted as Yang & Li 2020 plot them: h/H against
t* = t sqrt(g/H)."""

from __future__ import annotations

import math
import time

import numpy as np

from cosim.validations.registry import case

DATASET = "dambreak_lobovsky2014"

#: column height and tank length [m] (refdata SOURCE.txt), as the scene file gives them (with the
#: column's length, 0.6 m, and the side walls' height, 1.0 m: the run-up at the far wall stays below it)
H, TANK_L = 0.3, 1.61
#: level gauges [m] from the left wall (refdata SOURCE.txt: TNL-SPH's set-up of the case)
GAUGES = {"H1": 0.300, "H2": 0.865, "H3": 1.114, "H4": 1.3625}

#: the judged window: t* up to 5, the surge's passage before the bore reflected from the far wall
#: reaches H4 (t* about 5.5): what Yang & Li 2020 says its curves "almost overlap" on
T_JUDGED = 5.0
#: judged: RMS of (h_ours - h_measured) / H over t* <= T_JUDGED at each gauge, against each run
TOL_RMS = 0.05
#: judged: the surge's arrival (first h/H >= ARRIVAL_LEVEL) at H2-H4 within this of the measured [t*]
TOL_ARRIVAL = 0.25
ARRIVAL_LEVEL = 0.05
#: the quick variant's RMS tolerance (declared; the stated one, TOL_RMS, stays in its record)
TOL_RMS_QUICK = 0.06

#: pressure sensors P1-P4 on the far (downstream) wall x = TANK_L: their heights [m] above the floor
#: (refdata SOURCE.txt: TNL-SPH's set-up of the case); measured_pressure reads each one's file (one
#: experimental run, "peak event 5" of the paper's Figure 18)
SENSORS = {"P1": 0.003, "P2": 0.015, "P3": 0.030, "P4": 0.080}
#: the first impact: the largest p/(rho g H) at t* <= IMPACT_WINDOW (P1-P3; P4, 80 mm up, has no
#: impact peak in the measured run: its largest reading comes at t* = 5.95, the reflected bore)
IMPACT_WINDOW = 3.5
#: reported: the mean p/(rho g H) over these windows of t* (the impact, the run-up's fall, the
#: column's settling, the reflected bore), ours and measured: the level of the pressure, which the
#: impact's spikes leave out of the peak and swamp in the RMS
P_WINDOWS = ((2.45, 2.75), (2.75, 4.0), (4.0, 5.5), (5.5, 7.15))
#: declared (reported, not yet judged: see PRESSURE_TARGET): the first impact peak at P1 within this
#: fraction of the measured one, its time within TOL_ARRIVAL in t*, and the RMS of p/(rho g H) over the
#: measured record (t* <= 7.15) at P1-P4 within TOL_P_RMS
TOL_P_PEAK = 0.30
TOL_P_RMS = 0.15
PRESSURE_TARGET = (f"wall pressure p/(rho g H) at the sensors P1-P4 (far wall, 3 / 15 / 30 / 80 mm up) against "
                   f"Lobovsky et al. 2014's run 'peak event 5' (Figure 18 data): the first impact peak at P1 "
                   f"(t* <= {IMPACT_WINDOW:g}) within {TOL_P_PEAK:.0%} of the measured one and at its time within "
                   f"{TOL_ARRIVAL:g} in t*; the RMS difference over the measured record (t* <= 7.15) within "
                   f"{TOL_P_RMS:g} at each sensor; P2-P3's peaks reported")


def measured() -> dict[str, dict[str, np.ndarray]]:
    """The measured levels, by gauge and run: ``(n, 2)`` arrays of t* [-], h/H [-]."""
    from cosim.refdata import path

    def _level_file(name):
        return np.loadtxt(path(DATASET, name))

    return {"H1": {"ETSIN 01": _level_file("Fig16_WaterLevels_H1_2.dat")},
            "H2": {"ETSIN 02": _level_file("Fig16_WaterLevels_H2_3.dat"),
                   "ETSIN 01": _level_file("Fig16_WaterLevels_H2_4.dat")},
            "H3": {"ETSIN 02": _level_file("Fig16_WaterLevels_H3_3.dat"),
                   "ETSIN 01": _level_file("Fig16_WaterLevels_H3_4.dat")},
            "H4": {"ETSIN 02": _level_file("Fig16_WaterLevels_H4_4.dat"),
                   "ETSIN 01": _level_file("Fig16_WaterLevels_H4_5.dat")}}


def measured_pressure() -> dict[str, np.ndarray]:
    """The measured wall pressure by sensor: ``(n, 2)`` arrays of t* [-], p / (rho g H) [-]
    (20 kHz, t* <= 7.15, refdata SOURCE.txt)."""
    from cosim.refdata import path

    def _pressure_file(name):
        return np.loadtxt(path(DATASET, name))

    # the files' sensors 5 / 4 / 2 / 1 are P1-P4 (SOURCE.txt)
    return {"P1": _pressure_file("Fig18_peak_event_5_sensors_5.dat"),
            "P2": _pressure_file("Fig18_peak_event_5_sensors_4.dat"),
            "P3": _pressure_file("Fig18_peak_event_5_sensors_2.dat"),
            "P4": _pressure_file("Fig18_peak_event_5_sensors_1.dat")}


def sensor_pressures(f, size: float) -> tuple[np.ndarray, np.ndarray]:
    """The pressure [Pa] at the sensors :data:`SENSORS` on the far wall's face x = TANK_L:
    as a flush transducer of length ``size`` [m] reads it (:func:`fluid.probes.wall_patch_pressure`,
    the wall's momentum balance), and the fluid's pressure averaged at the face point
    (:func:`fluid.probes.pressure_at`, Sunara et al. 2021, Eq. 15)."""
    from fluid.probes import pressure_at, wall_patch_pressure

    zs = list(SENSORS.values())
    patch = np.array([wall_patch_pressure(f, [TANK_L, z], [-1.0, 0.0], size) for z in zs])
    point = pressure_at(f, np.array([[TANK_L, z] for z in zs]))
    return patch, point


def compare_pressure(t_star, p: dict, t_end: float) -> dict:
    """Ours (p/(rho g H) at ``t_star``, by sensor) against the measured run: the first impact
    peak (the largest value at t* <= :data:`IMPACT_WINDOW`) and its time at each sensor, our
    peak over the measured one less 1 at P1-P3, its time's difference [t*], and the RMS
    difference over the measured record up to ``t_end`` (the measured sampled at ours), and
    the means over :data:`P_WINDOWS` inside ``t_end`` (``"name.lo-hi"``: ours, measured)."""
    ref = measured_pressure()
    out = {"peak": {}, "peak_measured": {}, "peak_rel_err": {}, "peak_t_star": {}, "peak_t_star_measured": {},
           "peak_t_err": {}, "rms": {}, "window_mean": {}}
    for name, d in ref.items():
        ours = np.asarray(p[name], float)
        for lo, hi in P_WINDOWS:
            w, wm = (t_star > lo) & (t_star <= hi), (d[:, 0] > lo) & (d[:, 0] <= hi)
            if hi <= t_end + 1e-9 and w.any():
                out["window_mean"][f"{name}.{lo:g}-{hi:g}"] = [float(ours[w].mean()), float(d[wm, 1].mean())]
        use = t_star <= min(t_end, d[-1, 0]) + 1e-9
        out["rms"][name] = float(np.sqrt(np.mean((ours[use] - np.interp(t_star[use], d[:, 0], d[:, 1])) ** 2)))
        if name == "P4":
            continue
        w, wm = t_star <= IMPACT_WINDOW, d[:, 0] <= IMPACT_WINDOW
        i, im = int(np.argmax(np.where(w, ours, -np.inf))), int(np.argmax(np.where(wm, d[:, 1], -np.inf)))
        out["peak"][name], out["peak_measured"][name] = float(ours[i]), float(d[im, 1])
        out["peak_rel_err"][name] = float(ours[i] / d[im, 1] - 1.0)
        out["peak_t_star"][name], out["peak_t_star_measured"][name] = float(t_star[i]), float(d[im, 0])
        out["peak_t_err"][name] = float(t_star[i] - d[im, 0])
    out["rms_max"] = float(max(out["rms"].values()))
    return out


def arrival(ts, hs, level: float = ARRIVAL_LEVEL) -> float:
    """The first time in ``ts`` at which ``hs`` reaches ``level`` (linear between samples);
    NaN if it never does. Gauge H1, wet from the start, has none."""
    hs = np.asarray(hs, float)
    k = np.flatnonzero(hs >= level)
    if k.size == 0 or k[0] == 0:
        return float("nan")
    i = k[0]
    return float(ts[i - 1] + (level - hs[i - 1]) / (hs[i] - hs[i - 1]) * (ts[i] - ts[i - 1]))


def layer_level(pos, kind, gauges, dx: float) -> np.ndarray:
    """The water level [m] at each gauge x position [m] of ``gauges``: the top of the water
    standing on the floor (z = 0) there. The fluid particles within dx of the gauge's
    vertical line, from the lowest up, as long as no gap wider than 2 dx opens between
    them, + dx/2 (a flat layer of n particle rows reads n dx, as
    :func:`fluid.probes.surface_elevation` reads it); 0 where no particle lies within 2.5 dx
    of the floor (a dry gauge: the flowing water's lowest particles stand 1.5-1.6 dx above
    the dynamic-boundary floor, measured at dx = H/20). Water above a dry gap (a jet passing over the gauge, spray)
    does not count: the top-down surface of :func:`fluid.probes.surface_elevation` takes
    the highest crossing instead, and reads such a jet as the level."""
    from fluid.particles import Kind

    fl = kind == Kind.FLUID
    x, z = pos[fl, 0], pos[fl, 1]
    out = np.zeros(len(gauges))
    for i, xg in enumerate(gauges):  # four gauges, each a vectorised pass over the particles
        zz = np.sort(z[np.abs(x - xg) <= dx])
        if zz.size == 0 or zz[0] > 2.5 * dx:
            continue
        gap = np.flatnonzero(np.diff(zz) > 2.0 * dx)
        out[i] = (zz[gap[0]] if gap.size else zz[-1]) + 0.5 * dx
    return out


def lobovsky_scene(dx: float, t_star_end: float = 11.0, **settings):
    """The scene ``scenes/dambreak-lobovsky.toml`` at spacing ``dx`` [m], run to ``t_star_end``
    (t* = t sqrt(g / H)), its pressure patches 2 h long; ``settings``: the SPH fluid's
    fields set on it (``fluid.KEY``)."""
    from cosim.scene.build import fluid_config
    from cosim.scene.setup import choose
    from cosim.validations import case_scene
    from cosim.validations.case_scene import number

    values = [f"fluid.dx={number(dx)}", f"world.duration={number(t_star_end / math.sqrt(9.81 / H))}"]
    values += case_scene.settings("fluid", settings)
    scene = case_scene.load("dambreak-lobovsky", values)
    h = fluid_config(scene, choose(scene), numbers_only=True).h
    return scene.with_values([f"probes.pressure[{i}].size={number(2 * h)}" for i in range(len(scene.probes.pressure))])


def run_lobovsky(dx: float, t_star_end: float = 11.0, sample_star: float = 0.05, p_star: float = 0.005,
                 **settings) -> dict:
    """The dam break (2-D, x-z): a column 0.6 m x ``H`` at rest against the left wall
    of a tank ``TANK_L`` long, released at once at t = 0 (the gate's removal is not
    modelled): the scene :func:`lobovsky_scene` (``settings``: its SPH fluid's fields).
    Fluid: the scene's set-up for a dam break ("impact": Wendland, h = sqrt(2) dx, alpha =
    0.01, Fourtakas delta = 0.1, CFL 0.2, dynamic boundaries), c0 = 10 sqrt(2 g H) (Yang & Li
    2020, Eq. 6's rule); the column starts hydrostatic. The level at each gauge (``h``) is
    the top of the water standing on the floor there (:func:`layer_level`); ``h_top`` is
    the highest free surface on the gauge's line (:func:`fluid.probes.surface_elevation`:
    the highest z where the kernel-interpolated fluid fraction crosses 0.5), which also
    reads a jet or spray passing over the gauge. Both sampled every ``sample_star`` in t*;
    a dry gauge reads 0 (``h_top``: the floor's face). The wall pressure at the sensors
    P1-P4 (:func:`sensor_pressures`, a patch 2h long) is sampled every ``p_star`` in t*
    (``p`` over rho g H, and ``p_point``, Eq. 15 at the face point). Returns t* and h/H per
    gauge, the pressures, and the CPU seconds of the run."""
    from cosim.validations import case_scene

    with case_scene.built(lobovsky_scene(dx, t_star_end, **settings)) as b:
        return _levels_and_pressures(b.sph, t_star_end, sample_star, p_star)


def _levels_and_pressures(f, t_star_end: float, sample_star: float, p_star: float) -> dict:
    """Advance the dam break ``f`` (initialised at t = 0) to ``t_star_end``, reading the
    levels every ``sample_star`` and the pressures every ``p_star`` (:func:`run_lobovsky`)."""
    from fluid.probes import surface_elevation

    g, cfg, dx = f.config.g_down, f.config, f.config.dx
    c0, w0 = time.process_time(), time.perf_counter()
    scale = math.sqrt(g / H)  # t* = t sqrt(g / H)
    gauges = np.array(list(GAUGES.values()))
    def levels():
        return (layer_level(f.ps.pos, f.ps.kind, gauges, dx) / H,
                surface_elevation(f, gauges) / H)

    rgh, size = 1000.0 * g * H, 2.0 * cfg.h
    ts, hs, tops = [0.0], [], []
    tp, pp, pq = [0.0], [], []
    for lst, v in zip((hs, tops), levels()):
        lst.append(v)
    for lst, v in zip((pp, pq), sensor_pressures(f, size)):
        lst.append(v / rgh)
    sub = max(1, int(round(sample_star / p_star)))
    n = int(round(t_star_end / sample_star))
    t = 0.0
    for k in range(1, n + 1):
        for j in range(1, sub + 1):
            ts_next = (k - 1 + j / sub) * sample_star
            f.advance(t, ts_next / scale - t)
            t = ts_next / scale
            tp.append(ts_next)
            for lst, v in zip((pp, pq), sensor_pressures(f, size)):
                lst.append(v / rgh)
        ts.append(k * sample_star)
        for lst, v in zip((hs, tops), levels()):
            lst.append(v)
    hs, tops, pp, pq = np.array(hs), np.array(tops), np.array(pp), np.array(pq)
    return {"t_star": np.array(ts), "h": {name: hs[:, i] for i, name in enumerate(GAUGES)},
            "h_top": {name: tops[:, i] for i, name in enumerate(GAUGES)},
            "t_star_p": np.array(tp), "p": {name: pp[:, i] for i, name in enumerate(SENSORS)},
            "p_point": {name: pq[:, i] for i, name in enumerate(SENSORS)},
            "particles": int(f.ps.n), "steps": int(f.counters.steps), "cpu_s": time.process_time() - c0,
            "wall_s": time.perf_counter() - w0, "c0": cfg.speed_of_sound, "dx": dx, "t_star_end": t_star_end}


def compare(t_star, h: dict, t_end: float) -> dict:
    """Ours (h/H at ``t_star``) against each measured run: the RMS difference over t* <=
    :data:`T_JUDGED` (``rms_early``, judged) and over T_JUDGED < t* <= ``t_end``
    (``rms_late``, the reflected bore; reported), the measured runs' own RMS difference over
    the same windows (the experiment's repeatability), and the surge's arrival at H2-H4
    (first h/H >= 0.05) with its difference to the mean measured one (judged)."""
    ref = measured()
    out = {"rms_early": {}, "rms_late": {}, "repeatability_rms_early": {}, "repeatability_rms_late": {},
           "arrival_t_star": {}, "arrival_t_star_measured": {}, "arrival_err_t_star": {},
           "peak_late": {}, "peak_late_measured": {}}
    for name, runs in ref.items():
        ours = h[name]
        for run, data in runs.items():
            for key, lo, hi in (("rms_early", -1.0, T_JUDGED), ("rms_late", T_JUDGED, t_end)):
                use = (data[:, 0] > lo) & (data[:, 0] <= hi + 1e-9)
                if use.any():
                    d = np.interp(data[use, 0], t_star, ours) - data[use, 1]
                    out[key][f"{name}.{run}"] = float(np.sqrt(np.mean(d**2)))
            late = data[(data[:, 0] > T_JUDGED) & (data[:, 0] <= t_end), 1]
            if late.size:
                out["peak_late_measured"][f"{name}.{run}"] = float(late.max())
        late_ours = ours[(t_star > T_JUDGED) & (t_star <= t_end)]
        if late_ours.size:
            out["peak_late"][name] = float(late_ours.max())
        if len(runs) == 2:
            a, b = runs.values()
            for key, lo, hi in (("repeatability_rms_early", -1.0, T_JUDGED),
                                ("repeatability_rms_late", T_JUDGED, t_end)):
                use = (a[:, 0] > lo) & (a[:, 0] <= hi + 1e-9)
                if use.any():
                    d = a[use, 1] - np.interp(a[use, 0], b[:, 0], b[:, 1])
                    out[key][name] = float(np.sqrt(np.mean(d**2)))
        if name != "H1":
            meas = float(np.mean([arrival(d[:, 0], d[:, 1]) for d in runs.values()]))
            ours_a = arrival(t_star, ours)
            out["arrival_t_star"][name] = ours_a
            out["arrival_t_star_measured"][name] = meas
            out["arrival_err_t_star"][name] = ours_a - meas
    out["rms_early_max"] = float(np.max(list(out["rms_early"].values())))
    out["arrival_err_abs_max"] = float(np.max(np.abs(list(out["arrival_err_t_star"].values()))))  # NaN: none
    return out


def series_plot(t_star, h: dict, h_top: dict | None = None) -> dict:
    """The report's plots, Yang & Li 2020, Figure A2 (a)-(d): h/H against t* at H1-H4, ours (the
    standing layer, and where given the highest surface) against each measured run."""
    out = {}
    for name, runs in measured().items():
        curves = {f"Lobovsky et al. 2014, {run}": {"x": d[:, 0], "y": d[:, 1], "style": "."}
                  for run, d in runs.items()}
        curves["SPH (ours)"] = {"x": t_star, "y": h[name], "style": "-"}
        if h_top is not None:
            curves["SPH (ours), highest surface"] = {"x": t_star, "y": h_top[name], "style": ":"}
        out[f"water level {name} (x = {GAUGES[name]} m)"] = {"xlabel": "t* = t sqrt(g/H)", "ylabel": "h/H",
                                                            "curves": curves}
    return out


def pressure_plot(t_star, p: dict, p_point: dict | None = None) -> dict:
    """The report's pressure plots (the paper's Figure 18): p/(rho g H) against t* at P1-P4,
    ours (the transducer patch, and where given Eq. 15 at the face point) against the
    measured run, t* from 2 to 7.15 (dry before)."""
    out = {}
    for name, d in measured_pressure().items():
        w, wo = d[:, 0] >= 2.0, t_star >= 2.0
        curves = {"Lobovsky et al. 2014, peak event 5": {"x": d[w, 0][::5], "y": d[w, 1][::5], "style": "-"},
                  "SPH (ours), patch": {"x": t_star[wo], "y": p[name][wo], "style": "-"}}
        if p_point is not None:
            curves["SPH (ours), Eq. 15 at the face"] = {"x": t_star[wo], "y": p_point[name][wo], "style": ":"}
        out[f"wall pressure {name} ({1e3 * SENSORS[name]:g} mm up the far wall)"] = {
            "xlabel": "t* = t sqrt(g/H)", "ylabel": "p/(rho g H)", "curves": curves}
    return out


LOBOVSKY_TARGET = (f"water level h/H at the gauges H1-H4 against Lobovsky et al. 2014's measured runs, as Yang & Li 2020, "
                   f"Figure A2 plots them: over t* = t sqrt(g/H) <= {T_JUDGED:g} (the surge, before the reflected "
                   f"bore) the RMS difference within {TOL_RMS:g} at each gauge against each run, and the surge's "
                   f"arrival (h/H >= {ARRIVAL_LEVEL:g}) at H2-H4 within {TOL_ARRIVAL:g} in t* of the measured one; the "
                   f"reflected bore (t* > {T_JUDGED:g}) reported with the runs' own spread")


#: each variant's spacing [m] and end t* (quick: True; the quick one is the scene file's)
RUNS = {True: (0.015, T_JUDGED), False: (0.005, 11.0)}


@case("dambreak-lobovsky", "2-D dam break of Lobovsky et al. 2014, H = 0.3 m (Yang & Li 2020, Appendix A, Figure A2): "
      "water levels at the gauges H1-H4 against the measured runs", target=LOBOVSKY_TARGET,
      quick=f"dx = H/20 = 15 mm, t* <= {T_JUDGED:g}: the surge's arrival at H2-H4 within {TOL_ARRIVAL:g} in t*, "
            f"and the RMS difference within {TOL_RMS_QUICK:g} (the full variant's {TOL_RMS:g} at H/60: at H/20 the "
            f"surge is 5-7 particles thick)", scene=lambda quick: lobovsky_scene(*RUNS[quick]))
def dambreak_lobovsky(quick: bool) -> dict:
    """See :func:`run_lobovsky` and :func:`compare`; the scene ``scenes/dambreak-lobovsky.toml``
    (:func:`lobovsky_scene`). Full: dx = H/60 = 5 mm, t* <= 11 (1.92 s); quick: dx = H/20 =
    15 mm, t* <= 5 (0.87 s).

    Result: the full variant meets the declared target. Over the surge (t* <= 5) the largest
    RMS difference of h/H is 0.033 (H2 against run ETSIN 01; 0.011-0.026 elsewhere); the
    measured runs differ from each other by 0.006-0.010 there. The surge arrives early at
    every gauge: by 0.09 / 0.16 / 0.19 in t* at H2 / H3 / H4 (15-33 ms), growing along the
    tank, as the instantly released column of ``dambreak-2d`` leads Martin & Moyce's clock
    (the gate's removal, about 0.1 s here, is not modelled).

    The reflected bore (t* > 5) is reported, not judged. It plunges back over H4-H2 with air
    beneath its front, so the two readings of the level part there. The water standing on
    the floor (:func:`layer_level`, the judged one) reads only the layer under the air. Its
    RMS differences at H/60 are 0.07 (H1), 0.12-0.23 (H2), 0.15-0.16 (H3) and 0.40 (H4). The
    highest surface on the gauge's line (``top_surface`` in the metrics) reads the bore's
    envelope: 0.15, 0.25-0.36, 0.15-0.16 and 0.16-0.18, but it also
    catches spray (1.19 H at H1). The two measured runs differ by 0.15 / 0.10 / 0.05 at H2 /
    H3 / H4. During the surge both readings agree at H1-H3. At H4 the highest surface reads
    1.97 H at t* = 4.5-4.8: the run-up jet from the far wall falls over the gauge with a dry
    gap beneath. That alone takes its RMS there to 0.39, which is why the judged level is
    the standing water.

    Measured at H/20, H/30 and H/60 (``python benchmarks/dambreak_lobovsky.py --dx
    0.015,0.01,0.005``), the quick variant's 0.052, and the wall pressure at P1-P4 (reported,
    not judged, not met: single-sample impact spikes 1.2-4 times the measured peaks, the mean
    levels close): docs/validation/dambreak-lobovsky_history.md.
    """
    dx, t_end = RUNS[quick]
    r = run_lobovsky(dx, t_end)
    m = compare(r["t_star"], r["h"], t_end)
    top = compare(r["t_star"], r["h_top"], t_end)
    m["top_surface"] = {k: top[k] for k in ("rms_early", "rms_late", "rms_early_max", "arrival_err_abs_max",
                                            "peak_late")}
    m["pressure"] = compare_pressure(r["t_star_p"], r["p"], t_end)  # reported: PRESSURE_TARGET
    m["pressure_point"] = compare_pressure(r["t_star_p"], r["p_point"], t_end)
    m.update({"dx_m": dx, "particles_across_H": round(H / dx), "c0_m_s": r["c0"],
              "simulated_s": t_end / math.sqrt(9.81 / H), "run_cpu_s": r["cpu_s"]})
    m["cpu_s_per_simulated_s"] = r["cpu_s"] / m["simulated_s"]
    tol = {"rms_early_max": TOL_RMS, "arrival_err_abs_max": TOL_ARRIVAL}
    out = {"metrics": m, "tolerances": tol, "particles": r["particles"], "steps": r["steps"],
           "series": {**series_plot(r["t_star"], r["h"], r["h_top"]),
                      **pressure_plot(r["t_star_p"], r["p"], r["p_point"])}}
    if quick:
        out["stated_tolerances"] = tol
        out["tolerances"] = {**tol, "rms_early_max": TOL_RMS_QUICK}
    return out
