"""Which validation cases are scenes: for each case, whether ``cosim/validations/scenes/CASE.toml``
exists and loads as a :class:`cosim.scene.Scene` (``Scene.from_toml``), and whether the case
runs it (builds its run from the file, ``Case.scene``) or only carries it (for its trade
study: the case itself still builds its set-up in code); then the counts.

    python benchmarks/validation_scenes.py

A case that runs its scene has the same set-up as a user's ``cosim run`` of the file; the
others build their set-up in code. A scene file that names no case is listed at the end (an
orphan, or a case's scene under another name)."""

from __future__ import annotations

from cosim.scene import Scene
from cosim.validation import case_scenes, cases
from cosim.validations.folders import SCENES


def main() -> None:
    scenes, known = case_scenes(), cases()
    rows, loads, runs = [], [], []
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
        if known[name].scene is not None:
            runs.append(name)
        how = "the case runs it" if known[name].scene is not None else "carried (the case builds in code)"
        rows.append((name, path.name, f"loads (scene {scene.name!r}); {how}"))
    print(f"{'case':28s} {'scene file':32s} status")
    for r in rows:
        print(f"{r[0]:28s} {r[1]:32s} {r[2]}")
    others = sorted(p.name for p in SCENES.glob("*.toml") if p.stem not in scenes)
    print(f"\n{len(loads)} of {len(scenes)} cases are scenes that load, {len(runs)} of them run by their case; "
          f"{len(scenes) - len(loads)} are not: {', '.join(n for n in scenes if n not in loads)}")
    print(f"carried, not run by their case: {', '.join(n for n in loads if n not in runs) or 'none'}")
    if others:
        print(f"scene files named after no case: {', '.join(others)}")


if __name__ == "__main__":
    main()
