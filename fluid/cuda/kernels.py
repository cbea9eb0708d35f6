"""CUDA kernels of the GPU path (numba-cuda): cell build and sort, the pair loop, the
integrators, the time-step reductions, the NaN guard and the group loads.

The formulas of the SPH terms (kernel, equation of state, the pair and particle terms
of the rates, the linear solves) are those of :mod:`fluid.terms`, compiled here as device
functions (``tm``) from the same code the CPU loops compile; each kernel walks its
neighbours and sums the terms in the CPU function's order, so that the two paths agree
to round-off in float64. A new term is written there once and called here as
``tm.term(...)`` (docs/fluid_equations.md, "The terms, written once"):

* :func:`k_bin` is ``fluid.neighbours.bin_particles``; :func:`k_fill` and
  :func:`k_order` together are ``counting_sort`` followed by ``order_cells_by_x``:
  the fill by atomics leaves a cell's particles in any order, and the insertion sort by
  (x, index before the sort) restores the CPU's (a stable counting sort keeps the index
  order, a stable insertion sort by x then sorts on x), so both paths hold the same
  particles in the same rows.
* :func:`make_pair_loop` is ``fluid.equations._make_interact`` (Barreiro et al. 2016,
  Eq. 6-8, Sunara et al. 2021, Eq. 6, the density diffusions and the laminar
  viscosity and XSPH of fluid.equations' docstring). It walks the whole row of three
  cells where the CPU loop walks the row trimmed to 2h in x: what it adds lies beyond
  2h, where every term is exactly zero (the kernel factors are clamped), so the sums hold
  the same non-zero terms in the same order; the CPU loop sums them in vector lanes, so
  the two differ by round-off only.
* :func:`make_gradient_loop` is ``fluid.equations._make_gradient`` (the renormalised
  gradients of ``diffusion="antuono"``); :func:`k_adami` is
  ``fluid.wall_density.adami_wall_density``; :func:`k_mdbc` is
  ``fluid.boundary_correction.mdbc_density``; :func:`k_mls` is ``fluid.mls.mls_density``
  (these three walk whole rows of cells, as their CPU functions do).
* :func:`k_relax` is ``fluid.relaxation.Slab.apply`` (``fluid.nearfield._relax_to_sea``
  towards a sea) and :func:`k_surface` ``fluid.probes._surface`` (a thread a gauge).
* :func:`k_predictor`, :func:`k_corrector`, :func:`k_verlet` are those of
  ``fluid.integrator``, from the same terms (``fluid.terms.predictor_density`` ...);
  :func:`d_block_max3` (in the pair loop) its ``_bounds``; :func:`k_first_non_finite` its
  ``first_non_finite`` (the lowest row, as the CPU's serial scan finds).

Particle arrays are structures of arrays: positions, velocities (and accelerations) as
``(dim, capacity)`` rows (x, z in 2-D; x, y, z in 3-D), scalars as ``(capacity,)``; only
the first ``n`` columns hold particles.
"""

from __future__ import annotations

import math
import types

import numpy as np
from numba import cuda

from fluid import equations as eq
from fluid import neighbours, probes, relaxation, terms, waves
from fluid.wall_density import SW_MIN

#: threads per block of every kernel
TPB = 128
#: most blocks of a launch (every kernel loops over its items with the grid's stride)
MAX_BLOCKS = 65535
def _simulator() -> bool:
    from fluid.cuda import simulator
    return simulator()


#: the launch on numba's CUDA simulator, which runs each thread as a Python thread: two
#: blocks of a few threads (the grid-stride loops and the block reduction still run over
#: several blocks), so that starting threads does not cost more than the kernels' work
SIM_LAUNCH = (2, 8)
_SIM = None


