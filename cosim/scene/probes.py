"""The scene's probes: every recorded quantity is a named column ``ENTITY.QUANTITY`` with
its unit (``box.heave`` [m], ``box.left.tension`` [N], ``gauge1.eta`` [m]), in groups
that become one HDF5 series, one CSV and one plot each:

- ``motion``: per body, surge, heave and pitch (2-D: rotation about +y) or surge, sway,
  heave, roll, pitch, yaw (3-D, z-y-x Euler angles), displacements from the start [m]
  and angles [deg]; per elastic plate, the displacement from the start [m] of its upper
  left corner (top, -x face) and of its tip (top centre), ``plate.corner_x``,
  ``plate.corner_z``, ``plate.tip_x``, ``plate.tip_z`` (3-D also ``_y``), in the tank's
  frame (under base motion: the deflection a transducer on the tank reads, the clamp
  fixed), and under base motion the displacement of its clamp from the start in the
  world, ``plate.clamp_x``, ``plate.clamp_z``: the tank's;
- ``line_states``: per line, its state (Barreiro et al. 2016, Fig. 5: 0 resting, 1 partly lifted, 2
  fully lifted, 3 taut; :class:`moorings.catenary.LineState`), from every model that
  reports them (:mod:`moorings.line_events`: the catenary, the catenary FMU, the SPH cable,
  MoorDyn);
- ``line_points``: the positions [m] of the material ``points`` a line names,
  ``LINE.point1_x`` ... (the sph-cable, the catenary);
- ``tensions``: per line, the tension at its fairlead [N], at its anchor
  (``.anchor_tension`` [N]; the catenary, the SPH cable and MoorDyn report it, an FMU does
  not) and ``.tether`` [N], the load a taut inextensible catenary line carries as a length
  constraint;
- ``loads``: per body, the fluid's and the moorings' force [N] over the last step (each
  where the scene has a fluid, lines; a plate's: the sum over its links, the clamped foot's
  share included); with a fluid, per elastic plate also the net pressure along x [Pa] on
  each node's share, ``plate.p0`` (the clamp) to ``plate.pN`` (the free end), node ``k``
  at ``k L / N`` from the clamp: the fluid's x force on link ``k`` (the hat-weighted share
  of the boundary particles' forces, :meth:`bodies.elastic.ElasticBody.split`) over its
  span (``l / 2`` at the two ends, ``l`` between) times the width (``PLATE_pressure``);
- ``gauges``: free-surface elevation above the still water [m] at each gauge (the SPH
  fluid's, or the analytic fluid's incident sea, :mod:`fluid.waves`); ``sea``: with an
  incident sea and no gauge, its elevation at the origin, ``sea.eta`` [m];
- ``pressure``: each wall patch's pressure [Pa]; ``energy``: the SPH fluid's kinetic and
  potential energy [J] (2-D: J/m), and an SPH cable's mechanical energy, ``LINE.energy``.

Gauges and wall patches are fixed to the tank: under base motion they move with it, as
instruments on a shaking table do (a gauge at x measures, on the vertical through where
the tank's point (x, still level) is now, the surface's height above that point; a
patch's centre and normal are carried rigidly).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np


@dataclass
class Group:
    """Columns sampled together: ``sample()`` returns one value per column. A group of
    codes (``categories``) holds integers that index those names (a line's state);
    ``labels``: what a plot calls each column's entity, where its name alone does not say
    it (a gauge and where it stands)."""

    name: str
    columns: list
    units: list
    sample: Callable[[], np.ndarray]
    categories: tuple | None = None
    labels: list | None = None


def _gauge_labels(gauges, dim: int) -> list[str]:
    """``gauge1 at x = 0.6 m`` (3-D: at (x, y) = (0.6, 0.2) m)."""
    out = []
    for i, g in enumerate(gauges):
        v = np.ravel(np.asarray(g, float))
        at = f"x = {v[0]:g} m" if dim == 2 or v.size == 1 else f"(x, y) = ({v[0]:g}, {v[1]:g}) m"
        out.append(f"gauge{i + 1} at {at}")
    return out


def _state_names() -> tuple:
    """The line states in code order, as people read them ("partly lifted")."""
    from moorings.catenary import LineState

    return tuple(s.name.lower().replace("_", " ") for s in sorted(LineState, key=int))


def _angles(R: np.ndarray, dim: int) -> list[float]:
    if dim == 2:  # the hinge about +y: x' = x cos + z sin
        return [math.degrees(math.atan2(R[0, 2], R[2, 2]))]
    pitch = math.asin(max(-1.0, min(1.0, -R[2, 0])))
    return [math.degrees(math.atan2(R[2, 1], R[2, 2])), math.degrees(pitch), math.degrees(math.atan2(R[1, 0], R[0, 0]))]


def _in_tank_frame(points, move, t: float, dim: int) -> np.ndarray:
    """World points ``(n, 3)`` [m] in the frame of a tank that moves rigidly by ``move``
    (``fluid.motion``: ``move(t, ref)`` places the tank's points ``ref`` at time ``t``;
    None: at rest), the frame in which the tank was built: ``x_ref = R^T (x - o)``, with
    ``o`` where the tank's origin is now and ``R`` its turn (the images of the unit
    vectors)."""
    p = np.array(points, float)
    if move is None:
        return p
    axes = [0, 2] if dim == 2 else [0, 1, 2]
    o = np.asarray(move(t, np.zeros((1, dim)))[0][0], float)
    Rt = np.asarray(move(t, np.eye(dim))[0], float) - o  # row i: R e_i, so this is R^T
    p[:, axes] = (p[:, axes] - o) @ Rt.T
    return p


class Probe:
    """A kind of recorded quantity, registered in :data:`cosim.scene.registry.PROBES`
    (entry-point group ``cosim.probes``): the names of its series, known from the scene
    alone (:meth:`names`: ``cosim study`` checks its metrics with them), and the groups that
    sample them in the built scene (:meth:`groups`), the same columns in the same order."""

    def names(self, scene) -> list[str]:
        """The series' names ``ENTITY.QUANTITY`` a run of ``scene`` records."""
        raise NotImplementedError(f"{type(self).__name__}.names")

    def groups(self, scene, built) -> list[Group]:
        """The groups that sample them in ``built`` (:class:`cosim.scene.build.Built`)."""
        raise NotImplementedError(f"{type(self).__name__}.groups")


