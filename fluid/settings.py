"""The SPH fluid's settings, each declared once: its name, default, unit, accepted range or
choices, what it is, and what the scene does with it.

:data:`SETTINGS` is the one table. ``fluid.solver.FluidConfig`` takes one field per entry
from it (:func:`declare`: the field's default) and refuses a value outside an entry's range
or choices (:func:`check`) before any work is done; the checks between fields (c0 or u_max,
gravity's components, the domain's corners, the symmetry plane) stay in its own code. The
scene's ``SPH`` fluid (``cosim.scene``) takes the entries whose ``scene`` role is set as its
own fields, with the same doc, unit and range, and its set-up chooser passes them on; a new
option of the fluid is therefore one entry here (and the code that uses it).

This module imports nothing of the solver (no numba): the scene reads it without
compiling the fluid.
"""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass

from errors import InputError

#: kernel names (their ids inside the numba loops: ``fluid.kernels.KERNELS``)
KERNELS = ("wendland", "cubic")
#: density diffusion terms (``fluid.equations``)
DIFFUSION = ("fourtakas", "antuono", "molteni", "none")
#: arithmetic of the pair loop (``fluid.equations.interact``)
PRECISION = ("float64", "float32")
#: tank-wall density treatments (``fluid.wall_density``)
WALLS = ("dbc", "adami")
#: particle shifting (``fluid.shifting``)
SHIFTING = ("none", "fickian")

#: what a scene does with a setting (:attr:`Setting.scene`): "": not a field of the scene's
#: (the scene sets it from elsewhere, or never); "set-up": the scene's field is
#: unset by default and then takes the set-up's value (``cosim.scene.setup``), then this
#: table's default; "default": the scene's field has this table's default; "required": the
#: scene must give it
SCENE_ROLES = ("", "set-up", "default", "required")


@dataclass(frozen=True)
class Setting:
    """One setting of the SPH fluid. ``kind``: float (a finite number; ``finite=False``
    also takes +-inf where the range allows it), int (a whole number, not a bool), bool,
    str, or object (checked by ``FluidConfig``'s own code); ``lo`` / ``hi`` bound a number
    (``lo_open`` / ``hi_open``: the bound itself refused); ``choices`` list the values
    accepted; ``optional``: None is accepted too (what None means, ``doc`` says). ``doc``
    says what it is in a phrase (the scene's reference and error messages read it),
    ``hint`` the usual values (said when a value is refused), ``note`` why and the
    reference. ``scene``: one of :data:`SCENE_ROLES`."""

    name: str
    default: object
    doc: str
    unit: str = ""
    kind: type = float
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    hi_open: bool = False
    choices: tuple = ()
    optional: bool = False
    finite: bool = True
    hint: str = ""
    note: str = ""
    scene: str = ""

    def __post_init__(self):
        if self.scene not in SCENE_ROLES:
            raise ValueError(f"setting {self.name}: scene={self.scene!r}, not one of {SCENE_ROLES}")
        if self.default is None and not self.optional:
            raise ValueError(f"setting {self.name}: a default of None needs optional=True")
        if self.kind is not object and self.default is not None and self.problem(self.default):
            raise ValueError(f"setting {self.name}: its default {self.default!r} is outside its own range")

    @property
    def annotation(self) -> str:
        """The field's type as a dataclass annotation."""
        return self.kind.__name__ + (" | None" if self.optional else "")

    def expected(self) -> str:
        """What is accepted, in words: ``a number [m] > 0 (particle spacing)``."""
        unit = f" [{self.unit}]" if self.unit else ""
        if self.choices:
            what = "one of " + ", ".join(repr(c) for c in self.choices)
        elif self.kind is bool:
            what = "True or False"
        elif self.kind in (float, int):
            rng = []
            if self.lo is not None:
                rng.append(f"{'>' if self.lo_open else '>='} {self.lo:g}")
            if self.hi is not None:
                rng.append(f"{'<' if self.hi_open else '<='} {self.hi:g}")
            what = f"{'a number' if self.kind is float else 'a whole number'}{unit}"
            what += " " + " and ".join(rng) if rng else ""
        else:
            what = "a text" if self.kind is str else "a value"
        return f"{what}{' or None' if self.optional else ''} ({self.doc})"

    def problem(self, v) -> str | None:
        """Why ``v`` is refused (None: accepted). A ``kind=object`` setting accepts anything
        here: its owner checks it."""
        if v is None and self.optional or self.kind is object:
            return None
        if self.kind is bool:
            ok = isinstance(v, bool)
        elif self.kind is str:
            ok = isinstance(v, str)
        elif self.kind is int:
            ok = isinstance(v, int) and not isinstance(v, bool)
        else:
            ok = (isinstance(v, (int, float)) and not isinstance(v, bool)
                  and (math.isfinite(v) if self.finite else not math.isnan(v)))
        if ok and self.choices:
            ok = v in self.choices
        elif ok and self.kind in (float, int):
            ok = ((self.lo is None or v > self.lo or (v == self.lo and not self.lo_open))
                  and (self.hi is None or v < self.hi or (v == self.hi and not self.hi_open)))
        if ok:
            return None
        unit = f" {self.unit}" if self.unit else ""
        return f"{self.name}={v!r}{unit}; give {self.expected()}" + (f"; {self.hint}" if self.hint else "")


