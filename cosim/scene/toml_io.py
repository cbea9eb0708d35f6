"""A scene as TOML, field for field: :func:`read_toml`, :func:`from_dict`, :func:`to_dict`,
:func:`to_toml`, and ``--set KEY.PATH=VALUE`` (:func:`with_values`).

The keys are the dataclasses' field names (:mod:`cosim.scene.spec`); a place that takes
one of several classes tells them apart by ``model`` (fluid), ``kind`` (domain, waves,
base_motion) or ``shape`` (bodies). ``from_dict(to_dict(scene)) == scene`` exactly
(floats are written with ``repr``). An unknown key, a wrong type or an out-of-range value
is refused before anything runs, naming its key path (``moorings.lines[1].length``) and
what would be accepted; a relative file name in the scene is read from the scene file's
folder. TOML has no null: a field left unset is left out.
"""

from __future__ import annotations

import dataclasses
import difflib
import re
import tomllib
from pathlib import Path

from cosim.scene.fields import Part, Parts, SceneError, Spec, spec_fields
from cosim.scene.spec import Scene

_FILE_FIELDS = ("file",)


def _key(prefix: str, name: str) -> str:
    return f"{prefix}.{name}" if prefix else name


def _pick_class(classes, data: dict, path: str):
    if len(classes) == 1:
        return classes[0]
    tag = classes[0].TAG[0]
    by = {c.TAG[1]: c for c in classes}
    if tag not in data:
        raise SceneError(_key(path, tag), f"is required: one of {', '.join(repr(k) for k in by)}")
    value = data[tag]
    if not isinstance(value, str) or value not in by:
        hint = difflib.get_close_matches(value, list(by), n=1) if isinstance(value, str) else []
        raise SceneError(_key(path, tag), f"{value!r} is not accepted"
                         f"{'; did you mean ' + repr(hint[0]) + '?' if hint else '.'}"
                         f" Give one of {', '.join(repr(k) for k in by)}")
    return by[value]


def _build(classes, data, path: str, base_dir):
    if not isinstance(data, dict):
        raise SceneError(path, f"{data!r} is not a table; give a table of {' or '.join(c.__name__ for c in classes)} "
                         "fields")
    cls = _pick_class(classes, data, path)
    fields = {name: check for name, check, _ in spec_fields(cls)}
    tag = cls.TAG[0] if cls.TAG else None
    unknown = [k for k in data if k not in fields and k != tag]
    if unknown:
        k = unknown[0]
        hint = difflib.get_close_matches(k, list(fields), n=1)
        raise SceneError(_key(path, k), f"unknown key{'; did you mean ' + repr(hint[0]) + '?' if hint else '.'} "
                         f"Known keys here: {', '.join(fields)}")
    kwargs = {}
    for name, value in data.items():
        if name == tag:
            continue
        check, key = fields[name], _key(path, name)
        if isinstance(check, Part):
            value = _build(check.classes, value, key, base_dir)
        elif isinstance(check, Parts):
            if not isinstance(value, list):
                raise SceneError(key, f"{value!r} is not a list; give {check.expected()}")
            value = [_build(check.part.classes, v, f"{key}[{i}]", base_dir) for i, v in enumerate(value)]
        elif name in _FILE_FIELDS and isinstance(value, str) and base_dir is not None and not Path(value).is_absolute():
            value = str(Path(base_dir) / value)
        kwargs[name] = value
    missing = [n for n, check, default in spec_fields(cls)
               if default is dataclasses.MISSING and n not in kwargs]
    if missing:
        n = missing[0]
        raise SceneError(_key(path, n), f"is required: {fields[n].expected()}")
    try:
        return cls(**kwargs)
    except SceneError as e:
        rel = e.path.split(".", 1)[1] if e.path.startswith(cls.__name__ + ".") else e.path
        raise e.__class__(_key(path, rel) if rel != cls.__name__ else path, e.problem) from None


def from_dict(data: dict, base_dir=None) -> Scene:
    """The scene described by ``data`` (the TOML document's tables); relative file names
    are taken from ``base_dir``."""
    return _build((Scene,), data, "", base_dir)


