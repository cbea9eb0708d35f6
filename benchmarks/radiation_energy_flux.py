"""Where a heaving hull's work on the water goes: the energy budget of the water inside
upright cylinders round the hull's axis, radius by radius, period by period after the ramp.
docs/validation/nearfield.md, "The deep cylinder at R/dx = 6, and where its work goes".

For the water inside radius ``r_k`` (a smooth edge: each particle counts with a weight
``S(r)`` that falls from 1 to 0 across the band ``|r - r_k| < w``, ``w`` = :data:`BAND`
spacings, its slope ``-S'`` a hat of unit area, so that the region's energy changes only by
what crosses the band), over each whole period:

    dE_k/dt = P_body - P_leak - F_k + P_diffusion + P_viscosity + P_mls + P_walls + residual

- ``E_k = sum_a S_a m_a (|v_a|^2 / 2 + g (z_a - d) + e(rho_a))``: kinetic, gravitational
  (from the still level ``d``) and internal energy (the Tait equation's, ``int p / rho^2 d
  rho``; Monaghan 2005, Rep. Prog. Phys. 68: 1703, the SPH thermal energy equation);
- ``P_body - P_leak``: the hull's power into the fluid less its boundary particles'
  compression work (:func:`radiation_energy_leak.powers`);
- ``F_k = sum_a S'_a V_a (rho_a eps_a + p_a) v_r,a``: the energy flux out through the
  band, the continuum flux ``(rho eps + p) v . n`` of the same energy density ``rho eps``
  averaged over the band with the hat's weight (``V_a = m_a / rho_a``);
- ``P_diffusion = sum S m p / rho^2 D``, ``D`` the density diffusion's part of the
  continuity rate; ``P_viscosity = sum S m v . a_nu``, the laminar viscosity's acceleration
  (each the rates less the rates with that term's coefficient zero);
- ``P_mls``: the internal energy the density re-initialisation adds, summed as it happens;
- ``P_walls = sum S m v . a_w``, ``a_w = -sum_w m_w p_w / rho_w^2 grad W`` the walls'
  pressure term: what the fluid gains from walls whose densities do not follow the
  continuity equation (Adami walls; :func:`wave_energy_budget.wall_pressure_acceleration`);
- ``residual``: the rest, the time integration's and the flux estimate's error.

The last radius is the whole box (no flux; the zones' work on the velocities joins it; the
absorbing end walls' does not). Also: the kinetic energy of the velocities about their
kernel average (:data:`NOISE_H`), a disorder no wave carries, and :func:`by_particle`. All
as the damping that spends them, ``2 <P> / (omega a)^2`` [kN s/m]; the half box doubled.

    python benchmarks/radiation_energy_flux.py [--hull cylinder] [--draft 3] [--amplitude 0.6]
        [--r-over-dx 4] [--periods 6] [--depth D] [--set KEY=VALUE ...] [--raw FILE.npz [--read]]
"""

from __future__ import annotations

import argparse
import math

import numpy as np
from scipy.spatial import cKDTree

from machine import cpu_name  # beside this script
from radiation_energy_leak import SAMPLES_A_PERIOD, powers  # beside this script
from radiation_hull import RADIUS, add_scene_arguments, scene_for  # beside this script
from standing_wave_energy_audit import internal_energy  # beside this script
from wave_energy_budget import rates_without, wall_pressure_acceleration  # beside this script
from fluid import equations as eq
from fluid.kernels import W

#: the audited radii, in hull radii (inf: the whole box, zones and all)
RADII = (1.1, 1.25, 1.5, 2.0, 2.5, 3.0, 3.5, math.inf)
#: the half-width of the band's hat weight S', in spacings
BAND = 1.5
#: the smoothing length of the velocity's average that the noise is read about, in spacings
NOISE_H = 1.0
#: the per-sample terms, each (len(RADII),)
TERMS = ("energy", "flux", "diffusion", "viscosity", "walls", "noise")


