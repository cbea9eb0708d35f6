"""cosim: couple an SPH fluid, MuJoCo bodies and mooring models.

``cosim run``       run a scene (TOML file or Python script) into an output folder
``cosim study``     the speed/accuracy trade of a scene: runs over varied fields, errors, costs, Pareto
``cosim line``      tabulate (and plot) one catenary mooring line against X
``cosim validate``  run validation cases, one JSON object per case
``cosim export-fmu`` write a scene's mooring lines (catenary) as an FMI 2.0 co-simulation FMU
``cosim inspect``   what an output file (HDF5) holds, as JSON; its series as CSV tables
``cosim plot``      the particles of a run's latest checkpoint (a running, stopped or finished run)
"""

from __future__ import annotations

import argparse
import json
import math
import signal
import sys
import threading

from cosim.errors import CosimError

#: Barreiro et al. 2016, Tables 1 and 2 (Johanning et al. 2007, 2006)
LINE_PRESETS = {
    "johanning-2007": dict(length=6.98, weight=1.036, height=2.651, x_range=(5.50, 6.40)),
    "johanning-2006": dict(length=150.0, weight=918.75, height=50.0, x_range=(102.0, 140.0)),
}


def add_light_body_option(parser: argparse.ArgumentParser) -> None:
    """``--light-body {auto,none,subiterate,added-mass}`` on a command that runs a
    coupled scene: the coupler's ``light_body`` (:class:`cosim.coupler.Coupler`,
    :mod:`cosim.added_mass`), default ``auto``; the help says what each choice does."""
    from cosim.added_mass import LIGHT_BODY, LIGHT_BODY_HELP

    parser.add_argument("--light-body", choices=LIGHT_BODY, default="auto", metavar="{" + ",".join(LIGHT_BODY) + "}",
                        help="what the coupler does for bodies much lighter than the fluid they displace (the "
                             "added-mass instability of staggered coupling); "
                             + "; ".join(f"{k}: {v}" for k, v in LIGHT_BODY_HELP.items())
                             + ". Default auto; the run reports the remedy chosen per body")


def _run_parser(sub):
    p = sub.add_parser(
        "run",
        help="run a scene: SCENE.toml or SCENE.py (a script defining `scene`)",
        description="Run a coupled scene and write its outputs (run.h5 + run.xmf for ParaView, one CSV and one "
        "PNG per probe group, summary.json, the scene as run in scene.toml, checkpoints) into one folder. The "
        "scene is checked before any work is done; a bad value is named by its key path.",
    )
    p.add_argument("scene", help="a .toml scene file, or a .py script that defines a Scene named `scene`")
    p.add_argument("--set", action="append", default=[], metavar="KEY.PATH=VALUE",
                   help="change one field, as its TOML key path, e.g. --set fluid.dx=0.01 --set moorings.model=moordyn "
                        "(repeatable; VALUE is read as TOML, a bare word as a string)")
    p.add_argument("--out", help="output folder (default out/<scene name>)")
    p.add_argument("--resume", action="store_true",
                   help="continue the run in --out from its last checkpoint (bit for bit; world.duration may grow). "
                        "A run writes one every world.checkpoint_wall s of wall time (default 120) and at its end")
    p.add_argument("--overwrite", action="store_true",
                   help="clear --out first when it holds an earlier run (a folder that holds files is refused "
                        "otherwise)")
    p.add_argument("--resume-any-version", action="store_true",
                   help="with --resume: continue from a checkpoint that other code wrote (it may not continue bit "
                        "for bit)")
    p.add_argument("--quiet", action="store_true", help="no progress line and no summary")
    p.add_argument("--dry-run", action="store_true",
                   help="print the run's estimated cost (particles, steps, memory, CPU time) and exit, building and "
                        "writing nothing; the exit status is the run's (2 where it would be refused)")
    p.add_argument("--yes", action="store_true",
                   help="run even where the estimated CPU time passes a day (else asked at a terminal, refused "
                        "elsewhere)")
    return p


def _ask(question: str) -> bool:
    """A yes/no question on the terminal (stderr), answered on stdin."""
    print(f"cosim: {question}", end="", file=sys.stderr, flush=True)
    try:
        return input().strip().lower() in ("y", "yes")
    except EOFError:
        return False


