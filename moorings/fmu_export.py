"""Export a catenary mooring system as a standalone FMI 2.0 co-simulation FMU.

:func:`export_catenary_fmu` writes an FMU whose binary is the C port of
:mod:`moorings.catenary` (``moorings/fmu/catenary.c``, the same algorithm and
state decisions, tested equal to the Python law) behind the FMI 2.0
co-simulation interface (``moorings/fmu/fmi2_catenary.c``). It runs where no
Python exists: the binary depends on the C library and libm only.

Variables of the FMU, per line (``<line>`` its name made an identifier; axes x, z in 2-D,
x, y, z in 3-D): parameters ``anchor``, ``length``, ``weight``, ``EA`` (0: inextensible), the
input ``fairlead``, outputs ``force``, ``tension``, ``H``, ``V``, ``touchdown``, ``state``; and
the total ``force`` and ``moment`` about ``reference``: the table is in docs/moorings.md.

With ``body_pose=True`` the fairleads follow a rigid body instead: the inputs
are the body pose (3-D ``body.x``, ``body.y``, ``body.z`` [m] and a unit
quaternion ``body.qw``, ``body.qx``, ``body.qy``, ``body.qz`` [-], normalised
by the FMU; 2-D ``body.x``, ``body.z`` [m] and ``body.theta`` [rad] about +y),
the body-frame fairleads are parameters ``<line>.fairlead_body.<axis>`` [m],
``<line>.fairlead.<axis>`` become outputs (world frame) and ``reference.<axis>``
is given in the body frame.

The outputs are a pure function of the parameters and inputs (direct
feedthrough, valid as soon as the inputs are set); ``fmi2DoStep`` only moves
the clock. The FMU declares ``canGetAndSetFMUstate`` and
``canSerializeFMUstate`` (its state is its variable values and time). A taut
inextensible line, a NaN input or a fairlead below the seabed is reported
through the FMI logger and an ``fmi2Error`` status.

The archive holds ``modelDescription.xml``, ``sources/`` (the C files, the
generated ``model_config.h``, the standard FMI 2.0 headers and
``buildDescription.xml`` as in FMI 2.0.4) and ``binaries/linux64/<id>.so``,
compiled at export time with the system C compiler.
"""

from __future__ import annotations

import datetime
import logging
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import uuid
import zipfile
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from errors import InputError
from moorings.line import named_lines

log = logging.getLogger(__name__)

C_DIR = Path(__file__).resolve().parent / "fmu"
C_SOURCES = ("catenary.c", "fmi2_catenary.c")
C_HEADERS = ("catenary.h",)
FMI_HEADERS = ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h")
#: flags that keep every floating-point operation as in the Python law (no fast-math, no FMA contraction)
CFLAGS = ("-std=c99", "-O2", "-ffp-contract=off", "-fPIC", "-fvisibility=hidden")
STATE_NAMES = ("RESTING", "PARTLY_LIFTED", "FULLY_LIFTED", "TAUT")


def _axes(dim: int) -> tuple[str, ...]:
    return ("x", "z") if dim == 2 else ("x", "y", "z")


def fmu_line_names(lines) -> list[str]:
    """The identifiers the FMU uses for the lines: each line's name with every
    character other than a letter, digit or ``_`` replaced by ``_`` (``line<i>``
    for all lines if that would make two alike or one start with a digit)."""
    names = [re.sub(r"\W", "_", ln.name, flags=re.ASCII) for ln in named_lines(lines)]
    if len(set(names)) != len(names) or any(not n or n[0].isdigit() for n in names):
        names = [f"line{i}" for i in range(len(names))]
    return names


def catenary_fmu_variable_map(lines) -> dict[str, list[list[str]]]:
    """The ``variable_map`` with which :class:`moorings.fmu_mooring.FMUMooring`
    drives an FMU written by :func:`export_catenary_fmu` from the same lines:
    ``{"positions": [[<line>.fairlead.<axis>, ...], ...], "forces": [[<line>.force.<axis>, ...], ...],
    "states": [<line>.state, ...]}``."""
    lines = named_lines(lines)
    ax = _axes(lines[0].dim)
    names = fmu_line_names(lines)
    out = {key: [[f"{n}.{var}.{a}" for a in ax] for n in names]
           for key, var in (("positions", "fairlead"), ("forces", "force"))}
    out["states"] = [f"{n}.state" for n in names]
    return out


