"""Sloshing and base-excitation cases of the SPH fluid (VALIDATION.md, "Fluid"): westergaard (2-D and 3-D), sloshing-frequency, sloshing-spheric10."""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np

from cosim import refdata
from cosim.study.metrics import spectral_peak
from cosim.validations.registry import case
from fluid.geometry import assemble, block, set_hydrostatic, tank_walls
from fluid.motion import Harmonic, Rotation, Translation
from fluid.particles import Kind
from fluid.probes import wall_patch_pressure
from fluid.solver import Fluid, FluidConfig

G = 9.81
RHO0 = 1000.0


# ------------------------------------------------------------------------------------ references
def westergaard_series(depth, H: float, length: float = math.inf, c: float = math.inf,
                       period: float = math.inf, terms: int = 400) -> np.ndarray:
    """Hydrodynamic pressure coefficient ``k_p = p_d / (rho a0 H)`` [-] on the wall of a
    rigid rectangular tank of ``length`` [m] (inf: Westergaard's semi-infinite reservoir)
    with water of depth ``H`` [m], under horizontal base acceleration ``a0 sin(w t)``, at
    ``depth`` [m] below the still surface (p = 0 on the surface: the frequency is far above
    the sloshing ones).

    Separation of variables with modes ``cos(k_n z)``, ``k_n = (2n-1) pi / (2H)``, z up from
    the bottom, and ``p ~ sinh(kappa_n (x - x_c))`` between the walls at ``x_c +- L/2``:

        k_p = sum_n 2 (-1)^(n+1) / (k_n H) * tanh(kappa_n L/2) / (kappa_n H) * cos(k_n z),
        kappa_n^2 = k_n^2 - w^2 / c^2,

    ``c`` [m/s] the speed of sound, ``period`` [s] = 2 pi / w. With L, c -> inf this is
    Westergaard's exact series ``(8/pi^2) sum_{m odd} sin(m pi y / 2H) / m^2`` (base value
    0.74245, refdata/analytic_hydrodynamics/SOURCE.txt A); the compressible factor
    ``1/sqrt(1 - (4H / (c T))^2 / (2n-1)^2)`` is the ``c_n`` of the same file. Valid while
    ``T > 4H/c`` (Sunara et al. 2021, Eq. 17: the first acoustic period of the column).
    """
    y = np.asarray(depth, np.float64)
    z = H - y
    n = np.arange(1, terms + 1)
    k = (2 * n - 1) * math.pi / (2 * H)
    w2c2 = (2 * math.pi / period) ** 2 / c**2 if math.isfinite(c) and math.isfinite(period) else 0.0
    if w2c2 >= k[0] ** 2:
        raise ValueError(f"period {period} s is not longer than the acoustic period 4H/c = {4 * H / c} s")
    kap = np.sqrt(k**2 - w2c2)
    th = np.tanh(kap * length / 2) if math.isfinite(length) else 1.0
    coef = 2 * (-1.0) ** (n + 1) / (k * H) * th / (kap * H)
    return (coef[None, :] * np.cos(np.outer(z, k))).sum(axis=1).reshape(y.shape)


def westergaard_parabola(depth, H: float) -> np.ndarray:
    """Westergaard's approximation ``k_p = 7/8 sqrt(y/H)``, y the depth below the surface
    (Sunara et al. 2021, Eq. 16/18; Eq. 16 prints ``sqrt(h (h - y))`` with y "the
    depth from the free surface", which would make it largest at the surface: the
    physical, Westergaard (1933) form is ``sqrt(h y)``, as VALIDATION.md notes)."""
    return 0.875 * np.sqrt(np.asarray(depth, np.float64) / H)


# ------------------------------------------------------------------------------------ helpers
def _moving_tank(dim: int, dx: float, length: float, depth: float, height: float, width: float = 0.0):
    """Open tank, inner corner at the origin, all walls one MOVING_WALL group 0, water to
    ``depth`` [m] with the hydrostatic density left to the caller."""
    lo = np.zeros(dim)
    hi = np.array([length, height] if dim == 2 else [length, width, height])
    top = hi.copy()
    top[-1] = depth
    walls = tank_walls(lo, hi, dx, 3)
    return assemble(dim, dx, RHO0, block(lo, top, dx), [(walls, Kind.MOVING_WALL, 0)]).particles


def face_pressure(f: Fluid, centres: np.ndarray, faces: np.ndarray, normals, accel, g_vec) -> np.ndarray:
    """Pressure [Pa] at points ``faces`` (m, dim) [m] on a wall face: the
    Sunara et al. 2021, Eq. 15 inverse-distance average over the fluid within 2h of
    ``centres`` (m, dim) [m] (a wall particle, or the face point itself), each fluid
    pressure first carried to the face along the unit wall ``normals`` ((dim,) or (m,
    dim), into the water) with the momentum balance at a rigid wall, ``dp/dn = rho (g -
    a_w) . n`` (``accel`` a_w [m/s^2] of the wall, (dim,) or (m, dim); ``g_vec`` [m/s^2];
    the normal part of the extrapolation of Adami, Hu & Adams 2012, J. Comput. Phys. 231,
    7057, Eq. 27), then fitted linearly along the wall (weights 1/r as Eq. 15) and taken
    at the face point. Eq. 15 alone reports the pressure at the mean position of the fluid
    it averages, about one dx into the water, which misses ``rho a dx`` of a pressure that
    varies across the wall, and near the surface or the bottom, where the neighbours lie on
    one side, it is biased along the wall as well. 0 where no fluid is near."""
    from scipy.spatial import cKDTree

    ps, c = f.ps, f.config
    dim = c.dim
    centres = np.atleast_2d(np.asarray(centres, float))
    faces = np.atleast_2d(np.asarray(faces, float))
    m = centres.shape[0]
    n = np.broadcast_to(np.asarray(normals, float), (m, dim))
    acc = np.broadcast_to(np.asarray(accel, float), (m, dim))
    fl = np.flatnonzero(ps.kind == Kind.FLUID)
    pairs = cKDTree(ps.pos[fl]).sparse_distance_matrix(cKDTree(centres), 2 * c.h, output_type="coo_matrix")
    b, j = fl[pairs.row], pairs.col
    w = 1.0 / np.maximum(pairs.data, 1e-6 * c.dx)
    d = ps.pos[b] - faces[j]
    dn = np.einsum("ij,ij->i", d, n[j])
    dpdn = np.einsum("ij,ij->i", np.asarray(g_vec, float)[None, :] - acc[j], n[j])
    q = ps.p[b] - ps.rho[b] * dpdn * dn
    tang = d - dn[:, None] * n[j]          # offset along the wall (dim-1 dof)
    if dim == 2:
        t1 = np.stack([-n[j][:, 1], n[j][:, 0]], axis=1)
        basis = np.stack([np.ones(b.size), np.einsum("ij,ij->i", tang, t1)], axis=1)
    else:
        basis = np.concatenate([np.ones((b.size, 1)), tang], axis=1)  # rank dim: lstsq below
    k = basis.shape[1]
    M = np.zeros((m, k, k))
    r = np.zeros((m, k))
    for u in range(k):
        r[:, u] = np.bincount(j, w * q * basis[:, u], m)
        for v in range(k):
            M[:, u, v] = np.bincount(j, w * basis[:, u] * basis[:, v], m)
    out = np.zeros(m)
    for i in np.flatnonzero(M[:, 0, 0] > 0):  # a few probe points: pseudo-inverse is fine
        out[i] = (np.linalg.pinv(M[i], rcond=1e-10) @ r[i])[0]
    return out