def groups(scene, built) -> list[Group]:
    """The probe groups of a built scene, probe by probe in the registry's order."""
    from cosim.scene.registry import PROBES

    return [g for _, probe in PROBES.items() for g in probe.groups(scene, built)]


def series_names(scene) -> list[str]:
    """The names of the series a run of ``scene`` records, known from the scene alone
    (before it is built: ``cosim study`` checks its ``--metric`` specs with them), in the
    order of :func:`groups`. An MJCF file's coupled bodies are read from the file."""
    from cosim.scene.registry import PROBES

    return [n for _, probe in PROBES.items() for n in probe.names(scene)]


def _axes(dim: int):
    """(translations, rotations, axes, components) of a body's motion in a ``dim``-D scene."""
    return ((["surge", "heave"], ["pitch"], [0, 2], "xz") if dim == 2 else
            (["surge", "sway", "heave"], ["roll", "pitch", "yaw"], [0, 1, 2], "xyz"))


def _body_names(built):
    """(coupled body names, elastic plates by name, the rigid bodies' names) of a built scene."""
    names = list(built.bodies.body_names)
    plates = getattr(built, "plates", None) or {}  # elastic plates: their links are coupled bodies
    links = {k for m in plates.values() for k in m.link_names}
    return names, plates, [n for n in names if n not in links]


def _scene_bodies(scene):
    """(the rigid bodies' names, elastic plates by name) from the scene alone."""
    from cosim.scene.checks import _check_mjcf
    from cosim.scene.spec import MJCF, ElasticPlate

    mjcf = [b for b in scene.bodies if isinstance(b, MJCF)]
    plates = {b.name: b for b in scene.bodies if isinstance(b, ElasticPlate)}
    rigid = (_check_mjcf(mjcf[0], "bodies[0]")["coupled"] if mjcf else
             [b.name for b in scene.bodies if not isinstance(b, ElasticPlate)])
    return rigid, plates


