"""``Fluid`` on the GPU: what ``Fluid(FluidConfig(device="cuda"), particles)`` builds.

:class:`CudaFluid` is the CPU ``Fluid`` with its step, sort, rates, NaN guard, group
loads and boundary placement run on the device (:class:`fluid.cuda.state.DeviceState`);
everything else (the sub-cycling of ``advance``, the step's order of operations in
``_end_step``, the time-step limit's arithmetic, the messages) is the CPU class's own.

The particle data live on the device between steps. The host copy (``ps``, the
integrator's ``_aux``, the rates ``_acc``, ``_drho``, ``_cs``, ``_xsph``, the cell
offsets ``_start``) is brought back only when something reads it (an output, a probe,
``wall_pressure``, ``save_state``, the NaN guard's message), and the device takes the
host copy back before its next step whenever the host copy was handed out (it may have
been changed: ``set_group_velocity``, ``settle``, ``load_state``). In a coupled step only
scalars, the group loads and the bodies' placements (by id) cross the bus.
"""

from __future__ import annotations

import logging
import math

import numba
import numpy as np
from numba import cuda

from errors import InputError, InstabilityError
from fluid.cuda.state import DeviceState
from fluid import mls
from fluid.integrator import step_limit
from fluid.kernels import alpha_d
from fluid.particles import Kind
from fluid.boundary_correction import MDBC
from fluid.relaxation import Slab
from fluid.wall_density import AdamiWalls
from fluid.solver import Fluid, motion_acceleration

log = logging.getLogger(__name__)


class _Host:
    """An attribute of the host copy: reading it brings the device state back first (and
    hands the copy out: the device re-reads it before its next step); writing it marks
    the device stale."""

    def __set_name__(self, owner, name):
        self.key = "_host" + name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        obj._to_host()
        obj._host_changed = True
        return obj.__dict__.get(self.key)

    def __set__(self, obj, value):
        obj.__dict__[self.key] = value
        obj._host_changed = True


