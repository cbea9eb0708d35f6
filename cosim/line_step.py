"""The largest coupling step at which the bodies can follow their mooring lines: the
stability limit of the explicit exchange between a body and a stiff line.

The exchange this bound is derived for (:mod:`cosim.coupler`, ``lines="explicit"``, and
the quasi-static laws): a mooring's force on a body is taken at the start of a coupling
step and held over it while MuJoCo moves the body (RK4 sub-steps: the body's motion under
the held force is exact); then the line moves to the body's new fairlead. The coupler's
default for dynamic lines (``lines="subiterate"``) advances them with the bodies until the
bodies' force is the lines' mean force over the step; the coupler applies the same bound
to it, where it has margin (measured: docs/benchmarks/line_step_sweep.md).
Each model tells what its line is to the body over a step (``fairlead_stiffness()``,
:mod:`moorings.fairlead_stiffness`): a spring ``k`` and a dashpot ``c`` at the fairlead.

Derivation, one degree of freedom (mass ``M`` [kg] with the added mass, line force ``F =
-k x - c v`` held over the step): the Jury conditions on the update matrix give stability if
and only if ``dt < 2 c / k`` and ``dt < 2 M / c``; an undamped spring grows at every step
size. What is applied, in generalised coordinates (MuJoCo's joint-space mass matrix with
the added mass as armature, the lines' ``k`` and ``c`` mapped through each fairlead's
Jacobian, ``K = sum J^T k J``):

- ``spring``: ``dt < 2 / omega_max``, ``omega_max^2`` the largest eigenvalue of ``K v =
  omega^2 M v``: beyond it every scheme of the coupler diverges within a few steps.
- ``dashpot``: ``dt < 2 / lambda_max``, ``lambda_max`` the largest eigenvalue of ``C v =
  lambda M v``: a dynamic line's axial impedance held over the step overshoots.
- ``dt < 2 c / k`` is not applied: lines damp the bodies more than their axial impedance
  alone says, and the quasi-static laws (``c = 0``) take their damping from the fluid.

Each bound is multiplied by its factor in :data:`SAFETY` (``spring`` 0.5, ``dashpot`` 0.8).
The derivation in full and the thresholds measured against it (the derived bound lies at
0.78-1.39 of the measured one): docs/benchmarks/line_step_sweep.md.
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
