"""The project's error hierarchy, at the bottom of the import graph.

Every error raised on purpose by ``cosim``, ``fluid``, ``bodies`` or ``moorings``
derives from :class:`CosimError`, one subclass per family. A message says what is
wrong, where (participant, line, particle, step) and how to fix it.

Why a top-level module: the solver packages (``fluid``, ``bodies``, ``moorings``)
never import ``cosim`` (docs/DESIGN.md, Layering), yet ``except CosimError`` must
catch everything the project raises. So the classes live here, importing nothing,
and ``cosim.errors`` re-exports the very same objects for user code.
"""

from __future__ import annotations


class CosimError(Exception):
    """Base class of every error this project raises on purpose."""


class InputError(CosimError, ValueError):
    """A parameter or an input array is invalid; raised before any work is done."""


class ConfigurationError(CosimError, ValueError):
    """Participants or a scene do not fit together (missing inputs, clashing sizes)."""


class ProtocolError(CosimError, TypeError):
    """An object given as a participant lacks part of the participant protocol."""


class SolverError(CosimError, RuntimeError):
    """A solver could not produce a valid result during a run."""


class InstabilityError(SolverError):
    """A run went unstable (NaN, infinite or runaway values); the data up to the last
    good step stays readable."""


class ConvergenceError(SolverError):
    """An iterative method did not converge within its iteration budget."""


class TautLineError(SolverError):
    """An inextensible mooring line is asked to span more than its length.

    There is no catenary solution; either give the line an axial stiffness ``EA``
    or let the coupler hold it with a length constraint.
    """
