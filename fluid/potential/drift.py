"""The mean wave drift force from the far field, and its slowly varying part in irregular seas.

What: a body in a regular wave of amplitude ``a`` [m], frequency ω and heading β feels, beside
the first-order force, a steady second-order force ``F̄ = a² D(ω, β)``: ``D`` [N/m², N m/m²]
is the mean drift coefficient per squared amplitude (a fully reflecting wall ``W`` wide gives
``D = ρ g W / 2``). The horizontal force comes from the momentum flux of the waves the body
scatters and radiates (Maruo 1960, J. Ship Res. 4(3)), the yaw moment from their angular
momentum flux (Newman 1967, J. Ship Res. 11(1)); both are integrals of the Kochin function
``H(θ) = i (H_D(θ) + Σ_j ξ_j H_j(θ))`` of diffraction and of radiation by the motions
``ξ`` (:mod:`.coefficients`, ``kochin=True``), evaluated by Capytaine's
``far_field_mean_drift_force`` on the angles :func:`.coefficients.kochin_angles`. The motions
are the first-order response of the freely floating body,
``ξ = [C − ω²(M + A(ω)) − iωB(ω)]⁻¹ X(ω)`` (Newman 1977 §6.20), or zero for a fixed body.
Heave, roll and pitch get no drift (the far field gives only the horizontal ones).

In an irregular sea of components ``(a_j, ω_j, φ_j)`` the slowly varying drift follows
Newman's (1974) approximation of the difference-frequency transfer function from its
diagonal, ``T_jk ≈ sgn(D_j) sqrt(|D_j D_k|)`` where ``D_j``, ``D_k`` share a sign and 0
where they do not (the form of Faltinsen 1990, §5.4, with the sign kept)::

    F(t) = Re[ P(t) Q(t)* ],  P = Σ_j a_j sgn(D_j) sqrt|D_j| e^{i(ψ_j − ω_j t)},
                              Q = Σ_j a_j sqrt|D_j| e^{i(ψ_j − ω_j t)}

(ψ_j the component's phase at the body, as in :mod:`.waves`), the difference-frequency part
of ``2 [Σ a_j sgn(D_j) sqrt|D_j| cos(ω_j t − ψ_j)] [Σ a_k sqrt|D_k| cos(ω_k t − ψ_k)]``, no
sum-frequency terms. One component gives ``a² D`` at all times: the regular-wave mean drift.
The force fades in as the square of the sea's fade-in.

Limits: the motions' response leaves out moorings and quadratic drag (they act mostly below the
wave frequencies) and other bodies; the far field needs the whole Kochin function, so Capytaine's
Kochin angles must resolve it (64 per turn: bodies up to a few wavelengths across); headings
between the table's are interpolated linearly; cross terms between components of different
headings use each one's own ``D`` (the same approximation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from errors import InputError
from fluid.potential.coefficients import DOFS, Coefficients
from fluid.potential.waves import Sea, _heading_interp

#: the degrees of freedom the far field gives a mean drift for (surge, sway, yaw)
DRIFT_DOFS = (0, 1, 5)


@dataclass(frozen=True)
class MeanDrift:
    """Mean drift coefficients ``D(ω, β)`` [N/m², N m/m²] per squared wave amplitude,
    ``(n_ω, n_headings, 6)`` (heave, roll, pitch zero), about the centre of mass."""

    omega: np.ndarray
    headings: np.ndarray  #: [deg]
    D: np.ndarray
    fixed: bool  #: True: the body held still (diffraction only)


def response(c: Coefficients, mass: np.ndarray) -> np.ndarray:
    """The freely floating body's motions per unit wave amplitude, ``(n_ω, n_headings, 6)``,
    ``[C − ω²(M + A) − iωB]⁻¹ X`` (Newman 1977 §6.20; ``e^{−iωt}``), ``mass`` the 6 x 6 mass
    matrix about the centre of mass, world axes [kg, kg m²]."""
    w = c.omega[:, None, None]
    Z = c.stiffness[None] - w**2 * (np.asarray(mass, float)[None] + c.added_mass) - 1j * w * c.damping
    return np.linalg.solve(Z[:, None], c.excitation[..., None])[..., 0]


def mean_drift(c: Coefficients, mass: np.ndarray | None = None, name: str = "body") -> MeanDrift:
    """The mean drift coefficients of a body from its coefficients (with Kochin functions),
    freely floating with ``mass`` (6 x 6, module docstring) or held fixed (None)."""
    if c.kochin_diffraction is None or c.wavenumber is None:
        raise InputError(f"potential flow: body '{name}': its coefficients carry no Kochin functions; compute them "
                         f"with kochin=True for the drift force")
    import xarray as xr
    from capytaine.post_pro import far_field_mean_drift_force

    beta = np.radians(c.headings)
    xi = np.zeros(c.excitation.shape, complex) if mass is None else response(c, mass)
    coords = {"omega": c.omega, "wave_direction": beta}
    ds = xr.Dataset(
        {"kochin_diffraction": (("omega", "wave_direction", "theta"), c.kochin_diffraction),
         "kochin_radiation": (("omega", "radiating_dof", "theta"), c.kochin_radiation)},
        coords={**coords, "radiating_dof": list(DOFS), "theta": c.theta,
                "wavenumber": ("omega", c.wavenumber), "water_depth": c.depth, "rho": c.rho, "g": c.g})
    X = xr.DataArray(xi, dims=("omega", "wave_direction", "radiating_dof"),
                     coords={**coords, "radiating_dof": list(DOFS)})
    out = far_field_mean_drift_force(X, ds)
    D = np.zeros((len(c.omega), len(beta), 6))
    n = np.arange(len(beta))
    for i, var in zip(DRIFT_DOFS, ("drift_force_surge", "drift_force_sway", "drift_force_yaw")):
        D[..., i] = np.asarray(out[var].values)[:, n, n].real  # each heading with itself
    if not np.isfinite(D).all():
        raise InputError(f"potential flow: body '{name}': the mean drift force is not finite (a Kochin function "
                         f"the angles do not resolve?)")
    return MeanDrift(c.omega.copy(), c.headings.copy(), D, mass is None)


class SlowDrift:
    """Newman's approximation of the drift force of a :class:`~fluid.potential.waves.Sea` on
    one body at horizontal position ``position_xy`` [m] (module docstring)."""

    def __init__(self, sea: Sea, drift: MeanDrift, position_xy, name: str = "body"):
        w = drift.omega
        out = (sea.omega < w[0] * (1 - 1e-9)) | (sea.omega > w[-1] * (1 + 1e-9))
        if out.any():
            raise InputError(f"potential flow: body '{name}': a wave of {sea.omega[out][0]:.4g} rad/s lies outside "
                             f"the drift coefficients' frequencies {w[0]:.4g}-{w[-1]:.4g} rad/s")
        Dw = np.stack([np.stack([np.interp(sea.omega, w, drift.D[:, j, i]) for i in range(6)], axis=-1)
                       for j in range(len(drift.headings))], axis=1)  # (n_c, n_β, 6)
        self.D = np.array([_heading_interp(drift.headings, Dw[c], sea.heading[c], name) for c in range(len(Dw))])
        psi = sea.k * (np.asarray(position_xy, float)[:2] @ sea._dir.T) + sea.phase
        root = sea.amplitude[:, None] * np.sqrt(np.abs(self.D))  # (n_c, 6)
        e = np.exp(1j * psi)[:, None]
        self._q = root * e
        self._p = np.sign(self.D) * root * e
        self.sea = sea

    def force(self, t: float) -> np.ndarray:
        """[F_x, F_y, 0, 0, 0, M_z] [N, N m] about the centre of mass at time ``t`` [s]."""
        rot = np.exp(-1j * self.sea.omega * t)[:, None]  # the components' phases at t, e^{i(ψ − ωt)}
        P = (self._p * rot).sum(axis=0)
        Q = (self._q * rot).sum(axis=0)
        return self.sea.fade(t) ** 2 * (P * Q.conj()).real

