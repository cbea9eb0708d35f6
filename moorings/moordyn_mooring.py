"""MoorDyn v2 (the ``moordyn`` package, a lumped-mass dynamic line model) behind
the mooring interface (``cosim.protocol.Mooring``).

The MoorDyn input file is written from the :class:`~moorings.line.MooringLine`
records: one line type and one line per record (``EA``, ``mass_per_length``
and the volume-equivalent ``diameter`` from the record), a fixed point at each
anchor and a coupled point at each fairlead. MoorDyn has one flat seabed, at
``z = water_level - depth``: all anchors must lie at one height, which becomes
the seabed (the catenary law's "seabed through the anchor").

Our coupler owns the clock: :meth:`MoorDynMooring.advance` hands MoorDyn the
fairlead positions at the step's start time ``t`` and their velocities (given,
or estimated by a backward difference of the positions of the last two
steps), and MoorDyn integrates from ``t`` to ``t + dt`` with its own internal
step ``dt_internal`` (it sub-cycles; the coupling step can be any size). The
coupler, which advances MoorDyn with the bodies (``Coupler(lines="subiterate")``),
calls :meth:`MoorDynMooring.drive_to_step_end` first: the positions it gives are
then the ones reached at the step's end, from where the last step left them.
That step is derived from every stiff term the adapter writes into MoorDyn's
input (:func:`internal_step_limits`, below) and :attr:`MoorDynMooring.dt_limit`
names the term that set it. MoorDyn's failures (input file, NaN in a line) become
:class:`~cosim.errors.InputError` / :class:`~cosim.errors.SolverError` naming
our line, with MoorDyn's own log lines attached.

Optional: ``pip install .[moordyn]``. Importing this module works without it;
constructing a :class:`MoorDynMooring` then raises an ``InputError`` that says
how to install it.
"""

from __future__ import annotations

import contextlib
import ctypes
import logging
import math
import os
import re
import shutil
import sys
import tempfile
import weakref
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from errors import InputError, SolverError
from moorings.fairlead_stiffness import FairleadStiffness, axial
from moorings.line import named_lines, per_line
from moorings.line_events import LineStateLog, node_states

log = logging.getLogger(__name__)


def moordyn_available() -> bool:
    """Whether the optional ``moordyn`` package can be imported."""
    try:
        import moordyn  # noqa: F401
    except ImportError:
        return False
    return True


