"""The mooring models a scene names in ``moorings.model``: each one a :class:`MooringModel`
that makes the participant (:class:`cosim.protocol.Mooring`) of the scene's lines and says
what the scene checks, records and estimates of it. The built-in ones are in
:data:`MODELS`; another package registers its own in :data:`cosim.scene.registry.MOORINGS`
(entry-point group ``cosim.moorings``).

Adding a model touches two files: its solver (in ``moorings/``, or in its own package) and
a :class:`MooringModel` here, listed in :data:`MODELS` (from another package: the
model's module and its ``pyproject.toml`` entry point); ``docs/scenes.md`` is then
regenerated (``python -m cosim.scene.reference > docs/scenes.md``).
"""

from __future__ import annotations

import math
from pathlib import Path


class MooringModel:
    """A mooring model as a scene sees it. Only :meth:`from_scene` must be given; the
    rest describes the model to the checks (:attr:`line_fields`), the coupler
    (:attr:`dynamic`), the records (:attr:`anchor_tensions`, :attr:`line_states`,
    :attr:`tethers`) and the cost estimate (:meth:`internal_step`)."""

    #: fields of :class:`cosim.scene.spec.Line` every line must give for this model
    line_fields: tuple[str, ...] = ()
    #: a line with state, resolved by ``moorings.segments`` and advanced with the bodies
    #: (the participant's ``dynamic`` is true; ``cosim study --extremes`` varies its segments)
    dynamic: bool = False
    #: the participant reports ``anchor_tensions()`` [N] (a series ``LINE.anchor_tension``)
    anchor_tensions: bool = False
    #: the participant logs each line's state (``state_log``; a series ``LINE.state``)
    line_states: bool = False
    #: inextensible lines are held by length constraints (a series ``LINE.tether``)
    tethers: bool = False
    #: CPU time [s] per node and internal step (the cost estimate's, measured)
    node_cost: float = 0.0
    #: the optional scene fields it honours, of ``moorings`` (``seabed``, ``damping``) and of
    #: its lines (``point_loads``, ``points``: then it has ``points_at(line, s)``; ``released``),
    #: and ``energy``: it has ``line_energies()`` (``probes.energy``); the checks refuse the others
    extras: tuple[str, ...] = ()
    #: the line's axial damping over its impedance ``sqrt(EA m)`` at the fairlead [-]
    #: (the coupling step's bound, :func:`cosim.scene.cost.line_coupling_step`)
    damping: float = 0.0

    def from_scene(self, scene, lines: list, *, level: float | None, rho: float, workdir: Path):
        """The mooring participant of ``lines`` (:class:`moorings.MooringLine`, one per
        ``scene.moorings.lines``, in order) in water of density ``rho`` [kg/m^3] whose
        still surface is at ``level`` [m] (None: no water), files it needs in ``workdir``."""
        raise NotImplementedError(f"{type(self).__name__}.from_scene")

    def internal_step(self, scene, line) -> tuple[float, float] | None:
        """A dynamic line's internal step [s] and the simulated time [s] it runs before
        the run (an initial relaxation), for ``line`` (a :class:`cosim.scene.spec.Line`)
        of ``scene``; None: the model takes no internal steps."""
        return None


_DYNAMIC_FIELDS = ("EA", "mass_per_length", "diameter")


class Catenary(MooringModel):
    """Quasi-static catenary lines (:class:`moorings.CatenaryMooring`, Barreiro et al. 2016, §3)."""

    anchor_tensions = line_states = tethers = True
    extras = ("points",)

    def from_scene(self, scene, lines, *, level, rho, workdir):
        from moorings import CatenaryMooring

        return CatenaryMooring(lines)


