"""Registry of validation cases, run by ``cosim validate NAME``.

A case is a function ``fn(quick: bool) -> dict`` registered with :func:`case`. It
returns at least ``passed`` (bool), ``metrics`` (measured errors and quantities),
``tolerances``, and, where they apply, ``particles`` and ``steps``; :func:`run`
adds ``name``, ``quick`` and ``wall_s``. ``quick=True`` is the coarse variant that
CI runs. Cases live in the modules of :mod:`cosim.validations`, imported only when
a case is listed or run, so ``import cosim`` stays light.
"""

from __future__ import annotations

import importlib
import time
from dataclasses import dataclass
from typing import Callable

from cosim.errors import InputError

#: modules that register cases; a new family adds its module here
CASE_MODULES = ("cosim.validations.catenary", "cosim.validations.cable", "cosim.validations.fluid",
                "cosim.validations.sloshing", "cosim.validations.coupling", "cosim.validations.floating",
                "cosim.validations.waves")


@dataclass(frozen=True)
class Case:
    name: str
    description: str
    fn: Callable[[bool], dict]


_CASES: dict[str, Case] = {}


def case(name: str, description: str):
    """Decorator registering ``fn(quick) -> dict`` as validation case ``name``."""

    def register(fn):
        if name in _CASES and _CASES[name].fn is not fn:
            raise ValueError(f"validation case {name!r} registered twice")
        _CASES[name] = Case(name, description, fn)
        return fn

    return register


def cases() -> dict[str, Case]:
    """All registered cases, by name."""
    for mod in CASE_MODULES:
        importlib.import_module(mod)
    return dict(sorted(_CASES.items()))


def run(name: str, quick: bool = False) -> dict:
    """Run one case and return its JSON-ready record."""
    known = cases()
    if name not in known:
        raise InputError(f"no validation case {name!r}; known cases: {', '.join(known)}")
    t0 = time.perf_counter()
    out = known[name].fn(quick)
    wall = time.perf_counter() - t0
    record = {"name": name, "quick": quick, "passed": bool(out.pop("passed"))}
    record.update({"metrics": {}, "tolerances": {}, "particles": 0, "steps": 0})
    record.update(out)
    record["wall_s"] = round(wall, 4)
    return record
