"""Shared test markers."""

import pytest

from moorings.fmu_export import find_compiler

try:
    find_compiler()
    HAVE_CC = True
except Exception:  # noqa: BLE001 - any failure to find one means: skip
    HAVE_CC = False

#: for tests that build an FMU binary
requires_cc = pytest.mark.skipif(not HAVE_CC, reason="no C compiler to build the FMU binary")
