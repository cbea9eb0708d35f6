"""A scene pays only for what it uses; imports run downwards only (DESIGN.md)."""

import ast
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_solvers_do_not_import_mujoco():
    code = (
        "import sys, moorings, fluid, moorings.catenary, moorings.catenary_mooring\n"
        "from moorings import CatenaryMooring\n"
        "assert 'mujoco' not in sys.modules, 'mujoco was imported'\n"
        "assert 'cosim.coupler' not in sys.modules\n"
        "print('ok')"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "ok"


def _imported_modules(path):
    """Every module an ``import`` or ``from ... import`` in the file names, lazy ones inside
    functions included (a relative import names its package's own modules: skipped)."""
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            yield node.module
        elif isinstance(node, ast.Import):
            yield from (a.name for a in node.names)


def test_solver_packages_never_import_cosim():
    """fluid, bodies and moorings sit below the coupler: not even cosim.errors (their errors
    come from the top-level errors module)."""
    files = [p for pkg in ("fluid", "bodies", "moorings") for p in (ROOT / pkg).rglob("*.py")]
    assert len(files) > 40  # the scan sees the packages, not an empty folder
    offenders = [f"{path.relative_to(ROOT)} imports {n}" for path in files
                 for n in _imported_modules(path) if n == "cosim" or n.startswith("cosim.")]
    assert not offenders, offenders


def test_the_ground_errors_module_imports_nothing_of_the_project():
    names = set(_imported_modules(ROOT / "errors.py"))
    assert not {n.split(".")[0] for n in names} & {"cosim", "fluid", "bodies", "moorings"}, names


def test_cosim_errors_are_the_ground_classes():
    """User code catching cosim.errors.InputError catches what fluid raises: one class."""
    import cosim
    import cosim.errors
    import errors

    names = ["CosimError", "InputError", "ConfigurationError", "ProtocolError", "SolverError",
             "InstabilityError", "ConvergenceError", "TautLineError"]
    for name in names:
        assert getattr(cosim.errors, name) is getattr(errors, name) is getattr(cosim, name), name
    assert issubclass(errors.TautLineError, errors.SolverError)
    assert issubclass(errors.InputError, ValueError)


def test_no_script_shadows_a_package():
    """A script's folder comes first on sys.path: benchmarks/fluid.py would hide
    the fluid package from every other benchmark (it did, twice)."""
    packages = {"cosim", "fluid", "bodies", "moorings"}
    for folder in ("benchmarks", "examples"):
        clash = sorted(p.name for p in (ROOT / folder).glob("*.py") if p.stem in packages)
        assert not clash, f"{folder}/{clash} shadows a package; rename it"
