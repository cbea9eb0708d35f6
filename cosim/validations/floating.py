"""Floating-body cases with the SPH fluid (VALIDATION.md, "Bodies and coupling"):
floating-box-draft, floating-heave-period, sinking-cylinder.

Every case is a scene (``scenes/CASE.toml``, :mod:`cosim.validations.case_scene`) built as
``cosim run`` builds it: the SPH fluid (``cosim.sph_fluid.SPHFluid``, bodies as boundary
particles with modified dynamic boundary conditions, ``fluid.boundary_correction``)
coupled to MuJoCo bodies through the fluid-first scheme of ``cosim.coupler.Coupler``: the
body receives exactly the impulse the fluid exchanged (Barreiro et al. 2016, Eq. 9-12), and the
fluid places the body's particles from its pose (Eq. 13). The case steps the coupler itself
and reads the body at every coupling step.

Set-up rule shared by the box cases: the box's faces lie on faces of the fluid's
particle lattice at the start (draft, water depth and box size are whole numbers of
``dx``), so that the fluid removed where the box is equals the box's submerged
volume exactly. (A face between lattice planes is now fitted at set-up,
``fluid.standoff``; the cases keep their aligned set-up, their measured references.)
"""

from __future__ import annotations

import math

import numpy as np

from cosim.validations import case_scene
from cosim.validations.case_scene import number
from cosim.validations.registry import case

RHO, G = 1000.0, 9.81


def box_scene(case: str, dim: int, dx: float, rho_b: float, *, width: float = 0.1, height: float = 0.05,
              tank: float = 0.3, depth: float = 0.1, lift: float = 0.0, boundary: str = "mdbc",
              c0_factor: float = 20.0):
    """The scene ``scenes/CASE.toml`` (a box floating in a tank of still water) with a box
    centred in the tank at its Archimedes draft (``rho_b / RHO * height``) raised by
    ``lift`` [m], the tank's walls 3 spacings above the top of the box at its draft.

    ``dim`` 2 (x-z, 1 m thick box) or 3 (square ``width`` x ``width`` box in a square
    tank); ``dx`` [m] particle spacing; ``rho_b`` [kg/m^3] box density; ``width``,
    ``height`` [m] box size; ``tank`` [m] inner tank length (and width in 3-D);
    ``depth`` [m] still-water depth; ``boundary``: "mdbc" or "dbc" for the body;
    ``c0_factor``: c0 / sqrt(g depth). Returns ``(scene, z_eq)`` with ``z_eq`` [m] the
    centre height at the Archimedes draft in water of depth ``depth``."""
    draft = rho_b / RHO * height
    z_eq = depth - draft + 0.5 * height
    across = [0.5 * tank] * (dim - 1)
    size = [width] * (dim - 1) + [height]
    values = [f"world.dim={dim}", f"fluid.dx={number(dx)}", f"fluid.c0_factor={number(c0_factor)}",
              f"fluid.body_boundary={boundary}", f"domain.length={number(tank)}", f"domain.depth={number(depth)}",
              f"domain.height={number(depth + height + 3 * dx)}", f"bodies[0].density={number(rho_b)}",
              f"bodies[0].size=[{', '.join(map(number, size))}]",
              f"bodies[0].pos=[{', '.join(map(number, across + [z_eq + lift]))}]"]
    if dim == 3:
        values.append(f"domain.width={number(tank)}")
    return case_scene.load(case, values), z_eq


def water_level(pos, kind, dx: float, keep_out: float, centre) -> float:
    """Still-water level [m] away from a body, from particle positions ``pos`` (n, dim) [m]
    and kinds ``kind``: the mean over lattice columns (of side ``dx`` [m]) farther than
    ``keep_out`` [m] from ``centre`` (x or (x, y)) of the highest fluid particle, plus half
    a spacing (the particle's cell)."""
    from fluid.particles import Kind

    p = np.asarray(pos)[np.asarray(kind) == Kind.FLUID]
    dim = p.shape[1]
    far = np.abs(p[:, 0] - centre[0]) > keep_out
    if dim == 3:
        far |= np.abs(p[:, 1] - centre[1]) > keep_out
    p = p[far]
    cols = np.floor(p[:, :dim - 1] / dx).astype(np.int64)
    key = cols[:, 0] * 100003 + (cols[:, 1] if dim == 3 else 0)
    _, inv = np.unique(key, return_inverse=True)
    top = np.full(inv.max() + 1, -np.inf)
    np.maximum.at(top, inv, p[:, -1])
    return float(top.mean() + 0.5 * dx)


