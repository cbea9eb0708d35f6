"""The catenary law: closed forms of Barreiro et al. 2016, an independent high-precision
oracle for the elastic law, state boundaries, extremes and bad input."""

import math

import mpmath as mp
import numpy as np
import pytest

from cosim import refdata
from cosim.errors import InputError, TautLineError
from moorings.catenary import (
    FULLY_LIFTED,
    PARTLY_LIFTED,
    RESTING,
    TAUT,
    LineState,
    lift_off_distance,
    shape,
    solve,
    taut_distance,
)

# Barreiro et al. 2016, Table 1 (Johanning et al. 2007)
H1, W1, L1 = 2.651, 1.036, 6.98


def rel(a, b):
    return abs(a - b) / abs(b)


# --- closed forms (Barreiro et al. 2016, §3.1) --------------------------------------------


def test_resting_line_hangs_straight_down():
    r = solve(3.0, H1, L1, W1)
    assert r.state is RESTING
    assert r.H == 0.0
    assert rel(r.V, W1 * H1) < 1e-15
    assert rel(r.touchdown, L1 - H1) < 1e-15


def test_partly_lifted_line_obeys_eq37_and_eq39():
    for X in (4.5, 5.5, 6.0, 6.28):
        r = solve(X, H1, L1, W1)
        assert r.state is PARTLY_LIFTED
        a, ls = r.H / W1, r.V / W1  # Eq. 34; the lifted length carries V = w l_s (Eq. 33)
        assert rel(ls**2, H1**2 + 2 * H1 * a) < 1e-12  # Eq. 37
        X39 = L1 - H1 * math.sqrt(1 + 2 * a / H1) + a * math.acosh(1 + H1 / a)  # Eq. 39
        assert rel(X39, X) < 1e-12
        assert rel(r.touchdown, L1 - ls) < 1e-12  # Eq. 38


def test_lift_off_point_closed_form():
    x_lift = lift_off_distance(H1, L1)
    a = (L1**2 - H1**2) / (2 * H1)  # Eq. 37 with l_s = L
    assert rel(x_lift, a * math.acosh(1 + H1 / a)) < 1e-14  # Eq. 35-36: X = x
    r = solve(x_lift, H1, L1, W1)
    assert r.state is FULLY_LIFTED and r.touchdown == 0.0
    assert rel(r.H, W1 * a) < 1e-12
    assert rel(r.V, W1 * L1) < 1e-12


def test_fully_lifted_line_matches_two_point_catenary():
    """Beyond lift-off both ends hang: check against the textbook two-point
    catenary, L^2 - h^2 = (2 a sinh(X / 2a))^2, independently solved in mpmath."""
    X = 0.5 * (lift_off_distance(H1, L1) + taut_distance(H1, L1))
    r = solve(X, H1, L1, W1)
    assert r.state is FULLY_LIFTED
    mp.mp.dps = 30
    a = mp.findroot(lambda a: (2 * a * mp.sinh(X / (2 * a))) ** 2 - (L1**2 - H1**2), r.H / W1 * 1.1)
    assert rel(r.H, float(a) * W1) < 1e-12
    # vertical: fairlead angle from the catenary through both ends
    xm = float(a * mp.asinh(H1 / (2 * a * mp.sinh(X / (2 * a))))) + X / 2  # vertex -> fairlead
    assert rel(r.V, r.H * math.sinh(xm / float(a))) < 1e-10
    assert r.V > W1 * L1  # the anchor is pulled up


def test_shape_satisfies_eq29_and_ends_at_fairlead():
    X = 5.8
    r = solve(X, H1, L1, W1)
    s, x, z = shape(X, H1, L1, W1, n=201)
    assert (x[0], z[0]) == (0.0, 0.0)
    assert math.hypot(x[-1] - X, z[-1] - H1) < 1e-12
    sus = s >= r.touchdown
    a = r.H / W1
    xr = x[sus] - r.touchdown
    np.testing.assert_allclose(z[sus], a * (np.cosh(xr / a) - 1), rtol=0, atol=1e-12)  # Eq. 29
    assert np.all(z[~sus] == 0)
    # arc length of the drawn curve equals the line length (inextensible)
    fine = shape(X, H1, L1, W1, n=20001)
    assert rel(np.sum(np.hypot(np.diff(fine[1]), np.diff(fine[2]))), L1) < 1e-7


def test_shape_of_elastic_suspended_line_ends_at_fairlead():
    s, x, z = shape(6.6, H1, L1, W1, EA=50.0)
    assert math.hypot(x[-1] - 6.6, z[-1] - H1) < 1e-10
    with pytest.raises(TautLineError, match="cannot span"):
        shape(7.0, H1, L1, W1)


