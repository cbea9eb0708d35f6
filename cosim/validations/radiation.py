"""A body forced in heave in still water inside the SPH near field (:mod:`fluid.nearfield`):
what it radiates must leave the box, and the fluid's force on it must carry the added mass
and radiation damping of linear potential flow.

- The force: the prescribed heave ``z = a sin(w t)`` (after its ramp) and the fluid's
  vertical force ``F(t)`` on the body; linear theory gives ``F = F0 - C z - A33 z'' -
  B33 z'`` (Newman 1977, Marine Hydrodynamics §6.16-6.17, Eq. 6.169 with the body's
  motion prescribed), ``C = rho g Awp`` the hydrostatic restoring. With ``F``'s first
  harmonic ``F1 = Fs sin(w t) + Fc cos(w t)`` (least squares over whole periods,
  :func:`cosim.validations.wave_propagation.harmonics`): the part in phase with the
  displacement ``Fs = -(C - A33 w^2) a`` and that in phase with the velocity
  ``Fc = -B33 w a`` (:func:`added_mass_damping`). ``C`` is the linear hydrostatics' of
  the hull (Capytaine's), so whatever SPH makes of the restoring force shows in ``A33``.
- The reflection: the first-harmonic elevation at gauges on a line out from the body is
  split by least squares into an outgoing and an incoming wave, the method of Goda &
  Suzuki (1976, Proc. 15th ICCE, two gauges, exactly determined) and Mansard & Funke
  (1980, Proc. 17th ICCE, three or more, least squares), with the waves of a plane
  problem ``exp(-+ i k x)`` or, round a body in the open, the cylindrical ones
  ``H0^(2)(k r)`` (outgoing) and ``H0^(1)(k r)`` (incoming) of the axisymmetric problem
  (Newman 1977 §6.18; time factor ``exp(i w t)``): the reflection coefficient is the ratio
  of their amplitudes (:func:`cosim.validations.wave_propagation.separate`).
- The reference: Capytaine's A33(w), B33(w) of the same truncated cylinder at the same
  depth (``fluid.potential.compute``, cached), and the outgoing wave that B33 implies by
  the energy flux, ``|A_out| = a w sqrt(B33 k / (4 rho g c_g))`` (the far field
  ``A_out H0^(2)(k r)`` carries ``2 rho g |A_out|^2 c_g / k`` [W], which the body's
  ``B33 w^2 a^2 / 2`` feeds: Newman 1977 §6.18), reported beside the gauges' amplitude;
  and Capytaine's elevation at each gauge (:func:`reference_elevation`), over which each
  gauge's is reported, and whose split is the method's floor (``reflection_floor``).
- The tare: the same box run once more with the body held still (:func:`held_scene`), whose
  force and gauges are subtracted from the forced run's before the fits, as a towing tank
  subtracts its still-model record: the water's own start-up oscillation in the box (the
  held body's force has ±2 kN a period at the heave's frequency, ±16 % of the damping
  force of 0.3 m of heave at R/dx = 4) is not the body's radiation. The fits without it
  are reported beside (``*_untared``).
- The fluid: the reference is inviscid, so the scene runs without the artificial viscosity,
  whose dissipation reads as damping, and with a small laminar viscosity (Lo & Shao 2002),
  without which the damping falls short after three periods (the scene file;
  docs/validation/nearfield.md, "The viscosity round the body").
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from cosim.validations import case_scene
from cosim.validations.registry import case
from cosim.validations.wave_propagation import harmonics, separate

#: the case's scene (quick variant: its file's spacing)
SCENE = Path(__file__).with_name("scenes") / "nearfield-radiation.toml"
#: each variant's spacing [m] (quick: True; R/dx = 4 and 6); the periods run after the ramp,
#: all of them fitted: the force's part in phase with the velocity beats over about four
#: (what the box sends back), so two periods read where they fall on the beat
RUNS = {True: 0.75, False: 0.5}
PERIODS_AFTER_RAMP = FIT_PERIODS = 6
#: targets: reflection below 10 %, A33 and B33 within 10 % of the boundary-element reference
REFLECTION_TOL, COEFFICIENT_TOL = 0.10, 0.10
#: the quick variant's own (R/dx = 4, two particles across the draft)
QUICK_REFLECTION_TOL, QUICK_COEFFICIENT_TOL = 0.20, 0.25
#: panel size of the reference, in radii: the damping of this sharp-edged hull converges
#: slowly with the panels, 0.05 R within half a per cent of its limit (docs/validation/
#: nearfield.md, "The reference's panels"); the case was first judged against 0.1 R's, whose
#: figures the record keeps beside (``*_error_panel_0.1R``)
PANEL, FIRST_PANEL = 0.05, 0.1


def added_mass_damping(ts, force, amplitude: float, omega: float, stiffness: float) -> tuple[float, float]:
    """``(A33, B33)`` [kg, kg/s] from the vertical fluid force ``force`` [N] at times ``ts``
    [s] on a body heaving as ``amplitude sin(omega t)`` [m], its restoring ``stiffness``
    [N/m] (module docstring: ``Fs = -(C - A w^2) a``, ``Fc = -B w a``)."""
    f1 = harmonics(np.asarray(ts, float), np.asarray(force, float)[:, None], omega)[0]
    fc, fs = f1.real, -f1.imag  # Re(f1 exp(i w t)) = fc cos + fs sin
    return float((fs / amplitude + stiffness) / omega**2), float(-fc / (amplitude * omega))


def cylinder_hull(radius: float, draft: float, panel: float = PANEL):
    """The wetted hull of an upright cylinder of ``radius`` [m] drawing ``draft`` [m], its
    waterline at z = 0, panels ``panel`` radii across: the case's reference hull."""
    from fluid.potential import wetted_hull

    return wetted_hull("cylinder", [radius, draft], np.eye(3), [0.0, 0.0, 0.0], panel * radius, name="cylinder")


