"""Validation cases of the body-mooring-fluid coupling (``../shared/VALIDATION.md``,
Bodies and coupling)."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from cosim.validation import case

RHO, G = 1000.0, 9.81
# a 2-D box (1 m thick) held by two catenary lines from its lower corners
BOX_W, BOX_H, BOX_RHO = 2.0, 1.0, 500.0
ANCHOR_X, ANCHOR_Z = 20.0, -10.0
LINE_L, LINE_W = 25.0, 50.0


def moored_box_scene(offset=(3.0, 0.1), cells=24, damping=(1500.0, 1500.0, 1500.0)):
    """Bodies, fluid and moorings of the moored-box case (imports MuJoCo)."""
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from fluid.analytic import AnalyticFluid
    from moorings import CatenaryMooring, MooringLine

    z0 = 0.5 * BOX_H - BOX_RHO / RHO * BOX_H  # free-floating equilibrium, centre height
    sites = {"fl_left": (-0.5 * BOX_W, 0.0, -0.5 * BOX_H), "fl_right": (0.5 * BOX_W, 0.0, -0.5 * BOX_H)}
    xml = builders.scene(builders.box("box", (BOX_W, BOX_H), (offset[0], 0.0, z0 + offset[1]), density=BOX_RHO,
                                      planar=True, sites=sites), gravity=G, timestep=2e-3)
    bodies = MujocoBodies(xml)
    bx, bz, br = damping
    fluid = AnalyticFluid(rho=RHO, g=G, cells=cells, linear_damping={"box": [bx, 0.0, bz, 0.0, br, 0.0]})
    lines = [MooringLine((-ANCHOR_X, ANCHOR_Z), LINE_L, LINE_W, name="left"),
             MooringLine((ANCHOR_X, ANCHOR_Z), LINE_L, LINE_W, name="right")]
    return bodies, fluid, CatenaryMooring(lines), ("fl_left", "fl_right")


def moored_box_equilibrium():
    """Centre height [m] where buoyancy balances weight plus the lines' vertical
    pull, at x = 0 and no tilt (symmetry); solved with the catenary law alone."""
    from moorings.catenary import solve

    m = BOX_RHO * BOX_W * BOX_H

    def residual(z):
        h = (z - 0.5 * BOX_H) - ANCHOR_Z  # fairlead height above the seabed
        V = solve(ANCHOR_X - 0.5 * BOX_W, h, LINE_L, LINE_W).V
        draft = min(max(0.5 * BOX_H - z, 0.0), BOX_H)
        return RHO * G * BOX_W * draft - m * G - 2.0 * V

    return brentq(residual, -0.5 * BOX_H + 1e-9, 0.5 * BOX_H - 1e-9, xtol=1e-14)


@case("moored-body", "2-D box on two catenary lines, analytic fluid: settles where lines + hydrostatics balance")
def moored_body(quick: bool) -> dict:
    """The box is offset 3 m sideways and 0.1 m up and released; damped (heave
    damping ratio ~0.17), it must come to rest at the equilibrium of buoyancy,
    weight and the lines' pull (solved independently by
    :func:`moored_box_equilibrium`), within 0.1 mm and 0.1 mrad. Uses the analytic fluid (seconds); the SPH variant comes with the
    SPH-body coupling."""
    from cosim.coupler import Coupler

    bodies, fluid, mooring, sites = moored_box_scene(cells=12 if quick else 24)
    c = Coupler(bodies=bodies, fluid=fluid, moorings=[(mooring, sites)])
    t_end = 40.0 if quick else 120.0
    c.run(t_end)
    k = bodies.kinematics()
    z_eq = moored_box_equilibrium()
    q = bodies.data.qpos
    err = {"x_m": abs(k.com[0, 0]), "z_m": abs(k.com[0, 2] - z_eq), "roll_rad": abs(q[2])}
    speed = float(np.abs(k.velocity).max())
    led = c.ledger.arrays()
    F_last = led["fluid_force"][-1, 0] + led["mooring_force"][-1, 0] + led["gravity"][-1, 0]
    passed = err["x_m"] < 1e-4 and err["z_m"] < 1e-4 and err["roll_rad"] < 1e-4 and speed < 1e-4
    return {
        "passed": bool(passed),
        "metrics": {
            "equilibrium_z_m": z_eq,
            "final_com_m": k.com[0].tolist(),
            "position_error": err,
            "final_max_speed_m_s": speed,
            "net_force_at_end_N": F_last.tolist(),
            "line_tensions_N": mooring.fairlead_tensions().tolist(),
            "line_states": [int(s) for s in mooring.solution.state],
            "simulated_s": t_end,
            "coupling_dt_s": float(np.median(np.diff(led["t"]))),
            "dt_limited_by": fluid.dt_limit,
        },
        "tolerances": {"position_m": 1e-4, "roll_rad": 1e-4, "speed_m_s": 1e-4},
        "steps": c.steps,
    }
