"""The shaken cantilever: an elastic plate clamped to a tank whose base moves harmonically
rides with it and deflects, relative to it, as the base-excited cantilever of structural
dynamics does; in a shaken SPH tank its clamp moves with the tank's walls.

Reference: the uniform Euler-Bernoulli cantilever under the base translation ``u_g = U
sin(w t)``, by modal superposition (Clough & Penzien 1993, Dynamics of Structures, §18-5,
base excitation of distributed-parameter systems; Chopra 2012, Dynamics of Structures,
§16.4). Each mode's coordinate obeys ``q_n'' + w_n^2 q_n = -Gamma_n u_g''`` with
``Gamma_n = int phi_n / int phi_n^2`` over the length, so the steady state of the tip's
deflection relative to the base is ``U sum_n Gamma_n phi_n(L) r_n^2 / (1 - r_n^2) sin(w t)``,
``r_n = w / w_n``: in phase with the base below the first mode, in antiphase above it.
Started at rest on the base, each mode also rings at its own frequency (the run is
undamped); a least-squares fit of the forcing's and the first two modes' frequencies
separates the steady state from that ringing.
"""

from __future__ import annotations

import math

import numpy as np

from cosim.validations import case_scene
from cosim.validations.registry import case

#: the scene of the SPH run (both variants)
SPH_SCENE = "shaken-cantilever-sph.toml"
#: the forcing frequency over the continuum's first bending frequency, and the run [s] at
#: each: a beat of the forcing against the first mode or more, for the fit to tell them apart
RUNS = {0.5: 2.0, 0.85: 4.0, 1.5: 2.0}
#: the forcing ratios and the plate's elements by variant (quick: True)
VARIANTS = {True: ((0.5,), 8), False: ((0.5, 0.85, 1.5), 16)}
#: the modes summed in the closed form
MODES = 3
#: tolerances: the steady tip deflection against the closed form (relative), the clamp
#: against the base's displacement [m], and in the SPH tank against the walls' [m]
TIP_TOL, CLAMP_TOL, SPH_CLAMP_TOL = 0.02, 1e-12, 1e-9


def mode_shape(n: int):
    """The uniform clamped-free beam's n-th mode ``phi(x) = cosh bx - cos bx - s (sinh bx -
    sin bx)``, ``s = (cosh b + cos b) / (sinh b + sin b)``, over x in [0, 1] (``phi(1) = 2``
    up to sign)."""
    from bodies.elastic import BETA_L

    b = BETA_L[n - 1]
    s = (math.cosh(b) + math.cos(b)) / (math.sinh(b) + math.sin(b))
    return lambda x: math.cosh(b * x) - math.cos(b * x) - s * (math.sinh(b * x) - math.sin(b * x))


def tip_participation(n: int) -> tuple[float, float]:
    """``Gamma_n`` and ``Gamma_n phi_n(L)`` of the n-th mode (:func:`mode_shape`), by
    quadrature: how much of the base's acceleration drives it, and its share at the tip."""
    from scipy.integrate import quad

    phi = mode_shape(n)
    gamma = quad(phi, 0.0, 1.0)[0] / quad(lambda x: phi(x) ** 2, 0.0, 1.0)[0]
    return gamma, gamma * phi(1.0)


def continuum_frequencies(plate) -> np.ndarray:
    """The first :data:`MODES` bending frequencies [Hz] of the scene's ``plate`` (an
    ``ElasticPlate``) as a uniform Euler-Bernoulli cantilever, ``(beta_n L)^2 / (2 pi L^2)
    sqrt(E I / (rho A))``, ``I / A = h^2 / 12``."""
    from bodies.elastic import BETA_L

    stiffness = math.sqrt(plate.E * plate.thickness**2 / (12.0 * plate.density))
    return np.array(BETA_L[:MODES]) ** 2 / (2.0 * math.pi * plate.length**2) * stiffness


def steady_tip(amplitude: float, omega: float, omegas) -> float:
    """The closed form's steady tip deflection relative to the base [m], the coefficient of
    ``sin(w t)`` for the base ``amplitude sin(w t)`` (module docstring): ``omega`` and the
    modes' ``omegas`` [rad/s]."""
    return amplitude * sum(tip_participation(n)[1] * (omega / wn) ** 2 / (1.0 - (omega / wn) ** 2)
                           for n, wn in enumerate(omegas, start=1))


def chain_frequencies(scene) -> np.ndarray:
    """The plate's chain's own first three bending frequencies [Hz] (linearised, no
    gravity; the support's rigid-body modes, at zero, left out): where its free modes ring."""
    import mujoco

    from bodies import builders
    from bodies.elastic import modal_frequencies

    plate = scene.bodies[0]
    with case_scene.built(scene) as b:
        beam = b.plates[plate.name]
        model = mujoco.MjModel.from_xml_string(builders.scene(beam.xml, gravity=0.0))
        f = modal_frequencies(model, mujoco.MjData(model))
        return f[f > 1e-6 * f.max()][:3]


def cantilever_scene(ratio: float, elements: int):
    """The scene ``scenes/shaken-cantilever.toml`` shaken at ``ratio`` times the plate's
    first continuum frequency, with ``elements`` elements, for the run of :data:`RUNS`."""
    n = case_scene.number
    plate = case_scene.load("shaken-cantilever").bodies[0]
    period = 1.0 / (ratio * continuum_frequencies(plate)[0])
    return case_scene.load("shaken-cantilever", [f"base_motion.period={n(period)}", f"bodies[0].elements={elements}",
                                                 f"world.duration={n(RUNS[ratio])}"])


