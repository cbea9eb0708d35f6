"""The project stands on its own: nothing reads a folder beside the checkout, every
reference file the code names ships in the package (cosim/refdata), and a
non-editable install carries it."""

import ast
import re
import tomllib
from pathlib import Path

import pytest

from cosim import refdata
from cosim.errors import InputError
from cosim.refdata import path as shipped  # not "refdata.path": the scan below would read our calls

ROOT = Path(__file__).resolve().parents[1]
SOURCE_DIRS = ("cosim", "fluid", "bodies", "moorings", "tests", "benchmarks", "examples")
BINARY = {".gz", ".pyc", ".so", ".dll", ".dylib", ".fmu", ".h5", ".png", ".ods", ".zip"}

# Paths built into the sibling folder the project was specified in. Written so that
# this file's own text matches none of them (it is scanned too).
# The examples each one catches are in test_the_scan_catches_a_path_into_a_sibling_folder.
SIBLING = (
    re.compile(r"\.\./+shared\b"),  # a relative path up and into it
    re.compile(r"""shared["']?\s*/+\s*["']?refdata"""),  # its refdata, as one string or joined
    re.compile(r"""(?:/|joinpath\(|join\([^)]*,)\s*["']shared["']"""),  # joined onto a parent folder
    re.compile(r"""["']shared/"""),  # a string path starting with it
)


