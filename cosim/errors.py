"""The project's error hierarchy, as seen from the coupler.

The classes are defined in the top-level module :mod:`errors` (importable by the solver
packages, which never import ``cosim``); this module re-exports the same objects, so
``from cosim.errors import InputError`` and ``from errors import InputError`` name one class.
"""

from __future__ import annotations

from errors import (
    ConfigurationError,
    ConvergenceError,
    CosimError,
    InputError,
    InstabilityError,
    ProtocolError,
    SolverError,
    TautLineError,
)

__all__ = [
    "ConfigurationError",
    "ConvergenceError",
    "CosimError",
    "InputError",
    "InstabilityError",
    "ProtocolError",
    "SolverError",
    "TautLineError",
]
