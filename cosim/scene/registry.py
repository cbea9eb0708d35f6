"""The one place where each kind of scene plug-in is listed: fluid models, body shapes,
wave kinds, mooring models and probes. Each registry holds the
built-in entries (named here, imported on first use, so that a scene loads only what it
names) and those that other packages declare in an entry-point group of their
distribution's metadata:

    [project.entry-points."cosim.moorings"]        # pyproject.toml of another package
    my-line = "my_package.lines:MyLineModel"

====================  =====================  ==============================================
registry              entry-point group      an entry (see its interface)
====================  =====================  ==============================================
:data:`FLUIDS`        ``cosim.fluids``       a scene class tagged ``model = NAME`` whose
                                             ``participant(scene, built)`` puts the fluid
                                             participant into ``built``
                                             (:class:`cosim.scene.build.Built`)
:data:`SHAPES`        ``cosim.shapes``       a scene class tagged ``shape = NAME`` deriving
                                             :class:`cosim.scene.shapes.RigidBody`
:data:`WAVES`         ``cosim.waves``        a scene class tagged ``kind = NAME`` deriving
                                             :class:`cosim.scene.seas.IncidentSea`
:data:`MOORINGS`      ``cosim.moorings``     a :class:`cosim.scene.mooring_models.MooringModel`
:data:`PROBES`        ``cosim.probes``       a :class:`cosim.scene.probes.Probe`
====================  =====================  ==============================================

An entry point's name is the entry's name (a scene class's tag value); what it points to
is registered by :meth:`Registry.register`, the same call a package makes by hand. An
entry that does not fit, or a name taken twice, is refused with a
:class:`~cosim.errors.ConfigurationError` naming the entry point and its distribution.
"""

from __future__ import annotations

import difflib
from importlib import import_module
from importlib.metadata import entry_points
from typing import Any, Callable, Iterator

from cosim.errors import ConfigurationError, InputError


def _import(target: str):
    """The object ``"module:attribute"`` names."""
    module, _, attr = target.partition(":")
    return getattr(import_module(module), attr)


class Registry:
    """Named entries of one kind, in registration order: the built-ins, then plug-ins.

    ``what``: the kind, for messages ("mooring model"); ``group``: the entry-point group
    searched; ``builtins``: ``"module:attribute"`` of the built-in entries, a sequence of
    scene classes (named by their tag) or a mapping of names to entries, imported on first
    use; ``check(name, entry)``: returns the entry to keep (it may, e.g., instantiate a
    class) or raises :class:`~cosim.errors.ConfigurationError` saying what it lacks."""

    def __init__(self, what: str, group: str, builtins: str, check: Callable[[str, Any], Any]):
        self.what, self.group = what, group
        self._builtins, self._check = builtins, check
        self._entries: dict[str, Any] = {}
        self._discovered = False

    # -- registering
    def register(self, name: str, entry: Any, *, replace: bool = False) -> Any:
        """Add ``entry`` under ``name`` (what an entry point of :attr:`group` does);
        returns the entry kept. A name already taken by another entry is refused unless
        ``replace``."""
        self._discover()
        return self._add(name, entry, replace)

    def _add(self, name, entry, replace=False):
        if not isinstance(name, str) or not name or not all(c.isalnum() or c in "_-" for c in name):
            raise ConfigurationError(f"{self.what} {name!r}: a name is letters, digits, '_' and '-'")
        kept = self._check(name, entry)
        old = self._entries.get(name)
        if old is not None and not _same(old, kept) and not replace:
            raise ConfigurationError(f"{self.what} {name!r} is registered twice ({_where(old)} and {_where(kept)}); "
                                     f"give one of them another name, or register with replace=True")
        self._entries[name] = kept
        return kept

    def unregister(self, name: str) -> None:
        """Remove the entry ``name`` (a plug-in's, e.g. at the end of a test)."""
        self._discover()
        if self._entries.pop(name, None) is None:
            raise InputError(f"no {self.what} {name!r} is registered")

    def rediscover(self) -> None:
        """Look again for entry points of :attr:`group` (after a package was installed
        in a running interpreter); entries registered by hand stay."""
        self._discovered = False
        self._discover()

    def _discover(self) -> None:
        if self._discovered:
            return
        self._discovered = True  # first: a built-in module that reads the registry while it loads finds it
        try:
            builtins = _import(self._builtins)
            pairs = builtins.items() if isinstance(builtins, dict) else ((c.TAG[1], c) for c in builtins)
            for name, entry in pairs:
                if name not in self._entries:
                    self._add(name, entry)
            for ep in entry_points(group=self.group):
                dist = getattr(getattr(ep, "dist", None), "name", None) or "an installed package"
                try:
                    self._add(ep.name, ep.load())
                except Exception as e:
                    raise ConfigurationError(f"the entry point {ep.name!r} = {ep.value!r} of {dist} (group "
                                             f"{self.group!r}) cannot be registered as a {self.what}: {e}; fix or "
                                             f"uninstall {dist}") from e
        except BaseException:
            self._discovered = False
            raise

    # -- reading
    def names(self) -> list[str]:
        self._discover()
        return list(self._entries)

    def classes(self) -> tuple:
        """The entries, in order (for a registry of scene classes: the classes a scene accepts)."""
        self._discover()
        return tuple(self._entries.values())

    def items(self) -> Iterator[tuple[str, Any]]:
        self._discover()
        return iter(list(self._entries.items()))

    def __contains__(self, name) -> bool:
        self._discover()
        return name in self._entries

    def __getitem__(self, name: str) -> Any:
        self._discover()
        if name not in self._entries:
            hint = difflib.get_close_matches(name, list(self._entries), n=1) if isinstance(name, str) else []
            raise InputError(f"no {self.what} {name!r}{'; did you mean ' + repr(hint[0]) + '?' if hint else ''}; "
                             f"registered: {', '.join(map(repr, self._entries))}")
        return self._entries[name]

    def __repr__(self) -> str:
        return f"Registry({self.what!r}, group={self.group!r})"


