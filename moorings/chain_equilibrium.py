"""The static equilibrium of the SPH cable's own discrete chain: the shape an
:class:`~moorings.sph_cable.SPHCable` starts from so that it starts at rest.

Why not the continuous catenary: the SPH cable's tension is the stretch of the chord
between neighbours, ``T_k = EA max(0, l_k / ds_k - 1)`` (``moorings.sph_cable``). Nodes
placed on the continuous elastic catenary at their arc coordinates have chords shorter
than the arc between them by ``(kappa ds)^2 / 24`` (kappa the curvature); on a stiff line
that is more than the elastic stretch itself. The wind-turbine base's chain (EA = 1.9e9 N,
w = 3770 N/m, H = 24.4 kN: kappa ds = 2.37 m / 6.5 m at its 20 nodes, 1.15 / 6.5 at 40)
reads chord deficits of 5.5e-3 and 1.3e-3 against a stretch of at most 5e-5: on the law's
curve its fairlead force started at 36 and 82 kN against the law's 94.2 kN, and the nodes
jerked 22 and 6 mm into their own equilibrium. On this shape: 93.9 and 94.1 kN against the
law's 94.2, and no node moves (tests/test_cable_mooring.py).

The discrete chain (nodes 0 = anchor .. n-1 = fairlead, rest lengths ``ds_k``, weight
``W_k`` at node k, the half-segment shares ``w (ds_{k-1} + ds_k) / 2``; a frictionless
seabed through the anchor). Equilibrium of node k: ``T_k - T_{k-1} - W_k e_z + N_k e_z =
0``, with ``T_k`` the tension vector of segment k (from node k to k+1) and ``N_k >= 0``
the seabed's reaction. In the vertical plane through anchor and fairlead every segment's
horizontal component is the same ``H``; the vertical one falls by each node's weight going
down, ``V_{k-1} = V_k - W_k``, until it would turn downwards: that node is the touchdown,
resting on the bed with every node below it (their segments horizontal, tension H). Shot
from the fairlead down (each segment ``ds_k (1 + |T_k| / EA)`` long along ``T_k``), the
two unknowns (H, V at the fairlead) are found by Newton-type root finding (scipy's
``root``, MINPACK's hybrid method) so that the chain ends at the anchor: the touchdown on
the bed and the laid length reaching the anchor, or a fully suspended chain's last node on
it. The residuals are continuous where the touchdown moves from node to node (the segment
between them is then horizontal). Started from the continuous law's (H, V), which differs
by O(ds^2).
"""

from __future__ import annotations

import math

import numpy as np

from moorings.line import vertical_plane


def _shoot(H: float, V: float, X: float, Z: float, ds: np.ndarray, W: np.ndarray, EA: float):
    """Nodes (x, z) in the line's plane (anchor at 0, 0; fairlead at X, Z) shot down from
    the fairlead with fairlead tension (H, V), and the two residuals (anchor missed by)."""
    n = ds.size + 1
    x, z = np.empty(n), np.empty(n)
    x[-1], z[-1] = X, Z
    v = V
    for k in range(n - 2, -1, -1):  # segment k joins node k to k + 1
        T = math.hypot(H, v)
        le = ds[k] * (1.0 + T / EA)
        cx, cz = (H / T, v / T) if T > 0 else (0.0, 1.0)
        x[k], z[k] = x[k + 1] - le * cx, z[k + 1] - le * cz
        if k == 0:
            return x, z, (x[0], z[0])
        below = v - W[k]
        if below <= 0.0:  # node k touches down: it and every node below lie on the bed
            laid = np.cumsum(ds[:k][::-1])[::-1] * (1.0 + H / EA)  # distance of nodes 0..k-1 from node k
            x[:k], z[:k] = x[k] - laid, 0.0
            return x, z, (x[0], z[k])
        v = below
    raise AssertionError("unreachable")


def discrete_equilibrium(anchor, fairlead, ds, weights, EA: float, guess: tuple[float, float],
                         tol: float = 1e-10) -> tuple[np.ndarray, float, float] | None:
    """The equilibrium node positions ``(n, dim)`` [m] of the chain (module docstring) from
    ``anchor`` to ``fairlead`` (world frame, z last), with rest lengths ``ds`` [m] (n - 1),
    node weights ``weights`` [N] (n; the ends' are carried by the supports), axial
    stiffness ``EA`` [N], on a frictionless seabed through the anchor; and
    the fairlead tension's (H, V) [N]. ``guess``: (H, V) to start from (the continuous
    law's). None if the root finding does not reach ``tol`` of the line's length (the
    caller falls back to the continuous shape)."""
    from scipy.optimize import root

    ds, W = np.asarray(ds, float), np.asarray(weights, float)
    X, Z, in_world = vertical_plane(anchor, fairlead)
    length = float(ds.sum())
    scale = max(float(W.sum()), 1e-12)  # forces in units of the line's weight

    def residual(u):
        _, _, end = _shoot(u[0] * scale, u[1] * scale, X, Z, ds, W, EA)
        return np.array(end) / length

    sol = root(residual, np.array(guess, float) / scale, method="hybr", options={"xtol": 1e-13})
    H, V = sol.x * scale
    if not np.all(np.isfinite(sol.x)) or H < 0.0 or np.max(np.abs(residual(sol.x))) > tol:
        return None
    pos = in_world(*_shoot(H, V, X, Z, ds, W, EA)[:2])
    pos[0], pos[-1] = anchor, fairlead
    return pos, float(H), float(V)
