"""An elastic plate turned about y (``ElasticPlate.angle``) and loaded across its length by
its own weight, without fluid.

References: the Euler-Bernoulli cantilever under a uniform load q, tip deflection ``w = q
L^4 / (8 E I)`` (Timoshenko & Gere 1961, Mechanics of Materials; the chain of N elements
is (1 - 1 / (2 N^2)) of it, :mod:`bodies.elastic`), and its first natural frequency
``f1 = 1.8751^2 / (2 pi) sqrt(E I / (m L^4))``; Greenhill's self-weight buckling (1881)
for the part of gravity along the plate."""

import math

import numpy as np
import pytest

from cosim.scene import ElasticPlate, NoFluid, Scene, World
from cosim.scene.build import buckling_warning, build, self_weight

L, H, RHO, E, G = 0.5, 0.01, 1000.0, 1e9, 9.81  # plate [m], [m], [kg/m^3], [Pa]; 2-D: 1 m wide
EI, Q = E * H**3 / 12.0, RHO * G * H  # [N m^2], its weight per length [N/m]
DT = 1e-3  # sampling [s]


def plate_scene(gravity=G, angle=0.0, E=E, duration=0.8):
    return Scene(world=World(dim=2, duration=duration, gravity=gravity), fluid=NoFluid(),
                 bodies=[ElasticPlate("p", length=L, thickness=H, E=E, density=RHO, base=(0.0, 1.0), angle=angle)])


def tip_history(scene, tmp_path):
    """The tip's displacement (x, z) [m] every DT over the scene's duration, from rest."""
    built = build(scene, tmp_path)
    b, c = built.bodies, built.coupler
    tip = b.site("p_tip")[0]
    x0 = b.site_positions([tip])[0].copy()
    out = []
    for k in range(1, round(scene.world.duration / DT) + 1):
        c.run(k * DT)
        out.append(b.site_positions([tip])[0] - x0)
    return np.array(out)[:, [0, 2]]


def test_a_horizontal_cantilever_sags_and_rings_as_euler_bernoulli_says(tmp_path):
    """Lying along +x (angle 90), undamped, released straight: the tip swings about its
    static sag. Over the whole first-mode periods the mean is the sag (the higher modes'
    shares average out to < 0.1 %), and the up-crossings give f1. At 8 elements: the sag
    within 1.5 % of q L^4 / (8 E I) (measured 0.8 % under, the chain's 1 - 1/(2 N^2)), f1
    within 1 % (measured 0.3 % over); the tip moves along x by (w/L)^2 only."""
    h = tip_history(plate_scene(angle=90.0), tmp_path)
    t = np.arange(1, len(h) + 1) * DT
    z = h[:, 1] - h[:, 1].mean()
    up = np.flatnonzero((z[:-1] < 0) & (z[1:] >= 0))
    tc = t[up] - z[up] / (z[up + 1] - z[up]) * DT
    f1 = (len(tc) - 1) / (tc[-1] - tc[0])
    sag = -h[(t >= tc[0]) & (t < tc[-1]), 1].mean()
    assert len(tc) >= 4
    assert sag == pytest.approx(Q * L**4 / (8 * EI), rel=0.015)
    assert f1 == pytest.approx(1.8751040687**2 / (2 * math.pi) * math.sqrt(EI / (RHO * H * L**4)), rel=0.01)
    assert np.abs(h[:, 0]).max() < 5 * (2 * sag) ** 2 / L


def test_a_standing_plate_under_gravity_along_x_is_the_lying_plate_turned(tmp_path):
    """Turning the plate and gravity together by 90 deg changes nothing: upright under g =
    (9.81, 0) its tip moves along +x as the lying plate's sags along -z, to round-off."""
    lying = tip_history(plate_scene(angle=90.0, duration=0.2), tmp_path / "lying")
    standing = tip_history(plate_scene(gravity=(G, 0.0), duration=0.2), tmp_path / "standing")
    assert np.abs(lying[:, 1]).max() > 0.01  # it moved: 2 w at the first swing
    np.testing.assert_allclose(standing[:, 0], -lying[:, 1], rtol=0, atol=1e-12)
    np.testing.assert_allclose(standing[:, 1], lying[:, 0], rtol=0, atol=1e-12)


def test_buckling_takes_the_part_of_gravity_along_the_plate():
    """Greenhill's factor scales as 1 / (g . e): gravity tilted 60 deg from the plate halves
    its axial load and doubles the factor; a plate lying across gravity, or hanging below
    its clamp, carries no compression and is never warned of."""
    E_cr = Q * L**3 / (7.837347 * (H**3 / 12.0))  # the Young's modulus at Greenhill's load
    upright = plate_scene(E=0.8 * E_cr)
    _, f0, _ = self_weight(upright, upright.bodies[0])
    assert f0 == pytest.approx(0.8, rel=1e-6) and buckling_warning(upright, 0) is not None
    a = math.radians(60.0)
    tilted = plate_scene(gravity=(G * math.sin(a), -G * math.cos(a)), E=0.8 * E_cr)
    P, f60, _ = self_weight(tilted, tilted.bodies[0])
    assert f60 == pytest.approx(2 * f0, rel=1e-9) and P == pytest.approx(0.5 * Q * L, rel=1e-12)
    assert buckling_warning(tilted, 0) is None
    lying = plate_scene(angle=90.0, E=0.8 * E_cr)
    assert self_weight(lying, lying.bodies[0])[1] == math.inf and buckling_warning(lying, 0) is None
    upside_down = plate_scene(angle=180.0, E=0.8 * E_cr)
    P, f, _ = self_weight(upside_down, upside_down.bodies[0])
    assert f == math.inf and P == pytest.approx(Q * L, rel=1e-12)  # hanging: the pull at its clamp
