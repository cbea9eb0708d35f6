"""The radiation impulse response against a closed-form cosine transform, its checks, and the
wave components against the analytic fluid's Airy wave (no BEM: runs without Capytaine)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.analytic import LinearWave
from fluid.potential.radiation import frequency_response, impulse_response, kernel
from fluid.potential.waves import Excitation, Sea, WaveComponent, from_spectrum, regular, wavenumber


def _gauss_damping(omega, b=2.0e4, s=1.5):
    """B(ω) = b (ω/σ)² exp(−ω²/2σ²) on every diagonal entry; its transform is
    K(t) = b σ sqrt(2/π) (1 − σ²t²) exp(−σ²t²/2) (from ∫_0^∞ e^{−aω²} cos ωt dω =
    ½ sqrt(π/a) e^{−t²/4a}, differentiated twice in t)."""
    B = np.zeros((len(omega), 6, 6))
    for i in range(6):
        B[:, i, i] = b * (omega / s) ** 2 * np.exp(-(omega**2) / (2 * s * s))
    return B


def test_kernel_is_the_cosine_transform_of_the_damping():
    omega = np.linspace(0.01, 12.0, 1200)
    B = _gauss_damping(omega)
    t = np.linspace(0.0, 6.0, 61)
    K = kernel(omega, B, t, taper=1.0)
    b, s = 2.0e4, 1.5
    exact = b * s * math.sqrt(2 / math.pi) * (1 - s * s * t * t) * np.exp(-s * s * t * t / 2)
    assert np.max(np.abs(K[:, 2, 2] - exact)) < 1e-5 * np.abs(exact).max()


def test_impulse_response_rebuilds_added_mass_and_damping():
    """A(ω) from its own Kramers–Kronig pair: with A(ω) = A∞ − (1/ω)∫K sin ωt dt built from the
    exact K, the fitted A∞ is recovered and both rebuild within the band."""
    omega = np.linspace(0.05, 8.0, 160)
    B = _gauss_damping(omega)
    t = np.linspace(0.0, 40.0, 8001)
    b, s = 2.0e4, 1.5
    K = b * s * math.sqrt(2 / math.pi) * (1 - s * s * t * t) * np.exp(-s * s * t * t / 2)
    q = np.full(len(t), t[1] - t[0])
    q[0] = q[-1] = 0.5 * q[0]
    A33 = 3.0e4 - (np.sin(np.outer(omega, t)) * q) @ K / omega
    A = np.zeros_like(B)
    for i in range(6):
        A[:, i, i] = A33
    irf = impulse_response(omega, A, B)
    assert irf.added_mass_inf[2, 2] == pytest.approx(3.0e4, rel=1e-3)  # the taper shifts it a little
    assert irf.error_A < 1e-3 and irf.error_B < 1e-3 and irf.decay <= 0.02
    assert 2.0 < irf.memory < 4.0  # K is below 1 % of its peak after 2.5 s (|1 - σ²t²| e^{-σ²t²/2})
    A2, B2 = frequency_response(irf, omega[omega < 4])
    assert np.allclose(A2[:, 2, 2], A33[omega < 4], rtol=1e-3)


def test_a_frequency_range_too_short_is_refused_with_the_measure():
    omega = np.linspace(0.05, 1.5, 30)  # B is still at its peak at 1.5 rad/s
    B = _gauss_damping(omega)
    A = np.ones_like(B) * np.eye(6)
    with pytest.raises(InputError, match=r"rebuilds the surge (added mass|damping) only within \d+\.\d%"):
        impulse_response(omega, A, B, name="b")


def test_a_memory_beyond_the_resolved_window_is_refused():
    omega = np.linspace(0.5, 8.0, 16)  # Δω = 0.5: K repeats every 4π s
    B = _gauss_damping(omega)
    with pytest.raises(InputError, match="longer than the 6.283 s that the frequency spacing resolves"):
        impulse_response(omega, B, B, memory=10.0)
    omega = np.linspace(0.2, 8.0, 40)
    B = np.zeros((40, 6, 6))
    B[:, 2, 2] = 1e4 * np.exp(-((omega - 1.0) ** 2) / 0.002)  # a sharp resonance rings for ~60 s
    with pytest.raises(InputError, match="still at .* of its peak over the last 10 % of the 15.71 s"):
        impulse_response(omega, B + np.eye(6), B)


def test_sea_matches_the_airy_wave_of_the_analytic_fluid():
    for depth in (math.inf, 8.0):
        lw = LinearWave(H=0.6, T=4.0, depth=depth if math.isfinite(depth) else 1e4, direction=30.0)
        sea = Sea(regular(0.6, 4.0, heading=30.0), depth=depth, g=9.81)
        assert sea.k[0] == pytest.approx(lw.k, rel=1e-9)
        p = np.array([[1.0, 2.0, -0.5], [-3.0, 0.5, -2.0], [0.0, 0.0, 0.0]])
        for t in (0.0, 1.3, 2.9):
            assert np.allclose(sea.elevation(p, t), lw.elevation(p, t), atol=1e-12)
            u, _ = lw.kinematics(p, t)
            assert np.allclose(sea.velocity(p, t), u, atol=1e-9)


def test_excitation_of_one_component_and_its_checks():
    omega = np.array([0.5, 1.0, 1.5])
    X = np.zeros((3, 2, 6), complex)
    X[:, 0, 2] = [1e4, 2e4 * np.exp(0.3j), 3e4]  # heading 0
    X[:, 1, 2] = [1e4, 1e4 * np.exp(-0.2j), 3e4]  # heading 90
    sea = Sea([WaveComponent(1.0, 0.5, phase=0.4, heading=0.0)], depth=math.inf, g=9.81)
    exc = Excitation(sea, omega, [0.0, 90.0], X, position_xy=(3.0, 1.0))
    k = 1.0 / 9.81
    for t in (0.0, 0.7, 5.0):
        expect = (0.5 * np.exp(1j * (0.4 + k * 3.0)) * 2e4 * np.exp(0.3j) * np.exp(-1j * t)).real
        assert exc.force(t)[2] == pytest.approx(expect, rel=1e-12)
    half = Excitation(Sea([WaveComponent(1.0, 1.0, heading=45.0)]), omega, [0.0, 90.0], X, (0.0, 0.0))
    assert half.amplitude[0, 2] == pytest.approx(0.5 * (2e4 * np.exp(0.3j) + 1e4 * np.exp(-0.2j)))
    with pytest.raises(InputError, match="outside the coefficients' frequencies"):
        Excitation(Sea(regular(0.1, 2 * math.pi / 2.0)), omega, [0.0], X[:, :1], (0.0, 0.0))
    with pytest.raises(InputError, match="add it to the headings"):
        Excitation(Sea(regular(0.1, 2 * math.pi, heading=20.0)), omega, [0.0], X[:, :1], (0.0, 0.0))


def test_excitation_of_many_components_is_their_sum():
    """The force of a sea of several components, each with its own frequency, phase and
    heading, is the sum of each one's Re(a e^{i(φ + k x_0 cos β + k y_0 sin β)} X e^{-iωt})."""
    rng = np.random.default_rng(5)
    omega = np.linspace(0.2, 2.0, 10)
    X = rng.standard_normal((10, 2, 6)) + 1j * rng.standard_normal((10, 2, 6))
    comps = [WaveComponent(w, a, p, h) for w, a, p, h in zip(rng.uniform(0.3, 1.9, 40), rng.uniform(0, 0.3, 40),
                                                               rng.uniform(0, 6.3, 40), rng.choice([0.0, 90.0], 40))]
    sea = Sea(comps, depth=12.0, g=9.81)
    x0 = np.array([2.0, -1.0])
    exc = Excitation(sea, omega, [0.0, 90.0], X, x0)
    for t in (0.3, 17.0):
        expect = np.zeros(6)
        for c in comps:
            j = 0 if c.heading == 0.0 else 1
            Xc = np.array([np.interp(c.omega, omega, X[:, j, i].real) + 1j * np.interp(c.omega, omega, X[:, j, i].imag)
                           for i in range(6)])
            k = wavenumber(c.omega, 12.0, 9.81)
            b = math.radians(c.heading)
            ph = c.phase + k * (x0[0] * math.cos(b) + x0[1] * math.sin(b))
            expect += (c.amplitude * np.exp(1j * ph) * Xc * np.exp(-1j * c.omega * t)).real
        assert np.allclose(exc.force(t), expect, rtol=1e-12, atol=1e-12)


def test_spectrum_components_carry_its_variance():
    w = np.linspace(0.2, 2.0, 200)
    S = np.exp(-((w - 0.8) ** 2) / 0.02)
    comps = from_spectrum(w, S, seed=3)
    m0 = np.trapezoid(S, w)
    assert sum(c.amplitude**2 / 2 for c in comps) == pytest.approx(m0, rel=0.01)
    assert wavenumber(1.0, 5.0, 9.81) * math.tanh(wavenumber(1.0, 5.0, 9.81) * 5.0) == pytest.approx(1 / 9.81)
