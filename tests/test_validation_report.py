"""The validation report (cosim.report, ``cosim validate ... --report DIR [--from FILE]``) and
what ``passed`` means: every metric named in a record's tolerances is within it, for a
quick variant (its own declared tolerances) as for a full one."""

import json
import math
import re
from pathlib import Path

import pytest

from cosim import report, validation
from cosim.cli import main

#: cheap quick cases (a second or less each); cable-exp2-static returns a series (a plot)
CHEAP = ["catenary-limits", "catenary-two-lines", "cable-exp2-static"]


@pytest.fixture(scope="module")
def quick_report(tmp_path_factory):
    """The report of the cheap quick cases, and the JSON lines ``cosim validate`` printed."""
    import contextlib
    import io

    folder = tmp_path_factory.mktemp("report")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        rc = main(["validate", *CHEAP, "--quick", "--report", str(folder)])
    return folder, rc, out.getvalue()


@pytest.mark.long
def test_the_report_has_a_row_and_a_page_per_case(quick_report):
    folder, rc, stdout = quick_report
    assert rc == 0
    index = (folder / "index.md").read_text()
    rows = [s for s in index.splitlines() if s.startswith("| [")]
    assert [re.match(r"\| \[([^\]]+)\]", s)[1] for s in rows] == sorted(CHEAP)
    header = next(s for s in index.splitlines() if s.startswith("| case |"))
    for col in ("description", "target as stated", "measured", "result", "wall [s]", "particles", "steps"):
        assert col in header
    for name in CHEAP:
        row = next(s for s in rows if s.startswith(f"| [{name}]"))
        assert "| pass |" in row and validation.cases()[name].target.split(";")[0] in row
        page = (folder / f"{name}.md").read_text()
        for section in ("## Set-up", "## Target", "**As stated**", "**Judged against**: quick:", "## Measured values",
                        "## Ours against the reference"):
            assert section in page, (name, section)
        assert (folder / f"{name}.html").read_text().startswith("<!DOCTYPE html>")
        assert f'href="{name}.html"' in (folder / "index.html").read_text()
    # a case with a reference series: its plot, from the series the JSON lines leave out
    page = (folder / "cable-exp2-static.md").read_text()
    png = re.search(r"!\[shape\]\((cable-exp2-static_shape\.png)\)", page)[1]
    assert (folder / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (folder / "series" / "cable-exp2-static.quick.json").exists()
    lines = [json.loads(s) for s in stdout.splitlines()]
    assert [r["name"] for r in lines] == CHEAP and all("series" not in r for r in lines)
    assert (folder / "records.jsonl").read_text().splitlines() == stdout.splitlines()


@pytest.mark.long
def test_from_rebuilds_the_same_report(quick_report, tmp_path):
    folder, _, stdout = quick_report
    # from the report's own records (the series beside them): the same pages, the same plots
    again = tmp_path / "again"
    assert main(["validate", "--from", str(folder / "records.jsonl"), "--report", str(again)]) == 0
    for md in folder.glob("*.md"):
        assert (again / md.name).read_text() == md.read_text(), md.name
    for f in [*folder.glob("*.html"), *folder.glob("*.png")]:
        assert (again / f.name).exists(), f.name
    # from the JSON lines alone, as printed (no series saved): the same report but for the plot
    saved = tmp_path / "printed" / "run.jsonl"
    saved.parent.mkdir()
    saved.write_text(stdout)
    bare = tmp_path / "bare"
    assert main(["validate", "all", "--from", str(saved), "--report", str(bare)]) == 0
    assert (bare / "index.md").read_text() == (folder / "index.md").read_text()
    assert (bare / "catenary-limits.md").read_text() == (folder / "catenary-limits.md").read_text()
    assert "(no plot" in (bare / "cable-exp2-static.md").read_text()
    # names select from the file; --from needs --report
    sub = tmp_path / "sub"
    assert main(["validate", "catenary-limits", "--from", str(saved), "--report", str(sub)]) == 0
    assert "catenary-two-lines" not in (sub / "index.md").read_text()
    with pytest.raises(SystemExit):
        main(["validate", "--from", str(saved)])


@pytest.mark.long
def test_cases_run_at_once_give_the_records_of_one_after_the_other(capsys):
    """--jobs 2 runs the cases in two worker processes: the same records (but their costs),
    printed in the order named; --jobs 0 is refused."""
    printed = {}
    for jobs in ("1", "2"):
        assert main(["validate", *CHEAP, "--quick", "--jobs", jobs]) == 0
        printed[jobs] = [json.loads(s) for s in capsys.readouterr().out.splitlines()]
    assert [r["name"] for r in printed["2"]] == CHEAP
    cost = ("wall_s", "case_cpu_s")
    for one, two in zip(printed["1"], printed["2"]):
        assert {k: v for k, v in one.items() if k not in cost} == {k: v for k, v in two.items() if k not in cost}
    with pytest.raises(SystemExit):
        main(["validate", *CHEAP, "--quick", "--jobs", "0"])
    assert "--jobs 0: give at least 1" in capsys.readouterr().err


@pytest.mark.parametrize("name", CHEAP + ["catenary-johanning-2007", "catenary-johanning-2006", "cable-case1"])
def test_a_quick_record_passes_when_every_metric_is_within_its_declared_tolerance(name):
    r = validation.run(name, quick=True)
    assert r["tolerances"], "a case judged on nothing"
    every = all(validation.within(validation.lookup(r["metrics"], k), b) for k, b in r["tolerances"].items())
    assert r["passed"] is every is True and r["outside_tolerance"] == []
    assert r["target"].startswith("quick: ") and r["target"].endswith("(declared)")
    assert r["stated_target"] == validation.cases()[name].target


def test_a_full_record_is_judged_against_the_stated_target():
    r = validation.run("catenary-limits", quick=False)
    assert r["passed"] and r["metrics"]["lines"] == 40
    assert r["target"] == "full: the stated target of docs/VALIDATION.md (row catenary-limits)"


def test_every_case_declares_its_targets_and_quotes_its_row_of_validation_md():
    doc = Path(report.DOCS / "VALIDATION.md").read_text()
    stated, last = {}, None
    for line in doc.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| ") and len(cells) == 4 and cells[0] != "name":
            stated[cells[0]] = last if cells[3] == "as above" else cells[3]
            last = stated[cells[0]]
    assert len(stated) >= 20
    for name, c in validation.cases().items():
        assert c.target and c.quick_target, name
        if c.row is not None:
            assert stated[c.row] == c.target, name


def test_judging():
    within, judge = validation.within, validation.judge
    assert within(-0.004, 0.005) and not within(0.006, 0.005) and within(0.005, 0.005)
    assert within(0.3, [0.0, 0.84]) and not within(-0.1, [0.0, 0.84]) and within(-0.9, [None, -0.75])
    assert within(True, True) and not within(False, True) and not within(1, True)
    assert within("TAUT", "TAUT") and not within("SLACK", "TAUT")
    assert within([0.01, -0.02], 0.05) and not within([0.01, 0.2], 0.05) and not within([], 0.05)
    assert not within(math.nan, 1.0) and not within(math.inf, [0, None]) and not within(None, 1.0)
    m = {"a": 0.1, "l90": {"sym": 1e-12}, "at": {"0.1s": {"v": 2.0}}, "x.y": 3.0}
    assert validation.lookup(m, "l90.sym") == 1e-12 and validation.lookup(m, "at.0.1s.v") == 2.0
    assert validation.lookup(m, "x.y") == 3.0
    assert judge(m, {"a": 0.2, "l90.sym": 1e-9}) == (True, [])
    assert judge(m, {"a": 0.05, "missing": 1.0}) == (False, ["a", "missing"])
    assert judge(m, {}) == (False, [])


def test_a_case_may_not_judge_itself(monkeypatch):
    monkeypatch.setitem(validation._CASES, "self-judged", validation.Case(
        "self-judged", "returns passed", lambda quick: {"passed": True, "metrics": {}, "tolerances": {}}, "t", "q"))
    with pytest.raises(TypeError, match="judged from its tolerances"):
        validation.run("self-judged", quick=True)


def test_a_departure_carries_the_stated_target_with_its_measured_value(monkeypatch):
    def fn(quick):
        return {"metrics": {"err_fitted": 0.02, "err_as_measured": 0.09}, "tolerances": {"err_fitted": 0.05},
                "stated_tolerances": {"err_as_measured": 0.05},
                "departure": {"criterion": "the error after a fitted offset", "why": "the clock is unknown"}}

    monkeypatch.setitem(validation._CASES, "departed", validation.Case("departed", "d", fn, "within 5 %", "q", None))
    r = validation.run("departed", quick=False)
    assert r["passed"] is True
    assert r["stated"] == {"target": "within 5 %", "tolerances": {"err_as_measured": 0.05},
                           "measured": {"err_as_measured": 0.09}, "met": False}
    assert r["departure"] == {"criterion": "the error after a fitted offset", "why": "the clock is unknown"}
    assert r["target"].startswith("full: the error after a fitted offset (departs from declared")


def test_trade_tables_come_from_docs_and_the_set_up_from_the_docstring():
    known = validation.cases()
    trade = report.case_trade("westergaard")
    assert trade.startswith("Measured trade") and "| dx [m] |" in trade and "| 0.025 |" in trade
    assert "| 10 | 758 | 3915 |" in report.case_trade("dambreak-2d")
    # "see :func:`run_spheric10`": its first paragraph is the set-up
    assert "SPHERIC benchmark 10" in report.case_setup(known["sloshing-spheric10"].fn)
    # the current trade is the case's trade file, the history's tables stay in the history
    trade = report.case_trade("sloshing-spheric10")
    assert "| 3.1, r2 | 320493 | 2042 |" in trade and "0.0186" not in trade
    assert "| 0.025 | 1118 | 47539 | +0.0084 |" in report.case_trade("sloshing-frequency")
    assert report.case_trade("catenary-limits") is None
    # every trade file belongs to a case, and the cases no longer carry the tables themselves
    files = sorted(report.HISTORY_DIR.glob("*_trade.md"))
    assert len(files) >= 6 and {f.name[:-len("_trade.md")] for f in files} <= set(known)
    assert not [n for n, c in known.items() if "=====" in (c.fn.__doc__ or "") and "Measured trade (" in c.fn.__doc__]
    # a line with an empty first cell, or with nothing but its first cell, continues the row above
    header, rows = report.rst_table("=====  ======\na      b\n       (b)\n=====  ======\n1      2\n       3\nx      y\n"
                                    "z\n=====  ======")
    assert header == ["a", "b (b)"] and rows == [["1", "2 3"], ["x z", "y"]]


def test_history_files_belong_to_cases_and_are_linked_and_included(tmp_path):
    files = sorted(report.HISTORY_DIR.glob("*_history.md"))
    assert {f.name for f in files} >= {"sloshing-spheric10_history.md", "hydrostatic-3d_history.md",
                                        "dambreak-2d_history.md", "sloshing-frequency_history.md"}
    known = validation.cases()
    for f in files:
        name = f.name[: -len("_history.md")]
        assert name in known, f.name
    rec = {"name": "hydrostatic-3d", "quick": True, "passed": True, "target": "quick: x (declared)",
           "stated_target": known["hydrostatic-3d"].target, "metrics": {"p_rms_err_time_avg": 0.0092},
           "tolerances": {"p_rms_err_time_avg": 0.01}, "particles": 3640, "steps": 10629, "wall_s": 75.0}
    report.write_report(tmp_path, [rec])
    page = (tmp_path / "hydrostatic-3d.md").read_text()
    assert "](history/hydrostatic-3d_history.md)" in page and (tmp_path / "history" / "hydrostatic-3d_history.md").exists()
    assert "Session 5" in page and "Fourtakas" in page  # the history is included


def test_markdown_to_html():
    h = report.md_to_html("# T\n\npara `a|b` and [x](x.md) **b**\n\n| a | b |\n|---|---|\n| 1 \\| 2 | 3 |\n\n- i\n- j\n")
    assert "<h1>T</h1>" in h and '<a href="x.html">x</a>' in h and "<code>a|b</code>" in h
    assert "<td>1 | 2</td><td>3</td>" in h and "<li>i</li><li>j</li>" in h and "<strong>b</strong>" in h


@pytest.mark.slow
def test_every_quick_record_is_judged_by_its_declared_tolerances():
    """Every registered case, quick (a few minutes): passed == every metric within its tolerance."""
    for name in validation.cases():
        r = validation.run(name, quick=True)
        assert r["tolerances"] and r["target"].startswith("quick: ")
        failed = validation.judge(r["metrics"], r["tolerances"])[1]
        assert r["passed"] == (not failed) and r["outside_tolerance"] == failed, name


def test_the_committed_records_give_every_case_its_quick_cost_and_status(capsys):
    """docs/validation/records.jsonl, the records of ``cosim validate all --quick --report
    DIR``: a quick record of every case, judged against the case's present quick target and
    by its own tolerances (passed as judge() finds it), with its costs; ``cosim validate
    --list`` on a bare checkout shows each case's cost and status from them."""
    recs = report.read_records(validation.committed_records())
    cases = validation.cases()
    quick = {r["name"]: r for r in recs if r["quick"]}
    assert set(quick) == set(cases), set(cases) ^ set(quick)
    for name, r in quick.items():
        assert r["target"] == validation.target_text(cases[name], True), f"{name}: run it again"
        assert r["passed"] == validation.judge(r["metrics"], r["tolerances"])[0], name
        assert r["wall_s"] > 0 and r["case_cpu_s"] >= 0, name
    assert main(["validate", "--list"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"from {validation.committed_records()}") and "(*)" not in out
    rows = {ln.split()[0]: ln for ln in out.splitlines() if ln.split() and ln.split()[0] in cases}
    for name, r in quick.items():
        cost, status = rows[name].split()[1], rows[name].split("  ")[-1]
        assert float(cost.lstrip("<")) == pytest.approx(validation.cost(r), rel=0.05, abs=0.01), name
        variant = "quick (long)" if cases[name].long else "quick"
        assert status.startswith(f"{variant}: target met;" if r["passed"] else f"{variant}: not met;"), name
