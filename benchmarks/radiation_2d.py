"""nearfield-radiation's problem in 2-D: a section forced in heave in still water in a 2-D
SPH near field, its added mass and damping per metre from the force's first harmonic
against a 2-D linear potential-flow reference (:func:`section_coefficients`, below), and
the damping its radiated wave carries (the energy flux of the outgoing wave at gauges on
both sides). The sections: a box (a rectangle's sharp corners, as the case's cylinder has
at its rim), a circle centred on the still water (smooth), a square turned 45 degrees
("diamond": a corner at the keel, faces at 45 degrees to the lattice). The case at 1/30
scale: half-beam R = 0.1 m, water 2 R deep, T = 3.54 s / sqrt(30) (k R = 1), the box
drawing R (the deep cylinder's draft over its radius) or R / 2 (the case's). A run costs
20 s at R/dx = 4 to 10 min at R/dx = 16 on one core: the cheap place to study the sharp
edge's excess (docs/validation/nearfield.md, "The sharp edge's excess in 2-D").

    python benchmarks/radiation_2d.py [--hull box|circle|diamond] [--draft 1.0] [--r-over-dx 4 8 16]
        [--amplitude 0.2 [0.05 ...]] [--periods 8] [--set KEY=VALUE ...] [--out OUT] [--reference-only]
    python benchmarks/radiation_2d.py --figure PNG [--r-over-dx 8] [--amplitude 0.2]
    python benchmarks/radiation_2d.py --slab 6 --r-over-dx 4 [--amplitude 0.2]

``--figure``: the water's vorticity round the box and the circle, phase-averaged
(:func:`vorticity_figure`; docs/validation/figures/radiation-2d_vorticity.png).
``--slab ROWS``: the box in 3-D numerics, a slab ROWS spacings wide between side walls
(no artificial viscosity at them; the laminar one holds them no-slip, as every wall).

``--draft`` and ``--amplitude`` are in radii (the box's draft; the heave amplitude, the
case's 0.1, KC = pi a / R). The force is fitted over the periods after the ramp and the
first two; the gauges stand 3.2-5.2 R from the axis, inside the zones (a wavelength
wide), where the first evanescent mode is down to 8 % or less. An excess of the force's
B33 over the reference is also given as the drag coefficient that would do its work
(Lorentz's equivalent linearisation, ``(8 / 3 pi) (rho / 2) Cd 2R omega a``): a drag's
equivalent damping grows in proportion to the amplitude, an error linear in the motion
does not: with several ``--amplitude`` values the excess at each spacing is split by least
squares into the two (``excess = L + D a``, :func:`cosim.validations.radiation.excess_split`).
"""

from __future__ import annotations

import argparse
import math
import tempfile
import time
from pathlib import Path

import numpy as np

#: the section's half-beam [m], the water's depth [m], the period [s]: the case at 1/30
RADIUS, DEPTH, PERIOD = 0.1, 0.2, 3.54 / math.sqrt(30.0)
#: the box's half-length [m] and its zones' width [m] (a wavelength at k R = 1)
HALF_LENGTH, ZONE = 1.2, 0.63
#: the gauges' distances from the axis [m], on each side
GAUGES = (0.32, 0.37, 0.42, 0.47, 0.52)
#: the case's laminar viscosity (0.005 m^2/s at R = 3 m) at this scale (Froude: L^1.5)
NU = 0.005 * (RADIUS / 3.0) ** 1.5
HULLS = ("box", "circle", "diamond")
_GAUSS = np.polynomial.legendre.leggauss(16)


def contour(hull: str, draft: float = 1.0, radius: float = RADIUS) -> list:
    """The wetted section of ``hull`` as points (x, z) [m] from the still water's line at
    x = R round under to x = -R (z up, 0 on the still water); ``draft`` in radii (the box's
    only: the circle and the turned square draw R)."""
    if hull == "box":
        d = draft * radius
        return [(radius, 0.0), (radius, -d), (-radius, -d), (-radius, 0.0)]
    if hull == "circle":
        th = np.linspace(0.0, math.pi, 121)
        return [(radius * math.cos(t), -radius * math.sin(t)) for t in th]
    if hull == "diamond":
        return [(radius, 0.0), (0.0, -radius), (-radius, 0.0)]
    raise ValueError(f"hull: give one of {HULLS}, not {hull!r}")