class _Var:
    __slots__ = ("name", "vr", "type", "causality", "variability", "initial", "start", "unit", "description")

    def __init__(self, name, vr, causality, unit, description, start=None, type_="Real"):
        self.name, self.vr, self.causality, self.unit, self.description = name, vr, causality, unit, description
        self.start, self.type = start, type_
        if causality == "parameter":
            self.variability, self.initial = "tunable", "exact"
        elif causality == "input":
            self.variability, self.initial = "continuous", None
        else:
            self.variability = "continuous" if type_ == "Real" else "discrete"
            self.initial = "calculated"


def _pose_names(dim):
    return ("body.x", "body.y", "body.z", "body.qw", "body.qx", "body.qy", "body.qz") if dim == 3 else \
        ("body.x", "body.z", "body.theta")


def _layout(names, dim, starts, body_pose=False):
    """The variables in value-reference order, matching fmi2_catenary.c's layout.

    ``starts`` holds, per line, (anchor, length, weight, EA or 0, fairlead) and
    the reference point under key ``"reference"`` (and the pose under ``"pose"``).
    With ``body_pose`` the fairleads are outputs placed by the body pose (inputs)
    from body-frame parameters, and the reference point is in the body frame."""
    ax = _axes(dim)
    v = []
    vr = 0
    frame = "body frame" if body_pose else "world frame"
    for k, a in enumerate(ax):
        v.append(_Var(f"reference.{a}", vr, "parameter", "m",
                      f"reference point of the total moment, {a}, {frame} [m]", starts["reference"][k]))
        vr += 1
    for i, n in enumerate(names):
        anchor, L, w, EA, fair = starts["lines"][i]
        for k, a in enumerate(ax):
            seabed = " (the seabed height: the seabed is the horizontal plane through the anchor)" if k == dim - 1 else ""
            v.append(_Var(f"{n}.anchor.{a}", vr, "parameter", "m", f"anchor {a} of line {n} [m]{seabed}", anchor[k]))
            vr += 1
        v.append(_Var(f"{n}.length", vr, "parameter", "m", f"unstretched length of line {n} [m]", L))
        v.append(_Var(f"{n}.weight", vr + 1, "parameter", "N/m", f"submerged weight per unit length of line {n} [N/m]", w))
        v.append(_Var(f"{n}.EA", vr + 2, "parameter", "N", f"axial stiffness of line {n} [N]; 0 = inextensible", EA))
        vr += 3
        for k, a in enumerate(ax):
            if body_pose:
                v.append(_Var(f"{n}.fairlead.{a}", vr, "output", "m", f"fairlead {a} of line {n}, world frame [m]"))
            else:
                v.append(_Var(f"{n}.fairlead.{a}", vr, "input", "m", f"fairlead {a} of line {n}, world frame [m]",
                              fair[k]))
            vr += 1
        for k, a in enumerate(ax):
            v.append(_Var(f"{n}.force.{a}", vr, "output", "N", f"force of line {n} on its fairlead, {a}, world frame [N]"))
            vr += 1
        for key, unit, what in (("tension", "N", "fairlead tension sqrt(H^2 + V^2)"),
                                ("H", "N", "horizontal tension at the fairlead"),
                                ("V", "N", "vertical tension at the fairlead"),
                                ("touchdown", "m", "unstretched length lying on the seabed")):
            v.append(_Var(f"{n}.{key}", vr, "output", unit, f"{what} of line {n} [{unit}]"))
            vr += 1
    for k, a in enumerate(ax):
        v.append(_Var(f"force.{a}", vr, "output", "N", f"total force of the lines, {a}, world frame [N]"))
        vr += 1
    for a in (ax if dim == 3 else ("y",)):
        v.append(_Var(f"moment.{a}", vr, "output", "N.m", f"total moment of the lines about the reference point, {a} [N m]"))
        vr += 1
    if body_pose:
        for i, n in enumerate(names):
            for k, a in enumerate(ax):
                v.append(_Var(f"{n}.fairlead_body.{a}", vr, "parameter", "m",
                              f"fairlead {a} of line {n} in the body frame [m]", starts["lines"][i][4][k]))
                vr += 1
        units = ("m", "m", "m", None, None, None, None) if dim == 3 else ("m", "m", "rad")
        what = ("position x", "position y", "position z", "orientation quaternion w (normalised by the FMU)",
                "orientation quaternion x", "orientation quaternion y", "orientation quaternion z") if dim == 3 else \
            ("position x", "position z", "pitch angle about +y (x' = x cos + z sin)")
        for pname, unit, desc, start in zip(_pose_names(dim), units, what, starts["pose"]):
            v.append(_Var(pname, vr, "input", unit, f"body {desc}" + (f" [{unit}]" if unit else " [-]"), start))
            vr += 1
    n_real = vr
    for i, n in enumerate(names):
        v.append(_Var(f"{n}.state", n_real + i, "output", None,
                      f"state of line {n}: 0 resting, 1 partly lifted, 2 fully lifted, 3 taut, "
                      f"-1 invalid input (reported as an error)", type_="Integer"))
    return v, n_real


