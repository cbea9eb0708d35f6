"""Issue 18's static check with the SPH fluid: Barreiro et al. 2016's wind-turbine base (the scene of
examples/wind_turbine_base.py: 16 000 kg, a vertical cylinder 6 m across and 3 m high, three
catenary lines of Table 4 at 120 deg) at rest in still water, against the draft and offset
that hydrostatics and the three catenaries predict together (``cosim.scene.placement``:
draft 1.51 m, no offset by symmetry). Target: within 2 % of the draft.

Set-up, chosen so that the CPU can resolve the draft: the water around the base is a pool
16 m x 16 m, 4 m deep (5 m of water between the base and each wall; the base's draft is
1.51 m), the seabed of the lines 20 m below the surface as in the scene (the anchors lie
below the pool's floor, outside the fluid, 37 m from the base's axis). Hydrostatics on the
base depends on the water next to it only, so the pool stands for the tank at rest. The
base starts at the predicted height; the SPH fluid (``setup = "still"``, sea water 1025
kg/m^3) and the coupler's light-body sub-iterations take it from there. Read over the
second half of the run (the base rings in heave at about 0.37 Hz and the pool's seiches
ring too; the mean over whole periods is the equilibrium): the base's bottom below the
water level that eight gauges read away from it, the mean offset, and the error against
the prediction. ``--dx`` keeps the pool 4 m deep, the base's bottom face where it falls
against the fluid's lattice (the water under it fitted to it: ``fluid.standoff``);
``--rows K`` takes dx = draft / K and the depth nearest 4 m that is a whole number of
rows, so that the face lies on a face of the lattice (how the floating-box-draft case
sets its box, and how this was judged before the fit).

    python benchmarks/wind_turbine_static.py --dx 0.5,0.375 --duration 12  # the pool 4 m deep
    python benchmarks/wind_turbine_static.py --rows 3,4 --duration 12      # aligned
    python benchmarks/wind_turbine_static.py --dx 0.5 --setup waves --h-coef 1.4142  # another set-up

Prints one line per spacing: particles, CPU seconds, the predicted draft, the SPH draft
below the water level the gauges read away from the base (``draft_sph_m``, judged) and
below the set-up's level (``draft_nominal_level_m``), the level's shift, the mean offset,
the heave's swing over the window.

The measured rows (aligned, and the pool 4 m deep before and after the fit):
docs/benchmarks/wind_turbine_static.md.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from cosim.validations.wind_turbine_sph import equilibrium_draft, static_draft

POOL, DEPTH, SEABED = 16.0, 4.0, 20.0  # m: the pool's side and depth; the lines' water depth
ANCHOR_R = 37.0  # m from the base's axis (examples/wind_turbine_base.py)
#: (x, y) [m] of the gauges that read the water level away from the base: by the corners
#: and mid-sides of the pool, 2 m from its walls, 5.7-8.5 m from the base's axis
GAUGES = ((2.0, 2.0), (14.0, 2.0), (2.0, 14.0), (14.0, 14.0), (8.0, 2.0), (2.0, 8.0), (14.0, 8.0), (8.0, 14.0))


def static_scene(dx: float, duration: float, depth: float = DEPTH, setup: str = "still", h_coef: float | None = None):
    """The base in the pool (module docstring), ``depth`` [m] of water, at spacing ``dx`` [m],
    the fluid's ``setup`` (cosim.scene.setup) and its ``h_coef`` where given."""
    from cosim.scene import SPH, Cylinder, Line, Moorings, Probes, Scene, Tank, World

    chain = dict(length=45.0, weight=3769.85, EA=1.9e9, mass_per_length=442.0, diameter=0.268, break_load=1.4e6)
    c = 0.5 * POOL
    floor = depth - SEABED  # the anchors' seabed, below the pool
    anchors = {k: (c + ANCHOR_R * math.cos(math.radians(a)), c + ANCHOR_R * math.sin(math.radians(a)), floor)
               for k, a in (("back", 0.0), ("front_port", 120.0), ("front_starboard", 240.0))}
    fairleads = {"back": (3.0, 0.0, -1.5), "port": (-1.5, 2.5981, -1.5), "starboard": (-1.5, -2.5981, -1.5)}
    return Scene(
        name="wind_turbine_static",
        world=World(dim=3, duration=duration, sample_every=0.05, snapshot_every=1.0),
        fluid=SPH(dx=dx, rho0=1025.0, setup=setup, h_coef=h_coef),
        domain=Tank(length=POOL, width=POOL, height=depth + 2.5, depth=depth),
        bodies=[Cylinder("base", radius=3.0, length=3.0, mass=16000.0, pos=(c, c), place="floating",
                         fairleads=fairleads)],
        moorings=Moorings(model="catenary", segments=20,
                          lines=[Line("base.back", name="back", anchor=anchors["back"], **chain),
                                 Line("base.port", name="front_port", anchor=anchors["front_port"], **chain),
                                 Line("base.starboard", name="front_starboard", anchor=anchors["front_starboard"],
                                      **chain)]),
        probes=Probes(gauges=GAUGES, motion=("base",), loads=False),
    )


