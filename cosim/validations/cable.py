"""Validation cases of the SPH cable (Dinçer & Demir 2020, ``docs/VALIDATION.md``, Moorings).

The reference for the static cases is the exact elastic catenary between two supports
with point loads (Irvine, *Cable Structures* 1981, Eq. 2.24-2.25 generalised piecewise),
solved here independently of the cable solver: :func:`elastic_catenary`.

Every case runs its scene (``scenes/cable-*.toml``) by ``cosim run``'s runner: the cable in
air between a held or shaken body and its anchor, or hanging from a moved fairlead. The
static cases settle for a fixed time at a large mass-proportional damping rate
(``moorings.damping``, Dinçer & Demir 2020, Eq. 12 as implemented: it changes no
equilibrium); the reported ``residual_speed`` (from the last two samples) shows how
settled the answer is.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import fsolve

from cosim.validations.registry import case
from moorings.sph_cable import MAX_STRAIN, catenary_points


def elastic_catenary(span_x, span_z, length, w, EA, loads=(), s=None):
    """Exact elastic catenary from (0, 0) to (span_x, span_z) [m], unstretched ``length`` [m],
    weight ``w`` [N/m], stiffness ``EA`` [N], downward point loads ``loads`` = [(s_i, P_i)]
    ([m] of unstretched arc from the first support, [N]).

    With H the horizontal tension and Q(s) = Q0 + w s + sum_{s_i < s} P_i the vertical
    component of the tension along the cable (Q0 < 0: the cable leaves (0, 0) downwards),
    each load-free piece integrates to
    ``dx = H ds/EA + (H/w)(asinh(Q1/H) - asinh(Q0/H))`` and
    ``dz = (Q0 ds + w ds^2/2)/EA + (H/w)(sqrt(1+(Q1/H)^2) - sqrt(1+(Q0/H)^2))``.
    Returns (H, Q0, positions at ``s`` (n, 2) or None); the reactions are (-H, -Q0) at the
    first support and (H, -Q(L)) at the second (force of the support on the cable).
    """
    loads = sorted((float(a), float(b)) for a, b in loads)
    bps = [0.0] + [a for a, _ in loads] + [length]
    jumps = [0.0] + [b for _, b in loads]

    def walk(H, Q0, upto=None):
        x = z = 0.0
        Q = Q0
        pts = []
        for i in range(len(bps) - 1):
            Q += jumps[i]
            a, b = bps[i], bps[i + 1]
            for si in ([] if upto is None else upto[(upto >= a) & ((upto < b) | ((i == len(bps) - 2) & (upto <= b)))]):
                d = si - a
                Qe = Q + w * d
                pts.append((si, x + H * d / EA + H / w * (math.asinh(Qe / H) - math.asinh(Q / H)),
                            z + (Q * d + 0.5 * w * d * d) / EA
                            + H / w * (math.hypot(1, Qe / H) - math.hypot(1, Q / H))))
            d = b - a
            Qe = Q + w * d
            x += H * d / EA + H / w * (math.asinh(Qe / H) - math.asinh(Q / H))
            z += (Q * d + 0.5 * w * d * d) / EA + H / w * (math.hypot(1, Qe / H) - math.hypot(1, Q / H))
            Q = Qe
        return x, z, pts

    # initial guess from the inextensible catenary without point loads
    sx = np.linspace(0, length, 3)
    p = catenary_points((0.0, 0.0), (span_x, span_z), length, sx)
    slope0 = (p[1, 1] - p[0, 1]) / max(p[1, 0] - p[0, 0], 1e-12)
    H0 = w * length / 4.0
    for _ in range(2):
        sol = fsolve(lambda u: np.array(walk(math.exp(u[0]), u[1] * math.exp(u[0]))[:2]) - (span_x, span_z),
                     [math.log(H0), slope0 - sum(P for _, P in loads) / max(H0, 1e-9)], xtol=1e-13, full_output=True)
        u, info, ier, _ = sol
        if ier == 1:
            break
        H0 *= 4
    H, Q0 = math.exp(u[0]), u[1] * math.exp(u[0])
    res = np.array(walk(H, Q0)[:2]) - (span_x, span_z)
    if np.abs(res).max() > 1e-9 * length:
        raise RuntimeError(f"elastic catenary did not converge (residual {res})")
    pos = None
    if s is not None:
        pts = walk(H, Q0, np.asarray(s, float))[2]
        pos = np.array([[px, pz] for _, px, pz in sorted(pts)])
    return H, Q0, pos


#: Dinçer & Demir 2020, Table 2: displacement of L (vertical, horizontal) [m], consensus of 8 methods
CASE1_REF = (-5.626, -0.859)


def case1_scene(quick: bool, particles: int | None = None):
    """cable-case1's scene (``scenes/cable-case1.toml``, the point load at L on), the quick
    variant's 40 particles, or ``particles``."""
    from cosim.validations import case_scene

    n = particles or (40 if quick else None)
    return case_scene.load("cable-case1", [f"moorings.segments={n}"] if n else [])


