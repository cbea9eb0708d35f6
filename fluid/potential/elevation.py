"""The free-surface elevation a body radiates when it oscillates in one degree of freedom, at
given points, from the boundary-element solver Capytaine, cached.

What: for a :class:`fluid.potential.hull.Hull` moving in ``dof`` (one of
:data:`fluid.potential.coefficients.DOFS`, about its centre of mass) as ``X(t) = Re(X
e^{−iωt})`` (Capytaine's convention, as :mod:`fluid.potential.coefficients`) at ``omega``
[rad/s], the linear radiated elevation ``η(x, y, t) = Re(X e(x, y) e^{−iωt})`` [m] at the
points ``(x, y)`` [m] of the still water surface: ``e`` per unit motion amplitude [m/m, or
m/rad], ``η = (iω/g) φ`` of the radiation potential ``φ`` (Newman 1977, Marine
Hydrodynamics §6.17; Capytaine's ``compute_free_surface_elevation`` on a radiation problem
with the body's unit displacement, its boundary condition ``∂φ/∂n = −iω n·ξ``).

Why: a body forced in still water (``cosim.validations.radiation``) is judged by its force,
and the wave it sends out is what the force's damping part feeds; comparing the measured
elevation with this one gauge by gauge needs no far-field assumption (the evanescent modes
near the body are in both), and splitting this elevation as the measured one is split
gives the method's own floor.

Limits: linear (small motion), zero forward speed, points outside the hull's waterline; the
lid against irregular frequencies as in :func:`fluid.potential.coefficients.compute`.

Cache: one ``.npz`` per hull mesh, lid, centre of mass, dof, ``omega``, points, ``rho``,
``g``, depth and Capytaine version (hashed), in :func:`fluid.potential.capytaine_io.cache_dir`.
"""

from __future__ import annotations

import hashlib
import math
from pathlib import Path

import numpy as np

from errors import InputError
from fluid.potential.capytaine_io import cache_dir, cache_key, lid_for, quiet, require_capytaine, say
from fluid.potential.coefficients import DOFS
from fluid.potential.hull import Hull


def radiated_elevation(hull: Hull, centre_of_mass_z: float, dof: str, omega: float, points, *,
                       depth: float = math.inf, rho: float = 1000.0, g: float = 9.81,
                       cache: Path | str | None = None, lid: bool | None = None) -> np.ndarray:
    """Complex ``e`` [m per unit motion] at ``points`` (n, 2) [m], the centre of mass at
    (0, 0, ``centre_of_mass_z``) [m] (module docstring: ``η = Re(X e e^{−iωt})``)."""
    cpt = require_capytaine()
    if dof not in DOFS:
        raise InputError(f"potential flow: dof {dof!r}; give one of {', '.join(DOFS)}")
    if not (math.isfinite(omega) and omega > 0):
        raise InputError(f"potential flow: omega = {omega!r} rad/s; give a finite frequency > 0")
    pts = np.asarray(points, float)
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) == 0 or not np.all(np.isfinite(pts)):
        raise InputError(f"potential flow: points must be an (n, 2) array of finite x, y [m], got shape {pts.shape}")
    if math.isfinite(depth) and hull.draft >= depth:
        raise InputError(f"potential flow: the hull draws {hull.draft:.4g} m in water {depth:g} m deep; it must "
                         f"float clear of the seabed")
    cog = np.array([0.0, 0.0, centre_of_mass_z])
    mesh = cpt.Mesh(vertices=hull.vertices, faces=hull.faces, name="body")
    lid_mesh, lid_arrays = lid_for(cpt, mesh, hull, omega, g, lid)
    # the coefficients' key of this hull, lid and water at the one frequency (no heading), then the dof and points
    h = hashlib.sha256(cache_key(hull, lid_arrays, cog, rho, g, depth, np.array([omega]), np.zeros(0),
                            cpt.__version__).encode())
    h.update(dof.encode())
    h.update(np.ascontiguousarray(np.round(pts, 12)).tobytes())
    path = Path(cache if cache is not None else cache_dir()) / f"elevation-{h.hexdigest()[:24]}.npz"
    if path.is_file():
        return np.load(path)["e"]
    body = cpt.FloatingBody(mesh=mesh, lid_mesh=lid_mesh, dofs=cpt.rigid_body_dofs(rotation_center=cog),
                            center_of_mass=cog)
    say("potential flow: the elevation radiated in %s at %.4g rad/s, %d points (%d panels); cached in %s",
        dof, omega, len(pts), hull.panels, path.parent)
    solver = cpt.BEMSolver()
    with quiet("capytaine"):
        result = solver.solve(cpt.RadiationProblem(body=body, radiating_dof=dof, omega=omega, water_depth=depth,
                                                   rho=rho, g=g), keep_details=True)
        e = np.asarray(solver.compute_free_surface_elevation(pts, result), complex).reshape(len(pts))
    path.parent.mkdir(parents=True, exist_ok=True)
    np.savez(path, e=e)
    return e
