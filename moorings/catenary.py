r"""The quasi-static catenary mooring law, inextensible and elastic, with a seabed.

Public entry point: :func:`solve` (``solve(X, h, L, w, EA=None)``), a pure
function of the line geometry; :func:`shape` gives the line's coordinates.

Geometry (Barreiro et al. 2016, Fig. 3): the anchor lies on a flat seabed; the fairlead is at
horizontal distance ``X`` and height ``h`` above it. The line has unstretched
length ``L``, submerged weight ``w`` per unit length and axial stiffness ``EA``
(``None``: inextensible). No current, no seabed friction, no bending stiffness.

States (Barreiro et al. 2016, Fig. 5), along X at fixed h (the boundaries are exact):

- ``RESTING``, ``X <= L - h``: the line hangs straight down, the rest slack on the seabed:
  ``H = 0``, ``V = w h`` (elastic: ``V = w l_s`` with ``l_s (1 + w l_s / 2EA) = h``).
- ``PARTLY_LIFTED``: a catenary from a touchdown point (horizontal tangent); ``touchdown`` > 0.
- ``FULLY_LIFTED``, from (and at) the lift-off point ``X_lift = (L^2 - h^2)/h * atanh(h/L)``
  (inextensible; Eq. 37 with ``l_s = L`` in Eq. 39): the whole line hangs, pulling the anchor up.
- ``TAUT``, ``sqrt(X^2 + h^2) >= L``: an elastic line stretches; an inextensible one has no
  catenary, so :func:`solve` returns ``H = V = inf`` and ``touchdown = 0`` (arrays of lines stay
  solvable; ``H`` near the taut point is ill-conditioned, about 1e-16 / (1 - X/X_taut)). A
  coupled scene holds such a line with a length constraint (statics, not Eq. 40's split);
  alone it raises :class:`~cosim.errors.TautLineError` naming the line.

Method: the inextensible law is Barreiro et al. 2016, Eq. 35-39 (Faltinsen 1993): with
``a = H/w`` (Eq. 34), ``l_s^2 = h^2 + 2 h a`` (Eq. 37), ``X = L - l_s + a acosh(1 + h/a)``
(Eq. 39). The elastic law with seabed contact and no friction is Jonkman's (2007,
NREL/TP-500-41958, §4.1, Eq. 4-1/4-2 with C_B = 0; also MAP++ and MoorPy); both reduce to
Eq. 28-29 and 35-39 as ``EA -> inf``. Each regime is one equation in one unknown, solved by a
bracketed, safeguarded Newton iteration in its logarithm (it cannot diverge; 4-6 evaluations)
in forms that neither overflow nor lose the answer for tiny ``w`` or huge ``EA``. The
equations and their reduction: docs/catenary.md.
"""

from __future__ import annotations

import math
from enum import IntEnum
from typing import NamedTuple

import numba as nb
import numpy as np

from errors import InputError


class LineState(IntEnum):
    """State of a catenary line (Barreiro et al. 2016, Fig. 5 a-d)."""

    RESTING = 0
    PARTLY_LIFTED = 1
    FULLY_LIFTED = 2
    TAUT = 3


RESTING = LineState.RESTING
PARTLY_LIFTED = LineState.PARTLY_LIFTED
FULLY_LIFTED = LineState.FULLY_LIFTED
TAUT = LineState.TAUT
_STATES = tuple(LineState)
_new_tuple = tuple.__new__  # builds a LineSolution without NamedTuple.__new__'s call overhead


class LineSolution(NamedTuple):
    """Result of :func:`solve`; arrays of the broadcast input shape for array input.

    ``state`` is a :class:`LineState` for a scalar call and an integer array of
    :class:`LineState` values otherwise (``res.state == TAUT`` works for both).
    """

    H: float | np.ndarray  #: horizontal tension at the fairlead [N]
    V: float | np.ndarray  #: vertical tension at the fairlead [N]
    touchdown: float | np.ndarray  #: unstretched length lying on the seabed [m]
    state: LineState | np.ndarray


# ---------------------------------------------------------------------------
# compiled core (units of L for lengths, w L for forces, eps = w L / EA)
# ---------------------------------------------------------------------------

_JIT = dict(cache=True, nogil=True, error_model="numpy")
_U_CAP = 350.0  # sinh(350) ~ 1e152: far from overflow, far past any physical angle
_LOG_T_CAP = math.log(700.0)  # sinh(700) ~ 5e303 still finite