def _harmonic_fit(t: np.ndarray, y: np.ndarray, omega: float):
    """Least-squares ``y ~ c0 + c1 t + s sin(w t) + k cos(w t)`` per column of ``y`` (T, M);
    returns (s, k) (M,) [units of y]. The linear term absorbs slow drift (sloshing)."""
    A = np.stack([np.ones_like(t), t - t.mean(), np.sin(omega * t), np.cos(omega * t)], axis=1)
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    return coef[2], coef[3]


# ------------------------------------------------------------------------------------ westergaard
#: the stated target of the westergaard row of docs/VALIDATION.md and its tolerances
WESTERGAARD_TARGET = ("RMS of k_p against the exact solution < 0.04 raw, < 0.02 with the boundary-pressure "
                      "averaging of Sunara et al. 2021, Eq. 15 (the paper's own figures against the parabola)")
WESTERGAARD_STATED = {"rms_raw_vs_exact": 0.04, "rms_avg_vs_exact": 0.02}
#: the quick 3-D slice's spacing [m]: 13 rows over the 1.0 m of water
QUICK_3D_DX = 0.075
#: what is judged: the second tolerance on Eq. 15's average carried to the wall face
WESTERGAARD_TOLERANCES = {"rms_raw_vs_exact": 0.04, "rms_face_vs_exact": 0.02}
WESTERGAARD_DEPARTURE = {
    "criterion": "RMS of k_p against the exact solution < 0.04 raw, < 0.02 with the boundary-pressure averaging of "
                 "Sunara et al. 2021, Eq. 15 carried to the wall face (face_pressure); plain Eq. 15 reported beside it",
    "why": "plain Eq. 15 reports the pressure at the mean position of the fluid it averages, about 1.1 dx into the "
           "water, where the impulsive pressure is lower than at the wall by rho a0 x; the rigid wall's normal "
           "momentum balance carries it to the face, where k_p is defined. The paper's own 0.02 is against the 7/8 "
           "parabola, which lies 0.15 above the exact series at the base",
    "source": "this run"}


def westergaard_series_plot(profile: dict) -> dict:
    """The report's plot of a :func:`run_westergaard` profile: k_p over the depth, ours
    (raw, Eq. 15, Eq. 15 at the face) against the exact series and the 7/8 parabola."""
    d = profile["depth_m"]
    curves = {"exact incompressible series": {"x": profile["kp_exact"], "y": d},
              "7/8 parabola (Sunara et al. 2021, Eq. 16)": {"x": profile["kp_parabola"], "y": d, "style": "--"}}
    for q, label in (("raw", "raw boundary pressure"), ("avg", "Eq. 15"), ("face", "Eq. 15 at the face")):
        curves[f"SPH (ours), {label}"] = {"x": profile[f"kp_{q}"], "y": d, "style": "o-"}
    return {"wall pressure": {"xlabel": "k_p = p_d / (rho a0 H)", "ylabel": "depth below the surface [m]",
                              "invert_y": True, "curves": curves}}


def run_westergaard(dx: float, c0: float = 1430.0, dim: int = 2, periods_skip: int = 2,
                    periods_fit: int = 3, samples_per_period: int = 40, a0: float = 0.5 * G,
                    Tp: float = 0.03, length: float = 3.0, H: float = 1.0, height: float = 1.5,
                    width: float = 1.0, **overrides) -> dict:
    """Rigid tank ``length`` x ``height`` (x ``width`` in 3-D) [m] with water to ``H`` [m]
    under the horizontal base acceleration ``a0 sin(2 pi t / Tp)`` (a0 [m/s^2], Tp [s]),
    started from rest (Sunara et al. 2021, §3.1: 3.0 m long x 1.0 m wide x 1.5 m
    high, water 1.0 m, a0 = 0.5 g, Tp = 0.03 s, dx = 0.05 m, Fig. 5; the paper's 38 170
    particles at dx = 0.05 m are 24 000 fluid ones, 60 x 20 x 20, and its boundary: the
    1.0 m is the width, 1.5 m the height).

    c0 [m/s]: the paper takes the real speed of sound (c_p = 1430 m/s, Eq. 17: acoustic
    period 4H/c = 2.8 ms, ten times shorter than Tp). A WCSPH c0 of 10 times the flow speed
    (here ~0.02 m/s) would make the column ring at its acoustic period instead of moving as
    an incompressible block: at c0 = 150 m/s, 4H/c0 = 0.027 s ~ Tp, resonance. So c0 is set
    from the acoustics, and the time step (CFL on c0) is ~1e-5 s.

    Extraction: the hydrodynamic pressure p_d on each side wall is the part of the wall
    pressure that oscillates with the excitation: a least-squares fit of ``c0 + c1 t +
    s sin(w t) + k cos(w t)`` over ``periods_fit`` whole periods after ``periods_skip``
    (the start-up transient), per wall particle of the first layer below the surface; the
    constant holds the hydrostatic part, so no hydrostatic reference is subtracted.
    ``k_p = s / (rho a0 H)`` with the sign that makes it positive on the wall the tank
    accelerates towards the water (in phase with the acceleration), averaged over the two
    side walls (they are antisymmetric). The out-of-phase part ``k`` is reported (it
    should vanish: the impulsive pressure follows the acceleration).

    Wall pressures: "raw" is the dynamic boundary particle's own pressure (its EOS
    pressure); "avg" is Sunara et al. 2021, Eq. 15 (inverse-distance average of the fluid pressure
    near the wall particle, :meth:`Fluid.wall_pressure`); "face" is Eq. 15 with each
    fluid pressure carried to the wall face by the wall's momentum balance
    (:func:`face_pressure`).

    In 3-D k_p is read on the wall rows of the mid-plane (y = width / 2: the keys without
    suffix) and on the rows next to the side walls (y = dx/2 and width - dx/2, averaged:
    keys ending ``_side``); ``kp_{q}_side_vs_mid_max`` is their largest difference. In
    theory the flow is uniform across (the side walls are parallel to the shaking), so
    the difference is the side walls' numerical effect.

    References: the exact incompressible pressure on the wall of this finite tank
    (:func:`westergaard_series`, L = 3 m: 1.5 % below the semi-infinite reservoir at the base),
    Westergaard's semi-infinite series (refdata), the 7/8 parabola (Eq. 16), and the
    compressible series with the run's c0 (what a perfect WCSPH model would give).
    """
    if dim not in (2, 3):
        raise ValueError("dim is 2 or 3")
    ps = _moving_tank(dim, dx, length, H, height, width)
    cfg = FluidConfig(dim=dim, dx=dx, c0=c0, **overrides)
    set_hydrostatic(ps, H, RHO0, cfg.speed_of_sound, cfg.gamma, cfg.g)
    f = Fluid(cfg, ps)
    shake = Translation((1.0, 0.0) if dim == 2 else (1.0, 0.0, 0.0),
                        Harmonic.from_peak_acceleration(a0, Tp, from_rest=True))
    f.prescribe_motion(0, shake)
    f.initialize(0.0)
    return westergaard_profile(f, shake, a0, Tp, length, H, width, periods_skip, periods_fit, samples_per_period)


