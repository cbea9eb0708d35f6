"""Running scenes: the builder wires what a hand-wired coupler does (to round-off), floating
bodies start in equilibrium, probes land on exact times, a resumed run continues bit
for bit, a failed run leaves readable outputs, and a scene loads only what it contains."""

import json
import re
import math
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from cosim import checkpoint
from cosim.scene import SPH, Analytic, Beach, Box, Flume, Line, Moorings, Piston, Probes, Scene, Shake, Tank, World
from cosim.scene.placement import floating_height

ROOT = Path(__file__).resolve().parents[1]
LINE = dict(length=0.9, weight=5.0, EA=1.0e5, mass_per_length=0.588, diameter=0.01)


def moored_box(dx=0.05, duration=0.2, **world):
    return Scene(
        name="box",
        world=World(dim=2, duration=duration, sample_every=0.02, snapshot_every=0.1, **world),
        fluid=SPH(dx=dx),
        domain=Flume(length=3.0, depth=0.3, height=0.45, beach=Beach(toe=2.0, slope=0.3)),
        waves=Piston(height=0.04, period=1.0, ramp=1.0),
        bodies=[Box("box", size=(0.2, 0.1), density=500.0, pos=(1.2,), place="floating",
                    fairleads={"left": (-0.1, -0.05), "right": (0.1, -0.05)})],
        moorings=Moorings(lines=[Line("box.left", anchor=(0.5, 0.0), **LINE),
                                 Line("box.right", anchor=(1.9, 0.0), **LINE)]),
        probes=Probes(gauges=[0.6, 1.6]),
    )


def shaken_tank(duration=0.2, **world):
    return Scene(name="tank", world=World(dim=2, duration=duration, sample_every=0.05, **world),
                 fluid=SPH(dx=0.04), domain=Tank(length=0.6, height=0.5, depth=0.3),
                 base_motion=Shake(period=1.0, amplitude=0.01, ramp=0.5), probes=Probes(gauges=[0.1], energy=True))


def test_floating_height_balances_weight_and_lines():
    """Without lines the box's centre sits at level + h/2 - (rho_b / rho_w) h exactly; with
    lines the buoyancy of the computed draft equals weight plus the catenary's pull."""
    from moorings.catenary import solve

    s = moored_box()
    box = s.bodies[0]
    z0 = floating_height(box, 2, 0.3, 1000.0, 9.81)
    assert z0 == pytest.approx(0.3 + 0.05 - 0.5 * 0.1, abs=1e-12)
    z = floating_height(box, 2, 0.3, 1000.0, 9.81, s.moorings.lines)
    draft = 0.3 - (z - 0.05)
    pull = sum(float(solve(abs(x - 1.2 - ox), z - 0.05, 0.9, 5.0, 1e5).V)
               for x, ox in ((0.5, -0.1), (1.9, 0.1)))
    assert 1000.0 * 9.81 * 0.2 * draft == pytest.approx(500.0 * 0.02 * 9.81 + pull, rel=1e-9)
    assert pull > 1.0 and z < z0  # the lines pull it down by about a millimetre
    assert z0 - z == pytest.approx(pull / (1000.0 * 9.81 * 0.2), rel=1e-9)


