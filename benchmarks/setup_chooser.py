"""Validation cases under each candidate set-up of ``cosim.scene.setup`` (``--setups``), the
same extraction and metric as the case, and the CPU seconds of each run
(``time.process_time``). The tank-pressure cases at their quick variants' spacing: the
case's own set-up (the solver's defaults, ``walls="adami"``: "impulsive") against
"sloshing" (h = 2 dx, walls "adami"; 3-D also the diffusion faded under the surface);
SPHERIC Test 10's first swing (the quick variant) and the 3-D floating box of
floating-box-draft's full variant (dx 12.5 mm, 500 kg/m^3: "defaults" against "still").
Run from the repository root with PYTHONPATH=$PWD and NUMBA_NUM_THREADS=1 (CPU seconds
then compare between runs on a shared machine).

    python benchmarks/setup_chooser.py westergaard [--dx 0.1]
    python benchmarks/setup_chooser.py inclined [--dx 0.1] [--angle 45]
    python benchmarks/setup_chooser.py cylinder [--dx 0.1]
    python benchmarks/setup_chooser.py westergaard-3d [--dx 0.1]   # the quick slice, 0.3 m wide
    python benchmarks/setup_chooser.py spheric10 --setups defaults,sloshing   # walls "adami" in both
    python benchmarks/setup_chooser.py draft-3d --setups defaults,still   # still: the chooser's (auto)

Prints one line per set-up: the case's judged metrics and the CPU seconds.
"""

from __future__ import annotations

import argparse
import time


def run(tank: str, dx: float, angle: float, setup: str) -> dict:
    from cosim.scene.setup import settings
    from cosim.validations.sloshing import run_westergaard
    from cosim.validations.tanks import run_cylinder, run_inclined

    dim = 3 if tank in ("cylinder", "westergaard-3d", "draft-3d") else 2
    cfg = settings(setup, dim)
    if tank == "spheric10":
        from cosim.validations.sloshing import run_spheric10

        return run_spheric10(0.0186, t_end=1.3, sample_dt=0.005, **{"walls": "adami", **cfg})
    if tank == "draft-3d":
        from cosim.validations import case_scene
        from cosim.validations.floating import settle_draft

        if setup == "defaults":  # the file's
            r = settle_draft(3, 0.0125, 500.0, 1.0, 0.5)
        else:  # the chooser's ("still")
            with case_scene.auto_setup():
                r = settle_draft(3, 0.0125, 500.0, 1.0, 0.5)
        return {"metrics": r, "particles": r["particles"], "steps": r["steps"]}
    if tank == "westergaard":
        return run_westergaard(dx, periods_skip=1, periods_fit=2, **cfg)
    if tank == "westergaard-3d":
        return run_westergaard(dx, dim=3, width=0.3, c0=700.0, periods_skip=1, periods_fit=1, **cfg)
    if tank == "inclined":
        return run_inclined(angle, dx, periods_skip=1, periods_fit=2, **cfg)
    return run_cylinder(dx, periods_skip=1, periods_fit=2, **cfg)


KEYS = {"westergaard": ("rms_face_vs_exact", "rms_raw_vs_exact", "kp_out_of_phase_max_avg"),
        "westergaard-3d": ("rms_face_vs_exact", "rms_raw_vs_exact", "kp_out_of_phase_max_avg"),
        "inclined": ("rms_right_vs_chwang", "rms_right_vs_exact"),
        "cylinder": ("rms_kpa_plane_vs_exact", "p_base_kpa", "p_base_exact_kpa", "out_of_phase_max_kpa"),
        "spheric10": ("swing1_peak_err", "swing1_lag_abs_s"),
        "draft-3d": ("error_of_height", "draft_std_m")}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("tank", choices=sorted(KEYS))
    ap.add_argument("--dx", type=float, default=0.1)
    ap.add_argument("--angle", type=float, default=45.0)
    ap.add_argument("--setups", default="impulsive,sloshing")
    args = ap.parse_args(argv)
    for setup in args.setups.split(","):
        t0 = time.process_time()
        r = run(args.tank, args.dx, args.angle, setup)
        cpu = time.process_time() - t0
        m = r["metrics"]
        print(f"{args.tank} dx={m.get('dx_m', args.dx):g} setup={setup}: "
              + ", ".join(f"{k}={m[k]:.4f}" for k in KEYS[args.tank] if k in m)
              + f", particles={r['particles']}, steps={r['steps']}, cpu_s={cpu:.1f}", flush=True)


if __name__ == "__main__":
    main()
