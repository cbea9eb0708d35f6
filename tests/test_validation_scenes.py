"""Validation cases as scenes: a case's scene file (cosim/validations/scenes/CASE.toml) loads as
a Scene; every scene file there belongs to a case; the studied cases are scenes.
``python benchmarks/validation_scenes.py`` prints which cases are scenes and which are not."""

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
