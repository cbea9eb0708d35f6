"""Checked fields of the scene's dataclasses: every default, unit, range and choice in
one declaration, and the error that names the field and says what would be accepted.

A scene class derives from :class:`Spec` and declares its fields with the helpers below
(``num``, ``whole``, ``choice``, ``flag``, ``text``, ``vec``, ``num_or_vec``, ``vecs``, ``part``,
``parts``, ``table``). ``Spec.__post_init__`` normalises every value (ints to floats
where a float is meant, lists to tuples) and raises :class:`SceneError` for a bad one,
before any work is done. The TOML reader (:mod:`cosim.scene.toml_io`) uses the same
declarations, so Python and TOML accept exactly the same scenes.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
from typing import Any

from cosim.errors import InputError
from cosim.scene.registry import Registry


class SceneError(InputError):
    """A bad scene value. ``path`` is the key path of the field (``moorings.lines[1].length``),
    ``problem`` what is wrong and what would be accepted."""

    def __init__(self, path: str, problem: str):
        self.path, self.problem = path, problem
        super().__init__(f"{path}: {problem}" if path else problem)

    def under(self, prefix: str) -> "SceneError":
        """The same error with its path put under ``prefix`` (a parent's key path)."""
        path = prefix if not self.path else (f"{prefix}{self.path}" if self.path.startswith("[")
                                              else f"{prefix}.{self.path}")
        return SceneError(path, self.problem)


def _is_num(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _is_finite(v) -> bool:
    """A number that is a finite float (an int beyond the float range is not)."""
    try:
        return _is_num(v) and math.isfinite(v)
    except OverflowError:
        return False


class Check:
    """How one field is checked and normalised; ``doc`` says what it is, ``unit`` in what."""


    def __init__(self, doc: str, unit: str = "", optional: bool = False):
        self.doc, self.unit, self.optional = doc, unit, optional

    def __call__(self, v, path: str):
        if v is None:
            if self.optional:
                return None
            raise SceneError(path, f"is required: {self.expected()}")
        return self.check(v, path)

    def check(self, v, path):  # pragma: no cover - every Check overrides it
        raise NotImplementedError

    def expected(self) -> str:
        return self.doc

    def _unit(self) -> str:
        return f" [{self.unit}]" if self.unit else ""


class Num(Check):
    """A finite number in ``lo`` .. ``hi``; ``why``: the reason for ``hi`` when it is a
    physical limit (:mod:`cosim.scene.limits`), said when a value passes it; ``infinite``:
    +inf is taken too (a depth's deep water)."""

    def __init__(self, doc, unit="", lo=None, hi=None, lo_open=False, hi_open=False, optional=False, why=None,
                 infinite=False):
        super().__init__(doc, unit, optional)
        self.lo, self.hi, self.lo_open, self.hi_open, self.why = lo, hi, lo_open, hi_open, why
        self.infinite = infinite

    def expected(self) -> str:
        rng = []
        if self.lo is not None:
            rng.append(f"{'>' if self.lo_open else '>='} {self.lo:g}")
        if self.hi is not None:
            rng.append(f"{'<' if self.hi_open else '<='} {self.hi:g}")
        return f"a number{self._unit()}{' ' + ' and '.join(rng) if rng else ''} ({self.doc})"

    def check(self, v, path):
        if self.infinite and _is_num(v) and v == math.inf:
            return math.inf
        if not _is_finite(v):
            raise SceneError(path, f"{_show(v)} is not a finite number; give {self.expected()}")
        v = float(v)
        bad = ((self.lo is not None and (v < self.lo or (self.lo_open and v == self.lo)))
               or (self.hi is not None and (v > self.hi or (self.hi_open and v == self.hi))))
        if bad and self.why and self.hi is not None and v >= self.hi:
            raise SceneError(path, f"{v:g}{self._unit()} is beyond {self.hi:g}{self._unit()}, {self.why}; give "
                             f"{self.expected()}")
        if bad:
            raise SceneError(path, f"{v!r}{self._unit()} is out of range; give {self.expected()}")
        return v


class Whole(Check):
    def __init__(self, doc, lo=None, hi=None, optional=False):
        super().__init__(doc, "", optional)
        self.lo, self.hi = lo, hi

    def expected(self) -> str:
        if self.lo is not None and self.hi is not None:
            rng = f"from {self.lo} to {self.hi}"
        else:
            rng = f">= {self.lo}" if self.lo is not None else f"<= {self.hi}" if self.hi is not None else ""
        return f"a whole number{' ' + rng if rng else ''} ({self.doc})"

    def check(self, v, path):
        if isinstance(v, bool) or not isinstance(v, int):
            raise SceneError(path, f"{v!r} is not a whole number; give {self.expected()}")
        if (self.lo is not None and v < self.lo) or (self.hi is not None and v > self.hi):
            raise SceneError(path, f"{v!r} is out of range; give {self.expected()}")
        return v


class Choice(Check):
    """One of ``choices``: a sequence, or a registry (:mod:`cosim.scene.registry`) whose
    names are read when a value is checked."""

    def __init__(self, doc, choices, optional=False):
        super().__init__(doc, "", optional)
        self._choices = choices if isinstance(choices, Registry) else tuple(choices)

    @property
    def choices(self) -> tuple:
        return tuple(self._choices.names()) if isinstance(self._choices, Registry) else self._choices

    def expected(self) -> str:
        return f"one of {', '.join(repr(c) for c in self.choices)} ({self.doc})"

    def check(self, v, path):
        if v not in self.choices or isinstance(v, bool):
            hint = difflib.get_close_matches(v, self.choices, n=1) if isinstance(v, str) else []
            give = f"did you mean {hint[0]!r}? Give" if hint else "give"
            raise SceneError(path, f"{_show(v)} is not accepted; {give} {self.expected()}")
        return v


class Flag(Check):
    def expected(self) -> str:
        return f"true or false ({self.doc})"

    def check(self, v, path):
        if not isinstance(v, bool):
            raise SceneError(path, f"{v!r} is not true or false; give {self.expected()}")
        return v


def is_name(v) -> bool:
    """The rule of every name that becomes a file name, an HDF5 path or a CSV column
    (a scene's, a body's, a probe's, a fairlead's): letters, digits, '_' and '-', so no
    path separator, '..', comma, space or control character."""
    return isinstance(v, str) and bool(v) and all(c.isalnum() or c in "_-" for c in v)


def is_label(v) -> bool:
    """A line's label: names (:func:`is_name`) joined by single dots, as ``BODY.NAME``."""
    return isinstance(v, str) and all(is_name(part) for part in v.split("."))


class Text(Check):
    """A text; ``name=True``: a name (:func:`is_name`), ``name="label"``: a label
    (:func:`is_label`) or empty."""

    RULES = {True: "a name of letters, digits, '_' and '-'",
             "label": "a name of letters, digits, '_' and '-', or names joined by single '.' (as BODY.NAME)"}

    def __init__(self, doc, optional=False, name=False):
        super().__init__(doc, "", optional)
        self.name = name

    def expected(self) -> str:
        return f"{self.RULES.get(self.name, 'a text')} ({self.doc})"

    def check(self, v, path):
        if self.name == "label":
            ok = v == "" or is_label(v)
        else:
            ok = is_name(v) if self.name else isinstance(v, str)
        if not ok:
            raise SceneError(path, f"{v!r} is not accepted; give {self.expected()}")
        return v


class Vec(Check):
    """A vector of finite numbers, ``sizes`` the accepted lengths (the scene checks the
    length against its dimension)."""

    def __init__(self, doc, unit="", sizes=(2, 3), optional=False, nonzero=False):
        super().__init__(doc, unit, optional)
        self.sizes, self.nonzero = tuple(sizes), nonzero

    def expected(self) -> str:
        n = " or ".join(filter(None, (", ".join(str(s) for s in self.sizes[:-1]), str(self.sizes[-1]))))
        return f"a list of {n} numbers{self._unit()} ({self.doc})"

    def check(self, v, path):
        if isinstance(v, (str, bytes)) or not hasattr(v, "__len__") or len(v) not in self.sizes \
                or not all(_is_finite(x) for x in v):
            raise SceneError(path, f"{_show(v)} is not accepted; give {self.expected()}")
        if self.nonzero and not any(x != 0 for x in v):
            raise SceneError(path, f"{_show(v)} is a zero vector; give {self.expected()}, not all zero")
        return tuple(float(x) for x in v)


class NumOrVec(Check):
    """A number (``num``'s range) or a vector of ``sizes`` finite numbers whose length is
    at most ``hi``: a magnitude along a default direction, or the full vector (gravity:
    9.81 along -z, or (gx, gz) / (gx, gy, gz))."""

    def __init__(self, doc, unit="", sizes=(2, 3), hi=None, why=None, optional=False):
        super().__init__(doc, unit, optional)
        self.num = Num(doc, unit, lo=0, hi=hi, why=why)
        self.vec = Vec(doc, unit, sizes)

    def expected(self) -> str:
        hi = f" up to {self.num.hi:g}" if self.num.hi is not None else ""
        return (f"a number{self._unit()} from 0{hi}, or a vector of {' or '.join(map(str, self.vec.sizes))} "
                f"numbers{self._unit()} no longer than that ({self.doc})")

    def check(self, v, path):
        if _is_num(v):
            if _is_finite(v) and v < 0:
                raise SceneError(path, f"{v!r}{self._unit()} is out of range; give {self.expected()}")
            return self.num.check(v, path)
        v = self.vec.check(v, path)
        size = math.sqrt(sum(x * x for x in v))
        if self.num.hi is not None and size > self.num.hi:
            why = f", {self.num.why}" if self.num.why else ""
            raise SceneError(path, f"{_show(v)} is {size:g}{self._unit()} long, beyond {self.num.hi:g}"
                             f"{self._unit()}{why}; give {self.expected()}")
        return v


class Vecs(Check):
    """A list of vectors (or of numbers, ``sizes=(0,)``: one number each)."""

    def __init__(self, doc, unit="", sizes=(2, 3), min_len=0):
        super().__init__(doc, unit, False)
        self.item = Vec(doc, unit, sizes) if sizes != (0,) else Num(doc, unit)
        self.min_len = min_len

    def expected(self) -> str:
        what = "numbers" if isinstance(self.item, Num) else f"points of {' or '.join(map(str, self.item.sizes))}"
        return f"a list of {what}{self._unit()}{f', at least {self.min_len}' if self.min_len else ''} ({self.doc})"

    def check(self, v, path):
        _require_list(v, path, self)
        out = tuple(self.item(x, f"{path}[{i}]") for i, x in enumerate(v))
        if len(out) < self.min_len:
            raise SceneError(path, f"has {len(out)} entries; give {self.expected()}")
        return out


class Names(Check):
    """A list of names (strings)."""

    def expected(self) -> str:
        return f"a list of names ({self.doc})"

    def check(self, v, path):
        _require_list(v, path, self)
        v = tuple(v)
        for i, x in enumerate(v):
            if not isinstance(x, str) or not x:
                raise SceneError(f"{path}[{i}]", f"{x!r} is not a name; give {self.expected()}")
        return v


class Gauges(Check):
    """Wave-gauge positions: numbers x [m] (2-D) or pairs (x, y) [m] (3-D)."""

    def expected(self) -> str:
        return f"a list of x positions (2-D) or of (x, y) pairs (3-D) [m] ({self.doc})"

    def check(self, v, path):
        _require_list(v, path, self)
        out = []
        for i, x in enumerate(v):
            if _is_finite(x):
                out.append(float(x))
            else:
                out.append(Vec(self.doc, "m", (2,))(x, f"{path}[{i}]"))
        return tuple(out)


class Table(Check):
    """A table of names to vectors (``{left = [-0.1, -0.05]}``), kept as a dict."""

    def __init__(self, doc, unit="", sizes=(2, 3)):
        super().__init__(doc, unit, False)
        self.item = Vec(doc, unit, sizes)
        self.key = Text("a name", name=True)

    def expected(self) -> str:
        return f"a table of names to {self.item.expected()}"

    def check(self, v, path):
        if not isinstance(v, dict):
            raise SceneError(path, f"{_show(v)} is not a table; give {self.expected()}")
        return {self.key(k, f"{path}.{k}"): self.item(x, f"{path}.{k}") for k, x in v.items()}


class Part(Check):
    """A nested scene object: one class, or one of several told apart by the value of
    their ``tag`` field (``kind``, ``model``, ``shape``), given as a sequence or as a
    registry (:mod:`cosim.scene.registry`) whose classes are read when a value is checked."""


    def __init__(self, doc, classes, optional=False):
        super().__init__(doc, "", optional)
        self._classes = (classes if isinstance(classes, Registry) else
                         tuple(classes) if isinstance(classes, (tuple, list)) else (classes,))

    @property
    def classes(self) -> tuple:
        return self._classes.classes() if isinstance(self._classes, Registry) else self._classes

    def expected(self) -> str:
        return f"{' or '.join(c.__name__ for c in self.classes)} ({self.doc})"

    def check(self, v, path):
        if not isinstance(v, self.classes):
            raise SceneError(path, f"{type(v).__name__} {v!r} is not accepted; give {self.expected()}")
        return v


class Parts(Check):

    def __init__(self, doc, classes):
        super().__init__(doc, "", False)
        self.part = Part(doc, classes)

    def expected(self) -> str:
        return f"a list of {self.part.expected()}"

    def check(self, v, path):
        _require_list(v, path, self)
        return tuple(self.part(x, f"{path}[{i}]") for i, x in enumerate(v))


def _require_list(v, path: str, check: Check) -> None:
    """Refuse a value that is not a list (a text, a table or a scene object is not one)."""
    if isinstance(v, (str, bytes, dict, Spec)) or not hasattr(v, "__iter__"):
        raise SceneError(path, f"{_show(v)} is not a list; give {check.expected()}")


def _show(v) -> str:
    s = repr(v)
    return s if len(s) <= 60 else s[:57] + "..."


# ------------------------------------------------------------------------ declarations
def _field(check: Check, default):
    if isinstance(default, (list, dict)):
        return dataclasses.field(default_factory=lambda d=default: type(d)(d), metadata={"check": check})
    return dataclasses.field(default=default, metadata={"check": check})


def num(default, doc, unit="", **rng):
    return _field(Num(doc, unit, optional=default is None and rng.pop("optional", True), **rng), default)


def whole(default, doc, **rng):
    return _field(Whole(doc, optional=default is None, **rng), default)


def choice(default, doc, choices):
    return _field(Choice(doc, choices, optional=default is None), default)


def flag(default, doc):
    return _field(Flag(doc, optional=default is None), default)


def text(default, doc, name=False):
    return _field(Text(doc, optional=default is None, name=name), default)


def vec(default, doc, unit="", sizes=(2, 3), nonzero=False):
    return _field(Vec(doc, unit, sizes, optional=default is None, nonzero=nonzero), default)


def num_or_vec(default, doc, unit="", sizes=(2, 3), hi=None, why=None):
    return _field(NumOrVec(doc, unit, sizes, hi, why, optional=default is None), default)


def vecs(doc, unit="", sizes=(2, 3), min_len=0, default=()):
    return _field(Vecs(doc, unit, sizes, min_len), default)


def names(doc, default=()):
    return _field(Names(doc), default)


def gauges(doc):
    return _field(Gauges(doc), ())


def table(doc, unit="", sizes=(2, 3)):
    return _field(Table(doc, unit, sizes), {})


def part(default, doc, classes):
    return _field(Part(doc, classes, optional=default is None), default)


def parts(doc, classes):
    return _field(Parts(doc, classes), ())


def setting_check(setting, optional: bool = True, hi=None, why=None) -> Check:
    """The check of a scene field that mirrors one of the SPH fluid's settings
    (``fluid.settings.Setting``): its kind, doc, unit, range or choices; ``hi`` / ``why``: a
    physical limit of the scene's (:mod:`cosim.scene.limits`) below the setting's own."""
    s = setting
    if s.choices:
        return Choice(s.doc, s.choices, optional=optional)
    if s.kind is bool:
        return Flag(s.doc, optional=optional)
    if s.kind is int:
        return Whole(s.doc, lo=s.lo, hi=s.hi, optional=optional)
    if s.kind is float:
        return Num(s.doc, s.unit, lo=s.lo, hi=s.hi if hi is None else hi, lo_open=s.lo_open,
                   hi_open=s.hi_open and hi is None, optional=optional, why=why)
    if s.kind is str:
        return Text(s.doc, optional=optional)
    raise TypeError(f"setting {s.name}: a scene field cannot mirror a setting of kind {s.kind.__name__}")


def mirror_settings(settings, limits: dict | None = None):
    """Class decorator, applied before ``@dataclass``: one checked field per setting of
    ``settings`` (``fluid.settings.SETTINGS``) that has a ``scene`` role, in the table's
    order and ahead of the class's own fields. "set-up": unset by default (None); "default":
    the setting's default; "required": no default. ``limits``: {name: (hi, why)}, the
    scene's physical limits on a setting."""
    limits = limits or {}

    def decorate(cls):
        own = dict(cls.__dict__.get("__annotations__", {}))
        mine = [s for s in settings if s.scene]
        clash = sorted(own.keys() & {s.name for s in mine})
        if clash:
            raise TypeError(f"{cls.__name__} declares {clash}, which the fluid's settings declare")
        for s in mine:
            hi, why = limits.get(s.name, (None, None))
            check = setting_check(s, optional=s.scene == "set-up", hi=hi, why=why)
            f = _field(check, None if s.scene == "set-up" else s.default)
            setattr(cls, s.name, required(f) if s.scene == "required" else f)
        cls.__annotations__ = {s.name: s.annotation for s in mine} | own
        return cls

    return decorate


def required(check_field):
    """A declaration without a default: the field must be given."""
    check_field.metadata["check"].optional = False
    return dataclasses.field(metadata=check_field.metadata)


class Spec:
    """Base of the scene's frozen dataclasses: checks and normalises every declared field
    on construction (:class:`Check`), then runs the class's own ``validate()``."""

    #: the field that tells this class apart among others in the same place, and its value
    TAG: tuple[str, str] | None = None

    def __post_init__(self):
        name = type(self).__name__
        for f in dataclasses.fields(self):
            check = f.metadata.get("check")
            if check is None:
                continue
            try:
                object.__setattr__(self, f.name, check(getattr(self, f.name), f.name))
            except SceneError as e:
                raise SceneError(f"{name}.{e.path}", e.problem) from None
        try:
            self.validate()
        except SceneError as e:
            raise SceneError(f"{name}.{e.path}" if e.path else name, e.problem) from None

    def validate(self) -> None:
        """Checks between fields (override)."""

    def replace(self, **changes):
        return dataclasses.replace(self, **changes)


def spec_fields(cls) -> list[tuple[str, Check, Any]]:
    """(name, check, default) of every declared field of a scene class, in order
    (default ``dataclasses.MISSING`` when the field must be given)."""
    out = []
    for f in dataclasses.fields(cls):
        if "check" in f.metadata:
            default = f.default if f.default is not dataclasses.MISSING else (
                f.default_factory() if f.default_factory is not dataclasses.MISSING else dataclasses.MISSING)
            out.append((f.name, f.metadata["check"], default))
    return out
