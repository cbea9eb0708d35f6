"""docs/scenes.md is the field reference made from the declarations; it stays current."""

from pathlib import Path

from cosim.scene import spec
from cosim.scene.fields import spec_fields
from cosim.scene.reference import SECTIONS, markdown

DOC = Path(__file__).resolve().parents[1] / "docs" / "scenes.md"


def test_field_reference_is_current():
    assert DOC.read_text() == markdown(), "regenerate: python -m cosim.scene.reference > docs/scenes.md"


def test_every_scene_class_is_documented_with_every_field_explained():
    listed = {c for _, classes in SECTIONS for c in classes}
    classes = {v for v in vars(spec).values() if isinstance(v, type) and issubclass(v, spec.Spec)
               and v not in (spec.Spec,) and not v.__name__.startswith("_")}
    assert classes <= listed, sorted(c.__name__ for c in classes - listed)
    for cls in listed:
        assert cls.__doc__ and cls.__doc__.strip(), cls.__name__
        for name, check, _ in spec_fields(cls):
            assert check.doc, f"{cls.__name__}.{name} has no text"
