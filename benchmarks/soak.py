"""Soak benchmark (not a test, not in CI): many coupling steps of the moored box of
``examples/moored_box.toml`` on the analytic fluid, once per mooring model, checking that

- memory stays flat (resident set size, /proc/self/status VmRSS),
- the clock is exact (``coupler.clock.ticks`` == steps x ``to_ticks(dt)``, to the tick),
- the ledger's momentum balance does not drift: the box's momentum change equals the time
  integral of every load the ledger booked (fluid + mooring + gravity).

    python benchmarks/soak.py [--steps 1000000] [--models catenary,sph-cable,fmu,moordyn]
                              [--dt 0.01] [--every K] [--ledger truncate|keep]
                              [--ledger-rows 1000000] [--patch-moordyn] [--csv soak.csv]

The full soak the issue asks for (10^6 steps per model)::

    python benchmarks/soak.py --steps 1000000 --every 20000 --ledger-rows 1000000 --csv soak.csv

Each model runs in a fresh interpreter (its libraries, freed memory and a crash in a C
extension are its own); the scene is built with ``cosim.scene.build.build`` and stepped in
chunks of ``--every`` steps, each recording wall and CPU time, steps/s, VmRSS, gc-tracked
objects, ``sys.getrefcount(None)``, the tick error and the residuals. ``--ledger truncate``
empties the ledger after each chunk (memory net of it); ``--ledger keep`` keeps it as a run does.

Why dt = 0.01 s. The analytic fluid's own stable step for this box is 0.0183 s (its
hydrostatic stiffness: 50 steps per heave period); 0.01 s is inside it with margin, is a
whole number of MuJoCo steps (5 x 2 ms, the scene's ``body_timestep``) and of clock ticks
(10^10 ps), and makes 10^6 steps = 10^4 s simulated (2.8 h, ~7000 heave periods). No
participant asks for less (every step's limiter is "user dt": counted, 0 in every run).

The balance: m (v_N - v_0) = sum_k (F_fluid + F_mooring + G)_k dt_k holds up to floating
point, since the ledger books the loads the body is advanced with and nothing else acts on
the box (no contacts, tendons, armature or joint damping: checked every chunk); the same
for the angular momentum about the centre of mass. The residual dp - J [N s] is reported
alone and relative to the gross impulse, its drift as its least-squares slope against steps.

How each part works in full, the measured runs (10^6 steps of every model) and the
findings: docs/benchmarks/soak_history.md.
"""

from __future__ import annotations

import argparse
import csv
import datetime
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

from cosim.clock import TICKS_PER_SECOND, to_ticks

from machine import cpu_name  # noqa: E402  (benchmarks/machine.py, beside this script)

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "examples" / "moored_box.toml"
MODELS = ("catenary", "sph-cable", "fmu", "moordyn")


# ------------------------------------------------------------------ machine and memory
def rss_bytes() -> int:
    """Resident set size of this process [B] (VmRSS)."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    return 0


def load1() -> float:
    return os.getloadavg()[0]


class ExactImpulse:
    """The exact sum of load x dt over steps, as fractions: the loads are the floats the
    ledger booked, each dt a whole number of clock ticks, so the sum has an exact value and
    the balance checks the coupler's books, not this sum's round-off."""

    def __init__(self, shape):
        self.shape = shape
        self.total = np.full(shape, Fraction(0), dtype=object)

    def add(self, loads, ticks) -> None:
        """``loads`` (k, *shape) [N or N m] held over steps of ``ticks`` (k,) ticks each."""
        for n in np.unique(ticks):
            sel = loads[ticks == n].reshape(-1, int(np.prod(self.shape)))
            dt = Fraction(int(n), TICKS_PER_SECOND)
            for j in range(sel.shape[1]):
                col = sel[:, j].tolist()
                hi = math.fsum(col)
                lo = math.fsum(col + [-hi])  # hi + lo: the exact sum to ~1e-32 relative
                self.total.flat[j] += (Fraction(hi) + Fraction(lo)) * dt


def exact(a) -> np.ndarray:
    """A float array as an array of exact fractions."""
    a = np.asarray(a, float)
    return np.array([Fraction(x) for x in a.ravel()], dtype=object).reshape(a.shape)


def slope_per(xs, ys, per: float = 1.0) -> float:
    """Least-squares slope of ys against xs, times ``per`` (nan for fewer than 2 points)."""
    if len(xs) < 2:
        return math.nan
    return float(np.polyfit(np.asarray(xs, float), np.asarray(ys, float), 1)[0]) * per


def ledger_getsizeof(led) -> int:
    """Bytes the ledger's Python objects hold, by ``sys.getsizeof`` (lists, floats, arrays)."""
    n = sys.getsizeof(led._t) + sum(sys.getsizeof(x) for x in led._t)  # a benchmark may look inside
    for lst in led._rows.values():
        n += sys.getsizeof(lst) + sum(sys.getsizeof(x) for x in lst)
    return n


