"""benchmarks/radiation_2d.py's potential inside the water (section_field) and
benchmarks/radiation_2d_where.py's reading of it: a progressive wave far from the body,
nothing outside the water, the bands' shares summing to the section's coefficients, and
the pressure under the keel meeting the keel's."""

import math

import numpy as np
import pytest

from benchmarks.radiation_2d import DEPTH, PERIOD, RADIUS, contour, section_coefficients, section_field, \
    section_solution
from benchmarks.radiation_2d_where import BANDS, band_of, map_fields, map_grid, reference_by_band, reference_rows, \
    row_heights

OMEGA = 2.0 * math.pi / PERIOD


@pytest.fixture(scope="module")
def box():
    return section_solution(contour("box"), DEPTH, OMEGA, panel=RADIUS / 20)


def test_far_from_the_body_the_field_is_the_outgoing_wave(box):
    """Beyond the evanescent modes (e^-(k1 x) ~ 5e-5 at 0.8 m) the potential is
    ``A cosh(k (z + h)) / cosh(k h) e^(i k x)``: its depth profile and its phase's advance
    along x are the linear wave's."""
    k, h = box["k"], DEPTH
    zs = np.array([-0.01, -0.05, -0.1, -0.15, -0.19])
    column = section_field(box, np.column_stack([np.full_like(zs, 0.9), zs]))
    profile = np.cosh(k * (zs + h)) / np.cosh(k * h)
    assert np.abs(column / column[0]) == pytest.approx(profile / profile[0], rel=1e-3)
    pair = section_field(box, [[0.85, -0.05], [0.95, -0.05]])
    assert abs(pair[1]) == pytest.approx(abs(pair[0]), rel=2e-3)
    assert np.angle(pair[1] / pair[0]) == pytest.approx(0.1 * k, rel=5e-3)


def test_the_representation_vanishes_outside_the_water(box):
    """Green's representation gives zero at a point outside the boundary (inside the body):
    a check of the panels' potential and normal derivative together."""
    inside = section_field(box, [[0.0, -0.05], [0.05, -0.02]])
    scale = abs(section_field(box, [[0.0, -0.15]])[0])
    assert np.abs(inside).max() < 1e-3 * scale


@pytest.mark.parametrize("hull", ["box", "circle"])
def test_the_bands_shares_sum_to_the_sections_coefficients(hull):
    """The bands' A33 and B33 add up to the section's; the box's vertical sides take no
    vertical force, so its keel's band holds all of it."""
    sol = section_solution(contour(hull), DEPTH, OMEGA, panel=RADIUS / 20)
    whole = section_coefficients(contour(hull), DEPTH, OMEGA, panel=RADIUS / 20)
    bands = reference_by_band(sol, -RADIUS, 0.025, OMEGA)
    assert sum(a for a, _ in bands.values()) == pytest.approx(whole["A33"], rel=1e-9)
    assert sum(b for _, b in bands.values()) == pytest.approx(whole["B33"], rel=1e-9)
    if hull == "box":
        assert bands["keel"][1] == pytest.approx(whole["B33"], rel=1e-9)
        assert np.abs([bands["waterline"], bands["between"]]).max() < 1e-12 * whole["A33"]
    else:
        assert all(b > 0.0 for _, b in bands.values())


def test_the_pressure_under_the_keel_meets_the_keels():
    """The reference's pressure in the row touching the box's flat keel, averaged across
    the beam, is the keel panels' mean (A33 and B33 over the beam) within 2 % and 0.5 %; it falls
    away from the keel as the radiated wave's does with depth."""
    sol = section_solution(contour("box"), DEPTH, OMEGA, panel=RADIUS / 40)
    whole = section_coefficients(contour("box"), DEPTH, OMEGA, panel=RADIUS / 40)
    rows = reference_rows(sol, row_heights(-RADIUS, RADIUS / 40, 2), RADIUS - RADIUS / 40, OMEGA, points=39)
    assert rows[0, 0] == pytest.approx(whole["A33"] / (2.0 * RADIUS), rel=0.02)
    assert rows[0, 1] == pytest.approx(whole["B33"] / (2.0 * RADIUS), rel=5e-3)
    assert rows[1, 1] < rows[0, 1]


def test_bands_and_rows():
    """A height within the reach above the keel is the keel's, one within it of the
    waterline the waterline's (the keel's first where both hold); rows start at the keel."""
    assert [BANDS[i] for i in band_of([-0.1, -0.08, -0.05, -0.01, 0.02], -0.1, 0.025)] == \
        ["keel", "keel", "between", "waterline", "waterline"]
    assert BANDS[band_of(-0.02, -0.03, 0.025)] == "keel"
    assert row_heights(-0.1, 0.01, 3) == pytest.approx([-0.105, -0.115, -0.125])


def test_the_map_reads_the_references_own_pressure_back(box):
    """Cells whose pressure follows the reference's field for a heave ``a sin(omega t)``
    read back as the reference's in-phase-with-velocity pressure (the signs and phases of
    the SPH side and the reference side agree); the swept cells and those at the surface
    are left out."""
    grid = map_grid(RADIUS / 4)
    ex, ez = grid
    X, Z = np.meshgrid(0.5 * (ex[1:] + ex[:-1]), 0.5 * (ez[1:] + ez[:-1]) - DEPTH, indexing="ij")
    water = (np.abs(X) > RADIUS) | (Z < -RADIUS)
    phi = np.zeros(X.shape, complex)
    phi[water] = section_field(box, np.column_stack([X[water], Z[water]]))
    a = 0.0025
    ts = np.linspace(0.0, 3.0 * PERIOD, 241)[:-1]
    # unit velocity Re(e^(-i w t)) = cos(w t) gives p = Re(i w rho phi e^(-i w t)); the heave's velocity is a w cos
    cells = a * OMEGA * (1j * OMEGA * 1000.0 * phi[None] * np.exp(-1j * OMEGA * ts)[:, None, None]).real
    sph, ref, ok = map_fields(ts, cells, grid, box, "box", 1.0, a, OMEGA)
    assert ok.sum() > 20 and not ok[~water].any() and not ok[Z > -RADIUS / 4].any()
    assert sph[ok] == pytest.approx(ref[ok], rel=1e-6, abs=1e-6 * np.abs(ref[ok]).max())
    under = ok & (np.abs(X) < 0.5 * RADIUS)
    assert ref[under] == pytest.approx(195.0, rel=0.05)  # the keel's mean, B33 / 2R (test above)
