"""What a validation case is, and the table the cases register themselves in.

A leaf below :mod:`cosim.validation` (which lists, runs and judges the cases): the case
modules of :mod:`cosim.validations` import :func:`case` from here, and
:mod:`cosim.validation` imports them by name, so the imports run one way (the runner,
then the cases, then this table) with no circle between them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class Case:
    name: str
    description: str
    fn: Callable[[bool], dict]
    #: the stated target: the target column of ``row`` in docs/VALIDATION.md, or declared
    target: str = ""
    #: what the quick variant is judged against (declared)
    quick_target: str = ""
    #: the row of docs/VALIDATION.md the target comes from (None: declared, no row)
    row: str | None = None
    #: ``scene(quick)``: the :class:`cosim.scene.Scene` a variant runs (its first, where it runs
    #: several), built from the case's file ``scenes/NAME.toml``; the quick variant's is the
    #: file's (tests/test_validation_scenes.py). None: the case builds its set-up in code
    scene: Callable[[bool], object] | None = None
    #: the quick variant takes more than :data:`LONG_QUICK_S` of CPU (near-field runs of many
    #: periods): ``cosim validate all --quick`` leaves it out unless ``--long`` asks for it
    long: bool = False


#: the quick variants of the tier ``cosim validate all --quick`` runs take at most this much
#: CPU each [s] (by the committed records, tests/test_validation_tiers.py); a case whose quick
#: variant takes more is marked ``long``
LONG_QUICK_S = 300.0

_CASES: dict[str, Case] = {}


def case(name: str, description: str, *, target: str, quick: str, row: str | None = "", scene=None,
         long: bool = False):
    """Decorator registering ``fn(quick) -> dict`` as validation case ``name``.

    ``target``: the stated target (the target column of the ``row`` of docs/VALIDATION.md,
    by default the row named ``name``; ``row=None``: no row, the target is declared here);
    ``quick``: what the quick variant is judged against; ``scene``: ``scene(quick)``, the
    scene the variant runs (:attr:`Case.scene`), for a case that runs its scene file;
    ``long``: its quick variant is beyond the quick tier (:attr:`Case.long`)."""

    def register(fn):
        if name in _CASES and _CASES[name].fn is not fn:
            raise ValueError(f"validation case {name!r} registered twice")
        _CASES[name] = Case(name, description, fn, target, quick, name if row == "" else row, scene, long)
        return fn

    return register
