"""The particle data of a fluid on the GPU, and the operations of a step on it.

:class:`DeviceState` holds every per-particle array on the device between steps (the
arrays are listed, with their bytes, by :meth:`DeviceState.bytes_per_particle`) and runs
the kernels of :mod:`fluid.cuda.kernels`; it moves data to and from the host only when
asked (:meth:`push`, :meth:`pull`), and per step returns scalars only (the stable step's
bounds, the count of particles that left the domain, the NaN guard's row) and the group
loads (G x dim).
"""

from __future__ import annotations

import numpy as np
from numba import cuda

from fluid.cuda import kernels as K
from fluid.equations import equation_of_state

#: float64 rows: (dim, capacity); the rest (capacity,)
_F2 = ("P", "V")
_F1 = ("rho", "mass")


class DeviceState:
    """Particles on the device, sorted by cell on ``grid`` (``fluid.neighbours.Grid``,
    cells 2h wide, reach 1). ``saved``: the integrator's saved state, ``("pos", "vel",
    "rho")`` (symplectic) or ``("vel", "rho")`` (Verlet)."""

    def __init__(self, n: int, dim: int, grid, saved: tuple, xsph: bool, ids_max: int, renorm: bool = False):
        self.cap = n
        self.n = 0
        self.dim = dim
        self.grid = grid
        nx, ny, nz = grid.shape
        self.ncells = nx * ny * nz
        self.lo3 = cuda.to_device(grid.lo3)  # the pair loop's (x, y, z)
        self.lo = cuda.to_device(np.asarray(grid.lo, np.float64))  # the binning's (dim,)
        f2 = lambda: cuda.device_array((dim, n), np.float64)  # noqa: E731
        f1 = lambda: cuda.device_array(n, np.float64)  # noqa: E731
        self.a = {"P": f2(), "V": f2(), "rho": f1(), "mass": f1(),
                  "kind": cuda.device_array(n, np.int8), "group": cuda.device_array(n, np.int32),
                  "ids": cuda.device_array(n, np.int32)}
        #: the integrator's saved state, by the names of Fluid._aux
        self.saved = tuple(saved)
        for k in self.saved:
            self.a["aux_" + k] = f2() if k in ("pos", "vel") else f1()
        # rates
        self.drho, self.cs, self.pr2 = f1(), f1(), f1()
        self.acc = f2()
        self.xsph = xsph
        self.xs = f2() if xsph else cuda.device_array((dim, 0), np.float64)
        #: the renormalised density gradients of diffusion="antuono"
        self.G = f2() if renorm else cuda.device_array((dim, 0), np.float64)
        # the sort: cell of each particle, permutation, one scratch array per kind of array
        self.cell = cuda.device_array(n, np.int32)
        self.perm = cuda.device_array(n, np.int32)
        self.scratch = {"f2": f2(), "f1": f1(), "i4": cuda.device_array(n, np.int32),
                        "i1": cuda.device_array(n, np.int8)}
        self.start = cuda.device_array(self.ncells + 2, np.int32)
        self.fill = cuda.device_array(self.ncells + 1, np.int32)
        #: the chunk totals of each level of the scan of the cell counts
        self.sums = []
        m = self.ncells + 2
        while m > 1:
            m = (m + K.SCAN_CHUNK - 1) // K.SCAN_CHUNK
            self.sums.append(cuda.device_array(m, np.int32))
        self.slot = cuda.device_array(ids_max + 1, np.int32)
        self.bounds = cuda.device_array(3, np.float64)
        self.flag = cuda.device_array(1, np.int64)
        self.zero_aux = cuda.device_array((dim, 0), np.float64)
        #: the walls' prescribed accelerations (Adami walls with moving walls only; made when first needed)
        self.accw = None
        self._groups = None  # the group loads' arrays on the device (made when first needed)
        self._g3 = None  # gravity (x, y, z) of the Adami pass
        self.goff = None  # the bodies' mDBC ghost vectors (dim, ids in their range; made when first needed)

    # ------------------------------------------------------------------ memory
    def device_bytes(self) -> dict:
        """Bytes of every device array, by name: ``per_particle`` (arrays of the capacity,
        and the id map), ``per_cell`` (the cell offsets and the sort's cursors), ``fixed``."""
        part = {f"a.{k}": v.nbytes for k, v in self.a.items()}
        part.update({f"scratch.{k}": v.nbytes for k, v in self.scratch.items()})
        for k in ("drho", "cs", "pr2", "acc", "xs", "G", "cell", "perm", "slot"):
            part[k] = getattr(self, k).nbytes
        cells = {k: getattr(self, k).nbytes for k in ("start", "fill")}
        cells.update({f"sums.{i}": a.nbytes for i, a in enumerate(self.sums)})
        if self.accw is not None:
            part["accw"] = self.accw.nbytes
        if self.goff is not None:  # by id over the bodies' id range only
            part["goff"] = self.goff.nbytes
        fixed = {k: getattr(self, k).nbytes for k in ("bounds", "flag", "lo3", "lo", "zero_aux")}
        fixed.update({f"groups.{i}": a.nbytes for i, a in enumerate(self._groups or ())})
        return {"per_particle": part, "per_cell": cells, "fixed": fixed}

    def bytes_per_particle(self) -> float:
        """Device memory [B] per particle of the arrays sized by the particle capacity (the
        id map included), over the capacity; the cell offsets come on top
        (:meth:`bytes_per_cell`)."""
        return sum(self.device_bytes()["per_particle"].values()) / self.cap

    def bytes_per_cell(self) -> float:
        """Device memory [B] per cell of the grid (offsets, cursors, scan totals)."""
        return sum(self.device_bytes()["per_cell"].values()) / self.ncells

    # ------------------------------------------------------------------ transfers
    def push(self, ps, aux: dict, rates: dict | None) -> None:
        """Upload the particle set (in its order), the integrator's saved state and, if
        given, the rates (``drho``, ``acc``, ``cs``, ``xsph``) and ``start``."""
        n, dim = ps.pos.shape
        if n > self.cap:
            raise ValueError(f"{n} particles exceed the device capacity {self.cap}")
        self.n = n
        put = self._put
        put(self.a["P"], ps.pos.T)
        put(self.a["V"], ps.vel.T)
        put(self.a["rho"], ps.rho)
        put(self.a["mass"], ps.mass)
        put(self.a["kind"], ps.kind)
        put(self.a["group"], ps.group)
        put(self.a["ids"], ps.ids)
        for k in self.saved:
            if k in aux:
                v = aux[k]
                put(self.a["aux_" + k], v.T if v.ndim == 2 else v)
        if rates is not None:
            for name, dev in (("drho", self.drho), ("cs", self.cs), ("acc", self.acc), ("xsph", self.xs)):
                v = rates.get(name)
                if v is not None and dev.size:
                    put(dev, v.T if v.ndim == 2 else v)
            if rates.get("start") is not None:
                self.start.copy_to_device(rates["start"].astype(np.int32))
        self._slots()

    def _put(self, dev, host: np.ndarray) -> None:
        """Copy ``host`` (..., n) into the first n columns of ``dev`` (whole arrays move:
        a strided device slice is not a valid copy target)."""
        buf = np.zeros(dev.shape, dev.dtype)
        buf[..., :host.shape[-1]] = host
        dev.copy_to_device(buf)

    def pull(self, ps, rho0: float, c0: float, gamma: float):
        """Download the state into ``ps`` (arrays replaced, current order, ``n``
        particles; ``p`` from the equation of state as the CPU pack computes it). Returns
        (aux dict, rates dict)."""
        n = self.n
        host = lambda d: d.copy_to_host()[..., :n]  # noqa: E731
        ps.pos = np.ascontiguousarray(host(self.a["P"]).T)
        ps.vel = np.ascontiguousarray(host(self.a["V"]).T)
        ps.rho = host(self.a["rho"])
        ps.mass = host(self.a["mass"])
        ps.kind = host(self.a["kind"])
        ps.group = host(self.a["group"])
        ps.ids = host(self.a["ids"]).astype(np.int64)
        ps.p = np.empty(n)
        cs = np.empty(n)
        equation_of_state(ps.rho, rho0, c0, gamma, ps.p, cs)
        aux = {}
        for k in self.saved:
            v = host(self.a["aux_" + k])
            aux[k] = np.ascontiguousarray(v.T) if v.ndim == 2 else v
        rates = {"drho": host(self.drho), "acc": np.ascontiguousarray(host(self.acc).T), "cs": host(self.cs),
                 "xsph": np.ascontiguousarray(host(self.xs).T) if self.xsph else None,
                 "start": self.start.copy_to_host().astype(np.int64)}
        return aux, rates

    # ------------------------------------------------------------------ the cell list
    def bin(self) -> int:
        """Bin and order the particles (perm, start); returns how many lie outside the
        domain (sorted to the end; :meth:`gather` drops them)."""
        n, g = self.n, self.grid
        nx, ny, nz = g.shape
        m = self.ncells + 2
        K.k_zero_i4[K.launch(m)](self.start, m)
        K.k_bin[K.launch(n)](self.a["P"], n, self.lo, 1.0 / g.cell, nx, ny, nz, self.cell, self.start)
        self._scan(self.start, m, 0)
        K.k_copy_i4[K.launch(m - 1)](self.start, m - 1, self.fill)
        K.k_fill[K.launch(n)](self.cell, n, self.fill, self.perm)
        K.k_order[K.launch(self.ncells + 1)](self.perm, self.start, self.a["P"], self.ncells)
        K.k_read_i4[1, 1](self.start, self.ncells, self.flag)
        inside = int(self.flag.copy_to_host()[0])
        return n - inside

    def _scan(self, a, m: int, level: int) -> None:
        """Inclusive scan of ``a[0:m]`` in place: chunks of K.SCAN_CHUNK scanned in
        parallel, their totals scanned the same way (recursively), then added back."""
        sums = self.sums[level]
        k = (m + K.SCAN_CHUNK - 1) // K.SCAN_CHUNK
        K.k_scan_chunks[K.launch(k)](a, m, sums)
        if k > 1:
            self._scan(sums, k, level + 1)
            K.k_scan_add[K.launch(m)](a, m, sums)

    def outside_rows(self, outside: int) -> np.ndarray:
        """Rows (before the gather) of the particles that left the domain, in row order."""
        return self.perm.copy_to_host()[self.n - outside:self.n].astype(np.int64)

    def rows(self, name: str, rows: np.ndarray) -> np.ndarray:
        """Host copy of device array ``name`` at ``rows`` (a few particles)."""
        return self.a[name].copy_to_host()[..., rows]

    def gather(self, keep: int) -> None:
        """Apply the permutation to every particle array (the first ``keep`` rows: the
        particles inside the domain) and refresh the id map."""
        for name, arr in list(self.a.items()):
            kind = "f2" if arr.ndim == 2 else {np.dtype(np.float64): "f1", np.dtype(np.int32): "i4",
                                                np.dtype(np.int8): "i1"}[arr.dtype]
            dst = self.scratch[kind]
            if arr.ndim == 2:
                K.k_gather2[K.launch(keep)](arr, dst, self.perm, keep)
            else:
                K.k_gather1[K.launch(keep)](arr, dst, self.perm, keep)
            self.a[name], self.scratch[kind] = dst, arr
        self.n = keep
        self._slots()

    def _slots(self) -> None:
        K.k_slots[K.launch(self.n)](self.a["ids"], self.n, self.slot)

    def place(self, ids: np.ndarray, pos: np.ndarray, vel: np.ndarray) -> None:
        """Set positions and velocities (m, dim) of the particles ``ids`` (present ones)."""
        if len(ids) == 0:
            return
        K.k_place[K.launch(len(ids))](self.slot, cuda.to_device(np.ascontiguousarray(ids, np.int32)),
                                             cuda.to_device(np.ascontiguousarray(pos, np.float64)),
                                             cuda.to_device(np.ascontiguousarray(vel, np.float64)),
                                             self.a["P"], self.a["V"])

    # ------------------------------------------------------------------ rates and step
    def wall_accelerations(self, ids: np.ndarray | None, acc: np.ndarray | None) -> None:
        """The prescribed accelerations (m, dim) [m/s^2] of the particles ``ids``, zero for
        every other particle (:meth:`adami` reads them)."""
        if self.accw is None:
            self.accw = cuda.device_array((self.dim, self.cap), np.float64)
        K.k_zero2[K.launch(self.n)](self.accw, self.n)
        if ids is not None and len(ids):
            K.k_place_one[K.launch(len(ids))](self.slot, cuda.to_device(np.ascontiguousarray(ids, np.int32)),
                                              cuda.to_device(np.ascontiguousarray(acc, np.float64)), self.accw)

    def relax(self, axis: int, inner: float, outer: float, rate: float, dt: float, verlet: bool, t: float,
              sea=None, current=(0.0, 0.0, 0.0), wall: float = 0.0) -> None:
        """A relaxation slab (``fluid.relaxation.Slab`` from ``inner`` to ``outer`` [m] along
        ``axis``, ``rate`` [1/s]) over ``dt`` [s] ending at ``t`` [s], towards rest or the
        ``sea``'s velocity (``fluid.waves.Sea``: a linear sea summed at each particle, or a
        Stokes-2 ``RegularWave``) plus the return ``current`` (3,) [m/s] and the end wall's
        rate ``wall`` [m/s] along x; Verlet's n-1 velocity alike (``verlet``)."""
        want, comps, frame, stokes2 = self._sea_arrays(sea)
        cx, cy, cz = (float(v) for v in current)
        K.k_relax[K.launch(self.n)](
            self.a["P"], self.a["V"], self.a["aux_vel"] if verlet else self.zero_aux, verlet, self.a["kind"],
            self.n, axis, float(inner), 1.0 / (outer - inner), float(rate), float(dt), sea is not None, float(t),
            *frame[:4], *comps, *frame[4:], want, cx, cy, cz, float(wall), *stokes2)

    def _sea_arrays(self, sea):
        """What :meth:`relax` passes for ``sea`` (None: rest), made once and kept for the
        fluid's life: the velocity rows ``point_sums`` is asked for, the device copies of the
        components and their factors (``fluid.waves.component_factors``), the frame
        (heading cosines, level, depth, ``s_ref`` and the fade-in's arguments), and Stokes
        second order's flag and wave (``k_relax``'s last two arguments)."""
        from fluid.nearfield import _U_ONLY
        from fluid.waves import component_factors

        cache = self.__dict__.setdefault("_seas", {})
        key = id(sea)
        if key not in cache:
            wave2 = getattr(sea, "_stokes2", None)  # a Stokes-2 RegularWave's (fluid.waves.stokes2_wave)
            if sea is None:
                comps = tuple(np.zeros(0) for _ in range(6))
                frame = (1.0, 0.0, 0.0, 1.0, 0.0, False, 0.0, 1.0, 0.0)
            else:
                w, a, ph, k = (np.ascontiguousarray(v, np.float64) for v in sea._comp)
                comps = (w, a, ph, k) + component_factors(a, k, float(sea.depth), float(sea.g))
                e0, e1 = sea._heading2
                frame = (float(e0), float(e1), float(sea.level), float(sea.depth), float(sea._s_ref),
                         *sea._fade_args())
            stokes2 = (wave2 is not None, (0.0,) * 9 if wave2 is None else wave2)
            cache[key] = (sea, cuda.to_device(_U_ONLY), tuple(cuda.to_device(c) for c in comps), frame, stokes2)
        return cache[key][1:]

    def surface(self, gauges: np.ndarray, kernel: int, h: float, ad: float, step: float) -> np.ndarray:
        """The free surface's height [m] at each gauge (M, 1) x or (M, 2) (x, y) [m]
        (``fluid.probes.surface_elevation``), from the current cell list."""
        g = self.grid
        nx, ny, nz = g.shape
        out = cuda.device_array(gauges.shape[0], np.float64)
        K.k_surface[K.launch(gauges.shape[0])](cuda.to_device(np.ascontiguousarray(gauges, np.float64)),
                                               self.a["P"], self.a["kind"], self.a["mass"], self.a["rho"],
                                               self.start, self.lo, 1.0 / g.cell, nx, ny, nz, g.reach, kernel,
                                               h, ad, step, out)
        return out.copy_to_host()

    def reinitialise_density(self, kernel: int, ad: float, h: float, min_det: float) -> None:
        """MLS densities of the fluid particles (fluid.mls; Fluid._reinitialise_density),
        into the sort's scratch array, then applied (Verlet's n-1 density shifted with them)."""
        g3 = self.grid
        nx, ny, nz = g3.shape
        new = self.scratch["f1"]
        K.k_mls[K.launch(self.n)](self.a["P"], self.a["rho"], self.a["mass"], self.a["kind"], self.n, self.start,
                                  self.lo3, 1.0 / g3.cell, nx, ny, nz, kernel, ad, h, min_det, new)
        shift = "aux_rho" in self.a and "aux_pos" not in self.a  # Verlet's n-1 density
        K.k_mls_apply[K.launch(self.n)](self.a["rho"], new, self.a["aux_rho"] if shift else new, shift, self.n)

    def mdbc(self, offsets: np.ndarray, id_lo: int, kernel: int, ad: float, h: float, rho0: float,
             det_min: float) -> None:
        """The bodies' mDBC densities (fluid.boundary_correction.mdbc_density); ``offsets``
        (m, dim) [m] the ghost vectors of the ids ``id_lo .. id_lo + m - 1``."""
        m = offsets.shape[0]
        if self.goff is None or self.goff.shape[1] != m:
            self.goff = cuda.device_array((self.dim, m), np.float64)
        self.goff.copy_to_device(np.ascontiguousarray(offsets.T))
        g3 = self.grid
        nx, ny, nz = g3.shape
        K.k_mdbc[K.launch(self.n)](self.a["P"], self.a["rho"], self.a["mass"], self.a["kind"], self.a["ids"],
                                   self.goff, id_lo, self.n, self.start, self.lo3, 1.0 / g3.cell, nx, ny, nz, kernel,
                                   ad, h, rho0, det_min)

    def adami(self, has_acc: bool, kernel: int, ad: float, h: float, rho0: float, B: float, gamma: float,
              g: np.ndarray, kmin: int, kmax: int, p_floor: float) -> None:
        """Wall densities from the fluid's pressure: fluid.wall_density.adami_wall_density."""
        g3 = self.grid
        nx, ny, nz = g3.shape
        acc = self.accw if has_acc else self.zero_aux
        if self._g3 is None:
            self._g3 = cuda.to_device(np.asarray(g, np.float64))
        K.k_adami[K.launch(self.n)](self.a["P"], self.a["rho"], self.a["kind"], acc, has_acc, self.n, self.start,
                                    self.lo3, 1.0 / g3.cell, nx, ny, nz, kernel, ad, h, rho0, B, gamma,
                                    self._g3, kmin, kmax, p_floor)

    def rates(self, key: tuple, prm_dev, rho0: float, c0: float, gamma: float) -> None:
        """Equation of state, the density gradients if ``key`` (make_pair_loop's) asks for
        the renormalised diffusion, and the pair loop (fluid.equations.evaluate)."""
        n, g = self.n, self.grid
        nx, ny, nz = g.shape
        K.k_pack[K.launch(n)](self.a["rho"], n, rho0, c0, gamma, self.cs, self.pr2)
        if key[-1]:  # the renormalised gradients first (diffusion="antuono")
            grad = K.make_gradient_loop(key[0], key[1])
            grad[K.launch(n)](self.a["P"], self.a["rho"], self.a["mass"], self.a["kind"], self.cs, n, self.start,
                              self.lo3, g.cell, nx, ny, nz, prm_dev, self.G)
        loop = K.make_pair_loop(*key)
        K.k_zero_f8[K.launch(3)](self.bounds, 3)
        loop[K.launch(n)](self.a["P"], self.a["V"], self.a["rho"], self.a["mass"], self.a["kind"], self.cs,
                          self.pr2, n, self.start, self.lo3, g.cell, nx, ny, nz, prm_dev, self.drho, self.acc,
                          self.xs, self.bounds, self.G)

    def drop_rates_of_kinds(self, k1: int, k2: int) -> None:
        """Zero the density rates of the particles of kind ``k1`` or ``k2`` (Adami walls:
        fluid.solver.Fluid._rates)."""
        K.k_zero_of_kinds[K.launch(self.n)](self.drho, self.a["kind"], self.n, k1, k2)

    def max_bounds(self):
        """(max |a|^2 over fluid, max (c + visc), max c) of the last :meth:`rates`:
        fluid.integrator._bounds."""
        return self.bounds.copy_to_host()

    def predictor(self, dt: float, rho0: float) -> None:
        a, n = self.a, self.n
        K.k_predictor[K.launch(n)](a["P"], a["V"], a["rho"], self.drho, self.acc, a["kind"], n, rho0, dt,
                                          a["aux_pos"], a["aux_vel"], a["aux_rho"], self.xs, self.xsph)

    def corrector(self, dt: float, rho0: float) -> None:
        a, n = self.a, self.n
        K.k_corrector[K.launch(n)](a["P"], a["V"], a["rho"], self.drho, self.acc, a["kind"], n, rho0, dt,
                                          a["aux_pos"], a["aux_vel"], a["aux_rho"], self.xs, self.xsph)

    def verlet(self, dt: float, rho0: float, euler: bool) -> None:
        a, n = self.a, self.n
        K.k_verlet[K.launch(n)](a["P"], a["V"], a["rho"], self.drho, self.acc, a["kind"], n, rho0, dt,
                                       a["aux_vel"], a["aux_rho"], euler, self.xs, self.xsph)

    def damp(self, factor: float) -> None:
        a, n = self.a, self.n
        K.k_damp[K.launch(n)](a["V"], a.get("aux_vel", self.zero_aux), a["kind"], n, factor)

    def first_non_finite(self) -> int:
        """Lowest row with a non-finite position, velocity or density; -1 if none."""
        n = self.n
        K.k_set_i8[1, 1](self.flag, n)
        K.k_first_non_finite[K.launch(n)](self.a["P"], self.a["V"], self.a["rho"], n, self.flag)
        i = int(self.flag.copy_to_host()[0])
        return -1 if i >= n else i

    def group_sums(self, centre: np.ndarray, n_groups: int):
        """Force (G, dim) and moment (G, 1 or 3) on each boundary group: fluid.solver._sum_groups."""
        F = np.zeros((n_groups, self.dim))
        M = np.zeros((n_groups, 3 if self.dim == 3 else 1))
        if not n_groups:
            return F, M
        if self._groups is None or self._groups[0].shape != F.shape:
            self._groups = (cuda.device_array(F.shape, np.float64), cuda.device_array(M.shape, np.float64),
                            cuda.device_array((n_groups, self.dim), np.float64))
        dF, dM, dc = self._groups
        K.k_zero_all[K.launch(dF.size)](dF)
        K.k_zero_all[K.launch(dM.size)](dM)
        dc.copy_to_device(np.ascontiguousarray(centre, np.float64))
        K.k_group_sums[K.launch(self.n)](self.a["P"], self.a["mass"], self.acc, self.a["group"], self.n, dc, dF, dM)
        return dF.copy_to_host(), dM.copy_to_host()
