"""SPHERIC Test 10, first impact (2.375 s, 3.68 kPa measured): one lever at a time.

    NUMBA_NUM_THREADS=1 .venv/bin/python benchmarks/spheric10_levers.py --dx 0.0093 --walls adami
    ... --c0 56 --alpha 0.01 --alpha-wall 1 --delta 0.1 --mls-every 20 --t-end 2.7 --npz out.npz

Runs :func:`cosim.validations.sloshing.run_spheric10`'s set-up (same tank, roll, c0
default 28 m/s) to ``--t-end`` and records several left-wall pressure probes, every
``--fine-dt`` [s] from ``--fine-from`` on (every 1 ms before), so that a spike of a few
time steps is not missed:

- ``patch``: the case's sensor (:func:`~cosim.validations.sloshing.spheric10_sensor`:
  the wall's normal force over a 10 mm patch, as a transducer reads it);
- ``face2h``: the case's earlier probe (:func:`~cosim.validations.sloshing.face_pressure`:
  Sunara et al. 2021, Eq. 15 over 2h, carried to the wall face, fitted along the wall) at z = 93 mm;
- ``face1h``: the same with a support of h;
- ``face_sensor``: ``face2h`` averaged over the sensor's face (``--sensor-d`` [m], the
  diameter, along the wall about z = 93 mm; 5 points);
- ``wall``: the own pressure of the innermost wall particles within ``--sensor-d`` / 2
  (plus dx / 2) of the sensor centre (with ``walls="adami"`` this is the pressure the wall
  carries from the fluid; with ``"dbc"`` the wall's own equation of state);
- ``face2h_1ms``: ``face2h`` sampled every 1 ms as the case does.

Prints one line per probe: the peak within 0.1 s of the measured impact, its time, its
ratio to 3.68 kPa, the ratio of the largest 20 ms running mean to the record's (2.15 kPa)
and the ratio of the impulses over 2.300 - 2.475 s (the record: 119 Pa s).

The measured levers (dx, walls, c0, viscosity, diffusion) and probes: docs/benchmarks/spheric10_levers.md.
"""

from __future__ import annotations

import argparse
import pickle
import time

import numpy as np
from cosim.validations.sloshing import (face_pressure, running_mean_max, spheric10_built, spheric10_pressure,
                                        spheric10_sensor)
from fluid.particles import Kind

T1, P1 = 2.375, 3683.0  # the first measured impact: time [s], peak [Pa]


def spheric10_wall_ids(f, z, half):
    """ids of the innermost left-wall particles within ``half`` [m] of height z (t = 0)."""
    ps = f.ps
    w = np.flatnonzero(ps.kind != Kind.FLUID)
    xin = -0.5 * f.config.dx  # the left wall's face at x = 0 (the scene's tank frame)
    sel = w[(np.abs(ps.pos[w, 0] - xin) < 0.25 * f.config.dx) & (np.abs(ps.pos[w, 1] - z) <= half + 1e-9)]
    return ps.ids[sel]


