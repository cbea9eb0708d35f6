"""The scene's field reference as Markdown (``docs/scenes.md``), made from the
declarations themselves so that it cannot drift from them:
``python -m cosim.scene.reference > docs/scenes.md``."""

from __future__ import annotations

import dataclasses
import inspect

from cosim.scene import spec
from cosim.scene.fields import spec_fields
from cosim.scene.registry import FLUIDS, SHAPES, WAVES

SECTIONS = [
    ("The scene", [spec.Scene, spec.World, spec.Coupling]),
    ("Fluids (`[fluid]`, told apart by `model`)", list(FLUIDS.classes())),
    ("Domains (`[domain]`, by `kind`)", list(spec.DOMAINS) + [spec.Block, spec.Beach, spec.Absorber]),
    ("Waves (`[waves]`, by `kind`): wavemakers, the incident sea", list(WAVES.classes())),
    ("Base motions (`[base_motion]`, by `kind`)", list(spec.BASE_MOTIONS) + [spec.Record]),
    ("Bodies (`[[bodies]]`, by `shape`)", list(SHAPES.classes()) + [spec.ForcedMotion, spec.ForcedTable]),
    ("Moorings (`[moorings]`)", [spec.Moorings, spec.Line, spec.PointLoad]),
    ("Probes (`[probes]`)", [spec.Probes, spec.Patch]),
]

#: a paragraph at the head of a section, where what the section's classes share needs saying once
NOTES = {
    "Base motions (`[base_motion]`, by `kind`)": (
        "What rides with a moving tank: the SPH fluid's walls; the wave gauges and pressure patches (`[probes]`, read "
        "in the tank's frame); the clamps of elastic plates (their clamped link on joints driven by the tank's "
        "motion, so that a plate feels the base's acceleration and starts at rest on the tank; its corner and tip "
        "probes read its deflection in the tank's frame, `PLATE.clamp_x` and `PLATE.clamp_z` the clamp's "
        "displacement). With `fluid.model = \"none\"` a base motion shakes the plates alone, without a tank: the "
        "cheap way to a base-excited structure. What does not: free bodies, which the water carries; mooring lines "
        "(refused: the mooring models hold their anchors fixed in space while the tank's floor would move); what "
        "an MJCF model fixes to its world (bodies welded or jointed to it, equality constraints to it, its colliding "
        "geoms), which stands still (warned of when the scene is built). The SPH domain, outside which particles "
        "are removed, covers the tank's travel over the whole run and, above the walls, the tank's own height again "
        "(`cosim.scene.sph_domain`; reported in summary.json's `sph_domain`)."),
}


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
        out += [f"## {title}", ""] + ([NOTES[title], ""] if title in NOTES else [])
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
