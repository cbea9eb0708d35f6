"""Boundary particles sampled from geoms and placed from the body pose."""

import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from bodies import builders
from bodies.mujoco_bodies import MujocoBodies
from bodies.sampling import GeomShape, cross, disc_rings, ghost_offsets, place, sample_geoms, signed_distance
from cosim.errors import InputError
from fluid.analytic import geom_volume

I3 = np.eye(3)


def test_box_band_has_the_lattice_count_and_depth():
    g = GeomShape("box", np.array([0.5, 0.3, 0.2]), np.zeros(3), I3)
    dx, layers = 0.05, 2
    p, owner = sample_geoms([g], dx, layers)
    n = (20, 12, 8)  # cells along each axis
    inner = (20 - 4, 12 - 4, 8 - 4)
    assert len(p) == np.prod(n) - np.prod(inner)
    sd = signed_distance("box", g.size, p)
    assert sd.max() == pytest.approx(-dx / 2) and sd.min() == pytest.approx(-1.5 * dx)
    assert (owner == 0).all()


@pytest.mark.parametrize("kind, size", [("sphere", [0.3]), ("cylinder", [0.2, 0.4]), ("capsule", [0.15, 0.3]),
                                        ("ellipsoid", [0.3, 0.2, 0.25])])
def test_curved_geoms_fill_a_band_inside_the_surface(kind, size):
    size = np.array(size + [0.0] * (3 - len(size)))
    dx, layers = 0.02, 3
    p, _ = sample_geoms([GeomShape(kind, size, np.zeros(3), I3)], dx, layers)
    sd = signed_distance(kind, size, p)
    assert len(p) > 100 and sd.max() <= 0 and sd.min() > -layers * dx
    # the band is full: its volume over dx^3 matches the particle count within 10 %
    if kind == "sphere":
        r = size[0]
        band = 4 / 3 * math.pi * (r**3 - (r - layers * dx) ** 3)
        assert len(p) == pytest.approx(band / dx**3, rel=0.1)


@pytest.mark.parametrize("r_over_dx", np.linspace(2.4, 25.0, 227))
def test_a_discs_rings_hold_its_area_spaced_and_mirrored(r_over_dx):
    """disc_rings: round(pi R^2 / dx^2) points (within half a point of the area), none
    closer than 0.69 dx nor a nearest neighbour farther than 1.11 dx (the spacings the
    rings take between R/dx = 2.4 and 25), symmetric about y = 0; the square lattice
    misses the area by up to 18 % over the same range (+17.7 % at R/dx = 3.75)."""
    dx = 0.1
    R = r_over_dx * dx
    p = disc_rings(R, dx)
    assert len(p) == round(math.pi * R**2 / dx**2)
    assert abs(len(p) * dx**2 / (math.pi * R**2) - 1.0) <= 0.5 / (math.pi * r_over_dx**2) + 1e-12
    r = np.hypot(p[:, 0], p[:, 1])
    assert r.max() < R and r.max() == pytest.approx(R - 0.5 * R / round(R / dx))
    tree = cKDTree(p)
    nearest = tree.query(p, 2)[0][:, 1]
    assert 0.69 * dx < nearest.min() and nearest.max() < 1.11 * dx
    assert tree.query(p * [1.0, -1.0])[0].max() < 1e-12


def test_a_cylinders_layers_are_its_discs_rings_full_at_the_caps_a_band_between():
    """A 3-D cylinder (R/dx = 3.75, where the lattice's section is 17.7 % too large) laid in
    rings: every layer along its axis on the lattice's planes; its two cap layers (3 layers
    each) the whole disc, the layers between only the three outer rings; every particle
    inside the surface and less than 3 dx deep."""
    R, half, dx, layers = 0.3, 0.4, 0.08, 3
    p, _ = sample_geoms([GeomShape("cylinder", np.array([R, half, 0.0]), np.zeros(3), I3)], dx, layers)
    disc = disc_rings(R, dx)
    zs = np.unique(np.round(p[:, 2], 12))
    assert len(zs) == 10 and np.allclose(np.diff(zs), 2 * half / 10)
    counts = [int((np.abs(p[:, 2] - z) < 1e-9).sum()) for z in zs]
    rings_r = np.unique(np.round(np.hypot(disc[:, 0], disc[:, 1]), 12))[::-1]
    band = int((np.hypot(disc[:, 0], disc[:, 1]) > rings_r[layers] + 1e-9).sum())
    assert counts == [len(disc)] * 3 + [band] * 4 + [len(disc)] * 3
    assert len(disc) * dx**2 == pytest.approx(math.pi * R**2, rel=0.01)
    sd = signed_distance("cylinder", np.array([R, half]), p)
    assert sd.max() < 0 and sd.min() > -layers * dx


