"""What a run's settings and outputs tell an engineer: the coupling step asked for is the
step taken (or refused, cosim.scene.timing and the coupler), the output folder holds one
run, plots outside the run are dropped with a notice, plots name what they show and
particle plots draw the mooring lines where they hang."""

import math
from pathlib import Path

import numpy as np
import pytest

from cosim.errors import InputError
from cosim.scene import SPH, Scene, Shake, Tank, World
from cosim.scene.fields import SceneError
from cosim.scene.probes import Group
from cosim.scene.timing import landing_steps

ROOT = Path(__file__).resolve().parents[1]
BOX = ROOT / "examples" / "moored_box.toml"  # the analytic fluid: a run of 0.2 s takes a second
WAVES = ROOT / "examples" / "moored_box_waves.toml"


def test_a_coupling_step_lands_on_every_output_time_or_is_refused():
    """At 0.016 s and samples every 0.05 s one step in four would be 0.002 s (1600 steps in
    20 s, not 1250): refused, offering the steps that land (0.05 / 4 and 0.05 / 3 s); 0.01
    s lands on the samples and the snapshots and is taken."""
    scene = Scene.from_toml(BOX)
    with pytest.raises(SceneError, match=r"coupling.dt: 0.016 s does not divide world.sample_every = 0.05 s "
                                         r"\(3.125 steps\).*e.g. 0.0125 s or 0.0166667 s"):
        scene.with_values(["coupling.dt=0.016"])
    assert landing_steps(0.016, [0.05, 0.1]) == (0.0125, pytest.approx(0.05 / 3, rel=1e-12))
    assert landing_steps(0.5, [0.05]) == (0.05, None)  # longer than the samples: only shorter ones land
    assert scene.with_values(["coupling.dt=0.01"]).coupling.dt == 0.01
    # round-off of a multiple (5 x a step) is no reason to refuse it
    dt = 2 / 119.57
    assert Scene.from_toml(BOX).with_values([f"world.sample_every={5 * dt!r}", f"coupling.dt={dt!r}"])


@pytest.mark.long
def test_the_step_taken_is_the_step_set_and_summary_json_says_so(tmp_path):
    r = Scene.from_toml(BOX).with_values(["world.duration=0.2", "coupling.dt=0.01"]).run(tmp_path, progress=False)
    c = r.summary["coupling"]
    assert c["dt_set_s"] == 0.01 and c["steps"] == 20 == r.summary["steps"]
    assert c["dt_min_s"] == pytest.approx(0.01, rel=1e-12) and c["dt_max_s"] == pytest.approx(0.01, rel=1e-12)
    assert set(c["by_limiter"]) <= {"user dt", "end time"}  # the coupler's own step, landing on the samples
    free = Scene.from_toml(BOX).with_values(["world.duration=0.2"]).run(tmp_path / "free", progress=False)
    assert free.summary["coupling"]["dt_set_s"] is None and "fluid" in free.summary["coupling"]["by_limiter"]


@pytest.mark.long
def test_an_output_folder_holds_one_run(tmp_path):
    """A second run into a folder that holds one is refused before any work; with overwrite
    the earlier run's files go, the new run's come."""
    scene = Scene.from_toml(BOX).with_values(["world.duration=0.1"])
    scene.run(tmp_path, progress=False)
    (tmp_path / "notes_of_the_first_run.csv").write_text("t [s]\n")
    stamp = (tmp_path / "summary.json").stat().st_mtime_ns
    with pytest.raises(InputError, match=r"is not empty \(.*\): a run would leave the earlier files beside its own; "
                                         r"give --overwrite"):
        scene.run(tmp_path, progress=False)
    assert (tmp_path / "summary.json").stat().st_mtime_ns == stamp
    r = scene.run(tmp_path, overwrite=True, progress=False)
    assert not (tmp_path / "notes_of_the_first_run.csv").exists() and r.summary["t_reached_s"] == 0.1
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "thesis.tex").write_text("mine")
    with pytest.raises(InputError, match="none of them a run's output.*it is not cleared"):
        scene.run(tmp_path / "other", overwrite=True, progress=False)
    assert (tmp_path / "other" / "thesis.tex").read_text() == "mine"


def test_plot_times_beyond_the_end_are_dropped_with_a_notice(tmp_path):
    """Shortening the run needs no edit of plot_at: what lies beyond it is not drawn, and
    the run says so."""
    scene = Scene(name="tank", world=World(dim=2, duration=0.1, sample_every=0.05, plot_at=(0.05, 0.5)),
                  fluid=SPH(dx=0.04), domain=Tank(length=0.6, height=0.5, depth=0.3),
                  base_motion=Shake(period=1.0, amplitude=0.01, ramp=0.5))
    r = scene.run(tmp_path, progress=False)
    assert [p.name for p in tmp_path.glob("particles_*.png")] == ["particles_t000.050.png"]
    assert "world.plot_at: 0.5 s lie beyond the run's end (0.1 s); not drawn" in r.summary["warnings"]
    assert Scene.from_toml(WAVES).with_values(["world.duration=1.0"]).world.plot_at == (2.5, 5.0)


