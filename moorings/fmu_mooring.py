"""Any FMI co-simulation FMU with fairlead positions in and fairlead forces out,
as a mooring participant (``cosim.protocol.Mooring``), through fmpy.

The FMU's variable names are mapped in a small dictionary, ``variable_map``:

``"positions"``  (required) the Real inputs that receive the fairlead positions [m]
``"forces"``     (required) the Real outputs that give the force on each fairlead [N]
``"velocities"`` (optional) Real inputs for the fairlead velocities [m/s]
``"states"``     (optional) Integer outputs, one per line: its state, Barreiro et al. 2016, Fig. 5
                 (0 resting, 1 partly lifted, 2 fully lifted, 3 taut;
                 :class:`moorings.catenary.LineState`); then :attr:`FMUMooring.state_log`
                 records when each line goes fully lifted or taut

Each value is either a nested list of names, ``(n_lines, dim)``, or a template
string formatted per line and axis with ``{line}`` (the line's name), ``{i}``
(its index), ``{axis}`` (``x``, ``z`` or ``x``, ``y``, ``z``) and ``{k}`` (the
axis index), e.g. ``"{line}.fairlead.{axis}"``. For an FMU written by
:func:`moorings.fmu_export.export_catenary_fmu`,
:func:`moorings.fmu_export.catenary_fmu_variable_map` gives the map.

The coupler owns the clock: :meth:`FMUMooring.advance` calls ``fmi2DoStep``
from the exact start time it is handed. The forces are read right after the
inputs are set, so an FMU with direct feedthrough (a quasi-static law) gives
the forces at the current positions, and a dynamic one those at the end of its
last step. FMU errors become :class:`~cosim.errors.SolverError` (a taut line:
:class:`~cosim.errors.TautLineError`) carrying the FMU's log messages.
"""

from __future__ import annotations

import logging
import math
import shutil
import weakref
from pathlib import Path

import numpy as np

from errors import InputError, SolverError, TautLineError
from moorings.fairlead_stiffness import FairleadStiffness, by_differences
from moorings.line import MooringLine, named_lines, per_line
from moorings.line_events import LineStateLog

log = logging.getLogger(__name__)

_STATUS = ("OK", "WARNING", "DISCARD", "ERROR", "FATAL", "PENDING")

# fmpy's native logger proxy (it formats the FMU's printf-style message) keeps ONE
# Python logger per process. All FMUMooring instances share one dispatcher that
# routes each message by the componentEnvironment its instance was given, and
# re-arm it before every FMI call, in case other fmpy users replaced it meanwhile.
_SINKS: dict[int, tuple[list, str]] = {}
_KEYS = iter(range(1, 1 << 62))
_LOGGER = {}


def _dispatch(env, instance, status, category, message):
    text = message.decode("utf-8", "replace") if message else ""
    st = _STATUS[status] if 0 <= status < len(_STATUS) else str(status)
    sink = _SINKS.get(env or 0)
    level = logging.DEBUG if status == 0 else logging.WARNING if status in (1, 2) else logging.ERROR
    if sink is None:
        name = instance.decode("utf-8", "replace") if instance else "?"
        log.log(level, "FMU %s (not an FMUMooring): %s: %s", name, st, text)
        return
    messages, label = sink
    messages.append((st, text))
    del messages[:-20]
    log.log(level, "%s: FMU %s: %s", label, st, text)


def _arm():
    """Make the shared dispatcher the process's FMU logger again; returns its C proxy."""
    from ctypes import byref

    from fmpy.fmi2 import fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
    from fmpy.logging import addLoggerProxy

    if "py" not in _LOGGER:
        _LOGGER["py"] = fmi2CallbackLoggerTYPE(_dispatch)
    a = fmi2CallbackFunctions()
    a.logger = _LOGGER["py"]
    addLoggerProxy(byref(a))  # now a.logger is the formatting proxy that calls _dispatch
    _LOGGER["proxy"] = a.logger
    return a.logger