def westergaard_profile(f: Fluid, shake, a0: float, Tp: float, length: float, H: float, width: float,
                        periods_skip: int, periods_fit: int, samples_per_period: int) -> dict:
    """Run the shaken tank ``f`` (initialised at t = 0, its walls one moving group following
    ``shake``, the base acceleration ``a0 sin(2 pi t / Tp)``; ``length`` x ``width`` (3-D) [m],
    water ``H`` [m], inner corner at the origin) and fit k_p on both end walls as
    :func:`run_westergaard` describes: the case's metrics, tolerances, counts and profile."""
    cfg, ps = f.config, f.ps
    dim, dx, c0 = cfg.dim, cfg.dx, cfg.speed_of_sound
    # wall particles of the first layer of both end walls, below the surface (ids), per
    # plane across the width: "" the mid-plane, "_side0/1" the rows next to the side walls
    x, z = ps.pos[:, 0], ps.pos[:, -1]
    first = (ps.kind == Kind.MOVING_WALL) & (z > 0) & (z < H)
    planes = {"": first}
    if dim == 3:
        ys = np.unique(ps.pos[first & (ps.pos[:, 1] > 0) & (ps.pos[:, 1] < width), 1])
        planes = {name: first & np.isclose(ps.pos[:, 1], y) for name, y in
                  (("", ys[np.argmin(np.abs(ys - width / 2))]), ("_side0", ys[0]), ("_side1", ys[-1]))}
    ids = {}
    for pl, sel in planes.items():
        ids[("left", pl)] = np.sort(ps.ids[sel & np.isclose(x, -0.5 * dx)])
        ids[("right", pl)] = np.sort(ps.ids[sel & np.isclose(x, length + 0.5 * dx)])
    zs = {k: ps.pos[np.isin(ps.ids, v), -1][np.argsort(ps.ids[np.isin(ps.ids, v)])] for k, v in ids.items()}
    dt_s = Tp / samples_per_period
    n_skip = periods_skip * samples_per_period
    n_fit = periods_fit * samples_per_period
    rec = {(k, q): [] for k in ids for q in ("raw", "avg", "face")}
    normals = {("left", pl): np.eye(dim)[0] for pl in planes} | {("right", pl): -np.eye(dim)[0] for pl in planes}
    times = []
    t = 0.0
    for i in range(n_skip + n_fit):
        f.advance(t, dt_s)
        t = (i + 1) * dt_s
        if i + 1 <= n_skip:
            continue
        pw = f.wall_pressure()
        sels = []
        for k, v in ids.items():
            sel = np.flatnonzero(np.isin(f.ps.ids, v))
            sels.append(sel[np.argsort(f.ps.ids[sel])])
            rec[(k, "raw")].append(f.ps.p[sels[-1]].copy())
            rec[(k, "avg")].append(pw[sels[-1]].copy())
        wp = f.ps.pos[np.concatenate(sels)]
        nrm = np.concatenate([np.broadcast_to(normals[k], (s.size, dim)) for k, s in zip(ids, sels)])
        pf = np.split(face_pressure(f, wp, wp + 0.5 * dx * nrm, nrm, shake.acceleration(t), cfg.gravity),
                      np.cumsum([s.size for s in sels])[:-1])
        for k, v in zip(ids, pf):
            rec[(k, "face")].append(v)
        times.append(t)
    times = np.asarray(times)
    w = 2 * math.pi / Tp
    scale = RHO0 * a0 * H
    metrics = {}
    depth = H - zs[("left", "")]
    if not all(np.allclose(v, zs[("left", "")]) for v in zs.values()):
        raise RuntimeError("the wall rows of the planes differ")
    refs = {"exact": westergaard_series(depth, H, length),
            "westergaard_inf": westergaard_series(depth, H),
            "parabola": westergaard_parabola(depth, H),
            "compressible": westergaard_series(depth, H, length, c0, Tp)}
    kp = {}
    for q in ("raw", "avg", "face"):
        per_plane = {}
        for pl in planes:
            sl, kl = _harmonic_fit(times, np.asarray(rec[(("left", pl), q)]), w)
            sr, kr = _harmonic_fit(times, np.asarray(rec[(("right", pl), q)]), w)
            # tank accelerating +x (sin > 0): the left wall pushes the water, p rises there
            per_plane[pl] = (0.5 * (sl - sr) / scale, 0.5 * (kl - kr) / scale, (sl + sr) / scale)
        groups = {"": per_plane[""]}
        if dim == 3:  # the two rows next to the side walls, averaged (symmetric about y = width / 2)
            groups["_side"] = tuple(0.5 * (a + b) for a, b in zip(per_plane["_side0"], per_plane["_side1"]))
        for g, (k_in, k_out, asym) in groups.items():
            kp[q + g] = k_in
            metrics[f"kp_base_{q}{g}"] = float(k_in[np.argmax(depth)])
            metrics[f"kp_out_of_phase_max_{q}{g}"] = float(np.abs(k_out).max())
            metrics[f"kp_left_right_asymmetry_max_{q}{g}"] = float(np.abs(asym).max())
            for name, ref in refs.items():
                metrics[f"rms_{q}_vs_{name}{g}"] = float(np.sqrt(np.mean((k_in - ref) ** 2)))
        if dim == 3:
            metrics[f"kp_{q}_side_vs_mid_max"] = float(np.abs(kp[q + "_side"] - kp[q]).max())
    metrics.update({"kp_base_exact": float(refs["exact"][np.argmax(depth)]),
                    "kp_base_compressible": float(refs["compressible"][np.argmax(depth)]),
                    "acoustic_period_over_Tp": 4 * H / c0 / Tp, "dx_m": dx, "c0_m_s": c0,
                    "h_over_dx": cfg.h_coef, "walls": cfg.walls,
                    "wall_rows": int(depth.size), "max_speed_m_s": float(f.max_speed())})
    metrics["kp_base_face_rel_err"] = metrics["kp_base_face"] / metrics["kp_base_exact"] - 1
    metrics["face_below_avg_rms"] = bool(metrics["rms_face_vs_exact"] < metrics["rms_avg_vs_exact"])
    tolerances = dict(WESTERGAARD_TOLERANCES)
    return {"metrics": metrics, "tolerances": tolerances,
            "particles": int(f.ps.n), "steps": int(f.counters.steps),
            "profile": {"depth_m": depth.tolist(), **{f"kp_{q}": v.tolist() for q, v in kp.items()},
                        **{f"kp_{k}": v.tolist() for k, v in refs.items()}}}


def _scene_profile(scene, periods_skip: int = 1) -> dict:
    """:func:`westergaard_profile` of the shaken tank ``scene`` built as ``cosim run`` builds
    it: k_p fitted over its periods after ``periods_skip`` of them, sampled at its
    ``world.sample_every``."""
    from cosim.validations import case_scene

    d, shake = scene.domain, scene.base_motion
    samples, periods = case_scene.shaken_samples(scene)
    with case_scene.built(scene) as b:
        return westergaard_profile(b.sph, b.base_motion, shake.acceleration, shake.period, d.length, d.depth,
                                   d.width or 0.0, periods_skip, periods - periods_skip, samples)


