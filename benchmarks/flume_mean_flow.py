"""Does a current or a deeper water lengthen the wave of a kept wave-propagation run? Reads
the last state of the case's kept flume runs (their ``checkpoint.h5``, under
``$COSIM_CASE_RUNS/wave-propagation/full``) over whole wavelengths of the flume and prints,
for each:

- the mean horizontal velocity of the fluid particles in layers a tenth of the depth thick,
  by height above the floor: below the wave troughs a spatial mean over whole wavelengths of a
  progressive wave is its Eulerian mean flow (the return current under the waves' drift);
- that flow weighted as it Doppler-shifts the wave, ``U_eff = int U(z) 2 k cosh(2 k z) dz /
  sinh(2 k d)`` over the layers below the troughs (Stewart & Joy 1974, Deep-Sea Res. 21,
  Eq. 4; z from the floor), and the wavenumber change it makes at the paddle's frequency,
  ``dk / k = -U_eff / c_g`` (``omega = sigma(k) + k U``);
- the water's mean depth, its mass over rho0 and the flume's plan area.

A current running down the flume at U_eff makes the wave long (k / linear below 1), a
return current short; a water deeper by e d makes it long by about 0.18 e at kd = 1.37.

    COSIM_CASE_RUNS=DIR python benchmarks/flume_mean_flow.py rows20 rows3d_15
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from cosim import checkpoint
from cosim.validations import case_scene
from cosim.validations.wave_propagation import GAUGES_PER_STATION, WP_DEPTH, WP_HEIGHT, WP_PERIOD, _wave
from fluid.particles import Kind


def read(folder, troughs: float) -> dict:
    """The mean-flow figures of one kept run's last state (``folder`` holds its
    ``checkpoint.h5`` and ``scene.toml``); ``troughs``: the height [m] above the floor below
    which a layer is under every trough."""
    from cosim.scene.load import load

    scene = load(folder / "scene.toml")
    wm, L, cg = _wave(WP_HEIGHT, WP_PERIOD, WP_DEPTH)
    k, d = wm.k, WP_DEPTH
    state = checkpoint.read(folder / "checkpoint.h5")["state"]["participants"]["fluid"]
    ps = state["ps"]
    water = ps.kind == int(Kind.FLUID)
    pos, u, m = ps.pos[water], ps.vel[water, 0], ps.mass[water]
    z = pos[:, -1]
    width = scene.domain.width if scene.world.dim == 3 else 1.0
    out = {"run": folder.name, "t_s": float(state["t"]), "dim": scene.world.dim, "windows": []}
    edges = np.linspace(0.0, 1.1 * d, 12)
    stations = len(scene.probes.gauges) // GAUGES_PER_STATION
    # whole wavelengths from half a wavelength out, as far as the flume's stations go
    for x0 in np.arange(0.5, stations - 1.0) * L:
        inside = (pos[:, 0] >= x0) & (pos[:, 0] < x0 + L)
        layers, num, den = [], 0.0, 0.0
        for z0, z1 in zip(edges[:-1], edges[1:]):
            b = inside & (z >= z0) & (z < z1)
            if b.sum() < 5:
                continue
            U = float(u[b].mean())
            layers.append((0.5 * (z0 + z1), U))
            if z1 <= troughs:
                w = 2.0 * k * math.cosh(2.0 * k * 0.5 * (z0 + z1)) / math.sinh(2.0 * k * d) * (z1 - z0)
                num, den = num + U * w, den + w
        out["windows"].append({"from_L": x0 / L, "layers": layers, "U_eff_m_s": num / den,
                               "dk_over_k": -num / den / cg,
                               "depth_m": float(m[inside].sum() / scene.fluid.rho0 / (L * width))})
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="kept runs' folder names (rows10, rows3d_15, ...)")
    args = ap.parse_args(argv)
    kept = case_scene.kept_runs("wave-propagation", False)
    # a layer wholly below the troughs: under the still level less half the wave height
    troughs = WP_DEPTH - 0.5 * WP_HEIGHT
    print("| run | x / L | depth [m] | mean u by layer [mm/s] (height above the floor [mm]) | U_eff [mm/s] | dk / k |")
    print("|---|---|---|---|---|---|")
    for name in args.runs:
        r = read(kept / name, troughs)
        for w in r["windows"]:
            layers = " ".join(f"{1e3 * U:+.1f} ({1e3 * zc:.0f})" for zc, U in w["layers"])
            print(f"| {name} | {w['from_L']:.1f}-{w['from_L'] + 1:.1f} | {w['depth_m']:.4f} | {layers} "
                  f"| {1e3 * w['U_eff_m_s']:+.2f} | {100 * w['dk_over_k']:+.2f} % |")


if __name__ == "__main__":
    main()
