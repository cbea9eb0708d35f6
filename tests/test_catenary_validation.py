"""The catenary validation cases, quick variants (the fast tier runs them all)."""

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