def westergaard_scene(quick: bool):
    """The scene of westergaard (``scenes/westergaard.toml``, the quick variant's: dx = 0.1 m,
    3 periods); the full variant's spacing is 0.025 m, its run 5 periods."""
    from cosim.validations import case_scene

    return case_scene.load("westergaard", [] if quick else ["fluid.dx=0.025", "world.duration=0.15"])


@case("westergaard", "2-D tank 3.0 m long, water 1.0 m, base acceleration 0.5 g sin(2 pi t / 0.03 s): "
      "wall k_p = p_d/(rho a0 H) vs the exact incompressible series, RMS < 0.04 (raw boundary "
      "pressure) and < 0.02 (Eq. 15 averaging carried to the wall face); walls='adami'",
      target=WESTERGAARD_TARGET,
      quick="dx = 0.1 m (10 rows), 1 + 2 periods: the face k_p within 0.06 RMS of the exact series and its base "
            "value within 6 %, the out-of-phase part below 0.05, the face correction better than plain Eq. 15 "
            "(first-order errors of ~dx/H: the stated 0.04 / 0.02 need dx <= 0.05 m)", scene=westergaard_scene)
def westergaard(quick: bool) -> dict:
    """Sunara et al. 2021, §3.1 (Fig. 5): the scene :func:`westergaard_scene` (the tank,
    walls and shaking of :func:`run_westergaard`), read by :func:`westergaard_profile`; see
    :func:`run_westergaard` for set-up and extraction. c0 = 1430 m/s (the paper's c_p);
    tank walls carrying the fluid's pressure (``walls="adami"``: fluid.wall_density, with
    the wall acceleration of Adami et al. 2012 Eq. 27); Wendland, h = sqrt(2) dx, alpha =
    0.01, Fourtakas delta = 0.1, CFL 0.2 (the defaults); 2 periods skipped, 3 fitted (quick:
    1 and 2), 40 samples a period. Why h = sqrt(2) dx and not the sloshing set-up's 2 dx:
    shaken far above its first sloshing frequency the water's pressure is impulsive and the
    waves' speed hardly enters; at dx = 0.1 m h = 2 dx reads 0.073 face RMS against 0.040
    (docs/setup_chooser.md). A scene of this kind gets this set-up from the chooser
    ("impulsive", :mod:`cosim.scene.setup`).

    Reference: the exact incompressible wall pressure of this 3 m tank
    (:func:`westergaard_series`; base k_p = 0.728, Westergaard's semi-infinite 0.742, the
    7/8 parabola 0.875); the compressible series with c0 = 1430 m/s differs from it by
    0.4 %.

    Measured trade: ``docs/validation/westergaard_trade.md`` (on the case's report page).

    What limits the error: (1) plain Eq. 15 reports the pressure at the mean position of
    the fluid it averages, ~1.1 dx into the water, where the impulsive pressure is lower
    by ``rho a0 x``; carrying each fluid pressure to the wall face with the normal
    momentum balance of a rigid wall (:func:`face_pressure`) removes it. (2) The two rows
    next to the free surface read high: the SPH free surface holds p_d away from zero over
    ~dx; it dominates the remaining RMS and shrinks with dx. The paper's own numbers
    (dx = 0.05 m, against the 7/8 parabola): 0.0411 raw, 0.02 with Eq. 15; the parabola
    is 0.15 above the exact series at the base, so an accurate model cannot come close to
    it there. What was tried before (the default walls, whose raw pressure misses the
    target at every dx; the wave set-up): docs/validation/westergaard_history.md.
    """
    out = _scene_profile(westergaard_scene(quick), periods_skip=1 if quick else 2)
    out["series"] = westergaard_series_plot(out.pop("profile"))
    out["stated_tolerances"], out["departure"] = dict(WESTERGAARD_STATED), dict(WESTERGAARD_DEPARTURE)
    if quick:
        out["tolerances"] = {"rms_face_vs_exact": 0.06, "kp_base_face_rel_err": 0.06, "kp_out_of_phase_max_avg": 0.05,
                             "face_below_avg_rms": True}
    return out


def westergaard_3d_scene(quick: bool):
    """The scene of westergaard-3d (``scenes/westergaard-3d.toml``, the full variant's: the
    whole tank at dx = 0.05 m, c0 = 1430 m/s, 2 periods); the quick variant's is a slice
    0.3 m wide at dx = :data:`QUICK_3D_DX` with c0 = 700 m/s, its pressure patch on the
    slice's mid-plane."""
    from cosim.validations import case_scene

    if not quick:
        return case_scene.load("westergaard-3d")
    n = case_scene.number
    return case_scene.load("westergaard-3d", [
        f"fluid.dx={n(QUICK_3D_DX)}", "fluid.c0=700.0", "domain.width=0.3",
        'probes.pressure=[{name = "mid_plane", centre = [0.0, 0.15, 0.25], normal = [1.0, 0.0, 0.0], size = 0.2}]'])


def westergaard_3d_series_plot(profile: dict) -> dict:
    """The report's plot of a 3-D :func:`run_westergaard` profile: that of
    :func:`westergaard_series_plot` on the mid-plane, and the rows next to the side walls."""
    plot = westergaard_series_plot(profile)
    curves = plot["wall pressure"]["curves"]
    for q, label in (("raw", "raw boundary pressure"), ("face", "Eq. 15 at the face")):
        curves[f"SPH (ours), {label}, mid-plane"] = curves.pop(f"SPH (ours), {label}")
        curves[f"SPH (ours), {label}, next to a side wall"] = {"x": profile[f"kp_{q}_side"],
                                                              "y": profile["depth_m"], "style": "s:"}
    curves["SPH (ours), Eq. 15, mid-plane"] = curves.pop("SPH (ours), Eq. 15")
    return plot


@case("westergaard-3d", "the whole 3-D tank of Sunara et al. 2021, §3.1, 3.0 m long x 1.0 m wide x 1.5 m high, water 1.0 m, "
      "base acceleration 0.5 g sin(2 pi t / 0.03 s): wall k_p on the mid-plane and next to the side walls vs the "
      "exact incompressible series, the targets of westergaard (walls='adami', dx 0.05 m; quick: a 0.3 m slice "
      "at dx 0.075 m, also checked against the 2-D section)", target=WESTERGAARD_TARGET, row="westergaard",
      quick="a 0.3 m slice at dx = 0.075 m, c0 = 700 m/s, 1 + 1 periods, walls 'adami': the face k_p within 0.07 "
            "RMS of the exact series and its base value within 6 %, the out-of-phase part below 0.08, the face "
            "correction better than plain Eq. 15, and the 2-D section's profile (same settings) within 0.03 "
            "(Eq. 15) and 0.05 (face) row by row", scene=westergaard_3d_scene)
