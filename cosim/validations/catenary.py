"""Validation cases of the quasi-static catenary (``docs/VALIDATION.md``, Moorings).

The single lines and the pair of lines are test rigs, scenes (``scenes/catenary-*.toml``): a
body driven along x with the lines on it and no fluid, run by ``cosim run``'s runner, the
lines' tensions read at both ends (:func:`rig_run`); catenary-limits also reads points along
its 40 random lines. All are cheap; ``quick`` thins the sampling or takes 5 lines.
"""

from __future__ import annotations

import math

import numpy as np

from cosim.validations.registry import case
from moorings.catenary import (
    FULLY_LIFTED,
    PARTLY_LIFTED,
    RESTING,
    TAUT,
    lift_off_distance,
    shape,
    solve,
    taut_distance,
)
from moorings.catenary_mooring import TETHER_SLACK


def _rel(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-300)))


def limits_scene(quick: bool):
    """catenary-limits' scene (``scenes/catenary-limits.toml``: 40 rigs), or its first 5 rigs
    and lines (quick)."""
    from cosim.scene.toml_io import from_dict, to_dict
    from cosim.validations import case_scene

    scene = case_scene.load("catenary-limits")
    if not quick:
        return scene
    d = to_dict(scene)
    d["bodies"], d["moorings"]["lines"] = d["bodies"][:5], d["moorings"]["lines"][:5]
    return from_dict(d)


@case("catenary-limits", "inextensible catenary against Barreiro et al. 2016 closed forms (Eq. 29, 35-39)",
      target="exact to 1e-10 relative",
      quick="the stated target, exact to 1e-10 relative, on 5 random lines instead of 40", scene=limits_scene)
def catenary_limits(quick: bool) -> dict:
    """Closed forms of Barreiro et al. 2016, §3.1 over a family of lines, to 1e-10 relative,
    read from the case's rigs (``scenes/catenary-limits.toml``, :func:`rig_run`: H and V from
    the tensions at both ends, the shape from 11 points along each line):

    - RESTING (X <= L - h): H = 0, V = w h, touchdown = L - h (Fig. 5a).
    - PARTLY_LIFTED: the lifted length l_s = V/w obeys l_s^2 = h^2 + 2 h a with
      a = H/w (Eq. 37); Eq. 39 returns the X the rig set; touchdown = L - l_s.
    - At the lift-off point l_s = L, so H = w (L^2 - h^2) / (2 h) (Eq. 37); on the rig, or
      for the lines whose lift-off lies within the rig's tether slack of taut (a length
      constraint there, not the law), from the law at that X (``lift_off_H_of_the_law_lines``).
    - The line shape's suspended part obeys z = a (cosh(x/a) - 1) from the
      touchdown point (Eq. 29) and ends at the fairlead (X, h).
    """
    run = rig_run(limits_scene(quick))
    errs = {k: 0.0 for k in ("resting", "eq37", "eq39", "touchdown", "liftoff_H", "eq29_shape", "shape_end")}
    from_law = 0
    for ln in run["lines"].values():
        X, H, T, h, L, w = ln["X"], ln["H"], ln["T"], ln["h"], ln["L"], ln["w"]
        V = np.sqrt(np.maximum(T**2 - H**2, 0.0))
        law = solve(X, h, L, w)
        assert law.state[0] == RESTING and (law.state[1:-1] == PARTLY_LIFTED).all()
        errs["resting"] = max(errs["resting"], abs(H[0]) / (w * h), _rel(V[0], w * h), _rel(law.touchdown[0], L - h))
        for k in range(1, len(X) - 1):
            a, ls = H[k] / w, V[k] / w
            errs["eq37"] = max(errs["eq37"], _rel(ls**2, h**2 + 2 * h * a))
            errs["eq39"] = max(errs["eq39"], _rel(L - h * math.sqrt(1 + 2 * a / h) + a * math.acosh(1 + h / a), X[k]))
            errs["touchdown"] = max(errs["touchdown"], _rel(law.touchdown[k], L - ls))
            td, x, z = L - ls, ln["x"][k], ln["z"][k]
            sus = ln["s"] >= td
            errs["eq29_shape"] = max(errs["eq29_shape"],
                                     float(np.max(np.abs(z[sus] - a * (np.cosh((x[sus] - td) / a) - 1)))) / h)
            errs["shape_end"] = max(errs["shape_end"], math.hypot(x[-1] - X[k], z[-1] - h) / L)
        # within the tether's slack of taut the rig's line is a length constraint (the coupler's
        # taut inextensible line, moorings.CatenaryMooring's ``slack``): there the law itself
        if math.hypot(X[-1], h) > L * (1.0 - TETHER_SLACK):
            H_lift, from_law = float(law.H[-1]), from_law + 1
        else:
            H_lift = H[-1]
        errs["liftoff_H"] = max(errs["liftoff_H"], _rel(H_lift, w * (L**2 - h**2) / (2 * h)))
    tol = 1e-10
    return {
        "metrics": {f"max_rel_err_{k}": v for k, v in errs.items()} | {"lines": len(run["lines"]),
                                                                      "lift_off_H_of_the_law_lines": from_law},
        "tolerances": {f"max_rel_err_{k}": tol for k in errs},
        "steps": run["steps"],
    }


