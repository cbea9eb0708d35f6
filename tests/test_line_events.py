"""When each catenary line goes fully lifted and taut (Barreiro et al. 2016, Fig. 5 c-d), recorded after
every step (``moorings.line_events``), in a probe column and in summary.json."""

import math

import numpy as np
import pytest

from moorings import CatenaryMooring, MooringLine
from moorings.catenary import LineState

L, H, W = 30.0, 10.0, 100.0  # m, m, N/m: the fairlead 10 m above the anchor's seabed


def _drive(m, xs, dt):
    """Move the fairlead along x through ``xs`` [m], one step of ``dt`` [s] each."""
    m.set_fairlead_motion([[xs[0], H]])
    m.initialize(0.0)
    for k, x in enumerate(xs[1:]):
        m.set_fairlead_motion([[x, H]])
        m.advance(k * dt, dt)


def test_fairlead_out_and_back_times_the_states_at_the_law_boundaries():
    """Out at 1 m/s from X = 25 m to 28.3 m and back: fully lifted from the lift-off
    point X = (L^2 - h^2)/h atanh(h/L) (Barreiro et al. 2016, Eq. 35-39 with the anchor's vertical
    load zero), taut (held by its length constraint) from chord = L (1 - slack)."""
    m = CatenaryMooring([MooringLine((0.0, 0.0), L, W, name="front")])
    m.set_tethered(True)  # as a coupler does: taut inextensible lines become length constraints
    dt, v = 1e-3, 1.0
    out = np.arange(25.0, 28.3, v * dt)
    xs = np.concatenate([out, out[-2::-1]])
    _drive(m, xs, dt)
    x_lift = (L * L - H * H) / H * math.atanh(H / L)  # 27.726 m
    x_taut = math.sqrt((L * (1 - m.slack)) ** 2 - H * H)  # 28.252 m
    t_turn = (len(out) - 1) * dt
    ev = m.state_log.summary()["front"]
    assert ev["initial_state"] == "PARTLY_LIFTED" and ev["state"] == "PARTLY_LIFTED"
    # each event within one step after the law's crossing (the step in which it is first seen)
    for got, want in ((ev["fully_lifted_s"], [(x_lift - 25.0) / v]), (ev["taut_s"], [(x_taut - 25.0) / v]),
                      (ev["slack_s"], [2 * t_turn - (x_taut - 25.0) / v]),
                      (ev["touched_down_s"], [2 * t_turn - (x_lift - 25.0) / v])):
        assert len(got) == 1 and want[0] <= got[0] <= want[0] + 1.5 * dt, (got, want)
    assert ev["first_fully_lifted_s"] == ev["fully_lifted_s"][0] and ev["first_taut_s"] == ev["taut_s"][0]
    # the log survives save_state / load_state (checkpoints, sub-iterations)
    saved = m.save_state()
    m.set_fairlead_motion([[28.0, H]])
    m.advance(100.0, dt)
    m.load_state(saved)
    assert m.state_log.summary()["front"] == ev


def test_resting_line_has_no_events():
    m = CatenaryMooring([MooringLine((0.0, 0.0), L, W, name="a")])
    _drive(m, np.linspace(5.0, 15.0, 50), 0.1)  # X <= L - h: resting
    ev = m.state_log.summary()["a"]
    assert ev["initial_state"] == "RESTING" and ev["first_fully_lifted_s"] is None and ev["first_taut_s"] is None
    assert LineState(int(m.line_states()[0])) == LineState.RESTING


@pytest.mark.long
def test_scene_reports_line_events_and_a_state_column(tmp_path):
    """A box on one line, pushed by long waves out past the line's lift-off point and back:
    summary.json's line_events agree with the state column sampled every step."""
    from cosim.scene import Analytic, Box, Coupling, Line, LinearWaves, Moorings, Scene, World

    line = dict(length=30.0, weight=200.0)
    scene = Scene(name="events", world=World(dim=2, duration=10.0, sample_every=0.01),
                  fluid=Analytic(rho=1025.0, level=0.0, linear_damping={"box": [2000, 0, 4000, 0, 4000, 0]}),
                  waves=LinearWaves(height=2.4, period=10.0, depth=10.0, ramp=0.5),
                  bodies=[Box("box", size=(4.0, 2.0), density=500.0, pos=(0.0,), place="floating",
                              fairleads={"aft": (-2.0, -1.0), "fore": (2.0, -1.0)})],
                  moorings=Moorings(lines=[Line("box.aft", anchor=(-29.0, -10.0), name="stern", **line),
                                           Line("box.fore", anchor=(29.0, -10.0), name="bow", **line)]),
                  coupling=Coupling(dt=0.01, body_timestep=0.005))  # below the fluid's 0.0195 s: a sample a step
    res = scene.run(tmp_path / "r")
    ev = res.summary["line_events"]["stern"]
    state, t = res["stern.state"], res.t
    assert res.units["stern.state"] == "-"
    k = np.flatnonzero((state[1:] >= 2) & (state[:-1] < 2)) + 1  # samples at which it is first seen lifted
    assert len(k) >= 1 and len(ev["fully_lifted_s"]) == len(k)
    for i, j in enumerate(k):  # the event lies in the step that ended within the sampling interval
        assert t[j - 1] < ev["fully_lifted_s"][i] <= t[j] + 1e-9
    assert len(ev["touched_down_s"]) >= 1 and ev["touched_down_s"][0] > ev["fully_lifted_s"][0]
    assert res.summary["line_events"]["bow"]["first_fully_lifted_s"] is None  # the bow line stays on the seabed