def cmd_run(args, parser) -> int:
    from pathlib import Path

    from cosim.scene import cost
    from cosim.scene.load import load

    scene = load(args.scene)
    if args.set:
        scene = scene.with_values(args.set)
    out = Path(args.out) if args.out else Path("out") / scene.name
    if args.resume_any_version and not args.resume:
        parser.error("--resume-any-version goes with --resume")
    if args.overwrite and args.resume:
        parser.error("--overwrite clears the folder that --resume continues: give one")
    if args.dry_run:
        est = cost.estimate(scene)
        print(f"{scene.name}: estimated cost")
        print("\n".join(est.describe()))
        cost.check(est, out, yes=args.yes)
        return 0
    res = scene.run(out, resume=args.resume, resume_any_version=args.resume_any_version, overwrite=args.overwrite,
                    progress=False if args.quiet else None, yes=args.yes,
                    ask=_ask if sys.stdin.isatty() and not args.yes else None)
    if not args.quiet:
        s = res.summary
        size = f"{s['particles']} particles ({s['fluid_particles']} fluid), " if "particles" in s else ""
        print(f"{scene.name}: {size}{s['steps']} steps, {s['wall_s']:.1f} s wall for {s['t_reached_s']:g} s "
              f"simulated")
        if "setup" in s:
            c0 = f"; speed of sound {s['speed_of_sound_m_s']:.4g} m/s" if "speed_of_sound_m_s" in s else ""
            print(f"fluid set-up: {s['setup']['name']} ({s['setup']['reason']}){c0}")
        if "remedies" in s:
            print(f"coupling: {s['scheme']}; light-body remedy: "
                  + ", ".join(f"{k} {v}" for k, v in s["remedies"].items()))
        print(_steps_line(s.get("coupling", {})))
        for name in res.names:
            v = res[name]
            print(f"  {name:28s} {v.min():12.5g} .. {v.max():<12.5g} [{res.units[name]}]")
        print(f"wrote {out}/: run.h5 (+ run.xmf), " + ", ".join(sorted(p.name for p in out.glob("*.csv")))
              + ", " + ", ".join(sorted(p.name for p in out.glob("*.png"))) + ", summary.json, scene.toml")
    return 0


def _steps_line(c: dict) -> str:
    """The coupling steps a run took (summary.json's ``coupling``), in one line."""
    if not c.get("steps"):
        return "coupling steps: none"
    what = {"user dt": "coupling.dt", "end time": "cut to land on an output time"}
    by = ", ".join(f"{what.get(k, k)} {v['steps']}" for k, v in c["by_limiter"].items())
    asked = f"coupling.dt = {c['dt_set_s']:g} s; " if c.get("dt_set_s") else ""
    return (f"coupling steps: {asked}{c['dt_mean_s']:.4g} s on average, {c['dt_min_s']:.3g} .. {c['dt_max_s']:.3g} s; "
            f"set by {by}")


def _study_parser(sub):
    p = sub.add_parser(
        "study",
        help="measure the speed/accuracy trade of a scene over varied fields (on Dask)",
        description="Run a scene for every combination of the varied fields, reduce its probes to metrics, "
        "measure each run's error against a reference and its cost, and write study.csv, study.md, study.json "
        "and pareto.png with a recommendation: the cheapest run within the tolerance. Runs are cached by a hash "
        "of the scene and the code (an interrupted study resumes; a repeated one costs nothing); a failed run "
        "is a row with its error.",
    )
    p.add_argument("scene", help="a .toml scene file, or a .py script that defines `scene`")
    p.add_argument("--vary", action="append", default=[], metavar="KEY.PATH=V1,V2,...",
                   help="a field and its values, e.g. --vary fluid.dx=0.02,0.01 --vary moorings.model=catenary,moordyn")
    p.add_argument("--set", action="append", default=[], metavar="KEY.PATH=VALUE",
                   help="change a field for every run (a field of one kind alone, e.g. fluid.dx with --vary "
                        "fluid.model=analytic,sph: for the runs of that kind)")
    p.add_argument("--metric", action="append", default=[], metavar="SERIES:STAT",
                   help="a probe series and a statistic: peak, max, min, mean, last, amplitude, harmonic, period, arrival, rms "
                        "(e.g. box.heave:amplitude)")
    p.add_argument("--reference", default="finest", help="finest (default), richardson, or a .json / .csv file")
    p.add_argument("--tol", help="relative tolerance for the recommendation, e.g. 5%% or 0.05")
    p.add_argument("--out", help="study folder (default out/study_<scene name>)")
    p.add_argument("--workers", type=int, help="runs at once (default: cores / --threads)")
    p.add_argument("--threads", type=int, default=1, help="numba threads per run (default 1)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler, e.g. tcp://host:8786")
    p.add_argument("--serial", action="store_true", help="no Dask: one run after the other in this process's children")
    p.add_argument("--extremes", action="store_true",
                   help="push each lever (dx, c0, CFL, bodies' density, line stiffness, segments, coupling step) "
                        "towards its limits and report where the run stays stable and where it stops with a clear error")
    p.add_argument("--yes", action="store_true",
                   help="run even where the runs' estimated CPU time together passes a day (else asked at a "
                        "terminal, refused elsewhere)")
    return p