@nb.njit(**_JIT)
def _seabed(t, z, eps):
    """Seabed-contact regime at fairlead angle t: returns (X, H, V, dX/dt)."""
    q = math.tanh(0.5 * t)
    S = math.sqrt(q * q + 2.0 * eps * z)
    V = 2.0 * z / (q + S)
    st = math.sinh(t)
    H = V / st
    dV = -V * (1.0 + q / S) / (q + S) * 0.5 * (1.0 - q * q)
    dH = (dV - H * math.cosh(t)) / st
    return 1.0 - V + H * t + eps * H, H, V, -dV + H + (t + eps) * dH


@nb.njit(**_JIT)
def _suspended(u, z, eps):
    """Fully suspended regime at half angle range u: returns (X, H, V, dX/du)."""
    tu = math.tanh(u)
    a = tu + 0.5 * eps
    tau = z * tu / a  # tanh m
    dtau = 0.5 * z * eps * (1.0 - tu * tu) / (a * a)
    c = math.sqrt((1.0 - tau) * (1.0 + tau))
    su = math.sinh(u)
    H = c / (2.0 * su)
    V = 0.5 + 0.5 * z / a
    dH = (-0.5 * tau * dtau / c - H * math.cosh(u)) / su
    return (2.0 * u + eps) * H, H, V, 2.0 * H + (2.0 * u + eps) * dH


@nb.njit(**_JIT)
def _one_minus_sinhc(u):
    """g(u) = 1 - u / sinh(u) and g'(u), without cancellation at small u:
    g = (sinh u - u) / sinh u with sinh u - u summed as its series below 1."""
    if u >= 1.0:
        s = math.sinh(u)
        return (s - u) / s, (u * math.cosh(u) - s) / (s * s)
    u2 = u * u
    term = u * u2 / 6.0  # u^3/3!
    excess = term
    k = 1
    while term > 1e-17 * excess:
        term *= u2 / ((2 * k + 2) * (2 * k + 3))
        excess += term
        k += 1
    s = u + excess
    # u cosh u - sinh u = sum 2k u^(2k+1) / (2k+1)!, the leading terms suffice for Newton
    return excess / s, (u2 * u / 3.0) * (1.0 + u2 / 10.0) / (s * s)


@nb.njit(**_JIT)
def _f(regime, p, z, eps, x):
    """Residual of a regime at e^p and its derivative in p: X(e^p) - x for the
    seabed (0) and suspended (1) regimes; for the inextensible suspended regime
    near taut (2), 1 - u/sinh(u) - x, where x is then the relative gap to taut."""
    t = math.exp(p)
    if regime == 2:
        g, dg = _one_minus_sinhc(t)
        return g - x, dg * t
    X, _, _, dX = _seabed(t, z, eps) if regime == 0 else _suspended(t, z, eps)
    return X - x, dX * t


@nb.njit(**_JIT)
def _newton(regime, a, b, fa, fb, z, eps, x):
    """Safeguarded Newton on a bracket [a, b] with f(a) f(b) <= 0 (log variable p).

    Starts at the regula-falsi point of the bracket; a step that would leave the
    bracket or shrink it too slowly is replaced by bisection, so it cannot
    diverge. If rounding left both ends with the same sign, the root sits at
    the end with the smaller residual: return it (exact to rounding).
    """
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0.0) == (fb > 0.0):
        return a if abs(fa) < abs(fb) else b
    lo, hi = (a, b) if fa < 0.0 else (b, a)  # f(lo) < 0 < f(hi)
    p = a - fa * (b - a) / (fb - fa)
    step = step_old = abs(b - a)
    f, df = _f(regime, p, z, eps, x)
    for _ in range(100):
        if ((p - hi) * df - f) * ((p - lo) * df - f) > 0.0 or abs(2.0 * f) > abs(step_old * df):
            step_old, step = step, 0.5 * (hi - lo)
            p = lo + step
            if p == lo:
                return p
        else:
            step_old, step = step, f / df
            p_prev = p
            p -= step
            if p == p_prev:
                return p
        if abs(step) < 1e-14 * max(1.0, abs(p)):
            return p
        f, df = _f(regime, p, z, eps, x)
        if f < 0.0:
            lo = p
        else:
            hi = p
    return p