def run_case1(scene):
    """Dinçer & Demir 2020, Case 1: ``scene`` (:func:`case1_scene`) run as written and without
    its point load, by ``cosim run``'s runner; the displacement of L (the line's recorded
    point) between the two settled states against Table 2 and the exact elastic catenary.
    Returns (metrics, steps of both runs)."""
    from cosim.validations.case_scene import run_once

    ln, body = scene.moorings.lines[0], scene.bodies[0]
    (s_L,), (load,) = ln.points, ln.point_loads
    span = body.pos[0] + body.fairleads[ln.fairlead.split(".", 1)[1]][0] - ln.anchor[0]
    settled, steps = {}, 0
    for label, sc in (("selfweight", scene.with_values(["moorings.lines[0].point_loads=[]"])), ("loaded", scene)):
        res = run_once(sc)
        xL = np.stack([res[f"{ln.name}.point1_x"], res[f"{ln.name}.point1_z"]], axis=-1)
        speed = float(np.linalg.norm(xL[-1] - xL[-2]) / sc.world.sample_every)
        settled[label] = (xL[-1], -float(res[f"{body.name}.mooring_Fx"][-1]), speed)  # H: the pull on the far support
        steps += res.summary["steps"]
    (xL0, Hs, v1), (xL1, Hl, v2) = settled["selfweight"], settled["loaded"]
    d = xL1 - xL0
    P = -load.force[-1]
    H0, _, e0 = elastic_catenary(span, 0.0, ln.length, ln.weight, ln.EA, s=[s_L])
    H1, _, e1 = elastic_catenary(span, 0.0, ln.length, ln.weight, ln.EA, loads=[(s_L, P)], s=[s_L])
    de = e1[0] - e0[0]
    m = {
        "dz_L_m": float(d[1]), "dx_L_m": float(d[0]),
        "err_dz_vs_table2": float(d[1] / CASE1_REF[0] - 1), "err_dx_vs_table2": float(d[0] / CASE1_REF[1] - 1),
        "exact_dz_L_m": float(de[1]), "exact_dx_L_m": float(de[0]),
        "err_dz_vs_exact": float(d[1] / de[1] - 1), "err_dx_vs_exact": float(d[0] / de[0] - 1),
        "H_selfweight_N": Hs, "H_selfweight_exact_N": H0,
        "H_loaded_N": Hl, "H_loaded_exact_N": H1,
        "err_L_selfweight_m": float(np.linalg.norm(xL0 - e0[0])),
        "residual_speed_m_s": max(v1, v2),
    }
    return m, steps


@case("cable-case1", "SPH cable, Dinçer & Demir 2020, Case 1: self-weight catenary + 35.586 kN point load (Table 1-2)",
      target="within 0.5 %",
      quick="the stated target, the displacement of L within 0.5 % of Table 2, with 40 particles instead of 313",
      scene=case1_scene)