class Motion(Probe):
    """``motion``: each body's displacements and angles, each plate's corner, tip and clamp."""

    def names(self, scene):
        if not scene.bodies:
            return []
        lin, ang, _, comps = _axes(scene.world.dim)
        rigid, plates = _scene_bodies(scene)
        chosen = rigid + list(plates) if "all" in scene.probes.motion else list(scene.probes.motion)
        out = [f"{n}.{q}" for n in chosen if n not in plates for q in lin + ang]
        out += [f"{n}.{s}_{c}" for n in chosen if n in plates for s in ("corner", "tip") for c in comps]
        if scene.base_motion is not None:
            out += [f"{n}.clamp_{c}" for n in chosen if n in plates for c in comps]
        return out

    def groups(self, scene, built):
        b, dim = built.bodies, scene.world.dim
        if b is None:
            return []
        names, plates, rigid = _body_names(built)
        chosen = rigid + list(plates) if "all" in scene.probes.motion else [n for n in scene.probes.motion]
        idx = [names.index(n) for n in chosen if n not in plates]
        sites = {n: [b.site(f"{n}_corner")[0], b.site(f"{n}_tip")[0]] for n in chosen if n in plates}
        move, clock = getattr(built, "base_motion", None), built.coupler
        site0 = {n: _in_tank_frame(b.site_positions(ids), move, clock.t, dim) for n, ids in sites.items()}
        clamps = {n: names.index(plates[n].link_names[0]) for n in sites} if move is not None else {}
        com0, origin0 = b.kinematics().com.copy(), b.kinematics().origin.copy()
        lin, ang, axes, comps = _axes(dim)

        def motion():
            k = b.kinematics()
            row = []
            for j in idx:
                row += [float(k.com[j, a] - com0[j, a]) for a in axes] + _angles(k.rotation[j], dim)
            for n, ids in sites.items():
                row += list((_in_tank_frame(b.site_positions(ids), move, clock.t, dim) - site0[n])[:, axes].ravel())
            for n, j in clamps.items():
                row += [float(k.origin[j, a] - origin0[j, a]) for a in axes]
            return np.array(row)

        if not (idx or sites):
            return []
        cols = [f"{names[j]}.{q}" for j in idx for q in lin + ang]
        cols += [f"{n}.{s}_{c}" for n in sites for s in ("corner", "tip") for c in comps]
        cols += [f"{n}.clamp_{c}" for n in clamps for c in comps]
        units = [u for _ in idx for u in ["m"] * len(lin) + ["deg"] * len(ang)] + ["m"] * (
            (2 * len(sites) + len(clamps)) * len(comps))
        return [Group("motion", cols, units, motion)]


def _load_sources(scene) -> tuple:
    """Whose forces the ``loads`` probe reports: the fluid's where the scene has one
    (``fluid.model`` not "none"), the moorings' where it has lines (a column that could only
    read zero is left out)."""
    return tuple(s for s, there in (("fluid", scene.fluid.model != "none"), ("mooring", scene.moorings is not None))
                 if there)


