"""What a scene will cost, estimated from the scene alone before any work is done
(``cosim run --dry-run`` prints it, ``summary.json`` keeps it as ``estimate``): particles,
steps, memory and CPU time, each term with the scene field that drives it. Nothing is
built: a scene of 10^9 particles or 10^12 steps is estimated as fast as a small one.

The terms (CPU in core-seconds, the sum over threads; the constants below are measured
on this code, ``benchmarks/cost_estimate.py``, ``docs/benchmarks/cost_estimate.md``):

- ``fluid`` (SPH): ``N`` particles counted from the geometry: the water's area (2-D) or
  volume (3-D) over ``dx^dim`` (a section's outline clipped at the still level; water
  blocks), the walls' length (area) times their ``ceil(2 h / dx)`` layers over
  ``dx^(dim-1)``, each body's boundary its surface times the same layers (at most its
  section). Its step at rest, :func:`fluid.integrator.step_limit` with the speed of sound
  and gravity of the set-up (the flow's own speed and accelerations only shorten it):
  ``(duration + settle) / dt`` steps, ``C_SPH[dim] N`` s each; ``B_SPH[dim] N`` bytes.
- ``bodies`` (MuJoCo, and the exchange of loads, ``C_BODY_STEP`` a coupling step): steps
  of ``min(body_timestep, dt_plate / 2)``, an elastic plate's
  stable step from the highest modes of its chain of ``n`` links ``l = L / n`` long
  (bending ``2 sqrt(12 E I / (rho A l^2 (l^2 + t^2)))``, shear ``(2 / l) sqrt(kappa G /
  rho)``, RK4's ``2 sqrt 2 / omega``), ``C_MJ`` per link or body and step.
- ``lines`` (SPH cable, MoorDyn): each node's internal step (the model's
  :meth:`~cosim.scene.mooring_models.MooringModel.internal_step`: the SPH cable's Courant
  step ``cfl ds / c``, ``c = sqrt(EA / m)``, MoorDyn's
  :func:`moorings.moordyn_mooring.internal_step_limits`), advanced ``LINE_ADVANCES`` times
  per coupling step (the sub-iterated exchange), the model's ``node_cost`` per node and step.
- ``coupling``: ``duration / dt_c`` steps, at least one per event; ``dt_c`` the smallest
  of ``coupling.dt``, the SPH step, the analytic fluid's (50 steps per heave period,
  ``m / B`` of its damping, 50 per wave period: ``fluid.analytic.AnalyticFluid.max_dt``) and
  the lines' (:mod:`cosim.line_step`: ``dt < 1 / omega``, ``omega^2 = (EA / L) / M``;
  ``dt < 1.6 M / sqrt(EA m)`` for a dynamic line), ``C_STEP`` each.
- ``records``: the run's event list, the probe rows kept in memory, the coupler's ledger
  (``2 (8 + 120 n_bodies)`` bytes per step, :class:`cosim.ledger.Ledger`); the snapshots
  go to disk (``disk_bytes``).

The step counts are lower bounds (a flow that speeds up takes more, smaller steps): the
estimate is for the scene as it starts. Not counted: the potential fluid's boundary-element
solve (cached after the first run) and an FMU's export.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from cosim.scene.registry import MOORINGS
from cosim.scene.shapes import RigidBody
from cosim.scene.spec import (MJCF, SPH, Analytic, ArchRib, CylinderTank, ElasticPlate, Flap, Flume, InclinedTank,
                              IrregularWaves, LinearWaves, NearField, OpenWater, PaddleRecord, Piston, PolygonTank,
                              RegularWaves, Tank)

#: CPU [s] per particle and step of the SPH fluid at h = sqrt(2) dx, by dimension (one
#: thread, the symplectic scheme's two pair loops, Adami's walls; measured on scenes of
#: 20 000-80 000 particles, where a step no longer fits the cache: smaller ones cost less)
C_SPH = {2: 7.6e-7, 3: 3.2e-6}
#: the growth of that cost with the smoothing length, ``(h_coef / sqrt 2)^H_POWER``
#: (the pairs grow as ``h^dim``, the rest of a step does not)
H_POWER = {2: 1.5, 3: 1.6}
#: memory [bytes] per SPH particle, by dimension (measured: the peak resident size)
B_SPH = {2: 500.0, 3: 600.0}
#: CPU [s] of the SPH fluid's start (the compiled kernels loaded, the set-up built)
C_SPH_START = 0.5
#: the fluid's advances per coupling step when a light body is sub-iterated
#: (cosim.added_mass.AUTO_THRESHOLD; measured on the SPH wind-turbine base: about 3)
SUBITER_ADVANCES = 3.0
#: CPU [s] per coupling step (the coupler's clock, events, probes)
C_STEP = 3e-4
#: CPU [s] per coupling step of a scene with bodies (the exchange: MuJoCo's calls, the
#: lines' forces, the analytic fluid's loads, the ledger; measured on the moored box and
#: the wind-turbine base, 1.4 and 2.6 ms)
C_BODY_STEP = 1.6e-3
#: CPU [s] per MuJoCo step and body (or plate link)
C_MJ = 2e-6
#: the lines' advances per coupling step with the sub-iterated exchange (cosim.line_step)
LINE_ADVANCES = 2.0
#: memory [bytes] per event of the run (its time and what is due), per probe sample and column
B_EVENT, B_SAMPLE, B_COLUMN = 400.0, 150.0, 16.0
#: disk [bytes] per particle of a snapshot (positions, velocities, density, pressure, kind, id)
B_SNAPSHOT = {2: 57.0, 3: 73.0}
#: memory [bytes] of the process before the run (Python, numpy, numba, MuJoCo loaded)
B_PROCESS = 2.5e8
#: above this CPU time [s] a run asks to be confirmed (a day of one core)
CONFIRM_CPU_S = 86_400.0


@dataclass(frozen=True)
class Term:
    """One part of the cost: its name, the scene field that drives it and why, its
    steps, CPU [s] and memory [bytes]."""

    name: str
    field: str
    why: str
    cpu_s: float = 0.0
    memory_bytes: float = 0.0
    per_second: float = 0.0  #: CPU [s] per simulated second (0: not proportional to the duration)
    memory_field: str = ""  #: the field that drives its memory, where not ``field``

    def as_dict(self) -> dict:
        return {"field": self.field, "why": self.why, "cpu_s": _round(self.cpu_s),
                "memory_bytes": _round(self.memory_bytes)}


@dataclass(frozen=True)
class Estimate:
    """A scene's cost (module docstring)."""

    particles: int  #: SPH particles (fluid, walls, bodies' boundaries); 0 without the SPH fluid
    fluid_particles: int
    dt: float  #: the coupling step [s] at the start
    dt_by: str  #: what sets it
    steps: float  #: coupling steps
    fluid_steps: float  #: SPH steps, settling included
    cpu_s: float  #: CPU time [s] of the run (core-seconds)
    memory_bytes: float  #: the run's largest memory [bytes]
    disk_bytes: float  #: what the run writes [bytes]
    terms: tuple = field(default_factory=tuple)

    @property
    def driver(self) -> Term:
        """The term that costs the most CPU."""
        return max(self.terms, key=lambda t: t.cpu_s)

    @property
    def memory_driver(self) -> Term:
        return max(self.terms, key=lambda t: t.memory_bytes)

    def as_dict(self) -> dict:
        return {"particles": self.particles, "fluid_particles": self.fluid_particles, "dt_s": _round(self.dt),
                "dt_by": self.dt_by, "steps": _round(self.steps), "fluid_steps": _round(self.fluid_steps),
                "cpu_s": _round(self.cpu_s), "memory_bytes": _round(self.memory_bytes),
                "disk_bytes": _round(self.disk_bytes), "driver": self.driver.field,
                "terms": {t.name: t.as_dict() for t in self.terms}}

    def describe(self) -> list[str]:
        """The estimate as lines of text (``cosim run --dry-run``)."""
        out = []
        if self.particles:
            out.append(f"particles: {self.particles:,} ({self.fluid_particles:,} fluid)")
        out.append(f"coupling step: {self.dt:.3g} s ({self.dt_by}); {self.steps:.3g} steps"
                   + (f", {self.fluid_steps:.3g} fluid steps" if self.fluid_steps else ""))
        out.append(f"CPU time: {human_time(self.cpu_s)} (core-seconds); memory: {human_bytes(self.memory_bytes)}; "
                   f"disk: {human_bytes(self.disk_bytes)}")
        for t in sorted(self.terms, key=lambda t: -t.cpu_s):
            out.append(f"  {t.name:9s} {human_time(t.cpu_s):>12s} {human_bytes(t.memory_bytes):>10s}  {t.field}: "
                       f"{t.why}")
        return out


