"""The water in the hollow arch rib of Wang et al. 2022 (§4) under the
1940 El Centro records: a coarse run, and what the paper's spike frequencies are.

``--predict`` (no run, a second): the quarter-wave acoustic resonance of the water column
in each leg of the rib, ``f_n = (2n - 1) c0 / (4 L)`` (a column closed at the springing,
free at the surface; L its length along the rib's axis from the springing to the water
level, c0 the model's speed of sound), with the paper's c0 = sqrt(7 B / rho0) = 140 m/s
(B = 2.8e6 Pa, §4), against the paper's first spike / inner-wave frequency over its depth
study (Table 5, Eq. 18) and its overtones (Table 3: near 3, 5, 7 times the first). At an
arch-axis coefficient m = 2.24 the first mode meets Table 5 within 2.4 % at all ten depths,
the overtones 8-10 % above Table 3's: the spikes the paper reads as the water's natural
frequency look like the acoustic modes of its artificially compressible water, which move
with the speed of sound chosen (real water: 1480 m/s, 11.7 Hz).

Run (``--dx 0.2 --duration 20``): the rib (``fluid.shapes.arch_rib_cavity``, m = 2.24,
inner height 1.458 m: the paper gives neither; these meet its particle counts within 1 %,
tests/test_arch_rib.py) filled to 15.56 m, shaken by El Centro (``--record ew``, ``ns``,
``up``, ``ew+up``, ``ns+up``: the paper's cases without Wenchuan), a pressure patch on
the lower face of each leg where the axis is at z = 8 m (the paper's B1-B18 are drawn in
its Figure 6, not given as numbers); prints the FFT peaks of both patches, their
correlation (the paper: opposite phase under horizontal excitation, Figure 13), and the
quarter-wave prediction for the run's c0. ``--c0`` sets the speed of sound (the paper's
140 m/s; default: the sloshing set-up's 10 sqrt(g h)).

``--ringdown`` rings the mode free (a pulse, then free ringing; ``cosim.validations.arch_rib.ring_rib``,
fitted by ``damped_mode``) instead of driving it; ``--convergence DXS`` runs the resolution
study at the design level against the column's continuum mode (``stratified_quarter_wave``:
the Tait water's sound speed rises with depth as sqrt(c0^2 + 6 g d)); ``--depth-study`` rings
the mode at each of Table 5's ten levels (``--levels`` a subset, ``--json FILE`` keeps the
rows); ``--cases ew,ns,up,ew+up,ns+up`` runs one record each at the design level (Tables 3-4,
Figures 13-15; ``--figures DIR`` one PNG per case); ``--stop T`` holds the rib still from T
on, the water ringing after the record. For example::

    python benchmarks/arch_rib_quake.py --convergence 0.3,0.2,0.15,0.1,0.07 --ringdown --duration 6
    python benchmarks/arch_rib_quake.py --depth-study --ringdown --dx 0.1 --duration 4

The measured tables (resolution, depth study, the five records, the inner wave) and what
they show: docs/benchmarks/arch_rib_quake.md.
"""

from __future__ import annotations

import argparse
import csv
import json
import math

import numpy as np

from cosim import refdata
from fluid.shapes import arch_rib_cavity, catenary_arch_axis

SPAN, RISE, LEVEL = 140.0, 23.333, 15.56  # m, Wang et al. 2022, §4
M, HC = 2.24, 1.458  # arch-axis coefficient [-], inner height [m]: chosen (see the docstring)
C0_PAPER = math.sqrt(7 * 2.8e6 / 1000.0)  # m/s, from the paper's B = 2.8e6 Pa and gamma = 7


def _records():
    return {"ns": refdata.path("earthquake_el_centro_1940", "RSN6_IMPVALL.I_I-ELC180-hor1.AT2"),
            "ew": refdata.path("earthquake_el_centro_1940", "RSN6_IMPVALL.I_I-ELC270-hor2.AT2"),
            "up": refdata.path("earthquake_el_centro_1940", "RSN6_IMPVALL.I_I-ELC-UP.AT2")}


def column_length(depth: float, m: float = M) -> float:
    """Length [m] along the rib's axis from a springing up to the water level ``depth`` [m]."""
    a = catenary_arch_axis(SPAN, RISE, m, 200001)
    right = a[a[:, 0] >= 0][::-1]  # from the springing up to the crown
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(right, axis=0).T))])
    return float(np.interp(depth, right[:, 1], s))


