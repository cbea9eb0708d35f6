"""The SPH fluid as a co-simulation participant (structurally a
``cosim.protocol.Participant``; this package never imports the coupler).

One :class:`FluidConfig` holds every setting (each declared once, with its unit, default and
range, in :mod:`fluid.settings`) and is validated on construction. :class:`Fluid` owns a
:class:`~fluid.particles.ParticleSet`, keeps it sorted by cell, steps it with the symplectic
scheme of :mod:`fluid.integrator` and sub-cycles inside :meth:`Fluid.advance` to reach the
coupler's time exactly.
"""

from __future__ import annotations

import logging
import math
from contextlib import contextmanager
from dataclasses import dataclass, field

import numba
import numpy as np

from errors import InputError, InstabilityError
from fluid import equations as eq
from fluid import mls, settings, shifting, terms
from fluid.integrator import (StepLimit, corrector, diffusion_coefficient, first_non_finite, predictor,
                              stable_dt, verlet)
from fluid.kernels import alpha_d, kernel_id
from fluid.mirror import Mirror
from fluid.neighbours import Grid, fluid_near_cells, sort_by_cell, x_bin_array, x_bins
from fluid.particles import Kind, ParticleSet

log = logging.getLogger(__name__)


@numba.njit(cache=True)
def _sum_groups(pos, mass, acc, group, centre, F, M):
    """Force m a and moment (r - c) x m a summed per boundary group
    (:func:`fluid.terms.particle_load`; serial: a few microseconds per thousand particles)."""
    dim = pos.shape[1]
    for i in range(pos.shape[0]):
        g = group[i]
        if g < 0:
            continue
        three = dim == 3
        fx, fy, fz, mx, my, mz = terms.cpu.particle_load(
            mass[i], acc[i, 0], acc[i, 1] if three else 0.0, acc[i, dim - 1], pos[i, 0] - centre[g, 0],
            pos[i, 1] - centre[g, 1] if three else 0.0, pos[i, dim - 1] - centre[g, dim - 1])
        F[g, 0] += fx
        F[g, dim - 1] += fz
        if three:
            F[g, 1] += fy
            M[g, 0] += mx
            M[g, 1] += my
            M[g, 2] += mz
        else:
            M[g, 0] += my


#: the 2-D set-up for sloshing and wall pressures (standing waves in a tank):
#: ``FluidConfig(..., **SLOSHING_2D)``. Wendland with h = 2 dx, the one support near the usual
#: ones at which the square particle lattice under pressure is stable
#: (benchmarks/lattice_stiffness.py --stability; at the default sqrt(2) dx its spurious shear
#: stiffness makes waves 5-8 % fast), and tank walls that carry the fluid's pressure
#: ("adami": plain dynamic walls put a stiff spring at the contact line). It needs the
#: resolution: at 10 particle layers over the depth the 4 dx support's truncation at the
#: surface costs 1.5 % of rho g H in a tank at rest. Start a tank from rest with
#: Fluid.settle. Measured figures: the docstring of cosim.scene.setup.
SLOSHING_2D = {"h_coef": 2.0, "walls": "adami"}

#: the set-up for waves that travel (a flume's wavemaker, 2-D and 3-D): that of
#: :data:`SLOSHING_2D`, and what keeps a wave's height along the flume (docs/validation/
#: wave-propagation_history.md; ``cosim validate wave-propagation``). Measured, the height a wave loses per
#: wavelength comes from three terms: the density diffusion where the free surface cuts
#: the kernel's support (there it is a first-derivative flux, not a Laplacian: faded out,
#: ``diffusion_at_surface=False``), the artificial viscosity's friction on the floor
#: (a laminar boundary layer of nu ~ alpha h c0 / 8: slip walls, ``alpha_wall=0``) and
#: the artificial viscosity in the interior (2 nu k^2 / c_g per metre, Lamb 1932 §348:
#: ``alpha`` lowered from 0.01)
TRAVELLING_WAVES = {"h_coef": 2.0, "walls": "adami", "diffusion_at_surface": False, "alpha_wall": 0.0,
                    "alpha": 0.002}

#: particle rows over the depth from which travelling waves take :data:`FINE_WAVES`
FINE_WAVE_ROWS = 20
#: the wave set-up at :data:`FINE_WAVE_ROWS` rows over the depth and finer: h = 2.5 dx,
#: with which a piston wave's decay per wavelength halves from 10 to 20 rows (1.95 to 0.91 %
#: over 8 wavelengths) where h = 2 dx keeps 2.1 % at both; coarser, the wider kernel spans
#: too much of the depth (at 10 rows the wave 3 % high and 0.16 periods late at 8 wavelengths)
#: (docs/validation/wave-propagation_history.md)
FINE_WAVES = TRAVELLING_WAVES | {"h_coef": 2.5}


def travelling_waves(rows: float) -> dict:
    """The set-up of waves that travel many wavelengths at ``rows`` particle rows over the
    water's depth: :data:`FINE_WAVES` from :data:`FINE_WAVE_ROWS`, else
    :data:`TRAVELLING_WAVES`."""
    return dict(FINE_WAVES if rows >= FINE_WAVE_ROWS - 1e-9 else TRAVELLING_WAVES)


#: the set-up of a near field (fluid.nearfield: waves through a closed box for tens of
#: periods): that of :data:`TRAVELLING_WAVES`, and the density re-initialised from the
#: particles' positions every 150 steps (first-order MLS, Colagrossi & Landrini 2003), which
#: holds the box's mean level: without it the particles pack closer than their density says
#: and the level falls by about 1.3 % of the depth over 20 periods; every 30 steps it rises
#: and the heights scatter by 7 % (docs/validation/nearfield.md)
NEAR_FIELD = TRAVELLING_WAVES | {"mls_every": 150}


def _bad(what: str, fix: str):
    return InputError(f"FluidConfig: {what}; {fix}")