def _split_values(text: str) -> list[str]:
    """``a,b,[1, 2]`` -> ``["a", "b", "[1, 2]"]``: commas inside brackets stay."""
    parts, depth, cur = [], 0, ""
    for ch in text:
        depth += (ch in "[{") - (ch in "]}")
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    return [x.strip() for x in parts + [cur] if x.strip()]


def cmd_study(args, parser) -> int:
    from pathlib import Path

    from cosim.errors import InputError
    from cosim.scene.load import load
    from cosim.scene.toml_io import parse_value
    from cosim.study import run_study
    from cosim.study.sweep import foreign

    scene = load(args.scene)
    later = []  # a field of another kind than the scene's (fluid.dx on the analytic fluid): for the runs of that kind
    for a in args.set:
        if not args.extremes and foreign(scene, a) is not None:
            later.append(a)
        else:
            scene = scene.with_values([a])

    def report(case, rec):
        state = "cached" if rec.get("cached") else (f"error: {rec['error']}" if rec.get("error") else "done")
        wall = f"{rec['wall_s']:.1f} s" if rec.get("wall_s") is not None else ""
        print(f"  {case.values} {wall} {state}", flush=True)

    if args.extremes:
        from cosim.study.extremes import run_extremes, summary

        out = Path(args.out) if args.out else Path("out") / f"extremes_{scene.name}"
        rows = run_extremes(scene, out, workers=args.workers, threads=args.threads, scheduler=args.scheduler,
                            serial=args.serial, report=report)
        print("\n".join(summary(rows)))
        print(f"wrote {out}/extremes.md, extremes.csv, extremes.json")
        return 0
    vary = {}
    for v in args.vary:
        if "=" not in v:
            raise InputError(f"--vary {v!r}: give KEY.PATH=V1,V2,...")
        key, values = v.split("=", 1)
        if key.strip() in vary:
            raise InputError(f"--vary {key.strip()}: given twice; give all its values in one --vary")
        vary[key.strip()] = [parse_value(x) for x in _split_values(values)]
        if not vary[key.strip()]:
            raise InputError(f"--vary {v!r}: give at least one value")
    tol = None
    if args.tol:
        try:
            tol = float(args.tol[:-1]) / 100 if args.tol.endswith("%") else float(args.tol)
        except ValueError:
            raise InputError(f"--tol {args.tol!r}: give a relative tolerance, e.g. 5% or 0.05") from None
    out = Path(args.out) if args.out else Path("out") / f"study_{scene.name}"

    res = run_study(scene, vary, args.metric, out, reference=args.reference, tol=tol, workers=args.workers,
                    threads=args.threads, scheduler=args.scheduler, serial=args.serial, report=report, yes=args.yes,
                    ask=_ask if sys.stdin.isatty() and not args.yes else None, sets=later)
    print((out / "study.md").read_text())
    print(f"{len(res.rows)} runs in {res.wall_s:.1f} s wall; wrote {out}/study.csv, study.md, study.json, pareto.png")
    return 0