def quarter_wave(c0: float, depth: float, m: float = M, n: int = 1) -> float:
    """``(2n - 1) c0 / (4 L)`` [Hz]: the n-th acoustic mode of the leg's water column."""
    return (2 * n - 1) * c0 / (4 * column_length(depth, m))


def _paper_table(name):
    with open(refdata.path("arch_rib_wang2022", name)) as f:
        return list(csv.DictReader(f))


def predict() -> None:
    t5 = [(float(r["depth_m"]), float(r["wave_frequency_Hz"]))
          for r in csv.DictReader(open(refdata.path("arch_rib_wang2022", "table5_wave_frequency_vs_depth.csv")))]
    print(f"quarter-wave mode c0/(4L), c0 = {C0_PAPER:.1f} m/s (the paper's B), against Wang et al. 2022, Table 5 and Eq. 18")
    print(f"{'depth [m]':>10} {'L [m]':>7} " + " ".join(f"{'m=' + str(m):>8}" for m in (1.5, 2.24, 3.0))
          + f" {'Table 5':>8} {'Eq. 18':>8}")
    for d, f5 in t5:
        eq18 = (4.10239 * (d / RISE) ** 2 - 9.22848 * (d / RISE) + 6.06132) / math.sqrt(RISE / 9.81)
        row = " ".join(f"{quarter_wave(C0_PAPER, d, m):8.3f}" for m in (1.5, 2.24, 3.0))
        print(f"{d:10.2f} {column_length(d):7.2f} {row} {f5:8.2f} {eq18:8.3f}")
    print("\novertones at 15.56 m (quarter wave: 1, 3, 5, 7 times the first) against Wang et al. 2022, Table 3 [Hz]:")
    f1 = quarter_wave(C0_PAPER, LEVEL)
    print(f"{'quarter wave, m = 2.24':>26}: " + ", ".join(f"{(2 * n - 1) * f1:.3f}" for n in range(1, 5)))
    for r in _paper_table("table3_spikes.csv"):
        print(f"{r['case']:>26}: " + ", ".join(r[f"spike{n}_Hz"] for n in range(1, 5)))
    modes = {int(r["order"]): float(r["frequency_Hz"]) for r in _paper_table("table2_bridge_modes.csv")}
    print(f"\nthe bridge's 2nd and 4th modes (Table 2): {modes[2]} and {modes[4]} Hz")


def _patches(dx: float):
    """A patch on the lower face of each leg where the axis is at z = 8 m."""
    from cosim.scene import Patch

    a = catenary_arch_axis(SPAN, RISE, M, 200001)
    right = a[a[:, 0] >= 0][::-1]
    x = float(np.interp(8.0, right[:, 1], right[:, 0]))
    k, xi = math.acosh(M), 2 * x / SPAN
    slope = -RISE / (M - 1) * k * math.sinh(k * xi) * 2 / SPAN
    n = np.array([-slope, 1.0]) / math.hypot(1.0, slope)
    c = np.array([x, RISE - RISE / (M - 1) * (math.cosh(k * xi) - 1)]) - 0.5 * HC * n
    return [Patch("right", tuple(c), tuple(n), 4 * dx), Patch("left", (-c[0], c[1]), (-n[0], n[1]), 4 * dx)]


