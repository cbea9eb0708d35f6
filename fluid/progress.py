"""A one-line progress bar for long runs: simulated time, steps per second, wall-clock ETA.

On a terminal (stderr by default) the line is redrawn in place; elsewhere (a run under
``nohup``, a batch scheduler's log) the same line is written whole, once a minute by
default, so that an hours-long run says where it is without filling its log. It lives in
``fluid`` (plain Python, no numba) because the solver packages may not import the coupler:
:mod:`cosim.progress` re-exports it for the coupler and the scene runner.
"""

from __future__ import annotations

import sys
import time


def _clock(seconds: float) -> str:
    """Wall time as h:mm:ss (or m:ss)."""
    if seconds != seconds or seconds == float("inf"):
        return "?"
    s = int(round(seconds))
    h, s = divmod(s, 3600)
    m, s = divmod(s, 60)
    return f"{h}:{m:02d}:{s:02d}" if h else f"{m}:{s:02d}"


class Progress:
    """Call :meth:`update` after each step, :meth:`close` at the end.

    ``t0``, ``t_end`` [s] the simulated span; ``stream`` where to write (stderr);
    ``enabled``: True draws the line in place, False writes nothing, None draws it on a
    terminal and elsewhere writes it whole every ``log_every_s`` [s] of wall time;
    ``every_s`` [s] the least wall time between two redraws; ``width`` [characters] of the
    bar.
    """

    def __init__(self, t0: float, t_end: float, *, stream=None, enabled: bool | None = None,
                 every_s: float = 0.2, width: int = 20, log_every_s: float = 60.0):
        self.stream = stream if stream is not None else sys.stderr
        self.logging = False  # whole lines (not a terminal) instead of a redrawn one
        if enabled is None:
            isatty = getattr(self.stream, "isatty", None)
            enabled = True
            if not (callable(isatty) and isatty()):
                self.logging, every_s = True, log_every_s
        self.enabled = enabled
        self.t0, self.t_end, self.every_s, self.width = t0, t_end, every_s, width
        self.wall0 = self._last = time.perf_counter()
        self.steps = 0
        self.shown = 0

    def line(self, t: float) -> str:
        wall = time.perf_counter() - self.wall0
        frac = (t - self.t0) / (self.t_end - self.t0) if self.t_end > self.t0 else 1.0
        frac = min(max(frac, 0.0), 1.0)
        rate = self.steps / wall if wall > 0 else 0.0
        eta = wall * (1.0 - frac) / frac if frac > 0 else float("inf")
        full = int(round(frac * self.width))
        bar = "#" * full + "-" * (self.width - full)
        return (f"[{bar}] t = {t:.4g} / {self.t_end:.4g} s ({100 * frac:5.1f} %)  {self.steps} steps, "
                f"{rate:.0f} steps/s, ETA {_clock(eta)}")

    def update(self, t: float, steps: int = 1) -> None:
        """Count ``steps`` more steps, now at simulated time ``t`` [s]; redraw if due."""
        self.steps += steps
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self._last >= self.every_s:
            self._last = now
            self.stream.write(self.line(t) + "\n" if self.logging else "\r" + self.line(t))
            self.stream.flush()
            self.shown += 1

    def close(self, t: float) -> None:
        """Draw the final line and end it (only if a line was shown)."""
        if self.enabled and self.shown:
            self.stream.write(("" if self.logging else "\r") + self.line(t) + "\n")
            self.stream.flush()
