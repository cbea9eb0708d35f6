"""Accuracy and cost of two ways to build an elastic cantilever in MuJoCo.

Yang & Li 2020's plate (§3.3: 1.2 cm thick, 8 cm high, rho_s = 2500 kg/m^3,
E = 1 MPa, nu = 0, clamped at its foot; 1 m deep as in a 2-D scene), against the
clamped-free Timoshenko beam (kappa = 5/6; :func:`bodies.elastic.timoshenko_frequencies`,
tip load ``P L^3 / (3 E I) + P L / (kappa G A)``):

- chain:     :func:`bodies.elastic.elastic_beam`, N rigid links, a hinge (E I / l) and a
             shear slide (kappa G A / l) at each element's midpoint; RK4
- chain-EB:  the same without shear slides (a Rayleigh beam): what the shear term is worth
- flex2d:    MuJoCo's own deformable, ``<flexcomp type="grid" dim="2">`` with
             ``<elasticity young poisson thickness elastic2d="stretch">`` (linear triangles in
             plane stress), nx x nz cells across x thickness along z; Euler (MuJoCo 4.0 no
             longer integrates flex elasticity implicitly)
- flex3d:    ``dim="3"`` (tetrahedra), nx x 1 x nz cells, 1 m deep; Euler

Columns: degrees of freedom; the error of the first three bending frequencies (the
model linearised by finite differences of MuJoCo's own forces, :func:`linearise`) and of
the static tip deflection under a tip load; the largest stable step (2 sqrt 2 / omega_max
for RK4, 2 / omega_max for Euler); wall time per MuJoCo step and per simulated second
at ``--dt`` (the coupler's step, default 1e-4 s), from a free vibration, or at 0.9 of the
stable step where that is smaller (the flex: MuJoCo would have to sub-step it). The observed order of each candidate's frequency
error follows the table.

    python benchmarks/elastic_beam.py [--dt 1e-4] [--seconds 0.2]

Prints figures; asserts nothing.
"""

from __future__ import annotations

import argparse
import math
import platform
import sys
import time
from pathlib import Path

import mujoco
import numpy as np
from scipy.linalg import eigh

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bodies import builders  # noqa: E402
from bodies.elastic import elastic_beam, linearise  # noqa: E402

from machine import cpu_name  # noqa: E402  (benchmarks/machine.py, beside this script)

L, H, E, RHO, W = 0.08, 0.012, 1e6, 2500.0, 1.0


def flex_xml(nx: int, nz: int, dim: int, dt: float) -> str:
    """A flexcomp grid: x across the thickness, z along the plate; the z = 0 row pinned."""
    sx, sz = H / nx, L / nz
    if dim == 2:  # the grid's plane is its x-y: turned so that its y is the world's z
        pins = " ".join(str(ix * (nz + 1)) for ix in range(nx + 1))
        grid = f'count="{nx + 1} {nz + 1} 1" spacing="{sx} {sz} 1" euler="90 0 0"'
        extra = f'thickness="{W}" elastic2d="stretch"'
    else:
        pins = " ".join(str(ix * 2 * (nz + 1) + iy * (nz + 1)) for ix in range(nx + 1) for iy in range(2))
        grid = f'count="{nx + 1} 2 {nz + 1}" spacing="{sx} {W} {sz}"'
        extra = ""
    return (f'<mujoco><option gravity="0 0 0" timestep="{dt}" integrator="Euler"/><worldbody>'
            f'<flexcomp name="f" type="grid" {grid} pos="0 0 {L / 2}" dim="{dim}" radius="1e-4" '
            f'mass="{RHO * H * L * W}" dof="full"><elasticity young="{E}" poisson="0" damping="0" {extra}/>'
            f'<contact contype="0" conaffinity="0"/><edge equality="false"/><pin id="{pins}"/></flexcomp>'
            f'</worldbody></mujoco>')


def dof_axes(m) -> np.ndarray:
    """(nv,) 0/1/2: the world axis of each slide dof, 3 for hinges."""
    out = np.full(m.nv, 3)
    for j in range(m.njnt):
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE:
            out[m.jnt_dofadr[j]] = int(np.argmax(np.abs(m.jnt_axis[j])))
    return out