def run(dx: float, duration: float, record: str, out: str, c0: float | None) -> dict:
    from cosim.scene import SPH, GroundMotion, PolygonTank, Probes, Record, Scene, World

    files = _records()
    comps = [Record(file=str(files[r]), direction=(0.0, 1.0) if r == "up" else (1.0, 0.0)) for r in record.split("+")]
    scene = Scene(name="arch_rib", world=World(dim=2, duration=duration, sample_every=0.02, snapshot_every=0),
                  fluid=SPH(dx=dx, c0=c0), domain=PolygonTank(vertices=arch_rib_cavity(SPAN, RISE, HC, M).tolist(),
                                                             fill_level=LEVEL),
                  base_motion=GroundMotion(components=comps), probes=Probes(pressure=_patches(dx), energy=True))
    r = scene.run(out, overwrite=True, progress=None)
    t = r.t
    keep = t >= min(2.5, 0.25 * duration)  # past the start's transient
    res = {k: r.summary[k] for k in ("particles", "fluid_particles", "steps", "cpu_s", "wall_s", "speed_of_sound_m_s")}
    for name in ("right", "left"):
        y = r[f"{name}.p"][keep]
        y = (y - y.mean()) * np.hanning(y.size)
        F = np.abs(np.fft.rfft(y, 8 * y.size))
        f = np.fft.rfftfreq(8 * y.size, t[1] - t[0])
        peaks = [i for i in range(1, F.size - 1) if F[i] > F[i - 1] and F[i] >= F[i + 1] and f[i] > 0.2]
        peaks = sorted(sorted(peaks, key=lambda i: -F[i])[:5])
        res[f"{name}_peaks_Hz"] = [round(float(f[i]), 3) for i in peaks]
    res["correlation"] = round(float(np.corrcoef(r["right.p"][keep], r["left.p"][keep])[0, 1]), 3)
    res["quarter_wave_Hz"] = round(quarter_wave(r.summary["speed_of_sound_m_s"], LEVEL), 3)
    return res


MIN_PERIODS = 1.2  # periods of c0/(4L) that ring_rib's shortest fit window must hold (ring_duration)


def ring_duration(level: float, c0: float, base: float) -> float:
    """The length [s] of the ring-down run at ``level`` [m] in the depth study: ``base``,
    lengthened in 2 s steps until the shortest of ``ring_rib``'s four fit windows (from
    PULSE_PERIOD + 0.5 s to the run's end less 1 s) holds :data:`MIN_PERIODS` periods of
    the level's quarter wave c0/(4L). The deeper the water, the longer the column and the
    slower its mode: at dx = 0.1 m and 4 s the window held 1.23 periods at 19 m and its
    fits agreed within 0.37 %, 1.13 at 20 m: 0.93 %, 1.03 at 21 m: 7 % (the mode read the same);
    with base 4 s at 140 m/s it gives 4 s down to 19 m, 6 s at 20 and 21 m."""
    from cosim.errors import InputError
    from cosim.validations.arch_rib import PULSE_PERIOD, shortest_window

    if not base >= PULSE_PERIOD + 3.0:
        raise InputError(f"ring_duration: base={base!r} s (--duration) leaves under 3 s of free ringing after the "
                         f"{PULSE_PERIOD} s pulse; give at least {PULSE_PERIOD + 3.0} s")
    d = base
    while shortest_window(PULSE_PERIOD, d) * quarter_wave(c0, level) < MIN_PERIODS:
        d += 2.0
    return d


def depth_study(dx: float, duration: float, c0: float, record: str, levels=None, ringdown: bool = False) -> list[dict]:
    """One run per level of Table 5: ours, Table 5's and the quarter wave's first spike
    (``ringdown``: the mode rung by a vertical pulse, ``cosim.validations.arch_rib.ring_rib``,
    over ``ring_duration(level, c0, duration)`` [s]; under El Centro over ``duration``)."""
    from cosim.validations.arch_rib import ring_rib, run_rib, stratified_quarter_wave

    t5 = {float(r["depth_m"]): float(r["wave_frequency_Hz"])
          for r in _paper_table("table5_wave_frequency_vs_depth.csv")}
    rows = []
    for d in (levels or sorted(t5)):
        run_s = ring_duration(d, c0, duration) if ringdown else duration
        if ringdown:
            r = ring_rib(dx, run_s, level=d, c0=c0)
            f1, qw, extra = r["mode_Hz"], r["quarter_wave_Hz"], {"mode_std_Hz": r["mode_std_Hz"],
                                                                  "mode_window_spread": r["mode_window_spread"]}
        else:
            r = run_rib(dx, run_s, tuple(record.split("+")), level=d, c0=c0)
            f1, qw, extra = r["free_spikes_Hz"][0], r["quarter_wave_Hz"][0], {"all_points_first_spike_Hz":
                                                                              r["spikes_Hz"][0]}
        rows.append({"depth_m": d, "duration_s": run_s, "ours_Hz": f1, **extra,
                     "table5_Hz": t5.get(d), "quarter_wave_Hz": qw,
                     "ours_vs_table5": None if d not in t5 else round(f1 / t5[d] - 1, 4),
                     "ours_vs_quarter_wave": round(f1 / qw - 1, 4), "particles": r["particles"], "steps": r["steps"],
                     "cpu_s": r["cpu_s"], "cpu_s_per_simulated_s": r["cpu_s_per_simulated_s"]})
        rows[-1]["stratified_Hz"] = round(stratified_quarter_wave(c0, d), 4)
        rows[-1]["ours_vs_stratified"] = round(f1 / rows[-1]["stratified_Hz"] - 1, 4)
        print(json.dumps(rows[-1]), flush=True)
    print(f"\n{'depth':>6} {'ours':>7} {'Table 5':>8} {'c0/4L':>7} {'column':>7} {'vs T5':>7} {'vs c0/4L':>8} "
          f"{'vs column':>9} {'CPU-s/s':>8} {'run [s]':>7}")
    for x in rows:
        t5s = f"{x['table5_Hz']:8.3f}" if x["table5_Hz"] else f"{'-':>8}"
        vs = f"{100 * x['ours_vs_table5']:6.1f}%" if x["ours_vs_table5"] is not None else f"{'-':>7}"
        print(f"{x['depth_m']:6.2f} {x['ours_Hz']:7.3f} {t5s} {x['quarter_wave_Hz']:7.3f} {x['stratified_Hz']:7.3f} {vs} "
              f"{100 * x['ours_vs_quarter_wave']:7.1f}% {100 * x['ours_vs_stratified']:8.1f}% "
              f"{x['cpu_s_per_simulated_s']:8.1f} {x['duration_s']:7g}")
    return rows


