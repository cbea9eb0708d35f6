"""The fixed coupling step of a scene and the output times it must land on.

The runner (:mod:`cosim.scene.runner`) stops exactly at every output time: the probe
samples (every ``world.sample_every``), the particle snapshots (``snapshot_every``, with
the SPH fluid), the checkpoints (``checkpoint_every``), the particle plots (``plot_at``)
and the end (``duration``). A fixed ``coupling.dt`` that does not divide one of the
repeating intervals would have the step before every such output time cut short, so that
the run's steps would not be ``coupling.dt`` (at 0.016 s and samples every 0.05 s, one
step in four would be 0.002 s: 1600 steps in 20 s instead of 1250).
:func:`check_fixed_step` refuses such a step when the scene is made, naming the interval it
misses and the steps that do land (the largest below it, and the next above). The single
times (the duration, the plots) may cut one step each; ``summary.json`` reports every step
that was not ``coupling.dt`` (``coupling``, :meth:`cosim.coupler.Coupler.step_summary`).
"""

from __future__ import annotations

import math

from cosim.clock import TICKS_PER_SECOND
from cosim.scene.fields import SceneError

#: how far from a whole number of steps an interval may be [steps] (binary round-off of
#: values such as 5 x 0.0167)
TOL = 1e-6


def intervals(scene) -> list[tuple[str, float]]:
    """``(field, interval [s])``: the repeating output intervals of the scene's run."""
    from cosim.scene.spec import SPH

    w = scene.world
    out = [("world.sample_every", w.sample_every)]
    if w.snapshot_every > 0 and isinstance(scene.fluid, SPH):  # without particles, no snapshot stops the run
        out.append(("world.snapshot_every", w.snapshot_every))
    if w.checkpoint_every > 0:
        out.append(("world.checkpoint_every", w.checkpoint_every))
    return out


def landing_steps(dt: float, every) -> tuple[float, float | None]:
    """The largest step [s] not above ``dt`` [s] of which every interval in ``every`` [s]
    is a whole multiple, and the smallest such step above ``dt`` (None if there is none:
    ``dt`` is longer than the intervals' greatest common divisor). In clock ticks."""
    g = 0
    for t in every:
        g = math.gcd(g, round(t * TICKS_PER_SECOND))
    n = max(1, round(dt * TICKS_PER_SECOND))
    below = g / math.ceil(g / n) / TICKS_PER_SECOND
    above = g / (g // n) / TICKS_PER_SECOND if g // n >= 1 and g % n else None
    return below, above


def check_fixed_step(scene) -> None:
    """Refuse a ``coupling.dt`` that does not divide every repeating output interval of
    ``scene`` (module docstring); nothing to check when it is unset."""
    dt = scene.coupling.dt
    if dt is None:
        return
    if dt * TICKS_PER_SECOND < 1:
        raise SceneError("coupling.dt", f"{dt:g} s is below the clock's resolution, {1 / TICKS_PER_SECOND:g} s")
    every = intervals(scene)
    for field, t in every:
        if abs(t / dt - round(t / dt)) > TOL or round(t / dt) < 1:
            below, above = landing_steps(dt, [x for _, x in every])
            also = f" or {above:.6g} s" if above is not None else ""
            raise SceneError("coupling.dt", f"{dt:g} s does not divide {field} = {t:g} s ({t / dt:.6g} steps): "
                             f"the run stops exactly at each output time, so the step before each would be cut "
                             f"short and {dt:g} s would not be the step used; give a step that divides the output "
                             f"intervals, e.g. {below:.6g} s{also}, or leave coupling.dt unset (the participants "
                             f"then choose the step)")