def _over(a: float, b: float) -> float:
    """``a / b`` [-], inf where ``b`` is 0 (a step that underflowed: unbounded work)."""
    return a / b if b else (math.inf if a > 0 else 0.0)


def _round(x: float):
    return float(f"{x:.4g}") if math.isfinite(x) else str(x)


def human_time(s: float) -> str:
    if not math.isfinite(s):
        return "forever"
    for unit, k in (("years", 365.25 * 86400), ("days", 86400), ("h", 3600), ("min", 60)):
        if s >= k:
            x = f"{s / k:.3g}"
            return f"{x} {unit[:-1] if x == '1' and unit.endswith('s') else unit}"
    return f"{s:.3g} s"


def human_bytes(b: float) -> str:
    if not math.isfinite(b):
        return "unbounded"
    for unit, k in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if b >= k:
            return f"{b / k:.3g} {unit}"
    return f"{b:.0f} B"


# ------------------------------------------------------------------------ the SPH fluid
def _clip_below(v, level):
    """The part of the closed polygon ``v`` (x, z) below ``z = level`` (Sutherland-Hodgman)."""
    out = []
    for k in range(len(v)):
        (x0, z0), (x1, z1) = v[k], v[(k + 1) % len(v)]
        in0, in1 = z0 <= level, z1 <= level
        if in0:
            out.append((x0, z0))
        if in0 != in1:
            f = (level - z0) / (z1 - z0)
            out.append((x0 + f * (x1 - x0), level))
    return out


