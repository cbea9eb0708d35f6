"""cosim: the coupler, the participant protocol, scenes, outputs and the CLI.

Kept light on import: :mod:`cosim.errors` re-exports the top-level :mod:`errors`,
so nothing heavy (MuJoCo, the fluid) is loaded by ``import cosim``.
"""

from cosim.errors import (
    ConfigurationError,
    ConvergenceError,
    CosimError,
    InputError,
    InstabilityError,
    ProtocolError,
    SolverError,
    TautLineError,
)

__version__ = "0.1.0"

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
