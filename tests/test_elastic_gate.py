"""The elastic-gate case (cosim/validations/elastic_gate.py; Antoci et al. 2007): the
measured data as refdata SOURCE.txt describes them, the comparison's arithmetic, and the
quick variant."""

import numpy as np
import pytest

from cosim.validations import elastic_gate as eg


def test_the_measured_data_are_the_ones_source_txt_describes():
    ref = eg.experiment()
    x, y = ref["x"], ref["y"]
    assert len(x) == 9 and len(y) == 10
    # SOURCE.txt: peak x 46.4 mm at 0.16 s, peak y 17.1 mm at 0.16 s; frames 0.04 s apart
    assert x[:, 1].max() == pytest.approx(0.0464, abs=5e-5)
    assert x[np.argmax(x[:, 1]), 0] == pytest.approx(0.16, abs=2e-3)
    assert y[:, 1].max() == pytest.approx(0.0171, abs=5e-5)
    assert y[np.argmax(y[:, 1]), 0] == pytest.approx(0.16, abs=2e-3)
    assert np.diff(x[:, 0]) == pytest.approx(0.04, abs=2e-3)


def test_compare_measures_the_rms_difference_relative_to_the_peak_and_the_lag():
    """The experiment against itself: no error, no lag. Scaled by 1.1: every frame 10 % of
    its own value off, so the RMS relative to the peak is 0.1 rms(ref) / peak exactly.
    Delayed by one frame: the peak lags by 0.04 s."""
    ref = eg.experiment()
    t = np.linspace(0.0, 0.4, 401)
    x, y = (np.interp(t, np.clip(ref[k][:, 0], 0, None), ref[k][:, 1]) for k in ("x", "y"))
    m = eg.compare(t, x, y, 0.4)
    assert m["rms_rel_x"] < 2e-3 and m["rms_rel_y"] < 2e-3  # our grid puts the frames 1 ms off
    assert m["peak_lag_s_x"] == pytest.approx(0.0, abs=2e-3) and m["correlation_x"] > 0.999
    m = eg.compare(t, 1.1 * x, 1.1 * y, 0.4)
    rx = ref["x"][:, 1]
    assert m["rms_rel_x"] == pytest.approx(0.1 * np.sqrt(np.mean(rx**2)) / rx.max(), rel=0.02)
    assert m["peak_rel_err_x"] == pytest.approx(0.1, abs=0.01)
    m = eg.compare(t + 0.04, x, y, 0.4)
    assert m["peak_lag_s_x"] == pytest.approx(0.04, abs=2e-3) and m["peak_lag_s_y"] == pytest.approx(0.04, abs=2e-3)
    assert len(m["err_rel_x"]) == 9 and len(m["err_rel_y"]) == 10


def test_the_published_numerical_solutions_lie_as_far_from_the_experiment():
    """Judged by the case's own criterion, the three published solutions (Khayyer 2018,
    Yang 2012, Ng 2020; refdata SOURCE.txt) miss the measurement as well: their RMS
    difference over the frames is 18-23 % of the measured peak in x and 26-31 % in y, and
    their peaks lead the measured one by 0.041-0.046 s (ours: elastic_gate docstring)."""
    t = np.linspace(0.0, 0.4, 801)
    for name, c in eg.numerical().items():
        x, y = (np.interp(t, c[k][:, 0], c[k][:, 1]) for k in ("x", "y"))
        m = eg.compare(t, x, y, 0.4)
        assert 0.17 < m["rms_rel_x"] < 0.24 and 0.25 < m["rms_rel_y"] < 0.32, name
        assert -0.047 < m["peak_lag_s_x"] < -0.040, name
        assert m["rms_rel_vs_numerical"][f"{name}.x"] < 0.01  # itself


@pytest.mark.long
def test_elastic_gate_validation_quick():
    """dx = 5 mm (thin wall), N = 8, 0.3 s (cosim validate elastic-gate --quick). Judged
    against the stated criterion the case does not pass (its docstring: neither do the
    published solutions); what is asserted here is the opening, which all of them get: the
    frames up to 0.08 s within 15 % of the measured peak, x and y."""
    from cosim import validation

    r = validation.run("elastic-gate", quick=True)
    m = r["metrics"]
    early_x = [e for t, e in zip(m["t_frames_x"], m["err_rel_x"]) if t <= 0.085]
    early_y = [e for t, e in zip(m["t_frames_y"], m["err_rel_y"]) if t <= 0.085]
    assert len(early_x) == 2 and len(early_y) == 3
    assert max(map(abs, early_x + early_y)) < 0.15
    assert set(m["rms_rel_vs_numerical"]) == {f"{n}.{k}" for n in eg.NUMERICAL for k in "xy"}
    assert r["passed"] == (m["rms_rel_x"] <= 0.15 and m["rms_rel_y"] <= 0.15
                           and abs(m["peak_lag_s_x"]) <= 0.04 and abs(m["peak_lag_s_y"]) <= 0.04)


@pytest.mark.slow
def test_elastic_gate_validation_full():
    """dx = 1.25 mm, N = 16, 0.4 s (about 155 CPU s): the opening within 15 % of the measured
    peak, and the whole curve within 12 % (RMS relative to each one's peak) of the three
    published numerical solutions, which miss the experiment as ours does (docstring)."""
    from cosim import validation

    r = validation.run("elastic-gate", quick=False)
    m = r["metrics"]
    early = [e for t, e in zip(m["t_frames_x"] + m["t_frames_y"], m["err_rel_x"] + m["err_rel_y"]) if t <= 0.085]
    assert len(early) == 5 and max(map(abs, early)) < 0.15
    assert max(m["rms_rel_vs_numerical"].values()) < 0.12