def _line_parser(sub):
    p = sub.add_parser(
        "line",
        help="tabulate and plot one catenary line: H, V, touchdown and state against X",
        description="Solve one quasi-static catenary line (Barreiro et al. 2016, §3) over a range of horizontal "
        "anchor-fairlead distances X and print X, H, V, fairlead tension, touchdown length and state. "
        "Give the line with --length/--weight/--height (and --EA for an elastic line), or --preset.",
    )
    p.add_argument("--preset", choices=sorted(LINE_PRESETS), help="a line of Barreiro et al. 2016, Tables 1-2")
    p.add_argument("--length", type=float, help="unstretched line length L [m]")
    p.add_argument("--weight", type=float, help="submerged weight per unit length w [N/m]")
    p.add_argument("--height", type=float, help="fairlead height above the anchor/seabed h [m]")
    p.add_argument("--EA", type=float, default=None, help="axial stiffness [N]; omit for an inextensible line")
    p.add_argument("--x-range", type=float, nargs=2, metavar=("START", "STOP"), help="range of X [m]")
    p.add_argument("--points", type=int, default=19, help="number of X values (default 19)")
    p.add_argument("--csv", metavar="FILE", help="also write the table as CSV")
    p.add_argument("--png", metavar="FILE", help="also plot H and V against X, state changes marked")
    return p


def _validate_parser(sub):
    p = sub.add_parser(
        "validate",
        help="run validation cases (one JSON object per case), optionally write a report",
        description="Run validation cases of docs/VALIDATION.md; each prints one JSON object "
        "with name, passed, target (what it was judged against), metrics, tolerances, particles, steps, "
        "wall_s and case_cpu_s; passed means every metric named in tolerances is within it, for a quick "
        "variant (its own declared tolerances) as for a full one. Exit status 1 if any fails. Several cases "
        "run at once, one per core (--jobs). --report DIR also writes a report (index.md, index.html, a page "
        "per case with its plots); --from FILE.jsonl builds the report from saved records (the JSON lines "
        "printed here) without running anything.",
    )
    p.add_argument("names", nargs="*", help="case names, or 'all' (with --from: all the file holds)")
    p.add_argument("--list", action="store_true",
                   help="list the cases with the cost (CPU seconds) and status (target met, departure met, not met) of "
                        "their quick and full variants from the records of a report (--from FILE.jsonl, default "
                        "docs/validation/records.jsonl where a checkout has one), and exit")
    p.add_argument("--quick", action="store_true", help="coarse variant (what CI runs)")
    p.add_argument("--long", action="store_true",
                   help="with 'all --quick': also the long cases, whose quick variants take more than 5 CPU-minutes "
                        "each (near-field runs of many periods; marked long in --list), which 'all --quick' leaves out")
    p.add_argument("--jobs", type=int, metavar="N",
                   help="cases run at once, each in a process of its own with cores/N numba threads, the costliest "
                        "first by the committed records; default: as many as the machine has cores (1: one after "
                        "the other in this process)")
    p.add_argument("--report", metavar="DIR", help="also write a report into DIR (records.jsonl, series/, "
                   "index.md, index.html, CASE.md, CASE.html, plots)")
    p.add_argument("--from", dest="from_file", metavar="FILE.jsonl",
                   help="build the --report from saved records instead of running the cases (their plots from "
                   "the series/ folder beside FILE, if there is one)")
    return p


def _export_fmu_parser(sub):
    p = sub.add_parser(
        "export-fmu",
        help="write a scene's mooring lines (catenary) as a standalone FMI 2.0 co-simulation FMU",
        description="Write the quasi-static catenary law (compiled C, no Python needed to run it) as an "
        "FMI 2.0 co-simulation FMU: fairlead positions in, fairlead forces, total force and moment, "
        "tensions and line states out; anchors, lengths, weights and EA are tunable parameters. "
        "The lines come from a scene (cosim export-fmu SCENE.toml [--out FILE.fmu]: its moorings.lines, "
        "the fairleads' start values where the run starts them), or from a TOML or JSON file of lines "
        "(cosim export-fmu FILE.fmu --lines LINES.toml: a list 'line' of tables with anchor [m] (x, z or "
        "x, y, z), length [m], weight [N/m], optional EA [N] (omit: inextensible), name and fairlead "
        "[m] (the input's start value)).",
    )
    p.add_argument("target", help="a scene (.toml, or a .py script that defines `scene`): export its lines; or, "
                                   "with --lines, the .fmu file to write")
    p.add_argument("--out", metavar="FILE.fmu", help="with a scene: the .fmu file to write (default "
                                                     "<scene name>_mooring.fmu)")
    p.add_argument("--set", action="append", default=[], metavar="KEY.PATH=VALUE",
                   help="with a scene: change one of its fields first, as cosim run --set does")
    p.add_argument("--lines", metavar="FILE", help="TOML or JSON file with the lines (instead of a scene)")
    p.add_argument("--model-identifier", default="catenary_mooring", help="FMU model identifier (a C identifier)")
    p.add_argument("--reference", type=float, nargs="+", metavar="C",
                   help="point of the total moment [m] (2 or 3 coordinates; default the origin)")
    p.add_argument("--body-pose", action="store_true",
                   help="inputs are a body pose (3-D x, y, z and quaternion qw, qx, qy, qz; 2-D x, z, theta) and "
                   "each line's 'fairlead' is in the body frame (required); the fairleads become outputs")
    p.add_argument("--sources-only", action="store_true", help="ship the C sources without compiling a binary")
    p.add_argument("--cc", help="C compiler (default $CC, cc, gcc or clang)")
    return p