def launch(n: int) -> tuple:
    """(blocks, threads per block) for ``n`` items: enough blocks of :data:`TPB` threads,
    or :data:`SIM_LAUNCH` on the simulator. Results do not depend on it (but for the
    order of atomic sums)."""
    global _SIM
    if _SIM is None:
        _SIM = _simulator()
    if _SIM:
        return SIM_LAUNCH
    return min(MAX_BLOCKS, max(1, (n + TPB - 1) // TPB)), TPB


# ------------------------------------------------------------------ the terms of fluid.terms
#: every term of :mod:`fluid.terms` as a device function: the kernels call ``tm.term(...)``
tm = terms.compiled(cuda.jit(device=True), name="cuda")
#: the cell walk of :mod:`fluid.neighbours` as device functions, from the CPU's code: a
#: point's cell (clamped at the box) and the index range of a row of three cells
cell_coords = cuda.jit(device=True)(neighbours.cell_coords.py_func)
row_range = cuda.jit(device=True)(neighbours.row_range.py_func)


@cuda.jit(device=True)
def d_first_at_or_above(P, j0, j1, x):
    """First row in [j0, j1) whose x is at least ``x`` (j1 if none): a binary search in a
    row of cells, which the sort keeps ordered by x as a whole."""
    while j0 < j1:
        m = (j0 + j1) // 2
        if P[0, m] < x:
            j0 = m + 1
        else:
            j1 = m
    return j0


# ------------------------------------------------------------------ cell list
@cuda.jit
def k_bin(P, n, lo, inv_cell, nx, ny, nz, cell, count):
    """``bin_particles``: the cell of every particle (``nx ny nz`` outside), and its count
    into ``count[cell + 1]``."""
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        three = P.shape[0] == 3
        zc = P.shape[0] - 1
        fx = (P[0, i] - lo[0]) * inv_cell
        fz = (P[zc, i] - lo[zc]) * inv_cell
        fy = (P[1, i] - lo[1]) * inv_cell if three else 0.0
        ok = (fx >= 0.0) and (fz >= 0.0) and (fy >= 0.0) and (fx < nx) and (fy < ny) and (fz < nz)
        if ok:
            c = int(fx) + nx * (int(fy) + ny * int(fz))
        else:
            c = nx * ny * nz
        cell[i] = c
        cuda.atomic.add(count, c + 1, 1)


#: entries of the offsets array each thread of the scan sums in turn (fewer on the
#: simulator, so that its small grids take the scan's recursion too)
SCAN_CHUNK = 4 if _simulator() else 256


@cuda.jit
def k_scan_chunks(a, m, sums):
    """Inclusive scan of ``a[0:m]`` within each chunk of :data:`SCAN_CHUNK`; the chunk's
    total into ``sums``."""
    for t in range(cuda.grid(1), (m + SCAN_CHUNK - 1) // SCAN_CHUNK, cuda.gridsize(1)):
        j0 = t * SCAN_CHUNK
        j1 = min(j0 + SCAN_CHUNK, m)
        s = 0
        for j in range(j0, j1):
            s += a[j]
            a[j] = s
        sums[t] = s


@cuda.jit
def k_scan_add(a, m, sums):
    """Add the total of the preceding chunks (``sums`` scanned) to every entry of ``a``."""
    for j in range(cuda.grid(1), m, cuda.gridsize(1)):
        c = j // SCAN_CHUNK
        if c > 0:
            a[j] += sums[c - 1]


@cuda.jit
def k_copy_i4(a, m, out):
    for j in range(cuda.grid(1), m, cuda.gridsize(1)):
        out[j] = a[j]


@cuda.jit
def k_fill(cell, n, fill, perm):
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        j = cuda.atomic.add(fill, cell[i], 1)
        perm[j] = i


@cuda.jit
def k_order(perm, start, P, ncells):
    """Each cell's particles ordered by (x, index before the sort), the CPU's order
    (module docstring); the outside cell ``ncells`` by index only."""
    for c in range(cuda.grid(1), ncells + 1, cuda.gridsize(1)):
        j0 = start[c]
        j1 = start[c + 1]
        by_x = c < ncells
        for j in range(j0 + 1, j1):
            p = perm[j]
            x = P[0, p]
            i = j - 1
            while i >= j0:
                q = perm[i]
                if by_x:
                    later = P[0, q] > x or (P[0, q] == x and q > p)
                else:
                    later = q > p
                if not later:
                    break
                perm[i + 1] = q
                i -= 1
            perm[i + 1] = p


@cuda.jit
def k_gather2(src, dst, perm, n):
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        j = perm[i]
        for k in range(src.shape[0]):
            dst[k, i] = src[k, j]


@cuda.jit
def k_gather1(src, dst, perm, n):
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        dst[i] = src[perm[i]]


@cuda.jit
def k_slots(ids, n, slot):
    """Row of every particle by its id (the map :func:`k_place` reads)."""
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        slot[ids[i]] = i


@cuda.jit
def k_place(slot, ids, pos, vel, P, V):
    """Place the particles ``ids``: positions ``pos`` and velocities ``vel`` (m, dim)."""
    for k in range(cuda.grid(1), ids.shape[0], cuda.gridsize(1)):
        i = slot[ids[k]]
        for d in range(P.shape[0]):
            P[d, i] = pos[k, d]
            V[d, i] = vel[k, d]


# ------------------------------------------------------------------ equation of state
@cuda.jit
def k_pack(rho, n, rho0, c0, gamma, cs, pr2):
    """``fluid.equations.pack``'s per-particle part: sound speed and p / rho^2."""
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        B = c0 * c0 * rho0 / gamma
        e = 0.5 * (gamma - 1.0)
        r = rho[i]
        pi, c = tm.tait(r, rho0, c0, gamma, B, e)
        cs[i] = c
        pr2[i] = pi / (r * r)


# ------------------------------------------------------------------ the pair loop
_PAIR_LOOPS = {}


def make_pair_loop(kernel: int, three: bool, laminar: bool, xsph: bool, wall_visc: bool, fade: bool,
                   renorm: bool = False):
    """The pair loop compiled for one kernel, dimension and choice of optional terms (the
    closure's constants fold away, as in fluid.equations._make_interact). Writes, for
    every particle a < n: ``drho[a]``, ``acc[:, a]`` and, with XSPH, ``xs[:, a]``
    (fluid.equations.interact; with ``renorm`` the density diffusion of Antuono et al.
    with the gradients ``G`` of :func:`make_gradient_loop`), and the time step's three
    bounds into ``bounds``
    (:func:`d_block_max3`; the viscous term of Eq. 14 is used there and not stored)."""
    key = (kernel, three, laminar, xsph, wall_visc, fade, renorm)
    if key in _PAIR_LOOPS:
        return _PAIR_LOOPS[key]
    P_H, P_AD, P_ALPHA, P_DDT, P_HYDRO = eq.P_H, eq.P_AD, eq.P_ALPHA, eq.P_DDT, eq.P_HYDRO
    P_RHO0, P_G, P_NU4, P_XSPH, P_AWALL = eq.P_RHO0, eq.P_G, eq.P_NU4, eq.P_XSPH, eq.P_AWALL
    s0, s1 = eq.SURFACE_FADE
    zc = 2 if three else 1

    @cuda.jit
    def pair_loop(P, V, rho, mass, kind, cs, pr2, n, start, lo, cell, nx, ny, nz, prm, drho, acc, xs, bounds, G):
        sh_a = cuda.shared.array(TPB, np.float64)
        sh_v = cuda.shared.array(TPB, np.float64)
        sh_c = cuda.shared.array(TPB, np.float64)
        am = 0.0
        cvm = 0.0
        cm = 0.0
        for a in range(cuda.grid(1), n, cuda.gridsize(1)):
            h = prm[P_H]
            ad = prm[P_AD]
            ddt = prm[P_DDT]
            nu4 = prm[P_NU4]
            awall = prm[P_AWALL]
            eps2 = 2.0 * prm[P_XSPH] * ad
            gx = prm[P_G]
            gy = prm[P_G + 1] if three else 0.0
            gz = prm[P_G + 2] if three else prm[P_G + 1]
            Fc = tm.kernel_grad_scale(kernel, ad, h)
            avh = -prm[P_ALPHA] * h
            hgx = -0.5 * prm[P_HYDRO] * gx
            hgy = -0.5 * prm[P_HYDRO] * gy
            hgz = -0.5 * prm[P_HYDRO] * gz
            tilted = gx != 0.0 or gy != 0.0
            irho0 = 1.0 / prm[P_RHO0]
            eta2 = 0.01 * h * h
            R2 = 4.0 * h * h
            ih = 1.0 / h
            inv_cell = 1.0 / cell
            xa = P[0, a]
            ya = P[1, a] if three else 0.0
            za = P[zc, a]
            ux = V[0, a]
            uy = V[1, a] if three else 0.0
            uz = V[zc, a]
            rhoa = rho[a]
            pa = pr2[a]
            ca = cs[a]
            ka = rhoa / (ca * ca)
            fa = 1.0 if kind[a] == 0 else 0.0
            if renorm:
                gxa = G[0, a]
                gya = G[1, a] if three else 0.0
                gza = G[zc, a]
            cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)
            sd = 0.0
            sdd = 0.0
            sx = 0.0
            sy = 0.0
            sz = 0.0
            lx = 0.0
            ly = 0.0
            lz = 0.0
            wx = 0.0
            wy = 0.0
            wz = 0.0
            vmax = 0.0
            gsx = 0.0
            gsy = 0.0
            gsz = 0.0
            tz = za - lo[2] - cz * cell
            ty = ya - lo[1] - cy * cell
            ez_lo = tz * tz
            ez_hi = (cell - tz) * (cell - tz)
            ey_lo = ty * ty
            ey_hi = (cell - ty) * (cell - ty)
            dys = 3 if three else 1
            for dz in range(-1, 2):
                for k in range(dys):
                    dy = k - 1 if three else 0
                    if three and dy != 0 and dz != 0:
                        ey2 = ey_lo if dy < 0 else ey_hi
                        ez2 = ez_lo if dz < 0 else ez_hi
                        if ey2 + ez2 >= R2:
                            continue
                    j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, 1)
                    j0 = d_first_at_or_above(P, j0, j1, xa - 2.0 * h)
                    j1 = d_first_at_or_above(P, j0, j1, xa + 2.0 * h)
                    for b in range(j0, j1):
                        rx = xa - P[0, b]
                        rz = za - P[zc, b]
                        vx = ux - V[0, b]
                        vz = uz - V[zc, b]
                        if three:
                            ry = ya - P[1, b]
                            vy = uy - V[1, b]
                            r2 = rx * rx + ry * ry + rz * rz
                            vr = vx * rx + vy * ry + vz * rz
                        else:
                            ry = 0.0
                            vy = 0.0
                            r2 = rx * rx + rz * rz
                            vr = vx * rx + vz * rz
                        q = math.sqrt(r2) * ih
                        Fs = tm.kernel_grad_shape(kernel, q)
                        fb = 1.0 if kind[b] == 0 else 0.0
                        mask = max(fa, fb)
                        mb = mass[b]
                        mbm = mb * mask
                        mbF = mbm * Fs
                        rhob = rho[b]
                        cb = cs[b]
                        e2, d, inv = tm.pair_division(r2, eta2, rhoa + rhob)
                        sd += tm.continuity(mbF, vr)
                        volb = mb / rhob if fb > 0.0 else 0.0
                        if renorm:
                            rhoH = tm.renormalised_hydrostatic(gxa, gya, gza, G[0, b], G[1, b] if three else 0.0,
                                                               G[zc, b], rx, ry, rz, three)
                        else:
                            rhoH = tm.fourtakas_hydrostatic(hgx, hgy, hgz, rx, ry, rz, ka, rhob / (cb * cb), tilted)
                        sdd += tm.density_diffusion(volb, rhoa, rhob, rhoH, Fs, r2, inv)
                        if fade:
                            vf = tm.support_volume(volb, fb, mb, irho0) * Fs
                            gsx += vf * rx
                            gsy += vf * ry
                            gsz += vf * rz
                        Pi = tm.artificial_viscosity(avh, ca, cb, vr, d)
                        if wall_visc:
                            Pi *= tm.wall_viscosity(awall, fa, fb)
                        coef = tm.momentum(mbF, pa, pr2[b], Pi)
                        sx -= coef * rx
                        sy -= coef * ry
                        sz -= coef * rz
                        if laminar:
                            lam = tm.laminar_viscosity(mbF, r2, d)
                            lx += lam * vx
                            ly += lam * vy
                            lz += lam * vz
                        vmax += tm.viscous_bound(mask, r2, R2, vr, inv, 1.0)
                        if xsph:
                            wgt = tm.xsph_weight(mbm, d, e2, tm.kernel_w(kernel, q, 1.0))
                            wx -= wgt * vx
                            wy -= wgt * vy
                            wz -= wgt * vz
            fd = tm.surface_fade(h, Fc, gsx, gsy, gsz, s0, s1) if fade else 1.0
            drho[a] = tm.continuity_rate(Fc, sd, ddt, fa, fd, sdd)
            visc = tm.viscous_speed(h, vmax)
            acc[0, a] = tm.acceleration(Fc, sx, nu4, lx, laminar, fa, gx)
            if three:
                acc[1, a] = tm.acceleration(Fc, sy, nu4, ly, laminar, fa, gy)
                acc[2, a] = tm.acceleration(Fc, sz, nu4, lz, laminar, fa, gz)
            else:
                acc[1, a] = tm.acceleration(Fc, sz, nu4, lz, laminar, fa, gz)
            if xsph:
                xs[0, a] = eps2 * fa * wx
                if three:
                    xs[1, a] = eps2 * fa * wy
                    xs[2, a] = eps2 * fa * wz
                else:
                    xs[1, a] = eps2 * fa * wz
            # the time step's bounds (fluid.integrator._bounds), folded in: no array for
            # the viscous term, no second pass
            a2 = 0.0
            for k in range(acc.shape[0]):
                a2 += acc[k, a] * acc[k, a]
            am = max(am, a2 if fa > 0.0 else 0.0)
            cvm = max(cvm, ca + visc)
            cm = max(cm, ca)
        d_block_max3(sh_a, sh_v, sh_c, am, cvm, cm, bounds)

    _PAIR_LOOPS[key] = pair_loop
    return pair_loop


_GRADIENT_LOOPS = {}


def make_gradient_loop(kernel: int, three: bool):
    """``fluid.equations._make_gradient``: the renormalised density gradient ``G[:, a]``
    [kg/m^4] (rows x, (y,) z) of every fluid particle (Dinçer & Demir 2020, Eq. 3-4;
    the hydrostatic gradient where the matrix is near singular; 0 on boundary particles),
    for the density diffusion of ``diffusion="antuono"``."""
    key = (kernel, three)
    if key in _GRADIENT_LOOPS:
        return _GRADIENT_LOOPS[key]
    P_H, P_G = eq.P_H, eq.P_G
    zc = 2 if three else 1

    @cuda.jit
    def gradient_loop(P, rho, mass, kind, cs, n, start, lo, cell, nx, ny, nz, prm, G):
        h = prm[P_H]
        gx = prm[P_G]
        gy = prm[P_G + 1] if three else 0.0
        gz = prm[P_G + 2] if three else prm[P_G + 1]
        ih = 1.0 / h
        inv_cell = 1.0 / cell
        for a in range(cuda.grid(1), n, cuda.gridsize(1)):
            if kind[a] != 0:
                for k in range(G.shape[0]):
                    G[k, a] = 0.0
                continue
            xa = P[0, a]
            ya = P[1, a] if three else 0.0
            za = P[zc, a]
            rhoa = rho[a]
            cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)
            mxx = 0.0
            mxy = 0.0
            mxz = 0.0
            myy = 0.0
            myz = 0.0
            mzz = 0.0
            bx = 0.0
            by = 0.0
            bz = 0.0
            dys = 3 if three else 1
            for dz in range(-1, 2):
                for k in range(dys):
                    dy = k - 1 if three else 0
                    j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, 1)
                    j0 = d_first_at_or_above(P, j0, j1, xa - 2.0 * h)
                    j1 = d_first_at_or_above(P, j0, j1, xa + 2.0 * h)
                    for b in range(j0, j1):
                        rx = xa - P[0, b]
                        rz = za - P[zc, b]
                        ry = ya - P[1, b] if three else 0.0
                        q = math.sqrt(rx * rx + ry * ry + rz * rz) * ih
                        volb = mass[b] / rho[b] if kind[b] == 0 else 0.0
                        w = volb * tm.kernel_grad_shape(kernel, q)
                        d = (rho[b] - rhoa) * w
                        mxx += w * rx * rx
                        mxz += w * rx * rz
                        mzz += w * rz * rz
                        bx += d * rx
                        bz += d * rz
                        if three:
                            mxy += w * rx * ry
                            myy += w * ry * ry
                            myz += w * ry * rz
                            by += d * ry
            ca = cs[a]
            rx_, ry_, rz_ = tm.renormalised_gradient(mxx, mxy, mxz, myy, myz, mzz, bx, by, bz, rhoa / (ca * ca), gx,
                                                     gy, gz, three)
            G[0, a] = rx_
            if three:
                G[1, a] = ry_
                G[2, a] = rz_
            else:
                G[1, a] = rz_

    _GRADIENT_LOOPS[key] = gradient_loop
    return gradient_loop