def settle_draft(dim: int, dx: float, rho_b: float, t_end: float, window: float, **kw) -> dict:
    """Run the scene of :func:`box_scene` (``scenes/floating-box-draft.toml``; ``kw`` its
    keywords) for ``t_end`` [s] and average, over the last ``window``
    [s], the box's draft below the far-field water level. Returns the draft, the
    Archimedes draft and the error as a fraction of the box height."""
    height = kw.get("height", 0.05)
    width = kw.get("width", 0.1)
    tank = kw.get("tank", 0.3)
    scene, _ = box_scene("floating-box-draft", dim, dx, rho_b, **kw)
    centre = [0.5 * tank] * (dim - 1)
    drafts = []
    with case_scene.built(scene) as b:
        coupler, bodies, fluid = b.coupler, b.bodies, b.fluid

        def sample(info):
            if info.t > t_end - window:
                ps = fluid.fluid.ps
                level = water_level(ps.pos, ps.kind, dx, 0.5 * width + 0.05, centre)
                drafts.append(level - (bodies.kinematics().com[0, 2] - 0.5 * height))

        coupler.run(t_end, callback=sample)
    exact = rho_b / RHO * height
    d = float(np.mean(drafts))
    return {"dx_m": dx, "rho_b": rho_b, "draft_m": d, "archimedes_m": exact,
            "error_of_height": (d - exact) / height, "draft_std_m": float(np.std(drafts)),
            "particles": int(fluid.fluid.ps.n), "steps": int(coupler.steps)}


#: the draft case's runs (dim, dx [m], box density [kg/m^3]): each dx divides the box, the draft and the depth
DRAFT_RUNS_FULL = ((2, 0.005, 500.0), (2, 0.005, 800.0), (3, 0.0125, 500.0), (3, 0.01, 800.0))
DRAFT_RUNS_QUICK = ((2, 0.0125, 500.0),)


def draft_scene(quick: bool):
    """The scene of floating-box-draft's first run (the quick variant's only one: the file's)."""
    return box_scene("floating-box-draft", *(DRAFT_RUNS_QUICK if quick else DRAFT_RUNS_FULL)[0])[0]


@case("floating-box-draft", "2-D and 3-D boxes (500, 800 kg/m^3) float at the Archimedes draft within 2 % of the height",
      target="within 2 % of the height after settling",
      quick="the stated target (draft within 2 % of the height) for the 2-D box of 500 kg/m^3 at dx = 12.5 mm "
            "only, instead of 2-D and 3-D boxes of 500 and 800 kg/m^3 at 5-12.5 mm", scene=draft_scene)
def floating_box_draft(quick: bool) -> dict:
    """A 0.10 x 0.05 m box (2-D, 1 m thick; 3-D: 0.10 x 0.10 x 0.05 m) of density 500
    or 800 kg/m^3 in a 0.3 m tank (square in 3-D) of 0.1 m still water, released at
    rest at its Archimedes draft ``rho_b / rho_w x height`` with faces on the fluid's
    lattice (module docstring), mDBC body boundaries, fluid-first coupling: the scene
    ``scenes/floating-box-draft.toml`` (:func:`box_scene` sets each run's). Over 1 s
    (about 2.5 heave periods: a body with wrong loads leaves that position within the
    first) the draft below the far-field water level (:func:`water_level`) is averaged
    over the last 0.5 s. Reference: Archimedes. Target: within 2 % of the height.

    Quick: 2-D, 500 kg/m^3, dx = 12.5 mm (two particle rows in the draft), same 2 %.
    Full: 2-D 500 and 800 at dx = 5 mm, 3-D 500 at 12.5 mm and 800 at 10 mm.

    What limits the error: the body oscillates by a fraction of a millimetre about
    its mean (SPH pressure noise; mDBC's extrapolated boundary pressure follows the
    fluid's noise), and the water level is read from the top particle row (half a
    spacing uncertain at a wave crest, averaged over columns and time).

    Measured (``cosim validate floating-box-draft [--quick]``, see the record):
    quick 2-D 500 at 12.5 mm: -1.3 % of the height (plain DBC: -0.4 %); full: 2-D
    500 and 800 at 5 mm -0.20 % and -0.19 %, 3-D 500 at 12.5 mm -1.86 % (two rows
    in the draft) and 3-D 800 at 10 mm -0.90 % (13 min of CPU in all). Released
    one spacing above the equilibrium instead (``benchmarks/floating_box_sph.py``,
    1.5 s), the error is -3.1 % with mDBC and -6.5 % with plain DBC at 12.5 mm,
    -1.6 % and -2.2 % at 6.25 mm: plain DBC keeps the density the fluid gave its
    boundary particles when the body moved into it, so a moving body rides high.
    """
    runs = DRAFT_RUNS_QUICK if quick else DRAFT_RUNS_FULL
    tol = 0.02
    res = [settle_draft(dim, dx, rho_b, 1.0, 0.5) | {"dim": dim} for dim, dx, rho_b in runs]
    worst = max(abs(r["error_of_height"]) for r in res)
    return {"metrics": {"runs": res, "worst_error_of_height": worst},
            "tolerances": {"worst_error_of_height": tol},
            "particles": max(r["particles"] for r in res), "steps": sum(r["steps"] for r in res)}


