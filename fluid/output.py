"""HDF5 output of a run: time series and particle snapshots, with an XDMF file beside the
HDF5 file so that ParaView opens the snapshots as a time series of point clouds.

Usage::

    from fluid.output import H5Output
    with H5Output("run.h5", dim=2, attrs={"dx": 0.01}) as out:     # also writes run.xmf
        out.series("body", t, x=0.1, z=0.2, theta=0.0)              # one row
        out.series_block("ledger/box", t_array, force=F_array)       # many rows at once
        out.snapshot(t, pos, rho=rho, p=p, vel=vel, kind=kind)       # one snapshot

Layout of the HDF5 file (a stable contract: readers, tests and the examples rely on it)::

    /                       attrs: dim, and every entry of ``attrs``
    /series/NAME/t          (n,) time [s]
    /series/NAME/KEY        (n,) or (n, k) float64, one row per call; NAME may hold '/'
    /snapshots/0000/pos     (N, dim) positions [m]; the group has attrs t [s] and index
    /snapshots/0000/FIELD   (N,) or (N, k), any numeric dtype (kind stays int8)
    /snapshot_times         (n_snapshots,) time of each snapshot [s]

Units: every time dataset (``t``, ``snapshot_times``) and ``pos`` carry a CF-style
``units`` attribute (``"s"``, ``"m"``); :meth:`H5Output.annotate` gives any series key or
snapshot field its attributes (``units``, or ``flag_values`` and ``flag_meanings`` for a
categorical code, as the CF conventions name them), set when the dataset is made. Snapshot
groups are numbered ``f"{k:04d}"`` (0000, 0001, ...; 10000 after 9999).

Crash safety: series rows are buffered (h5py costs ~30 us per dataset write) and written
every ``buffer_rows`` rows, at every snapshot, on :meth:`flush`, on close, and at least every
``flush_every_s`` seconds of wall time (a run killed outright loses at most that much). Leaving the ``with`` block by an exception writes what was buffered and closes the
file: a run that raised leaves a readable file. The XDMF file is rewritten (atomically)
after every snapshot.

XDMF: a temporal collection of Polyvertex grids, one per snapshot. 2-D runs live in the
x-z plane, so 2-D positions are shown as (x, 0, z): the geometry is ``X_Y_Z`` made of
hyperslabs of ``pos`` and of a shared zero column ``/xdmf/zeros`` (no copy of the
positions). Fields of shape (N,) are scalars; (N, dim) are vectors (2-D: (x, 0, z)
joined from hyperslabs); other (N, k) fields appear as k scalars ``FIELD_0`` ... (checked
with VTK's XDMF (v2) reader, the one ParaView uses for .xmf files).
"""

from __future__ import annotations

import math
import os
import time
from pathlib import Path

import h5py
import numpy as np

from errors import InputError

#: XDMF number type and precision per numpy dtype kind and item size
_XDMF_TYPES = {("f", 4): ("Float", 4), ("f", 8): ("Float", 8),
               ("i", 1): ("Char", 1), ("u", 1): ("UChar", 1), ("b", 1): ("UChar", 1),
               ("i", 4): ("Int", 4), ("u", 4): ("UInt", 4), ("i", 8): ("Int", 8), ("u", 8): ("UInt", 8)}


def _check_name(name, what: str) -> str:
    if not isinstance(name, str) or not name or name.startswith("/") or name.endswith("/") \
            or "//" in name or any(c in name for c in " \t\n<>&\"'"):
        raise InputError(f"H5Output: {what} name {name!r} is not usable; give a non-empty name of "
                         "letters, digits, '_' and '.' (a series name may hold '/' between parts)")
    return name


def _finite_time(t, what: str) -> float:
    try:
        t = float(t)
    except (TypeError, ValueError):
        raise InputError(f"H5Output: {what} time must be a number of seconds, got {t!r}") from None
    if not math.isfinite(t):
        raise InputError(f"H5Output: {what} time must be finite, got {t!r} s")
    return t


