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

Measured over the 90 s (surge, heave, pitch: half the peak-to-peak over 30-90 s, after the
wave has reached the base; mean fairlead tension over 30-90 s of the back line and of the
two front lines; coupling steps; wall and CPU time of the run) with
`python examples/wind_turbine_base.py`, on the project machine's 2 cores (AMD EPYC, as
/proc/cpuinfo names it) with other jobs beside it (compare CPU times; the dynamic rows
2026-11-26, load 3-4):

=========  =====  =====  =====  =====================  ======  =====  =====
model      surge  heave  pitch  mean tension [kN]      steps   wall   CPU
           [m]    [m]    [deg]  back / port / stbd             [s]    [s]
=========  =====  =====  =====  =====================  ======  =====  =====
catenary   1.585  0.318  0.74   94.8 / 94.3 / 94.3     3600    36.2   13.2
fmu        1.585  0.318  0.74   94.8 / 94.3 / 94.3     3600    30.7   13.1
moordyn    1.667  0.330  1.37   95.0 / 94.5 / 94.5     19260   150.5  120.4
sph-cable  1.620  0.328  1.19   94.9 / 94.7 / 94.7     15716   87.1   87.4
=========  =====  =====  =====  =====================  ======  =====  =====

(moordyn and sph-cable at the coupler's own step, cosim.line_step: 0.0045-0.0050 s and
0.0057 s on average, moving with the lines' geometry.)

Within 5.2 % of each other in surge (the dynamic lines +2.2 % and +5.2 %), 4 % in heave and
0.7 % in mean tension; the two dynamic models agree with each other within 3 % in surge
and 1 % in heave. Pitch differs more (0.74 against 1.2-1.4 deg: the dynamic lines'
inertia and drag act at the bottom rim, 1.5 m under the centre); their tensions swing a
little wider (SPH cable 81.3-109.9 kN, MoorDyn 80.8-108.2 kN, against the catenary's
84-108 kN over 30-90 s: the inertia and drag of 60 t of chain). With the lines' force held
over each step (``coupling.lines = "explicit"``) the SPH cables swung 19-208 kN: a ~28 Hz
limit cycle of the exchange (benchmarks/line_step_sweep.py), gone when the lines advance
with the base. The FMU is the catenary law compiled: the same figures
to the digits shown. No line breaks (largest tension over 30-90 s 208 kN against 1400 kN);
every line of every model stays partly lifted (summary.json line_events). The surge beats
between the 20 s wave and the moored base's own surge period (~13 s: 60 t against ~15 kN/m
from the three lines), so its amplitude varies from window to window (catenary: 0.86-1.59 m
over 20 s windows). The wave at the base is the piston's far field, H = 0.700 m (gauges:
0.35 m amplitude), from a stroke of 1.51 m.

The SPH fluid on the same scene (``--set fluid.model=sph --set fluid.dx=2.0``, the 3-D
wave set-up: h = 2 dx, four wall layers): 43 402 particles, c0 = 140 m/s, coupling steps of
~5 ms with the light-body sub-iterations the coupler picks (the base weighs 0.18 of the
water its volume holds); 88 CPU-s per simulated second on one thread of an Intel Xeon
(Emerald Rapids, 2026-11-26, the 0.2 s and 1.2 s runs' CPU differenced, so compilation
apart; the scene leaves out the tank walls' own accelerations, which no probe of it reads,
``FluidConfig.wall_loads``: 117 with them, the same motion to every digit), about 2.2
CPU-hours for the 90 s. A machinery check only: the 1.51 m draft
is under one spacing, and the boundary particles feel the water over their kernel's
reach, so at t = 0 the fluid lifts the base with 900 kN where hydrostatics gives 429 kN
(weight + the lines' pull); the base leaps 2.9 m in 1.2 s. A rate evaluation costs 6.4
times as much at dx = 1 m (465 against 72.7 ms, one thread), with twice the steps: ~1 100
CPU-s per simulated second, ~28 CPU-hours for the 90 s; three spacings over the draft
(dx = 0.5 m) another ~15 times that, ~400 CPU-hours (extrapolated, not run).
The wave alone is cheap to check: without the body the flume's wave is the 2-D one (the
tank is uniform across), and a 2-D flume of the scene's depth (360 m long, so no
reflection reaches the gauges before 46 s) makes 0.98 H at the base's x = 70 m at dx = 2 m
and 0.99 H at dx = 1 m with h = 2 dx, wavenumber 0.97 and 0.99 of theory's (22 and 101
CPU-s; at h = sqrt(2) dx, dx = 2 m: 0.90 H, 0.95). In 3-D, a slab of that flume 8 m wide
(4 rows between side walls, dx = 2 m, the 3-D wave set-up) makes 0.96 / 0.92 / 0.87 H at
x = 40 / 70 / 100 m (wavenumber 0.96; 1 120 CPU-s; h = sqrt(2) dx: 0.79 / 0.69 / 0.56 H);
with the artificial viscosity off between the water and the walls (alpha_wall = 0) 1.00 /
1.00 / 0.97 H: the extra 3-D loss is the side walls' viscous drag, which matters less in
the scene's 40 m (20 rows) than in the slab.: ``cosim.validations.waves.paddle_wave_heights``.

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