def added_mass_rectangle_2d(width: float, draft: float) -> float:
    """Heave added mass [kg/m] of a floating 2-D rectangle of ``width`` and ``draft``
    [m], high-frequency limit: the free surface then acts as a plane of zero
    potential, so the floating section's added mass is half that of the double
    body (``width`` x 2 ``draft``) moving in unbounded fluid, ``C_A rho pi a^2`` with
    ``a = width / 2``, ``C_A`` from DNV-RP-C205 (2010) Table D-1 (rectangle, 2-D),
    interpolated linearly in log(a/b), ``b = draft`` the half-height along the motion."""
    ab = np.array([0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0])  # a/b
    ca = np.array([2.23, 1.98, 1.70, 1.51, 1.36, 1.21, 1.14])
    r = 0.5 * width / draft
    if not ab[0] <= r <= ab[-1]:
        raise ValueError(f"a/b = {r} is outside DNV-RP-C205 Table D-1 (0.1 ... 10)")
    c = float(np.interp(math.log(r), np.log(ab), ca))
    return 0.5 * c * RHO * math.pi * (0.5 * width) ** 2


def fit_decay(t, z):
    """Least-squares fit of a damped oscillation ``z_m + A exp(-zeta w t) cos(w_d t + phi)``,
    ``w_d = w sqrt(1 - zeta^2)``; returns (z_m [m], A [m], zeta [-], w [rad/s], rms [m])."""
    from scipy.optimize import curve_fit

    def f(t, zm, A, zeta, w, ph):
        return zm + A * np.exp(-zeta * w * t) * np.cos(w * np.sqrt(max(1 - zeta * zeta, 1e-9)) * t + ph)

    zm0 = float(np.mean(z))
    # initial frequency from the first two mean crossings
    y = z - zm0
    cross = np.flatnonzero(np.sign(y[:-1]) != np.sign(y[1:]))
    w0 = math.pi / (t[cross[1]] - t[cross[0]]) if len(cross) > 1 else 2 * math.pi / (t[-1] - t[0])
    p, _ = curve_fit(f, t, z, p0=[zm0, z[0] - zm0, 0.1, w0, 0.0], maxfev=20000)
    return (*(float(v) for v in p[:4]), float(np.std(z - f(t, *p))))


#: the heave-period case's box (width, height [m], density [kg/m^3]), its lift [m] and tank
#: (length, depth [m]); its spacings [m], quick and full
HEAVE_BOX, HEAVE_LIFT, HEAVE_TANK, HEAVE_DX = (0.1, 0.05, 500.0), 0.0125, (0.6, 0.2), (0.0125, 0.00625)


def heave_scene(quick: bool):
    """The scene of floating-heave-period (``scenes/floating-heave-period.toml``, the quick
    variant's) at the variant's spacing, and the Archimedes centre height [m]."""
    (width, height, rho_b), (tank, depth) = HEAVE_BOX, HEAVE_TANK
    return box_scene("floating-heave-period", 2, HEAVE_DX[0 if quick else 1], rho_b, width=width, height=height,
                     tank=tank, depth=depth, lift=HEAVE_LIFT)


