"""Speed of the catenary law: microseconds per scalar call from Python, and
line-solves per second for a batch of 100 000 lines, against a straightforward
scipy ``brentq`` implementation of the same law measured in the same run.

    python benchmarks/catenary.py

Prints figures; asserts nothing about time. Compilation (or loading the numba
cache) is reported apart from run time.
"""

from __future__ import annotations

import math
import os
import platform
import time

import numba
import numpy as np
from scipy.optimize import brentq

# Barreiro et al. 2016, Table 1 line, at a partly lifted and a fully lifted X
L, W, H_FAIR = 6.98, 1.036, 2.651
CASES = [("partly lifted", 5.8), ("fully lifted", 6.4)]
EA = 1e4


# --- a straightforward scipy implementation of the same law -------------------


def brentq_inextensible(X, h, L, w):
    """Barreiro et al. 2016, Eq. 39 solved for a = H/w with brentq (partly lifted), or the
    two-point catenary (L^2 - h^2 = (2a sinh(X/2a))^2) beyond lift-off."""
    if X <= L - h:
        return 0.0, w * h
    a_lift = (L * L - h * h) / (2 * h)
    x_lift = a_lift * math.acosh(1 + h / a_lift)
    if X < x_lift:
        f = lambda a: L - h * math.sqrt(1 + 2 * a / h) + a * math.acosh(1 + h / a) - X  # noqa: E731
        a = brentq(f, 1e-12 * L, a_lift, xtol=1e-14, rtol=1e-14)
        return w * a, w * math.sqrt(h * h + 2 * h * a)
    g = lambda a: 2 * a * math.sinh(X / (2 * a)) - math.sqrt(L * L - h * h)  # noqa: E731
    a = brentq(g, a_lift * 0.999, 1e6 * a_lift, xtol=1e-14, rtol=1e-14)
    xv = a * math.asinh(h / (2 * a * math.sinh(X / (2 * a)))) + X / 2
    return w * a, w * a * math.sinh(xv / a)


def brentq_elastic(X, h, L, w, EA):
    """Jonkman (2007) Eq. 4-1/4-2, C_B = 0: outer brentq on H, inner on V."""

    def V_of(H):
        def seabed(V):
            return H / w * (math.sqrt(1 + (V / H) ** 2) - 1) + V * V / (2 * EA * w) - h

        def susp(V):
            Va = V - w * L
            return H / w * (math.sqrt(1 + (V / H) ** 2) - math.sqrt(1 + (Va / H) ** 2)) + (V * L - w * L * L / 2) / EA - h

        if seabed(w * L) >= 0:
            return brentq(seabed, 0.0, w * L, xtol=1e-14, rtol=1e-14), True
        return brentq(susp, w * L, w * L + 10 * (h * w + H), xtol=1e-14, rtol=1e-14), False

    def fx(H):
        V, on_bed = V_of(H)
        if on_bed:
            return L - V / w + H / w * math.asinh(V / H) + H * L / EA - X
        return H / w * (math.asinh(V / H) - math.asinh((V - w * L) / H)) + H * L / EA - X

    H = brentq(fx, 1e-9 * w * L, 1e3 * w * L, xtol=1e-12, rtol=1e-14)
    return H, V_of(H)[0]


def per_call_us(fn, args, n):
    fn(*args)
    best = math.inf
    for _ in range(5):
        t = time.perf_counter()
        for _ in range(n):
            fn(*args)
        best = min(best, (time.perf_counter() - t) / n)
    return best * 1e6


def main():
    t0 = time.perf_counter()
    from moorings.catenary import solve  # noqa: E402  (timed: import + cache load/compile)

    solve(5.8, H_FAIR, L, W)
    solve(5.8, H_FAIR, L, W, EA)
    solve(np.array([5.8, 6.4]), H_FAIR, L, W)
    t_first = time.perf_counter() - t0
    print(f"catenary benchmark on {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"numba {numba.__version__}, {numba.get_num_threads()} threads")
    print(f"import + first calls (compile, or load from the numba cache): {t_first:.2f} s")
    print()
    print(f"{'scalar call from Python':34s} {'ours [us]':>10} {'brentq [us]':>12} {'speed-up':>9} {'max rel diff':>13}")
    for label, X in CASES:
        for kind, ea in (("inextensible", None), ("elastic", EA)):
            ours = per_call_us(solve, (X, H_FAIR, L, W, ea), 20000)
            ref_fn, ref_args = (brentq_inextensible, (X, H_FAIR, L, W)) if ea is None else (
                brentq_elastic, (X, H_FAIR, L, W, ea))
            ref = per_call_us(ref_fn, ref_args, 300)
            r, (Hr, Vr) = solve(X, H_FAIR, L, W, ea), ref_fn(*ref_args)
            diff = max(abs(r.H - Hr) / Hr, abs(r.V - Vr) / Vr)
            print(f"{kind + ', ' + label:34s} {ours:10.2f} {ref:12.1f} {ref / ours:8.0f}x {diff:13.1e}")
    print()
    n = 100_000
    rng = np.random.default_rng(0)
    X = rng.uniform(L - H_FAIR, 6.45, n)  # partly and fully lifted
    print(f"batch of {n} lines (X uniform over the partly and fully lifted range)")
    for kind, ea in (("inextensible", None), ("elastic", EA)):
        solve(X[:10], H_FAIR, L, W, ea)
        best = math.inf
        for _ in range(5):
            t = time.perf_counter()
            solve(X, H_FAIR, L, W, ea)
            best = min(best, time.perf_counter() - t)
        print(f"  {kind:14s} {n / best / 1e6:6.2f} million line-solves/s  ({best * 1e3:.1f} ms per batch)")


if __name__ == "__main__":
    main()