def _area(v) -> float:
    return 0.5 * abs(sum(x0 * z1 - x1 * z0 for (x0, z0), (x1, z1) in zip(v, v[1:] + v[:1])))


def _open_length(v, top) -> float:
    """The perimeter [m] of the outline ``v``, less its edges along the open top ``z = top``."""
    total = 0.0
    for (x0, z0), (x1, z1) in zip(v, v[1:] + v[:1]):
        if not (abs(z0 - top) < 1e-12 and abs(z1 - top) < 1e-12):
            total += math.hypot(x1 - x0, z1 - z0)
    return total


def sph_particles(scene) -> tuple[float, float, float]:
    """(fluid, wall, body) particles of the scene's SPH fluid, counted from its geometry
    (module docstring)."""
    from cosim.scene.build import fluid_config, water_level
    from cosim.scene.checks import _outline
    from cosim.scene.plausible import paddle_stroke
    from cosim.scene.setup import choose

    d, dim, dx = scene.domain, scene.world.dim, scene.fluid.dx
    cfg = fluid_config(scene, choose(scene), numbers_only=True)
    layers = math.ceil(2.0 * cfg.h_coef - 1e-9)
    t = layers * dx
    if isinstance(d, NearField):
        from cosim.scene.nearfield import box_for

        from cosim.scene.build import incident_sea
        from fluid.nearfield import excursion

        c = box_for(scene)
        length = c.x[1] - c.x[0]
        slack = excursion(incident_sea(scene)) + 2 * dx  # the floor under the end walls' excursion
        span = length + 2 * t + 2 * slack
        if dim == 2:
            water = length * d.depth / dx ** 2
            walls = (span * t + 2 * c.height * t) / dx ** 2
        else:
            w = c.y[1] - c.y[0]
            sides = 0 if d.sides == "symmetry" else 1 if d.symmetry else 2  # a symmetry plane has no wall
            water = length * w * d.depth / dx ** 3
            walls = (span * (w + sides * t) * t + 2 * c.height * w * t + sides * span * c.height * t) / dx ** 3
    elif isinstance(d, OpenWater):
        water = sum(math.prod(h - lo for lo, h in zip(b.lo, b.hi)) for b in d.water) / dx ** dim
        walls = 0.0
    elif isinstance(d, CylinderTank):
        r = 0.5 * d.diameter
        water = math.pi * r * r * d.depth / dx ** 3
        walls = (2 * math.pi * (r + 0.5 * t) * d.height + math.pi * (r + t) ** 2) * t / dx ** 3
    else:
        v = _outline(d)
        closed = isinstance(d, (PolygonTank, ArchRib))
        top = max(z for _, z in v)
        back = 0.5 * paddle_stroke(scene) + dx if isinstance(d, Flume) and scene.waves is not None else 0.0
        if isinstance(d, Tank) and d.water:
            section = None
            water = sum(math.prod(h - lo for lo, h in zip(b.lo, b.hi)) for b in d.water) / dx ** dim
        else:
            section = _area(_clip_below(v, water_level(scene)))
            if isinstance(d, Flume) and d.beach is not None:  # the water is laid half a spacing clear of the beach
                wet = min(d.depth / d.beach.slope, d.length - d.beach.toe)
                section -= 0.5 * dx * wet * math.hypot(1.0, d.beach.slope)
        edge = (_open_length(v, math.inf) if closed else _open_length(v, top)) + back + 2 * t  # the walls' mid-line
        if isinstance(d, Flume) and d.beach is not None:  # the floor and the far wall run on under the beach
            edge += d.length - d.beach.toe + min(d.beach.slope * (d.length - d.beach.toe), d.height)
        if dim == 2:
            if section is not None:
                water = section / dx ** 2
            walls = edge * t / dx ** 2
        else:
            w = d.width
            if section is not None:
                water = section * w / dx ** 3
            if isinstance(d, Flume) and d.sides == "symmetry":  # no side walls, the rest only across the width
                walls = edge * w * t / dx ** 3
            else:
                walls = (edge * (w + 2 * t) + 2 * (_area(v) + back * top)) * t / dx ** 3
    bodies = 0.0
    for b in scene.bodies:
        if isinstance(b, MJCF):
            continue
        bodies += min(b.volume(dim), b.surface_area(dim) * t) / dx ** dim  # 2-D: area and perimeter
    return water, walls, bodies


