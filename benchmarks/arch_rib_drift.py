"""The state of the water in the arch rib of Wang et al. 2022 (§4) while
El Centro EW shakes it, against the frequency read from the free (symmetric) part of the
wall pressures: does the water change (density, level, particles lost) so that its
quarter-wave mode f = c / (4 L) falls during the record?

One run of ``cosim.validations.arch_rib.rib_scene`` (the full variant's set-up: c0 = 140
m/s, settled 1.5 s, El Centro EW from t = 0; ``--stop T``: the rib brought to rest at T,
``GroundMotion.stop``, its velocity faded out over the last 0.5 s, so that the water rings
free from the state the record left; ``--ringdown``: the 20 mm vertical pulse of ``ring_rib``) with
particle snapshots every ``--every`` s (0.1), then, per snapshot, in the rib's frame (the
rib translates rigidly: its displacement is the walls' mean displacement):

- ``rho``: the water's mean density; ``dev``: the mean of rho / rho_h - 1 over the water
  inside the cavity, rho_h the Tait density (Barreiro et al. 2016, Eq. 8) of the
  hydrostatic rest state at the particle's height under the still level
  (``fluid.equations.hydrostatic_density``), all and in height bands (0-4, 4-8, 8-12,
  12-14, 14 m up): the water's expansion (< 0) or compression against rest;
- ``L_R``, ``L_L``: each leg's column length along the rib's axis, s_ref + N(s > s_ref) /
  n_full (s the arc length of a particle's nearest axis point, s_ref 3 m under the still
  surface, n_full the particles per metre over the 5 m of full column under s_ref: a level
  surface's chord above and below its axis crossing cancel), ``lev_axis`` the axis' height
  there; ``lev_vol``: the level under which the leg's cavity holds its SPH volume
  sum m / rho (m = rho0 dx^2); ``lev_p99``: the 99th percentile of the leg's heights;
  ``nfull``: n_full dx^2 / inner height (1: the lattice's packing);
- ``inside`` / ``outside``: water particles inside and outside the cavity polygon (in or
  through the walls), ``removed``: those that left the domain;
- ``void``: 1 - (the leg's SPH volume) / (the cavity's area under lev_axis).

Over windows: the free part's first spike (``spikes`` at half the highest, as ``run_rib``), each
leg's and the antisymmetric part's, the state's means, the quarter-wave frequency the state
predicts relative to t = 0 (``pred_rel`` = (L(0) / L) (1 + 3 (dev - dev(0))): Tait, gamma = 7),
the forced part's share of the free one (``leak_share``, R^2 in the band 0.6-1.6 Hz), per 2 s
each part's zero-crossing frequency and envelope; with ``--stop`` / ``--ringdown``, ``damped_mode`` fits.

    python benchmarks/arch_rib_drift.py --dx 0.2 --duration 20 --out /tmp/ardrift_02
    python benchmarks/arch_rib_drift.py --analyse /tmp/ardrift_02 --dx 0.2   # again, from the snapshots

The runs at dx = 0.2 and 0.1 m, with and without ``--stop``, and what they show: docs/benchmarks/arch_rib_drift.md.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import time
from pathlib import Path

import numpy as np

BANDS = (0.0, 4.0, 8.0, 12.0, 14.0, 99.0)  # m above the springings: depth bands of the mean density


def make_scene(dx: float, duration: float, every: float, ringdown: bool, settle: float = 1.5,
               stop: float | None = None, **fluid):
    """The full variant's scene (``rib_scene``) with snapshots every ``every`` [s] and any
    SPH field overridden by ``fluid`` (e.g. ``diffusion="antuono"``); with ``stop`` [s]
    the record stops there (``GroundMotion.stop``: its velocity faded out over the last
    0.5 s) and the rib rests after it."""
    from cosim.validations.arch_rib import rib_scene

    sc = rib_scene(dx, duration, () if ringdown else ("ew",), settle=settle, pulse=0.02 if ringdown else None,
                   stop=stop)
    sc = dataclasses.replace(sc, world=dataclasses.replace(sc.world, snapshot_every=every))
    if fluid:
        sc = dataclasses.replace(sc, fluid=dataclasses.replace(sc.fluid, **fluid))
    return sc


def _axis(rib):
    from fluid.shapes import catenary_arch_axis

    a = catenary_arch_axis(rib.span, rib.rise, rib.m, 20001)
    right = a[a[:, 0] >= 0][::-1]  # from the right springing up to the crown
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(right, axis=0).T))])
    return right, s


def _axis_coordinate(p: np.ndarray, right: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Arc length along the right leg's axis of the nearest axis point to each of ``p``
    (x >= 0; mirror the left leg first)."""
    from scipy.spatial import cKDTree

    _, i = cKDTree(right).query(p)
    return s[i]


