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
