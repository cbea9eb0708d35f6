"""Light bodies: their mass ratio, the remedy chosen from it, and the added-mass remedy.

Why: a body in a fluid feels, besides the other loads ``F_r``, a reaction to its own
acceleration, ``-m_a a`` (added mass). Staggered coupling hands the body the fluid load
of the previous exchange, so the body's step reads ``m a_{n+1} = F_r - m_a a_n``: the
acceleration is multiplied by ``-m_a / m`` every step and grows without bound once the
added mass exceeds the body's mass (``docs/DESIGN.md``, added mass).

Remedies (the coupler's ``light_body``):

- ``"added-mass"``: with an estimate ``m^`` of the added mass per degree of freedom,
  the body gets ``m^`` as extra inertia without weight (MuJoCo ``dof_armature``) and the
  fluid load is handed over as ``F_fluid + m^ a_prev``, ``a_prev`` being the body's mean
  acceleration over the previous coupling step. Then

      (m + m^) a_{n+1} = F_r - m_a a_n + m^ a_n,   a_{n+1} / a_n -> (m^ - m_a) / (m + m^),

  stable for any ``m^ > (m_a - m) / 2`` (an over-estimate is safe), exact at once if
  ``m^ = m_a`` (``a = F_r / (m + m_a)``) and exact in any steady state (the added term
  cancels the armature's). Momentum: the body holds ``m^ (v_n - v_{n-1})`` more than the
  impulse it received (one step's change, no drift). It assumes a fluid whose reaction
  to the body's acceleration comes within the step; the weakly compressible SPH fluid's
  comes acoustically later, and there it made every scheme worse
  (``benchmarks/density_ratio_sweep.py``), so ``"auto"`` never picks it.
- ``"subiterate"``: the fluid-first step repeated from saved states until the bodies'
  motion and the fluid's agree (``Coupler._subiterated_fluid_loads``); what ``"auto"``
  picks for a fluid-first coupler below :data:`AUTO_THRESHOLD`.

The added-mass estimate is the mass and inertia of the fluid the body displaces: per
degree of freedom the body's own inertia times ``rho V / m`` (a uniform body filled
with fluid; a circle's heave added mass is exactly this, a box's 1 to 2 times it, a
sphere's half of it).
"""

from __future__ import annotations

import logging

import numpy as np

from cosim.errors import ConfigurationError, InputError
from fluid.analytic import geom_volume

log = logging.getLogger(__name__)

#: the values of the coupler's ``light_body`` option
LIGHT_BODY = ("auto", "none", "added-mass", "subiterate")

#: body mass / displaced fluid mass below which ``"auto"`` sub-iterates the fluid-first
#: scheme: the break measured by ``benchmarks/density_ratio_sweep.py`` (submerged 2-D box
#: in SPH, dx = 2 cm: growing oscillation at 0.05, clean at 0.1 over 0.12 s but growing
#: over 0.2 s with an earlier body boundary, clean at 0.2) times 3 as margin. The explicit
#: and predictor-corrector schemes ran clean down to 0.003 there and have no remedy of
#: their own, so "auto" leaves them alone (the instability watch still stops a run).
AUTO_THRESHOLD = 0.3

#: what each ``light_body`` value does, in a user's words (the ``--light-body`` help of
#: the command-line scenarios, :func:`cosim.cli.add_light_body_option`)
LIGHT_BODY_HELP = {
    "auto": f"pick per body from its mass / displaced fluid mass: 'subiterate' below {AUTO_THRESHOLD} when the "
            f"fluid's loads carry added mass (the SPH fluid) and the scheme is fluid-first, else 'none'",
    "none": "plain staggered coupling (unstable once a body is much lighter than the fluid it displaces)",
    "subiterate": "repeat each coupling step from saved states until the body's and the fluid's motion agree "
                  "(fluid-first only; 2-4 fluid advances a step, stable down to a ratio of 0.001)",
    "added-mass": "add the displaced fluid's mass to the body's inertia and its lagged reaction to the load "
                  "(for fluids that react within the step; it made every scheme worse with the weakly "
                  "compressible SPH fluid)",
}