class Loads(Probe):
    """``loads``: the fluid's and the moorings' force on each body; each plate's node pressures."""

    def names(self, scene):
        if not (scene.bodies and scene.probes.loads):
            return []
        comps = _axes(scene.world.dim)[3]
        rigid, plates = _scene_bodies(scene)
        sources = _load_sources(scene)
        out = [f"{n}.{src}_F{c}" for n in rigid + list(plates) for src in sources for c in comps]
        return out + [f"{n}.p{k}" for n, b in plates.items() for k in range(b.elements + 1) if "fluid" in sources]

    def groups(self, scene, built):
        b = built.bodies
        sources = _load_sources(scene)
        if b is None or not scene.probes.loads or not sources:
            return []
        names, plates, rigid = _body_names(built)
        axes, comps = _axes(scene.world.dim)[2:]
        led = built.coupler.ledger
        rows = [[names.index(n)] for n in rigid] + [[names.index(k) for k in m.link_names] for m in plates.values()]

        def loads():
            last = led.last()
            if not last:  # before the first step: the loads the coupler would apply now
                F, _, Fm, _ = built.coupler._loads(b.kinematics())
                last = {"fluid_force": F, "mooring_force": Fm}
            return np.concatenate([last[f"{src}_force"][j][:, axes].sum(axis=0) for j in rows for src in sources])

        cols = [f"{n}.{src}_F{c}" for n in rigid + list(plates) for src in sources for c in comps]
        out = [Group("loads", cols, ["N"] * len(cols), loads)]
        for n, m in plates.items() if "fluid" in sources else ():  # the net pressure on each node's share
            ids = [names.index(k) for k in m.link_names]
            area = np.diff(m.link_bounds, axis=1)[:, 0] * m.width

            def node_pressure(ids=ids, area=area):
                last = led.last()
                return np.asarray(last["fluid_force"])[ids, 0] / area if last else 0.0 * area

            out.append(Group(f"{n}_pressure", [f"{n}.p{k}" for k in range(len(ids))], ["Pa"] * len(ids),
                             node_pressure))
        return out


class Tensions(Probe):
    """``tensions``: each line's fairlead tension, anchor tension and tether load."""

    def names(self, scene):
        m = scene.moorings
        if m is None or not scene.probes.tensions:
            return []
        from cosim.scene.registry import MOORINGS

        model = MOORINGS[m.model]
        labels = [ln.name or ln.fairlead for ln in m.lines]
        breaking = any(ln.break_load is not None for ln in m.lines)
        out = [f"{n}.tension" for n in labels]
        if model.anchor_tensions or breaking:  # the models that report it (a breaking line's wrapper always does)
            out += [f"{n}.anchor_tension" for n in labels]
        if model.tethers and any(ln.EA is None for ln in m.lines):  # inextensible lines: tethers
            out += [f"{n}.tether" for n in labels]
        return out

    def groups(self, scene, built):
        m = built.mooring
        if m is None or not scene.probes.tensions:
            return []
        lines = built.line_names
        tethered = bool(built.coupler.tether_tensions())
        c = built.coupler

        anchors = callable(getattr(m, "anchor_tensions", None))  # the catenary, the SPH cable, MoorDyn

        def tensions():
            t = [np.linalg.norm(np.asarray(m.fairlead_forces(), float), axis=1)]
            if anchors:
                t.append(np.asarray(m.anchor_tensions(), float))
            if tethered:
                tt = c.tether_tensions()
                t.append([tt.get(f"{m.name}.{i}", 0.0) for i in range(len(lines))])
            return np.concatenate(t)

        cols = ([f"{n}.tension" for n in lines] + ([f"{n}.anchor_tension" for n in lines] if anchors else [])
                + ([f"{n}.tether" for n in lines] if tethered else []))
        return [Group("tensions", cols, ["N"] * len(cols), tensions)]


class LineStates(Probe):
    """``line_states``: each line's state (Barreiro et al. 2016, Fig. 5)."""

    def names(self, scene):
        m = scene.moorings
        if m is None or not scene.probes.tensions:
            return []
        from cosim.scene.registry import MOORINGS

        return [f"{ln.name or ln.fairlead}.state" for ln in m.lines] if MOORINGS[m.model].line_states else []

    def groups(self, scene, built):
        m = built.mooring
        if m is None or not scene.probes.tensions or getattr(m, "state_log", None) is None:
            return []
        return [Group("line_states", [f"{n}.state" for n in built.line_names], ["-"] * len(built.line_names),
                      lambda: np.asarray(m.line_states(), float), categories=_state_names())]