# ------------------------------------------------------------------ integrators (fluid.integrator)
@cuda.jit
def k_predictor(P, V, rho, drho, acc, kind, n, rho0, dt, Pn, Vn, rhon, xs, use_xs):
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        f = kind[i] == 0
        rhon[i] = rho[i]
        rho[i] = tm.predictor_density(rho[i], drho[i], dt, f, rho0)
        for k in range(P.shape[0]):
            Vn[k, i] = V[k, i]
            Pn[k, i] = P[k, i]
            P[k, i], V[k, i] = tm.predictor_component(P[k, i], V[k, i], acc[k, i], xs[k, i] if use_xs else 0.0, dt, f)


@cuda.jit
def k_corrector(P, V, rho, drho, acc, kind, n, rho0, dt, Pn, Vn, rhon, xs, use_xs):
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        f = kind[i] == 0
        rho[i] = tm.corrector_density(rhon[i], drho[i], rho[i], dt, f, rho0)
        for k in range(P.shape[0]):
            P[k, i], V[k, i] = tm.corrector_component(Pn[k, i], Vn[k, i], acc[k, i], xs[k, i] if use_xs else 0.0,
                                                      dt, f)


@cuda.jit
def k_verlet(P, V, rho, drho, acc, kind, n, rho0, dt, Vm1, rhom1, euler, xs, use_xs):
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        f = kind[i] == 0
        r = rho[i]
        rho[i] = tm.verlet_density(r, rhom1[i], drho[i], dt, euler, f, rho0)
        rhom1[i] = r
        for k in range(P.shape[0]):
            v = V[k, i]
            P[k, i], V[k, i] = tm.verlet_component(P[k, i], v, Vm1[k, i], acc[k, i], xs[k, i] if use_xs else 0.0,
                                                   dt, euler, f)
            Vm1[k, i] = v


