"""The plots of a scene's run (PNG), drawn for an engineer to read without the code.

- ``GROUP.png`` per probe group (:mod:`cosim.scene.probes`): one panel per quantity, its
  name and unit on the axis (``fluid force Fx [N]``, not the column's ``fluid_Fx``), one
  curve per entity with its name in the legend (a gauge's position with it); a group of
  codes (a line's state) on a categorical axis with the codes' names, as steps;
- ``particles_tT.png`` at each ``world.plot_at``: the particles (3-D: seen from the side,
  x-z) coloured by speed or pressure, walls grey, the paddle orange, the bodies dark with
  their names, the mooring lines as they hang now (the catenary's shape, MoorDyn's nodes,
  the SPH cable's particles) from their anchors, and the wave gauges.
"""

from __future__ import annotations

import numpy as np

#: what each probe group is, as a plot's title
TITLES = {"motion": "body motion from the start", "loads": "loads on the bodies over each coupling step",
          "tensions": "mooring line tensions", "line_states": "mooring line states (Barreiro et al. 2016, Fig. 5)",
          "gauges": "free-surface elevation above still water", "sea": "incident sea at the origin",
          "pressure": "wall pressure", "energy": "fluid energy",
          "line_points": "positions of points along the lines", "line_energy": "mechanical energy of the lines"}
#: readable names of the probe columns' quantities (``ENTITY.QUANTITY``), where the column's is terse
QUANTITIES = {"fluid_Fx": "fluid force Fx", "fluid_Fy": "fluid force Fy", "fluid_Fz": "fluid force Fz",
              "mooring_Fx": "mooring force Fx", "mooring_Fy": "mooring force Fy", "mooring_Fz": "mooring force Fz",
              "tension": "tension at the fairlead", "anchor_tension": "tension at the anchor",
              "tether": "tension of the length constraint", "state": "line state", "eta": "elevation η",
              "p": "pressure", "kinetic": "kinetic energy", "potential": "potential energy",
              "energy": "mechanical energy", "x": "x", "y": "y", "z": "z"}
#: the most curves a panel's legend names
LEGEND_MAX = 12


def _figure(figsize, dpi: int = 110):
    """A figure drawn by Agg, outside pyplot (no figure manager to import, keep or close)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, dpi=dpi)
    FigureCanvasAgg(fig)
    return fig


def _fit_margins(fig, axes) -> None:
    """Place a column of panels sharing their x axis so that the y tick labels and labels,
    the top panel's title and the bottom panel's x axis fit inside the figure with matplotlib's
    own paddings (``tight_layout``'s pad of 1.08 font sizes, the rcParams' tick and label
    pads). ``Figure.tight_layout`` finds the same margins by laying out every artist of the
    figure, which costs as much as the draw that saves it: here only those texts are
    measured, with the figure's renderer (the tick labels the locator gives, a few beyond
    the limits included: the margin errs wide). A panel's y offset text (``1e6``) is given
    a line above the panel."""
    import matplotlib as mpl
    from matplotlib.font_manager import FontProperties

    renderer = fig.canvas.get_renderer()
    px = fig.dpi / 72.0  # pixels per point

    def extent(texts, size):
        prop = FontProperties(size=size)
        ext = [renderer.get_text_width_height_descent(s, prop, ismath=False) for s in texts if s] or [(0.0, 0.0, 0.0)]
        return max(w for w, _, _ in ext), max(h for _, h, _ in ext)

    rc = mpl.rcParams
    pad = 1.08 * rc["font.size"] * px
    label_h = extent(["[Tg"], rc["axes.labelsize"])[1]
    tick_w = max(extent([t.get_text() for t in ax.get_yticklabels()], rc["ytick.labelsize"])[0] for ax in axes)
    xtick_w, xtick_h = extent([t.get_text() for t in axes[-1].get_xticklabels()], rc["xtick.labelsize"])
    title = axes[0].title
    title_h = extent([title.get_text()], title.get_fontsize())[1]
    offset = any(ax.yaxis.get_major_formatter().get_offset() for ax in axes)
    W, H = fig.bbox.width, fig.bbox.height
    left = pad + label_h + rc["axes.labelpad"] * px + tick_w + (rc["ytick.major.pad"] + rc["ytick.major.size"]) * px
    bottom = pad + label_h + rc["axes.labelpad"] * px + xtick_h + (rc["xtick.major.pad"] + rc["xtick.major.size"]) * px
    top = pad + title_h + rc["axes.titlepad"] * px + (label_h if offset else 0.0)
    right = pad + 0.5 * xtick_w
    n = len(axes)
    gap = pad + (label_h if offset else 0.0)  # between two panels
    panel = (H - top - bottom - (n - 1) * gap) / n
    fig.subplots_adjust(left=left / W, right=1.0 - right / W, bottom=bottom / H, top=1.0 - top / H,
                        hspace=gap / max(panel, 1.0))


def quantity(column: str) -> str:
    """The readable name of a probe column's quantity (``box.fluid_Fx`` -> ``fluid force Fx``)."""
    q = column.rsplit(".", 1)[1]
    return QUANTITIES.get(q, q.replace("_", " "))


