"""The coupler: keeps every participant on one clock and runs the coupling steps.

One coupling step (:meth:`Coupler.step`), in this order (``docs/DESIGN.md``):

1. the step size: the smallest ``max_dt()`` of all participants and the step the
   bodies can follow their mooring lines at (:mod:`cosim.line_step`, from each line's
   ``fairlead_stiffness()``; a fixed step the user asks for above it at the start is
   refused), or the fixed step the user asked for, if smaller, rounded down to whole
   clock ticks and clipped so that the run lands exactly on its end time (a step the
   lines set is evened out towards it instead: no sliver of a step);
2. the fluid's loads on each body, for the bodies' current kinematics (force,
   and torque about the centre of mass; world frame);
3. each mooring's force on its fairleads (for the fairlead motion it was last
   given), turned into a force and a torque about each body's centre of mass;
4. the bodies advance with the sum of 2 and 3 (MuJoCo adds gravity, joints and
   contacts, and sub-steps as it needs); with the predictor-corrector scheme the
   loads are first re-taken at the predicted pose and averaged, with the fluid-first
   scheme the fluid has advanced first and 2 is the load it exchanged (see ``scheme``;
   for light bodies see ``light_body``); dynamic mooring lines advance with the bodies
   until the bodies' force from them is the lines' mean force over the step (see
   ``lines``); the instability watch (:mod:`cosim.watch`) looks at the bodies' new
   accelerations and speeds;
5. the fluid gets the new body kinematics and advances; each quasi-static mooring gets
   the new fairlead motion and advances;
6. any other participant advances; the clock advances by whole ticks (no drift).

The coupler is the only owner of time: participants get ``t`` and ``dt`` with
every ``advance`` and never accumulate time themselves. It is also the only
writer of body loads, and it books them per body and step in :attr:`ledger`.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, Callable, Sequence

import numpy as np

from bodies.sampling import cross
from cosim.added_mass import LIGHT_BODY, AddedMass, fluid_density
from cosim.clock import TICKS_PER_SECOND, Clock, to_ticks
from cosim.errors import ConfigurationError, ConvergenceError, InputError, InstabilityError, SolverError
from cosim.ledger import Ledger
from cosim.progress import Progress
from cosim.protocol import (AddedMassLoads, Breaking, Configured, DrivenBodies, DrivenToStepEnd, DynamicMooring,
                            ElasticStructures, ExchangedLoads, Fluid, Gravity, LimitReported, Mooring, Participant,
                            SaysDynamic, SpeedOfSound, Tethered, TimedLoads, check_participant)
from cosim.watch import InstabilityWatch


log = logging.getLogger(__name__)

SCHEMES = ("auto", "explicit", "predictor-corrector", "fluid-first")
LINES = ("auto", "subiterate", "explicit")


@dataclass(frozen=True)
class StepInfo:
    """What one coupling step did."""

    index: int  #: step number, from 1
    t: float  #: time at the end of the step [s]
    dt: float  #: step taken [s]
    limiter: str  #: what set dt: a participant's name, "user dt" or "end time"


@dataclass(frozen=True)
class MooringAttachment:
    """A mooring system whose lines end on body sites.

    ``sites`` names, for each line in order, the MJCF site of its fairlead. A 2-D
    mooring (lines in the x-z plane) sees the sites' (x, z) and returns (F_x, F_z).
    """

    mooring: Mooring
    sites: tuple[str, ...]


class Coupler:
    """Runs participants on one drift-free clock and exchanges their data.

    Parameters
    ----------
    participants: participants with no data exchange (advanced last, in this order).
    bodies: the bodies participant (``bodies.MujocoBodies``), if the scene has bodies.
    fluid: a fluid that loads the bodies: a participant with ``attach_bodies(bodies)``,
        ``set_body_kinematics(kinematics)`` and ``body_wrenches()``.
    moorings: :class:`MooringAttachment` records (or ``(mooring, sites)`` pairs).
    dt:
        Fixed coupling step [s]; ``None``: the participants' ``max_dt()`` and the lines'
        limit (:mod:`cosim.line_step`) decide. A step above a participant's stable step or the
        lines' limit at the start is refused (:class:`~cosim.errors.ConfigurationError` naming
        it, the limit and the fix); :meth:`step_summary` counts what set each step.
    t0: start time [s]. ``fluid_steps``: the fluid's stable steps per exchange (1: each);
        above 1 it sub-steps across an exchange with the bodies' motion held (docs/coupling.md).
    scheme:
        How body loads are taken over a step: ``"explicit"`` (the start loads held; adds
        energy, growth ~ (ω dt)²/4 per step, ω² = k/m), ``"predictor-corrector"`` (the mean of
        the start loads and those at the predicted pose, exchanging participants rolled back;
        growth ~ (ω dt)⁴), ``"fluid-first"`` (the fluid first; the bodies receive exactly the
        impulse it exchanged, ``exchanged_wrenches()``), ``"auto"`` (default: fluid-first with
        the SPH fluid; explicit where no participant gives the bodies loads, which every
        scheme then steps alike; else predictor-corrector).
    light_body:
        For bodies much lighter than the fluid they displace (added mass, :mod:`cosim.added_mass`,
        ``benchmarks/density_ratio_sweep.py``): ``"auto"`` (default) takes ``"subiterate"`` with
        fluid-first, a fluid whose loads carry added mass (SPH) and a mass ratio below
        ``cosim.added_mass.AUTO_THRESHOLD`` (0.3), else ``"none"``; ``"subiterate"`` repeats
        each step from saved states, Aitken-relaxed, until bodies and fluid agree;
        ``"added-mass"`` puts an estimate into each body's inertia (not for SPH). The choice
        is in :attr:`remedies`. A body whose acceleration oscillates with growing amplitude or
        outruns the fluid (``MAX_MACH``) stops the run with an :class:`InstabilityError`.
    lines:
        How bodies and dynamic lines (SPH cable, MoorDyn) exchange loads: ``"subiterate"``
        (``"auto"``, the default: each step repeated from saved states until the force the
        bodies were given is the lines' mean force over it; :attr:`line_iterations`) or
        ``"explicit"`` (the start force held; on a stiff chain a limit cycle at the derived
        step, ``benchmarks/line_step_sweep.py``). Quasi-static laws follow ``scheme``.
    """

    def __init__(self, participants: Sequence[Participant] = (), *, bodies=None, fluid=None,
                 moorings: Sequence = (), dt: float | None = None, t0: float = 0.0,
                 scheme: str = "auto", light_body: str = "auto", lines: str = "auto", fluid_steps: int = 1):
        self.bodies, self.fluid = bodies, fluid
        if isinstance(fluid_steps, bool) or not isinstance(fluid_steps, (int, np.integer)) or fluid_steps < 1:
            raise InputError(f"fluid_steps must be a whole number of the fluid's steps per exchange, 1 or more; "
                             f"got {fluid_steps!r}")
        if fluid_steps > 1 and fluid is None:
            raise ConfigurationError("fluid_steps > 1 sub-cycles a fluid that loads bodies: this coupler has none; "
                                     "leave fluid_steps at 1")
        #: the fluid's own stable steps per exchange with the bodies and lines
        self.fluid_steps = int(fluid_steps)
        self.moorings = [m if isinstance(m, MooringAttachment) else MooringAttachment(m[0], tuple(m[1]))
                         for m in moorings]
        if (self.moorings or fluid is not None) and bodies is None:
            raise ConfigurationError("moorings and a fluid attach to bodies: pass bodies= as well")
        if fluid is not None:
            check_participant(fluid, Fluid)
        # the roles the moorings take (what they are does not change during a run; a
        # protocol's isinstance costs ~13 us, so it is asked once)
        self._says_dynamic = [isinstance(a.mooring, SaysDynamic) and a.mooring.dynamic for a in self.moorings]
        self._breaking = [isinstance(a.mooring, Breaking) for a in self.moorings]
        for a, dynamic in zip(self.moorings, self._says_dynamic):
            check_participant(a.mooring, Mooring)
            if dynamic:
                check_participant(a.mooring, DynamicMooring)
            if len(a.sites) != a.mooring.n_lines:
                raise ConfigurationError(
                    f"mooring '{a.mooring.name}' has {a.mooring.n_lines} lines but {len(a.sites)} fairlead sites "
                    f"were given; name one MJCF site per line, in line order"
                )
        self.others = list(participants)
        roles = [p for p in (fluid, bodies) if p is not None] + [a.mooring for a in self.moorings]
        self.participants = roles + self.others
        for p in self.participants:
            check_participant(p)
        names = [p.name for p in self.participants]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ConfigurationError(f"participant names must be unique; repeated: {', '.join(dup)}. Rename them.")
        if dt is not None and not (math.isfinite(dt) and dt > 0):
            raise InputError(f"coupling step dt must be a positive finite number of seconds, got {dt!r}")
        if dt is not None and to_ticks(dt) < 1:
            raise InputError(f"coupling step dt={dt!r} s is below the clock resolution of 1e-12 s")
        if scheme not in SCHEMES:
            raise InputError(f"coupling scheme {scheme!r} is not one of {', '.join(SCHEMES)}")
        #: whether a participant gives the bodies loads (with none, every scheme steps them alike)
        self._exchanges = fluid is not None or bool(self.moorings) or bool(self.others)
        if scheme == "auto":
            if isinstance(fluid, ExchangedLoads):
                scheme = "fluid-first"
            else:
                scheme = "predictor-corrector" if self._exchanges else "explicit"
        if scheme == "fluid-first" and not isinstance(fluid, ExchangedLoads):
            raise ConfigurationError("the fluid-first scheme needs a fluid that reports the loads it exchanged "
                                     "over its last advance (exchanged_wrenches(), e.g. cosim.sph_fluid.SPHFluid)")
        self.scheme = scheme
        self._warned_held = False  #: the explicit scheme's held loads warned of (once)
        self._scheme = SCHEME_STEPS[scheme]  #: how this scheme takes the bodies' loads over a step
        self._timed_loads = isinstance(fluid, TimedLoads)
        config = fluid.config if isinstance(fluid, Configured) else None  # a weakly compressible fluid's
        self._speed_of_sound = config.speed_of_sound if isinstance(config, SpeedOfSound) else None
        if light_body not in LIGHT_BODY:
            raise InputError(f"light_body={light_body!r} is not one of {', '.join(LIGHT_BODY)}")
        if light_body == "added-mass" and fluid is None:
            raise ConfigurationError("light_body='added-mass' moves a fluid's added mass into the bodies: pass fluid=")
        self.light_body = light_body
        if lines not in LINES:
            raise InputError(f"lines={lines!r} is not one of {', '.join(LINES)}")
        self.lines = "subiterate" if lines == "auto" else lines
        self.line_iterations = 0  #: advances of the dynamic lines the last step took (lines="subiterate")
        #: the light-body remedy chosen for each body, by name ("none" or "added-mass"), set at initialize()
        self.remedies: dict[str, str] = {}
        self.added_mass: AddedMass | None = None
        #: stops a run whose bodies go unstable (:mod:`cosim.watch`); its settings may be changed before a run
        self.watch = InstabilityWatch(
            [bodies.dofs(k) for k in range(bodies.n_bodies)] if bodies is not None else [],
            max(float(np.linalg.norm(bodies.model.opt.gravity)), 1.0) if bodies is not None else 1.0)
        self.subiterations = 0  #: fluid advances the last step took (the "subiterate" remedy)
        self._exchanging = roles  # rolled back by the predictor-corrector
        self.dt = dt
        #: the mooring lines' coupling-step limit at the last step (cosim.line_step), or None
        self.line_limit = None
        self._last_dt = math.inf
        self.clock = Clock(t0)
        self.steps = 0
        self._step_stats: dict[str, list] = {}  # what set each step's size (step_summary)
        self.ledger = Ledger(bodies.body_names if bodies is not None else [])
        self._sites: list[tuple[np.ndarray, np.ndarray]] = []  # per attachment: site ids, body index
        self._initialized = False

    @property
    def t(self) -> float:
        """Current time [s]."""
        return self.clock.t

    def initialize(self) -> None:
        """Resolve attachments and initialise every participant at the start time
        (each checks its own inputs before any step is taken). Once only: later
        calls do nothing (attachments add constraints and inertia to the bodies)."""
        if self._initialized:
            return
        t0 = self.clock.t
        if self.bodies is not None:
            self._attach_tethers()
            self.bodies.initialize(t0)
            driven = self.bodies.driven_dofs if isinstance(self.bodies, DrivenBodies) else set()
            for k, s in enumerate(self.watch.dofs):  # a prescribed motion (a moving support) is not the coupling's
                if s.stop > s.start and set(range(s.start, s.stop)) <= driven:
                    self.watch.dofs[k] = slice(0, 0)
            self._sites = []
            for a in self.moorings:
                ids = [self.bodies.site(s) for s in a.sites]
                self._sites.append((np.array([i for i, _ in ids]), np.array([b for _, b in ids])))
            kin = self.bodies.kinematics()
            for a, sites in zip(self.moorings, self._sites):
                a.mooring.set_fairlead_motion(*self._fairlead_motion(a, sites, kin))
            if self.fluid is not None:
                self._check_gravity()
                self.fluid.attach_bodies(self.bodies)
                # an elastic structure's links vibrate by nature (an impact rings its high modes up for
                # hundreds of steps, which the watch takes for unstable coupling): its own check
                # watches it (bodies.elastic.ElasticBody.check, every placement)
                for k in (self.fluid.elastic_rows if isinstance(self.fluid, ElasticStructures) else ()):
                    self.watch.dofs[k] = slice(0, 0)
                self.fluid.set_body_kinematics(kin)
                self._choose_light_body_remedy()
            self.remedies = self.remedies or {n: "none" for n in self.bodies.body_names}
        for p in self.participants:
            if p is not self.bodies:
                p.initialize(t0)
        for j in self._dynamic_lines():  # the motion they are given is where the bodies took the fairleads
            m = self.moorings[j].mooring
            if isinstance(m, DrivenToStepEnd):
                m.drive_to_step_end()
        self._initialized = True
        self._check_fixed_step()
        self._check_line_step()

    def _check_fixed_step(self) -> None:
        """Refuse a fixed step that a participant's stable step cuts short at the start: the
        step asked for would not be the step used."""
        if self.dt is None:
            return
        for p in self.participants:
            d = self._exchange_dt(p)
            if d < self.dt * (1.0 - 1e-9):
                why = p.dt_limit if isinstance(p, LimitReported) else None
                why = f" (limited by {why})" if isinstance(why, str) and why else ""
                raise ConfigurationError(
                    f"coupling step dt = {self.dt:g} s is above the stable step of participant '{p.name}', "
                    f"{d:.4g} s{why}, which would set the step instead; leave dt unset (a scene: remove "
                    f"coupling.dt) and the participants choose the step, or give dt <= {d:.4g} s")

    def _line_step(self):
        """The mooring lines' coupling-step limit now (:mod:`cosim.line_step`), or None."""
        if self.bodies is None or not self.moorings:
            return None
        from cosim.line_step import limit

        self.line_limit = limit(self.bodies, self.moorings, self._sites)
        return self.line_limit

    def _check_line_step(self) -> None:
        """Refuse a fixed step the bodies cannot follow their mooring lines at."""
        lim = self._line_step()
        if lim is None:
            return
        log.info("coupler: mooring lines allow a coupling step of %.4g s (%s)", lim.dt, lim.describe())
        if self.dt is not None and self.dt > lim.dt:
            raise ConfigurationError(
                f"coupling step dt = {self.dt:g} s is above {lim.dt:.3g} s, the largest step at which the bodies "
                f"follow {lim.describe()}: the explicit exchange would go unstable (cosim.line_step). Leave dt "
                f"unset (a scene: remove coupling.dt) and the coupler takes the stable step itself, or set dt <= "
                f"{lim.dt:.3g} s")

    def _check_gravity(self) -> None:
        """The fluid and the bodies must fall the same way: one gravity for every participant."""
        states = self.fluid.config if isinstance(self.fluid, Configured) else self.fluid
        if not isinstance(states, Gravity):
            return
        g_f = states.g
        if g_f is None:
            return
        g_b = np.asarray(self.bodies.model.opt.gravity, float)
        if np.ndim(g_f) == 0:
            g_w, said = (0.0, 0.0, -float(g_f)), f"g = {g_f!r} m/s^2 along -z"
        else:  # a vector: (gx, gz) in the x-z plane or (gx, gy, gz)
            g_w, said = ((g_f[0], 0.0, g_f[1]) if len(g_f) == 2 else tuple(g_f)), f"gravity {list(g_f)} m/s^2"
        if not np.allclose(g_b, g_w, rtol=1e-12, atol=1e-12):
            raise ConfigurationError(
                f"gravity differs between participants: fluid '{self.fluid.name}' has {said}, "
                f"bodies '{self.bodies.name}' {g_b.tolist()} m/s^2; give both the same (a scene sets one world.gravity "
                f"for all; by hand: FluidConfig(g=...) and bodies.builders.scene(gravity=...))")

    def _choose_light_body_remedy(self) -> None:
        carries = self.fluid.loads_carry_added_mass if isinstance(self.fluid, AddedMassLoads) else True
        rho = fluid_density(self.fluid, required=self.light_body in ("added-mass", "subiterate"))
        if rho is None:
            if self.light_body == "auto" and carries:
                log.warning("coupler: fluid '%s' states no density, so no light-body remedy can be chosen; give it "
                            "an attribute rho [kg/m^3] or pass light_body='none' to silence this", self.fluid.name)
            return
        self.added_mass = AddedMass(self.bodies, rho)  # the mass ratios, for the choice and for messages
        self.remedies = self.added_mass.choose(self.light_body, self.scheme, carries)

    def _attach_tethers(self) -> None:
        """Length constraints (MuJoCo tendons) for the mooring lines that ask for
        them (inextensible catenary lines), between each anchor and fairlead site."""
        for a in self.moorings:
            wanted = a.mooring.tethers() if isinstance(a.mooring, Tethered) else []
            if not wanted:
                continue
            spec = []
            for i, anchor, length in wanted:
                anchor3 = anchor if a.mooring.dim == 3 else np.array([anchor[0], 0.0, anchor[1]])
                spec.append((f"{a.mooring.name}.{i}", anchor3, a.sites[i], length))
            self.bodies.add_tethers(spec)
            a.mooring.set_tethered(True)

    def tether_tensions(self) -> dict[str, float]:
        """Tension [N] in each mooring length constraint after the last step, by
        ``"<mooring>.<line index>"`` (0 when the line is slack)."""
        if self.bodies is None or not self.bodies.tethers:
            return {}
        return dict(zip(self.bodies.tethers, self.bodies.tether_tensions().tolist()))

    #: the lines' step limit is recomputed every step while it is below this many times the
    #: last step, else every this many steps [-]
    LINE_STEP_MARGIN = 10

    #: with ``fluid_steps`` k > 1, the exchange spans k of the fluid's stable steps less this
    #: fraction, so that a stable step shrinking by up to it over the exchange still fits k
    #: sub-steps (else the fluid splits the last one: +2.8 to +10.5 % steps at k = 8 to 2 on
    #: floating-heave-period's quick scene, +2.0 % at every k with the margin; docs/coupling.md)
    FLUID_STEPS_MARGIN = 0.02

    def _exchange_dt(self, p) -> float:
        """The longest exchange participant ``p`` allows now [s]: its stable step, the fluid's
        ``fluid_steps`` of them less :data:`FLUID_STEPS_MARGIN`."""
        d = p.max_dt()
        if p is self.fluid and self.fluid_steps > 1:
            d *= self.fluid_steps * (1.0 - self.FLUID_STEPS_MARGIN)
        return d

    def _step_size(self, ticks_left: int) -> tuple[int, str]:
        best, limiter = math.inf, "user dt"
        if self.dt is not None:
            best = self.dt
        for p in self.participants:
            d = self._exchange_dt(p)
            if not (d > 0):  # catches NaN too
                raise InstabilityError(
                    f"step {self.steps + 1}, t = {self.t:.9g} s: participant '{p.name}' reports a "
                    f"stable step of {d!r} s; its state is no longer valid (see its own diagnostics)."
                )
            if d < best:
                best, limiter = d, p.name
        lim = self.line_limit  # as initialize() found it, then refreshed: every step while it is within
        if lim is not None and self.steps and (lim.dt < self.LINE_STEP_MARGIN * self._last_dt  # a factor of
                                               or self.steps % self.LINE_STEP_MARGIN == 0):  # the step, else
            lim = self._line_step()  # every LINE_STEP_MARGIN steps (the lines' state moves with the bodies)
        if lim is not None and lim.dt < best:
            best, limiter = lim.dt, lim.mooring
        n = ticks_left if math.isinf(best) else to_ticks(best)
        if n >= ticks_left:
            return ticks_left, "end time"
        if lim is not None and limiter == lim.mooring and n > 0:
            # the lines' step: evened out towards the end time rather than leaving a sliver of a
            # step before it (a dynamic line driven a step ahead, as MoorDyn's fairlead is
            # extrapolated, jumps when the step changes: on Barreiro et al. 2016's chain the slivers before
            # each output time drove the base's roll)
            k = -(-ticks_left // n)
            n = -(-ticks_left // k)
        if n < 1:
            raise InstabilityError(
                f"step {self.steps + 1}, t = {self.t:.9g} s: participant '{limiter}' asks for a step of "
                f"{best:.3g} s, below the clock resolution (1e-12 s); the run is stiff or unstable there."
            )
        return n, limiter

    def _fairlead_motion(self, a: MooringAttachment, sites, kin):
        ids, body = sites
        pos = self.bodies.site_positions(ids)
        vel = kin.velocity[body] + cross(kin.omega[body], pos - kin.com[body])
        if a.mooring.dim == 2:
            return pos[:, [0, 2]], vel[:, [0, 2]]
        return pos, vel

    def fairlead_positions(self) -> list[np.ndarray]:
        """Where each attachment's fairleads are now [m], world frame, in the mooring's
        coordinates (2-D: (x, z)), ``(n_lines, dim)`` per attachment."""
        if not self._initialized:
            self.initialize()
        kin = self.bodies.kinematics()
        return [self._fairlead_motion(a, sites, kin)[0] for a, sites in zip(self.moorings, self._sites)]

    def _lever_arms(self, kin, only) -> dict:
        """Each fairlead's position relative to its body's centre of mass now [m], ``(n_lines,
        3)``, for the attachments in ``only``."""
        return {j: self.bodies.site_positions(self._sites[j][0]) - kin.com[self._sites[j][1]] for j in only}

    def _mooring_wrenches(self, kin, forces=None, only=None, arms=None):
        """Force and torque about each body's centre of mass of the moorings' fairlead forces:
        each mooring's ``fairlead_forces()``, or ``forces[j]`` for the ``j``-th attachment
        where ``forces`` (a dict) has it; of the attachments in ``only`` if given; the lever
        arms ``arms[j]`` where given, else the fairleads' now (:meth:`_lever_arms`)."""
        n = self.bodies.n_bodies
        F, T = np.zeros((n, 3)), np.zeros((n, 3))
        for j, (a, (ids, body)) in enumerate(zip(self.moorings, self._sites)):
            if only is not None and j not in only:
                continue
            f = forces[j] if forces and j in forces else np.asarray(a.mooring.fairlead_forces(), dtype=float)
            if not np.isfinite(f).all():
                i = int(np.argmax(~np.isfinite(f).all(axis=1)))
                raise InstabilityError(
                    f"step {self.steps + 1}, t = {self.t:.9g} s: mooring '{a.mooring.name}' returned a non-finite "
                    f"force {f[i]} on the fairlead of its line {i} (site '{a.sites[i]}')"
                )
            f3 = f if a.mooring.dim == 3 else np.stack([f[:, 0], np.zeros(len(f)), f[:, 1]], axis=1)
            r = arms[j] if arms and j in arms else self.bodies.site_positions(ids) - kin.com[body]
            np.add.at(F, body, f3)
            np.add.at(T, body, cross(r, f3))
        return F, T

    def step(self, t_end: float) -> StepInfo:
        """Advance every participant by one coupling step, not past ``t_end``."""
        if not self._initialized:
            self.initialize()
        ticks_left = self.clock.ticks_until(t_end)
        if ticks_left < 1:
            raise InputError(f"t_end = {t_end!r} s is not after the current time {self.t!r} s")
        n, limiter = self._step_size(ticks_left)
        t, dt = self.clock.t, n / TICKS_PER_SECOND
        if self.scheme == "explicit" and self._exchanges and not self._warned_held:
            self._warn_held_loads(dt)
        try:
            if self.bodies is not None:
                self._exchange_and_advance(t, dt)
            for p in self.others:
                p.advance(t, dt)
        except SolverError as exc:
            raise type(exc)(f"step {self.steps + 1}, t = {t:.9g} s: {exc}") from exc
        self.clock.advance(n)
        self.steps += 1
        self._last_dt = dt
        self._count_step(dt, limiter)
        if self.bodies is not None:
            self._check_line_breaks()
        return StepInfo(self.steps, self.clock.t, dt, limiter)

    def _warn_held_loads(self, dt: float) -> None:
        """Warn once when the explicit scheme holds its loads over several MuJoCo sub-steps:
        a restoring load taken at the step's start lags the motion by about ``dt / 2``, a
        negative damping of ``omega dt / 4`` of critical on each mode of angular frequency
        ``omega``, which can outgrow a lightly damped mode's own damping (a moored floating
        body's pitch on the potential-flow fluid: docs/validation/nearfield.md)."""
        sub = dt / getattr(self.bodies, "dt_mujoco", math.inf)
        if sub > 1.0 + 1e-9:
            self._warned_held = True
            log.warning("coupler: the explicit scheme holds the loads over %d MuJoCo sub-steps (coupling step %.3g s): "
                        "held restoring loads add energy to the bodies' lightly damped modes; scheme = \"auto\" "
                        "(predictor-corrector or fluid-first) or a coupling dt at most the body timestep avoid it",
                        math.ceil(sub - 1e-9), dt)

    def _count_step(self, dt: float, limiter: str) -> None:
        st = self._step_stats.setdefault(limiter, [0, math.inf, 0.0, 0.0])  # steps, min, max, sum [s]
        st[0] += 1
        st[1], st[2], st[3] = min(st[1], dt), max(st[2], dt), st[3] + dt

    def step_summary(self) -> dict:
        """The steps this coupler took (since it was made: a resumed run counts its own),
        by what set each (``StepInfo.limiter``: a participant's name, ``"user dt"`` for the
        fixed step, ``"end time"`` for a step cut to land on the time :meth:`run` was asked
        to reach): ``{"dt_set_s", "steps", "dt_min_s", "dt_max_s", "dt_mean_s",
        "by_limiter": {limiter: {"steps", "dt_min_s", "dt_max_s"}}}`` [s]."""
        st = self._step_stats
        n = sum(v[0] for v in st.values())
        out = {"dt_set_s": self.dt, "steps": n}
        if n:
            out |= {"dt_min_s": min(v[1] for v in st.values()), "dt_max_s": max(v[2] for v in st.values()),
                    "dt_mean_s": sum(v[3] for v in st.values()) / n,
                    "by_limiter": {k: {"steps": v[0], "dt_min_s": v[1], "dt_max_s": v[2]} for k, v in st.items()}}
        return out

    def _check_line_breaks(self) -> None:
        """Moorings whose lines break (``moorings.breaking.BreakingMooring``) look at their
        tensions after the step, the tension of a line's length constraint included; a
        released line loses its constraint."""
        tt = None
        for a, breaking in zip(self.moorings, self._breaking):
            if breaking:
                tt = self.tether_tensions() if tt is None else tt
                a.mooring.check_breaks(self.t, [tt.get(f"{a.mooring.name}.{i}", 0.0) for i in range(a.mooring.n_lines)])
        if tt is not None:
            self._release_tethers()

    def _release_tethers(self) -> None:
        for a, breaking in zip(self.moorings, self._breaking):
            for i in (a.mooring.released_lines() if breaking else []):
                if f"{a.mooring.name}.{i}" in self.bodies.tethers:
                    self.bodies.release_tether(f"{a.mooring.name}.{i}")

    def _loads(self, kin) -> tuple[np.ndarray, ...]:
        """Fluid force and torque, mooring force and torque on each body, for the
        kinematics the fluid and the moorings were last given."""
        zeros = np.zeros((self.bodies.n_bodies, 3))
        F_fluid, T_fluid = self.fluid.body_wrenches() if self.fluid is not None else (zeros, zeros)
        self._check_loads(F_fluid, T_fluid)
        return (F_fluid, T_fluid) + self._mooring_wrenches(kin, only=self._held_lines())

    def _give_kinematics(self, kin) -> None:
        if self.fluid is not None:
            try:
                self.fluid.set_body_kinematics(kin)
            except InputError as exc:  # mid-run, the fluid's state no longer fits the bodies
                if not self._initialized:
                    raise
                where = ", ".join(f"'{n}' at {np.array2string(c, precision=3)} m"
                                  for n, c in zip(self.bodies.body_names, kin.com))
                raise InstabilityError(
                    f"fluid '{self.fluid.name}' could not place the bodies' particles ({exc}); bodies: {where}. A body "
                    f"has left the fluid's domain or passed through a wall: a heavy body needs a floor to rest on "
                    f"(bodies.builders.scene(floor_z=...)), a fast one a smaller step") from exc
        for a, sites in zip(self.moorings, self._sites):
            self._give_fairlead_motion(a, sites, kin)

    def _give_fairlead_motion(self, a: MooringAttachment, sites, kin) -> None:
        try:
            a.mooring.set_fairlead_motion(*self._fairlead_motion(a, sites, kin))
        except InputError as exc:  # mid-run, the bodies carried a fairlead where no line can be
            if not self._initialized:
                raise
            raise InstabilityError(
                f"mooring '{a.mooring.name}' cannot take the fairlead motion ({exc}); the bodies moved there "
                f"during the run: unstable coupling, or a body that the lines do not hold") from exc

    def _fluid_first_loads(self, dt: float, velocity) -> tuple[np.ndarray, np.ndarray]:
        """The loads the fluid exchanged over its advance, the bodies' particles having
        moved with ``velocity`` [m/s] (centre of mass)."""
        F_fluid, T_fluid = self.fluid.exchanged_wrenches()
        self._check_loads(F_fluid, T_fluid)
        # the fluid's moment is about the centre of mass at the start of the step; the
        # bodies take the force at their moving centre, half a step on on average
        return F_fluid, T_fluid - cross(0.5 * dt * velocity, F_fluid)

    #: sub-iterations: relative tolerance on the bodies' mean velocity over a step [-]
    #: (of its size plus g dt, the velocity one step of gravity gives) ...
    SUBITER_TOL = 1e-3
    #: ... reached within this many fluid advances, or the run stops
    SUBITER_MAX = 40

    def _subiterated_fluid_loads(self, t, dt, kin0, moor):
        """Fluid-first with sub-iterations (the "subiterate" light-body remedy): the
        fluid advances with a guess of the bodies' mean velocity over the step, the
        bodies advance with the impulse it exchanged, and the guess is corrected with
        Aitken-relaxed fixed-point updates (Küttler & Wall 2008) until the bodies'
        mean velocity agrees with the one the fluid moved them with. Every try starts
        from the saved states; the fluid stays advanced with the converged guess, the
        bodies at the start (the caller advances them). Momentum stays exact: the
        bodies receive the impulse the fluid exchanged. ``moor``: the held moorings' wrench;
        dynamic lines (``lines="subiterate"``) advance with the bodies inside every try
        (:meth:`_advance_with_dynamic_lines`), so that the motion the fluid is matched to is
        the one the lines allow; they are back at the start on return."""
        b, f = self.bodies, self.fluid
        fs, bs = f.save_state(), b.save_state()
        dynamic = self._dynamic_lines()
        line_states = [self.moorings[j].mooring.save_state() for j in dynamic]
        start = np.hstack([kin0.velocity, kin0.omega])
        guess, r_prev = start.copy(), None
        light = min(self.added_mass.ratio.min(), 1.0)
        w = light / (1.0 + light)  # the best fixed relaxation if the added mass were the displaced mass
        g = float(np.linalg.norm(b.model.opt.gravity))
        F_moor, T_moor = moor
        for it in range(1, self.SUBITER_MAX + 1):
            if it > 1:
                f.load_state(fs)
                b.load_state(bs)
                self._load_line_states(dynamic, line_states)
            f.set_body_kinematics(kin0._replace(velocity=guess[:, :3], omega=guess[:, 3:]))
            f.advance(t, dt)
            # the moment about the moving centre, as in _fluid_first_loads: the bodies start a
            # step with their start velocity whatever the fluid was given (angular momentum)
            F_fluid, T_fluid = self._fluid_first_loads(dt, kin0.velocity)
            if dynamic:
                self._advance_with_dynamic_lines(t, dt, kin0, F_fluid + F_moor, T_fluid + T_moor, dynamic)
            else:
                b.set_wrenches(F_fluid + F_moor, T_fluid + T_moor)
                b.advance(t, dt)
            k1 = b.kinematics()
            r = 0.5 * (start + np.hstack([k1.velocity, k1.omega])) - guess
            tol = self.SUBITER_TOL * (np.abs(guess).max() + g * dt)
            if np.abs(r).max() <= tol:
                break
            dr = None if r_prev is None else (r - r_prev).ravel()
            if dr is not None and np.dot(dr, dr) > 0:
                w = float(np.clip(-w * np.dot(r_prev.ravel(), dr) / np.dot(dr, dr), 1e-3, 1.0))
            guess, r_prev = guess + w * r, r
        else:
            k = int(np.argmax(np.abs(r).max(axis=1)))
            raise ConvergenceError(
                f"body '{b.body_names[k]}': the sub-iterations did not converge in {self.SUBITER_MAX} tries "
                f"(mean velocity residual {np.abs(r[k]).max():.3g}, tolerance {tol:.3g})"
                f"{self._light_body_hint([k])}; a smaller coupling step converges faster"
            )
        self.subiterations = it
        b.load_state(bs)
        self._load_line_states(dynamic, line_states)
        return F_fluid, T_fluid

    def _load_line_states(self, attachments, states) -> None:
        for j, st in zip(attachments, states):
            self.moorings[j].mooring.load_state(st)

    def _exchange_and_advance(self, t: float, dt: float) -> None:
        """Steps 2-5 of the module docstring: the loads as the scheme takes them
        (:data:`SCHEME_STEPS`), the bodies advanced with them (with the dynamic lines, where
        there are), the fluid and the held moorings given the new motion and advanced."""
        b = self.bodies
        kin0 = b.kinematics()
        qvel0 = b.dof_velocities()
        if self.added_mass is not None:
            F_am, T_am = self.added_mass.correction()  # m^ a_prev, before the step moves the bodies
            self.added_mass.step_started(dt)
        dynamic = self._dynamic_lines()
        loads = self._scheme.loads(self, t, dt, kin0, dynamic)
        F_fluid, T_fluid, F_moor, T_moor = loads
        # the ledger books the fluid's own load: the armature and the added-mass term cancel in a steady state
        F_add, T_add = (F_fluid + F_am, T_fluid + T_am) if self.added_mass is not None else (F_fluid, T_fluid)
        gravity = b.gravity_forces()
        if dynamic:
            F_dyn, T_dyn = self._advance_with_dynamic_lines(t, dt, kin0, F_add + F_moor, T_add + T_moor, dynamic)
            F_moor, T_moor = F_moor + F_dyn, T_moor + T_dyn
        else:
            b.set_wrenches(F_add + F_moor, T_add + T_moor)
            self._advance_bodies(t, dt)
        self.ledger.record(t, F_fluid, T_fluid, F_moor, T_moor, gravity)
        kin1 = b.kinematics()
        self._watch_bodies((b.dof_velocities() - qvel0) / dt, kin1)
        self._give_kinematics(kin1)
        if self.fluid is not None and not self._scheme.advances_fluid:
            self.fluid.advance(t, dt)
        for j, a in enumerate(self.moorings):
            if j not in dynamic:  # those have advanced with the bodies
                a.mooring.advance(t, dt)

    def _advance_bodies(self, t: float, dt: float) -> None:
        try:
            self.bodies.advance(t, dt)
        except InstabilityError as exc:
            raise InstabilityError(f"{exc}{self._light_body_hint(range(self.bodies.n_bodies))}") from exc

    def _dynamic_lines(self) -> list[int]:
        """The attachments whose lines the bodies advance with (``lines="subiterate"``):
        moorings that say they are ``dynamic`` (their force is an integral over the step)."""
        if self.lines != "subiterate":
            return []
        return [j for j, dynamic in enumerate(self._says_dynamic) if dynamic]

    def _held_lines(self) -> list[int]:
        """The attachments whose force is taken at the step's start (and, with the
        predictor-corrector, at the predicted end): all but :meth:`_dynamic_lines`."""
        dynamic = self._dynamic_lines()
        return [j for j in range(len(self.moorings)) if j not in dynamic]

    #: dynamic lines' sub-iterations: relative tolerance on the lines' mean fairlead forces over a
    #: step [-] (of the largest of them, at least 1 N); what is left of it moves the bodies (Barreiro
    #: et al. 2016's base at rest: 1e-4 leaves 1e-5 rad/s, 1e-5 1-2e-6 and 1e-6 3-7e-7, the last as the
    #: waves alone move it, in 1.7, 1.7 and 1.7-2.4 advances of the lines a step) ...
    LINES_TOL = 1e-5
    #: ... reached within this many advances of the lines, or the run stops
    LINES_MAX = 30

    def _advance_with_dynamic_lines(self, t, dt, kin0, F_other, T_other, dynamic):
        """Advance the bodies and the dynamic lines together over one step (``lines="subiterate"``).

        The bodies advance with the other loads plus a guess of each line's mean fairlead
        force over the step; the lines advance (from their saved states) with the fairleads
        moving from the step's start to where the bodies took them, and report the mean force
        they exerted (``mean_fairlead_forces()``: their impulse on the fairlead over ``dt``);
        the guess is corrected by Aitken-relaxed fixed-point updates (Küttler & Wall 2008)
        until the two agree (``LINES_TOL``). Converged, the bodies have received the impulse
        the lines exerted and the lines have followed the fairleads the bodies moved, within
        the same step: no force is held from the step's start, so a wave the fairlead sends
        down a line and back within a few steps cannot pump the body (the explicit exchange's
        limit cycle, ``benchmarks/line_step_sweep.py``). The first try is the explicit one
        (the force at the step's start); where the bodies move on prescribed joints only (a
        test rig), it is the last, with the lines' mean force as the load. Returns the lines'
        force and torque on the bodies; the bodies and the lines stay advanced."""
        b = self.bodies
        moorings = [self.moorings[j].mooring for j in dynamic]
        body_state, line_states = b.save_state(), [m.save_state() for m in moorings]
        shapes = [np.shape(m.fairlead_forces()) for m in moorings]
        x = np.concatenate([np.asarray(m.fairlead_forces(), dtype=float).ravel() for m in moorings])
        cuts = np.cumsum([int(np.prod(sh)) for sh in shapes])[:-1]

        def by_mooring(v):  # the stacked fairlead forces, back to each mooring's (lines, dim)
            return {j: part.reshape(sh) for j, part, sh in zip(dynamic, np.split(v, cuts), shapes)}

        arms0 = self._lever_arms(kin0, dynamic)
        arms = arms0
        held = self._only_driven(dynamic)
        w, r_prev = 0.5, None
        for it in range(1, self.LINES_MAX + 1):
            if it > 1:
                b.load_state(body_state)
                for m, st in zip(moorings, line_states):
                    m.load_state(st)
            F_lines, T_lines = self._mooring_wrenches(kin0, by_mooring(x), dynamic, arms)
            b.set_wrenches(F_other + F_lines, T_other + T_lines)
            self._advance_bodies(t, dt)
            kin1 = b.kinematics()
            # the moment of the mean force about the moving centre: the mean of the start's and
            # the end's lever arms (the trapezoid rule, as on the force), the end's from this try
            arms = {j: 0.5 * (arms0[j] + a1) for j, a1 in self._lever_arms(kin1, dynamic).items()}
            for j, m in zip(dynamic, moorings):
                self._give_fairlead_motion(self.moorings[j], self._sites[j], kin1)
                m.advance(t, dt)
            got = np.concatenate([np.asarray(m.mean_fairlead_forces(), dtype=float).ravel() for m in moorings])
            if not np.isfinite(got).all():  # stop, naming the mooring and the line
                self._mooring_wrenches(kin0, by_mooring(got), dynamic)
            if held:  # the bodies moved as prescribed whatever the force: the lines' own mean is the load
                F_lines, T_lines = self._mooring_wrenches(kin0, by_mooring(got), dynamic, arms)
                break
            r = got - x
            tol = self.LINES_TOL * max(float(np.abs(got).max()), float(np.abs(x).max()), 1.0)
            if np.abs(r).max() <= tol:
                break
            dr = None if r_prev is None else r - r_prev
            if dr is not None and np.dot(dr, dr) > 0:
                w = float(np.clip(-w * np.dot(r_prev, dr) / np.dot(dr, dr), 1e-3, 1.0))
            x, r_prev = x + w * r, r
        else:
            k = int(np.argmax(np.abs(r)))
            j = int(np.searchsorted(cuts, k, side="right"))
            line = (k - (cuts[j - 1] if j else 0)) // shapes[j][1]
            raise ConvergenceError(
                f"mooring '{moorings[j].name}', line {line} (site '{self.moorings[dynamic[j]].sites[line]}'): the "
                f"bodies and the dynamic lines did not agree on the line's mean force within {self.LINES_MAX} "
                f"advances (residual {abs(r[k]):.3g} N, tolerance {tol:.3g} N); a smaller coupling step converges "
                f"faster, or lines='explicit' holds the force at the step's start")
        self.line_iterations = it
        return F_lines, T_lines

    def _only_driven(self, attachments) -> bool:
        """Whether every body the ``attachments``' lines end on moves only on prescribed joints
        (:meth:`bodies.mujoco_bodies.MujocoBodies.drive`: a test rig): their motion over a
        step does not depend on the lines' force, so one advance is the converged one."""
        b = self.bodies
        driven = b.driven_dofs
        ends = {int(k) for j in attachments for k in self._sites[j][1]}
        return bool(driven) and all(set(range(b.model.nv)[b.dofs(k)]) <= driven for k in ends)

    def _check_loads(self, F, T) -> None:
        """Nothing non-finite crosses the coupler: a fluid load that is not finite stops the
        run here, naming the fluid and the body (the fluid checks its own particles)."""
        if self.fluid is None:
            return
        bad = ~(np.isfinite(F).all(axis=1) & np.isfinite(T).all(axis=1))
        if bad.any():
            k = int(np.argmax(bad))
            raise InstabilityError(
                f"fluid '{self.fluid.name}' returned a non-finite load on body '{self.bodies.body_names[k]}' "
                f"(force {F[k]}, torque {T[k]}): its particles by the body went unstable; a smaller coupling step, "
                f"a finer dx or a higher speed of sound may help{self._light_body_hint([k])}")

    #: a body faster than this fraction of a weakly compressible fluid's speed of sound
    #: stops the run [-] (the predictor-corrector at ratio 0.001 of the density-ratio
    #: sweep reached Mach 0.77 and came back, with a state that meant nothing)
    MAX_MACH = 0.5

    def _watch_bodies(self, qacc: np.ndarray, kin) -> None:
        """Stop a run whose body accelerations oscillate with growing amplitude (the
        signature of unstable staggered coupling; for light bodies, added mass), or
        whose bodies outrun the fluid's speed of sound, before it overflows."""
        c0 = self._speed_of_sound
        if c0 is not None:
            speed = np.linalg.norm(kin.velocity, axis=1)
            k = int(np.argmax(speed))
            if speed[k] > self.MAX_MACH * c0:
                raise InstabilityError(
                    f"body '{self.bodies.body_names[k]}' moves at {speed[k]:.3g} m/s, more than {self.MAX_MACH:g} x "
                    f"the fluid's speed of sound {c0:.3g} m/s, beyond what a weakly compressible fluid can follow "
                    f"(density errors ~ Mach^2 / 2): unstable coupling{self._light_body_hint([k])}")
        for k, why in enumerate(self.watch.add(qacc)):
            if why:
                raise InstabilityError(f"body '{self.bodies.body_names[k]}': {why} (m/s^2 or rad/s^2): unstable "
                                       f"coupling{self._light_body_hint([k])}")

    def _light_body_hint(self, bodies) -> str:
        """The mass ratio and remedy of the given bodies, for an instability message."""
        am = self.added_mass
        if am is None:
            return ""
        parts = []
        for k in bodies:
            name = self.bodies.body_names[k]
            fix = ("scheme='explicit', or a smaller coupling step" if self.remedies.get(name) != "none"
                   else "scheme='fluid-first' with light_body='subiterate', or scheme='explicit'")
            parts.append(f"body '{name}' weighs {am.ratio[k]:.3g} x the fluid it displaces, light-body remedy "
                         f"'{self.remedies.get(name)}' (try {fix})")
        return "; " + "; ".join(parts)

    def write_checkpoint(self, path) -> None:
        """Write :meth:`save_state` and the ledger of the steps so far to a checkpoint file
        (:mod:`cosim.checkpoint`: data only, written atomically)."""
        from cosim import checkpoint
        from cosim.version import __version__, code_version

        checkpoint.write(path, {"meta": {"of": "coupler", "cosim_version": __version__, "code_version": code_version(),
                                         "t": self.t, "steps": self.steps},
                                "state": self.save_state(), "ledger": self.ledger.arrays()})

    def read_checkpoint(self, path, any_version: bool = False) -> None:
        """Continue from a file written by :meth:`write_checkpoint`, into a coupler set up
        the same way (same participants and options) as the one that wrote it. Refused
        (:class:`cosim.checkpoint.CheckpointError`, naming the cause): a file that is not
        one, corrupt or truncated, written by other code (unless ``any_version``), or
        holding a state no run reaches (a NaN, an infinite time). Nothing in it is run."""
        from cosim import checkpoint
        from cosim.version import code_version

        ck = checkpoint.read(path)
        meta = ck.get("meta")
        if not isinstance(meta, dict) or meta.get("of") != "coupler" or "state" not in ck or "ledger" not in ck:
            raise checkpoint.CheckpointError(f"{str(path)!r} is a checkpoint but not one written by "
                                             f"Coupler.write_checkpoint")
        if meta.get("code_version") != code_version() and not any_version:
            raise checkpoint.CheckpointError(f"{str(path)!r} was written by other code (sources "
                                             f"{meta.get('code_version')}, these are {code_version()}); give "
                                             f"any_version=True to read it anyway")
        where = checkpoint.first_not_finite({"t": meta.get("t"), "state": ck["state"], "ledger": ck["ledger"]})
        if where is not None:
            raise checkpoint.CheckpointError(f"{str(path)!r} holds a state no run reaches ({where})")
        self.load_state(ck["state"])
        self.ledger.restore(ck["ledger"])  # the steps before the checkpoint, so that the ledger is whole

    def run(self, t_end: float, callback: Callable[[StepInfo], Any] | None = None,
            progress: bool | None = None) -> int:
        """Step until ``t_end`` [s] exactly; returns the number of steps taken.
        ``progress``: a one-line progress display on stderr (default: only when
        stderr is a terminal)."""
        if not math.isfinite(t_end):
            raise InputError(f"t_end must be finite, got {t_end!r}")
        n0 = self.steps
        bar = Progress(self.t, t_end, enabled=progress)
        try:
            while self.clock.ticks_until(t_end) > 0:
                info = self.step(t_end)
                bar.update(info.t)
                if callback is not None:
                    callback(info)
        finally:
            bar.close(self.t)
        return self.steps - n0

    def save_state(self) -> dict:
        """A checkpoint of the clock and every participant."""
        return {
            "ticks": self.clock.ticks,
            "steps": self.steps,
            "ledger": len(self.ledger),
            "participants": {p.name: p.save_state() for p in self.participants},
            # the coupler's own memory of past steps: the added-mass term and the watch use it
            "added_mass": None if self.added_mass is None else self.added_mass.save_state(),
            "watch": self.watch.save_state(),
            "last_dt": self._last_dt,  # when the lines' step limit is next recomputed, and the limit
            "line_limit": self.line_limit,
        }

    def load_state(self, state: dict) -> None:
        """Return to a checkpoint taken by :meth:`save_state` (of this coupler, or of
        one set up the same way, e.g. read back by :meth:`read_checkpoint`)."""
        missing = sorted(set(p.name for p in self.participants) - set(state.get("participants", {})))
        if missing:
            raise InputError(f"the checkpoint has no state for participants {missing} (it holds "
                             f"{sorted(state.get('participants', {}))}); restore it into a coupler set up the same way")
        if not self._initialized:
            self.initialize()  # attachments (tethers, added mass) exist before the states go in
        for p in self.participants:
            p.load_state(state["participants"][p.name])
        self.clock.ticks = state["ticks"]
        self.steps = state["steps"]
        self.ledger.truncate(state["ledger"])
        if self.added_mass is not None:
            self.added_mass.load_state(state["added_mass"])
        self.watch.load_state(state["watch"])
        self._last_dt = state.get("last_dt", math.inf)
        self.line_limit = state.get("line_limit", self.line_limit)
        if self.bodies is not None and self._initialized:
            self._release_tethers()  # model data, not state: lines released before the checkpoint
            kin = self.bodies.kinematics()
            if self.fluid is not None:
                self.fluid.set_body_kinematics(kin)


# ------------------------------------------------------------------------ the coupling schemes
class ExplicitScheme:
    """``scheme="explicit"``: the loads at the step's start, held over it (one evaluation)."""

    #: the fluid advances while the loads are taken (else after the bodies, with their new motion)
    advances_fluid = False

    def loads(self, c: Coupler, t: float, dt: float, kin0, dynamic) -> tuple[np.ndarray, ...]:
        """Fluid force and torque, held moorings' force and torque on each body for the step
        from ``t`` [s] over ``dt`` [s], the bodies at ``kin0`` (``dynamic``: the attachments
        of the dynamic lines, which advance with the bodies)."""
        return c._loads(kin0)


class PredictorCorrectorScheme(ExplicitScheme):
    """``scheme="predictor-corrector"``: the bodies advance with the start loads (the
    dynamic lines' force at the start added), the loads are taken at the predicted pose
    and time, every exchanging participant is rolled back, and the mean of both is taken."""

    def loads(self, c, t, dt, kin0, dynamic):
        start = c._loads(kin0)
        b = c.bodies
        saved = [(p, p.save_state()) for p in c._exchanging]
        F_dyn, T_dyn = c._mooring_wrenches(kin0, only=dynamic)  # the dynamic lines' force at the start
        b.set_wrenches(start[0] + start[2] + F_dyn, start[1] + start[3] + T_dyn)
        b.advance(t, dt)
        kin1 = b.kinematics()
        if c._timed_loads:  # loads that depend on time (waves): at the predicted time
            c.fluid.set_time(t + dt)
        c._give_kinematics(kin1)
        end = c._loads(kin1)
        for p, st in saved:
            p.load_state(st)
        c._give_kinematics(kin0)
        return tuple(0.5 * (a + e) for a, e in zip(start, end))


class FluidFirstScheme:
    """``scheme="fluid-first"``: the fluid advances first with the bodies' current motion
    (sub-iterated with the bodies for the ``"subiterate"`` light-body remedy), and the bodies
    receive the impulse it exchanged; the held moorings' force at the step's start."""

    advances_fluid = True

    def loads(self, c, t, dt, kin0, dynamic):
        moor = c._mooring_wrenches(kin0, only=c._held_lines())
        if "subiterate" in c.remedies.values():
            return c._subiterated_fluid_loads(t, dt, kin0, moor) + moor
        c.fluid.advance(t, dt)  # the fluid moves the bodies' particles with their current motion
        return c._fluid_first_loads(dt, kin0.velocity) + moor


#: one strategy per coupling scheme (``Coupler(scheme=...)``)
SCHEME_STEPS = {"explicit": ExplicitScheme(), "predictor-corrector": PredictorCorrectorScheme(),
                "fluid-first": FluidFirstScheme()}