def _fmt(x: float) -> str:
    return repr(float(x))


def _model_description(model_identifier, guid, description, variables, names, dim):
    units = {"m": 'm="1"', "N": 'kg="1" m="1" s="-2"', "N/m": 'kg="1" s="-2"', "N.m": 'kg="1" m="2" s="-2"',
             "rad": 'rad="1"'}
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<fmiModelDescription fmiVersion="2.0" modelName={quoteattr(model_identifier)} guid="{guid}"',
        f'  description={quoteattr(description)}',
        '  generationTool="cosim-sph moorings.fmu_export"',
        f'  generationDateAndTime="{datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")}"',
        '  variableNamingConvention="structured" numberOfEventIndicators="0">',
        f'  <CoSimulation modelIdentifier={quoteattr(model_identifier)} needsExecutionTool="false"',
        '    canHandleVariableCommunicationStepSize="true" canInterpolateInputs="false"',
        '    maxOutputDerivativeOrder="0" canRunAsynchronuously="false"',
        '    canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="false"',
        '    canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="false">',
        '    <SourceFiles>',
        *[f'      <File name="{s}"/>' for s in C_SOURCES],
        '    </SourceFiles>',
        '  </CoSimulation>',
        '  <UnitDefinitions>',
        *[f'    <Unit name="{u}"><BaseUnit {b}/></Unit>' for u, b in units.items()],
        '  </UnitDefinitions>',
        '  <LogCategories>',
        '    <Category name="logStatusError" description="errors: invalid parameters or inputs, taut inextensible lines"/>',
        '    <Category name="logStatusWarning" description="warnings"/>',
        '  </LogCategories>',
        '  <DefaultExperiment startTime="0" stopTime="1" stepSize="0.01"/>',
        '  <ModelVariables>',
    ]
    index = {}
    for i, v in enumerate(variables, start=1):
        index[v.name] = i
        attrs = [f'name="{v.name}"', f'valueReference="{v.vr}"', f"description={quoteattr(v.description)}",
                 f'causality="{v.causality}"', f'variability="{v.variability}"']
        if v.initial:
            attrs.append(f'initial="{v.initial}"')
        inner = []
        if v.unit:
            inner.append(f'unit="{v.unit}"')
        if v.start is not None:
            inner.append(f'start="{_fmt(v.start)}"')
        out.append(f'    <ScalarVariable {" ".join(attrs)}><{v.type} {" ".join(inner)}/></ScalarVariable>'
                   .replace(" />", "/>"))
    out.append("  </ModelVariables>")
    ax = _axes(dim)
    inputs = [v for v in variables if v.causality == "input"]
    all_inputs = " ".join(str(index[v.name]) for v in inputs)
    if any(v.name.startswith("body.") for v in inputs):  # body pose: every output depends on the whole pose
        inputs_of = {n: all_inputs for n in names}
    else:
        inputs_of = {n: " ".join(str(index[f"{n}.fairlead.{a}"]) for a in ax) for n in names}
    outs = [v for v in variables if v.causality == "output"]
    out.append("  <ModelStructure>")
    out.append("    <Outputs>")
    for v in outs:
        line = v.name.split(".")[0]
        deps = inputs_of.get(line, all_inputs)
        kinds = " ".join("dependent" for _ in deps.split())
        out.append(f'      <Unknown index="{index[v.name]}" dependencies="{deps}" dependenciesKind="{kinds}"/>')
    out.append("    </Outputs>")
    out.append("    <InitialUnknowns>")
    for v in outs:
        out.append(f'      <Unknown index="{index[v.name]}"/>')
    out.append("    </InitialUnknowns>")
    out.append("  </ModelStructure>")
    out.append("</fmiModelDescription>")
    return "\n".join(out) + "\n"


