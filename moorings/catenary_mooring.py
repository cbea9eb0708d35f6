"""A mooring system of quasi-static catenary lines (seed 004 §3.1) as a participant.

Each line runs from a fixed anchor to a fairlead on a body. The force on the
fairlead has a horizontal component ``H`` along the fairlead→anchor direction
and a vertical component ``V`` downwards (seed 004 §3.1, ``F_x = T_H cos ψ``,
``F_y = T_H sin ψ``), both from :func:`moorings.catenary.solve`. The seabed of
each line is the horizontal plane through its anchor.

In 2-D scenes (x-z plane) anchors and fairleads are ``(x, z)``; in 3-D ``(x, y, z)``.
"""

from __future__ import annotations

import math

import numpy as np

from cosim.errors import InputError, TautLineError
from moorings.catenary import TAUT, LineSolution, solve_packed
from moorings.line import MooringLine, named_lines


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
    """

    def __init__(self, lines, fairleads=None, name: str = "moorings"):
        self.lines = named_lines(lines)
        self.name = name
        self.n_lines = len(self.lines)
        self.dim = self.lines[0].dim
        self.anchors = np.array([ln.anchor for ln in self.lines], dtype=float)
        self._L = np.array([ln.length for ln in self.lines])
        self._w = np.array([ln.weight for ln in self.lines])
        self._EA = np.array([math.inf if ln.inextensible else ln.EA for ln in self.lines])
        # rows (X, h, L, w, EA) for catenary.solve_packed: the lines were checked above
        self._packed = np.column_stack([np.zeros(self.n_lines), np.zeros(self.n_lines), self._L, self._w, self._EA])
        self._out = np.empty((self.n_lines, 4))
        self.t = 0.0
        self._pos: np.ndarray | None = None
        self.solution: LineSolution | None = None  #: per-line H, V, touchdown, state
        self._forces = np.zeros((self.n_lines, self.dim))
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

    def max_dt(self) -> float:
        """Unlimited: a quasi-static law has no stability limit."""
        return math.inf

    def advance(self, t: float, dt: float) -> None:
        """Nothing to integrate: the forces follow the fairlead positions."""
        self.t = t + dt

    def save_state(self):
        return None if self._pos is None else self._pos.copy()

    def load_state(self, state) -> None:
        if state is not None:
            self.set_fairlead_motion(state)

    # -- mooring interface ---------------------------------------------------
    def set_fairlead_motion(self, positions, velocities=None) -> None:
        """Fairlead positions [m], ``(n_lines, dim)``, world frame; velocities are
        ignored (quasi-static). Solves every line at once."""
        want = f"shape ({self.n_lines}, {self.dim}) (one row per line, {'x, z' if self.dim == 2 else 'x, y, z'})"
        try:
            pos = np.asarray(positions, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"{self.name}: fairlead positions must be numbers of {want}") from None
        if pos.shape != (self.n_lines, self.dim):
            raise InputError(f"{self.name}: fairlead positions must have {want}, got shape {pos.shape}")
        bad = ~np.all(np.isfinite(pos), axis=1)
        if bad.any():
            i = int(np.argmax(bad))
            raise InputError(f"{self.name}, line '{self.lines[i].name}': fairlead position {pos[i]} is not finite")
        d = pos - self.anchors
        h = d[:, -1]
        if (h < 0).any():
            i = int(np.argmax(h < 0))
            raise InputError(
                f"{self.name}, line '{self.lines[i].name}': fairlead at z = {pos[i, -1]:.6g} m is below "
                f"the seabed through its anchor (z = {self.anchors[i, -1]:.6g} m); move the anchor down "
                f"or the fairlead up"
            )
        horiz = d[:, :-1]
        X = np.sqrt(np.sum(horiz**2, axis=1))
        self._packed[:, 0], self._packed[:, 1] = X, h
        solve_packed(self._packed, self._out)
        o = self._out
        sol = LineSolution(o[:, 0].copy(), o[:, 1].copy(), o[:, 2].copy(), o[:, 3].astype(np.int8))
        taut = (sol.state == TAUT) & np.isinf(sol.H)
        if taut.any():
            i = int(np.argmax(taut))
            dist = math.hypot(X[i], h[i])
            raise TautLineError(
                f"{self.name}, line '{self.lines[i].name}': the inextensible line of length "
                f"{self._L[i]:.6g} m would have to span {dist:.6g} m (X = {X[i]:.6g} m, h = {h[i]:.6g} m); "
                f"no catenary exists. Give the line an axial stiffness EA, lengthen it, or limit the "
                f"body's offset."
            )
        e = np.divide(horiz, X[:, None], out=np.zeros_like(horiz), where=X[:, None] > 0)
        self._forces = np.concatenate([-sol.H[:, None] * e, -sol.V[:, None]], axis=1)
        self._pos = pos.copy()
        self.solution = sol

    def fairlead_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its fairlead, ``(n_lines, dim)``, world frame."""
        if self.solution is None:
            raise InputError(f"{self.name}: fairlead positions are not set; call set_fairlead_motion() first")
        return self._forces.copy()

    # -- reporting -----------------------------------------------------------
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