def analyse(m, is_flex: bool):
    """(first three bending frequencies [Hz], tip deflection [m] per N, omega_max [rad/s])."""
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    K, M = linearise(m, d)
    axes = dof_axes(m)
    if is_flex:  # the in-plane (x-z) dofs only: the 2-D flex has no stiffness out of its plane
        keep = axes != 1
        K, M = K[np.ix_(keep, keep)], M[np.ix_(keep, keep)]
        axes = axes[keep]
    w2, V = eigh(K, M)
    bend = w2 > 1e-6 * w2.max()
    if is_flex:  # bending: mostly x motion, and (3-D) the same at the front and back faces, y = -W/2, W/2
        bend &= (V[axes == 0] ** 2).sum(0) / (V**2).sum(0) > 0.5
        x_dofs = np.flatnonzero(axes == 0)
        xz = np.array([[d.xpos[m.jnt_bodyid[j]][0], d.xpos[m.jnt_bodyid[j]][2]]
                       for j in range(m.njnt) if m.jnt_dofadr[j] in set(np.flatnonzero(keep)[x_dofs])])
        y = np.array([d.xpos[m.jnt_bodyid[j]][1] for j in range(m.njnt)
                      if m.jnt_dofadr[j] in set(np.flatnonzero(keep)[x_dofs])])
        if np.ptp(y) > 1e-6:  # pair each back vertex with the front one at the same (x, z)
            front, back = np.flatnonzero(y < 0), np.flatnonzero(y > 0)
            order = [front[np.argmin(np.abs(xz[front] - xz[i]).sum(1))] for i in back]
            va, vb = V[x_dofs[back]], V[x_dofs[order]]
            sym = ((va + vb) ** 2).sum(0) / (2 * ((va**2).sum(0) + (vb**2).sum(0)))
            bend &= sym > 0.5
    f = np.sqrt(w2[bend][:3]) / (2 * math.pi)
    if is_flex:  # 1 N along x shared by the top row of vertices; tip = their mean x displacement
        z = np.array([d.xpos[b][2] for b in range(m.nbody)])
        top = [b for b in range(1, m.nbody) if abs(z[b] - L) < 1e-9]
        F = np.zeros(m.nv)
        rows = []
        for b in top:
            for j in range(m.body_jntadr[b], m.body_jntadr[b] + m.body_jntnum[b]):
                if dof_axes(m)[m.jnt_dofadr[j]] == 0:
                    F[m.jnt_dofadr[j]] = 1.0 / len(top)
                    rows.append(m.jnt_dofadr[j])
        full_keep = dof_axes(m) != 1
        u = np.zeros(m.nv)
        u[full_keep] = np.linalg.solve(K, F[full_keep])
        tip = u[rows].mean()
    else:
        jp = np.zeros((3, m.nv))
        mujoco.mj_jacSite(m, d, jp, None, mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "p_tip"))
        tip = jp[0] @ np.linalg.solve(K, jp[0])
    return f, tip, math.sqrt(w2.max())


