"""Shared test markers, and the property tests' profile."""

import os

import pytest
from hypothesis import settings

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