def shaken_run(scene) -> dict:
    """Run ``scene`` (:func:`cantilever_scene`) and fit its tip's deflection in the tank's
    frame: the steady part against the closed form, the clamp against the base."""
    plate, shake = scene.bodies[0], scene.base_motion
    omega = 2.0 * math.pi / shake.period
    U = shake.amplitude
    res = case_scene.run_once(scene)
    t, tip = res.t, res[f"{plate.name}.tip_x"]
    clamp = max(float(np.abs(res[f"{plate.name}.clamp_x"] - U * np.sin(omega * t)).max()),
                float(np.abs(res[f"{plate.name}.clamp_z"]).max()))
    own = 2.0 * math.pi * chain_frequencies(scene)
    A = np.column_stack([f(w * t) for w in (omega, own[0], own[1]) for f in (np.sin, np.cos)])
    fit = np.linalg.lstsq(A, tip, rcond=None)[0]
    continuum = continuum_frequencies(plate)
    closed = steady_tip(U, omega, 2.0 * math.pi * continuum)
    r1 = omega / own[0]
    return {"ratio_to_f1": round(omega / (2.0 * math.pi * continuum[0]), 9),
            "elements": plate.elements, "steady_tip_m": float(fit[0]), "closed_form_tip_m": closed,
            "tip_error": abs(fit[0] / closed - 1.0), "quadrature_over_closed": abs(fit[1] / closed),
            "clamp_error_m": clamp,
            "chain_f_Hz": (own / (2.0 * math.pi)).tolist(),
            "continuum_f_Hz": continuum.tolist(),
            # started at rest on the base: the first mode rings at -r1 times its steady part
            "ringing_over_predicted": float(fit[2] / (-r1 * U * tip_participation(1)[1] * r1**2 / (1.0 - r1**2))),
            "cpu_s": res.summary["cpu_s"], "steps": res.summary["steps"]}


def sph_clamp_run() -> dict:
    """The SPH scene :data:`SPH_SCENE` built as ``cosim run`` builds it and stepped to each
    sample: the clamp's displacement against the wall particles' (a few of them, found by
    their ids), and how far the walls moved."""
    from cosim.scene import Scene
    from cosim.scene.probes import groups
    from cosim.validations.folders import SCENES
    from fluid.particles import Kind

    scene = Scene.from_toml(SCENES / SPH_SCENE)
    name = scene.bodies[0].name
    every = scene.world.sample_every
    with case_scene.built(scene) as b:
        sph, c = b.sph, b.coupler
        g = next(x for x in groups(scene, b) if x.name == "motion")
        ids = sph.ps.ids[sph.ps.kind == Kind.MOVING_WALL][::50]

        def walls():
            return sph.ps.pos[np.argsort(sph.ps.ids)[ids]]  # ids are 0..N-1

        start, error, rigid, moved = walls(), 0.0, 0.0, 0.0
        for k in range(1, round(scene.world.duration / every) + 1):
            c.run(k * every)
            row = dict(zip(g.columns, g.sample()))
            shift = walls() - start
            rigid = max(rigid, float(np.ptp(shift, axis=0).max()))
            error = max(error, abs(row[f"{name}.clamp_x"] - shift[0, 0]), abs(row[f"{name}.clamp_z"] - shift[0, 1]))
            moved = max(moved, abs(float(shift[0, 0])))
    return {"clamp_vs_walls_m": float(error), "walls_spread_m": rigid, "walls_moved_m": moved,
            "particles": int(sph.ps.n)}


@case("shaken-cantilever", "an elastic plate clamped to a tank shaken harmonically along x, no fluid and no gravity "
      "(L = 0.5 m, h = 10 mm, E = 1e8 Pa, 1000 kg/m^3, f1 = 2.04 Hz; 1 mm at 0.5, 0.85, 1.5 f1): the base-excited "
      "cantilever; and the same kind of plate in a shaken 2-D SPH tank of water",
      target="the clamp follows the base to 1e-12 m; the tip's steady deflection relative to the base at the forcing "
             "frequency within 2 % of the modal closed form (three modes) at 0.5, 0.85 and 1.5 f1, in phase below "
             "the first mode and in antiphase above; in the SPH tank the clamp moves with the walls to 1e-9 m",
      quick="8 elements, forced at 0.5 f1 alone, and the SPH tank: the same tolerances",
      scene=lambda quick: cantilever_scene(VARIANTS[quick][0][0], VARIANTS[quick][1]))
def shaken_cantilever(quick: bool) -> dict:
    """The runs of :data:`VARIANTS` (module docstring) and the SPH tank's."""
    ratios, elements = VARIANTS[quick]
    runs = {f"r{r:g}": shaken_run(cantilever_scene(r, elements)) for r in ratios}
    sph = sph_clamp_run()
    metrics = {"runs": runs, "sph": sph,
               "tip_error": max(v["tip_error"] for v in runs.values()),
               "clamp_error_m": max(v["clamp_error_m"] for v in runs.values()),
               "sph_clamp_error_m": sph["clamp_vs_walls_m"]}
    tol = {"tip_error": TIP_TOL, "clamp_error_m": CLAMP_TOL, "sph_clamp_error_m": SPH_CLAMP_TOL}
    return {"metrics": metrics, "tolerances": tol, "particles": sph["particles"],
            "steps": sum(v["steps"] for v in runs.values())}