class SPHCable(MooringModel):
    """Dynamic lines as SPH cables (:class:`moorings.sph_cable.SPHCableMooring`, Dinçer & Demir 2020)."""

    line_fields = ("EA", "mass_per_length")  # a line without a diameter feels no water (a cable in air)
    dynamic = anchor_tensions = line_states = True
    extras = ("seabed", "damping", "point_loads", "points", "released", "energy")
    node_cost = 3.3e-7
    damping = 15.0 / 32.0

    def from_scene(self, scene, lines, *, level, rho, workdir):
        from moorings.sph_cable import SPHCableMooring

        m = scene.moorings
        options = {} if m.damping is None else {"omega": m.damping}
        # the loads and the recorded points on nodes (exact there, not between two)
        nodes = [sorted({p.s for p in ln.point_loads} | {x for x in ln.points if 0.0 < x < ln.length})
                 for ln in m.lines]
        return SPHCableMooring(lines, n_particles=m.segments, seabed=m.seabed, nodes_at=nodes,
                               point_loads=[[(p.s, p.force) for p in ln.point_loads] for ln in m.lines],
                               released=[ln.released for ln in m.lines],
                               water_z=level if level is not None else math.inf, gravity=scene.world.gravity,
                               rho_water=rho, **options)

    def internal_step(self, scene, line):
        """The Courant step ``cfl ds / c``, ``c = sqrt(EA / m)`` the axial wave speed."""
        import inspect

        from moorings.sph_cable import SPHCable

        cfl = inspect.signature(SPHCable).parameters["cfl"].default
        return cfl * (line.length / scene.moorings.segments) / math.sqrt(line.EA / line.mass_per_length), 0.0


class MoorDyn(MooringModel):
    """MoorDyn v2 lines (:class:`moorings.moordyn_mooring.MoorDynMooring`, the optional
    ``moordyn`` package)."""

    line_fields = _DYNAMIC_FIELDS
    dynamic = anchor_tensions = line_states = True
    node_cost = 2.3e-7
    damping = 0.8

    def from_scene(self, scene, lines, *, level, rho, workdir):
        from moorings.moordyn_mooring import MoorDynMooring

        return MoorDynMooring(lines, segments=scene.moorings.segments,
                              water_level=level if level is not None else 0.0, rho=rho, g=scene.world.gravity)

    def internal_step(self, scene, line):
        """MoorDyn's RK2 step within :func:`moorings.moordyn_mooring.internal_step_limits`,
        after its initial-condition relaxation ``ic_time``."""
        import inspect

        from moorings.moordyn_mooring import RK2_SAFETY, MoorDynMooring, internal_step_limits

        o = {k: p.default for k, p in inspect.signature(MoorDynMooring).parameters.items()}
        rho = getattr(scene.fluid, "rho", getattr(scene.fluid, "rho0", o["rho"]))
        lim = internal_step_limits(line.length, scene.moorings.segments, line.EA, line.mass_per_length,
                                   line.diameter, rho=rho,
                                   **{k: o[k] for k in ("damping_ratio", "cd_normal", "ca_normal", "cd_axial",
                                                        "ca_axial", "seabed_stiffness", "seabed_damping",
                                                        "drag_speed")})
        return RK2_SAFETY * min(lim.values()), o["ic_time"]


class CatenaryFMU(MooringModel):
    """The catenary exported as an FMU (:func:`moorings.export_catenary_fmu`) and run
    through FMPy (:class:`moorings.FMUMooring`)."""

    line_states = True

    def from_scene(self, scene, lines, *, level, rho, workdir):
        from moorings.fmu_export import catenary_fmu_variable_map, export_catenary_fmu
        from moorings.fmu_mooring import FMUMooring

        workdir.mkdir(parents=True, exist_ok=True)
        path = export_catenary_fmu(lines, workdir / "mooring.fmu")
        return FMUMooring(path, lines, catenary_fmu_variable_map(lines))


#: the built-in models, by the name ``moorings.model`` gives
MODELS = {"catenary": Catenary(), "sph-cable": SPHCable(), "moordyn": MoorDyn(), "fmu": CatenaryFMU()}
