"""Validation cases as scenes: a case's scene file (cosim/validations/scenes/CASE.toml) loads as
a Scene; every scene file there belongs to a case; the studied cases are scenes; a case that
runs its scene runs the file as written. ``python benchmarks/validation_scenes.py`` prints
which cases are scenes and which are not."""

from pathlib import Path

import pytest

from cosim import validation
from cosim.scene import Scene
from cosim.validations import trade
from cosim.validations.folders import SCENES

FILES = sorted(SCENES.glob("*.toml"))


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_every_scene_file_loads_as_a_scene(path):
    scene = Scene.from_toml(path)
    assert isinstance(scene, Scene) and scene.name


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_every_scene_file_written_and_read_again_is_the_same_scene(path, tmp_path):
    """The TOML writer keeps every field of the packaged scenes (open water, a body's
    velocity, tables of base motion among them)."""
    scene = Scene.from_toml(path)
    scene.to_toml(tmp_path / path.name)
    assert _resolved(Scene.from_toml(tmp_path / path.name)) == _resolved(scene)


def test_every_scene_file_belongs_to_a_case():
    """Named after its case, or named by the module of the case that runs it."""
    known = validation.cases()
    sources = "".join(p.read_text(encoding="utf-8") for p in SCENES.parent.glob("*.py"))
    orphans = [p.name for p in FILES if p.stem not in known and f'"{p.name}"' not in sources]
    assert len(FILES) > 5 and not orphans, orphans


def test_case_scenes_names_each_case_by_its_file():
    scenes = validation.case_scenes()
    assert set(scenes) == set(validation.cases())
    assert {n for n, p in scenes.items() if p is not None} == {p.stem for p in FILES} & set(scenes)
    assert all(p is None or p == SCENES / f"{n}.toml" for n, p in scenes.items())
    assert set(trade.STUDIES) <= {n for n, p in scenes.items() if p is not None}  # a study runs the case's scene


def _resolved(scene) -> dict:
    """The scene's fields, each file named by its absolute path (a file names a record
    relative to itself, a case by its place in the package)."""
    def walk(v, key=None):
        if isinstance(v, dict):
            return {k: walk(x, k) for k, x in v.items()}
        if isinstance(v, list):
            return [walk(x) for x in v]
        return str(Path(v).resolve()) if key == "file" else v

    return walk(scene.to_dict())


@pytest.mark.long
def test_a_case_that_runs_its_scene_runs_the_file_as_written():
    """A case that builds its run from its scene (``Case.scene``) runs the file unchanged in
    one variant (the quick one's, or the full one's where the file is an example's): a
    user's ``cosim run`` of the file is that variant's set-up, field for field. The other
    variant's scene is checked on construction, as ``cosim run --set`` would be."""
    known = validation.cases()
    runs = {n: c for n, c in known.items() if c.scene is not None}
    for name, c in runs.items():
        file = _resolved(Scene.from_toml(SCENES / f"{name}.toml"))
        variants = (c.scene(True), c.scene(False))
        assert all(isinstance(s, Scene) for s in variants), name
        assert file in map(_resolved, variants), f"{name}: neither variant runs {name}.toml as written"
    assert len(runs) >= 9, sorted(runs)
