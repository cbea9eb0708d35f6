"""The SPH fluid's settings are declared once (fluid.settings.SETTINGS): FluidConfig, the
scene's SPH fluid and its set-up chooser all take them from that table, with the same
default and range, and each refuses a value outside the range naming the field."""

import dataclasses
import math
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from cosim.errors import InputError
from cosim.scene import SPH, Scene, Tank, World
from cosim.scene.build import fluid_config
from cosim.scene.fields import SceneError, spec_fields
from cosim.scene.limits import MAX_DENSITY
from cosim.scene.setup import CONFIG_FIELDS, choose
from fluid import kernels, settings
from fluid.settings import SETTINGS, Setting
from fluid.solver import FluidConfig

ROOT = Path(__file__).resolve().parents[1]
CHECKED = [s for s in SETTINGS if s.kind is not object]  # object: checked by FluidConfig's own code
IN_SCENE = [s for s in SETTINGS if s.scene]


def _base(s):
    """FluidConfig's other arguments: exactly one of c0 and u_max, never the one tested."""
    return {"u_max": 1.0} if s.name == "c0" else {"c0": 30.0}


def _refused(s):
    """Values outside the setting's range or choices, or of another kind."""
    if s.choices:
        return [4 if s.kind is int else "nonsense", True]
    if s.kind is bool:
        return ["no", 1]
    if s.kind is str:
        return [3]
    out = ["1.0", True]
    if s.lo is not None:
        out.append(s.lo if s.lo_open else s.lo - (1 if s.kind is int else 1e-9))
    if s.hi is not None:
        out.append(s.hi if s.hi_open else s.hi + (1 if s.kind is int else 1e-9))
    if s.kind is float:
        out += [math.nan] + ([math.inf] if s.finite else [])
    else:
        out.append(1.5)
    return out


def _accepted(s):
    """Values at the closed ends of its range, and each choice (not cuda: this machine may
    have no GPU)."""
    if s.choices:
        return [c for c in s.choices if c != "cuda"]
    if s.kind is bool:
        return [True, False]
    return [b for b, is_open in ((s.lo, s.lo_open), (s.hi, s.hi_open)) if b is not None and not is_open]


def _other_value(s):
    """A value the setting accepts that is not its default."""
    if s.choices:
        return next(c for c in s.choices if c != s.default)
    if s.kind is bool:
        return not s.default
    if s.kind is int:
        return s.lo + 1
    return 0.5 * (s.lo + s.hi) if s.hi is not None else s.lo + 20.0


def test_fluid_config_has_one_field_per_setting_with_its_default():
    fields = dataclasses.fields(FluidConfig)
    assert [f.name for f in fields] == [s.name for s in SETTINGS]
    assert [f.default for f in fields] == [s.default for s in SETTINGS]
    assert FluidConfig(c0=30.0).h_coef == math.sqrt(2.0) and FluidConfig(c0=30.0).walls == "dbc"


@pytest.mark.parametrize("s", CHECKED, ids=lambda s: s.name)
def test_fluid_config_refuses_out_of_range_values_naming_the_field(s):
    for v in _refused(s):
        with pytest.raises(InputError, match=rf"^FluidConfig: {s.name}=.*; give .*\({s.doc[:20]}") as e:
            FluidConfig(**_base(s), **{s.name: v})
        assert s.expected() in str(e.value)
    for v in _accepted(s):
        assert getattr(FluidConfig(**_base(s), **{s.name: v}), s.name) == v


def test_the_refusal_says_the_range_the_unit_and_the_usual_values():
    with pytest.raises(InputError) as e:
        FluidConfig(c0=30.0, h_coef=0.5)
    assert str(e.value) == ("FluidConfig: h_coef=0.5; give a number >= 1 and <= 3 (smoothing length / dx); "
                            "1.2 ... 2 is usual")
    with pytest.raises(InputError, match=r"^FluidConfig: dx=-0.01 m; give a number \[m\] > 0 \(particle spacing\)$"):
        FluidConfig(c0=30.0, dx=-0.01)
    with pytest.raises(InputError, match=r"threads=0; give a whole number >= 1 or None"):
        FluidConfig(c0=30.0, threads=0)
    assert FluidConfig(c0=30.0, dt_max=math.inf).dt_max == math.inf  # the one number that may be infinite


