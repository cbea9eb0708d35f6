"""Where a travelling wave's particle disorder and pressure noise sit: piston waves (d = 0.3
m, T = 1 s, H = 4 cm, the wave-propagation case's) in a short 2-D flume (3 wavelengths and
an absorbing zone) with the scenes' wave set-up, read once a period between 0.5 and 3
wavelengths from the paddle. Prints one JSON line a period:

- ``gradC``: RMS of ``h |sum_b (m_b/rho_b) grad_a W_ab|`` (walls ``m_b/rho0``) over the
  fluid particles whose support is full (the renormalisation matrix's smallest eigenvalue
  above 0.98): the disorder (0 on the square lattice of equal volumes);
  ``gradC_along_surface``, its component along the surface (normal to ``B^-1 grad C``) in
  the rows under the free surface (the eigenvalue below 0.8);
- ``noise_bulk``, ``noise_surface``: RMS of the pressure minus its first-order moving
  least-squares fit over the fluid neighbours, over rho g H, in the bulk and in the rows
  under the free surface;
- ``ke``: the fluid's kinetic energy [J per metre of width]; ``level_mm``: the mean of the
  surface elevation at 41 gauges over the period [mm].

    python benchmarks/wave_noise.py
    python benchmarks/wave_noise.py --set shifting=fickian shifting_coef=2

Brute-force sums over the neighbour pairs (numpy): a few seconds a reading.
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np

from cosim.scene.setup import settings
from cosim.validations.wave_propagation import WP_DEPTH, WP_HEIGHT, WP_PERIOD
from cosim.validations.waves import G
from fluid.flume import PADDLE_GROUP, flume
from fluid.geometry import assemble, set_hydrostatic
from fluid.kernels import W, grad_W
from fluid.neighbours import neighbour_pairs
from fluid.particles import Kind
from fluid.probes import surface_elevation
from fluid.relaxation import Slab
from fluid.solver import Fluid, FluidConfig
from fluid.wavemaker import RegularWavemaker
from wave_propagation import setting_value  # benchmarks/wave_propagation.py, beside this script


def readings(f: Fluid, L: float) -> dict:
    """The disorder, pressure noise and kinetic energy of ``f`` (module docstring)."""
    c, ps = f.config, f.ps
    pos, h, n = ps.pos, c.h, ps.n
    fl = ps.kind == Kind.FLUID
    V = np.where(fl, ps.mass / ps.rho, 0.0)
    Vs = np.where(fl, V, ps.mass / c.rho0)  # walls count as filled support
    i, j = neighbour_pairs(pos, 2.0 * h).T
    r = pos[i] - pos[j]
    g = grad_W(r, h)
    w = W(np.linalg.norm(r, axis=1), h, 2)
    gc, B = np.zeros((n, 2)), np.zeros((n, 2, 2))
    np.add.at(gc, i, Vs[j, None] * g)
    np.add.at(B, i, Vs[j, None, None] * (-r)[:, :, None] * g[:, None, :])
    lam = np.linalg.eigvalsh(B)[:, 0]
    e = np.stack([np.ones(len(i)), -r[:, 0], -r[:, 1]], axis=1)  # (1, r_b - r_a)
    A, b = np.zeros((n, 3, 3)), np.zeros((n, 3))
    np.add.at(A, i, (V[j] * w)[:, None, None] * e[:, :, None] * e[:, None, :])
    np.add.at(b, i, (V[j] * w * ps.p[j])[:, None] * e)
    fit = np.linalg.solve(A + 1e-12 * np.eye(3), b[:, :, None])[:, 0, 0]
    window = fl & (pos[:, 0] > 0.5 * L) & (pos[:, 0] < 3.0 * L)
    bulk, top = window & (lam > 0.98), window & (lam < 0.8)
    scale = c.rho0 * c.g_down * WP_HEIGHT
    rms = lambda x: float(np.sqrt(np.mean(x ** 2)))
    nrm = np.linalg.solve(B[top] + 1e-12 * np.eye(2), gc[top][:, :, None])[:, :, 0]
    nrm /= np.maximum(np.linalg.norm(nrm, axis=1), 1e-300)[:, None]
    along = gc[top] - np.einsum("ij,ij->i", gc[top], nrm)[:, None] * nrm
    return {"gradC": rms(h * np.linalg.norm(gc[bulk], axis=1)),
            "gradC_along_surface": rms(h * np.linalg.norm(along, axis=1)),
            "noise_bulk": rms(ps.p[bulk] - fit[bulk]) / scale,
            "noise_surface": rms(ps.p[top] - fit[top]) / scale,
            "ke": 0.5 * float((ps.mass[fl] * (ps.vel[fl] ** 2).sum(axis=1)).sum())}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rows", type=int, default=10, help="particle rows over the depth")
    ap.add_argument("--periods", type=int, default=12, help="wave periods to run")
    ap.add_argument("--set", nargs="*", default=[], metavar="KEY=VALUE", help="FluidConfig settings on top")
    args = ap.parse_args(argv)
    depth, T = WP_DEPTH, WP_PERIOD
    dx = depth / args.rows
    wm = RegularWavemaker("piston", H=WP_HEIGHT, T=T, depth=depth, ramp=1.0, g=G)
    L, omega = 2.0 * math.pi / wm.k, 2.0 * math.pi / T
    x_abs = 3.5 * L
    length = x_abs + 1.5 * L
    cfg = FluidConfig(dim=2, dx=dx, g=G, u_max=math.sqrt(G * depth),
                      **{**settings("waves", 2), **{k: setting_value(v) for k, v in (s.split("=", 1) for s in args.set)}})
    fl = flume(dx, length, depth, 1.5 * depth, layers=math.ceil(2.0 * cfg.h_coef - 1e-9), back=0.5 * wm.stroke + dx)
    ps = assemble(2, dx, cfg.rho0, fl.fluid, fl.walls).particles
    set_hydrostatic(ps, depth, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    f = Fluid(cfg, ps)
    f.prescribe_motion(PADDLE_GROUP, wm.paddle())
    f.zones.append(Slab(0, x_abs, length, 2.0 * omega))
    f.initialize(0.0)
    gauges = np.linspace(0.5 * L, 3.0 * L, 41)
    t, cpu = 0.0, 0.0
    print(json.dumps({"t": 0.0, **readings(f, L)}), flush=True)
    for _ in range(args.periods):
        level = []
        c0 = time.process_time()
        for _ in range(8):
            f.advance(t, T / 8)
            t += T / 8
            level.append(np.mean(surface_elevation(f, gauges)) - depth)
        cpu += time.process_time() - c0
        out = {"t": round(t, 6), **readings(f, L), "level_mm": 1e3 * float(np.mean(level)), "steps": f.counters.steps,
               "cpu_s": round(cpu, 1)}
        print(json.dumps({k: round(v, 5) if isinstance(v, float) else v for k, v in out.items()}), flush=True)


if __name__ == "__main__":
    main()
