"""Two opposed catenary lines holding a body (Barreiro et al. 2016, §4.2.2, Table 3).

The body sits at x = 0 between anchors at x = ±55 m, 50 m below the fairlead,
with 50 kN horizontal pretension. Moving it from −15 m to +15 m, this prints
each line's horizontal tension and state and the net restoring force, and plots
them. As printed, Barreiro et al. 2016's 75 m lines would be taut 0.90 m from rest, so this
uses 90 m lines (see ``cosim validate catenary-two-lines``).

    python examples/two_line_mooring.py [--out DIR]
"""

import argparse
from pathlib import Path

import numpy as np

from moorings import CatenaryMooring, MooringLine
from moorings.catenary import LineState, solve

DEPTH, HALF_SPAN, LENGTH, PRETENSION = 50.0, 55.0, 90.0, 50e3  # m, m, m, N


def main(out: Path) -> None:
    w = PRETENSION / solve(HALF_SPAN, DEPTH, LENGTH, 1.0).H  # H is proportional to w
    mooring = CatenaryMooring(
        [MooringLine((-HALF_SPAN, -DEPTH), LENGTH, w, name="A"), MooringLine((HALF_SPAN, -DEPTH), LENGTH, w, name="B")]
    )
    offsets = np.linspace(-15.0, 15.0, 31)
    rows = []
    for d in offsets:
        mooring.set_fairlead_motion([[d, 0.0], [d, 0.0]])
        F, _ = mooring.total_wrench([d, 0.0])
        sol = mooring.solution
        rows.append((d, sol.H[0], sol.H[1], F[0], LineState(sol.state[0]).name, LineState(sol.state[1]).name))
    print(f"lines: L = {LENGTH} m, w = {w:.1f} N/m, depth {DEPTH} m, anchors at x = ±{HALF_SPAN} m")
    print(f"{'offset [m]':>10} {'H_A [kN]':>10} {'H_B [kN]':>10} {'F_x [kN]':>10}  state A / state B")
    for d, ha, hb, fx, sa, sb in rows[::3]:
        print(f"{d:10.1f} {ha / 1e3:10.2f} {hb / 1e3:10.2f} {fx / 1e3:10.2f}  {sa} / {sb}")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    arr = np.array([r[:4] for r in rows], dtype=float)
    fig, ax = plt.subplots(figsize=(6.5, 4), dpi=120)
    ax.plot(arr[:, 0], arr[:, 1] / 1e3, label="line A (anchor at −55 m)")
    ax.plot(arr[:, 0], arr[:, 2] / 1e3, label="line B (anchor at +55 m)")
    ax.plot(arr[:, 0], arr[:, 3] / 1e3, "k--", label="net force on the body, x")
    ax.set_xlabel("body offset [m]")
    ax.set_ylabel("horizontal force [kN]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "two_line_mooring.png")
    print(f"wrote {out / 'two_line_mooring.png'}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/two_line_mooring"), help="output folder")
    main(parser.parse_args().out)
