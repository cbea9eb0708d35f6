"""Polygon, inclined-tank and cylinder builders (fluid.shapes): fluid volumes against the
exact areas and volumes, wall layer spacing, no overlaps, the inclined wall's angle."""

import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from cosim.errors import InputError
from fluid import shapes
from fluid.geometry import set_hydrostatic
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig


def _split(b):
    ps = b.particles
    fl = ps.kind == Kind.FLUID
    return ps.pos[fl], ps.pos[~fl]


def _dist_to_segments(p, v, closed=True):
    """Distance of points p (N, 2) to the polyline v."""
    ends = np.vstack([v, v[:1]]) if closed else v
    d = np.full(len(p), np.inf)
    for a, b in zip(ends[:-1], ends[1:]):
        t = np.clip(((p - a) @ (b - a)) / ((b - a) @ (b - a)), 0, 1)
        d = np.minimum(d, np.linalg.norm(p - (a + t[:, None] * (b - a)), axis=1))
    return d


def test_area_and_inside():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    assert shapes.signed_area(sq) == 1.0 and shapes.signed_area(sq[::-1]) == -1.0
    pts = np.array([[0.5, 0.5], [1.5, 0.5], [0.5, -0.1]])
    np.testing.assert_array_equal(shapes.inside_polygon(pts, sq), [True, False, False])
    with pytest.raises(InputError, match="vertices"):
        shapes.signed_area([[0, 0], [1, 0]])
    with pytest.raises(InputError, match="repeated"):
        shapes.polygon_fluid([[0, 0], [1, 0], [1, 0], [0, 1]], 0.1)


def test_polygon_fluid_volume():
    # a triangle (area 0.5 m^2) and a regular hexagon off the lattice: the lattice count
    # times dx^2 misses the area by less than half a spacing round the perimeter
    dx = 0.01
    tri = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    hexa = 0.3 * np.array([[math.cos(a), math.sin(a)] for a in np.arange(6) * math.pi / 3]) + 0.0123
    for poly, perim in ((tri, 2 + math.sqrt(2)), (hexa, 6 * 0.3)):
        area = abs(shapes.signed_area(poly))
        pts = shapes.polygon_fluid(poly, dx)
        assert abs(len(pts) * dx**2 - area) < 0.5 * perim * dx
        assert shapes.inside_polygon(pts, poly).all()


@pytest.mark.parametrize("outside", [True, False])
def test_closed_wall_layers_lie_at_half_spacings(outside):
    # a square container (wall outside) or obstacle (wall inside), given in either
    # orientation: layer k is the square offset by (k + 1/2) dx to the chosen side (mitred
    # corners: a square again, so its max-norm distance from the centre is exact), sampled
    # at spacing dx with a point on every corner
    dx, layers = 0.02, 3
    sq = np.array([[0, 0], [0.4, 0], [0.4, 0.4], [0, 0.4]], float)
    w = shapes.polyline_wall(sq[::-1] if outside else sq, dx, layers, closed=True, outside=outside)
    off = np.abs(w - 0.2).max(axis=1) - 0.2  # signed offset from the square's edges
    assert ((off > 0) == outside).all()
    k = np.abs(off) / dx - 0.5
    np.testing.assert_allclose(k, np.round(k), atol=1e-9)
    assert set(np.round(k).astype(int)) == set(range(layers))
    for kk in range(layers):  # the side of layer k: 0.4 +- (2k + 1) dx, / dx points per side
        side = 0.4 + (1 if outside else -1) * (2 * kk + 1) * dx
        assert (np.round(k) == kk).sum() == 4 * round(side / dx)
    nn = cKDTree(w).query(w, k=2)[0][:, 1]
    np.testing.assert_allclose(nn, dx, rtol=1e-9)