def fluid_density(fluid, required: bool = True) -> float | None:
    """The fluid's density [kg/m^3] (an SPH fluid's reference density); ``None`` if it
    states none and ``required`` is false."""
    rho = getattr(fluid, "rho", None)
    if rho is None and hasattr(fluid, "config"):
        rho = getattr(fluid.config, "rho0", None)
    if rho is None and not required:
        return None
    if rho is None:
        raise ConfigurationError(f"fluid '{fluid.name}' states no density (attribute rho or config.rho0); the "
                                 f"light-body remedy needs it: give the fluid one or pass light_body='none'")
    return float(rho)


class AddedMass:
    """Added-mass estimates of the coupled bodies and the load correction that goes
    with the armature. Built at set-up; :meth:`choose` decides which bodies get it."""

    def __init__(self, bodies, rho: float):
        self.bodies = bodies
        self.rho = rho
        self.mass = bodies.masses()
        self.volume = np.array([sum(geom_volume(g.kind, g.size, g.mesh) for g in shapes) for shapes in bodies.geoms()])
        #: body mass / mass of the fluid it displaces [-], per body
        self.ratio = np.divide(self.mass, rho * self.volume, out=np.full(len(self.mass), np.inf),
                               where=self.volume > 0)
        self.armature: dict[int, np.ndarray] = {}  #: body index -> added inertia per dof [kg, kg m^2]
        self._qvel: np.ndarray | None = None  # generalised velocities at the start of the last step
        self._dt = 0.0

    def estimate(self, k: int) -> np.ndarray:
        """Added mass and inertia per degree of freedom of body ``k`` [kg, kg m^2]:
        its own inertia there times rho V / m."""
        return self.bodies.dof_inertia(k) / self.ratio[k]

    def choose(self, mode: str, scheme: str, carries_added_mass: bool) -> dict[str, str]:
        """Decide the remedy of each body (installing the armature of "added-mass");
        returns the remedy per body name."""
        if mode not in LIGHT_BODY:
            raise InputError(f"light_body={mode!r} is not one of {', '.join(LIGHT_BODY)}")
        if mode == "subiterate" and scheme != "fluid-first":
            raise ConfigurationError(f"light_body='subiterate' iterates the fluid-first scheme; the coupler uses "
                                     f"{scheme!r}: pass scheme='fluid-first'")
        remedies = {}
        for k, name in enumerate(self.bodies.body_names):
            if mode == "auto":
                light = carries_added_mass and scheme == "fluid-first" and self.ratio[k] < AUTO_THRESHOLD
                remedy = "subiterate" if light else "none"
            else:
                remedy = mode
            if remedy == "added-mass":
                if self.volume[k] <= 0:
                    raise ConfigurationError(f"body '{name}' has no solid geom, so no displaced volume to estimate "
                                             f"its added mass from; pass light_body='none'")
                self.armature[k] = self.estimate(k)
                self.bodies.add_armature(k, self.armature[k])
            remedies[name] = remedy
            log.info("coupler: body '%s' mass / displaced fluid mass = %.3g (%s scheme, light_body=%r): "
                     "light-body remedy %s%s", name, self.ratio[k], scheme, mode, remedy,
                     f", added inertia per dof {np.array2string(self.armature[k], precision=4)}"
                     if remedy == "added-mass" else "")
        return remedies

    def correction(self) -> tuple[np.ndarray, np.ndarray]:
        """The load that goes with the armature, ``m^ a_prev`` per body: force [N] and
        torque about the centre of mass [N m], world frame (zero before the first step)."""
        n = self.bodies.n_bodies
        F, T = np.zeros((n, 3)), np.zeros((n, 3))
        if self._qvel is None or not self.armature:
            return F, T
        qacc = (self.bodies.dof_velocities() - self._qvel) / self._dt
        for k, ma in self.armature.items():
            F[k], T[k] = self.bodies.wrench_for_dof_forces(k, ma * qacc[self.bodies.dofs(k)])
        return F, T

    def step_started(self, dt: float) -> None:
        """Remember the velocities at the start of a step of ``dt`` [s] (after :meth:`correction`)."""
        if self.armature:
            self._qvel, self._dt = self.bodies.dof_velocities(), dt

    def save_state(self):
        return None if self._qvel is None else (self._qvel.copy(), self._dt)

    def load_state(self, state) -> None:
        self._qvel, self._dt = (None, 0.0) if state is None else (state[0].copy(), state[1])