def _panels(points, size: float) -> list:
    """Straight panels along the polyline ``points``, none longer than ``size`` [m]."""
    out = []
    for p, q in zip(points[:-1], points[1:]):
        n = max(1, math.ceil(math.dist(p, q) / size))
        t = np.linspace(0.0, 1.0, n + 1)[:, None]
        seg = (1.0 - t) * np.asarray(p, float) + t * np.asarray(q, float)
        out += [(seg[i], seg[i + 1]) for i in range(n)]
    return out


def section_coefficients(section, depth: float, omega: float, *, g: float = 9.81, rho: float = 1000.0,
                         half_length: float = HALF_LENGTH, panel: float = RADIUS / 40) -> dict:
    """Heave added mass ``A33`` [kg/m] and damping ``B33`` [kg/(m s)] of the 2-D section
    ``section`` (:func:`contour`) floating in water ``depth`` [m] deep, heaving at
    ``omega`` [rad/s], by linear potential flow (:func:`section_solution`). ``B33_far``:
    the same damping from the energy flux of the wave at the vertical boundaries (``rho g
    |eta|^2 c_g`` a side), a check (it converges to ``B33`` with the panels, 2.4 % under
    it at R / 40). ``panels``: their number."""
    sol = section_solution(section, depth, omega, g=g, half_length=half_length, panel=panel)
    body = sol["kind"] == "body"
    f = (sol["phi"][body] * sol["normal"][body, 1] * sol["length"][body]).sum()  # force / (i omega rho)
    top = np.flatnonzero(sol["kind"] == "open")[0]
    eta = omega * abs(sol["phi"][top]) / g
    return {"A33": rho * f.real, "B33": omega * rho * f.imag,
            "B33_far": 2.0 * rho * g * eta**2 * float(sol["group_velocity"]), "panels": len(sol["kind"])}


def section_solution(section, depth: float, omega: float, *, g: float = 9.81, half_length: float = HALF_LENGTH,
                     panel: float = RADIUS / 40) -> dict:
    """The linear radiation problem of the 2-D section ``section`` (:func:`contour`) heaving
    at unit velocity ``Re(e^(-i omega t))`` [m/s] in water ``depth`` [m] deep, solved by
    Green's second identity with the Rankine kernel ln(r) / 2 pi over constant panels
    (Brebbia & Dominguez 1992, ch. 3) on the body, the free surface (``dphi/dn = omega^2
    phi / g``), the flat bed and two vertical boundaries ``half_length`` [m] from the axis,
    where the outgoing wave's condition ``dphi/dn = i k phi`` holds (Sommerfeld; exact for
    the propagating mode, the evanescent ones decayed there, e^-(k1 x)). Panels no longer
    than ``panel`` [m]; the bed's twice that. Returns the panels (``p``, ``q`` their ends,
    ``mid``, ``length``, ``normal`` out of the water, ``kind``: body, surface, bed, open),
    the potential ``phi`` [m^2/s] and its normal derivative ``dphi_dn`` on them, the
    wavenumber ``k`` and ``group_velocity``; :func:`section_field` evaluates the potential
    inside the water."""
    from fluid.waves import group_velocity, wavenumbers

    k = float(wavenumbers(omega, depth, g))
    xr, xl = section[0][0], section[-1][0]
    X = half_length
    # the fluid's boundary walked once round (its outward normal on the left of the walk)
    parts = [([(-X, 0.0), (xl, 0.0)], "surface", panel), (section[::-1], "body", panel),
             ([(xr, 0.0), (X, 0.0)], "surface", panel), ([(X, 0.0), (X, -depth)], "open", panel),
             ([(X, -depth), (-X, -depth)], "bed", 2.0 * panel), ([(-X, -depth), (-X, 0.0)], "open", panel)]
    ends, kind = [], []
    for pts, name, size in parts:
        ps = _panels(pts, size)
        ends += ps
        kind += [name] * len(ps)
    p = np.array([e[0] for e in ends])
    q = np.array([e[1] for e in ends])
    kind = np.array(kind)
    mid, d = 0.5 * (p + q), q - p
    length = np.hypot(d[:, 0], d[:, 1])
    normal = np.stack([-d[:, 1], d[:, 0]], 1) / length[:, None]
    n = len(length)
    G, H = np.empty((n, n)), np.empty((n, n))
    for j in range(n):
        G[:, j], H[:, j] = _influence(mid, p[j], q[j], normal[j])
        G[j, j] = length[j] * (math.log(0.5 * length[j]) - 1.0) / (2.0 * math.pi)  # ln r over its own panel
        H[j, j] = 0.0  # a straight panel sees itself edge-on
    # (1/2) phi_i = sum_j H_ij phi_j - G_ij dphi/dn_j, dphi/dn given on the body and the bed,
    # proportional to phi on the surface and the open boundaries
    lhs = H.astype(complex) - 0.5 * np.eye(n)
    surface, open_, body = kind == "surface", kind == "open", kind == "body"
    lhs[:, surface] -= G[:, surface] * (omega**2 / g)
    lhs[:, open_] -= G[:, open_] * (1j * k)
    phi = np.linalg.solve(lhs, G[:, body] @ normal[body, 1])  # the body's unit heave velocity
    dphi_dn = np.zeros(n, complex)
    dphi_dn[body] = normal[body, 1]
    dphi_dn[surface] = omega**2 / g * phi[surface]
    dphi_dn[open_] = 1j * k * phi[open_]
    return {"p": p, "q": q, "mid": mid, "length": length, "normal": normal, "kind": kind, "phi": phi,
            "dphi_dn": dphi_dn, "k": k, "group_velocity": float(group_velocity(k, depth, g))}


