"""Regular waves from a flap (and a piston) in an SPH flume against linear wavemaker theory:
their height, their decay along the flume against the artificial viscosity's, and their
wavenumber against the dispersion relation's, as one table.

    NUMBA_NUM_THREADS=1 .venv/bin/python benchmarks/flap_waves.py            # ~3 min
    .venv/bin/python benchmarks/flap_waves.py --kinds flap piston --dx 0.01

The floating-box-waves case (cosim.validations.waves) drives a flap in 0.4 m of water; the
packet's crest at probe N1 is made of 0.5-0.8 s waves. Here: T = 0.7 s (kd = 3.3),
H = 0.03 m, dx = 2 cm, gauges 0.3 ... 1.2 m from the paddle, the first-harmonic height over
the two periods before 4.4 s (the ramp's end has passed the last gauge; the far wall's
reflection has not come back). Rows: paddle, h / dx, alpha (0.0018 and 0.0015 give the
reference set-up's kinematic artificial viscosity, cosim.validations.waves.hadzic_alpha).
Columns: the height at each gauge over linear theory's H (Dean & Dalrymple 1991 §6.2,
fluid.wavemaker), the fitted decay rate [1/m], the decay rate of a viscosity nu = alpha h
c0 / 8 (Monaghan 2005, 2-D; cosim.validations.waves.viscous_decay), the fitted height at
the paddle over H (the generation, without the propagation), and the wavenumber of the
first harmonic's phase along x over the dispersion relation's.

The measured rows at dx = 2 and 1 cm (h = sqrt(2) dx does not converge with dx):
docs/benchmarks/flap_waves.md.

The flap makes linear theory's height at the paddle. With h = sqrt(2) dx (this code's
default) the waves travel ~5 % too fast and decay faster than their viscosity explains;
with the reference's h = 1.70 dx they travel at the dispersion relation's speed and keep
their height.
"""

from __future__ import annotations

import argparse
import time

from cosim.validations.waves import G, hadzic_alpha, paddle_wave_heights, viscous_decay

D, T, H, DX = 0.4, 0.7, 0.03, 0.02
GAUGES = [0.3, 0.45, 0.6, 0.75, 0.9, 1.05, 1.2]
SQ2, REF = 2 ** 0.5, 1.2 * 2 ** 0.5  # h / dx: this code's default, the reference's
#: (h / dx, alpha); alpha None: the reference's kinematic artificial viscosity (hadzic_alpha)
ROWS = [(SQ2, 0.01), (SQ2, None), (SQ2, 0.0), (REF, 0.01), (REF, None)]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kinds", nargs="+", default=["flap"])
    ap.add_argument("--dx", type=float, default=DX)
    a = ap.parse_args(argv)
    from fluid.solver import FluidConfig

    print(f"T = {T} s, H = {H} m, depth {D} m, dx = {a.dx} m; gauges {GAUGES} m")
    for kind in a.kinds:
        for h_coef, alpha in ROWS:
            cfg = FluidConfig(dim=2, dx=a.dx, g=G, u_max=(G * D) ** 0.5, h_coef=h_coef)
            alpha = hadzic_alpha(cfg.h, cfg.speed_of_sound) if alpha is None else alpha
            t0 = time.perf_counter()
            r = paddle_wave_heights(kind, a.dx, H, T, D, GAUGES, 4.4, 3.0, alpha=alpha, h_coef=h_coef)
            nu = alpha * cfg.h * cfg.speed_of_sound / 8.0
            print(f"{kind:6s} h {h_coef:.2f} dx alpha {alpha:<6.4g}: " + " ".join(f"{v / H:.2f}" for v in r["H1"])
                  + f"  decay {r['decay']:.3f} /m, nu's {viscous_decay(nu, T, D):.3f}; at paddle "
                  + f"{r['H1_paddle'] / H:.2f}; k/k_linear {r['k'] / r['k_linear']:.3f}"
                  + f"  ({time.perf_counter() - t0:.0f} s)", flush=True)


if __name__ == "__main__":
    main()