def cable_case1(quick: bool) -> dict:
    """Dinçer & Demir 2020, Case 1 (Table 1): span 304.8 m, length 312.73 m, E = 131 GPa, A = 548.4 mm²,
    w = 46.12 N/m; after the self-weight state has settled, 35.586 kN at L (125.88 m of
    unstretched arc from A). Target: the displacement of L within 0.5 % of Table 2
    (-5.626 m vertical, -0.859 m horizontal); also reported against the exact two-segment
    elastic catenary (``refdata/cable_static_dynamic``: -5.6313, -0.8615 m).
    The seed used 312 particles; the full case uses 313 (nodes at both supports), the
    quick one 40. The case's scene (``scenes/cable-case1.toml``) runs with the load and
    without it, each settled at 2.5 1/s from the inextensible catenary."""
    scene = case1_scene(quick)
    m, steps = run_case1(scene)
    tol = 0.005
    return {"metrics": m, "tolerances": {"err_dz_vs_table2": tol, "err_dx_vs_table2": tol},
            "particles": scene.moorings.segments, "steps": steps}


#: Dinçer & Demir 2020, Experiment 2 (Section 3.3.2, Table 5)
EXP2 = dict(length=1.272, support_b=(1.2, -0.22), w=0.2656, E=109e9, d_wire=0.5e-3)
#: Table 5: (unstretched arc from P0 [m], measured x, y [m]) of P1..P5
EXP2_POINTS = ((0.212, 0.187, -0.127), (0.424, 0.371, -0.223), (0.636, 0.573, -0.283),
               (0.848, 0.782, -0.306), (1.060, 0.989, -0.288))


def exp2_scene(case: str, quick: bool, particles: int | None = None):
    """The scene of an Experiment 2 case (``scenes/CASE.toml``), the quick variant's 31
    particles, or ``particles``."""
    from cosim.validations import case_scene

    n = particles or (31 if quick else None)
    return case_scene.load(case, [f"moorings.segments={n}"] if n else [])


def exp2_run(scene, every_particle: bool = False):
    """Run an Experiment 2 scene (:func:`exp2_scene`) by ``cosim run``'s runner; returns
    (its results, the line's material points recorded [m] from P0, their positions over
    time (samples, points, 2) [m]). ``every_particle``: every particle's position is
    recorded too (the points set to all the cable's nodes, which adds none)."""
    from cosim.validations import case_scene
    from moorings.sph_cable import material_coordinates

    ln = scene.moorings.lines[0]
    if every_particle:
        nodes = material_coordinates(ln.length, scene.moorings.segments, [x for x in ln.points if 0 < x < ln.length])
        scene = scene.with_values(["moorings.lines[0].points=[" + ", ".join(case_scene.number(x) for x in nodes)
                                   + "]"])
        ln = scene.moorings.lines[0]
    res = case_scene.run_once(scene)
    xz = np.stack([np.stack([res[f"{ln.name}.point{k + 1}_x"], res[f"{ln.name}.point{k + 1}_z"]], axis=-1)
                   for k in range(len(ln.points))], axis=1)
    return res, ln.length - np.asarray(ln.points), xz


