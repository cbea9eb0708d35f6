"""fluid: the weakly-compressible SPH solver (2-D and 3-D, numba).

Knows nothing of the coupler: it satisfies ``cosim.protocol.Participant``
structurally and imports only ``cosim.errors`` from ``cosim``. Never imports MuJoCo.
"""