@cuda.jit
def k_damp(V, Vaux, kind, n, factor):
    """Multiply the fluid velocities (and the integrator's saved ones) by ``factor``
    (Fluid.settle)."""
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        if kind[i] != 0:
            continue
        for k in range(V.shape[0]):
            V[k, i] *= factor
            if Vaux.shape[1] > 0:
                Vaux[k, i] *= factor


# ------------------------------------------------------------------ relaxation zones
def _device(fn, **calls):
    """The numba CPU function ``fn`` compiled as a device function from its Python code, the
    numba functions it calls replaced by ``calls`` (their device versions)."""
    py = fn.py_func
    scope = dict(py.__globals__)
    scope.update(calls)
    return cuda.jit(device=True)(types.FunctionType(py.__code__, scope, py.__name__, py.__defaults__,
                                                    py.__closure__))


#: the slab's weight (Jacobsen et al. 2012, Eq. 5), the linear sea's sums at a point and Stokes
#: second order's terms there, from the CPU's code (fluid.relaxation._weight,
#: fluid.waves.point_sums and its fade-in, fluid.waves.stokes2_point)
d_zone_weight = _device(relaxation._weight)
d_point_sums = _device(waves.point_sums, _fade_at=_device(waves._fade_at))
d_stokes2_point = _device(waves.stokes2_point)


