"""The coupler: keeps every participant on one clock and runs the coupling steps.

One coupling step (``Coupler.step``), in this order (``../shared/DESIGN.md``):

1. the step size: the smallest ``max_dt()`` of all participants (or the fixed
   step the user asked for, if smaller), rounded down to whole clock ticks and
   clipped so that the run lands exactly on its end time;
2. data exchange (fluid -> body forces, moorings -> fairlead forces, bodies ->
   kinematics): filled in by the coupling issue; until then participants exchange
   nothing;
3. every participant advances from ``t`` to ``t + dt``, in the order given;
4. the clock advances by an integer number of ticks (no drift).

The coupler is the only owner of time: participants get ``t`` and ``dt`` with
every ``advance`` and never accumulate time themselves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Sequence

from cosim.clock import TICKS_PER_SECOND, Clock, to_ticks
from cosim.errors import ConfigurationError, InputError, InstabilityError
from cosim.protocol import Participant, check_participant


@dataclass(frozen=True)
class StepInfo:
    """What one coupling step did."""

    index: int  #: step number, from 1
    t: float  #: time at the end of the step [s]
    dt: float  #: step taken [s]
    limiter: str  #: what set dt: a participant's name, "user dt" or "end time"


class Coupler:
    """Runs participants on one drift-free clock.

    Parameters
    ----------
    participants:
        Objects satisfying :class:`cosim.protocol.Participant`, advanced in this order.
    dt:
        Fixed coupling step [s]; ``None`` lets the participants' ``max_dt()`` decide.
        Participants that need less still get less.
    t0:
        Start time [s].
    """

    def __init__(self, participants: Sequence[Participant], *, dt: float | None = None, t0: float = 0.0):
        for p in participants:
            check_participant(p)
        names = [p.name for p in participants]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ConfigurationError(f"participant names must be unique; repeated: {', '.join(dup)}. Rename them.")
        if dt is not None and not (math.isfinite(dt) and dt > 0):
            raise InputError(f"coupling step dt must be a positive finite number of seconds, got {dt!r}")
        if dt is not None and to_ticks(dt) < 1:
            raise InputError(f"coupling step dt={dt!r} s is below the clock resolution of 1e-12 s")
        self.participants = list(participants)
        self.dt = dt
        self.clock = Clock(t0)
        self.steps = 0
        self._initialized = False

    @property
    def t(self) -> float:
        """Current time [s]."""
        return self.clock.t

    def initialize(self) -> None:
        """Initialise every participant at the start time (each checks its own inputs)."""
        for p in self.participants:
            p.initialize(self.clock.t)
        self._initialized = True

    def _step_size(self, ticks_left: int) -> tuple[int, str]:
        best, limiter = math.inf, "user dt"
        if self.dt is not None:
            best = self.dt
        for p in self.participants:
            d = p.max_dt()
            if not (d > 0):  # catches NaN too
                raise InstabilityError(
                    f"step {self.steps + 1}, t = {self.t:.9g} s: participant '{p.name}' reports a "
                    f"stable step of {d!r} s; its state is no longer valid (see its own diagnostics)."
                )
            if d < best:
                best, limiter = d, p.name
        n = ticks_left if math.isinf(best) else to_ticks(best)
        if n >= ticks_left:
            return ticks_left, "end time"
        if n < 1:
            raise InstabilityError(
                f"step {self.steps + 1}, t = {self.t:.9g} s: participant '{limiter}' asks for a step of "
                f"{best:.3g} s, below the clock resolution (1e-12 s); the run is stiff or unstable there."
            )
        return n, limiter

    def step(self, t_end: float) -> StepInfo:
        """Advance every participant by one coupling step, not past ``t_end``."""
        if not self._initialized:
            self.initialize()
        ticks_left = self.clock.ticks_until(t_end)
        if ticks_left < 1:
            raise InputError(f"t_end = {t_end!r} s is not after the current time {self.t!r} s")
        n, limiter = self._step_size(ticks_left)
        t, dt = self.clock.t, n / TICKS_PER_SECOND
        for p in self.participants:
            p.advance(t, dt)
        self.clock.advance(n)
        self.steps += 1
        return StepInfo(self.steps, self.clock.t, dt, limiter)

    def run(self, t_end: float, callback: Callable[[StepInfo], Any] | None = None) -> int:
        """Step until ``t_end`` [s] exactly; returns the number of steps taken."""
        if not math.isfinite(t_end):
            raise InputError(f"t_end must be finite, got {t_end!r}")
        n0 = self.steps
        while self.clock.ticks_until(t_end) > 0:
            info = self.step(t_end)
            if callback is not None:
                callback(info)
        return self.steps - n0

    def save_state(self) -> dict:
        """A checkpoint of the clock and every participant."""
        return {
            "ticks": self.clock.ticks,
            "steps": self.steps,
            "participants": {p.name: p.save_state() for p in self.participants},
        }

    def load_state(self, state: dict) -> None:
        """Return to a checkpoint taken by :meth:`save_state`."""
        for p in self.participants:
            p.load_state(state["participants"][p.name])
        self.clock.ticks = state["ticks"]
        self.steps = state["steps"]
