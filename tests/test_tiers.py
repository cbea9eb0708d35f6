"""The test tiers (pyproject's markers): the fast one (`python -m pytest`), the long one
(`python -m pytest -m long`, CI's second step) and the slow one (full validations, never
in CI). No test is in both the long and the slow tier."""

from types import SimpleNamespace

import pytest
from conftest import BOTH_TIERS, in_both_tiers


def test_no_collected_test_is_both_long_and_slow(request):
    """Every test this session collected (deselected ones included)."""
    assert request.config.stash[BOTH_TIERS] == []


def test_a_test_marked_long_and_slow_is_found():
    def item(nodeid, *marks):
        return SimpleNamespace(nodeid=nodeid, get_closest_marker=lambda name: name if name in marks else None)

    items = [item("a", "long"), item("b", "slow"), item("c", "long", "slow"), item("d")]
    assert in_both_tiers(items) == ["c"]


@pytest.mark.parametrize("tier", ["long", "slow"])
def test_the_tiers_are_registered(request, tier):
    assert any(line.startswith(f"{tier}:") for line in request.config.getini("markers"))


def test_a_fast_test_has_the_tiers_time_limit(request):
    """A hung test fails by name after TIER_TIMEOUT_S instead of holding the run (pytest-timeout,
    the test extra); slow tests are exempt (conftest.pytest_collection_modifyitems)."""
    from conftest import TIER_TIMEOUT_S

    assert request.config.pluginmanager.hasplugin("timeout")
    assert request.node.get_closest_marker("timeout").args == (TIER_TIMEOUT_S,)


@pytest.mark.long
@pytest.mark.timeout(120)
def test_a_hung_call_is_stopped_by_the_time_limit(pytester):
    """The limit interrupts a test blocked in a system call (here a child process's wait):
    run in a pytest of its own, the test fails with pytest-timeout's message."""
    pytester.makepyfile("""
        import subprocess, sys, pytest

        @pytest.mark.timeout(1)
        def test_hangs():
            subprocess.run([sys.executable, "-c", "import time; time.sleep(30)"])
    """)
    res = pytester.runpytest_subprocess("-p", "no:xdist", "-p", "no:cacheprovider", "-o", "addopts=")
    res.assert_outcomes(failed=1)
    assert "Timeout (>1.0s)" in res.stdout.str()
