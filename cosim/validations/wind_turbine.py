"""The wind-turbine base of Barreiro et al. 2016 (§5, Table 4, Figs. 17-19) on
its three lines in regular waves (H = 0.7 m, T = 20 s), with each mooring model changed in
the one field ``moorings.model``: the models against each other (issue 18's model
agreement).

Set-up: ``scenes/wind-turbine-moorings.toml``, the scene of ``examples/wind_turbine_base.toml``
(its header says what is the paper's and what is chosen): the 16 t cylinder drawing 1.51 m,
three 45 m chains of 442 kg/m (EA 1.9e9 N) at 120 deg, partly lifted at rest; the analytic
fluid (hydrostatics, added mass, Morison drag, the piston's far-field linear wave). Each
model runs the same scene: the quasi-static catenary (its taut limit a MuJoCo length
constraint), the FMU of the same law, MoorDyn (20 segments) and the SPH cable (20 nodes),
the dynamic two advanced with the base until their mean force over each coupling step
agrees (``Coupler(lines="subiterate")``), at the step the coupler derives.

What is compared, and what it proves: the surge and heave amplitudes (half the range over
the window, after the wave has reached the base) and the mean fairlead tensions (back line,
mean of the two front lines) of every model, as the spread max / min - 1 across the models;
the issue's target is 10 % while no line goes taut (every line stays partly lifted, from
``line_events``). It proves that the models give the base the same restoring force and the
same response when the lines' own dynamics (the chain's inertia and drag, 60 t) matter
little, i.e. that swapping the model changes the physics, not the coupling. It does not
test the fluid: the SPH fluid on this scene at a resolving spacing (dx <= 0.5 m, ~400 CPU-h
for the 90 s) is a GPU's work (``examples/wind_turbine_base.py``). The paper gives no
numbers for it (Figs. 18-19 only).

Measured: the full run passes, surge 5.2 %, heave 3.7 % and mean tensions under 0.5 % of
spread, every line partly lifted throughout; the table and the quick variant:
docs/validation/wind-turbine-moorings_history.md.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from cosim.validations.registry import case

SCENE = Path(__file__).with_name("scenes") / "wind-turbine-moorings.toml"
MODELS = ("catenary", "fmu", "moordyn", "sph-cable")
QUICK_MODELS = ("catenary", "sph-cable")
LINES = ("back", "front_port", "front_starboard")


def model_figures(res, t0: float) -> dict:
    """Surge, heave and sway amplitudes [m] and pitch amplitude [deg] (half the range after
    ``t0`` [s]), mean fairlead tensions [N] (back, and the mean of the two front lines),
    the lines' states, and the run's steps and cost."""
    late = res.t >= t0
    events = res.summary.get("line_events") or {}
    return {"surge_m": 0.5 * float(np.ptp(res["base.surge"][late])),
            "heave_m": 0.5 * float(np.ptp(res["base.heave"][late])),
            "sway_m": 0.5 * float(np.ptp(res["base.sway"][late])),
            "pitch_deg": 0.5 * float(np.ptp(res["base.pitch"][late])),
            "tension_back_N": float(res["back.tension"][late].mean()),
            "tension_front_N": float(0.5 * (res["front_port.tension"][late] + res["front_starboard.tension"][late]).mean()),
            "tension_range_N": [float(min(res[f"{n}.tension"][late].min() for n in LINES)),
                                float(max(res[f"{n}.tension"][late].max() for n in LINES))],
            "lines_not_partly_lifted": sum(1 for n in LINES if events.get(n, {}).get("state") != "PARTLY_LIFTED"
                                           or events.get(n, {}).get("taut_s") or events.get(n, {}).get("fully_lifted_s")),
            "steps": res.summary["steps"], "cpu_s": res.summary["cpu_s"], "wall_s": res.summary["wall_s"]}


def spread(per_model: dict) -> dict:
    """For each compared quantity, max / min - 1 across the models [-]."""
    keys = ("surge_m", "heave_m", "tension_back_N", "tension_front_N")
    return {k: float(max(f[k] for f in per_model.values()) / min(f[k] for f in per_model.values()) - 1.0)
            for k in keys}


def model_scene(model: str, duration: float):
    """The scene :data:`SCENE` with the mooring model ``model`` for ``duration`` [s]."""
    from cosim.scene import Scene

    return Scene.from_toml(SCENE).with_values([f"moorings.model={model}", f"world.duration={duration}"])


#: each variant's models, duration [s] and the start of the compared window [s] (quick: True)
RUNS = {True: (QUICK_MODELS, 20.0, 10.0), False: (MODELS, 90.0, 30.0)}


def run_models(models, duration: float, t0: float, out: Path) -> dict:
    """Run the scene with each model for ``duration`` [s]; each model's figures after ``t0``."""
    return {m: model_figures(model_scene(m, duration).run(out / m, progress=False), t0) for m in models}


@case("wind-turbine-moorings", "Barreiro et al. 2016's wind-turbine base in waves (analytic fluid): every mooring model against "
      "the others",
      target="surge and heave amplitudes and mean fairlead tensions of the mooring models within 10 % of each other "
             "while no line goes taut",
      quick="catenary and SPH cable over 20 s (window 10-20 s, the wave's first half period at the base): heave half "
            "ranges and mean tensions within 10 % of each other, every line partly lifted; the surge is reported, not "
            "judged (the chain's inertia and drag slow its build-up: the dynamic lines reach the catenary's surge "
            "after ~30 s)", scene=lambda quick: model_scene(RUNS[quick][0][0], RUNS[quick][1]))
def wind_turbine_moorings(quick: bool) -> dict:
    """Every model on the same scene (module docstring); the spread of each quantity.

    Full (90 s, window 30-90 s): MODELS. Quick (20 s, window 10-20 s): catenary and SPH
    cable, the surge not judged: it builds up more slowly on the dynamic lines (half range
    over 20-40 s: catenary 1.585 m, SPH cable 1.157, MoorDyn 1.246; over 30-90 s 1.585,
    1.620, 1.667), so only the full window compares it."""
    models, duration, t0 = RUNS[quick]
    with tempfile.TemporaryDirectory(prefix="wind_turbine_") as tmp:
        per_model = run_models(models, duration, t0, Path(tmp))
    sp = spread(per_model)
    metrics = {"spread": sp, "models": per_model, "window_s": [t0, duration],
               "lines_not_partly_lifted": sum(f["lines_not_partly_lifted"] for f in per_model.values())}
    stated = {f"spread.{k}": 0.10 for k in sp}
    stated["lines_not_partly_lifted"] = 0
    out = {"metrics": metrics, "tolerances": dict(stated), "steps": sum(f["steps"] for f in per_model.values())}
    if quick:
        del out["tolerances"]["spread.surge_m"]
        out["stated_tolerances"] = stated
    return out
