"""The validation cases' trade studies (cosim.validations.trade): each case's scene loads
and varies as its study says, its reference gives a number per metric, its metrics name
series the scene records, the command is one ``cosim study`` accepts, and the report
shows the committed study on the case's page."""

import json
import shlex
from pathlib import Path

import pytest

from cosim import report, validation
from cosim.scene.build import build
from cosim.scene.load import load
from cosim.scene.probes import groups
from cosim.study import metrics as M
from cosim.validations import trade

NAMES = sorted(trade.STUDIES)


def test_every_study_belongs_to_a_registered_case():
    assert NAMES and set(NAMES) <= set(validation.cases())


@pytest.mark.parametrize("name", NAMES)
def test_the_scene_varies_and_records_what_the_study_measures(name, tmp_path):
    s = trade.STUDIES[name]
    scene = load(s.scene)
    assert scene.name == name
    for key, values in s.vary.items():  # every value passes the scene's checks
        for v in values:
            assert scene.with_values([f"{key}={v}"]) is not None
    coarsest = scene.with_values([f"{k}={max(v)}" if k == "fluid.dx" else f"{k}={v[0]}" for k, v in s.vary.items()])
    cols = [c for g in groups(coarsest, build(coarsest, tmp_path)) for c in g.columns]
    ref = json.loads(s.reference.read_text())
    assert ref["source"]
    for m in s.metrics:
        series, _ = M.parse(m)
        assert series in cols, (m, cols)
        assert isinstance(ref[m], float) and ref[m] > 0


@pytest.mark.parametrize("name", NAMES)
def test_the_command_is_a_cosim_study_command(name):
    from cosim.cli import main

    s = trade.STUDIES[name]
    argv = shlex.split(s.command("somewhere"))
    assert argv[:2] == ["cosim", "study"] and argv[1:] == s.argv("somewhere")
    with pytest.raises(SystemExit) as e:  # the parser accepts every option (and --help stops it there)
        main(argv[1:] + ["--help"])
    assert e.value.code == 0


def test_the_report_shows_the_committed_study(tmp_path, monkeypatch):
    name = "hydrostatic"
    folder = tmp_path / "trade" / name
    folder.mkdir(parents=True)
    (folder / "study.md").write_text("# Study: bottom.p:mean\n\nReference: file. cheapest within 0.01: x.\n\n"
                                     "| fluid.dx | bottom.p:mean |\n|---|---|\n| 0.01 | 1950 |\n")
    (folder / "pareto.png").write_bytes(b"\x89PNG\r\n\x1a\nfake")
    monkeypatch.setattr(trade, "TRADE_DIR", tmp_path / "trade")
    text = report.study_section(name)
    assert "## Trade measured by `cosim study`" in text and "| 0.01 | 1950 |" in text
    assert trade.STUDIES[name].command() in text and "# Study" not in text
    assert report.study_section("catenary-limits") is None  # no study: no section
    rec = {"name": name, "quick": True, "passed": True, "metrics": {}, "tolerances": {}}
    out = tmp_path / "report"
    report.write_report(out, [rec])
    page = (out / f"{name}.md").read_text()
    assert f"![error against cost, the Pareto front marked](trade/{name}_pareto.png)" in page
    assert (out / "trade" / f"{name}_pareto.png").read_bytes() == (folder / "pareto.png").read_bytes()


@pytest.mark.parametrize("name", NAMES)
def test_a_committed_study_is_the_one_its_case_declares(name):
    """The committed table measured what the study declares (same metrics, same levers)."""
    d = trade.study_dir(name)
    assert (d / "study.md").exists() and (d / "pareto.png").exists(), f"measure it: {trade.STUDIES[name].command()}"
    js = json.loads((d / "study.json").read_text())
    s = trade.STUDIES[name]
    assert js["metrics"] == list(s.metrics)
    assert {k: [float(x) for x in v] for k, v in js["vary"].items()} == \
        {k: [float(x) for x in v] for k, v in s.vary.items()}
    assert Path(js["reference"]["file"]).name == s.reference.name
