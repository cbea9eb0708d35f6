"""The quick tier of `cosim validate all --quick`: the cases it runs are those whose
committed quick record is within the tier's CPU bound, and the long ones are left out
unless `--long` asks for them."""

import pytest

from cosim import validation
from cosim.cli import main
from cosim.report import read_records


def test_long_marks_the_cases_beyond_the_quick_tier_by_their_records():
    """A case is marked long exactly when its committed quick record costs more than the
    tier's bound, so that the tier stays what the records say it is."""
    known = validation.cases()
    quick = {r["name"]: validation.cost(r) for r in read_records(validation.committed_records()) if r.get("quick")}
    assert set(quick) == set(known)
    beyond = {n for n, c in quick.items() if c > validation.LONG_QUICK_S}
    assert beyond == {n for n, c in known.items() if c.long}
    tier, long = validation.quick_tier()
    assert set(tier) | set(long) == set(known) and not set(tier) & set(long) and set(long) == beyond


@pytest.fixture
def ran(monkeypatch):
    """The names `cosim validate` would run, nothing run."""
    names = []

    def run_many(given, quick=False, jobs=1, costs=None):
        names.extend(given)
        return iter(())

    monkeypatch.setattr(validation, "run_many", run_many)
    return names


def test_all_quick_leaves_the_long_cases_out_and_says_so(ran, capsys):
    tier, long = validation.quick_tier()
    assert long, "no long case: the tier's test has nothing to check"
    assert main(["validate", "all", "--quick"]) == 0
    assert ran == tier
    err = capsys.readouterr().err
    assert f"all --quick: {len(tier)} cases; left out, as long" in err and all(n in err for n in long)


def test_long_adds_them(ran):
    assert main(["validate", "all", "--quick", "--long"]) == 0
    assert ran == list(validation.cases())


@pytest.mark.parametrize("argv", [["all", "--long"], ["nearfield-radiation", "--quick", "--long"]])
def test_long_without_all_quick_is_refused(argv, ran, capsys):
    with pytest.raises(SystemExit):
        main(["validate", *argv])
    assert "--long goes with 'all --quick'" in capsys.readouterr().err and not ran


def test_a_long_case_named_runs(ran):
    long = validation.quick_tier()[1][0]
    assert main(["validate", long, "--quick"]) == 0
    assert ran == [long]
