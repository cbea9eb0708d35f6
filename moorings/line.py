"""What a mooring line is, independent of the model that solves it.

Every mooring model (quasi-static catenary, SPH cable, MoorDyn, FMU) is built from
the same :class:`MooringLine` records, so a scene swaps models by changing one
constructor call and nothing else.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from errors import InputError


def _positive(line: str, name: str, value, unit: str, hint: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{line}: {name} must be a number [{unit}], got {value!r}") from None
    if not math.isfinite(v) or v <= 0:
        raise InputError(f"{line}: {name} = {value!r} {unit}; it must be a finite number > 0 ({hint})")
    return v


@dataclass(frozen=True)
class MooringLine:
    """One line from a fixed anchor to a fairlead on a body.

    Parameters
    ----------
    anchor:
        Anchor position in the world frame [m], 2 values (x, z) in a 2-D scene or 3
        (x, y, z) in 3-D. The seabed is the horizontal plane through the anchor.
    length:
        Unstretched line length [m].
    weight:
        Submerged weight per unit length [N/m] (weight in air minus buoyancy).
    EA:
        Axial stiffness [N]; ``None`` (or ``inf``) for an inextensible line.
    mass_per_length:
        Mass per unit length in air [kg/m]; dynamic models need it.
    diameter:
        Hydrodynamic (volume-equivalent) diameter [m]; dynamic models use it for
        drag and added mass.
    name:
        Label used in messages and outputs; the mooring system numbers unnamed lines.
    break_load:
        Tension [N] at which the line breaks (``None``: never); a mooring system
        wrapped in :class:`moorings.breaking.BreakingMooring` reports it, and may
        release the line.
    """

    anchor: tuple[float, ...]
    length: float
    weight: float
    EA: float | None = None
    mass_per_length: float | None = None
    diameter: float | None = None
    name: str = ""
    break_load: float | None = None

    def __post_init__(self):
        label = f"mooring line '{self.name}'" if self.name else "mooring line"
        a = np.asarray(self.anchor, dtype=float)
        if a.ndim != 1 or a.size not in (2, 3) or not np.all(np.isfinite(a)):
            raise InputError(
                f"{label}: anchor = {self.anchor!r}; give 2 finite coordinates (x, z) in 2-D or 3 (x, y, z) in 3-D [m]"
            )
        object.__setattr__(self, "anchor", tuple(float(c) for c in a))
        object.__setattr__(self, "length", _positive(label, "length", self.length, "m", "the unstretched length"))
        object.__setattr__(
            self, "weight", _positive(label, "weight", self.weight, "N/m", "submerged weight per unit length")
        )
        if self.EA is not None:
            ea = _positive(label, "EA", self.EA, "N", "axial stiffness; use EA=None for an inextensible line")
            object.__setattr__(self, "EA", ea)
        for name, unit, hint in (("mass_per_length", "kg/m", "or leave it None"), ("diameter", "m", "or leave it None"),
                                 ("break_load", "N", "the tension at which the line breaks; None: it never breaks")):
            v = getattr(self, name)
            if v is not None:
                object.__setattr__(self, name, _positive(label, name, v, unit, hint))

    @property
    def dim(self) -> int:
        """2 for a line in the x-z plane, 3 in space."""
        return len(self.anchor)

    @property
    def inextensible(self) -> bool:
        return self.EA is None or math.isinf(self.EA)


def named_lines(lines) -> list[MooringLine]:
    """The lines with unique names (unnamed ones become ``line0``, ``line1``, ...),
    all of one dimension; raises :class:`InputError` otherwise."""
    lines = list(lines)
    if not lines:
        raise InputError("a mooring system needs at least one MooringLine")
    out = []
    for i, ln in enumerate(lines):
        if not isinstance(ln, MooringLine):
            raise InputError(f"mooring line {i}: expected a moorings.MooringLine, got {type(ln).__name__}")
        out.append(ln if ln.name else MooringLine(**{**ln.__dict__, "name": f"line{i}"}))
    dims = {ln.dim for ln in out}
    if len(dims) != 1:
        raise InputError("all mooring lines must have anchors of the same dimension (all 2-D or all 3-D)")
    names = [ln.name for ln in out]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise InputError(f"mooring line names must be unique; repeated: {', '.join(dup)}")
    return out


def per_line(values, line_names, dim: int, owner: str, what: str) -> np.ndarray:
    """``values`` as a new finite float array of shape ``(n_lines, dim)``, one row
    per line (fairlead positions, velocities); otherwise an :class:`InputError`
    naming the owner, the quantity and the first bad line."""
    want = f"shape ({len(line_names)}, {dim}) (one row per line, {'x, z' if dim == 2 else 'x, y, z'})"
    try:
        a = np.array(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{owner}: {what} must be numbers of {want}") from None
    if a.shape != (len(line_names), dim):
        raise InputError(f"{owner}: {what} must have {want}, got shape {a.shape}")
    bad = ~np.all(np.isfinite(a), axis=1)
    if bad.any():
        i = int(np.argmax(bad))
        raise InputError(f"{owner}, line '{line_names[i]}': {what} {a[i]} is not finite")
    return a


def vertical_plane(a, b):
    """The vertical plane through a line's ends ``a`` and ``b`` (world frame, z last): the
    horizontal distance ``X`` [m] and the height ``Z`` [m] of ``b`` over ``a``, and the map
    from in-plane coordinates (``x`` horizontal from ``a`` towards ``b``, ``z`` up) [m] to
    world points ``(n, dim)`` (along the first axis where ``b`` is straight above ``a``)."""
    a = np.asarray(a, float)
    d = np.asarray(b, float) - a
    horiz = d.copy()
    horiz[-1] = 0.0
    X = float(np.linalg.norm(horiz))
    eh = horiz / X if X > 0 else np.eye(a.size)[0]
    ez = np.zeros(a.size)
    ez[-1] = 1.0
    return X, float(d[-1]), lambda xs, zs: a + np.outer(xs, eh) + np.outer(zs, ez)


__all__ = ["MooringLine", "named_lines", "per_line", "vertical_plane"]
