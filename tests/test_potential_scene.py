"""The potential-flow fluid in a scene: `fluid.model = "potential"` runs, its heave in regular
waves is the frequency-domain response of its coefficients, and a machine without Capytaine is
told which extra to install."""

from __future__ import annotations

import builtins
import sys

import numpy as np
import pytest

from cosim.scene import Scene
from cosim.scene.fields import SceneError

SCENE = {
    "world": {"dim": 3, "duration": 30.0, "sample_every": 0.05},
    "fluid": {"model": "potential", "panel_size": 1.0, "omega_max": 3.0, "frequencies": 20},
    "waves": {"kind": "linear", "height": 0.2, "period": 6.0, "depth": 20.0, "ramp": 1.0},
    "bodies": [{"shape": "cylinder", "name": "buoy", "radius": 3.0, "length": 3.0, "pos": [0.0, 0.0],
                "place": "floating", "density": 500.0}],
    "probes": {"gauges": [[0.0, 0.0]]},
}


@pytest.mark.long
@pytest.mark.skipif(not all(m in sys.modules or __import__("importlib").util.find_spec(m) for m in
                            ("capytaine", "h5netcdf")), reason="needs the potential extra")
def test_scene_runs_and_heaves_as_the_frequency_domain_predicts(tmp_path):
    from cosim.scene.build import build
    from cosim.validations.potential import frequency_domain_rao

    scene = Scene.from_dict(SCENE)
    (tmp_path / "s.toml").write_text(scene.to_toml())
    assert Scene.from_toml(tmp_path / "s.toml") == scene
    res = scene.run(tmp_path / "out", progress=False)
    t, z, eta = res.t, res["buoy.heave"], res["gauge1.eta"]
    late = t >= 18.0  # after the fade-in (6 s) and the impulse response's memory
    built = build(scene, tmp_path / "work")
    c, b = built.fluid.coefficients[0], built.bodies
    rao = frequency_domain_rao(c, float(b.masses()[0]), float(b.dof_inertia(0)[4]), 2 * np.pi / 6.0)
    assert np.ptp(eta[late]) / 2 == pytest.approx(0.1, rel=1e-3)  # the gauge reads the wave
    assert np.ptp(z[late]) / 2 == pytest.approx(abs(rao[1]) * 0.1, rel=0.03)


def test_without_capytaine_the_scene_names_the_extra(monkeypatch):
    real = builtins.__import__

    def no_capytaine(name, *args, **kwargs):
        if name.split(".")[0] == "capytaine":
            raise ImportError("No module named 'capytaine'", name="capytaine")
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_capytaine)
    with pytest.raises(SceneError, match=r"fluid.model: \"potential\" needs Capytaine and h5netcdf \(capytaine is "
                                         r"not installed\): pip install cosim-sph\[potential\]"):
        Scene.from_dict(SCENE)