def load_cell_H(T, T_anchor, w: float, L: float):
    """The horizontal tension [N] of an inextensible catenary line from the tensions at its
    two ends, ``T`` at the fairlead and ``T_anchor`` [N] (two load cells): the vertical load
    at the anchor is ``V_a = ((T^2 - T_a^2) / (w L) - w L) / 2`` where the whole line hangs
    (``V - V_a = w L`` and ``T^2 - T_a^2 = V^2 - V_a^2``), zero where part of it rests on
    the seabed (which carries H to the anchor, Barreiro et al. 2016, §3.1); ``H = sqrt(T_a^2
    - V_a^2)``."""
    T, Ta = np.asarray(T, float), np.asarray(T_anchor, float)
    Va = np.maximum(0.0, 0.5 * ((T**2 - Ta**2) / (w * L) - w * L))
    return np.sqrt(np.maximum(Ta**2 - Va**2, 0.0))


def rig_run(scene) -> dict:
    """Run a test-rig scene (``scenes/catenary-*.toml``: bodies driven along x, catenary
    lines on them, no fluid) by ``cosim run``'s runner; per line (by name) the fairlead's
    horizontal distance from the anchor ``X`` [m], the tensions ``T`` and ``T_anchor`` [N]
    at each sample, the horizontal tension ``H`` [N] from them (:func:`load_cell_H`) and the
    line's state, its recorded points (``x`` horizontal from the anchor, ``z`` over it,
    (samples, points) [m], at arc lengths ``s``); per body its ``offset`` [m] along x from
    the middle of its lines' anchors."""
    from cosim.validations.case_scene import run_once

    bodies = {b.name: b for b in scene.bodies}
    res = run_once(scene)
    lines, anchors = {}, {n: [] for n in bodies}
    for ln in scene.moorings.lines:
        name, site = ln.fairlead.split(".", 1)
        body, moved = bodies[name], res[f"{name}.surge"]
        anchors[name].append(ln.anchor[0])
        X = np.abs(body.pos[0] + body.fairleads[site][0] + moved - ln.anchor[0])
        T, Ta = res[f"{ln.name}.tension"], res[f"{ln.name}.anchor_tension"]
        lines[ln.name] = {"X": X, "T": T, "T_anchor": Ta, "H": load_cell_H(T, Ta, ln.weight, ln.length),
                          "state": np.rint(res[f"{ln.name}.state"]).astype(int),
                          "h": body.pos[-1] + body.fairleads[site][-1] - ln.anchor[-1], "L": ln.length,
                          "w": ln.weight, "s": np.asarray(ln.points),
                          # the points in the line's plane: horizontal distance from the anchor, height over it
                          "x": np.stack([np.abs(res[f"{ln.name}.point{k + 1}_x"] - ln.anchor[0])
                                         for k in range(len(ln.points))], axis=1) if ln.points else None,
                          "z": np.stack([res[f"{ln.name}.point{k + 1}_z"] - ln.anchor[-1]
                                         for k in range(len(ln.points))], axis=1) if ln.points else None}
    offsets = {n: b.pos[0] + res[f"{n}.surge"] - float(np.mean(anchors[n])) for n, b in bodies.items()}
    return {"offsets": offsets, "lines": lines, "samples": len(res.t), "steps": res.summary["steps"]}