def test_scene_equals_hand_wired_coupler(tmp_path):
    """The scene's participants step exactly as the same set-up wired by hand (flume with
    ceil(2 h / dx) wall layers and the paddle's back space, the wave set-up without the
    walls' loads, the box at its computed height, elastic catenary lines, fluid-first
    coupling)."""
    from bodies import builders
    from bodies.mujoco_bodies import MujocoBodies
    from cosim.coupler import Coupler
    from cosim.scene.build import build
    from cosim.sph_fluid import SPHFluid
    from fluid.flume import PADDLE_GROUP, flume
    from fluid.solver import TRAVELLING_WAVES, FluidConfig
    from fluid.wavemaker import RegularWavemaker
    from moorings import CatenaryMooring, MooringLine

    scene = moored_box()
    got = build(scene, tmp_path)
    dx, g = 0.05, 9.81
    wm = RegularWavemaker("piston", 0.04, 1.0, 0.3, 1.0, g)
    fl = flume(dx, 3.0, 0.3, 0.45, layers=4, back=0.5 * wm.stroke + dx, beach=(2.0, 0.3))
    # no pressure patch reads the walls' loads: the scene does not compute them
    cfg = FluidConfig(dim=2, dx=dx, g=g, u_max=math.sqrt(g * 0.3), wall_loads=False, **TRAVELLING_WAVES)
    fluid = SPHFluid(cfg, fl.fluid, fl.walls, z_surface=0.3, motions={PADDLE_GROUP: wm.paddle()})
    z = got.start_heights["box"]
    sites = {"box__left": (-0.1, 0.0, -0.05), "box__right": (0.1, 0.0, -0.05)}
    box = builders.box("box", (0.2, 0.1), (1.2, 0.0, z), density=500.0, planar=True, sites=sites)
    bodies = MujocoBodies(builders.scene(box, gravity=g, timestep=1e-3))
    lines = [MooringLine((0.5, 0.0), 0.9, 5.0, EA=1e5, mass_per_length=0.588, diameter=0.01, name="box.left"),
             MooringLine((1.9, 0.0), 0.9, 5.0, EA=1e5, mass_per_length=0.588, diameter=0.01, name="box.right")]
    hand = Coupler(bodies=bodies, fluid=fluid, moorings=[(CatenaryMooring(lines), list(sites))], scheme="fluid-first")
    hand.initialize()
    assert got.coupler.scheme == "fluid-first" and not got.sph.config.wall_loads
    for c in (got.coupler, hand):
        for _ in range(25):
            c.step(1.0)
    a, b = got.sph.ps, fluid.fluid.ps
    assert a.n == b.n and got.coupler.t == hand.t
    np.testing.assert_array_equal(a.pos, b.pos)
    np.testing.assert_array_equal(a.rho, b.rho)
    np.testing.assert_array_equal(got.bodies.data.qpos, bodies.data.qpos)


def test_run_writes_outputs_at_exact_times(tmp_path):
    scene = moored_box(dx=0.03, duration=0.3, plot_at=[0.1])
    r = scene.run(tmp_path, progress=False)
    np.testing.assert_array_equal(r.t, [k * 0.02 for k in range(16)])  # counted, not accumulated
    for name in ("run.h5", "run.xmf", "scene.toml", "summary.json", "motion.csv", "tensions.csv", "gauges.csv",
                 "loads.csv", "ledger.csv", "motion.png", "gauges.png", "particles_t000.100.png"):
        assert (tmp_path / name).stat().st_size > 0, name
    assert Scene.from_toml(tmp_path / "scene.toml") == scene
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["setup"]["name"] == "waves" and s["scheme"] == "fluid-first" and s["steps"] == r.summary["steps"]
    with h5py.File(tmp_path / "run.h5") as f:
        np.testing.assert_array_equal(f["series/probes/motion/box.heave"][:], r["box.heave"])
        assert len(f["snapshot_times"]) == 4 and len(f["series/ledger/box/t"]) == s["steps"]
        Fz = f["series/ledger/box/fluid_force"][:, 2]
        rows = [r.split(",") for r in (tmp_path / "ledger.csv").read_text().splitlines()]
        assert rows[0][:3] == ["t [s]", "body", "fluid_force_x [N]"] and {r[1] for r in rows[1:]} == {"box"}
        # every dataset says its unit (CF's units attribute), a line's state what its codes mean
        assert f["series/ledger/box/fluid_torque"].attrs["units"] == "N m"
        assert f["series/probes/motion/box.pitch"].attrs["units"] == "deg"
        assert f["series/probes/motion/t"].attrs["units"] == "s" and f["snapshots/0000/p"].attrs["units"] == "Pa"
        states = f["series/probes/line_states/box.left.state"].attrs
        assert list(states["flag_values"]) == [0, 1, 2, 3]
        assert states["flag_meanings"].split() == ["resting", "partly_lifted", "fully_lifted", "taut"]
        np.testing.assert_array_equal([float(r[0]) for r in rows[1:]], f["series/ledger/box/t"][:])
        np.testing.assert_array_equal([float(r[4]) for r in rows[1:]], Fz)
    head = (tmp_path / "tensions.csv").read_text().splitlines()[0]
    assert head == ("t [s],box.left.tension [N],box.right.tension [N],box.left.anchor_tension [N],"
                    "box.right.anchor_tension [N]")
    # afloat near its start, the lines hang (~ w * suspended length), the gauges see still water
    assert np.abs(r["box.heave"]).max() < 0.02 and np.abs(r["box.pitch"]).max() < 5.0
    assert (r["box.left.tension"] > 0.5).all() and (r["box.left.tension"] < 5.0).all()
    assert np.abs(r["gauge1.eta"]).max() < 0.02
    # the fluid carries the box: buoyancy ~ its weight 98 N plus the lines' pull 2.5 N
    assert 90.0 < np.median(Fz) < 110.0


