"""Probes of the SPH fluid: pressure at points, the pressure on a patch of wall (as a
flush-mounted transducer reads it), free-surface elevation at gauges, the load on a
boundary group, the fluid's energies.

Every probe has a ``name`` (the series it is written to), ``columns`` (the keys of its
sample) and ``sample(fluid) -> dict`` mapping each column to a float or a 1-D array of
fixed length, ready for :meth:`fluid.output.H5Output.series`.
The functional forms (:func:`pressure_at`, :func:`wall_patch_pressure`,
:func:`surface_elevation`, :func:`fluid_energies`) read the same quantities once.

The per-point kernels gather over the fluid's own cell list (the particles are sorted by
cell after every step), so a probe costs a few neighbour rows per point, not a pass over
all particles. The wall patch is the exception: it sums the forces on the boundary
particles, one vectorised pass over the particle arrays per sample (cheaper than the
SPHERIC-10 face fit it replaced, which builds a k-d tree of the fluid).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from errors import InputError
from fluid.kernels import W, alpha_d, w_value
from fluid.neighbours import cell_coords, row_range
from fluid.particles import Kind

_OPTS = dict(fastmath=True, cache=True, error_model="numpy")
_FLUID = int(Kind.FLUID)


def _grid(fluid):
    """The fluid's grid, its cell list and pressures refreshed for the current placement."""
    if fluid.limit is None:
        raise InputError("probe: the fluid is not initialised; call fluid.initialize(t0) first")
    fluid.refresh_rates()  # pressures and cells of the current placement
    return fluid._grid


def _cells(fluid):
    """The fluid's cell list: (grid, start). Probes read the fluid's sorted particles."""
    return _grid(fluid), fluid._start  # same package: the cell list the solver keeps sorted


# ---------------------------------------------------------------------- pressure
@njit(**_OPTS)  # serial: a handful of probe points, threads would cost more than they gain
def _idw_pressure(pts, pos, kind, p, start, lo, inv_cell, nx, ny, nz, reach, R2, eps2, out):
    """Inverse-distance average of the fluid pressures within ``sqrt(R2)`` of each point
    (Sunara et al. 2021, Eq. 15); 0 where no fluid is near (a dry point)."""
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    dys = 2 * reach + 1 if three else 1
    for a in range(pts.shape[0]):
        xa = pts[a, 0]
        za = pts[a, zc]
        ya = pts[a, 1] if three else 0.0
        cx, cy, cz = cell_coords(xa, ya, za, lo, inv_cell, three, nx, ny, nz)
        num = 0.0
        den = 0.0
        for dz in range(-reach, reach + 1):
            for k in range(dys):
                dy = k - reach if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, dz, nx, ny, nz, start, reach)
                for b in range(j0, j1):
                    rx = xa - pos[b, 0]
                    rz = za - pos[b, zc]
                    ry = ya - pos[b, 1] if three else 0.0
                    r2 = rx * rx + ry * ry + rz * rz
                    # 0/1 mask, no branch; eps2 keeps a point on a particle finite
                    w = ((kind[b] == _FLUID) & (r2 < R2)) / math.sqrt(r2 + eps2)
                    num += w * p[b]
                    den += w
        out[a] = num / den if den > 0.0 else 0.0


def _points(points, dim: int, what: str) -> np.ndarray:
    pts = np.ascontiguousarray(points, dtype=np.float64)
    if pts.ndim == 1 and pts.size == dim:
        pts = pts[None, :]
    if pts.ndim != 2 or pts.shape[1] != dim or pts.shape[0] == 0 or not np.isfinite(pts).all():
        raise InputError(f"{what}: points have shape {np.shape(points)}; give finite (M, {dim}) "
                         f"positions [m] ({'x, z' if dim == 2 else 'x, y, z'})")
    return pts