class H5Output:
    """One HDF5 file of series and snapshots, and its XDMF companion.

    ``path`` [file] the .h5 file (overwritten); the XDMF file is ``path`` with suffix .xmf.
    ``dim`` 2 (x-z plane) or 3. ``attrs`` run metadata stored as root attributes (numbers,
    strings or arrays; give lengths in metres, times in seconds). ``buffer_rows`` [-] series
    rows held in memory per series before they are written; ``flush_every_s`` [s] the
    longest wall time between two flushes to disk.
    """

    def __init__(self, path, dim: int, attrs: dict | None = None, *, buffer_rows: int = 256,
                 flush_every_s: float = 10.0):
        if dim not in (2, 3):
            raise InputError(f"H5Output: dim={dim!r}; use 2 (x-z plane) or 3")
        if not isinstance(buffer_rows, int) or buffer_rows < 1:
            raise InputError(f"H5Output: buffer_rows={buffer_rows!r}; give a positive number of rows")
        self.path = Path(path)
        self.xmf_path = self.path.with_suffix(".xmf")
        self.dim = dim
        self.buffer_rows = buffer_rows
        if not (isinstance(flush_every_s, (int, float)) and flush_every_s > 0):
            raise InputError(f"H5Output: flush_every_s={flush_every_s!r}; give a positive number of seconds")
        self.flush_every_s = float(flush_every_s)
        self._flushed = time.monotonic()
        self.n_snapshots = 0
        self._snap_meta: list[tuple] = []  # (t, group, N, pos dtype, fields) per snapshot
        self._grids: list[str] = []  # each snapshot's XDMF grid, made once
        self._series: dict[str, dict] = {}  # name -> {"keys": {key: shape}, "rows": [...]}
        self._attrs: dict[str, dict[str, dict]] = {"snapshots": {"pos": {"units": "m"}}}  # annotate()
        self._zeros_n = 0
        self._closed = False
        self.file = h5py.File(self.path, "w")
        try:
            self.file.attrs["dim"] = dim
            for k, v in (attrs or {}).items():
                try:
                    self.file.attrs[_check_name(k, "attribute")] = v
                except (TypeError, ValueError) as e:
                    raise InputError(f"H5Output: attribute {k}={v!r} cannot be stored in HDF5 ({e}); "
                                     "give a number, a string or an array") from None
            self.file.create_group("series")
            self.file.create_group("snapshots")
            self.file.create_dataset("snapshot_times", shape=(0,), maxshape=(None,), chunks=(256,), dtype="f8")
            self.file["snapshot_times"].attrs["units"] = "s"
            self._write_xdmf()
            self.file.flush()
        except BaseException:
            self.file.close()
            raise

    # ------------------------------------------------------------------ context
    def __enter__(self) -> "H5Output":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    @property
    def closed(self) -> bool:
        return self._closed

    def close(self) -> None:
        """Write buffered rows and close the file (idempotent)."""
        if self.closed:
            return
        try:
            self.flush()
        finally:
            self.file.close()
            self._closed = True

    def flush(self) -> None:
        """Write every buffered series row and flush the file to disk."""
        self._require_open()
        for name in self._series:
            self._write_rows(name)
        self.file.flush()
        self._flushed = time.monotonic()

    def _require_open(self) -> None:
        if self.closed:
            raise InputError(f"H5Output: {self.path} is closed; write inside the `with` block")

    # ------------------------------------------------------------------ attributes
    def annotate(self, name: str, key: str, **attrs) -> None:
        """Attributes of the dataset ``key`` of series ``name`` (``name="snapshots"``: of
        the snapshot field ``key``), e.g. ``units="m"``: set now where it exists and on
        every dataset of that key made later (each snapshot's)."""
        self._require_open()
        self._attrs.setdefault(name, {}).setdefault(key, {}).update(attrs)
        g = self.file["series"].get(name) if name != "snapshots" else None
        if isinstance(g, h5py.Group) and key in g:
            g[key].attrs.update(attrs)

    # ------------------------------------------------------------------ series
    def series(self, name: str, t: float, **values) -> None:
        """Append one row at time ``t`` [s] to series ``name``: each value a float or a 1-D
        array; the keys and each key's length are fixed by the first row."""
        self._require_open()
        t = _finite_time(t, f"series {name!r}")
        row = {}
        for k, v in values.items():
            a = np.asarray(v, dtype=np.float64)
            if a.ndim > 1:
                raise InputError(f"H5Output: series {name!r} value {k} has shape {a.shape}; give a float "
                                 "or a 1-D array (flatten it, or split it into keys)")
            row[k] = a
        s = self._declare(name, {k: a.shape for k, a in row.items()})
        s["t"].append(t)
        for k, a in row.items():
            s["rows"][k].append(a)
        if len(s["t"]) >= self.buffer_rows:
            self._write_rows(name)
        if time.monotonic() - self._flushed > self.flush_every_s:
            self.flush()

    def series_block(self, name: str, t, **values) -> None:
        """Append many rows at once: ``t`` (n,) [s], each value (n,) or (n, k); the same
        keys and widths as :meth:`series` rows of this series."""
        self._require_open()
        t = np.asarray(t, dtype=np.float64)
        if t.ndim != 1 or not np.isfinite(t).all():
            raise InputError(f"H5Output: series {name!r} times must be a 1-D array of finite seconds, "
                             f"got shape {t.shape}")
        block = {}
        for k, v in values.items():
            a = np.asarray(v, dtype=np.float64)
            if a.ndim not in (1, 2) or a.shape[0] != t.shape[0]:
                raise InputError(f"H5Output: series {name!r} value {k} has shape {a.shape}; give ({t.shape[0]},) "
                                 f"or ({t.shape[0]}, k), one row per time")
            block[k] = a
        self._declare(name, {k: a.shape[1:] for k, a in block.items()})
        self._write_rows(name)
        self._append(name, t, block)

    def _declare(self, name: str, shapes: dict) -> dict:
        """The buffer of series ``name``, created on first use; checks keys and widths."""
        s = self._series.get(name)
        if s is None:  # names are checked once, when the series is made
            _check_name(name, "series")
            for k in shapes:
                _check_name(k, f"series {name!r} key")
            if "t" in shapes:
                raise InputError(f"H5Output: series {name!r} has a key 't'; the time is the second argument")
            if not shapes:
                raise InputError(f"H5Output: series {name!r} got no values; give keys, e.g. x=0.1")
            if name in self.file["series"] and not isinstance(self.file["series"][name], h5py.Group):
                raise InputError(f"H5Output: series {name!r} clashes with an existing dataset")
            g = self.file["series"].require_group(name)
            if "t" in g:
                raise InputError(f"H5Output: series {name!r} clashes with another series' key")
            g.create_dataset("t", shape=(0,), maxshape=(None,), chunks=(self.buffer_rows,), dtype="f8")
            g["t"].attrs["units"] = "s"
            for k, shp in shapes.items():
                g.create_dataset(k, shape=(0,) + shp, maxshape=(None,) + shp,
                                 chunks=(self.buffer_rows,) + shp, dtype="f8")
                g[k].attrs.update(self._attrs.get(name, {}).get(k, {}))
            s = self._series[name] = {"shapes": dict(shapes), "t": [], "rows": {k: [] for k in shapes}}
            return s
        if shapes == s["shapes"]:
            return s
        if set(shapes) != set(s["shapes"]):
            raise InputError(f"H5Output: series {name!r} got keys {sorted(shapes)}, but its first row had "
                             f"{sorted(s['shapes'])}; give the same keys in every row")
        for k, shp in shapes.items():
            if shp != s["shapes"][k]:
                raise InputError(f"H5Output: series {name!r} key {k} has width {shp}, but {s['shapes'][k]} "
                                 "before; a key keeps its length")
        return s

    def _write_rows(self, name: str) -> None:
        s = self._series[name]
        if not s["t"]:
            return
        t = np.array(s["t"])
        block = {k: np.array(rows).reshape((len(t),) + s["shapes"][k]) for k, rows in s["rows"].items()}
        s["t"].clear()
        for rows in s["rows"].values():
            rows.clear()
        self._append(name, t, block)

    def _append(self, name: str, t: np.ndarray, block: dict) -> None:
        g = self.file["series"][name]
        n0, n = g["t"].shape[0], t.shape[0]
        for k, a in list(block.items()) + [("t", t)]:  # the time last: a row counts once it is whole
            d = g[k]
            d.resize(n0 + n, axis=0)
            d[n0:] = a

    # ------------------------------------------------------------------ snapshots
    def snapshot(self, t: float, pos, **fields) -> int:
        """Write particle snapshot k (returned) at time ``t`` [s]: positions ``pos`` (N, dim)
        [m] and per-particle ``fields`` of shape (N,) or (N, k) (rho [kg/m^3], p [Pa],
        vel [m/s], kind, ...). Rewrites the XDMF file and flushes."""
        self._require_open()
        t = _finite_time(t, "snapshot")
        pos = np.asarray(pos)
        if pos.ndim != 2 or pos.shape[1] != self.dim or pos.dtype.kind not in "fiu":
            raise InputError(f"H5Output: snapshot positions have shape {pos.shape} ({pos.dtype}); "
                             f"give a numeric (N, {self.dim}) array")
        n = pos.shape[0]
        data = {"pos": pos}
        for k, v in fields.items():
            _check_name(k, "snapshot field")
            if k == "pos":
                raise InputError("H5Output: 'pos' is the positions argument, not a field")
            a = np.asarray(v)
            if a.dtype == bool:
                a = a.astype(np.uint8)
            elif a.dtype.kind in "iu" and a.dtype.itemsize == 2:
                a = a.astype(np.int32)  # XDMF readers know 1-, 4- and 8-byte integers
            if a.dtype.kind not in "fiu" or a.ndim not in (1, 2) or a.shape[0] != n:
                raise InputError(f"H5Output: snapshot field {k} has shape {a.shape} ({a.dtype}); give a "
                                 f"numeric ({n},) or ({n}, k) array, one row per particle")
            data[k] = a
        key = f"{self.n_snapshots:04d}"
        g = self.file["snapshots"].create_group(key)
        g.attrs["t"] = t
        g.attrs["index"] = self.n_snapshots
        for k, a in data.items():
            g.create_dataset(k, data=a)
            g[k].attrs.update(self._attrs["snapshots"].get(k, {}))
        regrid = self.dim == 2 and n > self._zeros_n
        if regrid:
            if "xdmf" in self.file:
                del self.file["xdmf"]
            self.file.create_dataset("xdmf/zeros", data=np.zeros((n, 1)))
            self._zeros_n = n
        times = self.file["snapshot_times"]
        times.resize(self.n_snapshots + 1, axis=0)
        times[-1] = t
        self._snap_meta.append((t, key, n, pos.dtype, [(k, a.dtype, a.shape[1:]) for k, a in data.items() if k != "pos"]))
        self.n_snapshots += 1
        for name in self._series:
            self._write_rows(name)
        self._write_xdmf(regrid)
        self.file.flush()
        return self.n_snapshots - 1

    # ------------------------------------------------------------------ XDMF
    def _item(self, key: str, field: str, dtype, shape) -> str:
        nt, prec = _XDMF_TYPES[(dtype.kind, dtype.itemsize)]
        dims = " ".join(str(d) for d in shape)
        return (f'<DataItem Dimensions="{dims}" NumberType="{nt}" Precision="{prec}" Format="HDF">'
                f'{self.path.name}:/snapshots/{key}/{field}</DataItem>')

    def _column(self, key: str, field: str, dtype, n: int, k: int, col: int) -> str:
        """Column ``col`` of the (n, k) dataset ``field``, as an XDMF hyperslab."""
        return (f'<DataItem ItemType="HyperSlab" Dimensions="{n} 1" Type="HyperSlab">'
                f'<DataItem Dimensions="3 2" Format="XML">0 {col} 1 1 {n} 1</DataItem>'
                f'{self._item(key, field, dtype, (n, k))}</DataItem>')

    def _zeros(self, n: int) -> str:
        """The first ``n`` rows of the zero column: the y of a 2-D run's x-z plane."""
        return (f'<DataItem ItemType="HyperSlab" Dimensions="{n} 1" Type="HyperSlab">'
                f'<DataItem Dimensions="3 2" Format="XML">0 0 1 1 {n} 1</DataItem>'
                f'<DataItem Dimensions="{self._zeros_n} 1" NumberType="Float" Precision="8" Format="HDF">'
                f'{self.path.name}:/xdmf/zeros</DataItem></DataItem>')

    def _grid(self, t: float, key: str, n: int, pos_dtype, fields: list) -> str:
        out = [f'<Grid Name="snapshot_{key}" GridType="Uniform">',
               f'<Time Value="{t!r}"/>',
               f'<Topology TopologyType="Polyvertex" NumberOfElements="{n}" NodesPerElement="1"/>']
        if self.dim == 3:
            out += ['<Geometry GeometryType="XYZ">', self._item(key, "pos", pos_dtype, (n, 3)), "</Geometry>"]
        else:
            out += ['<Geometry GeometryType="X_Y_Z">', self._column(key, "pos", pos_dtype, n, 2, 0),
                    self._zeros(n), self._column(key, "pos", pos_dtype, n, 2, 1), "</Geometry>"]
        for name, dtype, tail in fields:
            if not tail:
                out += [f'<Attribute Name="{name}" AttributeType="Scalar" Center="Node">',
                        self._item(key, name, dtype, (n,)), "</Attribute>"]
            elif self.dim == 3 and tail == (3,):
                out += [f'<Attribute Name="{name}" AttributeType="Vector" Center="Node">',
                        self._item(key, name, dtype, (n, 3)), "</Attribute>"]
            elif self.dim == 2 and tail == (2,):  # a vector in the x-z plane: (x, 0, z)
                out += [f'<Attribute Name="{name}" AttributeType="Vector" Center="Node">',
                        f'<DataItem ItemType="Function" Function="JOIN($0, $1, $2)" Dimensions="{n} 3">',
                        self._column(key, name, dtype, n, 2, 0), self._zeros(n),
                        self._column(key, name, dtype, n, 2, 1), "</DataItem>", "</Attribute>"]
            else:
                k = tail[0]
                for col in range(k):
                    out += [f'<Attribute Name="{name}_{col}" AttributeType="Scalar" Center="Node">',
                            self._column(key, name, dtype, n, k, col), "</Attribute>"]
        out.append("</Grid>")
        return "\n".join(out)

    def _write_xdmf(self, regrid: bool = False) -> None:
        """Rewrite the XDMF file: the grids made so far, plus any new one (all of them
        again when ``regrid``: the shared zero column grew)."""
        if regrid:
            self._grids = []
        for meta in self._snap_meta[len(self._grids):]:
            self._grids.append(self._grid(*meta))
        lines = ['<?xml version="1.0" ?>',
                 '<Xdmf Version="2.0">',
                 "<Domain>",
                 '<Grid Name="particles" GridType="Collection" CollectionType="Temporal">']
        lines += self._grids
        lines += ["</Grid>", "</Domain>", "</Xdmf>", ""]
        tmp = self.xmf_path.with_suffix(".xmf.tmp")
        tmp.write_text("\n".join(lines))
        os.replace(tmp, self.xmf_path)  # a reader never sees a half-written file