@dataclass(frozen=True)
@settings.declare
class FluidConfig:
    """Every setting of the SPH fluid: one field per entry of :data:`fluid.settings.SETTINGS`,
    which gives its default, unit, range and meaning. Validated on construction: each field
    against its entry's range (:func:`fluid.settings.check`), then the checks between fields
    (c0 or u_max, gravity's components, the domain's corners, the symmetry plane)."""

    def __post_init__(self):
        settings.check(self)
        num = lambda v: isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
        if (self.c0 is None) == (self.u_max is None):
            raise _bad("give exactly one of c0 [m/s] and u_max [m/s]",
                       "set c0, or set u_max (the expected maximum flow speed) and let c0 = c0_factor*u_max")
        if isinstance(self.g, (tuple, list, np.ndarray)):
            if len(self.g) != self.dim or not all(num(x) for x in self.g):
                raise _bad(f"g={self.g!r} m/s^2", f"give gravity as {self.dim} finite components (2-D: (gx, gz), "
                           f"3-D: (gx, gy, gz)), or as a number >= 0 acting along -z")
            object.__setattr__(self, "g", tuple(float(x) for x in self.g))
        elif not num(self.g) or self.g < 0:
            raise _bad(f"g={self.g!r} m/s^2", "give the magnitude of gravity (>= 0), it acts along -z; or the "
                       "vector (gx, gz) / (gx, gy, gz)")
        if self.device == "cuda":  # numba.cuda is imported here only
            from fluid.cuda import check_config
            check_config(self)
        if self.symmetry_y is not None:
            if self.dim != 3:
                raise _bad(f"symmetry_y={self.symmetry_y!r} m (dim={self.dim})", "a symmetry plane y = const is a "
                           "finite number in 3-D; leave it None in 2-D")
            if self.device != "cpu":
                raise _bad(f"symmetry_y with device={self.device!r}", "run a symmetry plane on device='cpu'")
        if self.symmetry_y_hi is not None:
            if self.symmetry_y is None:
                raise _bad(f"symmetry_y_hi={self.symmetry_y_hi!r} m without symmetry_y", "give symmetry_y too, the "
                           "slice's lower plane")
            if not self.symmetry_y_hi - self.symmetry_y >= 2.0 * self.h:
                raise _bad(f"symmetry_y_hi={self.symmetry_y_hi!r} m, {self.symmetry_y_hi - self.symmetry_y:g} m "
                           f"above symmetry_y", f"give a slice at least the kernel's support 2h = {2.0 * self.h:g} m "
                           "wide (its images reflect across one plane only)")
        if (self.domain_lo is None) != (self.domain_hi is None):
            raise _bad("only one domain corner given", "give both domain_lo and domain_hi, or neither")
        if self.domain_lo is not None:
            lo, hi = np.asarray(self.domain_lo, float), np.asarray(self.domain_hi, float)
            if lo.shape != (self.dim,) or hi.shape != (self.dim,) or not (hi > lo).all():
                raise _bad(f"domain {self.domain_lo} .. {self.domain_hi}",
                           f"give two corners of {self.dim} components with hi > lo")

    @property
    def h(self) -> float:
        """Smoothing length [m]."""
        return self.h_coef * self.dx

    @property
    def speed_of_sound(self) -> float:
        """c0 [m/s], given or c0_factor * u_max."""
        return self.c0 if self.c0 is not None else self.c0_factor * self.u_max

    @property
    def gravity(self) -> np.ndarray:
        """Gravity vector [m/s^2] of length dim (along -z where ``g`` is a number)."""
        if isinstance(self.g, tuple):
            return np.array(self.g)
        g = np.zeros(self.dim)
        g[-1] = -self.g
        return g

    @property
    def gravity3(self) -> np.ndarray:
        """Gravity vector [m/s^2] as (x, y, z) (2-D: y = 0)."""
        g = self.gravity
        return np.array([g[0], 0.0, g[1]]) if self.dim == 2 else g

    @property
    def g_down(self) -> float:
        """Gravity's component along -z [m/s^2]: what the hydrostatic rest state of a
        horizontal free surface is set from (``fluid.geometry.set_hydrostatic``)."""
        return float(-self.gravity[-1]) + 0.0

    @property
    def g_magnitude(self) -> float:
        """Gravity's magnitude [m/s^2]."""
        return float(np.linalg.norm(self.gravity))


@dataclass
class _Counters:
    steps: int = 0
    removed: dict = field(default_factory=lambda: {k.name: 0 for k in Kind})
    limiter: str = ""

    def count_removed(self, kinds: np.ndarray, t: float) -> None:
        """Count the particles of ``kinds`` that left the domain at ``t`` [s], and warn the
        first time and whenever the total has doubled: a splash can take one particle a
        step for thousands of steps (``removed`` keeps the whole count)."""
        before = sum(self.removed.values())
        names, counts = np.unique(kinds, return_counts=True)
        for k, cnt in zip(names, counts):
            self.removed[Kind(k).name] += int(cnt)
        total = before + kinds.size
        if before == 0 or total.bit_length() > before.bit_length():
            log.warning("fluid: %d particles left the domain at t=%.6g s and were removed (total %s; told again "
                        "when the total has doubled)", kinds.size, t, dict(self.removed))


def motion_acceleration(motion, ref: np.ndarray, t: float, eps: float = 1e-6) -> np.ndarray:
    """The acceleration [m/s^2] (m, dim) at time ``t`` [s] of the points ``ref`` (their
    reference positions) under a prescribed ``motion`` (``motion(t, ref) -> (pos, vel)``):
    its own ``particle_acceleration(t, ref)`` where it has one that gives an array, else the
    central difference of its velocity over ``+-eps`` [s] (of one point, for every one,
    where the motion says it is ``uniform``: a rigid translation)."""
    own = getattr(motion, "particle_acceleration", None)
    a = None if own is None else own(t, ref)
    if a is None:
        rows = ref[:1] if getattr(motion, "uniform", False) else ref
        v1 = np.asarray(motion(t + eps, rows)[1])
        v0 = np.asarray(motion(t - eps, rows)[1])
        a = np.broadcast_to((v1 - v0) / (2.0 * eps), ref.shape)
    return np.asarray(a)