class Audit:
    """The sampled terms of the budget (module docstring) for a fluid whose hull's axis is
    the z axis, with still water ``depth`` [m] deep; the re-initialisation's and the zones'
    energy are summed step by step from ``t_from`` [s] by period of ``period`` [s]."""

    def __init__(self, depth: float, t_from: float, period: float, periods: int):
        self.depth, self.t_from, self.period = depth, t_from, period
        self.mls = np.zeros((periods, len(RADII)))
        self.zones = np.zeros(periods)  # the zones' change of the whole water's kinetic energy [J]
        self.ids, self.particles = None, []  # the kept particles' ids and their values by sample (_keep)

    def _bucket(self, t: float):
        i = math.floor((t - self.t_from) / self.period - 1e-9)
        return i if 0 <= i < len(self.zones) else None

    def _weights(self, f, rows):
        """The radius [m] of ``rows``, their inside weights S (len(RADII), n) and band
        weights S' = -dS/dr [1/m] (module docstring)."""
        pos = f.ps.pos[rows]
        r = np.hypot(pos[:, 0], pos[:, 1])
        w = BAND * f.config.dx
        s = (r - np.array(RADII)[:, None] * RADIUS) / w
        inside = np.where(s < 0, 1.0 - 0.5 * np.clip(1.0 + s, 0.0, 1.0) ** 2, 0.5 * np.clip(1.0 - s, 0.0, 1.0) ** 2)
        return r, inside, np.clip(1.0 - np.abs(s), 0.0, 1.0) / w

    def _fields(self, f):
        """The simulated fluid rows and :meth:`_weights` of them."""
        fl = np.flatnonzero(f._fluid_rows())
        return (fl, *self._weights(f, fl))

    def _eps(self, f, rows):
        """Energy per unit mass [J/kg] of ``rows``: kinetic, gravitational, internal."""
        ps, c = f.ps, f.config
        return (0.5 * (ps.vel[rows] ** 2).sum(axis=1) + c.g_magnitude * (ps.pos[rows, -1] - self.depth)
                + internal_energy(c, ps.rho[rows]))

    def on_built(self, f) -> None:
        """Wrap ``f``'s re-initialisation and zones to sum the energy each adds."""
        reinit, zones = f._reinitialise_density, f._apply_zones

        def reinitialise():
            i = self._bucket(f.t)
            if i is None:
                return reinit()
            fl, _, inside, _ = self._fields(f)  # rows stay: the re-initialisation sets densities in place
            before = internal_energy(f.config, f.ps.rho[fl])
            reinit()
            self.mls[i] += 2.0 * inside @ (f.ps.mass[fl] * (internal_energy(f.config, f.ps.rho[fl]) - before))

        def apply_zones(dt):
            i = self._bucket(f.t)
            if i is None:
                return zones(dt)
            fl = f._fluid_rows()
            before = f.ps.mass[fl] @ (f.ps.vel[fl] ** 2).sum(axis=1)
            zones(dt)
            # m v^2 summed: the kinetic energy's change of the half box, doubled for the whole
            self.zones[i] += f.ps.mass[fl] @ (f.ps.vel[fl] ** 2).sum(axis=1) - before

        f._reinitialise_density, f._apply_zones = reinitialise, apply_zones

    def sample(self, f) -> np.ndarray:
        """The terms of :data:`TERMS` now [J for the energy, W for the rest], (len(TERMS),
        len(RADII)), the whole body of water's (the half box doubled)."""
        ps, c = f.ps, f.config
        fl, r, inside, band = self._fields(f)
        m, rho, v, p = ps.mass[fl], ps.rho[fl], ps.vel[fl], ps.p[fl]
        eps = self._eps(f, fl)
        vr = (ps.pos[fl, 0] * v[:, 0] + ps.pos[fl, 1] * v[:, 1]) / np.maximum(r, 1e-12)
        flux = m / rho * (rho * eps + p) * vr
        D = f._drho - rates_without(f, eq.P_DDT)[0]
        a_nu = f._acc - rates_without(f, eq.P_NU4)[1]
        a_walls = sum(wall_pressure_acceleration(f, math.inf).values())
        per = {"D": D[fl], "visc": m * (v * a_nu[fl]).sum(axis=1), "walls": m * (v * a_walls[fl]).sum(axis=1),
               "noise": 0.5 * m * (self._noise(f, fl) ** 2).sum(axis=1)}
        self._keep(f, fl, {**per, "a_walls": a_walls[fl]})
        out = np.stack([inside @ (m * eps), band @ flux, inside @ (m * p / rho ** 2 * per["D"]),
                        inside @ per["visc"], inside @ per["walls"], inside @ per["noise"]])
        return 2.0 * out

    def _keep(self, f, fl, per: dict) -> None:
        """Keep the sample's particle values by particle id (float32; NaN for a particle gone)
        in :attr:`particles`, for :func:`by_particle`."""
        ps = f.ps
        ids = ps.ids[fl]
        if self.ids is None:
            self.ids = np.sort(ids)
        at = np.searchsorted(self.ids, ids)
        ok = (at < self.ids.size) & (self.ids[np.minimum(at, self.ids.size - 1)] == ids)
        rows = {"pos": ps.pos[fl], "vel": ps.vel[fl], "rho": ps.rho[fl], "p": ps.p[fl], "m": ps.mass[fl], **per}
        out = {}
        for k, a in rows.items():
            b = np.full((self.ids.size,) + a.shape[1:], np.nan, np.float32)
            b[at[ok]] = a[ok]
            out[k] = b
        self.particles.append(out)

    def _noise(self, f, fl) -> np.ndarray:
        """Each fluid row's velocity less Shepard's kernel average of its fluid neighbours'
        (itself included; the kernel's h :data:`NOISE_H` spacings) [m/s]."""
        ps, c = f.ps, f.config
        pos = ps.pos[fl]
        h = NOISE_H * c.dx
        pairs = cKDTree(pos).query_pairs(2.0 * h, output_type="ndarray")
        a, b = np.concatenate([pairs[:, 0], pairs[:, 1]]), np.concatenate([pairs[:, 1], pairs[:, 0]])
        vol = ps.mass[fl] / ps.rho[fl]
        wab = W(np.linalg.norm(pos[a] - pos[b], axis=1), h, c.dim) * vol[b]
        w0 = W(np.zeros(1), h, c.dim)[0] * vol
        norm = np.bincount(a, wab, len(fl)) + w0
        v = ps.vel[fl]
        avg = np.stack([np.bincount(a, wab * v[b, d], len(fl)) + w0 * v[:, d] for d in range(v.shape[1])], 1)
        return v - avg / norm[:, None]


