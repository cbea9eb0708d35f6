"""Compiled kernels of the SPH cable (Dinçer & Demir 2020, Eq. 1-12).

Everything here is a numba ``njit`` function on plain arrays; the physics, the
derivations of the paper's ambiguous equations and the units are in docs/sph_cable.md and
:mod:`moorings.sph_cable`. One call of :func:`advance` runs the whole sub-cycling
loop from ``t0`` to ``t1`` inside compiled code.

Notation (1-D cable embedded in 2-D or 3-D, cross-section integrated): particle ``a``
has line density ``lam`` [kg/m], tension ``T`` [N], kernel mass ``mk`` [kg] (its full
segment, mirrored at the ends) and inertial mass ``m`` [kg]; segment ``k`` joins
particles ``k`` and ``k+1`` and has unstretched length ``ds[k]`` [m]. The Wendland C2
kernel with support 2h, h = ds, reaches the two neighbours of each particle, so every
SPH sum runs over the two segments next to a particle; ``wl``/``wr`` are the
renormalised (Dinçer & Demir 2020, Eq. 4) weights of its left and right neighbour (they sum to 1).
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

#: |dW/dr| h^2 of the 1-D Wendland C2 kernel W = 5/(8h) (1-q/2)^3 (1+3q/2) at q = 1
DW1 = 15.0 / 32.0


@njit(cache=True, fastmath=_FM, error_model="numpy")
def segments(x, e, ell):
    """Unit vectors ``e`` (n-1, dim) from particle k to k+1 and segment lengths ``ell`` [m]."""
    n, dim = x.shape
    for k in range(n - 1):
        r2 = 0.0
        for d in range(dim):
            dx = x[k + 1, d] - x[k, d]
            e[k, d] = dx
            r2 += dx * dx
        r = math.sqrt(r2)
        ell[k] = r
        inv = 1.0 / (r + 1e-300)
        for d in range(dim):
            e[k, d] *= inv


@njit(cache=True, fastmath=_FM, error_model="numpy")
def forces(x, v, lam, ds, m, mk, lam0, EA, c0, delta, alpha, beta, omega, fext, wl, wr, hyd, water_z, bed,
           e, ell, T, fseg, Tseg, grad, F, acc, dlam_diff, kfr):
    """Internal forces ``F`` [N], accelerations ``acc`` [m/s²], particle tension ``T`` [N]
    (renormalised mean of the two stress points), segment force ``fseg`` [N] and δ-SPH
    diffusion ``dlam_diff`` [kg/(m s)] of the state; ``e``/``ell`` must hold the segments of
    ``x``; ``Tseg`` (n-1,) gets the stress-point tensions [N].

    - Dinçer & Demir 2020, Eq. 6-9 on the axis, at the stress point midway between neighbours:
      ``T_k = EA max(0, l_k/ds_k - 1)``.
    - Dinçer & Demir 2020, Eq. 5: the pair term of neighbours a, b is the stress-point tension along the chord.
    - Dinçer & Demir 2020, Eq. 10-11: ``Pi_ab`` with mu from the chord; pair force ``mk_a mk_b Pi |W'|``;
      only on taut segments (the viscosity damps the stiff axial response; a slack cable
      has none, and a viscosity there would stop it folding -- the paper's varphi = 1
      made a slack cable fall ~100 times too slowly).
    - Dinçer & Demir 2020, Eq. 12 as mass-proportional damping ``-omega v``.
    - Morison drag and added mass in still water below ``water_z`` [m], per particle
      ``hyd[a] = (kn, kt, ma_n, ma_t)``: drag ``-kn |v_n| v_n - kt |v_t| v_t`` [N] and the
      mass matrix ``m I + ma_n (I - t t) + ma_t t t`` (t: the particle's tangent).
    - Seabed friction ``bed = (z_bed, mu, v_eps)``: a particle on the seabed pressed down by
      N gets ``-mu N v_h / max(|v_h|, v_eps)`` horizontally (Coulomb, regularised below
      ``v_eps`` [m/s]).
    """
    n, dim = x.shape
    # renormalised density gradient (Dinçer & Demir 2020, Eq. 3) for the δ-SPH term
    for a in range(n):
        g = 0.0
        if a > 0:
            g += wl[a] * (lam[a] - lam[a - 1]) / ds[a - 1]
        if a < n - 1:
            g += wr[a] * (lam[a + 1] - lam[a]) / ds[a]
        grad[a] = g
    for k in range(n - 1):
        # stress point of segment k: its own continuity gives lam_k = lam0 ds/l exactly, so
        # Dinçer & Demir 2020, Eq. 6-9 on the axis read T_k = EA max(0, l/ds - 1) (tension only)
        Tk = EA * max(0.0, ell[k] / ds[k] - 1.0)
        h = ds[k]
        vr = 0.0
        for d in range(dim):
            vr += (v[k, d] - v[k + 1, d]) * e[k, d]
        vr *= -ell[k]  # v_ab . r_ab with a = k, b = k+1, r_ab = x_k - x_{k+1}
        # only where the stress point is taut: a slack cable folds freely, with no wave to damp
        taut = 1.0 if ell[k] > ds[k] else 0.0
        mu = taut * h * min(vr, 0.0) / (ell[k] * ell[k] + 0.001 * h * h)
        pi_ab = (beta * mu * mu - alpha * mu * c0) / (0.5 * (lam[k] + lam[k + 1]))
        fseg[k] = Tk - mk[k] * mk[k + 1] * pi_ab * DW1 / (h * h)
        Tseg[k] = Tk
    for a in range(n):
        T[a] = (wl[a] * Tseg[a - 1] if a > 0 else 0.0) + (wr[a] * Tseg[a] if a < n - 1 else 0.0)
    for a in range(n):
        fl = fseg[a - 1] if a > 0 else 0.0
        fr = fseg[a] if a < n - 1 else 0.0
        dd = 0.0
        # δ-SPH (Dinçer & Demir 2020, Eq. 1-2): sum_b V_b psi_ab . grad W_ab, with V_b |W'| ds = weight
        if a > 0:
            psi = 2.0 * (lam[a - 1] - lam[a]) / ds[a - 1] + (grad[a] + grad[a - 1])
            dd += wl[a] * psi / ds[a - 1]
        if a < n - 1:
            psi = 2.0 * (lam[a + 1] - lam[a]) / ds[a] - (grad[a] + grad[a + 1])
            dd += wr[a] * psi / ds[a]
        dlam_diff[a] = delta * ds[min(a, n - 2)] * c0 * dd
        # tangent of the particle (chord of its two neighbours; the segment at the ends)
        tx0 = 0.0
        tx1 = 0.0
        tx2 = 0.0
        vt = 0.0
        for d in range(dim):
            el = e[a - 1, d] if a > 0 else 0.0
            er = e[a, d] if a < n - 1 else 0.0
            F[a, d] = fr * er - fl * el
        # seabed friction (regularised Coulomb) on particles resting on the seabed: the
        # coefficient kfr [N s/m] is applied implicitly in the kick (stable at any step)
        kfr[a] = 0.0
        if bed[1] > 0.0 and x[a, dim - 1] <= bed[0] + 1e-9 * ds[min(a, n - 2)]:
            N = max(0.0, -(F[a, dim - 1] + fext[a, dim - 1]))
            vh2 = 0.0
            for d in range(dim - 1):
                vh2 += v[a, d] * v[a, d]
            kfr[a] = bed[1] * N / max(math.sqrt(vh2), bed[2])
        wet = 1.0 if x[a, dim - 1] < water_z else 0.0
        kn = hyd[a, 0] * wet
        kt = hyd[a, 1] * wet
        man = hyd[a, 2] * wet
        mat = hyd[a, 3] * wet
        a0 = max(a - 1, 0)
        a1 = min(a + 1, n - 1)
        tn2 = 0.0
        for d in range(dim):
            td = x[a1, d] - x[a0, d]
            tn2 += td * td
        tinv = 1.0 / (math.sqrt(tn2) + 1e-300)
        tx0 = (x[a1, 0] - x[a0, 0]) * tinv
        tx1 = (x[a1, 1] - x[a0, 1]) * tinv
        if dim == 3:
            tx2 = (x[a1, 2] - x[a0, 2]) * tinv
        vt = v[a, 0] * tx0 + v[a, 1] * tx1 + (v[a, 2] * tx2 if dim == 3 else 0.0)
        vn2 = 0.0
        for d in range(dim):
            td = tx0 if d == 0 else (tx1 if d == 1 else tx2)
            vnd = v[a, d] - vt * td
            vn2 += vnd * vnd
        vn = math.sqrt(vn2)
        ftot_t = 0.0
        for d in range(dim):
            td = tx0 if d == 0 else (tx1 if d == 1 else tx2)
            vnd = v[a, d] - vt * td
            F[a, d] += -kn * vn * vnd - kt * abs(vt) * vt * td
        for d in range(dim):
            td = tx0 if d == 0 else (tx1 if d == 1 else tx2)
            ftot_t += (F[a, d] + fext[a, d]) * td
        inv_n = 1.0 / (m[a] + man)
        inv_t = 1.0 / (m[a] + mat)
        for d in range(dim):
            td = tx0 if d == 0 else (tx1 if d == 1 else tx2)
            ftd = F[a, d] + fext[a, d]
            acc[a, d] = (ftd - ftot_t * td) * inv_n + ftot_t * td * inv_t - omega * v[a, d]


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
def force_buffers(n, dim):
    """The work arrays of :func:`segments` and :func:`forces` for ``n`` particles in ``dim``
    dimensions: e, ell, T, fseg, Tseg, grad, F, acc, dld, kfr (kfr zeroed)."""
    return (np.empty((n - 1, dim)), np.empty(n - 1), np.empty(n), np.empty(n - 1), np.empty(n - 1), np.empty(n),
            np.empty((n, dim)), np.empty((n, dim)), np.empty(n), np.zeros(n))


@njit(cache=True, fastmath=_FM, error_model="numpy")
def advance(x, v, lam, ds, t0, t1, n_sub, m, mk, lam0, EA, c0, delta, alpha, beta, omega, fext, wl, wr,
            hyd, water_z, free, pidx, p0, v0, p1, v1, amp, om, t_on, t_off, bed, fend_mean, fend_last, tension):
    """Leap-frog from ``t0`` to ``t1`` [s] in ``n_sub`` equal sub-steps (Dinçer & Demir 2020, Section 2).

    Per sub-step: forces at (x^n, v^n, lam^n); kick v^{n+1} = v^n + dt a^n (free particles);
    drift x^{n+1} = x^n + dt v^{n+1}; prescribed particles placed at t^{n+1}; continuity
    (Dinçer & Demir 2020, Eq. 1) integrated exactly over the step: lam^{n+1} = lam^n exp(-D dt) + dt·δ-term,
    with D dt = wl ln(l^{n+1}/l^n)_left + wr ln(l^{n+1}/l^n)_right (in 1-D the velocity
    divergence is d ln(l)/dt). Returns (status, step, particle); status 0 is success.

    ``bed = (seabed_z, mu, v_eps)``: free particles are kept at or above ``seabed_z`` [m]
    (no penetration: the position is projected onto the seabed and a downward velocity
    removed; ``-inf`` for none), with friction coefficient ``mu`` [-] (see :func:`forces`).

    ``fend_mean``/``fend_last`` (n_presc, dim): force [N] the cable exerts on each prescribed
    particle's support, averaged over the sub-steps / at t1. ``tension`` (n,) gets T at t1.
    """
    n, dim = x.shape
    npr = pidx.shape[0]
    dt = (t1 - t0) / n_sub
    e, ell, T, fseg, Tseg, grad, F, acc, dld, kfr = force_buffers(n, dim)
    ell1 = np.empty(n - 1)
    lnr = np.empty(n - 1)
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
    segments(x, e, ell)
    for step in range(n_sub):
        t = t0 + step * dt
        forces(x, v, lam, ds, m, mk, lam0, EA, c0, delta, alpha, beta, omega, fext, wl, wr, hyd, water_z, bed,
               e, ell, T, fseg, Tseg, grad, F, acc, dld, kfr)
        if step > 0:
            prescribed_state(t, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, ppos, pvel, pacc)
        for i in range(npr):
            a = pidx[i]
            for d in range(dim):
                fend_mean[i, d] += F[a, d] + fext[a, d] - m[a] * pacc[i, d]
        bad = -1
        for a in range(n):
            fa = free[a]
            # friction: the exact Coulomb decrement while sliding (never reversing the motion),
            # implicit linear damping in the regularised range
            r = dt * kfr[a] / m[a]
            vh2 = 0.0
            for d in range(dim - 1):
                vh2 += v[a, d] * v[a, d]
            fr = max(0.0, 1.0 - r) if vh2 > bed[2] * bed[2] else 1.0 / (1.0 + r)
            for d in range(dim):
                v[a, d] += dt * acc[a, d] * fa
                if d < dim - 1:
                    v[a, d] *= fr
                x[a, d] += dt * v[a, d] * fa
            if x[a, dim - 1] < bed[0] and fa > 0.0:
                x[a, dim - 1] = bed[0]
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
        segments(x, e, ell1)
        for k in range(n - 1):
            lnr[k] = math.log(max(ell1[k], 1e-300) / max(ell[k], 1e-300))
            ell[k] = ell1[k]
        # continuity, Dinçer & Demir 2020, Eq. 1, exact increment over the step
        for a in range(n):
            Ddt = 0.0
            if a > 0:
                Ddt += wl[a] * lnr[a - 1]
            if a < n - 1:
                Ddt += wr[a] * lnr[a]
            lam[a] = lam[a] * math.exp(-Ddt) + dt * dld[a]
            if not lam[a] > 0.0:
                return COLLAPSED, step, a
    for i in range(npr):
        for d in range(dim):
            fend_mean[i, d] /= n_sub
    forces(x, v, lam, ds, m, mk, lam0, EA, c0, delta, alpha, beta, omega, fext, wl, wr, hyd, water_z, bed,
           e, ell, T, fseg, Tseg, grad, F, acc, dld, kfr)
    prescribed_state(t1, t0, t1, p0, v0, p1, v1, amp, om, t_on, t_off, ppos, pvel, pacc)
    for i in range(npr):
        a = pidx[i]
        for d in range(dim):
            fend_last[i, d] = F[a, d] + fext[a, d] - m[a] * pacc[i, d]
    for a in range(n):
        tension[a] = T[a]
    return OK, n_sub, -1


@njit(cache=True, fastmath=_FM, error_model="numpy")
def state_end_forces(x, v, lam, ds, m, mk, lam0, EA, c0, delta, alpha, beta, omega, fext, wl, wr, hyd, water_z, bed,
                     pidx, fend, tension):
    """The force [N] the cable exerts on each held end's support, ``fend`` (n_presc, dim),
    and the particle tensions ``tension`` [N] of the present state, as :func:`advance` gives
    them at its end (the held ends taken at rest): what a cable reports before its first
    advance."""
    n, dim = x.shape
    e, ell, T, fseg, Tseg, grad, F, acc, dld, kfr = force_buffers(n, dim)
    segments(x, e, ell)
    forces(x, v, lam, ds, m, mk, lam0, EA, c0, delta, alpha, beta, omega, fext, wl, wr, hyd, water_z, bed,
           e, ell, T, fseg, Tseg, grad, F, acc, dld, kfr)
    for i in range(pidx.shape[0]):
        for d in range(dim):
            fend[i, d] = F[pidx[i], d] + fext[pidx[i], d]
    for a in range(n):
        tension[a] = T[a]
