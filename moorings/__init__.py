"""moorings: mooring models behind one interface (``cosim.protocol.Mooring``).

- :mod:`moorings.catenary`: the quasi-static catenary law (seed 004 §3) and the
  mooring system built on it.
- :class:`moorings.line.MooringLine`: the model-independent description of a line.

Never imports MuJoCo or the coupler (only ``cosim.errors``).
"""

from moorings.line import MooringLine, named_lines

__all__ = ["MooringLine", "named_lines"]