def sph_step(scene) -> tuple[float, str]:
    """The SPH fluid's step [s] at rest and what sets it (fluid.integrator.step_limit with
    the set-up's speed of sound and gravity, and the peak acceleration of a base motion)."""
    from cosim.scene.build import fluid_config
    from cosim.scene.setup import choose
    from fluid.integrator import diffusion_coefficient, step_limit

    c = fluid_config(scene, choose(scene), numbers_only=True)
    h, c0 = c.h, c.speed_of_sound
    a = c.g_magnitude
    lim = step_limit(a * a, h / c0, c0, h, c.cfl, c.dt_max, c.nu, alpha_eff=c.alpha / (2.0 * (c.dim + 2)),
                     nu_delta=0.0 if c.diffusion == "none" else c.delta * h * c0,
                     c_diff=diffusion_coefficient(c.integrator, c.verlet_reset))
    return lim.dt, lim.limiter


# ------------------------------------------------------------------------ bodies and lines
#: the chain's highest frequency over its links' own (a link's rotation on its hinges, its
#: slide on its shear springs): the joints' reactions couple each link to its neighbours
#: and lower the mode's inertia (measured 1.4-1.8 against MuJoCo's linearised chain,
#: bodies.elastic.BeamModel.stable_dt, tests/test_cost.py)
CHAIN_FACTOR = 2.0


def plate_step(b, dim) -> float:
    """The stable RK4 step [s] of an elastic plate's chain (module docstring), ``2 sqrt 2
    / omega`` with ``omega`` :data:`CHAIN_FACTOR` times the larger of the bending and
    shear frequencies of one link."""
    n = b.elements
    w = b.width if dim == 3 else 1.0
    t, l = b.thickness, b.length / n
    A, I = t * w, w * t ** 3 / 12.0
    G = b.E / (2.0 * (1.0 + b.nu))
    bend = 2.0 * math.sqrt(12.0 * b.E * I / (b.density * A * l * l * (l * l + t * t)))
    shear = 2.0 / l * math.sqrt(5.0 / 6.0 * G / b.density)
    return 2.0 * math.sqrt(2.0) / (CHAIN_FACTOR * max(bend, shear))


def _body_mass(b, dim, rho) -> float:
    if b.mass is not None:
        return b.mass
    return b.density * b.volume(dim)


def line_steps(scene) -> list[tuple[int, float, float, float]]:
    """Each dynamic line's (index, nodes, internal step [s], simulated time [s] before the
    run: MoorDyn's initial-condition relaxation ``ic_time``)."""
    m = scene.moorings
    if m is None:
        return []
    out = []
    for i, ln in enumerate(m.lines):
        step = MOORINGS[m.model].internal_step(scene, ln)
        if step is not None:
            out.append((i, m.segments + 1, *step))
    return out


def _fairlead_start(scene, b, offset):
    """Where a builder body's fairlead starts [m] (a floating body's at its computed height;
    a 2-D body's frame stays the world's); None where the body cannot float."""
    from cosim.scene.build import water_level
    from cosim.scene.shapes import rotation as _rotation
    from cosim.scene.placement import floating_height

    from cosim.errors import InputError

    dim = scene.world.dim
    if b.place == "floating":
        rho = getattr(scene.fluid, "rho", getattr(scene.fluid, "rho0", 1000.0))
        mine = [ln for ln in scene.moorings.lines if ln.fairlead.split(".")[0] == b.name]
        try:
            z = floating_height(b, dim, water_level(scene), rho, scene.world.gravity, mine)
        except InputError:
            return None  # the build refuses it, naming the body or the line
        centre = list(b.pos) + [z]
    else:
        centre = list(b.pos)
        if dim == 3 and b.euler is not None:
            r = _rotation(b.euler)
            offset = [sum(r[k][j] * offset[j] for j in range(3)) for k in range(3)]
    return [c + o for c, o in zip(centre, offset)]


