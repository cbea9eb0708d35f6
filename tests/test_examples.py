"""Every example runs at its default settings (users copy them); the SPH examples,
whose default runs take a minute or more, run at their defaults in the slow tier and
at a tiny size in the fast one."""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.py"))
#: examples whose default run is too long for the fast tier (minutes of SPH)
SLOW = {"moored_box_waves"}


def _run(args, timeout=1800):
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.mark.parametrize("path", [pytest.param(p, marks=pytest.mark.slow) if p.stem in SLOW else p
                                  for p in EXAMPLES], ids=[p.stem for p in EXAMPLES])
def test_example_runs(path, tmp_path):
    out = _run([path, "--out", tmp_path])
    assert out.returncode == 0, out.stderr[-3000:]
    assert list(tmp_path.iterdir()), "the example wrote no output"


def test_moored_box_in_waves_tiny(tmp_path):
    """The main example at dx = 3 cm for 0.6 s: every output is written and holds
    finite, sensible numbers (the box floats near its draft, the lines pull)."""
    import h5py

    path = Path(__file__).resolve().parents[1] / "examples" / "moored_box_waves.py"
    out = _run([path, "--dx", "0.03", "--duration", "0.6", "--snapshot-every", "0.3", "--out", tmp_path])
    assert out.returncode == 0, out.stderr[-3000:]
    assert "particles" in out.stdout and "steps" in out.stdout
    for name in ("run.h5", "run.xmf", "ledger.csv", "motion.png", "tensions.png"):
        assert (tmp_path / name).stat().st_size > 0, name
    with h5py.File(tmp_path / "run.h5") as f:
        z = f["series/body/z"][:]
        tension = f["series/fairleads/tension"][:]
        eta = f["series/gauges/eta"][:]
        assert len(f["snapshot_times"]) == 3  # t = 0, 0.3, 0.6 s
        F = f["series/ledger/box/fluid_force"][:]
    assert np.isfinite(z).all() and np.isfinite(tension).all() and np.isfinite(F).all()
    # afloat: the centre stays within a few mm of its Archimedes height (0.3 m + 0.05 - 0.05)
    assert np.abs(z - 0.3).max() < 0.02
    # the lines hang: each pulls with a tension of order w * (suspended length) ~ 1 N
    assert (tension > 0.3).all() and (tension < 5.0).all()
    # the fluid carries the box: buoyancy ~ its weight 500 * 0.2 * 0.1 * 9.81 = 98 N (+ the lines' pull)
    assert 80.0 < np.median(F[:, 2]) < 120.0
    assert np.abs(eta).max() < 0.05


def _load_example(stem):
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "examples" / f"{stem}.py"
    spec = importlib.util.spec_from_file_location(f"example_{stem}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_light_body_option_reaches_the_coupler(tmp_path, capsys):
    """``--light-body`` parses to the coupler's ``light_body`` (default auto, which
    leaves this box of half the water's density uncorrected: ratio 0.5 > 0.3) and the
    coupler applies the forced choice; a wrong value is refused listing the choices.
    The scene is only built (dx = 5 cm, no step)."""
    ex = _load_example("moored_box_waves")
    assert ex.parse_args([]).light_body == "auto"
    assert ex.parse_args(["--light-body", "subiterate"]).light_body == "subiterate"
    for mode, remedy in (("auto", "none"), ("subiterate", "subiterate"), ("none", "none")):
        coupler, *_ = ex.build(0.05, 0.04, 1.0, "catenary", tmp_path, light_body=mode)
        assert coupler.light_body == mode and coupler.remedies == {"box": remedy}
        assert coupler.added_mass.ratio[0] == pytest.approx(0.5, rel=0.02)
    with pytest.raises(SystemExit):
        ex.parse_args(["--light-body", "implicit"])
    err = capsys.readouterr().err
    assert "invalid choice: 'implicit'" in err and "auto" in err and "added-mass" in err
    from cosim.added_mass import LIGHT_BODY
    with pytest.raises(SystemExit):
        ex.parse_args(["--help"])
    help_text = " ".join(capsys.readouterr().out.split())
    assert all(f"{k}:" in help_text for k in LIGHT_BODY) and "mass / displaced fluid mass" in help_text
