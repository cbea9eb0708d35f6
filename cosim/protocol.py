"""The participant protocol: what the coupler asks of every solver, and the roles it
gives them: every participant (:class:`Participant`), the fluid (:class:`Fluid`), the
moorings (:class:`Mooring`), and the optional hooks a participant may add, each a
``typing.Protocol`` the coupler tests with ``isinstance``.

The solvers (``fluid``, ``bodies``, ``moorings``) never import this module; they
satisfy it structurally and :func:`check_participant` verifies it, naming what is
missing. All arrays are numpy, SI units, world frame.

The coupler owns the clock (:mod:`cosim.clock`): it hands every participant the
exact start time of each step, so no participant accumulates time on its own.
"""

from __future__ import annotations

from typing import Any, Protocol, Sequence, runtime_checkable

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


@runtime_checkable
class Fluid(Participant, Protocol):
    """The coupler's fluid: a participant that loads the bodies (``Coupler(fluid=...)``).

    It is given the bodies once (:meth:`attach_bodies`, the bodies participant, before the
    run), their kinematics after every move (:meth:`set_body_kinematics`, a
    :class:`bodies.sampling.BodyKinematics`), and reports the load it exerts on each body
    for the kinematics last given (:meth:`body_wrenches`: force [N] and torque about the
    centre of mass [N m], world frame, ``(n_bodies, 3)`` each; 2-D fluids per metre of
    depth). It advances with the bodies' motion last given. The optional hooks below
    (:class:`ExchangedLoads`, :class:`TimedLoads`, :class:`ElasticStructures`,
    :class:`AddedMassLoads`, :class:`Configured`) add to this role.
    """

    def attach_bodies(self, bodies) -> None:
        """Take the bodies' geometry (e.g. sample their boundary particles)."""

    def set_body_kinematics(self, kinematics) -> None:
        """The bodies' pose and velocity now, world frame."""

    def body_wrenches(self) -> tuple[np.ndarray, np.ndarray]:
        """Force [N] and torque [N m] on each body, ``(n_bodies, 3)`` each."""


# ------------------------------------------------------------------------ optional hooks
@runtime_checkable
class ExchangedLoads(Protocol):
    """A fluid that reports the load it exchanged with each body over its last advance
    (its impulse over the step): the coupler's fluid-first scheme, the default with it."""

    def exchanged_wrenches(self) -> tuple[np.ndarray, np.ndarray]:
        """Force [N] and torque [N m] about each body's centre of mass at the step's start."""


@runtime_checkable
class TimedLoads(Protocol):
    """A fluid whose loads depend on the time itself (an incident sea): the
    predictor-corrector takes them at the predicted time."""

    def set_time(self, t: float) -> None:
        """The time [s] at which the next :meth:`Fluid.body_wrenches` is taken."""


@runtime_checkable
class ElasticStructures(Protocol):
    """A fluid that carries elastic structures: the rows of the coupled bodies that are
    their links, whose vibration the instability watch leaves to the structures' own check."""

    elastic_rows: Sequence[int]


@runtime_checkable
class AddedMassLoads(Protocol):
    """A fluid that says whether its loads carry added mass (default: they do): the
    automatic light-body remedy applies only where they do."""

    loads_carry_added_mass: bool


@runtime_checkable
class Gravity(Protocol):
    """Whatever states the gravity [m/s^2] it assumes: a fluid, or its ``config``; ``g`` a
    number along -z, or the vector ((gx, gz) in the x-z plane, or (gx, gy, gz))."""

    g: float | tuple


@runtime_checkable
class SpeedOfSound(Protocol):
    """A weakly compressible fluid's settings: its speed of sound [m/s], which no body may
    approach (the coupler stops a body faster than ``Coupler.MAX_MACH`` of it)."""

    speed_of_sound: float


@runtime_checkable
class Configured(Protocol):
    """A participant whose settings are one object, ``config`` (the SPH fluid's
    ``fluid.solver.FluidConfig``: :class:`Gravity`, :class:`SpeedOfSound`)."""

    config: Any


@runtime_checkable
class LimitReported(Protocol):
    """A participant that says what limits its ``max_dt()`` now (``dt_limit``: text)."""

    dt_limit: str


@runtime_checkable
class DrivenBodies(Protocol):
    """Bodies some of whose degrees of freedom are driven (a moving support): not the
    coupling's, so the instability watch leaves them out."""

    driven_dofs: set


@runtime_checkable
class SaysDynamic(Protocol):
    """A mooring that says whether it has state (``dynamic``); a dynamic one is a
    :class:`DynamicMooring`."""

    dynamic: bool


@runtime_checkable
class DynamicMooring(Mooring, Protocol):
    """A mooring with state (:class:`Mooring`'s docstring): advanced with the bodies until
    its mean fairlead force over a step is the one the bodies were given."""

    dynamic: bool

    def mean_fairlead_forces(self) -> np.ndarray:
        """The mean force [N] on each fairlead over the last advance, ``(n_lines, dim)``."""


@runtime_checkable
class DrivenToStepEnd(Protocol):
    """A dynamic mooring whose own convention drives the fairleads to where they are at the
    step's start; called once before the run so that it takes them at the step's end."""

    def drive_to_step_end(self) -> None:
        """Take the fairlead motion as the bodies' at the end of each step."""


@runtime_checkable
class Tethered(Protocol):
    """A mooring some of whose lines are length constraints on the bodies (taut
    inextensible lines): the coupler adds them to the bodies as tendons."""

    def tethers(self) -> list:
        """``(line index, anchor [m], length [m])`` of each line held as a constraint."""

    def set_tethered(self, tethered: bool = True) -> None:
        """The bodies hold those lines now (their force is no longer the mooring's)."""


@runtime_checkable
class Breaking(Protocol):
    """A mooring whose lines break (``moorings.breaking.BreakingMooring``)."""

    def check_breaks(self, t: float, extra_tension=None) -> list:
        """Look at the tensions after a step (``extra_tension``: each line's constraint's)."""

    def released_lines(self) -> list[int]:
        """The lines that no longer act."""


@runtime_checkable
class LineStiffness(Protocol):
    """A mooring that says what its lines are to the bodies over a step: a spring and a
    dashpot at each fairlead (:mod:`moorings.fairlead_stiffness`, :mod:`cosim.line_step`)."""

    def fairlead_stiffness(self):
        """``k`` [N/m] and ``c`` [N s/m], ``(n_lines, dim, dim)`` each."""


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
