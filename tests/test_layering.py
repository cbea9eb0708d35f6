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


def test_solver_packages_import_only_cosim_errors():
    offenders = []
    for pkg in ("fluid", "bodies", "moorings"):
        for path in (ROOT / pkg).rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text())):
                names = []
                if isinstance(node, ast.ImportFrom) and node.module:
                    names = [node.module]
                elif isinstance(node, ast.Import):
                    names = [a.name for a in node.names]
                for n in names:
                    if (n == "cosim" or n.startswith("cosim.")) and n != "cosim.errors":
                        offenders.append(f"{path.relative_to(ROOT)} imports {n}")
    assert not offenders, offenders


def test_no_script_shadows_a_package():
    """A script's folder comes first on sys.path: benchmarks/fluid.py would hide
    the fluid package from every other benchmark (it did, twice)."""
    packages = {"cosim", "fluid", "bodies", "moorings"}
    for folder in ("benchmarks", "examples"):
        clash = sorted(p.name for p in (ROOT / folder).glob("*.py") if p.stem in packages)
        assert not clash, f"{folder}/{clash} shadows a package; rename it"
