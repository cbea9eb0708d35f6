"""Fickian particle shifting (fluid.shifting; Lind et al. 2012, Skillen et al. 2013, the free
surface from the renormalisation matrix of Marrone et al. 2010): the loop against its
equations summed by brute force, a uniform lattice left in place, a disordered one made
more uniform, no shift along the free surface's normal nor beside a wall, positions the only
thing changed, and bad settings refused."""

import numpy as np
import pytest

from cosim.errors import InputError
from fluid import shifting
from fluid.geometry import tank_with_water
from fluid.kernels import KERNELS, W, grad_W
from fluid.neighbours import Grid, neighbour_pairs, sort_by_cell, x_bin_array
from fluid.particles import Kind
from fluid.solver import Fluid, FluidConfig

DX = 0.03
RHO0 = 1000.0


def _tank(dim=2, dx=DX, disorder=0.0, seed=0, length=0.6, depth=0.3):
    """Still water ``depth`` [m] deep in a tank ``length`` [m] long (3-D: 0.8 x 0.6 m, 0.5 m
    deep), particles of the fluid displaced by up to ``disorder`` dx in each direction."""
    if dim == 3:
        length, depth = 0.8, 0.5
    ps = tank_with_water(dim, dx, length, depth, depth, width=0.6 if dim == 3 else 0.0, layers=4).particles
    fl = ps.kind == Kind.FLUID
    ps.pos[fl] += disorder * dx * np.random.default_rng(seed).uniform(-1.0, 1.0, (fl.sum(), dim))
    return ps


def _shift(ps, h, dx=DX, D=1e-4, kernel="wendland"):
    """Sort ``ps`` by cell (in place) and return its shift with ``D = A h |v| dt`` [m^2]:
    every fluid particle moving at 1 m/s along x, A = 1, dt = D / h."""
    grid = Grid.covering(ps.pos.min(axis=0) - 0.1, ps.pos.max(axis=0) + 0.1, 2.0 * h, reach=1)
    perm, start, _, tab = sort_by_cell(ps.pos, grid, x_bin_array(grid))
    ps.permute(perm)
    vel = np.zeros_like(ps.pos)
    vel[ps.kind == Kind.FLUID, 0] = 1.0
    return shifting.fickian_shift(ps.pos, vel, ps.mass, ps.kind, start, tab, grid, KERNELS[kernel], h, dx, RHO0,
                                  1.0, D / h).copy()


def _sums(ps, h, dx=DX, kernel="wendland", tensile=True):
    """grad C_a [1/m] and B_a of every particle over its fluid neighbours (volumes m / rho0),
    and whether a boundary particle lies within 2h, summed by brute force over all pairs."""
    pos, n, dim = ps.pos, ps.n, ps.pos.shape[1]
    fluid = ps.kind == Kind.FLUID
    V = np.where(fluid, ps.mass / RHO0, 0.0)
    i, j = neighbour_pairs(pos, 2.0 * h).T
    walled = np.zeros(n, bool)
    walled[i[~fluid[j]]] = True
    r = pos[i] - pos[j]
    g = grad_W(r, h, kernel)
    w = W(np.linalg.norm(r, axis=1), h, dim, kernel) / W(np.array([dx]), h, dim, kernel)[0]
    gc, B = np.zeros((n, dim)), np.zeros((n, dim, dim))
    np.add.at(gc, i, (V[j] * (1.0 + (0.2 * w ** 4 if tensile else 0.0)))[:, None] * g)
    np.add.at(B, i, V[j, None, None] * (-r)[:, :, None] * g[:, None, :])
    return gc, B, walled


@pytest.mark.parametrize("dim, kernel, h_coef", [(2, "wendland", 2.0), (2, "cubic", 1.2), (3, "wendland", 2.0)])
def test_shift_is_its_equations_summed_by_brute_force(dim, kernel, h_coef):
    """delta r = -D grad C (Lind et al. 2012) where B's smallest eigenvalue is at least
    LAMBDA_FULL, -D (I - n n) grad C with n along B^-1 grad C below it; boundary particles
    and those within 2h of one stay put."""
    dx = DX if dim == 2 else 0.05
    h = h_coef * dx
    ps = _tank(dim, dx, disorder=0.15)
    D = 1e-4
    got = _shift(ps, h, dx, D, kernel)
    gc, B, walled = _sums(ps, h, dx, kernel)
    want = -D * gc
    free = (ps.kind == Kind.FLUID) & ~walled
    cut = free & (np.linalg.eigvalsh(B)[:, 0] < shifting.LAMBDA_FULL)
    n = np.linalg.solve(B[cut], gc[cut][:, :, None])[:, :, 0]
    n /= np.linalg.norm(n, axis=1)[:, None]
    want[cut] -= np.einsum("ij,ij->i", want[cut], n)[:, None] * n
    want[~free] = 0.0
    assert 0 < cut.sum() < free.sum()  # both regions are exercised
    assert (np.abs(got[free]).max(axis=1) > 0).all()
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-9 * np.abs(want).max())


@pytest.mark.parametrize("dim", [2, 3])
def test_a_uniform_lattice_moves_nothing(dim):
    """The square (cubic) lattice is the arrangement shifting aims at: in the bulk grad C
    vanishes, at the free surface it is normal to it and removed; so no particle moves
    (while grad C is 0.68 / h on the surface row: D times that would be a shift of 2 % of
    dx here)."""
    dx = DX if dim == 2 else 0.05
    h = 2.0 * dx
    ps = _tank(dim, dx)
    D = 1e-3 * h * h
    got = _shift(ps, h, dx, D)
    assert np.abs(got).max() < 1e-12 * dx
    gc, _, walled = _sums(ps, h, dx)
    assert D * np.linalg.norm(gc[~walled & (ps.kind == Kind.FLUID)], axis=1).max() > 5e-4 * dx


