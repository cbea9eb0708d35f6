"""What every Capytaine solve of :mod:`fluid.potential` shares: Capytaine's import (or an
error naming the extra that installs it), its log held back while it solves, the lid against
irregular frequencies, and the cache of solved datasets (its folder, the key's format, the
NetCDF files written whole). Used by :mod:`~fluid.potential.coefficients` (one body),
:mod:`~fluid.potential.group` (bodies solved together) and
:mod:`~fluid.potential.elevation` (the radiated wave at points)."""

from __future__ import annotations

import hashlib
import logging
import math
import os
import sys
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from errors import InputError
from fluid.potential.hull import Hull

log = logging.getLogger("fluid.potential")

#: bump when what is stored changes meaning (old cache files are then not read)
CACHE_FORMAT = 2
ENV_CACHE = "COSIM_POTENTIAL_CACHE"
EXTRA = "pip install cosim-sph[potential]"


def say(msg: str, *args) -> None:
    """A log record, and on a terminal the same line on standard error."""
    log.info(msg, *args)
    if sys.stderr.isatty():
        print(msg % args, file=sys.stderr, flush=True)


def require_capytaine():
    """Capytaine and the NetCDF engine, or an :class:`InputError` naming the extra."""
    try:
        import capytaine  # noqa: F401
        import h5netcdf  # noqa: F401
    except ImportError as e:
        raise InputError(f"the potential-flow fluid needs Capytaine and h5netcdf ({e.name} is not installed): "
                         f"{EXTRA}") from None
    return capytaine


def cache_dir() -> Path:
    """Where coefficients are cached: ``$COSIM_POTENTIAL_CACHE`` or ``~/.cache/cosim-sph/potential``."""
    env = os.environ.get(ENV_CACHE)
    return Path(env) if env else Path.home() / ".cache" / "cosim-sph" / "potential"


def cache_key(hull: Hull, lid, cog, rho, g, depth, omega, headings, version, theta=None) -> str:
    """The cache file's key of one body's solve: a SHA-256 (24 hex digits) of the hull and lid
    panels, the centre of mass, ``rho``, ``g``, depth, frequencies, headings, Kochin angles
    and Capytaine's ``version``, each rounded to 12 digits."""
    h = hashlib.sha256()
    h.update(f"cosim-potential-{CACHE_FORMAT}|capytaine-{version}|".encode())
    extra = () if theta is None else (theta,)  # without: the keys of files written before Kochin functions
    for arr in (hull.vertices, hull.faces, lid[0], lid[1], cog, omega, headings,
                np.array([rho, g, depth], float)) + extra:
        a = np.ascontiguousarray(np.round(np.asarray(arr, float), 12))
        h.update(str(a.shape).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:24]


def lid_for(cpt, mesh, hull: Hull, omega_max: float, g: float, lid: bool | None):
    """The lid mesh and its arrays, or (None, empty arrays) when ``lid`` is False or, None,
    when no irregular frequency is estimated below 1.5 ``omega_max`` [rad/s] (the estimate is
    rough and the errors grow on the way to the first irregular frequency)."""
    empty = (np.zeros((0, 3)), np.zeros((0, 4)))
    if lid is False or min(hull.waterline_span) <= 0:
        return None, empty
    bare = cpt.FloatingBody(mesh=mesh)
    if lid is None and bare.first_irregular_frequency_estimate(g=g) > 1.5 * omega_max:
        return None, empty
    with np.errstate(invalid="ignore"):  # NaN where no irregular frequency lies below omega_max
        z = mesh.lowest_lid_position(omega_max, g=g)
    z = 0.0 if not math.isfinite(z) else max(z, -0.5 * hull.draft)  # inside the hull, above its keel
    lid = mesh.generate_lid(z=z)
    return lid, (np.asarray(lid.vertices, float), np.asarray(lid.faces, float))


@contextmanager
def quiet(logger: str):
    """Capytaine's log held back to its errors while it solves: its per-problem lines, and its
    warnings, which its handler prints on standard output (where ``cosim validate`` writes
    JSON) and which say what :mod:`fluid.potential` checks itself (the frequencies against the panels,
    ``fluid.potential.participant.default_omega``; a finite depth at ω = ∞)."""
    lg = logging.getLogger(logger)
    level = lg.level
    lg.setLevel(max(level, logging.ERROR))
    try:
        yield
    finally:
        lg.setLevel(level)


def plain(ds):
    """Categorical coordinates (Capytaine's dof names) as plain strings, which NetCDF stores."""
    for name in ("radiating_dof", "influenced_dof"):
        if name in ds.coords:
            ds = ds.assign_coords({name: np.asarray(ds[name].values, dtype=str)})
    return ds


def write_dataset(path: Path, ds) -> None:
    """``ds`` as NetCDF at ``path`` (complex values split; written whole or not at all)."""
    from capytaine.io.xarray import separate_complex_values

    path.parent.mkdir(parents=True, exist_ok=True)
    out = separate_complex_values(ds)
    for k in list(out.attrs):  # NetCDF attributes are numbers or strings
        if not isinstance(out.attrs[k], (int, float, str, np.number)):
            out.attrs[k] = str(out.attrs[k])
    tmp = path.with_suffix(f".{os.getpid()}.tmp")
    out.to_netcdf(tmp, engine="h5netcdf")
    os.replace(tmp, path)  # whole or not at all: a reader never sees half a file


def read_dataset(cpt, path: Path):
    """A dataset :func:`write_dataset` wrote, its complex values merged again."""
    import xarray as xr
    from capytaine.io.xarray import merge_complex_values

    with xr.open_dataset(path, engine="h5netcdf") as f:
        return merge_complex_values(f.load())