def hull_reference(hull, depth: float, omega: float, rho: float, g: float, cache=None,
                   name: str = "radiation-cylinder"):
    """Capytaine's ``(A33, B33, C33)`` of ``hull`` (a :func:`fluid.potential.wetted_hull`, its
    waterline at z = 0) in water ``depth`` [m] deep at ``omega`` [rad/s] (solved at 0.9, 1 and
    1.1 omega, cached under ``name``)."""
    from fluid.potential import compute

    c = compute(hull, 0.0, omega=omega * np.array([0.9, 1.0, 1.1]), depth=depth, rho=rho, g=g, cache=cache,
                name=name)
    return float(c.added_mass[1, 2, 2]), float(c.damping[1, 2, 2]), float(c.stiffness[2, 2])


def reference(radius: float, draft: float, depth: float, omega: float, rho: float, g: float, cache=None,
              panel: float = PANEL):
    """:func:`hull_reference` of an upright cylinder of ``radius`` [m] drawing ``draft`` [m]
    (panels ``panel`` radii across)."""
    return hull_reference(cylinder_hull(radius, draft, panel), depth, omega, rho, g, cache)


def hull_elevation(hull, depth: float, omega: float, rho: float, g: float, points) -> np.ndarray:
    """Capytaine's complex elevation [m per m of heave] radiated at ``points`` (n, 2) [m] by
    ``hull`` (as :func:`hull_reference`) heaving as ``Re(X exp(i omega t))``: the elevation is
    ``Re(X e exp(i omega t))`` (this module's time factor; :mod:`fluid.potential.elevation`
    works in Capytaine's ``exp(-i omega t)``, hence the conjugate). Cached."""
    from fluid.potential.elevation import radiated_elevation

    return np.conj(radiated_elevation(hull, 0.0, "Heave", omega, points, depth=depth, rho=rho, g=g))


def reference_elevation(radius: float, draft: float, depth: float, omega: float, rho: float, g: float, points,
                        panel: float = PANEL) -> np.ndarray:
    """:func:`hull_elevation` of the cylinder of :func:`reference`."""
    return hull_elevation(cylinder_hull(radius, draft, panel), depth, omega, rho, g, points)


def outgoing_amplitude(b33: float, amplitude: float, omega: float, depth: float, rho: float, g: float) -> float:
    """The far-field amplitude ``|A_out|`` [m] of ``A_out H0^(2)(k r)`` that a body heaving
    ``amplitude`` [m] at ``omega`` [rad/s] radiates when its damping is ``b33`` [kg/s], by
    the energy flux (module docstring)."""
    from fluid.waves import group_velocity, wavenumbers

    k = float(wavenumbers(omega, depth, g))
    return amplitude * omega * math.sqrt(b33 * k / (4.0 * rho * g * float(group_velocity(k, depth, g))))