@case("floating-heave-period", "2-D box released from a heave offset: natural period within 10 % of "
      "2 pi sqrt((m + a33) / (rho g A_w))", target="within 10 %",
      quick="the stated target (period within 10 %, the damped-oscillation fit within 10 % of its amplitude) "
            "at dx = 12.5 mm instead of 6.25 mm", scene=lambda quick: heave_scene(quick)[0])
def floating_heave_period(quick: bool) -> dict:
    """The 0.10 x 0.05 m box of 500 kg/m^3 (2-D, 1 m thick) in a 0.6 m tank of 0.2 m
    water, released at rest 12.5 mm above its Archimedes position (half its draft;
    its faces on the lattice): the scene :func:`heave_scene`. A damped oscillation is fitted to the heave over the
    first second, before the waves it radiates come back from the walls
    (group speed g / 2 omega ~ 0.45 m/s over 2 x 0.25 m); its undamped natural period
    ``2 pi / omega`` is compared with ``T = 2 pi sqrt((m + a33) / (rho g B))``,
    m = 2.5 kg/m, rho g B = 981 N/m^2 (per metre), a33 from
    :func:`added_mass_rectangle_2d` (DNV-RP-C205 Table D-1, B / T = 4: a/b = 2,
    C_A = 1.36, a33 = 5.34 kg/m, the high-frequency limit), T = 0.562 s.

    What limits the comparison: a33 is the infinite-frequency value, and the box
    oscillates at omega^2 B / 2g ~ 0.65, where a 2-D section's heave added mass
    differs from that limit (Vugts 1968 measured it frequency dependent); the
    amplitude is half the draft (the stiffness is linear for a wall-sided box, the
    damping is not); the tank is 6 beams long and 8 drafts deep, not unbounded.

    Measured (``cosim validate floating-heave-period [--quick]``): dx = 12.5 mm,
    T_n = 0.574 s (+2.2 %); dx = 6.25 mm, T_n = 0.577 s (+2.7 %); damping ratio 0.18
    at both.
    """
    dx = HEAVE_DX[0 if quick else 1]
    width, height, rho_b = HEAVE_BOX
    scene, z_eq = heave_scene(quick)
    with case_scene.built(scene) as b:
        coupler, bodies, fluid = b.coupler, b.bodies, b.fluid
        t, z = [0.0], [bodies.kinematics().com[0, 2]]
        coupler.run(1.0, callback=lambda i: (t.append(i.t), z.append(bodies.kinematics().com[0, 2])))
    zm, amp, zeta, w, rms = fit_decay(np.array(t), np.array(z))
    m = rho_b * width * height
    a33 = added_mass_rectangle_2d(width, rho_b / RHO * height)
    t_ref = 2 * math.pi * math.sqrt((m + a33) / (RHO * G * width))
    err = 2 * math.pi / w / t_ref - 1
    tol = 0.10
    t_fit = np.array(t)
    z_fit = zm + amp * np.exp(-zeta * w * t_fit) * np.cos(w * math.sqrt(max(1 - zeta * zeta, 1e-9)) * t_fit)
    series = {"heave": {"xlabel": "t [s]", "ylabel": "centre height - Archimedes [mm]", "curves": {
        "SPH (ours)": {"x": t_fit, "y": (np.array(z) - z_eq) * 1e3},
        "fitted damped oscillation": {"x": t_fit, "y": (z_fit - z_eq) * 1e3, "style": "--"}}}}
    return {"metrics": {"dx_m": dx, "period_s": 2 * math.pi / w, "reference_period_s": t_ref,
                        "period_error": err, "damping_ratio": zeta, "added_mass_kg_per_m": a33,
                        "mass_kg_per_m": m, "fit_amplitude_m": amp, "fit_rms_m": rms,
                        "fit_rms_over_amplitude": rms / abs(amp),
                        "mean_centre_m": zm, "archimedes_centre_m": z_eq},
            "tolerances": {"period_error": tol, "fit_rms_over_amplitude": 0.1}, "series": series,
            "particles": int(fluid.fluid.ps.n), "steps": int(coupler.steps)}