def westergaard_3d(quick: bool) -> dict:
    """The 3-D tank of Sunara et al. 2021, §3.1 (3.0 m long x 1.0 m wide x 1.5 m high,
    water 1.0 m, a0 = 0.5 g, Tp = 0.03 s; the paper's 38 170 particles at dx = 0.05 m fix
    the 1.0 m as the width: 60 x 20 x 20 fluid particles): the scene
    :func:`westergaard_3d_scene` (the tank of :func:`run_westergaard` with ``dim=3``), read
    by :func:`westergaard_profile`. k_p is read on the end walls' rows on the mid-plane
    (y = 0.5 m) and next to the side walls (averaged); references and targets as :func:`westergaard`'s. In theory the
    flow is uniform across the tank (the side walls are parallel to the shaking and carry
    no pressure gradient), so the 3-D profile is the 2-D one everywhere across; what the
    whole tank adds over a slice is the measured effect of the side walls.

    Full: the whole tank at dx = 0.05 m (the paper's), c0 = 1430 m/s (the paper's c_p),
    ``walls="adami"`` (as the 2-D case), 1 period skipped and 1 fitted (2 periods
    run instead of the slice's 1 + 2, on 44 628 particles: 24 000 fluid ones, 60 x 20 x 20,
    as the paper's), 40 samples a period. Quick (CI): a 0.3 m slice of the width
    (4 fluid rows between the side walls) at dx = 0.075 m with c0 = 700 m/s (4H/c0 = 0.19
    Tp: the compressible excess is 1.8 % at the base, see :func:`westergaard`), 1 + 1
    periods and the full variant's walls (``"adami"``, the set-up chooser's for this
    tank), and the 2-D section with the same settings: it checks that the 3-D solver
    (kernel normalisation, neighbour search, wall boundaries in 3-D) gives the 2-D
    impulsive pressure (``kp_avg_vs_2d_max``, ``kp_face_vs_2d_max``: the largest row-by-row
    differences). At dx = 0.1 m (10 rows over the depth) these walls read the base k_p
    6.8 % high; the plain dynamic walls read it 7.6 % low at dx = 0.075 m
    (docs/setup_chooser.md).

    At the full variant both targets are met on the mid-plane (raw 0.031 < 0.04, face 0.018 <
    0.02, the second a declared departure: plain Eq. 15 misses it), and the rows next to the side
    walls differ from it by less than the resolution's own error (the quick slice, the notes:
    docs/validation/westergaard-3d_history.md).

    Measured trade: ``docs/validation/westergaard-3d_trade.md`` (on the case's report page).
    """
    from cosim.validations import case_scene

    scene = westergaard_3d_scene(quick)
    out = _scene_profile(scene)
    if not quick:
        out["metrics"]["width_m"] = scene.domain.width
        out["series"] = westergaard_3d_series_plot(out.pop("profile"))
        out["stated_tolerances"], out["departure"] = dict(WESTERGAARD_STATED), dict(WESTERGAARD_DEPARTURE)
        return out
    section = _scene_profile(case_scene.section(scene))
    for q in ("raw", "avg", "face"):
        d = np.abs(np.asarray(out["profile"][f"kp_{q}"]) - np.asarray(section["profile"][f"kp_{q}"]))
        out["metrics"][f"kp_{q}_vs_2d_max"] = float(d.max())
        out["metrics"][f"rms_{q}_vs_exact_2d"] = section["metrics"][f"rms_{q}_vs_exact"]
    out["metrics"]["width_m"] = scene.domain.width
    plot = westergaard_3d_series_plot(out.pop("profile"))
    plot["wall pressure"]["curves"]["2-D section (same settings), Eq. 15 at the face"] = {
        "x": section["profile"]["kp_face"], "y": section["profile"]["depth_m"], "style": "x--"}
    out["series"] = plot
    out["stated_tolerances"], out["departure"] = dict(WESTERGAARD_STATED), dict(WESTERGAARD_DEPARTURE)
    out["tolerances"] = {"rms_face_vs_exact": 0.07, "kp_base_face_rel_err": 0.06, "kp_out_of_phase_max_avg": 0.08,
                         "face_below_avg_rms": True, "kp_avg_vs_2d_max": 0.03, "kp_face_vs_2d_max": 0.05}
    return out


# ------------------------------------------------------------------------------------ sloshing
def sloshing_omega(L: float, h: float, mode: int = 1, g: float = G) -> float:
    """Linear sloshing frequency [rad/s] of a rectangular tank of length ``L`` [m] and
    depth ``h`` [m], mode n excited by horizontal motion: ``w^2 = g k tanh(k h)``,
    ``k = (2n - 1) pi / L`` (refdata/analytic_hydrodynamics/sloshing_frequencies_housner.csv)."""
    k = (2 * mode - 1) * math.pi / L
    return math.sqrt(g * k * math.tanh(k * h))


#: the spacing [m], forced and free periods and c0_factor of the full (False) and quick
#: (True) variants (:func:`frequency_scene`'s arguments); the full one the scene file's
FREQUENCY_RUNS = {False: dict(dx=0.025, cycles_forced=3, cycles_free=8, c0_factor=20.0),
                  True: dict(dx=0.05, cycles_forced=2, cycles_free=4, c0_factor=10.0)}


def frequency_scene(dx: float, L: float = 1.0, h: float = 0.5, amplitude: float = 0.002, cycles_forced: int = 3,
                    cycles_free: int = 8, samples_per_period: int = 40, c0_factor: float = 20.0, **overrides):
    """The scene ``scenes/sloshing-frequency.toml`` at spacing ``dx`` [m]: the tank ``L`` x
    1.5 h [m] with water ``h`` [m] shaken by ``amplitude`` [m] at linear theory's first
    period T1 for ``cycles_forced`` periods (faded in and out over one), then free for
    ``cycles_free``, sampled ``samples_per_period`` times a period; c0 = ``c0_factor``
    sqrt(g h); ``overrides`` set the fluid's fields (e.g. ``setup="defaults"``)."""
    from cosim.validations import case_scene

    n = case_scene.number
    T1 = 2 * math.pi / sloshing_omega(L, h)
    return case_scene.load("sloshing-frequency", [
        f"fluid.dx={n(dx)}", f"fluid.c0_factor={n(c0_factor)}", f"domain.length={n(L)}", f"domain.depth={n(h)}",
        f"domain.height={n(1.5 * h)}", f"base_motion.amplitude={n(amplitude)}", f"base_motion.period={n(T1)}",
        f"base_motion.ramp={n(T1)}", f"base_motion.stop={n(cycles_forced * T1)}",
        f"world.duration={n((cycles_forced + cycles_free) * T1)}", f"world.sample_every={n(T1 / samples_per_period)}",
        *case_scene.settings("fluid", overrides)])


