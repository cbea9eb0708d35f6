"""A scene from a file: TOML (``Scene.from_toml``) or a Python script that defines a
``Scene`` named ``scene`` (run as a module, not as ``__main__``: its
``if __name__ == "__main__":`` block stays out)."""

from __future__ import annotations

import runpy
from pathlib import Path

from cosim.scene.fields import SceneError


def load(path) -> "Scene":  # noqa: F821 - the Scene class, imported below
    from cosim.scene.spec import Scene

    p = Path(path)
    if not p.is_file():
        raise SceneError("", f"no scene file {str(path)!r}; give a .toml file or a .py script that defines `scene`")
    if p.suffix == ".toml":
        return Scene.from_toml(p)
    if p.suffix != ".py":
        raise SceneError("", f"{p.name}: a scene is a .toml file or a .py script")
    names = runpy.run_path(str(p), run_name=f"cosim_scene_{p.stem}")
    scene = names.get("scene")
    if not isinstance(scene, Scene):
        found = sorted(k for k, v in names.items() if isinstance(v, Scene))
        raise SceneError("", f"{p.name} defines no Scene named `scene`" + (f" (it has {found})" if found else "")
                         + "; assign one: scene = Scene(...)")
    return scene
