"""The wave kinds that are an incident sea on the bodies of the analytic and potential
fluids (``waves.kind`` "linear", "regular", "irregular", and those of other packages,
:data:`cosim.scene.registry.WAVES`), as opposed to a flume's wavemaker, which moves the SPH
fluid's paddle (:class:`cosim.scene.spec.Piston`, ``Flap``, ``PaddleRecord``).

An incident sea is a frozen dataclass deriving :class:`IncidentSea`, with ``TAG = ("kind",
NAME)`` and the fields ``depth`` [m] (the still-water depth its kinematics decay to),
``direction`` [deg] (of propagation, from +x towards +y) and ``ramp`` (its fade-in, in
periods), which the scene's checks compare with the domain and the dimension, and gives
:meth:`IncidentSea.sea`.
"""

from __future__ import annotations

from cosim.scene.fields import Spec


class IncidentSea(Spec):
    """A sea that acts on the bodies of a fluid without particles (module docstring)."""

    def sea(self, scene):
        """The sea of ``scene`` as :mod:`fluid.waves` makes it (elevation, kinematics and
        its linear ``components``, over still water at the scene's level; raising
        :class:`fluid.waves.SeaError` for what it cannot be)."""
        raise NotImplementedError(f"{type(self).__name__}.sea")