def _inside(fluid, pts, what: str) -> None:
    grid, _ = _cells(fluid)
    lo = np.asarray(grid.lo)
    hi = lo + grid.cell * np.array([grid.shape[0], grid.shape[2]] if lo.size == 2 else grid.shape)
    bad = ~np.all((pts >= lo) & (pts < hi), axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        raise InputError(f"{what}: point {pts[i]} m lies outside the fluid's domain {lo} .. {hi} m; "
                         "move it inside (or enlarge domain_lo/domain_hi)")


def pressure_at(fluid, points) -> np.ndarray:
    """Pressure [Pa] at ``points`` (M, dim) [m]: the inverse-distance average of the fluid
    pressures within the kernel support 2h (Sunara et al. 2021, Eq. 15), exactly as
    :meth:`fluid.solver.Fluid.wall_pressure` reports it at boundary particles; 0 at a dry
    point. On a wall, put the point on the wall face or on the first boundary layer.
    Accuracy: exact for a linear pressure field where the fluid within 2h lies symmetric
    about the point's height; within 2h of the free surface or the bottom the neighbours
    lie on one side and the average is biased by up to ~rho g h (measured on a tank at
    rest, dx = 1 cm, h = 1.41 dx: 0.0 % at 3 dx depth and below, +41 % at 1 dx, -2 % at
    1 dx above the bottom)."""
    c = fluid.config
    pts = _points(points, c.dim, "pressure_at")
    _inside(fluid, pts, "pressure_at")
    grid, start = _cells(fluid)
    ps = fluid.ps
    out = np.empty(pts.shape[0])
    nx, ny, nz = grid.shape
    _idw_pressure(pts, ps.pos, ps.kind, ps.p, start, np.asarray(grid.lo, np.float64), 1.0 / grid.cell,
                  nx, ny, nz, grid.reach, (2.0 * c.h) ** 2, 1e-12 * c.h * c.h, out)
    return out


class PressureProbe:
    """Pressure [Pa] at fixed points ``points`` (M, dim) [m] (see :func:`pressure_at`).
    Column ``p`` (M,)."""

    columns = ("p",)

    def __init__(self, points, name: str = "pressure"):
        pts = np.asarray(points, dtype=np.float64)
        if pts.ndim == 1:
            pts = pts[None, :]
        if pts.ndim != 2 or pts.shape[1] not in (2, 3) or not np.isfinite(pts).all():
            raise InputError(f"PressureProbe: points have shape {np.shape(points)}; give finite (M, 2) "
                             "(x, z) or (M, 3) (x, y, z) positions [m]")
        self.points = pts
        self.name = name

    def sample(self, fluid) -> dict:
        return {"p": pressure_at(fluid, self.points)}


def wall_patch_pressure(fluid, centre, normal, size: float, group: int | None = None) -> float:
    """Pressure [Pa] on a patch of a wall face, as a flush-mounted transducer reads it: the
    normal force the fluid exerts on the boundary particles behind the patch
    (:meth:`fluid.solver.Fluid.boundary_forces_now`) divided by the patch's area.

    ``centre`` (dim,) [m] a point on the wall face, ``normal`` (dim,) the wall's normal
    into the water, ``size`` [m] the patch's length along the wall (2-D, per metre of
    depth) or its diameter (3-D, a disc); ``group`` restricts it to one boundary group.
    The patch holds the boundary particles within ``size``/2 of the centre along the wall
    and within the kernel's reach 2h behind the face; its area is dx^(dim-1) per particle
    of the first layer (within one dx behind the face), as the wall builders lay them out.

    Unlike :func:`pressure_at` (an average of the pressure of the fluid near the point),
    this is a momentum balance: a patch half wet reads about half the pressure of the water
    on it, and a lone splash particle reads its momentum, not its own pressure. The force
    of a fluid particle is spread over the wall particles within 2h of it, so the reading
    is the wall pressure smoothed over ~h along the wall; ``size`` of a few h keeps the
    patch's count of particles, and with it the reading, steady."""
    c = fluid.config
    dim = c.dim
    cen = _points(centre, dim, "wall_patch_pressure")[0]
    n = np.asarray(normal, dtype=np.float64).reshape(-1)
    if n.shape != (dim,) or not np.isfinite(n).all() or np.linalg.norm(n) == 0:
        raise InputError(f"wall_patch_pressure: normal={normal!r}; give a nonzero {dim}-vector into the water")
    n = n / np.linalg.norm(n)
    if not (isinstance(size, (int, float)) and math.isfinite(size) and size >= c.dx):
        raise InputError(f"wall_patch_pressure: size={size!r} m; give a patch at least one particle "
                         f"spacing ({c.dx} m) across")
    F = fluid.boundary_forces_now()
    ps = fluid.ps
    d = ps.pos - cen
    dn = d @ n
    along = np.linalg.norm(d - dn[:, None] * n, axis=1)
    # the simulated particles only: a symmetry plane's images carry no rates (on the half
    # that is simulated, force over area is the whole patch's)
    sel = (ps.kind != Kind.FLUID) & (ps.ids >= 0) & (along <= 0.5 * size) & (dn <= 0.0) & (dn >= -2.0 * c.h)
    if group is not None:
        sel &= ps.group == group
    first = sel & (dn >= -c.dx)
    if not first.any():
        raise InputError(f"wall_patch_pressure: no boundary particle within one dx behind the face at "
                         f"{cen} m (normal {n}); put the centre on the wall's face")
    if np.isnan(F[sel]).any():
        raise InputError("wall_patch_pressure: the patch is on a tank wall, whose loads are not computed "
                         "(FluidConfig.wall_loads=False); set wall_loads=True to read them")
    area = first.sum() * c.dx ** (dim - 1)
    return float(-(F[sel] @ n).sum() / area)


class PatchPressureProbe:
    """Pressure [Pa] on a patch of wall face (see :func:`wall_patch_pressure`): ``centre``
    (dim,) [m] on the face, ``normal`` into the water, ``size`` [m] its length (2-D) or
    diameter (3-D), optionally of boundary ``group`` only. The patch is fixed in space; on
    a wall that moves, call :func:`wall_patch_pressure` with its current position. Column
    ``p`` (a float)."""

    columns = ("p",)

    def __init__(self, centre, normal, size: float, group: int | None = None, name: str = "patch"):
        c, n = np.asarray(centre, dtype=np.float64), np.asarray(normal, dtype=np.float64)
        if c.shape not in ((2,), (3,)) or n.shape != c.shape or not (np.isfinite(c).all() and np.isfinite(n).all()):
            raise InputError(f"PatchPressureProbe: centre={centre!r}, normal={normal!r}; give two finite "
                             "(x, z) or (x, y, z) vectors")
        if not (isinstance(size, (int, float)) and math.isfinite(size) and size > 0):
            raise InputError(f"PatchPressureProbe: size={size!r}; give the patch's length or diameter [m] > 0")
        self.centre, self.normal, self.size, self.group, self.name = c, n, float(size), group, name

    def sample(self, fluid) -> dict:
        return {"p": wall_patch_pressure(fluid, self.centre, self.normal, self.size, self.group)}


# ---------------------------------------------------------------------- free surface
@njit(**_OPTS)
def _fraction(z, dh2, zb, vb, kernel, h, ad):
    """The fraction whose crossing of 0.5 is the surface at height ``z`` [m] of the gauge
    line: the kernel-interpolated fluid fraction ``f = sum_b V_b W(r_b)`` over the fluid
    candidates (``vb`` > 0), plus half the solid's ``s`` (the same sum over the boundary
    candidates, ``vb`` < 0, whose volume is -vb), ``s`` taken up to 1/2. ``f + s/2 = 1/2``
    is ``f = (1 - s) / 2``: the water fills half the kernel's room that no wall or body
    takes, so a gauge beside a wall, or over water shallower than the kernel, reads the
    surface where the water is; up to 1/2, since a gauge's line stands in the water (a wall
    face takes at most half the kernel), so inside a solid ``f`` must still reach 1/4. ``dh2``
    the squared horizontal distances of the candidates."""
    c = 0.0
    s = 0.0
    for b in range(zb.shape[0]):
        dz = z - zb[b]
        v = vb[b] * w_value(kernel, math.sqrt(dh2[b] + dz * dz) / h, ad)
        if v >= 0.0:
            c += v
        else:
            s -= v
    return c + 0.5 * min(s, 0.5)


@njit(**_OPTS)
def _crossing(z_lo, f_lo, z_hi, f_hi, dh2, zb, vb, kernel, h, ad, tol):
    """The height in ``z_lo .. z_hi`` where the fluid fraction less 0.5 (``f_lo`` >= 0 at
    ``z_lo``, ``f_hi`` < 0 at ``z_hi``) crosses zero, to ``tol`` [m]: the Illinois variant
    of false position (Dowell & Jarratt 1971, BIT 11), whose bracket closes from both
    sides; the fraction is smooth, so a handful of evaluations replace bisection's forty."""
    side = 0
    z = 0.5 * (z_lo + z_hi)
    for _ in range(100):
        z_new = (z_lo * f_hi - z_hi * f_lo) / (f_hi - f_lo)
        if not z_lo <= z_new <= z_hi:  # round-off at a flat crossing: bisect
            z_new = 0.5 * (z_lo + z_hi)
        done = abs(z_new - z) < tol or z_hi - z_lo < tol
        z = z_new
        if done:
            break
        f = _fraction(z, dh2, zb, vb, kernel, h, ad) - 0.5
        if f >= 0.0:
            z_lo, f_lo = z, f
            if side == -1:
                f_hi *= 0.5
            side = -1
        else:
            z_hi, f_hi = z, f
            if side == 1:
                f_lo *= 0.5
            side = 1
    return z


@njit(**_OPTS)  # serial: a handful of gauges
def _surface(gauges, pos, kind, mass, rho, start, lo, inv_cell, nx, ny, nz, reach, kernel, h, ad,
             step, out):
    """Highest z where the fraction of :func:`_fraction` crosses 0.5 going down each gauge's
    vertical line; where it never does (a dry gauge), the bed's surface: half a spacing (2 ``step``)
    above the highest boundary particle within 3 ``step`` of the line; NaN where there is
    neither."""
    three = pos.shape[1] == 3
    zc = pos.shape[1] - 1
    dys = 2 * reach + 1 if three else 1
    R2 = 4.0 * h * h
    B2 = 9.0 * step * step  # a lattice's nearest boundary column lies within dx / sqrt(2)
    for a in range(gauges.shape[0]):
        gx = gauges[a, 0]
        gy = gauges[a, 1] if three else 0.0
        cx, cy, cz0 = cell_coords(gx, gy, lo[zc], lo, inv_cell, three, nx, ny, nz)
        # the particles within 2h of the line (two passes, count then fill; the fluid's
        # volumes positive, the boundary's negative: _fraction), the fluid's extent, and
        # the top of the bed under the line
        n = 0
        n_fluid = 0
        bed = -np.inf
        z_top = -np.inf
        z_bottom = np.inf
        for cz in range(nz):
            for k in range(dys):
                dy = k - reach if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, 0, nx, ny, nz, start, reach)
                for b in range(j0, j1):
                    rx = gx - pos[b, 0]
                    ry = gy - pos[b, 1] if three else 0.0
                    r2 = rx * rx + ry * ry
                    if r2 < R2:
                        n += 1
                        if kind[b] == _FLUID:
                            n_fluid += 1
                            z_top = max(z_top, pos[b, zc])
                            z_bottom = min(z_bottom, pos[b, zc])
                    if kind[b] != _FLUID and r2 <= B2 and pos[b, zc] > bed:
                        bed = pos[b, zc]
        dry = bed + 2.0 * step if bed > -np.inf else np.nan
        if n_fluid == 0:
            out[a] = dry
            continue
        dh2 = np.empty(n)
        zb = np.empty(n)
        vb = np.empty(n)
        n = 0
        for cz in range(nz):
            for k in range(dys):
                dy = k - reach if three else 0
                j0, j1 = row_range(cx, cy, cz, dy, 0, nx, ny, nz, start, reach)
                for b in range(j0, j1):
                    rx = gx - pos[b, 0]
                    ry = gy - pos[b, 1] if three else 0.0
                    if rx * rx + ry * ry < R2:
                        dh2[n] = rx * rx + ry * ry
                        zb[n] = pos[b, zc]
                        vb[n] = mass[b] / rho[b] if kind[b] == _FLUID else -mass[b] / rho[b]
                        n += 1
        # march down from above the fluid candidates' support (no water there) in steps of
        # ``step`` until the fraction reaches 0.5, then solve for the crossing in that step
        z_hi = z_top + 2.0 * h
        z_end = z_bottom - 2.0 * h
        f_hi = -0.5
        out[a] = dry
        while z_hi > z_end:
            z_lo = z_hi - step
            f_lo = _fraction(z_lo, dh2, zb, vb, kernel, h, ad) - 0.5
            if f_lo >= 0.0:
                out[a] = _crossing(z_lo, f_lo, z_hi, f_hi, dh2, zb, vb, kernel, h, ad, 1e-9 * step)
                break
            z_hi, f_hi = z_lo, f_lo