def face_pressure_r(f, centre, normal, acc, g_vec, radius):
    """face_pressure with a support ``radius`` instead of 2h (same carry-and-fit)."""
    ps = f.ps
    fl = np.flatnonzero(ps.kind == Kind.FLUID)
    near = fl[np.linalg.norm(ps.pos[fl] - centre, axis=1) <= radius]
    if near.size == 0:
        return 0.0
    d = ps.pos[near] - centre
    dn = d @ normal
    q = ps.p[near] - ps.rho[near] * ((g_vec - acc) @ normal) * dn
    w = 1.0 / np.maximum(np.linalg.norm(d, axis=1), 1e-6 * f.config.dx)
    t1 = np.array([-normal[1], normal[0]])
    s = d @ t1
    A = np.stack([np.ones_like(s), s], axis=1)
    M = (A * w[:, None]).T @ A
    r = (A * w[:, None]).T @ q
    return float((np.linalg.pinv(M, rcond=1e-10) @ r)[0])


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--dx", type=float, default=0.0093)
    ap.add_argument("--c0", type=float, default=28.0)
    ap.add_argument("--walls", default="dbc")
    ap.add_argument("--alpha", type=float, default=None)
    ap.add_argument("--alpha-wall", type=float, default=None)
    ap.add_argument("--delta", type=float, default=None)
    ap.add_argument("--mls-every", type=int, default=None)
    ap.add_argument("--t-end", type=float, default=2.7)
    ap.add_argument("--fine-from", type=float, default=2.3)
    ap.add_argument("--fine-to", type=float, default=2.45)
    ap.add_argument("--fine-dt", type=float, default=5e-5)
    ap.add_argument("--sensor-d", type=float, default=0.0)
    ap.add_argument("--npz", default=None)
    ap.add_argument("--snap", type=float, nargs="*", default=[],
                    help="times [s] to store the fluid's positions, velocities and pressures at (in --npz)")
    ap.add_argument("--save", default=None, help="pickle the state at --save-at [s] to this path")
    ap.add_argument("--save-at", type=float, default=2.0)
    ap.add_argument("--load", default=None, help="start from a state pickled by --save (same dx and walls); "
                    "a different --c0 keeps each particle's pressure (density re-derived)")
    a = ap.parse_args(argv)
    over = {k: v for k, v in dict(alpha=a.alpha, alpha_wall=a.alpha_wall, delta=a.delta,
                                         mls_every=a.mls_every).items() if v is not None}
    t0 = time.perf_counter()
    with spheric10_built(a.dx, c0=a.c0, t_end=a.t_end, walls=a.walls, **over) as (f, roll):
        cfg = f.config
        h_s = 0.093
        zs = np.linspace(-a.sensor_d / 2, a.sensor_d / 2, 5) if a.sensor_d > 0 else np.zeros(1)
        wall_ids = spheric10_wall_ids(f, h_s, max(a.sensor_d / 2, 0.0) + 0.5 * a.dx)
        rec = {k: [] for k in ("t", "patch", "face2h", "face1h", "face_sensor", "wall")}
        t = 0.0
        snaps = {}
        if a.load:
            with open(a.load, "rb") as fh:
                state, c0_old = pickle.load(fh)
            f.load_state(state)
            t = f.t
            if c0_old != a.c0:  # keep p: rho = rho0 (p / B + 1)^(1/gamma), B = rho0 c0^2 / gamma
                g, r0 = cfg.gamma, cfg.rho0
                for arr in (f.ps.rho, f._aux["rho"]):
                    p = r0 * c0_old ** 2 / g * ((arr / r0) ** g - 1)
                    arr[:] = r0 * (p / (r0 * a.c0 ** 2 / g) + 1) ** (1 / g)
            f._stale = True
            f.refresh_rates()
        while t < a.t_end - 1e-12:
            dt = a.fine_dt if a.fine_from - 1e-12 <= t < a.fine_to - 1e-12 else 1e-3
            f.advance(t, dt)
            t = round(t + dt, 10)
            for ts in a.snap:
                if abs(t - ts) < 1e-9:
                    fl = f.ps.kind == Kind.FLUID
                    snaps[f"snap_{ts:.3f}"] = np.concatenate([f.ps.pos[fl], f.ps.vel[fl], f.ps.p[fl, None]], axis=1)
            if a.save and abs(t - a.save_at) < 1e-9:
                with open(a.save, "wb") as fh:
                    pickle.dump((f.save_state(), a.c0), fh)
            pts = np.array([[0.0, h_s + z] for z in zs])
            at, _ = roll(t, pts)
            normal = roll(t, pts[:1] + [1.0, 0.0])[0][0] - at[0]
            th, dth, ddth = roll.signal.state(t)
            r = at - np.asarray(roll.point)
            acc = np.stack([ddth * r[:, 1], -ddth * r[:, 0]], axis=1) - dth ** 2 * r
            fp = face_pressure(f, at, at, normal, acc, cfg.gravity)
            rec["t"].append(t)
            rec["patch"].append(spheric10_sensor(f, roll, t))
            rec["face2h"].append(fp[len(zs) // 2])
            rec["face_sensor"].append(fp.mean())
            rec["face1h"].append(face_pressure_r(f, at[len(zs) // 2], normal, acc[len(zs) // 2], cfg.gravity, cfg.h))
            sel = np.isin(f.ps.ids, wall_ids)
            rec["wall"].append(float(f.ps.p[sel].mean()))
    wall_s = time.perf_counter() - t0
    rec = {k: np.asarray(v) for k, v in rec.items()}
    tt = rec["t"]
    ms = np.isclose((tt * 1000) % 1, 0, atol=1e-6) | np.isclose((tt * 1000) % 1, 1, atol=1e-6)
    print(f"dx {a.dx} c0 {a.c0} walls {a.walls} {over} sensor_d {a.sensor_d}: {f.ps.n} particles, "
          f"{f.counters.steps} steps, {wall_s:.0f} s")
    e = spheric10_pressure()
    e20 = running_mean_max(e[:, 0], e[:, 1], 0.02, T1 - 0.1, T1 + 0.1)[0]
    ew = (e[:, 0] >= T1 - 0.075) & (e[:, 0] <= T1 + 0.1)
    e_imp = np.trapezoid(np.maximum(e[ew, 1], 0), e[ew, 0])
    for k in ("patch", "face2h", "face1h", "face_sensor", "wall", "face2h_1ms"):
        y = rec["face2h"] if k == "face2h_1ms" else rec[k]
        m = (np.abs(tt - T1) <= 0.1) & (ms if k == "face2h_1ms" else True)
        if not m.any():
            continue
        j = np.flatnonzero(m)[np.argmax(y[m])]
        w = (tt >= T1 - 0.075) & (tt <= T1 + 0.1)
        print(f"  {k:<12} peak {y[j]:8.0f} Pa at {tt[j]:.4f} s  ratio {y[j] / P1:.3f}  lag {tt[j] - T1:+.4f} s  "
              f"20 ms mean ratio {running_mean_max(tt[m], y[m], 0.02, T1 - 0.1, T1 + 0.1)[0] / e20:.3f}  "
              f"impulse ratio {np.trapezoid(np.maximum(y[w], 0), tt[w]) / e_imp:.3f}")
    if a.npz:
        np.savez(a.npz, **rec, **snaps, dx=a.dx, c0=a.c0, walls=a.walls, wall_s=wall_s)


if __name__ == "__main__":
    main()