def _inspect_parser(sub):
    p = sub.add_parser(
        "inspect",
        help="print what an output file (HDF5, fluid.output) holds; write its series as CSV",
        description="Print one JSON object: the file's attributes, each time series (rows, keys and "
        "their widths, time span) and the particle snapshots (count, time span). With --csv DIR, "
        "also write every series as DIR/NAME.csv ('/' in a name becomes '__').",
    )
    p.add_argument("file", help="an .h5 file written by fluid.output.H5Output")
    p.add_argument("--csv", metavar="DIR", help="write every series as a CSV table into DIR")
    return p


def cmd_inspect(args, parser) -> int:
    from pathlib import Path

    from cosim.errors import InputError
    from fluid.output import describe, read_series, read_units, write_csv

    try:
        info = describe(args.file)
    except (OSError, KeyError) as exc:
        raise InputError(f"{args.file} is not an output file of fluid.output.H5Output ({exc})") from None
    print(json.dumps(info, default=_json_default))
    if args.csv:
        folder = Path(args.csv)
        folder.mkdir(parents=True, exist_ok=True)
        for name in info["series"]:
            write_csv(folder / (name.replace("/", "__") + ".csv"), read_series(args.file, name),
                      read_units(args.file, name))
        print(f"wrote {len(info['series'])} CSV tables into {folder}", file=sys.stderr)
    return 0


def _plot_parser(sub):
    p = sub.add_parser(
        "plot",
        help="draw the particles of a run's latest checkpoint (a running, stopped or finished SPH run)",
        description="Draw the particles, bodies, lines and gauges of the run in FOLDER as its checkpoint holds them "
        "(a run writes one every world.checkpoint_wall s of wall time and at its end), as world.plot_at's plots "
        "do: a look at a long run without particle snapshots, or while it goes on.",
    )
    p.add_argument("folder", help="the run's output folder (cosim run --out)")
    p.add_argument("--png", help="the figure's file (default FOLDER/particles_checkpoint_tT.png)")
    return p


def cmd_plot(args, parser) -> int:
    from cosim.scene.runner import plot_checkpoint

    print(f"wrote {plot_checkpoint(args.folder, args.png)}", file=sys.stderr)
    return 0


def _read_lines_file(path):
    """MooringLine records and fairlead start values from a TOML or JSON file."""
    from pathlib import Path

    from cosim.errors import InputError
    from moorings.line import MooringLine

    p = Path(path)
    if not p.is_file():
        raise InputError(f"--lines: no file {path!r}")
    try:
        if p.suffix.lower() == ".toml":
            import tomllib

            data = tomllib.loads(p.read_text())
        else:
            data = json.loads(p.read_text())
    except ValueError as exc:
        raise InputError(f"--lines: cannot parse {path!r}: {exc}") from None
    items = data.get("line", data.get("lines")) if isinstance(data, dict) else data
    if not isinstance(items, list) or not items:
        raise InputError(f"--lines: {path!r} must hold a non-empty list 'line' of tables")
    lines, fairleads = [], []
    allowed = {"anchor", "length", "weight", "EA", "mass_per_length", "diameter", "name", "fairlead"}
    for i, it in enumerate(items):
        if not isinstance(it, dict):
            raise InputError(f"--lines: line {i} must be a table of anchor, length, weight, ...")
        unknown = set(it) - allowed
        if unknown:
            raise InputError(f"--lines: line {i}: unknown key(s) {sorted(unknown)}; known: {sorted(allowed)}")
        missing = {"anchor", "length", "weight"} - set(it)
        if missing:
            raise InputError(f"--lines: line {i}: missing {sorted(missing)}")
        fairleads.append(it.get("fairlead"))
        lines.append(MooringLine(**{k: v for k, v in it.items() if k != "fairlead"}))
    if any(f is None for f in fairleads):
        if any(f is not None for f in fairleads):
            raise InputError("--lines: give a fairlead for every line or for none")
        fairleads = None
    return lines, fairleads


