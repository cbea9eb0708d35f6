"""The participant protocol: what the coupler asks of every solver.

The solvers (``fluid``, ``bodies``, ``moorings``) never import this module; they
satisfy it structurally and :func:`check_participant` verifies it, naming what is
missing. All arrays are numpy, SI units, world frame.

The coupler owns the clock (:mod:`cosim.clock`): it hands every participant the
exact start time of each step, so no participant accumulates time on its own.
"""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

import numpy as np

from cosim.errors import ProtocolError


@runtime_checkable
class Participant(Protocol):
    """Anything that advances in time and exchanges data with others."""

    name: str

    def initialize(self, t0: float) -> None:
        """Allocate and check inputs; raise a clear error before any work is done."""

    def max_dt(self) -> float:
        """Largest stable step [s] from the current state; ``math.inf`` if unlimited."""

    def advance(self, t: float, dt: float) -> None:
        """Move from time ``t`` to ``t + dt`` [s] with the inputs last given."""

    def save_state(self) -> Any:
        """An opaque snapshot from which :meth:`load_state` restores this exact state."""

    def load_state(self, state: Any) -> None:
        """Restore a snapshot taken by :meth:`save_state`."""


@runtime_checkable
class Mooring(Participant, Protocol):
    """A mooring system: fairlead kinematics in, fairlead forces out.

    A quasi-static law is a pure function of the fairlead positions; a dynamic
    line has state and sub-cycles inside :meth:`advance`. Both look alike here,
    so a scene swaps one for the other in one line.

    A dynamic line says so (``dynamic = True``) and adds ``mean_fairlead_forces()``: the
    mean force [N] it exerted on each fairlead over its last advance (its impulse over
    ``dt``), ``(n_lines, dim)``. The coupler then advances it with the bodies until that
    mean is the force the bodies were given (``Coupler(lines="subiterate")``), the
    fairlead motion it gives being where the bodies took the fairleads by the step's end;
    a model whose own convention differs has ``drive_to_step_end()``, which the coupler
    calls once before the run (MoorDyn's adapter).
    """

    n_lines: int
    dim: int

    def set_fairlead_motion(self, positions: np.ndarray, velocities: np.ndarray | None = None) -> None:
        """Fairlead positions [m] and velocities [m/s], arrays of shape ``(n_lines, dim)``."""

    def fairlead_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its fairlead (on the body), ``(n_lines, dim)``."""


def protocol_members(protocol: type) -> set[str]:
    """Public attribute and method names a protocol class declares (its bases included)."""
    names: set[str] = set()
    for cls in protocol.__mro__:
        if cls in (Protocol, object) or cls.__module__ == "typing":
            continue
        names.update(getattr(cls, "__annotations__", {}))
        names.update(k for k, v in vars(cls).items() if callable(v))
    return {n for n in names if not n.startswith("_")}


def _missing(obj: Any, protocol: type) -> list[str]:
    return sorted(n for n in protocol_members(protocol) if not hasattr(obj, n))


def check_participant(obj: Any, protocol: type = Participant) -> None:
    """Raise :class:`ProtocolError` naming every attribute ``obj`` lacks for ``protocol``."""
    missing = _missing(obj, protocol)
    if missing:
        raise ProtocolError(
            f"{type(obj).__name__} cannot act as a {protocol.__name__}: it lacks "
            f"{', '.join(missing)}. Implement them (see cosim.protocol.{protocol.__name__})."
        )
