"""The catenary validation cases, quick variants (the fast tier runs them all)."""

import numpy as np
import pytest

from cosim.validation import run


def test_catenary_limits_quick():
    r = run("catenary-limits", quick=True)
    assert r["passed"]
    assert max(v for k, v in r["metrics"].items() if k.startswith("max_rel_err")) < 1e-10


@pytest.mark.parametrize("name, x_lift", [("catenary-johanning-2007", 6.2881002), ("catenary-johanning-2006", 138.629436)])
def test_johanning_lines_quick(name, x_lift):
    r = run(name, quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert m["monotone"] and m["convex"]
    assert m["X_lift_off_m"] == pytest.approx(x_lift, rel=1e-7)
    assert m["lift_off_rel_err"] < 1e-12


def test_two_lines_quick():
    r = run("catenary-two-lines", quick=True)
    m = r["metrics"]
    assert r["passed"], m
    assert m["l90"]["odd_symmetry_rel_err"] < 1e-9 and m["l90"]["TH0_N"] == pytest.approx(50e3, rel=1e-12)
    assert m["l75_reach_m"] == pytest.approx(0.9017, abs=1e-4)  # the printed line: taut 0.90 m from rest
    assert m["l75_state_at_plus_15m"] == "TAUT"


@pytest.mark.parametrize("name", ["catenary-johanning-2007", "catenary-johanning-2006"])
def test_the_rig_s_line_is_the_law_at_every_sampled_fairlead_position(name):
    """The case runs its scene (a driven rig, the line on it): H from its two load cells is
    the closed form's at every sample, the states are, and they change at the first sample
    past the lift-off point."""
    from cosim.validations.catenary import rig_scene

    m = run(name, quick=True)["metrics"]
    assert m["samples"] == 91 and m["H_vs_closed_form_rel_err"] < 1e-12 and m["states_as_closed_form"]
    (x,) = m["sampled_state_changes_at_m"]
    spacing = np.diff(rig_scene(name, True).bodies[0].motion.points, axis=0)[0, 1] / 90
    assert 0.0 <= x - m["X_lift_off_m"] < spacing


def test_load_cells_give_the_horizontal_tension_of_a_resting_or_hanging_line():
    """H from the fairlead and anchor tensions (load_cell_H) against the law's own H, from a
    line resting on the seabed to one lifted whole (Barreiro et al. 2016, Eq. 35-39)."""
    from cosim.validations.catenary import load_cell_H
    from moorings.catenary import lift_off_distance, solve, taut_distance

    h, L, w = 50.0, 150.0, 918.75
    X = np.linspace(L - h + 1.0, taut_distance(h, L) - 1e-3, 200)
    r = solve(X, h, L, w)
    T, Ta = np.hypot(r.H, r.V), np.hypot(r.H, np.maximum(r.V - w * L, 0.0))
    assert (X > lift_off_distance(h, L)).any() and (X < lift_off_distance(h, L)).any()
    assert np.allclose(load_cell_H(T, Ta, w, L), r.H, rtol=1e-10, atol=0.0)