def _line_spring(ln, fairlead, dynamic: bool, damping: float) -> tuple[float, float, list]:
    """(k [N/m], c [N s/m], e) of a line at its fairlead (moorings.fairlead_stiffness), ``e``
    its unit tangent there (towards the anchor, from the catenary's H and V): a
    quasi-static line its catenary's tangent stiffness (the larger of dH/dX and dV/dh, by
    central differences of moorings.catenary.solve), a dynamic one ``EA / L_s`` on its
    suspended length and the impedance ``(1 + damping) sqrt(EA m)``."""
    from moorings.catenary import solve

    a = ln.anchor
    X, h = math.dist(fairlead[:-1], a[:-1]), fairlead[-1] - a[-1]
    if h < 0:
        return 0.0, 0.0, [0.0] * len(a)
    r = solve(X, h, ln.length, ln.weight, ln.EA)
    H, V = float(r.H), float(r.V)
    across = [(x - y) / X if X > 0 else 0.0 for x, y in zip(a[:-1], fairlead[:-1])]  # towards the anchor
    T = math.hypot(H, V)
    e = ([H / T * u for u in across] + [-V / T]) if 0 < T < math.inf else across + [-1.0]
    if dynamic:
        suspended = ln.length - float(r.touchdown) if math.isfinite(r.touchdown) else ln.length
        return (ln.EA / max(suspended, 1e-3 * ln.length), (1.0 + damping) * math.sqrt(ln.EA * ln.mass_per_length),
                e)
    if not (math.isfinite(H) and math.isfinite(V)):
        return 0.0, 0.0, e  # a taut inextensible line: a length constraint in MuJoCo, no spring
    d = 1e-4 * max(h, X, 1e-3)
    kx = (float(solve(X + d, h, ln.length, ln.weight, ln.EA).H) - float(solve(max(X - d, 0.0), h, ln.length,
                                                                                ln.weight, ln.EA).H)) / (2 * d)
    kz = (float(solve(X, h + d, ln.length, ln.weight, ln.EA).V) - float(solve(X, max(h - d, 0.0), ln.length,
                                                                                ln.weight, ln.EA).V)) / (2 * d)
    k = max(abs(kx), abs(kz))
    return (k if math.isfinite(k) else 0.0), 0.0, e


def line_coupling_step(scene) -> tuple[float, str]:
    """The coupling step [s] the lines allow (cosim.line_step's bounds ``dt < 1 / omega``
    and ``dt < 1.6 / rate`` on each body, ``omega^2 = sum k (1 + |r x e|^2 / rho_g^2) / M``
    and ``rate = sum c (1 + |r x e|^2 / rho_g^2) / M`` over its lines: ``r`` the fairlead's
    arm, ``e`` the line's tangent there, ``rho_g`` the body's smallest radius of gyration,
    ``M`` its mass with its smallest translational added mass), and the key path of the
    line that pulls hardest on that body; (inf, "") where no line is stiff (or every body
    with lines is driven, ``motion``)."""
    from cosim.line_step import SAFETY

    m = scene.moorings
    if m is None:
        return math.inf, ""
    dim = scene.world.dim
    dynamic, damping = MOORINGS[m.model].dynamic, MOORINGS[m.model].damping
    added = getattr(scene.fluid, "added_mass", {}) or {}
    best, key = math.inf, ""
    for b in scene.bodies:
        if not isinstance(b, RigidBody) or getattr(b, "motion", None) is not None:
            continue  # a driven body follows its motion whatever its lines pull: no bound
        mine = [(i, ln) for i, ln in enumerate(m.lines) if ln.fairlead.split(".")[0] == b.name]
        if not mine:
            continue
        M = _body_mass(b, dim, 0.0) + min(added.get(b.name, [0.0] * 3)[: dim if dim == 3 else 2])
        g2 = b.gyration2(dim)
        k_sum = c_sum = 0.0
        worst, i_worst = -1.0, mine[0][0]
        for i, ln in mine:
            offset = b.fairleads[ln.fairlead.split(".")[1]]
            start = _fairlead_start(scene, b, offset)
            if start is None:
                continue
            k, c, e = _line_spring(ln, start, dynamic, damping)
            if dim == 2:
                lever = (offset[0] * e[1] - offset[1] * e[0]) ** 2
            else:
                lever = sum(x * x for x in (offset[1] * e[2] - offset[2] * e[1], offset[2] * e[0] - offset[0] * e[2],
                                            offset[0] * e[1] - offset[1] * e[0]))
            arm = 1.0 + lever / g2
            k_sum, c_sum = k_sum + k * arm, c_sum + c * arm
            if k * arm > worst:
                worst, i_worst = k * arm, i
        bounds = [SAFETY["spring"] * 2.0 / math.sqrt(k_sum / M) if k_sum > 0 else math.inf,
                  SAFETY["dashpot"] * 2.0 * M / c_sum if c_sum > 0 else math.inf]
        if min(bounds) < best:
            best, key = min(bounds), f"moorings.lines[{i_worst}].EA"
    return best, key


