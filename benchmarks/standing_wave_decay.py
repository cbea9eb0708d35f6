"""How fast a standing wave loses its amplitude in a closed tank (2-D, or a 3-D slice), and
its period: a quick probe of the water's numerical damping and speed
(docs/validation/wave-propagation_history.md), minutes where the flume takes hours.

The tank is one wavelength long, L = 1.373 m, water d = 0.3 m (the wave-propagation case's
wave: kd = 1.37, T = 1 s), rounded to whole spacings (``tank_mode``: 1.38 m at 10 rows); its
second sloshing mode has k = 2 pi / L, its periods read against linear theory's at that k.
The water is settled at rest first (``Fluid.settle``, 2 s; ``--settle``), then given linear theory's
velocity of that mode at the instant its surface is flat (Dean & Dalrymple 1991, §4.3:
standing waves, ``u = -A cosh kz sin kx``, ``w = A sinh kz cos kx``, ``A = a g k / (omega
cosh kd)``, z from the bed, amplitude ``a`` = 2 cm; ``--amplitude``). Read every T/32: the velocity field projected on the mode's
shape (``sum m v . phi / sum m |phi|^2``, A at the start), the elevation at the middle and the
kinetic energy. The decay of the amplitude per period is ``1 - exp(s)``, ``s`` the slope of a
straight line through log(each period's first harmonic of the projection) over the periods
after the first; the middle's elevation gives the same within a few tenths of a per cent.
The kinetic energy (each period's mean, its root) is printed beside them and misleads (it
carries the particles' noise); ``period_over_linear``: the mode's period over linear theory's.

The water also keeps sinking by a fraction of a millimetre a period while it moves (the
particles pack closer than their density says; docs/validation/nearfield.md): the potential
energy that releases is several times the wave's, so no energy balance is read.

A travelling wave that loses a fraction ``e`` of its height per period in time loses ``e /
n`` per wavelength in space (energy travels at the group velocity ``n c``; n = 0.677 here).
The tank's walls add the friction of the standing wave's vertical flow along them, so the
figure is a probe to compare set-ups with, not the flume's decay.

    python benchmarks/standing_wave_decay.py --rows 10 --periods 10 --set alpha=0 --set alpha=0 delta=0.2
    python benchmarks/standing_wave_decay.py --rows 10 --periods 4 --width 5

``--width ROWS``: the tank as a 3-D slice that many spacings wide between its walls
(``--sides symmetry``: between two symmetry planes, a slice of a tank of any width), the
mode uniform across it, the middle's elevation the mean of a gauge on each particle column
across the width. ``first_period_elevation_over_mode`` compares the surface with the water
under it: the middle's first-period amplitude over ``a`` against the mode's over ``A``.

Each ``--set`` is one run (FluidConfig settings on top of the wave set-up,
``cosim.scene.setup.settings("waves", 2)``); with none, the set-up alone.
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np

from machine import cpu_name  # benchmarks/machine.py, beside this script
from wave_propagation import setting_value  # benchmarks/, beside this script
from cosim.scene.setup import settings
from cosim.validations.wave_propagation import G, WP_DEPTH as DEPTH, WP_PERIOD, harmonics, upward_crossings
from fluid.wavemaker import wavenumber

#: the tank's length [m]: the wave-propagation case's wavelength
LENGTH = 2.0 * math.pi / wavenumber(WP_PERIOD, DEPTH, G)
#: the mode's amplitude at the tank's ends [m] (``--amplitude``)
AMPLITUDE = 0.02
#: how long the water settles at rest before the mode starts [s] (``--settle``)
SETTLE_S = 2.0


def tank_mode(dx: float) -> tuple[float, float, float]:
    """``(length, k, omega)``: the tank's length [m] at spacing ``dx`` as it is built,
    :data:`LENGTH` rounded to whole spacings (``fluid.geometry.lattice_extent``), and its
    mode's wavenumber [rad/m] and linear angular frequency [rad/s] (``omega^2 = g k tanh
    kd``)."""
    from fluid.geometry import lattice_extent

    length = lattice_extent(LENGTH, dx)
    k = 2.0 * math.pi / length
    return length, k, math.sqrt(G * k * math.tanh(k * DEPTH))


def started_tank(rows: int, extra: dict, width_rows: int = 0, make_fluid=None, amplitude: float = AMPLITUDE,
                 settle: float = SETTLE_S, sides: str = "walls"):
    """``(fluid, A)``: the tank at ``rows`` particle rows over the depth, settled at rest for
    ``settle`` [s], then given the velocity of the mode of elevation amplitude
    ``amplitude`` [m], ``A`` [m/s], at the instant its surface is flat; in 2-D, or with
    ``width_rows`` > 0 a 3-D slice that many spacings wide between the tank's walls (the
    mode uniform across it); ``sides`` "symmetry": between two symmetry planes instead of
    side walls (the fluid's ``symmetry_y`` and ``symmetry_y_hi``, fluid.mirror).
    ``extra``: FluidConfig settings on top of the wave set-up; ``make_fluid(config,
    particles)``: the fluid built instead of ``Fluid(config, particles)`` (a probe's
    variant)."""
    from fluid.geometry import set_hydrostatic, tank_with_water
    from fluid.solver import Fluid, FluidConfig

    dx = DEPTH / rows
    length, k, omega = tank_mode(dx)
    dim = 3 if width_rows else 2
    planes = {"symmetry_y": 0.0, "symmetry_y_hi": width_rows * dx} if width_rows and sides == "symmetry" else {}
    cfg = FluidConfig(dim=dim, dx=dx, g=G, **{"u_max": math.sqrt(G * DEPTH), **settings("waves", dim), **planes,
                                              **extra})
    ps = tank_with_water(dim, dx, length, DEPTH, 1.6 * DEPTH, width=width_rows * dx,
                         layers=math.ceil(2.0 * cfg.h_coef - 1e-9)).particles
    if planes:  # the side walls give way to the planes' mirror images
        ps = ps.select((ps.pos[:, 1] > 0.0) & (ps.pos[:, 1] < width_rows * dx))
    set_hydrostatic(ps, DEPTH, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = (make_fluid or Fluid)(cfg, ps)
    fluid.initialize(0.0)
    fluid.settle(settle)
    water = (fluid.ps.kind == 0) & (fluid.ps.ids >= 0)  # a symmetry plane's images left out
    x, z = fluid.ps.pos[water, 0], fluid.ps.pos[water, -1]
    A = amplitude * G * k / (omega * math.cosh(k * DEPTH))
    fluid.ps.vel[water, 0] = -A * np.cosh(k * z) * np.sin(k * x)
    fluid.ps.vel[water, -1] = A * np.sinh(k * z) * np.cos(k * x)
    return fluid, A


def run(rows: int, periods: int, extra: dict, width_rows: int = 0, make_fluid=None, amplitude: float = AMPLITUDE,
        settle: float = SETTLE_S, sides: str = "walls", series: list | None = None) -> dict:
    """One run of :func:`started_tank` for ``periods`` periods; ``series``: a list that
    gets each sample's ``(t / T, projection / A)``."""
    from fluid.probes import surface_elevation

    dx = DEPTH / rows
    length, k, omega = tank_mode(dx)
    T = 2.0 * math.pi / omega
    dim = 3 if width_rows else 2
    fluid, A = started_tank(rows, extra, width_rows, make_fluid, amplitude, settle, sides)
    ke0 = fluid.kinetic_energy()

    def modal() -> float:
        """The velocity field's projection on the mode's shape [m/s] (A at the start)."""
        w = (fluid.ps.kind == 0) & (fluid.ps.ids >= 0)  # a symmetry plane's images left out
        m, xx, zz, v = fluid.ps.mass[w], fluid.ps.pos[w, 0], fluid.ps.pos[w, -1], fluid.ps.vel[w]
        fu, fw = -np.cosh(k * zz) * np.sin(k * xx), np.sinh(k * zz) * np.cos(k * xx)
        return float((m * (v[:, 0] * fu + v[:, -1] * fw)).sum() / (m * (fu * fu + fw * fw)).sum())

    # the middle's elevation: on the tank's mid-line in 2-D; in 3-D the mean of a gauge on
    # every particle column across the width
    middle = [0.5 * length] if dim == 2 else [[0.5 * length, (j + 0.5) * dx] for j in range(width_rows)]

    def middle_eta() -> float:
        return float(np.mean(surface_elevation(fluid, middle)) - DEPTH)

    every = T / 32.0
    ts, ke, eta, q = [0.0], [ke0], [middle_eta()], [modal()]
    cpu0, t = time.process_time(), 0.0
    for _ in range(32 * periods):
        fluid.advance(t, every)
        t += every
        ts.append(t)
        ke.append(fluid.kinetic_energy())
        eta.append(middle_eta())
        q.append(modal())
    if series is not None:
        series.extend(zip((t / T for t in ts), (v / A for v in q)))
    ts, ke, eta, q = np.array(ts), np.array(ke), np.array(eta), np.array(q)
    period_of = np.minimum((ts / T + 1e-9).astype(int), periods - 1)
    mean_ke = np.array([ke[period_of == p].mean() for p in range(periods)])
    amp, mode = [], []
    for p in range(periods):  # first harmonics over each period: the middle's elevation, the mode's velocity
        m = period_of == p
        amp.append(abs(harmonics(ts[m], eta[m], omega)) / amplitude)
        mode.append(abs(harmonics(ts[m], q[m], omega)) / A)

    def per_period(x):  # 1 - exp(slope of log x over the periods after the first)
        return float(-math.expm1(np.polyfit(np.arange(1, periods), np.log(x[1:]), 1)[0]))

    decay = per_period(np.array(mode))
    # the period from the mode's upward zero crossings after the first period (linear
    # interpolation between samples): how fast the tank's water makes the wave (a wave that
    # is fast in time is long in space: k / k_linear = 1 - (T / T_sph - 1) / n in a flume)
    after = ts >= T - 1e-9
    crossings = upward_crossings(ts[after], q[after])
    period = float(np.diff(crossings).mean()) if len(crossings) > 1 else float("nan")
    n = 0.5 * (1.0 + 2.0 * k * DEPTH / math.sinh(2.0 * k * DEPTH))  # group over phase velocity
    return {"rows": rows, "width_rows": width_rows, "sides": sides if width_rows else None, "amplitude_m": amplitude,
            "settle_s": settle, "set": extra,
            "first_period_elevation_over_mode": round(amp[0] / mode[0], 4), "decay_per_period": decay,
            "per_wavelength_if_travelling": decay / n,
            "decay_of_the_middle_elevation": per_period(np.array(amp)),
            "decay_of_the_kinetic_energy_amplitude": per_period(np.sqrt(mean_ke)),
            "mode_amplitude_over_start": np.round(mode, 4).tolist(),
            "mean_ke_over_start": np.round(mean_ke / ke0, 4).tolist(), "middle_amplitude_over_a": np.round(amp, 3).tolist(),
            "period_s": T, "period_over_linear": round(period / T, 5), "particles": int(fluid.ps.n), "steps": int(fluid.counters.steps),
            "cpu_s": round(time.process_time() - cpu0, 1)}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rows", nargs="+", type=int, default=[10], help="particle rows over the depth")
    ap.add_argument("--periods", type=int, default=10)
    ap.add_argument("--width", type=int, default=0, metavar="ROWS",
                    help="a 3-D slice this many spacings wide (default: 2-D)")
    ap.add_argument("--sides", choices=("walls", "symmetry"), default="walls",
                    help="3-D: the slice between side walls, or between two symmetry planes")
    ap.add_argument("--amplitude", type=float, nargs="+", default=[AMPLITUDE], metavar="M",
                    help="the mode's elevation amplitude at the tank's ends [m], one run each")
    ap.add_argument("--settle", type=float, default=SETTLE_S, metavar="S",
                    help="how long the water settles at rest before the mode starts [s]")
    ap.add_argument("--set", nargs="*", action="append", metavar="KEY=VALUE",
                    help="one run's FluidConfig settings on top of the wave set-up (repeat for more runs)")
    args = ap.parse_args(argv)
    variants = [{k: setting_value(v) for k, v in (s.split("=", 1) for s in group)} for group in (args.set or [[]])]
    print(f"# CPU: {cpu_name()}")
    rows_out = []
    for rows in args.rows:
        for amplitude in args.amplitude:
            for extra in variants:
                r = run(rows, args.periods, extra, args.width, amplitude=amplitude, settle=args.settle,
                        sides=args.sides)
                print(json.dumps(r), flush=True)
                rows_out.append(r)
    print("\n| rows | amplitude [m] | settings on the wave set-up | decay per period: the mode | the middle's elevation "
          "| the kinetic energy's root | period / linear | particles | steps | CPU s |\n|---|---|---|---|---|---|---|---|---|---|")
    for r in rows_out:
        s = " ".join(f"{k}={v}" for k, v in r["set"].items()) or "(none)"
        print(f"| {r['rows']} | {r['amplitude_m']:g} | {s} | {100 * r['decay_per_period']:.2f} % | "
              f"{100 * r['decay_of_the_middle_elevation']:.2f} % | {100 * r['decay_of_the_kinetic_energy_amplitude']:.2f} % "
              f"| {r['period_over_linear']:.4f} | {r['particles']} | {r['steps']} | {r['cpu_s']:.0f} |")


if __name__ == "__main__":
    main()
