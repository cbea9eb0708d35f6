"""The floating base of an offshore wind turbine on three catenary lines in regular waves:
Barreiro et al. 2016, §5, Table 4, Figs. 17-19, in 3-D. The same scene as
examples/wind_turbine_base.toml, field for field; that file's header says what is the
paper's (16 000 kg; depth 20 m, 45 m lines of 442 kg/m steel, break load 1400 kN, at
120 deg; H = 0.7 m, T = 20 s from a wavemaker; past 80 s) and what is chosen because the
dimensions are only in Fig. 17 (a cylinder 6 m across and 3 m high, drawing 1.51 m with
the lines' 27.8 t hanging from it; anchors 37 m from its axis; the chain's EA and
diameter; the tank; the analytic fluid's added mass and drag).

`cosim run examples/wind_turbine_base.py` runs it once (analytic fluid, catenary lines);
run as a script (`python examples/wind_turbine_base.py [--models catenary,fmu,...]`) it
runs each mooring model, changed in the one field `moorings.model`, and writes the
figures below into out/wind_turbine_base/models.json. The two dynamic models need no
coupling step set by hand: their stiff chain (EA = 1.9e9 N, 442 kg/m, 20 segments of
2.25 m) resists the fairlead's motion with its axial impedance sqrt(EA m) = 9.2e5 N s/m
per line, which, held over a coupling step against the base's roll and pitch inertia, is
stable only below 2 / rate = 0.0062 s (MoorDyn) and 0.0077 s (SPH cable); the coupler
takes 0.8 of that (cosim.line_step) and refuses a coupling.dt above it. It advances the
dynamic lines with the base until their mean force over each step is the force the base
was given (the coupler's ``lines="subiterate"``, 1.6-2.2 advances of the lines a step).
At 0.025 s (the analytic fluid's own step), with the force held, MoorDyn's fairlead
tensions swung 1-550 kN and the SPH cable stopped at 0.35 s with the coupler's
growing-oscillation error.

The measured figures of every model, the SPH fluid's cost on this scene and the wave it
makes: docs/examples.md ("wind_turbine_base").

What the analytic fluid gives here: the base rides the long wave (λ = 271 m, 45 times
its diameter): heave close to the wave's amplitude (0.35 m), surge close to the water's
orbital excursion (a / tanh kd = 0.83 m) plus the moorings' slow response; no line
leaves the partly lifted state, so the paper's taut front lines at 71.1 s and 81.1 s
(Fig. 19) are not reproduced: linear waves on a linear-inertia body give no mean drift,
while the paper's SPH run carries the base down-wave (wave drift, the wavemaker's
mass transport and the tank's reflection, none of which this fluid has).
"""
import sys

from cosim.scene import Analytic, Beach, Coupling, Cylinder, Flume, Line, Moorings, Piston, Probes, Scene, World

G, RHO = 9.81, 1025.0
chain = dict(length=45.0, weight=3769.85, EA=1.9e9, mass_per_length=442.0, diameter=0.268, break_load=1.4e6)
scene = Scene(
    name="wind_turbine_base",
    world=World(dim=3, duration=90.0, sample_every=0.1, snapshot_every=0.0),
    fluid=Analytic(rho=RHO, linear_damping={"base": [2.0e3, 2.0e3, 1.2e4, 2.0e4, 2.0e4, 1.0e4]},
                   quadratic_damping={"base": [4.6e3, 4.6e3, 2.9e4, 0.0, 0.0, 0.0]},
                   added_mass={"base": [4.38e4, 4.38e4, 3.69e4, 0.0, 0.0, 0.0]}),
    domain=Flume(length=200.0, width=40.0, depth=20.0, height=26.0, beach=Beach(toe=110.0, slope=0.25)),
    waves=Piston(height=0.7, period=20.0, ramp=1.0),
    bodies=[Cylinder("base", radius=3.0, length=3.0, mass=16000.0, pos=(70.0, 20.0), place="floating",
                     fairleads={"back": (3.0, 0.0, -1.5), "port": (-1.5, 2.5981, -1.5),
                                "starboard": (-1.5, -2.5981, -1.5)})],
    moorings=Moorings(model="catenary", segments=20,
                      lines=[Line("base.back", name="back", anchor=(107.0, 20.0, 0.0), **chain),
                             Line("base.port", name="front_port", anchor=(51.5, 52.0429, 0.0), **chain),
                             Line("base.starboard", name="front_starboard", anchor=(51.5, -12.0429, 0.0), **chain)]),
    probes=Probes(gauges=((70.0, 10.0), (40.0, 20.0))),
    coupling=Coupling(body_timestep=0.005),
)

if __name__ == "__main__":
    import json
    from pathlib import Path

    from cosim.validations.wind_turbine import model_figures  # what cosim validate wind-turbine-moorings compares

    models = ["catenary", "fmu", "moordyn", "sph-cable"]
    if "--models" in sys.argv:
        models = sys.argv[sys.argv.index("--models") + 1].split(",")
    out = Path("out/wind_turbine_base")
    rows = {}
    for model in models:
        r = scene.with_values([f"moorings.model={model}"]).run(out / model, overwrite=True, progress=False)
        rows[model] = f = model_figures(r, t0=30.0)
        print(f"{model:10s} surge {f['surge_m']:.3f} m  heave {f['heave_m']:.3f} m  pitch {f['pitch_deg']:.2f} deg  "
              f"tension {f['tension_back_N'] / 1e3:.1f} / {f['tension_front_N'] / 1e3:.1f} kN  {f['steps']} steps  "
              f"{f['wall_s']:.1f} s wall  {f['cpu_s']:.1f} s CPU", flush=True)
    out.mkdir(parents=True, exist_ok=True)
    (out / "models.json").write_text(json.dumps(rows, indent=1))
    print(f"wrote {out}/models.json and one run folder per model")