# --- the elastic law against an independent oracle ---------------------------


def elastic_oracle(X, h, L, w, EA, guess):
    """Jonkman (2007) Eq. 4-1/4-2 (C_B = 0), solved in 40-digit arithmetic."""
    mp.mp.dps = 40
    X, h, L, w, EA = (mp.mpf(v) for v in (X, h, L, w, EA))

    def seabed(H, V):
        return [
            L - V / w + H / w * mp.asinh(V / H) + H * L / EA - X,
            H / w * (mp.sqrt(1 + (V / H) ** 2) - 1) + V**2 / (2 * EA * w) - h,
        ]

    def suspended(H, V):
        Va = V - w * L
        return [
            H / w * (mp.asinh(V / H) - mp.asinh(Va / H)) + H * L / EA - X,
            H / w * (mp.sqrt(1 + (V / H) ** 2) - mp.sqrt(1 + (Va / H) ** 2)) + (V * L - w * L**2 / 2) / EA - h,
        ]

    H0, V0 = (mp.mpf(g) * mp.mpf("1.001") for g in guess)
    f = seabed if V0 < w * L else suspended
    H, V = mp.findroot(f, (H0, V0))
    return float(H), float(V)


@pytest.mark.parametrize(
    "X, h, EA",
    [
        (5.0, H1, 30.0),  # on the seabed
        (6.3, H1, 200.0),
        (6.0, H1, 1e6),
        (5.5, H1, 2.0),  # very soft: never lifts off
        (9.0, H1, 2.0),  # ... even stretched 30 % beyond its length
        (6.6, H1, 50.0),  # taut but still touching the seabed
        (6.6, H1, 1e3),  # fully suspended
        (7.0, H1, 1e3),  # suspended and stretched
        (6.45, H1, 1e9),  # stiff, near the inextensible taut point
        (1.0, 8.0, 100.0),  # fairlead higher than the line is long
    ],
)
def test_elastic_law_matches_high_precision_oracle(X, h, EA):
    r = solve(X, h, L1, W1, EA)
    assert r.state is not RESTING
    H, V = elastic_oracle(X, h, L1, W1, EA, (r.H, r.V))
    assert rel(r.H, H) < 1e-11
    assert rel(r.V, V) < 1e-11
    if r.state in (PARTLY_LIFTED,):
        assert rel(r.touchdown, L1 - r.V / W1) < 1e-12


def test_moorpy_regression_vector():
    """MoorPy's frictionless (CB = 0) vector of the refdata file: agreement to MoorPy's
    own solver tolerance (~3e-7; our answer matches a 40-digit solve to 1e-14)."""
    text = refdata.path("cable_static_dynamic", "moorpy_catenary_test_vectors.csv").read_text().splitlines()
    rows = np.genfromtxt([ln for ln in text if not ln.startswith("#")], delimiter=",", names=True)
    row = rows[(rows["CB"] == 0.0)][0]
    r = solve(row["x"], row["z"], row["L"], row["w"], row["EA"])
    assert rel(r.H, -row["fBH"]) < 1e-6
    assert rel(r.V, -row["fBV"]) < 1e-6
    assert rel(r.touchdown, row["LBot"]) < 1e-6
    H, V = elastic_oracle(row["x"], row["z"], row["L"], row["w"], row["EA"], (r.H, r.V))
    assert rel(r.H, H) < 1e-12 and rel(r.V, V) < 1e-12


def test_elastic_resting_line_stretches_under_its_own_weight():
    EA = 40.0
    r = solve(1.0, H1, L1, W1, EA)
    ls = r.V / W1
    assert r.state is RESTING and r.H == 0.0
    assert rel(ls + W1 * ls**2 / (2 * EA), H1) < 1e-14  # hanging part stretched to h
    assert rel(r.touchdown, L1 - ls) < 1e-14


def test_elastic_taut_line_is_solved_and_flagged():
    r = solve(7.2, H1, L1, W1, EA=1e4)
    assert r.state is TAUT and math.isfinite(r.H) and r.H > 0
    # a straight bar's axial strain estimate: T ~ EA (chord / L - 1)
    chord = math.hypot(7.2, H1)
    assert rel(math.hypot(r.H, r.V - W1 * L1 / 2), 1e4 * (chord / L1 - 1)) < 0.02


# --- state boundaries, exactly and within 1e-12 -------------------------------


def test_exact_state_boundaries():
    assert solve(L1 - H1, H1, L1, W1).state is RESTING
    assert solve(lift_off_distance(H1, L1), H1, L1, W1).state is FULLY_LIFTED
    r = solve(taut_distance(H1, L1), H1, L1, W1)
    assert r.state is TAUT and r.H == math.inf and r.V == math.inf and r.touchdown == 0.0