def test_resume_is_bit_for_bit(tmp_path):
    """A run stopped at a checkpoint and resumed to a longer duration equals the run made
    in one go: every probe sample and the last particle snapshot, exactly."""
    whole = moored_box(duration=0.2, checkpoint_every=0.1).run(tmp_path / "whole", progress=False)
    moored_box(duration=0.1, checkpoint_every=0.1).run(tmp_path / "split", progress=False)
    resumed = moored_box(duration=0.2, checkpoint_every=0.1).run(tmp_path / "split", resume=True, progress=False)
    assert resumed.summary["resumed"] and resumed.summary["steps"] == whole.summary["steps"]
    np.testing.assert_array_equal(resumed.t, whole.t)
    for name in whole.names:
        np.testing.assert_array_equal(resumed[name], whole[name], err_msg=name)
    with h5py.File(tmp_path / "whole" / "run.h5") as f, h5py.File(tmp_path / "split" / "run.h5") as g:
        np.testing.assert_array_equal(f["snapshot_times"][:], g["snapshot_times"][:])
        np.testing.assert_array_equal(f["snapshots/0002/pos"][:], g["snapshots/0002/pos"][:])
        np.testing.assert_array_equal(f["series/ledger/box/fluid_force"][:], g["series/ledger/box/fluid_force"][:])


@pytest.mark.long
def test_a_resumed_run_may_add_plot_times(tmp_path):
    """Plot times on the sampling grid added when resuming are drawn, and the run stays the
    one made in one go (they change no step)."""
    whole = moored_box(duration=0.2, checkpoint_every=0.1).run(tmp_path / "whole", progress=False)
    moored_box(duration=0.1, checkpoint_every=0.1).run(tmp_path / "split", progress=False)
    resumed = moored_box(duration=0.2, checkpoint_every=0.1, plot_at=(0.14,)).run(tmp_path / "split", resume=True,
                                                                                   progress=False)
    assert (tmp_path / "split" / "particles_t000.140.png").is_file()
    assert not (tmp_path / "whole" / "particles_t000.140.png").exists()
    assert resumed.summary["steps"] == whole.summary["steps"]
    for name in whole.names:
        np.testing.assert_array_equal(resumed[name], whole[name], err_msg=name)


@pytest.mark.long
def test_a_resumed_runs_time_counts_every_segment(tmp_path):
    """``summary.json``'s ``cpu_s`` and ``wall_s`` are the whole run's: the first segment's
    (kept in the checkpoint) plus the resumed one's, ``cpu_s_this_run`` the latter's."""
    first = moored_box(duration=0.1, checkpoint_every=0.1).run(tmp_path, progress=False).summary
    ck = checkpoint.read(tmp_path / "checkpoint.h5")["meta"]
    assert 0 < ck["cpu_s"] <= first["cpu_s"] + 1e-6 and ck["wall_s"] <= first["wall_s"] + 1e-6
    second = moored_box(duration=0.2, checkpoint_every=0.1).run(tmp_path, resume=True, progress=False).summary
    assert second["cpu_s_this_run"] > 0
    assert second["cpu_s"] == pytest.approx(ck["cpu_s"] + second["cpu_s_this_run"], abs=2e-3)
    assert second["wall_s"] > ck["wall_s"] and first["cpu_s_this_run"] == first["cpu_s"]


@pytest.mark.long
def test_resume_refuses_a_changed_scene(tmp_path):
    from cosim.errors import InputError

    moored_box(duration=0.04, checkpoint_every=0.02).run(tmp_path, progress=False)
    changed = moored_box(duration=0.1, checkpoint_every=0.02).with_values(["bodies[0].density=600"])
    with pytest.raises(InputError, match=r"bodies\[0\]\.density: differs from the run being resumed"):
        changed.run(tmp_path, resume=True, progress=False)
    with pytest.raises(InputError, match="no checkpoint"):
        moored_box().run(tmp_path / "empty", resume=True, progress=False)