@cuda.jit(device=True)
def d_relax_col(V, i, vx, vy, vz, f, three):
    """``V[:, i] <- vt + (V[:, i] - vt) f`` (fluid.nearfield._relax_row)."""
    V[0, i] = vx + (V[0, i] - vx) * f
    if three:
        V[1, i] = vy + (V[1, i] - vy) * f
    dim = V.shape[0]
    V[dim - 1, i] = vz + (V[dim - 1, i] - vz) * f


@cuda.jit
def k_relax(P, V, X, use_x, kind, n, axis, x_in, inv, rate, dt, to_sea, t, e0, e1, level, depth, w, a, ph, k,
            den, ap, s_ref, has_source, source, c_front, ramp, want, cx, cy, cz, wall, stokes2, wave2):
    """A relaxation slab over a step ``dt`` [s] ending at ``t`` [s] (``fluid.relaxation.Slab``):
    each fluid particle inside it (``chi > 0``, ``chi = (x - x_in) inv`` along ``axis``)
    relaxed with the factor ``exp(-rate w(chi) dt)`` (``zone_factor``), towards rest
    (``_damp_to_rest``) or, ``to_sea``, towards the linear sea's velocity at it plus the
    return current (``cx``, ``cy``, ``cz``) and the end wall's rate ``wall`` along x
    (``fluid.nearfield._relax_to_sea``, in its order); ``stokes2``: plus Stokes second
    order's terms of the regular wave ``wave2`` (``fluid.waves.stokes2_wave``), as its
    ``velocity_at`` adds them; ``X`` (Verlet's n-1 velocity) alike where ``use_x``."""
    dim = P.shape[0]
    three = dim == 3
    fade = (has_source, source, c_front, ramp)
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        if kind[i] != 0:
            continue
        chi = (P[axis, i] - x_in) * inv
        if chi <= 0.0:
            continue
        f = math.exp(-rate * d_zone_weight(min(chi, 1.0)) * dt)
        if not to_sea:
            for d in range(dim):
                V[d, i] *= f
                if use_x:
                    X[d, i] *= f
            continue
        s = P[0, i] * e0 + P[1, i] * e1 if three else P[0, i] * e0
        zeta = min(max(P[dim - 1, i] - level, -depth), 0.0)
        _, uh, wz, _, _, _, r, dr = d_point_sums(s, zeta, t, True, w, a, ph, k, depth, den, ap, s_ref, fade, want)
        if stokes2:
            _, uh2, wz2, _, _, _ = d_stokes2_point(s, zeta, True, t, wave2, depth, r, dr, want)
            uh += uh2
            wz += wz2
        vx, vy, vz = uh * e0, uh * e1, wz
        vx += cx
        vy += cy
        vz += cz
        vx += wall
        d_relax_col(V, i, vx, vy, vz, f, three)
        if use_x:
            d_relax_col(X, i, vx, vy, vz, f, three)


# ------------------------------------------------------------------ free surface
@cuda.jit(device=True)
def d_line_walk(z, rows, arrays, kernel, h, ad, B2):
    """One walk over a gauge's line in the order ``fluid.probes._surface`` gathers its
    candidates: the fraction at height ``z`` [m] (``_fraction``: the fluid's, plus half the
    boundary's up to 1/2), the count of fluid particles within 2h of the line and their
    highest and lowest z [m], and the top of the boundary particles within ``sqrt(B2)`` of
    it (the bed); ``rows`` = (gx, gy, cx, cy, nx, ny, nz, reach, R2), ``arrays`` = (P, kind,
    mass, rho, start)."""
    gx, gy, cx, cy, nx, ny, nz, reach, R2 = rows
    P, kind, mass, rho, start = arrays
    three = P.shape[0] == 3
    zc = P.shape[0] - 1
    dys = 2 * reach + 1 if three else 1
    c = 0.0
    s = 0.0
    n = 0
    bed = -math.inf
    top = -math.inf
    bottom = math.inf
    for cz in range(nz):
        for k in range(dys):
            dy = k - reach if three else 0
            j0, j1 = row_range(cx, cy, cz, dy, 0, nx, ny, nz, start, reach)
            for b in range(j0, j1):
                rx = gx - P[0, b]
                ry = gy - P[1, b] if three else 0.0
                dh2 = rx * rx + ry * ry
                zb = P[zc, b]
                if dh2 < R2:
                    dz = z - zb
                    v = mass[b] / rho[b] * tm.kernel_w(kernel, math.sqrt(dh2 + dz * dz) / h, ad)
                    if kind[b] == 0:
                        c += v
                        n += 1
                        top = max(top, zb)
                        bottom = min(bottom, zb)
                    else:
                        s += v
                if kind[b] != 0 and dh2 <= B2 and zb > bed:
                    bed = zb
    return c + 0.5 * min(s, 0.5), n, bed, top, bottom