def group_figure(t: np.ndarray, table: np.ndarray, group, title: str):
    """The figure of one probe group's series ``table`` (n_samples, n_columns) at times
    ``t`` [s] (the caller saves it)."""
    # a line's points: one panel per coordinate (``line.point3_x``: the quantity "x"), not per point
    split = (lambda c: c.rsplit("_", 1)) if group.name == "line_points" else (lambda c: c.rsplit(".", 1))
    qs = list(dict.fromkeys(split(c)[1] for c in group.columns))
    labels = group.labels or [split(c)[0] for c in group.columns]
    tall = 2.2 if group.categories else 1.8
    fig = _figure((7.5, 1.3 + tall * len(qs)))
    axes = fig.subplots(len(qs), 1, sharex=True, squeeze=False)
    for ax, q in zip(axes[:, 0], qs):
        cols = [j for j, c in enumerate(group.columns) if split(c)[1] == q]
        for k, j in enumerate(cols):
            if group.categories:  # codes: steps, each curve nudged so that equal codes stay apart
                ax.step(t, table[:, j] + 0.06 * (k - (len(cols) - 1) / 2), where="post", label=labels[j])
            else:
                ax.plot(t, table[:, j], label=labels[j])
        name = quantity(group.columns[cols[0]]) if group.name != "line_points" else QUANTITIES[q]
        if group.categories:
            ax.set_yticks(range(len(group.categories)), group.categories)
            ax.set_ylim(-0.5, len(group.categories) - 0.5)
            ax.set_ylabel(name)
        else:
            ax.set_ylabel(f"{name} [{group.units[cols[0]]}]")
        ax.grid(alpha=0.3)
        if len(cols) <= LEGEND_MAX:
            ax.legend(fontsize=7, loc="best")
    axes[-1, 0].set_xlabel("t [s]")
    axes[0, 0].set_title(title, fontsize=10)
    _fit_margins(fig, axes[:, 0])
    return fig


def plot_groups(out, t, groups, tables, scene) -> None:
    """``GROUP.png`` for each probe group (``tables[name]``: its samples at ``t``)."""
    for g in groups:
        fig = group_figure(np.asarray(t), tables[g.name], g,
                           f"{scene.name}: {TITLES.get(g.name, g.name.replace('_', ' '))}")
        fig.savefig(out / f"{g.name}.png")


def line_shapes(scene, built) -> list[tuple[str, np.ndarray]]:
    """Each mooring line as it hangs now, ``(name, points (n, 2) [m] in x-z)``: MoorDyn's
    nodes, the SPH cable's particles, else (the catenary, an FMU) the catenary's shape
    through the anchor and where the fairlead is now (:func:`moorings.catenary.shape`;
    a straight line where no catenary exists)."""
    from cosim.errors import CosimError
    from moorings.catenary import shape

    m = built.mooring
    if m is None:
        return []
    inner = getattr(m, "inner", m)  # a mooring whose lines may break wraps the model
    if callable(getattr(inner, "nodes", None)):
        pts = inner.nodes()
    elif callable(getattr(inner, "shapes", None)):
        pts = inner.shapes()
    else:
        pts = []
        for ln, f in zip(scene.moorings.lines, built.coupler.fairlead_positions()[0]):
            a, f = np.asarray(ln.anchor, float), np.asarray(f, float)
            X, h = float(np.linalg.norm(f[:-1] - a[:-1])), float(f[-1] - a[-1])
            try:
                _, x, z = shape(X, h, ln.length, ln.weight, ln.EA)
            except CosimError:  # taut and inextensible: no catenary, the chord
                x, z = np.array([0.0, X]), np.array([0.0, h])
            u = (f[:-1] - a[:-1]) / X if X > 0 else np.zeros(len(f) - 1)
            pts.append(np.column_stack([a[:-1] + np.outer(x, u), a[-1] + z]))
    return [(name, np.asarray(p, float)[:, [0, -1]]) for name, p in zip(built.line_names, pts)]