class CudaFluid(Fluid):
    """The fluid stepped on an NVIDIA GPU (module docstring)."""

    ps = _Host()
    _aux = _Host()
    _acc = _Host()
    _drho = _Host()
    _cs = _Host()
    _xsph = _Host()
    _start = _Host()

    def __init__(self, config, particles):
        self.__dict__["_dev"] = None
        self.__dict__["_device_ahead"] = False
        self.__dict__["_host_changed"] = True
        super().__init__(config, particles)
        ps = particles
        if ps.ids.max() >= 2 ** 31 - 1:
            raise InputError("fluid: device='cuda' takes particle ids below 2^31")
        #: kind of every particle by id, and which ids are still in the domain (the
        #: checks of set_particle_motion without reading the device)
        self._kind_by_id = np.full(int(ps.ids.max()) + 1, -1, np.int8)
        self._kind_by_id[ps.ids] = ps.kind
        self._alive = np.zeros(self._kind_by_id.size, bool)
        self._alive[ps.ids] = True
        c = config
        self._key = (self._kernel, c.dim == 3, c.nu > 0.0, c.xsph_eps > 0.0, c.alpha_wall != 1.0,
                     not c.diffusion_at_surface, c.diffusion == "antuono")
        self._prm_dev = None

    def _threads(self) -> int:  # the host's share is transfers and set-up: numba's threads as they are
        return numba.get_num_threads()

    # ------------------------------------------------------------------ host <-> device
    def _to_host(self) -> None:
        """Bring the device state into the host copy if the device is ahead of it."""
        if not self.__dict__.get("_device_ahead"):
            return
        d = self.__dict__
        ps = d["_hostps"]
        c = self.config
        aux, rates = self._dev.pull(ps, c.rho0, c.speed_of_sound, c.gamma)
        d["_host_aux"] = aux
        for k in ("acc", "drho", "cs", "xsph", "start"):
            d["_host_" + k] = rates[k]
        d["_device_ahead"] = False

    def _to_device(self) -> DeviceState:
        """The device state, after taking the host copy if it was handed out or changed."""
        d = self.__dict__
        if d["_dev"] is None:
            c = self.config
            saved = ("vel", "rho") if c.integrator == "verlet" else ("pos", "vel", "rho")
            d["_dev"] = DeviceState(d["_hostps"].n, c.dim, self._grid, saved, c.xsph_eps > 0.0,
                                    int(self._kind_by_id.size - 1), renorm=c.diffusion == "antuono")
            self._prm_dev = cuda.to_device(self._prm)
        if d["_host_changed"]:
            rates = None
            if d.get("_host_acc") is not None:
                rates = {k: d.get("_host_" + k) for k in ("acc", "drho", "cs", "xsph", "start")}
            d["_dev"].push(d["_hostps"], d.get("_host_aux") or {}, rates)
            d["_host_changed"] = False
        d["_device_ahead"] = True
        return d["_dev"]

    @property
    def device_memory(self) -> dict:
        """Device memory this fluid allocated: bytes per particle (arrays sized by the
        particle count, the id map included), bytes per cell of the grid, and the total
        [B]."""
        dev = self._to_device()
        total = sum(sum(v.values()) for v in dev.device_bytes().values())
        return {"bytes_per_particle": dev.bytes_per_particle(), "bytes_per_cell": dev.bytes_per_cell(),
                "cells": dev.ncells, "particles": dev.cap, "total_bytes": total}

    # ------------------------------------------------------------------ the step
    def step(self, dt: float):
        c = self.config
        for i, zone in enumerate(self.zones):  # before any work: _apply_zones takes them as checked
            _zone_on_device(zone, i)
        dev = self._to_device()
        if c.integrator == "verlet":
            loads = self._group_sums()
            euler = self.counters.steps % c.verlet_reset == 0
            dev.verlet(dt, c.rho0, euler)
            self._end_step(dt)
            return loads
        dev.predictor(dt, c.rho0)
        self._place_prescribed(self.t + 0.5 * dt)
        self._sort()
        self._rates()
        loads = self._group_sums()
        self._to_device().corrector(dt, c.rho0)
        self._end_step(dt)
        return loads

    def _sort(self):
        dev = self._to_device()
        outside = dev.bin()
        n = dev.n - outside
        if outside:
            gone = dev.outside_rows(outside)
            P, V, rho = dev.rows("P", gone), dev.rows("V", gone), dev.rows("rho", gone)
            bad = ~(np.isfinite(P).all(axis=0) & np.isfinite(V).all(axis=0) & np.isfinite(rho))
            if bad.any():
                self._raise_non_finite(int(gone[np.argmax(bad)]))
            ids = dev.rows("ids", gone).astype(np.int64)
            self.counters.count_removed(dev.rows("kind", gone), self.t)
            self._alive[ids] = False
            if not (self._kind_by_id[self._alive] == Kind.FLUID).any():
                raise InstabilityError(f"fluid: every fluid particle has left the domain by t={self.t:.6g} s")
        dev.gather(n)
        self.__dict__["_sorted"] = object()  # a new cell list (cells_version)

    def _rates(self):
        c = self.config
        dev = self._to_device()
        for hook in _hooks(self.boundary_correction):
            if isinstance(hook, AdamiWalls):
                has = self._wall_accelerations(dev)
                dev.adami(has, hook.kernel, hook.ad, c.h, c.rho0, hook.B, c.gamma, hook.g, int(Kind.FIXED_WALL),
                          int(Kind.MOVING_WALL), hook.p_floor)
            elif isinstance(hook, MDBC):
                lo, hi = self._ghost_range(hook)
                dev.mdbc(hook.offset[lo:hi], lo, hook.kernel, hook.ad, hook.h, hook.rho0, hook.det_min)
            else:
                raise InputError(f"fluid: device='cuda' runs the Adami walls and the bodies' mDBC as boundary "
                                 f"corrections, not {type(hook).__name__}; use device='cpu' for it")
        dev.rates(self._key, self._prm_dev, c.rho0, c.speed_of_sound, c.gamma)
        if self._drop_wall_continuity:
            dev.drop_rates_of_kinds(int(Kind.FIXED_WALL), int(Kind.MOVING_WALL))
        amax2, cvmax, cmax = dev.max_bounds()
        self._limit = step_limit(amax2, c.h / cvmax if cvmax > 0.0 else math.inf, cmax, c.h, c.cfl, c.dt_max, c.nu,
                                 **self._diffusivity)
        self._stale = False

    def _ghost_range(self, hook) -> tuple:
        """The ids [lo, hi) whose mDBC ghost vectors go to the device: those set when the
        rates were first taken (the bodies' particles; the coupler sets the same ids at
        every exchange)."""
        r = self.__dict__.get("_ghost_ids")
        if r is None:
            set_ = np.flatnonzero(np.any(hook.offset != 0.0, axis=1))
            r = (int(set_[0]), int(set_[-1]) + 1) if set_.size else (0, 0)
            self.__dict__["_ghost_ids"] = r
        return r

    def _wall_accelerations(self, dev, eps: float = 1e-6) -> bool:
        """The prescribed groups' accelerations onto the device, as
        Fluid.prescribed_acceleration takes them (``fluid.solver.motion_acceleration`` at
        the time they were last placed); False when there are none."""
        if not self._motions or math.isnan(self._t_placed):
            return False
        t, ids_all, acc_all = self._t_placed, [], []
        for group, (motion, ids, ref) in self._motions.items():
            keep = self._alive[ids]
            ids_all.append(ids[keep])
            acc_all.append(motion_acceleration(motion, ref, t, eps)[keep])
        dev.wall_accelerations(np.concatenate(ids_all), np.concatenate(acc_all))
        return True

    def _check_finite(self):
        i = self._to_device().first_non_finite()
        if i >= 0:
            self._raise_non_finite(i)

    def _group_sums(self):
        F, M = self._to_device().group_sums(self.moment_points, self.n_groups)
        F[self._wall_groups] = np.nan  # FluidConfig.wall_loads = False, as on the CPU (computed here all the same)
        M[self._wall_groups] = np.nan
        return F, M

    def _place_prescribed(self, t: float) -> None:
        self._t_placed = t
        if not self._motions:
            return
        dev = self._to_device()
        for group, (motion, ids, ref) in self._motions.items():
            keep = self._alive[ids]
            pos, vel = motion(t, ref)
            pos, vel = np.asarray(pos)[keep], np.asarray(vel)[keep]
            if not (np.isfinite(pos).all() and np.isfinite(vel).all()):
                raise InstabilityError(f"fluid: the prescribed motion of group {group} gave non-finite "
                                       f"positions or velocities at t={t:.9g} s")
            dev.place(ids[keep], pos, vel)

    def set_particle_motion(self, ids, pos, vel) -> None:
        if self._grid is None:  # before initialize (the coupler places its bodies first): on the host copy
            return super().set_particle_motion(ids, pos, vel)
        ids = np.asarray(ids, np.int64)
        if ids.size and (ids.min() < 0 or ids.max() >= self._alive.size or not self._alive[ids].all()):
            raise InputError("fluid: set_particle_motion got ids of particles that do not exist (removed?)")
        k = self._kind_by_id[ids]
        if (k == Kind.FLUID).any() or (k == Kind.FIXED_WALL).any():
            raise InputError("fluid: set_particle_motion moves MOVING_WALL or BODY particles only")
        pos, vel = np.asarray(pos, np.float64), np.asarray(vel, np.float64)
        if pos.shape != (len(ids), self.config.dim) or vel.shape != pos.shape:
            raise InputError(f"fluid: positions and velocities must have shape ({len(ids)}, {self.config.dim})")
        if not (np.isfinite(pos).all() and np.isfinite(vel).all()):
            raise InstabilityError("fluid: non-finite positions or velocities given for boundary particles")
        self._to_device().place(ids, pos, vel)
        if self._limit is not None:
            self._stale = True

    @property
    def cells_version(self):
        return self.__dict__.get("_sorted")

    def surface_on_device(self, gauges: np.ndarray) -> np.ndarray:
        """``fluid.probes.surface_elevation`` at ``gauges`` (M, 1) or (M, 2) [m], read on the
        device (only the heights come back)."""
        self.refresh_rates()
        c = self.config
        return self._to_device().surface(gauges, self._kernel, c.h, alpha_d(self._kernel, c.dim, c.h), 0.25 * c.dx)

    def _apply_zones(self, dt: float) -> None:
        dev = self._to_device()
        verlet = self.config.integrator == "verlet"
        for zone in self.zones:
            target = zone.target  # None (rest) or a SeaVelocity: _zone_on_device at the step's start
            if target is None:
                dev.relax(zone.axis, zone.inner, zone.outer, zone.rate, dt, verlet, self.t)
                continue
            current = target._current(self.t) if target.back is not None else (0.0, 0.0, 0.0)
            wall = target.wall.rate if target.wall is not None else 0.0
            dev.relax(zone.axis, zone.inner, zone.outer, zone.rate, dt, verlet, self.t, target.sea, current, wall)

    def _reinitialise_density(self) -> None:
        c = self.config
        self._to_device().reinitialise_density(self._kernel, alpha_d(self._kernel, c.dim, c.h), c.h,
                                               mls.MIN_SCALED_DET)


