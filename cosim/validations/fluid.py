"""Validation cases of the SPH fluid (VALIDATION.md, "Fluid")."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from cosim.validation import case
from fluid.geometry import set_hydrostatic, tank_with_water
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig


def run_hydrostatic(dim: int, dx: float, t_end: float, depth: float = 0.2, length: float = 0.4,
                    width: float = 0.2, **overrides) -> dict:
    """A tank at rest filled to ``depth`` [m]; compare the fluid pressure with
    ``p = rho0 g (H - z)`` (H the set-up depth, z the particle's current height).

    Set-up: open tank ``length`` x ``width`` (3-D) [m], walls 1.25 H high, 3 layers of dynamic
    boundary particles, particles on a lattice of spacing ``dx`` [m] with the hydrostatic
    Tait density; c0 = 20 sqrt(g H) (DualSPHysics' usual coefsound); Wendland, h = sqrt(2) dx,
    alpha = 0.01, Fourtakas diffusion delta = 0.1, CFL 0.2 (the defaults).

    Wall pressure: on the first layer of the side walls, beside the water, the average of
    the fluid pressures near each wall particle (001_14936b82710365b2.txt Eq. 15), against
    the same reference at the wall particle's height. Reported, not yet part of the pass
    criterion: it is 1.3 % RMS at dx = 0.01 m and 3.6 % at 0.02 m (first order in dx),
    because near the free surface and the bottom corner the fluid neighbours lie on one
    side of the wall particle, so their average is biased by ~ rho g h. A linearly
    corrected (MLS) interpolation at the wall face is the remedy (open).

    What limits the error (measured): particles settle to within 0.01 dx of their lattice
    sites, and the pressure is too high by ~1 % at the bottom and at the surface, ~0.35 %
    at three-quarter depth. The bottom part is the lattice quadrature error of the SPH
    pressure gradient: sum_b V_b r_ab (x) grad W_ab = -(1 - 0.78 %) I for Wendland at
    h = sqrt(2) dx (0.66 % in 3-D), so the column compresses until the weaker discrete
    gradient carries the weight. It does not shrink with dx at fixed h/dx (h = 2 dx: 0.08 %);
    the surface part is the kernel truncation at the free surface.

    Open: at dx = 0.005 m (40 layers, 3 s) the pressure stays within 0.69 % RMS (wall
    0.57 %) but particles start to move after ~0.9 s (up to 5e-3 sqrt(g H)), with and
    without density diffusion: the square lattice rearranges. In 3-D see
    :func:`hydrostatic_3d` (what was found).

    "After settling": the residual motion is dominated by the first sloshing mode (period
    T1 from linear theory, weakly damped by alpha = 0.01). The pressure error is therefore
    measured on the pressure averaged over the last T1 of the run (sampled 40 times), and
    reported also for the last instant. Speeds are the largest over that window.
    """
    g, rho0 = 9.81, 1000.0
    H = depth
    b = tank_with_water(dim, dx, length, H, 1.25 * H, width=width)
    overrides = {"c0_factor": 20.0, **overrides}
    cfg = FluidConfig(dim=dim, dx=dx, u_max=math.sqrt(g * H), **overrides)
    ps = b.particles
    set_hydrostatic(ps, H, rho0, cfg.speed_of_sound, cfg.gamma, g)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    k1 = math.pi / length
    T1 = 2 * math.pi / math.sqrt(g * k1 * math.tanh(k1 * H))
    t_avg = t_end - T1
    if t_avg <= 0:
        raise ValueError(f"t_end={t_end} s is shorter than the sloshing period {T1:.3f} s")
    n_fl = int((ps.kind == Kind.FLUID).sum())
    acc = np.zeros(n_fl)
    # first layer of the side walls, beside the water: the wall pressure of 001 Eq. 15
    x = ps.pos[:, 0]
    side = (ps.kind != Kind.FLUID) & (np.isclose(x, -0.5 * dx) | np.isclose(x, length + 0.5 * dx)) \
        & (ps.pos[:, -1] > 0) & (ps.pos[:, -1] < H)
    if dim == 3:  # the x-walls' first layer only where it faces the water (not the y-walls)
        side &= (ps.pos[:, 1] > 0) & (ps.pos[:, 1] < width)
    side_ids = np.sort(ps.ids[side])
    acc_w = np.zeros(side_ids.size)
    samples, vmax = 0, 0.0
    rgh = rho0 * g * H
    t = 0.0
    f.advance(0.0, t_avg)
    t = t_avg
    dt = T1 / 40
    for _ in range(40):
        f.advance(t, dt)
        t += dt
        fl = f.ps.kind == Kind.FLUID
        order = np.argsort(f.ps.ids[fl])
        z = f.ps.pos[fl, -1][order]
        err = (f.ps.p[fl][order] - rho0 * g * (H - z)) / rgh
        if err.size != n_fl:
            raise RuntimeError("fluid particles were lost in a hydrostatic tank")
        acc += err
        sel = np.isin(f.ps.ids, side_ids)
        ow = np.argsort(f.ps.ids[sel])
        pw = f.wall_pressure()[sel][ow]
        err_w = (pw - rho0 * g * (H - f.ps.pos[sel, -1][ow])) / rgh
        acc_w += err_w
        samples += 1
        vmax = max(vmax, f.max_speed())
    mean_err = acc / samples
    metrics = {
        "p_rms_err_time_avg": float(np.sqrt(np.mean(mean_err**2))),
        "p_rms_err_final": float(np.sqrt(np.mean(err**2))),
        "p_mean_err_time_avg": float(np.mean(mean_err)),
        "p_max_abs_err_time_avg": float(np.abs(mean_err).max()),
        "wall_p_rms_err_time_avg": float(np.sqrt(np.mean((acc_w / samples) ** 2))),
        "wall_p_mean_err_time_avg": float(np.mean(acc_w / samples)),
        "max_speed_over_sqrt_gH": vmax / math.sqrt(g * H),
        "t_end_s": t_end,
        "averaging_window_s": T1,
        "dx_m": dx,
        "c0_m_s": cfg.speed_of_sound,
    }
    tolerances = {"p_rms_err_time_avg": 0.01, "max_speed_over_sqrt_gH": 1e-3}
    passed = all(metrics[k] < v for k, v in tolerances.items())
    return {"passed": passed, "metrics": metrics, "tolerances": tolerances,
            "particles": int(f.ps.n), "steps": int(f.counters.steps)}


@case("hydrostatic", "2-D tank at rest (0.4 m long, H = 0.2 m): fluid pressure vs rho g (H - z) "
      "< 1 % RMS of rho g H, max speed < 1e-3 sqrt(g H)")
def hydrostatic(quick: bool) -> dict:
    if quick:  # 10 particle layers over the depth
        return run_hydrostatic(2, dx=0.02, t_end=2.0)
    return run_hydrostatic(2, dx=0.01, t_end=3.0)


@case("hydrostatic-3d", "3-D tank at rest (0.2 x 0.1 m, H = 0.1 m): as hydrostatic")
def hydrostatic_3d(quick: bool) -> dict:
    """Quick: 5 particle layers over the depth (dx = 0.02 m, 1.5 s), the coarsest sensible
    3-D tank; full: 10 (dx = 0.01 m, 2 s). Does not pass (strict xfail in the tests).

    What was found (quick set-up, per 0.1 s: largest fluid speed over sqrt(g H), largest
    displacement from the lattice site; NUMBA_NUM_THREADS=1, ~1 min per run):

    * A static pressure bias that no lever removes at 5 layers: the pressure is 1.3-1.5 %
      of rho g H too high on average from t = 0.1 s on (RMS 1.5-1.7 %), with Fourtakas,
      without diffusion, with MLS re-initialisation, with a constant rho0/c0^2 in the
      hydrostatic correction. It is the kernel truncation at the free surface and at the
      walls, 3 of 5 layers being within 2h of the surface (2-D at 10 layers: 0.7 %). The
      quick variant cannot meet 1 % RMS at this resolution, moving or not.
    * The motion: with Fourtakas diffusion (delta = 0.1) the largest speed falls to
      1.5e-3 by 0.7 s and then grows, e-folding in ~0.35 s, to 5.9e-3 at 1.4 s, at
      particles one spacing in from both walls of a vertical edge, one or two layers below
      the surface; the largest displacement reaches 0.15 dx at 1.4 s and is still growing
      (the lattice starts to rearrange). Unchanged by: the linearised local
      ``rho/c^2`` versus Fourtakas' ``rho0/c0^2`` (same to 3 digits); letting fluid
      particles take diffusion from boundary particles too (same growth); h = sqrt(3) dx
      (DualSPHysics' 3-D default: bias 2.5 %, growth alike). Slowed by alpha = 0.05 (1.2e-3
      at 1.2 s, still growing). Removed by less diffusion: none decays to 7.4e-4 at 1.5 s
      (pressure noise 2.5 % RMS), delta = 0.03 decays to 7.5e-4 at 1.4 s (displacement
      steady at 0.037 dx, pressure 1.6 % RMS: the bias). At the full resolution (10
      layers, 2 s) delta = 0.03 meets both criteria: pressure 0.77 % RMS (0.71 % mean),
      largest speed 5.95e-4 sqrt(g H), wall pressure 3.3 % (14 162 steps, 5840 particles,
      18 min on one loaded core: ``run_hydrostatic(3, dx=0.01, t_end=2.0, depth=0.1,
      length=0.2, width=0.1, delta=0.03)``); the same run with delta = 0.1: pressure
      0.76 % RMS but largest speed 4.0e-3 sqrt(g H). The case keeps the solver's default
      delta = 0.1 (lowering it for this case alone would be tuning it to pass); what
      delta the solver should default to in 3-D is open. Diffusion none
      with MLS every 30 steps: 1.4e-3 to 2.5e-3, displacement creeping (0.07 dx at 1.4 s).
    * The boundary-density clamp (rho >= rho0 on wall particles, fluid.integrator) is a
      ratchet near the free surface: the wall particles there sit within a fraction of a
      kg/m^3 of rho0, so the start-up oscillation is clipped on one side and their mean
      density, hence the wall push, grows. Without the clamp the start-up transient halves
      (2.2e-3 at 0.1 s instead of 4.9e-3) and the bias drops to 1.1 %, but the growth after
      0.7 s remains (4.0e-3 at 1.4 s). A pressure floor in the equation of state (p >= 0 on
      boundaries, density state unclipped) would keep the clamp's purpose without the
      ratchet; not done (fluid.equations is being rewritten).
    * Interpretation (consistent with the above, not proven): Fourtakas' term drives each
      particle's density towards the hydrostatic density at its current height, which is
      not the discrete equilibrium near truncated supports (the bias above); the two
      cannot both hold, so a residual mass flux keeps particles creeping, and it erases
      the density anomaly that resists a displacement faster than the acoustic response
      (diffusion rate ~ delta c0 / h x 10 vs c0 / h). Evaluated on the settled state of a
      run without diffusion, the Fourtakas term would inject a volumetric strain rate of
      1.4e-2 1/s RMS in 3-D against 5.0e-3 in 2-D (speeds ~ rate x h of 1.3e-3 and 2.9e-4
      sqrt(g H)): 3-D is 3 to 4 times more exposed. A diffusion term that vanishes for any
      linear density field (delta-SPH with renormalised density gradients, the full
      000_7d114ab96e048b26.txt Eq. 1-4) would not fight the discrete equilibrium; it costs
      a second pair loop (open).
    """
    if quick:
        return run_hydrostatic(3, dx=0.02, t_end=1.5, depth=0.1, length=0.2, width=0.1)
    return run_hydrostatic(3, dx=0.01, t_end=2.0, depth=0.1, length=0.2, width=0.1)


REFDATA = Path(os.environ.get("COSIM_REFDATA", Path(__file__).resolve().parents[3] / "shared" / "refdata"))


def _read_front(name: str) -> np.ndarray:
    """(T, Z) rows of a surge-front table in refdata/dambreak_martin_moyce_koshizuka."""
    path = REFDATA / "dambreak_martin_moyce_koshizuka" / name
    return np.loadtxt(path, delimiter=",", comments="#", skiprows=3)


def _pressure_noise(ps, h: float, p_scale: float) -> float:
    """RMS over fluid particles with a full support (>= 2h from any boundary of the fluid
    region, by neighbour count) of ``p_a - <p>_a``, the pressure minus its kernel-weighted
    (Shepard) mean over the neighbours within 2h, over ``p_scale`` [Pa]: the particle-scale
    pressure noise, which a smooth flow does not have (a linear field has none)."""
    from scipy.spatial import cKDTree

    from fluid.kernels import W

    fl = ps.kind == Kind.FLUID
    x, p = ps.pos[fl], ps.p[fl]
    tree = cKDTree(x)
    pairs = tree.query_pairs(2 * h, output_type="ndarray")
    w = W(np.linalg.norm(x[pairs[:, 0]] - x[pairs[:, 1]], axis=1), h, x.shape[1])
    w0 = float(W(np.zeros(1), h, x.shape[1])[0])
    num = w0 * p + np.bincount(pairs[:, 0], w * p[pairs[:, 1]], len(p)) + np.bincount(pairs[:, 1], w * p[pairs[:, 0]], len(p))
    den = w0 + np.bincount(pairs[:, 0], w, len(p)) + np.bincount(pairs[:, 1], w, len(p))
    cnt = np.bincount(pairs.ravel(), minlength=len(p))
    inner = cnt >= np.percentile(cnt, 90) * 0.95  # full support: as many neighbours as the bulk
    return float(np.sqrt(np.mean(((p - num / den)[inner]) ** 2)) / p_scale)


def run_dambreak(n_a: int, T_end: float = 3.0, a: float = 0.146, **overrides) -> dict:
    """Collapse of a water column ``a`` wide and ``2a`` high [m] (n^2 = 2) on a dry bed in a
    tank ``4a`` long (Koshizuka & Oka 1996: a = L = 0.146 m), ``n_a`` particles across the
    column. Surge front Z = x_front / a against T = t sqrt(2 g / a), residual height at the
    back wall H = h / (2a) against tau = t sqrt(g / a) (SOURCE.txt). The fluid's edge lies
    half a spacing beyond the outermost particle centre (the column of n_a particles is a
    wide at t = 0): front ``x_front = max x + dx/2``, height ``max z + dx/2`` of the
    particles within 2 dx of the back wall. c0 = 10 sqrt(2 g 2a) (the defaults otherwise:
    Wendland h = sqrt(2) dx, alpha = 0.01, Fourtakas delta = 0.1, CFL 0.2). Compared with
    Koshizuka & Oka (1996) and Martin & Moyce (1952, a = 2.25 in) as digitised in refdata,
    over the published points with T <= T_end and Z < 3.9 (before the front meets the far
    wall at Z = 4), and with Martin & Moyce's residual heights (Table 6) for tau <= T_end /
    sqrt(2).

    Checked (task of issue 4): the time and length scales are those of SOURCE.txt (T uses
    n t sqrt(g/a) with n = sqrt 2, Z and H are measured from the back wall and the bed);
    the column starts at rest with the hydrostatic Tait density (``set_hydrostatic``), so
    there is no start-up pressure wave; the tank wall at x < 0 is the back wall and there is
    no gate (removed instantly, as idealised). The front used to be taken at the particle
    centre, which put it dx/2 behind the fluid's edge (Z(0) = 1 - 1/(2 n_a)); now consistent.

    Status: the front target (5 %) is not met and the error grows as dx shrinks: RMS
    against Martin & Moyce 7.8 %, 12.2 %, 14.7 % and against Koshizuka & Oka 7.0 %, 10.4 %,
    12.7 % at 10, 20, 40 particles across the column, while the residual height at the
    back wall, which the fluid's bulk sets, converges to Martin & Moyce: 2.6 %, 2.0 %,
    1.2 % RMS (``python benchmarks/fluid_trade.py --case dambreak``). Where the difference
    comes from, at 20 particles against Martin & Moyce's tabulated front (Table 2): the
    computed front is slightly behind at T = 0.4 (Z = 1.098 vs 1.11), then between T = 0.4
    and 1.2 it advances at a mean dZ/dT = 0.73 while the measured one advances at 0.42
    (Z = 1.22 at T = 0.84, 1.44 at 1.19), after which both move at 1.2-1.3 (T = 1.6 to
    2.4: computed 1.22, measured 1.29 from T = 1.63 to 2.32): the whole
    difference is built in that early phase, which is when a gate or diaphragm is being
    removed in an experiment, and it is a time lag (best-fitting delay dT = 0.23, after
    which the RMS is 0.75 %), not a different front speed. The model has no bed
    friction (dynamic boundaries are nearly free-slip at alpha = 0.01) and no gate; a
    front that runs ahead of these experiments while the column's collapse agrees is what
    an inviscid model gives (numerical fronts are commonly reported ahead of them). Delaying
    the computed front by the best-fitting dT is reported as ``diag_*`` metrics, not judged.
    Open: a numerical reference of the same inviscid problem to settle it.

    ``p_noise_rms`` is the particle-scale pressure noise (:func:`_pressure_noise`) averaged
    over T = 1, 2, 3, in units of rho0 g 2a: what MLS re-initialisation (``mls_every``) is
    for."""
    from fluid.geometry import assemble, block, tank_walls

    g = 9.81
    dx = a / n_a
    walls = tank_walls([0.0, 0.0], [4 * a, 3 * a], dx, 3)
    b = assemble(2, dx, 1000.0, block([0.0, 0.0], [a, 2 * a], dx), [(walls, Kind.FIXED_WALL, 0)])
    cfg = FluidConfig(dim=2, dx=dx, u_max=math.sqrt(2 * g * 2 * a),
                      domain_lo=(-0.5 * a, -0.5 * a), domain_hi=(4.5 * a, 6 * a), **overrides)
    set_hydrostatic(b.particles, 2 * a, 1000.0, cfg.speed_of_sound, cfg.gamma, g)
    f = Fluid(cfg, b.particles)
    f.initialize(0.0)
    tscale = math.sqrt(2 * g / a)
    dT = 0.05
    Ts, Zs, Hs = [0.0], [1.0], [1.0]
    noise = []
    t = 0.0
    p_scale = 1000.0 * g * 2 * a
    while Ts[-1] < T_end - 1e-9:
        f.advance(t, dT / tscale)
        t += dT / tscale
        fl = f.ps.kind == Kind.FLUID
        x, z = f.ps.pos[fl, 0], f.ps.pos[fl, 1]
        Ts.append(Ts[-1] + dT)
        Zs.append((float(x.max()) + 0.5 * dx) / a)
        Hs.append((float(z[x < 2 * dx].max(initial=-0.5 * dx)) + 0.5 * dx) / (2 * a))
        if abs(Ts[-1] - round(Ts[-1])) < 1e-6 and Ts[-1] > 0.5:
            noise.append(_pressure_noise(f.ps, cfg.h, p_scale))
    Ts, Zs, Hs = np.array(Ts), np.array(Zs), np.array(Hs)
    metrics = {"dx_m": dx, "n_a": n_a, "c0_m_s": cfg.speed_of_sound,
               "p_noise_rms": float(np.mean(noise)) if noise else float("nan")}
    for key, name in (("ko1996", "koshizuka_oka1996_front_pysph.csv"),
                      ("mm1952", "mm1952_fig3_n2sq2_a2.25in_pysph.csv")):
        ref = _read_front(name)
        use = (ref[:, 0] <= T_end) & (ref[:, 1] < 3.9) & (ref[:, 0] > 0)
        Zsim = np.interp(ref[use, 0], Ts, Zs)
        rel = (Zsim - ref[use, 1]) / ref[use, 1]
        metrics[f"front_max_rel_err_{key}"] = float(np.abs(rel).max())
        metrics[f"front_rms_rel_err_{key}"] = float(np.sqrt(np.mean(rel**2)))
        metrics[f"front_rel_err_{key}"] = [round(float(v), 4) for v in rel]
        metrics[f"T_{key}"] = ref[use, 0].tolist()
        # diagnostic only (not judged): the time delay of the experiment that fits best
        shifts = np.arange(0.0, 0.6, 0.01)
        fit = [np.sqrt(np.mean(((np.interp(ref[use, 0] - s, Ts, Zs) - ref[use, 1]) / ref[use, 1]) ** 2))
               for s in shifts]
        metrics[f"diag_best_delay_T_{key}"] = float(shifts[int(np.argmin(fit))])
        metrics[f"diag_front_rms_rel_err_delayed_{key}"] = float(min(fit))
    href = _read_front("mm1952_table_height_ocellaris.csv")
    tau = Ts / math.sqrt(2.0)  # tau = t sqrt(g/a) = T / sqrt(2)
    use = href[:, 0] <= tau[-1]
    rel = (np.interp(href[use, 0], tau, Hs) - href[use, 1]) / href[use, 1]
    metrics["height_rms_rel_err_mm1952"] = float(np.sqrt(np.mean(rel**2)))
    metrics["height_rel_err_mm1952"] = [round(float(v), 4) for v in rel]
    metrics["front_T_Z"] = [[round(float(x), 3), round(float(z), 4)] for x, z in zip(Ts[::4], Zs[::4])]
    tolerances = {"front_rms_rel_err_ko1996": 0.05, "front_rms_rel_err_mm1952": 0.05}
    passed = all(metrics[k] < v for k, v in tolerances.items())
    return {"passed": passed, "metrics": metrics, "tolerances": tolerances,
            "particles": int(f.ps.n), "steps": int(f.counters.steps)}


@case("dambreak-2d", "2-D water column a x 2a collapsing on a dry bed: surge front against "
      "Koshizuka & Oka (1996) and Martin & Moyce (1952) within 5 % (RMS over the published points)")
def dambreak_2d(quick: bool) -> dict:
    return run_dambreak(20 if quick else 40)
