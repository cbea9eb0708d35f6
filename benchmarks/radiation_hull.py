"""nearfield-radiation's box with another hull of the cylinder's waterline (R = 3 m): a floating
hemisphere (no sharp edge, draft R) or the cylinder drawing another draft, forced in heave
as the case forces its cylinder (0.3 m, T = 3.54 s, k R = 1), its tare run beside, read as
the case reads its own (``cosim.validations.radiation``: the tared force's first harmonic
over whole periods after the ramp, period by period too; each gauge against Capytaine's
radiated elevation there). The reference: Capytaine's A33, B33 of the same hull at the
case's depth (panels 0.05 R, cached). docs/validation/nearfield.md, "Other hulls in the
case's box".

    python benchmarks/radiation_hull.py --out OUT [--hull hemisphere|cylinder] [--draft D]
        [--r-over-dx 4] [--periods 6] [--amplitude 0.3] [--depth 6] [--set KEY=VALUE ...] [--only forced|held]
        [--upto N]

Each run is kept in ``OUT/forced`` and ``OUT/held`` and resumed from its checkpoint; a
call without ``--only`` runs what is missing (one after the other) and prints the figures.
``--upto N`` reads the first N periods after the ramp of runs still going. ``--amplitude A``
forces the hull through A [m] instead of the case's 0.3 m: radiation damping does not depend
on it, a drag from flow separating at an edge grows in proportion to it (its equivalent
linear damping, Lorentz's equal work per cycle, is (8/3pi) (rho/2) Cd A_p omega a); the tare
run does not depend on it and can be copied from another OUT. ``--set`` changes the scene's
values in both runs (``fluid.nu=0``: no laminar viscosity). Without ``OUT/held`` the figures
are untared (at 0.6 m of heave the tare moves the deep cylinder's B33 by 1.2 kN s/m).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from cosim.validations import case_scene
from cosim.validations.radiation import (PANEL, added_mass_damping, cylinder_hull, damping_by_period, gauge_line,
                                         held_scene, hull_elevation, hull_reference, outgoing_amplitude,
                                         radiation_scene)
from cosim.validations.wave_propagation import harmonics

RADIUS = 3.0  # m: the cylinder's


def scene_for(hull: str, draft: float, r_over_dx: float, periods: int, held: bool, amplitude: float = 0.3,
              settings=(), depth: float | None = None):
    """The case's quick scene with ``hull`` in place of its cylinder: a sphere of
    :data:`RADIUS` centred on the still water ("hemisphere"), or the cylinder drawing
    ``draft`` [m] (its centre on the still water, twice as long), at ``r_over_dx``, forced
    through ``amplitude`` [m], for the ramp and ``periods`` periods, with ``settings``
    ("KEY=VALUE", as ``cosim run --set``), in water ``depth`` [m] deep (unset: the case's;
    the walls keep the case's height above the water)."""
    from cosim.scene.toml_io import from_dict, to_dict

    d = to_dict(radiation_scene(True))
    b = d["bodies"][0]
    if depth is not None:
        d["domain"]["height"] += depth - d["domain"]["depth"]
        d["domain"]["depth"] = d["waves"]["depth"] = depth
    depth = d["domain"]["depth"]
    if hull == "hemisphere":
        b.pop("length")
        b.update(shape="sphere", name="hemisphere", radius=RADIUS, pos=[0.0, 0.0, depth])
        d["probes"]["motion"] = ["hemisphere"]
    else:
        b.update(radius=RADIUS, length=2.0 * draft, pos=[0.0, 0.0, depth])
    b["motion"]["amplitude"] = amplitude
    d["fluid"]["dx"] = RADIUS / r_over_dx
    d["world"]["duration"] = (b["motion"]["ramp"] + periods) * b["motion"]["period"]
    d["name"] = f"radiation-{hull}"
    s = from_dict(d).with_values(list(settings))
    return held_scene(s) if held else s


def reference_hull(hull: str, draft: float):
    """The wetted hull of ``hull`` (:func:`scene_for`) for Capytaine, panels :data:`PANEL` R."""
    from fluid.potential import wetted_hull

    if hull == "cylinder":
        return cylinder_hull(RADIUS, draft)
    return wetted_hull("sphere", [RADIUS], np.eye(3), [0.0, 0.0, 0.0], PANEL * RADIUS, name=hull)


def _records(folder: Path):
    """The run's records, of a run still going too, as far as every series is written:
    ``(t, series)``."""
    from cosim.scene.runner import read

    r = read(folder, unfinished=True)
    n = min([len(r.t)] + [len(v) for v in r.series.values()])
    return r.t[:n], {k: v[:n] for k, v in r.series.items()}


def figures(out: Path, hull_name: str, draft: float, r_over_dx: float, periods: int, amplitude: float = 0.3,
            settings=(), depth: float | None = None) -> str:
    """The table's lines: A33, B33 (whole and by period) and the gauges against Capytaine;
    tared by ``out/held`` where it is there."""
    from fluid.waves import wavenumbers

    s = scene_for(hull_name, draft, r_over_dx, periods, False, amplitude, settings, depth)
    m, depth = s.bodies[0].motion, s.domain.depth
    g, rho = s.world.gravity, s.fluid.rho0
    w = 2.0 * math.pi / m.period
    k = float(wavenumbers(w, depth, g))
    hull = reference_hull(hull_name, draft)
    a_ref, b_ref, c33 = hull_reference(hull, depth, w, rho, g, name=f"radiation-{hull_name}")
    t, forced = _records(out / "forced")
    tare = (out / "held").is_dir()
    t_held, held = _records(out / "held") if tare else (t, None)
    n = min(len(t), len(t_held))
    t0 = m.ramp * m.period
    fit = (t[:n] > t0 - 1e-9) & (t[:n] <= t0 + periods * m.period + 1e-9)  # as the case: from the ramp's end
    if t[:n][-1] < t0 + periods * m.period - 1e-6:
        raise SystemExit(f"the runs reach {t[:n][-1]:.4g} s, short of {periods} periods after the ramp; "
                         f"give --upto with fewer")
    ts = t[:n][fit]

    def tared(name):
        return forced[name][:n][fit] - (held[name][:n][fit] if tare else 0.0)

    body = next(k for k in forced if k.endswith(".fluid_Fz"))[:-len(".fluid_Fz")]  # the one body's series
    fz = tared(f"{body}.fluid_Fz")
    a33, b33 = added_mass_damping(ts, fz, m.amplitude, w, c33)
    per = damping_by_period(ts, fz, m.amplitude, w, c33, m.period)
    z1 = harmonics(ts, forced[f"{body}.heave"][:n][fit][:, None], w)[0]
    pts = np.asarray(s.probes.gauges, float)[:, :2]
    z = harmonics(ts, np.column_stack([tared(f"gauge{i + 1}.eta") for i in range(len(pts))]), w)
    z_ref = z1 * hull_elevation(hull, depth, w, rho, g, pts)
    theory = outgoing_amplitude(b_ref, m.amplitude, w, depth, rho, g)
    r = np.hypot(pts[:, 0], pts[:, 1])
    along_x = np.abs(pts[:, 0]) > np.abs(pts[:, 1])
    lines = [f"{hull_name}, draft {hull.draft:g} m, depth {depth:g} m, R/dx = {r_over_dx:g}, "
             f"amplitude {m.amplitude:g} m, "
             f"{' '.join(settings) + ', ' if settings else ''}{periods} periods after the ramp, "
             f"{'tared' if tare else 'untared'}; "
             f"Capytaine (panels {PANEL:g} R): A33 {a_ref:.0f} kg, B33 {b_ref:.0f} kg/s, C33 {c33:.0f} N/m",
             f"SPH: A33 {a33:.0f} kg ({a33 / a_ref - 1:+.1%}), B33 {b33:.0f} kg/s ({b33 / b_ref - 1:+.1%}); "
             f"B33 by period " + ", ".join(f"{x / 1e3:.1f}" for x in per) + " kN s/m"]
    for name, sel in (("x", along_x), ("y", ~along_x)):
        f = gauge_line(r[sel], z[sel], z_ref[sel], k, theory)
        lines.append(f"{name} line, r = {np.round(r[sel], 2).tolist()} m: H1 / Capytaine's {f['H1_over_reference']}, "
                     f"lag {f['lag_periods']} periods; outgoing / B33's {f['outgoing_over_theory']:.3f}, "
                     f"reflection {f['reflection']:.3f} (floor {f['reflection_floor']:.3f})")
    return "\n".join(lines)


def add_scene_arguments(ap, hull: str = "hemisphere", draft: float = 1.5, amplitude: float = 0.3) -> None:
    """The options of :func:`scene_for` on the parser ``ap``, with these defaults."""
    ap.add_argument("--hull", choices=("hemisphere", "cylinder"), default=hull)
    ap.add_argument("--draft", type=float, default=draft, help="the cylinder's draft [m] (the case's: 1.5)")
    ap.add_argument("--r-over-dx", type=float, default=4.0)
    ap.add_argument("--periods", type=int, default=6)
    ap.add_argument("--amplitude", type=float, default=amplitude, help="the heave amplitude [m] (the case's: 0.3)")
    ap.add_argument("--depth", type=float, help="the water's depth [m] (the case's: 6)")
    ap.add_argument("--set", dest="settings", action="append", default=[], metavar="KEY=VALUE",
                    help="a scene value (as cosim run --set), e.g. fluid.nu=0")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, type=Path)
    add_scene_arguments(ap)
    ap.add_argument("--only", choices=("forced", "held"))
    ap.add_argument("--upto", type=int, help="read the first UPTO periods after the ramp (runs still going)")
    args = ap.parse_args(argv)
    if args.upto is None:
        for run in ([args.only] if args.only else ["forced", "held"]):
            case_scene.run_or_resume(scene_for(args.hull, args.draft, args.r_over_dx, args.periods, run == "held",
                                               args.amplitude, args.settings, args.depth), args.out / run)
    if args.only != "held":
        print(figures(args.out, args.hull, args.draft, args.r_over_dx, args.upto or args.periods, args.amplitude,
                      args.settings, args.depth))


if __name__ == "__main__":
    main()