def read_series(path, name: str) -> dict[str, np.ndarray]:
    """Series ``name`` of an :class:`H5Output` file: ``t`` and every key, as arrays."""
    with h5py.File(path, "r") as f:
        if f"series/{name}" not in f:
            have = []
            f["series"].visititems(lambda k, v: have.append(k) if isinstance(v, h5py.Group) and "t" in v else None)
            raise InputError(f"{path}: no series {name!r}; it holds {sorted(have)}")
        g = f["series"][name]
        keys = [k for k in g if isinstance(g[k], h5py.Dataset)]
        n = min(g[k].shape[0] for k in keys)  # a run killed mid-write: only the whole rows
        return {k: g[k][:n] for k in keys}


def read_units(path, name: str) -> dict[str, str]:
    """The ``units`` attribute of each dataset of series ``name`` that has one."""
    with h5py.File(path, "r") as f:
        g = f["series"][name]
        return {k: str(g[k].attrs["units"]) for k in g if isinstance(g[k], h5py.Dataset) and "units" in g[k].attrs}


def read_snapshot(path, k: int) -> dict:
    """Snapshot ``k`` of an :class:`H5Output` file: ``t`` [s], ``pos`` and every field."""
    with h5py.File(path, "r") as f:
        n = f["snapshot_times"].shape[0]
        if not (isinstance(k, (int, np.integer)) and -n <= k < n):
            raise InputError(f"{path}: no snapshot {k!r}; it holds {n} (0 .. {n - 1})")
        g = f["snapshots"][f"{k % n:04d}"]
        out = {"t": float(g.attrs["t"])}
        out.update({name: g[name][()] for name in g})
        return out


