"""Is the 3-D slice's high wave in the water or only at its surface? The piston flume's
first harmonics along its mid-line, station by station: the surface the gauges read, the
top particles' height, and the horizontal and vertical velocities at mid-depth, each turned
into a wave height through linear theory and divided by linear theory's progressive wave
(docs/validation/wave-propagation_history.md, "Is the 3-D wave's excess in the water?").

The wave-propagation case's scene (`cosim.validations.wave_propagation`: H = 4 cm, T = 1 s,
d = 0.3 m) one wavelength long plus its absorber, as `benchmarks/wave_slice_across.py`
builds it, run for ``--duration`` seconds and read over the last three periods at
``--per-wavelength`` stations a wavelength from L / N to 1.25 L. Velocities: the mean of
the fluid particles within dx of the station in x and 1.5 dx of mid-depth in z, over the
slice's interior columns (those not beside a side wall); the top particles: the highest
fluid particle within dx / 2 of the station in x, over the same columns. ``--width 0``: the
2-D flume. Linear theory's velocity amplitudes at z = -d/2: u = a w cosh(k d/2) / sinh(k d),
w = a w sinh(k d/2) / sinh(k d) (Dean & Dalrymple 1991, Table 4.1); the paddle's
evanescent modes, which linear_elevation leaves out, are in the readings near the paddle,
so compare 3-D with 2-D there, not with 1. Printed beside them: the mean horizontal
velocity at mid-depth over the three periods (a current along the flume lengthens the wave).

    python benchmarks/wave_slice_kinematics.py --rows 10 --width 5
    python benchmarks/wave_slice_kinematics.py --rows 10 --width 0
"""

from __future__ import annotations

import json
import math
import time

import numpy as np

from wave_slice_across import arguments, slice_scene, stations  # beside this script
from cosim.validations import case_scene
from cosim.validations.wave_propagation import WP_DEPTH, WP_HEIGHT, WP_PERIOD, _wave, harmonics, linear_elevation
from fluid.particles import Kind
from fluid.probes import surface_elevation


def run(rows: int, width_rows: int, per_wavelength: int, duration: float, values=()) -> dict:
    wm, L, _ = _wave(WP_HEIGHT, WP_PERIOD, WP_DEPTH)
    xs, dx = stations(rows, per_wavelength)
    at = np.stack([xs, np.full(xs.size, 0.5 * width_rows * dx)], 1) if width_rows else xs
    scene = slice_scene(rows, width_rows, duration, (), values)
    every = WP_PERIOD / 32.0
    t_fit = duration - 3.0 * WP_PERIOD
    times = list(np.arange(WP_PERIOD, t_fit - 1e-9, WP_PERIOD)) + list(t_fit + every * np.arange(97))
    ts, rec = [], {"eta": [], "top": [], "u": [], "w": []}
    cpu0 = time.process_time()
    with case_scene.built(scene) as b:
        f = b.sph
        t = 0.0
        for target in times:
            f.advance(t, target - t)
            t = target
            if t < t_fit - 1e-9:
                continue
            ps = f.ps
            fl = ps.kind == Kind.FLUID
            pos, vel = ps.pos[fl], ps.vel[fl]
            inner = np.ones(len(pos), bool) if not width_rows else \
                (pos[:, 1] > dx) & (pos[:, 1] < (width_rows - 1) * dx)
            near = np.abs(pos[:, 0][None, :] - xs[:, None]) < 0.5 * dx
            band = np.abs(pos[:, 0][None, :] - xs[:, None]) < dx
            mid = band & inner[None, :] & (np.abs(pos[:, -1] - 0.5 * WP_DEPTH) < 1.5 * dx)[None, :]
            top = near & inner[None, :]
            ts.append(t)
            rec["eta"].append(surface_elevation(f, at) - WP_DEPTH)
            rec["top"].append([pos[m, -1].max() for m in top])
            rec["u"].append([vel[m, 0].mean() for m in mid])
            rec["w"].append([vel[m, -1].mean() for m in mid])
    ts = np.asarray(ts)
    omega = 2.0 * math.pi / WP_PERIOD
    a_lin = np.abs(harmonics(ts, linear_elevation(wm, xs, ts), omega))
    kd = wm.k * WP_DEPTH
    per_a = {"eta": 1.0, "top": 1.0, "u": omega * math.cosh(0.5 * kd) / math.sinh(kd),
             "w": omega * math.sinh(0.5 * kd) / math.sinh(kd)}
    out = {"rows": rows, "width_rows": width_rows, "set": list(values), "x_over_L": np.round(xs / L, 4).tolist(),
           "cpu_s": round(time.process_time() - cpu0, 1)}
    for key, series in rec.items():
        amp = np.abs(harmonics(ts, np.asarray(series), omega)) / per_a[key]
        out[key] = np.round(amp / a_lin, 4).tolist()
    # the mean flow at mid-depth over the three periods [m/s]: a current U along the flume
    # makes the wave longer by about U / c_g
    out["u_mean_mid_m_s"] = np.round(np.mean(rec["u"], axis=0), 5).tolist()
    return out


def main(argv=None) -> None:
    args = arguments(__doc__, 5, 8, argv)
    r = run(args.rows, args.width, args.per_wavelength, args.duration, args.set)
    print(json.dumps(r))
    print("\n| x / L | surface (gauge) | top particles | u at mid-depth | w at mid-depth | mean u at mid-depth [mm/s] |")
    print("|---|---|---|---|---|---|")
    for i, x in enumerate(r["x_over_L"]):
        print(f"| {x} | " + " | ".join(f"{r[k][i]:.3f}" for k in ("eta", "top", "u", "w"))
              + f" | {1e3 * r['u_mean_mid_m_s'][i]:.2f} |")


if __name__ == "__main__":
    main()
