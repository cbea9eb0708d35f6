"""Where a 2-D section's heave damping sits in SPH, against linear potential flow: the
scene of :mod:`radiation_2d` (a section forced in heave in still water), its force's first
harmonic in phase with the velocity split by bands of the hull, and the water's pressure
under the keel, each beside the boundary-element reference's on the same places.

- **By band of the hull**: the boundary particles within the kernel's reach (2 h) above
  the keel, within 2 h of the still waterline, and between (in the body's frame; a
  particle near both belongs to the keel's band). The reference's share of each band is
  its panels' pressure there (:func:`reference_by_band`); on the box's vertical sides
  potential flow puts no vertical force, so all its damping is on the keel's band.
- **The water under the keel**: the dynamic pressure (each particle's pressure less the
  still water's hydrostatic one at its height) averaged over rows a spacing high under
  the keel, across the middle half of the beam (``|x| < R / 2``), in the body's frame, its
  first harmonic per unit heave velocity against the reference's at the rows' centres
  (:func:`radiation_2d.section_field`). The velocity-phase part is what the keel's band
  integrates into B33; the acceleration-phase part, A33.

A run costs what :mod:`radiation_2d`'s does (about 90 s at R/dx = 8 on one core) and
takes the bodies' particle forces at every fluid step. Measured:
docs/validation/nearfield.md, "Where the box's excess sits: in the water's pressure under the keel".

    python benchmarks/radiation_2d_where.py [--hull box|circle|diamond] [--draft 1.0] [--r-over-dx 8]
        [--amplitude 0.025] [--periods 8] [--rows 8] [--map PNG] [--set KEY=VALUE ...]
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

try:  # imported as a module of benchmarks/ (the tests)
    from benchmarks.radiation_2d import DEPTH, HULLS, RADIUS, contour, scene_2d, section_field, section_solution
except ImportError:  # run as a script: benchmarks/radiation_2d.py is beside it on the path
    from radiation_2d import DEPTH, HULLS, RADIUS, contour, scene_2d, section_field, section_solution

BANDS = ("keel", "between", "waterline")


def band_of(z, keel: float, reach: float) -> np.ndarray:
    """The band (index into :data:`BANDS`) of each height ``z`` [m] in the body's frame
    (0 at the still waterline): ``keel`` within ``reach`` [m] above the keel's height
    ``keel`` [m] (< 0), else ``waterline`` within ``reach`` of 0, else ``between``."""
    z = np.asarray(z, float)
    return np.where(z < keel + reach, 0, np.where(z > -reach, 2, 1))


def reference_by_band(sol: dict, keel: float, reach: float, omega: float, rho: float = 1000.0) -> dict:
    """The reference's ``(A33, B33)`` [kg/m, kg/(m s)] on each band of :data:`BANDS`: the
    body panels' shares of :func:`radiation_2d.section_coefficients`' sums, the panels put
    in bands by their middles (:func:`band_of`)."""
    body = sol["kind"] == "body"
    f = sol["phi"][body] * sol["normal"][body, 1] * sol["length"][body]
    band = band_of(sol["mid"][body, 1], keel, reach)
    return {name: (rho * f[band == i].real.sum(), omega * rho * f[band == i].imag.sum())
            for i, name in enumerate(BANDS)}


def row_heights(keel: float, dx: float, rows: int) -> np.ndarray:
    """The centres [m] (body frame) of ``rows`` rows a spacing ``dx`` high under the keel,
    the first touching it."""
    return keel - (np.arange(rows) + 0.5) * dx


def reference_rows(sol: dict, heights, half_width: float, omega: float, rho: float = 1000.0,
                   points: int = 9) -> np.ndarray:
    """The reference's pressure per unit heave velocity at ``heights`` [m] (still-water
    frame), averaged over ``points`` points across ``|x| <= half_width`` [m]: rows ``(A,
    B)``, ``A`` the part in phase with the acceleration per unit acceleration [kg/m^2]
    (``rho Re phi``), ``B`` the part in phase with the velocity [Pa s/m] (``omega rho Im
    phi``), signed as a pressure pushing the keel up adds to A33 and B33."""
    X, Z = np.meshgrid(np.linspace(-half_width, half_width, points), heights)
    phi = section_field(sol, np.column_stack([X.ravel(), Z.ravel()])).reshape(X.shape).mean(axis=1)
    return np.column_stack([rho * phi.real, omega * rho * phi.imag])


def record(scene, keel: float, heights, half_width: float, grid=None):
    """Run ``scene`` (:func:`radiation_2d.scene_2d`, its keel ``keel`` [m] below the still
    waterline) to its end, reading at every fluid step: ``t`` [s]; ``forces``, the vertical force [N] on the body's particles of each band
    of :data:`BANDS` (body frame: heights from the mean of the body's particles, which is
    its centre on the still water; the bands' ``reach`` [m] is the fluid's kernel support
    2 h); ``rows``, the fluid's dynamic pressure [Pa] (its pressure less the still water's
    hydrostatic one at its height) averaged over each row under the keel (``heights`` [m]
    their centres, a spacing high, ``|x| < half_width``); with ``grid`` (cell edges ``(x,
    z)`` [m], the still water's frame) ``cells``, the dynamic pressure averaged over each
    cell, NaN where a cell holds no fluid. Returned as a dict of those names."""
    from cosim.validations import case_scene
    from fluid.particles import Kind

    level = DEPTH
    ts, forces, pressures, cells = [], [], [], []
    with case_scene.built(scene) as b:
        ps, sph = b.sph.ps, b.sph
        rho0, g = sph.config.rho0, scene.world.gravity
        dx, reach = sph.config.dx, 2.0 * sph.config.h
        edges = np.append(np.asarray(heights) + 0.5 * dx, heights[-1] - 0.5 * dx)

        def grab(info):
            F = sph.boundary_forces_now()
            body = ps.kind == Kind.BODY
            zc = ps.pos[body, -1].mean()
            band = band_of(ps.pos[body, -1] - zc, keel, reach)
            forces.append(np.bincount(band, weights=F[body, -1], minlength=len(BANDS)))
            fl = (ps.kind == Kind.FLUID) & (np.abs(ps.pos[:, 0]) < half_width)
            z = ps.pos[fl, -1]
            dyn = ps.p[fl] - rho0 * g * (level - z)
            row = np.searchsorted(-edges, -(z - zc)) - 1  # edges fall; row i between edges i and i + 1
            ok = (row >= 0) & (row < len(heights))
            n = np.bincount(row[ok], minlength=len(heights))
            s = np.bincount(row[ok], weights=dyn[ok], minlength=len(heights))
            pressures.append(np.where(n > 0, s / np.maximum(n, 1), np.nan))
            if grid is not None:
                fl = ps.kind == Kind.FLUID
                x, z = ps.pos[fl, 0], ps.pos[fl, -1]
                s = np.histogram2d(x, z, grid, weights=ps.p[fl] - rho0 * g * (level - z))[0]
                n = np.histogram2d(x, z, grid)[0]
                cells.append(np.where(n > 0, s / np.maximum(n, 1), np.nan).astype(np.float32))
            ts.append(info.t)

        b.coupler.run(scene.world.duration, callback=grab)
    out = {"t": np.array(ts), "forces": np.array(forces), "rows": np.array(pressures), "reach": reach}
    return out | ({"cells": np.array(cells)} if grid is not None else {})


def map_grid(dx: float) -> tuple:
    """Cell edges ``(x, z)`` [m] of :func:`map_fields`' map: cells two spacings square from
    the bed to the still water (``z`` from the bed, as the scene's), 3 R each side."""
    x = np.arange(-3.0 * RADIUS, 3.0 * RADIUS + 1e-9, 2.0 * dx)
    return x, np.arange(0.0, DEPTH + 1e-9, 2.0 * dx)


def map_fields(ts, cells, grid, sol, hull: str, draft: float, amplitude: float, omega: float,
               rho: float = 1000.0) -> tuple:
    """The water's dynamic pressure in phase with the heave velocity, per unit velocity
    [Pa s/m] (signed as it adds to B33 under the keel), on :func:`record`'s ``cells``
    (series at ``ts`` [s] of a heave ``amplitude`` [m]): ``(sph, ref, ok)``, SPH's and the
    reference's at the cells' centres (:func:`radiation_2d.section_field` of ``sol``), and
    the cells to show: not those the hull sweeps, nor those within 2 dx of the still water
    (where the surface crosses them), nor those that were ever empty."""
    from cosim.validations.wave_propagation import harmonics

    ex, ez = grid
    xc, zc = 0.5 * (ex[1:] + ex[:-1]), 0.5 * (ez[1:] + ez[:-1]) - DEPTH
    X, Z = np.meshgrid(xc, zc, indexing="ij")
    half = 0.5 * (ex[1] - ex[0])
    swept = (np.abs(X) < RADIUS + half) & (Z > keel_of(hull, draft) - amplitude - half)
    ok = ~swept & (Z < -2.0 * half) & ~np.isnan(cells).any(axis=0)
    c = harmonics(ts, np.nan_to_num(cells).reshape(len(ts), -1).astype(float), omega).reshape(X.shape)
    ref = np.full(X.shape, np.nan)
    ref[ok] = omega * rho * section_field(sol, np.column_stack([X[ok], Z[ok]])).imag
    return -c.real / (amplitude * omega), ref, ok


def map_figure(path: Path, fields: tuple, grid, hull: str, draft: float, amplitude: float) -> None:
    """:func:`map_fields`' ``fields`` drawn on ``grid``: SPH's, the reference's and their
    difference, the hull's outline over them; written to ``path`` (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ex, ez = grid
    sph, ref, ok = fields
    fig, axes = plt.subplots(3, 1, figsize=(7.5, 7.5), sharex=True)
    outline = np.array(contour(hull, draft))
    for ax, val, title, lim in ((axes[0], sph, "SPH", 300), (axes[1], ref, "reference (linear potential flow)", 300),
                                (axes[2], sph - ref, "SPH - reference", 100)):
        im = ax.pcolormesh(ex, ez - DEPTH, np.where(ok, val, np.nan).T, cmap="RdBu_r", vmin=-lim, vmax=lim)
        ax.plot(outline[:, 0], outline[:, 1], "k-", lw=1.0)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=9)
        ax.set_ylabel("z [m]")
        fig.colorbar(im, ax=ax, shrink=0.8, label="Pa s/m")
    axes[-1].set_xlabel("x [m]")
    fig.suptitle(f"{hull} drawing {draft:g} R, heave {amplitude * 1000:.1f} mm: pressure in phase with the velocity",
                 fontsize=10)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def keel_of(hull: str, draft: float) -> float:
    """The keel's height [m] below the still waterline (body frame): the box's draft, the
    circle's and the turned square's R."""
    return -(draft if hull == "box" else 1.0) * RADIUS


def main(argv=None):
    from cosim.validations.radiation import added_mass_damping

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--hull", choices=HULLS, default="box")
    ap.add_argument("--draft", type=float, default=1.0, help="the box's draft in radii")
    ap.add_argument("--r-over-dx", type=float, default=8.0)
    ap.add_argument("--amplitude", type=float, default=0.025, help="the heave amplitude in radii")
    ap.add_argument("--periods", type=int, default=8)
    ap.add_argument("--rows", type=int, default=8, help="rows of water under the keel (at most down to the bed)")
    ap.add_argument("--map", type=Path, metavar="PNG", help="also draw the water's pressure in phase with the "
                    "velocity round the hull, SPH against the reference (map_figure)")
    ap.add_argument("--set", dest="settings", action="append", default=[], metavar="KEY=VALUE",
                    help="a scene value (as cosim run --set), e.g. fluid.h_coef=2.5")
    a = ap.parse_args(argv)
    s = scene_2d(a.hull, a.draft, a.r_over_dx, a.amplitude, a.periods, a.settings)
    m = s.bodies[0].motion
    w = 2.0 * math.pi / m.period
    dx = RADIUS / a.r_over_dx
    keel = keel_of(a.hull, a.draft)
    half_width = 0.5 * RADIUS
    heights = row_heights(keel, dx, min(a.rows, int(round((DEPTH + keel) / dx))))  # rows down to the bed
    print(f"{a.hull}, draft {a.draft:g} R, R/dx {a.r_over_dx:g}, a = {a.amplitude:g} R "
          f"(R = {RADIUS} m, depth {DEPTH} m, T = {m.period:.4f} s) {' '.join(a.settings)}", flush=True)
    cpu = time.process_time()
    r = record(s, keel, heights, half_width, map_grid(dx) if a.map else None)
    ts, forces, pressures, reach = r["t"], r["forces"], r["rows"], r["reach"]
    fit = ts > (m.ramp + 2.0) * m.period - 1e-9
    print(f"{len(ts)} fluid steps, {time.process_time() - cpu:.0f} CPU s; bands {reach * 1000:.1f} mm high "
          "(the kernel's reach)")
    sol = section_solution(contour(a.hull, a.draft), DEPTH, w, g=s.world.gravity)
    ref_bands = reference_by_band(sol, keel, reach, w)
    ref_rows = reference_rows(sol, heights, half_width, w)
    print("\n| band | SPH B33 [kg/(m s)] | reference's | SPH - reference |\n|---|---|---|---|")
    total = [0.0, 0.0]
    for i, name in enumerate(BANDS):
        b_sph = added_mass_damping(ts[fit], forces[fit, i], m.amplitude, w, 0.0)[1]
        b_ref = ref_bands[name][1]
        total = [total[0] + b_sph, total[1] + b_ref]
        print(f"| {name} | {b_sph:.1f} | {b_ref:.1f} | {b_sph - b_ref:+.1f} |")
    print(f"| all | {total[0]:.1f} | {total[1]:.1f} | {total[0] - total[1]:+.1f} |")
    print("\nthe water under the keel (|x| < R/2), per unit heave velocity: velocity phase [Pa s/m], "
          "acceleration phase [kg/m^2]")
    print("| row centre below the keel [dx] | SPH, velocity phase | reference's | SPH / reference | "
          "SPH, acceleration phase | reference's |\n|---|---|---|---|---|---|")
    for j, z in enumerate(heights):
        A, B = added_mass_damping(ts[fit], pressures[fit, j], m.amplitude, w, 0.0)
        ra, rb = ref_rows[j]
        print(f"| {(keel - z) / dx:.1f} | {B:.1f} | {rb:.1f} | {B / rb:.2f} | {A:.1f} | {ra:.1f} |")
    if a.map:
        grid = map_grid(dx)
        fields = map_fields(ts[fit], r["cells"][fit], grid, sol, a.hull, a.draft, m.amplitude, w)
        map_figure(a.map, fields, grid, a.hull, a.draft, m.amplitude)
        print(f"\nmap: {a.map}")


if __name__ == "__main__":
    main()
