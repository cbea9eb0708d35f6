"""A mooring system of quasi-static catenary lines (Barreiro et al. 2016, §3.1) as a participant.

Each line runs from a fixed anchor to a fairlead on a body. The force on the
fairlead has a horizontal component ``H`` along the fairlead→anchor direction
and a vertical component ``V`` downwards (Barreiro et al. 2016, §3.1, ``F_x = T_H cos ψ``,
``F_y = T_H sin ψ``), both from :func:`moorings.catenary.solve`. The seabed of
each line is the horizontal plane through its anchor.

In 2-D scenes (x-z plane) anchors and fairleads are ``(x, z)``; in 3-D ``(x, y, z)``.
"""

from __future__ import annotations

import math

import numpy as np

from errors import InputError, TautLineError
from moorings.catenary import LineSolution, solve_fairleads
from moorings.fairlead_stiffness import FairleadStiffness, by_differences
from moorings.line import MooringLine, named_lines, per_line
from moorings.line_events import LineStateLog


#: the relative slack ``1 - chord / L`` within which a taut inextensible line is held as a
#: length constraint by default (``CatenaryMooring``'s ``slack``) [-]
TETHER_SLACK = 1e-3


class CatenaryMooring:
    """Quasi-static catenary lines; satisfies ``cosim.protocol.Mooring``.

    Parameters
    ----------
    lines:
        The :class:`~moorings.line.MooringLine` records (all 2-D or all 3-D).
    fairleads:
        Optional initial fairlead positions [m], ``(n_lines, dim)``; checked at once.
    name:
        Participant name used in messages and outputs.
    taut:
        What an inextensible line does at its length. ``"tether"`` (default): the
        coupler adds a length constraint between anchor and fairlead to the
        bodies (see :meth:`tethers`) and the catenary force is capped at the
        geometry of ``slack`` (its stiffness diverges at taut, which no explicit
        exchange survives): the constraint then carries the rest, and several taut
        lines share a load as statics says. Without a coupler (no constraint
        attached), or beyond the length by more than 1 %, a taut line raises
        :class:`~cosim.errors.TautLineError`. ``"raise"``: always raise at taut.
    slack:
        Relative slack ``1 - chord / L`` below which an inextensible line's force is
        capped in ``"tether"`` mode (default 1e-3: there the tension is ~6.5 w L).
    """

    def __init__(self, lines, fairleads=None, name: str = "moorings", taut: str = "tether", slack: float = TETHER_SLACK):
        self.lines = named_lines(lines)
        self.name = name
        if taut not in ("tether", "raise"):
            raise InputError(f"{name}: taut must be 'tether' or 'raise', got {taut!r}")
        if not (0.0 < slack < 0.5):
            raise InputError(f"{name}: slack must be between 0 and 0.5, got {slack!r}")
        self.taut, self.slack = taut, float(slack)
        self._tethered = False
        self.n_lines = len(self.lines)
        self.dim = self.lines[0].dim
        self.anchors = np.array([ln.anchor for ln in self.lines], dtype=float)
        self._L = np.array([ln.length for ln in self.lines])
        self._w = np.array([ln.weight for ln in self.lines])
        self._EA = np.array([math.inf if ln.inextensible else ln.EA for ln in self.lines])
        self._inextensible = np.isinf(self._EA)
        self.t = 0.0
        self._pos: np.ndarray | None = None
        self.solution: LineSolution | None = None  #: per-line H, V, touchdown, state
        self._forces = np.zeros((self.n_lines, self.dim))
        #: when each line became fully lifted or taut (Barreiro et al. 2016, Fig. 5), after every step
        self.state_log = LineStateLog([ln.name for ln in self.lines])
        if fairleads is not None:
            self.set_fairlead_motion(fairleads)

    # -- participant protocol ------------------------------------------------
    def initialize(self, t0: float) -> None:
        if self._pos is None:
            raise InputError(
                f"{self.name}: fairlead positions are not set; call set_fairlead_motion() "
                f"or pass fairleads= before the run"
            )
        self.t = float(t0)
        if self.state_log.state is None:  # a resumed run keeps its log
            self.state_log.update(self.t, self.solution.state)

    def max_dt(self) -> float:
        """Unlimited: a quasi-static law has no stability limit."""
        return math.inf

    def advance(self, t: float, dt: float) -> None:
        """Nothing to integrate: the forces follow the fairlead positions (given for
        ``t + dt`` before this call); the lines' states at ``t + dt`` go into
        :attr:`state_log`."""
        self.t = t + dt
        if self.solution is not None:
            self.state_log.update(self.t, self.solution.state)

    def save_state(self):
        return None if self._pos is None else {"pos": self._pos.copy(), "states": self.state_log.save()}

    def load_state(self, state) -> None:
        if state is None:
            return
        if isinstance(state, dict):
            self.state_log.load(state["states"])
            state = state["pos"]
        self.set_fairlead_motion(state)

    # -- mooring interface ---------------------------------------------------
    def set_fairlead_motion(self, positions, velocities=None) -> None:
        """Fairlead positions [m], ``(n_lines, dim)``, world frame; velocities are
        ignored (quasi-static). Solves every line at once."""
        pos = per_line(positions, [ln.name for ln in self.lines], self.dim, self.name, "fairlead positions")
        h = pos[:, -1] - self.anchors[:, -1]
        if (h < 0).any():
            i = int(np.argmax(h < 0))
            raise InputError(
                f"{self.name}, line '{self.lines[i].name}': fairlead at z = {pos[i, -1]:.6g} m is below "
                f"the seabed through its anchor (z = {self.anchors[i, -1]:.6g} m); move the anchor down "
                f"or the fairlead up"
            )
        over = self._inextensible
        if over.any():  # an inextensible line cannot span more than its length
            X = np.sqrt(np.sum((pos - self.anchors)[:, :-1] ** 2, axis=1))
            chord = np.hypot(X, h)
            over = over & (chord >= self._L * (1.0 + (0.01 if self._tethered else 0.0)))
        if over.any():
            i = int(np.argmax(over))
            why = ("its length constraint lets it stretch more than 1 %: the load is too large for the "
                   "constraint, or the coupling step too long" if self._tethered else
                   "no catenary exists; give the line an axial stiffness EA, lengthen it, limit the body's "
                   "offset, or attach the mooring to bodies through a Coupler, which holds it taut")
            raise TautLineError(
                f"{self.name}, line '{self.lines[i].name}': the inextensible line of length "
                f"{self._L[i]:.6g} m would have to span {chord[i]:.6g} m (X = {X[i]:.6g} m, h = {h[i]:.6g} m); "
                f"{why}."
            )
        sol, self._forces = self._law(pos)
        self._pos = pos
        self.solution = sol

    def _law(self, pos: np.ndarray) -> tuple[LineSolution, np.ndarray]:
        """The lines' solution and fairlead forces [N] for fairlead positions ``pos`` [m]
        (checked by the caller), without storing them; ``pos`` may stack several sets of
        the lines' fairleads, ``(r n_lines, dim)`` (:meth:`fairlead_stiffness`). A tethered
        inextensible line is solved at the point of its chord where the slack is ``slack``
        (:func:`moorings.catenary.solve_fairleads`)."""
        pos = np.ascontiguousarray(pos, dtype=float)
        out, forces = np.empty((len(pos), 4)), np.empty(pos.shape)
        solve_fairleads(pos, self.anchors, self._L, self._w, self._EA, self.slack if self._tethered else 0.0, out,
                        forces)
        return LineSolution(out[:, 0], out[:, 1], out[:, 2], out[:, 3].astype(np.int8)), forces

    def points_at(self, line: int, s) -> np.ndarray:
        """World positions [m] of line ``line``'s points at arc lengths ``s`` [m] from its
        anchor, (k, dim), on the solved line's shape (:func:`moorings.catenary.shape`)."""
        from moorings.catenary import shape
        from moorings.line import vertical_plane

        ln = self.lines[line]
        X, h, in_world = vertical_plane(ln.anchor, self._pos[line])
        _, x, z = shape(X, h, self._L[line], self._w[line], None if np.isinf(self._EA[line]) else self._EA[line],
                        s=s)
        return in_world(x, z)

    def fairlead_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its fairlead, ``(n_lines, dim)``, world frame."""
        if self.solution is None:
            raise InputError(f"{self.name}: fairlead positions are not set; call set_fairlead_motion() first")
        return self._forces.copy()

    def fairlead_stiffness(self):
        """The lines' tangent stiffness ``-dF/dx`` [N/m] at the fairleads now, by central
        differences of the law (:mod:`moorings.fairlead_stiffness`; no damping: the law is
        quasi-static). A line held by its length constraint is stiff through the
        constraint, not through this law (its force is capped there)."""
        if self._pos is None:
            raise InputError(f"{self.name}: fairlead positions are not set; call set_fairlead_motion() first")
        step = 1e-6 * float(self._L.max())
        with np.errstate(invalid="ignore"):
            s = by_differences(lambda p: self._law(p)[1], self._pos, step, batched=True)
        return FairleadStiffness(np.nan_to_num(s.k, nan=0.0, posinf=0.0, neginf=0.0), s.c)

    # -- length constraints ----------------------------------------------------
    def tethers(self) -> list[tuple[int, np.ndarray, float]]:
        """``(line index, anchor [m], length [m])`` of the lines that need a length
        constraint: the inextensible ones, in ``"tether"`` mode."""
        if self.taut != "tether":
            return []
        return [(i, self.anchors[i].copy(), float(self._L[i])) for i in range(self.n_lines) if np.isinf(self._EA[i])]

    def set_tethered(self, tethered: bool = True) -> None:
        """Told by the coupler once the length constraints of :meth:`tethers` exist."""
        self._tethered = bool(tethered)
        if self._pos is not None:
            self.set_fairlead_motion(self._pos)

    # -- reporting -----------------------------------------------------------
    def line_states(self) -> np.ndarray:
        """Each line's :class:`~moorings.catenary.LineState` now (Barreiro et al. 2016, Fig. 5 a-d), as
        integers 0-3; a line held by its length constraint is ``TAUT``."""
        return np.asarray(self.solution.state, dtype=np.int8).copy()

    def fairlead_tensions(self) -> np.ndarray:
        """Line tension at each fairlead [N]: ``sqrt(H^2 + V^2)``."""
        return np.hypot(self.solution.H, self.solution.V)

    def anchor_tensions(self) -> np.ndarray:
        """Line tension at each anchor [N]: ``H`` where line lies on the seabed (no
        friction), ``sqrt(H^2 + (V - w L)^2)`` where it pulls the anchor up."""
        Va = np.clip(self.solution.V - self._w * self._L, 0.0, None)
        return np.hypot(self.solution.H, Va)

    def total_wrench(self, point) -> tuple[np.ndarray, np.ndarray | float]:
        """Total mooring force [N] and its moment [N m] about ``point`` [m].

        3-D: the moment is a 3-vector. 2-D (x-z plane): the moment about the y axis,
        ``M_y = r_z F_x - r_x F_z``.
        """
        f = self.fairlead_forces()
        r = self._pos - np.asarray(point, dtype=float)
        if self.dim == 3:
            return f.sum(axis=0), np.cross(r, f).sum(axis=0)
        return f.sum(axis=0), float(np.sum(r[:, 1] * f[:, 0] - r[:, 0] * f[:, 1]))


__all__ = ["CatenaryMooring", "MooringLine"]
