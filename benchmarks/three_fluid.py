"""The fluids of one scene side by side, from a ``cosim study`` that varies ``fluid.model``
(and any other field): per run, the motion amplitudes (half the range over the last half of
the run, as ``cosim study``'s ``amplitude``), the range of each fairlead's tension over it
and the run's CPU time, as a markdown table; the relative difference of each fluid's
amplitudes from those of ``--reference`` (a fluid model) with the same other values; and a
figure of the motions and the first line's tension against time, one curve per run.

    python benchmarks/three_fluid.py STUDY_DIR [--body base] [--reference potential] [--figure F.png]

Reads ``STUDY_DIR/study.json`` and each run's ``run.h5`` (``cosim.study.sweep.series``).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from cosim.study import sweep

MOTIONS = (("surge", "m"), ("heave", "m"), ("pitch", "deg"))


def late(t, x):
    """The samples of the last half of the run."""
    keep = t >= 0.5 * t[-1]
    return x[keep]


def summarise(study: Path, body: str) -> list[dict]:
    """Per run of the study: its values, CPU time [s], steps, motion amplitudes and the
    (min, max) of each fairlead tension [N] over the last half."""
    js = json.loads((study / "study.json").read_text())
    out = []
    for r in js["rows"]:
        if r.get("error"):
            out.append({"values": r["values"], "error": r["error"]})
            continue
        s = sweep.series(study / "runs" / r["case"])
        row = {"values": r["values"], "cpu_s": r["cpu_s"], "wall_s": r["wall_s"], "steps": r["steps"],
               "series": s, "error": None}
        for m, _ in MOTIONS:
            x = late(*s[f"{body}.{m}"])
            row[m] = 0.5 * float(x.max() - x.min())
        row["tension"] = {k[: -len(".tension")]: (float(late(*v).min()), float(late(*v).max()))
                          for k, v in s.items() if k.endswith(".tension") and not k.endswith("anchor_tension")}
        out.append(row)
    return out


def table(rows: list[dict], reference: str) -> list[str]:
    keys = list(rows[0]["values"])
    lines_ = sorted({n for r in rows if not r["error"] for n in r["tension"]})
    big = max((r["tension"][n][1] for r in rows if not r["error"] for n in r["tension"]), default=0.0) > 1e4
    unit, scale, fmt = ("kN", 1e3, ".1f") if big else ("N", 1.0, ".3g")
    head = keys + [f"{m} amplitude [{u}]" for m, u in MOTIONS] + [f"{n} tension [{unit}]" for n in lines_] + \
        ["CPU [s]", "steps"]
    md = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [str(r["values"][k]) for k in keys]
        if r["error"]:
            md.append("| " + " | ".join(cells + [f"error: {r['error']}"] + [""] * (len(head) - len(cells) - 1)) + " |")
            continue
        cells += [f"{r[m]:.4g}" for m, _ in MOTIONS]
        cells += [f"{r['tension'][n][0] / scale:{fmt}}-{r['tension'][n][1] / scale:{fmt}}" for n in lines_]
        cells += [f"{r['cpu_s']:.1f}", str(r["steps"])]
        md.append("| " + " | ".join(cells) + " |")
    others = [k for k in keys if k != "fluid.model"]
    ref = {tuple(r["values"][k] for k in others): r for r in rows
           if not r["error"] and r["values"].get("fluid.model") == reference}
    diffs = []
    for r in rows:
        base = ref.get(tuple(r["values"][k] for k in others))
        if r["error"] or base is None or base is r:
            continue
        d = ", ".join(f"{m} {r[m] / base[m] - 1:+.1%}" for m, _ in MOTIONS)
        swing = lambda q: {n: q["tension"][n][1] - q["tension"][n][0] for n in q["tension"]}  # noqa: E731
        t = ", ".join(f"{n} {swing(r)[n] / swing(base)[n] - 1:+.1%}" for n in lines_ if swing(base)[n] > 0)
        diffs.append(f"- {r['values']}: amplitudes against {reference}: {d}; tension ranges: {t}")
    return md + ([""] + diffs if diffs else [])


def figure(rows: list[dict], body: str, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ok = [r for r in rows if not r["error"]]
    first = sorted(ok[0]["tension"])[0] if ok else None
    fig, axes = plt.subplots(4, 1, figsize=(8, 9), sharex=True, dpi=80)
    styles = ["-", "--", ":", "-."]
    fluids = sorted({r["values"].get("fluid.model", "") for r in ok})
    others = sorted({tuple((k, v) for k, v in r["values"].items() if k != "fluid.model") for r in ok})
    for r in ok:
        c = f"C{fluids.index(r['values'].get('fluid.model', ''))}"
        ls = styles[others.index(tuple((k, v) for k, v in r["values"].items() if k != "fluid.model")) % 4]
        label = ", ".join(str(v) for v in r["values"].values())
        for ax, (m, u) in zip(axes, MOTIONS):
            t, x = r["series"][f"{body}.{m}"]
            ax.plot(t, x, c, ls=ls, lw=0.9, label=label)
            ax.set_ylabel(f"{m} [{u}]")
        t, x = r["series"][f"{first}.tension"]
        axes[3].plot(t, x / 1e3, c, ls=ls, lw=0.9)
    axes[3].set_ylabel(f"{first} tension [kN]")
    axes[3].set_xlabel("t [s]")
    axes[0].legend(fontsize=7, ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(f"{body}: the fluids side by side (colour: fluid; line: the other values)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("study", type=Path)
    p.add_argument("--body", default="base")
    p.add_argument("--reference", default="potential", help="the fluid the others are compared with")
    p.add_argument("--figure", type=Path, help="write the figure here (PNG)")
    a = p.parse_args(argv)
    rows = summarise(a.study, a.body)
    print("\n".join(table(rows, a.reference)))
    if a.figure:
        figure(rows, a.body, a.figure)
    return 0


if __name__ == "__main__":
    sys.exit(main())