class Fluid:
    """Weakly-compressible SPH fluid participant.

    ``Fluid(config, particles)``; then ``initialize(t0)``, ``max_dt()``, ``advance(t, dt)``.
    After :meth:`advance`, :meth:`group_loads` gives per boundary group the force and moment
    the fluid exerted on it, averaged over the interval (impulse / dt).
    """

    def __new__(cls, config=None, *args, **kwargs):
        if cls is Fluid and isinstance(config, FluidConfig) and config.device == "cuda":
            from fluid.cuda.fluid import CudaFluid  # its step on the GPU (fluid.cuda)
            cls = CudaFluid
        return super().__new__(cls)

    def __init__(self, config: FluidConfig, particles: ParticleSet):
        if not isinstance(config, FluidConfig):
            raise InputError("Fluid needs a FluidConfig as its first argument")
        particles.check()
        if particles.dim != config.dim:
            raise InputError(f"particles are {particles.dim}-D but the config says dim={config.dim}")
        if particles.n == 0 or not (particles.kind == Kind.FLUID).any():
            raise InputError("the particle set holds no fluid particle")
        self.config = config
        self.name = config.name
        self.ps = particles.copy()
        self._id_rows = None  # Fluid._rows_of's table, made after each sort
        self._group_kept: dict = {}  # Fluid._group_rows' answers, per group, while _id_rows stays
        self._movable_ids: dict = {}  # read-only id arrays set_particle_motion checked, by id()
        self._id_count = int(self.ps.ids.max()) + 1
        self.t = math.nan
        self.counters = _Counters()
        self.n_groups = int(particles.group.max()) + 1 if particles.group.max() >= 0 else 0
        self.moment_points = np.zeros((self.n_groups, config.dim))
        c = config
        self._kernel = kernel_id(c.kernel)
        self._prm = eq.params(c.h, alpha_d(self._kernel, c.dim, c.h), c.alpha, c.delta, c.diffusion,
                              c.rho0, c.speed_of_sound, c.gravity, nu=c.nu, xsph=c.xsph_eps,
                              alpha_wall=c.alpha_wall, diffusion_at_surface=c.diffusion_at_surface,
                              precision=c.precision)
        #: the diffusion limit's terms (fluid.integrator.stable_dt): artificial viscosity's
        #: share alpha / (2 (d + 2)), density diffusivity delta h c0 [m^2/s], the scheme's C
        self._diffusivity = dict(alpha_eff=c.alpha / (2.0 * (c.dim + 2)),
                                 nu_delta=0.0 if c.diffusion == "none" else c.delta * c.h * c.speed_of_sound,
                                 c_diff=diffusion_coefficient(c.integrator, c.verlet_reset))
        self._grid = None
        self._work = eq.Workspace()
        self._xbins = None  # the cell list's sub-bin table (fluid.neighbours.order_cells_by_x)
        #: the cells near the fluid (fluid.neighbours.fluid_near_cells), set before each rate
        #: evaluation for the boundary_correction hook and the pair loop
        self.near_fluid = None
        #: the rows of a symmetry plane's mirror images (bool; empty without a plane), set
        #: before each rate evaluation: the pair loops and the boundary_correction hook skip
        #: them, the step limit leaves them out
        self.image_rows = np.zeros(0, np.bool_)
        self._limit: StepLimit | None = None
        #: boundary particles were placed since the rates were taken (set_particle_motion)
        self._stale = False
        self._loads = (np.zeros((self.n_groups, c.dim)), np.zeros((self.n_groups, 3 if c.dim == 3 else 1)))
        #: prescribed motions: group -> (motion, ids sorted, reference positions in id order)
        self._motions: dict[int, tuple] = {}
        #: called as ``boundary_correction(ps, start, grid)`` before every rate evaluation, to
        #: set boundary-particle densities (e.g. ``fluid.boundary_correction.MDBC``); None: plain
        #: dynamic boundaries
        self.boundary_correction = None
        #: time [s] the prescribed groups were last placed at (the stage of the rates)
        self._t_placed = math.nan
        #: relaxation zones (fluid.relaxation: absorbing layers, imposed waves), applied to
        #: the fluid's velocities at the end of every step
        self.zones: list = []
        #: controllers of prescribed motions that read the fluid (``update(fluid, t, dt)`` at
        #: the end of every step, once it is sorted and its rates taken; ``save_state`` /
        #: ``load_state``: the near field's absorbing end walls, fluid.wall_absorption)
        self.controllers: list = []
        if c.walls == "adami":
            from fluid.wall_density import AdamiWalls
            self.boundary_correction = AdamiWalls(self)
        #: what the pair loop computes for the wall particles (fluid.equations.WALLS_*)
        self._walls_rates = (eq.WALLS_FULL if c.wall_loads else
                             eq.WALLS_NONE if c.walls == "adami" else eq.WALLS_CONTINUITY)
        #: Adami walls whose loads are computed: the pair loop's continuity rate of their
        #: particles is dropped, their density being Adami's Eq. 27 alone (as without loads)
        self._drop_wall_continuity = c.walls == "adami" and c.wall_loads
        #: a symmetry plane's mirror images (fluid.mirror), None without one
        self.mirror = None
        if c.symmetry_y is not None:
            y = particles.pos[:, 1]
            for beyond, plane, fix in ((y < c.symmetry_y, c.symmetry_y, "the half y >= it"),
                                       (y > (np.inf if c.symmetry_y_hi is None else c.symmetry_y_hi),
                                        c.symmetry_y_hi, "the slice between the planes (symmetry_y_hi)")):
                if beyond.any():
                    i = int(np.argmax(beyond))
                    raise InputError(f"particle {particles.ids[i]} at y = {y[i]:.6g} m lies beyond the symmetry "
                                     f"plane y = {plane:g} m: give only {fix}")
            self.mirror = Mirror(c.symmetry_y, 2.0 * c.h, c.dx, c.symmetry_y_hi)
        #: the groups made of wall particles: their loads are NaN when not computed
        self._wall_groups = np.zeros(self.n_groups, bool)
        if not c.wall_loads and self.n_groups:
            walls = (particles.kind == Kind.FIXED_WALL) | (particles.kind == Kind.MOVING_WALL)
            self._wall_groups[np.unique(particles.group[walls & (particles.group >= 0)])] = True

    # ------------------------------------------------------------------ protocol
    def _threads(self) -> int:
        c = self.config
        if c.threads is not None:
            return min(c.threads, numba.config.NUMBA_NUM_THREADS)
        return numba.config.NUMBA_NUM_THREADS if self.ps.n >= c.parallel_min_particles else 1

    @contextmanager
    def _own_threads(self):
        """Run the enclosed work on this fluid's numba threads, restoring the caller's."""
        saved = numba.get_num_threads()
        numba.set_num_threads(self._threads())
        try:
            yield
        finally:
            numba.set_num_threads(saved)

    def _on_own_threads(self, work, *args):
        """``work(*args)`` on this fluid's numba threads (:meth:`_own_threads`), switched only
        where the caller's differ: the switch costs more than a small fluid's step."""
        if numba.get_num_threads() == self._threads():
            return work(*args)
        with self._own_threads():
            return work(*args)

    def initialize(self, t0: float) -> None:
        self._on_own_threads(self._initialize, t0)

    def _initialize(self, t0: float) -> None:
        c = self.config
        pos = self.ps.pos
        if c.domain_lo is None:
            lo, hi = pos.min(axis=0), pos.max(axis=0)
            grow = np.maximum(0.1 * (hi - lo), 4 * c.h)
            lo, hi = lo - grow, hi + grow
        else:
            lo, hi = np.asarray(c.domain_lo, float), np.asarray(c.domain_hi, float)
        if self.mirror is not None:  # room for the images
            lo = lo.copy()
            lo[1] = min(lo[1], c.symmetry_y - 2.0 * c.h - c.dx)
            if c.symmetry_y_hi is not None:
                hi = hi.copy()
                hi[1] = max(hi[1], c.symmetry_y_hi + 2.0 * c.h + c.dx)
        # reach 1 (cells of the support 2h): fewer, longer contiguous rows vectorise
        # better; reach 2 visits 9 % fewer candidates in 3-D at the same speed
        # (docs/benchmarks/fluid_throughput_history.md)
        self._grid = Grid.covering(lo, hi, 2.0 * c.h, reach=1)
        out = ~np.all((pos >= lo) & (pos < hi), axis=1)
        if out.any():
            i = int(np.argmax(out))
            raise InputError(f"particle {self.ps.ids[i]} at {pos[i]} lies outside the domain {lo} .. {hi} m; "
                             "enlarge domain_lo/domain_hi")
        self.t = float(t0)
        self._place_prescribed(self.t)
        # the integrator's saved state: the n state of the predictor-corrector, Verlet's
        # n-1 velocity and density (sorted with the particles every step: keep no more)
        saved = ("vel", "rho") if self.config.integrator == "verlet" else ("pos", "vel", "rho")
        self._aux = {k: getattr(self.ps, k).copy() for k in saved}
        self._sort()
        self._rates()
        self._check_finite()
        if not (self._limit.dt > 0 and math.isfinite(self._limit.dt)):
            raise InputError(f"fluid: the initial state gives no finite stable step ({self._limit}); "
                             "give the fluid gravity, motion or a dt_max")

    def max_dt(self) -> float:
        return self._limit.dt

    @property
    def limiter(self) -> str:
        """Which condition limited the last step: one of ``fluid.integrator.LIMITERS`` (force,
        courant_viscous, a diffusion limit, dt_max or coupling)."""
        return self.counters.limiter

    def advance(self, t: float, dt: float) -> None:
        self._on_own_threads(self._advance, t, dt)

    def _advance(self, t: float, dt: float) -> None:
        if self._limit is None:
            raise InputError("Fluid.advance called before initialize")
        if not (dt > 0 and math.isfinite(dt)):
            raise InputError(f"fluid: cannot advance by dt={dt} s")
        if abs(t - self.t) > 1e-9 * max(1.0, abs(t)):
            log.warning("fluid: coupler time %.12g s differs from the fluid's %.12g s; taking the coupler's", t, self.t)
        t_end = t + dt
        self.t = t
        F = np.zeros_like(self._loads[0])
        M = np.zeros_like(self._loads[1])
        first = True
        while True:
            remaining = t_end - self.t
            if remaining <= 1e-12 * max(1.0, abs(t_end)):
                break
            lim = self._limit
            nsub = max(1, math.ceil(remaining / lim.dt * (1 - 1e-12)))
            h = remaining / nsub
            if first:  # the interval was cut into sub-steps by the stable step, or not
                self.counters.limiter = lim.limiter if nsub > 1 else "coupling"
                first = False
            fk, mk = self.step(h)
            F += fk * h
            M += mk * h
        self.t = t_end
        self._loads = (F / dt, M / dt)

    def settle(self, duration: float, tau: float | None = None) -> dict:
        """Relax the fluid at rest for ``duration`` [s] of damped motion, then restore the
        clock: the set-up lattice is not the discrete equilibrium of the SPH forces (kernel
        truncation at the free surface and the walls, the lattice's quadrature error), so a
        tank started from it moves by a fraction of dx and rings in weakly damped sloshing.
        Each step the fluid velocities are multiplied by ``exp(-dt / tau)`` (default
        ``tau = duration / 10``); boundaries are held still (prescribed motions frozen at
        the current time, boundary velocities zero) and restored afterwards.

        Settling finds a stable equilibrium only where there is one: on a square lattice
        the pressure term has a spurious shear stiffness that is negative at some h/dx
        (2-D Wendland h = 1.7 dx; benchmarks/lattice_stiffness.py ``--stability``), and
        there the particles rearrange, damped or not. Returns the largest fluid speed
        [m/s] before and after, the steps taken and the simulated time.
        """
        with self._own_threads():
            return self._settle(duration, tau)

    def _settle(self, duration: float, tau: float | None) -> dict:
        if self._limit is None:
            raise InputError("Fluid.settle called before initialize")
        if not (isinstance(duration, (int, float)) and math.isfinite(duration) and duration > 0):
            raise InputError(f"fluid: settle needs a positive duration [s], got {duration!r}")
        tau = 0.1 * duration if tau is None else tau
        if not (isinstance(tau, (int, float)) and math.isfinite(tau) and tau > 0):
            raise InputError(f"fluid: settle needs a positive damping time tau [s], got {tau!r}")
        t0, motions = self.t, self._motions
        v_before = self.max_speed()
        ps = self.ps
        bnd = (ps.kind != Kind.FLUID) & (ps.ids >= 0)
        order = np.argsort(ps.ids[bnd])
        bnd_ids, bnd_vel = ps.ids[bnd][order], ps.vel[bnd][order]  # restored afterwards
        frozen = {}
        for group, (motion, ids, ref) in motions.items():
            pos, _ = motion(t0, ref)
            frozen[group] = (lambda t, r, p=np.asarray(pos, float): (p, np.zeros_like(p)), ids, ref)
        self._motions = frozen
        controls = [c.save_state() for c in self.controllers]  # they read waves, not the settling
        steps0 = self.counters.steps
        try:
            ps.vel[bnd] = 0.0
            self._rates()
            elapsed = 0.0
            while elapsed < duration:
                dt = min(self._limit.dt, duration - elapsed + 1e-15)
                self.step(dt)
                elapsed += dt
                damp = math.exp(-dt / tau)
                fl = self.ps.kind == Kind.FLUID
                self.ps.vel[fl] *= damp
                if "vel" in self._aux:
                    self._aux["vel"][fl] *= damp
        finally:
            self._motions = motions
            self.t = t0
            for control, saved in zip(self.controllers, controls):
                control.load_state(saved)
        ps = self.ps
        bnd = (ps.kind != Kind.FLUID) & (ps.ids >= 0)
        ps.vel[bnd] = bnd_vel[np.searchsorted(bnd_ids, ps.ids[bnd])]
        self._place_prescribed(t0)
        self._sort()
        self._rates()
        out = {"max_speed_before_m_s": v_before, "max_speed_after_m_s": self.max_speed(),
               "steps": self.counters.steps - steps0, "duration_s": float(duration), "tau_s": float(tau)}
        log.info("fluid: settled for %.3g s (%d steps, tau %.3g s): largest speed %.3g -> %.3g m/s",
                 duration, out["steps"], tau, v_before, out["max_speed_after_m_s"])
        return out

    def save_state(self):
        # the rates travel with the state: the next step starts from them even when
        # boundary particles were placed since (see set_particle_motion), so a restored
        # run continues exactly as the original did
        rates = (self._drho, self._acc, self._cs, self._xsph, self._start, self._xbins)
        return {"ps": self.ps.copy(), "t": self.t, "steps": self.counters.steps,
                "removed": dict(self.counters.removed),
                "aux": {k: v.copy() for k, v in self._aux.items()},  # Verlet's n-1 state
                "rates": tuple(None if a is None else a.copy() for a in rates) + (self._limit, self._stale),
                "mirror": None if self.mirror is None else (self.mirror.rows.copy(), self.mirror.src.copy(),
                                                            self.mirror.plane.copy()),
                "controllers": [c.save_state() for c in self.controllers]}

    def load_state(self, state) -> None:
        self.ps = state["ps"].copy()
        self._id_rows = None
        self.t = state["t"]
        self.counters.steps = state["steps"]
        self.counters.removed = dict(state["removed"])
        self._aux = {k: v.copy() for k, v in state["aux"].items()}
        for control, saved in zip(self.controllers, state.get("controllers", ())):
            control.load_state(saved)
        if self.mirror is not None and state.get("mirror") is not None:  # the images' sources in this order
            rows, src, *plane = state["mirror"]
            self.mirror.rows, self.mirror.src = np.array(rows, np.int64), np.array(src, np.int64)
            # a state saved before the planes were kept: one plane
            self.mirror.plane = np.array(plane[0], float) if plane else np.full(len(rows), self.mirror.y0)
        if "rates" not in state or (self.mirror is not None and state.get("mirror") is None):
            self._sort()
            self._rates()
            self._stale = False
            return
        *arrays, self._limit, self._stale = state["rates"]
        if len(arrays) == 5:  # saved before the cell list had its sub-bin table
            arrays.append(None)
        self._drho, self._acc, self._cs, self._xsph, self._start, self._xbins = (
            None if a is None else a.copy() for a in arrays)
        if self._xbins is None:
            self._xbins = x_bins(self.ps.pos[:, 0], self._start, self._grid)

    # ------------------------------------------------------------------ outputs
    def group_loads(self):
        """(forces (G, dim) [N], moments [N m]) the fluid exerted on each boundary group over
        the last advance, about ``moment_points[k]``; moments are (G, 1) about +y in 2-D
        (``M_y = z F_x - x F_z``) and (G, 3) in 3-D."""
        return self._loads

    def group_forces_now(self):
        """Force (G, dim) [N] and moment on each boundary group from the rates of the current
        state (no time average)."""
        self.refresh_rates()
        return self._group_sums()

    def boundary_forces_now(self) -> np.ndarray:
        """Force [N] (N, dim) the fluid exerts on each particle at the current state, in the
        current order of ``self.ps``: ``m a`` of the boundary particles from the rates (the
        per-particle terms of :meth:`group_forces_now`), zero rows for the fluid and for a
        symmetry plane's images. With ``FluidConfig.wall_loads = False`` the tank walls' rows
        are NaN (their accelerations are not computed, as their groups' loads read NaN); the
        bodies' rows are computed either way."""
        self.refresh_rates()
        ps = self.ps
        F = ps.mass[:, None] * self._acc
        F[ps.kind == Kind.FLUID] = 0.0
        if not self.config.wall_loads:
            F[(ps.kind == Kind.FIXED_WALL) | (ps.kind == Kind.MOVING_WALL)] = np.nan
        return F

    def boundary_compression_power_now(self) -> np.ndarray:
        """Per particle [W] at the current state: ``m_b p_b / rho_b^2 (drho_b/dt)`` of each
        boundary particle, ``drho_b/dt`` its continuity sum over the fluid (Barreiro et al.
        2016, Eq. 7), ``p_b`` the pressure it acted with in that rate evaluation; zero for
        the fluid, and for tank walls whose densities do not follow the continuity equation
        (``walls = "adami"``: their rate is not kept). Summed over a body, it is the part of
        the work its pair forces do that no energy of the fluid receives: with neither
        viscosity nor density diffusion, the fluid's kinetic and internal energy (``de_a/dt
        = p_a / rho_a^2 drho_a/dt``, the SPH thermal energy equation; Monaghan 2005, Rep.
        Prog. Phys. 68: 1703) gain exactly the boundary's power less this sum. A boundary
        particle whose density follows the same continuity equation stores it as its own
        internal energy; one whose density is set otherwise (mDBC) does not."""
        self.refresh_rates()
        ps = self.ps
        out = ps.mass * ps.p / ps.rho ** 2 * self._drho
        out[ps.kind == Kind.FLUID] = 0.0
        return out

    def fluid_force_from_groups(self):
        """The force the boundary particles exert on the fluid at the current state (total
        rate of fluid momentum minus gravity) [N]; equal and opposite to the sum of
        :meth:`group_forces_now` (pair antisymmetry)."""
        self.refresh_rates()
        ps = self.ps
        fl = self._fluid_rows()
        return (ps.mass[fl, None] * (self._acc[fl] - self.config.gravity)).sum(axis=0)

    def set_group_velocity(self, group: int, velocity) -> None:
        """Prescribe the velocity [m/s] (dim,) of every particle of boundary ``group`` (a
        MOVING_WALL or BODY group), from now on; the particles move with it (dynamic
        boundaries, Barreiro et al. 2016, §2.6)."""
        ps = self.ps
        sel = ps.group == group
        if not sel.any():
            raise InputError(f"fluid: no boundary group {group}; groups are 0..{self.n_groups - 1}")
        if (ps.kind[sel] == Kind.FIXED_WALL).any():
            raise InputError(f"fluid: group {group} is a FIXED_WALL; give it kind MOVING_WALL to move it")
        v = np.asarray(velocity, np.float64)
        if v.shape != (self.config.dim,) or not np.isfinite(v).all():
            raise InputError(f"fluid: a group velocity has {self.config.dim} finite components, got {velocity!r}")
        ps.vel[sel] = v
        if self._limit is not None:  # the rates depend on the boundary velocity
            self._rates()

    def prescribe_motion(self, group: int, motion) -> None:
        """Drive the MOVING_WALL ``group`` by ``motion(t, ref) -> (pos, vel)``: ``ref`` are
        the group's particle positions [m] at the time of this call (the reference
        configuration, rows in particle-id order) and the call returns the positions [m]
        and velocities [m/s] ``(len(ref), dim)`` at time ``t`` [s] (a wavemaker, a tank
        under base excitation: ``fluid.motion``). The particles are placed exactly from
        it at every stage of every step (no drift from integrating the velocity)."""
        ps = self.ps
        sel = np.flatnonzero(ps.group == group)
        if sel.size == 0:
            raise InputError(f"fluid: no boundary group {group}; groups are 0..{self.n_groups - 1}")
        if (ps.kind[sel] != Kind.MOVING_WALL).any():
            raise InputError(f"fluid: group {group} is not a MOVING_WALL group; only those take a prescribed "
                             "motion (BODY groups are moved by the coupler)")
        if not callable(motion):
            raise InputError(f"fluid: a prescribed motion is a callable motion(t, ref) -> (pos, vel), got {motion!r}")
        order = np.argsort(ps.ids[sel])
        ids, ref = ps.ids[sel][order], ps.pos[sel][order].copy()
        pos, vel = motion(0.0 if math.isnan(self.t) else self.t, ref)
        if np.shape(pos) != ref.shape or np.shape(vel) != ref.shape:
            raise InputError(f"fluid: the motion of group {group} returned shapes {np.shape(pos)}, "
                             f"{np.shape(vel)}; expected {ref.shape} each")
        self._motions[group] = (motion, ids, ref)
        if self._limit is not None:
            self._place_prescribed(self.t)
            self._sort()
            self._rates()

    def _rows_of(self, ids: np.ndarray) -> np.ndarray:
        """The rows (current order) of the particles ``ids`` (int64 array of ids the fluid
        was built with), -1 for those that left the domain: the inverse of ``ps.ids`` over
        the simulated particles (a symmetry plane's images carry negative ids), made once
        after each sort."""
        inv = self._id_rows
        if inv is None:
            ps = self.ps
            inv = np.full(self._id_count, -1, np.int64)
            if self.mirror is None:
                inv[ps.ids] = np.arange(ps.n)
            else:
                real = np.flatnonzero(ps.ids >= 0)
                inv[ps.ids[real]] = real
            self._id_rows = inv
        return inv[ids]

    def _group_rows(self, group: int, ids: np.ndarray):
        """(rows of the prescribed ``group``'s particles ``ids`` (in id order) still present,
        the selection of those among ``ids``: particles may have left the domain), kept
        until the next sort (each sort makes a new :meth:`_rows_of` table)."""
        kept = self._group_kept.get(group)
        if kept is not None and kept[0] is self._id_rows and kept[1] is ids:
            return kept[2]
        rows = self._rows_of(ids)
        keep = rows >= 0
        out = (rows, slice(None)) if keep.all() else (rows[keep], keep)
        self._group_kept[group] = (self._id_rows, ids, out)
        return out

    def _place_prescribed(self, t: float) -> None:
        """Place every prescribed group at time ``t`` [s]."""
        ps = self.ps
        self._t_placed = t
        for group, (motion, ids, ref) in self._motions.items():
            sel, keep = self._group_rows(group, ids)
            pos, vel = motion(t, ref)
            pos, vel = np.asarray(pos)[keep], np.asarray(vel)[keep]
            if not (np.isfinite(pos).all() and np.isfinite(vel).all()):
                raise InstabilityError(f"fluid: the prescribed motion of group {group} gave non-finite "
                                       f"positions or velocities at t={t:.9g} s")
            ps.pos[sel] = pos
            ps.vel[sel] = vel

    @property
    def x_bins(self) -> np.ndarray:
        """The cell list's sub-bin table (fluid.neighbours.order_cells_by_x) of the current
        sort, for the boundary_correction hooks' loops."""
        return self._xbins

    def prescribed_acceleration(self, eps: float = 1e-6):
        """Acceleration [m/s^2] (N, dim) of every particle (current order) at the time the
        prescribed groups were last placed: the motion's own
        ``motion.particle_acceleration(t, ref)`` where it has one that gives an array, else the central difference of its velocity
        over ``+-eps`` [s] about it (of one particle, for every one, where the motion says it
        is ``uniform``: a rigid translation); zero for the other particles. None when no group
        has a prescribed motion."""
        if not self._motions or math.isnan(self._t_placed):
            return None
        ps, t = self.ps, self._t_placed
        acc = np.zeros((ps.n, self.config.dim))
        for group, (motion, ids, ref) in self._motions.items():
            sel, keep = self._group_rows(group, ids)
            acc[sel] = motion_acceleration(motion, ref, t, eps)[keep]
        return acc

    def set_particle_motion(self, ids, pos, vel) -> None:
        """Place boundary particles given by their ids: positions [m] and velocities
        [m/s], ``(len(ids), dim)`` (a body's particles placed from its pose by the
        coupler). They move with these velocities within the following steps.

        The rates are not recomputed here: the next step starts (its predictor) from the
        rates of the end of the last step, taken where the integrator had moved these
        particles, O(dt^2) from where they are placed now; its mid-step rates, which set
        the fluid's momentum change and the loads it exchanges, see the new placement.
        That saves one pair loop per coupling step (a third of the fluid's cost when the
        coupler places bodies every step). Loads and pressures asked for in between
        (:meth:`group_forces_now`, :meth:`wall_pressure`, probes) are recomputed for the
        new placement first (:meth:`refresh_rates`)."""
        ps = self.ps
        ids = np.asarray(ids, np.int64)
        if self._movable_ids.get(id(ids)) is ids:  # read-only ids checked before (a body's, every step)
            idx = self._rows_of(ids)
            if (idx < 0).any():
                raise InputError("fluid: set_particle_motion got ids of particles that do not exist (removed?)")
        else:
            inside = (ids >= 0) & (ids < self._id_count)
            idx = self._rows_of(np.where(inside, ids, 0))
            if not inside.all() or (idx < 0).any():
                raise InputError("fluid: set_particle_motion got ids of particles that do not exist (removed?)")
            if (ps.kind[idx] == Kind.FLUID.value).any() or (ps.kind[idx] == Kind.FIXED_WALL.value).any():
                raise InputError("fluid: set_particle_motion moves MOVING_WALL or BODY particles only")
            if not ids.flags.writeable:  # held, so its id stays its own; a particle's kind never changes
                self._movable_ids[id(ids)] = ids
        pos, vel = np.asarray(pos, np.float64), np.asarray(vel, np.float64)
        if pos.shape != (len(ids), self.config.dim) or vel.shape != pos.shape:
            raise InputError(f"fluid: positions and velocities must have shape ({len(ids)}, {self.config.dim})")
        if not (np.isfinite(pos).all() and np.isfinite(vel).all()):
            raise InstabilityError("fluid: non-finite positions or velocities given for boundary particles")
        ps.pos[idx] = pos
        ps.vel[idx] = vel
        if self._limit is not None:
            self._stale = True

    @property
    def cells_version(self):
        """What identifies the current cell list: a new object after each sort (the sort's
        ``start`` array here), for readers that keep what they read while the particles stay
        as sorted (fluid.wall_absorption.StripReader)."""
        return self._start

    def refresh_rates(self) -> None:
        """Take the rates (and the cell list) for the current placement of the boundary
        particles, if they were placed since the rates were last taken."""
        if self._stale:
            self._sort()
            self._rates()

    def wall_pressure(self) -> np.ndarray:
        """Pressure [Pa] per particle (current order of ``self.ps``): the fluid's own, and on
        boundary particles the average of the fluid next to them (Sunara et al. 2021, Eq. 15), which is the
        wall pressure to report (a dynamic boundary particle's own pressure is not)."""
        self.refresh_rates()
        c = self.config
        ps = self.ps
        return eq.boundary_pressure(ps.pos, ps.vel, ps.rho, ps.mass, ps.kind, self._start,
                                    self._grid, c.rho0, c.speed_of_sound, c.gamma)

    @property
    def limit(self) -> StepLimit:
        return self._limit

    # ------------------------------------------------------------------ internals
    def step(self, dt: float):
        """One step of ``dt`` [s] from the current state (rates already known). Returns the
        group forces and moments that moved the fluid over the step (symplectic: at the half
        step; Verlet: at the start)."""
        c = self.config
        ps, aux = self.ps, self._aux
        if c.integrator == "verlet":
            loads = self._group_sums()
            euler = self.counters.steps % c.verlet_reset == 0
            verlet(ps.pos, ps.vel, ps.rho, self._drho, self._acc, ps.kind, c.rho0, dt,
                   aux["vel"], aux["rho"], euler, self._xs())
            self._shift(dt)
            self._end_step(dt)
            return loads
        predictor(ps.pos, ps.vel, ps.rho, self._drho, self._acc, ps.kind, c.rho0, dt,
                  aux["pos"], aux["vel"], aux["rho"], self._xs())
        self._place_prescribed(self.t + 0.5 * dt)
        self._sort()
        self._rates()
        loads = self._group_sums()
        ps, aux = self.ps, self._aux
        corrector(ps.pos, ps.vel, ps.rho, self._drho, self._acc, ps.kind, c.rho0, dt,
                  aux["pos"], aux["vel"], aux["rho"], self._xs())
        self._shift(dt)
        self._end_step(dt)
        return loads

    def _shift(self, dt: float) -> None:
        """Particle shifting (``FluidConfig.shifting``; fluid.shifting): the fluid particles
        moved down their concentration gradient, after the step's position update and before
        the next sort, with the cell list of the step's last sort."""
        c = self.config
        if c.shifting == "none":
            return
        ps = self.ps
        ps.pos += shifting.fickian_shift(ps.pos, ps.vel, ps.mass, ps.kind, self._start, self._xbins,
                                         self._grid, self._kernel, c.h, c.dx, c.rho0, c.shifting_coef, dt,
                                         work=self._work)

    def _end_step(self, dt: float) -> None:
        """Count the step, check for non-finite values, re-sort, re-initialise the density
        every ``mls_every`` steps (on the sorted particles, so the cell list is current) and
        take the new rates."""
        self.counters.steps += 1
        self.t += dt
        self._place_prescribed(self.t)
        self._apply_zones(dt)
        self._check_finite()
        self._sort()
        if self.config.mls_every and self.counters.steps % self.config.mls_every == 0:
            self._reinitialise_density()
        self._rates()
        for control in self.controllers:  # on the sorted particles and their rates: the next step's motion
            control.update(self, self.t, dt)

    def _apply_zones(self, dt: float) -> None:
        """Relax the fluid in :attr:`zones` over the step ``dt`` [s] that ended now (Verlet's
        n-1 velocity alike)."""
        if not self.zones:  # self.ps is the host copy on a GPU: not read for nothing
            return
        ps = self.ps
        extra = self._aux["vel"] if self.config.integrator == "verlet" else None
        for zone in self.zones:
            zone.apply(ps.pos, ps.vel, ps.kind, self.t, dt, extra)

    def _reinitialise_density(self) -> None:
        """Fluid densities from the MLS interpolation (fluid.mls). Verlet's n-1 density is
        shifted by the same correction so that its leap-frog update keeps it."""
        c, ps = self.config, self.ps
        new, _ = mls.reinitialise(ps.pos, ps.rho, ps.mass, ps.kind, self._start, self._grid,
                                  self._kernel, alpha_d(self._kernel, c.dim, c.h), c.h)
        if c.integrator == "verlet":
            self._aux["rho"] += new - ps.rho
        ps.rho[:] = new

    def _sort(self):
        """Sort particles (and the saved n state) by cell; remove those outside the domain.
        With a symmetry plane the simulated particles and new mirror images of those near
        it are sorted together, in the same one gather (fluid.mirror)."""
        ps, m = self.ps, self.mirror
        if self._xbins is None:
            self._xbins = x_bin_array(self._grid)
        if m is None:
            rows, pos, n_real = None, ps.pos, ps.n
        else:
            m.reflect_crossing(ps, self._aux)
            rows, pos, n_real = m.extend(ps)
        perm, start, outside, self._xbins = sort_by_cell(pos, self._grid, self._xbins)
        kept = len(pos) - outside
        order = perm[:kept] if rows is None else rows[perm[:kept]]
        if outside:
            gone = perm[kept:]
            if rows is not None:  # images leave silently
                gone = rows[gone[gone < n_real]]
            if gone.size:
                bad = ~(np.isfinite(ps.pos[gone]).all(axis=1) & np.isfinite(ps.vel[gone]).all(axis=1)
                        & np.isfinite(ps.rho[gone]))
                if bad.any():
                    self._raise_non_finite(int(gone[np.argmax(bad)]))
                self.counters.count_removed(ps.kind[gone], self.t)
            if not (ps.kind[order] == Kind.FLUID).any():  # an image's source is kept with it
                raise InstabilityError(f"fluid: every fluid particle has left the domain by t={self.t:.6g} s")
        keys = list(self._aux)
        self._aux = dict(zip(keys, ps.permute(order, *(self._aux[k] for k in keys))))
        self._id_rows = None
        if m is not None:
            m.finish(ps, self._aux, perm, kept, n_real)
        self._start = start

    def _rates(self):
        c = self.config
        ps = self.ps
        m = self.mirror
        if m is not None:
            m.refresh(ps)
        self.near_fluid = fluid_near_cells(ps.kind, self._start, self._grid, self._work)
        if m is not None:
            self.image_rows = ps.ids < 0
        if self.boundary_correction is not None:
            self.boundary_correction(ps, self._start, self._grid)
            if m is not None:  # the images' own neighbourhoods are cut at the band's edge
                m.refresh(ps, density_only=True)
        self._drho, self._acc, visc, self._cs, self._xsph = eq.evaluate(
            ps.pos, ps.vel, ps.rho, ps.mass, ps.kind, self._start, self._grid, self._kernel,
            self._prm, c.rho0, c.speed_of_sound, c.gamma, ps.p, self._work, self._xbins, self.near_fluid,
            self._walls_rates, m, None if m is None else self.image_rows)
        if self._drop_wall_continuity:
            # the kinds' int values: numpy compares an array with an IntEnum member three times slower
            self._drho[(ps.kind == Kind.FIXED_WALL.value) | (ps.kind == Kind.MOVING_WALL.value)] = 0.0
        if m is None:
            self._limit = stable_dt(self._acc, visc, self._cs, ps.kind, c.h, c.cfl, c.dt_max, c.nu,
                                    **self._diffusivity)
        else:  # the images' rates are not used
            r = ~self.image_rows
            self._limit = stable_dt(self._acc[r], visc[r], self._cs[r], ps.kind[r], c.h, c.cfl, c.dt_max, c.nu,
                                    **self._diffusivity)
        self._stale = False

    def _xs(self) -> np.ndarray:
        """The XSPH correction of the current rates [m/s] (N, dim); empty when off."""
        return self._xsph if self._xsph is not None else np.zeros((0, self.config.dim))

    def _group_sums(self):
        ps = self.ps
        dim = self.config.dim
        F = np.zeros((self.n_groups, dim))
        M = np.zeros((self.n_groups, 3 if dim == 3 else 1))
        if self.n_groups:
            _sum_groups(ps.pos, ps.mass, self._acc, ps.group, self.moment_points, F, M)
            F[self._wall_groups] = np.nan  # FluidConfig.wall_loads = False
            M[self._wall_groups] = np.nan
        return F, M

    def _check_finite(self):
        ps = self.ps
        i = first_non_finite(ps.pos, ps.vel, ps.rho)
        if i >= 0:
            self._raise_non_finite(i)

    def _raise_non_finite(self, i: int):
        ps = self.ps
        prev = self._aux.get("pos")  # the start of the step (predictor-corrector only)
        where = ps.pos[i] if np.isfinite(ps.pos[i]).all() or prev is None else prev[i]
        raise InstabilityError(
            f"fluid: non-finite state at step {self.counters.steps}, t={self.t:.9g} s: particle id "
            f"{int(ps.ids[i])} (kind {Kind(int(ps.kind[i])).name}) at {np.array2string(where, precision=5)} m "
            f"(pos {ps.pos[i]}, vel {ps.vel[i]}, rho {ps.rho[i]}). Remedies: a smaller cfl, a larger c0, "
            "more artificial viscosity, or check the set-up for overlapping particles.")

    # ------------------------------------------------------------------ diagnostics
    def simulated(self) -> ParticleSet:
        """The particle set without a symmetry plane's mirror images (``self.ps`` itself
        when there is no plane)."""
        return self.ps if self.mirror is None else self.ps.select(self.ps.ids >= 0)

    def _fluid_rows(self) -> np.ndarray:
        """The simulated fluid particles (mask over the current order)."""
        fl = self.ps.kind == Kind.FLUID
        return fl if self.mirror is None else fl & (self.ps.ids >= 0)

    def kinetic_energy(self) -> float:
        fl = self._fluid_rows()
        return 0.5 * float((self.ps.mass[fl] * (self.ps.vel[fl] ** 2).sum(axis=1)).sum())

    def max_speed(self) -> float:
        fl = self._fluid_rows()
        return float(np.sqrt((self.ps.vel[fl] ** 2).sum(axis=1).max()))
