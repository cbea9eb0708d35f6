"""The largest coupling step at which the bodies can follow their mooring lines: the
stability limit of the explicit exchange between a body and a stiff line.

The exchange this bound is derived for (:mod:`cosim.coupler`, ``lines="explicit"``, and
the quasi-static laws): a mooring's force on a body is taken at the start of a coupling
step and held over it while MuJoCo moves the body (RK4 sub-steps: the body's motion under
the held force is exact); then the line moves to the body's new fairlead. The coupler's
default for dynamic lines (``lines="subiterate"``) advances them with the bodies until the
bodies' force is the lines' mean force over the step; the coupler applies the same bound
to it, where it has margin (measured below).
Each model tells what its line is to the body over a step (``fairlead_stiffness()``,
:mod:`moorings.fairlead_stiffness`): a spring ``k`` and a dashpot ``c`` at the fairlead.

Derivation, one degree of freedom (mass ``M`` [kg] with the added mass in it, line force
``F = -k x - c v``): with the force of step n held, ``v' = v + dt F/M`` and
``x' = x + dt v + dt^2 F / (2M)``. With ``omega^2 = k/M``, ``zeta = c / (2 M omega)``,
``y = omega dt`` and ``u = v dt`` the update matrix is
``[[1 - y^2/2, 1 - zeta y], [-y^2, 1 - 2 zeta y]]``: trace ``2 - y^2/2 - 2 zeta y``,
determinant ``1 - 2 zeta y + y^2/2``. The Jury conditions (|det| < 1, 1 + tr + det > 0,
1 - tr + det > 0) give stability if and only if

    ``y < 4 zeta``  and  ``y < 1 / zeta``,  i.e.  ``dt < 2 c / k``  and  ``dt < 2 M / c``.

An undamped spring (``zeta = 0``) grows at every step size, by ``y^2 / 4`` per step (the
coupler's ``scheme`` docstring); the widest range, ``dt < 2 / omega``, is reached at
``zeta = 1/2``. What is applied (each bound in generalised coordinates: MuJoCo's
joint-space mass matrix, added mass included as armature, and the lines' ``k`` and ``c``
mapped through each fairlead site's Jacobian, ``K = sum J^T k J``):

- ``spring``: ``dt < 2 / omega_max``, ``omega_max^2`` the largest eigenvalue of
  ``K v = omega^2 M v``: beyond it every scheme of the coupler diverges within a few
  steps (the predictor-corrector's quasi-static lines too: its growth per step is
  ``(omega dt)^4 / 8`` below it, ``(1 + y^4/4)^(1/2)`` at it); below it the growth of an
  undamped line is slow and the fluid's damping holds it.
- ``dashpot``: ``dt < 2 / lambda_max``, ``lambda_max`` the largest eigenvalue of
  ``C v = lambda M v``: a dynamic line's axial impedance held over the step overshoots
  (the bound ``2 M / c`` above). For seed 004's chain (EA = 1.9e9 N, 442 kg/m) on the
  wind-turbine base this is the one that limits: the impedance of the three lines makes
  the base's roll and pitch overdamped (``zeta ~ 1``).
- The bound ``dt < 2 c / k`` (a lightly damped line) is not applied: the lines damp the
  bodies more than their axial impedance alone says (on the test's taut MoorDyn line the
  impedance gives ``zeta = 0.06``, i.e. ``dt < 0.002 s``, and the run is stable up to
  0.012 s: MoorDyn's internal damping over the whole line and its drag), and the
  quasi-static laws (``c = 0``) take their damping from the fluid.

Each bound is multiplied by its factor in :data:`SAFETY`: ``spring`` 0.5 (``dt < 1 /
omega``: inside the stable range ``omega dt < min(4 zeta, 1 / zeta)`` for any line damping
``1/4 < zeta < 1``; ``2 / omega`` itself is reached only at ``zeta = 1/2``), ``dashpot`` 0.8
(``2 M / c`` is the exact limit of a held dashpot).

Measured (2026-11-25, AMD EPYC, 2 cores, loaded; the coupling step swept with even steps,
a run counted unstable when its motion and tensions grow; ``tests/test_line_step.py``):

=============================================  ========  =========  ===============  ========
case                                           bound     derived    threshold        chosen
                                                         [s]        [s]              [s]
=============================================  ========  =========  ===============  ========
box on one vertical taut line, MoorDyn         spring    0.0167     0.012 - 0.013    0.0084
(2-D, 7.2 + 7.2 t, EA 1.4e9 N, 10 kg/m, 6.8 m)
wind-turbine base, MoorDyn (3 lines, 20 seg.)  dashpot   0.0062     0.0062 - 0.0080  0.0050
wind-turbine base, SPH cable (20 particles)    dashpot   0.0077     0.0095 - 0.0100  0.0061
=============================================  ========  =========  ===============  ========

(threshold: the largest step found stable - the smallest found unstable.) The derived bound
lies at 0.78-1.39 of the threshold, the chosen step at 0.62-0.80 of it. Not covered by the
table's criterion (a run whose motion does not grow): with the force held, the base on SPH
cables holds a limit cycle at the chosen step (0.03 rad/s, the tensions swinging by some
100 kN at ~28 Hz; the bound takes each line for a semi-infinite bar, whose radiation damps
the base, but the wave comes back from the anchor within four steps), and MoorDyn settles
only through its adapter's one-step lead (its fairlead moved from the body's new position
on by one step of its velocity; given the step's own start and end, 0.035 rad/s).

The sub-iterated exchange (the default for dynamic lines; ``benchmarks/line_step_sweep.py``
and ``tests/test_line_step.py``, same machine): the base settles at the chosen step,
1-3e-6 rad/s on SPH cables and on MoorDyn (no lead), 20 or 40 nodes, in 1.6-2.3 advances
of the lines per step on average, for 20-45 % more CPU than the held force. It settles at
twice the chosen step too (2.0-2.9 advances), where MoorDyn with the held force and its
lead does not; at three times it the SPH cables hold a limit cycle of 0.025 rad/s again
(MoorDyn settles up to four times it). So the coupler keeps this bound for both
exchanges: the SPH cable's margin is 2-3. The box on its stiff MoorDyn line does not grow
at 1.5 times the spring bound 2 / omega (0.025 s), where the held force does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: safety factor on each derived bound [-] (module docstring)
SAFETY = {"spring": 0.5, "dashpot": 0.8}


@dataclass(frozen=True)
class LineStepLimit:
    """The coupling step the moorings allow and what sets it."""

    dt: float  #: [s], the smaller bound times its ``SAFETY`` factor
    term: str  #: "spring" or "dashpot"
    mooring: str  #: the mooring participant's name
    line: str  #: the line that carries most of the critical mode
    body: str  #: the body that moves most in it
    omega: float  #: largest natural frequency of the bodies on the lines' springs [rad/s]
    rate: float  #: largest damping rate of the lines' dashpots on the bodies [1/s]

    def describe(self) -> str:
        what = (f"its fairlead spring against body '{self.body}' (omega = {self.omega:.4g} rad/s, dt < "
                f"{SAFETY['spring']:g} x 2/omega)" if self.term == "spring" else
                f"its axial impedance on body '{self.body}' (damping rate {self.rate:.4g} 1/s, dt < "
                f"{SAFETY['dashpot']:g} x 2/rate)")
        return f"mooring '{self.mooring}', line '{self.line}': {what}"


def limit(bodies, attachments, sites) -> LineStepLimit | None:
    """The largest stable coupling step [s] of the bodies on their mooring lines now
    (module docstring), or ``None`` where no mooring reports ``fairlead_stiffness()``
    or none is stiff. ``attachments``: the coupler's :class:`~cosim.coupler.MooringAttachment`
    records, ``sites`` their ``(site ids, body index)`` pairs."""
    import mujoco

    from cosim.protocol import LineStiffness

    m, d = bodies.model, bodies.data
    nv = m.nv
    K, C = np.zeros((nv, nv)), np.zeros((nv, nv))
    parts = []  # (mooring name, line name, J^T k J, J^T c J)
    J = np.zeros((3, nv))
    for a, (ids, _) in zip(attachments, sites):
        if not isinstance(a.mooring, LineStiffness):
            continue
        s = a.mooring.fairlead_stiffness()
        names = list(getattr(a.mooring, "line_names", None) or [ln.name for ln in a.mooring.lines])
        ax = [0, 2] if a.mooring.dim == 2 else [0, 1, 2]
        for i, sid in enumerate(ids):
            mujoco.mj_jacSite(m, d, J, None, int(sid))
            Ja = J[ax]
            Ki, Ci = Ja.T @ s.k[i] @ Ja, Ja.T @ s.c[i] @ Ja
            K += Ki
            C += Ci
            parts.append((a.mooring.name, names[i], Ki, Ci))
    if not parts:
        return None
    M = np.zeros((nv, nv))
    mujoco.mj_fullM(m, d, M)
    dofs = np.concatenate([np.arange(nv)[bodies.dofs(k)] for k in range(bodies.n_bodies)])
    Li = np.linalg.inv(np.linalg.cholesky(M[np.ix_(dofs, dofs)]))  # M = L L^T: A v = lam M v <=> L^-1 A L^-T
    found = {}
    for term, A in (("spring", K), ("dashpot", C)):
        As = A[np.ix_(dofs, dofs)]
        vals, vecs = np.linalg.eigh(Li @ (0.5 * (As + As.T)) @ Li.T)
        found[term] = (max(float(vals[-1]), 0.0), Li.T @ vecs[:, -1])
    omega, rate = math.sqrt(found["spring"][0]), found["dashpot"][0]
    bounds = {"spring": SAFETY["spring"] * 2.0 / omega if omega > 0 else math.inf,
              "dashpot": SAFETY["dashpot"] * 2.0 / rate if rate > 0 else math.inf}
    term = min(bounds, key=bounds.get)
    if math.isinf(bounds[term]):
        return None
    full = np.zeros(nv)
    full[dofs] = found[term][1]
    share = [float(full @ (Ki if term == "spring" else Ci) @ full) for _, _, Ki, Ci in parts]
    j = int(np.argmax(share))
    body = max(range(bodies.n_bodies), key=lambda k: float(np.abs(full[bodies.dofs(k)]).max()))
    return LineStepLimit(bounds[term], term, parts[j][0], parts[j][1], bodies.body_names[body], omega, rate)


__all__ = ["LineStepLimit", "SAFETY", "limit"]
