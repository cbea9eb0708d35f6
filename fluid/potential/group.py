"""Hydrodynamic coefficients of several bodies solved together: their interaction, cached.

What: for N hulls (:class:`fluid.potential.hull.Hull`, each relative to its own centre of mass
horizontally) at horizontal positions ``positions`` [m] (world), one boundary-element problem
over all of them (Capytaine's ``FloatingBody.join_bodies``: the union of the meshes, each body
with its six rigid-body dofs about its own centre of mass, world axes), which gives

- the coupled added mass ``A(ω)`` and radiation damping ``B(ω)``, ``(n, 6N, 6N)``: block
  ``(i, j)`` is the load on body i per acceleration / velocity of body j, symmetrised
  ``(A + Aᵀ)/2`` (reciprocity: ``A_ij = A_jiᵀ``, Newman 1977 §6.17), and ``A∞`` likewise;
- each body's excitation in the presence of the others (diffraction by all of them),
  ``(n, n_headings, 6N)``, its phase referred to the world origin;
- per body, a :class:`~fluid.potential.coefficients.Coefficients` with its diagonal blocks,
  its own hydrostatics (as :func:`~fluid.potential.coefficients.compute`) and its excitation
  referred to its own centre (``X e^{−i k (x_i cos β + y_i sin β)}``, Capytaine's incident
  wave being ``e^{i k (x cos β + y sin β)}``), the form :mod:`.waves` takes.

Why: bodies a few diameters apart shelter, reflect and radiate onto one another (Ohkusu 1974;
Kagemoto & Yue 1986); the cross terms decay only as ``1 / sqrt(k r)`` with the distance ``r``
in waves, while the diagonal blocks tend to each body's own quickly.

Cache: as :mod:`.coefficients` (same folder), keyed by every hull, its name, its position and
its centre of mass, the lids, ``rho``, ``g``, depth, frequencies, headings and Capytaine's
version; the hydrostatics are recomputed (no BEM). Limits: as :mod:`.coefficients`; no Kochin
functions (no drift force) for a group.
"""

from __future__ import annotations

import hashlib
import math
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import numpy as np

from errors import InputError
from fluid.potential.capytaine_io import (CACHE_FORMAT, cache_dir, lid_for, plain, quiet, read_dataset,
                                          require_capytaine, say, write_dataset)
from fluid.potential.coefficients import DOFS, Coefficients, symmetric_part
from fluid.potential.hull import Hull


@dataclass(frozen=True)
class GroupCoefficients:
    """The coupled coefficients of N bodies (module docstring); dofs body by body, each surge,
    sway, heave, roll, pitch, yaw about its centre of mass."""

    names: tuple
    positions: np.ndarray  #: (N, 2) [m]
    omega: np.ndarray
    added_mass: np.ndarray  #: (n, 6N, 6N)
    damping: np.ndarray  #: (n, 6N, 6N)
    added_mass_inf: np.ndarray  #: (6N, 6N)
    excitation: np.ndarray  #: (n, n_headings, 6N), phase at the world origin
    headings: np.ndarray  #: [deg]
    bodies: tuple  #: per body, its Coefficients (module docstring)
    key: str

    def block(self, a: np.ndarray, i: int, j: int) -> np.ndarray:
        """Block ``(i, j)`` (body i's load, body j's motion) of a ``(..., 6N, 6N)`` array."""
        return a[..., 6 * i:6 * i + 6, 6 * j:6 * j + 6]


def _key(parts, omega, headings, rho, g, depth, version) -> str:
    h = hashlib.sha256()
    h.update(f"cosim-potential-group-{CACHE_FORMAT}|capytaine-{version}|".encode())
    for name, arrays in parts:
        h.update(name.encode())
        for arr in arrays:
            a = np.ascontiguousarray(np.round(np.asarray(arr, float), 12))
            h.update(str(a.shape).encode())
            h.update(a.tobytes())
    for arr in (omega, headings, np.array([rho, g, depth], float)):
        h.update(np.ascontiguousarray(np.round(np.asarray(arr, float), 12)).tobytes())
    return h.hexdigest()[:24]


