"""bodies: MuJoCo bodies (rigid, articulated, elastic chains) as a participant.

- :class:`bodies.mujoco_bodies.MujocoBodies`: a MuJoCo model whose bodies take
  world-frame wrenches from the coupler and report their kinematics.
- :mod:`bodies.builders`: MJCF for boxes, cylinders and spheres, 2-D (x-z plane)
  and 3-D, with fairlead sites.

MuJoCo is imported here and only here, so scenes without bodies never load it.
"""
