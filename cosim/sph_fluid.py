"""The SPH fluid in the coupler's fluid role: bodies join it as boundary particles.

At attachment each coupled body's geoms are sampled into dynamic boundary
particles (``bodies.MujocoBodies.boundary_particles``, on the fluid's spacing,
enough layers to fill the kernel support), placed from the body's pose, and
assembled with the fluid and its walls (fluid inside a body, found from its
geoms, is removed and counted). Each body is one ``BODY`` group of the fluid. Every
exchange places the group from the body's pose (rigid transform of body
coordinates: no drift) with velocities ``V + Ω × r`` (Barreiro et al. 2016, Eq. 13), and the
loads on a body are the sum over its particles of the force the fluid exerts on
them, about its centre of mass (Barreiro et al. 2016, Eq. 9-12). An elastic plate (``elastic=``,
:mod:`bodies.elastic`) is laid over whole instead: each of its particles blends the
poses of the two links nearest it and is its own group, and its exchanged impulse is
split between those links with the same weights.

By default the bodies' particles take modified dynamic boundary densities (mDBC,
``fluid.boundary_correction``): each has a ghost node mirrored across its geom's
surface (``bodies.sampling.ghost_offsets``, rotated with the body), and its density
is the fluid's there, extrapolated back. Measured on a 2-D box of 500 kg/m^3
released one spacing above its Archimedes position (``benchmarks/floating_box_sph.py``,
1.5 s): draft error -3.1 % of the height with mDBC and -6.5 % with plain dynamic
boundaries at dx = 12.5 mm, -1.6 % and -2.2 % at 6.25 mm (plain dynamic boundary
particles keep the density the body's motion into the fluid gave them).
"""

from __future__ import annotations

import logging
import math

import numpy as np

from bodies.sampling import ghost_offsets, particles_across, place, signed_distance
from cosim.errors import InputError
from fluid.boundary_correction import MDBC
from fluid.geometry import assemble, set_hydrostatic
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig
from fluid.standoff import fit_to_faces

log = logging.getLogger(__name__)


class _Both:
    """Two ``Fluid.boundary_correction`` hooks in turn (the tank walls' and the bodies'
    mDBC: they set the densities of different particles from the fluid's)."""

    def __init__(self, first, second):
        self.first, self.second = first, second

    def __call__(self, ps, start, grid) -> None:
        self.first(ps, start, grid)
        self.second(ps, start, grid)


