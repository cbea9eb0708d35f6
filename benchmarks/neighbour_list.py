"""Issue 20's lever "neighbour lists reused across steps with a skin", measured on a
prototype (not a test, not used by the solver): the pair loop of ``fluid.equations.interact``
for the 3-D dam break of ``benchmarks/fluid_throughput.py`` (Wendland, artificial viscosity,
Fourtakas diffusion, dynamic boundaries, float64), run over each particle's stored list of
neighbours within ``2h + skin`` (Verlet's list) instead of over the rows of cells.

A list built at one step holds every pair within 2h for as long as no particle has moved
more than ``skin / 2`` since (the Verlet criterion), so it can be reused for ``K`` steps
and the cell sort, the reordering of every array and the range look-ups are paid once per
``K``. In exchange the loop reads each neighbour through an index (a gather: eight
separate loads per 8-pair vector of each of the 13 quantities) where the row loop reads
contiguous particles. The prototype measures both sides on the same state:

* the loop over the lists, every term as the solver's, against the loop as it is
  (the rates must agree to round-off: terms beyond 2h are exactly zero in both);
* building the lists (``fluid.neighbours.neighbour_lists``: a sort on cells of
  ``2h + skin``, then a count and a fill pass, both parallel);
* ``K`` from the Verlet criterion at the dam break's fastest speed, Ritter's front
  ``2 sqrt(g H)`` (the dam break's largest speed), and at the state's own largest speed.

    NUMBA_NUM_THREADS=1 python benchmarks/neighbour_list.py [--dp 0.017] [--steps 30] [--skin 0.1,0.2,0.4]

Prints, per skin (in units of h), the pairs per particle, the CPU time of each loop (best of
``--repeat`` calls), of one build, ``K`` and the list's cost per step amortised over ``K``
(loop + (build + the fluid's sort and reordering) / K) against the rows' (loop + sort and
reordering, every step).

**Not adopted: the list loop alone is slower than the row loop at every skin** (a gathered
pair costs some three times a contiguous candidate); the measured figures:
docs/benchmarks/neighbour_list.md.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np
from numba import njit, prange

from fluid.equations import CS, ISF, KAP, MASS, P_ALPHA, P_G, P_H, P_HYDRO, PR2, RHO, VOL, VX, VY, VZ, X, Y, Z
from fluid.kernels import grad_scale, grad_shape


@njit(parallel=True, fastmath=True, error_model="numpy")
def listed_loop(S, order, offsets, nbr, kernel, prm, sums):
    """The sums of the loop as it is over the pairs of the lists, into ``sums`` (6, n):
    continuity, diffusion, momentum x y z, the viscous 8-norm (``pair_once.finish`` turns
    them into rates). Particle ``order[i]``'s neighbours are ``nbr[offsets[i]:offsets[i + 1]]``
    (int32 indices of ``S``)."""
    h = prm[P_H]
    ih = 1.0 / h
    avh = -prm[P_ALPHA] * h
    hgz = -0.5 * prm[P_HYDRO] * prm[P_G + 2]
    eta2 = 0.01 * h * h
    R2 = 4.0 * h * h
    for i in prange(order.shape[0]):
        a = order[i]
        xa = S[X, a]
        ya = S[Y, a]
        za = S[Z, a]
        ux = S[VX, a]
        uy = S[VY, a]
        uz = S[VZ, a]
        rhoa = S[RHO, a]
        pa = S[PR2, a]
        ka = S[KAP, a]
        fa = S[ISF, a]
        ca = S[CS, a]
        qd = 0.0
        qdd = 0.0
        qx = 0.0
        qy = 0.0
        qz = 0.0
        qv = 0.0
        for k in range(offsets[i], offsets[i + 1]):
            b = nbr[k]
            rx = xa - S[X, b]
            ry = ya - S[Y, b]
            rz = za - S[Z, b]
            vx = ux - S[VX, b]
            vy = uy - S[VY, b]
            vz = uz - S[VZ, b]
            r2 = rx * rx + ry * ry + rz * rz
            vr = vx * rx + vy * ry + vz * rz
            Fs = grad_shape(kernel, math.sqrt(r2) * ih)
            mask = max(fa, S[ISF, b])
            mbF = S[MASS, b] * mask * Fs
            rhob = S[RHO, b]
            e2 = r2 + eta2
            rs = rhoa + rhob
            d = 1.0 / (e2 * rs)
            inv = d * rs
            qd += mbF * vr
            qdd += S[VOL, b] * (rhob - rhoa - hgz * (ka + S[KAP, b]) * rz) * Fs * r2 * inv
            coef = mbF * (pa + S[PR2, b] + avh * (ca + S[CS, b]) * min(vr, 0.0) * d)
            qx -= coef * rx
            qy -= coef * ry
            qz -= coef * rz
            m2 = (mask if r2 < R2 else 0.0) * vr * inv
            m2 = m2 * m2
            m4 = m2 * m2
            qv += m4 * m4
        sums[0, a] = qd
        sums[1, a] = qdd
        sums[2, a] = qx
        sums[3, a] = qy
        sums[4, a] = qz
        sums[5, a] = qv


def best_cpu(fn, repeat: int) -> float:
    """The least CPU time [s] of ``repeat`` calls of ``fn``."""
    t = []
    for _ in range(repeat):
        c0 = time.process_time()
        fn()
        t.append(time.process_time() - c0)
    return min(t)


def main(argv=None) -> None:
    import numba

    import fluid.equations as eq
    from fluid.neighbours import neighbour_lists
    from machine import cpu_name
    from pair_once import captured_loop, finish, largest_difference

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dp", type=float, default=0.017)
    ap.add_argument("--steps", type=int, default=30)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--skin", default="0.1,0.2,0.4", help="skins to measure, in units of h")
    a = ap.parse_args(argv)
    f, (S, start, tab, lo, cell, nx, ny, nz, kernel, prm, out, acc, xs, G) = captured_loop(a.dp, a.steps)
    real = eq.interact
    n = acc.shape[0]
    h = prm[P_H]
    Fc = grad_scale(kernel, prm[eq.P_AD], h)
    pos = np.ascontiguousarray(S[X:Z + 1, :n].T)
    box_lo, box_hi = pos.min(axis=0) - 1e-9, pos.max(axis=0) + 1e-9
    ref_out, ref_acc = np.zeros_like(out), np.zeros_like(acc)
    new_out, new_acc = np.zeros_like(out), np.zeros_like(acc)
    sums = np.zeros((6, S.shape[1]))

    def row_loop():
        real(S, start, tab, lo, cell, nx, ny, nz, kernel, prm, ref_out, ref_acc, xs, G)

    row_loop()
    t_row = best_cpu(row_loop, a.repeat)
    t_sort = best_cpu(f._sort, a.repeat)  # what a reused list also saves: the sort, the reordering
    dt = f.max_dt()
    speed = float(np.sqrt((f.ps.vel ** 2).sum(axis=1)).max())
    g = abs(prm[P_G + 2])
    ritter = 2.0 * math.sqrt(g * 1.0)  # the 3-D case's column is 1 m high
    print(f"3-D dam break, {n} particles, dp {a.dp} m, h {h:.4g} m, after {a.steps + 1} steps, dt {dt:.3g} s, "
          f"{numba.get_num_threads()} thread(s), {cpu_name()}")
    print(f"  row loop (as it is): {1e3 * t_row:.1f} ms CPU, sort and reorder {1e3 * t_sort:.1f} ms; "
          f"largest speed now {speed:.3g} m/s, "
          f"Ritter's front 2 sqrt(gH) {ritter:.3g} m/s")
    for skin in (float(v) for v in a.skin.split(",")):
        radius = (2.0 + skin) * h
        perm, offsets, idx = neighbour_lists(pos, radius, box_lo, box_hi)
        nbr = perm[idx].astype(np.int32)
        t_build = best_cpu(lambda: neighbour_lists(pos, radius, box_lo, box_hi), max(1, a.repeat // 2))

        def list_loop():
            listed_loop(S, perm, offsets, nbr, kernel, prm, sums)
            finish(S, n, prm, Fc, sums, new_out, new_acc)

        list_loop()
        diff = max(largest_difference(n, ref_out, ref_acc, new_out, new_acc).values())
        t_list = best_cpu(list_loop, a.repeat)
        k_ritter = max(int(0.5 * skin * h / (ritter * dt)), 1)
        k_now = max(int(0.5 * skin * h / (max(speed, 1e-12) * dt)), 1)
        print(f"  skin {skin:.2f} h: {len(nbr) / n:.1f} pairs per particle, rates within {diff:.1e}; "
              f"list loop {1e3 * t_list:.1f} ms ({t_row / t_list:.2f} x the row loop's speed), "
              f"build {1e3 * t_build:.1f} ms; K {k_ritter} at Ritter's speed ({k_now} now): "
              f"list + (build + sort) / K {1e3 * (t_list + (t_build + t_sort) / k_ritter):.1f} ms against "
              f"rows + sort {1e3 * (t_row + t_sort):.1f} ms")


if __name__ == "__main__":
    main()