#: every setting of the SPH fluid, in the order of FluidConfig's fields
SETTINGS: tuple[Setting, ...] = (
    Setting("dim", 2, "dimensions: 2 runs in the x-z plane, 3 in space", kind=int, choices=(2, 3)),
    Setting("dx", 0.01, "particle spacing", "m", lo=0, lo_open=True, scene="required"),
    Setting("rho0", 1000.0, "reference density", "kg/m^3", lo=0, lo_open=True, hint="1000 for water",
            scene="default"),
    Setting("h_coef", math.sqrt(2.0), "smoothing length / dx", lo=1, hi=3, hint="1.2 ... 2 is usual",
            note="h = h_coef dx; sqrt(2) is DualSPHysics' 2-D default (coefh = 1)", scene="set-up"),
    Setting("kernel", "wendland", "SPH kernel: Wendland C2 or the cubic spline", kind=str, choices=KERNELS,
            scene="set-up"),
    Setting("c0", None, "speed of sound; unset: c0_factor * u_max", "m/s", lo=0, lo_open=True, optional=True,
            scene="set-up"),
    Setting("u_max", None, "expected largest flow speed; sets c0 = c0_factor * u_max where c0 is unset; a scene "
            "estimates it", "m/s", lo=0, lo_open=True, optional=True,
            hint="e.g. sqrt(2 g H) for a column of height H falling", scene="set-up"),
    Setting("c0_factor", 10.0, "c0 / u_max", lo=10,
            hint="at least 10 keeps the density within 1 % of rho0 (Barreiro et al. 2016, §2.5; Monaghan 1994)",
            scene="set-up"),
    Setting("gamma", 7.0, "polytropic exponent of Tait's equation of state", lo=1, hint="7 for water",
            note="Barreiro et al. 2016, Eq. 8"),
    Setting("alpha", 0.01, "artificial viscosity", lo=0, hi=1, hint="0.01 ... 0.1 is usual",
            note="Sunara et al. 2021, Eq. 6; 0.01 as in Wang et al. 2022", scene="set-up"),
    Setting("alpha_wall", 1.0, "factor on alpha between fluid and walls; 1: as in the fluid, 0: slip walls",
            lo=0, hi=1, note="DualSPHysics' ViscoBoundFactor (fluid.equations); 0: waves over a bed lose no energy "
            "to the wall's artificial friction", scene="set-up"),
    Setting("nu", 0.0, "kinematic viscosity of the laminar term, added to the artificial one; 0: off", "m^2/s",
            lo=0, hint="1e-6 for water", note="Lo & Shao 2002 (fluid.equations)", scene="set-up"),
    Setting("xsph_eps", 0.0, "XSPH coefficient; 0: off", lo=0, hi=1, hint="0.1 is usual",
            note="Monaghan 1989; Wang et al. 2022 uses 0.1: particles move with the velocity smoothed over their "
            "neighbours", scene="set-up"),
    Setting("shifting", "none", "particle shifting: none, or fickian (fluid particles moved down their "
            "concentration gradient each step; along the free surface only near it, not within 2h of a wall)",
            kind=str, choices=SHIFTING, note="Lind et al. 2012 with Skillen et al. 2013's coefficient; the free "
            "surface found from the renormalisation matrix (fluid.shifting); cpu only. Measured in the wave flume, it "
            "adds to a wave's decay (docs/validation/wave-propagation_history.md)", scene="set-up"),
    Setting("shifting_coef", 2.0, "Fickian shifting's A in D = A h |v| dt", lo=0, hi=6, lo_open=True,
            hint="1 ... 6 (Skillen et al. 2013); 2 as DualSPHysics", note="Skillen et al. 2013, Eq. 13",
            scene="set-up"),
    Setting("diffusion", "fourtakas", "density diffusion term", kind=str, choices=DIFFUSION,
            note="antuono: renormalised, exact for linear fields, a second pair loop (fluid.equations)",
            scene="set-up"),
    Setting("delta", 0.1, "density diffusion coefficient", lo=0, hi=1, hint="0.1 is usual",
            note="Dinçer & Demir 2020, Eq. 1 uses 0.1", scene="set-up"),
    Setting("diffusion_at_surface", True, "false: fade the density diffusion out under the free surface", kind=bool,
            note="faded where a particle's support is cut by the free surface (the surface row and the one below "
            "it): keeps a 3-D tank of still water at rest, raises the pressure noise of violent flows "
            "(fluid.equations)", scene="set-up"),
    Setting("g", 9.81, "gravitational acceleration: a number >= 0 acting along -z, or the vector (dim components: "
            "(gx, gz) in 2-D, (gx, gy, gz) in 3-D) in any direction", "m/s^2", kind=object),
    Setting("cfl", 0.2, "CFL factor of the variable time step", lo=0, hi=0.4, lo_open=True,
            hint="the stable range of this scheme; 0.2 is the default", note="Sunara et al. 2021, Eq. 14",
            scene="set-up"),
    Setting("integrator", "symplectic", "time integration: symplectic, predictor-corrector with 2 pair loops per "
            "step; verlet, 1 pair loop per step", kind=str, choices=("symplectic", "verlet"),
            note="fluid.integrator", scene="set-up"),
    Setting("verlet_reset", 40, "Verlet: steps between forward-Euler steps", kind=int, lo=1,
            hint="DualSPHysics uses 40", note="fewer lets the density diffusion take longer steps (fluid.integrator)",
            scene="set-up"),
    Setting("dt_max", math.inf, "upper bound of the fluid step; inf: none", "s", lo=0, lo_open=True, finite=False),
    Setting("domain_lo", None, "the domain box's lower corner; particles leaving the box are removed and counted "
            "(unset: the box of the initial particles grown by max(10 % of its size, 4 h) on every side)", "m",
            kind=object, optional=True),
    Setting("domain_hi", None, "the domain box's upper corner (with domain_lo)", "m", kind=object, optional=True),
    Setting("threads", None, "numba threads; unset: by particle count", kind=int, lo=1, optional=True,
            note="unset: one thread below parallel_min_particles particles (where waking threads costs more than "
            "it gains, and much more on a busy machine), all of numba's threads above", scene="set-up"),
    Setting("parallel_min_particles", 20000, "particle count from which unset threads means all threads", kind=int,
            lo=0),
    Setting("mls_every", 0, "steps between MLS density re-initialisations (0: never)", kind=int, lo=0,
            hint="30 in Sunara et al. 2021, §2", note="Sunara et al. 2021, Eq. 9-12 (fluid.mls)", scene="set-up"),
    Setting("walls", "dbc", "tank-wall densities: dbc, dynamic boundaries; adami, the fluid's pressure",
            kind=str, choices=WALLS,
            note="the FIXED_WALL and MOVING_WALL particles' density: dbc, the continuity equation (Barreiro et al. "
            "2016, §2.6); adami, the fluid's pressure carried to each wall particle (Adami, Hu & Adams 2012, "
            "J. Comput. Phys. 231, Eq. 27; fluid.wall_density). BODY particles are not affected", scene="set-up"),
    Setting("wall_loads", True, "the fluid's load on the tank walls is computed (their group loads, wall-pressure "
            "patches); false: those read NaN, as do their rows of boundary_forces_now (the bodies' rows are "
            "computed either way)", kind=bool,
            note="false: the pair loop gives the FIXED_WALL and MOVING_WALL particles their continuity rate and "
            "their viscous terms' bound on the step only, not their accelerations; the fluid's rates and step are "
            "those of the full pass (to round-off) and it costs less (docs/benchmarks/"
            "fluid_throughput_history.md). Scenes set it from their probes (cosim.scene.build.fluid_config)"),
    Setting("device", "cpu", "where the fluid steps: cpu, or cuda (an NVIDIA GPU with numba-cuda; see fluid.cuda)",
            kind=str, choices=("cpu", "cuda"), hint="cuda needs numba-cuda: pip install numba-cuda",
            note="numba's CUDA simulator with NUMBA_ENABLE_CUDASIM=1 runs the cuda path on the CPU",
            scene="set-up"),
    Setting("precision", "float64", "arithmetic of the pair terms: float64 (the reference), or float32 summed in "
            "float64 (a 3-D step ~1.2x faster; momentum kept to ~5e-9, not round-off; cpu only)", kind=str,
            choices=PRECISION, note="float32 terms summed into float64 per row of cells, separations from offsets "
            "in the cells: rates within 5e-7 of float64's (fluid.equations.interact); integration and state stay "
            "float64 (benchmarks/float32_validations.py)", scene="set-up"),
    Setting("symmetry_y", None, "3-D: the symmetry plane y = symmetry_y; only the particles on y >= it are "
            "simulated, those near it with mirror images (fluid.mirror); the scene must be symmetric about it; unset: no "
            "plane", "m",
            optional=True),
    Setting("symmetry_y_hi", None, "3-D: a second symmetry plane y = symmetry_y_hi above symmetry_y: only the "
            "particles between the two are simulated, a slice of a flow uniform across y (plane waves along x) "
            "with no side walls; at least the kernel's support 2h above symmetry_y; unset: no second plane", "m",
            optional=True),
    Setting("name", "fluid", "participant name", kind=str),
)