def aligned(rows: int) -> tuple[float, float]:
    """The spacing [m] that puts ``rows`` rows of particles in the draft and the pool's
    depth [m] (the nearest whole number of rows to 4 m) that put the base's bottom face on
    a face of the fluid's lattice, as the floating-box-draft case sets its box (the fluid
    removed where the base is then equals its submerged volume)."""
    d0 = equilibrium_draft(static_scene(1.0, 1.0))
    dx = d0 / rows
    return dx, round(DEPTH / dx) * dx


def measure(dx: float, duration: float, out: str, depth: float = DEPTH, setup: str = "still",
            h_coef: float | None = None) -> dict:
    scene = static_scene(dx, duration, depth, setup, h_coef)
    c0 = time.process_time()
    r = scene.run(f"{out}/dx{dx:.4g}", overwrite=True, progress=False)
    cpu = time.process_time() - c0
    d = static_draft(r, scene)  # the draft below the gauges' level and the nominal one, over the second half
    d0 = d["draft_predicted_m"]
    heave, surge, sway = (np.asarray(r[f"base.{k}"], float) for k in ("heave", "surge", "sway"))
    late = r.t >= 0.5 * duration
    sm = r.summary
    return {"dx_m": dx, "depth_m": scene.domain.depth, "rows_over_draft": d0 / dx, "particles": sm["particles"],
            "steps": sm["steps"], "c0_m_s": sm["speed_of_sound_m_s"], "cpu_s": cpu,
            "cpu_s_per_simulated_s": cpu / duration, "draft_predicted_m": d0,
            "draft_nominal_level_m": d0 - float(heave[late].mean()), "error_nominal_level": d["draft_nominal_level_error"],
            "level_shift_m": d["level_shift_m"], "draft_sph_m": d["draft_sph_m"], "error_of_draft": d["draft_signed_error"],
            "offset_m": float(math.hypot(surge[late].mean(), sway[late].mean())),
            "heave_swing_m": float(heave[late].max() - heave[late].min())}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dx", default="", help="spacings [m], comma-separated (the pool 4 m deep)")
    ap.add_argument("--rows", default="", help="rows of particles in the draft, comma-separated: the spacing and "
                    "depth that align the base's bottom with the lattice (aligned)")
    ap.add_argument("--duration", type=float, default=12.0, help="simulated seconds")
    ap.add_argument("--setup", default="still", help="the fluid's set-up (cosim.scene.setup), e.g. still, waves")
    ap.add_argument("--h-coef", type=float, default=None, help="h / dx over the set-up's")
    ap.add_argument("--out", default="out/wind_turbine_static")
    a = ap.parse_args(argv)
    runs = [(float(v), DEPTH) for v in a.dx.split(",") if v] + [aligned(int(k)) for k in a.rows.split(",") if k]
    for dx, depth in runs:
        m = measure(dx, a.duration, a.out, depth, a.setup, a.h_coef)
        print(" ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in m.items()), flush=True)


if __name__ == "__main__":
    main()
