"""Where the piston flume's wave gains or loses its energy: the power each term of the SPH
fluid that does not conserve energy puts into the wave, row by row under the surface, in
the 2-D flume or a 3-D slice (docs/validation/wave-propagation_history.md, "The wave's
energy budget").

The fluid's pressure and continuity sums conserve energy pair by pair (the symmetric
pressure form with the continuity equation keeps the sum of the kinetic, gravitational and
internal energies: Monaghan 2005, Rep. Prog. Phys. 68, 1703); the terms that do
not are the density diffusion, the artificial viscosity and the walls, whose pressures are
set from the fluid (Adami et al. 2012) instead of evolving with it. Their powers [W] on
the fluid particles, sampled every eighth evaluation of the rates over the last three
periods:

- the density diffusion: ``P_D = sum_a m_a p_a / rho_a^2 D_a`` (the internal energy it
  adds; Antuono et al. 2015 read the δ-SPH term's energy the same way), ``D_a`` the rate
  with the diffusion less the rate without it (``delta = 0``);
- the artificial viscosity: ``P_V = sum_a m_a v_a . (a_a - a_a(alpha = 0))``;
- the fixed walls: ``P_W = -sum_a sum_w m_a m_w p_w / rho_w^2 v_a . grad_a W_aw`` (what is
  left of a fluid-wall pair's pressure and continuity terms when the wall's density is not
  evolved), for the floor and the side walls apart; the floor's part along it (the
  horizontal velocity's) is printed apart too, within the floor's.

Each is the time covariance of the particle's two factors (power less the product of the
means): the water settles by a fraction of a millimetre a period while it moves, and the
mean pressure times the mean rate of that settling (the potential energy it releases) is
not the wave's. Summed over the fluid particles that start between L / 4 and 1.25 L from
the paddle, binned by the row they start in (row 0 the surface's), and turned into the
change of the wave's height per wavelength it would make: ``0.5 P / E L / c_g``, E the
energy of linear theory's wave over that stretch (rho g H^2 / 8 per unit area). In the
2-D flume at 10 rows the three sum to the case's decay within 0.2 % per wavelength. Not
measured: the time integration's own energy error, and the moving paddle's walls (outside
the stretch).

    python benchmarks/wave_energy_budget.py --rows 10 --width 0
    python benchmarks/wave_energy_budget.py --rows 10 --width 5
"""

from __future__ import annotations

import json
import time

import numpy as np
from scipy.spatial import cKDTree

from wave_slice_across import arguments, slice_scene  # beside this script
from cosim.validations import case_scene
from cosim.validations.wave_propagation import G, WP_DEPTH, WP_HEIGHT, WP_PERIOD, _wave
from fluid import equations as eq
from fluid.kernels import grad_W
from fluid.particles import Kind

ROWS_SHOWN = 8  # rows under the surface binned apart; deeper ones join the last bin
TERMS = ("diffusion", "viscosity", "floor", "side walls")
SHOWN = TERMS + ("floor, along it",)  # the last is part of "floor"
RHO_WATER = 1000.0  # kg/m^3: the scenes' rho0, for linear theory's wave energy


def rates_without(f, index: int):
    """The fluid ``f``'s rates with the parameter ``index`` of the pair loop set to 0."""
    ps, c, m = f.ps, f.config, f.mirror
    prm = f._prm.copy()
    prm[index] = 0.0
    return eq.evaluate(ps.pos, ps.vel, ps.rho, ps.mass, ps.kind, f._start, f._grid, f._kernel, prm, c.rho0,
                       c.speed_of_sound, c.gamma, ps.p.copy(), eq.Workspace(), f._xbins, f.near_fluid,
                       f._walls_rates, m, None if m is None else f.image_rows)


def wall_pressure_acceleration(f, width: float) -> dict:
    """``-sum_w m_w p_w / rho_w^2 grad_a W_aw`` on every particle [m/s^2], from the floor
    (and end walls) and from the side walls (outside 0 <= y <= ``width`` [m]), (N, dim) each."""
    ps, h = f.ps, f.config.h
    dim = ps.pos.shape[1]
    fl = np.flatnonzero(ps.kind == Kind.FLUID)
    wl = np.flatnonzero(ps.kind == Kind.FIXED_WALL)
    near = cKDTree(ps.pos[wl]).query_ball_point(ps.pos[fl], 2.0 * h)
    a = fl[np.repeat(np.arange(fl.size), [len(q) for q in near])]
    w = wl[np.concatenate([np.asarray(q, int) for q in near])]
    term = -(ps.mass[w] * ps.p[w] / ps.rho[w] ** 2)[:, None] * grad_W(ps.pos[a] - ps.pos[w], h)
    side = np.zeros(w.size, bool) if dim == 2 else (ps.pos[w, 1] < 0.0) | (ps.pos[w, 1] > width)
    return {name: np.stack([np.bincount(a[m], term[m, d], len(ps.pos)) for d in range(dim)], 1)
            for name, m in (("floor", ~side), ("side", side))}


def term_rates(f, width: float):
    """What the terms that do not conserve energy add to the rates of ``f`` now: the
    density diffusion's ``D`` [kg/(m^3 s)], the artificial viscosity's acceleration and
    the walls' pressure accelerations [m/s^2] (:func:`wall_pressure_acceleration`)."""
    D = f._drho - rates_without(f, eq.P_DDT)[0]
    dv = f._acc - rates_without(f, eq.P_ALPHA)[1]
    return D, dv, wall_pressure_acceleration(f, width)


