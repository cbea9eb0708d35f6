"""Yang & Li 2020, §4.2 (Table 2, Tests 1, 4, 5): the
distance a between the dam-break column and the elastic structure, 146 / 176 / 206 mm, as
the validation case ``elastic-table2`` (:mod:`cosim.validations.elastic_table2`). The
paper's text gives the structure's peak top displacement for each: 0.82 / 0.76 / 0.67 mm."""

import pytest

from cosim import validation
from cosim.validations.elastic_table2 import A_GROUP, PAPER, a_group_metrics


def _ms(peaks, onsets):
    return {t: {"peak_mm": p, "motion_onset_s": o, "peak_t_s": 0.2, "arrival_s": o - 0.005}
            for t, p, o in zip(A_GROUP, peaks, onsets)}


def test_the_metrics_hold_the_ratios_to_a146_against_the_papers():
    m = a_group_metrics(_ms([0.82, 0.76, 0.67], [0.13, 0.15, 0.16]))  # the paper's own peaks
    assert m["ratio_err"] == pytest.approx({"a176": 0.0, "a206": 0.0}, abs=1e-12)
    assert m["peak_falls_with_a"] and m["onset_later_with_a"] and m["paper_peaks_within_15pct"]
    m = a_group_metrics(_ms([4.0, 3.0, 3.2], [0.13, 0.12, 0.16]))
    assert m["ratio_to_a146"] == pytest.approx({"a176": 0.75, "a206": 0.8})
    assert m["ratio_err"]["a176"] == pytest.approx(0.75 - 0.76 / 0.82)
    assert not m["peak_falls_with_a"] and not m["onset_later_with_a"] and not m["paper_peaks_within_15pct"]
    assert m["peak_rel_err_vs_paper"]["a146"] == pytest.approx(4.0 / 0.82 - 1.0)


@pytest.mark.slow  # 1-2 CPU-minutes: out of CI's time (docs/development.md); elastic-plate and elastic-gate stay
def test_quick_variant_the_peak_falls_and_the_motion_starts_later_with_a():
    """dx = 5 mm, Tests 1 and 5 (~40 CPU-s; measured 2026-11-26: 3.24 / 2.91 mm, ratio
    0.896, onsets 0.132 / 0.165 s); the paper's ratio within 0.05 is the full variant's."""
    r = validation.run("elastic-table2", quick=True)
    m = r["metrics"]
    assert r["passed"], r["outside_tolerance"]
    assert m["ratio_to_a146"]["a206"] < 0.95 and m["peak_falls_with_a"] and m["onset_later_with_a"]
    assert set(r["stated"]["tolerances"]) == {"ratio_err.a206", "peak_falls_with_a", "onset_later_with_a"}


@pytest.fixture(scope="module")
def full():
    return validation.run("elastic-table2", quick=False)


@pytest.mark.slow
def test_the_peak_falls_with_the_distance_in_the_papers_ratios(full):
    """§4.2 at dx = 2.5 mm (~330 CPU-s): the peak falls as a grows and the structure starts
    to move later; x / x(a = 146 mm) within 0.05 of the paper's 0.927 and 0.817 (measured
    2026-11-25: 3.34 / 3.04 / 2.60 mm, ratios 0.909 / 0.779; onsets 0.134 / 0.150 / 0.163 s)."""
    m = full["metrics"]
    assert full["passed"], full["outside_tolerance"]
    paper = [PAPER["peak_mm"][t] for t in A_GROUP]
    assert m["ratio_to_a146"]["a176"] == pytest.approx(paper[1] / paper[0], abs=0.05)
    assert m["ratio_to_a146"]["a206"] == pytest.approx(paper[2] / paper[0], abs=0.05)


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="our peaks are 3.9-4.1 times the paper's (3.34 mm at a = 146 mm against "
                   "0.82): our load matches the momentum flux of the dam-break flow and beam theory under it "
                   "gives our peak; the paper's values fit a structure 3-4 times stiffer than the one it prints "
                   "(docs/studies/elastic_dambreak/README.md)")
def test_the_peak_is_the_papers_within_15_percent(full):
    """The paper's absolute peaks, reported beside the judged ratios: each within 15 %."""
    assert full["metrics"]["paper_peaks_within_15pct"]