def cavity_area_below(rib, n: int = 2001):
    """(levels [m], area of one leg's cavity under each level [m^2]) of the scene's polygon."""
    from matplotlib.path import Path as MPath

    path = MPath(np.asarray(rib.vertices))
    z = np.linspace(0.0, rib.rise + rib.inner_height / 2, n)
    xs = np.linspace(0.0, rib.span / 2 + rib.inner_height, 8001)
    widths = np.array([path.contains_points(np.column_stack([xs, np.full_like(xs, zz)])).sum() for zz in z])
    widths = widths * (xs[1] - xs[0])
    area = np.concatenate([[0.0], np.cumsum(0.5 * (widths[1:] + widths[:-1]) * np.diff(z))])
    return z, area


def state_series(h5: Path, rib, dx: float, c0: float, rho0: float = 1000.0, gamma: float = 7.0,
                 g: float = 9.81) -> dict:
    """The per-snapshot quantities of the module docstring, as arrays over the snapshots."""
    import h5py
    from matplotlib.path import Path as MPath

    from cosim.validations.arch_rib import column_length
    from fluid.equations import hydrostatic_density

    cav = MPath(np.asarray(rib.vertices))
    right, s_axis = _axis(rib)
    zlev, area = cavity_area_below(rib)
    mass = rho0 * dx * dx
    s_ref = column_length(rib.level) - 3.0  # 3 m along the axis under the still surface: always full
    out: dict[str, list] = {}
    with h5py.File(h5, "r") as f:
        times = f["snapshot_times"][:]
        wall0 = None
        n_fluid0 = None
        for k in range(len(times)):
            gr = f["snapshots"][f"{k:04d}"]
            pos, rho, kind = gr["pos"][()], gr["rho"][()], gr["kind"][()]
            wall = kind != 0
            if wall0 is None:
                wall0 = pos[wall].mean(axis=0)
            shift = pos[wall].mean(axis=0) - wall0  # the tank translates rigidly
            fl = kind == 0
            p, r = pos[fl] - shift, rho[fl]
            if n_fluid0 is None:
                n_fluid0 = int(fl.sum())
            ins = cav.contains_points(p)
            row = {"t": float(times[k]), "shift_x": float(shift[0]), "inside": int(ins.sum()),
                   "outside": int((~ins).sum()), "removed": n_fluid0 - int(fl.sum()), "rho": float(r.mean())}
            rh = hydrostatic_density(rib.level - p[:, 1], rho0, c0, gamma, g)
            dev = r / rh - 1.0
            row["dev"] = float(dev[ins].mean())
            for lo, hi in zip(BANDS[:-1], BANDS[1:]):
                m = ins & (p[:, 1] >= lo) & (p[:, 1] < hi)
                row[f"dev_{lo:g}_{min(hi, 99):g}"] = float(dev[m].mean()) if m.any() else math.nan
            for leg, sgn in (("R", 1.0), ("L", -1.0)):
                m = ins & (sgn * p[:, 0] > 0)
                q = np.column_stack([sgn * p[m, 0], p[m, 1]])
                row[f"rho_{leg}"] = float(r[m].mean())
                row[f"n_{leg}"] = int(m.sum())
                sa = _axis_coordinate(q, right, s_axis)
                # the column's length: s_ref plus the particles above it over the full column's count per metre
                # (under a level surface the parts of the chord above and below its axis crossing cancel)
                n_full = np.count_nonzero((sa > s_ref - 5.0) & (sa <= s_ref)) / 5.0
                L = s_ref + np.count_nonzero(sa > s_ref) / n_full
                row[f"L_{leg}"] = float(L)
                row[f"lev_axis_{leg}"] = float(np.interp(L, s_axis, right[:, 1]))
                row[f"nfull_{leg}"] = float(n_full * dx * dx / rib.inner_height)  # particles per dx^2 of cavity
                vol = float((mass / r[m]).sum())
                row[f"lev_vol_{leg}"] = float(np.interp(vol, area, zlev))
                row[f"lev_p99_{leg}"] = float(np.percentile(q[:, 1], 99.0))
                a_axis = float(np.interp(row[f"lev_axis_{leg}"], zlev, area))
                row[f"void_{leg}"] = 1.0 - vol / a_axis
            for key, v in row.items():
                out.setdefault(key, []).append(v)
    return {k: np.asarray(v) for k, v in out.items()}


