"""The elevation a body radiates (fluid.potential.elevation): its far field carries the
damping's power (energy flux, Newman 1977 §6.18), travels outwards in Capytaine's time
factor, is cached, and bad input is refused (a coarse cylinder: a few seconds)."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("capytaine")
pytest.importorskip("h5netcdf")

from scipy.special import hankel1  # noqa: E402

from cosim.errors import InputError  # noqa: E402
from fluid.potential import compute, wetted_hull  # noqa: E402
from fluid.potential.elevation import radiated_elevation  # noqa: E402
from fluid.waves import group_velocity, wavenumbers  # noqa: E402

RHO, G, DEPTH, OMEGA = 1000.0, 9.81, 6.0, 1.775
FAR = np.array([[150.0, 0.0], [0.0, 200.0], [180.0, 180.0]])  # well past the evanescent modes


@pytest.fixture(scope="module")
def cylinder():
    """The radiation case's hull (R = 3 m, draft 1.5 m) on coarse panels (0.2 R)."""
    return wetted_hull("cylinder", [3.0, 1.5], np.eye(3), [0.0, 0.0, 0.0], 0.6)


def test_the_far_wave_carries_the_damping_and_travels_outwards(cylinder, tmp_path):
    """Far out the heave's wave is ``A H0^(1)(k r)`` (outgoing with ``exp(-i w t)``): the
    same ``A`` at every distance and bearing, and its flux ``2 rho g |A|^2 c_g / k`` is the
    power ``B33 w^2 / 2`` of a unit heave, B33 from the same solver's pressure on the hull
    (within 1.5 %: the two are the panels' discretisation apart)."""
    e = radiated_elevation(cylinder, 0.0, "Heave", OMEGA, FAR, depth=DEPTH, rho=RHO, g=G, cache=tmp_path)
    k = float(wavenumbers(OMEGA, DEPTH, G))
    amp = e / hankel1(0, k * np.hypot(FAR[:, 0], FAR[:, 1]))
    assert np.abs(amp / amp[0] - 1.0).max() < 0.01
    c = compute(cylinder, 0.0, omega=[0.95 * OMEGA, OMEGA], depth=DEPTH, rho=RHO, g=G, cache=tmp_path)
    b33 = float(c.damping[1, 2, 2])
    from_flux = math.sqrt(b33 * OMEGA**2 / 2.0 * k / (2.0 * RHO * G * float(group_velocity(k, DEPTH, G))))
    assert abs(amp[0]) == pytest.approx(from_flux, rel=0.015)


def test_the_elevation_is_cached_and_keyed_by_the_points(cylinder, tmp_path):
    a = radiated_elevation(cylinder, 0.0, "Heave", OMEGA, FAR[:2], depth=DEPTH, cache=tmp_path)
    assert len(list(tmp_path.glob("elevation-*.npz"))) == 1
    assert np.array_equal(radiated_elevation(cylinder, 0.0, "Heave", OMEGA, FAR[:2], depth=DEPTH, cache=tmp_path), a)
    radiated_elevation(cylinder, 0.0, "Heave", OMEGA, FAR[:1], depth=DEPTH, cache=tmp_path)
    assert len(list(tmp_path.glob("elevation-*.npz"))) == 2


@pytest.mark.parametrize("kw, match", [({"dof": "Bob"}, "dof"), ({"omega": 0.0}, "omega"),
                                       ({"points": [[1.0, 2.0, 3.0]]}, "points"), ({"depth": 1.0}, "seabed")])
def test_bad_input_is_refused_before_solving(cylinder, tmp_path, kw, match):
    args = {"dof": "Heave", "omega": OMEGA, "points": FAR, "depth": DEPTH} | kw
    with pytest.raises(InputError, match=match):
        radiated_elevation(cylinder, 0.0, args.pop("dof"), args.pop("omega"), args.pop("points"), cache=tmp_path,
                           **args)
    assert not list(tmp_path.iterdir())