def test_polygon_tank_removes_and_counts_overlaps():
    # a trapezoid container off the lattice: fluid inside the outline, none within 0.9 dx
    # of the wall, the removed particles counted, the fluid area within a spacing of exact
    dx = 0.01
    poly = np.array([[0.003, 0.002], [0.5, 0.002], [0.7, 0.3], [0.003, 0.3]])
    b = shapes.polygon_tank(poly, dx, fill_level=0.2, conform_layers=0)
    f, w = _split(b)
    assert b.removed_overlap > 0
    assert len(f) + b.removed_overlap == (shapes.polygon_fluid(poly, dx)[:, 1] < 0.2).sum()
    assert cKDTree(w).query(f)[0].min() >= 0.9 * dx
    exact = 0.198 * (0.497 + 0.497 + 0.198 * 0.2 / 0.298) / 2
    perim = 2 * 0.198 + 0.497 + 0.497 + 0.198 / 0.298 * 0.2
    assert abs(len(f) * dx**2 - exact) < perim * dx


@pytest.mark.parametrize("angle", [15.0, 30.0, 45.0])
def test_inclined_tank_2d(angle):
    # Sunara et al. 2021, §3.2 at 5 cm (the paper's spacing): the first wall layer of the inclined side lies
    # on a line at `angle` from the vertical, dx/2 outside the face; the water is the
    # trapezoid 3 m long at the bottom and 1 m deep
    dx = 0.05
    b = shapes.inclined_tank(2, dx, angle)
    f, w = _split(b)
    t = math.tan(math.radians(angle))
    face = np.array([[3.0, 0.0], [3.0 + 1.5 * t, 1.5]])
    d = _dist_to_segments(w, face, closed=False)
    first = w[(np.abs(d - 0.5 * dx) < 1e-9) & (w[:, 1] > 0.1) & (w[:, 1] < 1.4)]
    slope = np.polyfit(first[:, 1], first[:, 0], 1)[0]  # dx/dz of the layer
    assert math.degrees(math.atan(slope)) == pytest.approx(angle, abs=1e-9)
    # the layer is outside the water, to the right of the face
    assert (first[:, 0] > 3.0 + first[:, 1] * t).all()
    exact = 1.0 * (3.0 + 0.5 * t)
    assert abs(len(f) * dx**2 - exact) < (3 + 2 / math.cos(math.radians(angle))) * 0.5 * dx
    assert cKDTree(w).query(f)[0].min() >= 0.9 * dx
    assert f[:, 1].max() < 1.0 and f[:, 0].min() > 0
    # the conforming fluid layer: next to the face (away from its ends) the fluid lies
    # dx/2 inside it, i.e. dx from the first wall layer, where the lattice fill leaves
    # 1.0-1.3 dx; the lattice behind it starts dx from the face
    d_f = _dist_to_segments(f, face, closed=False)
    mid = (f[:, 1] > 0.1) & (f[:, 1] < 0.9)
    np.testing.assert_allclose(np.sort(d_f[mid & (d_f < 0.9 * dx)]), 0.5 * dx, atol=1e-9)
    assert (d_f[mid & (d_f > 0.9 * dx)] >= dx - 1e-9).all()
    # and the water area is closer to the trapezoid's than the lattice fill's
    lat, _ = _split(shapes.inclined_tank(2, dx, angle, conform_layers=0))
    assert abs(len(f) * dx**2 - exact) < abs(len(lat) * dx**2 - exact)