def test_a_disordered_lattice_becomes_more_uniform():
    """Particles displaced at random by up to 0.2 dx, shifted 50 times with D = 0.02 h^2:
    the concentration gradient in the bulk (farther than 2h from the walls and the surface)
    falls by half (h |grad C| RMS), the water keeps its level (the surface row moves by less
    than 1 % of dx) and no particle leaves the tank."""
    h = 2.0 * DX
    ps = _tank(disorder=0.2, length=1.2, depth=0.6)
    fl = ps.kind == Kind.FLUID

    def bulk_gradient():
        gc, _, walled = _sums(ps, h, tensile=False)
        x, z = ps.pos[:, 0], ps.pos[:, 1]
        inside = (ps.kind == Kind.FLUID) & ~walled & (z < 0.6 - 2.5 * h) & (x > 3 * h) & (x < 1.2 - 3 * h)
        return np.sqrt(np.mean((h * np.linalg.norm(gc[inside], axis=1)) ** 2))

    before, top = bulk_gradient(), np.sort(ps.pos[fl, 1])[-40:].mean()
    for _ in range(50):
        d = _shift(ps, h, D=0.02 * h * h)  # sorts ps anew: its arrays are replaced
        ps.pos += d
    fl = ps.kind == Kind.FLUID
    assert bulk_gradient() < 0.5 * before
    assert abs(np.sort(ps.pos[fl, 1])[-40:].mean() - top) < 0.01 * DX
    assert (ps.pos[fl, 0] > 0.0).all() and (ps.pos[fl, 0] < 1.2).all() and (ps.pos[fl, 1] > 0.0).all()


def test_a_surface_particle_is_shifted_along_the_surface_only():
    """A surface particle pushed 0.2 dx towards its neighbour along the surface: its shift
    takes it back along the surface (against the displacement), with no component along
    the surface's normal B^-1 grad C, whose direction is within a few degrees of the
    vertical; the same particle in the bulk moves back too."""
    h = 2.0 * DX
    for depth, surface in ((0.285, True), (0.165, False)):
        ps = _tank()
        a = int(np.flatnonzero((np.abs(ps.pos[:, 0] - 0.315) < 1e-9) & (np.abs(ps.pos[:, 1] - depth) < 1e-9))[0])
        pid = ps.ids[a]
        ps.pos[a, 0] -= 0.2 * DX
        got = _shift(ps, h, D=1e-4)
        a = int(np.flatnonzero(ps.ids == pid)[0])
        assert got[a, 0] > 0.0  # back towards its place
        gc, B, _ = _sums(ps, h)
        n = np.linalg.solve(B[a], gc[a])
        n /= np.linalg.norm(n)
        if surface:
            assert abs(n[1]) > np.cos(np.radians(10.0))
            assert abs(got[a] @ n) < 1e-12 * np.linalg.norm(got[a])
        else:
            np.testing.assert_allclose(got[a], -1e-4 * gc[a], rtol=1e-9, atol=1e-12 * DX)


def _sloshing_fluid(shift):
    ps = _tank(disorder=0.05)
    fl = ps.kind == Kind.FLUID
    ps.vel[fl, 0] = 0.2 * np.sin(np.pi * ps.pos[fl, 0] / 0.6) * np.cosh(np.pi * ps.pos[fl, 1] / 0.6)
    cfg = FluidConfig(dim=2, dx=DX, u_max=1.7, h_coef=2.0, walls="adami", diffusion_at_surface=False,
                      shifting="fickian" if shift else "none")
    f = Fluid(cfg, ps)
    f.initialize(0.0)
    return f


def test_shifting_moves_positions_only():
    """One step with and without shifting from the same state: the velocities, the fluid's
    densities and the masses are the same to the last bit (the shift comes after the step's
    update; the walls' densities are taken from the fluid's new places), so are the total
    mass and momentum; the fluid's positions differ, by the shift."""
    plain, shifted = _sloshing_fluid(False), _sloshing_fluid(True)
    dt = plain.max_dt()
    plain.step(dt)
    shifted.step(dt)
    p, s = (np.argsort(f.ps.ids) for f in (plain, shifted))
    np.testing.assert_array_equal(plain.ps.vel[p], shifted.ps.vel[s])
    fl = plain.ps.kind[p] == Kind.FLUID
    np.testing.assert_array_equal(plain.ps.rho[p][fl], shifted.ps.rho[s][fl])
    np.testing.assert_array_equal(plain.ps.mass[p], shifted.ps.mass[s])
    moved = np.linalg.norm(plain.ps.pos[p] - shifted.ps.pos[s], axis=1)
    assert 0.0 < moved.max() < 1e-3 * DX
    assert (moved[plain.ps.kind[p] != Kind.FLUID] == 0.0).all()


@pytest.mark.parametrize("bad, field", [(dict(shifting="lagrangian"), "shifting"), (dict(shifting=True), "shifting"),
                                        (dict(shifting_coef=0.0), "shifting_coef"),
                                        (dict(shifting_coef=-1.0), "shifting_coef"),
                                        (dict(shifting_coef=7.0), "shifting_coef"),
                                        (dict(shifting="fickian", device="cuda"), "shifting")])
def test_bad_settings_are_refused(bad, field):
    """Unknown kinds and coefficients outside Skillen et al.'s range are refused naming
    the field; the GPU path has no shifting and refuses it rather than run without."""
    with pytest.raises(InputError, match=field):
        FluidConfig(c0=10.0, **bad)
