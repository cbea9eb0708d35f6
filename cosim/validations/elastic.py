"""Validation cases of elastic structures in the SPH fluid (issue 17; Yang & Li 2020,
Yang & Li 2020, §3.3 and Figure 6)."""

from __future__ import annotations

import time

import numpy as np

from cosim.validations import case_scene
from cosim.validations.registry import case

DATASET = "dambreak_elastic_obstacle_walhorn_idelsohn"
#: the four published curves of the plate's upper left corner (refdata SOURCE.txt), key -> label
CURVES = {"idelsohn_2008_pfem": "Idelsohn et al. 2008 (PFEM)", "bogaers_2016_qn_ls": "Bogaers et al. 2016 (QN-LS)",
          "liu_2013_sph": "Liu et al. 2013 (SPH)", "sun_2019_mps_dem": "Sun et al. 2019 (MPS-DEM)"}
#: Idelsohn's PFEM peak (refdata SOURCE.txt): 48.3 mm at 0.260 s
PEAK_REF_M, PEAK_REF_T = 0.0483, 0.260
#: the references' peak times (0.217 ... 0.260 s) widened by 0.02 s
PEAK_WINDOW = (0.20, 0.28)


def _curve(name: str) -> np.ndarray:
    from cosim.refdata import path

    return np.loadtxt(path(DATASET, name), delimiter=",")


def reference_curves() -> dict[str, np.ndarray]:
    """The four published corner-displacement curves, ``(n, 2)``: t [s], x [m] (digitised
    from Sun et al. 2019's figure; numerical solutions, no experiment)."""
    return {
        "idelsohn_2008_pfem": _curve(
            "sun_2019_dam_breaking_flow_impacting_an_elastic_plate_x_displacement_idelsohn_2008_pfrem.csv"),
        "bogaers_2016_qn_ls": _curve(
            "sun_2019_dam_breaking_flow_impacting_an_elastic_plate_x_displacement_bogaers_2016_qn_ls.csv"),
        "liu_2013_sph": _curve(
            "sun_2019_dam_breaking_flow_impacting_an_elastic_plate_x_displacement_liu_2013_sph.csv"),
        "sun_2019_mps_dem": _curve(
            "sun_2019_dam_breaking_flow_impacting_an_elastic_plate_x_displacement_sun_2019_mps_dem.csv"),
    }


#: the spacing [m] and the run [s] by variant (quick: True): the scene file's, the full one's
PLATE_RUNS = {True: (0.005, 0.3), False: (0.0025, 0.4)}


def plate_scene(quick: bool):
    """The scene ``scenes/elastic-plate.toml`` (the quick variant's) at the variant's spacing
    and duration (:data:`PLATE_RUNS`)."""
    dx, t_end = PLATE_RUNS[quick]
    return case_scene.load("elastic-plate", [f"fluid.dx={case_scene.number(dx)}",
                                             f"world.duration={case_scene.number(t_end)}"])


def run_elastic_plate(scene) -> dict:
    """The dam break on an elastic plate of ``scene`` (:func:`plate_scene`; Walhorn et al.
    2005, Idelsohn et al. 2008; Yang & Li 2020, §3.3), built as ``cosim run`` builds it: the
    water column collapses at t = 0 and strikes the plate clamped to the floor. Fluid: the
    set-up of a dam break (the solver's defaults: Wendland, h = sqrt(2) dx, alpha = 0.01,
    Fourtakas delta = 0.1, CFL 0.2; c0 = 10 sqrt(2 g H), Yang & Li 2020, Eq. 6's rule),
    tank walls plain dynamic, the plate's particles mDBC; the column starts hydrostatic.
    Plate: the MuJoCo chain of :mod:`bodies.elastic` (Timoshenko elements, RK4), coupled
    fluid-first. Returns the upper left corner's x displacement [m] every
    ``world.sample_every`` [s] up to ``world.duration`` [s]."""
    sample, t_end = scene.world.sample_every, scene.world.duration
    with case_scene.built(scene) as b:
        coupler, plate = b.coupler, b.fluid.elastic[0]
        ts, xs = [0.0], [0.0]
        t0 = time.perf_counter()
        for k in range(1, int(round(t_end / sample)) + 1):
            coupler.run(k * sample)
            plate.check()
            ts.append(coupler.t)
            xs.append(float(plate.displacement("corner")[0]))
        wall = time.perf_counter() - t0
        return {"t": np.array(ts), "x": np.array(xs), "particles": int(b.sph.ps.n), "steps": coupler.steps,
                "wall_s": wall, "c0": b.sph.config.speed_of_sound, "dx": scene.fluid.dx,
                "n_elements": scene.bodies[0].elements}