@nb.njit(**_JIT)
def _taut_x(h, L):
    """X [m] at which the anchor-fairlead distance equals L."""
    return math.sqrt((L - h) * (L + h)) if h < L else 0.0


@nb.njit(**_JIT)
def _lift_x(h, L):
    """X [m] of the inextensible lift-off point (Barreiro et al. 2016, Eq. 37, 39 with l_s = L)."""
    if h <= 0.0:
        return L
    r = h / L
    return (L - h) * (L + h) / L * (math.atanh(r) / r)


@nb.njit(**_JIT)
def _seabed_root(x, z, eps, d, u_lift):
    """Unknown t of the seabed regime, between lift-off and the resting point.

    X(t) decreases in t; the bracket is walked in unit steps of log t from the
    lift-off angle (or, where there is none, down from where X ~ sqrt(2 z eps)/t
    exceeds x) so that it ends one step wide around the root.
    """
    if d > 0.0:
        a = math.log(2.0 * u_lift)  # the lift-off angle
        fa = _f(0, a, z, eps, x)[0]
    else:
        a = math.log(math.sqrt(2.0 * z * eps) / x) - 1.0
        fa = _f(0, a, z, eps, x)[0]
        while fa < 0.0 and a > -700.0:
            a -= 2.0
            fa = _f(0, a, z, eps, x)[0]
    b = max(a + 1.0, 1.0)
    fb = _f(0, b, z, eps, x)[0]
    while fb > 0.0 and b < _LOG_T_CAP:
        a, fa = b, fb
        b = min(b + 1.0, _LOG_T_CAP)
        fb = _f(0, b, z, eps, x)[0]
    return math.exp(_newton(0, a, b, fa, fb, z, eps, x))


@nb.njit(**_JIT)
def _suspended_root(x, z, eps, u_max):
    """Unknown u of the elastic fully suspended regime, in (0, u_max]; X(u) decreases."""
    b = math.log(u_max)
    fb = _f(1, b, z, eps, x)[0]
    a = min(math.log(0.25 * eps / max(x, 1e-300)), b - 1.0)  # X ~ 1 + eps / 2u there
    fa = _f(1, a, z, eps, x)[0]
    while fa < 0.0 and a > -700.0:
        b, fb = a, fa
        a -= 2.0
        fa = _f(1, a, z, eps, x)[0]
    return math.exp(_newton(1, a, b, fa, fb, z, eps, x))


@nb.njit(**_JIT)
def _taut_gap_root(gap, u_lift):
    """Unknown u of the inextensible fully suspended regime: X = X_taut u/sinh(u),
    i.e. 1 - u/sinh(u) = gap with gap = 1 - X/X_taut > 0 taken from the
    dimensional values, so that even one ulp below taut gives a finite answer."""
    b = math.log(u_lift)
    fb = _f(2, b, 0.0, 0.0, gap)[0]
    a = min(0.5 * math.log(6.0 * gap) - 1.0, b - 1.0)  # 1 - u/sinh(u) ~ u^2/6
    fa = _f(2, a, 0.0, 0.0, gap)[0]
    while fa > 0.0 and a > -700.0:
        b, fb = a, fa
        a -= 2.0
        fa = _f(2, a, 0.0, 0.0, gap)[0]
    return math.exp(_newton(2, a, b, fa, fb, 0.0, 0.0, gap))