def declare(cls):
    """Class decorator, applied before ``@dataclass``: one field per entry of
    :data:`SETTINGS`, in its order and with its default, ahead of the class's own
    annotated fields; the table is kept as ``cls.SETTINGS`` for :func:`check` and listed
    at the end of the class's docstring (``help(cls)``)."""
    own = dict(cls.__dict__.get("__annotations__", {}))
    table = tuple(SETTINGS)
    clash = sorted(own.keys() & {s.name for s in table})
    if clash:
        raise TypeError(f"{cls.__name__} declares {clash}, which fluid.settings.SETTINGS declares")
    cls.__annotations__ = {s.name: s.annotation for s in table} | own
    for s in table:
        setattr(cls, s.name, s.default)
    cls.SETTINGS = table
    cls.__doc__ = inspect.cleandoc(cls.__doc__ or "") + "\n\nFields (fluid.settings.SETTINGS):\n\n" + "\n".join(
        f"- {s.name} = {s.default!r}: {s.expected()}" + (f"; {s.hint}" if s.hint else "")
        + (f". {s.note}" if s.note else "") for s in table)
    return cls


def check(config) -> None:
    """Refuse the first field of ``config`` (a class made by :func:`declare`) outside its
    setting's range or choices, with an :class:`errors.InputError` that names the field,
    the value and what is accepted."""
    for s in type(config).SETTINGS:
        problem = s.problem(getattr(config, s.name))
        if problem:
            raise InputError(f"{type(config).__name__}: {problem}")