def patch_moordyn_deserialize() -> list:
    """Work around the lost reference in ``moordyn.Deserialize`` (moordyn 2.7.2's cmoordyn
    returns None without a reference of its own: every call takes one from None, and on
    Python < 3.12, where None is not immortal, the interpreter aborts with "none_dealloc"
    once they are gone). Gives back what each call took; returns a one-item list counting
    the references given back."""
    import ctypes

    import moordyn

    orig, given = moordyn.Deserialize, [0]

    def deserialize(*args):
        before = sys.getrefcount(None)
        out = orig(*args)
        lost = before + (out is None) - sys.getrefcount(None)
        for _ in range(max(lost, 0)):
            ctypes.pythonapi.Py_IncRef(ctypes.py_object(None))
        given[0] += max(lost, 0)
        return out

    moordyn.Deserialize = deserialize
    return given


# ------------------------------------------------------------------ one model (in a child process)
def soak(model: str, steps: int, dt: float, every: int, ledger_mode: str, out: str,
         patch_moordyn: bool = False) -> None:
    """Run the moored box with ``model`` for ``steps`` coupling steps of ``dt`` [s]; after
    the build, after each chunk of ``every`` steps and at the end, one JSON line into
    ``out`` (``meta``, ``row``, ``final``), so that a run that dies leaves its rows."""
    import gc

    from cosim.scene.build import build
    from cosim.scene.spec import Scene

    fh = open(out, "a")

    def emit(kind, obj):
        fh.write(json.dumps({kind: obj}) + "\n")
        fh.flush()

    rss_import = rss_bytes()
    given = patch_moordyn_deserialize() if (patch_moordyn and model == "moordyn") else [0]
    scene = Scene.from_toml(SCENE).with_values(
        [f"moorings.model={model}", f"coupling.dt={dt!r}", f"world.sample_every={dt!r}",
         f"world.duration={max(steps * dt, 1.0)!r}"])
    n_dt = to_ticks(dt)
    with tempfile.TemporaryDirectory(prefix="soak_") as wd:
        t0 = time.perf_counter()
        built = build(scene, Path(wd))
        build_s = time.perf_counter() - t0
        c, b, led = built.coupler, built.bodies, built.coupler.ledger
        m, d = b.model, b.data
        nb = b.n_bodies
        mass = b.masses()[:, None]
        ib = b.body_ids

        def angular(kin):
            """Angular momentum about each centre of mass, world frame [kg m^2/s]."""
            R = d.ximat[ib].reshape(-1, 3, 3)
            inertia = np.einsum("bij,bj,bkj->bik", R, m.body_inertia[ib], R)
            return np.einsum("bij,bj->bi", inertia, kin.omega)

        def other():
            return (f"ncon<={ncon_max} nefc<={nefc_max} ngeom={m.ngeom} tendons={m.ntendon} eq={m.neq} "
                    f"armature={float(m.dof_armature.sum()):g} damping={float(m.dof_damping.sum()):g}")

        kin = b.kinematics()
        p0, L0 = exact(mass * kin.velocity), exact(angular(kin))
        J = {f: ExactImpulse((nb, 3)) for f in ("fluid", "mooring", "gravity", "fluid_T", "mooring_T")}
        gross = 0.0
        naive = np.zeros((nb, 3))  # the same balance with plain float sums, for comparison
        buf = np.zeros((every, 5, nb, 3))  # fluid F, mooring F, gravity, fluid T, mooring T
        dts = np.zeros(every)
        ticks = np.zeros(every, dtype=np.int64)
        t_stop = (steps + 1) * n_dt / TICKS_PER_SECOND  # past the run: no step is clipped
        t_naive, off_dt = 0.0, 0
        ncon_max = nefc_max = 0
        done = 0
        emit("meta", dict(model=model, ledger=ledger_mode, steps=steps, dt=dt, every=every, scheme=c.scheme,
                          build_s=build_s, rss_import_mb=rss_import / 2**20, rss_built_mb=rss_bytes() / 2**20,
                          python=platform.python_version(), patch_moordyn=patch_moordyn and model == "moordyn"))
        w0, c0 = time.perf_counter(), time.process_time()
        w_prev, done_prev = w0, 0
        while done < steps:
            k = min(every, steps - done)
            for i in range(k):
                info = c.step(t_stop)
                if info.limiter != "user dt":
                    off_dt += 1
                last = led.last()
                buf[i, 0] = last["fluid_force"]
                buf[i, 1] = last["mooring_force"]
                buf[i, 2] = last["gravity"]
                buf[i, 3] = last["fluid_torque"]
                buf[i, 4] = last["mooring_torque"]
                dts[i] = info.dt
                ticks[i] = round(info.dt * TICKS_PER_SECOND)  # info.dt is a whole number of ticks / 10^12
                t_naive += dt
            done += k
            now, cpu = time.perf_counter(), time.process_time()
            bk, dk = buf[:k], dts[:k, None, None]
            for j, f in enumerate(("fluid", "mooring", "gravity", "fluid_T", "mooring_T")):
                J[f].add(bk[:, j], ticks[:k])
            naive += sum((bk[:, j] * dk).sum(axis=0) for j in range(3))  # numpy: sequential along axis 0
            gross += math.fsum((np.linalg.norm(bk[:, :3], axis=-1).sum(axis=(1, 2)) * dts[:k]).tolist())
            ledger_rows = len(led)
            if ledger_mode == "truncate":
                led.truncate(0)
            ncon_max, nefc_max = max(ncon_max, int(d.ncon)), max(nefc_max, int(d.nefc))
            kin = b.kinematics()
            impulse = J["fluid"].total + J["mooring"].total + J["gravity"].total
            p = mass * kin.velocity
            res = ((exact(p) - p0) - impulse).astype(float)
            res_L = ((exact(angular(kin)) - L0) - (J["fluid_T"].total + J["mooring_T"].total)).astype(float)
            res_naive = (p - p0.astype(float)) - naive
            ticks_exp = done * n_dt
            row = dict(
                model=model, ledger=ledger_mode, steps=done, wall_s=now - w0, cpu_s=cpu - c0,
                steps_per_s=(done - done_prev) / (now - w_prev), rss_mb=rss_bytes() / 2**20,
                ledger_rows=ledger_rows, ticks=c.clock.ticks, ticks_expected=ticks_exp,
                tick_error=c.clock.ticks - ticks_exp, steps_not_user_dt=off_dt,
                t_float_error_s=c.clock.t - ticks_exp / TICKS_PER_SECOND,
                t_naive_sum_error_s=t_naive - ticks_exp / TICKS_PER_SECOND,
                px=float(p[0, 0]), pz=float(p[0, 2]), x=float(kin.com[0, 0]), z=float(kin.com[0, 2]),
                impulse_fluid_z=float(J["fluid"].total[0, 2]), impulse_mooring_x=float(J["mooring"].total[0, 0]),
                impulse_mooring_z=float(J["mooring"].total[0, 2]), impulse_gravity_z=float(J["gravity"].total[0, 2]),
                residual_x_Ns=float(res[0, 0]), residual_z_Ns=float(res[0, 2]),
                residual_Ns=float(np.linalg.norm(res)), gross_impulse_Ns=gross,
                residual_rel=float(np.linalg.norm(res) / gross),
                residual_naive_float_sum_Ns=float(np.linalg.norm(res_naive)),
                residual_L=float(np.linalg.norm(res_L)),
                none_refs=sys.getrefcount(None), none_refs_given_back=given[0], gc_objects=len(gc.get_objects()),
                load1=load1(),
            )
            emit("row", row)
            w_prev, done_prev = time.perf_counter(), done
            print(f"  {model:9s} {done:>8d} steps {row['wall_s']:8.1f} s {row['steps_per_s']:6.0f}/s "
                  f"RSS {row['rss_mb']:7.1f} MB ledger {ledger_rows:>7d} rows  ticks {row['tick_error']:+d}  "
                  f"|dp - J| {row['residual_Ns']:.3e} N s (rel {row['residual_rel']:.1e})  "
                  f"|dL - JT| {row['residual_L']:.1e}  None refs {row['none_refs']}  x {row['x']:+.4f} m  "
                  f"load {row['load1']:.2f}", flush=True)
        final = dict(wall_s=time.perf_counter() - w0, cpu_s=time.process_time() - c0, other=other())
        if ledger_mode == "keep":  # the incremental balance against the whole ledger, and what arrays() costs
            r0, ta = rss_bytes(), time.perf_counter()
            a = led.arrays()
            arrays_s, arrays_mb = time.perf_counter() - ta, (rss_bytes() - r0) / 2**20
            impulse = J["fluid"].total + J["mooring"].total + J["gravity"].total
            # the ledger keeps each step's start time, not its dt: with the fixed step every dt is n_dt
            # ticks; np.diff of the float times (what a reader of the ledger alone would do) is off by
            # up to an ulp of t per step
            whole = ExactImpulse((nb, 3))
            for f in ("fluid_force", "mooring_force", "gravity"):
                whole.add(a[f], np.full(len(a["t"]), n_dt))
            F_rows = sum(a[f] for f in ("fluid_force", "mooring_force", "gravity"))
            J_diff = (F_rows * np.diff(np.append(a["t"], c.clock.t))[:, None, None]).sum(axis=0)
            final.update(arrays_s=arrays_s, arrays_mb=arrays_mb,
                         incremental_vs_arrays_Ns=float(np.abs((whole.total - impulse).astype(float)).max()),
                         incremental_vs_arrays_difft_Ns=float(np.abs(J_diff - impulse.astype(float)).max()),
                         ledger_bytes_per_step_getsizeof=ledger_getsizeof(led) / max(len(led), 1))
            del a
        emit("final", final)
    fh.close()