@pytest.mark.parametrize("EA", [None, 1e3, 1e9])
def test_continuity_within_1e12_of_the_boundaries(EA):
    eps = 1e-12
    for X in (L1 - H1, lift_off_distance(H1, L1)):
        a = solve(X * (1 - eps), H1, L1, W1, EA)
        b = solve(X * (1 + eps), H1, L1, W1, EA)
        scale = W1 * L1
        assert abs(a.H - b.H) < 1e-6 * scale
        assert abs(a.V - b.V) < 1e-6 * scale
        assert abs(a.touchdown - b.touchdown) < 1e-6 * L1


def test_states_on_either_side_of_the_boundaries():
    eps = 1e-12
    xl, xt = lift_off_distance(H1, L1), taut_distance(H1, L1)
    assert solve((L1 - H1) * (1 + eps), H1, L1, W1).state is PARTLY_LIFTED
    assert solve(xl * (1 - eps), H1, L1, W1).state is PARTLY_LIFTED
    assert solve(xt * (1 - eps), H1, L1, W1).state is FULLY_LIFTED
    just_below = solve(xt * (1 - eps), H1, L1, W1)
    assert math.isfinite(just_below.H) and just_below.H > 1e4 * W1 * L1  # tension -> inf at taut
    assert solve(xt * (1 + eps), H1, L1, W1).state is TAUT


@pytest.mark.parametrize("h, L", [(H1, L1), (9.0, 10.0), (50.0, 150.0), (1e-3, 1.0), (0.999, 1.0)])
def test_one_ulp_below_taut_is_finite_and_steep(h, L):
    """Regression: the relative gap to taut is taken from dimensional values, so
    even the last double below the taut point gives a finite, huge tension
    (~ w X sqrt(X / (24 gap)) from the flat-catenary expansion) and no NaN."""
    xt = taut_distance(h, L)
    prev = 0.0
    for X in (xt * (1 - 1e-8), xt * (1 - 1e-11), xt * (1 - 1e-14), float(np.nextafter(xt, 0))):
        r = solve(X, h, L, W1)
        assert r.state is FULLY_LIFTED and math.isfinite(r.H) and math.isfinite(r.V)
        assert r.H > prev
        prev = r.H
    assert prev > 1e5 * W1 * L


def test_h_to_zero_and_L_to_h():
    # fairlead on the seabed: flat line, slack up to X = L then taut
    r = solve(L1, 0.0, L1, W1)
    assert r.state is RESTING and r.H == 0.0 and r.V == 0.0 and r.touchdown == L1
    assert solve(L1 * (1 + 1e-12), 0.0, L1, W1).state is TAUT
    r = solve(L1 * 1.01, 0.0, L1, W1, EA=1e5)  # elastic: stretched along the seabed
    assert r.state is TAUT and rel(r.H, 1e5 * 0.01) < 1e-12 and r.V == 0.0
    for h in (1e-6, 1e-9, 1e-12):
        r = solve(L1 - 0.5 * h, h, L1, W1)  # between resting and lift-off
        assert r.state in (PARTLY_LIFTED, FULLY_LIFTED) and np.isfinite([r.H, r.V]).all()
    # L -> h: a line exactly as long as the depth hangs straight at X = 0 ...
    r = solve(0.0, L1, L1, W1)
    assert r.state is RESTING and rel(r.V, W1 * L1) < 1e-15 and r.touchdown == 0.0
    # ... and is taut for any offset
    assert solve(1e-9, L1, L1, W1).state is TAUT
    r = solve(1e-3, L1 * (1 - 1e-12), L1, W1)
    assert r.state is TAUT


# --- arrays -----------------------------------------------------------------


def test_arrays_broadcast_and_equal_scalar_calls():
    X = np.linspace(0, 8, 33)
    for EA in (None, 100.0):
        r = solve(X, H1, L1, W1, EA)
        assert r.H.shape == X.shape and r.state.dtype == np.int8
        for i in (0, 10, 20, 27, 32):
            s = solve(float(X[i]), H1, L1, W1, EA)
            assert (r.H[i], r.V[i], r.touchdown[i]) == (s.H, s.V, s.touchdown)
            assert LineState(r.state[i]) is s.state
    r = solve(np.full((2, 3), 5.0), H1, np.array([6.98, 7.5, 8.0]), W1, np.array([np.inf, 1e3, 1e4]))
    assert r.H.shape == (2, 3)
    assert solve(5.0, H1, L1, W1, np.inf) == solve(5.0, H1, L1, W1)