def b_points(h5: Path) -> tuple[np.ndarray, np.ndarray]:
    """(t, the pressure at B1-B18 (samples, 18) [Pa]) from the run's probe series: B1-B9
    on the right leg, B10-B18 their mirror images."""
    from fluid.output import read_series

    s = read_series(h5, "probes/pressure")  # the rib scene's wall-pressure probes
    return s["t"], np.column_stack([s[f"B{k}.p"] for k in range(1, 19)])


def _band(t: np.ndarray, y: np.ndarray, lo: float = 0.6, hi: float = 1.6) -> np.ndarray:
    """``y`` (samples, ...) band-passed to ``lo``-``hi`` [Hz] (4th-order Butterworth, both ways)."""
    from scipy.signal import butter, filtfilt

    b, a = butter(4, [lo, hi], btype="band", fs=1.0 / (t[1] - t[0]))
    return filtfilt(b, a, y - y.mean(axis=0), axis=0)


def cycle_frequency(t: np.ndarray, y: np.ndarray, bins) -> list:
    """Per time bin (lo, hi) [s]: (the mean frequency [Hz] from the periods between the
    upward zero crossings of ``y`` band-passed around the mode (:func:`_band`), its
    mean Hilbert envelope [Pa])."""
    from scipy.signal import hilbert

    yf = _band(t, y)
    env = np.abs(hilbert(yf))
    i = np.nonzero((yf[:-1] < 0) & (yf[1:] >= 0))[0]
    tc = t[i] - yf[i] * (t[1] - t[0]) / (yf[i + 1] - yf[i])
    per, tm = np.diff(tc), 0.5 * (tc[1:] + tc[:-1])
    out = []
    for lo, hi in bins:
        k, e = (tm >= lo) & (tm < hi), (t >= lo) & (t < hi)
        out.append((1.0 / per[k].mean() if k.any() else math.nan, float(env[e].mean())))
    return out


def leak_share(t: np.ndarray, p: np.ndarray, lo: float, hi: float) -> tuple[float, float]:
    """How much of the symmetric part (pR + pL)/2 is the antisymmetric (forced) part
    leaking into it, over ``lo``-``hi`` [s], both band-passed around the mode: (rms of
    the symmetric / rms of the antisymmetric, the mean over the nine pairs of the R^2 of
    the symmetric on the antisymmetric and its quadrature (Hilbert))."""
    from scipy.signal import hilbert

    sym, anti = _band(t, (p[:, :9] + p[:, 9:]) / 2), _band(t, (p[:, :9] - p[:, 9:]) / 2)
    k = (t >= lo) & (t <= hi)
    r2 = []
    for j in range(9):
        x = np.column_stack([anti[k, j], np.imag(hilbert(anti[:, j]))[k]])
        c = np.linalg.lstsq(x, sym[k, j], rcond=None)[0]
        r2.append(1.0 - np.var(sym[k, j] - x @ c) / np.var(sym[k, j]))
    return float(sym[k].std() / anti[k].std()), float(np.mean(r2))