@pytest.mark.parametrize("r_over_dx", [0.76, 0.8, 0.88, 0.9, 1.0, 1.2])
def test_a_thin_cylinder_has_two_particles_across_its_section_each_way(r_over_dx):
    """A cylinder 1.5-2.4 spacings across (what SPHFluid.MIN_PARTICLES_ACROSS admits) has at
    least two distinct coordinates along each axis of its section: below R = dx, where rings
    would lay two points on one line through the axis, it keeps the lattice's 2 x 2."""
    dx = 0.1
    p, _ = sample_geoms([GeomShape("cylinder", np.array([r_over_dx * dx, 0.3, 0.0]), np.zeros(3), I3)], dx, 3)
    layer = p[np.abs(p[:, 2] - p[:, 2].min()) < 1e-9]
    assert min(np.unique(np.round(layer[:, k], 9)).size for k in (0, 1)) >= 2


def test_planar_sections_of_a_box_and_an_end_on_cylinder():
    dx = 0.05
    b = MujocoBodies(builders.scene(builders.box("box", (1.0, 0.5), (0, 0, 0), mass=1.0, planar=True),
                                    builders.cylinder("cyl", 0.5, 1.0, (3, 0, 0), mass=1.0, planar=True)))
    p, owner = b.boundary_particles(dx, 3, dim=2)
    assert (p[:, 1] == 0).all()
    box = p[owner == 0]
    assert len(box) == 20 * 10 - 14 * 4  # a 3-layer rectangle ring
    cyl = p[owner == 1]
    r = np.hypot(cyl[:, 0], cyl[:, 2])
    assert r.max() < 0.5 and r.min() > 0.5 - 3 * dx
    band = math.pi * (0.5**2 - (0.5 - 3 * dx) ** 2)
    assert len(cyl) == pytest.approx(band / dx**2, rel=0.05)


def test_placement_is_rigid_and_velocities_follow_eq13():
    xml = builders.scene(builders.box("b", (1.0, 0.6, 0.4), (0.5, -0.2, 1.0), density=700.0, euler=(10, 20, 30)),
                         gravity=0.0)
    b = MujocoBodies(xml)
    b.data.qvel[:] = [0.3, -0.1, 0.2, 0.7, -0.4, 0.5]
    b.initialize(0.0)
    pb, owner = b.boundary_particles(0.05, 2)
    x0, u0 = place(pb, owner, b.kinematics())
    dt = 1e-6
    b.advance(0.0, dt)
    x1, _ = place(pb, owner, b.kinematics())
    np.testing.assert_allclose((x1 - x0) / dt, u0, atol=1e-5)
    d0 = np.linalg.norm(x0[::37] - x0[0], axis=1)
    d1 = np.linalg.norm(x1[::37] - x1[0], axis=1)
    np.testing.assert_allclose(d1, d0, atol=1e-12)  # rigid: no drift, no stretch


def test_the_row_wise_cross_product_is_numpys_bit_for_bit():
    """``cross`` replaces ``np.cross`` in the coupler's per-step moments: the same bits,
    one row or many, broadcast against one row, antisymmetric, orthogonal to both."""
    rng = np.random.default_rng(7)
    for n in (1, 3, 500):
        a, b = rng.normal(size=(n, 3)) * 10.0 ** rng.integers(-6, 6, (n, 1)), rng.normal(size=(n, 3))
        assert np.array_equal(cross(a, b), np.cross(a, b))
        assert np.array_equal(cross(a[:1], b), np.cross(a[:1], b))
        assert np.array_equal(cross(b, a), -cross(a, b))
        c = cross(a, b)
        assert np.abs(np.einsum("ij,ij->i", c, a)).max() <= 1e-12 * (np.abs(a).max() ** 2 * np.abs(b).max())