def _same(a, b) -> bool:
    """The same entry: one object, or two instances of one class (registered twice)."""
    return a is b or (not isinstance(a, type) and type(a) is type(b))


def _where(entry) -> str:
    obj = entry if isinstance(entry, type) else type(entry)
    return f"{obj.__module__}.{obj.__qualname__}"


def _scene_class(tag: str, bases: tuple[str, ...] = ("cosim.scene.fields:Spec",), needs: tuple[str, ...] = ()):
    """The check of a registry of scene classes: a subclass of one of ``bases`` (``"module:
    attribute"``; a plug-in derives the first) whose ``TAG`` is ``(tag, name)`` and which
    has the methods ``needs``."""

    def check(name, entry):
        kinds = tuple(_import(b) for b in bases)
        if not (isinstance(entry, type) and issubclass(entry, kinds)):
            raise ConfigurationError(f"{name!r}: {entry!r} is not a scene class of this kind (a frozen dataclass "
                                     f"deriving {bases[0].replace(':', '.')})")
        if entry.TAG != (tag, name):
            raise ConfigurationError(f"{name!r}: {entry.__name__}.TAG is {entry.TAG!r}; give it TAG = ({tag!r}, "
                                     f"{name!r}) and a field {tag} = tag({name!r})")
        lacks = [m for m in needs if not callable(getattr(entry, m, None))]
        if lacks:
            raise ConfigurationError(f"{name!r}: {entry.__name__} lacks the method(s) {', '.join(lacks)}")
        return entry

    return check


def _instance_of(where: str):
    """The check of a registry of objects deriving the class ``where`` names: a subclass
    is instantiated without arguments."""

    def check(name, entry):
        base = _import(where)
        if isinstance(entry, type) and issubclass(entry, base):
            entry = entry()
        if not isinstance(entry, base):
            raise ConfigurationError(f"{name!r}: {entry!r} is not a {base.__name__} (derive {where.replace(':', '.')} "
                                     f"and register the class or an instance)")
        return entry

    return check


FLUIDS = Registry("fluid model", "cosim.fluids", "cosim.scene.spec:FLUIDS",
                  _scene_class("model", needs=("participant",)))
SHAPES = Registry("body shape", "cosim.shapes", "cosim.scene.spec:BODIES",
                  _scene_class("shape", ("cosim.scene.shapes:RigidBody", "cosim.scene.spec:MJCF",
                                         "cosim.scene.spec:ElasticPlate")))
WAVES = Registry("wave kind", "cosim.waves", "cosim.scene.spec:WAVES",
                 _scene_class("kind", ("cosim.scene.seas:IncidentSea", "cosim.scene.spec:Piston",
                                       "cosim.scene.spec:Flap", "cosim.scene.spec:PaddleRecord")))
MOORINGS = Registry("mooring model", "cosim.moorings", "cosim.scene.mooring_models:MODELS",
                    _instance_of("cosim.scene.mooring_models:MooringModel"))
PROBES = Registry("probe", "cosim.probes", "cosim.scene.probes:PROBES", _instance_of("cosim.scene.probes:Probe"))
#: the registries of scene classes, told apart in a scene by their tag
TAGGED = (FLUIDS, SHAPES, WAVES)