def run_sloshing_frequency(dx: float, L: float = 1.0, h: float = 0.5, amplitude: float = 0.002,
                           cycles_forced: int = 3, cycles_free: int = 8, sensor_depth: float = 0.1,
                           samples_per_period: int = 40, c0_factor: float = 20.0, **overrides) -> dict:
    """2-D rectangular tank ``L`` x 1.5 h [m], water ``h`` [m], shaken along x by
    ``amplitude`` [m] sin(w1 t) at the linear first-mode frequency w1 for
    ``cycles_forced`` periods (half-cosine ramps of one period in and out, so the tank
    stops at rest with no jump in velocity), then left still for ``cycles_free`` periods
    (free decay): the scene :func:`frequency_scene` built as ``cosim run`` builds it. The
    first natural frequency is the peak of the FFT (:func:`spectral_peak`)
    of the wall pressure (Sunara et al. 2021, Eq. 15, :meth:`Fluid.wall_pressure`) on the left wall at
    ``sensor_depth`` [m] below the surface, over the free decay only, searched between
    0.5 and 1.5 w1 (the next mode a horizontal motion excites is at 2.3 w1 for h/L = 0.5);
    compared with linear theory ``w1^2 = g (pi/L) tanh(pi h/L)`` (:func:`sloshing_omega`).
    c0 = ``c0_factor`` sqrt(g h) [-]; the set-up the scene's (``overrides`` set its fields).
    """
    from cosim.validations import case_scene

    scene = frequency_scene(dx, L, h, amplitude, cycles_forced, cycles_free, samples_per_period, c0_factor,
                            **overrides)
    w1 = sloshing_omega(L, h)
    T1 = 2 * math.pi / w1
    with case_scene.built(scene) as b:
        f = b.sph
        cfg, ps = f.config, f.ps
        x, z = ps.pos[:, 0], ps.pos[:, 1]
        wall = (ps.kind == Kind.MOVING_WALL) & np.isclose(x, -0.5 * dx) & (z > 0) & (z < h)
        cand = np.flatnonzero(wall)
        sensor_id = ps.ids[cand[np.argmin(np.abs(z[cand] - (h - sensor_depth)))]]
        sensor_z = float(z[ps.ids == sensor_id][0])
        dt_s = T1 / samples_per_period
        n_forced = cycles_forced * samples_per_period
        n_total = n_forced + cycles_free * samples_per_period
        times, p = [], []
        t = 0.0
        for i in range(n_total):
            f.advance(t, dt_s)
            t = (i + 1) * dt_s
            if i + 1 > n_forced:
                times.append(t)
                p.append(f.wall_pressure()[np.flatnonzero(f.ps.ids == sensor_id)[0]])
    times, p = np.asarray(times), np.asarray(p)
    f1_ref = w1 / (2 * math.pi)
    f1, _, _ = spectral_peak(times, p, 0.5 * f1_ref, 1.5 * f1_ref)
    amp = 0.5 * (p.max() - p.min())
    metrics = {"f1_hz": f1, "f1_linear_hz": f1_ref, "f1_rel_err": abs(f1 / f1_ref - 1),
               "f1_signed_rel_err": f1 / f1_ref - 1,
               "pressure_amplitude_pa": float(amp),
               "wave_amplitude_estimate_m": float(amp / (RHO0 * G) * math.cosh(math.pi / L * h)
                                                  / math.cosh(math.pi / L * sensor_z)),
               "sensor_z_m": sensor_z, "decay_s": float(times[-1] - times[0]), "dx_m": dx,
               "c0_m_s": cfg.speed_of_sound, "h_over_dx": cfg.h_coef, "walls": cfg.walls}
    tolerances = {"f1_rel_err": 0.02}
    return {"metrics": metrics, "tolerances": tolerances,
            "particles": int(f.ps.n), "steps": int(f.counters.steps)}


# ------------------------------------------------------------------------------------ SPHERIC 10
#: impact peaks of the measured record (SOURCE.txt): time [s], pressure [Pa]
SPHERIC10_PEAKS = ((2.375, 3683.0), (4.067, 3890.0), (5.672, 2663.0), (7.303, 7148.0))


def spheric10_scene(dx: float = 0.0031, c0: float = 28.0, t_end: float = 8.0, sample_dt: float = 1e-4,
                    **overrides):
    """The case's scene file ``scenes/sloshing-spheric10.toml`` (the tank, its water, the
    measured roll about the centre of its bottom, the sensor's patch) at spacing ``dx``
    [m], ``c0`` [m/s], ``t_end`` [s] long, sampled every ``sample_dt`` [s]; ``overrides``
    set the fluid's fields (e.g. ``walls="dbc"``, ``alpha=0.02``). The patch is
    ``max(SPHERIC10_SENSOR, 2 dx)`` long: at least two particle columns, so that a coarse
    lattice does not put its centre between two."""
    from cosim.validations import case_scene

    n = case_scene.number
    size = max(SPHERIC10_SENSOR, 2 * dx)
    (x, z) = SPHERIC10_SENSOR_AT
    return case_scene.load("sloshing-spheric10", [
        f"fluid.dx={n(dx)}", f"fluid.c0={n(c0)}", f"world.duration={n(t_end)}", f"world.sample_every={n(sample_dt)}",
        f'probes.pressure=[{{name = "sensor", centre = [{n(x)}, {n(z)}], normal = [1.0, 0.0], size = {n(size)}}}]',
        *case_scene.settings("fluid", overrides)])


def spheric10_motion() -> Rotation:
    """The measured roll of SPHERIC Test 10 as the case's scene gives it: the record's
    angle (refdata SloshingMotionData.dat.gz: t [s], angle [deg], 5e-5 s apart) about the
    centre of the tank bottom, (0.45, 0) m in the tank's frame (its inner corner at the
    origin). Sign: the record's positive angle lowers the left wall (x = 0): the measured
    impacts on the left-wall sensor come 0.15 s after each positive extreme of the angle;
    our positive angle about +y lowers the right wall, so the scene negates the record
    (``scale = -1``)."""
    from cosim.scene.build import roll_record
    from cosim.validations import case_scene

    b = case_scene.load("sloshing-spheric10").base_motion
    return Rotation(b.point, roll_record(b))


def spheric10_pressure() -> np.ndarray:
    """(t [s], p [Pa]) of the measured left-wall pressure, sorted by time (the file's rows
    come as interleaved min/max pairs, SOURCE.txt)."""
    p = np.loadtxt(refdata.path("sloshing_spheric_test10", "EXP_Pressure_SPHERIC_Benchmark#10.txt"), skiprows=2)
    return p[np.argsort(p[:, 0], kind="stable")]


@contextmanager
def spheric10_built(dx: float, c0: float = 28.0, t_end: float = 8.0, sample_dt: float = 1e-4,
                    **overrides) -> Iterator[tuple[Fluid, Rotation]]:
    """The SPHERIC Test 10 tank of :func:`spheric10_scene` built as ``cosim run`` builds it,
    at rest, its walls rolled by the measured angle: (Fluid, Rotation), initialised at
    t = 0, for the ``with`` block."""
    from cosim.validations import case_scene

    with case_scene.built(spheric10_scene(dx, c0, t_end, sample_dt, **overrides)) as b:
        yield b.sph, b.base_motion


#: (dx [m], c0 [m/s], t_end [s], sample_dt [s]) of the case's full (False) and quick (True)
#: variants: the quick one the first swing only (no impact), 5 particle rows over the depth
SPHERIC10_RUNS = {False: (0.0031, 28.0, 8.0, 1e-4), True: (0.0186, 28.0, 1.3, 0.005)}
#: length [m] along the wall of the SPHERIC 10 sensor's patch (:func:`spheric10_sensor`)
SPHERIC10_SENSOR = 0.010
#: the sensor's centre [m] on the left wall's face at the still-water level, in the tank's
#: frame (inner corner at the origin)
SPHERIC10_SENSOR_AT = (0.0, 0.093)
#: the sensor readings :func:`run_spheric10` offers
SPHERIC10_SENSORS = ("patch", "face")