def budget(raw, period: float, to_b: float) -> dict:
    """Per period and radius, each term of the module docstring's budget as a damping
    [kN s/m]: ``{term: (periods, len(RADII))}``; ``raw``: the samples (``--raw``)."""
    x = raw["extra"]  # (samples, TERMS, RADII)
    per = SAMPLES_A_PERIOD
    n = len(x) // per
    mean = lambda a: np.array([a[i * per:(i + 1) * per].mean(axis=0) for i in range(n)])
    # the first period's start (the ramp's end) is not sampled: its change is taken over the
    # period's other samples
    dE = np.array([(x[(i + 1) * per - 1, 0] - x[i * per - 1, 0]) / period if i else
                   (x[per - 1, 0] - x[0, 0]) / (period * (per - 1) / per) for i in range(n)])
    body = mean(raw["p_in"] - raw["leak"])[:, None] * np.ones(len(RADII))
    t = {"body less leak": body, "flux out": mean(x[:, 1]), "diffusion": mean(x[:, 2]),
         "viscosity": mean(x[:, 3]), "re-initialisation": raw["mls"][:n] / period, "walls": mean(x[:, 4]),
         "energy's change": dE}
    t["zones"] = np.zeros_like(body)
    t["zones"][:, np.isinf(RADII)] = raw["zones"][:n, None] / period  # only the whole box holds them
    t["residual"] = (t["energy's change"] - t["body less leak"] + t["flux out"] - t["diffusion"] - t["viscosity"]
                     - t["re-initialisation"] - t["walls"] - t["zones"])
    out = {k: v * to_b / 1e3 for k, v in t.items()}
    out["noise KE [J]"] = mean(x[:, 5])
    return out


#: the annuli of :func:`by_particle`, in hull radii
ANNULI = (0.0, 1.1, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, math.inf)


