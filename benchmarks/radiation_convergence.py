"""nearfield-radiation at several spacings: does the heave damping B33 of the cylinder forced
in the SPH near field converge to the boundary-element reference as R/dx grows? The case's
scene (``cosim/validations/scenes/nearfield-radiation.toml``: the wind-turbine base's hull,
R = 3 m, forced 0.3 m at k R = 1) at each R/dx, read by the case's ``radiation_metrics``
(A33 and B33 from the force's first harmonic against Capytaine's, the radiated wave's
reflection and its amplitude against the one B33 carries). Each run is kept in
``OUT/R_over_dx_N`` and resumed from its checkpoint or read back when the script runs again
(``cosim.validations.case_scene.run_or_resume``): R/dx = 8 takes several CPU-hours (``cosim
run ... --dry-run`` estimates 2.2), and a run a stopped process leaves, the next one resumes.

    python benchmarks/radiation_convergence.py --out OUT [--r-over-dx 4 6 8] [--periods 6] [--amplitude 0.3] [--no-tare]
        [--set fluid.nu=0 ...]

``--periods``: the periods run after the ramp (the case's 6, all of them fitted); each run's
B33 and A33 are also fitted over every whole period after the ramp, and over the last 2, 4
and 6, which show how B33 swings with what the zones send back. ``--amplitude``: the heave
amplitude [m] (the case's 0.3 m), for how the coefficients' errors scale with the motion.
Each spacing's tare (the body held still, ``radiation.held_scene``) is run and subtracted
as the case does; ``--no-tare`` leaves it out (the forced run's force alone). ``--set``:
scene values changed in both runs (``cosim run``'s ``--set``), for the fluid's levers; the
runs' folders are named by them.

Prints one JSON line per run, then two markdown tables.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

from cosim.validations import case_scene
from cosim.validations.radiation import (PERIODS_AFTER_RAMP, added_mass_damping, held_scene, radiation_metrics,
                                         radiation_scene)
from cosim.validations.wave_propagation import harmonics


def scene_at(r_over_dx: float, periods: float = PERIODS_AFTER_RAMP, amplitude: float | None = None,
             extra=()):
    """The case's full scene at ``R / dx = r_over_dx``, run ``periods`` periods after the ramp
    (``amplitude`` [m]: its heave amplitude instead of the case's; ``extra``: further
    ``KEY=VALUE`` changes, made first, so that a longer ramp lengthens the run; the spacing
    is ``r_over_dx``'s)."""
    scene = radiation_scene(False).with_values(list(extra))
    m = scene.bodies[0].motion
    values = [f"fluid.dx={case_scene.number(scene.bodies[0].radius / r_over_dx)}",
              f"world.duration={case_scene.number((m.ramp + periods) * m.period)}"]
    if amplitude is not None:
        values.append(f"bodies[0].motion.amplitude={case_scene.number(amplitude)}")
    return scene.with_values(values)


def by_period(res, scene, reference: tuple, tare=None) -> dict:
    """B33 [kg/s] and the errors of B33 and A33 against ``reference`` = (A33, B33, C33) fitted
    by the case's ``added_mass_damping`` over each whole period after the ramp, and over the
    last 2, 4 and 6 periods where the run has them; less the held run ``tare``'s force where
    given. ``sliding``: B33 [kg/s] and the first gauge's first-harmonic amplitude [m] (the
    radiated wave 2 R from the axis) in one-period windows every quarter period after the
    ramp: whether a swing of the damping is the body's radiated wave's too."""
    a_ref, b_ref, c33 = reference
    b = scene.bodies[0]
    m = b.motion
    w = 2.0 * math.pi / m.period
    name = f"{b.name}.fluid_Fz"
    t, fz = res.t, res[name] - (0.0 if tare is None else tare[name])

    def fit(sel):
        a33, b33 = added_mass_damping(t[sel], fz[sel], m.amplitude, w, c33)
        return {"B33_kg_s": b33, "B33_error": b33 / b_ref - 1.0, "A33_error": a33 / a_ref - 1.0}

    whole = int((t[-1] + 1e-9) / m.period - m.ramp)
    periods = [fit((t >= (m.ramp + j) * m.period - 1e-9) & (t <= (m.ramp + j + 1) * m.period + 1e-9))
               for j in range(whole)]
    last = {n: fit(t >= t[-1] - n * m.period - 1e-9) for n in (2, 4, 6) if n <= whole}
    eta = res["gauge1.eta"] - (0.0 if tare is None else tare["gauge1.eta"])
    sliding = []
    for j in range(4 * whole - 3):
        t0 = (m.ramp + 0.25 * j) * m.period
        sel = (t >= t0 - 1e-9) & (t <= t0 + m.period + 1e-9)
        sliding.append({"periods_after_ramp": 0.25 * j, "B33_kg_s": fit(sel)["B33_kg_s"],
                        "gauge1_m": float(abs(harmonics(t[sel], eta[sel][:, None], w)[0]))})
    return {"periods": periods, "last": last, "sliding": sliding}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", type=Path, required=True, help="folder of the kept runs")
    p.add_argument("--r-over-dx", type=float, nargs="+", default=[4.0, 6.0, 8.0], help="radii per spacing")
    p.add_argument("--periods", type=float, default=PERIODS_AFTER_RAMP, help="periods run after the ramp")
    p.add_argument("--amplitude", type=float, help="heave amplitude [m] (default: the case's)")
    p.add_argument("--no-tare", action="store_true", help="no held run: the forced run's force alone")
    p.add_argument("--only", choices=("forced", "held"), help="run this one of the pair alone (two processes)")
    p.add_argument("--set", dest="values", action="append", default=[], metavar="KEY=VALUE",
                   help="a scene value changed in both runs (repeat)")
    a = p.parse_args(argv)
    rows = []
    for r in a.r_over_dx:
        scene = scene_at(r, a.periods, a.amplitude, a.values)
        held = (f"R_over_dx_{r:g}" + ("" if a.periods == PERIODS_AFTER_RAMP else f"_{a.periods:g}periods")
                + "".join(f"_{v}" for v in a.values))
        tag = held + ("" if a.amplitude is None else f"_A{a.amplitude:g}")
        if a.only is not None:
            case_scene.run_or_resume(scene if a.only == "forced" else held_scene(scene),
                                     a.out / (tag if a.only == "forced" else f"{held}_held"))
            continue
        res, earlier = case_scene.run_or_resume(scene, a.out / tag)
        tare = None
        if not a.no_tare:  # one held run for every amplitude at this spacing and length
            tare, held_cpu = case_scene.run_or_resume(held_scene(scene), a.out / f"{held}_held")
            earlier += held_cpu
        m = radiation_metrics(res, scene, tare)
        keep = ("R_over_dx", "A33_kg", "A33_error", "B33_kg_s", "B33_error", "reflection", "particles", "steps",
                "cpu_s")
        row = {k: m.get(k) for k in keep} | {"cpu_s_earlier": earlier, "outgoing_over_B33": max(
            v["outgoing_over_theory"] for v in m["lines"].values()), "heave_amplitude_m": m["heave_amplitude_m"]}
        row["by_period"] = by_period(res, scene, (m["A33_ref_kg"], m["B33_ref_kg_s"], m["C33_N_m"]), tare)
        row |= {"tared": m["tared"], "B33_error_untared": m["B33_error_untared"]}
        print(json.dumps(row), flush=True)
        rows.append(row)
    if not rows:
        return 0
    print("\n| R/dx | A33 error | B33 error | B33 error untared | reflection | outgoing / B33's | particles | steps "
          "| CPU s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for w in rows:
        print(f"| {w['R_over_dx']:g} | {w['A33_error']:.1%} | {w['B33_error']:.1%} | {w['B33_error_untared']:.1%} | "
              f"{w['reflection']:.3f} | "
              f"{w['outgoing_over_B33']:.3f} | {w['particles']} | {w['steps']} | {w['cpu_s']:.0f} |")
    print("\n| R/dx | heave [m] | B33 per period after the ramp [kN s/m] | B33 error over the last 2 / 4 / 6 periods "
          "| A33 error over the same |")
    print("|---|---|---|---|---|")
    for w in rows:
        bp = w["by_period"]
        per = ", ".join(f"{q['B33_kg_s'] / 1e3:.1f}" for q in bp["periods"])
        print(f"| {w['R_over_dx']:g} | {w['heave_amplitude_m']:.3g} | {per} | "
              + " / ".join(f"{q['B33_error']:+.1%}" for q in bp["last"].values()) + " | "
              + " / ".join(f"{q['A33_error']:+.1%}" for q in bp["last"].values()) + " |")
    print("\n| R/dx | heave [m] | B33 [kN s/m] / first gauge's amplitude [cm], one-period windows every quarter "
          "period after the ramp |")
    print("|---|---|---|")
    for w in rows:
        print(f"| {w['R_over_dx']:g} | {w['heave_amplitude_m']:.3g} | "
              + ", ".join(f"{q['B33_kg_s'] / 1e3:.1f} / {100 * q['gauge1_m']:.2f}" for q in w["by_period"]["sliding"])
              + " |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