def compute_group(hulls: Sequence[Hull], positions, centre_of_mass_z, *, names: Sequence[str], omega,
                  headings=(0.0,), depth: float = math.inf, rho: float = 1000.0, g: float = 9.81,
                  cache: Path | str | None = None, lid: bool | None = None, use_cache: bool = True
                  ) -> GroupCoefficients:
    """The coefficients of ``hulls`` solved together (module docstring): ``positions`` (N, 2) [m]
    their centres of mass horizontally, ``centre_of_mass_z`` (N,) [m] their heights above the
    still water; the rest as :func:`fluid.potential.coefficients.compute`."""
    cpt = require_capytaine()
    import xarray as xr

    n = len(hulls)
    positions = np.asarray(positions, float).reshape(n, 2)
    zc = np.asarray(centre_of_mass_z, float).reshape(n)
    omega = np.asarray(omega, float)
    headings = np.asarray(headings, float).ravel()
    names = tuple(names)
    if n < 1 or len(set(names)) != n or any("__" in s for s in names):
        raise InputError(f"potential flow: a group needs distinct body names without '__', got {names}")
    if omega.ndim != 1 or len(omega) < 2 or not np.all(np.diff(omega) > 0) or omega[0] <= 0:
        raise InputError(f"potential flow: omega must be at least 2 increasing frequencies > 0 rad/s, got {omega}")
    for hull, name in zip(hulls, names):
        if math.isfinite(depth) and hull.draft >= depth:
            raise InputError(f"potential flow: body '{name}' draws {hull.draft:.4g} m in water {depth:g} m deep; it "
                             f"must float clear of the seabed")
    members, parts, statics = [], [], []
    for hull, name, (x, y), z in zip(hulls, names, positions, zc):
        cog = np.array([x, y, z])
        mesh = cpt.Mesh(vertices=hull.vertices + [x, y, 0.0], faces=hull.faces, name=name)
        lid_mesh, lid_arrays = lid_for(cpt, mesh, hull, float(omega[-1]), g, lid)
        members.append(cpt.FloatingBody(mesh=mesh, lid_mesh=lid_mesh, dofs=cpt.rigid_body_dofs(rotation_center=cog),
                                        center_of_mass=cog, name=name))
        parts.append((name, (mesh.vertices, hull.faces, lid_arrays[0], lid_arrays[1], cog)))
        exact = cpt.FloatingBody(mesh=mesh.with_quadrature("Gauss-Legendre 2"),
                                 dofs=cpt.rigid_body_dofs(rotation_center=cog), center_of_mass=cog, name=name)
        statics.append(exact.compute_hydrostatics(rho=rho, g=g))
    key = _key(parts, omega, headings, rho, g, depth, cpt.__version__)
    folder = Path(cache) if cache is not None else cache_dir()
    path = folder / f"group-{'-'.join(names)[:60]}-{key}.nc"
    dofs = [f"{s}__{d}" for s in names for d in DOFS]
    hit = use_cache and path.is_file()
    if hit:
        ds = read_dataset(cpt, path)
        say("potential flow: bodies %s solved together: coefficients from the cache %s", ", ".join(names), path)
    else:
        body = cpt.FloatingBody.join_bodies(*members, name="group") if n > 1 else members[0]
        common = {"radiating_dof": list(body.dofs), "water_depth": [depth], "rho": [rho], "g": [g]}
        waves = xr.Dataset(coords={"omega": omega, "wave_direction": np.radians(headings), **common})
        say("potential flow: bodies %s solved together: %d problems on %d panels", ", ".join(names),
            len(omega) * (6 * n + len(headings)) + 6 * n, sum(h.panels for h in hulls))
        solver = cpt.BEMSolver()
        t0 = time.perf_counter()
        with quiet("capytaine"):
            ds = solver.fill_dataset(waves, body, progress_bar=sys.stderr.isatty())
            ds_inf = solver.fill_dataset(xr.Dataset(coords={"omega": [np.inf], **common}), body, progress_bar=False)
        ds = plain(ds)
        ds["added_mass_inf"] = plain(ds_inf)["added_mass"].isel(omega=0, drop=True)
        if n == 1:  # a lone body's dofs carry no prefix
            ds = ds.assign_coords(radiating_dof=dofs, influenced_dof=dofs)
        ds.attrs.update(cosim_key=key, cosim_solve_s=time.perf_counter() - t0)
        if use_cache:
            write_dataset(path, ds)
    order = dict(influenced_dof=dofs, radiating_dof=dofs)
    A = symmetric_part(ds["added_mass"].sel(**order).transpose("omega", "influenced_dof", "radiating_dof").values)
    B = symmetric_part(ds["radiation_damping"].sel(**order).transpose("omega", "influenced_dof", "radiating_dof").values)
    Ainf = symmetric_part(ds["added_mass_inf"].sel(**order).values)
    X = ds["excitation_force"].sel(influenced_dof=dofs).transpose("omega", "wave_direction", "influenced_dof").values
    k = np.asarray(ds["wavenumber"].values, float).ravel()
    if not (np.isfinite(A).all() and np.isfinite(B).all() and np.isfinite(X).all()):
        raise InputError(f"potential flow: the BEM solve of bodies {names} left non-finite coefficients")
    beta = np.radians(headings)
    single = []
    for i, (hull, name, hs) in enumerate(zip(hulls, names, statics)):
        s = slice(6 * i, 6 * i + 6)
        shift = np.exp(-1j * k[:, None] * (positions[i] @ np.stack([np.cos(beta), np.sin(beta)])))[..., None]
        cob = np.asarray(hs["center_of_buoyancy"], float) - [*positions[i], 0.0]
        single.append(Coefficients(
            omega=omega, added_mass=A[:, s, s], damping=B[:, s, s], added_mass_inf=Ainf[s, s],
            excitation=X[..., s] * shift, headings=headings,
            stiffness=np.asarray(hs["hydrostatic_stiffness"], float).reshape(6, 6), volume=float(hs["disp_volume"]),
            centre_of_buoyancy=cob, centre_of_mass=np.array([0.0, 0.0, zc[i]]),
            waterplane_area=float(hs["waterplane_area"]), rho=rho, g=g, depth=depth, panels=hull.panels, key=key,
            meta={"from_cache": hit, "group": names}, wavenumber=k))
    return GroupCoefficients(names, positions, omega, A, B, Ainf, X, headings, tuple(single), key)