@nb.njit(**_JIT)
def _solve_dim(X, h, L, w, EA):
    """One line, inputs already checked. Returns (H, V, touchdown, state).

    State decisions compare dimensional X with the same expressions as
    lift_off_distance() and taut_distance(), so the boundaries are exact.
    """
    inf = math.inf
    # RESTING: straight down, hanging length l_s with l_s (1 + w l_s / 2 EA) = h
    ls = 2.0 * h / (1.0 + math.sqrt(1.0 + 2.0 * w * h / EA))
    if ls <= L and X <= L - ls:
        return 0.0, w * ls, L - ls, 0
    taut = X >= _taut_x(h, L)
    wl = w * L
    eps = wl / EA
    x, z = X / L, h / L
    if eps == 0.0:
        if taut:
            return inf, inf, 0.0, 3
        X_lift = _lift_x(h, L)
        if X == X_lift:  # exactly at lift-off: Eq. 37 with l_s = L
            return w * (L - h) * (L + h) / (2.0 * h), wl, 0.0, 2
        if X < X_lift:
            _, H, V, _ = _seabed(_seabed_root(x, z, 0.0, z, math.atanh(z)), z, 0.0)
            return H * wl, V * wl, max(1.0 - V, 0.0) * L, 1
        X_taut = _taut_x(h, L)
        u = _taut_gap_root((X_taut - X) / X_taut, math.atanh(z))
        _, H, V, _ = _suspended(u, z, 0.0)
        return H * wl, V * wl, 0.0, 2
    if h == 0.0:  # flat on the seabed and stretched
        return EA * (x - 1.0), 0.0, L, 3
    d = z - 0.5 * eps  # tanh of the half angle range at lift-off
    if 0.0 < d < 1.0:
        u_lift = math.atanh(d)
        x_lift = _suspended(u_lift, z, eps)[0]
    else:
        u_lift = _U_CAP
        x_lift = inf if d <= 0.0 else 0.0
    if x < x_lift:
        _, H, V, _ = _seabed(_seabed_root(x, z, eps, d, u_lift), z, eps)
        return H * wl, V * wl, max(1.0 - V, 0.0) * L, (3 if taut else 1)
    if d >= 1.0:  # hangs clear of the seabed at any X; X -> 0 as tanh m -> 1
        u_max = min(math.atanh(min(0.5 * eps / (z - 1.0), 1.0)), _U_CAP)
    else:
        u_max = u_lift
    _, H, V, _ = _suspended(_suspended_root(x, z, eps, u_max), z, eps)
    return H * wl, V * wl, 0.0, (3 if taut else 2)


@nb.njit(**_JIT)
def _check(X, h, L, w, EA):
    """0 if the inputs are valid, else the number of the first bad parameter."""
    if not (math.isfinite(X) and X >= 0.0):
        return 1
    if not (math.isfinite(h) and h >= 0.0):
        return 2
    if not (math.isfinite(L) and L > 0.0):
        return 3
    if not (math.isfinite(w) and w > 0.0):
        return 4
    if not (EA > 0.0):  # inf is allowed: inextensible
        return 5
    return 0


@nb.njit("Tuple((f8, f8, f8, i8, i8))(f8, f8, f8, f8, f8)", **_JIT)
def _solve_scalar(X, h, L, w, EA):
    err = _check(X, h, L, w, EA)
    if err:
        return 0.0, 0.0, 0.0, 0, err
    H, V, td, state = _solve_dim(X, h, L, w, EA)
    return H, V, td, state, 0


@nb.njit(parallel=True, **_JIT)
def _solve_batch(X, h, L, w, EA, H, V, td, state):
    for i in nb.prange(X.size):
        H[i], V[i], td[i], state[i] = _solve_dim(X[i], h[i], L[i], w[i], EA[i])


@nb.njit(**_JIT)
def _solve_batch_serial(X, h, L, w, EA, H, V, td, state):
    for i in range(X.size):
        H[i], V[i], td[i], state[i] = _solve_dim(X[i], h[i], L[i], w[i], EA[i])


# below this many lines, waking the thread pool costs more than it saves
_PARALLEL_MIN = 512


#: TAUT as the plain integer the compiled laws return
_TAUT_CODE = int(LineState.TAUT)


@nb.njit(**_JIT)
def solve_fairleads(pos, anchors, L, w, EA, capped_slack, out, forces):
    """The law for fairleads at ``pos`` (r n, dim) [m] of ``n`` lines anchored at
    ``anchors`` (n, dim) [m] (``pos`` may stack r sets of the lines' fairleads; the seabed
    the horizontal plane through each anchor): ``out[i] = (H, V, touchdown, state)`` and
    the force on the fairlead ``forces[i]`` (dim) [N], ``H`` along the fairlead→anchor
    direction, ``V`` downwards. ``capped_slack`` > 0: an inextensible line whose chord is
    beyond ``L (1 - capped_slack)`` is solved where its slack is that, its state TAUT (a
    tethered line: its length constraint carries the rest); 0: none. No checks: for a
    mooring inside a coupling loop that validated its lines and fairleads once."""
    n, dim = anchors.shape[0], pos.shape[1]
    for i in range(pos.shape[0]):
        j = i % n
        X2 = 0.0
        for k in range(dim - 1):
            X2 += (pos[i, k] - anchors[j, k]) ** 2
        X = math.sqrt(X2)
        h = pos[i, dim - 1] - anchors[j, dim - 1]
        scale = 1.0
        capped = False
        if capped_slack > 0.0 and math.isinf(EA[j]):
            chord = math.hypot(X, h)
            if chord > L[j] * (1.0 - capped_slack):
                capped = True
                scale = L[j] * (1.0 - capped_slack) / chord
        H, V, td, state = _solve_dim(X * scale, h * scale, L[j], w[j], EA[j])
        out[i, 0], out[i, 1], out[i, 2], out[i, 3] = H, V, td, _TAUT_CODE if capped else state
        for k in range(dim - 1):
            forces[i, k] = -H * ((pos[i, k] - anchors[j, k]) / X) if X > 0.0 else -H * 0.0
        forces[i, dim - 1] = -V


