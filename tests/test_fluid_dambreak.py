"""Dam break (VALIDATION.md, dambreak-2d). The comparison with the experiments is the
registered case (`cosim validate dambreak-2d`); its front does not meet the 5 % target
(see cosim/validations/fluid.py). Here: physical bounds that any correct run obeys, and
the column's collapse (residual height at the back wall) against Martin & Moyce (1952)."""

import numpy as np
import pytest

from cosim.validation import run
from cosim.validations.fluid import run_dambreak


def test_dambreak_front_obeys_physical_bounds():
    rec = run("dambreak-2d", quick=True)
    TZ = np.array(rec["metrics"]["front_T_Z"])
    T, Z = TZ[:, 0], TZ[:, 1]
    assert T[-1] >= 2.8 and Z[0] == 1.0
    # the front only advances (up to one particle spacing of jitter, 1/20 a)
    assert (np.diff(Z) > -0.05).all()
    # it has moved (gravity acts) but not faster than Ritter's inviscid shallow-water front
    # on a dry bed, dx/dt = 2 sqrt(g 2a), i.e. dZ/dT = 2 in these units
    assert Z[-1] > 2.0
    assert (np.diff(Z) / np.diff(T) <= 2.0).all()
    # and it stays in the tank (Z <= 4): no particle escaped through the wall
    assert Z.max() <= 4.0
    assert rec["steps"] > 1000
    # the bulk of the column collapses as in the experiment: the residual height at the
    # back wall within 5 % RMS of Martin & Moyce's Table 6 (measured 2.0 % at 20 particles
    # across the column, 2.6 % at 10)
    assert rec["metrics"]["height_rms_rel_err_mm1952"] < 0.05


@pytest.mark.slow
def test_dambreak_residual_height_converges():
    # the column's collapse converges to the experiment with dx (residual height at the
    # back wall, RMS against Martin & Moyce Table 6: 2.6 %, 2.0 %, 1.2 % at 10, 20, 40
    # particles across the column), while the front does not (7.8 %, 12 %, 15 % ahead of
    # Martin & Moyce: see run_dambreak)
    coarse, fine = (run_dambreak(n)["metrics"] for n in (20, 40))
    assert fine["height_rms_rel_err_mm1952"] < coarse["height_rms_rel_err_mm1952"]
    assert fine["height_rms_rel_err_mm1952"] < 0.02
