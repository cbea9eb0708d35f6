"""Property-based tests of the catenary law over wide ranges: w from 1e-6 to
1e5 N/m, EA from 1e2 to 1e15 N, X across all four states."""

import math

import numpy as np
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from moorings.catenary import FULLY_LIFTED, PARTLY_LIFTED, RESTING, TAUT, lift_off_distance, solve, taut_distance

SETTINGS = settings(max_examples=300, deadline=None)

lengths = st.floats(0.1, 5000.0)
depth_ratio = st.floats(0.0, 0.999)
weights = st.floats(1e-6, 1e5)
stiffness = st.one_of(st.none(), st.floats(1e2, 1e15))


def seabed_boundaries(h, L, w, EA):
    """Resting and lift-off X [m] of a line, from the closed forms (module docstring):
    hanging length l_s (1 + w l_s / 2EA) = h; lift-off where tanh(u) = h/L - eps/2."""
    eps = 0.0 if EA is None else w * L / EA
    z = h / L
    ls = 2 * z / (1 + math.sqrt(1 + 2 * eps * z))
    x_rest = (1 - ls) * L if ls <= 1 else -math.inf
    d = z - eps / 2
    if 0 < d < 1:
        Hl = (1 - d * d) / (2 * d)
        x_lift = (Hl * math.asinh(1 / Hl) + eps * Hl) * L
    else:
        x_lift = math.inf
    return x_rest, x_lift


@SETTINGS
@given(L=lengths, hr=depth_ratio, w=weights, EA=stiffness, n=st.integers(20, 80))
def test_H_is_monotone_in_X_and_never_nan(L, hr, w, EA, n):
    h = hr * L
    X = np.linspace(0.0, 1.3 * L, n)
    r = solve(X, h, L, w, EA)
    assert not np.isnan(r.H).any() and not np.isnan(r.V).any() and not np.isnan(r.touchdown).any()
    assert np.all(r.H >= 0) and np.all(r.V >= 0)
    assert np.all((r.touchdown >= 0) & (r.touchdown <= L * (1 + 1e-12)))
    fin = np.isfinite(r.H)  # an inextensible TAUT line has H = inf
    assert np.all(fin[:-1] >= fin[1:])  # ... and only beyond the taut point
    Hf = r.H[fin]
    assert np.all(np.diff(Hf) >= -1e-9 * np.maximum(Hf[1:], w * L))
    if EA is not None:
        assert np.isfinite(r.H).all()  # an elastic line always has a solution
    # states appear in their physical order along X
    order = {int(RESTING): 0, int(PARTLY_LIFTED): 1, int(FULLY_LIFTED): 2, int(TAUT): 3}
    ranks = [order[int(s)] for s in r.state]
    if EA is None:
        assert ranks == sorted(ranks)


@SETTINGS
@given(L=lengths, hr=st.floats(1e-4, 0.999), w=weights, EA=stiffness, which=st.sampled_from(["rest", "lift"]))
def test_continuity_across_the_seabed_boundaries(L, hr, w, EA, which):
    """H, V and touchdown do not jump where the formulas switch: the change across
    the boundary (a 2e-12 relative step) is at most a few times the change over the
    same step just before it. Near taut H is steep (from lift-off to taut can be
    a 1e-7 window), so only a jump relative to the local slope means anything."""
    h = hr * L
    x_rest, x_lift = seabed_boundaries(h, L, w, EA)
    Xb = x_rest if which == "rest" else x_lift
    assume(math.isfinite(Xb) and Xb > 0)
    assume(Xb < taut_distance(h, L) * (1 - 1e-6) or EA is not None)
    lo2, lo, hi = (solve(Xb * (1 + k * 1e-12), h, L, w, EA) for k in (-3, -1, 1))
    assume(math.isfinite(hi.H))
    before, after = (RESTING, PARTLY_LIFTED) if which == "rest" else (PARTLY_LIFTED, FULLY_LIFTED)
    if lo.state != TAUT:
        assert lo.state == before
    if hi.state != TAUT:
        assert hi.state == after
    for q, floor in (("H", w * L), ("V", w * L), ("touchdown", L)):
        a2, a, b = getattr(lo2, q), getattr(lo, q), getattr(hi, q)
        assert abs(b - a) <= 3 * abs(a - a2) + 1e-9 * max(floor, abs(a))


