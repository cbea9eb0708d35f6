"""Validation cases of the body-mooring-fluid coupling (``docs/VALIDATION.md``,
Bodies and coupling)."""

from __future__ import annotations


import numpy as np
from scipy.optimize import brentq

from cosim.validations.registry import case

#: the moored box's duration [s] by variant (quick: True); the rest is the file's (scenes/moored-body.toml)
MOORED_DURATION = {True: 40.0, False: 120.0}


def moored_box_scene(quick: bool):
    """The scene ``scenes/moored-body.toml`` (the full variant's) run for the variant's
    duration (:data:`MOORED_DURATION`): a 2-D box held by two catenary lines from its lower
    corners, in the analytic fluid, released offset from its rest position."""
    from cosim.validations import case_scene

    return case_scene.load("moored-body", [f"world.duration={case_scene.number(MOORED_DURATION[quick])}"])


def moored_box_equilibrium(scene) -> float:
    """Centre height [m] where buoyancy balances weight plus the lines' vertical pull,
    at x midway between the anchors and no tilt (symmetry), of the box of ``scene``
    (:func:`moored_box_scene`: a box of width ``W``, height ``B`` and density ``rho_b`` on two
    lines from its lower corners to anchors at the same depth either side, still water at
    ``fluid.level``); solved with the catenary law alone (Barreiro et al. 2016, Eq. 35-39)."""
    from moorings.catenary import solve

    box, (left, right), rho, g = scene.bodies[0], scene.moorings.lines, scene.fluid.rho, scene.world.g
    (W, B), level = box.size, scene.fluid.level
    spread = 0.5 * (right.anchor[0] - left.anchor[0])
    m = box.density * W * B

    def residual(z):
        h = (z - 0.5 * B) - left.anchor[1]  # fairlead height above the seabed
        V = solve(spread - 0.5 * W, h, left.length, left.weight).V
        draft = min(max(level + 0.5 * B - z, 0.0), B)
        return rho * g * W * draft - m * g - 2.0 * V

    return brentq(residual, level - 0.5 * B + 1e-9, level + 0.5 * B - 1e-9, xtol=1e-14)


@case("moored-body", "2-D box on two catenary lines, analytic fluid: settles where lines + hydrostatics balance",
      target="decay to the equilibrium predicted by lines + hydrostatics",
      quick="at rest at the equilibrium of lines + hydrostatics within 0.1 mm, 0.1 mrad and 0.1 mm/s after 40 s "
            "instead of 120 s", scene=moored_box_scene)
def moored_body(quick: bool) -> dict:
    """The box of ``scenes/moored-body.toml`` (:func:`moored_box_scene`) is offset 3 m
    sideways and 0.1 m up and released; damped (heave damping ratio ~0.17), it must come to
    rest at the equilibrium of buoyancy, weight and the lines' pull (solved independently
    from the scene's fields by :func:`moored_box_equilibrium`), within 0.1 mm and 0.1 mrad.
    Uses the analytic fluid (seconds); the SPH variant is ``moored-body-sph``."""
    from cosim.validations import case_scene

    scene = moored_box_scene(quick)
    t_end = scene.world.duration
    with case_scene.built(scene) as b:
        c, bodies, fluid, mooring = b.coupler, b.bodies, b.fluid, b.mooring
        c.run(t_end)
    left, right = scene.moorings.lines
    x_rest = 0.5 * (left.anchor[0] + right.anchor[0])
    k = bodies.kinematics()
    z_eq = moored_box_equilibrium(scene)
    q = bodies.data.qpos
    err = {"x_m": abs(k.com[0, 0] - x_rest), "z_m": abs(k.com[0, 2] - z_eq), "roll_rad": abs(q[2])}
    speed = float(np.abs(k.velocity).max())
    led = c.ledger.arrays()
    F_last = led["fluid_force"][-1, 0] + led["mooring_force"][-1, 0] + led["gravity"][-1, 0]
    return {
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
        "tolerances": {"position_error.x_m": 1e-4, "position_error.z_m": 1e-4, "position_error.roll_rad": 1e-4,
                       "final_max_speed_m_s": 1e-4},
        "steps": c.steps,
    }