def _scene_lines(args):
    """The lines of the scene ``args.target``, the fairleads' start values (in the body's
    frame with ``--body-pose``, and the body's start pose) and the .fmu to write."""
    from pathlib import Path

    from cosim.errors import InputError
    from cosim.scene.build import fairleads_at_start, mooring_lines
    from cosim.scene.load import load
    from cosim.scene.spec import MJCF

    scene = load(args.target)
    if args.set:
        scene = scene.with_values(args.set)
    if scene.moorings is None:
        raise InputError(f"{args.target}: the scene has no mooring lines (moorings.lines) to export")
    out = Path(args.out) if args.out else Path(f"{scene.name}_mooring.fmu")
    lines, pose = mooring_lines(scene), None
    if not args.body_pose:
        return lines, fairleads_at_start(scene), pose, out
    owners = {ln.fairlead.split(".")[0] for ln in scene.moorings.lines}
    body = next((b for b in scene.bodies if b.name in owners), None)
    if len(owners) > 1 or isinstance(body, MJCF) or getattr(body, "euler", None) is not None:
        raise InputError(f"--body-pose: the scene's lines end on {', '.join(sorted(owners))}; the FMU follows one "
                         f"upright builder body's pose: export without --body-pose (fairlead positions in)")
    fairleads = [body.fairleads[ln.fairlead.split(".")[1]] for ln in scene.moorings.lines]
    start = fairleads_at_start(scene)[0] - fairleads[0]  # the body's origin where the run starts it
    pose = list(start) + ([0.0] if scene.world.dim == 2 else [1.0, 0.0, 0.0, 0.0])
    return lines, fairleads, pose, out


def cmd_export_fmu(args, parser) -> int:
    import os

    from fmpy.validation import validate_fmu

    from moorings.fmu_export import export_catenary_fmu

    pose = None
    if args.lines:
        if args.out or args.set:
            parser.error("--out and --set go with a scene; with --lines the first argument is the .fmu to write")
        (lines, fairleads), output = _read_lines_file(args.lines), args.target
    elif args.target.endswith((".toml", ".py")):
        lines, fairleads, pose, output = _scene_lines(args)
    else:
        parser.error(f"{args.target}: give a scene (.toml or .py), or the .fmu to write with --lines FILE")
    path = export_catenary_fmu(lines, output, fairleads=fairleads, reference_point=args.reference,
                               body_pose=args.body_pose, pose=pose, model_identifier=args.model_identifier,
                               compile_binary=not args.sources_only, cc=args.cc)
    problems = validate_fmu(str(path))
    kind = "sources only" if args.sources_only else "sources and a linux64 binary"
    print(f"wrote {path} ({os.path.getsize(path)} bytes, {len(lines)} line(s), {lines[0].dim}-D, {kind})")
    for pr in problems:
        print(f"validation problem: {pr}")
    print("fmpy.validate_fmu: " + ("passed" if not problems else f"{len(problems)} problem(s)"))
    return 1 if problems else 0


def _line_args(args, parser):
    preset = LINE_PRESETS.get(args.preset, {})
    vals = {}
    for key in ("length", "weight", "height", "x_range"):
        v = getattr(args, key)
        vals[key] = v if v is not None else preset.get(key)
        if vals[key] is None:
            parser.error(f"--{key.replace('_', '-')} is required (or give --preset)")
    if args.points < 2:
        parser.error("--points must be at least 2")
    return vals