def test_zero_d_array_and_numpy_scalars():
    a = solve(np.float64(5.5), np.float64(H1), L1, W1)
    b = solve(np.array(5.5), H1, L1, W1)
    c = solve(6, 2, 7, 1)  # ints
    assert a == b and c.state is PARTLY_LIFTED


# --- bad input ----------------------------------------------------------------


@pytest.mark.parametrize(
    "args, match",
    [
        ((-1.0, H1, L1, W1), "X = -1.0 m"),
        ((math.nan, H1, L1, W1), "X = nan"),
        ((5.0, -0.1, L1, W1), "h = -0.1 m.*below the seabed"),
        ((5.0, H1, 0.0, W1), "L = 0.0 m"),
        ((5.0, H1, -2.0, W1), "L = -2.0"),
        ((5.0, H1, L1, 0.0), "w = 0.0 N/m"),
        ((5.0, H1, L1, math.inf), "w = inf"),
        ((5.0, H1, L1, W1, 0.0), "EA = 0.0 N.*EA=None"),
        ((5.0, H1, L1, W1, math.nan), "EA = nan"),
    ],
)
def test_bad_input_names_the_parameter(args, match):
    with pytest.raises(InputError, match=match):
        solve(*args)


def test_bad_input_in_arrays_names_the_line():
    L = np.array([6.0, 7.0, -1.0, 8.0])
    with pytest.raises(InputError, match=r"catenary line 2: L = -1.0 m"):
        solve(5.0, H1, L, W1)
    with pytest.raises(InputError, match="broadcast"):
        solve(np.ones(3), H1, np.ones(4), W1)


def test_shape_of_a_resting_line_ends_at_the_fairlead():
    """X <= L - h: the line hangs vertically below the fairlead and its slack lies on the
    bed between anchor and fairlead (the hanging part used to stand at x = L - h, beyond
    the fairlead, which started an SPH cable with its last segment stretched 45 %)."""
    X, h, L, w = 0.6, 0.25, 0.9, 5.0
    for EA in (None, 1e5):
        r = solve(X, h, L, w, EA)
        assert r.state == RESTING
        s, x, z = shape(X, h, L, w, EA, n=20)
        assert math.hypot(x[-1] - X, z[-1] - h) < 1e-12 and (x[0], z[0]) == (0.0, 0.0)
        hanging = s > r.touchdown
        assert np.all(x[hanging] == X) and np.all(z[~hanging] == 0.0)
        assert np.all(np.diff(x) >= 0) and np.all(np.diff(x[~hanging]) < np.diff(s[~hanging]))  # slack on the bed
        np.testing.assert_allclose(np.diff(z[hanging]), np.diff(s[hanging]), rtol=1e-4)  # hanging at its length


@pytest.mark.parametrize("dim", [2, 3])
def test_the_fairleads_law_is_solve_along_each_line(dim):
    """``solve_fairleads`` (the mooring's compiled law over stacked sets of fairleads) gives
    per line what ``solve`` gives for its span and height, the force along the fairlead's
    horizontal direction to the anchor and down; a tethered inextensible line beyond its
    slack is solved at the slack's geometry and flagged TAUT."""
    from moorings.catenary import solve_fairleads

    rng = np.random.default_rng(7)
    anchors = rng.uniform(-10, 10, size=(3, dim))
    L, w, EA = np.array([12.0, 15.0, 9.0]), np.array([1.0, 2.5, 0.7]), np.array([math.inf, 4e4, math.inf])
    pos = np.tile(anchors, (4, 1)) + rng.uniform(0.5, 7.0, size=(12, dim))
    out, forces = np.empty((12, 4)), np.empty((12, dim))
    solve_fairleads(pos, anchors, L, w, EA, 0.0, out, forces)
    for i in range(12):
        j = i % 3
        d = pos[i] - anchors[j]
        X = float(np.linalg.norm(d[:-1]))
        ref = solve(X, d[-1], L[j], w[j], None if math.isinf(EA[j]) else EA[j])
        assert tuple(out[i]) == (ref.H, ref.V, ref.touchdown, int(ref.state))
        np.testing.assert_array_equal(forces[i], np.append(-ref.H * (d[:-1] / X), -ref.V))
    far = anchors[0] + np.append(np.full(dim - 1, 11.99 / math.sqrt(dim - 1)), 0.1)[None, :]
    solve_fairleads(far, anchors[:1], L[:1], w[:1], EA[:1], 1e-3, out[:1], forces[:1])
    chord = math.hypot(11.99, 0.1)
    ref = solve(11.99 * 0.999 * 12.0 / chord, 0.1 * 0.999 * 12.0 / chord, 12.0, 1.0)
    assert out[0, 0] == pytest.approx(ref.H, rel=1e-12) and out[0, 3] == int(TAUT)
