"""Scenes: a coupled run described as plain Python or plain TOML, checked before any work
is done, run by ``Scene.run()`` or ``cosim run SCENE.toml|SCENE.py``.

    from cosim.scene import SPH, Beach, Box, Flume, Line, Moorings, Piston, Probes, Scene, World

See :mod:`cosim.scene.spec` for the fields, :mod:`cosim.scene.setup` for the fluid set-up
chosen from what a scene contains, :mod:`cosim.scene.runner` for what a run writes.
"""

from cosim.scene.fields import SceneError
from cosim.scene.spec import (MJCF, SPH, Absorber, Analytic, ArchRib, Beach, Block, Box, Coupling, Cylinder, CylinderTank, Earthquake,
                              ElasticPlate, Flap, Flume, GroundMotion, InclinedTank, IrregularWaves, Line, LinearWaves,
                              Moorings, NearField, NoFluid, OpenWater, PaddleRecord, Patch, Piston, PolygonTank,
                              Potential, Probes, Record, RegularWaves, Roll, RollTable, Scene, Shake, Sphere, TableMotion, Tank, World,
                              arch_rib_monitors)

__all__ = ["MJCF", "SPH", "Absorber", "Analytic", "ArchRib", "Beach", "Block", "Box", "Coupling", "Cylinder", "CylinderTank", "Earthquake",
           "ElasticPlate",
           "Flap", "Flume", "GroundMotion", "InclinedTank", "IrregularWaves", "Line", "LinearWaves", "Moorings",
           "NearField", "NoFluid", "OpenWater", "PaddleRecord", "Patch", "Piston", "PolygonTank", "Potential", "Probes",
           "Record", "RegularWaves",
           "Roll", "RollTable", "Scene", "SceneError", "Shake",
           "Sphere", "TableMotion", "Tank", "World", "arch_rib_monitors"]
