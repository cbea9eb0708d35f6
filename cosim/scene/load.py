"""A scene from a file: TOML (``Scene.from_toml``) or a Python script that defines a
``Scene`` named ``scene`` (run as a module, not as ``__main__``: its
``if __name__ == "__main__":`` block stays out). A script that raises or exits while it
is loaded is refused with its message."""

from __future__ import annotations

import runpy
from pathlib import Path

from cosim.errors import CosimError
from cosim.scene.fields import SceneError


def load(path):
    """The scene of a .toml file or a .py script (see the module docstring)."""
    from cosim.scene.spec import Scene

    p = Path(path)
    if not p.is_file():
        raise SceneError("", f"no scene file {str(path)!r}; give a .toml file or a .py script that defines `scene`")
    if p.suffix == ".toml":
        return Scene.from_toml(p)
    if p.suffix != ".py":
        raise SceneError("", f"{p.name}: a scene is a .toml file or a .py script")
    try:
        names = runpy.run_path(str(p), run_name=f"cosim_scene_{p.stem}")
    except CosimError:
        raise  # a scene the script made and the checks refused: the message names the field
    except SyntaxError as e:
        raise SceneError("", f"{p.name} line {e.lineno}: {e.msg}; correct the script") from None
    except SystemExit as e:  # the script's own exit would end cosim silently, with its status
        raise SceneError("", f"{p.name} called sys.exit({e.code!r}) while it was loaded; a scene "
                         f"script defines `scene` and leaves running it to cosim (put the exit under "
                         f"if __name__ == \"__main__\":)") from None
    except Exception as e:
        import traceback

        where = traceback.extract_tb(e.__traceback__)[-1]
        raise SceneError("", f"{p.name} raised {type(e).__name__}: {e} (at {Path(where.filename).name} line "
                         f"{where.lineno}); the script must run and define `scene`") from None
    scene = names.get("scene")
    if not isinstance(scene, Scene):
        found = sorted(k for k, v in names.items() if isinstance(v, Scene))
        raise SceneError("", f"{p.name} defines no Scene named `scene`" + (f" (it has {found})" if found else "")
                         + "; assign one: scene = Scene(...)")
    return scene