def _keep_spectra(spectra: dict, label: str, r: dict) -> None:
    """The run's summed spectra (all points, free part) up to 10 Hz, for ``--spectra``."""
    for key in ("_spectrum", "_free_spectrum"):
        if key in r:
            f, a = r[key]
            spectra[f"{label}{key}_f"], spectra[f"{label}{key}_a"] = f, a


def convergence(dxs, duration: float, c0: float, record: str, spectra_file: str | None = None,
                ringdown: bool = False) -> list[dict]:
    """The first spike at the design level against dx (``ringdown``: the mode rung by a
    vertical pulse, ``ring_rib``); the reference is the Richardson extrapolation from the
    three finest (``cosim.study._richardson``: f(dx) = f* + C dx^p, p observed) where they
    converge monotonically, else the finest; the cheapest dx within 2 % of it
    (``spectra_file``: each run's spectra and series kept there as it ends)."""
    from cosim.errors import InputError
    from cosim.study import _richardson
    from cosim.validations.arch_rib import ring_rib, run_rib, stratified_quarter_wave

    rows, spectra = [], {}
    for dx in dxs:
        if ringdown:
            r = ring_rib(dx, duration, c0=c0)
            row = {"first_spike_Hz": r["mode_Hz"], "mode_std_Hz": r["mode_std_Hz"],
                   "mode_window_Hz": r["mode_window_Hz"], "mode_window_spread": r["mode_window_spread"],
                   "sigma_1_s": r["sigma_1_s"]}
        else:
            r = run_rib(dx, duration, tuple(record.split("+")), c0=c0)
            row = {"first_spike_Hz": r["free_spikes_Hz"][0], "free_spikes_Hz": r["free_spikes_Hz"],
                   "all_points_spikes_Hz": r["spikes_Hz"], "pair_correlation_max": max(r["pair_correlation"])}
        if spectra_file:
            _keep_spectra(spectra, f"dx{dx}", r)
            spectra[f"dx{dx}_t"], spectra[f"dx{dx}_p"] = r["_series"][:2]
            np.savez_compressed(spectra_file, **spectra)
        rows.append({"dx_m": dx, "particles_across": round(HC / dx, 1), "fluid_particles": r["fluid_particles"],
                     **row, "particles": r["particles"], "steps": r["steps"], "cpu_s": r["cpu_s"],
                     "cpu_s_per_simulated_s": r["cpu_s_per_simulated_s"],
                     "cpu_s_for_40_s": round(40 * r["cpu_s_per_simulated_s"])})
        print(json.dumps(rows[-1]), flush=True)
    ref, how = min(rows, key=lambda x: x["dx_m"])["first_spike_Hz"], f"the finest, dx {min(dxs)} m"
    if len(rows) >= 3:
        fine = sorted(rows, key=lambda x: x["dx_m"])[:3]
        try:
            f_inf, order = _richardson([x["dx_m"] for x in fine], [x["first_spike_Hz"] for x in fine])
            ref, how = f_inf, f"Richardson from dx {', '.join(str(x['dx_m']) for x in fine)} m, order {order:.2f}"
        except InputError as e:
            how += f" (no Richardson extrapolation: {e})"
    column = stratified_quarter_wave(c0, LEVEL)
    for x in rows:
        x["vs_reference"] = round(x["first_spike_Hz"] / ref - 1, 4)
        x["vs_column_mode"] = round(x["first_spike_Hz"] / column - 1, 4)
    print(f"\n{'dx':>5} {'across':>6} {'particles':>9} {'CPU-s/s':>8} {'spike':>7} {'vs ref':>7} {'vs column':>9} "
          f"{'40 s [CPU-s]':>12}")
    for x in rows:
        print(f"{x['dx_m']:5.2f} {x['particles_across']:6.1f} {x['particles']:9d} {x['cpu_s_per_simulated_s']:8.1f} "
              f"{x['first_spike_Hz']:7.4f} {100 * x['vs_reference']:6.2f}% {100 * x['vs_column_mode']:8.2f}% "
              f"{x['cpu_s_for_40_s']:12d}")
    print(f"reference {ref:.4f} Hz ({how}); the column's continuum mode (stratified_quarter_wave) {column:.4f} Hz")
    for name, key in (("the reference", "vs_reference"), ("the column's continuum mode", "vs_column_mode")):
        ok = [x for x in rows if abs(x[key]) <= 0.02]
        best = min(ok, key=lambda x: x["cpu_s"]) if ok else None
        print(f"cheapest within 2 % of {name}: " + (f"dx = {best['dx_m']} m ({best['cpu_s_per_simulated_s']} CPU-s per "
                                                    f"simulated s, a 40 s record {best['cpu_s_for_40_s']} CPU-s)"
                                                    if best else "none"))
    return rows


