"""Tanks of Sunara et al. 2021 beyond the vertical wall (VALIDATION.md, "Fluid"): the inclined side
(Sunara et al. 2021, §3.2) and the cylinder (§3.3) under horizontal base excitation."""

from __future__ import annotations

import math

import numpy as np

from cosim import refdata
from cosim.validations import case_scene
from cosim.validations.registry import case
from cosim.validations.sloshing import _harmonic_fit, face_pressure
from cosim.validations.tank_potential import wall_profiles
from fluid.geometry import assemble, set_hydrostatic
from fluid.motion import Harmonic, Translation
from fluid.particles import Kind
from fluid.shapes import cylinder_tank, inclined_tank
from fluid.solver import Fluid, FluidConfig

G = 9.81
RHO0 = 1000.0
ANGLES = (15.0, 30.0, 45.0)


def chwang_profile(beta_deg: float) -> tuple[np.ndarray, np.ndarray]:
    """(y/H, k_p) on an inclined dam face ``beta_deg`` from the vertical, Chwang's
    semi-infinite reservoir (refdata analytic_hydrodynamics/inclined_dam_Cp_FEM_thiswork.csv,
    which tabulates theta = 90 - beta, the face's angle with the horizontal)."""
    text = refdata.path("analytic_hydrodynamics", "inclined_dam_Cp_FEM_thiswork.csv").read_text().splitlines()
    rows = np.genfromtxt([s for s in text if not s.startswith("#")], delimiter=",", names=True)
    theta = 90.0 - beta_deg
    hit = np.flatnonzero(np.isclose(rows["theta_deg"], theta))
    if hit.size == 0:
        raise ValueError(f"no tabulated face at {beta_deg} deg from the vertical (theta = {theta} deg)")
    row = rows[hit[0]]
    y = np.linspace(0.0, 1.0, 11)
    return y, np.array([row[f"Cp_y{k // 10}{k % 10}H"] for k in range(0, 11)])


def moving_walls(built, dim: int, dx: float, wall_top: float | None = None):
    """The particles of a tank (a :class:`fluid.geometry.Built` with FIXED walls) with its
    walls one MOVING_WALL group 0, those above ``wall_top`` [m] (None: all kept) left out;
    water at rest, its hydrostatic density left to the caller."""
    src = built.particles
    fl = src.kind == Kind.FLUID
    walls = src.pos[~fl]
    if wall_top is not None:
        walls = walls[walls[:, -1] <= wall_top]
    return assemble(dim, dx, RHO0, src.pos[fl], [(walls, Kind.MOVING_WALL, 0)]).particles