def _gauges(gauges, dim: int, what: str) -> np.ndarray:
    g = np.asarray(gauges, dtype=np.float64)
    if dim == 2:
        ok = g.ndim <= 1 or (g.ndim == 2 and g.shape[1] == 1)
        g = g.reshape(-1, 1)
    else:
        if g.ndim == 1 and g.size == 2:
            g = g[None, :]
        ok = g.ndim == 2 and g.shape[1] == 2
    if not ok or g.shape[0] == 0 or not np.isfinite(g).all():
        raise InputError(f"{what}: gauges have shape {np.shape(gauges)}; give finite "
                         + ("x positions [m], shape (M,)" if dim == 2 else "(x, y) positions [m], shape (M, 2)"))
    return np.ascontiguousarray(g)


def surface_elevation(fluid, gauges) -> np.ndarray:
    """Free-surface height z [m] at each gauge: 2-D ``gauges`` are x positions (M,) [m],
    3-D (x, y) positions (M, 2) [m]. The surface is the highest z on the gauge's vertical
    line where the kernel-interpolated fluid fraction ``f = sum_b (m_b/rho_b) W(r_b)``
    fills half the kernel's room that walls and bodies leave, ``f = (1 - s) / 2`` with ``s``
    the same sum over the boundary particles, up to 1/2 (a flat surface lies dx/2 above its
    top particle layer, where a half-space of fluid fills half the kernel; beside a wall or
    over water shallower than the kernel's support the wall takes its share of the kernel,
    which the fluid's fraction alone would read as a surface up to a spacing low). Isolated
    drops in the air do not count (one particle fills at most ~0.3 of the kernel). A dry
    gauge (a film too thin for the fraction to reach its half, or no fluid within 2h of the
    line) reads the bed's surface, half a spacing above the highest wall or body particle
    within 0.75 dx of the line (a water depth of zero); NaN where there is neither water nor
    bed under it. Located to dx/4, then solved to 1e-9 of that."""
    c = fluid.config
    g = _gauges(gauges, c.dim, "surface_elevation")
    grid = _grid(fluid)
    lo = np.asarray(grid.lo, np.float64)
    n_h = np.array(grid.shape)[[0, 1]] if c.dim == 3 else np.array([grid.shape[0]])
    hi = lo[:-1] + grid.cell * n_h
    bad = ~np.all((g >= lo[:-1]) & (g < hi), axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        raise InputError(f"surface_elevation: gauge {g[i]} m lies outside the fluid's domain "
                         f"{lo[:-1]} .. {hi} m; move it inside")
    on_device = getattr(fluid, "surface_on_device", None)
    if on_device is not None:  # a GPU fluid reads it there (fluid.cuda): the state stays on the device
        return on_device(g)
    start = fluid._start
    ps = fluid.ps
    out = np.empty(g.shape[0])
    nx, ny, nz = grid.shape
    k = fluid._kernel
    _surface(g, ps.pos, ps.kind, ps.mass, ps.rho, start, lo, 1.0 / grid.cell, nx, ny, nz, grid.reach,
             k, c.h, alpha_d(k, c.dim, c.h), 0.25 * c.dx, out)
    return out


def gauge_response(k, h: float, dim: int, kernel: str = "wendland") -> np.ndarray:
    """The fraction of a small sinusoidal surface wave's amplitude that
    :func:`surface_elevation` reads, at wavenumbers ``k`` [1/m] (any shape), smoothing
    length ``h`` [m], in ``dim`` dimensions: a gauge is a low-pass filter. Linearised about a
    flat surface, the fraction at the gauge's line changes by ``sum_b V_b W`` over the
    surface's displacement, ``int eta(x') W(x - x', 0) dx'``, and by ``z int W(s, 0) ds``
    with the height ``z``; so the crossing reads ``eta`` averaged with the kernel's profile
    across the surface, ``G(k) = int W(s) cos(k s) ds / int W(s) ds`` (2-D: along a line;
    3-D: over the plane, ``int W(r) J0(k r) r dr / int W(r) r dr``). G = 0.80, 0.905, 0.945,
    0.975, 0.991 at wavelengths 10, 15, 20, 30, 50 dx at h = 2 dx (the wave's height
    stands beside it in the particles; tests/test_fluid_probes.py reads stretched lattices).
    Limits: linear in the amplitude (measured independent of it up to a = dx); the lattice's
    discreteness adds about 0.002."""
    from scipy.special import j0

    x, wq = np.polynomial.legendre.leggauss(64)
    r = h * (1.0 + x)  # the support 0 .. 2h
    w = W(r, h, dim, kernel) * wq  # the normalisation cancels
    kr = np.multiply.outer(np.asarray(k, np.float64), r)
    if dim == 2:
        return (np.cos(kr) * w).sum(-1) / w.sum()
    return (j0(kr) * (w * r)).sum(-1) / (w * r).sum()


class WaveGauge:
    """Free-surface elevation z [m] at gauges (see :func:`surface_elevation`): 2-D x
    positions (M,) [m], 3-D (x, y) positions (M, 2) [m]. Column ``eta`` (M,), the absolute
    height of the surface (subtract the still-water level for the elevation above it)."""

    columns = ("eta",)

    def __init__(self, gauges, name: str = "gauges"):
        g = np.asarray(gauges, dtype=np.float64)
        if g.ndim > 2 or g.size == 0 or not np.isfinite(g).all():
            raise InputError(f"WaveGauge: gauges {gauges!r}; give x positions [m] (2-D) or (x, y) "
                             "positions [m] (3-D)")
        self.gauges = g
        self.name = name

    def sample(self, fluid) -> dict:
        return {"eta": surface_elevation(fluid, self.gauges)}


# ---------------------------------------------------------------------- loads
class GroupLoad:
    """Force [N] and moment [N m] the fluid exerts on boundary ``group`` at the sampled
    state (:meth:`fluid.solver.Fluid.group_forces_now`). The moment is about ``about``
    (dim,) [m] when given, else about the fluid's ``moment_points[group]``; 2-D: one
    component, about +y (``M_y = z F_x - x F_z``). Columns ``F`` (dim,), ``M`` (1 or 3,)."""

    columns = ("F", "M")

    def __init__(self, group: int, about=None, name: str | None = None):
        if not isinstance(group, (int, np.integer)) or group < 0:
            raise InputError(f"GroupLoad: group={group!r}; give a boundary group id >= 0")
        self.group = int(group)
        self.about = None if about is None else np.asarray(about, dtype=np.float64)
        if self.about is not None and (self.about.shape not in ((2,), (3,)) or not np.isfinite(self.about).all()):
            raise InputError(f"GroupLoad: about={about!r}; give a finite point (x, z) or (x, y, z) [m]")
        self.name = name if name is not None else f"group_{self.group}"

    def sample(self, fluid) -> dict:
        if self.group >= fluid.n_groups:
            raise InputError(f"GroupLoad: no boundary group {self.group}; the fluid has groups "
                             f"0..{fluid.n_groups - 1}")
        F, M = fluid.group_forces_now()
        F, M = F[self.group].copy(), M[self.group].copy()
        if np.isnan(F).all() and not fluid.config.wall_loads:
            raise InputError(f"GroupLoad: group {self.group} is a tank wall, whose loads are not computed "
                             "(FluidConfig.wall_loads=False); set wall_loads=True to read them")
        if self.about is not None:
            if self.about.size != fluid.config.dim:
                raise InputError(f"GroupLoad: about has {self.about.size} components, the fluid is "
                                 f"{fluid.config.dim}-D")
            d = fluid.moment_points[self.group] - self.about  # M_about = M_ref + d x F
            if fluid.config.dim == 2:
                M[0] += d[1] * F[0] - d[0] * F[1]
            else:
                M += np.cross(d, F)
        return {"F": F, "M": M}


# ---------------------------------------------------------------------- energy
#: particles per block of the energy sums: each block is summed in index order, the blocks
#: then in block order, so the sums do not depend on the thread count or the threading
#: layer (a prange reduction's grouping does, in its last bits; a resumed run must
#: reproduce the uninterrupted one's probes bit for bit)
_ENERGY_BLOCK = 4096


@njit(parallel=True, **_OPTS)
def _energies(pos, vel, mass, kind, g, z_ref):
    zc = pos.shape[1] - 1
    n = pos.shape[0]
    nb = (n + _ENERGY_BLOCK - 1) // _ENERGY_BLOCK
    ke_b = np.zeros(nb)
    pe_b = np.zeros(nb)
    for b in prange(nb):
        ke = 0.0
        pe = 0.0
        for i in range(b * _ENERGY_BLOCK, min(n, (b + 1) * _ENERGY_BLOCK)):
            if kind[i] == _FLUID:
                v2 = 0.0
                for k in range(pos.shape[1]):
                    v2 += vel[i, k] * vel[i, k]
                ke += 0.5 * mass[i] * v2
                gr = -g[zc] * z_ref  # -g . (r - z_ref e_z): g (z - z_ref) for gravity along -z
                for k in range(pos.shape[1]):
                    gr += g[k] * pos[i, k]
                pe -= mass[i] * gr
        ke_b[b] = ke
        pe_b[b] = pe
    ke = 0.0
    pe = 0.0
    for b in range(nb):
        ke += ke_b[b]
        pe += pe_b[b]
    return ke, pe


def fluid_energies(fluid, z_ref: float = 0.0) -> tuple[float, float]:
    """(kinetic, potential) energy [J] of the fluid particles: ``sum m v^2 / 2`` and
    ``-sum m g . (r - z_ref e_z)`` (``sum m g (z - z_ref)`` for gravity along -z) with
    ``z_ref`` [m] the height of zero potential energy. With a symmetry plane
    (``fluid.mirror``): the whole domain's, twice the simulated half's (no fluid particle
    lies on the plane); between two planes (a slice of a flow uniform across y), the
    slice's."""
    ps = fluid.simulated()
    with fluid._own_threads():  # the fluid's own choice: one thread for small sets
        k, u = _energies(ps.pos, ps.vel, ps.mass, ps.kind, fluid.config.gravity, float(z_ref))
    half = fluid.mirror is not None and fluid.mirror.y1 is None
    return (2.0 * k, 2.0 * u) if half else (k, u)


class Energy:
    """Kinetic and potential energy [J] of the fluid (see :func:`fluid_energies`); 2-D:
    per metre of width [J/m]. ``z_ref`` [m] the height of zero potential energy. Columns
    ``kinetic``, ``potential``."""

    columns = ("kinetic", "potential")

    def __init__(self, z_ref: float = 0.0, name: str = "energy"):
        if not (isinstance(z_ref, (int, float)) and math.isfinite(z_ref)):
            raise InputError(f"Energy: z_ref={z_ref!r}; give a finite height [m]")
        self.z_ref = float(z_ref)
        self.name = name

    def sample(self, fluid) -> dict:
        ke, pe = fluid_energies(fluid, self.z_ref)
        return {"kinetic": ke, "potential": pe}
