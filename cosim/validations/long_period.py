"""The long-period excitations of Sunara et al. 2021 (§3.1 Fig. 7-8, §3.3
Fig. 18, §3.2 Fig. 13): the rectangular tank (3.0 m long, 1.0 m wide, water 1.0 m) and the
same tank with its right side 45 deg from the vertical at T_p = 1.0 s, and the cylinder
(D = 2 m, water 0.6 m) at T_p = 0.7 s, base acceleration 0.5 g sin(2 pi t / T_p)
from rest. The paper shows total wall pressures at some times (the times are in its
figures, not in its text) and says only that the water climbs the walls with "big churning
and splattering"; it gives no numbers. So the sloshing is compared with linear
potential-flow theory (:mod:`cosim.validations.forced_sloshing`: every mode, exact for small
waves; Housner's first-mode frequency beside it), twice:

- **linear regime**, a0 = 0.05 g: the waves are small (wall run-up ~0.1 m, k A ~ 0.1), so
  linear theory should hold over the whole record: this checks the SPH sloshing itself
  (surface at gauges across the tank, the wall pressure, the first mode's free frequency);
- **the paper's 0.5 g**: linear theory predicts a run-up of 0.5 m within the first period
  and 1.2 m after it (on 1.0 m of water in a 1.5 m tank): far outside its range. Reported:
  how far the SPH departs from it, from when, and the first mode's free frequency.

Excitation: ``periods`` whole periods of the paper's acceleration, then the tank stops
(at whole periods of a0 sin(w t) from rest its velocity is back to zero and its
acceleration continuous), then ``free_periods`` first-mode periods of free sloshing.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy import optimize, special

from cosim.errors import InputError
from cosim.validations import case_scene
from cosim.validations import forced_sloshing as fs
from cosim.validations.registry import case
from cosim.validations.sloshing import face_pressure
from fluid.particles import Kind
from fluid.probes import surface_elevation
from fluid.solver import Fluid

G = 9.81
RHO0 = 1000.0

#: the paper's tanks: (length or diameter, water depth, wall height, width) [m] and T_p [s]
#: (the inclined tank: its bottom's length, the right side ``beta`` [deg] from the vertical)
TANKS = {"rectangular": dict(size=3.0, depth=1.0, height=1.5, width=1.0, period=1.0),
         "inclined": dict(size=3.0, depth=1.0, height=1.5, width=1.0, period=1.0, beta=45.0),
         "cylinder": dict(size=2.0, depth=0.6, height=1.0, width=2.0, period=0.7)}


def _check_lattice(shape: str, dx: float, tank: dict) -> None:
    """Refuse a ``dx`` [m] that does not divide the water depth (every tank) or the
    rectangle's length: the lattice fills whole rows, so the water would stand lower (1.0
    m at dx = 0.075 m: 13 rows, 0.975 m, every gauge 25 mm low against a linear peak of
    0.12 m) or the tank be shorter than linear theory's."""
    if not dx > 0:
        raise InputError(f"long-period: dx={dx} m; give a positive particle spacing")
    sizes = {"depth": tank["depth"]}
    if shape == "rectangular":
        sizes["length"] = tank["size"]
    for name, s in sizes.items():
        n = s / dx
        if abs(n - round(n)) > 1e-6 * n:
            k = max(1, math.floor(n))
            raise InputError(f"long-period: dx={dx:g} m puts {n:.2f} particle rows in the {shape} tank's {name} "
                             f"{s:g} m (the lattice fills {math.floor(n + 1e-9)}); give a dx that divides it, e.g. "
                             f"{s:g}/{k} = {s / k:.4g} m or {s:g}/{k + 1} = {s / (k + 1):.4g} m")


def _domain(shape: str, tank: dict, dim: int) -> dict:
    """The scene's ``[domain]`` of the tank ``shape`` of :data:`TANKS`: the rectangle's and the
    inclined tank's inner bottom-left corner at the origin, the cylinder's axis on z."""
    L, h, H = tank["size"], tank["depth"], tank["height"]
    width = {"width": tank["width"]} if dim == 3 else {}
    if shape == "rectangular":
        return {"kind": "tank", "length": L, "height": H, "depth": h, **width}
    if shape == "inclined":
        return {"kind": "inclined-tank", "angle": tank["beta"], "length": L, "depth": h, "height": H, **width}
    return {"kind": "cylinder-tank", "diameter": L, "depth": h, "height": H}


