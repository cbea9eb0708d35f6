"""Linear potential flow: coefficients from a boundary-element solver, run in time.

The middle of the speed/accuracy trade between the analytic fluid (Morison with a constant
added mass: seconds) and SPH (hours in 3-D): the model offshore engineers use every day.

- :mod:`fluid.potential.hull`: the wetted hull of a body at its floating position, panelled;
- :mod:`fluid.potential.coefficients`: added mass, damping, excitation and hydrostatics
  from Capytaine (optional dependency: ``pip install cosim-sph[potential]``), cached;
- :mod:`fluid.potential.capytaine_io`: what every Capytaine solve shares (its import, its
  log, the irregular-frequency lid, the cache's keys and files);
- :mod:`fluid.potential.radiation`: the radiation impulse response and its checks;
- :mod:`fluid.potential.elevation`: the elevation a body radiates, at given points;
- :mod:`fluid.potential.waves`: wave components and the excitation they give;
- :mod:`fluid.potential.participant`: :class:`PotentialFluid`, the Cummins equation as a
  participant with the analytic fluid's coupling interface.

Capytaine is imported only when coefficients are computed.
"""

from fluid.potential.capytaine_io import cache_dir
from fluid.potential.coefficients import Coefficients, compute
from fluid.potential.hull import Hull, wetted_hull
from fluid.potential.participant import PotentialFluid, default_omega
from fluid.potential.waves import Sea, WaveComponent, from_spectrum, regular

__all__ = ["Coefficients", "Hull", "PotentialFluid", "Sea", "WaveComponent", "cache_dir", "compute",
           "default_omega", "from_spectrum", "regular", "wetted_hull"]
