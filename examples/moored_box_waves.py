"""A moored box in regular waves: a 2-D SPH flume, a piston wavemaker, two catenary lines.

A 0.2 x 0.1 m box of 500 kg/m^3 floats at x = 1.2 m in 0.3 m of water (its height is
computed: hydrostatics plus the lines' pull), held by two chains to anchors 0.6 m either
side of its fairleads; a piston makes waves of 0.04 m and 1 s, a 1:3.3 beach takes them out.
The fluid's wave set-up, the fluid-first coupling and the wall layers are chosen by the runner.

The lines are designed with the catenary (``cosim line --length 0.825 --weight 10 --height
0.247 --x-range 0.55 0.7``): at rest each is just lifted off the seabed (H = 0.07 N, T =
2.5 N), so a surge of 22 mm towards its anchor, or a trough that lowers its fairlead 20 mm,
lays it on the seabed (RESTING) and the other way lifts it (PARTLY_LIFTED). In the run
both lines do both, and their tensions swing by 30-80 % (tensions.png, line_states.png).

    cosim run examples/moored_box_waves.py            # or the same scene as TOML: .toml
    cosim run examples/moored_box_waves.py --set fluid.dx=0.01 --set moorings.model=moordyn
"""
from cosim.scene import SPH, Beach, Box, Flume, Line, Moorings, Piston, Probes, Scene, World

line = dict(length=0.825, weight=10.0, EA=1.0e5, mass_per_length=1.173, diameter=0.014)  # m, N/m, N, kg/m, m
scene = Scene(
    name="moored_box_waves",
    world=World(dim=2, duration=5.0, sample_every=0.02, snapshot_every=0.1, plot_at=[2.5, 5.0]),
    fluid=SPH(dx=0.02),
    domain=Flume(length=3.0, depth=0.3, height=0.45, beach=Beach(toe=2.0, slope=0.3)),
    waves=Piston(height=0.04, period=1.0, ramp=1.0),
    bodies=[Box("box", size=(0.2, 0.1), density=500.0, pos=(1.2,), place="floating",
                fairleads={"left": (-0.1, -0.05), "right": (0.1, -0.05)})],
    moorings=Moorings(model="catenary", segments=20,  # "sph-cable", "moordyn", "fmu": this field only
                      lines=[Line("box.left", anchor=(0.5, 0.0), **line),
                             Line("box.right", anchor=(1.9, 0.0), **line)]),
    probes=Probes(gauges=[0.6, 0.8, 1.6], motion=["box"]),
)

if __name__ == "__main__":
    results = scene.run(overwrite=True)  # a script that remakes its outputs: the earlier ones go
    heave = results["box.heave"]
    print(f"heave range {(heave.max() - heave.min()) * 1e3:.1f} mm, written to {results.out}")