def rig_scene(case: str, quick: bool):
    """A rig case's scene: the file as written (full), or sampled 10 times more coarsely (quick)."""
    from cosim.validations import case_scene

    scene = case_scene.load(case)
    return scene.with_values([f"world.sample_every={case_scene.number(10 * scene.world.sample_every)}"]) \
        if quick else scene


def _single_line(case: str, quick: bool, extensions):
    """The rig of ``case`` run: H(X) from its load cells monotone and convex, equal to the
    closed form at every sampled X, the states the run reports changing where the closed
    forms put them; and the law itself: its slope continuous across the lift-off point,
    its state switching exactly there (bisected)."""
    run = rig_run(rig_scene(case, quick))
    ln = next(iter(run["lines"].values()))
    X, H, h, L, w = ln["X"], ln["H"], ln["h"], ln["L"], ln["w"]
    law = solve(X, h, L, w)
    dH = np.diff(H) / np.diff(X)
    x_lift = lift_off_distance(h, L)
    # where does solve() itself switch state? bisect on its reported state
    lo, hi = L - h, taut_distance(h, L)
    a, b = lo, hi
    for _ in range(200):
        m = 0.5 * (a + b)
        if m in (a, b):
            break
        a, b = (m, b) if solve(m, h, L, w).state == PARTLY_LIFTED else (a, m)
    e = 1e-7 * L
    slopes = np.diff(solve(np.array([x_lift - 2 * e, x_lift, x_lift + 2 * e]), h, L, w).H) / (2 * e)
    states = ln["state"]
    changes = [float(X[i + 1]) for i in range(len(X) - 1) if states[i + 1] != states[i]]
    # a change is reported at the first sample past the closed form's boundary
    boundaries = [x for x in (lo, x_lift, hi) if X[0] < x <= X[-1]]
    expected = [float(X[np.searchsorted(X, x)]) for x in boundaries]
    metrics = {
        "X_resting_to_partly_m": lo,
        "X_lift_off_m": x_lift,
        "X_taut_m": hi,
        "X_lift_off_from_solver_m": b,
        "lift_off_rel_err": abs(b - x_lift) / x_lift,
        "sampled_state_changes_at_m": changes,
        "state_changes_where_closed_forms_put_them": changes == expected,
        "monotone": bool(np.all(np.diff(H) > 0)),
        "convex": bool(np.all(np.diff(dH) > 0)),
        "H_vs_closed_form_rel_err": float(np.max(np.abs(H / law.H - 1.0))),
        "states_as_closed_form": bool(np.array_equal(states, np.asarray(law.state, int))),
        "slope_jump_at_lift_off_rel": float(abs(slopes[1] - slopes[0]) / slopes[0]),
        "H_at_extensions_N": {f"{x:g}": float(solve(x, h, L, w).H) for x in extensions},
        "H_range_N": [float(H[0]), float(H[-1])],
        "samples": run["samples"],
        "states_partly_or_fully_lifted": set(int(s) for s in states) <= {int(PARTLY_LIFTED), int(FULLY_LIFTED)},
    }
    return {
        "metrics": metrics,
        "tolerances": {"monotone": True, "convex": True, "lift_off_rel_err": 1e-12, "H_vs_closed_form_rel_err": 1e-9,
                       "states_as_closed_form": True, "state_changes_where_closed_forms_put_them": True,
                       "slope_jump_at_lift_off_rel": 1e-4, "states_partly_or_fully_lifted": True},
        "steps": run["steps"],
    }


_SINGLE_TARGET = "smooth, monotone H(X); state changes reported at the right X"
_SINGLE_QUICK = ("the stated target on 91 fairlead positions of the rig instead of 901: H(X) from its load cells "
                 "monotone, convex and the closed form's to 1e-9, the states the closed form's and changing at the "
                 "first sample past its boundaries; the law's slope continuous across the lift-off point (1e-4), "
                 "its lift-off within 1e-12 of the closed form")


@case("catenary-johanning-2007", "single line of Barreiro et al. 2016, Table 1 (Johanning et al. 2007), X = 5.50-6.40 m",
      target=_SINGLE_TARGET, quick=_SINGLE_QUICK,
      scene=lambda quick: rig_scene("catenary-johanning-2007", quick))
def johanning_2007(quick: bool) -> dict:
    """h = 2.651 m, w = 1.036 N/m, l = 6.98 m, fairlead at the surface (Barreiro et al. 2016, Table 1)."""
    return _single_line("catenary-johanning-2007", quick, (5.735, 6.367))