def _centre(shape: str, tank: dict) -> np.ndarray:
    """(x, y) [m] of the middle of the still surface in the tank's frame (:func:`_domain`)."""
    return np.zeros(2) if shape == "cylinder" else np.array([_centre_x(tank), 0.5 * tank["width"]])


def long_period_scene(shape: str = "rectangular", dx: float = 0.1, dim: int = 2, a0: float = 0.05 * G,
                      period: float | None = None, periods: int = 3, free_periods: float = 3.0, c0: float = 40.0,
                      sample_dt: float = 0.02, settle: float | None = None):
    """The scene of one run of :func:`run_long_period` (its arguments): the case's scene file
    ``scenes/long-period.toml`` with the tank ``shape`` (:func:`_domain`), ``dim``, ``dx``,
    ``c0``, ``a0`` [m/s^2] sin(2 pi t / ``period``) from rest for ``periods`` periods, then the
    tank held where it got to (``base_motion.hold``) for ``free_periods`` periods of linear
    theory's first mode, sampled every ``sample_dt`` [s]; ``settle`` [s] of damped rest first
    (default 1 s for the inclined tank, whose lattice water is not at rest against the slope,
    none for the others). Refused, before any work: an unknown shape, a 2-D cylinder, a
    ``dx`` that does not divide the water depth (or the rectangle's length)."""
    from cosim.scene.toml_io import from_dict, to_dict

    if shape not in TANKS:
        raise InputError(f"long-period: shape={shape!r}; give one of {sorted(TANKS)}")
    if shape == "cylinder" and dim != 3:
        raise InputError("long-period: the cylinder is 3-D; give dim=3")
    tank = TANKS[shape]
    _check_lattice(shape, dx, tank)
    period = tank["period"] if period is None else period
    t_end = periods * period + free_periods * 2 * math.pi / _modes(shape).omega[0]
    settle = (1.0 if shape == "inclined" else 0.0) if settle is None else settle
    d = to_dict(case_scene.load("long-period"))
    d["world"] |= {"dim": dim, "duration": round(round(t_end / sample_dt) * sample_dt, 12), "sample_every": sample_dt}
    d["fluid"] |= {"dx": dx, "c0": c0, "settle": settle}
    d["domain"] = _domain(shape, tank, dim)
    d["base_motion"] |= {"direction": [1.0] + [0.0] * (dim - 1), "acceleration": round(float(a0), 12),
                         "period": float(period), "stop": round(periods * period, 12)}
    if (shape, dim) != ("rectangular", 2):
        d.pop("probes", None)  # the file's gauges are the 2-D rectangle's; the case reads its own
    return from_dict(d)


@functools.lru_cache(maxsize=None)
def _modes(shape: str):
    """Linear theory's sloshing modes of the tank ``shape`` of :data:`TANKS`
    (:mod:`cosim.validations.forced_sloshing`; the inclined tank's by finite elements, so
    computed once)."""
    tank = TANKS[shape]
    L, h = tank["size"], tank["depth"]
    if shape == "rectangular":
        return fs.rectangular_modes(L, h)
    if shape == "cylinder":
        return fs.cylinder_modes(0.5 * L, h)
    return fs.trapezoid_modes(L, h, tank["beta"])


def gauge_mode_basis(shape: str, size: float, xc: np.ndarray, modes) -> np.ndarray:
    """Least-squares basis along the gauge line (x from the centre [m]): the first three
    antisymmetric modes (the linear response) and two symmetric ones (what second order
    adds), columns in that order; the inclined tank, which has no symmetry: its first five
    modes."""
    if shape == "inclined":
        return modes.surface_shapes(xc)[:5].T
    if shape == "rectangular":
        k = (2 * np.arange(1, 4) - 1) * math.pi / size
        ks = 2 * np.arange(1, 3) * math.pi / size
        return np.column_stack([np.sin(np.outer(xc, k)), np.cos(np.outer(xc, ks))])
    R = 0.5 * size
    k = special.jnp_zeros(1, 3) / R
    ks = special.jn_zeros(1, 2) / R              # J0'(r) = -J1(r): the axisymmetric modes
    return np.column_stack([special.j1(np.outer(xc, k)), special.j0(np.outer(np.abs(xc), ks))])


