"""When each mooring line changes state: Barreiro et al. 2016, Fig. 5's four states of a catenary line
(a: resting on the seabed, b: partly lifted, c: fully lifted, d: fully extended, "taut"),
classified by the catenary law (:class:`moorings.catenary.LineState`; the boundaries are
Barreiro et al. 2016, Eq. 35-39 and the taut limit ``sqrt(X² + h²) = L``, its §3.2 "fully extended"
case, Eq. 40).

:class:`LineStateLog` takes each line's state after every coupling step and records the
times at which a line

- becomes fully lifted: no seabed contact (state FULLY_LIFTED or TAUT, panels c-d), and
  when it touches down again;
- becomes taut: fully extended (state TAUT, panel d), and when it slackens again.

A time is the end of the coupling step in which the state was first seen (so it is known
to within one step). The paper's wind-turbine base has its two front lines fully extended
at 71.1 s and 81.1 s (Barreiro et al. 2016, §5, Fig. 19).

Where the states come from, per model:

- catenary: the law's own state (:func:`moorings.catenary.solve`); a line held by its
  length constraint is ``TAUT``;
- FMU: the FMU's ``<line>.state`` output where its variable map names one (the exported
  catenary FMU: the same law);
- SPH cable and MoorDyn, from their nodes (:func:`node_states`): ``TAUT`` where the
  anchor-fairlead distance is at least the unstretched length, the law's own boundary
  (Fig. 5 d: the line is stretched straight, its tension along the whole line above
  zero); ``RESTING`` where ``X <= L - h``, the law's boundary (the line could hang
  straight down); otherwise ``PARTLY_LIFTED`` while a node other than the anchor lies on
  the seabed (within a tolerance the model states: its seabed contact's penetration),
  ``FULLY_LIFTED`` when none does.
"""

from __future__ import annotations

import math

import numpy as np

from moorings.catenary import FULLY_LIFTED, PARTLY_LIFTED, RESTING, TAUT, LineState

#: events kept per line and kind (a line chattering at a boundary would otherwise fill the summary)
MAX_EVENTS = 200


def node_states(anchors, fairleads, lengths, nodes, seabed_z, tol) -> np.ndarray:
    """States (``LineState`` values, ``(n_lines,)`` int8) of dynamic lines from their nodes
    (module docstring): ``anchors``, ``fairleads`` [m] ``(n_lines, dim)``, unstretched
    ``lengths`` [m], ``nodes`` one ``(n, dim)`` array per line from the anchor to the
    fairlead [m], ``seabed_z`` [m] and ``tol`` [m] per line."""
    out = np.empty(len(nodes), np.int8)
    for i, x in enumerate(nodes):
        d = np.asarray(fairleads[i], float) - np.asarray(anchors[i], float)
        h, X = float(d[-1]), float(np.linalg.norm(d[:-1]))
        if math.hypot(X, h) >= lengths[i]:
            out[i] = TAUT
        elif X <= lengths[i] - h:
            out[i] = RESTING
        else:
            grounded = (np.asarray(x, float)[1:-1, -1] <= seabed_z[i] + tol[i]).any()
            out[i] = PARTLY_LIFTED if grounded else FULLY_LIFTED
    return out


class LineStateLog:
    """State changes of ``names`` (one per line), fed by :meth:`update`."""

    def __init__(self, names):
        self.names = list(names)
        self.state = None  #: the states last seen, (n_lines,) int8
        self.initial = None  #: the states at the start
        self.events = {n: {"lifted": [], "touched_down": [], "taut": [], "slack": []} for n in self.names}

    def update(self, t: float, states) -> None:
        """The lines' states (``LineState`` values) at time ``t`` [s]."""
        s = np.asarray(states, dtype=np.int8).copy()
        if self.state is None:
            self.state, self.initial = s, s.copy()
            return
        was_lifted, lifted = self.state >= FULLY_LIFTED, s >= FULLY_LIFTED
        was_taut, taut = self.state == TAUT, s == TAUT
        for i, name in enumerate(self.names):
            ev = self.events[name]
            for key, on in (("lifted", lifted[i] and not was_lifted[i]), ("touched_down", was_lifted[i] and
                                                                          not lifted[i]),
                            ("taut", taut[i] and not was_taut[i]), ("slack", was_taut[i] and not taut[i])):
                if on and len(ev[key]) < MAX_EVENTS:
                    ev[key].append(float(t))
        self.state = s

    def summary(self) -> dict:
        """Per line: its state at the start and now, the first time it became fully lifted
        and taut (None: never), and every such change [s]."""
        out = {}
        for i, name in enumerate(self.names):
            ev = self.events[name]
            out[name] = {
                "initial_state": None if self.initial is None else LineState(int(self.initial[i])).name,
                "state": None if self.state is None else LineState(int(self.state[i])).name,
                "first_fully_lifted_s": ev["lifted"][0] if ev["lifted"] else None,
                "first_taut_s": ev["taut"][0] if ev["taut"] else None,
                "fully_lifted_s": list(ev["lifted"]), "touched_down_s": list(ev["touched_down"]),
                "taut_s": list(ev["taut"]), "slack_s": list(ev["slack"]),
            }
        return out

    def save(self):
        return (None if self.state is None else self.state.copy(), None if self.initial is None else
                self.initial.copy(), {n: {k: list(v) for k, v in e.items()} for n, e in self.events.items()})

    def load(self, saved) -> None:
        state, initial, events = saved
        self.state = None if state is None else state.copy()
        self.initial = None if initial is None else initial.copy()
        self.events = {n: {k: list(v) for k, v in e.items()} for n, e in events.items()}


__all__ = ["LineStateLog", "MAX_EVENTS", "node_states"]
