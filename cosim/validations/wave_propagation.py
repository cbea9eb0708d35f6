"""Regular waves over many wavelengths of an SPH flume: how far they keep linear theory's
height and phase (the ``wave-propagation`` case).

A piston (linear wavemaker theory, :mod:`fluid.wavemaker`) makes regular waves at one end of
a flume; an absorbing relaxation zone (:mod:`fluid.relaxation`) at the other end takes them
out. Gauges every eighth of a wavelength record the surface; at each whole wavelength ``j``
out, the gauges within a quarter wavelength of it separate the incident and reflected
first harmonics (a least-squares fit of ``A_i exp(-i k x) + A_r exp(i k x)``, k from the
dispersion relation: Mansard & Funke 1980, Proc. 17th ICCE, with more than three gauges).
The incident heights give the decay per wavelength (a fit of ``log H_j`` against ``j``),
the phases the wavenumber the waves travel with, and ``|A_r| / |A_i|`` the reflection.
"""

from __future__ import annotations

import math
import time

import numpy as np

from cosim.validations.waves import G


def viscous_decay_per_wavelength(nu: float, T: float, depth: float, floor: bool) -> float:
    """The fraction of a linear wave's height lost per wavelength to a kinematic viscosity
    ``nu`` [m^2/s] in the interior, ``2 nu k^2 / c_g`` per metre (Lamb 1932, Hydrodynamics
    §348), and, with ``floor``, to the laminar boundary layer of a no-slip floor: its mean
    dissipation ``rho u_b^2 sqrt(nu omega / 2) / 2`` per unit area (Lamb 1932, §349;
    ``u_b = a omega / sinh kd`` the velocity above it) over twice the energy flux
    ``rho g a^2 c_g / 2``, i.e. ``sqrt(nu omega / 2) omega^2 / (2 g c_g sinh^2 kd)`` per
    metre; period ``T`` [s], ``depth`` [m]."""
    from fluid.wavemaker import wavenumber

    k = wavenumber(T, depth, G)
    omega, kd = 2.0 * math.pi / T, k * depth
    cg = 0.5 * (1.0 + 2.0 * kd / math.sinh(2.0 * kd)) * omega / k
    rate = 2.0 * nu * k * k / cg
    if floor:
        rate += math.sqrt(0.5 * nu * omega) * omega ** 2 / (2.0 * G * cg * math.sinh(kd) ** 2)
    return -math.expm1(-rate * 2.0 * math.pi / k)


def separate(x: np.ndarray, a: np.ndarray, k: float) -> tuple[complex, complex]:
    """Complex amplitudes ``(A_i, A_r)`` [m] of the incident and reflected waves from the
    complex first-harmonic amplitudes ``a`` [m] of ``eta = Re(a exp(i w t))`` at gauges
    ``x`` [m] (at least two, not half a wavelength apart), ``a(x) = A_i exp(-ikx) + A_r exp(ikx)``
    (Mansard & Funke 1980, least squares)."""
    M = np.stack([np.exp(-1j * k * x), np.exp(1j * k * x)], axis=1)
    sol = np.linalg.lstsq(M, a, rcond=None)[0]
    return complex(sol[0]), complex(sol[1])


def harmonics(ts: np.ndarray, eta: np.ndarray, omega: float) -> np.ndarray:
    """Complex first-harmonic amplitude ``a`` [m] of each column of ``eta`` (samples, gauges)
    at times ``ts`` [s], ``eta ~ c + Re(a exp(i omega t)) + second harmonic``, by least squares."""
    basis = np.stack([np.ones_like(ts), np.cos(omega * ts), np.sin(omega * ts), np.cos(2 * omega * ts),
                      np.sin(2 * omega * ts)], 1)
    coef = np.linalg.lstsq(basis, eta, rcond=None)[0]
    return coef[1] - 1j * coef[2]