def free_frequency(t: np.ndarray, y: np.ndarray, omega0: float) -> float:
    """Angular frequency [rad/s] of the damped sinusoid ``e^(-s t) (A cos w t + B sin w t) + C``
    that fits ``y(t)`` best, searched within 25 % of ``omega0`` (:func:`free_decay`)."""
    return free_decay(t, y, omega0)[0]


def free_decay(t: np.ndarray, y: np.ndarray, omega0: float, rates=(0.0,)) -> tuple[float, float]:
    """Angular frequency w [rad/s] and decay rate s [1/s] of the damped sinusoid
    ``e^(-s t) (A cos w t + B sin w t) + C`` that fits ``y(t)`` best (variable projection:
    the linear coefficients solved for each w, s), w within 25 % of ``omega0``; the
    search starts from the best of a grid of w and the decay ``rates`` [1/s] given."""
    tt = t - t[0]

    def resid(q):
        w, s = q
        e = np.exp(-s * tt)
        M = np.column_stack([e * np.cos(w * tt), e * np.sin(w * tt), np.ones_like(tt)])
        return M @ np.linalg.lstsq(M, y, rcond=None)[0] - y

    grid = [(w, s) for w in np.linspace(0.75 * omega0, 1.25 * omega0, 101) for s in rates]
    q0 = grid[int(np.argmin([np.sum(resid(q) ** 2) for q in grid]))]
    sol = optimize.least_squares(resid, q0, bounds=([0.75 * omega0, -1.0], [1.25 * omega0, 5.0]))
    return float(sol.x[0]), float(sol.x[1])


def _walls(shape: str, tank: dict, zf: np.ndarray, dim: int):
    """Face points (tank frame: x from the centre, y = 0, z up from the bottom) [m] and
    their normals into the water, left and right, at heights ``zf``; and the x of the
    still surface's ends (where linear theory's run-up is read)."""
    L = tank["size"]
    tb = math.tan(math.radians(tank.get("beta", 0.0)))
    half = _centre_x(tank)
    x = {"left": np.full(zf.size, -half),
         "right": (L + zf * tb - half) if shape == "inclined" else np.full(zf.size, half)}
    b = math.atan(tb)
    n = {"left": np.eye(dim)[0], "right": -np.eye(dim)[0]}
    if shape == "inclined":
        n["right"] = np.array([-math.cos(b), math.sin(b)] if dim == 2 else [-math.cos(b), 0.0, math.sin(b)])
    faces = {}
    for side in ("left", "right"):
        pts = np.zeros((zf.size, dim))
        pts[:, 0], pts[:, -1] = x[side], zf
        faces[side] = (pts, n[side])
    return faces, half


