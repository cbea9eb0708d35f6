"""Compiled kernels of the SPH cable (seed 000, Dinçer & Demir 2020, Eq. 1-12).

Everything here is a numba ``njit`` function on plain arrays; the physics, the
derivations of the seed's ambiguous equations and the units are documented in
:mod:`moorings.sph_cable`. One call of :func:`advance` runs the whole sub-cycling
loop from ``t0`` to ``t1`` inside compiled code.

Notation (1-D cable embedded in 2-D or 3-D, cross-section integrated):
``lam`` line density [kg/m], ``T`` axial tension [N], ``mk`` kernel mass of a
particle [kg] (its full segment, also at the ends), ``m`` inertial mass [kg] (half a
segment at the ends, plus point masses), arc distance ``xi`` [m] along the current
(stretched) cable, 1-D Wendland C2 kernel with support ``2h``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: fast-math flags without "nnan"/"ninf", so the NaN checks survive
_FM = {"nsz", "arcp", "contract", "afn", "reassoc"}

#: status codes returned by :func:`advance`
OK = 0
NONFINITE = 1
COLLAPSED = 2


@njit(cache=True, fastmath=_FM, error_model="numpy", inline="always")
def dw_abs(xi, h):
    """|dW/dxi| [1/m²] of the 1-D Wendland C2 kernel W = 5/(8h) (1-q/2)^3 (1+3q/2),
    q = xi/h, support 2h (000_7d114ab96e048b26.txt, Section 2: Wendland C2, support 2h).
    Branch-free: zero beyond the support."""
    q = xi / h
    t = max(0.0, 1.0 - 0.5 * q)
    return 15.0 / (8.0 * h * h) * q * t * t


@njit(cache=True, fastmath=_FM, error_model="numpy")
def arc_coordinates(x, S):
    """Cumulative current arc length S[a] [m] of the polyline through the particles."""
    n, dim = x.shape
    S[0] = 0.0
    for k in range(n - 1):
        r2 = 0.0
        for d in range(dim):
            dx = x[k + 1, d] - x[k, d]
            r2 += dx * dx
        S[k + 1] = S[k] + math.sqrt(r2)


@njit(cache=True, fastmath=_FM, error_model="numpy")
def renormalisation(s, mk, lam0, h, K, Bn, Bn1):
    """The 1-D renormalisation factor of 000 Eq. 4 in the reference configuration:
    ``Bn1[a] = 1/sum_b V0_b |s_ab| |W'(s_ab)|`` (one-sided at the ends) and ``Bn`` the same
    with the end particles mirrored (their sum doubled). Constant in time (total Lagrangian)."""
    n = s.shape[0]
    for a in range(n):
        B = 0.0
        for b in range(max(0, a - K), min(n, a + K + 1)):
            if b != a:
                xi0 = abs(s[b] - s[a])
                B += mk[b] / lam0[b] * xi0 * dw_abs(xi0, h)
        Bn1[a] = 1.0 / B if B > 0.0 else 0.0
        if a == 0 or a == n - 1:
            B *= 2.0
        Bn[a] = 1.0 / B if B > 0.0 else 0.0


@njit(cache=True, fastmath=_FM, error_model="numpy")
def forces(x, v, lam, s, m, mk, lam0, EA, c0, h, K, delta, alpha, beta, omega, fext,
           Bn, Bn1, T, grad, F, acc, dlam_diff):
    """Internal pair forces ``F`` [N], accelerations ``acc`` [m/s²], the tension ``T`` [N]
    (000 Eq. 6-9 in 1-D, tension only) and the δ-SPH density diffusion ``dlam_diff``
    [kg/(m s)] (000 Eq. 1-3) of the current state. Kernels are evaluated on the material
    distance ``|s_a - s_b|`` (total Lagrangian); directions on the current chords."""
    n, dim = x.shape
    # pass 1: tension and renormalised density gradient (000 Eq. 3)
    for a in range(n):
        G = 0.0
        for b in range(max(0, a - K), min(n, a + K + 1)):
            if b != a:
                xi0 = abs(s[b] - s[a])
                sgn = 1.0 if b > a else -1.0
                G += mk[b] / lam0[b] * (lam[b] - lam[a]) * dw_abs(xi0, h) * sgn
        grad[a] = G * Bn1[a]
        # 000 Eq. 6-9 reduced to the axis: sigma = E (rho0/rho - 1), tension only
        T[a] = EA * max(0.0, lam0[a] / lam[a] - 1.0)
    # pass 2: momentum (000 Eq. 5, 10-12) and δ-SPH diffusion (000 Eq. 1-2); gather only
    for a in range(n):
        fa0 = 0.0
        fa1 = 0.0
        fa2 = 0.0
        dd = 0.0
        Pa = T[a] * Bn[a] / (lam0[a] * lam0[a])
        for b in range(max(0, a - K), min(n, a + K + 1)):
            if b == a:
                continue
            xi0 = abs(s[b] - s[a])
            sgn = 1.0 if b > a else -1.0
            w = dw_abs(xi0, h)
            # chord b - a and v_ab . r_ab (r_ab = x_a - x_b)
            r2 = 0.0
            vr = 0.0
            for d in range(dim):
                dx = x[b, d] - x[a, d]
                r2 += dx * dx
                vr -= (v[a, d] - v[b, d]) * dx
            rn = math.sqrt(r2) + 1e-12 * h
            # 000 Eq. 10-11 (Monaghan viscosity, only for approaching particles)
            mu = h * min(vr, 0.0) / (r2 + 0.001 * h * h)
            pi_ab = (beta * mu * mu - alpha * mu * c0) / (0.5 * (lam[a] + lam[b]))
            Pb = T[b] * Bn[b] / (lam0[b] * lam0[b])
            coef = mk[a] * mk[b] * (Pa + Pb - pi_ab) * w / rn
            fa0 += coef * (x[b, 0] - x[a, 0])
            fa1 += coef * (x[b, 1] - x[a, 1])
            if dim == 3:
                fa2 += coef * (x[b, 2] - x[a, 2])
            # δ-SPH (000 Eq. 1-2 in 1-D): psi_ab . grad_a W_ab
            psi = 2.0 * (lam[b] - lam[a]) / xi0 - (grad[a] + grad[b]) * sgn
            dd += mk[b] / lam0[b] * psi * w
        F[a, 0] = fa0
        F[a, 1] = fa1
        if dim == 3:
            F[a, 2] = fa2
        dlam_diff[a] = delta * h * c0 * dd
        inv_m = 1.0 / m[a]
        for d in range(dim):
            # 000 Eq. 12 read as mass-proportional (Rayleigh) damping: f = -omega m v
            acc[a, d] = (F[a, d] + fext[a, d]) * inv_m - omega * v[a, d]


@njit(cache=True, fastmath=_FM, error_model="numpy")
def prescribed_state(t, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, pos, vel, accel):
    """Position [m], velocity [m/s], acceleration [m/s²] of each prescribed particle at ``t``:
    a cubic Hermite curve through (p0, v0) at t0 and (p1, v1) at t1 (the coupler's fairlead
    motion) plus a harmonic term amp·sin(om (t - t_on)) active for t_on <= t <= t_off."""
    npr, dim = p0.shape
    D = t1 - t0
    tau = (t - t0) / D if D > 0.0 else 0.0
    t2 = tau * tau
    t3 = t2 * tau
    h00, h10, h01, h11 = 2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + tau, -2 * t3 + 3 * t2, t3 - t2
    d00, d10, d01, d11 = 6 * t2 - 6 * tau, 3 * t2 - 4 * tau + 1, -6 * t2 + 6 * tau, 3 * t2 - 2 * tau
    s00, s10, s01, s11 = 12 * tau - 6, 6 * tau - 4, -12 * tau + 6, 6 * tau - 2
    iD = 1.0 / D if D > 0.0 else 0.0
    for i in range(npr):
        on = 1.0 if (t >= t_on[i] and t <= t_off[i]) else 0.0
        ph = om[i] * (t - t_on[i])
        sn = math.sin(ph) * on
        cs = math.cos(ph) * on
        for d in range(dim):
            pos[i, d] = h00 * p0[i, d] + h10 * D * v0[i, d] + h01 * p1[i, d] + h11 * D * v1[i, d] + amp[i, d] * sn
            vel[i, d] = (d00 * p0[i, d] + d01 * p1[i, d]) * iD + d10 * v0[i, d] + d11 * v1[i, d] \
                + amp[i, d] * om[i] * cs
            accel[i, d] = (s00 * p0[i, d] + s01 * p1[i, d]) * iD * iD + (s10 * v0[i, d] + s11 * v1[i, d]) * iD \
                - amp[i, d] * om[i] * om[i] * sn


@njit(cache=True, fastmath=_FM, error_model="numpy")
def advance(x, v, lam, s, t0, t1, n_sub, m, mk, lam0, EA, c0, h, K, delta, alpha, beta, omega, fext,
            free, pidx, p0, v0, p1, v1, amp, om, t_on, t_off, seabed_z, fend_mean, fend_last, tension):
    """Leap-frog from ``t0`` to ``t1`` [s] in ``n_sub`` equal sub-steps (000 Section 2).

    Per sub-step: forces at (x^n, v^n, lam^n); kick v^{n+1} = v^n + dt a^n (free particles);
    drift x^{n+1} = x^n + dt v^{n+1}; prescribed particles placed at t^{n+1}; continuity
    (000 Eq. 1) integrated exactly over the step: lam^{n+1} = lam^n exp(-D dt) + dt·δ-term,
    with D dt the kernel-weighted mean of ln(xi^{n+1}/xi^n) (in 1-D the velocity divergence
    is d ln(xi)/dt). Returns (status, step, particle); status 0 is success.

    ``seabed_z`` [m]: free particles are kept at or above this height (no penetration: the
    position is projected onto the seabed and a downward velocity removed); ``-inf`` for none.

    ``fend_mean``/``fend_last`` (n_presc, dim): force [N] the cable exerts on each prescribed
    particle's support, averaged over the sub-steps / at t1. ``tension`` (n,) gets T at t1.
    """
    n, dim = x.shape
    npr = pidx.shape[0]
    dt = (t1 - t0) / n_sub
    S = np.empty(n)
    S1 = np.empty(n)
    Bn = np.empty(n)
    Bn1 = np.empty(n)
    renormalisation(s, mk, lam0, h, K, Bn, Bn1)
    T = np.empty(n)
    grad = np.empty(n)
    F = np.empty((n, dim))
    acc = np.empty((n, dim))
    dld = np.empty(n)
    ppos = np.empty((npr, dim))
    pvel = np.empty((npr, dim))
    pacc = np.empty((npr, dim))
    for i in range(npr):
        for d in range(dim):
            fend_mean[i, d] = 0.0
    prescribed_state(t0, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, ppos, pvel, pacc)
    for i in range(npr):
        for d in range(dim):
            x[pidx[i], d] = ppos[i, d]
            v[pidx[i], d] = pvel[i, d]
    arc_coordinates(x, S)
    for step in range(n_sub):
        t = t0 + step * dt
        forces(x, v, lam, s, m, mk, lam0, EA, c0, h, K, delta, alpha, beta, omega, fext, Bn, Bn1, T, grad, F, acc, dld)
        if step > 0:
            prescribed_state(t, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, ppos, pvel, pacc)
        for i in range(npr):
            a = pidx[i]
            for d in range(dim):
                fend_mean[i, d] += F[a, d] + fext[a, d] - m[a] * pacc[i, d]
        bad = -1
        for a in range(n):
            fa = free[a]
            for d in range(dim):
                v[a, d] += dt * acc[a, d] * fa
                x[a, d] += dt * v[a, d] * fa
            if x[a, dim - 1] < seabed_z and fa > 0.0:
                x[a, dim - 1] = seabed_z
                v[a, dim - 1] = max(v[a, dim - 1], 0.0)
            if not (math.isfinite(x[a, 0]) and math.isfinite(v[a, 0]) and math.isfinite(lam[a])):
                bad = a
        if bad >= 0:
            return NONFINITE, step, bad
        prescribed_state(t + dt, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, ppos, pvel, pacc)
        for i in range(npr):
            for d in range(dim):
                x[pidx[i], d] = ppos[i, d]
                v[pidx[i], d] = pvel[i, d]
        arc_coordinates(x, S1)
        # continuity, 000 Eq. 1, exact increment over the step
        for a in range(n):
            b0 = max(0, a - K)
            b1 = min(n, a + K + 1)
            num = 0.0
            den = 0.0
            for b in range(b0, b1):
                if b == a:
                    continue
                xi0 = abs(s[b] - s[a])
                xi = max(abs(S[b] - S[a]), 1e-12 * h)
                xi1 = max(abs(S1[b] - S1[a]), 1e-12 * h)
                wgt = mk[b] / lam0[b] * xi0 * dw_abs(xi0, h)
                num += wgt * math.log(xi1 / xi)
                den += wgt
            Ddt = num / den if den > 0.0 else 0.0
            lam[a] = lam[a] * math.exp(-Ddt) + dt * dld[a]
            if not lam[a] > 0.0:
                return COLLAPSED, step, a
        for a in range(n):
            S[a] = S1[a]
    for i in range(npr):
        for d in range(dim):
            fend_mean[i, d] /= n_sub
    forces(x, v, lam, s, m, mk, lam0, EA, c0, h, K, delta, alpha, beta, omega, fext, Bn, Bn1, T, grad, F, acc, dld)
    prescribed_state(t1, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, ppos, pvel, pacc)
    for i in range(npr):
        a = pidx[i]
        for d in range(dim):
            fend_last[i, d] = F[a, d] + fext[a, d] - m[a] * pacc[i, d]
    for a in range(n):
        tension[a] = T[a]
    return OK, n_sub, -1