class LinePoints(Probe):
    """``line_points``: the positions [m] of the material points each line names in its
    ``points`` (arc lengths from its anchor), ``LINE.pointK_x`` (``_y`` in 3-D), ``_z``,
    K from 1 in the order given (the models that take ``points``: the sph-cable, the
    catenary)."""

    @staticmethod
    def _lines(scene):
        m = scene.moorings
        return [] if m is None else [(i, ln.name or ln.fairlead, ln.points) for i, ln in enumerate(m.lines)
                                     if ln.points]

    def names(self, scene):
        comps = _axes(scene.world.dim)[3]
        return [f"{n}.point{k + 1}_{c}" for _, n, pts in self._lines(scene) for k in range(len(pts)) for c in comps]

    def groups(self, scene, built):
        chosen = self._lines(scene)
        if not chosen:
            return []
        m = built.mooring
        cols = self.names(scene)

        def points():
            return np.concatenate([m.points_at(i, pts).ravel() for i, _, pts in chosen])

        labels = [f"{n}, s = {x:g} m" for _, n, pts in chosen for x in pts for _ in _axes(scene.world.dim)[3]]
        return [Group("line_points", cols, ["m"] * len(cols), points, labels=labels)]


def _has_sea(scene) -> bool:
    """Whether a fluid without particles has an incident sea (given, or a flume's wavemaker's)."""
    from cosim.scene.seas import IncidentSea
    from cosim.scene.spec import Analytic, Flap, Piston, Potential

    return isinstance(scene.fluid, (Analytic, Potential)) and isinstance(scene.waves, (IncidentSea, Piston, Flap))


class Gauges(Probe):
    """``gauges``: the free surface's elevation at each gauge (the SPH fluid's, or the
    incident sea's); ``sea``: with an incident sea and no gauge, its elevation at the origin."""

    def names(self, scene):
        from cosim.scene.spec import SPH

        p, sea = scene.probes, _has_sea(scene)
        if p.gauges and (isinstance(scene.fluid, SPH) or sea):
            return [f"gauge{i + 1}.eta" for i in range(len(p.gauges))]
        return ["sea.eta"] if sea else []

    def groups(self, scene, built):
        p, dim, sph = scene.probes, scene.world.dim, built.sph
        if sph is not None and p.gauges:
            from fluid.probes import surface_elevation

            g = np.array([x for x in p.gauges], float)
            level = built.level
            base = np.column_stack([g.reshape(len(g), -1), np.full(len(g), level)])  # the still surface under each

            def gauges():
                w = _in_tank(built, base)
                at = w[:, 0] if dim == 2 else w[:, :2].copy()
                if sph.mirror is not None:  # a gauge beyond a symmetry plane reads its mirror image
                    at[:, 1] = sph.mirror.y0 + np.abs(at[:, 1] - sph.mirror.y0)
                return surface_elevation(sph, at) - w[:, -1]

            return [Group("gauges", [f"gauge{i + 1}.eta" for i in range(len(g))], ["m"] * len(g), gauges,
                          labels=_gauge_labels(p.gauges, dim))]
        sea = _surface_sea(built.fluid) if sph is None else None  # the analytic or potential fluid's incident sea
        if sea is None:
            return []
        c = built.coupler
        if p.gauges:
            g = np.array([x for x in p.gauges], float).reshape(len(p.gauges), -1)
            gx, gy = (g[:, 0], np.zeros(len(g))) if dim == 2 else (g[:, 0], g[:, 1])

            def wave_gauges():
                return sea.elevation(gx, gy, c.t)

            return [Group("gauges", [f"gauge{i + 1}.eta" for i in range(len(g))], ["m"] * len(g), wave_gauges,
                          labels=_gauge_labels(p.gauges, dim))]
        return [Group("sea", ["sea.eta"], ["m"], lambda: np.atleast_1d(sea.elevation(0.0, 0.0, c.t)))]


def _in_tank(built, points):
    """Points [m] fixed to the tank, where they are now (rigidly moved with a moving tank)."""
    pts, move = np.asarray(points, float), built.base_motion
    return pts if move is None else np.asarray(move(built.sph.t, pts)[0], float)