def run_long_period(shape: str = "rectangular", dx: float = 0.05, dim: int = 2, a0: float = 0.5 * G,
                    period: float | None = None, periods: int = 3, free_periods: float = 3.0,
                    c0: float = 40.0, sample_dt: float = 0.02, gauges: int = 25, settle: float | None = None,
                    profile_times=None) -> dict:
    """The tank ``shape`` of :data:`TANKS` ("rectangular" and "inclined": the 2-D section
    or the whole 3-D tank; "cylinder": 3-D) under a0 [m/s^2] sin(2 pi t / period) along x
    from rest for ``periods`` periods, then ``free_periods`` linear first-mode periods at
    rest; sampled every ``sample_dt`` [s]: the scene :func:`long_period_scene`, built as
    ``cosim run`` builds it (its fluid set-up the chooser's, "sloshing": h = 2 dx and walls
    carrying the fluid's pressure; in 3-D also the density diffusion faded under the
    surface), stepped here from sample to sample.

    c0 [m/s]: 40 m/s puts the acoustic period 4 h / c0 (0.1 s at h = 1 m) at a tenth of
    T_p, as the paper's c_p does for its short periods (Sunara et al. 2021, Eq. 17; the compressible excess
    of the impulsive pressure is then 1 / sqrt(1 - (4 h / (c0 T_p))^2) - 1 = 0.5 %), and is
    ~30 times the largest sloshing speed.

    Recorded: the free surface (:func:`fluid.probes.surface_elevation`) at ``gauges``
    points on the tank's centre line along x, 2 h from the walls; the run-up at each wall
    (the top of the fluid within one dx of the wall, + dx/2, the median over the columns
    along the wall); the total pressure at points on each wall's face every dx up to the
    still level (:func:`cosim.validations.sloshing.face_pressure`, Sunara et al. 2021, Eq. 15 carried to
    the face). Each against linear theory at the same points. The first mode's amplitude
    is the least-squares fit of the gauges to the first modes (:func:`gauge_mode_basis`); its
    free frequency (:func:`free_frequency`) over the free sloshing. Returned: the metrics,
    and the record of the series (the gauges and all the fitted modal amplitudes
    included), each beside linear theory's.
    """
    scene = long_period_scene(shape, dx, dim, a0, period, periods, free_periods, c0, sample_dt, settle)
    tank = TANKS[shape]
    period = scene.base_motion.period
    h = tank["depth"]
    modes = _modes(shape)
    t_stop = scene.base_motion.stop
    n_samples = int(round(scene.world.duration / sample_dt))
    centre = _centre(shape, tank)
    with case_scene.built(scene) as b:
        f, shake = b.sph, b.base_motion
        if scene.fluid.settle > 0:
            f.settle(scene.fluid.settle)
        cfg = f.config
        zf = dx * (0.5 + np.arange(int(math.floor(h / dx + 1e-9))))
        faces, half = _walls(shape, tank, zf, dim)
        margin = 2 * cfg.h
        xg = np.linspace(-half + margin, half - margin, gauges)    # from the centre
        rec = {"t": [], "gauges": [], "runup_left": [], "runup_right": [], "p_left": [], "p_right": []}
        t = 0.0
        for i in range(n_samples):
            f.advance(t, sample_dt)
            t = (i + 1) * sample_dt
            origin = np.zeros(dim)
            origin[0] = centre[0] + shake.signal.state(t)[0]
            if dim == 3:
                origin[1] = centre[1]
            gpts = (xg[:, None] + origin[0] if dim == 2 else
                    np.column_stack([xg + origin[0], np.full(gauges, origin[1])]))
            rec["gauges"].append(surface_elevation(f, gpts) - h)
            up = _runup(f, shape, tank, origin, dx)
            rec["runup_left"].append(up[0] - h)
            rec["runup_right"].append(up[1] - h)
            acc = shake.acceleration(t)
            for side, (pts, n) in faces.items():
                here = pts + origin
                rec[f"p_{side}"].append(face_pressure(f, here, here, n, acc, cfg.gravity))
            rec["t"].append(t)
        rec = {k: np.asarray(v) for k, v in rec.items()}
        rec["gauges"] = np.nan_to_num(rec["gauges"], nan=-h)  # a gauge the water left: the bottom
        return _compare(rec, modes, shape, tank, a0, period, t_stop, xg, faces, half, f, cfg, profile_times)


