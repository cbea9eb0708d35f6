"""How a validation case's measured metrics are judged against its tolerances.

A leaf: pure functions on the dicts a case returns (``metrics``, ``tolerances``), used by
:func:`cosim.validation.run`, by the report and by the cases themselves, none of which
it imports.
"""

from __future__ import annotations

import math
from typing import Any


def lookup(metrics: dict, key: str) -> Any:
    """The metric ``key`` of ``metrics``: a key of the dict, or a dotted path into nested
    dicts (``"l90.odd_symmetry_rel_err"``; a key may itself hold dots, ``"0.1s"``: the
    longest key that matches comes first). Raises KeyError if there is none."""
    if key in metrics:
        return metrics[key]
    parts = key.split(".")
    for i in range(len(parts) - 1, 0, -1):
        head = ".".join(parts[:i])
        if head in metrics and isinstance(metrics[head], dict):
            try:
                return lookup(metrics[head], ".".join(parts[i:]))
            except KeyError:
                pass
    raise KeyError(key)


def within(value: Any, bound: Any) -> bool:
    """Whether a measured ``value`` is within ``bound``:

    - a number b: ``|value| <= b`` (an error or a distance);
    - ``[lo, hi]``: ``lo <= value <= hi``, None for an open end;
    - True / False: the value is that boolean (a property: monotone, restoring ...);
    - a string: the value equals it.

    A list of values is within when each one is; a non-finite value never is."""
    if isinstance(value, (list, tuple)):
        return len(value) > 0 and all(within(v, bound) for v in value)
    if isinstance(bound, bool):
        return type(value).__name__ in ("bool", "bool_") and bool(value) is bound
    if isinstance(bound, str):
        return value == bound
    if type(value).__name__ in ("bool", "bool_", "str") or value is None:
        return False
    value = float(value)
    if not math.isfinite(value):
        return False
    if isinstance(bound, (list, tuple)):
        lo, hi = bound
        return (lo is None or value >= lo) and (hi is None or value <= hi)
    return abs(value) <= bound


def judge(metrics: dict, tolerances: dict) -> tuple[bool, list[str]]:
    """(passed, the tolerance keys not met): every metric named in ``tolerances`` is
    within its bound (:func:`within`); a metric that is missing is not. No tolerance at
    all passes nothing."""
    out = []
    for key, bound in tolerances.items():
        try:
            v = lookup(metrics, key)
        except KeyError:
            out.append(key)
            continue
        if not within(v, bound):
            out.append(key)
    return (bool(tolerances) and not out), out


def measured(metrics: dict, tolerances: dict) -> dict:
    """The values of the metrics ``tolerances`` names (None where a metric is missing)."""
    out = {}
    for key in tolerances:
        try:
            out[key] = lookup(metrics, key)
        except KeyError:
            out[key] = None
    return out