def spheric10_sensor(f: Fluid, roll: Rotation, t: float, kind: str = "patch") -> float:
    """Pressure [Pa] at the sensor (left wall face, z = 93 mm in the tank frame) at time
    ``t`` [s]. ``kind="patch"``: :func:`~fluid.probes.wall_patch_pressure`, the normal force
    the fluid exerts on the wall over a ``SPHERIC10_SENSOR`` long patch about the sensor's
    centre, divided by its length: what a flush transducer measures, a momentum balance
    in which a half-wet face reads half and a splash particle its push. ``kind="face"``:
    :func:`face_pressure`, Sunara et al. 2021, Eq. 15 over 2h carried to the face with the wall's
    acceleration and fitted along the wall: an average of the fluid's own pressure near
    the point, which reads a thin film or a few splash particles as if they filled the
    support (and extrapolates wildly where only two or three particles are near)."""
    if kind not in SPHERIC10_SENSORS:
        raise ValueError(f"sensor kind {kind!r}: choose one of {SPHERIC10_SENSORS}")
    centre = np.array([SPHERIC10_SENSOR_AT])
    at, _ = roll(t, centre)
    normal = roll(t, centre + [1.0, 0.0])[0][0] - at[0]
    if kind == "patch":
        # at least two particle columns: a coarse lattice may put the centre between two
        return wall_patch_pressure(f, at[0], normal, max(SPHERIC10_SENSOR, 2 * f.config.dx), group=0)
    _, dth, ddth = roll.signal.state(t)
    r = at[0] - np.asarray(roll.point)
    acc = ddth * np.array([r[1], -r[0]]) - dth ** 2 * r
    return float(face_pressure(f, at, at, normal, acc, f.config.gravity)[0])


def running_mean_max(t: np.ndarray, p: np.ndarray, width: float, lo: float, hi: float):
    """Largest mean of ``p`` over a ``width`` [s] window inside ``lo``..``hi`` [s] (p
    interpolated linearly on a 25 us grid): (value, centre time [s])."""
    g = np.arange(lo, hi, 2.5e-5)
    n = max(1, int(round(width / 2.5e-5)))
    c = np.convolve(np.interp(g, t, p), np.ones(n) / n, mode="valid")
    j = int(np.argmax(c))
    return float(c[j]), float(g[j] + width / 2)


def run_spheric10(dx: float, t_end: float = 8.0, c0: float = 28.0, sample_dt: float = 1e-4,
                  window: float = 0.25, sensor: str = "patch", **overrides) -> dict:
    """SPHERIC benchmark 10, low filling, water, lateral impact (Souto-Iglesias et al.,
    CEHINAV-UPM; refdata/sloshing_spheric_test10/SOURCE.txt): 2-D section of the tank
    0.900 x 0.508 m, water 0.093 m, rolled by the measured angle about the centre of the
    tank bottom; pressure on the left wall at the still-water level (z = 0.093 m in the
    tank frame). The set-up is the case's scene (:func:`spheric10_scene`), built as
    ``cosim run`` builds it; the case steps the fluid and reads the sensor itself, so that
    it may read the "face" sensor too.

    Wang et al. 2022 (§3) validate their SPH on the same kind of test
    (Brizzolara et al. 2011: a 900 x 508 mm tank rolled +-4 deg about an axis 184 mm above
    the bottom, in a 2-D section); the record we hold is the SPHERIC Test 10 data as
    packaged by DualSPHysics, whose axis is the centre of the bottom (SOURCE.txt), so we
    follow that.

    dx [m]; c0 [m/s] (28: 10 times a 2.8 m/s impact speed, as ~29 sqrt(g h), and as
    DualSPHysics' own set-up of this case, coefsound 30 x sqrt(g h) = 28.7 m/s,
    examples/mdbc/03_Sloshing/CaseSloshingHR_Def.xml); ``overrides`` set the scene's fluid
    fields; the scene's ``walls="adami"`` (the tank walls carry the fluid's
    pressure, Adami et al. 2012: the wall pressure of a plain dynamic boundary is not a
    pressure the wall feels, and it halves the first impact, see the case's docstring).
    The sensor (:func:`spheric10_sensor`, ``sensor``) is by default the normal force the
    fluid exerts on a 10 mm patch of the wall face about its centre over the patch's
    length, as a transducer measures it (``"patch"``; SOURCE.txt gives the sensor's
    centre, not its size); ``"face"`` reads :func:`face_pressure` at the point instead
    (Eq. 15 average of the fluid within 2h, carried to the face and fitted along the wall),
    the sensor of sessions 3-5. Sampled every ``sample_dt`` [s] (1e-4: the experiment
    recorded at 20 kHz, SOURCE.txt; the SPH impact rings at the acoustic period of the
    water near the wall, ~5 ms at c0 = 28 m/s, which 1e-4 s resolves). For each measured
    impact before ``t_end`` [s] the SPH peak is the largest pressure within ``window`` [s]
    of the measured peak time: its ratio to the measured peak and its time lag are
    reported; so are the ratio of the pressure impulses (integral of the positive
    pressure over the same windows) and the ratio of the largest 20 ms running means
    (``impactK_mean20ms_ratio``; the same on the record), which vary less between
    experimental repetitions and between SPH settings than the peak.
    """
    if sensor not in SPHERIC10_SENSORS:
        raise ValueError(f"sensor={sensor!r}: choose one of {SPHERIC10_SENSORS}")
    n = int(round(t_end / sample_dt))
    times, p = np.empty(n), np.empty(n)
    with spheric10_built(dx, c0, t_end=t_end, sample_dt=sample_dt, **overrides) as (f, roll):
        cfg = f.config
        t = 0.0
        for i in range(n):
            f.advance(t, sample_dt)
            t = (i + 1) * sample_dt
            times[i], p[i] = t, spheric10_sensor(f, roll, t, sensor)
    exp = spheric10_pressure()
    metrics = {"dx_m": dx, "c0_m_s": c0, "h_over_dx": cfg.h_coef, "walls": cfg.walls, "t_end_s": t_end,
               "sensor": sensor}
    ratios, lags, imp = [], [], []
    for k, (tp, pp) in enumerate(SPHERIC10_PEAKS):
        if tp + window > t_end:
            continue
        sel = np.abs(times - tp) <= window
        j = np.argmax(np.where(sel, p, -np.inf))
        esel = np.abs(exp[:, 0] - tp) <= window
        ratios.append(p[j] / pp)
        lags.append(times[j] - tp)
        # impulse of the positive pressure over the window (the measured record is
        # decimated to min/max pairs, so its integral is approximate)
        imp.append(np.trapezoid(np.maximum(p[sel], 0), times[sel])
                   / np.trapezoid(np.maximum(exp[esel, 1], 0), exp[esel, 0]))
        m20 = running_mean_max(times, p, 0.02, tp - window, tp + window)[0]
        e20 = running_mean_max(exp[:, 0], exp[:, 1], 0.02, tp - window, tp + window)[0]
        metrics[f"impact{k + 1}_peak_ratio"] = float(ratios[-1])
        metrics[f"impact{k + 1}_lag_s"] = float(lags[-1])
        metrics[f"impact{k + 1}_impulse_ratio"] = float(imp[-1])
        metrics[f"impact{k + 1}_mean20ms_ratio"] = m20 / e20
    if ratios:
        metrics["peak_ratio_worst"] = float(max(abs(r - 1) for r in ratios))
        metrics["lag_worst_s"] = float(max(abs(x) for x in lags))
    metrics["max_pressure_pa"] = float(p.max())
    # the first swing (0.5 - 1.2 s): water runs to the lowered left wall without impact,
    # a nearly hydrostatic pressure that a coarse run resolves
    if t_end >= 1.2:
        w = (times >= 0.5) & (times <= 1.2)
        ew = (exp[:, 0] >= 0.5) & (exp[:, 0] <= 1.2)
        metrics["swing1_peak_ratio"] = float(p[w].max() / exp[ew, 1].max())
        metrics["swing1_lag_s"] = float(times[w][np.argmax(p[w])] - exp[ew, 0][np.argmax(exp[ew, 1])])
        metrics["swing1_peak_err"] = abs(metrics["swing1_peak_ratio"] - 1)
        metrics["swing1_lag_abs_s"] = abs(metrics["swing1_lag_s"])
    if ratios:  # the target: impact peaks within 20 %, in phase
        tolerances = {"peak_ratio_worst": 0.2, "lag_worst_s": 0.05}
    else:  # a run too short for an impact: the first swing
        tolerances = {"swing1_peak_err": 0.2, "swing1_lag_abs_s": 0.1}
    return {"metrics": metrics, "tolerances": tolerances,
            "particles": int(f.ps.n), "steps": int(f.counters.steps),
            "series": {"t": times, "p": p}}


