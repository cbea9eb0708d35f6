"""The SPH fluid's set-up, chosen from what a scene contains.

The solver's defaults (Wendland, h = sqrt(2) dx, plain dynamic walls, density diffusion
everywhere) are the fast ones; some flows need another set-up, measured in the
validation cases (README, "Waves and sloshing: the fluid's set-up"). ``SPH(setup="auto")``
picks, from the scene:

================  ========================================  =========================================
set-up            picked when the scene has                 FluidConfig settings (2-D / 3-D)
================  ========================================  =========================================
``waves``         a wavemaker (``waves``)                   ``TRAVELLING_WAVES``: h = 2 dx, walls
                                                            "adami", diffusion faded under the
                                                            surface, slip walls, alpha = 0.002
``sloshing``      a moving tank (``base_motion``)           2-D: ``SLOSHING_2D`` (h = 2 dx, walls
                                                            "adami"); 3-D: the same and the
                                                            diffusion faded under the surface
``impact``        water blocks in a tank (a dam break)      the solver's defaults
``still``         still water (a filled tank, no motion)    2-D: defaults; 3-D: diffusion faded under
                                                            the surface
``defaults``      (only when asked for)                     the solver's defaults
================  ========================================  =========================================

Why, with the measured figures (2-D unless said):

- waves that travel: the sloshing set-up keeps the wave's speed, but a wave loses its
  height along the flume to the density diffusion at the free surface, the artificial
  viscosity's friction on the floor and its interior viscosity (fluid.solver.TRAVELLING_WAVES;
  docs/validation/wave-propagation_history.md has the decay per wavelength of each term);
- sloshing (and the waves' speed): at h = sqrt(2) dx the square lattice under pressure has a spurious
  shear stiffness that makes waves 5-8 % fast; h = 2 dx is the one support near the usual
  ones at which it is stable. Plain dynamic walls put a stiff spring at the contact line.
  With ``SLOSHING_2D``: first sloshing mode +0.84 % (defaults +10 %), piston waves 0.97-1.00
  of linear theory's height (0.90), Westergaard wall pressure 0.016 RMS (0.17). It costs
  twice the pairs per step for a 1.4-1.5 times longer step. In 3-D the same holds: at
  h = sqrt(2) dx the first sloshing mode of the whole 3.0 x 1.0 m tank (water 1.0 m, dx
  0.1 m) runs 7.3 % fast and the cylinder's (D = 2 m, water 0.6 m) 4.2 %, at h = 2 dx
  2.1 % and 1.0 % (``cosim validate long-period``); piston waves in a 3-D flume (dx 2 cm,
  water 0.3 m, H = 4 cm, T = 1 s, 5 rows between side walls) travel with 0.970 of linear
  theory's wavenumber, 1.001 at h = 2 dx, and reach 1 depth out at 0.93 H against 0.98 H.
  It costs 2.4 times the pairs of sqrt(2) dx, 1.25 times the CPU per simulated second
  (its step is longer). The 3-D set-up takes the walls that carry the pressure
  (Westergaard 3-D meets its targets with them) and the faded diffusion that keeps a 3-D
  tank at rest;
- still water in 3-D: with diffusion everywhere a 3-D tank at rest starts circulating by
  its vertical edges after ~1 s (2-4e-3 sqrt(gH)); faded under the free surface it stays
  at rest (5e-5 sqrt(gH) at 3 s). Not for violent flow: it quadruples the 2-D dam break's
  pressure noise, hence
- impact: the defaults (the dam-break front within 5 % of Martin & Moyce).

The expected largest speed ``u_max`` that sets the speed of sound (c0 = c0_factor u_max,
c0_factor 10 unless set) is sqrt(g depth) for still water, waves and sloshing (the long
wave speed) and sqrt(2 g H) for an impact (the free-fall speed from the highest water
column's top H). Any field set on ``SPH`` overrides the set-up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from cosim.scene.spec import PolygonTank, Tank

#: FluidConfig fields that the SPH scene class can set
CONFIG_FIELDS = ("c0", "c0_factor", "u_max", "h_coef", "kernel", "walls", "alpha", "alpha_wall", "nu",
                 "xsph_eps", "diffusion", "delta", "diffusion_at_surface", "cfl", "integrator", "mls_every",
                 "threads", "device", "precision")

_SLOSHING_3D = {"walls": "adami", "diffusion_at_surface": False, "h_coef": 2.0}
_REASONS = {
    "waves": "the scene has a wavemaker: waves keep linear theory's speed and height",
    "sloshing": "the tank moves: sloshing frequencies and wall pressures need the wave set-up",
    "impact": "water blocks in a tank (a dam break): the solver's defaults, which keep violent flow's pressure "
              "noise low",
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
    if name == "still" and dim == 3:
        return {"diffusion_at_surface": False}
    return {}


def _auto(scene) -> str:
    if scene.waves is not None:
        return "waves"
    if scene.base_motion is not None:
        return "sloshing"
    if isinstance(scene.domain, Tank) and scene.domain.water:
        return "impact"
    return "still"


def u_max(scene, name: str) -> float:
    """The expected largest flow speed [m/s] of the scene (see the module docstring)."""
    g, d = scene.world.gravity, scene.domain
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
    cfg = settings(name, scene.world.dim)
    cfg["rho0"] = sph.rho0
    overridden = []
    for key in CONFIG_FIELDS:
        v = getattr(sph, key)
        if v is not None:
            cfg[key] = v
            overridden.append(key)
    if "c0" not in cfg and "u_max" not in cfg:
        cfg["u_max"] = u_max(scene, name)
    return Setup(name, reason, cfg, tuple(overridden))