def read_toml(path) -> Scene:
    """The scene of a TOML file (relative file names in it are read from its folder)."""
    p = Path(path)
    if not p.is_file():
        raise SceneError("", f"no scene file {str(path)!r}")
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except UnicodeDecodeError as e:
        raise SceneError("", f"{p} is not UTF-8 text (byte {e.start}: {e.reason}); TOML files are UTF-8: save it "
                         "as UTF-8") from None
    except tomllib.TOMLDecodeError as e:
        raise SceneError("", f"{p} is not valid TOML: {e}") from None
    return from_dict(data, p.resolve().parent)


def _plain(v):
    if isinstance(v, Spec):
        return to_dict(v)
    if isinstance(v, (tuple, list)):
        return [_plain(x) for x in v]
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    return v


def to_dict(spec: Spec) -> dict:
    """The scene (or any part of it) as plain tables, lists and values; unset fields are
    left out."""
    out = {}
    if spec.TAG:
        out[spec.TAG[0]] = spec.TAG[1]
    for name, _, _ in spec_fields(type(spec)):
        v = getattr(spec, name)
        if v is not None:
            out[name] = _plain(v)
    return out


def toml_value(v) -> str:
    """A value as TOML writes it (``--set`` and ``--vary`` assignments, the scene file)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)  # exact: floats round-trip through repr
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_bare(k)} = {toml_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {v!r} as TOML")


_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}


def _string(s: str) -> str:
    """A TOML basic string in ASCII (JSON's escapes, which are TOML's), except that a
    character beyond U+FFFF is one ``\\UXXXXXXXX`` escape: JSON splits it into two
    surrogate escapes, which TOML refuses."""
    out = []
    for ch in s:
        o = ord(ch)
        if ch in _ESCAPES:
            out.append(_ESCAPES[ch])
        elif 0x20 <= o < 0x7F:
            out.append(ch)
        else:
            out.append(f"\\u{o:04x}" if o <= 0xFFFF else f"\\U{o:08x}")
    return '"' + "".join(out) + '"'


def _bare(k: str) -> str:
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else _string(k)


def _table(d: dict, name: str, lines: list, header: str) -> None:
    """Keys first, then sub-tables, then arrays of tables (TOML's order)."""
    is_tables = lambda v: isinstance(v, list) and v and all(isinstance(x, dict) for x in v)
    plain = [(k, v) for k, v in d.items() if not isinstance(v, dict) and not is_tables(v)]
    if header:
        lines += ["", header]
    lines += [f"{_bare(k)} = {toml_value(v)}" for k, v in plain]
    for k, v in d.items():
        sub = f"{name}.{_bare(k)}" if name else _bare(k)
        if isinstance(v, dict):
            _table(v, sub, lines, f"[{sub}]")
        elif is_tables(v):
            for x in v:
                _table(x, sub, lines, f"[[{sub}]]")


def to_toml(scene: Scene, path=None) -> str:
    """The scene as TOML text (every set field); also written to ``path`` when given."""
    lines: list[str] = []
    _table(to_dict(scene), "", lines, "")
    text = "\n".join(lines).lstrip("\n") + "\n"
    if path is not None:
        Path(path).write_text(text)
    return text


_PART = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)((?:\[\d+\])*)")


def _split(path: str) -> list:
    out = []
    for piece in path.split("."):
        m = _PART.fullmatch(piece)
        if not m:
            raise SceneError(path, "is not a key path; write it as in TOML, e.g. fluid.dx or moorings.lines[1].length")
        out.append(m.group(1))
        out.extend(int(i) for i in re.findall(r"\[(\d+)\]", m.group(2)))
    return out