@SETTINGS
@given(L=lengths, hr=st.floats(0.01, 0.99), w=weights, f=st.floats(1e-3, 1.0))
def test_elastic_law_tends_to_the_inextensible_one(L, hr, w, f):
    """The difference shrinks like 1/EA (1000 times stiffer: 1000 times closer;
    asserted 300) down to round-off (1e-10: H -> 0 at the resting point, so start
    1e-3 of the way from it). Near the taut point the geometric stiffness
    amplifies the stretch: at h/L = 0.01 it is still 4e-6 at EA = 1e12 w L."""
    h = hr * L
    # from slack to halfway between lift-off and taut
    X = (L - h) + f * (0.5 * (lift_off_distance(h, L) + taut_distance(h, L)) - (L - h))
    ref = solve(X, h, L, w)
    assume(ref.H > 1e-9 * w * L)  # relative errors need a non-vanishing H
    errs = []
    for k in (9, 12, 15):
        r = solve(X, h, L, w, EA=w * L * 10.0**k)
        errs.append(max(abs(r.H - ref.H) / ref.H, abs(r.V - ref.V) / ref.V))
    for a, b in zip(errs, errs[1:]):
        assert b <= max(a / 300.0, 1e-10)
    assert errs[-1] < 1e-7


@SETTINGS
@given(L=lengths, hr=depth_ratio, w=weights)
def test_inextensible_state_boundaries_are_exact(L, hr, w):
    """At X = L - h: RESTING; at the lift-off point: FULLY_LIFTED with Eq. 37's H;
    at the taut point: TAUT. Where rounding makes boundaries coincide (h/L -> 0
    or 1), the earlier state wins."""
    h = hr * L
    assume(h > 0)
    assert solve(L - h, h, L, w).state == RESTING
    xl, xt = lift_off_distance(h, L), taut_distance(h, L)
    r = solve(xl, h, L, w)
    if L - h < xl < xt:
        assert r.state == FULLY_LIFTED and r.touchdown == 0.0
        assert abs(r.H - w * (L * L - h * h) / (2 * h)) <= 1e-12 * r.H  # Eq. 37, l_s = L
    if xt > L - h:
        assert solve(xt, h, L, w).state == TAUT


@SETTINGS
@given(L=lengths, hr=depth_ratio, w=weights, EA=stiffness, f=st.floats(0.0, 1.2))
@example(L=0.1015625, hr=0.1, w=1.0, EA=None, f=0.9)  # X = L - h: the scaled line rounds to RESTING
def test_scaling_by_w_and_L(L, hr, w, EA, f):
    """H/(w L), V/(w L) and touchdown/L depend only on X/L, h/L and w L/EA."""
    h, X = hr * L, f * L
    a = solve(X, h, L, w, EA)
    b = solve(X * 3.0, h * 3.0, L * 3.0, w * 7.0, None if EA is None else EA * 21.0)
    assume(math.isfinite(a.H))
    if a.state != b.state:
        # X = f L and 3 X = f (3 L) round differently: the scaled line may fall on the
        # other side of a state boundary, but only when X lies on it to within rounding
        x_rest, x_lift = seabed_boundaries(h, L, w, EA)
        x_taut = taut_distance(h, L)
        assert min(abs(X - x_rest), abs(X - x_lift), abs(X - x_taut)) <= 1e-12 * L
        assume(math.isfinite(b.H))
    for u, v in ((a.H, b.H / 21.0), (a.V, b.V / 21.0), (a.touchdown, b.touchdown / 3.0)):
        assert abs(u - v) <= 1e-9 * max(abs(u), w * L, 1e-300) or abs(u - v) <= 1e-9 * L