def _runup(f: Fluid, shape: str, tank: dict, origin: np.ndarray, dx: float) -> tuple[float, float]:
    """Height [m] of the water at the left and right walls: the top fluid particle within
    dx of the wall + dx / 2 (the surface of a particle layer), the median over the columns
    along the wall (dx wide; the cylinder: within 15 deg of the x-z plane)."""
    ps = f.ps
    pos = ps.pos[ps.kind == Kind.FLUID]
    rel = pos[:, :-1] - origin[:-1]
    z = pos[:, -1]
    L = tank["size"]
    out = []
    for side in ("left", "right"):
        sgn = -1.0 if side == "left" else 1.0
        if shape == "cylinder":
            R = 0.5 * L
            r = np.hypot(rel[:, 0], rel[:, 1])
            near = (r > R - dx) & (sgn * rel[:, 0] > r * math.cos(math.radians(15.0)))
            col = np.floor(np.arctan2(rel[near, 1], sgn * rel[near, 0]) * R / dx)
        else:
            x = rel[:, 0] + _centre_x(tank)                # from the bottom-left inner corner
            if side == "left":
                d = x
            else:
                b = math.radians(tank.get("beta", 0.0))
                d = (L + z * math.tan(b) - x) * math.cos(b)
            near = d < dx
            col = np.floor(rel[near, 1] / dx) if rel.shape[1] > 1 else np.zeros(int(near.sum()))
        zn = z[near]
        if zn.size == 0:
            out.append(0.0)
            continue
        tops = [zn[col == c].max() for c in np.unique(col)]
        out.append(float(np.median(tops)) + 0.5 * dx)
    return out[0], out[1]


def _centre_x(tank: dict) -> float:
    """x of the still surface's middle from the bottom-left inner corner [m]."""
    return 0.5 * (tank["size"] + tank["depth"] * math.tan(math.radians(tank.get("beta", 0.0))))


def _compare(rec: dict, modes, shape: str, tank: dict, a0: float, period: float, t_stop: float, xg, faces: dict,
             half: float, f: Fluid, cfg, profile_times) -> dict:
    t = rec["t"]
    L, h = tank["size"], tank["depth"]
    eta_n, a = fs.response(modes, a0, period, t_stop, t)
    lin_g = fs.surface(modes, eta_n, xg).T                                   # (times, gauges)
    lin_wall = fs.surface(modes, eta_n, np.array([-half, half])).T          # (times, 2)
    y0 = None if shape != "cylinder" else np.zeros(faces["left"][0].shape[0])
    lin_p = {side: fs.pressure(modes, eta_n, a, pts[:, 0], pts[:, -1] - h, y0).T for side, (pts, _) in faces.items()}
    zf = faces["left"][0][:, -1]
    basis = gauge_mode_basis(shape, L, xg, modes)
    amp = np.linalg.lstsq(basis, rec["gauges"].T, rcond=None)[0]           # (5, times)
    amp_lin = np.linalg.lstsq(basis, lin_g.T, rcond=None)[0]
    forced, free = t <= t_stop, t > t_stop
    w1 = float(modes.omega[0])
    runup = np.column_stack([rec["runup_left"], rec["runup_right"]])
    peak_lin = float(np.abs(lin_g).max())
    peak_wall_lin = float(np.abs(lin_wall).max())
    dev = np.abs(rec["gauges"] - lin_g).max(1)                               # (times,)
    late = np.flatnonzero(dev > 0.2 * peak_lin)
    p_scale = RHO0 * G * h
    p_err = np.concatenate([rec["p_left"] - lin_p["left"], rec["p_right"] - lin_p["right"]], axis=1)
    metrics = {
        "gauge_rms_rel": float(np.sqrt(np.mean((rec["gauges"] - lin_g) ** 2)) / peak_lin),
        "gauge_rms_rel_forced": float(np.sqrt(np.mean((rec["gauges"][forced] - lin_g[forced]) ** 2)) / peak_lin),
        "runup_peak_m": float(np.abs(runup).max()),
        "runup_peak_linear_m": peak_wall_lin,
        "runup_peak_forced_m": float(np.abs(runup[forced]).max()),
        "runup_peak_forced_linear_m": float(np.abs(lin_wall[forced]).max()),
        "runup_rms_rel": float(np.sqrt(np.mean((runup - lin_wall) ** 2)) / peak_wall_lin),
        "mode1_peak_m": float(np.abs(amp[0]).max()),
        "mode1_peak_linear_m": float(np.abs(amp_lin[0]).max()),
        "departure_time_s": float(t[late[0]]) if late.size else None,
        "wall_pressure_rms_rel": float(np.sqrt(np.mean(p_err**2)) / p_scale),
        "omega1_linear": w1,
        "omega1_housner": (None if shape == "inclined" else
                           fs.housner_omega1(shape, L if shape == "rectangular" else 0.5 * L, h)),
        "particles_lost": int(f.counters.removed["FLUID"]),
        "max_speed_m_s": float(f.max_speed()), "dx_m": cfg.dx, "c0_m_s": cfg.speed_of_sound,
        "a0_g": a0 / G, "period_s": period, "t_stop_s": t_stop,
    }
    metrics["omega1_free"] = free_frequency(t[free], amp[0][free], w1)
    metrics["omega1_free_rel_err"] = metrics["omega1_free"] / w1 - 1
    if metrics["omega1_housner"] is not None:
        metrics["omega1_housner_rel_err"] = metrics["omega1_housner"] / w1 - 1
    if profile_times is None:
        profile_times = [k * period / 4 for k in (1, 2, 3, 4)]
    idx = [int(np.argmin(np.abs(t - s))) for s in profile_times]
    profiles = {f"{t[i]:.2f}": {"left_kpa": (rec["p_left"][i] / 1e3).tolist(),
                                 "right_kpa": (rec["p_right"][i] / 1e3).tolist(),
                                 "left_linear_kpa": (lin_p["left"][i] / 1e3).tolist(),
                                 "right_linear_kpa": (lin_p["right"][i] / 1e3).tolist()} for i in idx}
    metrics["particles"] = int(f.ps.n + sum(f.counters.removed.values()))  # the set-up's, lost ones included
    return {"metrics": metrics, "particles": metrics["particles"], "steps": int(f.counters.steps),
            "record": {"t": t.tolist(), "runup_left_m": runup[:, 0].tolist(), "runup_right_m": runup[:, 1].tolist(),
                       "runup_left_linear_m": lin_wall[:, 0].tolist(), "runup_right_linear_m": lin_wall[:, 1].tolist(),
                       "mode1_m": amp[0].tolist(), "mode1_linear_m": amp_lin[0].tolist(),
                       "gauge_x_m": np.asarray(xg).tolist(), "gauges_m": rec["gauges"].tolist(),
                       "gauges_linear_m": lin_g.tolist(), "modes_m": amp.tolist(), "modes_linear_m": amp_lin.tolist(),
                       "z_faces_m": zf.tolist(), "profiles": profiles}}