def test_plots_name_their_quantities_units_states_and_gauge_positions():
    from cosim.scene.plots import group_figure
    from cosim.scene.probes import _gauge_labels, _state_names

    t = np.linspace(0.0, 1.0, 11)
    states = Group("line_states", ["box.left.state", "box.right.state"], ["-", "-"], None,
                   categories=_state_names())
    fig = group_figure(t, np.zeros((11, 2)), states, "states")
    ax = fig.axes[0]
    assert [x.get_text() for x in ax.get_yticklabels()] == ["resting", "partly lifted", "fully lifted", "taut"]
    assert [x.get_text() for x in ax.get_legend().get_texts()] == ["box.left", "box.right"]
    loads = Group("loads", ["box.fluid_Fx", "box.mooring_Fx"], ["N", "N"], None)
    fig = group_figure(t, np.zeros((11, 2)), loads, "loads")
    assert [a.get_ylabel() for a in fig.axes] == ["fluid force Fx [N]", "mooring force Fx [N]"]
    gauges = Group("gauges", ["gauge1.eta", "gauge2.eta"], ["m", "m"], None, labels=_gauge_labels([0.6, 1.6], 2))
    fig = group_figure(t, np.zeros((11, 2)), gauges, "gauges")
    assert [x.get_text() for x in fig.axes[0].get_legend().get_texts()] == ["gauge1 at x = 0.6 m",
                                                                            "gauge2 at x = 1.6 m"]
    assert fig.axes[0].get_ylabel() == "elevation η [m]"


@pytest.mark.parametrize("scale", [1e-3, 1.0, 2.5e6])
def test_a_group_plots_texts_lie_inside_the_figure_and_apart(scale):
    """The margins found from the texts' extents (plots._fit_margins, not tight_layout):
    drawn, every tick label, axis label, offset text and the title lie inside the figure,
    each panel's y label left of its tick labels, the x label below the bottom panel's
    tick labels, and the panels do not overlap; for small, unit and large values (an
    offset text), categorical codes and four panels."""
    from cosim.scene.plots import group_figure
    from cosim.scene.probes import _state_names

    t = np.linspace(0.0, 120.0, 301)
    loads = Group("loads", ["box.fluid_Fx", "box.fluid_Fz", "box.mooring_Fx", "box.mooring_Fz"], ["N"] * 4, None)
    table = scale * np.column_stack([np.sin(t), -3 - np.cos(t), 100 * t, np.full_like(t, -7.5)])
    states = Group("line_states", ["a.state", "b.state"], ["-", "-"], None, categories=_state_names())
    for fig in (group_figure(t, table, loads, "a scene: loads on the bodies over each coupling step"),
                group_figure(t, np.zeros((len(t), 2)), states, "a scene: mooring line states")):
        fig.canvas.draw()
        r = fig.canvas.get_renderer()
        inside = fig.bbox.padded(-1.0)
        axes = fig.axes

        def shown(labels, lo_hi, k):  # the tick labels drawn: those within the axis's limits
            lo, hi = sorted(lo_hi)
            return [x for x in labels if x.get_text() and lo <= x.get_position()[k] <= hi]

        yticks = [shown(a.get_yticklabels(), a.get_ylim(), 1) for a in axes]
        xticks = shown(axes[-1].get_xticklabels(), axes[-1].get_xlim(), 0)
        texts = [axes[0].title, axes[-1].xaxis.label] + [a.yaxis.label for a in axes] \
            + [a.yaxis.get_offset_text() for a in axes] + [x for y in yticks for x in y] + xticks
        for x in texts:
            if x.get_visible() and x.get_text():
                e = x.get_window_extent(r)
                assert inside.x0 <= e.x0 and e.x1 <= inside.x1 and inside.y0 <= e.y0 and e.y1 <= inside.y1, x
        for a, ticks in zip(axes, yticks):
            assert a.yaxis.label.get_window_extent(r).x1 <= min(x.get_window_extent(r).x0 for x in ticks)
        assert axes[-1].xaxis.label.get_window_extent(r).y1 <= min(x.get_window_extent(r).y0 for x in xticks)
        for upper, lower in zip(axes, axes[1:]):  # apart, a lower panel's offset text too
            below = [lower, lower.yaxis.get_offset_text()] if lower.yaxis.get_offset_text().get_text() else [lower]
            top = max(x.get_window_extent(r).y1 for x in below)
            assert upper.get_window_extent(r).y0 >= top + 3.0  # px, clear of the frame


def test_the_particle_plot_draws_each_line_from_its_anchor_to_its_fairlead(tmp_path):
    """The catenary's shape through the anchor and where the fairlead is: it starts at
    the anchor, ends at the fairlead, and (partly lifted, nearly inextensible) is as long
    as the line."""
    from cosim.scene.build import build
    from cosim.scene.plots import line_shapes

    scene = Scene.from_toml(WAVES).with_values(["fluid.dx=0.05"])
    built = build(scene, tmp_path)
    shapes = dict(line_shapes(scene, built))
    fairleads = built.coupler.fairlead_positions()[0]
    for (name, p), ln, f in zip(shapes.items(), scene.moorings.lines, fairleads):
        np.testing.assert_allclose(p[0], ln.anchor, atol=1e-12)
        np.testing.assert_allclose(p[-1], f, atol=1e-9)
        length = float(np.sum(np.linalg.norm(np.diff(p, axis=0), axis=1)))
        assert length == pytest.approx(ln.length, rel=2e-3), name
    assert math.isclose(shapes["box.left"][0, 0], 0.5) and list(shapes) == ["box.left", "box.right"]


def test_a_scene_without_fluid_or_lines_records_no_loads():
    """The loads probe leaves out what could only read zero: a plate on a shaken base with
    no fluid and no lines has no fluid force and no node pressures to report; in the SPH
    tank it has both, and no mooring force (no lines)."""
    from cosim.scene.probes import PROBES
    from cosim.validations.shaken_cantilever import cantilever_scene

    scene = cantilever_scene(0.5, 8)
    assert PROBES["loads"].names(scene) == []
    assert "plate.tip_x" in PROBES["motion"].names(scene)
    sph = Scene.from_toml(Path(__file__).parents[1] / "cosim" / "validations" / "scenes" / "shaken-cantilever-sph.toml")
    names = PROBES["loads"].names(sph)
    assert "plate.fluid_Fx" in names and "plate.p0" in names and not any("mooring" in n for n in names)