def gauge_line(r, z, z_ref, k: float, outgoing: float) -> dict:
    """The figures of one line of gauges at distances ``r`` [m] from the axis: their
    first-harmonic elevations ``z`` [m], the reference's ``z_ref`` for the same heave, split
    into outgoing and incoming cylindrical waves of wavenumber ``k`` (the reflection, and
    its floor from ``z_ref``), the outgoing wave over ``outgoing`` (:func:`outgoing_amplitude`)
    and each gauge over the reference in height and lag [periods]."""
    out, back = separate(r, z, k, "cylindrical")
    out_ref, back_ref = separate(r, z_ref, k, "cylindrical")
    q = z / z_ref
    return {"r_m": np.round(r, 4).tolist(), "reflection": abs(back) / abs(out),
            "reflection_floor": abs(back_ref) / abs(out_ref), "outgoing_over_theory": abs(out) / outgoing,
            "H1_m": np.round(2.0 * np.abs(z), 5).tolist(), "H1_over_reference": np.round(np.abs(q), 4).tolist(),
            "lag_periods": np.round(-np.angle(q) / (2.0 * math.pi), 4).tolist()}


def radiation_scene(quick: bool):
    """The case's scene at the variant's spacing, run for the ramp and
    :data:`PERIODS_AFTER_RAMP` periods."""
    from cosim.scene import Scene

    s = Scene.from_toml(SCENE)
    m = s.bodies[0].motion
    duration = (m.ramp + PERIODS_AFTER_RAMP) * m.period
    return s.with_values([f"fluid.dx={RUNS[quick]}", f"world.duration={duration:.6g}"])


def draft_of(scene) -> float:
    """The draft [m] of ``scene``'s first body, an upright cylinder: the still water's depth
    less the height of its bottom."""
    b = scene.bodies[0]
    return scene.domain.depth - (b.pos[-1] - 0.5 * b.length)


def held_scene(scene):
    """``scene`` with its body held still where its motion starts (the tare run)."""
    from cosim.scene.toml_io import from_dict, to_dict

    d = to_dict(scene)
    dof = d["bodies"][0]["motion"]["dof"]
    d["bodies"][0]["motion"] = {"kind": "table", "dof": dof, "points": [[0.0, 0.0], [scene.world.duration, 0.0]]}
    return from_dict(d)


def _lines(scene) -> dict:
    """The gauges' indices on each line out from the body (along x, along y) and their
    distances r [m] from its axis."""
    c = scene.bodies[0].pos
    pts = np.asarray(scene.probes.gauges, float)
    r = np.hypot(pts[:, 0] - c[0], pts[:, 1] - c[1])
    along_x = np.abs(pts[:, 0] - c[0]) > np.abs(pts[:, 1] - c[1])
    return {"x": (np.flatnonzero(along_x), r[along_x]), "y": (np.flatnonzero(~along_x), r[~along_x])}


def damping_by_period(ts, force, amplitude: float, omega: float, stiffness: float, period: float) -> list:
    """B33 [kg/s] fitted by :func:`added_mass_damping` over each whole ``period`` [s] of the
    samples ``ts`` [s] from the first (windows ``[t0, t0 + period)``, each period's samples
    once)."""
    eps = 1e-6 * period
    n = int((ts[-1] - ts[0]) / period + 1e-6)
    out = []
    for j in range(n):
        sel = (ts >= ts[0] + j * period - eps) & (ts < ts[0] + (j + 1) * period - eps)
        out.append(added_mass_damping(ts[sel], force[sel], amplitude, omega, stiffness)[1])
    return out


