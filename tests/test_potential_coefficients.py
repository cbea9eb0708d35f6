"""The potential-flow coefficients: hulls, hydrostatics against closed forms, the cache, and
the BEM's low-frequency limits (coarse meshes: each solve takes about a second)."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("capytaine")
pytest.importorskip("h5netcdf")

from cosim.errors import InputError  # noqa: E402
from fluid.potential import compute, wetted_hull  # noqa: E402
from fluid.potential.hull import displaced_volume  # noqa: E402

RHO, G = 1000.0, 9.81


def _ngon_area(r, n):
    return 0.5 * n * r * r * math.sin(2 * math.pi / n)


def test_upright_cylinder_hull_is_the_prism_below_the_waterline():
    # a cylinder 3 m long, its centre 0.3 m above the water: draft 1.2 m
    h = wetted_hull("cylinder", [1.0, 1.5], np.eye(3), [0.0, 0.0, 0.3], 0.25)
    v = h.vertices
    assert h.draft == pytest.approx(1.2)
    assert v[:, 2].min() == pytest.approx(-1.2) and v[:, 2].max() == pytest.approx(0.0, abs=1e-12)
    import capytaine as cpt

    mesh = cpt.Mesh(vertices=h.vertices, faces=h.faces)
    n = 26  # panels round the circumference: ceil(2 pi / 0.25)
    assert mesh.volume == pytest.approx(_ngon_area(1.0, n) * 1.2, rel=1e-9)  # outward normals, closed by z = 0
    assert mesh.waterplane_area == pytest.approx(_ngon_area(1.0, n), rel=1e-9)
    assert (mesh.faces_centers[:, 2] < 0).all()  # nothing on the free surface
    assert displaced_volume("cylinder", [1.0, 1.5], np.eye(3), 0.3) == pytest.approx(math.pi * 1.2)


def test_dry_and_submerged_bodies_are_refused():
    with pytest.raises(InputError, match="dry"):
        wetted_hull("box", [1, 1, 0.5], np.eye(3), [0, 0, 0.6], 0.5)
    with pytest.raises(InputError, match="fully submerged"):
        wetted_hull("sphere", [1.0], np.eye(3), [0, 0, -1.2], 0.5)
    with pytest.raises(InputError, match="panel_size"):
        wetted_hull("box", [1, 1, 0.5], np.eye(3), [0, 0, 0.0], 0.0)


def test_box_hydrostatics_are_exact(tmp_path):
    """A 4 m x 2 m box drawing 1 m, centre of mass 0.2 m above the water: V = 8 m^3,
    C33 = rho g L B, C44 = rho g (L B^3/12 + V (z_B - z_G)), C55 = rho g (B L^3/12 + V (z_B - z_G))
    (Newman 1977 Eq. 6.186 about the centre of mass, buoyancy only)."""
    h = wetted_hull("box", [2.0, 1.0, 0.6], np.eye(3), [0.0, 0.0, -0.4], 0.5)
    zg = 0.2
    c = compute(h, zg, omega=[0.5, 1.0], depth=math.inf, rho=RHO, g=G, cache=tmp_path)
    V, zb = 8.0, -0.5
    assert c.volume == pytest.approx(V, rel=1e-9)
    assert c.centre_of_buoyancy[2] == pytest.approx(zb, rel=1e-9)
    C = c.stiffness
    assert C[2, 2] == pytest.approx(RHO * G * 8.0, rel=1e-9)
    assert C[3, 3] == pytest.approx(RHO * G * (4 * 8 / 12 + V * (zb - zg)), rel=1e-9)
    assert C[4, 4] == pytest.approx(RHO * G * (2 * 64 / 12 + V * (zb - zg)), rel=1e-9)
    assert np.abs(C[:2]).max() == 0 and np.abs(C[:, :2]).max() == 0  # no horizontal restoring
    for M in (c.added_mass, c.damping):  # symmetric, positive on the diagonal
        assert np.allclose(M, np.swapaxes(M, 1, 2))
        assert (np.einsum("wii->wi", M)[:, :5] > 0).all()


@pytest.mark.long
def test_cache_hit_and_keys(tmp_path):
    h = wetted_hull("cylinder", [1.0, 1.0], np.eye(3), [0.0, 0.0, 0.0], 0.5)
    args = dict(omega=[0.5, 1.0, 1.5], headings=[0.0], rho=RHO, g=G, cache=tmp_path)
    a = compute(h, 0.0, **args)
    assert not a.meta["from_cache"] and len(list(tmp_path.glob("*.nc"))) == 1
    b = compute(h, 0.0, **args)
    assert b.meta["from_cache"] and b.key == a.key
    for f in ("added_mass", "damping", "added_mass_inf", "excitation", "stiffness"):
        assert np.array_equal(getattr(a, f), getattr(b, f)), f
    c = compute(h, 0.0, **{**args, "omega": [0.5, 1.0, 1.6]})  # another input, another entry
    d = compute(h, 0.0, depth=10.0, **args)
    assert len({a.key, c.key, d.key}) == 3 and len(list(tmp_path.glob("*.nc"))) == 3
    assert not d.meta["from_cache"] and not np.allclose(d.added_mass, a.added_mass)


def test_low_frequency_heave_excitation_is_the_hydrostatic_force(tmp_path):
    """As ω -> 0 the wave is a slow rise of the surface: X3 -> rho g A_wp (Newman 1977 §6.18)."""
    h = wetted_hull("cylinder", [1.0, 1.0], np.eye(3), [0.0, 0.0, 0.0], 0.35)
    c = compute(h, 0.0, omega=[0.05, 0.1], rho=RHO, g=G, cache=tmp_path)
    assert abs(c.excitation[0, 0, 2]) == pytest.approx(c.stiffness[2, 2], rel=0.01)


def test_excitation_phase_follows_the_wave_crest(tmp_path):
    """Capytaine's X is for a crest at the origin at t = 0 (η = Re e^{i(kx - ωt)}): the same
    hull moved 2 m along the wave sees X e^{i k 2} (what fluid.potential.waves relies on)."""
    import capytaine as cpt

    from fluid.potential.coefficients import DOFS

    h = wetted_hull("box", [0.5, 0.5, 0.5], np.eye(3), [0.0, 0.0, 0.0], 0.5)
    res = []
    for x0 in (0.0, 2.0):
        mesh = cpt.Mesh(vertices=h.vertices + [x0, 0.0, 0.0], faces=h.faces)
        body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(only=["Heave"], rotation_center=(x0, 0, 0)))
        pb = cpt.DiffractionProblem(body=body, omega=1.5, wave_direction=0.0, rho=RHO, g=G)
        res.append(cpt.BEMSolver().solve(pb).forces["Heave"])
    assert DOFS[2] == "Heave"
    k = 1.5**2 / G
    assert res[1] == pytest.approx(res[0] * np.exp(1j * k * 2.0), rel=1e-6)