def _files(suffix=None):
    for d in SOURCE_DIRS:
        for p in sorted((ROOT / d).rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts and p.suffix not in BINARY \
                    and (suffix is None or p.suffix == suffix):
                yield p


@pytest.mark.parametrize("text", [
    "REFDATA = Path(__file__).resolve().parents[3] / '{sh}' / 'refdata'",
    'REFDATA = Path(__file__).resolve().parents[2] / "{sh}" / "refdata" / "cable_static_dynamic"',
    'FLAP = Path(__file__).parents[2] / "{sh}/refdata/floating_box_waves_hadzic2005/Flap.dat"',
    'HERE.parent.parent / "{sh}" / "VALIDATION.md"',
    'os.path.join(root, "..", "{sh}", "DESIGN.md")',
    "help='cases of ../{sh}/VALIDATION.md'",
])
def test_the_scan_catches_a_path_into_a_sibling_folder(text):
    assert any(p.search(text.format(sh="sha" + "red")) for p in SIBLING)


@pytest.mark.parametrize("text", [
    "reference data copied from the shared refdata collection",
    'cmd = [cc, "-O2", "-shared", "-fPIC"]',
    "a core shared with two other runs",
])
def test_the_scan_passes_prose_and_compiler_flags(text):
    assert not any(p.search(text) for p in SIBLING)


def test_no_source_reads_a_folder_beside_the_checkout():
    hits = []
    for path in _files():
        for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if any(p.search(line) for p in SIBLING):
                hits.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert not hits, "paths outside the checkout (use cosim.refdata.path, docs/):\n" + "\n".join(hits)


# -- every cosim.refdata.path(...) in the source names a file that ships ----------------------------

def _is_refdata_path(func, imported_path: bool) -> bool:
    if isinstance(func, ast.Attribute) and func.attr == "path":
        v = func.value
        return (isinstance(v, ast.Name) and v.id == "refdata") or \
            (isinstance(v, ast.Attribute) and v.attr == "refdata")
    return imported_path and isinstance(func, ast.Name) and func.id == "path"


def _refdata_reads():
    """(files, problems): the (dataset, name) pairs that the source's calls of
    refdata.path name, with literal strings, module-level string constants, or through
    a one-line wrapper ``def f(name): ... refdata.path("dataset", name)`` called with a
    literal, and that the scene files name by a path into cosim/refdata; problems lists the
    calls that cannot be checked that way."""
    files, problems, wrappers, calls_of = set(), [], {}, []
    for path in _files(".py"):
        tree = ast.parse(path.read_text())
        nodes = list(ast.walk(tree))  # one walk of each file: walking again per call costs minutes
        calls = [n for n in nodes if isinstance(n, ast.Call)]
        calls_of.append((path, calls))
        imported = any(isinstance(n, ast.ImportFrom) and n.module == "cosim.refdata"
                       and any(a.name == "path" and a.asname is None for a in n.names) for n in nodes)
        reads = [c for c in calls if _is_refdata_path(c.func, imported)]
        if not reads:
            continue
        consts = {t.id: n.value.value for n in tree.body if isinstance(n, ast.Assign)
                  for t in n.targets if isinstance(t, ast.Name)
                  and isinstance(n.value, ast.Constant) and isinstance(n.value.value, str)}
        params = {}  # call node -> parameter names of the innermost function around it
        for fn in nodes:
            if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
                for c in ast.walk(fn):
                    params[c] = (fn.name, [a.arg for a in fn.args.args])

        def value(node):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                return node.value
            if isinstance(node, ast.Name) and node.id in consts:
                return consts[node.id]
            return None

        for call in reads:
            where = f"{path.relative_to(ROOT)}:{call.lineno}"
            args = list(call.args) + [k.value for k in call.keywords]
            ds = value(args[0]) if args else None
            name = value(args[1]) if len(args) > 1 else ""
            if ds is None:
                problems.append(f"{where}: dataset not a literal")
            elif name is not None:
                files.add((ds, name))
            elif isinstance(args[1], ast.Name) and call in params and args[1].id in params[call][1]:
                fname, names = params[call]
                wrappers[fname] = (ds, names.index(args[1].id), args[1].id, where)
            else:
                problems.append(f"{where}: file name not a literal")
    for fname, (ds, i, pname, where) in wrappers.items():
        used = 0
        for path, calls in calls_of:
            for call in calls:
                f = call.func
                if not ((isinstance(f, ast.Name) and f.id == fname) or (isinstance(f, ast.Attribute) and f.attr == fname)):
                    continue
                arg = call.args[i] if len(call.args) > i else next((k.value for k in call.keywords if k.arg == pname), None)
                if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                    files.add((ds, arg.value))
                    used += 1
                else:
                    problems.append(f"{path.relative_to(ROOT)}:{call.lineno}: {fname}(...) without a literal name")
        if not used:
            problems.append(f"{where}: wrapper {fname} is never called with a literal")
    for path in _files(".toml"):  # a scene file names a record by its path relative to itself
        for m in re.finditer(r'"([^"]*)"', path.read_text()):
            target, root = (path.parent / m.group(1)).resolve(), refdata.ROOT.resolve()
            if target.is_relative_to(root) and len(target.relative_to(root).parts) > 1:
                parts = target.relative_to(root).parts
                files.add((parts[0], "/".join(parts[1:])))
    return files, problems


def test_every_refdata_file_named_in_the_source_ships_and_every_shipped_one_is_read():
    files, problems = _refdata_reads()
    assert not problems, problems
    assert len(files) >= 10, files  # the scan found the readers
    missing = []
    for ds, name in sorted(files):
        try:
            shipped(ds, name)
        except InputError as e:
            missing.append(str(e))
    assert not missing, missing
    packaged = {(p.relative_to(refdata.ROOT).parts[0], "/".join(p.relative_to(refdata.ROOT).parts[1:]))
               for p in refdata.ROOT.rglob("*") if p.is_file() and len(p.relative_to(refdata.ROOT).parts) > 1
               and p.name != "SOURCE.txt" and "__pycache__" not in p.parts}
    assert packaged - files == set(), "shipped but read by nothing (drop it, or read it)"


def test_each_dataset_has_its_source():
    assert refdata.datasets(), "no dataset under cosim/refdata"
    for ds in refdata.datasets():
        source = shipped(ds, "SOURCE.txt")
        assert len(source.read_text(errors="replace").strip()) > 100, source
    assert (refdata.ROOT / "README.md").is_file()


def test_a_missing_dataset_or_file_is_named_with_what_exists():
    with pytest.raises(InputError, match="no dataset 'nope'.*sloshing_spheric_test10"):
        shipped("nope")
    with pytest.raises(InputError, match="no file 'x.csv'.*moorpy_catenary_test_vectors.csv"):
        shipped("cable_static_dynamic", "x.csv")
    with pytest.raises(InputError, match="no absolute paths"):
        shipped("cable_static_dynamic", "../README.md")
    assert shipped("cable_static_dynamic").is_dir()


def test_a_non_editable_install_carries_the_reference_data():
    """pyproject's package list and package data cover cosim.refdata and every file in it,
    and its module list the top-level errors module
    (setuptools' globs: ``*`` does not cross a folder)."""
    from setuptools import find_packages

    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    find = cfg["packages"]["find"]
    assert find.get("namespaces") is False
    packages = find_packages(str(ROOT), include=find["include"])
    assert {"cosim", "cosim.refdata", "cosim.validations", "fluid", "bodies", "moorings"} <= set(packages)
    assert cfg["py-modules"] == ["errors"]  # the ground module the solver packages import
    covered = {p for pattern in cfg["package-data"]["cosim.refdata"] for p in refdata.ROOT.glob(pattern) if p.is_file()}
    data = {p for p in refdata.ROOT.rglob("*") if p.is_file() and p.suffix not in (".py", ".pyc")}
    assert data - covered == set()