@cuda.jit(device=True)
def d_walk_fraction(z, rows, arrays, unused, kernel, h, ad):
    """``fluid.probes._fraction`` at height ``z`` [m] of a gauge's line (:func:`d_line_walk`),
    in ``_fraction``'s signature for :data:`d_line_crossing`."""
    c, _, _, _, _ = d_line_walk(z, rows, arrays, kernel, h, ad, -1.0)
    return c


#: ``fluid.probes._crossing`` (Illinois false position) over :func:`d_walk_fraction`
d_line_crossing = _device(probes._crossing, _fraction=d_walk_fraction)


@cuda.jit
def k_surface(G, P, kind, mass, rho, start, lo, inv_cell, nx, ny, nz, reach, kernel, h, ad, step, out):
    """``fluid.probes._surface`` with one thread per gauge (``G`` (M, 2): x, and y in 3-D):
    the highest z where the fraction (``_fraction``) crosses 0.5 going down the gauge's line, else
    the bed's surface (2 ``step`` above the highest boundary particle within 3 ``step`` of
    the line), NaN where there is neither; ``lo`` the grid's corner (dim,). The candidates
    are walked in the cells' rows at each evaluation, not gathered (no arrays here)."""
    three = P.shape[0] == 3
    zc = P.shape[0] - 1
    R2 = 4.0 * h * h
    arrays = (P, kind, mass, rho, start)
    for a in range(cuda.grid(1), G.shape[0], cuda.gridsize(1)):
        gx = G[a, 0]
        gy = G[a, 1] if three else 0.0
        cx, cy, cz0 = cell_coords(gx, gy, lo[zc], lo, inv_cell, three, nx, ny, nz)
        rows = (gx, gy, cx, cy, nx, ny, nz, reach, R2)
        _, n, bed, z_top, z_bottom = d_line_walk(0.0, rows, arrays, kernel, h, ad, 9.0 * step * step)
        out[a] = bed + 2.0 * step if bed > -math.inf else math.nan  # dry: the bed's surface
        if n == 0:
            continue
        z_hi = z_top + 2.0 * h
        z_end = z_bottom - 2.0 * h
        f_hi = -0.5
        while z_hi > z_end:
            z_lo = z_hi - step
            f_lo = d_walk_fraction(z_lo, rows, arrays, 0.0, kernel, h, ad) - 0.5
            if f_lo >= 0.0:
                out[a] = d_line_crossing(z_lo, f_lo, z_hi, f_hi, rows, arrays, 0.0, kernel, h, ad, 1e-9 * step)
                break
            z_hi, f_hi = z_lo, f_lo


# ------------------------------------------------------------------ reductions
@cuda.jit(device=True)
def d_block_max3(sa, sv, sc, a, v, c, out):
    """The block's largest ``a``, ``v``, ``c`` (one per thread; shared arrays of
    :data:`TPB`) into ``out[0:3]`` by atomics, one per block (out zeroed before the
    launch): the reductions of ``fluid.integrator._bounds``, max |a|^2 over fluid
    particles, max (c + visc), max c."""
    t = cuda.threadIdx.x
    sa[t] = a
    sv[t] = v
    sc[t] = c
    cuda.syncthreads()
    s = cuda.blockDim.x // 2  # a power of two (TPB, or SIM_LAUNCH's on the simulator)
    while s > 0:
        if t < s:
            sa[t] = max(sa[t], sa[t + s])
            sv[t] = max(sv[t], sv[t + s])
            sc[t] = max(sc[t], sc[t + s])
        cuda.syncthreads()
        s //= 2
    if t == 0:
        cuda.atomic.max(out, 0, sa[0])
        cuda.atomic.max(out, 1, sv[0])
        cuda.atomic.max(out, 2, sc[0])


@cuda.jit
def k_first_non_finite(P, V, rho, n, out):
    """Lowest row with a NaN or infinite position, velocity or density into ``out[0]``
    (set to n by the caller): ``fluid.integrator.first_non_finite``."""
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        s = rho[i]
        for k in range(P.shape[0]):
            s += P[k, i] + V[k, i]
        if s != s or s == math.inf or s == -math.inf:
            cuda.atomic.min(out, 0, i)


@cuda.jit(device=True)
def d_add_load(F, M, g, three, fx, fy, fz, mx, my, mz):
    """Add one load to group ``g``'s totals (F: fx, fz in 2-D; M: my in 2-D)."""
    dim = F.shape[1]
    cuda.atomic.add(F, (g, 0), fx)
    cuda.atomic.add(F, (g, dim - 1), fz)
    if three:
        cuda.atomic.add(F, (g, 1), fy)
        cuda.atomic.add(M, (g, 0), mx)
        cuda.atomic.add(M, (g, 1), my)
        cuda.atomic.add(M, (g, 2), mz)
    else:
        cuda.atomic.add(M, (g, 0), my)