class Pressure(Probe):
    """``pressure``: each wall patch's pressure (the SPH fluid)."""

    def names(self, scene):
        from cosim.scene.spec import SPH

        return [f"{q.name}.p" for q in scene.probes.pressure] if isinstance(scene.fluid, SPH) else []

    def groups(self, scene, built):
        sph, patches = built.sph, scene.probes.pressure
        if sph is None or not patches:
            return []
        from fluid.probes import wall_patch_pressure

        ends = [np.array([q.centre, np.add(q.centre, q.normal)], float) for q in patches]

        def pressure():
            row = []
            for q, e in zip(patches, ends):
                c, tip = _in_tank(built, e)
                row.append(wall_patch_pressure(sph, c, tip - c, q.size))
            return np.array(row)

        return [Group("pressure", [f"{q.name}.p" for q in patches], ["Pa"] * len(patches), pressure)]


class Energy(Probe):
    """``energy``: the SPH fluid's kinetic and potential energy."""

    def names(self, scene):
        from cosim.scene.spec import SPH

        return ["fluid.kinetic", "fluid.potential"] if isinstance(scene.fluid, SPH) and scene.probes.energy else []

    def groups(self, scene, built):
        sph = built.sph
        if sph is None or not scene.probes.energy:
            return []
        from fluid.probes import fluid_energies

        return [Group("energy", ["fluid.kinetic", "fluid.potential"], ["J/m" if scene.world.dim == 2 else "J"] * 2,
                      lambda: np.array(fluid_energies(sph)))]


class LineEnergy(Probe):
    """``energy`` with lines of a model that reports it (the sph-cable): each line's
    mechanical energy [J], ``LINE.energy`` (kinetic + the constant loads' potential +
    elastic)."""

    def names(self, scene):
        from cosim.scene.registry import MOORINGS

        m = scene.moorings
        if m is None or not scene.probes.energy or "energy" not in MOORINGS[m.model].extras:
            return []
        return [f"{ln.name or ln.fairlead}.energy" for ln in m.lines]

    def groups(self, scene, built):
        cols = self.names(scene)
        if not cols:
            return []
        return [Group("line_energy", cols, ["J"] * len(cols), lambda: np.asarray(built.mooring.line_energies()))]


class EndWalls(Probe):
    """``end_walls``: a near field's absorbing end walls (``domain.absorbing_walls``,
    :mod:`fluid.wall_absorption`): each wall's correction ``xi`` to the sea's orbits and
    the elevation ``eta`` beyond the sea's that it reads in front of it (what comes back)."""

    NAMES = ("near_wall.xi", "far_wall.xi", "near_wall.eta", "far_wall.eta")

    def names(self, scene):
        from cosim.scene.spec import NearField

        return list(self.NAMES) if isinstance(scene.domain, NearField) and scene.domain.absorbing_walls else []

    def groups(self, scene, built):
        if not self.names(scene):
            return []
        near, far = built.controllers[:2]

        def walls():
            f, t = built.sph, built.sph.t
            return np.array([near.xi(t), far.xi(t), near.beyond_sea(f, t), far.beyond_sea(f, t)])

        return [Group("end_walls", list(self.NAMES), ["m"] * 4, walls,
                      labels=["near end wall's correction", "far end wall's correction",
                              "elevation beyond the sea's before the near end wall",
                              "elevation beyond the sea's before the far end wall"])]


#: the built-in probes, in the order of the outputs' series
PROBES = {"motion": Motion(), "loads": Loads(), "tensions": Tensions(), "line_states": LineStates(),
          "line_points": LinePoints(), "gauges": Gauges(), "pressure": Pressure(), "energy": Energy(),
          "line_energy": LineEnergy(), "end_walls": EndWalls()}


class _PotentialSea:
    """The potential fluid's wave components read as ``elevation(x, y, t)``, as a
    ``fluid.waves.Sea`` is."""

    def __init__(self, sea):
        self.sea = sea

    def elevation(self, x, y, t):
        xy = np.column_stack([np.atleast_1d(np.asarray(x, float)), np.atleast_1d(np.asarray(y, float))])
        return self.sea.elevation(xy, t)


def _surface_sea(fluid):
    """The incident sea whose elevation the gauges of a fluid without particles read, or None."""
    from fluid.waves import Sea

    sea = getattr(fluid, "sea", None)
    if sea is None or isinstance(sea, Sea):
        return sea
    return _PotentialSea(sea) if hasattr(sea, "elevation") else None
