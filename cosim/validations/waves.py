"""Wave cases with SPH and moored or free bodies (VALIDATION.md, "Bodies and coupling"):
moored-body with SPH, floating-box-waves."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from cosim import refdata
from cosim.validations import case_scene
from cosim.validations.judging import judge
from cosim.validations.registry import case

RHO, G = 1000.0, 9.81

#: moored-body-sph's spacing [m], speed of sound [m/s] (None: the scene's, 10 sqrt(g depth)) and
#: duration [s], by variant (quick: True); the rest is the file's (scenes/moored-body-sph.toml)
MB_RUNS = {True: (0.02, 10.0, 3.0), False: (0.01, None, 6.0)}


def moored_equilibrium(width, height, rho_b, spread, length, weight, depth, rho=RHO, g=G):
    """Centre height [m] of a 2-D box (``width`` x ``height`` [m], ``rho_b``
    [kg/m^3], 1 m thick) floating in water of ``depth`` [m] (floor z = 0) on two
    symmetric catenary lines from its lower corners to anchors on the floor
    ``spread`` [m] either side of its centre (``length`` [m], submerged ``weight``
    [N/m]): buoyancy = weight + the lines' vertical pull (Barreiro et al. 2016, Eq. 35-39),
    at no offset and no tilt (symmetry)."""
    from moorings.catenary import solve

    m = rho_b * width * height

    def residual(z):
        V = solve(spread - 0.5 * width, z - 0.5 * height, length, weight).V
        draft = min(max(depth - (z - 0.5 * height), 0.0), height)
        return rho * g * width * draft - m * g - 2.0 * V

    return brentq(residual, depth - 0.5 * height + 1e-9, depth + 0.5 * height - 1e-9, xtol=1e-14)


def moored_scene(quick: bool):
    """The scene of moored-body-sph (``scenes/moored-body-sph.toml``, the full variant's) with
    the variant's spacing, speed of sound and duration (:data:`MB_RUNS`)."""
    dx, c0, t_end = MB_RUNS[quick]
    values = [f"fluid.dx={dx}", f"world.duration={t_end}"] + ([f"fluid.c0={c0}"] if c0 else [])
    return case_scene.load("moored-body-sph", values)


def moored_box_sph(scene):
    """Run ``scene`` (:func:`moored_scene`): the box released to +x of its rest position at
    its free-floating draft; returns time, centre x, z and roll histories at every coupling
    step, the coupler, the fluid and the mooring."""
    rec = []
    with case_scene.built(scene) as b:
        bodies = b.bodies
        b.coupler.run(scene.world.duration, callback=lambda i: rec.append(
            (i.t, *bodies.kinematics().com[0, [0, 2]], float(bodies.data.qpos[2]))))
    t, x, z, th = np.array(rec).T
    return t, x, z, th, b.coupler, b.fluid, b.mooring


@case("moored-body-sph", "2-D box on two catenary lines in SPH water, offset and released: settles where "
                         "lines + hydrostatics balance", row="moored-body",
      target="decay to the equilibrium predicted by lines + hydrostatics",
      quick="the full variant's criterion (the mean centre over the last second within half a spacing of the "
            "equilibrium in x and z) at dx = 2 cm, c0 = 10 m/s, 3 s instead of dx = 1 cm, 6 s: within 10 mm "
            "instead of 5 mm", scene=moored_scene)
def moored_body_sph(quick: bool) -> dict:
    """The box of the analytic ``moored-body`` case scaled to a tank: 0.2 x 0.1 m,
    500 kg/m^3, in 0.3 m of SPH water (tank 1.4 m), on two inextensible catenary
    lines (0.52 m, 40 N/m) from its lower corners to anchors on the floor 0.5 m
    either side. Released 4 cm to +x at its free-floating draft, it oscillates in
    surge (period ~1.1 s, from the lines' stiffness) and heave (~0.4 s), damped
    by the waves it radiates (the scene :func:`moored_scene`; the reference is computed
    from its fields). Reference: the equilibrium of buoyancy, weight and
    the lines' vertical pull (:func:`moored_equilibrium`, catenary of Barreiro et al. 2016,
    Eq. 35-39): 15 mm deeper than free floating. Measured: the mean centre over
    the last second (several heave periods, about one surge period) against it.

    What limits it: the SPH draft error of a floating body (dynamic boundaries
    stand the fluid off by a fraction of dx; see ``floating-box-draft``), and in
    the quick run an unfinished surge decay (mean over less than one period).

    Measured (quick: dx = 2 cm, c0 = 10 m/s, 3 s, 1430 particles, 5823 steps, 19 s
    of one core): mean centre 2.6 mm (0.13 dx) above the equilibrium, i.e. SPH
    finds 11.5 of the lines' 14.1 mm pull-down; 3.4 mm off in x with 8 mm of surge
    left; roll up to 2.2 deg. Full (dx = 1 cm, 6 s, 4952 particles, 37 577 steps,
    201 s of one core): 2.2 mm (0.22 dx) above the equilibrium, 1.8 mm off in x
    with 4.6 mm of surge left, roll up to 1.7 deg. The height error did not halve
    with dx (2.6 → 2.2 mm): the remaining 15 % of the pull-down is not (only) the
    boundary gap.
    """
    scene = moored_scene(quick)
    dx, t_end, depth = scene.fluid.dx, scene.world.duration, scene.domain.depth
    (bw, bh), rb = scene.bodies[0].size, scene.bodies[0].density
    left, right = scene.moorings.lines
    x_rest = 0.5 * (left.anchor[0] + right.anchor[0])  # the box at rest lies midway between the anchors
    t, x, z, th, c, fluid, mooring = moored_box_sph(scene)
    z_eq = moored_equilibrium(bw, bh, rb, x_rest - left.anchor[0], left.length, left.weight, depth)
    z_free = depth + 0.5 * bh - rb / RHO * bh
    late = t >= t_end - 1.0
    err_x, err_z = float(x[late].mean() - x_rest), float(z[late].mean() - z_eq)
    tol_x, tol_z = (0.5 * dx, 0.5 * dx)
    series = {"box centre": {"xlabel": "t [s]", "ylabel": "offset from the equilibrium [mm]", "curves": {
        "x - x_eq (ours)": {"x": t, "y": (x - x_rest) * 1e3},
        "z - z_eq (ours)": {"x": t, "y": (z - z_eq) * 1e3},
        "equilibrium (lines + hydrostatics)": {"x": [t[0], t[-1]], "y": [0.0, 0.0], "style": "--"}}}}
    return {
        "series": series,
        "metrics": {
            "equilibrium_z_m": z_eq, "free_floating_z_m": z_free,
            "mean_z_last_s_m": float(z[late].mean()), "mean_x_last_s_m": float(x[late].mean()),
            "x_error_m": err_x, "z_error_m": err_z, "z_error_over_dx": err_z / dx,
            "lines_pull_down_m": z_free - z_eq,
            "surge_amplitude_last_s_m": float(0.5 * np.ptp(x[late])),
            "max_roll_deg": float(np.degrees(np.abs(th)).max()),
            "tensions_N": mooring.fairlead_tensions().tolist(), "dx_m": dx, "t_end_s": t_end,
            "finite": bool(np.isfinite(z).all()),
        },
        "tolerances": {"x_error_m": tol_x, "z_error_m": tol_z, "finite": True},
        "particles": int(fluid.fluid.ps.n),
        "steps": c.steps,
    }


# floating-box-waves: Hadzic et al. (2005), DualSPHysics' CaseFloatingWavesVal (refdata SOURCE.txt);
# its flume, flap record, box and probes are the scene's (scenes/floating-box-waves.toml)
# The reference's artificial viscosity (DualSPHysics CaseFloatingWavesVal_Def.xml, refdata
# SOURCE.txt): alpha = 0.01 at dp = 2 mm, h = coefh sqrt(2) dp with coefh = 1.2, c0 = 15
# sqrt(g d): as a kinematic viscosity nu = alpha h c0 / 8 (Monaghan 2005, Rep. Prog. Phys.
# 68, 2-D) = 1.26e-4 m^2/s. See :func:`hadzic_alpha`.
HZ_H_COEF = 1.2 * math.sqrt(2.0)  # h / dx [-] of the reference (coefh = 1.2): 1.70
HZ_NU_ART = 0.01 * (1.2 * math.sqrt(2.0) * 0.002) * (15.0 * math.sqrt(G * 0.4)) / 8.0


def paddle_wave_heights(kind: str, dx: float, H: float, T: float, depth: float, gauges, t_end: float,
                        length: float, periods: float = 2.0, width: float | None = None, **config):
    """Regular waves from a paddle in an SPH flume: a ``kind`` ("piston" or "flap")
    :class:`fluid.wavemaker.RegularWavemaker` of height ``H`` [m], period ``T`` [s] in
    water ``depth`` [m] (ramped in over one period), a flume ``length`` [m] long at spacing
    ``dx`` [m], 2-D, or 3-D when ``width`` [m] is given (side walls at y = 0 and ``width``,
    the gauges on the mid-line); ``config``: further :class:`fluid.solver.FluidConfig` settings (default
    ``u_max = sqrt(g depth)``). Returns a dict: ``H1`` the first-harmonic height [m] at
    each gauge x [m] (increasing, closer than half a wavelength; a least-squares fit of mean + first and second harmonics over the
    last ``periods`` periods before ``t_end`` [s]; choose ``t_end`` after the ramp's end
    has reached the gauges and before the far wall's reflection comes back), ``decay``
    [1/m] and ``H1_paddle`` [m] of the exponential fitted through them (its value at x =
    0), ``k`` [rad/m] the slope of the first harmonic's phase along x (the wavenumber the
    SPH waves travel with) and ``k_linear`` [rad/m] linear theory's."""
    from fluid.flume import PADDLE_GROUP, flume
    from fluid.geometry import assemble, set_hydrostatic
    from fluid.probes import surface_elevation
    from fluid.solver import Fluid, FluidConfig
    from fluid.wavemaker import RegularWavemaker

    wm = RegularWavemaker(kind, H=H, T=T, depth=depth, ramp=1.0)
    back = 0.5 * wm.stroke + dx if kind == "piston" else 0.0
    f = flume(dx, length, depth, 1.5 * depth, back=back, width=width)
    config.setdefault("u_max", math.sqrt(G * depth))
    dim = 2 if width is None else 3
    cfg = FluidConfig(dim=dim, dx=dx, g=G, **config)
    ps = assemble(dim, dx, cfg.rho0, f.fluid, f.walls).particles
    set_hydrostatic(ps, depth, cfg.rho0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    fluid = Fluid(cfg, ps)
    fluid.prescribe_motion(PADDLE_GROUP, wm.paddle())
    fluid.initialize(0.0)
    at = gauges if width is None else [(x, 0.5 * width) for x in gauges]
    t, ts, eta = 0.0, [], []
    while t < t_end - 1e-12:
        dt = min(fluid.max_dt(), 0.01, t_end - t)
        fluid.advance(t, dt)
        t += dt
        if t > t_end - periods * T:
            ts.append(t)
            eta.append(surface_elevation(fluid, at) - depth)
    ts, eta = np.array(ts), np.array(eta)
    w = 2.0 * math.pi / T
    basis = np.stack([np.ones_like(ts), np.cos(w * ts), np.sin(w * ts), np.cos(2 * w * ts), np.sin(2 * w * ts)], 1)
    coef = np.linalg.lstsq(basis, eta, rcond=None)[0]
    h1 = 2.0 * np.hypot(coef[1], coef[2])
    x = np.asarray(gauges, float)
    slope, icpt = np.polyfit(x, np.log(h1), 1)
    # eta = A cos(w t - k x): the phase atan2(sin coef, cos coef) grows with k x
    k = np.polyfit(x, np.unwrap(np.arctan2(coef[2], coef[1])), 1)[0]
    return {"H1": h1, "decay": float(-slope), "H1_paddle": float(math.exp(icpt)), "k": float(k),
            "k_linear": wm.k}


def viscous_decay(nu: float, T: float, depth: float) -> float:
    """Spatial decay rate [1/m] of a linear wave's height under a kinematic viscosity
    ``nu`` [m^2/s]: the temporal rate 2 nu k^2 (Lamb 1932, Hydrodynamics §348) over the
    group velocity c_g = (1 + 2kd / sinh 2kd) omega / 2k; period ``T`` [s], ``depth`` [m]."""
    from fluid.wavemaker import wavenumber

    k = wavenumber(T, depth, G)
    kd = k * depth
    cg = 0.5 * (1.0 + 2.0 * kd / math.sinh(2.0 * kd)) * (2.0 * math.pi / T) / k
    return 2.0 * nu * k * k / cg


def hadzic_measured() -> dict:
    """The digitised measurements (refdata ``EXP_FloatingWavesVal_Hadzic_et_al_2005.txt``):
    ``{name: (t [s], value)}`` for WaveProbe_N1/N2 [m], WP_Heave [m], WP_Roll [deg], WP_Sway [m]."""
    path = refdata.path("floating_box_waves_hadzic2005", "EXP_FloatingWavesVal_Hadzic_et_al_2005.txt")
    lines = path.read_text(encoding="latin-1").splitlines()
    names = lines[1].split("\t")[1::2]
    cols = [[] for _ in range(2 * len(names))]
    for line in lines[2:]:
        for k, cell in enumerate(line.split("\t")[:2 * len(names)]):
            if cell.strip():
                cols[k].append(float(cell))
    return {n.strip(): (np.array(cols[2 * i]), np.array(cols[2 * i + 1])) for i, n in enumerate(names)}


def hadzic_alpha(h: float, c0: float) -> float:
    """The artificial viscosity alpha [-] that gives, at smoothing length ``h`` [m] and
    speed of sound ``c0`` [m/s], the reference set-up's kinematic artificial viscosity
    ``HZ_NU_ART`` = alpha h c0 / 8 = 1.26e-4 m^2/s (DualSPHysics' alpha = 0.01 at dp = 2
    mm; Monaghan 2005, 2-D). Keeping alpha = 0.01 at our 5-10 times coarser spacing makes
    the viscosity 3-6 times the reference's, and a viscosity damps a wave's height by
    exp(-2 nu k^2 x / c_g) over a distance x (Lamb 1932, §348; k wavenumber, c_g group
    velocity: :func:`viscous_decay`), most for the short waves: measured with a flap making
    regular waves T = 0.7 s in 0.4 m of water at dx = 2 cm, alpha = 0.01 (benchmarks/
    flap_waves.py), decay 0.167 /m against 0.171 /m from that formula. Linear theory with
    that damping per frequency puts the packet's crest at N1 at 32 mm (alpha = 0.01, dx =
    2 cm, h = sqrt(2) dx), 35 mm (dx = 1 cm) and 37 mm (the reference's nu) against 38 mm
    undamped. Gives 0.0015 at dx = 2 cm and 0.0030 at dx = 1 cm with the reference's h =
    1.70 dx (:data:`HZ_H_COEF`) and c0 = 10 sqrt(g d)."""
    return 8.0 * HZ_NU_ART / (h * c0)


def floating_box_scene(quick: bool):
    """The scene ``scenes/floating-box-waves.toml`` (the full variant as written: dx = 1 cm,
    record time 1 -> 8.2 s); the quick variant at dx = 2 cm (its artificial viscosity
    :func:`hadzic_alpha` there) for 0.3 s."""
    scene = case_scene.load("floating-box-waves")
    if not quick:
        return scene
    from cosim.scene.build import fluid_config
    from cosim.scene.setup import choose

    c0 = fluid_config(scene, choose(scene), numbers_only=True).speed_of_sound
    alpha = hadzic_alpha(scene.fluid.h_coef * 0.02, c0)
    return case_scene.load("floating-box-waves", ["fluid.dx=0.02", f"fluid.alpha={case_scene.number(alpha)}",
                                                  "world.duration=0.3"])


def floating_box_waves_run(scene, gauge_every: float = 0.02):
    """Run ``scene`` (:func:`floating_box_scene`: the Hadzic et al. (2005) flume, its t = 0
    the record's ``-waves.t_shift``); returns histories of the box centre and roll at every
    coupling step and the probes every ``gauge_every`` [s], in record time, the coupler
    and the fluid."""
    from fluid.probes import surface_elevation

    gauges, depth, t0 = list(scene.probes.gauges), scene.domain.depth, -scene.waves.t_shift
    rec, probes = [], []
    nxt = [0.0]
    with case_scene.built(scene) as b:
        bodies, fluid = b.bodies, b.sph

        def record(info):
            k = bodies.kinematics()
            rec.append((t0 + info.t, k.com[0, 0], k.com[0, 2], float(bodies.data.qpos[2])))
            if info.t >= nxt[0] - 1e-12:
                probes.append((t0 + info.t, *(surface_elevation(fluid, gauges) - depth)))
                nxt[0] += gauge_every

        b.coupler.run(scene.world.duration, callback=record)
        return np.array(rec), np.array(probes), b.coupler, b.fluid


def hadzic_compare(rec, probes):
    """Compare a run's box histories ``rec`` (t, x, z, roll rows) and probe
    elevations ``probes`` (t, N1, N2 rows) with the measurements: heave and sway
    peaks (relative error) and their times, the probes' peaks and correlation.
    Returns (all within 15 % and 0.1 s, metrics).

    Phase: the lag of the SPH history against the measured one that maximises their
    correlation over the measured window (:func:`best_lag`), within 0.1 s, for heave and
    sway; heave's crest and trough times are also checked (:data:`HADZIC_TOLERANCES`). The sway's maximum time is
    reported, not checked: the measured sway has two nearly equal maxima (110 mm at 7.55
    s, 116 mm at 8.14 s), so which one is the larger, and hence the time, flips with a
    5 % change of either (the check as first written failed on that alone)."""
    t, x, z, th = np.asarray(rec).T
    meas = hadzic_measured()
    metrics = {}
    for name, pos in (("WP_Heave", z), ("WP_Sway", x)):
        tm, vm = meas[name]
        # the measured motions start from the box at rest (0 at 6.3 s); the SPH box
        # settles from its initial 4 mm above Archimedes: from where it rests before
        rest = (t >= tm[0] - 0.5) & (t <= tm[0])
        sim = pos - pos[rest].mean()
        win = (tm.min(), tm.max())
        pm, qm, tpm, tqm = _peaks(tm, vm, win)
        ps_, qs_, tps, tqs = _peaks(t, sim, win)
        rel_max, rel_min = (ps_ - pm) / abs(pm), (qs_ - qm) / abs(qm)
        metrics[name] = {"measured_max_min_m": [pm, qm], "sph_max_min_m": [ps_, qs_],
                         "rel_error_max": rel_max, "rel_error_min": rel_min,
                         "t_max_measured_sph_s": [tpm, tps], "t_min_measured_sph_s": [tqm, tqs],
                         "t_max_diff_s": tps - tpm, "t_min_diff_s": tqs - tqm}
        lag, corr = best_lag(t, sim, tm, vm)
        metrics[name].update({"lag_s": lag, "correlation_at_lag": corr})
    for j, name in enumerate(("WaveProbe_N1", "WaveProbe_N2")):
        tm, vm = meas[name]
        probes = np.asarray(probes)
        inside = (tm >= probes[0, 0]) & (tm <= probes[-1, 0])  # the run's part of the record
        if inside.sum() < 10:
            continue
        tm, vm = tm[inside], vm[inside]
        sim = np.interp(tm, probes[:, 0], probes[:, 1 + j])
        metrics[name] = {"measured_max_m": float(vm.max()), "sph_max_m": float(sim.max()),
                         "measured_min_m": float(vm.min()), "sph_min_m": float(sim.min()),
                         "correlation": float(np.corrcoef(sim, vm)[0, 1])}
    return judge(metrics, HADZIC_TOLERANCES)[0], metrics


#: what floating-box-waves (full) is judged against: peaks within 15 %, phase as the lag of best
#: correlation within 0.1 s, heave's crest and trough times within 0.1 s (:func:`hadzic_compare`)
HADZIC_TOLERANCES = {"WP_Heave.rel_error_max": 0.15, "WP_Heave.rel_error_min": 0.15, "WP_Sway.rel_error_max": 0.15,
                     "WP_Heave.lag_s": 0.1, "WP_Sway.lag_s": 0.1, "WP_Heave.t_max_diff_s": 0.1,
                     "WP_Heave.t_min_diff_s": 0.1}
#: the stated target as first written: peaks within 15 %, in phase as the times of the extremes
#: within 0.1 s (heave crest and trough, sway maximum)
HADZIC_STATED = {"WP_Heave.rel_error_max": 0.15, "WP_Heave.rel_error_min": 0.15, "WP_Sway.rel_error_max": 0.15,
                 "WP_Heave.t_max_diff_s": 0.1, "WP_Heave.t_min_diff_s": 0.1, "WP_Sway.t_max_diff_s": 0.1}


def best_lag(t, v, tm, vm, max_lag: float = 0.25, step: float = 0.002) -> tuple[float, float]:
    """(lag [s], correlation): the shift of the history ``v(t)`` that best matches the
    measured ``vm(tm)``, i.e. the lag in [-max_lag, max_lag] maximising the correlation
    of ``v(tm + lag)`` with ``vm`` over the measured samples whose shifted time lies in
    ``t`` (positive: the history runs late)."""
    t, v, tm, vm = (np.asarray(a, float) for a in (t, v, tm, vm))
    best = (math.nan, -math.inf)
    for lag in np.arange(-max_lag, max_lag + 0.5 * step, step):
        inside = (tm + lag >= t[0]) & (tm + lag <= t[-1])
        if inside.sum() < 10:
            continue
        r = float(np.corrcoef(np.interp(tm[inside] + lag, t, v), vm[inside])[0, 1])
        if r > best[1]:
            best = (float(lag), r)
    return best


def _peaks(t, v, window):
    s = (t >= window[0]) & (t <= window[1])
    return float(v[s].max()), float(v[s].min()), float(t[s][np.argmax(v[s])]), float(t[s][np.argmin(v[s])])


@case("floating-box-waves", "2-D box 0.10 x 0.05 m, 680 kg/m^3, in a wave packet from a flap driven by the "
                            "measured angle (Hadzic et al. 2005): heave and sway peaks, phase",
      target="peaks within 15 %, in phase",
      quick="a smoke run of the whole set-up at dx = 2 cm from 1 to 1.3 s (the packet reaches the box after 6 s): "
            "every value finite, the box within one spacing of its initial position, no particle lost",
      scene=floating_box_scene)
def floating_box_waves(quick: bool) -> dict:
    """Set-up (Barreiro et al. 2016, §4.1; Hadzic, Hennig, Peric & Xing-Kaeding 2005, Appl.
    Math. Modelling 29:1196-1210; the DualSPHysics case CaseFloatingWavesVal as in
    refdata SOURCE.txt): 2-D flume, still water 0.4 m, flap hinged at the bottom of
    x = 0 driven by the measured angle (the file's sign is away from the water: its
    scale is -pi/180), 1:10 beach from x = 4 m; the box 0.10 x 0.05 m, 680
    kg/m^3, initially x = 2.06..2.16 m, z = 0.37..0.42 m (it starts 4 mm above its
    Archimedes draft of 34 mm), free (no lines): the scene :func:`floating_box_scene`, run
    by :func:`floating_box_waves_run`. Record time is the experiment's: the run starts 1 s
    into it (``waves.t_shift = -1``) with the flap upright (the record's angle there its
    zero; before, it moves by less than 0.18 deg; the packet is a chirp that focuses near
    the box). Reference: the digitised heave (6.3-8.1 s), sway (6.3-8.1 s) and probes N1 (x = 1.16 m), N2 (2.66 m) of
    refdata; heave and sway are displacements from the position at rest (the
    SPH box's mean over the 0.5 s before the first measured sample, 6.3 s).
    Target: heave and sway peaks within 15 %, in phase (the lag of best correlation
    within 0.1 s, :func:`hadzic_compare`; heave's crest and trough times too).

    SPH settings of the reference set-up (DualSPHysics CaseFloatingWavesVal_Def.xml,
    refdata SOURCE.txt), where they differ from this code's defaults: smoothing length h
    = 1.2 sqrt(2) dx = 1.70 dx (coefh = 1.2; :data:`HZ_H_COEF`), no artificial viscosity
    between the fluid and walls or the box (ViscoBoundFactor = 0: ``alpha_wall = 0``),
    and its kinematic artificial viscosity (alpha = 0.01 at dp = 2 mm) rather than its
    alpha (:func:`hadzic_alpha`: alpha = 0.0015 at dx = 2 cm, 0.0030 at 1 cm). The
    speed of sound stays 10 sqrt(g d) (the reference: 15). Why: with h = sqrt(2) dx the
    SPH waves travel 5-7 % too fast (first-harmonic wavenumber 0.936-0.952 of the
    dispersion relation's at T = 0.6-1.0 s), an error that does not shrink with dx, and
    decay by 0.08 /m at the reference's viscosity (0.17 /m at alpha = 0.01); with
    h = 1.70 dx the wavenumber is 1.01 of theory's and the decay 0.02 /m
    (``benchmarks/flap_waves.py``). The defaults left the packet a third too low at the
    probes (the settings measured one at a time:
    docs/validation/floating-box-waves_history.md).

    Full: dx = 1 cm (box 10 x 5 particles, 30 700 particles), 1 → 8.2 s. Quick: dx = 2 cm, 1 → 1.3 s,
    a smoke run of the whole set-up (the flap follows its record, the box stays
    afloat at its initial position within dx, no particle lost): too short for
    the packet, which reaches the box after 6 s.

    At dx = 1 cm the full variant passes: heave and sway peaks within 11 % and 1 %, in phase
    (best-correlation lags 0.002 and -0.004 s); at dx = 2 cm the focused packet's crest at N2 is
    22 % low. The figures and what limits them: docs/validation/floating-box-waves_history.md.
    """
    scene = floating_box_scene(quick)
    dx, t0 = scene.fluid.dx, -scene.waves.t_shift
    rec, probes, c, fluid = floating_box_waves_run(scene)
    t, x, z, th = rec.T
    xc, zc = scene.bodies[0].pos
    heave, sway = z - zc, x - xc
    ps = fluid.fluid.ps
    lost = {k: int(v) for k, v in fluid.fluid.counters.removed.items() if v}
    metrics = {"dx_m": dx, "t0_s": t0, "t_end_s": t0 + scene.world.duration, "lost_particles": lost,
               "heave_range_m": [float(heave.min()), float(heave.max())],
               "sway_range_m": [float(sway.min()), float(sway.max())],
               "max_roll_deg": float(np.degrees(np.abs(th)).max())}
    metrics["lost_particles_total"] = sum(lost.values())
    metrics["finite"] = bool(np.isfinite(rec).all())
    metrics["heave_max_abs_m"] = float(np.abs(heave).max())
    metrics["sway_max_abs_m"] = float(np.abs(sway).max())
    out = {"metrics": metrics, "particles": int(ps.n), "steps": c.steps,
           "series": hadzic_series(rec, probes), "stated_tolerances": dict(HADZIC_STATED)}
    out["departure"] = {
        "criterion": "peaks within 15 % (heave crest and trough, sway maximum); in phase as the lag of best "
                     "correlation of the heave and sway histories within 0.1 s (heave's crest and trough times too)",
        "why": "the measured sway has two nearly equal maxima (110 mm at 7.55 s, 116 mm at 8.14 s), so which one is "
               "the larger, and with it the time of the maximum, flips with a 5 % change of either; the check of "
               "that time as first written failed on that alone"}
    if quick:  # the full variant's criterion and the stated target are not measured: the packet comes later
        out["tolerances"] = {"heave_max_abs_m": dx, "sway_max_abs_m": dx, "lost_particles_total": [0, 0],
                             "finite": True}
        out["departure"]["source"] = "not measured by the quick variant: the packet reaches the box after 6 s"
        return out
    metrics.update(hadzic_compare(rec, probes)[1])
    out["tolerances"] = dict(HADZIC_TOLERANCES) | {"lost_particles_total": [0, 0]}
    return out


def hadzic_series(rec, probes) -> dict:
    """The report's plots of a floating-box-waves run: heave, sway (from the position at rest
    before the first measured sample, as :func:`hadzic_compare`) and the probes against
    the measurements."""
    t, x, z, _ = np.asarray(rec).T
    meas = hadzic_measured()
    out = {}
    for name, pos, label in (("WP_Heave", z, "heave"), ("WP_Sway", x, "sway")):
        tm, vm = meas[name]
        seen = (tm >= t[0]) & (tm <= t[-1])
        rest = (t >= tm[0] - 0.5) & (t <= tm[0])
        ref = pos[rest].mean() if rest.any() else pos[0]
        out[label] = {"xlabel": "t [s]", "ylabel": f"{label} [mm]", "curves": {
            "measured (Hadzic et al. 2005)": {"x": tm[seen], "y": vm[seen] * 1e3, "style": "o"},
            "SPH (ours)": {"x": t, "y": (pos - ref) * 1e3}}}
    probes = np.asarray(probes)
    for j, name in enumerate(("WaveProbe_N1", "WaveProbe_N2")):
        tm, vm = meas[name]
        seen = (tm >= probes[0, 0]) & (tm <= probes[-1, 0])
        out[f"probe {name[-2:]}"] = {"xlabel": "t [s]", "ylabel": "surface elevation [mm]", "curves": {
            "measured (Hadzic et al. 2005)": {"x": tm[seen], "y": vm[seen] * 1e3},
            "SPH (ours)": {"x": probes[:, 0], "y": probes[:, 1 + j] * 1e3}}}
    return out