def section_field(sol: dict, points) -> np.ndarray:
    """The potential [m^2/s] of :func:`section_solution`'s ``sol`` at ``points`` (M, 2) [m]
    inside the water, by Green's representation ``phi(x) = sum_j H_j(x) phi_j - G_j(x)
    dphi/dn_j`` (the identity :func:`section_solution` solves, with 1 for its 1/2 off the
    boundary); 16 Gauss points a panel, so a point nearer a panel than its length reads
    that panel's quadrature error."""
    pts = np.atleast_2d(np.asarray(points, float))
    out = np.zeros(len(pts), complex)
    for a, b, normal, phi, dn in zip(sol["p"], sol["q"], sol["normal"], sol["phi"], sol["dphi_dn"]):
        G, H = _influence(pts, a, b, normal)
        out += H * phi - G * dn
    return out


def _influence(points, a, b, normal) -> tuple:
    """``(G, H)`` at ``points`` (M, 2) [m] of the straight panel from ``a`` to ``b`` (its
    unit ``normal``): the integrals over it of the Rankine kernel ``ln(r) / 2 pi`` and of
    its derivative along the normal at the panel, by 16-point Gauss quadrature."""
    xg, wg = _GAUSS
    r = points[:, None, :] - (a + np.outer(0.5 * (xg + 1.0), b - a))[None, :, :]
    r2 = (r**2).sum(-1)
    half = 0.5 * math.dist(a, b) / (2.0 * math.pi)
    return (0.5 * np.log(r2) * wg).sum(1) * half, (-(r @ normal) / r2 * wg).sum(1) * half


def scene_2d(hull: str, draft: float, r_over_dx: float, amplitude: float, periods: int, settings=(),
             slab: int = 0):
    """The 2-D scene: ``hull`` (``draft`` in radii: the box's) centred on the still water
    at x = 0, forced in heave through ``amplitude`` radii at :data:`PERIOD` (a period's
    ramp), the ramp and ``periods`` periods long, 40 samples a period; the case's fluid at
    this scale (no artificial viscosity, :data:`NU`), dx = R / ``r_over_dx``; the near
    field's box :data:`HALF_LENGTH` each side with zones :data:`ZONE` wide; ``settings``
    ("KEY=VALUE", as ``cosim run --set``) last. ``slab`` > 0: the same section in 3-D
    numerics, a slab ``slab`` spacings wide between side walls (no side zones), the
    box spanning it (boxes only), the gauges across its middle."""
    from cosim.scene.toml_io import from_dict

    r = RADIUS
    body = {"name": "body", "density": 1000.0, "pos": [0.0, DEPTH],
            "motion": {"kind": "harmonic", "dof": "heave", "amplitude": amplitude * r, "period": PERIOD, "ramp": 1.0}}
    if hull == "box":
        body.update(shape="box", size=[2.0 * r, 2.0 * draft * r])
    elif hull == "circle":
        body.update(shape="cylinder", radius=r)
    elif hull == "diamond":
        body.update(shape="box", size=[math.sqrt(2.0) * r] * 2, euler=[0.0, 45.0, 0.0])
    else:
        raise ValueError(f"hull: give one of {HULLS}, not {hull!r}")
    d = {"name": f"radiation-2d-{hull}",
         "world": {"dim": 2, "duration": (1 + periods) * PERIOD, "sample_every": PERIOD / 40, "snapshot_every": 0.0},
         "fluid": {"model": "sph", "dx": r / r_over_dx, "alpha": 0.0, "nu": NU},
         "domain": {"kind": "nearfield", "depth": DEPTH, "x0": -HALF_LENGTH, "x1": HALF_LENGTH, "zone": ZONE,
                    "height": 4.0 * r / 1.5},
         "waves": {"kind": "still", "period": PERIOD, "depth": DEPTH},
         "bodies": [body],
         "probes": {"gauges": [-x for x in GAUGES] + list(GAUGES), "motion": ["body"], "tensions": False}}
    if slab:
        if hull != "box":
            raise ValueError(f"slab: a box only spans the slab, not a {hull}")
        width = slab * r / r_over_dx
        d["world"]["dim"] = 3
        d["domain"].update(width=width, side_zones=False, symmetry=False, sides="walls")
        body.update(size=[2.0 * r, width, 2.0 * draft * r], pos=[0.0, 0.5 * width, DEPTH])
        d["probes"]["gauges"] = [[x, 0.5 * width] for x in d["probes"]["gauges"]]
    return from_dict(d).with_values(list(settings))