@pytest.mark.long
def test_the_checkpoint_drawn_afterwards_is_the_plot_drawn_during_the_run(tmp_path):
    """``cosim plot FOLDER`` rebuilds the scene and restores its checkpoint: at the run's end
    it draws, pixel for pixel, the particle plot the run drew then; a folder without a run,
    or a run without particles, is refused naming why."""
    from matplotlib.image import imread

    from cosim.cli import main
    from cosim.errors import InputError
    from cosim.scene.runner import plot_checkpoint

    moored_box(duration=0.1, plot_at=[0.1]).run(tmp_path / "run", progress=False)
    assert main(["plot", str(tmp_path / "run"), "--png", str(tmp_path / "ck.png")]) == 0
    np.testing.assert_array_equal(imread(tmp_path / "ck.png"), imread(tmp_path / "run" / "particles_t000.100.png"))
    assert plot_checkpoint(tmp_path / "run").name == "particles_checkpoint_t000.100.png"
    with pytest.raises(InputError, match="no scene.toml; give the folder of a run"):
        plot_checkpoint(tmp_path / "nothing")
    analytic = moored_box(duration=0.02).to_dict()
    analytic["fluid"] = {"model": "analytic", "level": 0.3}
    analytic.pop("domain")
    analytic.pop("waves")
    analytic["probes"] = {"motion": ["box"]}
    Scene.from_dict(analytic).run(tmp_path / "analytic", progress=False)
    with pytest.raises(InputError, match="only an SPH run has particles to draw"):
        plot_checkpoint(tmp_path / "analytic")


def test_failed_run_leaves_readable_outputs(tmp_path, monkeypatch):
    import cosim.scene.plots as plots

    def broken(*a):
        raise RuntimeError("plotting failed")

    monkeypatch.setattr(plots, "plot_particles", broken)
    with pytest.raises(RuntimeError, match="plotting failed"):
        shaken_tank(duration=0.2, plot_at=[0.1]).run(tmp_path, progress=False)
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["error"] == "RuntimeError: plotting failed" and s["t_reached_s"] == pytest.approx(0.1)
    with h5py.File(tmp_path / "run.h5") as f:
        np.testing.assert_array_equal(f["series/probes/gauges/t"][:], [0.0, 0.05, 0.1])


def test_a_run_reads_back_finished_and_as_far_as_written_while_unfinished(tmp_path):
    """``read``: a finished run's series as the run returned them; without its summary (a
    run still going or killed) refused, unless ``unfinished``, which reads the same
    series, and of a row half written (one key a sample ahead) only the whole rows."""
    from cosim.scene.runner import read
    from errors import InputError

    res = shaken_tank(duration=0.2).run(tmp_path, progress=False)
    back = read(tmp_path)
    assert back.names == res.names and back.summary == res.summary
    np.testing.assert_array_equal(back.t, res.t)
    for k in res.names:
        np.testing.assert_array_equal(back[k], res[k], err_msg=k)
    (tmp_path / "summary.json").unlink()
    with pytest.raises(InputError, match="no summary.json.*unfinished=True"):
        read(tmp_path)
    with h5py.File(tmp_path / "run.h5", "a") as f:
        g = f["series/probes/gauges"]
        key = next(k for k in g if k != "t")
        g[key].resize(g[key].shape[0] + 1, axis=0)  # the writer one key into the next row
    part = read(tmp_path, unfinished=True)
    assert part.summary == {} and len(res.t) == 5
    np.testing.assert_array_equal(part.t, res.t)
    for k in res.names:
        np.testing.assert_array_equal(part[k], res[k], err_msg=k)
    with pytest.raises(InputError, match="no run.h5"):
        read(tmp_path / "nothing", unfinished=True)


def test_a_probe_that_fails_mid_run_leaves_whole_rows(tmp_path, monkeypatch):
    """The energy probe fails at its third sample, after the gauges were taken: the run
    stops with that error (not a reshape error of half a row) and the outputs hold the
    two whole rows sampled before."""
    import fluid.probes

    calls, real = [], fluid.probes.fluid_energies

    def failing(sph):
        calls.append(sph.t)
        if len(calls) == 3:
            raise RuntimeError("energy probe failed")
        return real(sph)

    monkeypatch.setattr(fluid.probes, "fluid_energies", failing)
    with pytest.raises(RuntimeError, match="energy probe failed"):
        shaken_tank(duration=0.2).run(tmp_path, progress=False)
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["error"] == "RuntimeError: energy probe failed"
    for name in ("gauges", "energy"):
        rows = (tmp_path / f"{name}.csv").read_text().splitlines()
        assert len(rows) == 3, rows  # the header and the samples at 0 and 0.05 s