def exp2_static_metrics(scene):
    """Dinçer & Demir 2020, Experiment 2 at rest: ``scene`` run and its settled cable against
    the exact elastic catenary (shape at every particle, the reactions at both supports) and
    the measured P1-P5; returns (metrics, every particle's settled position (n, 2) [m] from
    P0 on, their arc lengths [m] from P0)."""
    ln = scene.moorings.lines[0]
    bx, bz = ln.anchor
    L, w, EA = ln.length, ln.weight, ln.EA
    res, s0, xz = exp2_run(scene, every_particle=True)
    order = np.argsort(s0)
    s0, x = s0[order], xz[-1][order]
    H, Q0, ex = elastic_catenary(bx, bz, L, w, EA, s=s0)
    marks = [q[0] for q in EXP2_POINTS]
    sph_pts = np.array([x[np.argmin(np.abs(s0 - m))] for m in marks])
    ex_pts = elastic_catenary(bx, bz, L, w, EA, s=marks)[2]
    meas = np.array([q[1:] for q in EXP2_POINTS])
    Fx, Fz = res["support.mooring_Fx"][-1], res["support.mooring_Fz"][-1]  # the cable's pull on P0
    Ta = res[f"{ln.name}.anchor_tension"][-1]
    m = {
        "EA_assumed_N": EA,
        "shape_max_err_m": float(np.linalg.norm(x - ex, axis=1).max()),
        "reaction_x_P0_N": float(-Fx), "reaction_z_P0_N": float(-Fz), "anchor_tension_N": float(Ta),
        "H_exact_N": H, "V_P0_exact_N": float(-Q0), "anchor_tension_exact_N": math.hypot(H, Q0 + w * L),
        "err_H_vs_exact": float(abs(Fx / H - 1.0)),
        "err_V_P0_vs_exact": float(abs(Fz / Q0 - 1.0)),
        "err_anchor_tension_vs_exact": float(abs(Ta / math.hypot(H, Q0 + w * L) - 1.0)),
        "weight_N": w * L,
        "dist_to_measured_P1_P5_m": [float(d) for d in np.linalg.norm(sph_pts - meas, axis=1)],
        "exact_dist_to_measured_P1_P5_m": [float(d) for d in np.linalg.norm(ex_pts - meas, axis=1)],
        "residual_speed_m_s": float(np.linalg.norm(xz[-1] - xz[-2], axis=1).max() / scene.world.sample_every),
        "steps": res.summary["steps"],
    }
    return m, x, s0


@case("cable-exp2-static", "SPH cable, Dinçer & Demir 2020, Experiment 2 at rest: reactions and shape (Table 5)",
      target="shape within 1 mm of the exact catenary; reactions within 1 %; report the distance to the measured "
             "points",
      quick="the stated target (shape within 1 mm, reactions within 1 %) with 31 particles instead of 121",
      scene=lambda quick: exp2_scene("cable-exp2-static", quick))
def cable_exp2_static(quick: bool) -> dict:
    """Dinçer & Demir 2020, Experiment 2 (Section 3.3.2): supports (0, 0) and (1.2, -0.22) m, l = 1.272 m,
    w = 0.2656 N/m, E = 109 GPa. The paper gives no wire diameter; 0.5 mm is assumed
    (EA = 21.4 kN; the strain is ~2e-5, so the shape hardly depends on it and the reference
    catenary uses the same EA). The case's scene settles the cable at 30 1/s; targets: the
    reactions at both supports (the horizontal and vertical pull on P0, the anchor's
    tension) within 1 % of the exact elastic catenary's, the shape at every particle within
    1 mm of it. The distance to the measured P1-P5 is reported, not targeted (the measured
    points imply a longer cable: the exact 1.272 m catenary misses them by 15-19 mm)."""
    scene = exp2_scene("cable-exp2-static", quick)
    m, x, _ = exp2_static_metrics(scene)
    tol = {"err_H_vs_exact": 0.01, "err_V_P0_vs_exact": 0.01, "err_anchor_tension_vs_exact": 0.01,
           "shape_max_err_m": 1e-3}
    return {"metrics": m, "tolerances": tol, "particles": scene.moorings.segments, "steps": m["steps"],
            "series": exp2_static_series(x)}


def exp2_static_series(x) -> dict:
    """The settled cable of Experiment 2 (its particles ``x`` (n, 2) [m]) against the exact
    elastic catenary and the measured points P1-P5 (for the report's plot)."""
    p = EXP2
    EA = p["E"] * math.pi / 4 * p["d_wire"] ** 2
    s = np.linspace(0.0, p["length"], 201)
    ex = elastic_catenary(*p["support_b"], p["length"], p["w"], EA, s=s)[2]
    meas = np.array([q[1:] for q in EXP2_POINTS])
    return {"shape": {"xlabel": "x [m]", "ylabel": "z [m]", "curves": {
        "exact elastic catenary, 1.272 m": {"x": ex[:, 0], "y": ex[:, 1]},
        "SPH cable (ours)": {"x": x[:, 0], "y": x[:, 1], "style": "o"},
        "measured P1-P5 (Table 5)": {"x": meas[:, 0], "y": meas[:, 1], "style": "s"}}}}