def test_sampling_errors():
    g = GeomShape("box", np.array([0.5, 0.5, 0.5]), np.zeros(3), I3)
    with pytest.raises(InputError, match="dx must be"):
        sample_geoms([g], 0.0, 2)
    with pytest.raises(InputError, match="layers must be"):
        sample_geoms([g], 0.1, 0)
    tilted = GeomShape("box", np.array([0.5, 0.5, 0.5]), np.zeros(3),
                       np.array([[1, 0, 0], [0, math.cos(0.3), -math.sin(0.3)], [0, math.sin(0.3), math.cos(0.3)]]))
    with pytest.raises(InputError, match="no axis along y"):
        sample_geoms([tilted], 0.1, 2, dim=2)



def test_very_coarse_and_very_thin_bodies_still_get_particles():
    b = MujocoBodies(builders.scene(builders.box("coarse", (0.3, 0.3), (0, 0, 0), mass=1.0, planar=True),
                                    builders.box("plate", (1.0, 0.01), (2, 0, 0), mass=1.0, planar=True)))
    p, owner = b.boundary_particles(0.1, 2, dim=2)
    assert (owner == 0).sum() == 9  # 3 particles across, all within two layers
    plate = p[owner == 1]
    assert len(plate) == 10 and np.allclose(plate[:, 2], 0.0)  # one row along the mid-line


def _mesh_scene(vertex: str, face: str = "", body_pos: str = "0 0 0") -> str:
    face = f' face="{face}"' if face else ""
    return (f'<mujoco><asset><mesh name="m" vertex="{vertex}"{face}/></asset><worldbody>'
            f'<body name="hull" pos="{body_pos}"><freejoint/><geom type="mesh" mesh="m" mass="1"/></body>'
            f'<body name="box" pos="{body_pos}"><freejoint/><geom type="box" size="0.2 0.1 0.15" pos="0.2 0 0.15" '
            f'mass="1"/></body></worldbody></mujoco>')


#: the corners of the box [0, 0.4] x [-0.1, 0.1] x [0, 0.3] (MuJoCo builds the faces: convex hull)
BOX_CORNERS = ("0 -0.1 0  0.4 -0.1 0  0.4 0.1 0  0 0.1 0  0 -0.1 0.3  0.4 -0.1 0.3  0.4 0.1 0.3  "
               "0 0.1 0.3")


@pytest.mark.parametrize("dim", [3, 2])
def test_a_mesh_box_samples_as_the_box_geom(dim):
    """A mesh of the box's 8 corners (off-centre: MuJoCo moves it to its centre of mass
    and principal axes, here a permutation of x, y, z) gives the box geom's particles:
    same count, same body-frame positions (to the float32 of MuJoCo's vertices), and the
    same signed distance at points in and around it. In 2-D the section by the body's
    y = 0 plane leaves out the faces normal to y, as for the box."""
    b = MujocoBodies(_mesh_scene(BOX_CORNERS))
    mesh_g, box_g = b.geoms()[0][0], b.geoms()[1][0]
    assert mesh_g.kind == "mesh" and len(mesh_g.mesh[1]) == 12
    assert geom_volume("mesh", None, mesh_g.mesh) == pytest.approx(0.4 * 0.2 * 0.3, rel=1e-6)  # the added-mass volume
    p, owner = b.boundary_particles(0.02, 3, dim=dim)
    pm, pb = p[owner == 0], p[owner == 1]
    assert len(pm) == len(pb) == (2496 if dim == 3 else 20 * 15 - 14 * 9)
    np.testing.assert_allclose(pm[np.lexsort(pm.T)], pb[np.lexsort(pb.T)], atol=1e-6)
    q = np.random.default_rng(0).uniform(-0.3, 0.3, (500, 3))  # body frame, around the box's centre
    qb = q + box_g.pos
    sd_mesh = signed_distance("mesh", None, (qb - mesh_g.pos) @ mesh_g.rot, mesh_g.mesh)
    np.testing.assert_allclose(sd_mesh, signed_distance("box", box_g.size, q), atol=1e-6)


