"""Issue 20's lever "evaluate each pair once instead of twice", measured on a prototype
(not a test, not used by the solver): the pair loop of ``fluid.equations.interact`` for
the 3-D dam break of ``benchmarks/fluid_throughput.py`` (Wendland, artificial viscosity,
Fourtakas diffusion, dynamic boundaries, float64), written so that each pair within the
support is visited once: particle ``a`` visits only the rows of cells ahead of it (z + 1,
and y + 1 in its own z) and, in its own row, the particles after it; every term is added
to ``a`` and, with the sign and the mass or volume of ``a``, to ``b`` (continuity and
the 8-norm of the viscous term are symmetric in the pair, momentum and diffusion
antisymmetric: Sunara et al. 2021, Eq. 5-7 with ``m_a`` for ``m_b``). The inner loop stays
contiguous in ``b``, so the writes to ``b`` are vector loads and stores; they conflict
between threads, so the prototype is serial, compared with the loop as it is on one thread.

    NUMBA_NUM_THREADS=1 python benchmarks/pair_once.py [--dp 0.017] [--steps 30] [--repeat 10]

Prints the largest difference of the rates from the loop as it is (relative to each
field's largest value: round-off, the sums run in another order) and the CPU time of
each loop, best of ``--repeat`` alternating calls, on the state after ``--steps`` steps.

Measured on the 3-D dam break: the rates equal to round-off, the pair-once loop **0.76 times
the speed of the loop as it is, so not adopted** (the writes to b cost more than the halved
arithmetic saves); the figures: docs/benchmarks/pair_once.md.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np
from numba import njit, uint64

from fluid.equations import (CS, DRHO, ISF, KAP, MASS, P_AD, P_ALPHA, P_AWALL, P_DDT, P_F32, P_FADE, P_G, P_H,
                             P_HYDRO, P_NU4, P_RENORM, P_XSPH, PAD, PR2, RHO, VISC, VOL, VX, VY, VZ, X, Y, Z)
from fluid.kernels import grad_scale, grad_shape
from fluid.neighbours import XBINS, cell_coords, row_range_binned


@njit(fastmath=True, error_model="numpy")
def pair_once(S, n, start, tab, lo, cell, nx, ny, nz, kernel, prm, acc_b):
    """Sums of every term over the pairs, each pair visited once (module docstring),
    into ``acc_b`` (6, n): continuity, diffusion, momentum x y z, the viscous 8-norm."""
    h = prm[P_H]
    ih = 1.0 / h
    avh = -prm[P_ALPHA] * h
    hgz = -0.5 * prm[P_HYDRO] * prm[P_G + 2]
    eta2 = 0.01 * h * h
    R2 = 4.0 * h * h
    inv_cell = 1.0 / cell
    inv_w = XBINS / cell
    acc_b[:] = 0.0
    for a in range(n):
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
        ma = S[MASS, a]
        va = S[VOL, a]
        cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)
        tz = za - lo[2] - cz * cell
        ty = ya - lo[1] - cy * cell
        ey_lo, ey_hi = ty * ty, (cell - ty) * (cell - ty)
        ez_hi = (cell - tz) * (cell - tz)
        qd = 0.0
        qdd = 0.0
        qx = 0.0
        qy = 0.0
        qz = 0.0
        qv = 0.0
        for r in range(5):  # the rows ahead: (dy, dz) = (-1..1, +1), (+1, 0); then its own
            if r < 3:
                dy, dz = r - 1, 1
                if dy != 0 and (ey_lo if dy < 0 else ey_hi) + ez_hi >= R2:
                    continue
            elif r == 3:
                dy, dz = 1, 0
            else:
                dy, dz = 0, 0
            j0, j1 = row_range_binned(xa, 2.0 * h, lo[0], inv_w, cy, cz, dy, dz, nx, ny, nz, start, tab, PAD)
            bmin = uint64(0)
            if r == 4:  # its own row, sorted by x: the particles after it, selected by a
                bmin = uint64(a + 1)  # 0/1 factor so that the range keeps its whole passes of PAD
                j0 += ((a + 1 - j0) // PAD) * PAD
            for b in range(uint64(j0), uint64(j1)):
                sel = 1.0 if b >= bmin else 0.0
                rx = xa - S[X, b]
                ry = ya - S[Y, b]
                rz = za - S[Z, b]
                vx = ux - S[VX, b]
                vy = uy - S[VY, b]
                vz = uz - S[VZ, b]
                r2 = rx * rx + ry * ry + rz * rz
                vr = vx * rx + vy * ry + vz * rz
                Fs = grad_shape(kernel, math.sqrt(r2) * ih) * sel
                fb = S[ISF, b]
                mask = max(fa, fb)
                Fm = Fs * mask
                rhob = S[RHO, b]
                e2 = r2 + eta2
                rs = rhoa + rhob
                d = 1.0 / (e2 * rs)
                inv = d * rs
                c = Fm * vr
                qd += S[MASS, b] * c
                acc_b[0, b] += ma * c
                dif = (rhob - rhoa - hgz * (ka + S[KAP, b]) * rz) * Fs * r2 * inv
                qdd += S[VOL, b] * dif
                acc_b[1, b] -= va * dif
                Pi = avh * (ca + S[CS, b]) * min(vr, 0.0) * d
                k = Fm * (pa + S[PR2, b] + Pi)
                qx -= S[MASS, b] * k * rx
                qy -= S[MASS, b] * k * ry
                qz -= S[MASS, b] * k * rz
                acc_b[2, b] += ma * k * rx
                acc_b[3, b] += ma * k * ry
                acc_b[4, b] += ma * k * rz
                m2 = (mask * sel if r2 < R2 else 0.0) * vr * inv
                m2 = m2 * m2
                m4 = m2 * m2
                qv += m4 * m4
                acc_b[5, b] += m4 * m4
        acc_b[0, a] += qd
        acc_b[1, a] += qdd
        acc_b[2, a] += qx
        acc_b[3, a] += qy
        acc_b[4, a] += qz
        acc_b[5, a] += qv


@njit(fastmath=True, error_model="numpy")
def finish(S, n, prm, Fc, acc_b, out, acc):
    """The per-particle factors the loop as it is applies after its sums."""
    h = prm[P_H]
    ddt = prm[P_DDT]
    for a in range(n):
        fa = S[ISF, a]
        out[DRHO, a] = Fc * (acc_b[0, a] - ddt * fa * acc_b[1, a])
        out[VISC, a] = h * math.sqrt(math.sqrt(math.sqrt(acc_b[5, a])))
        acc[a, 0] = Fc * acc_b[2, a] + fa * prm[P_G]
        acc[a, 1] = Fc * acc_b[3, a] + fa * prm[P_G + 1]
        acc[a, 2] = Fc * acc_b[4, a] + fa * prm[P_G + 2]


def captured_loop(dp: float, steps: int):
    """The 3-D dam break of ``benchmarks/fluid_throughput.py`` at spacing ``dp`` [m] after
    ``steps`` steps: the fluid and the arguments its next step passed to
    ``fluid.equations.interact``; stops unless they switch on the dam break's terms only
    (the prototypes' own)."""
    import sys
    from pathlib import Path

    import fluid.equations as eq
    from fluid.solver import Fluid

    sys.path.insert(0, str(Path(__file__).parent))
    from fluid_throughput import build  # takes this folder off sys.path again

    cfg, ps = build("3d", dp)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    for _ in range(steps):
        f.step(f.max_dt())
    seen = {}
    real = eq.interact

    def spy(*args):
        seen["args"] = args
        return real(*args)

    eq.interact = spy
    try:
        f.step(f.max_dt())
    finally:
        eq.interact = real
    args = seen["args"][:14]
    prm = args[9]
    for p, v in ((P_NU4, 0.0), (P_XSPH, 0.0), (P_RENORM, 0.0), (P_FADE, 0.0), (P_F32, 0.0), (P_AWALL, 1.0)):
        if prm[p] != v:
            raise SystemExit("the prototype covers the 3-D dam break's terms only")
    return f, args


def largest_difference(n: int, ref_out, ref_acc, new_out, new_acc) -> dict:
    """The largest difference of each rate (density, viscous term, acceleration) between two
    loops' outputs, relative to the field's largest value."""
    pairs = {"drho": (ref_out[DRHO, :n], new_out[DRHO, :n]), "visc": (ref_out[VISC, :n], new_out[VISC, :n]),
             "acc": (ref_acc, new_acc)}
    return {k: float(np.abs(u - v).max() / np.abs(u).max()) for k, (u, v) in pairs.items()}


def main(argv=None) -> None:
    import numba

    import fluid.equations as eq
    from machine import cpu_name

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dp", type=float, default=0.017)
    ap.add_argument("--steps", type=int, default=30)
    ap.add_argument("--repeat", type=int, default=10)
    a = ap.parse_args(argv)
    _, (S, start, tab, lo, cell, nx, ny, nz, kernel, prm, out, acc, xs, G) = captured_loop(a.dp, a.steps)
    real = eq.interact
    n = acc.shape[0]
    Fc = grad_scale(kernel, prm[P_AD], prm[P_H])
    ref_out, ref_acc = np.zeros_like(out), np.zeros_like(acc)
    new_out, new_acc = np.zeros_like(out), np.zeros_like(acc)
    acc_b = np.zeros((6, S.shape[1]))

    def old():
        real(S, start, tab, lo, cell, nx, ny, nz, kernel, prm, ref_out, ref_acc, xs, G)

    def new():
        pair_once(S, n, start, tab, lo, cell, nx, ny, nz, kernel, prm, acc_b)
        finish(S, n, prm, Fc, acc_b, new_out, new_acc)

    old()
    new()
    for name, d in largest_difference(n, ref_out, ref_acc, new_out, new_acc).items():
        print(f"{name}: largest difference {d:.2e} of its largest value")
    t = {"as it is": [], "pair once": []}
    for _ in range(a.repeat):
        for key, fn in (("as it is", old), ("pair once", new)):
            c0 = time.process_time()
            fn()
            t[key].append(time.process_time() - c0)
    print(f"3-D dam break, {n} particles, dp {a.dp} m, {numba.get_num_threads()} thread(s), {cpu_name()}:")
    for key, v in t.items():
        print(f"  {key:10s} best {1e3 * min(v):7.1f} ms, median {1e3 * np.median(v):7.1f} ms CPU")
    print(f"  ratio (best) {min(t['as it is']) / min(t['pair once']):.2f}")


if __name__ == "__main__":
    main()
