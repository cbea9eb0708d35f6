"""The standing wave of benchmarks/standing_wave_decay.py (10 rows, the wave set-up, a = 2 cm)
in 2-D, in a 3-D slice 5 spacings wide between side walls and in the same slice between two
symmetry planes (``--sides symmetry``): the mode's velocity amplitude over 4 periods
against time in linear theory's periods. Between walls the mode runs fast and grows;
between planes it follows the 2-D water (docs/validation/wave-propagation_history.md,
"Side walls, not the 3-D water").

    python benchmarks/standing_wave_sides_figure.py docs/validation/figures/standing-wave_sides.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from standing_wave_decay import run  # noqa: E402  (beside this script)

ROWS, PERIODS, WIDTH = 10, 4, 5
CASES = (("2-D", 0, "walls", "k"), ("3-D slice, side walls", WIDTH, "walls", "tab:red"),
         ("3-D slice, symmetry planes", WIDTH, "symmetry", "tab:blue"))


def main(path: str) -> None:
    fig, ax = plt.subplots(figsize=(9, 3.6))
    for label, width, sides, colour in CASES:
        series = []
        r = run(ROWS, PERIODS, {}, width, sides=sides, series=series)
        t, q = np.array(series).T
        d = 100 * r["decay_per_period"]
        ax.plot(t, q, color=colour, lw=1.2, label=f"{label}: period {r['period_over_linear']:.4f} of linear theory's, "
                                                   f"{'grows' if d < 0 else 'decays'} {abs(d):.2f} % a period")
        print(f"{label}: period/linear {r['period_over_linear']:.4f}, decay per period {r['decay_per_period']:.4f}, "
              f"{r['particles']} particles, {r['cpu_s']:.0f} CPU-s", flush=True)
    ax.plot(t, np.cos(2 * np.pi * t), ":", color="0.5", lw=1, label="linear theory")
    ax.set_xlabel("t / T (linear theory's period)")
    ax.set_ylabel("mode's velocity / its start")
    ax.set_ylim(-1.25, 2.4)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title(f"standing wave, {ROWS} rows over the depth, h = 2 dx: the slice's side walls, not the 3-D water",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


if __name__ == "__main__":
    main(sys.argv[1])
