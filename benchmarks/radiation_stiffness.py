"""SPH's own heave stiffness of nearfield-radiation's cylinder: the case's held scene
(``cosim.validations.radiation.held_scene``) with the body placed ``dz`` [m] higher, run for
three heave periods, its vertical fluid force averaged over the last two, against
``rho g V`` of its draft there; the slope through the offsets against linear
hydrostatics' ``C33 = rho g pi R^2``. The case reads A33 with the linear C33, so SPH's error
in C33 shows in A33 as ``-dC / w^2`` (docs/validation/nearfield.md, "A33's share of the
restoring force"). Each run is kept in ``OUT/R_over_dx_N_dz_D`` and read back when the
script runs again.

    python benchmarks/radiation_stiffness.py --out OUT [--r-over-dx 4] [--dz -0.3 0 0.3] [--set KEY=VALUE ...]
        [--only DZ]

``--only DZ``: run that offset alone and print nothing (one process a core); a later call
without it reads every offset back. Prints one JSON line per offset, then the slope.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from cosim.validations import case_scene
from cosim.validations.radiation import draft_of, held_scene, radiation_scene, reference

PERIODS, AVERAGED = 3, 2


def offset_scene(r_over_dx: float, dz: float, values=()):
    """The case's held scene at ``r_over_dx``, the body ``dz`` [m] higher, for
    :data:`PERIODS` periods."""
    s = radiation_scene(True)
    b = s.bodies[0]
    s = s.with_values([f"fluid.dx={b.radius / r_over_dx:.6g}", f"world.duration={PERIODS * b.motion.period:.6g}",
                       *values])
    x, y, z = s.bodies[0].pos
    return held_scene(s).with_values([f"bodies[0].pos=[{x},{y},{z + dz}]"])


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", type=Path, required=True, help="folder for the kept runs")
    p.add_argument("--r-over-dx", type=float, default=4.0, help="radius over spacing (the quick variant's 4)")
    p.add_argument("--dz", type=float, nargs="+", default=[-0.3, 0.0, 0.3], help="the body's offsets [m], up")
    p.add_argument("--only", type=float, help="run this offset alone, print nothing")
    p.add_argument("--set", dest="values", action="append", default=[], metavar="KEY=VALUE",
                   help="a scene value changed in every run (repeat)")
    a = p.parse_args(argv)
    period = radiation_scene(True).bodies[0].motion.period
    rows = []
    for dz in ([a.only] if a.only is not None else a.dz):
        scene = offset_scene(a.r_over_dx, dz, a.values)
        tag = f"R_over_dx_{a.r_over_dx:g}_dz_{dz:g}" + "".join(f"_{v}" for v in a.values)
        res, _ = case_scene.run_or_resume(scene, a.out / tag)
        if a.only is not None:
            return 0
        b, d = scene.bodies[0], scene.domain
        g, rho = scene.world.gravity, scene.fluid.rho0
        draft = draft_of(scene)
        fit = res.t > res.t[-1] - AVERAGED * period - 1e-9
        f = res[f"{b.name}.fluid_Fz"][fit]
        weight = rho * g * math.pi * b.radius**2 * draft
        row = {"R_over_dx": a.r_over_dx, "dz_m": dz, "draft_m": draft, "Fz_N": float(f.mean()), "Fz_std_N": float(f.std()),
               "rho_g_V_N": weight, "over": float(f.mean() / weight - 1.0), "steps": res.summary["steps"],
               "cpu_s": res.summary["cpu_s"]}
        print(json.dumps(row), flush=True)
        rows.append(row)
    if len(rows) > 1:
        w = 2.0 * math.pi / period
        c_ref = reference(b.radius, rows[0]["draft_m"] + rows[0]["dz_m"], d.depth, w, rho, g)[2]  # the case's draft
        slope = -float(np.polyfit([r["dz_m"] for r in rows], [r["Fz_N"] for r in rows], 1)[0])
        print(f"\nC33: SPH {slope:.1f} N/m, Capytaine {c_ref:.1f} N/m ({slope / c_ref - 1.0:+.1%}); "
              f"in A33 that reads as {-(slope - c_ref) / w**2:.0f} kg")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