# ------------------------------------------------------------------------------- the case
#: the linear regime's judged metrics: the surface during the forcing, the first mode's
#: free frequency, the wall pressure over the whole record (module docstring)
LINEAR_TOLERANCES = {"gauge_rms_rel_forced": 0.10, "omega1_free_rel_err": 0.02, "wall_pressure_rms_rel": 0.03}
#: the quick variant (dx = 0.1 m, 10 rows over the depth): first-order errors of ~dx / h
QUICK_TOLERANCES = {"gauge_rms_rel_forced": 0.15, "omega1_free_rel_err": 0.03, "wall_pressure_rms_rel": 0.04}
#: the target column of docs/VALIDATION.md's row (Sunara et al. 2021 give figures, no numbers: ours)
LONG_PERIOD_TARGET = ("at 0.05 g, each tank: the surface at 25 gauges within 10 % RMS of the linear peak while "
                      "forced, the first mode's free frequency within 2 % of linear theory, the total wall "
                      "pressure within 3 % RMS of rho g h; at 0.5 g reported")
LINEAR_A0 = 0.05 * G
PAPER_A0 = 0.5 * G


def long_period_plots(runs: dict) -> dict:
    """The report's plots: per tank, the run-up at the left wall and the first mode's
    amplitude against linear theory in both regimes, and the paper's figure (Sunara et al. 2021, Fig. 7,
    13, 18): the total pressure up both walls at times of the first period at 0.5 g."""
    out = {}
    for tank, regimes in runs.items():
        for regime, r in regimes.items():
            rec = r["record"]
            out[f"{tank}, {regime}: run-up at the left wall"] = {
                "xlabel": "t [s]", "ylabel": "water level at the wall above still [m]",
                "curves": {"linear theory": {"x": rec["t"], "y": rec["runup_left_linear_m"]},
                           "SPH (ours)": {"x": rec["t"], "y": rec["runup_left_m"]}}}
            out[f"{tank}, {regime}: first sloshing mode"] = {
                "xlabel": "t [s]", "ylabel": "mode 1 amplitude [m]",
                "curves": {"linear theory": {"x": rec["t"], "y": rec["mode1_linear_m"]},
                           "SPH (ours)": {"x": rec["t"], "y": rec["mode1_m"]}}}
        rec = regimes["0.5 g"]["record"]
        z = rec["z_faces_m"]
        for side in ("left", "right"):
            curves = {}
            for i, (t, p) in enumerate(rec["profiles"].items()):
                curves[f"t = {t} s, SPH"] = {"x": p[f"{side}_kpa"], "y": z, "style": f"C{i}o"}
                curves[f"t = {t} s, linear"] = {"x": p[f"{side}_linear_kpa"], "y": z, "style": f"C{i}-"}
            out[f"{tank}, 0.5 g: total pressure on the {side} wall (Sunara et al. 2021, Fig. 7/13/18)"] = {
                "xlabel": "total pressure [kPa]", "ylabel": "height above the bottom [m]", "curves": curves}
    return out


