"""Which validation cases are scenes: for each case, whether ``cosim/validations/scenes/CASE.toml``
exists and loads as a :class:`cosim.scene.Scene` (``Scene.from_toml``), then the counts.

    python benchmarks/validation_scenes.py

A case that is a scene runs by the same runner as a user's scene; the others build their
set-up in code. A scene file that names no case is listed at the end (an orphan, or a case's
scene under another name)."""

from __future__ import annotations

from cosim.scene import Scene
from cosim.validation import case_scenes
from cosim.validations.folders import SCENES


def main() -> None:
    scenes = case_scenes()
    rows, loads = [], []
    for name, path in scenes.items():
        if path is None:
            rows.append((name, "-", "no scene file"))
            continue
        try:
            scene = Scene.from_toml(path)
        except Exception as e:  # the table reports it; the test suite fails on it
            rows.append((name, path.name, f"does not load: {type(e).__name__}: {e}"))
            continue
        loads.append(name)
        rows.append((name, path.name, f"loads (scene {scene.name!r})"))
    print(f"{'case':28s} {'scene file':30s} status")
    for r in rows:
        print(f"{r[0]:28s} {r[1]:30s} {r[2]}")
    others = sorted(p.name for p in SCENES.glob("*.toml") if p.stem not in scenes)
    print(f"\n{len(loads)} of {len(scenes)} cases are scenes that load; "
          f"{len(scenes) - len(loads)} are not: {', '.join(n for n in scenes if n not in loads)}")
    if others:
        print(f"scene files named after no case: {', '.join(others)}")


if __name__ == "__main__":
    main()