# ---------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------

_PARAMS = (
    None,
    ("X", "m", "the horizontal anchor-fairlead distance must be finite and >= 0"),
    ("h", "m", "the fairlead must not be below the seabed (h >= 0, finite)"),
    ("L", "m", "the unstretched length must be finite and > 0"),
    ("w", "N/m", "the submerged weight per unit length must be finite and > 0 (buoyant lines are not supported)"),
    ("EA", "N", "the axial stiffness must be > 0; use EA=None for an inextensible line"),
)


def _input_error(code: int, value, where: str) -> InputError:
    name, unit, why = _PARAMS[code]
    return InputError(f"{where}: {name} = {value!r} {unit}; {why}")


def solve(X, h, L, w, EA=None) -> LineSolution:
    """Solve the quasi-static catenary of one line or of an array of lines.

    Parameters
    ----------
    X : float or array_like
        Horizontal anchor–fairlead distance [m], >= 0.
    h : float or array_like
        Fairlead height above the anchor and seabed [m], >= 0.
    L : float or array_like
        Unstretched line length [m], > 0.
    w : float or array_like
        Submerged weight per unit length [N/m], > 0.
    EA : float, array_like or None
        Axial stiffness [N], > 0; ``None`` (or ``inf``) for an inextensible line
        (Barreiro et al. 2016, Eq. 35-39), otherwise the elastic catenary with seabed contact
        and no friction (see the module docstring).

    Returns
    -------
    LineSolution
        ``H`` and ``V`` [N], the horizontal and vertical tension at the fairlead
        (the line pulls the fairlead towards the anchor with ``H`` and down with
        ``V``); ``touchdown`` [m], the unstretched length lying on the seabed;
        ``state``, a :class:`LineState`. An inextensible line asked to span more
        than its length is ``TAUT`` with ``H = V = inf`` (no solution exists;
        this function does not raise for it). Arrays broadcast together and are
        solved in one compiled, parallel call.

    Raises
    ------
    cosim.errors.InputError
        For NaN, negative or zero inputs, naming the parameter (and the index
        of the first bad line for arrays), before anything is solved.
    """
    try:  # the scalar fast path: the compiled signature rejects anything but numbers
        H, V, td, state, err = _solve_scalar(X, h, L, w, math.inf if EA is None else EA)
    except TypeError:
        return _solve_array(X, h, L, w, EA)
    if err:
        raise _input_error(err, (X, h, L, w, EA)[err - 1], "catenary line")
    return _new_tuple(LineSolution, (H, V, td, _STATES[state]))


def _solve_array(X, h, L, w, EA) -> LineSolution:
    try:
        arrays = np.broadcast_arrays(
            *(np.asarray(a, dtype=float) for a in (X, h, L, w, math.inf if EA is None else EA))
        )
    except (TypeError, ValueError) as exc:
        raise InputError(f"catenary: X, h, L, w and EA must be numbers or arrays that broadcast together ({exc})")
    shape = arrays[0].shape
    flat = [np.ascontiguousarray(a).ravel() for a in arrays]
    bad = _first_bad(*flat)
    if bad is not None:
        i, code = bad
        idx = np.unravel_index(i, shape) if shape else ()
        where = f"catenary line {idx[0] if len(idx) == 1 else idx}"
        raise _input_error(code, float(flat[code - 1][i]), where)
    n = flat[0].size
    H, V, td = np.empty(n), np.empty(n), np.empty(n)
    state = np.empty(n, dtype=np.int64)
    if n:
        (_solve_batch if n >= _PARALLEL_MIN else _solve_batch_serial)(*flat, H, V, td, state)
    state = state.astype(np.int8)
    if not shape:
        return LineSolution(float(H[0]), float(V[0]), float(td[0]), _STATES[state[0]])
    return LineSolution(H.reshape(shape), V.reshape(shape), td.reshape(shape), state.reshape(shape))


