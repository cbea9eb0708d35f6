"""What a mooring line is to the body over one coupling step: a spring and a dashpot at
its fairlead, as each model reports them (``fairlead_stiffness()``), for the coupler's
stability limit (:mod:`cosim.line_step`).

:class:`FairleadStiffness` holds, per line, a stiffness ``k`` [N/m] and a damping ``c``
[N s/m], each a ``(dim, dim)`` matrix in world axes acting on the fairlead's displacement
and velocity (the line's force changes by ``-k dx - c dv``).

- A quasi-static law (the catenary, a catenary FMU) is a spring only: its tangent
  stiffness ``-dF/dx``, here by central differences of the force (:func:`by_differences`;
  the law answers at once, there is no state to disturb). ``c = 0``.
- A dynamic line of nodes (the SPH cable, MoorDyn) is, on the time scale of a coupling
  step, an elastic bar along its tangent at the fairlead (:func:`axial`): the suspended
  part, of unstretched length ``L_s`` (from the last node on the seabed to the fairlead),
  is a spring ``EA / L_s``; and an axial wave leaves the fairlead into the line, which
  therefore resists the fairlead's velocity with the bar's impedance ``sqrt(EA m)``
  [N s/m] (``m`` the mass per length; a semi-infinite bar, exact for times shorter than
  the wave's round trip ``2 L_s / sqrt(EA / m)``: 0.025 s on Barreiro et al. 2016's chain), plus the
  model's own axial damping on its first segment (``damping`` times the impedance: the
  SPH cable's artificial viscosity 15/32 alpha, MoorDyn's internal damping ratio).
  Bending, drag and the chain's transverse inertia are left out: they are slower.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FairleadStiffness:
    """Per line: stiffness ``k`` [N/m] and damping ``c`` [N s/m] at the fairlead, each
    ``(n_lines, dim, dim)``, world axes."""

    k: np.ndarray
    c: np.ndarray

    def zeroed(self, lines) -> "FairleadStiffness":
        """The same with the given lines (a boolean mask or indices) taken out (released)."""
        k, c = self.k.copy(), self.c.copy()
        k[lines] = 0.0
        c[lines] = 0.0
        return FairleadStiffness(k, c)


def by_differences(forces_at, positions, step: float = 1e-4, batched: bool = False) -> FairleadStiffness:
    """The tangent stiffness ``-dF/dx`` [N/m] of a quasi-static law, by central differences:
    ``forces_at(positions) -> (n_lines, dim)`` forces [N] for fairlead ``positions`` [m]
    ``(n_lines, dim)``; each fairlead is moved by ``step`` [m] along each axis (the lines
    are independent, so all lines move at once). ``batched``: ``forces_at`` takes the
    ``2 dim`` moved sets stacked, ``(2 dim n_lines, dim)``, in one call. ``c = 0``."""
    p0 = np.array(positions, dtype=float)
    n, dim = p0.shape
    moved = np.repeat(p0[None], 2 * dim, axis=0)
    for a in range(dim):
        moved[2 * a, :, a] += step
        moved[2 * a + 1, :, a] -= step
    if batched:
        f = np.asarray(forces_at(moved.reshape(2 * dim * n, dim)), float).reshape(2 * dim, n, dim)
    else:
        f = np.array([np.asarray(forces_at(p), float) for p in moved])
    k = np.stack([-(f[2 * a] - f[2 * a + 1]) / (2 * step) for a in range(dim)], axis=2)
    k = 0.5 * (k + np.transpose(k, (0, 2, 1)))  # the law is conservative: symmetric up to the differences
    return FairleadStiffness(k, np.zeros_like(k))


def axial(nodes, arc, EA: float, mass_per_length: float, seabed_z: float, tol: float,
          damping: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Spring and dashpot ``(k, c)``, each ``(dim, dim)``, of one dynamic line at its
    fairlead (module docstring): ``nodes`` [m] ``(n, dim)`` from the anchor to the
    fairlead, ``arc`` their unstretched arc lengths [m] from the anchor, nodes within
    ``tol`` [m] of ``seabed_z`` [m] lie on the seabed. ``k = EA / L_s e e^T``,
    ``c = (1 + damping) sqrt(EA m) e e^T``, ``e`` the tangent of the last segment."""
    x = np.asarray(nodes, float)
    on = np.flatnonzero(x[:-1, -1] <= seabed_z + tol)
    L_s = float(arc[-1] - arc[on[-1]]) if on.size else float(arc[-1] - arc[0])
    e = x[-1] - x[-2]
    norm = float(np.linalg.norm(e))
    e = e / norm if norm > 0 else np.eye(x.shape[1])[-1]
    ee = np.outer(e, e)
    return EA / max(L_s, 1e-12) * ee, (1.0 + damping) * math.sqrt(EA * mass_per_length) * ee


__all__ = ["FairleadStiffness", "axial", "by_differences"]