def state_changes(X, states, h, L, w, EA):
    """Exact X [m] of each state change within the sampled range, found by
    bisecting on the state that :func:`moorings.catenary.solve` reports (several
    changes between two samples included)."""
    from moorings.catenary import LineState, solve

    out = []
    for i in range(len(X) - 1):
        a, b = float(X[i]), float(X[i + 1])
        current = LineState(states[i])
        while current != states[i + 1]:
            lo, hi = a, b  # first X in (lo, hi] where the state is no longer `current`
            while True:
                m = 0.5 * (lo + hi)
                if m in (lo, hi):
                    break
                lo, hi = (m, hi) if solve(m, h, L, w, EA).state == current else (lo, m)
            new = solve(hi, h, L, w, EA).state
            out.append((hi, current, new))
            a, current = hi, new
    return out


def _plot_line(path, X, r, changes, title, line):
    """H and V against X: a dense curve, the table's points, the state changes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from moorings.catenary import solve

    Xd = np.linspace(X[0], X[-1], 600)
    d = solve(Xd, *line)
    fin, find = np.isfinite(r.H), np.isfinite(d.H)
    peak = max(np.max(d.H[find], initial=0.0), np.max(d.V[find], initial=0.0))
    unit, scale = next((u, s) for u, s in (("MN", 1e6), ("kN", 1e3), ("N", 1.0)) if peak >= 10 * s or s == 1.0)
    fig, ax = plt.subplots(figsize=(7, 4.2), dpi=120)
    ax.plot(Xd[find], d.H[find] / scale, "-", color="C0", label=f"H (horizontal) [{unit}]")
    ax.plot(Xd[find], d.V[find] / scale, "--", color="C1", label=f"V (vertical) [{unit}]")
    ax.plot(X[fin], r.H[fin] / scale, "o", color="C0", ms=3)
    ax.plot(X[fin], r.V[fin] / scale, "o", color="C1", ms=3)
    for x, _, new in changes:
        ax.axvline(x, color="0.5", lw=0.8, ls=":")
        ax.annotate(f"{new.name.lower().replace('_', ' ')} at {x:.4g} m", (x, 0.98),
                    xycoords=("data", "axes fraction"), rotation=90, va="top", ha="right", fontsize=8, color="0.3")
    ax.set_xlabel("X, horizontal anchor–fairlead distance [m]")
    ax.set_ylabel(f"tension at the fairlead [{unit}]")
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def cmd_line(args, parser) -> int:
    import numpy as np

    from moorings.catenary import LineState, solve

    v = _line_args(args, parser)
    L, w, h, EA = v["length"], v["weight"], v["height"], args.EA
    X = np.linspace(*v["x_range"], args.points)
    r = solve(X, h, L, w, EA)
    T = np.hypot(r.H, r.V)
    kind = "inextensible" if EA is None else f"EA = {EA:g} N"
    title = f"catenary line: L = {L:g} m, w = {w:g} N/m, h = {h:g} m, {kind}"
    print(title)
    print(f"{'X [m]':>12} {'H [N]':>14} {'V [N]':>14} {'T [N]':>14} {'touchdown [m]':>14}  state")
    for i in range(X.size):
        print(f"{X[i]:12.6g} {r.H[i]:14.6g} {r.V[i]:14.6g} {T[i]:14.6g} {r.touchdown[i]:14.6g}  "
              f"{LineState(r.state[i]).name}")
    changes = state_changes(X, r.state, h, L, w, EA)
    for x, old, new in changes:
        print(f"state change {old.name} -> {new.name} at X = {x:.9g} m")
    if (r.state == LineState.TAUT).any() and EA is None:
        print("TAUT inextensible line: no catenary exists (H = V = inf); give --EA for an elastic line")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("X [m],H [N],V [N],T [N],touchdown [m],state\n")
            for i in range(X.size):
                nums = (X[i], r.H[i], r.V[i], T[i], r.touchdown[i])
                f.write(",".join(repr(float(v)) for v in nums) + f",{LineState(r.state[i]).name}\n")
        print(f"wrote {args.csv}")
    if args.png:
        _plot_line(args.png, X, r, changes, title, (h, L, w, EA))
        print(f"wrote {args.png}")
    return 0


def cmd_validate(args, parser) -> int:
    from pathlib import Path

    from cosim import validation

    known = validation.cases()
    if args.list:
        from cosim import report

        path = Path(args.from_file) if args.from_file else validation.committed_records()
        records = report.read_records(path) if path.is_file() else None
        if args.from_file and records is None:
            parser.error(f"--from {args.from_file}: no such file")
        print("\n".join(validation.listing(records, str(path))))
        return 0
    if args.from_file:
        from cosim import report

        if not args.report:
            parser.error("--from builds a report: name its folder with --report DIR")
        records = report.read_records(args.from_file)
        if args.names and args.names != ["all"]:
            records = [r for r in records if r["name"] in args.names]
        if not records:
            parser.error(f"no records to report in {args.from_file}")
        report.write_report(args.report, records, series_from=Path(args.from_file).parent / "series",
                            source=args.from_file)
        print(f"wrote {Path(args.report) / 'index.md'} ({len(records)} case(s))", file=sys.stderr)
        return 0 if all(r["passed"] for r in records) else 1
    names = list(known) if args.names == ["all"] else args.names
    if not names:
        parser.error("name a case (see --list), or 'all'")
    if args.long and not (args.quick and args.names == ["all"]):
        parser.error("--long goes with 'all --quick': it adds the long cases' quick variants, which 'all --quick' "
                     "leaves out (a case named runs whatever its tier; 'all' without --quick runs every case)")
    if args.quick and args.names == ["all"] and not args.long:
        names, left = validation.quick_tier()
        print(f"all --quick: {len(names)} cases; left out, as long (quick variants beyond "
              f"{validation.LONG_QUICK_S / 60:.0f} CPU-minutes each): {', '.join(left)}; add --long for them too",
              file=sys.stderr)
    unknown = [n for n in names if n not in known]
    if unknown:
        parser.error(f"unknown case(s) {', '.join(unknown)}; known: {', '.join(known)}")
    if args.jobs is not None and args.jobs < 1:
        parser.error(f"--jobs {args.jobs}: give at least 1 (cases run at once)")
    ok = True
    records = []
    from cosim import report

    if args.report:
        report.prepare(args.report)
    committed = validation.committed_records()
    costs = {r["name"]: r["wall_s"] for r in (report.read_records(committed) if committed.is_file() else [])
             if bool(r.get("quick")) == args.quick and r.get("wall_s") is not None}
    jobs = args.jobs or validation.cores()
    for rec in validation.run_many(names, quick=args.quick, jobs=jobs, costs=costs):
        ok &= rec["passed"]
        line = json.dumps({k: v for k, v in rec.items() if k != "series"}, default=_json_default)
        print(line, flush=True)
        if args.report:
            report.save_record(args.report, rec, line)
            records.append(json.loads(line))
    if args.report:
        report.write_report(args.report, records, source=Path(args.report) / report.RECORDS)
        print(f"wrote {Path(args.report) / 'index.md'} ({len(records)} case(s))", file=sys.stderr)
    return 0 if ok else 1


def _json_default(o):
    import numpy as np

    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, float) and not math.isfinite(o):
        return str(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised as an interrupt so that a run ends as it does on Ctrl-C: its outputs so
    far written, its temporary folders removed, its participants closed."""

    signum = signal.SIGTERM


