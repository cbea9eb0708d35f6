"""The C port of the catenary law (moorings/fmu/catenary.c) equals the Python law.

The C file is compiled into a shared library in the test's temporary folder and
called through ctypes; every state, the exact state boundaries, inextensible and
elastic lines, and extreme parameters are compared with moorings.catenary.solve.
"""

import ctypes
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from moorings.catenary import LineState, lift_off_distance, solve, taut_distance

SRC = Path(__file__).resolve().parents[1] / "moorings" / "fmu"
CC = shutil.which("cc") or shutil.which("gcc")
pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler on PATH")


class Sol(ctypes.Structure):
    _fields_ = [("H", ctypes.c_double), ("V", ctypes.c_double), ("touchdown", ctypes.c_double), ("state", ctypes.c_int)]


@pytest.fixture(scope="module")
def claw(tmp_path_factory):
    out = tmp_path_factory.mktemp("claw") / "libcatenary.so"
    cmd = [CC, "-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror", "-ffp-contract=off",
           "-fPIC", "-shared", "-o", str(out), str(SRC / "catenary.c"), "-lm"]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    lib = ctypes.CDLL(str(out))
    d = ctypes.c_double
    lib.cat_solve.argtypes = [d, d, d, d, d, ctypes.POINTER(Sol)]
    lib.cat_solve.restype = ctypes.c_int
    lib.cat_check.argtypes = [d, d, d, d, d]
    lib.cat_lift_x.argtypes = lib.cat_taut_x.argtypes = [d, d]
    lib.cat_lift_x.restype = lib.cat_taut_x.restype = d

    def csolve(X, h, L, w, EA=None):
        s = Sol()
        err = lib.cat_solve(X, h, L, w, math.inf if EA is None else EA, ctypes.byref(s))
        return err, s

    csolve.lib = lib
    return csolve


def sweep_cases():
    """(X, h, L, w, EA) over all four states, the exact boundaries, both line kinds."""
    cases = []
    lines = [  # (h, L, w)
        (2.651, 6.98, 1.036),  # Barreiro et al. 2016, Table 1
        (50.0, 150.0, 918.75),  # Barreiro et al. 2016, Table 2
        (1e-3, 10.0, 5.0),  # nearly on the seabed
        (9.0, 10.0, 5.0),  # nearly vertical
        (0.0, 10.0, 5.0),  # fairlead on the seabed
    ]
    for h, L, w in lines:
        for EA in (None, 1e3 * w * L, 50.0 * w * L, 1e9 * w * L, 1.5 * w * L):
            xt = taut_distance(h, L)
            Xs = list(np.linspace(0.0, 1.2 * max(xt, L), 61))
            Xs += [max(L - h, 0.0), lift_off_distance(h, L), xt, np.nextafter(xt, 2 * xt + 1), np.nextafter(xt, 0),
                   0.5 * (lift_off_distance(h, L) + xt), xt * (1 - 1e-9)]
            cases += [(float(X), h, L, w, EA) for X in Xs if X >= 0.0]
    # tiny weight and huge stiffness (no overflow, same answer)
    cases += [(X, 3.0, 10.0, 1e-9, EA) for X in (5.0, 8.0, 9.4) for EA in (None, 1e12, 1e-6)]
    return cases


def test_c_law_equals_python_law_over_all_states(claw):
    seen = {True: set(), False: set()}
    worst = 0.0
    for X, h, L, w, EA in sweep_cases():
        ref = solve(X, h, L, w, EA)
        err, s = claw(X, h, L, w, EA)
        assert err == 0
        assert s.state == int(ref.state), (X, h, L, w, EA)
        scale = w * L  # H and V are compared on the scale of the line's weight
        assert not any(map(math.isnan, (ref.H, ref.V, s.H, s.V))), (X, h, L, w, EA)
        for got, want in ((s.H, ref.H), (s.V, ref.V)):
            if math.isinf(want):
                assert got == want
            else:
                worst = max(worst, abs(got - want) / max(abs(want), scale))
        worst = max(worst, abs(s.touchdown - ref.touchdown) / L)
        seen[EA is None].add(LineState(s.state))
    assert worst <= 1e-12, worst
    assert seen[True] == set(LineState) and seen[False] == set(LineState)


def test_c_law_boundaries_are_exact(claw):
    h, L, w = 2.651, 6.98, 1.036
    assert claw(L - h, h, L, w)[1].state == LineState.RESTING
    assert claw(lift_off_distance(h, L), h, L, w)[1].state == LineState.FULLY_LIFTED
    assert claw(np.nextafter(lift_off_distance(h, L), 0), h, L, w)[1].state == LineState.PARTLY_LIFTED
    s = claw(taut_distance(h, L), h, L, w)[1]
    assert s.state == LineState.TAUT and math.isinf(s.H) and math.isinf(s.V) and s.touchdown == 0.0
    assert claw.lib.cat_lift_x(h, L) == lift_off_distance(h, L)
    assert claw.lib.cat_taut_x(h, L) == taut_distance(h, L)
    # exactly at lift-off the closed form (Barreiro et al. 2016, Eq. 37 with l_s = L): H = w (L^2 - h^2) / 2h, V = w L
    s = claw(lift_off_distance(h, L), h, L, w)[1]
    assert s.H == pytest.approx(w * (L * L - h * h) / (2 * h), rel=1e-15) and s.V == w * L


@pytest.mark.parametrize(
    "args, code",
    [((math.nan, 1, 2, 1, 1), 1), ((-1.0, 1, 2, 1, 1), 1), ((1.0, math.inf, 2, 1, 1), 2), ((1.0, 1, 0, 1, 1), 3),
     ((1.0, 1, 2, -1, 1), 4), ((1.0, 1, 2, 1, 0), 5), ((1.0, 1, 2, 1, math.nan), 5), ((1.0, 1, 2, 1, math.inf), 0)],
)
def test_c_law_checks_inputs_like_python(claw, args, code):
    assert claw.lib.cat_check(*map(float, args)) == code
