"""Shared test markers and the check that the long and slow tiers do not meet, the property
tests' profile, the worker processes' threads, and the time limit of a fast or long test."""

import os

# The test command runs the tests in two worker processes (pytest-xdist, pyproject's addopts),
# which share the cores: OpenMP's idle threads must then sleep instead of spinning, or one
# worker's parallel loops take the cores the other needs (four jobs on 2 cores: a 2-thread
# step 11 times slower than 1 thread with spinning, 0.86 of it passive;
# docs/benchmarks/fluid_throughput_history.md). Set before numba starts its threads.
if os.environ.get("PYTEST_XDIST_WORKER"):
    os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

# The potential-flow fluid's coefficient cache (fluid.potential.cache_dir) in a temporary folder
# of this test session, not the user's: inherited by the scenes the tests run in subprocesses.
if "COSIM_POTENTIAL_CACHE" not in os.environ:
    import tempfile

    os.environ["COSIM_POTENTIAL_CACHE"] = tempfile.mkdtemp(prefix="cosim-potential-cache-")

import pytest
from hypothesis import settings

pytest_plugins = ["pytester"]  # tests/test_tiers.py runs a pytest of its own

from moorings.fmu_export import find_compiler

try:
    find_compiler()
    HAVE_CC = True
except Exception:  # noqa: BLE001 - any failure to find one means: skip
    HAVE_CC = False

#: for tests that build an FMU binary
requires_cc = pytest.mark.skipif(not HAVE_CC, reason="no C compiler to build the FMU binary")

# The test command must give the same verdict every time it runs on a commit: property
# tests draw their examples from a fixed seed. To search afresh for counter-examples,
# run with HYPOTHESIS_PROFILE=explore (a new random draw each run).
settings.register_profile("repeatable", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))


def in_both_tiers(items) -> list[str]:
    """The tests marked both ``long`` and ``slow``. The two tiers must not meet: CI runs
    ``-m long`` (seconds to a minute a test), and a slow test (an hour-long full validation)
    selected there would run past CI's time limit."""
    return [item.nodeid for item in items if item.get_closest_marker("long") and item.get_closest_marker("slow")]


#: what in_both_tiers found among every collected test, for tests/test_tiers.py
BOTH_TIERS = pytest.StashKey[list]()


#: wall seconds a test of the fast or long tier may take (pytest-timeout) before it fails
#: with its stack: a test that hangs then fails by name instead of holding its pytest
#: worker, and with it the whole run (the workers share the queue), until CI's limit. The
#: longest long test takes about 300 s on 2 loaded cores; slow tests have no limit.
TIER_TIMEOUT_S = 1500


@pytest.hookimpl(tryfirst=True)  # before `-m` deselects: every collected test is seen
def pytest_collection_modifyitems(config, items):
    config.stash[BOTH_TIERS] = in_both_tiers(items)
    if config.pluginmanager.hasplugin("timeout"):
        for item in items:
            if not item.get_closest_marker("slow") and not item.get_closest_marker("timeout"):
                item.add_marker(pytest.mark.timeout(TIER_TIMEOUT_S))