def _shaken_tank(built, dim: int, dx: float, depth: float, c0: float, a0: float, Tp: float,
                 wall_top: float | None = None, **overrides):
    """The fluid of a tank (a :class:`fluid.geometry.Built` with FIXED walls) whose walls,
    one MOVING group, follow the base acceleration ``a0 sin(2 pi t / Tp)`` along +x from
    rest, the water at hydrostatic density: (fluid, the motion, its config). Wall
    particles above ``wall_top`` [m] (None: all kept) are left out (:func:`moving_walls`)."""
    ps = moving_walls(built, dim, dx, wall_top)
    cfg = FluidConfig(dim=dim, dx=dx, c0=c0, **overrides)
    set_hydrostatic(ps, depth, RHO0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    f = Fluid(cfg, ps)
    shake = Translation(tuple(np.eye(dim)[0]), Harmonic.from_peak_acceleration(a0, Tp, from_rest=True))
    f.prescribe_motion(0, shake)
    f.initialize(0.0)
    return f, shake, cfg


def _face_amplitudes(f, shake, cfg, faces: dict, Tp: float, samples_per_period: int, periods_skip: int,
                     periods_fit: int) -> dict:
    """Run ``f`` and fit ``c0 + c1 t + s sin(w t) + k cos(w t)`` to the face pressure
    (:func:`face_pressure`, points carried by the tank) at each group of ``faces`` ({name:
    (points (m, dim), normals (dim,) or (m, dim))}) over ``periods_fit`` periods after
    ``periods_skip``: {name: (s, k)} [Pa]."""
    dt_s = Tp / samples_per_period
    n_skip, n_fit = periods_skip * samples_per_period, periods_fit * samples_per_period
    rec = {k: [] for k in faces}
    times = []
    t = 0.0
    for i in range(n_skip + n_fit):
        f.advance(t, dt_s)
        t = (i + 1) * dt_s
        if i + 1 <= n_skip:
            continue
        for k, (pts, n) in faces.items():
            here = shake(t, pts)[0]
            rec[k].append(face_pressure(f, here, here, n, shake.acceleration(t), cfg.gravity))
        times.append(t)
    return {k: _harmonic_fit(np.asarray(times), np.asarray(v), 2 * math.pi / Tp) for k, v in rec.items()}


def run_inclined(beta_deg: float, dx: float, c0: float = 1430.0, periods_skip: int = 2, periods_fit: int = 3,
                 samples_per_period: int = 40, a0: float = 0.5 * G, Tp: float = 0.03, length: float = 3.0,
                 H: float = 1.0, height: float = 1.5, dim: int = 2, rows: int = 3, **overrides) -> dict:
    """The 2-D section of Sunara et al. 2021, §3.2's tank: bottom ``length`` [m], vertical left side, right
    side inclined ``beta_deg`` from the vertical leaning outwards (:func:`fluid.shapes.inclined_tank`,
    walls offset from the true outline, one layer of fluid conforming to them), water
    ``H`` [m], under the base acceleration ``a0 sin(2 pi t / Tp)`` from rest, c0 [m/s]
    the paper's (Eq. 17). The flow is uniform across the 3-D tank's width (its front and
    back are parallel planes), so the section is the 3-D problem for inviscid water.

    Extraction as :func:`cosim.validations.sloshing.run_westergaard`: at face points every
    dx in height on both sides, the fluid pressure carried to the face (``face_pressure``,
    Sunara et al. 2021, Eq. 15 with the wall's momentum balance), fitted with ``c0 + c1 t + s sin(w t) +
    k cos(w t)`` over ``periods_fit`` periods after ``periods_skip``; k_p = s / (rho a0 H)
    on the left side and -s / (rho a0 H) on the inclined one (positive where the tank
    accelerates towards the water, Sunara et al. 2021, Eq. 18).

    References: Chwang's semi-infinite reservoir (refdata, :func:`chwang_profile`), the
    criterion the issue states; and the exact incompressible pressure of this finite tank
    (:func:`cosim.validations.tank_potential.wall_profiles`, 1-3 % below Chwang's at the
    base for L = 3 m) on both sides: what a perfect model of the tank would give.

    ``dim=3``: a slice of the 3-D tank ``rows`` (odd) fluid rows wide (width rows * dx)
    between its front and back walls (:func:`fluid.shapes.inclined_tank` extruded along
    y, 3 wall layers each side), k_p read on the middle row's plane. The wall particles
    higher than ``H + 3 dx`` are left out: they lie beyond the kernel's reach (2h = 2.83
    dx) of the water, whose surface moves ~0.1 mm at this period, and would be 40 % of
    the slice's particles.
    """
    if dim not in (2, 3):
        raise ValueError(f"dim must be 2 or 3, got {dim}")
    if dim == 3 and not (rows >= 1 and rows % 2 == 1):
        raise ValueError(f"rows (fluid rows across the 3-D slice) must be odd and >= 1 so that one lies on the "
                         f"mid-plane, got {rows}")
    width = rows * dx
    built = inclined_tank(dim, dx, beta_deg, length, H, height, width=width) if dim == 3 else \
        inclined_tank(2, dx, beta_deg, length, H, height)
    f, shake, cfg = _shaken_tank(built, dim, dx, H, c0, a0, Tp, wall_top=H + 3 * dx if dim == 3 else None,
                                 **overrides)
    return _inclined_profile(f, shake, cfg, beta_deg, length, H, a0, Tp, width if dim == 3 else None,
                             samples_per_period, periods_skip, periods_fit)


def _inclined_profile(f, shake, cfg, beta_deg: float, length: float, H: float, a0: float, Tp: float,
                      width: float | None, samples_per_period: int, periods_skip: int, periods_fit: int) -> dict:
    """Run the shaken inclined tank ``f`` (initialised at t = 0; its walls following
    ``shake``, the base acceleration ``a0 sin(2 pi t / Tp)``; bottom ``length`` [m], right
    side ``beta_deg`` from the vertical, water ``H`` [m]; ``width`` [m]: a 3-D slice's, None
    in 2-D) and fit k_p at the face points on both sides as :func:`run_inclined` describes;
    its metrics, counts and profiles."""
    dim, dx, c0 = cfg.dim, cfg.dx, cfg.speed_of_sound
    b = math.radians(beta_deg)
    z = dx * (0.5 + np.arange(int(math.floor(H / dx))))
    def on_plane(x, zz):  # face points (x, z) on the section, or on the 3-D slice's mid-plane
        return np.stack([x, zz], 1) if dim == 2 else np.stack([x, np.full_like(zz, 0.5 * width), zz], 1)

    nl = np.eye(dim)[0]
    nr = np.array([-math.cos(b), math.sin(b)]) if dim == 2 else np.array([-math.cos(b), 0.0, math.sin(b)])
    sides = {"left": (on_plane(np.zeros_like(z), z), nl), "right": (on_plane(length + z * math.tan(b), z), nr)}
    fits = _face_amplitudes(f, shake, cfg, sides, Tp, samples_per_period, periods_skip, periods_fit)
    scale = RHO0 * a0 * H
    kp, kout = {}, {}
    for k, sign in (("left", 1.0), ("right", -1.0)):
        s, c = fits[k]
        kp[k], kout[k] = sign * s / scale, np.abs(c) / scale
    tank = wall_profiles(length, H, beta_deg)
    ref = {"left_tank": np.interp(z, tank["z"], tank["left"]), "right_tank": np.interp(z, tank["z"], tank["right"])}
    yc, cp = chwang_profile(beta_deg)
    ref["right_chwang"] = np.interp(z / H, yc, cp)
    rms = lambda a, r: float(np.sqrt(np.mean((a - r) ** 2)))
    metrics = {"rms_right_vs_chwang": rms(kp["right"], ref["right_chwang"]),
               "rms_right_vs_tank": rms(kp["right"], ref["right_tank"]),
               "rms_left_vs_tank": rms(kp["left"], ref["left_tank"]),
               "kp_max_right": float(kp["right"].max()), "kp_max_right_tank": float(ref["right_tank"].max()),
               "kp_max_right_chwang": float(cp.max()),
               "kp_out_of_phase_max": float(max(kout["left"].max(), kout["right"].max())),
               "beta_deg": beta_deg, "dx_m": dx, "c0_m_s": c0, "rows": int(z.size),
               "max_speed_m_s": float(f.max_speed())}
    if dim == 3:
        metrics["width_m"] = width
    return {"metrics": metrics, "particles": int(f.ps.n), "steps": int(f.counters.steps),
            "profile": {"z_m": z.tolist(), "kp_left": kp["left"].tolist(), "kp_right": kp["right"].tolist(),
                        **{f"kp_{k}": v.tolist() for k, v in ref.items()}}}


#: the stated target of the inclined-wall row of docs/VALIDATION.md
INCLINED_TARGET = ("RMS of k_p along the inclined face against Chwang's exact theory (refdata "
                   "inclined_dam_Cp_FEM_thiswork.csv) < 0.04 at 15, 30 and 45 deg")


def inclined_series_plot(profiles: dict) -> dict:
    """The report's plot: k_p up the inclined face per angle, ours against Chwang's
    semi-infinite reservoir and the exact pressure of this tank."""
    curves = {}
    for beta, p in profiles.items():
        z = p["z_m"]
        curves[f"{beta:g} deg: SPH (ours)"] = {"x": p["kp_right"], "y": z, "style": "o-"}
        curves[f"{beta:g} deg: Chwang (refdata)"] = {"x": p["kp_right_chwang"], "y": z, "style": "--"}
        curves[f"{beta:g} deg: this tank, exact"] = {"x": p["kp_right_tank"], "y": z, "style": ":"}
    return {"inclined face": {"xlabel": "k_p = p_d / (rho a0 H)", "ylabel": "height above the bottom [m]",
                              "curves": curves}}


def inclined_scene(quick: bool, beta_deg: float = 45.0):
    """The scene ``scenes/inclined-wall.toml`` (the quick variant's 45 deg tank: dx = 0.1 m,
    3 periods; the full variant's: dx = 0.05 m, 5 periods) with its right side ``beta_deg``
    [deg] from the vertical and its pressure patch moved with the slope (0.25 m above the
    bottom)."""
    n = case_scene.number
    b = math.radians(beta_deg)
    dx, periods = (0.1, 3) if quick else (0.05, 5)
    scene = case_scene.load("inclined-wall")
    patch = (f'probes.pressure=[{{name = "slope", centre = [{n(scene.domain.length + 0.25 * math.tan(b))}, 0.25], '
             f'normal = [{n(-math.cos(b))}, {n(math.sin(b))}], size = 0.3}}]')
    return case_scene.load("inclined-wall", [f"fluid.dx={n(dx)}", f"domain.angle={n(beta_deg)}", patch,
                                             f"world.duration={n(periods * scene.base_motion.period)}"])


@case("inclined-wall", "2-D section of Sunara et al. 2021, §3.2's tank (bottom 3.0 m, right side 15/30/45 deg from the vertical, "
      "water 1.0 m), base acceleration 0.5 g sin(2 pi t / 0.03 s): k_p up the inclined face vs Chwang's exact "
      "theory, RMS < 0.04", target=INCLINED_TARGET,
      quick="dx = 0.1 m (10 rows), 1 + 2 periods: k_p up the inclined face within 0.06 RMS of Chwang's theory at "
            "each angle (first-order errors of ~dx/H, as westergaard's quick variant: the stated 0.04 is met at the "
            "paper's dx = 0.05 m, the full variant)", scene=inclined_scene)
def inclined_wall(quick: bool) -> dict:
    """Sunara et al. 2021, §3.2 (Fig. 12): the scene :func:`inclined_scene` at each angle (the
    tank of :func:`run_inclined`), read by :func:`run_inclined_scene`; see :func:`run_inclined`
    for the set-up and the extraction. c0 = 1430 m/s (the paper's), tank walls carrying the
    fluid's pressure (``walls="adami"``, as the westergaard case), the solver's other
    defaults (h = sqrt(2) dx: 45 deg at dx = 0.1 m, 0.0055 RMS against 0.0113 at h = 2 dx; at
    dx = 0.025 m the slope's pressure grows noisy, so the chooser gives a scene of this kind
    h = 2 dx, "sloshing": docs/setup_chooser.md); 40 samples a period. Judged: the RMS of k_p
    up the inclined face against Chwang's semi-infinite reservoir at each angle; reported
    beside it, the RMS against the exact pressure of this finite tank on both sides (the 3 m
    tank's inclined face carries 1-3 % less than Chwang's reservoir at the base).

    The errors are largest on the steepest face (15 deg: the face k_p scatters by +-0.03 from
    row to row); the measured table (``cosim validate inclined-wall [--quick]``):
    docs/validation/inclined-wall_history.md.
    """
    dx = 0.1 if quick else 0.05
    metrics, profiles, particles, steps = {}, {}, 0, 0
    for beta in ANGLES:
        r = run_inclined_scene(inclined_scene(quick, beta), periods_skip=1 if quick else 2)
        for k, v in r["metrics"].items():
            if k not in ("dx_m", "c0_m_s", "beta_deg"):
                metrics[f"{k}_{beta:g}"] = v
        profiles[beta] = r["profile"]
        particles, steps = max(particles, r["particles"]), steps + r["steps"]
    metrics.update({"dx_m": dx, "c0_m_s": 1430.0})
    out = {"metrics": metrics, "tolerances": {f"rms_right_vs_chwang_{b:g}": 0.04 for b in ANGLES},
           "particles": particles, "steps": steps, "series": inclined_series_plot(profiles)}
    if quick:
        out["stated_tolerances"] = out["tolerances"]
        out["tolerances"] = {f"rms_right_vs_chwang_{b:g}": 0.06 for b in ANGLES}
    return out


def inclined_3d_series_plot(profiles: dict, sections: dict | None = None) -> dict:
    """The report's plot of the 3-D slice: k_p up the inclined face per angle, ours on the
    slice's mid-plane against Chwang, the exact pressure of this tank and (``sections``,
    where given) the 2-D section run with the same settings."""
    plot = inclined_series_plot(profiles)
    curves = plot["inclined face"]["curves"]
    for beta, p in profiles.items():
        curves[f"{beta:g} deg: SPH 3-D slice, mid-plane (ours)"] = curves.pop(f"{beta:g} deg: SPH (ours)")
        if sections and beta in sections:
            curves[f"{beta:g} deg: SPH 2-D section, same settings"] = {
                "x": sections[beta]["kp_right"], "y": sections[beta]["z_m"], "style": "x--"}
    return plot


#: the 3-D slice by variant (quick: True): spacing [m], speed of sound [m/s], the angles run [deg]
INCLINED_3D_RUNS = {True: (0.1, 700.0, (45.0,)), False: (0.05, 1430.0, ANGLES)}
#: fluid rows across the 3-D slice (odd: one on the mid-plane)
SLICE_ROWS = 3


def inclined_3d_scene(quick: bool, beta_deg: float = 45.0):
    """The scene ``scenes/inclined-wall-3d.toml`` (the quick variant's 45 deg slice) with the
    variant's spacing and speed of sound (:data:`INCLINED_3D_RUNS`), a slice
    :data:`SLICE_ROWS` rows wide, its right side ``beta_deg`` [deg] from the vertical and its
    pressure patch moved with the slope (0.25 m above the bottom, on the mid-plane)."""
    n = case_scene.number
    dx, c0, _ = INCLINED_3D_RUNS[quick]
    width, b = SLICE_ROWS * dx, math.radians(beta_deg)
    length = case_scene.load("inclined-wall-3d").domain.length
    patch = (f'probes.pressure=[{{name = "slope", centre = [{n(length + 0.25 * math.tan(b))}, {n(0.5 * width)}, '
             f'0.25], normal = [{n(-math.cos(b))}, 0.0, {n(math.sin(b))}], size = 0.2}}]')
    return case_scene.load("inclined-wall-3d", [f"fluid.dx={n(dx)}", f"fluid.c0={n(c0)}", f"domain.width={n(width)}",
                                                f"domain.angle={n(beta_deg)}", patch])


def run_inclined_scene(scene, periods_skip: int = 1) -> dict:
    """The inclined tank of ``scene`` (:func:`inclined_3d_scene`, or its
    :func:`~cosim.validations.case_scene.section`), built as ``cosim run`` builds it and read
    as :func:`run_inclined` reads its tank: k_p fitted over the scene's periods after
    ``periods_skip`` of them, sampled at its ``world.sample_every``, on the slice's mid-plane
    in 3-D."""
    d, shake = scene.domain, scene.base_motion
    samples, periods = case_scene.shaken_samples(scene)
    with case_scene.built(scene) as b:
        f = b.sph
        return _inclined_profile(f, b.base_motion, f.config, d.angle, d.length, d.depth, shake.acceleration,
                                 shake.period, d.width if scene.world.dim == 3 else None, samples, periods_skip,
                                 periods - periods_skip)


@case("inclined-wall-3d", "3-D tank of Sunara et al. 2021, §3.2 (bottom 3.0 m, right side 15/30/45 deg from the vertical, water "
      "1.0 m), a slice 3 particle rows wide between its front and back walls, base acceleration 0.5 g "
      "sin(2 pi t / 0.03 s): k_p up the inclined face on the mid-plane vs Chwang's exact theory, RMS < 0.04",
      target=INCLINED_TARGET, row="inclined-wall",
      quick="the 45 deg tank only, dx = 0.1 m (a 0.3 m slice), c0 = 700 m/s, 1 + 1 periods: k_p up the inclined "
            "face within the stated 0.04 RMS of Chwang's theory, within 0.04 of the 2-D section run with the "
            "same settings row by row, the out-of-phase part below 0.05",
      scene=lambda quick: inclined_3d_scene(quick, INCLINED_3D_RUNS[quick][2][0]))
def inclined_wall_3d(quick: bool) -> dict:
    """Sunara et al. 2021, §3.2 (Fig. 12) in 3-D: the scene ``scenes/inclined-wall-3d.toml``
    (:func:`inclined_3d_scene`), a slice of the tank 3 fluid rows wide (3 dx: 0.15 m at dx =
    0.05 m) between front and back walls of 3 layers, read by :func:`run_inclined_scene`:
    k_p on the mid-plane; c0 = 1430 m/s, ``walls="adami"``, the solver's other defaults, 40
    samples a period, 1 period skipped and 1 fitted (quick: 45 deg only, dx = 0.1 m, c0 =
    700 m/s, 1 + 1, and the 2-D section with the same settings beside it,
    :func:`~cosim.validations.case_scene.section`).
    Why a slice and not the whole 1.0 m width: the front and back walls are parallel to the
    shaking, so in theory the flow is uniform across and any width is the same problem; the
    whole vertical tank (``westergaard-3d``) measures what the side walls do to k_p in this
    solver (see there), and a slice costs 1/7 of the whole width. The solver has no periodic
    boundaries, so the slice keeps its walls, to their full height (:func:`run_inclined`
    leaves out those above H + 3 dx, beyond the kernel's reach of water whose surface moves
    ~0.1 mm: the same k_p to 1e-10, 10 % fewer particles at dx = 0.1 m). Judged as
    ``inclined-wall``: the RMS of k_p up the inclined face against Chwang's semi-infinite
    reservoir at each angle; reported beside it, the RMS against the exact pressure of this
    finite tank (:mod:`cosim.validations.tank_potential`) on both sides.

    At the full variant's dx = 0.05 m the stated 0.04 is met at every angle, and the slice's
    RMS is within 0.005 of the 2-D section's (its walls hold the section's own points); the
    steepest face (15 deg) errs most. The measured trade (``python benchmarks/tanks_3d_trade.py
    inclined --dx DX --angle BETA``), the quick variant and the figures:
    docs/validation/inclined-wall-3d_history.md.

    Measured trade: ``docs/validation/inclined-wall-3d_trade.md`` (on the case's report page).
    """
    dx, c0, angles = INCLINED_3D_RUNS[quick]
    runs = {beta: inclined_3d_scene(quick, beta) for beta in angles}
    metrics, profiles, particles, steps = {}, {}, 0, 0
    for beta, scene in runs.items():
        r = run_inclined_scene(scene)
        for k, v in r["metrics"].items():
            if k not in ("dx_m", "c0_m_s", "beta_deg", "width_m"):
                metrics[f"{k}_{beta:g}"] = v
        profiles[beta] = r["profile"]
        particles, steps = max(particles, r["particles"]), steps + r["steps"]
    sections = None
    if quick:  # the 2-D section with the same settings beside the slice
        sections = {45.0: run_inclined_scene(case_scene.section(runs[45.0]))}
        for side in ("left", "right"):
            d = np.abs(np.asarray(profiles[45.0][f"kp_{side}"]) - np.asarray(sections[45.0]["profile"][f"kp_{side}"]))
            metrics[f"kp_{side}_vs_2d_max_45"] = float(d.max())
        metrics["rms_right_vs_chwang_2d_45"] = sections[45.0]["metrics"]["rms_right_vs_chwang"]
    metrics.update({"dx_m": dx, "c0_m_s": c0, "width_m": runs[angles[0]].domain.width})
    stated = {f"rms_right_vs_chwang_{b:g}": 0.04 for b in ANGLES}
    out = {"metrics": metrics, "tolerances": stated, "particles": particles, "steps": steps,
           "series": inclined_3d_series_plot(profiles, sections and {b: r["profile"] for b, r in sections.items()})}
    if quick:
        out["stated_tolerances"] = stated
        out["tolerances"] = {"rms_right_vs_chwang_45": 0.04, "kp_right_vs_2d_max_45": 0.04,
                             "kp_out_of_phase_max_45": 0.05}
    return out


# ------------------------------------------------------------------------------------ cylinder
#: the stated target of the cylinder-tank row of docs/VALIDATION.md (issue 16's)
CYLINDER_TARGET = ("wall pressure against Petrov–Moiseev (Sunara et al. 2021, Eq. 20-21) around the circumference and with depth; "
                   "RMS < 0.127 kPa (the paper's own SPH error)")
CYLINDER_DEPARTURE = {
    "criterion": "the wall's hydrodynamic pressure on the x-z plane against the exact incompressible series "
                 "(cylinder_series), RMS < 0.127 kPa; round the wall against the same series' cos(phi); "
                 "Petrov-Moiseev reported beside it",
    "why": "Petrov-Moiseev (Sunara et al. 2021, Eq. 20) is a Ritz approximation: on this tank at 0.5 g it lies 0.15 kPa RMS from "
           "the exact series on the x-z plane (2.53 against 2.42 kPa at the bottom), more than the 0.127 kPa asked, "
           "so the exact solution itself would miss the stated target",
    "source": "this run"}


def _cylinder_terms(h: float, R: float, terms: int):
    """alpha_n = (2n + 1) pi / 2, 2 (-1)^n / alpha_n^2 and the exponentially scaled
    I1'(alpha_n R/h) = (I0 + I2)/2 of the exact series (:func:`cylinder_series`)."""
    from scipy.special import ive

    n = np.arange(terms)
    a = (2 * n + 1) * math.pi / 2
    x = a * R / h
    return a, 2 * (-1.0) ** n / a**2, 0.5 * (ive(0, x) + ive(2, x))


def cylinder_series(z, h: float, R: float, terms: int = 400) -> np.ndarray:
    """k(z) of the exact impulsive pressure on the wall of a rigid vertical cylinder of
    radius ``R`` [m] with water ``h`` [m] under a horizontal base acceleration a0:
    ``p = rho a0 h k(z) cos(phi')``, phi' from the side that pushes the water,

        k(z) = sum_n 2 (-1)^n / alpha_n^2 I1(alpha_n R/h) / I1'(alpha_n R/h) cos(alpha_n z/h),
        alpha_n = (2n + 1) pi / 2,

    z [m] up from the bottom (Jacobsen 1949; Veletsos & Yang 1977; as written in
    docs/VALIDATION.md; its R/h -> inf limit is Westergaard's series). I1/I1' is taken
    from the exponentially scaled Bessel functions (I1' = (I0 + I2)/2), finite for any R/h."""
    from scipy.special import ive

    a, c, i1p = _cylinder_terms(h, R, terms)
    coef = c * ive(1, a * R / h) / i1p
    return (coef[None, :] * np.cos(np.outer(np.asarray(z, float) / h, a))).sum(axis=1)


def petrov_moiseev(z, h: float, R: float) -> np.ndarray:
    """k(z) on the wall by Petrov and Moiseev's Ritz approximation, Sunara et al. 2021,
    Eq. 20: ``sqrt(3) (y/h - (y/h)^2 / 2) tanh(sqrt(3) R/h)`` with y = h - z the depth below
    the surface (Eq. 20 vanishes at y = 0 and is largest at y = h: y is the depth)."""
    y = (h - np.asarray(z, float)) / h
    return math.sqrt(3) * (y - 0.5 * y**2) * math.tanh(math.sqrt(3) * R / h)


def cylinder_bottom_series(r, h: float, R: float, terms: int = 400) -> np.ndarray:
    """k_b(r) of the exact impulsive pressure on the bottom of the tank of
    :func:`cylinder_series`: ``p = rho a0 h k_b(r) cos(phi')`` at radius ``r`` [m],

        k_b(r) = sum_n 2 (-1)^n / alpha_n^2 I1(alpha_n r/h) / I1'(alpha_n R/h),

    the same potential at z = 0 (each term of the series is I1(alpha_n r/h) cos(alpha_n
    z/h) cos(phi'); k_b(R) = k(0)). With the exponentially scaled Bessel functions."""
    from scipy.special import ive

    a, c, i1p = _cylinder_terms(h, R, terms)
    rr = np.asarray(r, float)[:, None]
    return (c * ive(1, a * rr / h) / i1p * np.exp(a * (rr - R) / h)).sum(axis=1)


def petrov_moiseev_bottom(r, h: float, R: float) -> np.ndarray:
    """k_b(r) on the bottom by Petrov and Moiseev, Sunara et al. 2021, Eq. 21:
    ``(sqrt(3)/2) sinh(sqrt(3) r/h) / cosh(sqrt(3) R/h)`` (at r = R, Eq. 20 at the bottom)."""
    return 0.5 * math.sqrt(3) * np.sinh(math.sqrt(3) * np.asarray(r, float) / h) / math.cosh(math.sqrt(3) * R / h)


#: the angles from +x [deg] where the cylinder's wall pressure is read (half the wall)
CYLINDER_ANGLES = tuple(range(0, 181, 15))


def run_cylinder(dx: float, c0: float = 1430.0, periods_skip: int = 2, periods_fit: int = 3,
                 samples_per_period: int = 40, a0: float = 0.5 * G, Tp: float = 0.02, diameter: float = 2.0,
                 depth: float = 0.6, height: float = 1.0, angles_deg=CYLINDER_ANGLES, **overrides) -> dict:
    """Sunara et al. 2021, §3.3 (Fig. 14-17): the rigid cylinder ``diameter`` [m],
    ``height`` [m], water ``depth`` [m] (:func:`fluid.shapes.cylinder_tank`: rings of equal
    volume, wall shells) under the base acceleration ``a0 sin(2 pi t / Tp)`` along +x from
    rest, c0 [m/s] the paper's (its acoustic period 4 h / c0 = 1.7 ms is 1/12 of Tp: the
    compressible excess is 0.4 %). Extraction as :func:`run_inclined`, at face points on
    the wall every dx in height at the angles ``angles_deg`` from +x (half the wall: the
    pressure is odd about the y-z plane, even about x-z); the hydrodynamic amplitude
    ``s`` [Pa] against ``-rho a0 h k(z) cos(phi)`` (phi from +x: the wall at phi = 180 deg
    pushes the water). Judged on the x-z plane (phi = 0 and 180 deg: the paper's Fig. 17
    profile); over the whole half wall reported. The bottom's pressure along the x axis
    (face points every dx, both sides of the axis) against :func:`cylinder_bottom_series`
    and Petrov-Moiseev's Eq. 21 (:func:`petrov_moiseev_bottom`), reported."""
    f, shake, cfg = _shaken_tank(cylinder_tank(dx, diameter, depth, height), 3, dx, depth, c0, a0, Tp, **overrides)
    return _cylinder_profile(f, shake, cfg, a0, Tp, diameter, depth, angles_deg, samples_per_period, periods_skip,
                             periods_fit)


def _cylinder_profile(f, shake, cfg, a0: float, Tp: float, diameter: float, depth: float, angles_deg,
                      samples_per_period: int, periods_skip: int, periods_fit: int) -> dict:
    """The cylinder's wall and bottom pressure of :func:`run_cylinder` from its running fluid
    ``f`` (shaken by ``shake``, ``cfg`` its FluidConfig): the metrics and profiles."""
    dx, c0 = cfg.dx, cfg.speed_of_sound
    R = 0.5 * diameter
    z = dx * (0.5 + np.arange(int(math.floor(depth / dx + 1e-9))))
    phi = np.radians(np.asarray(angles_deg, float))
    P, Z = np.meshgrid(phi, z, indexing="ij")                     # (angles, rows)
    pts = np.stack([R * np.cos(P), R * np.sin(P), Z], -1).reshape(-1, 3)
    normals = np.stack([-np.cos(P), -np.sin(P), np.zeros_like(P)], -1).reshape(-1, 3)
    rb = dx * (0.5 + np.arange(int(math.floor(R / dx + 1e-9))))
    xb = np.concatenate([-rb[::-1], rb])                          # along x, phi = 180 deg then 0
    bottom = np.stack([xb, np.zeros_like(xb), np.zeros_like(xb)], -1)
    amp = _face_amplitudes(f, shake, cfg, {"wall": (pts, normals), "bottom": (bottom, np.array([0.0, 0.0, 1.0]))},
                           Tp, samples_per_period, periods_skip, periods_fit)
    s, c = amp["wall"]
    s, c = s.reshape(P.shape), c.reshape(P.shape)
    scale = RHO0 * a0 * depth
    p_exact, p_pm = scale * cylinder_series(z, depth, R), scale * petrov_moiseev(z, depth, R)  # [Pa], at phi' = 0
    exact = -p_exact[None, :] * np.cos(P)
    pm = -p_pm[None, :] * np.cos(P)
    plane = np.isclose(np.degrees(phi), 0.0) | np.isclose(np.degrees(phi), 180.0)
    rms = lambda a, r: float(np.sqrt(np.mean((a - r) ** 2)) / 1000.0)
    sb = amp["bottom"][0]
    pb_exact = -scale * np.sign(xb) * cylinder_bottom_series(np.abs(xb), depth, R)  # cos(phi) = sign(x)
    pb_pm = -scale * np.sign(xb) * petrov_moiseev_bottom(np.abs(xb), depth, R)
    ours_plane = 0.5 * (s[np.isclose(np.degrees(phi), 180.0)][0] - s[np.isclose(np.degrees(phi), 0.0)][0])
    metrics = {"rms_kpa_plane_vs_exact": rms(s[plane], exact[plane]),
               "rms_kpa_plane_vs_petrov_moiseev": rms(s[plane], pm[plane]),
               "rms_kpa_wall_vs_exact": rms(s, exact),
               "rms_kpa_wall_vs_petrov_moiseev": rms(s, pm),
               "rms_kpa_petrov_moiseev_vs_exact": rms(pm[plane], exact[plane]),
               "rms_kpa_bottom_vs_exact": rms(sb, pb_exact),
               "rms_kpa_bottom_vs_petrov_moiseev": rms(sb, pb_pm),
               "rms_kpa_petrov_moiseev_bottom_vs_exact": rms(pb_pm, pb_exact),
               "p_base_kpa": float(ours_plane[0] / 1000.0),
               "p_base_exact_kpa": float(p_exact[0] / 1000.0),
               "out_of_phase_max_kpa": float(np.abs(c).max() / 1000.0),
               "dx_m": dx, "c0_m_s": c0, "rows": int(z.size), "max_speed_m_s": float(f.max_speed())}
    return {"metrics": metrics, "particles": int(f.ps.n), "steps": int(f.counters.steps),
            "profile": {"z_m": z.tolist(), "p_kpa": (ours_plane / 1000.0).tolist(),
                        "p_exact_kpa": (p_exact / 1000.0).tolist(),
                        "p_petrov_moiseev_kpa": (p_pm / 1000.0).tolist(),
                        "angles_deg": np.degrees(phi).tolist(),
                        "p_round_kpa": (-s[:, 0] / 1000.0).tolist(),
                        "p_round_exact_kpa": (-exact[:, 0] / 1000.0).tolist(),
                        "x_bottom_m": xb.tolist(), "p_bottom_kpa": (sb / 1000.0).tolist(),
                        "p_bottom_exact_kpa": (pb_exact / 1000.0).tolist(),
                        "p_bottom_petrov_moiseev_kpa": (pb_pm / 1000.0).tolist()}}


def cylinder_series_plot(profile: dict) -> dict:
    """The report's plots: the hydrodynamic pressure amplitude up the wall on the x-z plane
    (the paper's Fig. 17) and round the wall at the lowest row."""
    z = profile["z_m"]
    return {"wall pressure, x-z plane": {
                "xlabel": "hydrodynamic pressure amplitude [kPa]", "ylabel": "height above the bottom [m]",
                "curves": {"exact series": {"x": profile["p_exact_kpa"], "y": z},
                           "Petrov-Moiseev (Sunara et al. 2021, Eq. 20)": {"x": profile["p_petrov_moiseev_kpa"], "y": z, "style": "--"},
                           "SPH (ours)": {"x": profile["p_kpa"], "y": z, "style": "o-"}}},
            "wall pressure round the wall, lowest row": {
                "xlabel": "angle from +x [deg]", "ylabel": "hydrodynamic pressure amplitude [kPa]",
                "curves": {"exact series": {"x": profile["angles_deg"], "y": profile["p_round_exact_kpa"]},
                           "SPH (ours)": {"x": profile["angles_deg"], "y": profile["p_round_kpa"], "style": "o-"}}},
            "bottom pressure along x": {
                "xlabel": "x [m] (the shaking pushes the water at x = -R)",
                "ylabel": "hydrodynamic pressure amplitude [kPa]",
                "curves": {"exact series": {"x": profile["x_bottom_m"], "y": profile["p_bottom_exact_kpa"]},
                           "Petrov-Moiseev (Sunara et al. 2021, Eq. 21)": {"x": profile["x_bottom_m"],
                                                          "y": profile["p_bottom_petrov_moiseev_kpa"], "style": "--"},
                           "SPH (ours)": {"x": profile["x_bottom_m"], "y": profile["p_bottom_kpa"], "style": "o-"}}}}


def cylinder_scene(quick: bool):
    """The scene ``scenes/cylinder-tank.toml``: the full variant as written (dx = 0.05 m,
    2 + 3 periods); the quick variant at dx = 0.1 m over 1 + 2 periods."""
    if not quick:
        return case_scene.load("cylinder-tank")
    period = case_scene.load("cylinder-tank").base_motion.period
    return case_scene.load("cylinder-tank", ["fluid.dx=0.1", f"world.duration={case_scene.number(3 * period)}"])


def run_cylinder_scene(scene, periods_skip: int) -> dict:
    """The cylinder of ``scene`` (:func:`cylinder_scene`), built as ``cosim run`` builds it
    and read as :func:`run_cylinder` reads its tank: the pressure fitted over the scene's
    periods after ``periods_skip`` of them, sampled at its ``world.sample_every``."""
    d, shake = scene.domain, scene.base_motion
    samples, periods = case_scene.shaken_samples(scene)
    with case_scene.built(scene) as b:
        f = b.sph
        return _cylinder_profile(f, b.base_motion, f.config, shake.acceleration, shake.period, d.diameter, d.depth,
                                 CYLINDER_ANGLES, samples, periods_skip, periods - periods_skip)


@case("cylinder-tank", "3-D cylinder D = 2 m, 1.0 m high, water 0.6 m, base acceleration 0.5 g sin(2 pi t / 0.02 s) "
      "(Sunara et al. 2021, §3.3): the wall's hydrodynamic pressure on the x-z plane vs the exact series, RMS < 0.127 kPa; "
      "Petrov-Moiseev (the stated reference) beside it", target=CYLINDER_TARGET,
      quick="dx = 0.1 m (6 rows over the depth), 1 + 2 periods: the x-z plane's RMS against the exact series "
            "below 0.35 kPa, the base pressure within 6 %, the out-of-phase part below 0.15 kPa (the row next to "
            "the free surface reads high by ~dx/h: the stated 0.127 kPa needs the full variant's dx = 0.05 m)",
      scene=cylinder_scene)
def cylinder_tank_case(quick: bool) -> dict:
    """The scene :func:`cylinder_scene` read by :func:`run_cylinder_scene`; see
    :func:`run_cylinder` for the set-up and the extraction. c0 = 1430 m/s, tank walls
    carrying the fluid's pressure (``walls="adami"``), the solver's other defaults
    (Wendland, h = sqrt(2) dx: at dx = 0.1 m 0.29 kPa RMS against 0.51 at h = 2 dx, for 3/4
    of its CPU; docs/setup_chooser.md; the chooser's "impulsive"); 40 samples a period.
    Reference: the exact series (:func:`cylinder_series`: 2.41 kPa at the bottom);
    Petrov-Moiseev (Sunara et al. 2021, Eq. 20, what the paper compares with) is a Ritz
    approximation 0.15 kPa RMS from it on this tank (2.53 kPa at the bottom).

    The stated target (0.127 kPa) is met at dx = 0.05 m against the exact series; against
    Petrov-Moiseev (Sunara et al. 2021, Eq. 20-21), itself 0.149 kPa from the exact series, it is
    not met at any dx, so the exact series is judged, a declared departure. The measured table
    (``python benchmarks/tanks_3d_trade.py cylinder --dx DX``), the row next to the free surface
    and the bottom along x: docs/validation/cylinder-tank_history.md.
    Figures: ``docs/validation/figures/cylinder-tank_dx0.05_*.png``.
    """
    r = run_cylinder_scene(cylinder_scene(quick), periods_skip=1 if quick else 2)
    m = r["metrics"]
    m["p_base_rel_err"] = m["p_base_kpa"] / m["p_base_exact_kpa"] - 1
    out = {"metrics": m, "tolerances": {"rms_kpa_plane_vs_exact": 0.127}, "particles": r["particles"],
           "steps": r["steps"], "series": cylinder_series_plot(r["profile"]),
           "stated_tolerances": {"rms_kpa_plane_vs_petrov_moiseev": 0.127}, "departure": dict(CYLINDER_DEPARTURE)}
    if quick:
        out["tolerances"] = {"rms_kpa_plane_vs_exact": 0.35, "p_base_rel_err": 0.06,
                             "out_of_phase_max_kpa": 0.15}
    return out
