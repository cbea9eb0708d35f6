"""moorings: mooring models behind one interface (``cosim.protocol.Mooring``).

- :class:`MooringLine`: the model-independent description of a line.
- :mod:`moorings.catenary`: the quasi-static catenary law (Barreiro et al. 2016, §3),
  ``solve(X, h, L, w, EA=None)``.
- :class:`CatenaryMooring`: a mooring system of catenary lines.
- :class:`SPHCableMooring`: dynamic lines as SPH cables (Dinçer & Demir 2020).
- :class:`FMUMooring`: any co-simulation FMU with fairlead positions in and
  forces out; :func:`export_catenary_fmu` writes the catenary law as one.
- :class:`MoorDynMooring`: MoorDyn v2 lines (optional ``moordyn`` package).
- :class:`BreakingMooring`: any of them, its lines reported (and optionally released)
  when their tension passes their ``break_load``.

Swapping models is one constructor call: every model takes the same list of
``MooringLine``. Models are imported on first use, so a scene loads (and
compiles) only the ones it uses. Never imports MuJoCo or ``cosim`` (its errors come
from the top-level :mod:`errors`).
"""

from importlib import import_module

from moorings.line import MooringLine, named_lines

_LAZY = {
    "CatenaryMooring": "moorings.catenary_mooring",
    "SPHCableMooring": "moorings.sph_cable",
    "FMUMooring": "moorings.fmu_mooring",
    "MoorDynMooring": "moorings.moordyn_mooring",
    "BreakingMooring": "moorings.breaking",
    "export_catenary_fmu": "moorings.fmu_export",
    "catenary_fmu_variable_map": "moorings.fmu_export",
}


def __getattr__(name):
    if name in _LAZY:
        return getattr(import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'moorings' has no attribute {name!r}")


__all__ = ["MooringLine", "named_lines", *_LAZY]
