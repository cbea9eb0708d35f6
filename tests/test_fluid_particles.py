"""ParticleSet: construction checks and reordering."""

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.particles import Kind, ParticleSet


def test_create_defaults_and_permute():
    pos = np.arange(10.0).reshape(5, 2)
    kind = [0, 0, 1, 1, 0]
    ps = ParticleSet.create(pos, rho=1000.0, mass=0.1, kind=kind)
    assert ps.n == 5 and ps.dim == 2
    assert ps.kind.dtype == np.int8 and ps.group.tolist() == [-1, -1, 0, 0, -1]
    perm = np.array([4, 3, 2, 1, 0])
    ps.permute(perm)
    assert ps.ids.tolist() == [4, 3, 2, 1, 0]
    assert np.array_equal(ps.pos, pos[perm])
    assert ps.kind.tolist() == kind[::-1]


def test_permute_reorders_companion_arrays_in_the_same_pass():
    rng = np.random.default_rng(3)
    ps = ParticleSet.create(rng.random((50, 3)), rho=1000.0 + rng.random(50), mass=0.1)
    old = ps.copy()
    vel_prev, rho_prev = rng.random((50, 3)), rng.random(50)
    perm = rng.permutation(50)[:40]  # a permutation that also drops particles
    v, r = ps.permute(perm, vel_prev, rho_prev)
    for f in ParticleSet.FIELDS:
        assert np.array_equal(getattr(ps, f), getattr(old, f)[perm]), f
    assert np.array_equal(v, vel_prev[perm]) and np.array_equal(r, rho_prev[perm])


@pytest.mark.parametrize("bad", [
    dict(pos=np.zeros((3, 4))),
    dict(rho=-1.0),
    dict(mass=0.0),
    dict(pos=np.array([[0.0, np.nan]] * 3)),
    dict(kind=[0, 7, 0]),
    dict(kind=[0, 1, 0], group=[-1, -1, -1]),
])
def test_bad_input_is_refused(bad):
    args = dict(pos=np.zeros((3, 2)), rho=1000.0, mass=1.0)
    args.update(bad)
    with pytest.raises(InputError):
        ParticleSet.create(**args)


def test_concatenate_renumbers():
    a = ParticleSet.create(np.zeros((2, 3)), 1000.0, 1.0)
    b = ParticleSet.create(np.ones((3, 3)), 1000.0, 1.0, kind=Kind.FIXED_WALL)
    c = ParticleSet.concatenate([a, b])
    assert c.n == 5 and c.ids.tolist() == [0, 1, 2, 3, 4]
    assert c.kind.tolist() == [0, 0, 1, 1, 1]


def test_fluid_imports_neither_mujoco_nor_the_coupler():
    import subprocess
    import sys

    code = ("import sys, fluid.solver, fluid.geometry, fluid.integrator; "
            "bad = [m for m in sys.modules if m.startswith('mujoco') or "
            "m.startswith('cosim')]; print(bad)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