@case("long-period", "The long periods of Sunara et al. 2021 (rectangular and 45 deg tanks at T_p = 1.0 s, the cylinder at "
      "0.7 s): sloshing against linear potential theory (every mode; Housner's first mode beside it), at 0.05 g "
      "where it holds and at the paper's 0.5 g where it does not",
      target=LONG_PERIOD_TARGET,
      quick="the 2-D section of the rectangular tank at dx = 0.1 m (10 rows): 15 %, 3 %, 4 % (first-order errors "
            "of ~dx/h); 0.5 g reported",
      scene=lambda quick: long_period_scene("rectangular", 0.1 if quick else 0.05, 2, LINEAR_A0))
def long_period(quick: bool) -> dict:
    """Sunara et al. 2021, §3.1 (Fig. 7-8), §3.2 (Fig. 13), §3.3 (Fig. 18): see :func:`run_long_period`.
    Three periods of forcing, three first-mode periods free. Full: the 2-D sections of the
    rectangular and the 45 deg tank at dx = 0.05 m, the whole 3-D rectangular tank at
    dx = 1/13 m (13 rows: dx divides the depth and length) and the cylinder at dx = 0.06 m
    (10 rows), the coarsest dx at which each 3-D tank meets its three targets; quick: the
    rectangular section at dx = 0.1 m.

    At 0.05 g each tank meets its three targets at the dx above; at the paper's 0.5 g the
    surface leaves linear theory within the first or second period and breaks (reported, not
    judged). The measured table, the full variant's record, why ours departs from linear
    theory and the 0.5 g runs: docs/validation/long-period_history.md.
    """
    plan = ({"rectangular 2-D": ("rectangular", 2, 0.1)} if quick else
            {"rectangular 2-D": ("rectangular", 2, 0.05), "inclined 45 deg 2-D": ("inclined", 2, 0.05),
             "rectangular 3-D": ("rectangular", 3, 1 / 13), "cylinder 3-D": ("cylinder", 3, 0.06)})
    runs, metrics, tolerances = {}, {}, {}
    particles = steps = 0
    for name, (shape, dim, dx) in plan.items():
        runs[name] = {}
        for regime, a0 in (("0.05 g", LINEAR_A0), ("0.5 g", PAPER_A0)):
            r = run_long_period(shape, dx=dx, dim=dim, a0=a0)
            runs[name][regime] = r
            metrics[f"{name}, {regime}"] = r["metrics"]
            particles, steps = max(particles, r["particles"]), steps + r["steps"]
        for k, v in (QUICK_TOLERANCES if quick else LINEAR_TOLERANCES).items():
            tolerances[f"{name}, 0.05 g.{k}"] = v
    out = {"metrics": metrics, "tolerances": tolerances, "particles": particles, "steps": steps,
           "series": long_period_plots(runs)}
    if quick:
        out["stated_tolerances"] = {f"rectangular 2-D, 0.05 g.{k}": v for k, v in LINEAR_TOLERANCES.items()}
    return out
