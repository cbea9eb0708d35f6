"""Lines that break: any mooring model, each line reported when its tension passes its
break load, and optionally released.

:class:`BreakingMooring` wraps a mooring system (catenary, SPH cable, MoorDyn, FMU) and
answers for it (``cosim.protocol.Mooring``). After every coupling step the coupler calls
:meth:`BreakingMooring.check_breaks` with the time and the tension that the bodies' length
constraints carry for each line (a taut inextensible catenary line: its tether); a line
whose fairlead tension (what its model returns, plus that) exceeds its break load is
recorded once as a :class:`LineBreak` (time, line, tension) and logged. With
``release=True`` it is released: from then on it exerts no force on its fairlead, its
model sees the fairlead where it broke (a line that no longer follows the body cannot
be driven past what its model accepts), and the coupler removes its length constraint.
Otherwise (the default) the run goes on with the line intact: a report only.

The tension checked is the one at the fairlead, where a line hanging in still water
carries its largest tension (Barreiro et al. 2016, §3.1: T = H + w z grows with the height above
the seabed). An inextensible catenary line that snaps taut is stopped by its length
constraint within one step: its tension then is the impulse over that step, which grows
as the step shrinks; give the line its ``EA`` where the snap load matters.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from errors import InputError

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class LineBreak:
    """A line whose tension passed its break load."""

    t: float  #: time [s] at the end of the coupling step in which it was seen
    line: str  #: the line's name
    tension: float  #: its fairlead tension then [N]
    break_load: float  #: [N]
    released: bool  #: whether it was released (stopped acting)

    def as_dict(self) -> dict:
        return {"t_s": self.t, "line": self.line, "tension_N": self.tension, "break_load_N": self.break_load,
                "released": self.released}


class BreakingMooring:
    """A mooring system whose lines break at their break load.

    Parameters
    ----------
    mooring:
        The mooring system (any model); its lines' ``break_load`` are used unless
        ``break_loads`` is given.
    break_loads:
        One break load [N] per line (``None`` for a line that never breaks).
    release:
        ``False`` (default): report only. ``True``: a broken line stops exerting force.
    """

    def __init__(self, mooring, break_loads=None, release: bool = False):
        self.inner = mooring
        self.name = mooring.name
        self.n_lines, self.dim = mooring.n_lines, mooring.dim
        lines = getattr(mooring, "lines", None)
        self.line_names = ([ln.name for ln in lines] if lines else
                           list(getattr(mooring, "line_names", [f"line{i}" for i in range(self.n_lines)])))
        if break_loads is None:
            if not lines:
                raise InputError(f"{self.name}: give break_loads, one per line (the mooring has no line records)")
            break_loads = [ln.break_load for ln in lines]
        if len(break_loads) != self.n_lines:
            raise InputError(f"{self.name}: {len(break_loads)} break loads for {self.n_lines} lines; give one per line "
                             f"(None for a line that never breaks)")
        loads = []
        for name, b in zip(self.line_names, break_loads):
            if b is not None and not (isinstance(b, (int, float)) and math.isfinite(b) and b > 0):
                raise InputError(f"{self.name}, line '{name}': break_load = {b!r} N; give the tension at which the "
                                 f"line breaks, a finite number > 0 [N], or None: it never breaks")
            loads.append(math.inf if b is None else float(b))
        self.break_loads = np.array(loads)
        self.release = bool(release)
        self.broken = np.zeros(self.n_lines, bool)  #: lines whose tension passed their break load
        self.released = np.zeros(self.n_lines, bool)  #: lines that no longer act
        self._frozen = None  # fairlead positions and velocities of the lines when they broke
        self._last = None  # the fairlead motion last given
        self.events: list[LineBreak] = []  #: the breaks, in order

    # -- participant protocol --------------------------------------------------
    def initialize(self, t0: float) -> None:
        self.inner.initialize(t0)

    def max_dt(self) -> float:
        return self.inner.max_dt()

    def advance(self, t: float, dt: float) -> None:
        self.inner.advance(t, dt)

    def save_state(self):
        return {"inner": self.inner.save_state(), "broken": self.broken.copy(), "released": self.released.copy(),
                "frozen": None if self._frozen is None else tuple(a.copy() for a in self._frozen),
                "events": list(self.events)}

    def load_state(self, state) -> None:
        self.inner.load_state(state["inner"])
        self.broken, self.released = state["broken"].copy(), state["released"].copy()
        self._frozen = None if state["frozen"] is None else tuple(a.copy() for a in state["frozen"])
        self.events = list(state["events"])

    # -- mooring interface -------------------------------------------------------
    def set_fairlead_motion(self, positions, velocities=None) -> None:
        """As the wrapped model's; a released line's fairlead stays where it broke."""
        if self.released.any():
            positions = np.array(positions, dtype=float)
            velocities = np.zeros_like(positions) if velocities is None else np.array(velocities, dtype=float)
            positions[self.released], velocities[self.released] = (a[self.released] for a in self._frozen)
        self._last = (np.array(positions, dtype=float),
                      None if velocities is None else np.array(velocities, dtype=float))
        self.inner.set_fairlead_motion(positions, velocities)

    def fairlead_forces(self) -> np.ndarray:
        """The wrapped model's forces [N], zero on released lines."""
        f = np.array(self.inner.fairlead_forces(), dtype=float)
        f[self.released] = 0.0
        return f

    def mean_fairlead_forces(self) -> np.ndarray:
        """A dynamic model's mean forces [N] over the last step, zero on released lines."""
        f = np.array(self.inner.mean_fairlead_forces(), dtype=float)
        f[self.released] = 0.0
        return f

    @property
    def anchor_tensions(self):
        """The wrapped model's ``anchor_tensions()`` [N], zero on released lines (absent
        where the model has none, an FMU)."""
        return self._zeroed(self.inner.anchor_tensions)

    @property
    def fairlead_tensions(self):
        """The wrapped model's ``fairlead_tensions()`` [N], zero on released lines."""
        return self._zeroed(self.inner.fairlead_tensions)

    def _zeroed(self, method):
        def call():
            a = np.array(method(), dtype=float)
            a[self.released] = 0.0
            return a
        return call

    def tethers(self):
        return getattr(self.inner, "tethers", lambda: [])()

    def set_tethered(self, tethered: bool = True) -> None:
        self.inner.set_tethered(tethered)

    def close(self) -> None:
        close = getattr(self.inner, "close", None)
        if callable(close):
            close()

    def __getattr__(self, name):  # what else the wrapped model offers (solution, lines, ...)
        if name == "inner":
            raise AttributeError(name)
        return getattr(self.inner, name)

    # -- breaking ------------------------------------------------------------------
    def released_lines(self) -> list[int]:
        """Indices of the released lines."""
        return [int(i) for i in np.flatnonzero(self.released)]

    def check_breaks(self, t: float, extra_tension=None) -> list[LineBreak]:
        """Record the lines whose fairlead tension (the model's, plus ``extra_tension`` [N]
        per line: what a length constraint carries) passes their break load at time ``t``
        [s]; release them if asked. Returns the new breaks."""
        tension = np.linalg.norm(np.asarray(self.inner.fairlead_forces(), float), axis=1)
        if extra_tension is not None:
            tension = tension + np.asarray(extra_tension, float)
        new = (tension > self.break_loads) & ~self.broken
        out = []
        for i in np.flatnonzero(new):
            ev = LineBreak(float(t), self.line_names[i], float(tension[i]), float(self.break_loads[i]), self.release)
            out.append(ev)
            log.warning("%s: line '%s' broke at t = %.6g s: tension %.6g N > break load %.6g N%s", self.name,
                        ev.line, ev.t, ev.tension, ev.break_load,
                        "; released, it no longer acts" if self.release else " (reported; it keeps acting)")
        self.broken |= new
        if self.release and new.any():
            if self._frozen is None:
                self._frozen = tuple(np.zeros((self.n_lines, self.dim)) for _ in range(2))
            pos, vel = self._last
            self._frozen[0][new] = pos[new]
            self._frozen[1][new] = 0.0
            self.released |= new
        self.events.extend(out)
        return out


__all__ = ["BreakingMooring", "LineBreak"]