def sinking_scene(dx: float, t_end: float, *, radius: float = 1.0, rho_c: float = 1200.0,
                  tank: float = 6.0, depth: float = 4.0, boundary: str = "mdbc"):
    """Barreiro et al. 2016, §4.1 (after Fekken 2004), the scene ``scenes/sinking-cylinder.toml``:
    a 2-D cylinder of ``radius`` [m] and density ``rho_c`` [kg/m^3], centre on the
    still-water surface (half submerged), released at rest in the middle of a ``tank``
    [m] long tank of ``depth`` [m] water (walls ``depth + 1.5 radius`` high); ``dx`` [m]
    spacing, ``t_end`` [s] long; ``boundary``: "mdbc" or "dbc" for the body."""
    return case_scene.load("sinking-cylinder", [
        f"fluid.dx={number(dx)}", f"fluid.body_boundary={boundary}", f"domain.length={number(tank)}",
        f"domain.depth={number(depth)}", f"domain.height={number(depth + 1.5 * radius)}",
        f"bodies[0].radius={number(radius)}", f"bodies[0].density={number(rho_c)}",
        f"bodies[0].pos=[{number(0.5 * tank)}, {number(depth)}]", f"world.duration={number(t_end)}"])


def sinking_cylinder(dx: float, t_end: float, **kw):
    """Run :func:`sinking_scene` (``kw`` its keywords) for ``t_end`` [s]. Returns the time
    [s], the centre's depth below its start [m] and its downward velocity [m/s] at every
    coupling step, the coupler and the fluid."""
    scene = sinking_scene(dx, t_end, **kw)
    z0 = scene.bodies[0].pos[1]  # the centre's start height
    t, s, v = [0.0], [0.0], [0.0]
    with case_scene.built(scene) as built:
        coupler, bodies, fluid = built.coupler, built.bodies, built.fluid

        def record(info):
            k = bodies.kinematics()
            t.append(info.t)
            s.append(z0 - k.com[0, 2])
            v.append(-k.velocity[0, 2])

        coupler.run(t_end, callback=record)
    return np.array(t), np.array(s), np.array(v), coupler, fluid


def sinking_cylinder_reference(t, radius: float = 1.0, rho_c: float = 1200.0):
    """Downward velocity [m/s] at times ``t`` [s] of a 2-D cylinder released from rest
    with its centre on the free surface, from ``(m + a33) dv/dt = (m - rho A(s)) g``:
    ``A(s)`` the exact submerged area of the circle with its centre ``s`` below the
    surface (``pi r^2 / 2 + r^2 asin(s/r) + s sqrt(r^2 - s^2)``), ``a33 = rho pi r^2 / 2``
    the impulsive added mass of the half-submerged circle (at the first instant the
    free surface is a plane of zero potential: half the added mass rho pi r^2 of the
    full circle in unbounded fluid). Exact at t = 0 (a0 = (rho_c - rho/2) /
    (rho_c + rho/2) g); later it omits the growth of a33 with submergence and the
    waves, both of which slow the cylinder (estimated -5 % in velocity by 0.25 s)."""
    from scipy.integrate import solve_ivp

    m = rho_c * math.pi * radius**2
    a33 = 0.5 * RHO * math.pi * radius**2

    def rhs(_, y):
        s = min(max(y[0], -radius), radius)
        area = 0.5 * math.pi * radius**2 + radius**2 * math.asin(s / radius) + s * math.sqrt(radius**2 - s * s)
        return [y[1], (m - RHO * area) * G / (m + a33)]

    t = np.asarray(t, float)
    sol = solve_ivp(rhs, (0.0, float(t.max())), [0.0, 0.0], t_eval=t, rtol=1e-10, atol=1e-12)
    return sol.y[1]


#: the sinking cylinder's spacing [m] and duration [s], by variant (quick: True)
SINKING_RUN = {True: (0.1, 0.25), False: (0.05, 1.0)}


@case("sinking-cylinder", "2-D cylinder r = 1 m, 1200 kg/m^3, half submerged, released: velocity over the first "
      "0.25 s vs added-mass + buoyancy model; trajectory over 1 s recorded",
      target="find the data; match within 10 % over the first second",
      quick="dx = 0.1 m (20 particles across), 0.25 s: the velocity over the first 0.25 s within 20 % of the "
            "added-mass + buoyancy model (least-squares ratio), what 20 particles across meet",
      scene=lambda quick: sinking_scene(*SINKING_RUN[quick]))
