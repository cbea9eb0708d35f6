"""The coupler's progress line: simulated time, steps per second, wall-clock ETA, redrawn
on a terminal and written whole once a minute elsewhere (a log). One implementation,
:class:`fluid.progress.Progress`, shared with the fluid's standalone run loop (the solver
packages may not import ``cosim``, so it lives there and is re-exported here)."""

from fluid.progress import Progress

__all__ = ["Progress"]