def plot_particles(path, scene, built, t: float) -> None:
    """The particles at time ``t`` [s] and what the scene holds besides (module docstring)."""
    from cosim.scene.build import PADDLE
    from cosim.scene.spec import Flume
    from fluid.particles import Kind

    ps = built.sph.simulated()
    fl = ps.kind == Kind.FLUID
    x, z = ps.pos[:, 0], ps.pos[:, -1]
    speed = scene.world.plot_color == "velocity"
    c = np.linalg.norm(ps.vel[fl], axis=1) if speed else ps.p[fl]
    aspect = (np.ptp(z) + 1e-9) / (np.ptp(x) + 1e-9)
    fig = _figure((9, min(max(7.5 * aspect + 1.9, 3.0), 9)))
    ax = fig.subplots()
    size = max(0.5, 3000.0 / max(len(x), 1))
    body = ps.kind == Kind.BODY
    paddle = (ps.group == PADDLE) & ~fl & ~body if isinstance(scene.domain, Flume) and scene.waves is not None \
        else np.zeros(len(x), bool)
    walls = ~fl & ~body & ~paddle
    ax.scatter(x[walls], z[walls], s=size, c="0.7", lw=0)
    if paddle.any():
        ax.scatter(x[paddle], z[paddle], s=size, c="tab:orange", lw=0, label="paddle")
    ax.scatter(x[body], z[body], s=size, c="0.2", lw=0)
    sc = ax.scatter(x[fl], z[fl], s=size, c=c, cmap="viridis", lw=0)
    fig.colorbar(sc, ax=ax, label="speed [m/s]" if speed else "pressure [Pa]", fraction=0.03, pad=0.02, shrink=0.8)
    if built.bodies is not None:
        plates = {k for m in (getattr(built, "plates", None) or {}).values() for k in m.link_names}
        com = built.bodies.kinematics().com
        for j, name in enumerate(built.bodies.body_names):
            if name not in plates:
                ax.annotate(name, (com[j, 0], com[j, -1]), xytext=(0, 14), textcoords="offset points",
                            ha="center", fontsize=8, color="0.15")
    for k, (name, p) in enumerate(line_shapes(scene, built)):
        ax.plot(p[:, 0], p[:, 1], "-", color=f"C{k + 3}", lw=1.4, label=f"line {name}")
        ax.plot(p[0, 0], p[0, 1], "^", color=f"C{k + 3}", ms=6)
    for i, g in enumerate(scene.probes.gauges):
        gx = float(np.ravel(g)[0])
        ax.axvline(gx, color="tab:red", lw=0.8, ls=":", label="wave gauges" if i == 0 else None)
        ax.text(gx, 0.97, f"gauge{i + 1} ", transform=ax.get_xaxis_transform(), fontsize=7, color="tab:red",
                rotation=90, ha="right", va="top")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_title(f"{scene.name}: t = {t:.3f} s" + (" (seen from the side)" if scene.world.dim == 3 else ""),
                 fontsize=10)
    handles, labels = ax.get_legend_handles_labels()
    if handles:  # along the figure's foot: nothing of the flow hidden
        fig.legend(handles, labels, fontsize=7, loc="lower center", ncol=min(5, len(handles)), frameon=False)
    fig.tight_layout(rect=(0, 0.07 if handles else 0, 1, 1))
    fig.savefig(path)


__all__ = ["TITLES", "QUANTITIES", "quantity", "group_figure", "plot_groups", "line_shapes", "plot_particles"]