def _first_bad(X, h, L, w, EA):
    checks = (
        ~(np.isfinite(X) & (X >= 0)),
        ~(np.isfinite(h) & (h >= 0)),
        ~(np.isfinite(L) & (L > 0)),
        ~(np.isfinite(w) & (w > 0)),
        ~(EA > 0),
    )
    firsts = [(int(np.argmax(c)), k + 1) for k, c in enumerate(checks) if c.any()]
    return min(firsts) if firsts else None


def lift_off_distance(h: float, L: float) -> float:
    """X [m] at which an inextensible line lifts off entirely (Barreiro et al. 2016, Eq. 37, 39
    with ``l_s = L``): ``(L^2 - h^2)/h * atanh(h/L)``; ``L`` when ``h = 0``.
    :func:`solve` returns ``FULLY_LIFTED`` exactly here."""
    return _lift_x(float(h), float(L))


def taut_distance(h: float, L: float) -> float:
    """X [m] at which an inextensible line becomes a straight bar: ``sqrt(L^2 - h^2)``.
    :func:`solve` returns ``TAUT`` exactly here."""
    return _taut_x(float(h), float(L))


def shape(X: float, h: float, L: float, w: float, EA: float | None = None, n: int = 101, s=None):
    """Coordinates of the line, anchor to fairlead, at ``n`` points evenly spaced
    in unstretched arc length (or at the arc lengths ``s`` [m] from the anchor, within
    0 .. L): returns ``(s, x, z)`` [m] with the anchor at (0, 0). Raises
    :class:`~cosim.errors.TautLineError` for a taut inextensible line.
    A resting line (``X <= L - h``) hangs vertically below the fairlead and lies on the
    seabed from the anchor to below the fairlead, its slack spread evenly along the bed
    (points closer than their arc length: no tension).

    Uses the closed-form profile of the solved line (Barreiro et al. 2016, Eq. 28-29 on the
    suspended part; Jonkman 2007 Eq. 4-3/4-4 with the elastic terms).
    """
    from errors import TautLineError

    sol = solve(float(X), float(h), float(L), float(w), EA)
    if math.isinf(sol.H):
        raise TautLineError(
            f"an inextensible line of length {L} m cannot span X = {X} m, h = {h} m "
            f"(distance {math.hypot(X, h):.6g} m): no catenary shape exists"
        )
    ea = math.inf if EA is None else float(EA)
    s = np.linspace(0.0, L, n) if s is None else np.clip(np.asarray(s, float), 0.0, L)
    H, Va = sol.H, sol.V - w * L  # Va < 0: part of the line lies on the seabed
    lb = sol.touchdown
    on_bed = s <= lb
    sus = np.clip(s - lb, 0.0, None)  # arc length along the suspended part
    V0 = max(Va, 0.0)
    Vs = V0 + w * sus
    x = np.where(on_bed, s * (1.0 + H / ea), lb * (1.0 + H / ea))
    z = np.zeros_like(s)
    if H > 0.0:
        x = x + (H / w) * (np.arcsinh(Vs / H) - np.arcsinh(V0 / H)) + H * sus / ea
        z = (np.hypot(H, Vs) - math.hypot(H, V0)) / w + (V0 * sus + 0.5 * w * sus**2) / ea
    else:  # resting: the hanging part is vertical, above the fairlead's X
        z = sus + 0.5 * w * sus**2 / ea
        # the bed part (length lb >= X, no tension) is slack: its particles are spread
        # evenly over [0, X] (a line resting with its excess bunched along the bed), so
        # the drawn line ends at the fairlead (before, the hanging part stood at x = lb)
        x = np.where(on_bed, s * (X / lb if lb > 0 else 0.0), float(X))
    return s, x, z


__all__ = [
    "solve_fairleads",
    "FULLY_LIFTED",
    "PARTLY_LIFTED",
    "RESTING",
    "TAUT",
    "LineSolution",
    "LineState",
    "lift_off_distance",
    "shape",
    "solve",
    "taut_distance",
]
