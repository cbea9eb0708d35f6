"""The README as a user meets it: its Python runs as written, its cheap shell commands run
(the costly ones parse: their flags, the scene they name and its --set values), and the
Python of the pages moved out of it runs too. Each in a scratch folder: they write outputs."""

import re
import shlex
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
#: the pages that took the README's longer sections, with their Python
PAGES = [ROOT / "docs" / name for name in ("coupling.md", "fluid.md", "moorings.md")]


def blocks(path: Path, lang: str) -> list[str]:
    return re.findall(rf"```{lang}\n(.*?)```", path.read_text(), flags=re.S)


def commands(path: Path) -> list[list[str]]:
    """Every command of the shell blocks, split at ``&&``, comments dropped."""
    out = []
    for block in blocks(path, "sh"):
        for line in block.replace("\\\n", " ").splitlines():
            line = line.split(" #", 1)[0].strip()
            out += [shlex.split(c) for c in line.split("&&") if c.strip()]
    return out


def _run_python(path: Path, tmp_path, monkeypatch) -> dict:
    monkeypatch.chdir(tmp_path)
    ran = {}
    for code in blocks(path, "python"):
        namespace = {}
        exec(compile(code, str(path), "exec"), namespace)  # noqa: S102 - our own pages
        ran.update(namespace)
    return ran


def test_readme_python_runs(tmp_path, monkeypatch):
    ran = _run_python(README, tmp_path, monkeypatch)
    # the scene ran its 20 s into its folder, and its TOML reads back as the same scene
    assert ran["results"].t[-1] == 20.0 and (tmp_path / "out" / "moored_box" / "summary.json").is_file()
    assert ran["scene"].from_dict(tomllib.loads(ran["toml"])) == ran["scene"]
    assert ran["results"].units["box.left.tension"] == "N"


@pytest.mark.long
def test_pages_python_runs(tmp_path, monkeypatch):
    ran = {}
    for page in PAGES:
        ran |= _run_python(page, tmp_path, monkeypatch)
    # the hand-wired coupled-scene snippet ran its 20 s and booked every step
    assert ran["coupler"].t == 20.0 and len(ran["coupler"].ledger) == ran["coupler"].steps
    # the wave set-up's tank settled with its clock held at 0
    assert ran["f"].t == 0.0 and ran["f"].max_speed() < 0.05
    # the catenary law: Barreiro et al. 2016's line partly lifted at 5.5 and 6 m, past its lift-off (6.288 m) at 6.4 m
    assert ran["r"].state.tolist() == [1, 1, 2] and ran["r"].H.shape == (3,)


def _absolute(args: list[str]) -> list[str]:
    """Arguments that name a file of the checkout, made absolute (the commands run elsewhere)."""
    return [str(ROOT / a) if (ROOT / a).is_file() and not Path(a).is_absolute() else a for a in args]


def test_readme_commands_run_or_parse(tmp_path, monkeypatch, capsys):
    """`pip install` names extras the project has; the two `python -m pytest` commands are
    what CI runs and select the tiers (test_readme_test_commands_select_their_tiers); `cosim
    run` parses and its scene loads with its --set values (a run costs 30 s); `cosim line`,
    `cosim export-fmu` and `cosim validate --list` run, writing what they say."""
    from cosim.cli import build_parser, main
    from cosim.scene.load import load

    cmds = commands(README)
    assert ["python", "-m", "pytest"] in cmds and ["cosim", "run", "examples/moored_box_waves.toml"] in cmds
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    monkeypatch.chdir(tmp_path)
    seen = set()
    for cmd in cmds:
        if cmd[:2] == ["pip", "install"]:
            spec = cmd[-1]
            assert cmd[2] == "-e" and spec.split("[")[0] == "."
            assert all(e in extras for e in re.findall(r"\[(.*)\]", spec)[0].split(",")) if "[" in spec else True
        elif cmd[0] == "python":
            assert cmd in TEST_COMMANDS, cmd
        elif cmd[:2] == ["cosim", "run"]:
            args = build_parser()[0].parse_args(_absolute(cmd[1:]))
            scene = load(args.scene)
            assert scene.with_values(args.set) is not None and args.out is None
        else:
            assert cmd[0] == "cosim", cmd
            if cmd[1] == "export-fmu" and shutil.which("cc") is None and shutil.which("gcc") is None:
                continue
            assert main(_absolute(cmd[1:])) == 0, cmd
            out = capsys.readouterr().out
            if "--png" in cmd:
                assert (tmp_path / cmd[cmd.index("--png") + 1]).read_bytes()[:4] == b"\x89PNG"
            if cmd[1] == "export-fmu":
                assert (tmp_path / cmd[cmd.index("--out") + 1]).stat().st_size > 0 and "passed" in out
            if cmd[1:3] == ["validate", "--list"]:
                assert "catenary-limits" in out
        seen.add(" ".join(cmd[:2]))
    assert {"cosim line", "cosim export-fmu", "cosim validate"} <= seen