def test_fluid_only_scene_shakes_the_tank(tmp_path):
    """No bodies: the SPH fluid runs as a plain participant; the shaken tank's water
    gains energy, and its initial state is at rest (hydrostatic densities)."""
    r = shaken_tank(duration=0.6).run(tmp_path, progress=False)
    ke = r["fluid.kinetic"]
    assert ke[0] == 0.0 and ke[-1] > 1e-3
    assert r.summary["setup"]["name"] == "sloshing" and "remedies" not in r.summary


def test_the_fluids_precision_is_a_scene_field(tmp_path):
    """fluid.precision reaches the solver; the shaken tank in float32 follows float64's to
    the rates' float32 round-off (its kinetic energy within 1e-4 after 0.2 s)."""
    runs = {p: shaken_tank().with_values([f"fluid.precision={p}"]).run(tmp_path / p, progress=False)
            for p in ("float64", "float32")}
    assert runs["float32"].summary["setup"]["config"]["precision"] == "float32"
    ke64, ke32 = runs["float64"]["fluid.kinetic"], runs["float32"]["fluid.kinetic"]
    assert ke64[-1] > 0 and ke32[-1] == pytest.approx(ke64[-1], rel=1e-4) and ke32[-1] != ke64[-1]


def test_analytic_scene_matches_its_physics(tmp_path):
    """A box of half the water's density on the analytic fluid, at its draft: at rest."""
    s = Scene(world=World(dim=2, duration=1.0, sample_every=0.1), fluid=Analytic(level=0.0),
              bodies=[Box("b", size=(1.0, 1.0), density=500.0, pos=(0.0, 0.0))])
    r = s.run(tmp_path, progress=False)
    assert np.abs(r["b.heave"]).max() < 1e-9
    assert r["b.fluid_Fz"][-1] == pytest.approx(500.0 * 9.81, rel=1e-6)


def test_the_loads_list_the_moorings_force_only_where_there_are_lines(tmp_path):
    """An unmoored body's loads are the fluid's alone (no column of zeros named after a
    mooring); with lines, each body has both, in the order the scene promises
    (``series_names``) and the run records."""
    from cosim.scene.probes import series_names

    bare = Scene(world=World(dim=2, duration=0.1, sample_every=0.05), fluid=Analytic(level=0.0),
                 bodies=[Box("b", size=(1.0, 1.0), density=500.0, pos=(0.0, 0.0))])
    r = bare.run(tmp_path / "bare", progress=False)
    loads = [n for n in r.names if "_F" in n]
    assert loads == ["b.fluid_Fx", "b.fluid_Fz"] == [n for n in series_names(bare) if "_F" in n]
    moored = Scene.from_toml(ROOT / "examples" / "moored_box.toml").with_values(["world.duration=0.1"])
    r = moored.run(tmp_path / "moored", progress=False)
    loads = [n for n in r.names if "_F" in n]
    assert loads == ["box.fluid_Fx", "box.fluid_Fz", "box.mooring_Fx", "box.mooring_Fz"]
    assert loads == [n for n in series_names(moored) if "_F" in n]
    assert np.abs(r["box.mooring_Fx"]).max() > 0