@case("catenary-johanning-2006", "single line of Barreiro et al. 2016, Table 2 (Johanning et al. 2006), X = 102-140 m",
      target=_SINGLE_TARGET, quick=_SINGLE_QUICK,
      scene=lambda quick: rig_scene("catenary-johanning-2006", quick))
def johanning_2006(quick: bool) -> dict:
    """h = 50 m, w = 918.75 N/m, l = 150 m (Barreiro et al. 2016, Table 2)."""
    return _single_line("catenary-johanning-2006", quick, (103.0, 138.0))


@case("catenary-two-lines", "two opposed lines of Barreiro et al. 2016, Table 3: restoring force odd in the offset",
      target="symmetry to 1e-9. As printed, each line is less than 1 m from taut at rest, so ±15 m offsets need "
             "an elastic line (or other numbers): document what you test",
      quick="the stated target on 31 offsets of the rigs instead of 301: odd symmetry and zero force at rest to "
            "1e-9, restoring and monotone, the printed 75 m line taut at +15 m",
      scene=lambda quick: rig_scene("catenary-two-lines", quick))
def two_lines(quick: bool) -> dict:
    """Barreiro et al. 2016, Table 3: h = 50 m, anchors at x = ±55 m, T_H0 = 50 kN at rest,
    body offsets −15 … +15 m.

    As printed (l = 75 m) each line is taut at X = sqrt(75² − 50²) = 55.90 m, only
    0.90 m beyond its rest position, so a +15 m offset is impossible for an
    inextensible 75 m line. The shortest line that still reaches X = 70 m at
    h = 50 m is sqrt(70² + 50²) = 86.02 m. We test l = 90 m over ±15 m (at
    −15 m the slack line sits exactly on its resting boundary X = l − h = 40 m),
    with w set so that T_H0 = 50 kN at rest, and the printed 75 m line over the
    ±0.85 m its length allows: two rigs of one scene (``scenes/catenary-two-lines.toml``),
    the net force from each line's two load cells (:func:`load_cell_H`).
    """
    run = rig_run(rig_scene("catenary-two-lines", quick))
    out = {}
    tol = {}
    for label, rig, a, b in (("l90", "rig90", "A90", "B90"), ("l75_printed", "rig75", "A75", "B75")):
        A, B = run["lines"][a], run["lines"][b]
        d, HA, HB = run["offsets"][rig], A["H"], B["H"]
        F = HB - HA  # line A pulls towards -x, B towards +x
        rest = int(np.argmin(np.abs(d)))
        F0 = F[rest]
        scale = np.max(np.abs(F))
        sym = float(np.max(np.abs(F + F[::-1])) / scale)
        restoring = bool(np.all(F[d > 1e-9] < 0) and np.all(F[d < -1e-9] > 0))
        monotone = bool(np.all(np.diff(F) < 0))
        L, w = A["L"], A["w"]
        tol |= {f"{label}.odd_symmetry_rel_err": 1e-9, f"{label}.force_at_rest_rel": 1e-9,
                f"{label}.restoring": True, f"{label}.monotone": True}
        out[label] = {
            "L_m": L,
            "w_N_per_m": w,
            "offset_range_m": [float(d[0]), float(d[-1])],
            "offsets": len(d),
            "offsets_symmetric_m": float(np.max(np.abs(d + d[::-1]))),
            "TH0_N": float(HA[rest]),
            "net_force_at_extremes_N": [float(F[0]), float(F[-1])],
            "line_A_H_range_N": [float(HA[0]), float(HA[-1])],
            "line_B_H_range_N": [float(HB[0]), float(HB[-1])],
            "odd_symmetry_rel_err": sym,
            "force_at_rest_N": float(F0),
            "force_at_rest_rel": float(abs(F0) / scale),
            "restoring": restoring,
            "monotone": monotone,
            "X_taut_m": taut_distance(50.0, L),
        }
    out["l75_reach_m"] = taut_distance(50.0, 75.0) - 55.0
    out["shortest_line_for_15m_m"] = math.hypot(70.0, 50.0)
    # the printed line cannot take +15 m: its far line is TAUT there
    out["l75_state_at_plus_15m"] = solve(70.0, 50.0, 75.0, 1.0).state.name
    tol["l75_state_at_plus_15m"] = TAUT.name
    return {"metrics": out, "tolerances": tol, "steps": run["steps"]}