#: the README's test commands: the fast tier, then the long one
TEST_COMMANDS = [["python", "-m", "pytest"], ["python", "-m", "pytest", "-m", "long"]]


@pytest.mark.long
def test_readme_test_commands_select_their_tiers():
    """Each test command of the README is one `.ci/run` runs, and, run (collecting only) on
    the hydrostatic validations and the links' momentum test, selects its tier: the fast one
    the 2-D hydrostatic case and the 2-D links, the long one the 3-D links, neither the slow
    hydrostatic ones (3-D, full; `-m long` replaces the addopts' `-m`)."""
    assert [c for c in commands(README) if c[0] == "python"] == TEST_COMMANDS
    ci = (ROOT / ".ci" / "run").read_text()
    for cmd in TEST_COMMANDS:
        assert re.search(rf"^(.* && )?{' '.join(cmd)}( \|\||$)", ci, flags=re.M), cmd
    links = "test_momentum_lost_by_the_fluid_is_what_the_links_receive_to_round_off"
    expected = [{"test_hydrostatic_quick[hydrostatic]", f"{links}[2-300]"}, {f"{links}[3-20]"}]
    for cmd, tests in zip(TEST_COMMANDS, expected):
        # -n 0: collected in this process, not in the addopts' two workers (the selection is the same)
        out = subprocess.run([sys.executable, *cmd[1:], "--collect-only", "-q", "-n", "0",
                              "tests/test_fluid_hydrostatic.py", "tests/test_elastic_coupling.py",
                              "-k", "hydrostatic_quick or momentum_lost"],
                             cwd=ROOT, capture_output=True, text=True, timeout=300)
        assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
        assert {ln.split("::")[1] for ln in out.stdout.splitlines() if "::" in ln} == tests, (cmd, out.stdout)


def test_readme_is_short_and_starts_with_the_commands():
    """A user reaches the first command after one paragraph; the long figures live in docs/."""
    lines = README.read_text().splitlines()
    first = next(i for i, ln in enumerate(lines) if ln.startswith("pip install"))
    assert first < 20 and len(lines) < 150
    for link in re.findall(r"\]\((docs/[^)#]+)", README.read_text()):
        assert (ROOT / link).is_file(), link


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_pages_link_to_files_that_exist(page):
    for link in re.findall(r"\]\(([^)#:]+)", page.read_text()):
        assert (page.parent / link).exists(), (page.name, link)


def test_the_quick_validations_cost_is_the_records():
    """The README's cost of `cosim validate all --quick` is what the committed records say
    (each variant's CPU as `cosim validate --list` counts it, `cosim.validation.cost`): the
    quick tier's cases, their total and minutes on 2 cores, the long cases it leaves out
    and what `--long` makes of the whole."""
    from cosim import validation
    from cosim.report import read_records

    text = " ".join(README.read_text().split())
    m = re.search(r"runs the quick tier, one case per core \(`--jobs`\): (\d+) cases whose records' CPU is about "
                  r"([\d ]+) s, so about (\d+) minutes on 2 cores \(from a fresh clone[^)]*\)\)\. "
                  r"It leaves out the (\w+) long cases \(quick variants beyond (\d+) CPU-minutes each: ([^)]*), "
                  r"about ([\d ]+) s\), which `--long` adds \(about (\d+) minutes on 2 cores in all\)", text)
    assert m, "the README's sentence on the quick validations' cost"
    count, total, minutes, n_long, bound, names, long_total, all_minutes = m.groups()
    quick = {r["name"]: validation.cost(r) for r in read_records(validation.committed_records()) if r.get("quick")}
    tier, long = validation.quick_tier()
    number = {"two": 2, "three": 3, "four": 4, "five": 5}
    assert int(count) == len(tier) and number[n_long] == len(long) and float(bound) * 60 == validation.LONG_QUICK_S
    assert sorted(re.split(r", | and ", names)) == sorted(long)
    seconds = sum(quick[n] for n in tier)
    assert float(total.replace(" ", "")) == pytest.approx(seconds, rel=0.02)
    assert float(minutes) == pytest.approx(seconds / 2 / 60, abs=1.0)
    assert float(long_total.replace(" ", "")) == pytest.approx(sum(quick[n] for n in long), rel=0.02)
    assert float(all_minutes) == pytest.approx(sum(quick.values()) / 2 / 60, abs=1.0)