def compare(t, x, t_max: float) -> dict:
    """Our corner displacement ``x`` [m] at times ``t`` [s] against the published curves:
    the peak and its time, its error relative to Idelsohn's PFEM peak, and the RMS
    difference [mm] to each curve over its points up to ``t_max`` [s] (ours interpolated)."""
    i = int(np.argmax(x))
    out = {"peak_mm": 1e3 * float(x[i]), "peak_t_s": float(t[i]),
           "peak_rel_err_vs_idelsohn": float(x[i] / PEAK_REF_M - 1.0), "rms_mm_over_s": t_max, "rms_mm": {},
           "reference_peaks": {}}
    for key, ref in reference_curves().items():
        use = ref[:, 0] <= t_max + 1e-12
        d = np.interp(ref[use, 0], t, x) - ref[use, 1]
        out["rms_mm"][key] = 1e3 * float(np.sqrt(np.mean(d**2)))
        j = int(np.argmax(ref[:, 1]))
        out["reference_peaks"][key] = {"peak_mm": 1e3 * float(ref[j, 1]), "t_s": float(ref[j, 0])}
    return out


def series_plot(t, x) -> dict:
    """The report's plot: Yang & Li 2020, Figure 6, ours against the four published curves."""
    curves = {CURVES[k]: {"x": ref[:, 0], "y": 1e3 * ref[:, 1], "style": "--"} for k, ref in reference_curves().items()}
    curves["SPH + MuJoCo chain (ours)"] = {"x": t, "y": 1e3 * x, "style": "-"}
    return {"upper left corner": {"xlabel": "t [s]", "ylabel": "horizontal displacement [mm]", "curves": curves}}


ELASTIC_TARGET = ("peak horizontal displacement of the upper left corner within 15 % of Idelsohn's PFEM curve (48.3 mm "
                  "at 0.260 s) and inside 0.20-0.28 s; RMS difference to each of the four curves over 0.4 s reported")


@case("elastic-plate", "2-D dam break on an elastic plate (Yang & Li 2020, §3.3, Figure 6; Walhorn 2005, Idelsohn 2008): "
      "the plate's upper left corner against four published numerical solutions", target=ELASTIC_TARGET,
      quick="dx = 5 mm (2.4 particles across the plate), 0.3 s: the same peak criteria (within 15 % of 48.3 mm, "
            "inside 0.20-0.28 s) and the RMS difference to Idelsohn's curve over 0.3 s below 7 mm",
      scene=plate_scene)
def elastic_plate(quick: bool) -> dict:
    """The scene ``scenes/elastic-plate.toml`` (:func:`plate_scene`), run by
    :func:`run_elastic_plate`. Geometry of the reference curves (refdata SOURCE.txt):
    the column 0.146 m wide and 0.292 m high (2L), not Yang & Li 2020's printed hu = 25.2 cm; the
    plate's left face a = L = 0.146 m beyond the column, at x = 0.292 m (the tank's centre).
    Yang & Li 2020 describes the same case (b = 1.2 cm, rho_s = 2500 kg/m^3, E = 1e6 Pa) but prints
    hu = 25.2 cm in its Table 1 set-up; the curves it compares with (Figure 6) are these.
    The scene's fluid domain reaches about 4 h above the tank's 0.32 m walls: in the quick
    run 18 of the 2400 fluid particles of the jet thrown up over the plate leave it (z > 0.365
    m) after 0.26 s, past the corner's peak, and are removed (the peak and the RMS
    differences move by < 1e-8).

    Full variant (dx = 2.5 mm, N = 8): peak 43.9 mm at 0.223 s, -9.0 % of Idelsohn's 48.3 mm,
    within the four references' spread (45.0-48.3 mm); the chain converged to 2 % of the peak, the
    fluid's resolution sets the rest. The measured resolution table and the 3-D slice:
    docs/validation/elastic-plate_history.md.
    """
    dx, t_end = PLATE_RUNS[quick]
    r = run_elastic_plate(plate_scene(quick))
    m = compare(r["t"], r["x"], t_end)
    m.update({"dx_m": dx, "n_elements": r["n_elements"], "c0_m_s": r["c0"], "simulated_s": t_end,
              "run_wall_s": r["wall_s"]})
    stated = {"peak_rel_err_vs_idelsohn": 0.15, "peak_t_s": list(PEAK_WINDOW)}
    out = {"metrics": m, "tolerances": stated, "particles": r["particles"], "steps": r["steps"],
           "series": series_plot(r["t"], r["x"])}
    if quick:
        out["stated_tolerances"] = stated
        out["tolerances"] = {**stated, "rms_mm.idelsohn_2008_pfem": 7.0}
    return out