def propagate(dx: float, depth: float, H: float, T: float, wavelengths: int = 8, absorber: float = 1.5,
              rate_per_omega: float = 2.0, settle_periods: float = 4.0, fit_periods: float = 3.0,
              width: float | None = None, progress: bool = False, **config) -> dict:
    """Run the flume: piston waves of height ``H`` [m], period ``T`` [s] in ``depth`` [m] of
    water at spacing ``dx`` [m], read at ``wavelengths`` whole wavelengths out; an absorbing
    zone ``absorber`` wavelengths long at the far end, relaxing at ``rate_per_omega`` wave
    frequencies at its end; the fit over the last ``fit_periods`` periods, ``settle_periods``
    after the ramp's front (at the group velocity) has passed the last station. 2-D, or 3-D
    across ``width`` [m] (gauges on the mid-line). ``config``: FluidConfig settings (default
    ``u_max = sqrt(g depth)``). Returns the stations' incident heights and phases, the decay
    per wavelength, the reflection and the run's cost."""
    from fluid.flume import PADDLE_GROUP, flume
    from fluid.geometry import assemble, set_hydrostatic
    from fluid.probes import surface_elevation
    from fluid.relaxation import Slab
    from fluid.solver import Fluid, FluidConfig
    from fluid.wavemaker import RegularWavemaker

    wm = RegularWavemaker("piston", H=H, T=T, depth=depth, ramp=1.0, g=G)
    k, omega = wm.k, 2.0 * math.pi / T
    L = 2.0 * math.pi / k
    kd = k * depth
    cg = 0.5 * (1.0 + 2.0 * kd / math.sinh(2.0 * kd)) * omega / k
    x_abs = (wavelengths + 0.5) * L
    length = x_abs + absorber * L
    f = flume(dx, length, depth, 1.5 * depth, back=0.5 * wm.stroke + dx, width=width)
    config.setdefault("u_max", math.sqrt(G * depth))
    dim = 2 if width is None else 3
    cfg = FluidConfig(dim=dim, dx=dx, g=G, **config)
    ps = assemble(dim, dx, cfg.rho0, f.fluid, f.walls).particles
    set_hydrostatic(ps, depth, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = Fluid(cfg, ps)
    fluid.prescribe_motion(PADDLE_GROUP, wm.paddle())
    fluid.zones.append(Slab(0, x_abs, length, rate_per_omega * omega))
    stations = np.arange(1, wavelengths + 1) * L
    gx = (stations[:, None] + np.linspace(-0.25, 0.25, 5)[None, :] * L).ravel()
    at = gx if width is None else np.stack([gx, np.full_like(gx, 0.5 * width)], 1)
    t_end = T * (1.0 + settle_periods + fit_periods) + stations[-1] / cg
    every = T / 32.0
    fluid.initialize(0.0)
    t, ts, eta, cpu0 = 0.0, [], [], time.process_time()
    t_fit = t_end - fit_periods * T
    # advance in chunks of a period until the fit starts, then sample every T/32
    targets = list(np.arange(T, t_fit, T)) + list(t_fit + every * np.arange(round(fit_periods * 32) + 1))
    for target in targets:
        fluid.advance(t, target - t)
        t = target
        if t >= t_fit - 1e-9:
            ts.append(t)
            eta.append(surface_elevation(fluid, at) - depth)
        elif progress:
            print(f"  t = {t:6.2f} / {t_end:.2f} s, {fluid.counters.steps} steps", flush=True)
    cpu = time.process_time() - cpu0
    a = harmonics(np.array(ts), np.array(eta), omega).reshape(wavelengths, 5)
    xs = gx.reshape(wavelengths, 5)
    inc, refl = zip(*(separate(xs[j], a[j], k) for j in range(wavelengths)))
    inc, refl = np.array(inc), np.array(refl)
    H1 = 2.0 * np.abs(inc)
    j = np.arange(1, wavelengths + 1)
    slope = np.polyfit(j, np.log(H1), 1)[0]
    # eta = Re(A exp(i(w t - k_s x))): inc exp(i k x) turns by -(k_s - k) per metre
    psi = np.unwrap(np.angle(inc * np.exp(1j * k * stations)))
    k_sph = k - np.polyfit(stations, psi, 1)[0]
    lag = -(psi - psi[0]) / (2.0 * math.pi)  # periods behind linear theory, from the first station
    return {
        "stations_m": stations, "wavelength_m": L, "H1_over_H": H1 / H, "decay_per_wavelength": float(-math.expm1(slope)),
        "k_over_linear": float(k_sph / k), "phase_lag_periods": lag,
        "reflection": float(np.median(np.abs(refl) / np.abs(inc))), "particles": int(ps.n),
        "steps": int(fluid.counters.steps), "cpu_s": cpu, "t_end_s": t_end, "kd": kd,
        "removed": int(sum(fluid.counters.removed.values())),
    }
