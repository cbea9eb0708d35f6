"""Why the ``long-period`` runs depart from linear theory: the gauges' error split by mode,
for runs written by ``benchmarks/long_period_trade.py``.

    python benchmarks/long_period_modes.py DIR/long_period_*.json

For each run, one line per part:

- the forced gauge error (RMS while shaken / linear theory's peak, the case's "forced")
  split over the least-squares fit of the gauges
  (:func:`cosim.validations.long_period.gauge_mode_basis`): the first mode, the next two
  antisymmetric modes (the rectangle's 3rd and 5th, whose frequencies 5.54 and 7.17
  rad/s bracket the forcing's 6.28), the two symmetric modes (second order: linear theory
  has none) and what the fit leaves; the 45 deg tank, which has no symmetry: its modes 1,
  2-3 and 4-5 (:func:`cosim.validations.forced_sloshing.trapezoid_modes`, FE), its "first
  three" in place of the antisymmetric ones below, and k there the wavenumber of the
  mode's frequency at the tank's depth (w^2 = g k tanh kh);
- each antisymmetric mode's free frequency and decay rate over the free sloshing
  (:func:`cosim.validations.long_period.free_decay`) against linear theory's frequency and
  the decay 2 nu k^2 of a free-surface wave (Lamb 1932 §348; the potential flow's
  dissipation gives the same 2 nu k^2 at any depth) under the artificial
  viscosity's equivalent kinematic viscosity nu = alpha h c0 / (2 (d + 2)) (the solver's
  ``alpha_eff``: Monaghan 2005, Rep. Prog. Phys. 68, 1703, §4.4);
- the gauges' error against linear theory whose three antisymmetric modes take those
  measured frequencies and decay rates (each mode's equation eta'' + 2 s eta' + w^2 eta
  = -w^2 b a(t) / g: the static tilt -b a / g kept), forced and over the whole record:
  what the modes' frequency and damping explain.
"""

from __future__ import annotations

import json
import sys
from dataclasses import fields
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from cosim.scene.setup import settings
from cosim.validations import forced_sloshing as fs
from cosim.validations.long_period import TANKS, gauge_mode_basis, free_decay
from fluid.solver import FluidConfig


def _modes(shape: str):
    tank = TANKS[shape]
    if shape == "rectangular":
        return fs.rectangular_modes(tank["size"], tank["depth"])
    if shape == "cylinder":
        return fs.cylinder_modes(0.5 * tank["size"], tank["depth"])
    return fs.trapezoid_modes(tank["size"], tank["depth"], tank["beta"])


def _damped(modes, j: int, w: float, s: float, a0: float, period: float, t_stop: float, t: np.ndarray) -> np.ndarray:
    """Mode j of linear theory [m] with frequency w [rad/s] and decay rate s [1/s]."""
    wf, F = 2 * np.pi / period, -w**2 * modes.b[j] * a0 / modes.g

    def rhs(tt, y):
        return [y[1], (F * np.sin(wf * tt) if tt <= t_stop else 0.0) - 2 * s * y[1] - w**2 * y[0]]

    return solve_ivp(rhs, (0.0, t[-1]), [0.0, 0.0], t_eval=t, rtol=1e-9, atol=1e-12, max_step=0.005).y[0]


def split(run: dict) -> list[str]:
    """The lines printed for one run (module docstring)."""
    a, m, rec = run["args"], run["metrics"], run["record"]
    modes = _modes(a["shape"])
    t = np.asarray(rec["t"])
    forced, free = t <= m["t_stop_s"], t > m["t_stop_s"]
    g, gl = np.asarray(rec["gauges_m"]), np.asarray(rec["gauges_linear_m"])
    amp, amp_lin = np.asarray(rec["modes_m"]), np.asarray(rec["modes_linear_m"])
    basis = gauge_mode_basis(a["shape"], TANKS[a["shape"]]["size"], np.asarray(rec["gauge_x_m"]), modes)
    peak = np.abs(gl).max()
    err = g - gl
    d = amp - amp_lin
    sloped = a["shape"] == "inclined"                  # no symmetry: its first five modes
    names = ("modes 2-3", "modes 4-5") if sloped else ("antisymmetric 2-3", "symmetric (2nd order)")
    parts = {"mode 1": basis[:, :1] @ d[:1], names[0]: basis[:, 1:3] @ d[1:3], names[1]: basis[:, 3:] @ d[3:]}
    parts["left by the fit"] = err.T - sum(parts.values())

    def rel(e, sel):
        return np.sqrt(np.mean(e[sel] ** 2)) / peak

    head = f"{a['shape']} {a['dim']}-D dx {a['dx']:.4f} ({TANKS[a['shape']]['depth'] / a['dx']:.0f} rows)"
    lines = [f"{head}: forced {rel(err, forced):.3f} = " +
             ", ".join(f"{k} {rel(v.T, forced):.3f}" for k, v in parts.items()) + " (each RMS / linear peak)"]
    dflt = {f.name: f.default for f in fields(FluidConfig)}
    h = settings("sloshing", a["dim"]).get("h_coef", dflt["h_coef"]) * a["dx"]
    nu = dflt["alpha"] * h * m["c0_m_s"] / (2 * (a["dim"] + 2))
    a0, T, ts = m["a0_g"] * modes.g, m["period_s"], m["t_stop_s"]
    eta0, _ = fs.response(modes, a0, T, ts, t)
    fitted, model = [], np.zeros((3, t.size))
    for j in range(3):
        w, s = free_decay(t[free], amp[j][free], modes.omega[j], rates=np.linspace(0.0, 2.0, 21))
        fitted.append(f"w {modes.omega[j]:.3f} -> {w:.3f} ({100 * (w / modes.omega[j] - 1):+.1f} %), "
                      f"s {s:.3f}/s (2 nu k^2 {2 * nu * modes.k[j] ** 2:.3f})")
        model[j] = _damped(modes, j, w, s, a0, T, ts, t) - eta0[j]
    lines.append(f"{head}: free {'first three' if sloped else 'antisymmetric'} modes (nu = {nu:.4f} m^2/s): " + "; ".join(fitted))
    left = err - (basis[:, :3] @ model).T
    lines.append(f"{head}: linear theory with those w, s: forced {rel(left, forced):.3f} "
                 f"(as run {rel(err, forced):.3f}), whole {rel(left, slice(None)):.3f} (as run {rel(err, slice(None)):.3f})")
    return lines


def main(argv=None) -> None:
    for f in (sys.argv[1:] if argv is None else argv):
        for line in split(json.loads(Path(f).read_text())):
            print(line, flush=True)


if __name__ == "__main__":
    main()
