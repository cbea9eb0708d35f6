"""MLS density re-initialisation (fluid.mls, Sunara et al. 2021, Eq. 9-12): exact
for constant and linear density fields (first-order consistency), Shepard fallback where
the moment matrix is degenerate, wired into the solver every ``mls_every`` steps."""

import math

import numpy as np
import pytest

from cosim.errors import InputError
from fluid import mls
from fluid.equations import hydrostatic_density
from fluid.geometry import block, set_hydrostatic, tank_with_water
from fluid.kernels import W, alpha_d, kernel_id
from fluid.neighbours import Grid, sort_by_cell
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig

DX = 0.01


def _reinit(pos, rho, mass, kind, kernel="wendland"):
    """Sort, re-initialise, return (positions, old rho, new rho, used) in sorted order."""
    dim = pos.shape[1]
    h = math.sqrt(2) * DX
    grid = Grid.covering(pos.min(0) - 4 * h, pos.max(0) + 4 * h, 2 * h)
    perm, start, _ = sort_by_cell(pos, grid)
    k = kernel_id(kernel)
    new, used = mls.reinitialise(pos[perm], rho[perm], mass[perm], kind[perm], start, grid, k,
                                 alpha_d(k, dim, h), h)
    return pos[perm], rho[perm], new, used


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("kernel", ["wendland", "cubic"])
def test_uniform_lattice_is_exact_everywhere(dim, kernel):
    # m = rho dx^dim on a lattice: rho = 1000 at every particle, corners and faces included
    # (the Shepard sum would give 1000 too only far from the edges)
    p = block(np.zeros(dim), [0.1] * dim, DX)
    n = len(p)
    _, _, new, used = _reinit(p, np.full(n, 1000.0), np.full(n, 1000 * DX**dim), np.zeros(n, np.int8), kernel)
    np.testing.assert_allclose(new, 1000.0, rtol=1e-12)
    assert used.all()


@pytest.mark.parametrize("dim", [2, 3])
def test_linear_density_field_is_reproduced(dim):
    # a linear field (a hydrostatic gradient plus a horizontal one, 10 % over the block) with
    # masses m_b = rho_b dx^dim: MLS is first-order consistent, so it is reproduced exactly,
    # also at the free surface and the corners, where the support is truncated
    p = block(np.zeros(dim), [0.1] * dim, DX)
    n = len(p)
    rho = 1000.0 + 800.0 * (0.1 - p[:, -1]) + 300.0 * p[:, 0]
    pos, old, new, used = _reinit(p, rho, rho * DX**dim, np.zeros(n, np.int8))
    np.testing.assert_allclose(new, old, rtol=1e-11)
    # the zeroth-order Shepard filter is off by a first-order amount at the surface
    h = math.sqrt(2) * DX
    top = np.argmax(pos[:, -1] + 1e-3 * pos[:, 0])
    w = W(np.linalg.norm(pos - pos[top], axis=1), h, dim) * DX**dim
    shepard = (old * w).sum() / w.sum()
    assert abs(shepard - old[top]) > 1.0  # kg/m^3: the bias MLS removes


def test_boundary_neighbours_complete_the_support_and_keep_their_density():
    # fluid over a wall layer, both on one linear field: the fluid next to the wall is exact
    # and the wall particles keep their own (continuity-equation) density
    p = block([0.0, -0.03], [0.1, 0.1], DX)
    n = len(p)
    kind = np.where(p[:, 1] < 0, Kind.FIXED_WALL, Kind.FLUID).astype(np.int8)
    rho = 1000.0 + 500.0 * (0.1 - p[:, 1])
    pos, old, new, used = _reinit(p, rho, rho * DX**2, kind)
    fl = pos[:, 1] > 0
    np.testing.assert_allclose(new[fl], old[fl], rtol=1e-11)
    np.testing.assert_array_equal(new[~fl], old[~fl])
    assert not used[~fl].any()


def test_degenerate_support_falls_back_to_shepard():
    # a one-particle-wide vertical jet: the neighbours lie on a line, A is singular in x;
    # the Shepard filter gives the kernel-weighted mean, finite and within the field's range
    z = DX * (0.5 + np.arange(20))
    p = np.stack([np.zeros_like(z), z], axis=1)
    rho = 1000.0 + 100.0 * z
    pos, old, new, used = _reinit(p, rho, rho * DX**2, np.zeros(len(p), np.int8))
    assert not used.any()
    assert np.isfinite(new).all()
    assert (new >= old.min() - 1e-9).all() and (new <= old.max() + 1e-9).all()
    # in the middle of the jet the mean of a linear field is the local value
    mid = np.argsort(pos[:, 1])[10]
    assert new[mid] == pytest.approx(old[mid], rel=1e-12)


def test_config_rejects_bad_mls_every():
    for bad in (-1, 2.5, True):
        with pytest.raises(InputError, match="mls_every"):
            FluidConfig(u_max=1.0, mls_every=bad)


def test_solver_reinitialises_every_n_steps_and_keeps_the_hydrostatic_state():
    # a hydrostatic column with 0.2 % random density noise: the noise stays for 4 steps
    # and the 5th step's re-initialisation removes most of it
    g, H = 9.81, 0.1
    b = tank_with_water(2, 0.01, 0.1, H, 0.12)
    cfg = FluidConfig(dim=2, dx=0.01, u_max=math.sqrt(g * H), c0_factor=20.0, mls_every=5,
                      diffusion="none")  # isolate the re-initialisation
    ps = b.particles
    set_hydrostatic(ps, H, 1000.0, cfg.speed_of_sound, cfg.gamma, g)
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    fl = f.ps.kind == Kind.FLUID
    rng = np.random.default_rng(1)
    f.ps.rho[fl] *= 1 + 2e-3 * rng.standard_normal(fl.sum())  # 0.2 % density noise
    f._rates()

    def noise():  # RMS relative deviation of the fluid density from the hydrostatic one
        fl = f.ps.kind == Kind.FLUID
        ref = hydrostatic_density(H - f.ps.pos[fl, 1], 1000.0, cfg.speed_of_sound, cfg.gamma, g)
        return float(np.sqrt(np.mean((f.ps.rho[fl] / ref - 1) ** 2)))

    before = noise()
    for _ in range(4):
        f.step(f.max_dt())
    assert noise() == pytest.approx(before, rel=0.2)  # nothing happens before step 5
    f.step(f.max_dt())
    # the MLS step removes most of the lattice-scale noise (a smoothing of radius 2h)
    assert noise() < 0.5 * before