def vs_catenary_scene(quick: bool, particles: int | None = None, speed: float | None = None):
    """cable-vs-catenary's scene (``scenes/cable-vs-catenary.toml``: 60 particles, 0.05 m/s;
    quick: 20 at 0.1 m/s), or with ``particles`` and the fairlead's ``speed`` [m/s] given:
    the same 20 m of travel."""
    from cosim.validations import case_scene

    scene = case_scene.load("cable-vs-catenary")
    if quick:
        particles, speed = particles or 20, speed or 0.1
    if particles is None and speed is None:
        return scene
    (t0, s0), (t1, s1) = scene.bodies[0].motion.points
    v0 = (s1 - s0) / (t1 - t0)
    v = speed or v0
    n = case_scene.number
    return scene.with_values([f"moorings.segments={particles or scene.moorings.segments}",
                              f"world.duration={n(scene.world.duration * v0 / v)}",
                              f"bodies[0].motion.points=[[0.0, 0.0], [{n(t1 * v0 / v)}, {n(s1)}]]"])


def run_vs_catenary(scene):
    """Run the rig ``scene`` (:func:`vs_catenary_scene`) by ``cosim run``'s runner; compare its
    line's fairlead tension with the quasi-static elastic catenary with seabed
    (moorings.catenary.solve) at every sample after the start. Returns (metrics, rows (X [m],
    T [N], quasi-static T [N]), the run's summary)."""
    from cosim.validations.case_scene import run_once
    from moorings.catenary import solve

    body, ln = scene.bodies[0], scene.moorings.lines[0]
    res = run_once(scene)
    site = body.fairleads[ln.fairlead.split(".", 1)[1]]
    X = (body.pos[0] + site[0] + res[f"{body.name}.surge"] - ln.anchor[0])[1:]
    T = res[f"{ln.name}.tension"][1:]
    law = solve(X, body.pos[-1] + site[-1] - ln.anchor[-1], ln.length, ln.weight, ln.EA)
    T_qs = np.hypot(law.H, law.V)
    e = T / T_qs - 1.0
    rows = [(round(float(x), 3), float(a), float(b)) for x, a, b in zip(X, T, T_qs)]
    (t0, s0), (t1, s1) = body.motion.points
    metrics = {"max_abs_err_tension": float(np.abs(e).max()), "mean_err_tension": float(e.mean()),
               "samples_X_T_Tqs": rows[:: max(1, len(rows) // 8)], "speed_m_s": (s1 - s0) / (t1 - t0)}
    return metrics, rows, res.summary


@case("cable-vs-catenary", "SPH cable as a mooring line with seabed, slowly moved fairlead, vs the elastic catenary",
      target="fairlead tension within 2 % when quasi-static",
      quick="the stated target, fairlead tension within 2 % at every sample, with 20 particles moved at 0.1 m/s "
            "instead of 60 at 0.05 m/s", scene=vs_catenary_scene)
def cable_vs_catenary(quick: bool) -> dict:
    """A 150 m chain (h = 50 m, w = 918.75 N/m, EA = 1 GN, d = 0.15 m with Morison drag
    and added mass) from its anchor with seabed contact; a rig moves its fairlead from
    X = 120 m to 140 m (fairlead tension 62 to 304 kN) at 0.05 m/s (quick: 0.1 m/s, 20
    particles): the case's scene. Target: fairlead tension within 2 % of the quasi-static
    elastic catenary with seabed (Barreiro et al. 2016, §3, moorings.catenary) at every
    sample."""
    scene = vs_catenary_scene(quick)
    m, rows, summary = run_vs_catenary(scene)
    X, T, Tqs = np.array(rows).T
    series = {"fairlead tension": {"xlabel": "fairlead X [m]", "ylabel": "tension [kN]", "curves": {
        "quasi-static elastic catenary": {"x": X, "y": Tqs / 1e3},
        "SPH cable (ours)": {"x": X, "y": T / 1e3, "style": "o"}}}}
    return {"metrics": m, "tolerances": {"max_abs_err_tension": 0.02},
            "particles": scene.moorings.segments, "steps": summary["steps"], "series": series}


def fit_length_to_measured_shape() -> float:
    """Unstretched length [m] whose exact catenary passes closest (RMS) to the measured
    P1-P5 of Dinçer & Demir 2020, Table 5, with the markers at the same fractions of the length."""
    from scipy.optimize import minimize_scalar

    p = EXP2
    EA = p["E"] * math.pi / 4 * p["d_wire"] ** 2
    meas = np.array([q[1:] for q in EXP2_POINTS])
    s = np.array([q[0] for q in EXP2_POINTS])

    def rms(L):
        pts = elastic_catenary(*p["support_b"], L, p["w"], EA, s=s * L / p["length"])[2]
        return float(np.sqrt(((pts - meas) ** 2).sum(axis=1).mean()))

    return float(minimize_scalar(rms, bounds=(p["length"], 1.05 * p["length"]), method="bounded",
                                 options={"xatol": 1e-6}).x)


#: the FFT length of the free-period measurement of :func:`run_exp2_shake`: at the scene's
#: sampling (2.5 ms) the spectral bin is 0.0061 Hz (about 1 ms of period at 0.42 s)
SHAKE_NFFT = 1 << 16
#: the free oscillation after the shaking [s]
SHAKE_FREE_S = 8.0


def shake_scene(quick: bool, frequency: float = 1.0, length: float | None = None, damping: float | None = None,
                particles: int | None = None):
    """cable-exp2-shake's scene (``scenes/cable-exp2-shake.toml``: 1.0 Hz, the stated length,
    the paper's damping) shaken at ``frequency`` [Hz] for its 3 cycles then 8 s free, on a
    cable of ``length`` [m] (its points P1-P5 at the same fractions of it), at ``damping``
    [1/s]; the quick variant's 31 particles, or ``particles``."""
    from cosim.validations.case_scene import number as n

    scene = exp2_scene("cable-exp2-shake", quick, particles)
    m, ln = scene.bodies[0].motion, scene.moorings.lines[0]
    L = length or ln.length
    points = [L - q[0] * L / EXP2["length"] for q in EXP2_POINTS]
    values = [f"bodies[0].motion.period={n(1.0 / frequency)}",
              f"world.duration={n(m.cycles / frequency + SHAKE_FREE_S)}",
              f"moorings.lines[0].length={n(L)}", "moorings.lines[0].points=[" + ", ".join(n(x) for x in points) + "]"]
    if damping is not None:
        values.append(f"moorings.damping={n(damping)}")
    return scene.with_values(values)


def run_exp2_shake(scene):
    """Run a shaken Experiment 2 scene (:func:`shake_scene`) and read the free oscillation
    after the shaking: returns (the fundamental free period [s], the RMS vertical
    displacement of P1-P5 in the first and the last 2 s of the free phase [m], the run's
    steps). The fundamental: the lowest-frequency spectral peak above 0.5 Hz holding at
    least 20 % of the largest peak's power (which mode dominates depends on the excitation
    frequency), in the summed spectra of P1-P5's vertical motion from 0.5 s after the
    shaking stops."""
    m = scene.bodies[0].motion
    res, _, xz = exp2_run(scene)
    t = res.t
    t_free = m.cycles * m.period
    free = t > t_free + 0.5 - 1e-9
    z = xz[free, :, 1] - xz[0, :, 1]
    z = z - z.mean(axis=0)
    dt = scene.world.sample_every
    spec = (np.abs(np.fft.rfft(z * np.hanning(len(z))[:, None], n=SHAKE_NFFT, axis=0)) ** 2).sum(axis=1)
    f = np.fft.rfftfreq(SHAKE_NFFT, dt)
    band = f > 0.5
    peaks = np.nonzero(band[1:-1] & (spec[1:-1] > spec[:-2]) & (spec[1:-1] >= spec[2:])
                       & (spec[1:-1] >= 0.2 * spec[band].max()))[0] + 1
    k = int(round(2.0 / dt))
    return (1.0 / f[peaks[0]], float(np.sqrt((z[:k] ** 2).mean())), float(np.sqrt((z[-k:] ** 2).mean())),
            res.summary["steps"])


#: Dinçer & Demir 2020, §3.3.2: free oscillation period after the excitation [s]
EXP2_PERIOD = 0.42


@case("cable-exp2-shake", "SPH cable, Dinçer & Demir 2020, Experiment 2: free oscillation period after 1.0/1.5 Hz shaking",
      target="period within 7 % of 0.42 s",
      quick="as the full variant (the period within 7 % of 0.42 s on the length fitted to the measured shape, "
            "damping lowers the late motion) with 31 particles instead of 61",
      scene=lambda quick: shake_scene(quick))
def cable_exp2_shake(quick: bool) -> dict:
    """Dinçer & Demir 2020, Experiment 2, Type1 (1.0 Hz) and Type2 (1.5 Hz), 25 mm at P0 in x (3 cycles
    assumed: the paper does not give the duration), then free oscillation; the dominant
    free period -- the fundamental, lowest significant peak of the summed spectra of the
    vertical motion of P1-P5 (which mode dominates depends on the excitation) -- against
    the measured 0.42 s
    (the paper's SPH: 0.45 s). Target: within 7 %.

    Run for two lengths: the stated 1.272 m, and the length whose exact catenary fits the
    measured static shape of Table 5 (about 1.286 m; the measured points lie 15-19 mm below
    the 1.272 m catenary). The period is very sensitive to the sag here, so the case passes
    on the measured geometry and reports the stated-length period beside it. Also checked:
    with omega = 0.04 1/s the RMS motion late in the free phase is smaller than without
    damping, by about exp(-omega t/2) (reported beside that expectation). The case's scene
    (``scenes/cable-exp2-shake.toml``) starts the cable on the inextensible catenary at
    the paper's damping; each run sets its frequency, length and points."""
    L_fit = fit_length_to_measured_shape()
    m = {"length_fit_m": L_fit}
    for label, fr in (("type1", 1.0), ("type2", 1.5)):
        for lname, L in (("measured_shape", L_fit), ("stated", EXP2["length"])):
            T, a0, a1, steps = run_exp2_shake(shake_scene(quick, fr, L))
            m[f"period_{label}_{lname}_s"] = float(T)
            m[f"err_period_{label}_{lname}"] = float(T / EXP2_PERIOD - 1)
            if lname == "measured_shape" and label == "type1":
                rms_damped = a1
    # damping: the same run without it; mass-proportional damping scales every mode by
    # exp(-omega t/2), t from the start of the shaking to the middle of the last 2 s
    scene = shake_scene(quick, 1.0, L_fit)
    _, _, rms_free, _ = run_exp2_shake(shake_scene(quick, 1.0, L_fit, damping=0.0))
    m["rms_last2s_damped_over_undamped"] = rms_damped / rms_free
    m["expected_exp(-omega t/2)"] = math.exp(-0.02 * (3.0 + SHAKE_FREE_S - 1.0))
    m["damped_rms_below_undamped"] = bool(rms_damped < rms_free)
    tol = {"err_period_type1_measured_shape": 0.07, "err_period_type2_measured_shape": 0.07,
           "damped_rms_below_undamped": True}
    return {"metrics": m, "tolerances": tol, "particles": scene.moorings.segments, "steps": steps,
            "stated_tolerances": {"err_period_type1_stated": 0.07, "err_period_type2_stated": 0.07},
            "departure": {
                "criterion": "the free period within 7 % of 0.42 s on the cable length (about 1.286 m) whose exact "
                             "catenary fits the measured static shape P1-P5 of Dinçer & Demir 2020, Table 5, instead of the "
                             "stated 1.272 m",
                "why": "the measured points P1-P5 lie 15-19 mm below the catenary of the stated 1.272 m (they imply "
                       "a longer cable) and the free period is very sensitive to the sag; the stated length's "
                       "periods are measured beside it"}}


#: Dinçer & Demir 2020, Experiment 1 (Table 4): initial positions of P1-P5 [(s, x, z)] of the 1 m cable
EXP1_POINTS = ((0.138, 0.098, -0.086), (0.350, 0.284, -0.183), (0.562, 0.492, -0.207), (0.774, 0.694, -0.143),
               (1.000, 0.880, 0.000))


def free_fall_scene(quick: bool, particles: int | None = None):
    """cable-free-fall's scene (``scenes/cable-free-fall.toml``), the quick variant's 48
    particles, or ``particles``."""
    from cosim.validations import case_scene

    n = particles or (48 if quick else None)
    return case_scene.load("cable-free-fall", [f"moorings.segments={n}"] if n else [])


def run_free_fall(scene):
    """Dinçer & Demir 2020, Experiment 1: ``scene`` (:func:`free_fall_scene`: the cable let
    go of at P5) run by ``cosim run``'s runner, every particle's position and the line's
    energy recorded; returns (metrics, the run's summary). See :func:`cable_free_fall`
    for the metrics."""
    ln = scene.moorings.lines[0]
    res, from_fairlead, xz = exp2_run(scene, every_particle=True)
    s = ln.length - from_fairlead  # Table 4's arc lengths are from the anchor, (0, 0)
    order = np.argsort(s)
    s, xz = s[order], xz[:, order]  # (samples, nodes along the line from the anchor, 2)
    E = res[f"{ln.name}.energy"]
    scale = ln.weight * ln.length * ln.length  # weight times length [J]
    strain = np.linalg.norm(np.diff(xz, axis=1), axis=2) / np.diff(s)[None, :] - 1.0
    table = np.array([q[1:] for q in EXP1_POINTS])
    init = np.array([xz[0, np.argmin(np.abs(s - q[0]))] for q in EXP1_POINTS])
    every = [k for k, t in enumerate(res.t) if t > 0 and abs(t / 0.1 - round(t / 0.1)) < 1e-6]
    m = {"initial_vs_table4_m": [float(d) for d in np.linalg.norm(init - table, axis=1)],
         "max_energy_rise_J": float(max(0.0, (E - E[0]).max())), "energy_scale_J": scale,
         "dissipated_fraction_of_w_L_L": float((E[0] - E[-1]) / scale),
         "free_end_lowest_z_m": float(xz[:, -1, 1].min()), "max_strain": float(strain.max()),
         "free_end_xz_every_0.1s": [[round(float(res.t[k]), 3), float(xz[k, -1, 0]), float(xz[k, -1, 1])]
                                    for k in every]}
    return m, res.summary


@case("cable-free-fall", "SPH cable, Dinçer & Demir 2020, Experiment 1: released at one end from its catenary (Table 4)",
      target="no published trajectory: invariants: the mechanical energy never grows (1e-6 of w L L), the line "
             "stays within its elastic range, the free end swings below z = -0.75 m",
      quick="the same invariants with 48 particles instead of 95", row=None, scene=free_fall_scene)
def cable_free_fall(quick: bool) -> dict:
    """Dinçer & Demir 2020, Experiment 1 (§3.3.1): a 1 m cable of the Experiment 2 kind (w = 0.2656 N/m,
    0.5 mm wire at 109 GPa assumed) hangs from (0, 0) and (0.88, 0) and is released at P5.
    No trajectory data is published (the paper's Fig. 6-9 are plots), so the case checks
    invariants: the mechanical energy (kinetic + potential + elastic) never grows (only
    artificial viscosity and the omega damping remove it; the fraction removed is
    reported), the line never stretches beyond its elastic range, the free end falls and
    swings through the bottom. The initial catenary is reported against the Table 4 points.
    The case's scene (``scenes/cable-free-fall.toml``) releases a line from its fairlead
    (``released``) and records its energy (``probes.energy``) and every particle's place."""
    scene = free_fall_scene(quick)
    m, summary = run_free_fall(scene)
    scale = m["energy_scale_J"]
    return {"metrics": m,
            "tolerances": {"max_energy_rise_J": [None, 1e-6 * scale], "max_strain": [None, MAX_STRAIN],
                           "free_end_lowest_z_m": [None, -0.75]},
            "particles": scene.moorings.segments, "steps": summary["steps"]}