PAPER_CASE = {"ew": "El Centro EW", "ns": "El Centro NS", "up": "El Centro Vertical",
              "ew+up": "El Centro EW + Vertical", "ns+up": "El Centro NS + Vertical"}


def _phase(corr) -> str:
    """Figures 13-14's reading of the pairs Bk/B(k+9): all below -0.5 opposite, all above
    +0.5 the same, else mixed."""
    return "opposite" if max(corr) < -0.5 else "same" if min(corr) > 0.5 else "mixed"


def spectrum_plot(curves: dict, folder: str, name: str, title: str) -> str:
    """One PNG (``cosim.report.plot_series``) of normalised spectra {label: (f, a)} up to
    8 Hz, with Table 3's first spike, c0/(4L) at 140 m/s and the bridge's 2nd and 4th
    modes (Table 2) marked: the paper's comparison of its Figure 15 with Table 2."""
    from pathlib import Path

    from cosim.report import plot_series
    from cosim.validations.arch_rib import F_MIN, bridge_mode_lines

    c = {}
    for label, (f, a) in curves.items():
        keep = f <= 8.0
        c[label] = {"x": f[keep].tolist(), "y": (a[keep] / a[(f > F_MIN) & keep].max()).tolist(), "style": "-"}
    for label, x in bridge_mode_lines().items():
        c[label] = {"x": x["x"].tolist(), "y": x["y"].tolist(), "style": x["style"]}
    c[f"Wang et al. 2022, Table 3 first spike (1.125 Hz); c0/(4L) at 140 m/s ({quarter_wave(C0_PAPER, LEVEL):.3f} Hz)"] = {
        "x": [1.125, 1.125, math.nan, quarter_wave(C0_PAPER, LEVEL), quarter_wave(C0_PAPER, LEVEL)],
        "y": [0.0, 1.0, math.nan, 0.0, 1.0], "style": "k--"}
    Path(folder).mkdir(parents=True, exist_ok=True)
    out = plot_series({title: {"xlabel": "f [Hz]", "ylabel": "amplitude / its largest above 0.3 Hz [-]",
                               "curves": c}}, Path(folder), name)
    return str(Path(folder) / out[0][1])