def _rings_and_layers(raw, depth: float, dx: float):
    """Each kept particle's mean place [m], its annulus of :data:`ANNULI` and its layer (0:
    the top two spacings, 2: the bottom two, 1: between), and whether it has one."""
    pos = np.nanmean(raw["particle_pos"].astype(np.float64), axis=0)
    r, z = np.hypot(pos[:, 0], pos[:, 1]) / RADIUS, pos[:, 2]
    layer = np.where(z > depth - 2 * dx, 0, np.where(z < 2 * dx, 2, 1))
    return pos, np.digitize(r, ANNULI) - 1, layer, np.isfinite(r)


def drift(raw, depth: float, dx: float) -> dict:
    """The particles' mean velocity over the samples [m/s], radial (from the axis) and
    vertical, averaged by annulus (:data:`ANNULI`) and layer: ``{"radial", "vertical"}``,
    each (3, len(ANNULI) - 1)."""
    pos, ring, layer, ok = _rings_and_layers(raw, depth, dx)
    v = np.nanmean(raw["particle_vel"].astype(np.float64), axis=0)
    ur = (pos[:, 0] * v[:, 0] + pos[:, 1] * v[:, 1]) / np.maximum(np.hypot(pos[:, 0], pos[:, 1]), 1e-12)
    cell = lambda x, i, j: float(np.nanmean(x[ok & (ring == i) & (layer == j)])) if (
        ok & (ring == i) & (layer == j)).any() else math.nan
    return {name: np.array([[cell(x, i, j) for i in range(len(ANNULI) - 1)] for j in range(3)])
            for name, x in (("radial", ur), ("vertical", v[:, 2]))}


def by_particle(raw, depth: float, to_b: float, dx: float) -> dict:
    """The dissipative terms' powers as the wave's, particle by particle (``raw``: the
    samples of ``--raw``, whole periods): each the time covariance of its two factors (the
    mean of the product less the product of the means, as
    :mod:`wave_energy_budget`), so that the mean pressure times a slow settling's rate is
    left out; summed by the annulus of :data:`ANNULI` of each particle's mean place and by
    its mean depth (the top and bottom two spacings apart), as dampings [kN s/m] (the
    half box doubled). Also the settling parts left out, and the noise's kinetic energy
    [J] by annulus over the first and the last period."""
    P = {k[len("particle_"):]: raw[k].astype(np.float64) for k in raw.keys() if k.startswith("particle_")}
    m = np.nanmean(P["m"], axis=0)
    w = np.nanmean(P["m"] / P["rho"] ** 2, axis=0)
    cov = lambda a, b: np.nanmean(a * b, axis=0) - np.nanmean(a, axis=0) * np.nanmean(b, axis=0)
    terms = {"diffusion": w * cov(P["p"], P["D"]),
             "diffusion's settling": w * np.nanmean(P["p"], axis=0) * np.nanmean(P["D"], axis=0),
             "viscosity": np.nanmean(P["visc"], axis=0)}
    if "a_walls" in P:
        settle = (np.nanmean(P["vel"], axis=0) * np.nanmean(P["a_walls"], axis=0)).sum(axis=1)
        terms["walls"] = m * ((P["vel"] * P["a_walls"]).sum(axis=2).mean(axis=0) - settle)
        terms["walls' settling"] = m * settle
    _, ring, layer, ok = _rings_and_layers(raw, depth, dx)
    out = {}
    for name, x in terms.items():
        x = np.where(ok & np.isfinite(x), x, 0.0) * 2.0 * to_b / 1e3
        out[name] = np.array([[x[(ring == i) & (layer == j)].sum() for i in range(len(ANNULI) - 1)]
                              for j in range(3)])
    per = SAMPLES_A_PERIOD
    noise = P["noise"]
    out["noise KE [J]"] = np.array([[2.0 * np.nansum(noise[s][:, ring == i]) / per for i in range(len(ANNULI) - 1)]
                                    for s in (slice(0, per), slice(len(noise) - per, len(noise)))])
    return out