def test_a_convex_polyhedron_mesh_fills_its_volume_and_its_band():
    """The octahedron |x| + |y| + |z| <= r (6 vertices, MuJoCo's convex hull: 8 faces),
    volume 4/3 r^3. Filled (layers enough to reach its centre) the particles times dx^3
    give that volume within 1 % (measured -0.4 %); in 3 layers they fill the band between
    the surface and the octahedron set in by 3 dx, |x| + |y| + |z| <= r - 3 sqrt(3) dx,
    within 5 % (measured -2.6 %), every particle inside the surface and less than 3 dx deep."""
    r, dx = 0.3, 0.02
    verts = f"{r} 0 0  -{r} 0 0  0 {r} 0  0 -{r} 0  0 0 {r}  0 0 -{r}"
    g = MujocoBodies(_mesh_scene(verts)).geoms()[0][0]
    assert len(g.mesh[1]) == 8 and geom_volume("mesh", None, g.mesh) == pytest.approx(4 / 3 * r**3, rel=1e-6)
    full, _ = sample_geoms([g], dx, 100)
    assert len(full) * dx**3 == pytest.approx(4 / 3 * r**3, rel=0.01)
    band, _ = sample_geoms([g], dx, 3)
    inset = r - 3 * math.sqrt(3) * dx
    assert len(band) * dx**3 == pytest.approx(4 / 3 * (r**3 - inset**3), rel=0.05)
    sd = signed_distance("mesh", None, (band - g.pos) @ g.rot, g.mesh)
    assert sd.max() < 0 and sd.min() > -3 * dx
    np.testing.assert_allclose(sd, (np.abs((band - g.pos) @ g.rot).sum(axis=1) - r) / math.sqrt(3), atol=1e-6)


def test_an_open_or_misoriented_mesh_is_refused():
    tetra = "0 0 0  1 0 0  0 1 0  0 0 1"
    closed = MujocoBodies(_mesh_scene(tetra, "0 2 1  0 1 3  0 3 2  1 2 3"))
    assert len(closed.boundary_particles(0.1, 2)[0]) > 0
    open_ = MujocoBodies(_mesh_scene(tetra, "0 2 1  0 1 3  0 3 2"))  # MuJoCo compiles it
    with pytest.raises(InputError, match=r"body 'hull' geom 0 \(mesh 'm'\) is not a closed surface"):
        open_.boundary_particles(0.1, 2)
    g = GeomShape("mesh", None, np.zeros(3), I3, (np.eye(4, 3), np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 3, 2]])))
    with pytest.raises(InputError, match="not consistently oriented"):
        sample_geoms([g], 0.1, 2)


def test_mesh_ghosts_mirror_across_the_nearest_face_and_bisect_ties():
    """mDBC ghost nodes of a mesh box: across the nearest face as the box geom's; on an
    edge's or a corner's diagonal along the bisector, 2 d from the particle (the box geom
    mirrors through the edge or corner instead; see ghost_offsets)."""
    b = MujocoBodies(_mesh_scene(BOX_CORNERS))
    mesh, box = b.geoms()[0], b.geoms()[1]
    p, owner = b.boundary_particles(0.02, 3)
    pm = p[owner == 0]
    gm, gb = ghost_offsets(mesh, pm), ghost_offsets(box, pm)
    depth = -signed_distance("box", box[0].size, pm - box[0].pos)
    q = np.sort(box[0].size - np.abs(pm - box[0].pos), axis=1)  # depths below the three faces, nearest first
    one = q[:, 1] - q[:, 0] > 1e-6  # a single nearest face (ties to float32 round-off of the vertices)
    np.testing.assert_allclose(gm[one], gb[one], atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(gm, axis=1), 2 * depth, atol=1e-6)
    tie = ~one
    assert tie.sum() > 0
    np.testing.assert_allclose(np.abs(gm[tie]).max(axis=1), 2 * depth[tie] / np.sqrt(2 + (q[tie, 2] - q[tie, 0] < 1e-6)),
                               rtol=0.01)  # the finite-difference gradient splits float32-broken ties unevenly
