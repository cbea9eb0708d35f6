"""Checkpoint files: a run's state as data, never as code.

A checkpoint is one HDF5 file holding arrays and plain values only (numbers, texts,
bytes, lists and tables of them, and the few plain records named in :data:`CLASSES`).
Reading one never runs anything from the file: each node is checked against the kinds
below and rebuilt by this module, where a pickle would run whatever it holds. The layout
(``docs/checkpoints.md``):

- root attributes ``format = "cosim-checkpoint"``, ``format_version`` (:data:`VERSION`)
  and ``sha256``, the checksum of the contents;
- below the root, a tree of nodes, each a group or a dataset with the attribute ``kind``:
  ``dict`` (group; a child is named by its key, or ``~N`` with the key in its ``key``
  attribute when the key is not a plain name), ``list``, ``tuple`` (groups, children
  ``0``, ``1``, ...), ``none`` (empty group), ``object`` (group of fields, attribute
  ``class``), ``array`` and ``scalar`` (numeric or boolean datasets), ``int``, ``float``,
  ``bool`` (0-d datasets of int64, float64, bool), ``str`` (UTF-8 bytes as uint8) and
  ``bytes`` (uint8).

``sha256`` is the SHA-256 of the sorted lines ``path, kind, key or class, dtype, shape,
SHA-256 of the bytes`` of every node: a flipped bit, a node added or removed is caught.
A file is written atomically (:func:`write`): into ``NAME.tmp`` beside it, flushed to
disk, then renamed over ``NAME``; a run killed at any moment leaves the previous file
whole. What a checkpoint means (the run's state, its scene, its code) is checked by
its reader: :func:`cosim.scene.runner.run` and :meth:`cosim.coupler.Coupler.read_checkpoint`.
"""

from __future__ import annotations

import dataclasses
import hashlib
import importlib
import math
import os
import re
from pathlib import Path

import numpy as np

from cosim.errors import InputError, ProtocolError

FORMAT = "cosim-checkpoint"
VERSION = 1
#: the records a state may hold besides plain values: name in the file -> (module, class).
#: A reader rebuilds only these (their fields, as data); any other class is refused.
CLASSES = {
    "ParticleSet": ("fluid.particles", "ParticleSet"),
    "StepLimit": ("fluid.integrator", "StepLimit"),
    "LineStepLimit": ("cosim.line_step", "LineStepLimit"),
    "LineBreak": ("moorings.breaking", "LineBreak"),
    "CableLoad": ("moorings.sph_cable", "_Load"),
}
_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.\-]*")
_DTYPES = "biuf"  # numeric and boolean arrays only
_HDF5 = b"\x89HDF\r\n\x1a\n"


class CheckpointError(InputError):
    """A checkpoint file that is refused: unreadable, corrupt, of another scene or code."""


# ------------------------------------------------------------------------ writing
def write(path, content: dict) -> None:
    """Write ``content`` (a dict of plain values, arrays and :data:`CLASSES` records) to
    ``path`` atomically: a temporary file beside it, fsync, rename, fsync of the folder."""
    import h5py

    if type(content) is not dict:
        raise ProtocolError(f"checkpoint: the content is a {type(content).__name__}; give a dict")
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")

    try:
        entries: list[str] = []
        with h5py.File(tmp, "w", track_order=True) as f:
            f.attrs["kind"] = "dict"
            entries.append(_entry("/", "dict"))
            _encode_items(f, content, "/", entries)
            f.attrs["format"] = FORMAT
            f.attrs["format_version"] = VERSION
            f.attrs["sha256"] = _digest(entries)
        _fsync(tmp)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    try:
        _fsync(path.parent)  # the rename itself on disk
    except OSError:  # a system whose folders cannot be opened: the file is whole either way
        pass