def _terminate(signum, frame):
    raise Terminated(f"signal {signum}")


def build_parser() -> tuple[argparse.ArgumentParser, dict]:
    """The ``cosim`` parser and its subcommands' parsers, by command."""
    parser = argparse.ArgumentParser(prog="cosim", description=__doc__.strip().splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    parsers = {"run": _run_parser(sub), "study": _study_parser(sub), "line": _line_parser(sub),
               "validate": _validate_parser(sub), "export-fmu": _export_fmu_parser(sub), "inspect": _inspect_parser(sub),
               "plot": _plot_parser(sub)}
    return parser, parsers


def main(argv=None) -> int:
    parser, parsers = build_parser()
    args = parser.parse_args(argv)
    handler = {"run": cmd_run, "study": cmd_study, "line": cmd_line, "validate": cmd_validate,
               "export-fmu": cmd_export_fmu, "inspect": cmd_inspect, "plot": cmd_plot}[args.command]
    main_thread = threading.current_thread() is threading.main_thread()
    before = signal.signal(signal.SIGTERM, _terminate) if main_thread else None
    try:
        return handler(args, parsers[args.command])
    except CosimError as exc:
        print(f"cosim {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        signum = getattr(exc, "signum", signal.SIGINT)
        print(f"cosim {args.command}: interrupted ({signal.Signals(signum).name})", file=sys.stderr)
        return 128 + signum
    finally:
        if main_thread:
            signal.signal(signal.SIGTERM, before)


if __name__ == "__main__":
    sys.exit(main())