def report(raw, scene, title: str) -> str:
    """The budget, the flux by period, the by-particle terms and the drift of ``raw`` (the
    samples of ``--raw``) of ``scene``, as markdown."""
    m, d, dx = scene.bodies[0].motion, scene.domain, scene.fluid.dx
    to_b = 2.0 / (2.0 * math.pi / m.period * m.amplitude) ** 2
    b = budget(raw, m.period, to_b)
    lines = [title, "", f"the body's power into the water {to_b * raw['p_in'].mean() / 1e3:.2f} kN s/m as a damping "
             f"(B33 of the force's fit), its boundary's compression work {to_b * raw['leak'].mean() / 1e3:.2f}", "",
             "as dampings [kN s/m], the mean of the periods (the energy's change and the residual: "
             "of all but the first two too)", "", "| r / R | " + " | ".join(b) + " |", "|---" * (len(b) + 1) + "|"]
    last = ("energy's change", "residual") if len(b["residual"]) > 2 else ()
    for k, rk in enumerate(RADII):
        lines.append(f"| {rk:g} | " + " | ".join(f"{a[:, k].mean():.2f}" + (f" ({a[2:, k].mean():.2f})" if name in last
                                                                          else "") for name, a in b.items()) + " |")
    lines += ["", "flux out by period [kN s/m]: " + "; ".join(
        f"{rk:g} R: " + ", ".join(f"{x:.1f}" for x in b["flux out"][:, k]) for k, rk in enumerate(RADII[:-1]))]
    head = "| term, layer | " + " | ".join(f"{ANNULI[i]:g}-{ANNULI[i + 1]:g} R" for i in range(len(ANNULI) - 1))
    layers = ("top 2 dx", "between", "bottom 2 dx")
    lines += ["", "by particle, as the wave's (covariances) and the settling's parts [kN s/m; the noise: J]", "",
              head + " | sum |", "|---" * len(ANNULI) + "|---|"]
    for name, a in by_particle(raw, d.depth, to_b, dx).items():
        rows = ((f"{name}, first period", a[0]), (f"{name}, last period", a[1])) if a.shape[0] == 2 else (
            (f"{name}, {layers[j]}", a[j]) for j in range(3))
        lines += [f"| {label} | " + " | ".join(f"{x:.2f}" for x in row) + f" | {row.sum():.2f} |" for label, row in rows]
    lines += ["", "the particles' mean velocity over the samples [mm/s]", "", head + " |", "|---" * len(ANNULI) + "|"]
    for name, a in drift(raw, d.depth, dx).items():
        lines += [f"| {name}, {layers[j]} | " + " | ".join(f"{1e3 * x:.0f}" for x in a[j]) + " |" for j in range(3)]
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_scene_arguments(ap, hull="cylinder", draft=3.0, amplitude=0.6)
    ap.add_argument("--raw", help="keep the samples here (.npz); with --read, read them from here, not run")
    ap.add_argument("--read", action="store_true", help="report the samples kept in --raw (the same scene options)")
    args = ap.parse_args(argv)
    s = scene_for(args.hull, args.draft, args.r_over_dx, args.periods, False, args.amplitude, args.settings,
                  args.depth)
    title = (f"{args.hull}, draft {args.draft:g} m, depth {s.domain.depth:g} m, R/dx = {args.r_over_dx:g}, amplitude "
             f"{s.bodies[0].motion.amplitude:g} m, {' '.join(args.settings) + ', ' if args.settings else ''}"
             f"{args.periods} periods after the ramp")
    if args.read:
        if not args.raw:
            ap.error("--read needs --raw FILE.npz")
        print(report(np.load(args.raw), s, title))
        return
    m = s.bodies[0].motion
    audit = Audit(s.domain.depth, m.ramp * m.period, m.period, args.periods)
    run = powers(s, audit.sample, audit.on_built)
    raw = {"extra": np.array(run["extra"]), "mls": audit.mls, "zones": audit.zones, "ids": audit.ids,
           **{k: run[k] for k in ("t", "fz", "w", "p_in", "leak")},
           **{"particle_" + k: np.stack([x[k] for x in audit.particles]) for k in audit.particles[0]}}
    if args.raw:
        np.savez(args.raw, **raw)
    print(report(raw, s, f"{title}; {run['cpu_s']:.0f} CPU-s, {cpu_name()}"))


if __name__ == "__main__":
    main()