def analytic_step(scene) -> tuple[float, str]:
    """The analytic fluid's step [s] (fluid.analytic.AnalyticFluid.max_dt at rest: damping
    ``m / B`` and ``I / B`` of the rotations, 50 steps per heave period on the largest
    waterplane, 50 per wave period)."""
    f, dim = scene.fluid, scene.world.dim
    best, key = math.inf, ""
    for i, b in enumerate(scene.bodies):
        if not isinstance(b, RigidBody):
            continue
        M = _body_mass(b, dim, f.rho)  # MuJoCo's mass: the added mass is in the joints' armature

        r = b.bounding_radius(dim) if dim == 3 else math.hypot(b.bounding_radius(dim), 0.5)
        k = f.rho * scene.world.g * math.pi * r * r
        if k > 0:
            dt = 0.02 * 2.0 * math.pi * math.sqrt(M / k)
            if dt < best:
                best, key = dt, f"bodies[{i}]"
        row = f.linear_damping.get(b.name, [0.0] * 6)
        for inertia, B in ((M, max(row[:3])), (M * b.gyration2(dim), max(row[3:]))):  # translations, rotations
            if B > 0 and inertia / B < best:
                best, key = inertia / B, f"fluid.linear_damping.{b.name}"
    w = scene.waves
    period = (w.period if isinstance(w, (LinearWaves, RegularWaves, Piston, Flap)) else
              w.tp / 3.0 if isinstance(w, IrregularWaves) and w.tp is not None else None)
    if period is not None and 0.02 * period < best:
        best, key = 0.02 * period, "waves"
    return best, key


# ------------------------------------------------------------------------ the estimate
def _events(w) -> tuple[float, str]:
    """The run's events (samples, snapshots, checkpoints, plots) and the field of the
    densest of them."""
    n = len(w.plot_at) + 2
    densest, key = 0.0, "world.sample_every"
    for every, k in ((w.sample_every, "world.sample_every"), (w.snapshot_every, "world.snapshot_every"),
                     (w.checkpoint_every, "world.checkpoint_every")):
        if every > 0:
            n += w.duration / every
            if w.duration / every > densest:
                densest, key = w.duration / every, k
    return n, key


def _by(per_10s: float, limit: float, field: str, duration: float) -> str:
    """The field that drives a term proportional to the duration: the duration itself
    where 10 s of simulated time would cost under a hundredth of ``limit``."""
    return "world.duration" if per_10s < 0.01 * limit and duration > 10.0 else field


