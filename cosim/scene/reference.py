"""The scene's field reference as Markdown (``docs/scenes.md``), made from the
declarations themselves so that it cannot drift from them:
``python -m cosim.scene.reference > docs/scenes.md``."""

from __future__ import annotations

import dataclasses
import inspect

from cosim.scene import spec
from cosim.scene.fields import spec_fields

SECTIONS = [
    ("The scene", [spec.Scene, spec.World, spec.Coupling]),
    ("Fluids (`[fluid]`, told apart by `model`)", list(spec.FLUIDS)),
    ("Domains (`[domain]`, by `kind`)", list(spec.DOMAINS) + [spec.Block, spec.Beach]),
    ("Waves (`[waves]`, by `kind`): wavemakers, the incident sea", list(spec.WAVES)),
    ("Base motions (`[base_motion]`, by `kind`)", list(spec.BASE_MOTIONS) + [spec.Record]),
    ("Bodies (`[[bodies]]`, by `shape`)", list(spec.BODIES)),
    ("Moorings (`[moorings]`)", [spec.Moorings, spec.Line]),
    ("Probes (`[probes]`)", [spec.Probes, spec.Patch]),
]


def _default(v) -> str:
    if v is dataclasses.MISSING:
        return "**required**"
    if v is None:
        return "unset"
    if isinstance(v, spec.Spec):
        return f"`{type(v).__name__}()`"
    if isinstance(v, str):
        return f'`"{v}"`'
    if isinstance(v, bool):
        return f"`{str(v).lower()}`"
    if isinstance(v, (tuple, list)):
        return "`[" + ", ".join(repr(x) if not isinstance(x, str) else f'"{x}"' for x in v) + "]`"
    if isinstance(v, dict):
        return "`{}`" if not v else f"`{v}`"
    return f"`{v!r}`"


def markdown() -> str:
    out = ["# Scene fields", "",
           "Every field of a scene (`cosim.scene`), its default and unit; the TOML key is the field's name. "
           "Generated from the declarations in `cosim/scene/spec.py` by `python -m cosim.scene.reference > "
           "docs/scenes.md` (a test keeps it current). A field left unset takes the value that the text says; "
           "a bad value is refused with its key path (`docs/scene_errors.md`).", ""]
    for title, classes in SECTIONS:
        out += [f"## {title}", ""]
        for cls in classes:
            doc = " ".join(inspect.cleandoc(cls.__doc__ or "").split("\n\n")[0].split())
            tag = f' — `{cls.TAG[0]} = "{cls.TAG[1]}"`' if cls.TAG else ""
            out += [f"### `{cls.__name__}`{tag}", "", doc, "", "| field | default | unit | what |",
                    "|---|---|---|---|"]
            for name, check, default in spec_fields(cls):
                what = check.expected().replace("|", "\\|")
                out.append(f"| `{name}` | {_default(default)} | {check.unit or ''} | {what} |")
            out.append("")
    return "\n".join(out).rstrip() + "\n"


if __name__ == "__main__":
    print(markdown(), end="")