def cases(dx: float, duration: float, c0: float, records, figures: str | None = None,
          gauges: bool = True, stop: float | None = None) -> list[dict]:
    """The paper's excitation cases without Wenchuan (Wang et al. 2022, §4.2, Tables 3-4, Figures 13-15),
    one run each at the design level: the spikes of B1-B18 summed against Table 3, those
    of the unforced part (one-direction records), the inner wave (the gauges' surface
    elevation) against Table 4, and the pairs' phase (Figures 13-14); with ``stop`` [s]
    the records end there and the water's free ringing after them is read (``run_rib``:
    ``ringing_Hz``, the validation's judged reading), the rest over the record."""
    from cosim.errors import InstabilityError
    from cosim.validations.arch_rib import run_rib

    t3 = {r["case"]: [float(r[f"spike{n}_Hz"]) for n in range(1, 5)] for r in _paper_table("table3_spikes.csv")}
    t4 = {r["case"]: float(r["wave_frequency_Hz"]) for r in _paper_table("table4_inner_wave_frequency.csv")}
    rows = []
    for rec in records:
        name = PAPER_CASE[rec]
        try:
            r = run_rib(dx, duration, tuple(rec.split("+")), c0=c0, gauges=gauges, stop=stop)
        except InstabilityError as e:  # a gauge left dry (the level fell) stops the run: again without them
            if not gauges or "gauge" not in str(e):
                raise
            print(json.dumps({"case": name, "dx_m": dx, "stopped": str(e), "again": "without gauges"}), flush=True)
            r = run_rib(dx, duration, tuple(rec.split("+")), c0=c0, stop=stop)
        rows.append({"case": name, "dx_m": dx, "duration_s": duration, "spikes_Hz": r["spikes_Hz"],
                     "table3_Hz": t3[name], "free_part": r.get("free_part"), "free_spikes_Hz": r.get("free_spikes_Hz"),
                     "inner_wave_Hz": r.get("inner_wave_Hz"), "free_inner_wave_Hz": r.get("free_inner_wave_Hz"),
                     "table4_Hz": t4[name], "surface_amplitude_m": r.get("surface_amplitude_m"),
                     "pair_correlation": r["pair_correlation"], "phase": _phase(r["pair_correlation"]),
                     "stop_s": stop, "ringing_Hz": r.get("ringing_Hz"), "ringing_spikes_Hz": r.get("ringing_spikes_Hz"),
                     "ringing_window_spread": r.get("ringing_window_spread"),
                     "particles": r["particles"], "fluid_particles": r["fluid_particles"], "steps": r["steps"],
                     "cpu_s": r["cpu_s"], "cpu_s_per_simulated_s": r["cpu_s_per_simulated_s"]})
        print(json.dumps(rows[-1]), flush=True)
        if figures:
            curves = {"B1-B18 summed": r["_spectrum"]}
            if "_free_spectrum" in r:
                curves[f"its {r['free_part']} part (unforced)"] = r["_free_spectrum"]
            if "_surface_spectrum" in r:
                curves["surface at the gauges"] = r["_surface_spectrum"]
            print(spectrum_plot(curves, figures, f"arch-rib_{rec.replace('+', '-')}_dx{dx}",
                                f"{name}, dx {dx} m, {duration:g} s"), flush=True)
    print(f"\n{'case':>24} {'first spike':>11} {'T3':>6} {'free':>6} {'ringing':>7} {'wave':>6} {'T4':>6} "
          f"{'pairs':>14} {'phase':>8}")
    for x in rows:
        free = f"{x['free_spikes_Hz'][0]:6.3f}" if x["free_spikes_Hz"] else f"{'-':>6}"
        wave = f"{x['inner_wave_Hz']:6.3f}" if x["inner_wave_Hz"] else f"{'-':>6}"
        ring = f"{x['ringing_Hz']:7.4f}" if x["ringing_Hz"] else f"{'-':>7}"
        print(f"{x['case']:>24} {x['spikes_Hz'][0]:11.3f} {x['table3_Hz'][0]:6.3f} {free} {ring} {wave} "
              f"{x['table4_Hz']:6.2f} {min(x['pair_correlation']):6.2f}..{max(x['pair_correlation']):5.2f} "
              f"{x['phase']:>8}")
    return rows