def estimate(scene) -> Estimate:
    """The cost of ``scene`` (module docstring); nothing is built."""
    w, dim, T = scene.world, scene.world.dim, scene.world.duration
    sph = isinstance(scene.fluid, SPH)
    terms = []
    # the coupling step: the smallest of what bounds it, (dt [s], what, the field behind it)
    events, ev_field = _events(w)
    bounds = [(T / events, f"the events ({ev_field})", ev_field)]
    if scene.coupling.dt is not None:
        bounds.append((scene.coupling.dt, "coupling.dt", "coupling.dt"))
    if sph:
        dt_f, by = sph_step(scene)
        by = by.replace("_", " ")
        own = next((f"fluid.{k}" for k in ("c0", "u_max", "c0_factor") if getattr(scene.fluid, k) is not None),
                   "fluid.dx") if by == "courant viscous" else "fluid.dx"
        bounds.append((dt_f, f"the SPH fluid's step ({by})", own))
    elif isinstance(scene.fluid, Analytic) and scene.bodies:
        dt_a, key = analytic_step(scene)
        bounds.append((dt_a, f"the analytic fluid ({key})", key or "world.duration"))
    dt_l, key = line_coupling_step(scene)
    bounds.append((dt_l, f"the mooring lines ({key})", key or "world.duration"))
    dt_c, dt_by, c_field = min(bounds, key=lambda b: b[0])
    gap = T / events  # the coupler lands on each event: a whole number of steps between two
    per_gap = _over(gap, dt_c)
    steps = _over(T, dt_c) if not per_gap <= 1e12 else events * math.ceil(per_gap - 1e-9)
    n_fluid = n_all = n_settle = 0.0
    if sph:
        from cosim.scene.build import fluid_config
        from cosim.scene.setup import choose

        water, walls, body = sph_particles(scene)
        n_fluid, n_all = water, water + walls + body
        h_coef = fluid_config(scene, choose(scene), numbers_only=True).h_coef
        advances = SUBITER_ADVANCES if _subiterated(scene) else 1.0
        per_step = C_SPH[dim] * (h_coef / math.sqrt(2.0)) ** H_POWER[dim] * n_all
        per_s = _over(per_step * advances, dt_c)
        field = "fluid.dx" if 1e3 * per_step > CONFIRM_CPU_S else c_field  # 1000 steps of it: a day
        sub = f", {advances:g} advances a step (a light body sub-iterated)" if advances > 1 else ""
        terms.append(Term("fluid", _by(10 * per_s, CONFIRM_CPU_S, field, T),
                          f"{n_all:.3g} particles, {steps:.3g} steps of {dt_c:.3g} s (set by {dt_by}){sub}",
                          C_SPH_START + per_s * T, B_SPH[dim] * n_all, per_s))
        if scene.fluid.settle > 0:
            n_settle = _over(scene.fluid.settle, dt_f)
            terms.append(Term("settle", "fluid.settle", f"{scene.fluid.settle:g} s of relaxation: {n_settle:.3g} "
                              f"steps of {dt_f:.3g} s, {n_all:.3g} particles", per_step * n_settle))
    n_bodies = sum(b.elements + 1 if isinstance(b, ElasticPlate) else len(b.bodies) or 1 if isinstance(b, MJCF)
                   else 1 for b in scene.bodies)
    if scene.bodies:
        dt_mj, mj_field = scene.coupling.body_timestep, "coupling.body_timestep"
        for i, b in enumerate(scene.bodies):
            if isinstance(b, ElasticPlate) and 0.5 * plate_step(b, dim) < dt_mj:
                dt_mj = 0.5 * plate_step(b, dim)
                mj_field = f"bodies[{i}].elements" if b.elements > 64 else f"bodies[{i}].E"
        mj_steps = max(_over(T, dt_mj), steps)
        per_s = (C_MJ * n_bodies * mj_steps + C_BODY_STEP * steps) / T
        mujoco = C_MJ * n_bodies * mj_steps > C_BODY_STEP * steps  # MuJoCo's steps cost more than the exchange
        terms.append(Term("bodies", _by(10 * per_s, CONFIRM_CPU_S, mj_field if mujoco else c_field, T),
                          f"{n_bodies} bodies and links, {mj_steps:.3g} MuJoCo steps of {_over(T, mj_steps):.3g} s, "
                          f"their exchange at {steps:.3g} coupling steps",
                          per_s * T, 0.0, per_s))
    lines = line_steps(scene)
    if lines:
        node_steps = sum(n * (max(_over(T, dt), steps) * LINE_ADVANCES + _over(before, dt))
                         for _, n, dt, before in lines)
        i, _, dt, _ = min(lines, key=lambda x: x[2])
        field = "moorings.segments" if scene.moorings.segments > 200 else f"moorings.lines[{i}].EA"
        per_s = MOORINGS[scene.moorings.model].node_cost * node_steps / T
        terms.append(Term("lines", _by(10 * per_s, CONFIRM_CPU_S, field if _over(T, dt) >= steps else c_field, T),
                          f"{sum(x[1] for x in lines)} nodes, internal steps of {dt:.3g} s ({scene.moorings.model})",
                          per_s * T, 0.0, per_s))
    ledger = 2.0 * (8.0 + 120.0 * n_bodies) * steps if scene.bodies else 0.0
    per_s = C_STEP * steps / T
    links = max(((b.elements, f"bodies[{i}].elements") for i, b in enumerate(scene.bodies)
                 if isinstance(b, ElasticPlate)), default=(0, ""))
    ledger_field = links[1] if links[0] > 64 else _by(10 * ledger / T, 1e9, c_field, T)  # a plate's many links
    terms.append(Term("coupling", _by(10 * per_s, CONFIRM_CPU_S, c_field, T), f"{steps:.3g} steps of {dt_c:.3g} s "
                      f"(set by {dt_by}); the ledger of their loads on {n_bodies} bodies and links "
                      f"{human_bytes(ledger)}", per_s * T, ledger, per_s, ledger_field))
    columns = _columns(scene)
    samples = T / w.sample_every
    rows = samples * (B_SAMPLE + B_COLUMN * columns)
    mem = B_EVENT * events + rows
    terms.append(Term("records", _by(10 * mem / T, 1e9, ev_field, T), f"{events:.3g} events, {samples:.3g} samples "
                      f"of {columns} series", 0.0, mem))
    snaps = (T / w.snapshot_every + 1) if w.snapshot_every > 0 and n_all else 0.0
    disk = snaps * n_all * B_SNAPSHOT[dim] + rows
    count = (lambda n: int(min(n, 2 ** 62)) if n == n else 2 ** 62)  # NaN: unbounded
    return Estimate(count(n_all), count(n_fluid), dt_c, dt_by, steps,
                    steps + n_settle if sph else 0.0,
                    sum(t.cpu_s for t in terms), B_PROCESS + sum(t.memory_bytes for t in terms), disk, tuple(terms))