def _config_header(model_identifier, guid, n, dim, n_real, starts, names, body_pose=False):
    vals = ",\n    ".join(_fmt(x) for x in starts)
    cnames = ", ".join('"' + s + '"' for s in names)
    return (
        f"/* Generated by moorings.fmu_export for {model_identifier}: the size of the system and its start values. */\n"
        "#ifndef MODEL_CONFIG_H\n#define MODEL_CONFIG_H\n"
        f'#define MODEL_IDENTIFIER "{model_identifier}"\n'
        f'#define MODEL_GUID "{guid}"\n'
        f"#define N_LINES {n}\n#define DIM {dim}\n#define N_REAL {n_real}\n#define BODY_POSE {int(body_pose)}\n"
        f"static const double START_VALUES[N_REAL] = {{\n    {vals}\n}};\n"
        f"static const char *const LINE_NAMES[N_LINES] = {{{cnames}}};\n"
        "#endif\n"
    )


def _build_description(model_identifier):
    files = "\n".join(f'        <SourceFile name="{s}"/>' for s in C_SOURCES)
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<!-- FMI 2.0.4 sources/buildDescription.xml (the FMI 3.0 build description schema) -->\n'
        '<fmiBuildDescription fmiVersion="3.0">\n'
        f'  <BuildConfiguration modelIdentifier="{model_identifier}" description="C99, link with libm (-lm)">\n'
        '    <SourceFileSet language="C99" compilerOptions="-ffp-contract=off">\n'
        f"{files}\n"
        '      <IncludeDirectory name="."/>\n'
        "    </SourceFileSet>\n"
        '    <Library name="m" description="the C maths library (libm)"/>\n'
        "  </BuildConfiguration>\n"
        "</fmiBuildDescription>\n"
    )


def _platform() -> tuple[str, str]:
    """(FMI platform folder, shared-library suffix) of this machine."""
    machine = platform.machine().lower()
    if sys.platform.startswith("linux") and machine in ("x86_64", "amd64"):
        return "linux64", ".so"
    if sys.platform == "darwin":
        return "darwin64", ".dylib"
    if sys.platform.startswith("linux") and machine in ("i386", "i686"):
        return "linux32", ".so"
    raise InputError(
        f"export_catenary_fmu: no FMI 2.0 platform name for {sys.platform}/{platform.machine()}; "
        f"export with compile_binary=False to ship the sources only"
    )


def find_compiler(cc: str | None = None) -> str:
    """The C compiler to use: ``cc`` if given, else ``$CC``, ``cc``, ``gcc`` or ``clang`` from PATH."""
    candidates = [cc] if cc else [os.environ.get("CC"), "cc", "gcc", "clang"]
    for c in candidates:
        if c and shutil.which(c):
            return shutil.which(c)
    raise InputError(
        f"export_catenary_fmu: no C compiler found (tried {', '.join(c for c in candidates if c)}); "
        f"install one (e.g. apt-get install gcc), pass cc=..., or export with compile_binary=False"
    )