def window_table(st: dict, t: np.ndarray, p: np.ndarray, windows, ref_f: float | None) -> list:
    """Per window: the free part's first spike (half the highest) and damped-mode fit,
    and the state's means and the predicted relative frequency."""
    from cosim.validations.arch_rib import damped_mode, spectrum, spikes

    L0 = 0.5 * (st["L_R"][0] + st["L_L"][0])  # the settled state at t = 0
    dev0 = st["dev"][0]
    free, forced = (p[:, :9] + p[:, 9:]) / 2, (p[:, :9] - p[:, 9:]) / 2
    rows = []
    for a, b in windows:
        keep = (t >= a) & (t <= b)
        f_sp = spikes(*spectrum(t[keep], free[keep], a), 1, rel=0.5)[0]
        legs = [spikes(*spectrum(t[keep], y[keep], a), 1, rel=0.5)[0] for y in (p[:, :9], p[:, 9:], forced)]
        try:
            f_dm = damped_mode(t, free, a, b)["f_Hz"]
        except Exception:  # a window the fit cannot take
            f_dm = math.nan
        ks = (st["t"] >= a) & (st["t"] <= b)
        lev = 0.5 * (st["lev_axis_R"][ks] + st["lev_axis_L"][ks])
        L = 0.5 * (st["L_R"][ks] + st["L_L"][ks])
        rel = np.mean(L0 / L * (1 + 3 * (st["dev"][ks] - dev0)))
        rel_L = np.mean(L0 / L)
        rows.append({"window": f"{a:g}-{b:g}", "f_spike_Hz": round(f_sp, 4), "f_fit_Hz": round(f_dm, 4),
                     "f_spike_R_L_anti_Hz": [round(x, 4) for x in legs],
                     "sym_over_anti_rms_R2": [round(x, 3) for x in leak_share(t, p, a, b)],
                     "L_R_minus_L_L_m": round(float(np.mean(st["L_R"][ks] - st["L_L"][ks])), 4),
                     "dev": float(np.mean(st["dev"][ks])), "lev_axis": float(lev.mean()),
                     "lev_vol": float(np.mean(0.5 * (st["lev_vol_R"][ks] + st["lev_vol_L"][ks]))),
                     "void": float(np.mean(0.5 * (st["void_R"][ks] + st["void_L"][ks]))),
                     "pred_rel_L": round(float(rel_L), 4), "pred_rel": round(float(rel), 4),
                     "pred_Hz": round(ref_f * rel, 4) if ref_f else None})
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--dx", type=float, default=0.2)
    ap.add_argument("--duration", type=float, default=10.0)
    ap.add_argument("--every", type=float, default=0.1, help="snapshot interval [s]")
    ap.add_argument("--ringdown", action="store_true", help="the vertical pulse instead of El Centro EW")
    ap.add_argument("--out", default=None, help="run folder (run.h5 with the snapshots)")
    ap.add_argument("--analyse", default=None, help="analyse the run folder given, no run")
    ap.add_argument("--windows", default="2-11.5,5-20,10-20,15-20")
    ap.add_argument("--ref-f", type=float, default=None, help="frequency [Hz] that pred_rel multiplies")
    ap.add_argument("--stop", type=float, default=None, help="the record stops at this time [s], the rib rests after")
    ap.add_argument("--diffusion", default=None)
    ap.add_argument("--delta", type=float, default=None)
    ap.add_argument("--json", default=None)
    a = ap.parse_args(argv)
    from cosim.scene import ArchRib

    info = {}
    if a.analyse:
        folder = Path(a.analyse)
        summ = json.loads((folder / "summary.json").read_text())
    else:
        folder = Path(a.out or f"/tmp/ardrift_{a.dx:g}")
        fluid = {k: v for k, v in (("diffusion", a.diffusion), ("delta", a.delta)) if v is not None}
        sc = make_scene(a.dx, a.duration, a.every, a.ringdown, stop=a.stop, **fluid)
        cpu0 = time.process_time()
        r = sc.run(folder, progress=None)
        summ = r.summary
        info["cpu_s_run"] = time.process_time() - cpu0
    rib = ArchRib()
    dx = a.dx
    c0 = summ["speed_of_sound_m_s"]
    st = state_series(folder / "run.h5", rib, dx, c0)
    t, p = b_points(folder / "run.h5")
    free = (p[:, :9] + p[:, 9:]) / 2
    tmax = t[-1]
    wins = [tuple(float(x) for x in w.split("-")) for w in a.windows.split(",")]
    wins = [(lo, min(hi, tmax)) for lo, hi in wins if lo < tmax - 2.0]
    rows = window_table(st, t, p, wins, a.ref_f)
    keys = ["t", "shift_x", "inside", "outside", "removed", "rho", "dev", *[k for k in st if k.startswith("dev_")],
            "L_R", "L_L", "nfull_R", "nfull_L", "lev_axis_R", "lev_axis_L", "lev_vol_R", "lev_vol_L", "lev_p99_R", "lev_p99_L", "void_R", "void_L"]
    print(" ".join(f"{k:>10s}" for k in keys))
    for i in range(0, len(st["t"]), max(1, int(round(1.0 / a.every)))):
        print(" ".join(f"{st[k][i]:10.5g}" for k in keys))
    if a.stop is not None or a.ringdown:
        from cosim.validations.arch_rib import PULSE_PERIOD, damped_mode

        t0 = PULSE_PERIOD if a.ringdown else a.stop
        for lo, hi in ((t0 + 0.5, tmax), (t0 + 1.0, tmax), (t0 + 0.5, tmax - 1.0)):
            ks = (st["t"] >= lo) & (st["t"] <= hi)
            row = {"window": f"free ringing {lo:g}-{hi:g}", "dev": float(np.mean(st["dev"][ks])),
                   "L_R_L_L": [round(float(np.mean(st[k][ks])), 3) for k in ("L_R", "L_L")]}
            for name, y in (("sym", free), ("R", p[:, :9]), ("L", p[:, 9:]), ("anti", (p[:, :9] - p[:, 9:]) / 2)):
                try:
                    fit = damped_mode(t, y, lo, hi)
                    row[f"f_{name}_Hz"] = round(fit["f_Hz"], 4)
                    row[f"res_{name}"] = round(fit["residual"], 3)
                except Exception as e:  # a fit that fails is reported, not fatal
                    row[f"f_{name}_Hz"] = repr(e)[:60]
            rows.append(row)
    for row in rows:
        print(row)
    bins = [(lo, lo + 2.0) for lo in np.arange(0.0, tmax - 1.0, 2.0)]
    print("2 s bins, zero-crossing frequency [Hz] / envelope [kPa] of the nine points' mean, band 0.6-1.6 Hz:")
    cyc = {name: cycle_frequency(t, y, bins) for name, y in
           (("sym", free.mean(axis=1)), ("anti", ((p[:, :9] - p[:, 9:]) / 2).mean(axis=1)),
            ("R", p[:, :9].mean(axis=1)), ("L", p[:, 9:].mean(axis=1)))}
    for j, (lo, hi) in enumerate(bins):
        print(f"{lo:5.1f}-{hi:5.1f} s  " + "  ".join(f"{n} {v[j][0]:.3f} / {v[j][1] / 1e3:6.2f}" for n, v in cyc.items()))
    info["cycles"] = {n: [[round(f, 4), round(e, 1)] for f, e in v] for n, v in cyc.items()}
    info.update({"summary_cpu_s": summ.get("cpu_s"), "particles": summ.get("particles"), "windows": rows})
    print(json.dumps({k: v for k, v in info.items() if k != "windows"}))
    if a.json:
        Path(a.json).write_text(json.dumps({"info": info, "state": {k: v.tolist() for k, v in st.items()}}, indent=0))


if __name__ == "__main__":
    main()
