"""The coupler's clock and step loop."""

import math

import pytest

from cosim.clock import Clock, to_ticks
from cosim.coupler import Coupler
from cosim.errors import ConfigurationError, InputError, InstabilityError, ProtocolError


class Recorder:
    """A participant that records every (t, dt) it is advanced with."""

    def __init__(self, name="rec", max_dt=math.inf, record=True):
        self.name, self._max_dt, self.record = name, max_dt, record
        self.calls, self.t_init, self.value = [], None, 0.0

    def initialize(self, t0):
        self.t_init = t0

    def max_dt(self):
        return self._max_dt

    def advance(self, t, dt):
        self.value += dt
        if self.record:
            self.calls.append((t, dt))

    def save_state(self):
        return (self.value, len(self.calls))

    def load_state(self, state):
        self.value = state[0]
        del self.calls[state[1]:]


@pytest.mark.long
def test_million_steps_land_on_100_s():
    c = Coupler([Recorder(record=False)], dt=1e-4)
    assert c.run(100.0) == 1_000_000
    assert abs(c.t - 100.0) <= 1e-12
    # naive accumulation drifts by far more than the clock allows
    t = 0.0
    for _ in range(1_000_000):
        t += 1e-4
    assert abs(t - 100.0) > 1e-10


def test_clock_nonzero_start_and_ticks():
    clk = Clock(t0=3.25)
    for _ in range(1000):
        clk.advance(to_ticks(1e-3))
    assert clk.t == 4.25
    assert to_ticks(1e-4) == 100_000_000
    assert to_ticks(2.5e-12) == 2


def test_every_participant_sees_the_same_clock_and_the_end_time_exactly():
    a, b = Recorder("a", max_dt=0.3), Recorder("b", max_dt=0.7)
    c = Coupler([a, b])
    infos = []
    c.run(1.0, callback=infos.append)
    assert a.calls == b.calls
    assert [round(t, 12) for t, _ in a.calls] == [0.0, 0.3, 0.6, 0.9]
    assert a.calls[-1][1] == pytest.approx(0.1, abs=1e-15)
    assert c.t == 1.0
    assert [i.limiter for i in infos] == ["a", "a", "a", "end time"]
    assert a.t_init == 0.0


def test_a_fixed_step_is_the_step_used_or_refused_and_every_other_step_is_counted():
    """A fixed step above a participant's stable step at the start could not be the step
    used: refused, naming the participant, its step and the fix. Below it, it is the step;
    a participant that needs less later gets less, and step_summary() counts each step by
    what set it."""
    with pytest.raises(ConfigurationError, match=r"dt = 0.01 s is above the stable step of participant 'fluid', 0.001 s, "
                                                 r"which would set the step instead; leave dt unset .* dt <= 0.001 s"):
        Coupler([Recorder("fluid", max_dt=1e-3)], dt=1e-2).step(1.0)
    p = Recorder("fluid", max_dt=1.0)
    c = Coupler([p], dt=1e-2)
    info = c.step(1.0)
    assert info.dt == 1e-2 and info.limiter == "user dt"
    p._max_dt = 4e-3  # later the fluid needs less: 0.004 s steps up to 0.03 s, the last one landing on it
    c.run(0.03)
    s = c.step_summary()
    assert s["dt_set_s"] == 0.01 and s["steps"] == 6
    assert {k: v["steps"] for k, v in s["by_limiter"].items()} == {"user dt": 1, "fluid": 4, "end time": 1}
    assert s["dt_min_s"] == pytest.approx(0.004, abs=1e-15) and s["dt_max_s"] == 0.01
    assert s["dt_mean_s"] == pytest.approx(0.03 / 6, rel=1e-12)


def test_fluid_steps_is_a_whole_number_and_needs_a_fluid():
    for bad in (0, -1, 1.5, True, "2"):
        with pytest.raises(InputError, match=r"fluid_steps must be a whole number .* 1 or more; got"):
            Coupler([Recorder()], fluid_steps=bad)
    with pytest.raises(ConfigurationError, match=r"fluid_steps > 1 .* this coupler has none; leave fluid_steps at 1"):
        Coupler([Recorder()], fluid_steps=4)
    assert Coupler([Recorder()], fluid_steps=1).fluid_steps == 1


def test_checkpoint_restores_clock_and_participants():
    p = Recorder(max_dt=0.1)
    c = Coupler([p])
    c.run(0.5)
    cp = c.save_state()
    c.run(1.0)
    assert c.steps == 10
    c.load_state(cp)
    assert c.t == 0.5 and c.steps == 5 and len(p.calls) == 5
    assert p.value == pytest.approx(0.5)


def test_bad_participant_and_bad_input_are_refused():
    class NoAdvance:
        name = "x"

        def initialize(self, t0): ...

    with pytest.raises(ProtocolError, match="advance.*load_state.*max_dt"):
        Coupler([NoAdvance()])
    with pytest.raises(ConfigurationError, match="repeated: a"):
        Coupler([Recorder("a"), Recorder("a")])
    with pytest.raises(InputError, match="positive"):
        Coupler([Recorder()], dt=-1.0)
    with pytest.raises(InputError, match="resolution"):
        Coupler([Recorder()], dt=1e-14)


def test_invalid_stable_step_stops_with_the_participant_named():
    c = Coupler([Recorder("fluid", max_dt=float("nan"))])
    with pytest.raises(InstabilityError, match="step 1.*'fluid'"):
        c.run(1.0)


def test_progress_line_redrawn_on_a_terminal_written_whole_elsewhere_silent_on_request():
    import io

    from cosim.progress import Progress

    buf = io.StringIO()
    c = Coupler([Recorder(max_dt=0.001, record=False)])
    c.run(0.5, progress=False)
    bar = Progress(0.0, 2.0, stream=buf, enabled=True, every_s=0.0)
    for k in range(1, 5):
        bar.update(0.5 * k)
    bar.close(2.0)
    text = buf.getvalue()
    assert "t = 2 / 2 s (100.0 %)  4 steps" in text and text.endswith("\n")
    # a StringIO is no terminal: whole lines, none before log_every_s of wall time has passed
    log = io.StringIO()
    bar = Progress(0.0, 1.0, stream=log, log_every_s=3600.0)
    bar.update(0.5)
    bar.close(1.0)
    assert bar.logging and log.getvalue() == ""
    bar = Progress(0.0, 1.0, stream=log, log_every_s=0.0)
    bar.update(0.5)
    bar.update(1.0)
    bar.close(1.0)
    lines = log.getvalue().split("\n")
    assert "\r" not in log.getvalue() and len(lines) == 4 and lines[-1] == ""
    assert "t = 0.5 / 1 s ( 50.0 %)  1 steps" in lines[0] and "(100.0 %)  2 steps" in lines[2]
    quiet = io.StringIO()
    bar = Progress(0.0, 1.0, stream=quiet, enabled=False, every_s=0.0)
    bar.update(1.0)
    bar.close(1.0)
    assert quiet.getvalue() == ""