def test_sph_mirrors_the_settings_a_scene_sets_with_the_same_range():
    fields = {name: (check, default) for name, check, default in spec_fields(SPH)}
    assert {s.name for s in IN_SCENE} <= fields.keys()
    assert not {s.name for s in SETTINGS if not s.scene} & fields.keys()
    for s in IN_SCENE:
        check, default = fields[s.name]
        assert check.doc == s.doc and check.unit == s.unit, s.name
        assert default == {"set-up": None, "default": s.default, "required": dataclasses.MISSING}[s.scene], s.name
        assert check.optional == (s.scene == "set-up"), s.name
        if s.choices:
            assert check.choices == s.choices
        elif s.kind in (int, float):
            hi = MAX_DENSITY if s.name == "rho0" else s.hi  # the scene's limit of matter (cosim.scene.limits)
            assert (check.lo, check.hi) == (s.lo, hi), s.name
            if s.kind is float:
                assert (check.lo_open, check.hi_open) == (s.lo_open, s.hi_open), s.name


@pytest.mark.parametrize("s", IN_SCENE, ids=lambda s: s.name)
def test_sph_refuses_what_fluid_config_refuses_naming_the_field(s):
    base = {} if s.name == "dx" else {"dx": 0.02}
    for v in _refused(s):
        with pytest.raises(SceneError) as e:
            SPH(**base, **{s.name: v})
        assert e.value.path == f"SPH.{s.name}"
    for v in _accepted(s):
        assert getattr(SPH(**base, **{s.name: v}), s.name) == v


def test_the_chooser_passes_every_setting_the_scene_sets():
    assert CONFIG_FIELDS == tuple(s.name for s in SETTINGS if s.scene == "set-up")
    assert kernels.KERNELS.keys() == set(settings.KERNELS)
    tank = Tank(length=0.5, height=0.3, depth=0.2)
    for name in CONFIG_FIELDS:
        s = next(s for s in SETTINGS if s.name == name)
        v = _other_value(s)
        scene = Scene(world=World(dim=2, duration=0.1), fluid=SPH(dx=0.02, **{name: v}), domain=tank)
        setup = choose(scene)
        assert setup.config[name] == v and name in setup.overridden, name
        if name != "device":  # cuda: this machine may have no GPU
            assert getattr(fluid_config(scene, setup), name) == v, name
    scene = Scene(world=World(dim=2, duration=0.1), fluid=SPH(dx=0.02, rho0=1025.0), domain=tank)
    assert choose(scene).config["rho0"] == fluid_config(scene, choose(scene)).rho0 == 1025.0
    assert "rho0" not in choose(scene).overridden


def test_a_setting_is_declared_in_one_place():
    """One entry added to the table (before anything imports it) is a FluidConfig field, an
    SPH field with its range, a TOML key, a row of the scene reference and a setting the
    chooser passes on, each refusing a value out of range by name."""
    code = textwrap.dedent("""
        import fluid.settings as fs
        fs.SETTINGS += (fs.Setting("test_option", 0.5, "an option for this test", "m", lo=0, hi=1, scene="set-up"),)
        from errors import InputError
        from fluid.solver import FluidConfig
        from cosim.scene import SPH, Scene, Tank, World
        from cosim.scene.build import fluid_config
        from cosim.scene.reference import markdown
        from cosim.scene.setup import choose

        assert FluidConfig(c0=30.0).test_option == 0.5
        try:
            FluidConfig(c0=30.0, test_option=2.0)
            raise SystemExit("FluidConfig took 2.0")
        except InputError as e:
            assert str(e).startswith("FluidConfig: test_option=2.0 m; give a number [m] >= 0 and <= 1"), e
        scene = Scene(world=World(dim=2, duration=0.1), fluid=SPH(dx=0.02), domain=Tank(length=0.5, height=0.3,
                      depth=0.2))
        assert scene.fluid.test_option is None and "test_option" not in choose(scene).config
        scene = scene.with_values(["fluid.test_option=0.7"])
        setup = choose(scene)
        assert setup.config["test_option"] == 0.7 and "test_option" in setup.overridden
        assert fluid_config(scene, setup).test_option == 0.7
        try:
            scene.with_values(["fluid.test_option=1.5"])
            raise SystemExit("the scene took 1.5")
        except InputError as e:
            assert "fluid.test_option" in str(e) and "<= 1 (an option for this test)" in str(e), e
        assert "| `test_option` | unset | m | a number [m] >= 0 and <= 1 (an option for this test) |" in markdown()
        print("ok")
    """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stdout + out.stderr


def test_a_setting_whose_default_is_outside_its_range_is_refused():
    with pytest.raises(ValueError, match="outside its own range"):
        Setting("bad", 2.0, "a setting", lo=0, hi=1)
    with pytest.raises(ValueError, match="optional"):
        Setting("bad", None, "a setting")
    with pytest.raises(ValueError, match="scene"):
        Setting("bad", 0.5, "a setting", scene="sometimes")