#: boundary groups whose loads a block sums in shared memory before adding them to the
#: totals (one atomic per block and component); groups from this one on go to the totals
#: particle by particle
GROUPS_SHARED = 16


@cuda.jit
def k_group_sums(P, mass, acc, group, n, centre, F, M):
    """``fluid.solver._sum_groups``: force m a and moment (r - c) x m a per boundary group
    (``fluid.terms.particle_load``), summed with atomics (their order varies: round-off).
    Each block sums its particles' loads in shared memory first: atomics on the totals
    from every particle of a group serialise (a 3-D step of 2.6 M particles spent 22 % of
    its time here; docs/fluid_cuda.md)."""
    sh = cuda.shared.array((GROUPS_SHARED, 6), np.float64)  # fx, fy, fz, mx, my, mz
    t = cuda.threadIdx.x
    for j in range(t, GROUPS_SHARED * 6, cuda.blockDim.x):
        sh[j // 6, j % 6] = 0.0
    cuda.syncthreads()
    dim = P.shape[0]
    three = dim == 3
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        g = group[i]
        if g < 0:
            continue
        fx, fy, fz, mx, my, mz = tm.particle_load(
            mass[i], acc[0, i], acc[1, i] if three else 0.0, acc[dim - 1, i], P[0, i] - centre[g, 0],
            P[1, i] - centre[g, 1] if three else 0.0, P[dim - 1, i] - centre[g, dim - 1])
        if g < GROUPS_SHARED:
            cuda.atomic.add(sh, (g, 0), fx)
            cuda.atomic.add(sh, (g, 2), fz)
            cuda.atomic.add(sh, (g, 4), my)
            if three:
                cuda.atomic.add(sh, (g, 1), fy)
                cuda.atomic.add(sh, (g, 3), mx)
                cuda.atomic.add(sh, (g, 5), mz)
        else:
            d_add_load(F, M, g, three, fx, fy, fz, mx, my, mz)
    cuda.syncthreads()
    for g in range(t, min(GROUPS_SHARED, F.shape[0]), cuda.blockDim.x):
        d_add_load(F, M, g, three, sh[g, 0], sh[g, 1], sh[g, 2], sh[g, 3], sh[g, 4], sh[g, 5])


@cuda.jit
def k_zero_i4(a, m):
    for j in range(cuda.grid(1), m, cuda.gridsize(1)):
        a[j] = 0


@cuda.jit
def k_zero_f8(a, m):
    for j in range(cuda.grid(1), m, cuda.gridsize(1)):
        a[j] = 0.0


@cuda.jit
def k_zero_of_kinds(a, kind, m, k1, k2):
    """``a[j] = 0`` where ``kind[j]`` is ``k1`` or ``k2`` (the Adami walls' continuity rates)."""
    for j in range(cuda.grid(1), m, cuda.gridsize(1)):
        if kind[j] == k1 or kind[j] == k2:
            a[j] = 0.0


@cuda.jit
def k_zero2(A, m):
    """Zero the first m columns of A (rows, capacity)."""
    for j in range(cuda.grid(1), m, cuda.gridsize(1)):
        for d in range(A.shape[0]):
            A[d, j] = 0.0


@cuda.jit
def k_zero_all(A):
    """Zero every entry of the 2-D array A."""
    m = A.shape[1]
    for j in range(cuda.grid(1), A.shape[0] * m, cuda.gridsize(1)):
        A[j // m, j % m] = 0.0


@cuda.jit
def k_set_i8(a, v):
    """``a[0] = v`` (no host-to-device copy)."""
    if cuda.grid(1) == 0:
        a[0] = v


@cuda.jit
def k_read_i4(a, j, out):
    """``out[0] = a[j]`` (one entry back to the host without a slice)."""
    if cuda.grid(1) == 0:
        out[0] = a[j]


# ------------------------------------------------------------------ tank-wall densities (fluid.wall_density)
@cuda.jit
def k_adami(P, rho, kind, accw, has_acc, n, start, lo, inv_cell, nx, ny, nz, kernel, ad, h, rho0, B, gamma, g,
            kmin, kmax, p_floor):
    """``fluid.wall_density.adami_wall_density`` (Adami, Hu & Adams 2012, Eq. 27): the
    density of every particle with ``kmin <= kind <= kmax`` from the pressure of the fluid
    within 2h, carried to it with ``g - a_w`` (``accw`` (dim, capacity) [m/s^2], read if
    ``has_acc``); whole rows of cells in the CPU's order. It writes wall densities and
    reads fluid ones only."""
    three = P.shape[0] == 3
    zc = P.shape[0] - 1
    R2 = 4.0 * h * h
    ih = 1.0 / h
    inv_gamma = 1.0 / gamma
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        k = kind[i]
        if k < kmin or k > kmax:
            continue
        xw = P[0, i]
        yw = P[1, i] if three else 0.0
        zw = P[zc, i]
        bx = g[0]
        by = g[1]
        bz = g[2]
        if has_acc:
            bx -= accw[0, i]
            if three:
                by -= accw[1, i]
            bz -= accw[zc, i]
        bx *= rho0
        by *= rho0
        bz *= rho0
        sw = 0.0
        sp = 0.0
        cx, cy, cz = cell_coords(xw, yw, zw, lo, inv_cell, True, nx, ny, nz)
        dys = 3 if three else 1
        for dz in range(-1, 2):
            for kk in range(dys):
                dy = kk - 1 if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, 1)
                for j in range(j0, j1):
                    if kind[j] != 0:
                        continue
                    rx = xw - P[0, j]
                    ry = yw - P[1, j] if three else 0.0
                    rz = zw - P[zc, j]
                    r2 = rx * rx + ry * ry + rz * rz
                    if r2 >= R2:
                        continue
                    w = tm.kernel_w(kernel, math.sqrt(r2) * ih, ad)
                    pj = tm.tait_pressure(rho[j], rho0, B, gamma)
                    sw += w
                    sp += w * tm.adami_pressure(pj, bx, by, bz, rx, ry, rz)
        p = tm.adami_wall_pressure(sp, sw, SW_MIN * ad, p_floor)  # w carries ad here
        rho[i] = tm.tait_density(p, rho0, B, inv_gamma)


@cuda.jit
def k_place_one(slot, ids, vec, A):
    """``A[:, row of ids[k]] = vec[k]`` (m, dim): a per-particle vector set by id."""
    for k in range(cuda.grid(1), ids.shape[0], cuda.gridsize(1)):
        i = slot[ids[k]]
        for d in range(A.shape[0]):
            A[d, i] = vec[k, d]


# ------------------------------------------------------------------ bodies' mDBC (fluid.boundary_correction)
@cuda.jit
def k_mdbc(P, rho, mass, kind, ids, goff, id_lo, n, start, lo, inv_cell, nx, ny, nz, kernel, ad, h, rho0, det_min):
    """``fluid.boundary_correction.mdbc_density`` (English et al. 2022, mDBC): the density
    of every boundary particle whose ghost vector ``goff[:, id - id_lo]`` (dim, m) [m] is
    non-zero, from the first-order consistent interpolation of the fluid at its ghost
    node, extrapolated back and clamped below at rho0; whole rows of cells in the CPU's
    order. It writes boundary densities and reads fluid ones only."""
    three = P.shape[0] == 3
    dim = P.shape[0]
    zc = dim - 1
    m = dim + 1
    R2 = 4.0 * h * h
    Fs = tm.kernel_grad_scale(kernel, ad, h)
    A = cuda.local.array((4, 4), np.float64)
    bv = cuda.local.array(4, np.float64)
    row = cuda.local.array(4, np.float64)
    col = cuda.local.array(4, np.float64)
    o = cuda.local.array(3, np.float64)
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        if kind[i] == 0:
            continue
        g = ids[i] - id_lo
        if g < 0 or g >= goff.shape[1]:
            continue
        o2 = 0.0
        for k in range(dim):
            o[k] = goff[k, g]
            o2 += o[k] * o[k]
        if o2 == 0.0:
            continue
        gx = P[0, i] + o[0]
        gy = P[1, i] + o[1] if three else 0.0
        gz = P[zc, i] + o[zc]
        for a in range(4):
            bv[a] = 0.0
            for k in range(4):
                A[a, k] = 0.0
        col[0] = 1.0
        cx, cy, cz = cell_coords(gx, gy, gz, lo, inv_cell, True, nx, ny, nz)
        dys = 3 if three else 1
        for dz in range(-1, 2):
            for kk in range(dys):
                dy = kk - 1 if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, 1)
                for j in range(j0, j1):
                    if kind[j] != 0:
                        continue
                    rx = P[0, j] - gx
                    ry = P[1, j] - gy if three else 0.0
                    rz = P[zc, j] - gz
                    r2 = rx * rx + ry * ry + rz * rz
                    if r2 >= R2:
                        continue
                    q = math.sqrt(r2) / h
                    V = mass[j] / rho[j]
                    VF = -V * (Fs * tm.kernel_grad_shape(kernel, q))
                    tm.mdbc_add_neighbour(A, bv, row, col, m, V, tm.kernel_w(kernel, q, ad), VF, rx, ry, rz, rho[j],
                                          three)
        rho[i] = tm.mdbc_extrapolate(A, bv, m, o, dim, det_min, rho0)[0]


