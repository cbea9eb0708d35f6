"""Hydrodynamic coefficients of one body from the boundary-element solver Capytaine, cached.

What: for a :class:`fluid.potential.hull.Hull` with six rigid-body degrees of freedom about
its centre of mass (surge, sway, heave [m]; roll, pitch, yaw [rad] about the world axes
through it), water of density ``rho`` [kg/m^3] and ``depth`` [m] (``inf``: deep), gravity
``g`` [m/s^2], angular frequencies ``omega`` [rad/s] and wave headings [deg] (towards which
the waves travel, from +x towards +y):

- the added mass ``A(ω)`` [kg, kg m, kg m^2] and radiation damping ``B(ω)`` [N s/m ...]
  (the radiation force is ``−A ẍ − B ẋ``), symmetrised ``(A + Aᵀ)/2`` (the panel method's
  matrices are symmetric only to discretisation error; Newman 1977 §6.17);
- ``A∞``, the added mass at infinite frequency (Capytaine's ``omega = inf`` problem);
- the excitation force ``X(ω, β)`` [N/m, N m/m] per unit wave amplitude, Froude–Krylov
  plus diffraction, for the wave ``η = Re(e^{i k (x cos β + y sin β)} e^{−iωt})`` (crest at
  the centre of mass at ``t = 0``; Capytaine's convention, ``e^{−iωt}``), so that a wave of
  amplitude ``a`` and phase ``φ`` gives ``F(t) = Re(a e^{iφ} X e^{−iωt})``;
- hydrostatics of the hull (displaced volume [m^3], centre of buoyancy [m], waterplane
  area [m^2]) and the buoyancy restoring matrix ``C`` about the centre of mass (Newman
  1977 §6.16 Eq. 6.186 with the rotation centre at the centre of mass: the weight, which
  MuJoCo applies at the centre of mass, gives no moment there and is left out);
- on request (``kochin=True``), the Kochin functions (far-field amplitudes) of the
  diffraction and radiation problems on the angles :func:`kochin_angles`, from which
  :mod:`fluid.potential.drift` takes the mean drift force (Capytaine's ``compute_kochin``).

The irregular frequencies of the hull's interior (John 1950) are removed by a lid on the
interior free surface (Capytaine's ``lid_mesh``, the extended boundary integral equation),
placed where Capytaine's ``lowest_lid_position`` puts it for the highest frequency, when
Capytaine's estimate of the first irregular frequency lies below 1.5 times the highest.

Cache: computed once per hull mesh, lid, rotation centre, ``rho``, ``g``, depth,
frequencies, headings and Capytaine version (a SHA-256 of all of them keys the file), as
NetCDF (Capytaine's dataset, complex values split, xarray's writer, engine h5netcdf) in
:func:`cache_dir` (``$COSIM_POTENTIAL_CACHE``, else ``~/.cache/cosim-sph/potential``).
A hit is reported, and a solve with its panel and problem counts, as a log record and, on a
terminal, a line on standard error (as the coupler's progress line) with Capytaine's progress
bar while it solves.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from errors import InputError
from fluid.potential.capytaine_io import (cache_dir, cache_key, lid_for, plain, quiet, read_dataset,
                                          require_capytaine, say, write_dataset)
from fluid.potential.hull import Hull

#: the six rigid-body degrees of freedom, in Capytaine's names and this order
DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")
#: Kochin angles per turn (:func:`kochin_angles`)
KOCHIN_STEPS = 64


@dataclass(frozen=True)
class Coefficients:
    """One body's frequency-domain coefficients (see the module docstring); dof order
    surge, sway, heave, roll, pitch, yaw about the centre of mass."""

    omega: np.ndarray  #: angular frequencies [rad/s], (n,), increasing
    added_mass: np.ndarray  #: A(ω), (n, 6, 6)
    damping: np.ndarray  #: B(ω), (n, 6, 6)
    added_mass_inf: np.ndarray  #: A∞, (6, 6)
    excitation: np.ndarray  #: X(ω, β) per unit amplitude, complex (n, n_headings, 6)
    headings: np.ndarray  #: wave headings [deg], (n_headings,)
    stiffness: np.ndarray  #: C, buoyancy restoring about the centre of mass, (6, 6)
    volume: float  #: displaced volume [m^3]
    centre_of_buoyancy: np.ndarray  #: relative to the centre of mass horizontally, z from the still water [m]
    centre_of_mass: np.ndarray  #: same frame [m]: (0, 0, z_G)
    waterplane_area: float  #: [m^2]
    rho: float
    g: float
    depth: float  #: [m], inf: deep water
    panels: int  #: hull panels
    key: str  #: the cache key
    meta: dict = field(default_factory=dict)  #: solve time [s], lid panels, from the cache or not
    wavenumber: np.ndarray | None = None  #: k(ω) [rad/m], (n,)
    theta: np.ndarray | None = None  #: Kochin angles [rad], (n_θ,); None: not computed
    kochin_diffraction: np.ndarray | None = None  #: complex (n, n_headings, n_θ) per unit amplitude
    kochin_radiation: np.ndarray | None = None  #: complex (n, 6, n_θ) per unit motion


def kochin_angles(headings) -> np.ndarray:
    """Angles [rad] for the Kochin functions: steps of 2π / :data:`KOCHIN_STEPS` from 0 to 2π
    (both on the grid, for Capytaine's integral over a turn) widened by two steps beyond the
    headings [deg] on either side (Capytaine differentiates at the headings, inside the grid)."""
    b = np.radians(np.asarray(headings, float))
    step = 2.0 * math.pi / KOCHIN_STEPS
    lo = math.floor(min(0.0, b.min()) / step + 1e-9) - 2
    hi = math.ceil(max(2.0 * math.pi, b.max()) / step - 1e-9) + 2
    return np.arange(lo, hi + 1) * step


def compute(hull: Hull, centre_of_mass_z: float, *, omega, headings=(0.0,), depth: float = math.inf,
            rho: float = 1000.0, g: float = 9.81, cache: Path | str | None = None, name: str = "body",
            lid: bool | None = None, use_cache: bool = True, kochin: bool = False) -> Coefficients:
    """The coefficients of ``hull`` (rotation centre and centre of mass at (0, 0,
    ``centre_of_mass_z``) [m]) at ``omega`` [rad/s] and ``headings`` [deg], read from the
    cache in ``cache`` (default :func:`cache_dir`) or solved and written there; ``lid``: the
    irregular-frequency lid always (True), never (False) or where estimated needed (None);
    ``kochin``: with the Kochin functions (module docstring)."""
    cpt = require_capytaine()
    omega = np.asarray(omega, float)
    headings = np.asarray(headings, float).ravel()
    if omega.ndim != 1 or len(omega) < 2 or not np.all(np.isfinite(omega)) or not np.all(np.diff(omega) > 0) \
            or omega[0] <= 0:
        raise InputError(f"potential flow: omega must be at least 2 increasing finite frequencies > 0 rad/s, got "
                         f"{omega}")
    if len(headings) < 1 or not np.all(np.isfinite(headings)):
        raise InputError(f"potential flow: headings must be finite angles [deg], got {headings}")
    if not (depth > 0):
        raise InputError(f"potential flow: depth = {depth!r} m; give a depth > 0 (inf: deep water)")
    if math.isfinite(depth) and hull.draft >= depth:
        raise InputError(f"potential flow: body '{name}' draws {hull.draft:.4g} m in water {depth:g} m deep; it "
                         f"must float clear of the seabed")
    cog = np.array([0.0, 0.0, centre_of_mass_z])
    mesh = cpt.Mesh(vertices=hull.vertices, faces=hull.faces, name=name)
    lid_mesh, lid = lid_for(cpt, mesh, hull, float(omega[-1]), g, lid)
    theta = kochin_angles(headings) if kochin else None
    key = cache_key(hull, lid, cog, rho, g, depth, omega, headings, cpt.__version__, theta)
    folder = Path(cache) if cache is not None else cache_dir()
    path = folder / f"{name}-{key}.nc"
    if use_cache and path.is_file():
        ds = read_dataset(cpt, path)
        say("potential flow: body '%s': coefficients from the cache %s (%d panels, %d frequencies, %d headings)",
            name, path, hull.panels, len(omega), len(headings))
        return _coefficients(ds, key, hull, from_cache=True)
    body = cpt.FloatingBody(mesh=mesh, lid_mesh=lid_mesh, dofs=cpt.rigid_body_dofs(rotation_center=cog),
                            center_of_mass=cog, name=name)
    import xarray as xr

    problems = len(omega) * (6 + len(headings)) + 6
    say("potential flow: body '%s': solving %d problems on %d panels (+%d lid panels), %d frequencies "
        "%.3g-%.3g rad/s and infinity, %d headings, depth %s; cached in %s", name, problems, hull.panels,
        len(lid[1]), len(omega), omega[0], omega[-1], len(headings), f"{depth:g} m", folder)
    common = {"radiating_dof": list(DOFS), "water_depth": [depth], "rho": [rho], "g": [g]}
    far = {} if theta is None else {"theta": theta}
    waves = xr.Dataset(coords={"omega": omega, "wave_direction": np.radians(headings), **common, **far})
    infinite = xr.Dataset(coords={"omega": [np.inf], **common})  # radiation only: no wave at ω = ∞
    solver = cpt.BEMSolver()
    t0 = time.perf_counter()
    with quiet("capytaine"):
        ds = solver.fill_dataset(waves, body, progress_bar=sys.stderr.isatty())
        ds_inf = solver.fill_dataset(infinite, body, progress_bar=False)
    wall = time.perf_counter() - t0
    ds = plain(ds)
    ds["added_mass_inf"] = plain(ds_inf)["added_mass"].isel(omega=0, drop=True)
    # the hydrostatics with a 2 x 2 Gauss-Legendre rule on each panel: its waterplane moments are
    # exact on flat panels (the one-point rule's second moments are short by A h^2 / 12)
    exact = cpt.FloatingBody(mesh=mesh.with_quadrature("Gauss-Legendre 2"),
                             dofs=cpt.rigid_body_dofs(rotation_center=cog), center_of_mass=cog, name=name)
    hs = exact.compute_hydrostatics(rho=rho, g=g)
    ds["hydrostatic_stiffness"] = (("influenced_dof", "radiating_dof"),
                                   np.asarray(hs["hydrostatic_stiffness"], float).reshape(6, 6))
    ds["disp_volume"] = float(hs["disp_volume"])
    ds["centre_of_buoyancy"] = (("xyz",), np.asarray(hs["center_of_buoyancy"], float))
    ds["waterplane_area"] = float(hs["waterplane_area"])
    ds.attrs.update(cosim_key=key, cosim_panels=hull.panels, cosim_lid_panels=len(lid[1]), cosim_solve_s=wall)
    say("potential flow: body '%s': solved in %.1f s", name, wall)
    if use_cache:
        write_dataset(path, ds)
    return _coefficients(ds, key, hull, from_cache=False)


def symmetric_part(a: np.ndarray) -> np.ndarray:
    """``(a + aᵀ) / 2`` over the last two axes: the panel method's matrices are symmetric only
    to discretisation error (Newman 1977 §6.17)."""
    return 0.5 * (a + np.swapaxes(a, -1, -2))


def _coefficients(ds, key: str, hull: Hull, from_cache: bool) -> Coefficients:
    order = dict(influenced_dof=list(DOFS), radiating_dof=list(DOFS))
    omega = np.asarray(ds["omega"].values, float)
    A = np.asarray(ds["added_mass"].sel(**order).transpose("omega", "influenced_dof", "radiating_dof").values)
    B = np.asarray(ds["radiation_damping"].sel(**order).transpose("omega", "influenced_dof", "radiating_dof").values)
    X = ds["excitation_force"].sel(influenced_dof=list(DOFS)).transpose("omega", "wave_direction", "influenced_dof")
    X = np.asarray(X.values)
    Ainf = np.asarray(ds["added_mass_inf"].sel(**order).values, float)
    C = np.asarray(ds["hydrostatic_stiffness"].sel(**order).values, float)
    cob = np.asarray(ds["centre_of_buoyancy"].values, float)
    cog = np.asarray(ds["center_of_mass"].values, float) if "center_of_mass" in ds.coords else np.zeros(3)
    far = {}
    if "kochin_diffraction" in ds:
        far = dict(theta=np.asarray(ds["theta"].values, float),
                   kochin_diffraction=np.asarray(ds["kochin_diffraction"].transpose("omega", "wave_direction",
                                                                                   "theta").values),
                   kochin_radiation=np.asarray(ds["kochin_radiation"].sel(radiating_dof=list(DOFS))
                                               .transpose("omega", "radiating_dof", "theta").values))
    if not (np.isfinite(A).all() and np.isfinite(B).all() and np.isfinite(X).all()):
        raise InputError(f"potential flow: the BEM solve of body '{ds.attrs.get('body', '?')}' left non-finite "
                         f"coefficients (a degenerate mesh?); refine or coarsen panel_size")
    return Coefficients(omega=omega, added_mass=symmetric_part(A), damping=symmetric_part(B), added_mass_inf=symmetric_part(Ainf),
                        excitation=X, headings=np.degrees(np.asarray(ds["wave_direction"].values, float)),
                        stiffness=C, volume=float(ds["disp_volume"]), centre_of_buoyancy=cob, centre_of_mass=cog,
                        waterplane_area=float(ds["waterplane_area"]), rho=float(ds["rho"]), g=float(ds["g"]),
                        depth=float(ds["water_depth"]), panels=hull.panels, key=key,
                        meta={"from_cache": from_cache, "solve_s": float(ds.attrs.get("cosim_solve_s", math.nan)),
                              "lid_panels": int(ds.attrs.get("cosim_lid_panels", 0))},
                        wavenumber=np.asarray(ds["wavenumber"].values, float).ravel() if "wavenumber" in ds else None,
                        **far)