def sinking_cylinder_case(quick: bool) -> dict:
    """Barreiro et al. 2016, §4.1 (Fig. 8) compares DualSPHysics with
    Fekken's (2004, PhD thesis, Groningen) VOF displacement and velocity of this
    cylinder but prints no numbers, and we found no published table of Fekken's
    curves: the comparison with them over the first second is NOT made here (the
    trajectory at 0.25 ... 1 s is recorded for it). What is compared: the velocity
    over the first 0.25 s (0.78 sqrt(r/g); the centre sinks 11 % of the radius)
    against :func:`sinking_cylinder_reference`, exact at release
    (a0 = 700/1700 g = 4.04 m/s^2) and carrying the exact buoyancy after it, by the
    least-squares ratio ``sum v v_ref / sum v_ref^2``. Target 10 % (full, dx = 0.05 m,
    40 particles across, 1 s, 6 m tank of 4 m water); quick: dx = 0.1 m, 0.25 s,
    20 % (what 20 particles across meet). The set-up: :func:`sinking_scene`.

    What limits the error: the model omits the growth of the added mass with
    submergence and the radiated waves (both slow the cylinder, ~5 % by 0.25 s);
    the SPH velocity rings with the tank's acoustic mode (period ~4 depth / c0 =
    0.13 s) around the trend, hence the fit over two periods rather than a point;
    fluid removed around the circle leaves the first fluid particles 0.5 ... 1.2
    spacings from the surface (a circle cannot lie on the lattice) at release.

    Measured (``cosim validate sinking-cylinder [--quick]``): velocity ratio 0.850
    (-15.0 %) at dx = 0.1 m and 0.881 (-11.9 %) at dx = 0.05 m: the full variant
    misses the 10 % target against this model, converging towards it; v(0.2 s) =
    0.66, 0.71 m/s against the model's 0.79 m/s. Trajectory at dx = 0.05 m: depth
    0.39 m and 1.31 m/s at 0.5 s, 0.74 m and 1.44 m/s at 0.75 s, 1.09 m and 1.36 m/s
    at 1 s.
    """
    dx, t_end = SINKING_RUN[quick]
    t, s, v, coupler, fluid = sinking_cylinder(dx, t_end)
    early = (t > 0) & (t <= 0.25)
    v_ref = sinking_cylinder_reference(t[early])
    ratio = float(np.sum(v[early] * v_ref) / np.sum(v_ref**2))  # least-squares v = ratio * v_ref
    err = ratio - 1
    samples = {f"{tt:g}s": {"depth_m": float(np.interp(tt, t, s)), "velocity_m_s": float(np.interp(tt, t, v)),
                            **({"reference_velocity_m_s": float(sinking_cylinder_reference([tt])[0])}
                               if tt <= 0.25 else {})}
               for tt in (0.05, 0.1, 0.15, 0.2, 0.25, 0.5, 0.75, 1.0) if tt <= t[-1] + 1e-9}
    tol = 0.20 if quick else 0.10
    series = {"downward velocity": {"xlabel": "t [s]", "ylabel": "v [m/s]", "curves": {
        "added-mass + buoyancy model (valid early)": {"x": t[t > 0], "y": sinking_cylinder_reference(t[t > 0]),
                                                      "style": "--"},
        "SPH (ours)": {"x": t, "y": v}}}}
    return {"series": series,
            "stated_tolerances": {"fekken_2004_velocity_error": 0.10},
            "departure": {
                "criterion": "the velocity over the first 0.25 s within 10 % (quick: 20 %) of an added-mass + "
                             "buoyancy model (exact at release), by the least-squares ratio",
                "why": "Barreiro et al. 2016, §4.1 plots Fekken's (2004) VOF displacement and velocity but prints no numbers, "
                       "and no published table of them was found: the comparison over the first second with "
                       "the published data is not made (the trajectory is recorded for it)",
                "stated_measured": {"fekken_2004_velocity_error": None}, "stated_met": None,
                "source": "not measured: no published numbers of Fekken (2004) found"},
            "metrics": {"dx_m": dx, "velocity_ratio_0_to_0.25s": ratio, "velocity_error": err,
                        "initial_acceleration_reference_m_s2": (1200.0 - 0.5 * RHO) / (1200.0 + 0.5 * RHO) * G,
                        "trajectory": samples,
                        "fekken_2004_comparison": "not made: no published numbers found"},
            "tolerances": {"velocity_error": tol},
            "particles": int(fluid.fluid.ps.n), "steps": int(coupler.steps)}