class Budget:
    """The four powers' time sums per particle id (the covariances' parts), sampled every
    ``every`` rate evaluation from ``t_from`` [s]."""

    def __init__(self, f, dx: float, width: float, t_from: float, every: int):
        ps = f.ps
        n = int(ps.ids.max()) + 1
        dim = ps.pos.shape[1]
        self.z0, self.x0, self.m = (np.full(n, np.nan) for _ in range(3))
        self.z0[ps.ids], self.x0[ps.ids], self.m[ps.ids] = ps.pos[:, -1], ps.pos[:, 0], ps.mass
        self.s = {k: np.zeros(n) for k in ("w", "p", "D", "pD", "V", "Xv_floor", "Xv_side", "Xv_along")}
        self.v = {k: np.zeros((n, dim)) for k in ("v", "X_floor", "X_side")}
        self.dx, self.width, self.t_from, self.every = dx, width, t_from, every
        self.calls = self.samples = 0

    def sample(self, f):
        self.calls += 1
        if f.t < self.t_from or self.calls % self.every:
            return
        ps = f.ps
        D, dv, X = term_rates(f, self.width)
        fl = ps.kind == Kind.FLUID
        ids = ps.ids[fl]
        s, v = self.s, self.v
        s["w"][ids] += ps.mass[fl] / ps.rho[fl] ** 2
        s["p"][ids] += ps.p[fl]
        s["D"][ids] += D[fl]
        s["pD"][ids] += ps.p[fl] * D[fl]
        s["V"][ids] += ps.mass[fl] * (ps.vel[fl] * dv[fl]).sum(axis=1)
        v["v"][ids] += ps.vel[fl]
        for name in ("floor", "side"):
            v["X_" + name][ids] += X[name][fl]
            s["Xv_" + name][ids] += (X[name][fl] * ps.vel[fl]).sum(axis=1)
        s["Xv_along"][ids] += (X["floor"][fl, :-1] * ps.vel[fl, :-1]).sum(axis=1)
        self.samples += 1

    def powers(self, x0: float, x1: float) -> dict:
        """Each term's power [W] by starting row over the particles starting in [x0, x1]."""
        n = self.samples
        sel = (self.x0 > x0) & (self.x0 < x1) & np.isfinite(self.m)
        row = np.clip(np.floor((WP_DEPTH - self.z0[sel]) / self.dx).astype(int), 0, ROWS_SHOWN - 1)
        s = {k: a[sel] / n for k, a in self.s.items()}
        v = {k: a[sel] / n for k, a in self.v.items()}
        per = {"diffusion": s["w"] * (s["pD"] - s["p"] * s["D"]), "viscosity": s["V"]}
        for name, key in (("floor", "floor"), ("side walls", "side")):
            per[name] = self.m[sel] * (s["Xv_" + key] - (v["X_" + key] * v["v"]).sum(axis=1))
        per["floor, along it"] = self.m[sel] * (s["Xv_along"] - (v["X_floor"][:, :-1] * v["v"][:, :-1]).sum(axis=1))
        return {k: np.bincount(row, p, ROWS_SHOWN) for k, p in per.items()}


def run(rows: int, width_rows: int, duration: float, values=(), every: int = 8) -> dict:
    _, L, cg = _wave(WP_HEIGHT, WP_PERIOD, WP_DEPTH)
    dx = WP_DEPTH / rows
    scene = slice_scene(rows, width_rows, duration, (), values)
    cpu0 = time.process_time()
    with case_scene.built(scene) as b:
        f = b.sph
        budget = Budget(f, dx, width_rows * dx, duration - 3.0 * WP_PERIOD, every)
        rates = f._rates

        def sampled():
            rates()
            budget.sample(f)

        f._rates = sampled
        f.advance(0.0, duration)
    x0, x1 = 0.25 * L, 1.25 * L
    E = 0.125 * RHO_WATER * G * WP_HEIGHT ** 2 * (width_rows * dx if width_rows else 1.0) * (x1 - x0)
    P = budget.powers(x0, x1)
    return {"rows": rows, "width_rows": width_rows, "set": list(values), "samples": budget.samples,
            "cpu_s": round(time.process_time() - cpu0, 1),
            "power_by_row_W": {t: np.round(P[t], 6).tolist() for t in SHOWN},
            "height_change_per_wavelength_pct": {t: round(100.0 * 0.5 * float(P[t].sum()) / E * L / cg, 3)
                                                 for t in SHOWN}}


def main(argv=None) -> None:
    args = arguments(__doc__, 5, None, argv)
    r = run(args.rows, args.width, args.duration, args.set)
    print(json.dumps(r))
    print("\n| term | " + " | ".join(f"row {i}" for i in range(ROWS_SHOWN)) + " | height per wavelength |")
    print("|---|" + "---|" * (ROWS_SHOWN + 1))
    for t in SHOWN:
        print(f"| {t} | " + " | ".join(f"{p * 1e3:.2f}" for p in r["power_by_row_W"][t])
              + f" | {r['height_change_per_wavelength_pct'][t]:+.2f} % |")
    print("(powers in mW over the stretch L/4 ... 1.25 L; rows under the surface, the last one and deeper)")


if __name__ == "__main__":
    main()