@case("sloshing-frequency", "2-D tank 1.0 m long, water 0.5 m, shaken 3 periods then free: first "
      "natural frequency from the FFT of the wall pressure within 2 % of linear theory (fluid set-up "
      "SLOSHING_2D: h = 2 dx, walls='adami')", target="first peak of the wall-pressure FFT within 2 %",
      quick="the stated target (within 2 % of linear theory) at dx = 0.05 m (10 rows), c0 = 10 sqrt(g h), 2 "
            "forced and 4 free periods, instead of dx = 0.025 m, 20 sqrt(g h), 3 and 8",
      scene=lambda quick: frequency_scene(**FREQUENCY_RUNS[quick]))
def sloshing_frequency(quick: bool) -> dict:
    """See :func:`run_sloshing_frequency`. Reference: linear potential theory
    ``w1^2 = g (pi/L) tanh(pi h/L)``: f1 = 0.8462 Hz for L = 1 m, h = 0.5 m (refdata
    sloshing_frequencies_housner.csv: T1 = 1.18182 s).

    Set-up: :data:`fluid.solver.SLOSHING_2D`, the one the chooser gives the scene's shaken
    tank ("sloshing"): Wendland with h = 2 dx and the tank walls carrying the fluid's
    pressure (``walls="adami"``), the other settings the solver's defaults. Why these two:
    the plain dynamic walls make a stiff spring at the contact line (first part below),
    and at the default h = sqrt(2) dx the particle lattice under pressure has a spurious
    shear stiffness (second part). h = 2 dx is the one support between 1.2 and 2.4 dx at
    which the square lattice is linearly stable for every wavelength
    (``benchmarks/lattice_stiffness.py --stability``); at h = 1.7 dx (DualSPHysics' coefh
    1.2), which also gives +0.9 %, a tank at rest rearranges its lattice.

    With this set-up the first mode meets the target (+0.84 % at dx = 0.025 m); with the
    solver's defaults it runs +9.4-10 % fast: the plain dynamic walls put a stiff spring at
    the contact line, and at h = sqrt(2) dx the lattice under pressure has a spurious shear
    stiffness; the two levers are needed together. The measured trade and the search:
    docs/validation/sloshing-frequency_history.md.

    Measured trade: ``docs/validation/sloshing-frequency_trade.md`` (on the case's report page).
    """
    return run_sloshing_frequency(**FREQUENCY_RUNS[quick])


@case("sloshing-spheric10", "SPHERIC Test 10 (rolling tank 900 x 508 mm, water 93 mm, measured roll): "
      "left-wall pressure impact peaks within 20 % and within 0.05 s of the measured ones (dx 3.1 mm, "
      "~35 min; quick: the first swing at 18.6 mm)", target="pressure peaks within 20 %, in phase",
      quick="the first swing only (0.5-1.2 s, before the first impact) at dx = 18.6 mm (5 rows over the depth): "
            "its pressure peak within 20 % and 0.1 s of the measured one",
      scene=lambda quick: spheric10_scene(*SPHERIC10_RUNS[quick]))
def sloshing_spheric10(quick: bool) -> dict:
    """See :func:`run_spheric10`. Reference: the measured pressure of SPHERIC Test 10
    (refdata/sloshing_spheric_test10; impact peaks 3.68, 3.89, 2.66, 7.15 kPa at 2.375,
    4.067, 5.672, 7.303 s; the record's largest 20 ms mean at the first impact 2.15 kPa).

    Set-up: ``walls="adami"`` (the walls carry the fluid's pressure), c0 = 28 m/s
    (DualSPHysics' own set-up of the case: 30 sqrt(g h)), the default alpha = 0.01,
    delta = 0.1, h = sqrt(2) dx (the chooser's "sloshing" h = 2 dx on the first swing: peak
    error 0.076 against 0.069, lag 0.038 against 0.043 s, neither better on both:
    docs/setup_chooser.md); the sensor is the wall's normal force over a 10 mm patch about z = 93 mm
    (:func:`spheric10_sensor`), sampled at 10 kHz (the record: 20 kHz). The roll axis is
    the centre of the tank bottom (SOURCE.txt, DualSPHysics' CaseSloshingHR_Def.xml), which
    the record fits better than the axis 184 mm above the bottom of VALIDATION.md's row and
    the case of Wang et al. 2022 (Brizzolara et al.); plain dynamic walls read the first impact lower
    (both measured: docs/validation/sloshing-spheric10_history.md).

    The full case runs dx = 3.1 mm, h = sqrt(2) dx, 8 s: every impact in phase (the 0.05 s
    target), the first carries the measured impulse and 20 ms mean, and no peak is within 20 %:
    the target is not met. The peaks are the weakly compressible model's water hammer (of the
    size of rho c0 u_n, sharper as dx shrinks); the measured peak is most likely set by the
    entrapped air and the real sound speed, which a single-phase model does not have (inferred,
    not tested). The sensor is a 10 mm patch because a transducer reads the force over its face
    (:func:`face_pressure` reads a film or splash as if it covered the wall). The measured table,
    the convergence trade and the history: docs/validation/sloshing-spheric10_history.md.

    Measured trade: ``docs/validation/sloshing-spheric10_trade.md`` (on the case's report page).
    """
    dx, c0, t_end, sample_dt = SPHERIC10_RUNS[quick]
    out = run_spheric10(dx, t_end, c0, sample_dt)
    if quick:  # the first swing only (no impact): 5 particle rows over the depth
        out["stated_tolerances"] = {"peak_ratio_worst": 0.2, "lag_worst_s": 0.05}
    ours = out.pop("series")
    exp = spheric10_pressure()
    seen = exp[:, 0] <= ours["t"][-1]
    out["series"] = {"left-wall pressure": {"xlabel": "t [s]", "ylabel": "p [kPa]", "curves": {
        "measured (SPHERIC Test 10)": {"x": exp[seen, 0], "y": exp[seen, 1] / 1e3},
        f"SPH (ours), {out['metrics']['sensor']} sensor": {"x": ours["t"], "y": ours["p"] / 1e3}}}}
    return out
