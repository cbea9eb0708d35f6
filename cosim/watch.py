"""The coupler's instability watch: catches a coupled run going unstable before it
overflows, from the bodies' accelerations (the coupler adds a speed limit for a weakly
compressible fluid, ``Coupler.MAX_MACH``).

Two signatures of unstable staggered coupling (tuned on the series of
``benchmarks/density_ratio_sweep.py``, with the body boundary of its day):

1. a body's acceleration changes sign at every one of ``steps`` steps in a row and
   grows by 4 over them (the period-2 flip of the incompressible added-mass
   instability, a_{n+1} = -(m_a / m) a_n; the predictor-corrector at ratio 0.001 and
   the stand-in fluid of ``tests/test_coupling_extremes.py``);
2. over ``windows`` consecutive windows of ``window`` steps it changes sign in every
   window and its peak grows from each window to the next, by ``growth`` in all (the
   slower oscillation of a light body on a weakly compressible fluid's acoustic
   stiffness: fluid-first at ratio 0.05, and at 0.1 over 0.2 s). With 8 windows and a
   growth of 2 the sub-iterated fluid-first run at 0.01 was stopped as its body broke
   the surface; 10 and 3 stop none of the clean runs of the sweep.

Both also need the acceleration to end above g (the coupler passes 1 m/s^2 in a scene
without gravity), so that round-off never trips them.
"""

from __future__ import annotations

import numpy as np


class InstabilityWatch:
    """Keeps the bodies' recent generalised accelerations and says what, if anything,
    looks unstable.

    Parameters
    ----------
    dofs:
        The degrees of freedom (``qvel`` indices, a slice) of each body.
    g:
        Gravity [m/s^2]: accelerations below it never count as unstable.
    steps:
        Steps of sign flips in a row for signature 1 [-].
    window, windows, growth:
        Window length [steps], number of windows [-] and total peak growth [-] for signature 2.
    """

    def __init__(self, dofs, g: float, steps: int = 8, window: int = 20, windows: int = 10, growth: float = 3.0):
        self.dofs, self.g = list(dofs), g
        self.steps, self.window, self.windows, self.growth = steps, window, windows, growth
        self._n_keep = max(steps + 1, window * (windows + 1))
        self._buf = None  # (n_keep, nv), newest last
        self._count = 0  # accelerations held, up to n_keep
        self._steps = 0  # accelerations booked; signature 2 is checked at each window's end

    def add(self, qacc: np.ndarray) -> list[str | None]:
        """Book one step's generalised accelerations [m/s^2, rad/s^2]; returns per body
        why it looks unstable, or None."""
        if self._buf is None:
            self._buf = np.zeros((self._n_keep, len(qacc)))
        self._buf[:-1] = self._buf[1:]
        self._buf[-1] = qacc
        self._count = min(self._count + 1, self._n_keep)
        self._steps += 1
        return [self._check(s) for s in self.dofs]

    def _check(self, dofs: slice) -> str | None:
        a = self._buf[:, dofs]
        # cheap first test (most steps): signature 1 needs a flip and |a| > g at this step
        if self._count > self.steps and np.dot(a[-1], a[-2]) < 0 and np.dot(a[-1], a[-1]) > self.g ** 2:
            last = a[-self.steps - 1:]
            mag = np.linalg.norm(last, axis=1)
            if (np.einsum("ij,ij->i", last[1:], last[:-1]) < 0).all() and mag[-1] > 4.0 * mag[0] \
                    and mag[-1] > self.g:
                return (f"its acceleration changed sign at each of the last {self.steps} steps and grew from "
                        f"{mag[0]:.3g} to {mag[-1]:.3g}")
        if self._count == self._n_keep and self._steps % self.window == 0:
            win = a[-self.window * (self.windows + 1):].reshape(self.windows + 1, self.window, -1)
            peaks = np.linalg.norm(win, axis=2).max(axis=1)
            turns = (np.einsum("wij,wij->wi", win[:, 1:], win[:, :-1]) < 0).any(axis=1)
            if turns.all() and (np.diff(peaks) > 0).all() and peaks[-1] > self.growth * peaks[0] \
                    and peaks[-1] > self.g:
                return (f"its acceleration oscillated with a peak growing in each of the last {self.windows} "
                        f"windows of {self.window} steps, from {peaks[0]:.3g} to {peaks[-1]:.3g}")
        return None

    def save_state(self):
        return None if self._buf is None else (self._buf.copy(), self._count, self._steps)

    def load_state(self, state) -> None:
        self._buf, self._count, self._steps = (None, 0, 0) if state is None else (state[0].copy(), *state[1:])
