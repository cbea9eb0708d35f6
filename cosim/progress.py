"""A one-line progress display for long runs: simulated time, steps per second,
wall-clock ETA. It writes to a terminal only (stderr), so logs and CI stay clean."""

from __future__ import annotations

import sys
import time


class Progress:
    """Call :meth:`update` after each step; :meth:`close` at the end.

    ``enabled=None`` shows it only when ``stream`` is a terminal.
    """

    def __init__(self, t0: float, t_end: float, *, stream=None, enabled: bool | None = None, every_s: float = 0.2):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.t0, self.t_end, self.every_s = t0, t_end, every_s
        self.wall0 = self._last = time.perf_counter()
        self.steps = 0
        self.shown = 0

    def line(self, t: float) -> str:
        wall = time.perf_counter() - self.wall0
        frac = (t - self.t0) / (self.t_end - self.t0) if self.t_end > self.t0 else 1.0
        rate = self.steps / wall if wall > 0 else 0.0
        eta = wall * (1.0 - frac) / frac if frac > 0 else float("inf")
        return (f"t = {t:.4g} / {self.t_end:.4g} s ({100 * frac:5.1f} %)  {self.steps} steps, "
                f"{rate:.0f} steps/s, ETA {eta:.0f} s")

    def update(self, t: float) -> None:
        self.steps += 1
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self._last >= self.every_s:
            self._last = now
            self.stream.write("\r" + self.line(t))
            self.stream.flush()
            self.shown += 1

    def close(self, t: float) -> None:
        if self.enabled and self.shown:
            self.stream.write("\r" + self.line(t) + "\n")
            self.stream.flush()