@contextlib.contextmanager
def _captured_stdio(sink: Path):
    """Send the C library's console output (fd 1 and 2) to ``sink`` for the duration."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    with open(sink, "ab") as f:
        try:
            os.dup2(f.fileno(), 1)
            os.dup2(f.fileno(), 2)
            yield
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)


#: safety factor on the smallest single-term limit for MoorDyn's RK2 (pinned in the input file)
RK2_SAFETY = 0.5

#: names of the terms that can limit the internal step (plus "user": dt_internal given)
STEP_TERMS = ("axial_wave", "internal_damping", "seabed_stiffness", "seabed_damping", "drag")


@dataclass(frozen=True)
class InternalStepLimit:
    """MoorDyn's internal step and what set it.

    ``dt`` [s] is ``safety * limits[limiter]`` (or the user's ``dt_internal`` with
    ``limiter == "user"``); ``limits`` maps each term of :data:`STEP_TERMS` to its own
    single-term bound [s] (before the safety factor) on the line ``line`` that is the
    most restrictive for that term."""

    dt: float  # [s]
    limiter: str  # a term of STEP_TERMS, or "user"
    line: str  # the line whose term set the step ("" for "user")
    safety: float  # [-]
    limits: dict  # term -> [s], the smallest over the lines, before the safety factor


def internal_step_limits(length: float, segments: int, EA: float, mass_per_length: float, diameter: float, *,
                         rho: float, damping_ratio: float, cd_normal: float, ca_normal: float, cd_axial: float,
                         ca_axial: float, seabed_stiffness: float, seabed_damping: float,
                         drag_speed: float) -> dict:
    """The explicit-stability bound [s] of each stiff term of one MoorDyn line, as MoorDyn
    v2 applies it to an internal node: the lumped-mass formulation of Hall & Goupee 2015
    (Ocean Engineering 104) as coded in MoorDyn v2.7 ``source/Line.cpp``
    (``Line::initialize`` for ``BA``, ``Line::getStateDeriv`` for the node forces).

    MoorDyn lumps the line into ``N = segments`` segments of length ``l = L / N`` [m] and
    integrates the internal nodes (the anchor is a fixed point, the fairlead a coupled
    one: neither is integrated). An internal node carries half of each neighbouring
    segment, so every per-node quantity is per segment length ``l``:

    - mass ``m_n = m l`` [kg] (``m`` the mass per length), and the added-mass matrix
      ``rho A l (Ca_n (I - q q^T) + Ca_t q q^T)`` (``A = pi d^2 / 4``, ``q`` the tangent):
      the node mass is ``m_t = m_n + rho A l Ca_t`` along the line and
      ``m_p = m_n + rho A l Ca_n`` across it.

    Each term, alone, makes the node a damped oscillator or a pure dashpot; an explicit
    scheme is stable when ``dt |lambda| < 2`` for its fastest eigenvalue ``lambda`` (the
    real-axis bound of forward Euler and of MoorDyn's RK2, ``|1 + z + z^2/2| <= 1``), i.e.
    ``dt < 2 / omega`` for a spring and ``dt < 2 m / c`` for a dashpot:

    ``axial_wave``: segment spring ``EA / l``, highest mode: ``dt < sqrt(m_t l / EA)``.
    ``internal_damping``: MoorDyn's ``BA = -zeta``, a dashpot ``zeta sqrt(EA m)`` [N s/m] between
    neighbours: ``dt < m_t / (2 zeta sqrt(EA m))``; unbounded for ``zeta = 0``.
    ``seabed_stiffness``, ``seabed_damping``: ``k_b = kb d l``, ``c_b = cb d l`` on the smaller
    node mass: ``dt < 2 sqrt(m_min / k_b)``, ``dt < 2 m_min / c_b`` (the same for every ``N``).
    ``drag``: Morison drag linearised at ``drag_speed`` ``U``: ``dt < 2 m_p / (rho d Cd_n l U)``
    and ``dt < 2 m_t / (rho d pi Cd_t l U)``. Each derivation: docs/moorings_moordyn_step.md.

    Not covered because the adapter sets none of them: bending stiffness ``EI`` (0),
    seabed friction (MoorDyn's ``FrictionCoefficient`` defaults to 0), nonlinear
    stiffness tables, VIV, points with mass.

    Returns ``{term: dt [s]}`` for the terms of :data:`STEP_TERMS` (``inf`` where a term
    is absent). Units: lengths [m], ``EA`` [N], ``mass_per_length`` [kg/m], ``rho``
    [kg/m^3], ``seabed_stiffness`` [Pa/m], ``seabed_damping`` [Pa s/m], ``drag_speed``
    [m/s]; coefficients [-].
    """
    inf = math.inf
    d, m = diameter, mass_per_length
    l_seg = length / segments
    vol = math.pi / 4.0 * d * d * l_seg  # node volume [m^3]
    m_n = m * l_seg
    m_t = m_n + rho * vol * ca_axial
    m_p = m_n + rho * vol * ca_normal
    m_min = min(m_t, m_p)
    c_int = damping_ratio * math.sqrt(EA * m)
    k_b, c_b = seabed_stiffness * d * l_seg, seabed_damping * d * l_seg
    c_dp = rho * d * cd_normal * l_seg * drag_speed
    c_dq = rho * d * math.pi * cd_axial * l_seg * drag_speed
    return {
        "axial_wave": math.sqrt(m_t * l_seg / EA),
        "internal_damping": m_t / (2.0 * c_int) if c_int > 0 else inf,
        "seabed_stiffness": 2.0 * math.sqrt(m_min / k_b) if k_b > 0 else inf,
        "seabed_damping": 2.0 * m_min / c_b if c_b > 0 else inf,
        "drag": min(2.0 * m_p / c_dp if c_dp > 0 else inf, 2.0 * m_t / c_dq if c_dq > 0 else inf),
    }


def _restore_none_references(before: int) -> None:
    """moordyn 2.7's ``Deserialize`` drops a reference to ``None`` on every call (its binding
    returns ``Py_None`` without a new reference); on Python < 3.12, where ``None`` is counted,
    the coupler's roll-backs (one per step with the predictor-corrector) run the count down
    and the interpreter aborts ("none_dealloc") after ~15 000 steps (benchmarks/soak.py).
    Give back exactly the references the call took; nothing when the count held (a fixed
    moordyn, or an immortal ``None``)."""
    lost = before - sys.getrefcount(None)
    for _ in range(max(lost, 0)):
        ctypes.pythonapi.Py_IncRef(ctypes.py_object(None))


def _num(x) -> str:
    """A number as MoorDyn reads it, exactly (shortest round-trip repr of the double)."""
    return repr(float(x))


def _close(box, tmpdir, keep_dir=False):
    """Close the MoorDyn system in ``box`` (its console output goes to the folder's
    console.txt) and, unless ``keep_dir``, remove the folder."""
    system = box.pop("system", None)
    if system is not None:
        import moordyn

        with contextlib.suppress(Exception):
            with _captured_stdio(Path(tmpdir) / "console.txt"):
                moordyn.Close(system)
    if not keep_dir:
        shutil.rmtree(tmpdir, ignore_errors=True)


class MoorDynMooring:
    """Lumped-mass dynamic mooring lines solved by MoorDyn v2; satisfies ``cosim.protocol.Mooring``.

    Parameters
    ----------
    lines:
        The :class:`~moorings.line.MooringLine` records (2-D lines run in MoorDyn at y = 0).
        Each needs ``EA`` [N] (MoorDyn lines are elastic) and ``mass_per_length`` [kg/m] or
        ``diameter`` [m]: the other follows from the submerged weight, ``w = (m - rho pi d^2 /
        4) g``; if both are given they must agree with ``weight`` to 0.1 %.
    fairleads: optional initial fairlead positions [m], ``(n_lines, dim)``.
    water_level: height of the free surface in our world frame [m] (MoorDyn's z = 0).
    rho, g: water density [kg/m^3], gravity [m/s^2].
    segments: number of segments per line (MoorDyn's NumSegs).
    dt_internal:
        MoorDyn's internal time step dtM [s]. Default: ``RK2_SAFETY`` (1/2) times the
        smallest single-term bound of :func:`internal_step_limits` over all lines and terms (the
        record is :attr:`dt_limit`; RK2 pinned; why 1/2: docs/moorings_moordyn_step.md). A given
        value is used as is; a warning says when it exceeds the derived one.
    damping_ratio:
        Axial internal damping as a fraction of a segment's critical damping (MoorDyn's
        negative BA) [-]; below 0.1 a warning says that RK2 lets the highest axial mode grow.
    cd_normal, ca_normal, cd_axial, ca_axial: drag and added-mass coefficients, normal and axial [-].
    seabed_stiffness, seabed_damping: MoorDyn's kbot [Pa/m] and cbot [Pa s/m] (per ``d l_seg``).
    drag_speed:
        Relative flow speed [m/s] at which the quadratic drag is linearised for the default
        ``dt_internal`` (:func:`internal_step_limits`); it limits only light, thin lines in fast flow.
    ic_time, ic_threshold, ic_drag_scale:
        MoorDyn's initial-condition relaxation: TmaxIC [s], threshIC [-], CdScaleIC [-], run
        as upscaled-drag dynamics (``ICgenDynamic 1``) so that the lines start settled (MoorDyn
        2.7's stationary default starts a line resting on the seabed slack: docs/moorings_moordyn_step.md).
    name: participant name used in messages.

    Attributes
    ----------
    dt_internal: the internal step MoorDyn runs with [s].
    dt_limit:
        :class:`InternalStepLimit`: the step, the term that limited it (``limiter``,
        e.g. ``"seabed_damping"``; ``"user"`` for a given ``dt_internal``), the line, the
        safety factor and every term's bound, as the fluid's ``limiter`` reports its own.
    """

    def __init__(self, lines, fairleads=None, *, water_level: float = 0.0, rho: float = 1025.0, g: float = 9.81,
                 segments: int = 20, dt_internal: float | None = None, damping_ratio: float = 0.8,
                 cd_normal: float = 1.2, ca_normal: float = 1.0, cd_axial: float = 0.2, ca_axial: float = 0.0,
                 seabed_stiffness: float = 3.0e6, seabed_damping: float = 3.0e5, drag_speed: float = 10.0,
                 ic_time: float = 20.0,
                 ic_threshold: float = 1e-3, ic_drag_scale: float = 4.0, name: str = "moordyn"):
        self.name = name
        self.lines = named_lines(lines)
        self.n_lines = len(self.lines)
        self.dim = self.lines[0].dim
        if not moordyn_available():
            raise InputError(f"{name}: the optional 'moordyn' package is not installed; "
                             f"pip install 'cosim-sph[moordyn]' (or pip install moordyn)")
        nums = dict(water_level=water_level, rho=rho, g=g, damping_ratio=damping_ratio, cd_normal=cd_normal,
                    ca_normal=ca_normal, cd_axial=cd_axial, ca_axial=ca_axial, seabed_stiffness=seabed_stiffness,
                    seabed_damping=seabed_damping, drag_speed=drag_speed, ic_time=ic_time,
                    ic_threshold=ic_threshold, ic_drag_scale=ic_drag_scale)
        for key, v in nums.items():
            if not isinstance(v, (int, float)) or not math.isfinite(v):
                raise InputError(f"{name}: {key} = {v!r} must be a finite number")
        for key in ("rho", "g", "ic_threshold", "ic_drag_scale"):
            if nums[key] <= 0:
                raise InputError(f"{name}: {key} = {nums[key]!r} must be > 0")
        for key in ("damping_ratio", "cd_normal", "ca_normal", "cd_axial", "ca_axial", "seabed_stiffness",
                    "seabed_damping", "drag_speed", "ic_time"):
            if nums[key] < 0:
                raise InputError(f"{name}: {key} = {nums[key]!r} must be >= 0")
        if not isinstance(segments, int) or segments < 1:
            raise InputError(f"{name}: segments = {segments!r} must be an integer >= 1")
        self.water_level, self.rho, self.g, self.segments = float(water_level), float(rho), float(g), segments
        self.anchors = np.array([ln.anchor for ln in self.lines], dtype=float)
        z = self.anchors[:, -1]
        span = float(np.max(np.abs(self.anchors))) + 1.0
        if np.ptp(z) > 1e-9 * span:
            raise InputError(f"{name}: MoorDyn has one flat seabed, but the anchors lie at z = "
                             f"{', '.join(f'{v:.6g}' for v in z)} m; put all anchors at one height")
        self.depth = self.water_level - float(z[0])
        if not self.depth > 0:
            raise InputError(f"{name}: the anchors (z = {z[0]:.6g} m) must lie below the water level "
                             f"({self.water_level:.6g} m)")
        self._mass, self._diam = [], []
        for ln in self.lines:
            m, d = self._mass_and_diameter(ln)
            self._mass.append(m)
            self._diam.append(d)
        self._options = nums
        derived = self._step_limit()
        if dt_internal is None:
            self.dt_limit = derived
        else:
            if not (isinstance(dt_internal, (int, float)) and math.isfinite(dt_internal) and dt_internal > 0):
                raise InputError(f"{name}: dt_internal = {dt_internal!r} s must be > 0")
            if dt_internal > derived.dt:
                log.warning("%s: dt_internal = %.3g s exceeds the derived stable step %.3g s (%s of line '%s'); "
                            "MoorDyn may stop with NaN", name, dt_internal, derived.dt, derived.limiter, derived.line)
            self.dt_limit = InternalStepLimit(float(dt_internal), "user", "", 1.0, derived.limits)
        if damping_ratio < 0.1:
            log.warning("%s: damping_ratio = %g < 0.1: MoorDyn's RK2 lets the highest axial mode of an undamped "
                        "line grow at any step size", name, damping_ratio)
        self.dt_internal = self.dt_limit.dt
        self._pos = None
        self._vel = None
        if fairleads is not None:
            self.set_fairlead_motion(fairleads)
        self._prev = None  # (t, positions) at the last step's start, for the velocity estimate
        self._forces = None
        self._mean = None  # mean fairlead force over the last step (mean_fairlead_forces)
        self._step_end = False  # drive_to_step_end(): the motion given is the step's end state
        self._start = None  # with it: the fairleads' positions at the start of the next step
        self.t = 0.0
        #: when each line became fully lifted or taut (:mod:`moorings.line_events`), after every step
        self.state_log = LineStateLog([ln.name for ln in self.lines])
        self._tmp = Path(tempfile.mkdtemp(prefix="cosim_moordyn_"))
        self._box = {}
        self._finalizer = weakref.finalize(self, _close, self._box, str(self._tmp))

    # -- set-up ------------------------------------------------------------------
    def _step_limit(self) -> InternalStepLimit:
        """The derived internal step: ``RK2_SAFETY`` times the smallest bound of
        :func:`internal_step_limits` over the lines and terms."""
        o = self._options
        keys = ("rho", "damping_ratio", "cd_normal", "ca_normal", "cd_axial", "ca_axial", "seabed_stiffness",
                "seabed_damping", "drag_speed")
        limits, where = {}, {}
        for ln, m, d in zip(self.lines, self._mass, self._diam):
            for term, v in internal_step_limits(ln.length, self.segments, ln.EA, m, d,
                                                **{k: o[k] for k in keys}).items():
                if v < limits.get(term, math.inf) or term not in limits:
                    limits[term], where[term] = v, ln.name
        term = min(STEP_TERMS, key=lambda k: limits[k])
        return InternalStepLimit(RK2_SAFETY * limits[term], term, where[term], RK2_SAFETY, limits)

    def _mass_and_diameter(self, ln):
        label = f"{self.name}, line '{ln.name}'"
        if ln.inextensible:
            raise InputError(f"{label}: MoorDyn models elastic lines only; give the line an axial stiffness EA [N]")
        m, d, w = ln.mass_per_length, ln.diameter, ln.weight
        buoy = self.rho * math.pi / 4.0 * self.g  # buoyancy per unit length per d^2 [N/m^3]
        if m is None and d is None:
            raise InputError(f"{label}: MoorDyn needs the mass per length [kg/m] or the volume-equivalent "
                             f"diameter [m] of the line (MooringLine mass_per_length= or diameter=)")
        if m is None:
            m = (w + buoy * d * d) / self.g
        elif d is None:
            vol = (m * self.g - w) / buoy
            if vol <= 0:
                raise InputError(f"{label}: mass_per_length = {m:g} kg/m weighs {m * self.g:g} N/m in air, not more "
                                 f"than the submerged weight {w:g} N/m; the line would need negative volume")
            d = math.sqrt(vol)
        else:
            w_md = (m - self.rho * math.pi / 4.0 * d * d) * self.g
            if abs(w_md - w) > 1e-3 * w:
                raise InputError(f"{label}: weight = {w:g} N/m disagrees with mass_per_length = {m:g} kg/m and "
                                 f"diameter = {d:g} m, which give (m - rho pi d^2/4) g = {w_md:g} N/m; drop one "
                                 f"of mass_per_length and diameter, or make them agree")
        return m, d

    def _md(self, p):
        """Our world-frame point(s) (n, dim) -> MoorDyn's 3-D frame (z from the water level)."""
        p = np.atleast_2d(p)
        if self.dim == 2:
            p = np.stack([p[:, 0], np.zeros(len(p)), p[:, 1]], axis=1)
        q = np.array(p, dtype=float)
        q[:, 2] -= self.water_level
        return q

    def _input_file(self, fairleads) -> str:
        o = self._options
        rows_types, rows_points, rows_lines = [], [], []
        a_md, f_md = self._md(self.anchors), self._md(fairleads)
        for i, ln in enumerate(self.lines):
            nums = (self._diam[i], self._mass[i], ln.EA, -o["damping_ratio"], 0.0, o["cd_normal"], o["ca_normal"],
                    o["cd_axial"], o["ca_axial"])
            rows_types.append(f"lt{i + 1} " + " ".join(_num(v) for v in nums))
        for i in range(self.n_lines):
            rows_points.append(f"{i + 1} Fixed {' '.join(_num(c) for c in a_md[i])} 0 0 0 0")
        for i in range(self.n_lines):
            rows_points.append(f"{self.n_lines + i + 1} Coupled {' '.join(_num(c) for c in f_md[i])} 0 0 0 0")
        for i, ln in enumerate(self.lines):
            rows_lines.append(f"{i + 1} lt{i + 1} {i + 1} {self.n_lines + i + 1} {_num(ln.length)} {self.segments} -")
        opts = [(self.dt_internal, "dtM"), (o["seabed_stiffness"], "kbot"), (o["seabed_damping"], "cbot"),
                (self.rho, "WtrDnsty"), (self.depth, "WtrDpth"), (self.g, "g"), (o["ic_time"], "TmaxIC"),
                (o["ic_drag_scale"], "CdScaleIC"), (o["ic_threshold"], "threshIC")]
        opts_text = [f"{_num(v)} {k}" for v, k in opts] + ["RK2 tScheme",  # dt_internal assumes RK2
                                                          "1 ICgenDynamic"]  # settled lines (ic_time's doc)
        return "\n".join([
            "--------------------- MoorDyn Input File ------------------------------------",
            f"written by moorings.moordyn_mooring for {self.name}: lines {', '.join(ln.name for ln in self.lines)}",
            "----------------------- LINE TYPES ------------------------------------------",
            "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx",
            "(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)",
            *rows_types,
            "---------------------- POINTS --------------------------------",
            "ID Attachment X Y Z Mass Volume CdA Ca",
            "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)",
            *rows_points,
            "---------------------- LINES --------------------------------------",
            "ID LineType AttachA AttachB UnstrLen NumSegs Outputs",
            "(#) (name) (#) (#) (m) (-) (-)",
            *rows_lines,
            "---------------------- OPTIONS -----------------------------------------",
            *opts_text,
            "1 disableOutput",
            "1 disableOutTime",
            "--------------------- need this line ------------------",
            "",
        ])

    def _log_text(self) -> str:
        text = ""
        for f in ("moordyn.log", "console.txt"):
            p = self._tmp / f
            if p.exists():
                text += p.read_text(errors="replace")
        return text

    def _error(self, what: str, exc: Exception, cls=SolverError):
        text = self._log_text()
        errs = [ln.strip() for ln in text.splitlines() if ln.strip() and ("ERR" in ln or "rror" in ln
                                                                           or re.match(r"Line \d+", ln.strip()))]
        culprits = sorted({int(k) for k in re.findall(r"Line (\d+)", " ".join(errs))})
        named = [f"line '{self.lines[k - 1].name}' (MoorDyn line {k})" for k in culprits if 1 <= k <= self.n_lines]
        where = f" in {', '.join(named)}" if named else ""
        detail = " | ".join(errs[-4:]) if errs else str(exc)
        lim = self.dt_limit
        hint = (f"; dt_internal = {lim.dt:.3g} s (limited by {lim.limiter}"
                + (f" of line '{lim.line}'" if lim.line else "") + "): try a smaller dt_internal, more damping, "
                "or check the fairlead motion (a line pulled far beyond its length)") if cls is SolverError else ""
        return cls(f"{self.name} at t = {self.t:.6g} s: MoorDyn failed {what}{where}: {detail}{hint}")

    # -- participant protocol ------------------------------------------------
    def initialize(self, t0: float) -> None:
        """Write the input file, create the MoorDyn system and let MoorDyn find its
        initial (static) state at the current fairlead positions."""
        import moordyn

        if self._pos is None:
            raise InputError(f"{self.name}: fairlead positions are not set; call set_fairlead_motion() "
                             f"or pass fairleads= before the run")
        _close(self._box, self._tmp, keep_dir=True)  # a second initialize() starts afresh
        path = self._tmp / "lines.txt"
        path.write_text(self._input_file(self._pos))
        console = self._tmp / "console.txt"
        try:
            with _captured_stdio(console):
                system = moordyn.Create(str(path))
        except Exception as exc:  # noqa: BLE001 - cmoordyn raises RuntimeError
            raise self._error("to read the input file it was given", exc, InputError) from None
        self._box["system"] = system
        moordyn.SetVerbosity(system, moordyn.LEVEL_NONE)
        moordyn.SetLogFile(system, str(self._tmp / "moordyn.log"))
        moordyn.SetLogLevel(system, moordyn.LEVEL_WRN)
        x, v = self._md(self._pos).ravel(), np.zeros(3 * self.n_lines)
        if self._vel is not None:
            v = self._md_vec(self._vel).ravel()
        self.t = float(t0)
        try:
            with _captured_stdio(console):
                err = moordyn.Init(system, x.tolist(), v.tolist())
        except Exception as exc:  # noqa: BLE001
            raise self._error("to find the initial state", exc) from None
        if err != 0:
            raise self._error(f"to find the initial state (error code {err})", RuntimeError(err))
        log.debug("%s: MoorDyn console output:\n%s", self.name, console.read_text(errors="replace"))
        f = [moordyn.GetPointForce(moordyn.GetPoint(system, self.n_lines + i + 1)) for i in range(self.n_lines)]
        self._forces = self._ours(np.asarray(f, dtype=float))
        self._mean = self._forces.copy()
        self._prev = None
        self._start = self._pos.copy()
        if self.state_log.state is None:  # a resumed run keeps its log
            self.state_log.update(self.t, self.line_states())

    def max_dt(self) -> float:
        """Unlimited: MoorDyn sub-cycles each coupling step with ``dt_internal``."""
        return math.inf

    #: a dynamic line: its force over a step is an integral (the coupler advances it with the bodies)
    dynamic = True

    def drive_to_step_end(self) -> None:
        """From now on the fairlead motion given is the state reached at the end of the next
        advance, and the fairleads move there in a straight line from where the last advance
        left them (the coupler's exchange with dynamic lines, ``Coupler(lines="subiterate")``).
        Until then (standalone use) it is the state at the step's start, moving on with its
        velocity."""
        self._step_end = True
        self._start = None if self._pos is None else self._pos.copy()

    def advance(self, t: float, dt: float) -> None:
        """Integrate from ``t`` to ``t + dt`` [s], the fairleads starting from the
        positions last set and moving with their velocities (after :meth:`drive_to_step_end`:
        moving from the last advance's end to the positions last set)."""
        import moordyn

        system = self._system()
        self.t = float(t)
        start = self._pos
        if self._step_end:
            start = self._pos if self._start is None else self._start
            vel = (self._pos - start) / dt
        elif self._vel is not None:
            vel = self._vel
        elif self._prev is not None and t > self._prev[0]:
            vel = (self._pos - self._prev[1]) / (t - self._prev[0])
        else:
            vel = np.zeros_like(self._pos)
        x, v = self._md(start).ravel().tolist(), self._md_vec(vel).ravel().tolist()
        try:
            f = moordyn.Step(system, x, v, float(t), float(dt))
        except Exception as exc:  # noqa: BLE001
            raise self._error(f"between t = {t:.6g} s and {t + dt:.6g} s", exc) from None
        f = np.asarray(f, dtype=float).reshape(self.n_lines, 3)
        if not np.all(np.isfinite(f)):
            raise self._error(f"between t = {t:.6g} s and {t + dt:.6g} s (non-finite fairlead forces)",
                              RuntimeError("NaN"))
        # MoorDyn returns the force at the step's end only: the mean over the step by the trapezoid rule
        self._mean = 0.5 * (self._forces + self._ours(f))
        self._forces = self._ours(f)
        self._prev = (float(t), self._pos.copy())
        self._start = self._pos.copy()
        self.t = float(t) + float(dt)
        self.state_log.update(self.t, self.line_states())

    def save_state(self):
        import moordyn

        return (moordyn.Serialize(self._system()), self._pos.copy(), None if self._vel is None else self._vel.copy(),
                self._prev, self._forces.copy(), self.t, self.state_log.save(),
                None if self._start is None else self._start.copy(), self._mean.copy())

    def load_state(self, state) -> None:
        import moordyn

        blob, pos, vel, prev, forces, t, log_ = state[:7]
        start, mean = state[7:] if len(state) > 7 else (pos, forces)  # a checkpoint written before them
        self.state_log.load(log_)
        before = sys.getrefcount(None)
        moordyn.Deserialize(self._system(), blob)
        _restore_none_references(before)
        self._pos, self._vel, self._prev, self._forces, self.t = pos.copy(), vel, prev, forces.copy(), t
        self._start, self._mean = None if start is None else start.copy(), mean.copy()

    # -- mooring interface ---------------------------------------------------
    def set_fairlead_motion(self, positions, velocities=None) -> None:
        """Fairlead positions [m] and velocities [m/s] (``None``: estimated from the
        positions of consecutive steps), ``(n_lines, dim)``, world frame."""
        self._pos = self._check(positions, "fairlead positions")
        self._vel = None if velocities is None else self._check(velocities, "fairlead velocities")

    def fairlead_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its fairlead at the end of the last step
        (after :meth:`initialize`: in the initial state), ``(n_lines, dim)``."""
        if self._forces is None:
            raise InputError(f"{self.name}: call initialize(t0) first")
        return self._forces.copy()

    def mean_fairlead_forces(self) -> np.ndarray:
        """Mean force [N] each line exerted on its fairlead over the last step, ``(n_lines,
        dim)``: the trapezoid rule on its forces at the step's start and end (MoorDyn
        reports no other); after :meth:`initialize`, the initial force."""
        if self._forces is None:
            raise InputError(f"{self.name}: call initialize(t0) first")
        return self._mean.copy()

    def fairlead_tensions(self) -> np.ndarray:
        """Magnitude of each fairlead force [N] (the catenary's ``sqrt(H^2 + V^2)``; MoorDyn's
        own GetLineFairTen is the tension of the last segment, without the end node's weight)."""
        return np.linalg.norm(self.fairlead_forces(), axis=1)

    def anchor_tensions(self) -> np.ndarray:
        """Tension [N] of each line at its anchor: MoorDyn's tension at the anchor node (that
        of the first segment); a line resting on the seabed there pulls its anchor by the
        seabed's share only."""
        import moordyn

        s = self._system()
        return np.array([float(np.linalg.norm(moordyn.GetLineNodeTen(moordyn.GetLine(s, i + 1), 0)))
                         for i in range(self.n_lines)])

    def nodes(self) -> list[np.ndarray]:
        """Each line's node positions [m], ``(segments + 1, dim)`` from the anchor to the
        fairlead, world frame."""
        import moordyn

        s = self._system()
        out = []
        for i in range(self.n_lines):
            line = moordyn.GetLine(s, i + 1)
            p = np.array([moordyn.GetLineNodePos(line, k) for k in range(self.segments + 1)], dtype=float)
            p[:, 2] += self.water_level
            out.append(p[:, [0, 2]] if self.dim == 2 else p)
        return out

    def _seabed_tol(self, i: int) -> float:
        """Nodes this close to the seabed [m] lie on it: MoorDyn's seabed is a spring of
        ``kbot`` [Pa/m] on a node's contact area ``d l``, so a node resting on it sinks by
        ``w / (kbot d)`` under its submerged weight ``w`` [N/m]; three times that, and at
        least a thousandth of a segment."""
        ln = self.lines[i]
        sink = ln.weight / max(self._options["seabed_stiffness"] * self._diam[i], 1e-300)
        return max(3.0 * sink, 1e-3 * ln.length / self.segments)

    def line_states(self) -> np.ndarray:
        """Each line's :class:`~moorings.catenary.LineState` now, from MoorDyn's nodes
        (:func:`moorings.line_events.node_states`: taut where the anchor-fairlead distance is
        at least the unstretched length, lifted where no node but the anchor's lies on the
        seabed, within :meth:`_seabed_tol`)."""
        x = self.nodes()
        return node_states(self.anchors, [p[-1] for p in x], [ln.length for ln in self.lines], x,
                           self.anchors[:, -1], [self._seabed_tol(i) for i in range(self.n_lines)])

    def fairlead_stiffness(self) -> FairleadStiffness:
        """Each line's spring and dashpot at its fairlead over a coupling step
        (:func:`moorings.fairlead_stiffness.axial`): ``EA`` over the suspended length along
        the last segment, and the axial impedance ``sqrt(EA m)`` plus MoorDyn's internal
        damping on that segment, ``damping_ratio`` times it (``BA = zeta l sqrt(EA m)``
        acting on the segment's strain rate)."""
        arc = np.linspace(0.0, 1.0, self.segments + 1)
        k, c = zip(*(axial(x, arc * ln.length, ln.EA, m, ln.anchor[-1], self._seabed_tol(i),
                           self._options["damping_ratio"])
                     for i, (x, ln, m) in enumerate(zip(self.nodes(), self.lines, self._mass))))
        return FairleadStiffness(np.array(k), np.array(c))

    def close(self) -> None:
        """Free MoorDyn and its files (also done at garbage collection)."""
        self._finalizer()

    # -- helpers ---------------------------------------------------------------
    def _system(self):
        s = self._box.get("system")
        if s is None:
            raise InputError(f"{self.name}: call initialize(t0) first (or the mooring was closed)")
        return s

    def _md_vec(self, v):
        v = np.atleast_2d(v)
        if self.dim == 2:
            return np.stack([v[:, 0], np.zeros(len(v)), v[:, 1]], axis=1)
        return np.array(v, dtype=float)

    def _ours(self, f3):
        return f3[:, [0, 2]].copy() if self.dim == 2 else f3

    def _check(self, values, what):
        return per_line(values, [ln.name for ln in self.lines], self.dim, self.name, what)


__all__ = ["MoorDynMooring", "moordyn_available"]