def _cleanup(fmu_box, unzip_dir, key):
    """Free the FMU instance and its extracted files (runs at close() or garbage collection)."""
    fmu = fmu_box.pop("fmu", None)
    if fmu is not None:
        _arm()
    if fmu is not None:
        try:
            fmu.terminate()
        except Exception:  # noqa: BLE001 - an FMU already in error may refuse; free it anyway
            pass
        try:
            fmu.freeInstance()
        except Exception:  # noqa: BLE001
            pass
    _SINKS.pop(key, None)
    shutil.rmtree(unzip_dir, ignore_errors=True)


class FMUMooring:
    """A co-simulation FMU as a mooring system; satisfies ``cosim.protocol.Mooring``.

    Parameters
    ----------
    path:
        The ``.fmu`` file (FMI 2.0 co-simulation).
    lines_or_n:
        The :class:`~moorings.line.MooringLine` records the FMU models (they give
        the line names and the dimension), or the number of lines (then ``dim``
        is required and the lines are named ``line0``, ``line1``, ...).
    variable_map:
        The FMU variable names, see the module docstring.
    dim:
        2 (x, z) or 3 (x, y, z), when ``lines_or_n`` is a number.
    parameters:
        ``{name: value}`` set on the FMU before its initialisation (e.g. a line
        length [m]); each must be a Real parameter or input of the FMU.
    fairleads:
        Optional initial fairlead positions [m], ``(n_lines, dim)``.
    max_step:
        Largest coupling step [s] to report from :meth:`max_dt` (default
        unlimited: the FMU sub-steps itself, or is quasi-static).
    name:
        Participant name used in messages.
    """

    def __init__(self, path, lines_or_n, variable_map, *, dim: int | None = None, parameters=None,
                 fairleads=None, max_step: float = math.inf, name: str = "fmu_mooring"):
        import fmpy
        from fmpy.model_description import read_model_description

        self.name = name
        if isinstance(lines_or_n, (int, np.integer)) and not isinstance(lines_or_n, bool):
            if int(lines_or_n) < 1 or dim not in (2, 3):
                raise InputError(f"{name}: give n_lines >= 1 and dim = 2 or 3 (got {lines_or_n}, {dim})")
            self.lines = None
            self.line_names = [f"line{i}" for i in range(int(lines_or_n))]
            self.dim = int(dim)
        else:
            self.lines: list[MooringLine] | None = named_lines(lines_or_n)
            self.line_names = [ln.name for ln in self.lines]
            self.dim = self.lines[0].dim
            if dim is not None and dim != self.dim:
                raise InputError(f"{name}: dim = {dim} contradicts the lines' dimension {self.dim}")
        self.n_lines = len(self.line_names)
        if not (max_step > 0):
            raise InputError(f"{name}: max_step = {max_step!r} s must be > 0")
        self._max_step = float(max_step)
        self.path = Path(path)
        if not self.path.is_file():
            raise InputError(f"{name}: no FMU file {str(path)!r}")
        try:
            md = read_model_description(str(self.path), validate=False)
        except Exception as exc:  # noqa: BLE001 - fmpy raises plain Exceptions for broken archives
            raise InputError(f"{name}: {str(path)!r} is not a readable FMU: {exc}") from None
        if md.fmiVersion != "2.0" or md.coSimulation is None:
            raise InputError(f"{name}: {self.path.name} must be an FMI 2.0 co-simulation FMU "
                             f"(it is FMI {md.fmiVersion}{'' if md.coSimulation else ', model exchange only'})")
        self.model_description = md
        self._vars = {v.name: v for v in md.modelVariables}
        if not isinstance(variable_map, dict) or not {"positions", "forces"} <= set(variable_map):
            raise InputError(f"{name}: variable_map must be a dict with 'positions' and 'forces' "
                             f"(and optionally 'velocities'); got {variable_map!r}")
        unknown = set(variable_map) - {"positions", "forces", "velocities", "states"}
        if unknown:
            raise InputError(f"{name}: unknown variable_map key(s) {sorted(unknown)}")
        self._vr_pos = self._resolve(variable_map["positions"], "positions", ("input",))
        self._vr_force = self._resolve(variable_map["forces"], "forces", ("output",))
        self._vr_vel = (self._resolve(variable_map["velocities"], "velocities", ("input",))
                        if variable_map.get("velocities") is not None else None)
        self._vr_state = (self._resolve_states(variable_map["states"])
                          if variable_map.get("states") is not None else None)
        #: when each line became fully lifted or taut (:mod:`moorings.line_events`), after every
        #: step; None unless the variable map names the lines' ``states``
        self.state_log = LineStateLog(self.line_names) if self._vr_state is not None else None
        self._params = []
        for pname, value in (parameters or {}).items():
            v = self._vars.get(pname)
            if v is None or v.type != "Real" or v.causality not in ("parameter", "input"):
                raise InputError(f"{name}: parameters[{pname!r}] is not a Real parameter or input of {self.path.name}")
            try:
                val = float(value)
            except (TypeError, ValueError):
                raise InputError(f"{name}: parameters[{pname!r}] = {value!r} is not a number") from None
            self._params.append((v.valueReference, val))
        self.can_save_state = bool(md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate)
        self._pos = None
        self._vel = None
        if fairleads is not None:
            self._pos = self._check_array(fairleads, "fairlead positions")
        self.t = 0.0
        self._initialized = False
        self.messages: list[tuple[str, str]] = []  #: the FMU's recent log messages (status, text)

        # load and instantiate now: a broken binary or GUID shows up at construction
        from fmpy.fmi1 import calloc, free
        from fmpy.fmi2 import FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE
        from fmpy.fmi2 import fmi2CallbackFunctions

        label = f"{name} ({self.path.name})"
        key = next(_KEYS)
        _SINKS[key] = (self.messages, label)
        cb = fmi2CallbackFunctions()
        cb.logger = _arm()
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        cb.componentEnvironment = key  # routes this instance's messages to self.messages
        self._callbacks = cb
        unzip_dir = fmpy.extract(str(self.path))
        self._box = {"cb": cb}
        self._finalizer = weakref.finalize(self, _cleanup, self._box, unzip_dir, key)
        try:
            fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzip_dir, modelIdentifier=md.coSimulation.modelIdentifier,
                            instanceName=name)
            fmu.instantiate(callbacks=cb)
        except Exception as exc:  # noqa: BLE001
            self._finalizer()
            raise InputError(f"{label}: cannot load or instantiate the FMU: {exc}"
                             f"{self._log_tail()}") from None
        self._box["fmu"] = fmu
        self._fmu = fmu

    # -- helpers ---------------------------------------------------------------
    def _resolve(self, spec, key, causalities):
        if isinstance(spec, str):
            axes = ("x", "z") if self.dim == 2 else ("x", "y", "z")
            try:
                names = [[spec.format(line=ln, i=i, axis=a, k=k) for k, a in enumerate(axes)]
                         for i, ln in enumerate(self.line_names)]
            except (KeyError, IndexError, ValueError) as exc:
                raise InputError(f"{self.name}: variable_map[{key!r}] = {spec!r} is not a valid template "
                                 f"(fields: line, i, axis, k): {exc}") from None
        else:
            names = spec
        try:
            arr = np.asarray(names, dtype=object)
        except ValueError:
            arr = np.empty(0, dtype=object)
        if arr.shape != (self.n_lines, self.dim):
            raise InputError(f"{self.name}: variable_map[{key!r}] must name ({self.n_lines}, {self.dim}) "
                             f"variables (one row per line); got {names!r}")
        missing = [str(n) for n in arr.ravel() if n not in self._vars]
        if missing:
            raise InputError(f"{self.name}: {self.path.name} has no variable(s) {', '.join(missing[:6])}"
                             f"{' ...' if len(missing) > 6 else ''} (variable_map[{key!r}])")
        vrs = []
        for n in arr.ravel():
            v = self._vars[n]
            if v.type != "Real" or v.causality not in causalities:
                raise InputError(f"{self.name}: variable {n!r} of {self.path.name} is a {v.causality} "
                                 f"{v.type}; variable_map[{key!r}] needs Real {' or '.join(causalities)}s")
            vrs.append(v.valueReference)
        return vrs

    def _resolve_states(self, spec):
        names = ([spec.format(line=ln, i=i) for i, ln in enumerate(self.line_names)] if isinstance(spec, str)
                 else list(spec) if isinstance(spec, (list, tuple)) else None)
        if names is None or len(names) != self.n_lines:
            raise InputError(f"{self.name}: variable_map['states'] must name one Integer output per line "
                             f"({self.n_lines}), a list or a template with {{line}} or {{i}}; got {spec!r}")
        vrs = []
        for n in names:
            v = self._vars.get(n)
            if v is None or v.type != "Integer" or v.causality != "output":
                raise InputError(f"{self.name}: variable_map['states']: {n!r} is not an Integer output of "
                                 f"{self.path.name}")
            vrs.append(v.valueReference)
        return vrs

    def _check_array(self, values, what):
        return per_line(values, self.line_names, self.dim, self.name, what)

    def _log_tail(self) -> str:
        bad = [t for s, t in self.messages if s not in ("OK",)]
        return ("; the FMU says: " + " | ".join(bad[-3:])) if bad else ""

    def _call(self, what, fn, *args, **kwargs):
        from fmpy.fmi1 import FMICallException

        n0 = len(self.messages)
        _arm()
        try:
            return fn(*args, **kwargs)
        except FMICallException as exc:
            new = [t for s, t in self.messages[n0:] if s != "OK"] or [t for s, t in self.messages[-1:]]
            text = " | ".join(new) if new else "no message logged"
            cls = TautLineError if "taut" in text.lower() else SolverError
            raise cls(f"{self.name} ({self.path.name}) at t = {self.t:.6g} s: {what} failed "
                      f"({exc}); the FMU says: {text}") from None

    def _push_inputs(self):
        if self._pos is not None:
            self._call("setting the fairlead positions", self._fmu.setReal, self._vr_pos, self._pos.ravel().tolist())
        if self._vr_vel is not None and self._vel is not None:
            self._call("setting the fairlead velocities", self._fmu.setReal, self._vr_vel, self._vel.ravel().tolist())

    # -- participant protocol ------------------------------------------------
    def initialize(self, t0: float) -> None:
        """Set up the FMU's experiment at ``t0`` [s], apply ``parameters`` and the
        fairlead positions, and leave initialisation mode (where a bad parameter
        or an impossible initial geometry is reported)."""
        if self._pos is None:
            raise InputError(f"{self.name}: fairlead positions are not set; call set_fairlead_motion() "
                             f"or pass fairleads= before the run")
        if self._initialized:
            self._call("fmi2Terminate", self._fmu.terminate)
            self._call("fmi2Reset", self._fmu.reset)
        self.t = float(t0)
        self._call("fmi2SetupExperiment", self._fmu.setupExperiment, startTime=self.t)
        for vr, val in self._params:
            self._call("setting parameters", self._fmu.setReal, [vr], [val])
        self._call("fmi2EnterInitializationMode", self._fmu.enterInitializationMode)
        self._push_inputs()
        self._call("fmi2ExitInitializationMode", self._fmu.exitInitializationMode)
        self._initialized = True
        if self.state_log is not None and self.state_log.state is None:  # a resumed run keeps its log
            self.state_log.update(self.t, self.line_states())

    def max_dt(self) -> float:
        """``max_step`` [s] as given (default unlimited)."""
        return self._max_step

    def advance(self, t: float, dt: float) -> None:
        """``fmi2DoStep`` from ``t`` [s] (the coupler's exact time) over ``dt`` [s]."""
        self._require_init()
        self.t = float(t)
        self._call("fmi2DoStep", self._fmu.doStep, currentCommunicationPoint=self.t, communicationStepSize=float(dt))
        self.t = float(t) + float(dt)
        if self.state_log is not None:
            self.state_log.update(self.t, self.line_states())

    def save_state(self):
        """The FMU's serialised state, the fairlead motion and the time (needs an FMU
        that declares canGetAndSetFMUstate and canSerializeFMUstate)."""
        self._require_init()
        if not self.can_save_state:
            raise SolverError(f"{self.name}: {self.path.name} cannot get and serialise its state "
                              f"(canGetAndSetFMUstate/canSerializeFMUstate false); checkpoints are unavailable")
        st = self._call("fmi2GetFMUstate", self._fmu.getFMUstate)
        try:
            blob = self._call("fmi2SerializeFMUstate", self._fmu.serializeFMUstate, st)
        finally:
            self._fmu.freeFMUstate(st)
        return (blob, None if self._pos is None else self._pos.copy(),
                None if self._vel is None else self._vel.copy(), self.t,
                None if self.state_log is None else self.state_log.save())

    def load_state(self, state) -> None:
        self._require_init()
        blob, pos, vel, t, log_ = state
        if self.state_log is not None:
            self.state_log.load(log_)
        st = self._call("fmi2DeSerializeFMUstate", self._fmu.deSerializeFMUstate, blob)
        try:
            self._call("fmi2SetFMUstate", self._fmu.setFMUstate, st)
        finally:
            self._fmu.freeFMUstate(st)
        self._pos, self._vel, self.t = pos, vel, t

    # -- mooring interface ---------------------------------------------------
    def set_fairlead_motion(self, positions, velocities=None) -> None:
        """Fairlead positions [m] and (if the map has ``velocities``) velocities
        [m/s], ``(n_lines, dim)``, world frame; passed to the FMU at once."""
        pos = self._check_array(positions, "fairlead positions")
        vel = self._check_array(velocities, "fairlead velocities") if velocities is not None else None
        self._pos, self._vel = pos, vel
        if self._initialized:
            self._push_inputs()

    def fairlead_forces(self) -> np.ndarray:
        """Force [N] each line exerts on its fairlead, ``(n_lines, dim)``, world frame."""
        self._require_init()
        f = self._call("reading the fairlead forces", self._fmu.getReal, self._vr_force)
        return np.reshape(np.asarray(f, dtype=float), (self.n_lines, self.dim))

    def line_states(self) -> np.ndarray:
        """Each line's state now (:class:`~moorings.catenary.LineState` values), as the FMU's
        ``states`` outputs give it; raises where the variable map names none."""
        self._require_init()
        if self._vr_state is None:
            raise InputError(f"{self.name}: the variable map names no 'states' outputs; add them "
                             f"(catenary_fmu_variable_map does for an exported catenary FMU)")
        return np.asarray(self._call("reading the line states", self._fmu.getInteger, self._vr_state), np.int8)

    def fairlead_stiffness(self) -> FairleadStiffness:
        """The lines' tangent stiffness ``-dF/dx`` [N/m] at the fairleads now, by central
        differences through the FMU (inputs moved, outputs read, inputs restored; no
        ``fmi2DoStep``): right for an FMU with direct feedthrough (a quasi-static law such
        as the exported catenary); a dynamic FMU, whose outputs change only in a step,
        shows no stiffness this way and reports its own limit through ``max_step``."""
        self._require_init()
        pos0 = self._pos.copy()

        def forces_at(p):
            self._pos = p
            self._push_inputs()
            return self.fairlead_forces()

        try:
            s = by_differences(forces_at, pos0, 1e-6 * max(1.0, float(np.abs(pos0).max())))
        finally:
            self._pos = pos0
            self._push_inputs()
        return FairleadStiffness(np.nan_to_num(s.k, nan=0.0, posinf=0.0, neginf=0.0), s.c)

    def get(self, names) -> np.ndarray:
        """Any Real variables of the FMU by name (e.g. tensions), as an array."""
        self._require_init()
        missing = [n for n in names if n not in self._vars]
        if missing:
            raise InputError(f"{self.name}: {self.path.name} has no variable(s) {', '.join(missing)}")
        return np.asarray(self._call("reading variables", self._fmu.getReal,
                                     [self._vars[n].valueReference for n in names]), dtype=float)

    def close(self) -> None:
        """Free the FMU instance and its extracted files (also done at garbage collection)."""
        self._finalizer()
        self._initialized = False

    def _require_init(self):
        if "fmu" not in self._box:
            raise InputError(f"{self.name}: the FMU is closed")
        if not self._initialized:
            raise InputError(f"{self.name}: call initialize(t0) first")


__all__ = ["FMUMooring"]
