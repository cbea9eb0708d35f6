"""fluid: the weakly-compressible SPH solver (2-D and 3-D, numba).

Knows nothing of the coupler: it satisfies ``cosim.protocol.Participant``
structurally and never imports ``cosim`` (its errors come from the top-level
:mod:`errors`). Never imports MuJoCo.
"""