def excess_split(amplitudes, excess) -> dict:
    """The damping's excess over the potential-flow reference, measured at several heave
    ``amplitudes`` (any unit), split by least squares as ``excess = L + D a``: ``L``, a
    part that does not depend on the amplitude (an error linear in the motion, or a loss
    that is, as a laminar boundary layer's), and ``D a``, the equivalent damping of a drag
    whose coefficient does not depend on the amplitude, as the vortex shedding at a
    right-angled edge at low KC (Graham 1980, J. Fluid Mech. 97, 331, whose scaling gives
    ``Cd ~ KC^((3n - 2) / (2 - n))`` at an edge the fluid turns round through ``pi / n``:
    KC^0 at a right angle, ``n = 2 / 3``; KC^(-1/3) at a flat plate's edge): by Lorentz's
    linearisation a drag ``(rho / 2) Cd S |v| v`` does over a period the work of a damping
    ``(8 / 3 pi) (rho / 2) Cd S w a``. Returns ``L``, ``D`` (excess per unit of amplitude)
    and, with three amplitudes or more, their standard errors from the residuals
    (``L_se``, ``D_se``; None with two)."""
    a = np.asarray(amplitudes, float)
    e = np.asarray(excess, float)
    if a.shape != e.shape or a.size < 2 or np.unique(a).size < 2:
        raise ValueError("excess_split: give the excess at two different amplitudes or more, one value each")
    m = np.column_stack([np.ones_like(a), a])
    (lin, drag), *_ = np.linalg.lstsq(m, e, rcond=None)
    out = {"L": float(lin), "D": float(drag), "L_se": None, "D_se": None}
    if a.size > 2:
        s2 = float(np.sum((e - m @ np.array([lin, drag]))**2)) / (a.size - 2)
        cov = s2 * np.linalg.inv(m.T @ m)
        out.update(L_se=math.sqrt(cov[0, 0]), D_se=math.sqrt(cov[1, 1]))
    return out


def radiation_metrics(res, scene, tare=None) -> dict:
    """The case's measured figures from a run's records ``res`` of ``scene``, less the
    records ``tare`` of :func:`held_scene` (the same sample times) where given; A33 and B33
    of the forced run alone beside them (``*_untared``), and against the reference of
    :data:`FIRST_PANEL` (``*_error_panel_0.1R``). ``B33_per_period_kg_s``: B33 fitted
    over each fitted period alone, and ``B33_error_standard`` their standard error of the
    mean over B33's reference: the force's part in phase with the velocity swings from
    period to period with what the box sends back (docs/validation/nearfield.md, "B33's
    swing is not the ramp's"), which this sizes; the periods are not independent draws (the
    swing's cycle is several periods), so it is an indication of the fit's spread, not a
    confidence interval. On each gauge line: the reflection, its floor (the same split of
    Capytaine's own elevation at those gauges), the outgoing wave over the one B33's
    energy flux implies, and each gauge's first harmonic ``H1_m``, over Capytaine's
    (``H1_over_reference``) and its lag behind Capytaine's (``lag_periods``, periods)."""
    from fluid.waves import wavenumbers

    b, d = scene.bodies[0], scene.domain
    m, g, rho = b.motion, scene.world.gravity, scene.fluid.rho0
    w = 2.0 * math.pi / m.period
    k = float(wavenumbers(w, d.depth, g))
    draft = draft_of(scene)
    a_ref, b_ref, c33 = reference(b.radius, draft, d.depth, w, rho, g)
    a_first, b_first, c_first = reference(b.radius, draft, d.depth, w, rho, g, panel=FIRST_PANEL)
    t_end = float(res.t[-1])
    fit = res.t > t_end - FIT_PERIODS * m.period - 1e-9
    ts = res.t[fit]
    if tare is not None and not (tare.t.shape == res.t.shape and np.allclose(tare.t, res.t)):
        raise ValueError("radiation_metrics: the tare run's sample times differ from the forced run's")

    def less_tare(name):
        return res[name][fit] - (0.0 if tare is None else tare[name][fit])

    z1 = harmonics(ts, res[f"{b.name}.heave"][fit][:, None], w)[0]
    fz = less_tare(f"{b.name}.fluid_Fz")
    a33, b33 = added_mass_damping(ts, fz, m.amplitude, w, c33)
    a33_raw, b33_raw = added_mass_damping(ts, res[f"{b.name}.fluid_Fz"][fit], m.amplitude, w, c33)
    a33_first = added_mass_damping(ts, fz, m.amplitude, w, c_first)[0]
    per_period = damping_by_period(ts, fz, m.amplitude, w, c33, m.period)
    eta = np.column_stack([less_tare(f"gauge{i + 1}.eta") for i in range(len(scene.probes.gauges))])
    z = harmonics(ts, eta, w)
    theory = outgoing_amplitude(b_ref, m.amplitude, w, d.depth, rho, g)
    gauges = np.asarray(scene.probes.gauges, float)[:, :2] - np.asarray(b.pos[:2], float)
    z_ref = z1 * reference_elevation(b.radius, draft, d.depth, w, rho, g, gauges)  # for the heave measured
    lines = {name: gauge_line(r, z[idx], z_ref[idx], k, theory) for name, (idx, r) in _lines(scene).items()}
    s = res.summary
    return {"A33_kg": a33, "B33_kg_s": b33, "A33_ref_kg": a_ref, "B33_ref_kg_s": b_ref, "C33_N_m": c33,
            "A33_error": abs(a33 / a_ref - 1.0), "B33_error": abs(b33 / b_ref - 1.0), "tared": tare is not None,
            "A33_error_untared": abs(a33_raw / a_ref - 1.0), "B33_error_untared": abs(b33_raw / b_ref - 1.0),
            f"A33_error_panel_{FIRST_PANEL:g}R": abs(a33_first / a_first - 1.0),
            f"B33_error_panel_{FIRST_PANEL:g}R": abs(b33 / b_first - 1.0), "reference_panel_R": PANEL,
            "B33_per_period_kg_s": [round(x, 1) for x in per_period],
            "B33_error_standard": float(np.std(per_period, ddof=1) / math.sqrt(len(per_period)) / b_ref)
            if len(per_period) > 1 else None,
            "reflection": max(v["reflection"] for v in lines.values()), "lines": lines,
            "heave_amplitude_m": abs(z1), "kR": k * b.radius, "R_over_dx": b.radius / scene.fluid.dx,
            "draft_over_dx": draft / scene.fluid.dx, "fit_s": [float(ts[0]), t_end],
            "particles": s.get("particles"), "steps": s["steps"],
            "cpu_s": s["cpu_s"] + (0.0 if tare is None else tare.summary["cpu_s"])}