class SPHFluid:
    """An SPH fluid that loads MuJoCo bodies.

    Parameters
    ----------
    config:
        The fluid's settings.
    fluid_points:
        Fluid particle positions [m], ``(N, dim)``.
    walls:
        ``(points, kind, group)`` wall sets, as for ``fluid.geometry.assemble``.
    z_surface:
        If given, the initial densities are hydrostatic below this surface height [m]
        (``surface_normal_to_gravity``: the height along -g of a plane normal to gravity).
    body_layers:
        Layers of boundary particles inside each body's surface; default: ceil(2 h / dx).
    boundary:
        How the bodies' boundary particles get their density: ``"mdbc"`` (default;
        modified dynamic boundaries, ``fluid.boundary_correction``: the fluid rests
        against the geometric surface, so a body displaces its own volume) or
        ``"dbc"`` (plain dynamic boundaries, Barreiro et al. 2016, §2.6: the fluid stands off
        by about h). The tank walls follow ``config.walls`` (``fluid.solver.FluidConfig``).
    motions:
        Prescribed motions of wall groups, ``{group: motion}`` (a wavemaker's paddle, a
        shaking tank; see ``fluid.solver.Fluid.prescribe_motion``), set when the fluid is
        built at attachment.
    elastic:
        Elastic cantilevers among the bodies (``bodies.elastic.BeamModel``, their links
        coupled: ``bodies=[..., *beam.link_names]``). Their boundary particles are laid over
        the whole plate and follow its deformed surface (``bodies.elastic.ElasticBody``:
        each particle blends the frames of the two links that carry it); each particle is
        its own boundary group, so that the impulse the fluid exchanged with it over an
        advance, and its moment about the origin, are known and split between its two
        links with the blending weights (momentum exchanged exactly, as for rigid bodies).
    zones, controllers:
        A near field's relaxation zones (``fluid.relaxation.Slab``) and absorbing end walls
        (``Fluid.controllers``, ``fluid.wall_absorption``), given to the fluid at attachment.

    A symmetry plane y = 0 (``config.symmetry_y``, :mod:`fluid.mirror`): each rigid body
    keeps its half y >= 0 and gets that half's load mirrored (:meth:`_to_wrench3`).
    """

    def __init__(self, config: FluidConfig, fluid_points, walls=(), *, z_surface: float | None = None,
                 surface_normal_to_gravity: bool = False,
                 body_layers: int | None = None, boundary: str = "mdbc", motions: dict | None = None,
                 elastic=(), zones=(), controllers=()):
        if boundary not in ("mdbc", "dbc"):
            raise InputError(f"SPH fluid: boundary={boundary!r}; choose 'mdbc' or 'dbc'")
        self.boundary = boundary
        self.config = config
        self.name = config.name
        self._fluid_points = np.asarray(fluid_points, float)
        self._walls = list(walls)
        self.z_surface = z_surface
        self.surface_normal_to_gravity = surface_normal_to_gravity
        self.body_layers = body_layers or math.ceil(2.0 * config.h_coef)
        self.fluid: Fluid | None = None
        self.removed_overlap = 0
        self.displaced_volume = 0.0
        self.motions = dict(motions or {})
        self.elastic_beams = list(elastic)
        self.elastic = []  #: bodies.elastic.ElasticBody per beam, made at attachment
        self.zones = list(zones)  #: relaxation zones (fluid.relaxation), given to the fluid at attachment
        self.controllers = list(controllers)  #: the fluid's controllers (Fluid.controllers), given alike
        self.symmetry = config.symmetry_y is not None
        if self.symmetry and config.symmetry_y_hi is None and (config.symmetry_y != 0.0 or self.elastic_beams):
            raise InputError(f"SPH fluid: a symmetry plane (symmetry_y = {config.symmetry_y}) is the plane y = 0 "
                             "of rigid bodies centred on it (no elastic plates)")
        if config.symmetry_y_hi is not None and self.elastic_beams:
            raise InputError(self._NO_BODIES_IN_SLICE.format(config.symmetry_y_hi))

    # -- coupling ----------------------------------------------------------------
    #: fewest boundary particles a body's geom may have across any of its axes [-]. With
    #: one particle across, that particle lies on the geom's mid-plane, at the same depth
    #: under both faces: its mDBC ghost node (the mirror image across the nearest face,
    #: ``bodies.sampling.ghost_offsets``) falls back onto the particle itself, inside the
    #: body (a box reflects it across both faces at once, the other shapes have no
    #: gradient there), so the density it takes is not the fluid's outside; and with plain
    #: DBC the fluid on each side meets a single row, a third of the kernel support
    #: (2 h = 2.8 dx), which it can push through. From two across every particle is nearest
    #: one face and mirrors into the fluid on that side (a 3-particle body floats: see
    #: tests/test_coupling_extremes.py).
    MIN_PARTICLES_ACROSS = 2

    def check_body_resolution(self, bodies) -> None:
        """Refuse, before any work, a body with a geom fewer than
        :attr:`MIN_PARTICLES_ACROSS` particles across, naming the body, the geom, its
        size, dx and the fix."""
        dx, dim = self.config.dx, self.config.dim
        names = getattr(bodies, "body_names", None)
        for beam in self.elastic_beams:
            n = beam.particles_across(dx)
            if n < self.MIN_PARTICLES_ACROSS:
                raise InputError(
                    f"SPH fluid: elastic plate '{beam.name}' is {beam.thickness:.4g} m thick, {n} particle(s) across "
                    f"at dx = {dx:.4g} m; its boundary needs at least {self.MIN_PARTICLES_ACROSS} across (a single "
                    f"column sits on the mid-plane, with no face of its own for its ghost node). Refine dx to "
                    f"{beam.thickness / self.MIN_PARTICLES_ACROSS:.3g} m or less, or give the plate the thin-wall "
                    f"treatment (thin_wall=True: two columns at +-dx/2, the fluid standing off by "
                    f"{max(dx - beam.thickness / 2, 0.0):.3g} m on each side)")
        links = self._link_names()
        for k, shapes in enumerate(bodies.geoms()):
            body = names[k] if names is not None else str(k)
            if body in links:  # an elastic beam's particles are laid over the whole plate
                continue
            for i, g in enumerate(shapes):
                axes, extent, n = particles_across(g, dx, dim)
                j = int(np.argmin(n))
                if n[j] < self.MIN_PARTICLES_ACROSS:
                    raise InputError(
                        f"SPH fluid: body '{body}' geom {i} ({g.kind}) is {extent[j]:.4g} m across along its "
                        f"{'xyz'[axes[j]]} axis, {n[j]} particle(s) at dx = {dx:.4g} m; its boundary needs at least "
                        f"{self.MIN_PARTICLES_ACROSS} particles across (a single row sits on the mid-plane, with no "
                        f"nearest face for its ghost node, and does not hold the fluid back). Refine dx to "
                        f"{extent[j] / self.MIN_PARTICLES_ACROSS:.3g} m or less, or make the body at least "
                        f"{self.MIN_PARTICLES_ACROSS * dx:.3g} m thick there")

    #: why a slice between two symmetry planes takes no bodies (its loads stand for a
    #: body repeated across y at the slice's width, which no scene means)
    _NO_BODIES_IN_SLICE = ("SPH fluid: a slice between two symmetry planes (symmetry_y_hi = {}) carries a flow "
                           "uniform across y and no bodies; leave symmetry_y_hi unset for a scene with bodies")

    def attach_bodies(self, bodies) -> None:
        c = self.config
        if c.symmetry_y_hi is not None and bodies.n_bodies:
            raise InputError(self._NO_BODIES_IN_SLICE.format(c.symmetry_y_hi))
        self.check_body_resolution(bodies)
        kin = bodies.kinematics()
        pb, owner = bodies.boundary_particles(c.dx, self.body_layers, c.dim)
        self._attach_elastic(bodies)
        rigid = ~np.isin(owner, self._elastic_rows)  # the links' own geom samples give way to the plate's
        pb, owner = pb[rigid], owner[rigid]
        # a symmetry plane: the half y >= 0 of each body (body frame), its particles on the
        # plane their own groups (counted once when the half's load is doubled)
        plane = np.zeros(len(pb), bool)
        if self.symmetry:
            tol = 1e-9 * c.dx
            keep = pb[:, 1] >= -tol
            pb, owner = pb[keep], owner[keep]
            plane = np.abs(pb[:, 1]) <= tol
        self._on_plane = plane
        x, _ = self._placed(pb, owner, kin)
        self._g0 = 1 + max([int(g) for _, _, g in self._walls], default=-1)
        pts = self._to_dim(x)
        body_sets = [(pts[(owner == k) & ~plane], Kind.BODY, self._g0 + k) for k in range(bodies.n_bodies)]
        g_e = self._g0 + bodies.n_bodies  # each beam one group here, one per particle after assembly
        for j, e in enumerate(self.elastic):
            body_sets.append((self._to_dim(e.place(kin)[0]), Kind.BODY, g_e + j))
        self._plane0 = g_e if self.symmetry else None  # no beams then: the bodies' plane rows' groups
        if self.symmetry:
            body_sets += [(pts[(owner == k) & plane], Kind.BODY, g_e + k) for k in range(bodies.n_bodies)]
        # the bodies' boundary particles fill only a band inside their surface: fluid
        # inside a body is found from its geoms, not from the distance to particles
        geoms = bodies.geoms()
        inside = self._inside_bodies(geoms, kin, self._to_3d(self._fluid_points))
        fpts, volume = self._fit_to_faces(self._fluid_points[~inside], geoms, getattr(bodies, "body_names", None), kin)
        built = assemble(c.dim, c.dx, c.rho0, fpts, self._walls + body_sets, volume=volume)
        ps = built.particles
        self.removed_overlap = int(inside.sum()) + built.removed_overlap
        #: fluid cells the bodies took at set-up [m^3, m^2 in 2-D], before the flat faces'
        #: fit (fluid.standoff) gave the water in front of them back its volume
        self.displaced_volume = int(inside.sum()) * c.dx**c.dim
        log.info("SPH fluid: %d fluid particles removed where the bodies are", self.removed_overlap)
        # ids are the assembly order: body k's particles in the order of pb[owner == k]
        self._ids = np.empty(len(pb), np.int64)
        for k in range(bodies.n_bodies):
            self._ids[(owner == k) & ~plane] = ps.ids[ps.group == self._g0 + k]
            if self.symmetry:
                self._ids[(owner == k) & plane] = ps.ids[ps.group == self._plane0 + k]
        self._ids.flags.writeable = False  # the fluid checks read-only ids once (Fluid.set_particle_motion)
        self._pb, self._owner = pb, owner
        self._elastic_ids, self._elastic_groups = [], []
        g_next = g_e + len(self.elastic)
        for j, e in enumerate(self.elastic):
            rows = np.flatnonzero(ps.group == g_e + j)
            rows = rows[np.argsort(ps.ids[rows])]  # assembly order: the beam's particle order
            ps.group[rows] = g_next + np.arange(len(rows))
            self._elastic_ids.append(ps.ids[rows].copy())
            self._elastic_ids[-1].flags.writeable = False
            self._elastic_groups.append(g_next + np.arange(len(rows)))
            g_next += len(rows)
        if self.z_surface is not None:
            set_hydrostatic(ps, self.z_surface, c.rho0, c.speed_of_sound, c.gamma,
                            c.gravity if self.surface_normal_to_gravity else c.g_down)
        self.fluid = Fluid(c, ps)
        for group, motion in self.motions.items():
            self.fluid.prescribe_motion(group, motion)
        self.fluid.zones.extend(self.zones)
        self.fluid.controllers.extend(self.controllers)
        self.n_bodies = bodies.n_bodies
        self._mdbc = None
        if self.boundary == "mdbc":
            geoms = bodies.geoms()
            self._ghost_b = np.zeros_like(pb)
            for k in range(bodies.n_bodies):
                self._ghost_b[owner == k] = ghost_offsets(geoms[k], pb[owner == k], c.dim)
            self._elastic_ghost = [e.beam.ghost_offsets(e.plate, c.dim, c.dx) for e in self.elastic]
            self._mdbc = MDBC(c.dim, c.h, c.rho0, c.kernel, int(ps.ids.max()) + 1)
            self._set_ghosts(kin)
            walls = self.fluid.boundary_correction  # the tank walls' own (FluidConfig.walls), if any
            self.fluid.boundary_correction = self._mdbc if walls is None else _Both(walls, self._mdbc)

    def _attach_elastic(self, bodies) -> None:
        """One :class:`bodies.elastic.ElasticBody` per elastic beam; the coupled-body rows of
        their links (which take no geom-sampled particles)."""
        from bodies.elastic import ElasticBody

        c = self.config
        self.elastic = [ElasticBody(beam, bodies, c.dx, self.body_layers, c.dim) for beam in self.elastic_beams]
        rows = [e.link_index for e in self.elastic]
        self._elastic_rows = np.concatenate(rows) if rows else np.zeros(0, np.int64)
        self._kin = None  # the kinematics the particles were last placed from

    @property
    def elastic_rows(self) -> list[int]:
        """The coupled-body indices of the elastic beams' links (after attachment)."""
        return [int(k) for k in getattr(self, "_elastic_rows", ())]

    def _elastic_wrenches(self, F, M):
        """The links' loads from the per-particle groups' (F (G, dim), M): each particle's
        force and moment about the origin (its group's moment point), split between its two
        links about their centres of mass where the particles were last placed."""
        n = self.n_bodies
        F3, T3 = np.zeros((n, 3)), np.zeros((n, 3))
        for e, groups in zip(self.elastic, self._elastic_groups):
            f, m = F[groups], M[groups]
            if self.config.dim == 2:
                f3, m3 = np.zeros((len(groups), 3)), np.zeros((len(groups), 3))
                f3[:, 0], f3[:, 2], m3[:, 1] = f[:, 0], f[:, 1], m[:, 0]
            else:
                f3, m3 = f, m
            Fe, Te = e.split(f3, m3, self._kin.com)
            F3 += Fe
            T3 += Te
        return F3, T3

    def _inside_bodies(self, geoms, kin, x3, slack: float = 0.5e-9) -> np.ndarray:
        """Fluid points ``x3`` (n, 3) whose cell (half a spacing around them) reaches into
        a body. A face on a lattice plane leaves the cells beside it alone: the test allows
        ``slack`` dx for round-off, and for a mesh for MuJoCo's float32 vertices (and the
        geom position it derives from them), 4 float32 epsilons of the mesh's reach from
        the body origin."""
        inside = np.zeros(len(x3), bool)
        for k, shapes in enumerate(geoms):
            pb = (x3 - kin.origin[k]) @ kin.rotation[k]  # body frame: R^T (x - origin)
            for g in shapes:
                pg = (pb - g.pos) @ g.rot  # geom frame
                tol = slack * self.config.dx
                if g.kind == "mesh":
                    reach = float(np.linalg.norm(g.pos)) + float(np.abs(g.mesh[0]).max())
                    tol += 4 * float(np.finfo(np.float32).eps) * reach
                inside |= signed_distance(g.kind, np.asarray(g.size, float), pg, g.mesh) < 0.5 * self.config.dx - tol
        return inside

    def _fit_to_faces(self, fp, geoms, names, kin):
        """The fluid points ``fp`` fitted to the rigid bodies' flat faces along the
        lattice's axes, and each one's volume factor (:func:`fluid.standoff.fit_to_faces`:
        a body at rest then carries its own volume's weight, not the cells missing
        between a face and the lattice's next plane). ``geoms``, ``names``: every body's."""
        links = self._link_names()
        world = []
        for k, shapes in enumerate(geoms):
            if names is not None and names[k] in links:
                continue
            R = kin.rotation[k]
            world += [(g.kind, np.asarray(g.size, float), kin.origin[k] + R @ g.pos, R @ g.rot) for g in shapes]

        def clear(p):  # a row put back stands dx/2 off its face: round-off allowed
            return ~self._inside_bodies(geoms, kin, p, slack=1e-6)

        x3, volume = fit_to_faces(self._to_3d(fp), world, self.config.dx, clear=clear)
        return self._to_dim(x3), volume

    def _link_names(self) -> set:
        """The MuJoCo bodies that are links of an elastic plate (their particles are the plate's)."""
        return {n for beam in self.elastic_beams for n in beam.link_names}

    def _to_3d(self, v):
        return v if self.config.dim == 3 else np.stack([v[:, 0], np.zeros(len(v)), v[:, 1]], axis=1)

    def _to_dim(self, v3):
        return v3[:, [0, 2]] if self.config.dim == 2 else v3

    def _set_ghosts(self, kin) -> None:
        """Ghost-node vectors of the body particles in the world frame (rotate with the body)."""
        g = np.einsum("nij,nj->ni", kin.rotation[self._owner], self._ghost_b)
        self._mdbc.set_offsets(self._ids, self._to_dim(g))
        for e, ids, ghost in zip(self.elastic, self._elastic_ids, self._elastic_ghost):
            self._mdbc.set_offsets(ids, self._to_dim(e.rotate(ghost, kin)))

    def _placed(self, pb, owner, kin):
        """World positions and velocities of the rigid bodies' particles (``place``), those on
        a symmetry plane put on it exactly: the pose's round-off (1e-17 m) would put them
        beyond it, where the fluid refuses particles."""
        x, u = place(pb, owner, kin)
        if self.symmetry:
            x[self._on_plane, 1] = 0.0
            u[self._on_plane, 1] = 0.0
        return x, u

    def set_body_kinematics(self, kin) -> None:
        if self._mdbc is not None:
            self._set_ghosts(kin)
        x, u = self._placed(self._pb, self._owner, kin)
        self.fluid.set_particle_motion(self._ids, self._to_dim(x), self._to_dim(u))
        self.fluid.moment_points[self._g0:self._g0 + self.n_bodies] = self._to_dim(kin.com)
        if self.symmetry:
            self.fluid.moment_points[self._plane0:self._plane0 + self.n_bodies] = kin.com
        self._kin = kin
        for e, ids in zip(self.elastic, self._elastic_ids):  # moment points stay at the origin
            e.check(kin)  # a chain gone unstable stops the run here, naming its element
            x, u = e.place(kin)
            self.fluid.set_particle_motion(ids, self._to_dim(x), self._to_dim(u))

    def body_wrenches(self):
        """Force [N] and torque about the centre of mass [N m] of the fluid on each
        body, world frame, from the rates at the current state (2-D: per metre of
        depth, which is the 1 m thick body's load)."""
        return self._to_wrench3(*self.fluid.group_forces_now())

    def body_particle_forces(self, k: int):
        """``(positions (n, 3) [m], forces (n, 3) [N], shares (n,))`` of body ``k``'s boundary
        particles at the current state, world frame: the force the fluid exerts on each
        (:meth:`fluid.solver.Fluid.boundary_forces_now`) and the number of times it counts in
        the body's load, so that ``(shares[:, None] * forces).sum(0)`` is the force of
        :meth:`body_wrenches` (a symmetry plane: 2 for the simulated half's rows, their
        images' too, and 1 on the plane, before the mirrored ``y`` component is dropped;
        without one 1). Rigid bodies only (``0 <= k < n_bodies``)."""
        F = self.fluid.boundary_forces_now()
        rows, shares = self.body_particle_rows(k)
        return self._to_3d(self.fluid.ps.pos[rows]), self._to_3d(F[rows]), shares

    def body_particle_rows(self, k: int):
        """``(rows, shares)``: body ``k``'s boundary particles in the current order of the
        fluid's particles, and the number of times each counts in the body's load (see
        :meth:`body_particle_forces`). The order is the one the last rates were taken in:
        read per-particle arrays with these rows after taking them (e.g.
        ``fluid.boundary_forces_now()``), not before. Rigid bodies only."""
        if not 0 <= k < self.n_bodies:
            raise InputError(f"SPH fluid: no rigid body {k}; bodies are 0..{self.n_bodies - 1}")
        ps = self.fluid.ps
        own = ps.group == self._g0 + k
        plane = (ps.group == self._plane0 + k) if self.symmetry else np.zeros_like(own)
        rows = np.flatnonzero((own | plane) & (ps.ids >= 0))
        return rows, np.where(plane[rows], 1.0, 2.0 if self.symmetry else 1.0)

    def exchanged_wrenches(self):
        """The loads the fluid actually exchanged with each body over its last
        advance (impulse / dt, about the centre of mass at the start of it): what a
        body must receive over the same interval for momentum to be exchanged
        exactly (the coupler's "fluid-first" scheme)."""
        return self._to_wrench3(*self.fluid.group_loads())

    def _to_wrench3(self, F_all, M_all):
        """The bodies' forces and torques (3-D) from the groups' loads. With a symmetry plane
        each body, symmetric about it and centred on it, has the boundary particles of its
        half y >= 0 (body frame): its load is its half's mirrored, ``F = (2 Fx, 0, 2 Fz)``,
        ``T = (0, 2 Ty, 0)`` about its centre of mass on the plane, its particles on the
        plane (their own groups, with no images) counted once."""
        F, M = F_all[self._g0:self._g0 + self.n_bodies], M_all[self._g0:self._g0 + self.n_bodies]
        if self.symmetry:  # the half's load mirrored across y = 0, the plane's rows once
            Fp, Mp = np.zeros_like(F), np.zeros_like(M)  # groups past the last one present hold nothing
            on = F_all[self._plane0:self._plane0 + self.n_bodies]
            Fp[:len(on)], Mp[:len(on)] = on, M_all[self._plane0:self._plane0 + len(on)]
            F3, T3 = 2.0 * F + Fp, 2.0 * M + Mp
            F3[:, 1] = 0.0
            T3[:, [0, 2]] = 0.0
            return F3, T3
        if self.config.dim == 3:
            F3, T3 = F.copy(), M.copy()
        else:
            n = self.n_bodies
            F3, T3 = np.zeros((n, 3)), np.zeros((n, 3))
            F3[:, 0], F3[:, 2] = F[:, 0], F[:, 1]
            T3[:, 1] = M[:, 0]
        if self.elastic:
            Fe, Te = self._elastic_wrenches(F_all, M_all)
            F3 += Fe
            T3 += Te
        return F3, T3

    # -- participant protocol (delegated) ------------------------------------------
    def _need(self):
        if self.fluid is None:
            raise InputError("SPH fluid: no bodies attached; add it to a Coupler with bodies=")
        return self.fluid

    def initialize(self, t0: float) -> None:
        self._need().initialize(t0)

    def max_dt(self) -> float:
        return self._need().max_dt()

    @property
    def dt_limit(self) -> str:
        """What sets :meth:`max_dt` now: one of ``fluid.integrator.LIMITERS`` (``force``:
        the CFL bound on the largest acceleration, ``courant_viscous``: the speed of sound's
        CFL bound, a diffusion limit or ``dt_max``)."""
        return self._need()._limit.limiter

    def advance(self, t: float, dt: float) -> None:
        self._need().advance(t, dt)

    def save_state(self):
        return self._need().save_state()

    def load_state(self, state) -> None:
        self._need().load_state(state)