def run_name(hull: str, draft: float, r_over_dx: float, amplitude: float, periods: int, slab: int = 0,
             settings=()) -> str:
    """The folder name of one run under ``--out``: every argument of :func:`scene_2d` in it,
    so that two variants kept in one OUT do not meet (the runner refuses a folder that
    holds another scene's run)."""
    name = f"{hull}-d{draft:g}-r{r_over_dx:g}-a{amplitude:g}-p{periods}" + (f"-slab{slab}" if slab else "")
    return name + "".join(f"-{s.replace('/', '_')}" for s in settings)


def figures(res, scene, reference: dict) -> dict:
    """The run's A33 and B33 per metre (a slab's force over its width; whole, and B33 by
    period) from the force's first harmonic after the ramp and two periods, the damping
    its outgoing waves carry, each side's reflection, and the excess of B33 over
    ``reference`` as a drag coefficient."""
    from cosim.validations.radiation import added_mass_damping, damping_by_period
    from cosim.validations.wave_propagation import harmonics, separate
    from fluid.waves import group_velocity, wavenumbers

    m = scene.bodies[0].motion
    g, rho = scene.world.gravity, scene.fluid.rho0
    w = 2.0 * math.pi / m.period
    k = float(wavenumbers(w, DEPTH, g))
    fit = res.t > (m.ramp + 2.0) * m.period - 1e-9
    ts = res.t[fit]
    stiffness = rho * g * 2.0 * RADIUS
    fz = res["body.fluid_Fz"][fit] / (scene.domain.width if scene.world.dim == 3 else 1.0)  # per metre
    a33, b33 = added_mass_damping(ts, fz, m.amplitude, w, stiffness)
    per = damping_by_period(ts, fz, m.amplitude, w, stiffness, m.period)
    z = harmonics(ts, np.column_stack([res[f"gauge{i + 1}.eta"][fit] for i in range(2 * len(GAUGES))]), w)
    sides = [separate(np.asarray(GAUGES), z[sl], k, "plane") for sl in (slice(len(GAUGES)), slice(len(GAUGES), None))]
    b_wave = sum(rho * g * abs(out)**2 for out, _ in sides) * float(group_velocity(k, DEPTH, g)) / (w * m.amplitude)**2
    drag = drag_damping(m.amplitude, rho, w)
    return {"A33": a33, "B33": b33, "B33_per_period": per, "B33_wave": b_wave,
            "reflection": max(abs(back) / abs(out) for out, back in sides),
            "Cd_of_excess": (b33 - reference["B33"]) / drag}


def drag_damping(amplitude: float, rho: float = 1000.0, omega: float = 2.0 * math.pi / PERIOD) -> float:
    """The damping [kg/(m s)] equivalent to a drag of Cd = 1 on the beam 2R at a heave
    ``amplitude`` [m] at ``omega`` [rad/s] (default: :data:`PERIOD`'s), by Lorentz's
    linearisation: ``(8 / 3 pi) (rho / 2) 2R omega a``; an excess over it is the drag
    coefficient that would do the excess's work."""
    return (8.0 / (3.0 * math.pi)) * 0.5 * rho * 2.0 * RADIUS * omega * amplitude