def _zone_on_device(zone, i: int):
    """The target of relaxation zone ``i`` as the GPU relaxes it: None (rest) or a
    ``fluid.nearfield.SeaVelocity`` of a linear sea or a Stokes-2 regular wave. A sea the
    CPU reads from a table (``fluid.sea_tables``, many components) is summed at each zone
    particle on the GPU: the table's interpolation (within 1 % of its shortest components'
    velocity) saves the CPU's time, where the GPU has the threads to sum. Any other zone is
    refused, saying which and what to change."""
    from fluid.nearfield import SeaVelocity
    from fluid.waves import RegularWave

    if not isinstance(zone, Slab):
        raise InputError(f"fluid: relaxation zone {i} is a {type(zone).__name__}; the GPU relaxes fluid.relaxation."
                         f"Slab zones only; use device='cpu'")
    target = zone.target
    if target is None:
        return None
    if isinstance(target, SeaVelocity) and (target.sea.linear or isinstance(target.sea, RegularWave)):
        return target
    what = (f"a {type(target.sea).__name__} with terms beyond linear theory" if isinstance(target, SeaVelocity) else
            f"a {type(target).__name__}")
    raise InputError(f"fluid: relaxation zone {i} relaxes towards {what}; the GPU relaxes towards rest, a linear "
                     f"sea or a Stokes-2 regular wave; use device='cpu'")


def _hooks(hook) -> list:
    """The boundary-correction hooks inside ``hook`` (None, one hook, or a pair with
    ``first`` and ``second``, as cosim.sph_fluid joins the walls' and the bodies')."""
    if hook is None:
        return []
    if hasattr(hook, "first") and hasattr(hook, "second"):
        return _hooks(hook.first) + _hooks(hook.second)
    return [hook]
