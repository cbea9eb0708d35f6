"""An irregular sea on the potential fluid: the components above the band its coefficients trust
(omega_max / 2) are left out when they carry at most 1 % of the sea's variance, measured against
the spectrum's integral; a scene with a JONSWAP sea runs on the default omega_max, and one that
would lose more is refused naming fluid.omega_max and the value it needs."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from fluid.potential.waves import band_share, cut_for_share, from_incident
from fluid.waves import SpectralSea


def _jonswap(w, hs, tp, gamma):
    """DNV-RP-C205 (2010) Eq. 3.5.5.2-3.5.5.4, written out here (not the code's): the
    Pierson-Moskowitz shape times gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2)), A = 1 - 0.287 ln gamma."""
    wp = 2 * math.pi / tp
    pm = 5 / 16 * hs**2 * wp**4 * w**-5 * math.exp(-5 / 4 * (w / wp) ** -4)
    sigma = 0.07 if w <= wp else 0.09
    return (1 - 0.287 * math.log(gamma)) * pm * gamma ** math.exp(-((w - wp) ** 2) / (2 * sigma**2 * wp**2))


@pytest.mark.parametrize("gamma, tp", [(3.3, 9.0), (1.0, 6.0)])  # gamma 1: Pierson-Moskowitz
def test_the_share_left_out_is_the_spectrum_integral_above_the_cut(gamma, tp):
    inc = SpectralSea(1.0, tp, 30.0, spectrum="jonswap", gamma=gamma)
    sea = from_incident(inc)
    wp, dw = 2 * math.pi / tp, inc.d_omega
    lo, hi = sea.omega[0] - dw / 2, sea.omega[-1] + dw / 2  # the band the components stand for

    def integral(a, b):
        return quad(_jonswap, a, b, args=(1.0, tp, gamma), points=[wp] if a < wp < b else None, limit=200)[0]

    total = integral(lo, hi)
    for cut in (2.0 * wp, 2.5 * wp, 3.0 * wp):
        keep, share = band_share(sea, 0.0, cut)
        assert keep.sum() == (sea.omega <= cut * (1 + 1e-9)).sum()
        assert share == pytest.approx(integral(cut, hi) / total, rel=0.03)
    # the lowest cut that keeps all but 1 %: within one component's spacing of the integral's
    cut = brentq(lambda x: integral(x, hi) / total - 0.01, wp, 4 * wp)
    assert abs(cut_for_share(sea, 0.0, 0.01) - cut) <= dw
    assert cut_for_share(sea, 3 * wp, 0.01) == math.inf  # the part below the band alone is more


capytaine = pytest.mark.skipif(not all(__import__("importlib").util.find_spec(m) for m in ("capytaine", "h5netcdf")),
                               reason="needs the potential extra")


def _scene(tp, spectrum):
    """A small cylinder (radius 1 m, draft 1 m, panels 0.5 m: default omega_max 4.53 rad/s, band to
    2.27 rad/s) in an irregular sea of peak period ``tp``, omega_max unset."""
    from cosim.scene import Scene

    return Scene.from_dict({
        "world": {"dim": 3, "duration": 20.0, "sample_every": 0.1},
        "fluid": {"model": "potential", "panel_size": 0.5},
        "waves": {"kind": "irregular", "spectrum": spectrum, "hs": 0.2, "tp": tp, "depth": 30.0, "ramp": 1.0},
        "bodies": [{"shape": "cylinder", "name": "buoy", "radius": 1.0, "length": 2.0, "pos": [0.0, 0.0],
                    "place": "floating", "density": 500.0}],
    })


@pytest.mark.long
@capytaine
def test_a_jonswap_sea_runs_on_the_default_omega_max(tmp_path, monkeypatch):
    monkeypatch.setenv("COSIM_POTENTIAL_CACHE", str(tmp_path / "cache"))
    scene = _scene(9.0, "jonswap")  # components to 4 wp = 2.79 rad/s; the band ends at 3.25 wp
    res = scene.run(tmp_path / "out", progress=False)
    wp, band = 2 * math.pi / 9.0, 0.5 * math.sqrt(2 * math.pi * 9.81 / (6 * 0.5))
    left = res.summary["sea_variance_left_out"]["buoy"]
    # JONSWAP (gamma 3.3) above 3.25 wp, of the components' 0.5-4 wp (measured 0.42 %)
    share = quad(_jonswap, band, 4 * wp, args=(0.2, 9.0, 3.3))[0] / quad(_jonswap, 0.5 * wp, 4 * wp,
                                                                        args=(0.2, 9.0, 3.3), points=[wp])[0]
    assert left == pytest.approx(share, rel=0.05) and left < 0.01
    heave = res["buoy.heave"]
    assert np.isfinite(heave).all() and np.ptp(heave[res.t > 10.0]) > 0.01  # the sea moves it


@capytaine
def test_a_sea_that_would_lose_more_is_refused_naming_omega_max(tmp_path, monkeypatch):
    from cosim.scene.fields import SceneError

    monkeypatch.setenv("COSIM_POTENTIAL_CACHE", str(tmp_path / "cache"))
    scene = _scene(6.0, "pierson-moskowitz")  # the band ends at 2.17 wp: 5 % of the variance above
    with pytest.raises(SceneError, match=r"fluid\.omega_max: .* carry 5\.\d% of its variance") as e:
        scene.run(tmp_path / "out", progress=False)
    assert not list((tmp_path / "cache").glob("*.nc"))  # refused before any solve
    need = float(re.search(r"set omega_max >= ([\d.]+) rad/s", str(e.value)).group(1))
    wp = 2 * math.pi / 6.0
    pm = lambda w: 5 / 16 * wp**4 * w**-5 * math.exp(-5 / 4 * (w / wp) ** -4)  # noqa: E731  (Hs = 1 m)
    # PM's variance above x wp is (1 - exp(-5/4 x^-4)) Hs^2 / 16 (its closed-form integral); 1 % of
    # the components' 0.5-4 wp lies above x = 3.02, so omega_max = 2 x wp
    total = quad(pm, 0.5 * wp, 4 * wp)[0]
    x = brentq(lambda x: (math.exp(-5 / 4 / 4**4) - math.exp(-5 / 4 / x**4)) / 16 / total - 0.01, 2, 4)
    assert need == pytest.approx(2 * x * wp, rel=0.01)