def _subiterated(scene) -> bool:
    """Whether the coupler will sub-iterate the SPH fluid for a light body (mass under
    AUTO_THRESHOLD of the fluid it displaces, ``light_body`` auto or subiterate)."""
    from cosim.added_mass import AUTO_THRESHOLD

    c = scene.coupling
    if c.light_body not in ("auto", "subiterate") or c.scheme not in ("auto", "fluid-first"):
        return False
    if c.light_body == "subiterate":
        return bool(scene.bodies)
    rho = scene.fluid.rho0
    return any(_body_mass(b, scene.world.dim, rho) < AUTO_THRESHOLD * rho * b.volume(scene.world.dim)
               for b in scene.bodies if isinstance(b, RigidBody))


def _columns(scene) -> int:
    """How many series the scene records (cosim.scene.probes.series_names; an MJCF file's
    bodies are not read here: one each)."""
    if any(isinstance(b, MJCF) for b in scene.bodies):
        return 20
    from cosim.scene.probes import series_names

    return len(series_names(scene))


# ------------------------------------------------------------------------ the refusals
#: what to change, by the field that drives a cost
_FIXES = {"fluid.dx": "a coarser fluid.dx (the particles go as dx^-dim, the steps as 1/dx)",
          "world.duration": "a shorter world.duration",
          "world.sample_every": "a larger world.sample_every (fewer samples)",
          "fluid.settle": "a shorter fluid.settle (a few periods of the slowest mode settle the water)",
          "coupling.dt": "a larger coupling.dt, or leave it out (the participants' stable step)",
          "coupling.body_timestep": "a larger coupling.body_timestep",
          "moorings.segments": "fewer moorings.segments"}


def _fix(field: str) -> str:
    if field in _FIXES:
        return _FIXES[field]
    if field.startswith("fluid."):
        return f"a lower speed of sound ({field}; c0 = 10 u_max keeps the density within 1 %)"
    if field.endswith(".elements") or field.endswith(".E"):
        return f"a softer or coarser plate ({field}: its stiffest mode sets MuJoCo's step)"
    if field.endswith(".EA"):
        return f"a softer line ({field}) or fewer moorings.segments"
    return f"a smaller {field}"


def available_memory() -> float:
    """The memory [bytes] this process may still take: the system's available memory
    (``MemAvailable``), or less where a control group limits it; inf where neither is known."""
    avail = math.inf
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemAvailable:"):
                avail = float(line.split()[1]) * 1024.0
    except OSError:
        pass
    try:
        limit = open("/sys/fs/cgroup/memory.max").read().strip()
        used = float(open("/sys/fs/cgroup/memory.current").read().strip())
        if limit != "max":
            avail = min(avail, float(limit) - used)
    except (OSError, ValueError):
        pass
    return avail


def check(est: Estimate, out=None, *, yes: bool = False, ask=None) -> None:
    """Refuse (:class:`cosim.scene.fields.SceneError`, named by the field that drives it) a
    run whose memory exceeds the machine's available memory, or whose files exceed the
    free disk under ``out``; and one whose CPU time exceeds :data:`CONFIRM_CPU_S` unless
    ``yes``, or ``ask(question)`` (an interactive confirmation) answers True."""
    from cosim.scene.fields import SceneError

    avail = available_memory()
    if est.memory_bytes > avail:
        t = est.memory_driver
        raise SceneError(t.memory_field or t.field, f"the run would need about {human_bytes(est.memory_bytes)} of memory ({t.name}: "
                         f"{t.why}), more than this machine's available memory ({human_bytes(avail)}); "
                         f"{_fix(t.field)}")
    if out is not None and est.disk_bytes > 0:
        import shutil
        from pathlib import Path

        probe = Path(out)
        while not probe.exists() and probe != probe.parent:
            probe = probe.parent
        free = shutil.disk_usage(probe).free
        if est.disk_bytes > free:
            raise SceneError("world.snapshot_every", f"the run would write about {human_bytes(est.disk_bytes)} "
                             f"(particle snapshots and probe series), more than the {human_bytes(free)} free under "
                             f"{str(probe)!r}; a larger world.snapshot_every (0: none), or {_fix('fluid.dx')}")
    if est.cpu_s > CONFIRM_CPU_S and not yes:
        t = est.driver
        question = (f"the run would take about {human_time(est.cpu_s)} of CPU, driven by {t.field} ({t.name}: "
                    f"{t.why})")
        if ask is not None and ask(question + ". Run it? [y/N] "):
            return
        raise SceneError(t.field, f"{question}, more than {human_time(CONFIRM_CPU_S)}; {_fix(t.field)}, or confirm "
                         f"that it should run: cosim run --yes (Scene.run(..., yes=True))")