def _fairlead_starts(lines, fairleads):
    n, dim = len(lines), lines[0].dim
    if fairleads is None:  # straight above each anchor at half its length: a resting line
        return np.array([np.add(ln.anchor, np.eye(dim)[-1] * 0.5 * ln.length) for ln in lines])
    try:
        f = np.asarray(fairleads, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"export_catenary_fmu: fairleads must be numbers of shape ({n}, {dim}) [m]") from None
    if f.shape != (n, dim) or not np.all(np.isfinite(f)):
        raise InputError(f"export_catenary_fmu: fairleads must be finite, of shape ({n}, {dim}) [m]; got {f.shape}")
    return f


def export_catenary_fmu(
    lines,
    path,
    *,
    fairleads=None,
    reference_point=None,
    body_pose: bool = False,
    pose=None,
    model_identifier: str = "catenary_mooring",
    description: str | None = None,
    compile_binary: bool = True,
    cc: str | None = None,
) -> Path:
    """Write an FMI 2.0 co-simulation FMU of a catenary mooring system.

    Parameters
    ----------
    lines:
        The :class:`~moorings.line.MooringLine` records (all 2-D or all 3-D);
        they give the parameters' start values (``EA=None`` becomes 0:
        inextensible). The FMU's variables: the module docstring, docs/moorings.md.
    path:
        The ``.fmu`` file to write (its folder must exist).
    fairleads:
        Start values of the fairlead inputs [m], ``(n_lines, dim)``, world frame;
        default: each fairlead straight above its anchor at half the line's
        length (a resting line). With ``body_pose``: the fairleads in the body
        frame (required), parameters ``<line>.fairlead_body.<axis>``.
    reference_point:
        Start value of the point about which the total moment is taken [m] (``dim``
        values, world frame; body frame with ``body_pose``); default the origin.
    body_pose:
        Make the body pose the input instead of the fairlead positions: 3-D
        ``body.x, body.y, body.z`` [m] and a unit quaternion ``body.qw, body.qx,
        body.qy, body.qz`` [-]; 2-D ``body.x, body.z`` [m] and ``body.theta``
        [rad] about +y. The fairleads (world frame) become outputs.
    pose:
        Start value of the pose with ``body_pose`` (the values above in that
        order); default the identity at the origin.
    model_identifier:
        The FMU's model identifier (a C identifier; names the binary).
    description:
        The model description's text; default a summary of the lines.
    compile_binary:
        Compile ``binaries/<platform>/<id>.so`` now (default). ``False`` ships the
        sources only, for a tool that builds FMUs from sources.
    cc:
        The C compiler; default ``$CC``, then ``cc``, ``gcc``, ``clang``.

    Returns the path written. Raises :class:`~cosim.errors.InputError` for bad
    arguments or when no C compiler is found (both before anything is written),
    :class:`~cosim.errors.SolverError` if the compilation fails.
    """
    from errors import SolverError

    lines = named_lines(lines)
    n, dim = len(lines), lines[0].dim
    path = Path(path)
    if path.suffix != ".fmu":
        raise InputError(f"export_catenary_fmu: the path must end in .fmu, got {str(path)!r}")
    if not path.parent.is_dir():
        raise InputError(f"export_catenary_fmu: folder {str(path.parent)!r} does not exist")
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", model_identifier or ""):
        raise InputError(f"export_catenary_fmu: model_identifier {model_identifier!r} must be a C identifier")
    if body_pose and fairleads is None:
        raise InputError("export_catenary_fmu: body_pose=True needs fairleads= (body-frame fairlead coordinates [m])")
    if pose is not None and not body_pose:
        raise InputError("export_catenary_fmu: pose= is the start pose of body_pose=True; set body_pose=True")
    n_pose = 7 if dim == 3 else 3
    pose0 = np.array([0, 0, 0, 1, 0, 0, 0] if dim == 3 else [0, 0, 0], dtype=float) if pose is None else \
        np.asarray(pose, dtype=float)
    if pose0.shape != (n_pose,) or not np.all(np.isfinite(pose0)):
        raise InputError(f"export_catenary_fmu: pose must be {n_pose} finite numbers "
                         f"({', '.join(_pose_names(dim))}); got {pose!r}")
    if dim == 3 and not np.linalg.norm(pose0[3:]) > 0:
        raise InputError("export_catenary_fmu: the pose quaternion (qw, qx, qy, qz) must not be zero")
    fair = _fairlead_starts(lines, fairleads)
    ref = np.zeros(dim) if reference_point is None else np.asarray(reference_point, dtype=float)
    if ref.shape != (dim,) or not np.all(np.isfinite(ref)):
        raise InputError(f"export_catenary_fmu: reference_point must be {dim} finite numbers [m]")
    compiler = find_compiler(cc) if compile_binary else None
    plat, suffix = _platform() if compile_binary else (None, None)
    fmi_headers = Path(__import__("fmpy").__file__).parent / "c-code"
    missing = [h for h in FMI_HEADERS if not (fmi_headers / h).is_file()]
    if missing:
        raise InputError(f"export_catenary_fmu: the FMI 2.0 headers {missing} are missing from {fmi_headers}")

    names = fmu_line_names(lines)
    starts = {
        "reference": ref,
        "pose": pose0,
        "lines": [(ln.anchor, ln.length, ln.weight, 0.0 if ln.inextensible else ln.EA, fair[i])
                  for i, ln in enumerate(lines)],
    }
    variables, n_real = _layout(names, dim, starts, body_pose)
    real_starts = [0.0 if v.start is None else v.start for v in variables if v.type == "Real"]
    if description is None:
        description = (f"Quasi-static catenary mooring system of {n} line(s) ({', '.join(names)}) in "
                       f"{'3-D (x, y, z)' if dim == 3 else '2-D (x, z)'}"
                       f"{', fairleads on a body whose pose is the input' if body_pose else ''}; "
                       f"moorings.catenary exported as C")
    # the GUID is a hash of everything that defines the model, so the same export gives the same GUID
    guid = "{" + str(uuid.uuid5(uuid.NAMESPACE_URL, repr((model_identifier, dim, bool(body_pose), names, real_starts,
                                                          (C_DIR / "fmi2_catenary.c").read_bytes(),
                                                          (C_DIR / "catenary.c").read_bytes())))) + "}"
    md = _model_description(model_identifier, guid, description, variables, names, dim)

    with tempfile.TemporaryDirectory(prefix="cosim_fmu_") as tmp:
        root = Path(tmp)
        src = root / "sources"
        src.mkdir()
        (root / "modelDescription.xml").write_text(md)
        for f in C_SOURCES + C_HEADERS:
            shutil.copyfile(C_DIR / f, src / f)
        for f in FMI_HEADERS:
            shutil.copyfile(fmi_headers / f, src / f)
        (src / "model_config.h").write_text(_config_header(model_identifier, guid, n, dim, n_real, real_starts, names,
                                                                     body_pose))
        (src / "buildDescription.xml").write_text(_build_description(model_identifier))
        if compile_binary:
            bdir = root / "binaries" / plat
            bdir.mkdir(parents=True)
            lib = bdir / (model_identifier + suffix)
            cmd = [compiler, *CFLAGS, "-shared", "-I", str(src), *(str(src / s) for s in C_SOURCES), "-o", str(lib), "-lm"]
            log.info("compiling %s: %s", model_identifier, " ".join(cmd))
            res = subprocess.run(cmd, capture_output=True, text=True)
            if res.returncode != 0:
                raise SolverError(f"export_catenary_fmu: compiling the FMU binary failed ({' '.join(cmd)}):\n"
                                  f"{res.stderr.strip()}")
        tmp_fmu = path.with_name(path.name + ".part")
        with zipfile.ZipFile(tmp_fmu, "w", zipfile.ZIP_DEFLATED) as zf:
            for f in sorted(root.rglob("*")):
                if f.is_file():
                    zf.write(f, f.relative_to(root).as_posix())
        os.replace(tmp_fmu, path)
    log.info("wrote %s (%d lines, %d-D, %d bytes)", path, n, dim, path.stat().st_size)
    return path


__all__ = ["catenary_fmu_variable_map", "export_catenary_fmu", "find_compiler", "fmu_line_names"]
