"""No import circles in cosim/: the CLI reads the report, the report reads the cases, never back.

Every import of a ``cosim`` module counts, at module level or inside a function (the
project imports lazily to keep ``import cosim`` light, and a lazy import closes a circle
just the same when it runs), and so does a module imported by name: the validation
runner's ``CASE_MODULES`` and any ``importlib.import_module("cosim....")``.
"""

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: The one circle allowed: the scene's specification (``spec``) gives its dataclasses
#: convenience methods (``Scene.run``, ``Scene.from_toml``, ``validate``, ``participant``)
#: that import the modules doing the work, and those modules import the specification's
#: classes; ``build`` and ``spec`` import each other. Breaking it means moving those
#: methods out of ``spec.py`` and ``build.py`` (the scene's public API, changed by others
#: at the time of writing). The knot may shrink; it may not grow or take in a new module.
SCENE_KNOT = {f"cosim.scene.{m}" for m in ("build", "checks", "cost", "nearfield", "plausible", "plots", "probes",
                                          "runner", "setup", "spec", "timing", "toml_io")}


def _modules() -> dict[str, Path]:
    out = {}
    for path in (ROOT / "cosim").rglob("*.py"):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


def _named_modules(node: ast.AST) -> list[str]:
    """Module names a node imports by name: ``CASE_MODULES = (...)``, ``import_module("...")``."""
    if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "CASE_MODULES" for t in node.targets):
        return [e.value for e in ast.walk(node.value) if isinstance(e, ast.Constant) and isinstance(e.value, str)]
    if (isinstance(node, ast.Call) and getattr(node.func, "attr", getattr(node.func, "id", None)) == "import_module"
            and node.args and isinstance(node.args[0], ast.Constant)):
        return [node.args[0].value]
    return []


def import_graph() -> dict[str, dict[str, int]]:
    """{module: {cosim module it imports: line}}: ``import a.b`` and ``from a import b`` name
    the most specific module that exists (``from cosim import report`` is cosim.report)."""
    mods = _modules()

    def resolve(name):
        while name and name not in mods:
            name = name.rpartition(".")[0]
        return name

    graph = {}
    for mod, path in mods.items():
        package = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
        edges = {}
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = package.split(".")[:len(package.split(".")) - node.level + 1]
                    base = ".".join(up + ([base] if base else []))
                names = [f"{base}.{a.name}" if f"{base}.{a.name}" in mods else base for a in node.names]
            else:
                names = _named_modules(node)
            for name in names:
                target = resolve(name) if name.split(".")[0] == "cosim" else ""
                if target and target != mod:
                    edges.setdefault(target, node.lineno)
        graph[mod] = edges
    return graph


def circles(graph: dict[str, dict[str, int]]) -> list[set[str]]:
    """The strongly connected components of more than one module (Tarjan 1972), iteratively."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], 0
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(graph[root]))]
        index[root] = low[root] = counter = counter + 1
        stack.append(root), on.add(root)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = counter = counter + 1
                    stack.append(w), on.add(w)
                    work.append((w, iter(graph[w])))
                elif w in on:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = set()
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.add(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    out.append(comp)
    return out


def _describe(comp: set[str], graph) -> str:
    return "\n".join(f"  {a} -> {b} (line {graph[a][b]})" for a in sorted(comp) for b in sorted(graph[a]) if b in comp)


def test_the_scan_sees_the_imports_it_must():
    g = import_graph()
    assert len(g) > 60
    assert "cosim.report" in g["cosim.cli"]  # a lazy import inside a function
    assert "cosim.validations.nearfield" in g["cosim.validation"]  # by name, CASE_MODULES
    assert "cosim.validation" in g["cosim.report"]


def test_the_scan_finds_a_circle():
    g = {"a": {"b": 1}, "b": {"c": 2}, "c": {"a": 3}, "d": {"a": 4}, "e": {}}
    assert circles(g) == [{"a", "b", "c"}]
    assert circles({"a": {"b": 1}, "b": {}}) == []


def test_no_import_circles_in_cosim():
    g = import_graph()
    bad = [c for c in circles(g) if not c <= SCENE_KNOT]
    assert not bad, "import circles:\n" + "\n\n".join(_describe(c, g) for c in bad)


def test_cli_report_and_cases_import_one_way():
    """cli -> report -> validation -> the case modules -> their registry, never back."""
    g = import_graph()
    layers = ["cosim.cli", "cosim.report", "cosim.validation", "cosim.validations.trade",
              "cosim.validations.registry", "cosim.validations.folders"]
    for i, low in enumerate(layers):
        for high in layers[:i]:
            assert high not in g[low], f"{low} imports {high} (line {g[low][high]})"
    cases = [m for m in g if m.startswith("cosim.validations.")]
    for m in cases:
        assert not {"cosim.cli", "cosim.report", "cosim.validation"} & set(g[m]), (m, g[m])