def timing(m, seconds: float, is_flex: bool):
    """(wall s per step, wall s per simulated second), or None when it goes unstable."""
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    axes = dof_axes(m)
    if is_flex:  # a bending-like start: x velocity growing with height
        for b in range(1, m.nbody):
            for j in range(m.body_jntadr[b], m.body_jntadr[b] + m.body_jntnum[b]):
                if axes[m.jnt_dofadr[j]] == 0:
                    d.qvel[m.jnt_dofadr[j]] = 0.05 * (d.xpos[b][2] / L) ** 2
    else:
        d.qvel[axes == 3] = 0.05 / L
    n = max(1, int(round(seconds / m.opt.timestep)))
    t0 = time.perf_counter()
    for _ in range(n):
        mujoco.mj_step(m, d)
    wall = time.perf_counter() - t0
    if not np.isfinite(d.qvel).all() or np.abs(d.qvel).max() > 1e3:
        return None
    return wall / n, wall / (n * m.opt.timestep)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dt", type=float, default=1e-4, help="coupling step [s] for the timings")
    ap.add_argument("--seconds", type=float, default=0.2, help="simulated time per timing run [s]")
    args = ap.parse_args(argv)

    ref_beam = elastic_beam("p", L, H, E=E, rho=RHO, width=W)
    f_ref = ref_beam.natural_frequencies()
    d_ref = ref_beam.tip_deflection_point(1.0)
    print(f"# elastic cantilever: Yang & Li 2020 plate L = {L} m, h = {H} m, W = {W} m, E = {E:g} Pa, "
          f"rho = {RHO:g} kg/m^3, nu = 0")
    print(f"# Timoshenko: f = {f_ref[0]:.4f}, {f_ref[1]:.3f}, {f_ref[2]:.3f} Hz; tip load {d_ref * 1e3:.4f} mm/N "
          f"(Euler-Bernoulli: {', '.join(f'{x:.3f}' for x in ref_beam.natural_frequencies(theory='euler-bernoulli'))}"
          f" Hz, {ref_beam.tip_deflection_point(1.0, 'euler-bernoulli') * 1e3:.4f} mm/N)")
    print(f"# CPU: {cpu_name()}, {platform.python_implementation()} {platform.python_version()}, "
          f"mujoco {mujoco.__version__}; timings at dt = {args.dt:g} s over {args.seconds:g} s simulated")
    head = (f"{'model':<9}{'size':>8}{'dofs':>6}{'f1 err%':>9}{'f2 err%':>9}{'f3 err%':>9}{'tip err%':>9}"
            f"{'dt_stable':>11}{'dt used':>10}{'us/step':>9}{'s/sim s':>9}")
    print(head)
    cases = [("chain", n, True) for n in (4, 8, 16, 32)] + [("chain-EB", 16, False)]
    cases += [("flex2d", s, None) for s in ((2, 16), (4, 32), (6, 48))]
    cases += [("flex3d", s, None) for s in ((2, 16), (4, 32))]
    errs = {}
    for kind, size, shear in cases:
        is_flex = kind.startswith("flex")
        if is_flex:
            m = mujoco.MjModel.from_xml_string(flex_xml(size[0], size[1], 2 if kind == "flex2d" else 3, args.dt))
            label = f"{size[0]}x{size[1]}"
        else:
            beam = elastic_beam("p", L, H, E=E, rho=RHO, width=W, n_elements=size, shear=shear)
            m = mujoco.MjModel.from_xml_string(builders.scene(beam.xml, gravity=0.0, timestep=args.dt,
                                                              integrator="RK4"))
            label = f"N={size}"
        f, tip, w_max = analyse(m, is_flex)
        e = (f / f_ref[: len(f)] - 1) * 100
        errs.setdefault(kind, []).append(np.abs(e))
        dt_stable = (2.0 if is_flex else 2.0 * math.sqrt(2.0)) / w_max  # Euler; RK4 undamped
        m.opt.timestep = dt = min(args.dt, 0.9 * dt_stable)  # the flex runs below --dt where it must
        t = timing(m, args.seconds, is_flex)
        cost = f"{dt:>10.2e}{t[0] * 1e6:>9.1f}{t[1]:>9.2f}" if t else f"{dt:>10.2e}{'unstable':>18}"
        print(f"{kind:<9}{label:>8}{m.nv:>6}" + "".join(f"{x:>+9.2f}" for x in e)
              + f"{(tip / d_ref - 1) * 100:>+9.2f}{dt_stable:>11.2e}" + cost)
    print("# observed order of the frequency error per refinement (log2 of the error ratio; the flex grids")
    print("# refine by 2 then 1.5)")
    for kind in ("chain", "flex2d", "flex3d"):
        e = np.array(errs[kind])
        ratios = [2.0] * (len(e) - 1) if kind != "flex2d" else [2.0, 1.5]
        orders = [np.log(e[i] / e[i + 1]) / np.log(r) for i, r in enumerate(ratios)]
        print(f"#  {kind:<8}" + "  ".join("[" + ", ".join(f"{x:.2f}" for x in o) + "]" for o in orders))


if __name__ == "__main__":
    main()
