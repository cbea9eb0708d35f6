"""What the code states, checked: papers cited by author and year, never by the seeds' file
names (those files are not in the repository); docstrings of at most 40 lines; no dates,
machine (CPU) names or machine loads in docstrings or comments, since measured figures,
dates, machines and histories belong in docs/."""

import ast
import io
import re
import tokenize
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("fluid", "bodies", "moorings", "cosim", "benchmarks")
MAX_DOCSTRING_LINES = 40

SEED_FILE = re.compile(r"[0-9]{3}_[0-9a-f]{16}")
DATE = re.compile(r"20\d\d-\d\d-\d\d")
CPU = re.compile(r"\b(EPYC|Xeon|Ryzen|Emerald|Zen)\b")
# the machine's load ("2 cores shared with two other jobs", "load average 2-3.5")
LOAD = re.compile(r"other jobs|load average|cores shared|\d-core machine")


def _python_files(folders):
    for folder in folders:
        yield from sorted((ROOT / folder).rglob("*.py"))


def _package_files():
    return [ROOT / "errors.py", *_python_files(PACKAGES)]


def _docstrings(path):
    """(name, first line, text) of the module's, each class's and each function's docstring."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            text = ast.get_docstring(node, clean=False)
            if text is not None:
                yield getattr(node, "name", "<module>"), node.body[0].lineno, text


def _comments(path):
    source = path.read_text(encoding="utf-8")
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT:
            yield tok.start[0], tok.string


def _where(path, line):
    return f"{path.relative_to(ROOT)}:{line}"


def test_the_scan_sees_the_packages():
    files = _package_files()
    assert len(files) > 100, len(files)
    assert sum(1 for f in files for _ in _docstrings(f)) > 1000


def test_no_seed_file_name_in_any_python_file():
    """Cite "Barreiro et al. 2016, Eq. 39", not the name of the file the paper came in."""
    files = [p for p in ROOT.rglob("*.py") if not {".git", ".venv", "venv"} & set(p.parts)]
    hits = [f"{_where(p, i)}: {line.strip()[:80]}" for p in files
            for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1) if SEED_FILE.search(line)]
    assert not hits, "seed file names in code (cite author, year and equation):\n" + "\n".join(hits)


def test_no_docstring_longer_than_40_lines():
    long = [f"{_where(p, line)} {name}: {text.count(chr(10)) + 1} lines"
            for p in _package_files() for name, line, text in _docstrings(p)
            if text.count("\n") + 1 > MAX_DOCSTRING_LINES]
    assert not long, ("docstrings over 40 lines (state what, why, units, limits and the reference; "
                      "move measured tables and histories to docs/):\n" + "\n".join(long))


def test_no_date_machine_or_load_in_docstrings_or_comments():
    hits = []
    for p in _package_files():
        for name, line, text in _docstrings(p):
            hits += [f"{_where(p, line)} {name}: {m.group()}" for rx in (DATE, CPU, LOAD) for m in rx.finditer(text)]
        for line, text in _comments(p):
            hits += [f"{_where(p, line)}: {m.group()}" for rx in (DATE, CPU, LOAD) for m in rx.finditer(text)]
    assert not hits, "dates, CPU names or the machine's load in code (they belong in docs/):\n" + "\n".join(hits)


@pytest.mark.parametrize("text, bad", [
    ("Measured 2026-11-26 on AMD EPYC (Zen 4)", True),
    ("Intel Xeon (Emerald Rapids)", True),
    ("2 cores shared with two other jobs", True),
    ("Barreiro et al. 2016, Eq. 39", False),
    ("the zenith angle, 1.5e-3 s", False),
])
def test_the_patterns_catch_what_they_are_for(text, bad):
    assert bool(DATE.search(text) or CPU.search(text) or LOAD.search(text) or SEED_FILE.search(text)) is bad
    assert bool(SEED_FILE.search("004_" + "1657bd4a51d29840" + ".txt"))
