"""Seed 002 §4.2 (002_1507eb345a9709e6.txt; Yang & Li 2020, Table 2, Tests 1, 4, 5): the
distance a between the dam-break column and the elastic structure, 146 / 176 / 206 mm, run
as scenes of :mod:`cosim.validations.elastic_table2` at the paper's spacing, dx = 2.5 mm.
The paper's text gives the structure's peak top displacement for each: 0.82 / 0.76 / 0.67
mm."""

import pytest

from cosim.validations.elastic_table2 import PAPER, metrics, run_cases

A_GROUP = (1, 4, 5)


@pytest.fixture(scope="module")
def a_group(tmp_path_factory):
    out = tmp_path_factory.mktemp("elastic_table2")
    res = run_cases(A_GROUP, [0.0025], out)
    assert not any(rec.get("error") for _, _, rec, _ in res), [rec.get("error") for _, _, rec, _ in res]
    return {t: metrics(t, folder) for t, _, _, folder in res}


@pytest.mark.slow
def test_the_peak_falls_with_the_distance_in_the_papers_ratios(a_group):
    """§4.2: the peak falls as a grows and the structure starts to move later; x / x(a =
    146 mm) within 0.05 of the paper's 0.76 / 0.82 = 0.927 and 0.67 / 0.82 = 0.817
    (measured 2026-11-25: 3.34 / 3.04 / 2.60 mm, ratios 0.909 / 0.779; onsets 0.134 /
    0.150 / 0.163 s)."""
    x = [a_group[t]["peak_mm"] for t in A_GROUP]
    onset = [a_group[t]["motion_onset_s"] for t in A_GROUP]
    assert x[0] > x[1] > x[2] and onset[0] < onset[1] < onset[2]
    paper = [PAPER["peak_mm"][t] for t in A_GROUP]
    for k in (1, 2):
        assert x[k] / x[0] == pytest.approx(paper[k] / paper[0], abs=0.05)


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="our peaks are 3.9-4.1 times the paper's (3.34 mm at a = 146 mm against "
                   "0.82): our load matches the momentum flux of the dam-break flow and beam theory under it "
                   "gives our peak; the paper's values fit a structure 3-4 times stiffer than the one it prints "
                   "(docs/studies/elastic_dambreak/README.md)")
def test_the_peak_is_the_papers_within_15_percent(a_group):
    """The stated comparison, kept visible: each peak within 15 % of the paper's."""
    for t in A_GROUP:
        assert a_group[t]["peak_mm"] == pytest.approx(PAPER["peak_mm"][t], rel=0.15)