def summarize(meta: dict, rows: list, final: dict | None, rc: int) -> dict:
    """One model's figures from its chunk records (a run that died: from the chunks it finished)."""
    steps = rows[-1]["steps"] if rows else 0
    wall = final["wall_s"] if final else (rows[-1]["wall_s"] if rows else math.nan)
    cpu = final["cpu_s"] if final else (rows[-1]["cpu_s"] if rows else math.nan)
    xs = [r["steps"] for r in rows]
    later = slice(len(rows) // 2, None)  # RSS and object slopes over the second half: past JIT and first touches
    none_refs = [r["none_refs"] for r in rows]
    mortal_none = tuple(int(v) for v in meta.get("python", "3.12").split(".")[:2]) < (3, 12)
    none_leak = -slope_per(xs[later], none_refs[later]) if mortal_none else 0.0
    none_leak = 0.0 if math.isnan(none_leak) else none_leak
    given = rows[-1]["none_refs_given_back"] / steps if rows and steps else 0.0
    out = dict(meta, steps_done=steps, status="ok" if rc == 0 and final else f"died (exit {rc}) after {steps} steps",
               wall_s=wall, cpu_s=cpu, steps_per_s=steps / wall if steps else math.nan,
               steps_per_cpu_s=steps / cpu if steps else math.nan,
               rss_start_mb=rows[0]["rss_mb"] if rows else math.nan,
               rss_end_mb=rows[-1]["rss_mb"] if rows else math.nan,
               rss_slope_b_per_1000=slope_per(xs[later], [r["rss_mb"] * 2**20 for r in rows][later], 1000.0),
               rss_growth_mb=(rows[-1]["rss_mb"] - rows[0]["rss_mb"]) if rows else math.nan,
               gc_objects_per_1000=slope_per(xs[later], [r["gc_objects"] for r in rows][later], 1000.0),
               none_refs_lost_per_step=max(none_leak, given), none_refs_end=rows[-1]["none_refs"] if rows else 0,
               tick_error_max=max((abs(r["tick_error"]) for r in rows), default=0),
               steps_not_user_dt=rows[-1]["steps_not_user_dt"] if rows else 0, rows=rows)
    if rows:
        last = rows[-1]
        out.update(t_float_error_s=last["t_float_error_s"], t_naive_sum_error_s=last["t_naive_sum_error_s"],
                   residual_Ns=last["residual_Ns"], residual_max_Ns=max(r["residual_Ns"] for r in rows),
                   residual_rel=last["residual_rel"], gross_impulse_Ns=last["gross_impulse_Ns"],
                   residual_drift_x_per_1e6=slope_per(xs, [r["residual_x_Ns"] for r in rows], 1e6),
                   residual_drift_z_per_1e6=slope_per(xs, [r["residual_z_Ns"] for r in rows], 1e6),
                   residual_L=last["residual_L"], residual_naive_Ns=last["residual_naive_float_sum_Ns"],
                   load_mean=float(np.mean([r["load1"] for r in rows])))
    out.update(final or {})
    out.setdefault("other", "")
    return out


def ledger_cost(rows: int, out: str) -> None:
    """The ledger alone: ``rows`` records of one body (what a coupling step books), RSS per
    step, then what ``arrays()`` of all of them adds; one JSON line into ``out``."""
    from cosim.ledger import Ledger

    z = np.zeros((1, 3))
    led = Ledger(["box"])
    r0, t0 = rss_bytes(), time.perf_counter()
    for i in range(rows):
        led.record(i * 0.01, z, z, z, z, z)
    rec_s, r1 = time.perf_counter() - t0, rss_bytes()
    getsz = ledger_getsizeof(led)
    t0 = time.perf_counter()
    a = led.arrays()
    arr_s, r2 = time.perf_counter() - t0, rss_bytes()
    raw = sum(v.nbytes for v in a.values())
    res = dict(rows=rows, rss_per_step=(r1 - r0) / rows, getsizeof_per_step=getsz / rows, raw_per_step=raw / rows,
               record_us=rec_s / rows * 1e6, arrays_s=arr_s, arrays_rss_mb=(r2 - r1) / 2**20,
               ledger_rss_mb=(r1 - r0) / 2**20)
    with open(out, "w") as f:
        f.write(json.dumps({"ledger": res}) + "\n")


# ------------------------------------------------------------------ command line
def _child(task: dict) -> tuple[int, list]:
    """Run ``task`` in a fresh interpreter (a clean RSS for each model; a crash in a C
    extension ends that model only); its return code and JSON records."""
    with tempfile.NamedTemporaryFile("w", suffix=".jsonl", delete=False) as f:
        out = f.name
    try:
        rc = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--child",
                             json.dumps(dict(task, out=out))]).returncode
        with open(out) as f:
            return rc, [json.loads(line) for line in f if line.strip()]
    finally:
        os.unlink(out)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--steps", type=int, default=1_000_000, help="coupling steps per model (default 10^6)")
    ap.add_argument("--models", default=",".join(MODELS), help="comma list of mooring models (default: all)")
    ap.add_argument("--dt", type=float, default=0.01, help="fixed coupling step [s] (default 0.01)")
    ap.add_argument("--every", type=int, default=None, help="steps per chunk and report (default steps/20)")
    ap.add_argument("--ledger", choices=("truncate", "keep"), default="truncate",
                    help="truncate: empty the ledger after each chunk (memory net of it); keep: as a run does")
    ap.add_argument("--ledger-rows", type=int, default=0,
                    help="also measure the ledger alone with this many rows (e.g. 1000000; 0: skip)")
    ap.add_argument("--patch-moordyn", action="store_true",
                    help="give back the reference to None that moordyn.Deserialize loses on each call (the adapter "
                         "now does it itself; for reproducing the runs of the docstring with an older adapter)")
    ap.add_argument("--csv", type=Path, default=None, help="write every chunk's record here")
    ap.add_argument("--child", default=None, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        task = json.loads(args.child)
        if task.pop("fn") == "ledger":
            ledger_cost(**task)
        else:
            soak(**task)
        return 0
    models = [s.strip() for s in args.models.split(",") if s.strip()]
    bad = [s for s in models if s not in MODELS]
    if bad or args.steps < 1 or not (args.dt > 0):
        ap.error(f"models among {', '.join(MODELS)} (got {bad}), steps >= 1, dt > 0")
    every = args.every or max(args.steps // 20, 1)
    print(f"soak: {args.steps} steps of {args.dt} s per model, chunks of {every}, ledger {args.ledger}; "
          f"{cpu_name()}, {os.cpu_count()} CPUs, Python {platform.python_version()}, load {os.getloadavg()}, "
          f"{datetime.datetime.now().isoformat(timespec='seconds')}", flush=True)
    print("  command: python benchmarks/soak.py " + " ".join(sys.argv[1:] if argv is None else argv), flush=True)
    results = []
    for model in models:
        if model == "moordyn":
            from moorings.moordyn_mooring import moordyn_available

            if not moordyn_available():
                print("  moordyn: not installed, skipped", flush=True)
                continue
        rc, recs = _child(dict(fn="soak", model=model, steps=args.steps, dt=args.dt, every=every,
                               ledger_mode=args.ledger, patch_moordyn=args.patch_moordyn))
        meta = next((r["meta"] for r in recs if "meta" in r), dict(model=model, ledger=args.ledger, scheme="?"))
        final = next((r["final"] for r in recs if "final" in r), None)
        results.append(summarize(meta, [r["row"] for r in recs if "row" in r], final, rc))
        if results[-1]["status"] != "ok":
            print(f"  {model}: {results[-1]['status']}", flush=True)
    print()
    hdr = (f"{'model':10s} {'steps':>8s} {'wall s':>7s} {'st/s':>5s} {'st/cpu-s':>8s} {'RSS start':>9s} "
           f"{'RSS end':>8s} {'B/1000st':>8s} {'ticks':>5s} {'|dp-J| N s':>10s} {'rel':>7s} "
           f"{'z/1e6 st':>9s} {'|dL-JT|':>8s} {'None/st':>7s} {'load':>5s}  other")
    print(hdr)
    for r in results:
        if not r["steps_done"]:
            print(f"{r['model']:10s} {r['status']}")
            continue
        print(f"{r['model']:10s} {r['steps_done']:>8d} {r['wall_s']:>7.0f} {r['steps_per_s']:>5.0f} "
              f"{r['steps_per_cpu_s']:>8.0f} {r['rss_start_mb']:>7.1f}MB {r['rss_end_mb']:>6.1f}MB "
              f"{r['rss_slope_b_per_1000']:>8.0f} {r['tick_error_max']:>5d} {r['residual_Ns']:>10.2e} "
              f"{r['residual_rel']:>7.0e} {r['residual_drift_z_per_1e6']:>9.1e} {r['residual_L']:>8.1e} "
              f"{r['none_refs_lost_per_step']:>7.2f} {r['load_mean']:>5.2f}  {r['other']}"
              + ("" if r["status"] == "ok" else f"  {r['status'].upper()}"))
    print()
    for r in results:
        if not r["steps_done"]:
            continue
        extra = ""
        if "arrays_s" in r:
            extra = (f"; ledger.arrays() of {r['steps_done']} rows: {r['arrays_s']:.2f} s, +{r['arrays_mb']:.1f} MB, "
                     f"its impulse vs the incremental one {r['incremental_vs_arrays_Ns']:.1e} N s "
                     f"({r['incremental_vs_arrays_difft_Ns']:.1e} N s with dt = np.diff(t)), "
                     f"{r['ledger_bytes_per_step_getsizeof']:.0f} B/step by getsizeof")
        if r["none_refs_lost_per_step"] > 0.01:
            extra += (f"; None loses {r['none_refs_lost_per_step']:.2f} references a step"
                      + (" (given back by --patch-moordyn)" if r.get("patch_moordyn") else
                         f", {r['none_refs_end']} left at the end: the interpreter aborts when they run out"))
        print(f"{r['model']:10s} {r['status']}; scheme {r['scheme']}, Python {r.get('python', '?')}, build "
              f"{r['build_s']:.2f} s, RSS after imports {r['rss_import_mb']:.1f} MB, built {r['rss_built_mb']:.1f} MB, "
              f"gc objects {r['gc_objects_per_1000']:+.1f} per 1000 steps; steps not at the user dt: "
              f"{r['steps_not_user_dt']}; clock.t float error {r['t_float_error_s']:.1e} s, a naive sum t += dt "
              f"would be off by {r['t_naive_sum_error_s']:.1e} s; gross impulse {r['gross_impulse_Ns']:.4e} N s, "
              f"max |dp-J| {r['residual_max_Ns']:.2e} N s (with plain float sums {r['residual_naive_Ns']:.2e}), "
              f"its slope per 10^6 steps x {r['residual_drift_x_per_1e6']:.1e}, z {r['residual_drift_z_per_1e6']:.1e} "
              f"N s; 10^6 steps: {1e6 / r['steps_per_s'] / 60:.0f} min at this wall rate, "
              f"{1e6 / r['steps_per_cpu_s'] / 60:.0f} min of CPU{extra}")
    if args.ledger_rows:
        rc, recs = _child(dict(fn="ledger", rows=args.ledger_rows))
        if rc == 0 and recs:
            lc = recs[0]["ledger"]
            print(f"\nledger alone, {lc['rows']} rows of one body: {lc['rss_per_step']:.0f} B/step resident "
                  f"({lc['ledger_rss_mb']:.0f} MB), {lc['getsizeof_per_step']:.0f} B/step by getsizeof, "
                  f"{lc['raw_per_step']:.0f} B/step as arrays; record() {lc['record_us']:.2f} us; arrays() "
                  f"{lc['arrays_s']:.2f} s, +{lc['arrays_rss_mb']:.0f} MB")
        else:
            print(f"\nledger alone: the child died (exit {rc})")
    if args.csv:
        rows = [row for r in results for row in r["rows"]]
        if rows:
            with open(args.csv, "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=list(rows[0]))
                w.writeheader()
                w.writerows(rows)
            print(f"wrote {args.csv}")
    return 0 if all(r["status"] == "ok" for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
