"""The measured trade of validation cases, by ``cosim study``.

A case listed in :data:`STUDIES` has its set-up as a scene (``scenes/CASE.toml`` beside
this module) and its reference values (``scenes/CASE.reference.json``: one number per
metric, with the ``source`` it comes from). ``cosim study`` runs that scene over the
levers of the study (resolution, speed of sound) and measures each run's error against
the reference and its cost; the validation report (:mod:`cosim.report`) shows the result
on the case's page from ``docs/validation/trade/CASE/`` (``study.md``, ``study.csv``,
``study.json``, ``pareto.png``; the runs themselves are not kept). Re-measure with

    python -m cosim.validations.trade CASE [--out DIR]     # prints and runs the command

The scene measures the case's physics with the scene's own probes (a wall patch, a
gauge), not with the case's extraction (per-particle fits): each study's ``quantity``
says what is compared, so that its errors are read for what they are.
"""

from __future__ import annotations

import shlex
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

from cosim.validations.folders import SCENES, TRADE_DIR


@dataclass(frozen=True)
class TradeStudy:
    """A case's study: ``vary`` {scene key: values}, ``metrics`` ``SERIES:STAT``, ``tol`` the
    relative error the recommendation asks for, ``quantity`` what the metrics measure,
    ``fixed`` {scene key: value} set for every run where the study's scene differs from the
    case's file (``cosim study --set``)."""

    case: str
    vary: dict
    metrics: tuple
    tol: float
    quantity: str
    fixed: dict = field(default_factory=dict)

    @property
    def scene(self) -> Path:
        return SCENES / f"{self.case}.toml"

    @property
    def reference(self) -> Path:
        return SCENES / f"{self.case}.reference.json"

    def argv(self, out: Path | str) -> list[str]:
        """The ``cosim study`` arguments (after ``cosim``) that measure this study into ``out``."""
        rel = lambda p: str(p.relative_to(Path.cwd())) if p.is_relative_to(Path.cwd()) else str(p)
        args = ["study", rel(self.scene)]
        for key, values in self.vary.items():
            args += ["--vary", f"{key}={','.join(str(v) for v in values)}"]
        for key, value in self.fixed.items():
            args += ["--set", f"{key}={value}"]
        for m in self.metrics:
            args += ["--metric", m]
        return args + ["--reference", rel(self.reference), "--tol", f"{self.tol:.6g}", "--out", str(out)]

    def command(self, out: Path | str | None = None) -> str:
        return "cosim " + " ".join(shlex.quote(a) for a in self.argv(out or f"out/trade_{self.case}"))


STUDIES = {s.case: s for s in [
    TradeStudy("hydrostatic", {"fluid.dx": [0.02, 0.01, 0.005]}, ("bottom.p:mean", "side.p:mean"), 0.01,
               "the mean pressure over 3 s on a 0.1 m patch of the bottom against rho g H (the column's weight) "
               "and on a 0.04 m patch of the side wall at mid-depth against rho g H / 2 (the case: every "
               "particle's pressure against rho g (H - z), RMS)"),
    TradeStudy("sloshing-frequency", {"fluid.dx": [0.05, 0.0333, 0.025], "fluid.c0_factor": [10, 20]},
               ("left_wall.p:period", "gauge1.eta:period"), 0.02,
               "the free sloshing period from the FFT of the wall pressure 0.1 m below the surface and of the "
               "elevation 5 cm from the wall, over the last half of the run, against linear theory's T1 (the "
               "case: the wall particle's pressure, its FFT peak over the whole free decay)"),
    TradeStudy("westergaard", {"fluid.dx": [0.1, 0.05, 0.025]}, ("left_wall.p:harmonic",), 0.04,
               "the amplitude of the sinusoid fitted to the pressure on a 0.3 m patch of the left wall over periods "
               "4-6, against the exact series averaged over the patch (the case: k_p fitted per wall row, RMS "
               "over the depth, after the first of 3 periods)", fixed={"world.duration": 0.18}),
    TradeStudy("inclined-wall", {"fluid.dx": [0.1, 0.05, 0.025]}, ("slope.p:harmonic",), 0.04,
               "the amplitude of the sinusoid fitted to the pressure on a 0.3 m patch of the 45 deg face, 0.25 m "
               "above the bottom, over periods 4-6, against Chwang's theory averaged over the patch (the case: k_p "
               "at every dx up the face at 15, 30 and 45 deg, RMS, with the case's set-up)",
               fixed={"world.duration": 0.18, "fluid.setup": "auto"}),
]}


def study_dir(case: str) -> Path:
    return TRADE_DIR / case


def main(argv=None) -> int:
    import argparse

    ap = argparse.ArgumentParser(prog="python -m cosim.validations.trade", description=__doc__.split("\n\n")[0])
    ap.add_argument("case", choices=sorted(STUDIES))
    ap.add_argument("--out", help="study folder (default out/trade_CASE)")
    ap.add_argument("--serial", action="store_true", help="no Dask: one run after the other")
    args = ap.parse_args(argv)
    s = STUDIES[args.case]
    argv = s.argv(args.out or f"out/trade_{s.case}") + (["--serial"] if args.serial else [])
    print(s.command(args.out), flush=True)
    # the CLI in its own process: this data module sits below the CLI and never imports it
    return subprocess.run([sys.executable, "-m", "cosim.cli", *argv]).returncode


if __name__ == "__main__":
    sys.exit(main())