def write_csv(path, series: dict, units: dict | None = None) -> None:
    """Write one series (``{"t": (n,) [s], key: (n,) or (n, k)}``, as :func:`read_series`
    reads it) as CSV: a header ``t``, then
    ``key`` or ``key_0 .. key_{k-1}`` per key, each with ``[UNIT]`` where ``units`` (as
    :func:`read_units` reads them) has it, one row per time, full precision."""
    if "t" not in series:
        raise InputError("write_csv: the series has no 't' (time) column")
    units = units or {}

    def label(name, key):
        return f"{name} [{units[key]}]" if key in units else name

    t = np.asarray(series["t"], dtype=np.float64)
    cols, names = [t[:, None]], [label("t", "t")]
    for k, v in series.items():
        if k == "t":
            continue
        a = np.asarray(v, dtype=np.float64).reshape(t.shape[0], -1)
        cols.append(a)
        names += [label(k, k)] if a.shape[1] == 1 and np.ndim(v) == 1 else [label(f"{k}_{j}", k)
                                                                           for j in range(a.shape[1])]
    np.savetxt(path, np.hstack(cols), delimiter=",", header=",".join(names), comments="", fmt="%.17g")


def describe(path) -> dict:
    """What an :class:`H5Output` file holds: ``attrs``, ``series`` (name -> rows, keys and
    time span [s]) and ``snapshots`` (count, particles in the last, time span [s])."""
    with h5py.File(path, "r") as f:
        attrs = {k: (v.item() if isinstance(v, np.generic) else v.tolist() if isinstance(v, np.ndarray) else v)
                 for k, v in f.attrs.items()}
        series = {}

        def visit(name, obj):
            if isinstance(obj, h5py.Group) and "t" in obj and isinstance(obj["t"], h5py.Dataset):
                t = obj["t"]
                series[name] = {"rows": int(t.shape[0]),
                                "keys": {k: list(obj[k].shape[1:]) for k in obj if k != "t"
                                         and isinstance(obj[k], h5py.Dataset)},
                                "t_s": [float(t[0]), float(t[-1])] if t.shape[0] else []}

        f["series"].visititems(visit)
        times = f["snapshot_times"][()]
        snaps = {"count": int(times.size), "t_s": [float(times[0]), float(times[-1])] if times.size else []}
        if times.size:
            snaps["particles_last"] = int(f["snapshots"][f"{times.size - 1:04d}"]["pos"].shape[0])
    return {"attrs": attrs, "series": series, "snapshots": snaps}