def test_inclined_tank_3d_is_the_extruded_section():
    dx = 0.1
    b3 = shapes.inclined_tank(3, dx, 30.0)
    f3, w3 = _split(b3)
    f2, _ = _split(shapes.inclined_tank(2, dx, 30.0))
    assert len(f3) == len(f2) * 10  # 1.0 m wide / 0.1 m
    assert cKDTree(w3).query(f3)[0].min() >= 0.9 * dx
    # walls front and back enclose the water along y: none escapes in a straight line
    assert (w3[:, 1] < 0).any() and (w3[:, 1] > 1.0).any()
    # no wall particles closer together than the water's own (its conforming layer meets
    # the lattice as close as 0.73 dx at 30 deg, and the front and back walls hold it)
    gap = lambda p: cKDTree(p).query(p, k=2)[0][:, 1].min()
    assert gap(w3) >= min(0.9 * dx, gap(f3)) - 1e-9
    # every front and back wall layer holds the water's (x, z) points (its conforming layer
    # along the slope included) and the side walls' section: the same points as each row
    # of water with its side walls, so the rows next to those walls are balanced as the
    # middle ones (a lattice section there is a staircase beside the conforming layer)
    row = np.round(f3[np.isclose(f3[:, 1], 0.5 * dx)][:, [0, 2]] / dx, 6)
    side = np.round(w3[np.isclose(w3[:, 1], 0.5 * dx)][:, [0, 2]] / dx, 6)
    wet = {tuple(p) for p in np.vstack([row, side])}
    for y in (-0.5 * dx, -2.5 * dx, 1.0 + 0.5 * dx, 1.0 + 2.5 * dx):
        layer = np.round(w3[np.isclose(w3[:, 1], y)][:, [0, 2]] / dx, 6)
        below = {tuple(p) for p in layer if p[1] * dx < 1.0}
        assert below == {p for p in wet if p[1] * dx < 1.0}


def test_cylinder_tank():
    # Sunara et al. 2021, §3.3: D = 2 m, water 0.6 m, at dx = 5 cm: equal-volume rings give the exact water
    # volume pi R^2 h to the rounding of the ring counts; the first shell lies dx/2 outside
    # R; spacing ~dx everywhere; no fluid within 0.9 dx of the wall
    dx = 0.05
    b = shapes.cylinder_tank(dx)
    f, w = _split(b)
    assert b.removed_overlap == 0
    V = math.pi * 1.0**2 * 0.6
    assert len(f) * dx**3 == pytest.approx(V, rel=2e-3)
    r_w = np.hypot(w[:, 0], w[:, 1])
    side = w[:, 2] > 0
    np.testing.assert_allclose(np.unique(np.round(r_w[side], 9)), 1.0 + dx * (0.5 + np.arange(3)))
    assert np.hypot(f[:, 0], f[:, 1]).max() == pytest.approx(1.0 - 0.5 * dx)
    assert cKDTree(w).query(f)[0].min() >= 0.9 * dx
    nn = cKDTree(f).query(f, k=2)[0][:, 1]
    assert nn.min() > 0.85 * dx and np.median(nn) == pytest.approx(dx, rel=0.01)
    assert f[:, 2].max() < 0.6 and w[:, 2].max() < 1.0


@pytest.mark.long
def test_inclined_tank_at_rest_keeps_its_particles_in_place():
    # 2-D, 45 deg, 0.4 m long, 0.2 m deep, dx = 0.02 m, 1 s at rest with the solver's
    # defaults: with the conforming fluid layer no particle moves by more than 2 dx
    # (measured 1.2 dx; the pure lattice fill, which leaves a 0-0.3 dx gap along the
    # slope, lets the fluid slump into it: 4.9 dx by 1 s)
    g, H, dx = 9.81, 0.2, 0.02
    b = shapes.inclined_tank(2, dx, 45.0, length=0.4, depth=H, height=0.25)
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(g * H), c0_factor=20.0)
    ps = b.particles
    set_hydrostatic(ps, H, 1000.0, cfg.speed_of_sound, cfg.gamma, g)
    f = Fluid(cfg, ps)
    f.initialize(0.0)

    def fluid_by_id():
        fl = f.ps.kind == Kind.FLUID
        return f.ps.pos[fl][np.argsort(f.ps.ids[fl])]

    x0 = fluid_by_id()
    f.advance(0.0, 1.0)
    assert np.linalg.norm(fluid_by_id() - x0, axis=1).max() < 2 * dx