@pytest.mark.long
@pytest.mark.parametrize("kind", ["analytic", "sph-no-bodies"])
def test_a_scene_loads_only_what_it_contains(kind, tmp_path):
    """A scene without the SPH fluid never imports (so never compiles) the fluid's
    kernels; one without bodies never imports MuJoCo."""
    scene = ("Scene(world=World(duration=0.1, sample_every=0.05), fluid=Analytic(), "
             "bodies=[Box('b', size=(1.0, 1.0), density=500.0, pos=(0.0, 0.0))])" if kind == "analytic" else
             "Scene(world=World(duration=0.02, sample_every=0.01, snapshot_every=0), fluid=SPH(dx=0.05), "
             "domain=Tank(length=0.3, height=0.3, depth=0.2))")
    code = ("import sys\nfrom cosim.scene import *\n"
            f"{scene}.run({str(tmp_path)!r}, progress=False)\n"
            "print(sorted(m for m in ('fluid.solver', 'fluid.equations', 'mujoco') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr[-2000:]
    loaded = eval(out.stdout.strip().splitlines()[-1])
    assert loaded == (["mujoco"] if kind == "analytic" else ["fluid.equations", "fluid.solver"])


def test_cli_run_and_set(tmp_path):
    out = subprocess.run([sys.executable, "-m", "cosim.cli", "run", str(ROOT / "examples" / "sloshing_tank.toml"),
                          "--set", "world.duration=0.1", "--set", "fluid.dx=0.05", "--set", "world.plot_at=[0.1]",
                          "--out", str(tmp_path)], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr[-2000:]
    assert "fluid set-up: sloshing" in out.stdout and "left_wall.p" in out.stdout
    assert Scene.from_toml(tmp_path / "scene.toml").fluid.dx == 0.05
    bad = subprocess.run([sys.executable, "-m", "cosim.cli", "run", str(ROOT / "examples" / "sloshing_tank.toml"),
                          "--set", "fluid.dxx=0.05", "--out", str(tmp_path / "bad")], capture_output=True, text=True)
    assert bad.returncode == 2 and "fluid.dxx: unknown key; did you mean 'dx'?" in bad.stderr
    assert not (tmp_path / "bad").exists()


def test_refused_by_a_solver_before_anything_is_written(tmp_path):
    """A scene that passes its own checks but that a solver refuses while it is built (a
    body thinner than two particles) leaves no output folder."""
    from cosim.errors import InputError

    thin = moored_box().with_values(["bodies[0].size=[0.2, 0.04]", "fluid.dx=0.05"])
    with pytest.raises(InputError, match="body 'box' geom 0 .* particle"):
        thin.run(tmp_path / "out", progress=False)
    assert not (tmp_path / "out").exists()


def test_output_folder_that_cannot_be_written(tmp_path):
    from cosim.errors import InputError

    (tmp_path / "file").write_text("")
    with pytest.raises(InputError, match="is not a folder; give another --out"):
        shaken_tank().run(tmp_path / "file" / "out", progress=False)


def test_unstable_run_names_step_and_body_and_stays_readable(tmp_path):
    """A speed of sound barely above the water's long-wave speed (2 m/s against sqrt(g h) =
    1.7 m/s; a lower one is refused) in a tank shaken at 4.6 g: the body outruns the fluid
    and the run stops naming the step and the body; what was sampled before stays readable."""
    from cosim.errors import InstabilityError
    from fluid.output import read_series

    s = Scene(world=World(dim=2, duration=1.0, sample_every=0.005), fluid=SPH(dx=0.03, c0=2.0),
              domain=Tank(length=0.6, height=0.5, depth=0.3), base_motion=Shake(period=0.5, acceleration=45.0),
              bodies=[Box("cork", size=(0.12, 0.08), density=10.0, pos=(0.3,), place="floating")])
    with pytest.raises(InstabilityError, match=r"step \d+, t = [0-9.]+ s: body 'cork' moves at .* speed of sound"):
        s.run(tmp_path, progress=False)
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["error"].startswith("InstabilityError: step")
    heave = read_series(tmp_path / "run.h5", "probes/motion")
    assert len(heave["t"]) >= 2 and np.isfinite(heave["cork.heave"]).all()


@pytest.mark.parametrize("name, content, says", [
    ("latin1.toml", "name = \"caf\xe9\"\n".encode("latin-1"), "is not UTF-8 text"),
    ("broken.py", b"scene = Scene(\n", "broken.py line 1"),
    ("raises.py", b"x = 1 / 0\n", "raises.py raised ZeroDivisionError: division by zero (at raises.py line 1)"),
])
def test_unreadable_scene_files_are_refused_by_name(name, content, says, tmp_path):
    from cosim.errors import InputError
    from cosim.scene.load import load

    (tmp_path / name).write_bytes(content)
    with pytest.raises(InputError, match=re.escape(says)):
        load(tmp_path / name)


@pytest.mark.long
def test_anchor_tensions_agree_between_models(tmp_path):
    """The anchor tension of MoorDyn's line matches the catenary's at the start where the line
    pulls its anchor up (the box 3 m off its rest position); an FMU reports none."""
    base = Scene.from_toml(ROOT / "examples" / "moored_box.toml").with_values(["world.duration=0.05"])
    cat = base.run(tmp_path / "cat", progress=False)
    md = base.with_values(["moorings.model=moordyn"]).run(tmp_path / "md", progress=False)
    assert cat["box.left.anchor_tension"][0] == pytest.approx(918.4, rel=1e-3)  # sqrt(H^2 + (V - w L)^2)
    assert md["box.left.anchor_tension"][0] == pytest.approx(cat["box.left.anchor_tension"][0], rel=0.01)
    assert "box.left.anchor_tension" not in base.with_values(["moorings.model=fmu"]).run(
        tmp_path / "fmu", progress=False).names
