"""fluid.standoff: fluid fitted to a body's flat faces, so that a body at rest carries its
own volume's weight (F = rho g V_hole, V_hole the region no fluid cell covers)."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bodies.sampling import signed_distance
from fluid.standoff import ROWS, fit_to_faces

DX = 0.1


def _lattice(lo, hi, dx=DX):
    axes = [np.arange(a + 0.5 * dx, b - 1e-9, dx) for a, b in zip(lo, hi)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


def _carved(kind, size, centre, rot=np.eye(3)):
    """Lattice water around a geom, its cells reaching into it removed (cosim.sph_fluid)."""
    pts = _lattice((-1.6, -1.6, -1.6), (1.6, 1.6, 1.6))
    sd = signed_distance(kind, np.asarray(size, float), (pts - centre) @ rot)
    return pts[sd >= 0.5 * DX - 1e-12]


def _column(pts, x, y, below=None, above=None):
    m = (np.abs(pts[:, 0] - x) < 1e-9) & (np.abs(pts[:, 1] - y) < 1e-9)
    if below is not None:
        m &= pts[:, 2] < below
    if above is not None:
        m &= pts[:, 2] > above
    return m


@pytest.mark.parametrize("phase", [0.0, 0.3, 0.55, 0.9])
def test_a_box_between_lattice_planes_leaves_no_hole_beyond_itself(phase):
    """Under the bottom face of a box whose faces lie ``phase`` dx off the lattice's
    planes: the first row stands dx/2 off the face (the lattice row nearest that, put
    back where it had been removed), it moves by at most dx/2, the stretched rows are
    evenly spaced, and their cells (volume factors) fill the column from the face down
    to the first unmoved row's cell exactly: the fluid's hole is the box."""
    half = np.array([0.6, 0.6, 0.45]) + phase * DX
    pts = _carved("box", half, np.zeros(3))
    fit, vol = fit_to_faces(pts, [("box", half, np.zeros(3), np.eye(3))], DX)
    face = -half[2]
    old = np.sort(pts[_column(pts, 0.05, 0.05, below=face), 2])[::-1]
    col = _column(fit, 0.05, 0.05, below=face)
    order = np.argsort(-fit[col, 2])
    z, v = fit[col, 2][order], vol[col][order]
    assert z[0] == pytest.approx(face - 0.5 * DX, abs=1e-12)
    lattice_first = old[0] + DX if old[0] + DX < face - 1e-12 else old[0]  # nearest dx/2, lattice
    assert abs(z[0] - lattice_first) <= 0.5 * DX + 1e-12
    gaps = -np.diff(z[: ROWS + 1])
    assert np.allclose(gaps, gaps[0], atol=1e-12) and abs(gaps[0] - DX) <= DX / (2 * ROWS) + 1e-12
    assert np.array_equal(np.sort(z[ROWS:]), np.sort(old[old < z[ROWS - 1] - 0.5 * DX]))  # beyond: unmoved
    assert np.all(v[ROWS:] == 1.0)
    assert v[:ROWS].sum() * DX == pytest.approx(face - (z[ROWS] + 0.5 * DX), abs=1e-12)
    assert np.allclose(v[1:ROWS], gaps[1:] / DX, atol=1e-12)  # the stretch's Jacobian


def test_water_ending_within_the_band_keeps_its_last_row():
    """A box with only five rows of water over its top face (a free surface there): the
    first row is fitted, the surface row stays where it was (the level kept), and the
    cells between still tile the column from the face to the surface row's cell; with
    three rows (fewer than MIN_ROWS to take the stretch) nothing moves."""
    half = np.array([0.6, 0.6, 0.47])
    pts = _carved("box", half, np.zeros(3))
    shallow = pts[pts[:, 2] < 0.8]  # rows at 0.55, 0.65, 0.75 over the top face at 0.47
    fit, vol = fit_to_faces(shallow, [("box", half, np.zeros(3), np.eye(3))], DX)

    def over(p):
        return (p[:, 2] > half[2]) & (np.abs(p[:, 0]) < half[0]) & (np.abs(p[:, 1]) < half[1])

    assert np.array_equal(fit[over(fit)], shallow[over(shallow)]) and np.all(vol[over(fit)] == 1.0)
    pts = pts[pts[:, 2] < 1.0]  # five rows: 0.55 ... 0.95
    fit, vol = fit_to_faces(pts, [("box", half, np.zeros(3), np.eye(3))], DX)
    col = _column(fit, 0.05, 0.05, above=half[2])
    order = np.argsort(fit[col, 2])
    z, v = fit[col, 2][order], vol[col][order]
    assert len(z) == 5 and z[0] == pytest.approx(half[2] + 0.5 * DX, abs=1e-12)
    assert z[-1] == pytest.approx(0.95, abs=1e-12) and v[-1] == 1.0
    assert v[:-1].sum() * DX == pytest.approx((z[-1] - 0.5 * DX) - half[2], abs=1e-12)


def test_a_cylinders_cap_is_fitted_and_its_curved_side_left_alone():
    """A vertical cylinder: the water under its bottom cap is fitted (first row dx/2
    off); beside its curved side (every phase of the lattice, no bias) nothing moves."""
    size = np.array([0.83, 0.47])  # radius, half-length: neither on a lattice plane
    pts = _carved("cylinder", size, np.zeros(3))
    fit, vol = fit_to_faces(pts, [("cylinder", size, np.zeros(3), np.eye(3))], DX)
    r = np.hypot(pts[:, 0], pts[:, 1])
    under = (r < size[0] - 3 * DX) & (pts[:, 2] < -size[1]) & (pts[:, 2] > -size[1] - DX)
    assert under.any() and np.allclose(fit[under, 2], -size[1] - 0.5 * DX, atol=1e-12)
    side = (np.abs(pts[:, 2]) < size[1] - 3 * DX)
    assert side.any() and np.array_equal(fit[side], pts[side]) and np.all(vol[side] == 1.0)
    # no two fitted points closer than the lattice allows after the fit's stretch
    from scipy.spatial import cKDTree

    d, _ = cKDTree(fit).query(fit, k=2)
    assert d[:, 1].min() > 0.99 * DX


@pytest.mark.parametrize("kind,size,rot", [
    ("sphere", [0.77], np.eye(3)),
    ("box", [0.63, 0.61, 0.44], Rotation.from_rotvec([0.3, 0.5, 0.2]).as_matrix()),
])
def test_faces_off_the_lattice_axes_are_left_alone(kind, size, rot):
    """A sphere has no flat face; a box turned about an oblique axis has no face along a
    lattice axis (its rows see every phase): no point moves."""
    pts = _carved(kind, size, np.zeros(3), rot)
    fit, vol = fit_to_faces(pts, [(kind, np.asarray(size, float), np.zeros(3), rot)], DX)
    assert np.array_equal(fit, pts) and np.all(vol == 1.0)


@pytest.mark.long
def test_a_held_box_carries_archimedes_whatever_its_faces_phase():
    """2-D SPH: a box held with its bottom face a quarter spacing below a lattice plane,
    the water settled (1 s, velocities damped) around it. Without the fit the water keeps
    the extra 3/4-row gap under it and the box carries that water's weight too (11 % over
    Archimedes, measured); with it, within 1 % of rho g W (level - bottom)."""
    from cosim.scene import SPH, Box, Scene, Tank, World
    from cosim.scene.build import build

    depth, width = 3.0, 2.0
    bottom = depth - 0.6 - 0.25 * DX
    s = Scene(name="held", world=World(dim=2, duration=1.0),
              fluid=SPH(dx=DX, rho0=1000.0, setup="waves"),
              domain=Tank(length=12.0, height=depth + 1.0, depth=depth),
              bodies=[Box(name="b", size=[width, 1.0], pos=[6.0, bottom + 0.5], density=500.0)])
    sph = build(s, "/tmp").fluid
    sph.fluid.settle(1.0, tau=0.2)
    archimedes = 1000.0 * 9.81 * width * (depth - bottom)
    assert sph.body_wrenches()[0][0][2] == pytest.approx(archimedes, rel=0.01)
