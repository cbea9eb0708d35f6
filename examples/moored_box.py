"""A moored floating box, one mooring model swapped for another in one field.

A 2-D box (2 m wide, 1 m tall, 500 kg/m^3, 1 m thick) floats on the analytic fluid
(hydrostatics and damping) of sea water, held by two 25 m chain-like lines to anchors
20 m either side, 10 m down. It starts 3 m to the right of its rest position and is let
go. `cosim run examples/moored_box.py` runs it once (the catenary); run as a script it
runs every mooring model (`moorings.model`: catenary, sph-cable, fmu, moordyn when
installed) and plots their surge and fairlead tensions together in out/moored_box/
(`--duration S`: each model over S seconds instead of the scene's 20).
1200 coupling steps for the 20 s with the catenary; what each model costs: docs/examples.md.
"""
from cosim.scene import Analytic, Box, Coupling, Line, Moorings, Scene, World

chain = dict(length=25.0, weight=50.0, EA=5.0e7, mass_per_length=5.82, diameter=0.03)  # m, N/m, N, kg/m, m
scene = Scene(
    name="moored_box",
    world=World(dim=2, duration=20.0, sample_every=0.05),
    fluid=Analytic(rho=1025.0, level=0.0, linear_damping={"box": [800.0, 0.0, 1500.0, 0.0, 1500.0, 0.0]}),
    bodies=[Box("box", size=(2.0, 1.0), density=500.0, pos=(3.0, 0.0),
                fairleads={"left": (-1.0, -0.5), "right": (1.0, -0.5)})],
    moorings=Moorings(model="catenary", segments=30,
                      lines=[Line("box.left", anchor=(-20.0, -10.0), **chain),
                             Line("box.right", anchor=(20.0, -10.0), **chain)]),
    coupling=Coupling(body_timestep=2e-3),
)

if __name__ == "__main__":
    import argparse

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from moorings.moordyn_mooring import moordyn_available

    parser = argparse.ArgumentParser(description="Run the moored box with every mooring model and plot them together.")
    parser.add_argument("--duration", type=float, default=scene.world.duration, help="seconds simulated per model")
    duration = parser.parse_args().duration
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), dpi=120, sharex=True)
    for model in ("catenary", "sph-cable", "fmu", "moordyn")[:None if moordyn_available() else 3]:
        r = scene.with_values([f"moorings.model={model}", f"world.duration={duration}"]).run(
            f"out/moored_box/{model}", overwrite=True, progress=False)
        print(f"{model:10s} {r.summary['steps']} steps, {r.summary['wall_s']:.2f} s wall; surge at the end "
              f"{r['box.surge'][-1]:+.4f} m, tensions {r['box.left.tension'][-1]:.1f} / "
              f"{r['box.right.tension'][-1]:.1f} N")
        (ln,) = ax1.plot(r.t, r["box.surge"], label=model)
        ax2.plot(r.t, r["box.left.tension"], color=ln.get_color(), label=f"{model}, left")
        ax2.plot(r.t, r["box.right.tension"], "--", color=ln.get_color(), label=f"{model}, right")
    ax1.set_ylabel("surge [m]")
    ax2.set_ylabel("fairlead tension [N]")
    ax2.set_xlabel("t [s]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig("out/moored_box/models.png")
    print("wrote out/moored_box/models.png and one run folder per model")
