"""Linear forced sloshing (cosim.validations.forced_sloshing): the reference of the
long-period tanks, checked against independent closed forms and invariants."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from cosim.validations import forced_sloshing as fs
from cosim.validations.sloshing import sloshing_omega, westergaard_series
from cosim.validations.tanks import cylinder_series

G = 9.81


def test_rectangular_frequencies_are_the_refdata_formula():
    m = fs.rectangular_modes(1.0, 0.5, n=3)
    # refdata sloshing_frequencies_housner.csv, rectangular 1.0 x 0.5: 5.31655, 9.61468, 12.41350 rad/s
    assert m.omega == pytest.approx([5.31655, 9.61468, 12.41350], abs=5e-5)
    assert m.omega[0] == pytest.approx(sloshing_omega(1.0, 0.5), rel=1e-12)
    assert fs.housner_omega1("rectangular", 1.0, 0.5) == pytest.approx(5.33876, abs=5e-5)


def test_cylinder_frequencies_are_the_refdata_formula():
    m = fs.cylinder_modes(1.0, 0.5, n=2)
    # refdata: cylindrical R = 1.0, h = 0.5: 3.62163, 7.19708 rad/s; Housner 3.61505
    assert m.omega == pytest.approx([3.62163, 7.19708], abs=5e-5)
    assert fs.housner_omega1("cylinder", 1.0, 0.5) == pytest.approx(3.61505, abs=5e-5)


@pytest.mark.parametrize("shape", ["rectangular", "cylinder"])
def test_modes_expand_x_over_the_surface(shape):
    """sum b_n S_n = x on the free surface (what makes the impulsive pressure vanish there);
    the series converges like 1/n^2 at the wall."""
    m = fs.rectangular_modes(3.0, 1.0, 400) if shape == "rectangular" else fs.cylinder_modes(1.0, 0.6, 400)
    half = 1.5 if shape == "rectangular" else 1.0
    x = np.linspace(-half, half, 41)
    y = None if shape == "rectangular" else np.zeros_like(x)
    got = m.surface_shapes(x, y).T @ m.b
    assert np.abs(got - x).max() < 2e-3 * half
    assert np.abs(got - x)[np.abs(x) < 0.8 * half].max() < 1e-5 * half


def test_impulsive_wall_pressure_is_westergaards_finite_tank_series():
    """An acceleration a held with the surface still (eta = 0): the wall carries the
    impulsive pressure, Westergaard's exact series for a tank of length L
    (cosim.validations.sloshing.westergaard_series), p = rho a H k_p(depth)."""
    L, H = 3.0, 1.0
    m = fs.rectangular_modes(L, H, 2000)
    depth = np.linspace(0.05, 1.0, 20)
    p = fs.pressure(m, np.zeros((m.k.size, 1)), np.array([2.0]), np.full(depth.size, -0.5 * L), -depth)[:, 0]
    kp = (p - 1000.0 * G * depth) / (1000.0 * 2.0 * H)
    assert kp == pytest.approx(westergaard_series(depth, H, L), abs=2e-4)


def test_impulsive_wall_pressure_is_the_cylinder_series():
    R, h = 1.0, 0.6
    m = fs.cylinder_modes(R, h, 2000)
    z = np.linspace(0.03, 0.57, 10)                     # above the bottom
    p = fs.pressure(m, np.zeros((m.k.size, 1)), np.array([1.0]), np.full(z.size, -R), z - h, y=np.zeros(z.size))[:, 0]
    assert (p - 1000.0 * G * (h - z)) / (1000.0 * h) == pytest.approx(cylinder_series(z, h, R), abs=2e-4)


def test_response_solves_the_modal_equation():
    """eta_n'' + w_n^2 eta_n = -(w_n^2 b_n / g) a(t), from rest, a = a0 sin(w t) until
    t_stop and 0 after: the closed form against a numerical integration."""
    m = fs.rectangular_modes(3.0, 1.0, n=3)
    a0, T, t_stop = 0.5 * G, 1.0, 3.0
    t = np.linspace(0.0, 8.0, 801)
    eta, a = fs.response(m, a0, T, t_stop, t)
    w = 2 * math.pi / T
    for n in range(3):
        wn, bn = m.omega[n], m.b[n]

        def rhs(tt, y):
            acc = a0 * math.sin(w * tt) if tt <= t_stop else 0.0
            return [y[1], -wn**2 * y[0] - wn**2 * bn / G * acc]

        sol = solve_ivp(rhs, (0.0, 8.0), [0.0, 0.0], method="DOP853", t_eval=t, rtol=1e-10, atol=1e-12,
                        max_step=0.05)
        assert eta[n] == pytest.approx(sol.y[0], abs=1e-7 * np.abs(sol.y[0]).max())
    assert a[t > t_stop] == pytest.approx(0.0)


def test_quasi_static_limit_tilts_the_surface():
    """A slow excitation (period 100 T_1): the surface follows -a x / g, mass conserved."""
    L, h = 3.0, 1.0
    m = fs.rectangular_modes(L, h, 400)
    T = 100 * 2 * math.pi / m.omega[0]
    t = np.array([0.25 * T])                            # a = a0 there
    eta, a = fs.response(m, 1.0, T, 10 * T, t)
    x = np.linspace(-1.2, 1.2, 13)
    assert fs.surface(m, eta, x)[:, 0] == pytest.approx(-a[0] * x / G, abs=2e-3 * 1.2 / G)
    xs = np.linspace(-0.5 * L, 0.5 * L, 2001)
    assert abs(np.trapezoid(fs.surface(m, eta, xs)[:, 0], xs)) < 1e-12


def test_resonant_excitation_is_refused():
    m = fs.rectangular_modes(3.0, 1.0, n=3)
    with pytest.raises(ValueError, match="natural period"):
        fs.response(m, 1.0, 2 * math.pi / m.omega[0], 3.0, [1.0])


def test_trapezoid_modes_of_a_vertical_tank_are_the_rectangles():
    """The FE modes (tank_potential.sloshing_modes) of the inclined tank at beta = 0: the
    rectangle's frequencies (odd and even modes) to the mesh's second-order error, and the
    forced response (the odd modes: the even ones have b_n = 0) the same."""
    fe = fs.trapezoid_modes(3.0, 1.0, 0.0, n=30, nz=40)
    k = np.arange(1, 9) * math.pi / 3.0
    err = np.abs(fe.omega[:8] / np.sqrt(G * k * np.tanh(k)) - 1)
    assert err.max() < 2e-2 and err[0] < 1e-4
    assert np.all(np.diff(err) > 0)                        # the mesh resolves the long modes best
    assert fe.omega[0] == pytest.approx(sloshing_omega(3.0, 1.0), rel=1e-4)
    assert fe.k[0] == pytest.approx(math.pi / 3.0, rel=1e-4)  # the rectangle's, not omega^2 / g (8 % less)
    assert np.abs(fe.b[1::2]).max() < 1e-10 * np.abs(fe.b).max()           # symmetric modes not excited
    rect = fs.rectangular_modes(3.0, 1.0, 200)
    t = np.linspace(0.0, 6.0, 61)
    x = np.linspace(-1.4, 1.4, 15)
    got = fs.surface(fe, fs.response(fe, 0.05 * G, 1.0, 3.0, t)[0], x)
    ref = fs.surface(rect, fs.response(rect, 0.05 * G, 1.0, 3.0, t)[0], x)
    # 2 %: mode 3 (k = 5 pi / L, 0.02 of the peak) runs 0.2 % fast on this mesh, 0.09 rad by 6 s
    assert np.abs(got - ref).max() < 0.02 * np.abs(ref).max()


def test_depth_wavenumber_solves_the_dispersion_relation():
    """k tanh(k h) = omega^2 / g from deep (k h = 20) to shallow water (k h = 0.01), and the
    two limits: omega^2 / g in deep water, omega / sqrt(g h) in shallow."""
    h = 2.0
    k_true = np.array([10.0, 1.0, 0.3, 0.05, 0.005])
    lam = k_true * np.tanh(k_true * h)
    k = fs.depth_wavenumber(lam, h)
    assert k == pytest.approx(k_true, rel=1e-13)
    assert k[0] == pytest.approx(lam[0], rel=1e-15)
    assert k[-1] == pytest.approx(np.sqrt(lam[-1] / h), rel=1e-4)


def test_trapezoid_impulsive_pressure_is_the_direct_solution():
    """The modes' impulsive pressure (sum b_n psi_n - x, eta = 0) on both sides of the
    45 deg tank equals tank_potential.impulsive_pressure's direct solve on the same mesh."""
    from cosim.validations.tank_potential import wall_profiles

    fe = fs.trapezoid_modes(3.0, 1.0, 45.0, n=60, nz=40)
    z = np.linspace(0.0, 0.9, 10)
    wp = wall_profiles(3.0, 1.0, 45.0, nz=40)
    half = fe.fe["x_mid"]
    sides = {"left": (np.full(z.size, -half), 1.0), "right": (3.0 + z - half, -1.0)}
    for side, (x, sign) in sides.items():
        p = fs.pressure(fe, np.zeros((60, 1)), np.array([1.0]), x, z - 1.0)[:, 0] - 1000.0 * G * (1.0 - z)
        # equal to 4e-5 (60 modes: the truncation shows next to the surface, 1e-8 below 0.8 H)
        assert sign * p / 1000.0 == pytest.approx(np.interp(z, wp["z"], wp[side]), abs=1e-4)
    # the sloped tank sloshes slower than the vertical one (a longer surface, 4 m against 3 m)
    assert fe.omega[0] < 0.8 * fs.rectangular_modes(3.0, 1.0, 1).omega[0]
