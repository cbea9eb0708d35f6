"""The `cosim` command line."""

import csv
import json

import numpy as np
import pytest

from cosim.cli import main
from moorings.catenary import solve


def test_line_table_csv_and_png(tmp_path, capsys):
    out_csv, out_png = tmp_path / "line.csv", tmp_path / "line.png"
    args = ["line", "--length", "6.98", "--weight", "1.036", "--height", "2.651", "--x-range", "4", "6.5",
            "--points", "6", "--csv", str(out_csv), "--png", str(out_png)]
    assert main(args) == 0
    text = capsys.readouterr().out
    assert "state change RESTING -> PARTLY_LIFTED at X = 4.329" in text
    assert "state change PARTLY_LIFTED -> FULLY_LIFTED at X = 6.2881002" in text
    assert "state change FULLY_LIFTED -> TAUT at X = 6.4569806" in text
    rows = list(csv.DictReader(out_csv.open()))
    # no sample falls between lift-off (6.288 m) and taut (6.457 m): both changes are still reported
    assert [r["state"] for r in rows] == ["RESTING", "PARTLY_LIFTED", "PARTLY_LIFTED", "PARTLY_LIFTED",
                                          "PARTLY_LIFTED", "TAUT"]
    X = np.array([float(r["X [m]"]) for r in rows])
    ref = solve(X, 2.651, 6.98, 1.036)
    np.testing.assert_array_equal([float(r["H [N]"]) for r in rows], ref.H)
    assert out_png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_line_preset_and_elastic(capsys):
    assert main(["line", "--preset", "johanning-2006", "--EA", "1e9", "--points", "3"]) == 0
    text = capsys.readouterr().out
    assert "L = 150 m, w = 918.75 N/m, h = 50 m, EA = 1e+09 N" in text
    assert "102" in text and "140" in text


def test_line_bad_input_is_a_clear_error(capsys):
    assert main(["line", "--length", "5", "--weight", "-1", "--height", "1", "--x-range", "0", "4"]) == 2
    assert "w = -1.0 N/m" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["line", "--weight", "1", "--height", "1", "--x-range", "0", "4"])
    assert "--length is required" in capsys.readouterr().err


def test_validate_list_and_run(capsys, tmp_path, monkeypatch):
    from cosim import validation

    monkeypatch.setattr(validation, "committed_records", lambda: tmp_path / "none.jsonl")
    assert main(["validate", "--list"]) == 0
    listed = capsys.readouterr().out
    for name in ("catenary-limits", "catenary-johanning-2007", "catenary-johanning-2006", "catenary-two-lines"):
        assert name in listed
    assert listed.startswith("no validation records in ") and "cost and status unknown" in listed
    # with records (a report's records.jsonl): each variant's cost [s] and what it met; a record
    # judged against another target than the case's present one is marked
    cases = validation.cases()
    records = tmp_path / "records.jsonl"
    records.write_text("\n".join(json.dumps(r) for r in (
        {"name": "catenary-limits", "quick": True, "passed": True, "wall_s": 0.31, "case_cpu_s": 0.3,
         "target": validation.target_text(cases["catenary-limits"], True)},
        {"name": "westergaard", "quick": False, "passed": True, "wall_s": 812.0,
         "departure": {"criterion": "RMS of k_p", "why": "..."}, "stated": {"met": False},
         "target": validation.target_text(cases["westergaard"], False, {"criterion": "RMS of k_p"})},
        {"name": "westergaard", "quick": True, "passed": True, "wall_s": 3.9, "case_cpu_s": 3.8,
         "departure": {"criterion": "RMS of k_p", "why": "..."}, "stated": {"met": False},
         "target": validation.target_text(cases["westergaard"], True)},
        {"name": "dambreak-2d", "quick": False, "passed": False, "wall_s": 95.0, "target": "full: an older one"}))
        + "\n")
    assert main(["validate", "--list", "--from", str(records)]) == 0
    out = capsys.readouterr().out
    rows = {ln.split()[0]: ln for ln in out.splitlines() if ln.strip()}
    # the cost: CPU seconds, or the wall time of a record without them
    assert rows["catenary-limits"].split()[1:3] == ["0.30", "-"] and "quick: target met;" in rows["catenary-limits"]
    assert rows["westergaard"].split()[1:3] == ["3.8", "812"]
    assert "quick: target met;" in rows["westergaard"]  # a quick variant is judged on its declared target
    assert "full: departure met (stated target not met)" in rows["westergaard"]
    assert "full: not met (*)" in rows["dambreak-2d"] and "quick: no record" in rows["dambreak-2d"]
    assert "(*) the record was judged against another target" in out
    n = validation.cores()
    assert f"quick variants: 2 of {len(cases)} cases recorded, 4 s in all;" in out
    assert (f"cosim validate all --quick runs the 2 recorded of the quick tier (4 s), {n} at once on this machine's "
            f"{n} cores (--jobs): about {max(4.1 / n, 3.8):.0f} s of wall time;") in out
    assert "--long adds" not in out  # none of the records is of a long case
    assert main(["validate", "catenary-limits", "--quick"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["name"] == "catenary-limits" and rec["passed"] is True and rec["quick"] is True
    for key in ("metrics", "tolerances", "particles", "steps", "wall_s", "case_cpu_s"):
        assert key in rec
    with pytest.raises(SystemExit):
        main(["validate", "no-such-case"])
    assert "unknown case" in capsys.readouterr().err