def _fsync(p: Path) -> None:
    fd = os.open(p, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _child_name(key, index: int) -> str:
    return key if isinstance(key, str) and _NAME.fullmatch(key) and key not in (".", "..") else f"~{index}"


def _entry(path, kind, extra="", data: bytes | None = None, dtype="", shape=()) -> str:
    digest = "" if data is None else hashlib.sha256(data).hexdigest()
    return f"{path}\t{kind}\t{extra}\t{dtype}\t{tuple(shape)}\t{digest}"


def _digest(entries) -> str:
    return hashlib.sha256("\n".join(sorted(entries)).encode()).hexdigest()


def _key_extra(key) -> str:
    return f"key={key!r}"


def _join(path: str, name: str) -> str:
    return f"{path.rstrip('/')}/{name}"


def _encode_items(g, d: dict, path: str, entries) -> None:
    for i, (k, x) in enumerate(d.items()):
        if not isinstance(k, str) and not (isinstance(k, int) and not isinstance(k, bool)):
            raise ProtocolError(f"checkpoint: the table at {path} has the key {k!r}; a checkpoint holds texts and "
                                f"whole numbers as keys")
        child = _child_name(k, i)
        _encode(g, child, k, x, _join(path, child), entries)


def _encode(parent, name, key, v, path, entries) -> None:
    """One node ``v`` as ``parent[name]`` (its dict key ``key``, or None for a list item)."""
    extra = "" if key is None else _key_extra(key)
    # containers of exactly these types: a subclass (a named tuple, a defaultdict) would come back as its base
    if v is None or type(v) in (dict, list, tuple) or (dataclasses.is_dataclass(v) and not isinstance(v, type)):
        g = parent.create_group(name, track_order=True)
        _mark_key(g, name, key)
        kind = "none" if v is None else type(v).__name__ if type(v) in (dict, list, tuple) else "object"
        g.attrs["kind"] = kind
        if kind == "object":
            cls = _class_name(v, path)
            g.attrs["class"] = cls
            extra = f"{extra} class={cls}"
        entries.append(_entry(path, kind, extra))
        if kind == "dict":
            _encode_items(g, v, path, entries)
        elif kind in ("list", "tuple"):
            for i, x in enumerate(v):
                _encode(g, str(i), None, x, _join(path, str(i)), entries)
        elif kind == "object":
            _encode_items(g, {f.name: getattr(v, f.name) for f in dataclasses.fields(v)}, path, entries)
        return
    kind, arr = _leaf(v, path)
    ds = parent.create_dataset(name, data=arr)
    ds.attrs["kind"] = kind
    _mark_key(ds, name, key)
    entries.append(_entry(path, kind, extra, arr.tobytes(), arr.dtype.str, arr.shape))


def _mark_key(node, name, key) -> None:
    if key is not None and name != key:
        node.attrs["key"] = str(key)
        if isinstance(key, int):
            node.attrs["key_int"] = True


def _class_name(v, path) -> str:
    for name, (module, cls) in CLASSES.items():
        if type(v).__module__ == module and type(v).__qualname__ == cls:
            return name
    raise ProtocolError(f"checkpoint: {path} holds a {type(v).__module__}.{type(v).__qualname__}, which a checkpoint "
                        f"cannot hold; a participant's save_state() returns arrays, numbers, texts, lists and "
                        f"tables of them, or a record named in cosim.checkpoint.CLASSES")


def _leaf(v, path) -> tuple[str, np.ndarray]:
    """(kind, the array written) of a value that is not a container."""
    if isinstance(v, (np.ndarray, np.generic)) and v.dtype.kind in _DTYPES:  # first: np.float64 is a float
        return ("array" if isinstance(v, np.ndarray) else "scalar"), np.array(v, order="C")
    if isinstance(v, bool):
        return "bool", np.asarray(v, np.bool_)
    if isinstance(v, int):
        if not -2 ** 63 <= v < 2 ** 63:
            raise ProtocolError(f"checkpoint: {path} = {v} does not fit in 64 bits")
        return "int", np.asarray(v, np.int64)
    if isinstance(v, float):
        return "float", np.asarray(v, np.float64)
    if isinstance(v, str):
        return "str", np.frombuffer(v.encode("utf-8"), np.uint8)
    if isinstance(v, (bytes, bytearray)):
        return "bytes", np.frombuffer(bytes(v), np.uint8)
    what = f" of dtype {v.dtype}" if isinstance(v, np.ndarray) else ""
    raise ProtocolError(f"checkpoint: {path} holds a {type(v).__module__}.{type(v).__qualname__}{what}, which a "
                        f"checkpoint cannot hold; a participant's save_state() returns arrays of numbers, numbers, "
                        f"texts, lists and tables of them")


# ------------------------------------------------------------------------ reading
def read(path) -> dict:
    """The content of the checkpoint file ``path``, after checking that it is one
    (format, every node's kind, checksum); raises :class:`CheckpointError` naming the
    cause. Nothing in the file is run."""
    import h5py

    path = Path(path)
    with open(path, "rb") as fh:
        head = fh.read(8)
    if head[:1] == b"\x80":
        raise CheckpointError(f"{path} is a Python pickle, not a checkpoint: cosim does not load pickles (loading one "
                              f"runs whatever code it holds); if an older cosim wrote it, run the scene again")
    if head != _HDF5:
        raise CheckpointError(f"{path} is not a checkpoint (not an HDF5 file); give the output folder of a run")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise CheckpointError(f"{path} is truncated or corrupt, HDF5 cannot open it ({e}); run the scene again "
                              f"without --resume") from None
    with f:
        if f.attrs.get("format") != FORMAT:
            raise CheckpointError(f"{path} is an HDF5 file but not a cosim checkpoint (its attribute format is "
                                  f"{f.attrs.get('format')!r}, not {FORMAT!r})")
        version = f.attrs.get("format_version")
        if version != VERSION:
            raise CheckpointError(f"{path} has checkpoint format version {version}; this cosim reads version "
                                  f"{VERSION}")
        entries: list[str] = []
        try:
            content = _decode_group(f, "/", None, entries)
        except CheckpointError as e:
            raise CheckpointError(f"{path} {e}; run the scene again without --resume") from None
        except (OSError, KeyError, ValueError, TypeError, UnicodeDecodeError, RecursionError) as e:
            raise CheckpointError(f"{path} is truncated or corrupt: {type(e).__name__}: {e}; run the scene again "
                                  f"without --resume") from None
        if not isinstance(content, dict) or f.attrs.get("sha256") != _digest(entries):
            raise CheckpointError(f"{path} is corrupt: its contents do not match their checksum (sha256); run the "
                                  f"scene again without --resume")
    return content


def _corrupt(node, what) -> CheckpointError:
    """A refusal of one node; :func:`read` puts the file's name in front."""
    return CheckpointError(f"is corrupt: {node} {what}")


def _key_of(node, name):
    if "key" not in node.attrs:
        return name
    key = str(node.attrs["key"])
    return int(key) if node.attrs.get("key_int", False) else key


def _decode_group(g, path, key, entries):
    import h5py

    kind = g.attrs.get("kind")
    extra = "" if key is None else _key_extra(key)
    names = []
    for name in g:
        link = g.get(name, getlink=True)
        if not isinstance(link, h5py.HardLink):
            raise _corrupt(_join(path, name), "is a link; a checkpoint holds none")
        names.append(name)
    if kind == "none":
        if names:
            raise _corrupt(path, "is empty (kind none) but has members")
        entries.append(_entry(path, kind, extra))
        return None
    if kind in ("list", "tuple"):
        if sorted(names, key=lambda s: (len(s), s)) != [str(i) for i in range(len(names))]:
            raise _corrupt(path, "is a list whose members are not 0, 1, ...")
        entries.append(_entry(path, kind, extra))
        items = [_decode(g[str(i)], _join(path, str(i)), None, entries) for i in range(len(names))]
        return items if kind == "list" else tuple(items)
    if kind == "dict":
        entries.append(_entry(path, kind, extra))
        return {k: v for k, v in (_decode_member(g, n, path, entries) for n in names)}
    if kind == "object":
        cls_name = g.attrs.get("class")
        if cls_name not in CLASSES:
            raise _corrupt(path, f"names the class {cls_name!r}, which a checkpoint may not hold (only "
                                 f"{', '.join(CLASSES)})")
        module, cls_attr = CLASSES[cls_name]
        cls = getattr(importlib.import_module(module), cls_attr)
        entries.append(_entry(path, kind, f"{extra} class={cls_name}"))
        fields = {k: v for k, v in (_decode_member(g, n, path, entries) for n in names)}
        want = {f.name for f in dataclasses.fields(cls)}
        if set(fields) != want:
            raise _corrupt(path, f"holds the fields {sorted(fields)} of a {cls_name}, which has {sorted(want)}")
        return cls(**fields)
    raise _corrupt(path, f"is a group of unknown kind {kind!r}")


def _decode_member(g, name, path, entries):
    node = g[name]
    key = _key_of(node, name)
    return key, _decode(node, _join(path, name), key, entries)


def _decode(node, path, key, entries):
    import h5py

    if isinstance(node, h5py.Group):
        return _decode_group(node, path, key, entries)
    kind = node.attrs.get("kind")
    extra = "" if key is None else _key_extra(key)
    dcpl = node.id.get_create_plist()
    if dcpl.get_nfilters() or dcpl.get_external_count() or dcpl.get_layout() == h5py.h5d.VIRTUAL:
        raise _corrupt(path, "is stored with filters or outside the file; a checkpoint stores plain arrays")
    if node.dtype.kind not in _DTYPES or node.dtype.fields is not None:
        raise _corrupt(path, f"has the type {node.dtype}; a checkpoint holds numbers and booleans")
    if node.id.get_storage_size() != node.size * node.dtype.itemsize:
        raise _corrupt(path, f"holds {node.id.get_storage_size()} bytes for its {node.size} values")
    want = {"int": ("i", ()), "float": ("f", ()), "bool": ("b", ()), "str": ("u", None), "bytes": ("u", None)}
    if kind in want:
        dk, shape = want[kind]
        if node.dtype.kind != dk or (shape is not None and node.shape != shape) or (shape is None and node.ndim != 1):
            raise _corrupt(path, f"is of kind {kind!r} but stored as {node.dtype} of shape {node.shape}")
    elif kind not in ("array", "scalar") or (kind == "scalar" and node.shape != ()):
        raise _corrupt(path, f"is a dataset of unknown kind {kind!r}")
    arr = np.asarray(node[()])
    entries.append(_entry(path, kind, extra, arr.tobytes(), arr.dtype.str, arr.shape))
    if kind == "int":
        return int(arr)
    if kind == "float":
        return float(arr)
    if kind == "bool":
        return bool(arr)
    if kind == "str":
        return arr.tobytes().decode("utf-8")
    if kind == "bytes":
        return arr.tobytes()
    return arr[()] if kind == "scalar" else arr


# ------------------------------------------------------------------------ checks of meaning
def first_not_finite(tree, path: str = "") -> str | None:
    """Where ``tree`` holds a value a state never holds: a NaN anywhere, an infinite value
    in an array (scalars may be infinite: an unbounded step limit, a load that never
    ends), or an infinite time (a key ``t``). None when there is none."""
    if isinstance(tree, dict):
        for k, v in tree.items():
            key = f"{path}.{k}" if path else str(k)
            if k == "t" and isinstance(v, float) and not math.isfinite(v):
                return f"{key} = {v}"
            where = first_not_finite(v, key)
            if where:
                return where
    elif isinstance(tree, (list, tuple)):
        for i, v in enumerate(tree):
            where = first_not_finite(v, f"{path}[{i}]")
            if where:
                return where
    elif dataclasses.is_dataclass(tree) and not isinstance(tree, type):
        return first_not_finite({f.name: getattr(tree, f.name) for f in dataclasses.fields(tree)}, path)
    elif isinstance(tree, float) and math.isnan(tree):
        return f"{path} = nan"
    elif isinstance(tree, (np.ndarray, np.generic)) and tree.dtype.kind == "f":
        bad = ~np.isfinite(tree)
        if bad.any():
            at = np.unravel_index(int(np.argmax(bad)), np.shape(tree)) if np.ndim(tree) else ()
            return f"{path}{list(map(int, at)) if at else ''} = {np.asarray(tree)[at]}"
    return None


__all__ = ["CLASSES", "CheckpointError", "FORMAT", "VERSION", "first_not_finite", "read", "write"]