@case("nearfield-radiation", "a vertical truncated cylinder (R = 3 m, draft 1.5 m, 6 m of water) forced in heave "
      "(0.3 m, T = 3.54 s, k R = 1) in still water in a 3-D SPH near field (half box, symmetry plane y = 0): the "
      "radiated wave's reflection from the zones and the added mass and damping against Capytaine",
      target="the radiated wave leaves the box with a reflection below 10 %; added mass and damping from the force's "
             "first harmonic within 10 % of the boundary-element reference",
      quick=f"R/dx = 4 (two particles across the draft), the ramp and {PERIODS_AFTER_RAMP} periods, and its tare: "
            f"reflection below {QUICK_REFLECTION_TOL:.0%}, A33 and B33 within {QUICK_COEFFICIENT_TOL:.0%} of Capytaine's",
      scene=radiation_scene, long=True)
def nearfield_radiation(quick: bool) -> dict:
    """The scene ``SCENE`` at the variant's spacing (quick R/dx = 4, full R/dx = 6) and its
    tare (:func:`held_scene`), judged over the last :data:`FIT_PERIODS` periods (module
    docstring). Both runs are kept under ``$COSIM_CASE_RUNS`` (the full variant's take
    hours) and read back or resumed when the case runs again."""
    scene = radiation_scene(quick)
    folder = case_scene.kept_runs("nearfield-radiation", quick)
    res, earlier = case_scene.run_or_resume(scene, folder / "forced")
    tare, earlier_held = case_scene.run_or_resume(held_scene(scene), folder / "held")
    m = radiation_metrics(res, scene, tare)
    tol = ((QUICK_REFLECTION_TOL, QUICK_COEFFICIENT_TOL) if quick else (REFLECTION_TOL, COEFFICIENT_TOL))
    return {"metrics": m,
            "tolerances": {"reflection": tol[0], "A33_error": tol[1], "B33_error": tol[1]},
            "stated_tolerances": ({"reflection": REFLECTION_TOL, "A33_error": COEFFICIENT_TOL,
                                   "B33_error": COEFFICIENT_TOL} if quick else None),
            "particles": m["particles"], "steps": m["steps"], "cpu_s": m["cpu_s"],
            "read_back_cpu_s": round(earlier + earlier_held, 1),
            "runs_of_other_code": case_scene.runs_of_other_code({"forced": res, "held": tare})}