def vorticity_figure(path: Path, r_over_dx: float = 8.0, amplitude: float = 0.2, draft: float = 1.0,
                     periods: tuple = (2, 3, 4, 5)) -> None:
    """The water's vorticity round the box and the circle (:func:`scene_2d`) at the top of
    the stroke and at the fastest downstroke, averaged over the same phase of ``periods``
    (counted after the ramp; the particles' noise averages out, the shed vortices stay):
    the particles' velocities averaged in cells a spacing wide, curled by central
    differences. Written to ``path`` (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from cosim.validations import case_scene
    from fluid.particles import Kind

    phases = (0.25, 0.5)  # of the period: the top (at rest), the fastest downstroke
    fig, axes = plt.subplots(2, 2, figsize=(10, 6.2), sharex=True, sharey=True, constrained_layout=True)
    dx = RADIUS / r_over_dx
    edges_x = np.arange(-2.0 * RADIUS, 2.0 * RADIUS + 1e-9, dx)
    edges_z = np.arange(0.0, DEPTH + 0.5 * RADIUS + 1e-9, dx)
    for row, hull in enumerate(("box", "circle")):
        s = scene_2d(hull, draft, r_over_dx, amplitude, max(periods) + 1)
        m = s.bodies[0].motion
        left = sorted(((m.ramp + n + f) * m.period, f) for n in periods for f in phases)  # (time, phase)
        end = left[-1][0]
        sums = {f: np.zeros((3, len(edges_x) - 1, len(edges_z) - 1)) for f in phases}
        with case_scene.built(s) as b:
            ps = b.fluid.fluid.ps

            def grab(info):
                if left and info.t >= left[0][0] - 1e-9:
                    f = left.pop(0)[1]
                    fl = ps.kind == Kind.FLUID
                    x, z = ps.pos[fl, 0], ps.pos[fl, -1]
                    for k, wts in enumerate((None, ps.vel[fl, 0], ps.vel[fl, -1])):
                        sums[f][k] += np.histogram2d(x, z, [edges_x, edges_z], weights=wts)[0]

            b.coupler.run(end + 1e-3 * m.period, callback=grab)
        scale = 2.0 * 2.0 * math.pi / m.period
        for col, f in enumerate(phases):
            count, u, w = sums[f]
            with np.errstate(invalid="ignore"):
                u, w = u / count, w / count
            curl = np.gradient(u, dx, axis=1) - np.gradient(w, dx, axis=0)  # du/dz - dw/dx
            ax = axes[row, col]
            im = ax.pcolormesh(edges_x, edges_z, np.nan_to_num(curl).T, cmap="RdBu_r", vmin=-scale, vmax=scale)
            zc = DEPTH + m.amplitude * math.sin(2.0 * math.pi * f)
            if hull == "box":
                h = draft * RADIUS
                c = np.array([(RADIUS, h), (RADIUS, -h), (-RADIUS, -h), (-RADIUS, h), (RADIUS, h)])
            else:
                th = np.linspace(0.0, 2.0 * math.pi, 181)
                c = RADIUS * np.column_stack([np.cos(th), np.sin(th)])
            ax.plot(c[:, 0], c[:, 1] + zc, "k-", lw=1.2)
            ax.axhline(DEPTH, color="0.5", lw=0.6, ls=":")
            ax.set_aspect("equal")
            ax.set_ylim(0.0, DEPTH + 0.5 * RADIUS)
            ax.set_title(f"{hull}: {'top of the stroke' if col == 0 else 'fastest downstroke'}", fontsize=9)
    fig.colorbar(im, ax=axes, label="vorticity [1/s]", shrink=0.8)
    for ax in axes[-1]:
        ax.set_xlabel("x [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel("z [m]")
    fig.suptitle(f"heave {amplitude:g} R, R/dx = {r_over_dx:g}: the water's vorticity, averaged over the same "
                 f"phase of periods {periods[0]}-{periods[-1]} after the ramp", fontsize=10)
    fig.savefig(path, dpi=110)


def print_split(amplitudes, excess: dict, reference_b33: float) -> None:
    """The excess of B33 over the reference at each R/dx (``excess``: R/dx to the excess at
    each of ``amplitudes`` [radii]) split as ``L + D a`` (:func:`excess_split`), ``D``
    given as the beam's drag coefficient (:func:`drag_damping`, in the scene's water of
    1000 kg/m^3)."""
    from cosim.validations.radiation import excess_split

    def pm(v, digits: int) -> str:
        return f" +- {v:.{digits}f}" if v is not None else ""

    per_cd = drag_damping(RADIUS)  # the amplitudes are in radii
    print("\nthe excess split as L + D a (least squares over the amplitudes; standard errors from the residuals)")
    print("| R/dx | L [kg/(m s)] | L / reference | D a at a = 0.1 R | D as the beam's Cd |")
    print("|---|---|---|---|---|")
    for rdx, e in excess.items():
        f = excess_split(amplitudes, e)
        cd_se = None if f["D_se"] is None else f["D_se"] / per_cd
        print(f"| {rdx:g} | {f['L']:.1f}{pm(f['L_se'], 1)} | {f['L'] / reference_b33:+.0%} | {0.1 * f['D']:.1f} | "
              f"{f['D'] / per_cd:.2f}{pm(cd_se, 2)} |")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--hull", choices=HULLS, default="box")
    ap.add_argument("--draft", type=float, default=1.0, help="the box's draft in radii")
    ap.add_argument("--r-over-dx", type=float, nargs="+", default=[4.0, 8.0])
    ap.add_argument("--amplitude", type=float, nargs="+", default=[0.2],
                    help="the heave amplitude in radii (the case's: 0.1); with several, the excess split as L + D a")
    ap.add_argument("--periods", type=int, default=8)
    ap.add_argument("--set", dest="settings", action="append", default=[], metavar="KEY=VALUE",
                    help="a scene value (as cosim run --set), e.g. fluid.nu=0")
    ap.add_argument("--out", type=Path, help="keep each run in OUT/<hull>-... (default: a temporary folder)")
    ap.add_argument("--reference-only", action="store_true", help="print the boundary-element reference only")
    ap.add_argument("--slab", type=int, default=0, metavar="ROWS",
                    help="run the box as a 3-D slab ROWS spacings wide between side walls")
    ap.add_argument("--figure", type=Path, metavar="PNG",
                    help="draw the vorticity round the box and the circle at the first --r-over-dx instead")
    a = ap.parse_args(argv)
    if a.figure:
        vorticity_figure(a.figure, a.r_over_dx[0], a.amplitude[0], a.draft)
        return
    w = 2.0 * math.pi / PERIOD
    ref = section_coefficients(contour(a.hull, a.draft), DEPTH, w)
    print(f"{a.hull}, draft {a.draft:g} R (R = {RADIUS} m, depth {DEPTH} m, T = {PERIOD:.4f} s) "
          f"{' '.join(a.settings)}")
    print(f"reference ({ref['panels']} panels): A33 {ref['A33']:.2f} kg/m, B33 {ref['B33']:.2f} kg/(m s) "
          f"(far field {ref['B33_far']:.2f})")
    if a.reference_only:
        return
    print("| a / R (KC) | R/dx | particles | steps | CPU s | A33 [kg/m] (ref) | B33 [kg/(m s)] (ref) | "
          "B33 by period | the wave's B33 | reflection | excess as Cd |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    excess = {rdx: [] for rdx in a.r_over_dx}
    for amp in a.amplitude:
        for rdx in a.r_over_dx:
            s = scene_2d(a.hull, a.draft, rdx, amp, a.periods, a.settings, a.slab)
            cpu = time.process_time()
            with tempfile.TemporaryDirectory(prefix="radiation-2d-") as tmp:
                out = (a.out or Path(tmp)) / run_name(a.hull, a.draft, rdx, amp, a.periods, a.slab, a.settings)
                res = s.run(out, progress=False)
            cpu = time.process_time() - cpu
            f = figures(res, s, ref)
            excess[rdx].append(f["B33"] - ref["B33"])
            per = ", ".join(f"{x:.0f}" for x in f["B33_per_period"])
            print(f"| {amp:g} ({math.pi * amp:.3f}) | {rdx:g} | {res.summary['particles']} | {res.summary['steps']} | "
                  f"{cpu:.0f} | {f['A33']:.2f} ({ref['A33']:.2f}) | {f['B33']:.1f} ({ref['B33']:.1f}), "
                  f"{f['B33'] / ref['B33'] - 1:+.0%} | {per} | {f['B33_wave']:.1f} | {f['reflection']:.3f} | "
                  f"{f['Cd_of_excess']:.2f} |", flush=True)
    if len(set(a.amplitude)) > 1:
        print_split(a.amplitude, excess, ref["B33"])


if __name__ == "__main__":
    main()