def convergence_figure(spectra_file: str, folder: str) -> str:
    """The unforced (symmetric) part's spectrum of every ``--convergence`` run kept in
    ``--spectra``, overlaid."""
    z = np.load(spectra_file)
    dxs = sorted({float(k[2:].split("_")[0]) for k in z.keys() if k.endswith("_free_spectrum_f")}, reverse=True)
    curves = {f"dx {dx} m ({HC / dx:.1f} particles across), symmetric part":
              (z[f"dx{dx}_free_spectrum_f"], z[f"dx{dx}_free_spectrum_a"]) for dx in dxs}
    return spectrum_plot(curves, folder, "arch-rib", "El Centro EW, the unforced part against dx")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--predict", action="store_true", help="the quarter-wave table only (no run)")
    ap.add_argument("--dx", type=float, default=0.2, help="particle spacing [m]")
    ap.add_argument("--duration", type=float, default=None,
                    help="seconds of the record [s] (default 20; with --ringdown 6: the pulse and the free ringing; "
                         "--depth-study --ringdown: the shortest, longer where the level's mode is slow)")
    ap.add_argument("--ringdown", action="store_true",
                    help="--convergence / --depth-study: the mode rung by one vertical pulse instead of El Centro")
    ap.add_argument("--record", default="ew", choices=["ew", "ns", "up", "ew+up", "ns+up"],
                    help="El Centro components (one direction for --depth-study / --convergence: the free part)")
    ap.add_argument("--c0", type=float, default=None, help="speed of sound [m/s] (the paper's: 140)")
    ap.add_argument("--out", default="out/arch_rib")
    ap.add_argument("--depth-study", action="store_true", help="Table 5's levels, one run each (c0 140 by default)")
    ap.add_argument("--levels", default=None, help="levels [m] for --depth-study, comma-separated (Table 5's)")
    ap.add_argument("--convergence", default=None, help="dx values [m], comma-separated: the first spike against dx")
    ap.add_argument("--json", default=None, help="write the study's rows to this file")
    ap.add_argument("--spectra", default=None,
                    help="write each run's summed spectra and its B1-B18 series to this .npz file")
    ap.add_argument("--cases", default=None,
                    help="records, comma-separated (ew,ns,up,ew+up,ns+up: the paper's cases without Wenchuan)")
    ap.add_argument("--no-gauges", action="store_true", help="--cases without the surface gauges (Table 4)")
    ap.add_argument("--stop", type=float, default=None,
                    help="--cases: the records end here [s], the rib at rest after, the water's ringing read")
    ap.add_argument("--figures", default=None, help="folder for the spectra's PNGs (--cases, --spectra-figure)")
    ap.add_argument("--spectra-figure", action="store_true",
                    help="no run: the PNG of the --spectra file's runs, overlaid, into --figures")
    a = ap.parse_args()
    if a.duration is None:
        a.duration = 6.0 if a.ringdown else 20.0
    if a.ringdown and not (a.depth_study or a.convergence):
        ap.error("--ringdown goes with --convergence or --depth-study")
    if a.predict:
        predict()
        return
    if a.spectra_figure:
        print(convergence_figure(a.spectra, a.figures or "."))
        return
    if a.cases:
        recs = a.cases.split(",")
        bad = [r for r in recs if r not in PAPER_CASE]
        if bad:
            ap.error(f"--cases: {bad} unknown; give some of {', '.join(PAPER_CASE)}")
        rows = cases(a.dx, a.duration, a.c0 or C0_PAPER, recs, a.figures, not a.no_gauges, a.stop)
        if a.json:
            with open(a.json, "w") as f:
                json.dump(rows, f, indent=1)
        return
    if a.depth_study or a.convergence:
        c0 = a.c0 or C0_PAPER
        rows = (depth_study(a.dx, a.duration, c0, a.record,
                            [float(x) for x in a.levels.split(",")] if a.levels else None, a.ringdown)
                if a.depth_study else
                convergence([float(x) for x in a.convergence.split(",")], a.duration, c0, a.record, a.spectra,
                            a.ringdown))
        if a.json:
            with open(a.json, "w") as f:
                json.dump(rows, f, indent=1)
        return
    print(json.dumps(run(a.dx, a.duration, a.record, a.out, a.c0), indent=1))


if __name__ == "__main__":
    main()