def momentum_exchange_scene(quick: bool = True, values=()):
    """The scene ``scenes/momentum-exchange.toml`` (both variants: they differ in the steps
    run) with ``values`` set (``KEY=VALUE``, as ``cosim run --set``): a free 2-D square box
    hits a resting blob of SPH water off-centre in open water, with no gravity."""
    from cosim.validations import case_scene

    return case_scene.load("momentum-exchange", list(values))


def momentum_exchange_run(scene, steps: int) -> dict:
    """Step ``scene`` (:func:`momentum_exchange_scene`) ``steps`` coupling steps, each as
    long as the participants allow. Returns the relative drift of the total linear and
    angular momentum (about the origin, per metre of depth) of fluid plus body, the body's
    speed along x and spin [rad/s] at the start and end, and the most sub-iterations a
    step took."""
    from cosim.validations import case_scene
    from fluid.particles import Kind

    with case_scene.built(scene) as b:
        bodies, fluid, coupler = b.bodies, b.sph, b.coupler
        M, Iyy = bodies.masses()[0], bodies.model.body_inertia[bodies.body_ids[0]][1]

        def totals():
            ps = fluid.ps
            fl = ps.kind == Kind.FLUID
            m, x, v = ps.mass[fl], ps.pos[fl], ps.vel[fl]
            k = bodies.kinematics()
            com, V, w = k.com[0], k.velocity[0], k.omega[0]
            P = (m[:, None] * v).sum(axis=0) + M * V[[0, 2]]
            L = (m * (x[:, 1] * v[:, 0] - x[:, 0] * v[:, 1])).sum() + Iyy * w[1] + M * (com[2] * V[0] - com[0] * V[2])
            return P, L

        P0, L0 = totals()
        v0, w0 = bodies.kinematics().velocity[0, 0], bodies.kinematics().omega[0, 1]
        iterations = 0
        for _ in range(steps):
            coupler.step(10.0)
            iterations = max(iterations, coupler.subiterations)
        P, L = totals()
        k = bodies.kinematics()
        return {
            "linear_drift": float(np.abs(P - P0).max() / np.abs(P0).max()),
            "angular_drift": float(abs(L - L0) / abs(L0)),
            "body_vx_m_s": [float(v0), float(k.velocity[0, 0])],
            "body_omega_rad_s": [float(w0), float(k.omega[0, 1])],
            "particles": int(fluid.ps.n),
            "t_s": coupler.t,
            "max_subiterations": iterations,
        }


@case("momentum-exchange", "a free body hits SPH water (no gravity, no walls): momentum of fluid + body to round-off",
      target="conserved to round-off (1e-10 relative per step)",
      quick="the full variant's 1e-12 relative drift of the total linear and angular momentum over the run "
            "(stricter than the stated 1e-10 per step), over 300 coupling steps instead of 2000",
      scene=momentum_exchange_scene)
def momentum_exchange(quick: bool) -> dict:
    """Total linear and angular momentum of fluid and body are conserved to
    round-off with the fluid-first scheme (the body receives exactly the impulse
    and angular impulse the fluid exchanged): the scene :func:`momentum_exchange_scene`
    stepped by :func:`momentum_exchange_run`; the start-of-step loads of the explicit
    scheme are shown beside it for contrast."""
    steps = 300 if quick else 2000
    scene = momentum_exchange_scene(quick)
    exact = momentum_exchange_run(scene, steps)
    explicit = momentum_exchange_run(scene.with_values(['coupling.scheme="explicit"']), steps)
    tol = 1e-12
    return {
        "metrics": {"fluid_first": exact, "explicit": {k: explicit[k] for k in ("linear_drift", "angular_drift")}},
        "tolerances": {"fluid_first.linear_drift": tol, "fluid_first.angular_drift": tol},
        "particles": exact["particles"],
        "steps": steps,
    }
