"""The SPH fluid's set-up, chosen from what a scene contains.

The solver's defaults (Wendland, h = sqrt(2) dx, plain dynamic walls, density diffusion
everywhere) are the fast ones; some flows need another set-up, measured in the validation
cases (docs/fluid.md, docs/setup_chooser.md). ``SPH(setup="auto")`` picks, from the scene:

================  ========================================  =========================================
set-up            picked when the scene has                 FluidConfig settings (2-D / 3-D)
================  ========================================  =========================================
``waves``         waves (a wavemaker, a near field's sea)   ``travelling_waves`` (h = 2 dx, 2.5 dx
                                                            from 20 rows; walls "adami", ...); a
                                                            near field: ``NEAR_FIELD`` (+ MLS)
``impulsive``     a vertical-walled tank shaken at a        the solver's defaults, walls "adami"
                  period <= T1 / 3 (T1: first sloshing)
``sloshing``      any other moving tank (``base_motion``)   2-D: ``SLOSHING_2D`` (h = 2 dx, walls
                                                            "adami"); 3-D: the same and the
                                                            diffusion faded under the surface
``impact``        water blocks in a tank (a dam break)      the solver's defaults
``still``         still water (a filled tank, no motion)    2-D: defaults; 3-D: diffusion faded under
                                                            the surface
``defaults``      (only when asked for)                     the solver's defaults
================  ========================================  =========================================

Why: travelling waves lose height to the diffusion at the surface and the floor's friction;
at h = sqrt(2) dx the square lattice under pressure makes waves and sloshing 5-8 % fast
(h = 2 dx is stable) and plain dynamic walls stiffen the contact line; in 3-D, diffusion
everywhere sets a tank at rest circulating. Shaken fast, the wall pressure is impulsive
(Housner 1963, Bull. Seismol. Soc. Am. 53): at steady state mode n's convective part is
``w_n^2 / (w^2 - w_n^2)`` of its impulsive part (the modal equation of
``cosim.validations.forced_sloshing``), at most 1/8 for the first mode at T <= T1 / 3, and
the wall-pressure cases meet their targets with less error at the solver's h (an inclined
wall's pressure at it grows noisy at fine dx: inclined tanks keep "sloshing"). An impact keeps
the defaults (the faded diffusion quadruples a dam break's pressure noise). The measured
figures: docs/fluid.md ("Why each set-up").

The expected largest speed ``u_max`` that sets the speed of sound (c0 = c0_factor u_max,
c0_factor 10 unless set) is sqrt(g depth) for still water, waves and sloshing (the long
wave speed) and sqrt(2 g H) for an impact (the free-fall speed from the highest water
column's top H). Any field set on ``SPH`` overrides the set-up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from cosim.scene.fields import SceneError
from cosim.scene.spec import SETUPS, CylinderTank, Flume, NearField, OpenWater, PolygonTank, Tank
from fluid.settings import SETTINGS

#: FluidConfig settings that the SPH scene class can set over the set-up's (fluid.settings:
#: scene role "set-up"); those with the role "default" (rho0) it always gives
CONFIG_FIELDS = tuple(s.name for s in SETTINGS if s.scene == "set-up")
_GIVEN = tuple(s.name for s in SETTINGS if s.scene == "default")

_SLOSHING_3D = {"walls": "adami", "diffusion_at_surface": False, "h_coef": 2.0}
_REASONS = {
    "waves": "the scene has waves (a wavemaker, or an incident sea through a near field): waves keep linear theory's "
             "speed and height",
    "impulsive": "the vertical-walled tank is shaken at a period at most a third of its first sloshing period: "
                 "impulsive (Westergaard) wall pressures, the solver's defaults with walls carrying the pressure",
    "sloshing": "the tank moves (at a period over a third of its first sloshing period, by a record or table, "
                "or with inclined walls): sloshing frequencies and wall pressures need the wave set-up",
    "impact": "water blocks in a tank (a dam break) or in open water: the solver's defaults, which keep violent "
              "flow's pressure noise low",
    "still": "still water",
    "defaults": "asked for: the solver's defaults",
}


@dataclass(frozen=True)
class Setup:
    """The set-up chosen: its ``name``, why, and the ``FluidConfig`` keyword arguments
    (set-up first, then the scene's own settings on top, listed in ``overridden``)."""

    name: str
    reason: str
    config: dict = field(default_factory=dict)
    overridden: tuple = ()


def settings(name: str, dim: int) -> dict:
    """The FluidConfig keyword arguments of the set-up ``name`` in ``dim`` dimensions (the
    table above)."""
    from fluid.solver import SLOSHING_2D, TRAVELLING_WAVES

    if name == "waves":
        return dict(TRAVELLING_WAVES)
    if name == "sloshing":
        return dict(SLOSHING_2D) if dim == 2 else dict(_SLOSHING_3D)
    if name == "impulsive":
        return {"walls": "adami"}
    if name == "still" and dim == 3:
        return {"diffusion_at_surface": False}
    return {}


def chosen_settings() -> tuple:
    """The FluidConfig settings that some set-up chooses (any of :func:`settings`' in 2-D or
    3-D, and the near field's), sorted."""
    from fluid.solver import NEAR_FIELD

    return tuple(sorted({k for name in SETUPS for dim in (2, 3) for k in settings(name, dim)} | set(NEAR_FIELD)))


#: the largest excitation period, as a fraction of the first sloshing period, that is "impulsive"
IMPULSIVE_PERIODS = 1.0 / 3.0


def _periods(scene) -> tuple:
    """(the base motion's period, the water's first sloshing period) [s]; None for one
    not known (a record or a table has no single period)."""
    from cosim.scene.checks import first_sloshing_period

    return getattr(scene.base_motion, "period", None), first_sloshing_period(scene)


def _impulsive(scene) -> bool:
    """Whether the tank has vertical walls (a box or a cylinder), its base motion is
    periodic and its period at most :data:`IMPULSIVE_PERIODS` of the water's first sloshing
    period."""
    period, t1 = _periods(scene)
    vertical = isinstance(scene.domain, (Tank, CylinderTank))
    return vertical and period is not None and t1 is not None and period <= IMPULSIVE_PERIODS * t1


def _auto(scene) -> str:
    if scene.waves is not None:
        return "waves"
    if scene.base_motion is not None:
        return "impulsive" if _impulsive(scene) else "sloshing"
    if isinstance(scene.domain, OpenWater) or (isinstance(scene.domain, Tank) and scene.domain.water):
        return "impact"
    return "still"


def u_max(scene, name: str) -> float:
    """The expected largest flow speed [m/s] of the scene (see the module docstring)."""
    g, d = scene.world.g, scene.domain
    if isinstance(d, OpenWater):  # the water's fall over its blocks' height, or the fastest body's start
        fall = math.sqrt(2.0 * g * (d.level - min(b.lo[-1] for b in d.water)))
        speed = max((math.hypot(*b.velocity) for b in scene.bodies if getattr(b, "velocity", None)), default=0.0)
        if max(fall, speed) == 0.0:
            raise SceneError("fluid.c0", "nothing sets the open water's flow speed (no gravity, no body given a "
                             "velocity), from which the speed of sound follows; give fluid.c0 [m/s] (about 10 "
                             "times the fastest flow expected)")
        return max(fall, speed)
    if isinstance(d, Tank) and d.water:
        top = max(b.hi[-1] for b in d.water)
        return math.sqrt(2.0 * g * top) if name == "impact" else math.sqrt(g * top)
    depth = d.fill_level - min(v[1] for v in d.vertices) if isinstance(d, PolygonTank) else d.level
    return math.sqrt(2.0 * g * depth) if name == "impact" else math.sqrt(g * depth)


def choose(scene) -> Setup:
    """The set-up of the scene's SPH fluid: its FluidConfig keyword arguments (without
    ``dim``, ``dx``, ``g``, which come from the world and the fluid)."""
    sph = scene.fluid
    name = _auto(scene) if sph.setup == "auto" else sph.setup
    reason = _REASONS[name] if sph.setup == "auto" else f"asked for (fluid.setup = {name!r})"
    periods = _periods(scene) if sph.setup == "auto" and name in ("impulsive", "sloshing") else (None,)
    if None not in periods:
        reason += " (period {:.4g} s, first sloshing period {:.4g} s)".format(*periods)
    cfg = settings(name, scene.world.dim)
    if name == "waves" and isinstance(scene.domain, NearField):
        from fluid.solver import NEAR_FIELD

        cfg.update(NEAR_FIELD)
        reason += "; a near field: the density re-initialised every 150 steps, which holds its mean level"
    elif name == "waves" and isinstance(scene.domain, Flume):
        from fluid.solver import FINE_WAVE_ROWS, FINE_WAVES, travelling_waves

        rows = scene.domain.level / scene.fluid.dx
        waves = travelling_waves(rows)
        cfg.update(waves)
        if waves == FINE_WAVES:
            reason += (f"; {rows:.3g} particle rows over the depth (>= {FINE_WAVE_ROWS}): h = 2.5 dx, with which a "
                       "wave's decay per wavelength halves")
    cfg.update({key: getattr(sph, key) for key in _GIVEN})
    overridden = []
    for key in CONFIG_FIELDS:
        v = getattr(sph, key)
        if v is not None:
            cfg[key] = v
            overridden.append(key)
    if "c0" not in cfg and "u_max" not in cfg:
        cfg["u_max"] = u_max(scene, name)
    return Setup(name, reason, cfg, tuple(overridden))