def parse_value(text: str):
    """A ``--set`` value as TOML reads it (``0.01``, ``true``, ``[1, 2]``, ``"sph"``);
    a bare word that is not TOML is taken as a string (``model=moordyn``)."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def with_values(scene: Scene, assignments, notes: list | None = None) -> Scene:
    """``scene`` with ``KEY.PATH=VALUE`` assignments applied and the result checked again,
    as TOML would be; what a change of a part's kind dropped or carried over (see
    :func:`_drop_foreign`) is appended to ``notes`` as sentences, where given."""
    data = to_dict(scene)
    for a in assignments:
        if "=" not in a:
            raise SceneError(a, "give --set as KEY.PATH=VALUE, e.g. fluid.dx=0.01")
        path, text = (x.strip() for x in a.split("=", 1))
        keys = _split(path)
        node, where = data, ""  # where: the key path of node
        for i, k in enumerate(keys):
            if isinstance(k, int):
                if not isinstance(node, list):
                    raise SceneError(path, f"{where} is {_what(node)}, not a list; leave out [{k}]")
                if k >= len(node):
                    raise SceneError(path, f"there is no entry {k} of {where} (the list has {len(node)}"
                                     f"{f'; the last is [{len(node) - 1}]' if node else ''})")
            elif not isinstance(node, dict):
                hint = f"; give an entry, e.g. {where}[0].{k}" if isinstance(node, list) and node else ""
                raise SceneError(path, f"{where or 'the scene'} is {_what(node)}, not a table{hint}")
            if i == len(keys) - 1:
                value = parse_value(text)
                if isinstance(node, dict) and isinstance(k, str) and node.get(k, value) != value:
                    _drop_foreign(node, k, value, where, notes)
                node[k] = value
            elif isinstance(k, int):
                node = node[k]
            else:
                node = node.setdefault(k, [] if isinstance(keys[i + 1], int) else {})
            where = f"{where}[{k}]" if isinstance(k, int) else _key(where, k)
    return from_dict(data)


#: fields that keep their meaning under another name when a part's kind changes by ``--set``:
#: per new kind's tag, {the old kind's name: the new kind's name}: the water's density
#: [kg/m^3] (``rho``, the SPH fluid's reference density ``rho0``), and the analytic fluid's
#: quadratic damping, the potential fluid's quadratic drag: the same Morison drag, 6
#: coefficients per body [N s^2/m^2, N m s^2] on the velocity relative to the water.
CARRIED = {("model", "potential"): {"quadratic_damping": "quadratic_drag", "rho0": "rho"},
           ("model", "analytic"): {"quadratic_drag": "quadratic_damping", "rho0": "rho"},
           ("model", "sph"): {"rho": "rho0"}}


def _drop_foreign(node: dict, key: str, value, where: str, notes: list | None = None) -> None:
    """A part's kind changed by ``--set`` (``fluid.model=sph``): its fields that the new
    kind has under another name (:data:`CARRIED`) are renamed, those it does not have go
    (logged, and said in ``notes``), so that one field swaps, e.g., the analytic fluid for
    the SPH fluid; the fields both kinds have stay."""
    import logging

    from cosim.scene import spec
    from cosim.scene.registry import TAGGED

    known = {c for c in vars(spec).values() if isinstance(c, type) and issubclass(c, Spec)}
    new = [c for c in known | {c for r in TAGGED for c in r.classes()} if c.TAG == (key, value)]
    if len(new) != 1:
        return  # not a tag, or an unknown kind: from_dict names it
    known = {name for name, _, _ in spec_fields(new[0])} | {key}
    said = []
    for old, name in CARRIED.get((key, value), {}).items():
        if old in node and old not in known and name not in node:
            node[name] = node.pop(old)
            said.append(f"its {old} taken as {name}")
    gone = sorted(set(node) - known)
    for name in gone:
        del node[name]
    if gone:
        said.append(f"dropped {', '.join(gone)} (not fields of {new[0].__name__})")
    if said:
        text = f"{_key(where, key)} = {value!r}: {'; '.join(said)}"
        logging.getLogger(__name__).info("%s", text)
        if notes is not None:
            notes.append(text)


def _what(v) -> str:
    if isinstance(v, list):
        return f"a list of {len(v)}"
    return "a table" if isinstance(v, dict) else repr(v)
