"""bodies: MuJoCo bodies (rigid, articulated, elastic chains) as a participant.

MuJoCo is imported here and only here, so scenes without bodies never load it.
"""
