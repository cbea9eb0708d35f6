"""Yang & Li 2020, §4 (Table 2): the seven tests run as one scene family
(:mod:`cosim.validations.elastic_table2`: the tests, their scenes, what is measured), the
tables written and Figures 7-14 redrawn from our runs.

    python benchmarks/elastic_table2.py run [--dx 0.005] [--out out/elastic_table2] [--docs DIR]
    python benchmarks/elastic_table2.py resolution --dx 0.0075,0.005,0.0035,0.0025 [--tests 1,2,3,4,5,6,7]

``run`` writes ``table2_dxDmm.md``, ``.csv`` and ``fig07 .. fig14`` PNGs into ``--docs``
(default ``docs/studies/elastic_dambreak``, where the measured study and its reading are:
README.md); ``resolution`` runs the tests (Test 1 by default) at each spacing and writes
``resolution.md`` there.
One group alone is an ordinary study, e.g. ``cosim study
cosim/validations/scenes/elastic-table2.toml --vary bodies[0].E=7.5e6,1.5e7,3e7 --metric
plate.corner_x:peak --metric plate.fluid_Fx:peak --serial``. Prints figures; asserts nothing.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from cosim.validations.elastic_table2 import GROUPS, PAPER, SLOPES, TABLE2, metrics, run_cases  # noqa: E402

def _report(c, rec) -> None:
    """One line per finished run: the test, dx, its CPU seconds, cached or failed."""
    print(f"  test {c.values['test']} dx {c.values['fluid.dx']}: {rec.get('cpu_s', float('nan')):.1f} CPU-s "
          f"{'(cached)' if rec.get('cached') else ''} {rec.get('error') or ''}", flush=True)


def _tag(dx: float) -> str:
    return f"dx{1e3 * dx:g}mm"


def _row(m, rec):
    return [m["test"], f"{m['hu_mm']:.0f}", f"{m['a_mm']:.0f}", f"{m['E_Pa']:.3g}", f"{m['arrival_s']:.3f}",
            f"{m['motion_onset_s']:.3f}", f"{m['peak_mm']:.3f}", f"{m['peak_t_s']:.3f}",
            f"{PAPER['peak_mm'].get(m['test'], float('nan')):.2f}", f"{m['quasi_static_max_mm']:.2f}",
            f"{m['force_peak_N_per_m']:.0f}", f"{m['foot_p_peak_kPa']:.2f}", f"{m['foot_p_peak_raw_kPa']:.2f}",
            f"{m['f_vib_hz']:.1f}",
            f"{m['f1_dry_hz']:.1f}", f"{rec.get('cpu_s', float('nan')):.0f}", rec.get("particles"), rec.get("steps")]


HEAD = ["test", "hu [mm]", "a [mm]", "E [Pa]", "arrival [s]", "motion onset [s]", "peak x [mm]", "at [s]",
        "paper peak [mm]", "quasi-static max [mm]", "peak force [N/m]", "foot p peak [kPa]",
        "foot p one sample [kPa]", "f vib [Hz]",
        "f1 dry [Hz]", "CPU [s]", "particles", "steps"]


def _table(rows, head):
    return ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)] + \
        ["| " + " | ".join(str(v) for v in r) + " |" for r in rows]


def trends(ms: dict) -> list[str]:
    """The paper's §4 trends, ours beside the paper's numbers."""
    out = []
    for g, (tests, col, scale, label) in GROUPS.items():
        xs = [ms[t]["peak_mm"] for t in tests]
        ps = [ms[t]["foot_p_peak_kPa"] for t in tests]
        vals = [TABLE2[t][col] * scale for t in tests]
        j = lambda fmt, v: ", ".join(fmt.format(u) for u in v)  # noqa: E731
        out.append(f"- {label} {j('{:g}', vals)}: peak x {j('{:.2f}', xs)} mm (x/xmax "
                   f"{j('{:.2f}', [v / max(xs) for v in xs])}); foot pressure {j('{:.1f}', ps)} kPa (P/Pmax "
                   f"{j('{:.2f}', [v / max(ps) for v in ps])}); f vib "
                   f"{j('{:.1f}', [ms[t]['f_vib_hz'] for t in tests])} "
                   f"Hz (dry f1 {j('{:.1f}', [ms[t]['f1_dry_hz'] for t in tests])})")
    return out


def plot(ms: dict, docs: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    note = "ours (SPH + MuJoCo chain, dx {:g} mm); 2-core AMD EPYC, loaded".format(1e3 * ms["_dx"])
    figs = {"hu": (7, 8), "a": (9, 10), "E": (11, 12)}
    for g, (tests, col, scale, label) in GROUPS.items():
        fa, fb = figs[g]
        fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 3.8), dpi=110, gridspec_kw={"width_ratios": [2, 1]})
        for t in tests:
            m = ms[t]
            lab = f"{label.split()[0]} = {TABLE2[t][col] * scale:g} (test {t})"
            ax.plot(m["_t"], 1e3 * m["_x"], label=lab)
            keep = (m["_f"] > 0) & (m["_f"] <= 150)
            bx.plot(m["_f"][keep], m["_spec"][keep] / m["_spec"][keep].max(), label=f"{m['f_vib_hz']:.1f} Hz")
            if t in PAPER["peak_mm"]:
                ax.plot([m["peak_t_s"]], [PAPER["peak_mm"][t]], "k*", ms=8)
        ax.axvline(PAPER["arrival_s"], color="0.5", ls=":", lw=1, label="paper: arrival 0.138 s")
        if any(t in PAPER["peak_mm"] for t in tests):
            ax.plot([], [], "k*", label="paper's peak (text), at our peak's time")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("corner x displacement [mm]")
        ax.set_title(f"Yang & Li 2020, Fig. {fa}: top of the structure, {label.split()[0]} varied", fontsize=9)
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        bx.axvspan(*PAPER["f_band_hz"], color="0.85", label="paper: 40-50 Hz (tests 1-3)")
        bx.set_xlabel("f [Hz] (after the peak)")
        bx.set_ylabel("|FFT| / max")
        bx.legend(fontsize=7)
        bx.grid(alpha=0.3)
        fig.text(0.01, 0.01, note, fontsize=7, color="0.4")
        fig.tight_layout(rect=(0, 0.03, 1, 1))
        fig.savefig(docs / f"fig{fa:02d}_{g}_displacement_{_tag(ms['_dx'])}.png")
        plt.close(fig)
        fig, ax = plt.subplots(figsize=(5, 4), dpi=110)
        for t in tests:
            m = ms[t]
            ax.plot(m["p_extreme_kPa"], m["z_mm"], "o-", label=f"{label.split()[0]} = {TABLE2[t][col] * scale:g}")
        ax.set_xlabel("extreme net pressure on the node's share, 5 ms mean [kPa]")
        ax.set_ylabel("z [mm]")
        ax.set_title(f"Yang & Li 2020, Fig. {fb}: extreme pressure, {label.split()[0]} varied", fontsize=9)
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        fig.text(0.01, 0.01, note, fontsize=6, color="0.4")
        fig.tight_layout(rect=(0, 0.03, 1, 1))
        fig.savefig(docs / f"fig{fb:02d}_{g}_pressure_{_tag(ms['_dx'])}.png")
        plt.close(fig)
    for num, key, what in ((13, "peak_mm", "x / x_max"), (14, "foot_p_peak_kPa", "P_foot / P_max")):
        fig, axs = plt.subplots(1, 3, figsize=(11, 3.4), dpi=110)
        for ax, (g, (tests, col, scale, label)) in zip(axs, GROUPS.items()):
            v = np.array([TABLE2[t][col] for t in tests])
            y = np.array([ms[t][key] for t in tests])
            ax.plot(v / v.max(), y / y.max(), "o-", label="ours")
            if g in SLOPES[key]:  # the text's slope, through our largest value
                j = int(np.argmax(y))
                u = np.array([v.min(), v.max()]) / v.max()
                ax.plot(u, 1.0 + SLOPES[key][g] * (u - v[j] / v.max()), color="0.5", ls=":",
                        label=f"paper §4.4 (text): slope {SLOPES[key][g]:+.2f}")
            if key == "peak_mm" and all(t in PAPER["peak_mm"] for t in tests):
                yp = np.array([PAPER["peak_mm"][t] for t in tests])
                ax.plot(v / v.max(), yp / yp.max(), "ks--", label="paper (text: 0.82, 0.76, 0.67 mm)")
            ax.set_xlabel(f"{g} / {g}_max")
            ax.set_ylabel(what)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
        fig.suptitle(f"Yang & Li 2020, Fig. {num}: {what} against each parameter", fontsize=9)
        fig.text(0.01, 0.01, note, fontsize=7, color="0.4")
        fig.tight_layout(rect=(0, 0.04, 1, 1))
        fig.savefig(docs / f"fig{num}_{'displacement' if num == 13 else 'pressure'}_trends_{_tag(ms['_dx'])}.png")
        plt.close(fig)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("what", choices=["run", "resolution"])
    ap.add_argument("--dx", default=None, help="spacing [m] (run: one; resolution: a comma-separated list)")
    ap.add_argument("--tests", default="1", help="resolution: the tests, comma-separated (1-7)")
    ap.add_argument("--out", default=str(ROOT / "out" / "elastic_table2"), help="the runs' folder")
    ap.add_argument("--docs", default=str(ROOT / "docs" / "studies" / "elastic_dambreak"), help="tables, figures")
    a = ap.parse_args(argv)
    docs = Path(a.docs)
    docs.mkdir(parents=True, exist_ok=True)
    if a.what == "run":
        dx = float(a.dx or 0.005)
        res = run_cases(list(TABLE2), [dx], Path(a.out), report=_report)
        ms, rows = {"_dx": dx}, []
        for t, _, rec, folder in res:
            if rec.get("error"):
                print(f"test {t}: {rec['error']}")
                continue
            ms[t] = metrics(t, folder)
            rows.append(_row(ms[t], rec))
        with open(docs / f"table2_{_tag(dx)}.csv", "w", newline="") as f:
            csv.writer(f).writerows([HEAD] + rows)
        lines = [f"# Yang & Li 2020, Table 2 at dx = {1e3 * dx:g} mm", "", *_table(rows, HEAD), "", *trends(ms), "",
                 "Extreme net pressure per node [kPa] (z = " + ", ".join(f"{z:.0f}" for z in ms[1]["z_mm"]) + " mm):",
                 ""] + [f"- test {t}: " + ", ".join(f"{v:.1f}" for v in ms[t]["p_extreme_kPa"])
                        for t in TABLE2 if t in ms]
        (docs / f"table2_{_tag(dx)}.md").write_text("\n".join(lines) + "\n")
        print("\n".join(lines))
        plot(ms, docs)
    else:
        dxs = [float(v) for v in (a.dx or "0.0075,0.005,0.0035,0.0025").split(",")]
        tests = [int(v) for v in a.tests.split(",")]
        res = run_cases(tests, dxs, Path(a.out), report=_report)
        head = ["test", "dx [mm]", "particles", "steps", "CPU [s]", "wall [s]", "peak x [mm]", "at [s]", "vs finest",
                "vs paper", "arrival [s]", "foot p [kPa]", "vs finest", "f vib [Hz]"]
        lines = [f"# Yang & Li 2020, Table 2, test{'s' if len(tests) > 1 else ''} {a.tests}, at several spacings", "",
                 "'vs finest': against the same test's finest spacing here; 'vs paper': against the peak the "
                 "paper's text gives (tests 1, 4, 5). 2-core AMD EPYC, loaded: compare CPU, not wall.", ""]
        rows = []
        for t in tests:
            ms = []
            for tt, dx, rec, folder in res:
                if tt != t:
                    continue
                if rec.get("error"):
                    print(f"test {t} dx {dx}: {rec['error']}")
                    continue
                ms.append((dx, metrics(t, folder), rec))
            if not ms:
                continue
            fine = min(ms, key=lambda r: r[0])[1]
            paper = PAPER["peak_mm"].get(t, math.nan)
            for dx, m, rec in sorted(ms, key=lambda r: -r[0]):
                rows.append([t, f"{1e3 * dx:g}", rec.get("particles"), rec.get("steps"),
                             f"{rec.get('cpu_s', math.nan):.0f}", f"{rec.get('wall_s', math.nan):.0f}",
                             f"{m['peak_mm']:.3f}", f"{m['peak_t_s']:.3f}", f"{m['peak_mm'] / fine['peak_mm'] - 1:+.1%}",
                             f"{m['peak_mm'] / paper - 1:+.0%}" if paper == paper else "",
                             f"{m['arrival_s']:.3f}", f"{m['foot_p_peak_kPa']:.2f}",
                             f"{m['foot_p_peak_kPa'] / fine['foot_p_peak_kPa'] - 1:+.1%}", f"{m['f_vib_hz']:.1f}"])
        lines += _table(rows, head)
        (docs / "resolution.md").write_text("\n".join(lines) + "\n")
        print("\n".join(lines))


if __name__ == "__main__":
    main()