# ------------------------------------------------------------------ MLS density re-initialisation (fluid.mls)
@cuda.jit
def k_mls(P, rho, mass, kind, n, start, lo, inv_cell, nx, ny, nz, kernel, ad, h, min_det, out):
    """``fluid.mls.mls_density`` (Sunara et al. 2021, Eq. 9-12): the MLS density of
    every fluid particle into ``out`` (boundary particles: their own); whole rows of cells
    in the CPU's order."""
    three = P.shape[0] == 3
    zc = P.shape[0] - 1
    ih = 1.0 / h
    for a in range(cuda.grid(1), n, cuda.gridsize(1)):
        if kind[a] != 0:
            out[a] = rho[a]
            continue
        xa = P[0, a]
        za = P[zc, a]
        ya = P[1, a] if three else 0.0
        cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, True, nx, ny, nz)
        m = terms.MLS_ZERO
        dys = 3 if three else 1
        for dz in range(-1, 2):
            for k in range(dys):
                dy = k - 1 if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, 1)
                for b in range(j0, j1):
                    rx = (xa - P[0, b]) * ih
                    rz = (za - P[zc, b]) * ih
                    ry = (ya - P[1, b]) * ih if three else 0.0
                    q = math.sqrt(rx * rx + ry * ry + rz * rz)
                    mw = mass[b] * tm.kernel_w(kernel, q, ad)
                    m = tm.mls_moments(m, mw / rho[b], mw, rx, ry, rz)
        out[a] = tm.mls_solve(m, three, min_det)[0]


@cuda.jit
def k_mls_apply(rho, new, rhom1, shift, n):
    """The densities from :func:`k_mls`; with ``shift`` (Verlet) the n-1 density moved by
    the same correction (Fluid._reinitialise_density)."""
    for i in range(cuda.grid(1), n, cuda.gridsize(1)):
        if shift:
            rhom1[i] += new[i] - rho[i]
        rho[i] = new[i]
