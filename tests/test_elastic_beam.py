"""Elastic cantilever (bodies/elastic.py) on its own, against Euler-Bernoulli and
Timoshenko beam theory: static tip deflections, the first three natural frequencies,
second-order convergence, time-stepped behaviour, the coupling helpers and bad input.

Yang & Li 2020 (§3.3): a plate b = 1.2 cm thick
and 20b/3 = 8 cm high, rho_s = 2500 kg/m^3, E = 1e6 Pa, clamped to the floor; 1 m
deep (2-D). L/h = 6.7: stubby, so Timoshenko is the reference (Euler-Bernoulli is
off by 1.5, 10 and 21 % on the first three frequencies)."""

import math

import mujoco
import numpy as np
import pytest

from bodies import builders
from bodies.elastic import (BETA_L, ElasticBody, elastic_beam, link_wrenches, linearise, modal_frequencies,
                            timoshenko_frequencies)
from bodies.mujoco_bodies import MujocoBodies
from bodies.sampling import place
from cosim.errors import InputError, InstabilityError

SEED = dict(length=0.08, thickness=0.012, E=1e6, rho=2500.0)  # Yang & Li 2020, §3.3, 2-D (W = 1 m)
SLENDER = dict(length=0.5, thickness=0.005, width=0.02, E=2e9, rho=1200.0)  # L/h = 100


def compiled(beam, **kw):
    kw = {"gravity": 0.0, "timestep": 1e-4, **kw}
    m = mujoco.MjModel.from_xml_string(builders.scene(beam.xml, **kw))
    return m, mujoco.MjData(m)


def frequencies(beam):
    return modal_frequencies(*compiled(beam))[:3]


def static_tip(beam, load):
    """Tip x deflection [m] of the linearised MuJoCo chain under ``load``: "tip" (1 N at
    the tip) or "uniform" (1 N/m, each link's share at its centre of mass)."""
    m, d = compiled(beam)
    K, _ = linearise(m, d)
    jp = np.zeros((3, m.nv))
    tip = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, f"{beam.name}_tip")
    if load == "tip":
        mujoco.mj_jacSite(m, d, jp, None, tip)
        tau = jp[0] * 1.0
    else:
        tau = np.zeros(m.nv)
        for k, (z0, z1) in enumerate(beam.link_bounds):
            b = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, f"{beam.name}_link{k}")
            mujoco.mj_jacBodyCom(m, d, jp, None, b)
            tau += jp[0] * (z1 - z0)
    x0 = d.site_xpos[tip, 0]
    q = np.linalg.solve(K, tau)
    scale = 1e-5 / np.abs(q).max()  # read through MuJoCo's kinematics at a small deflection
    d.qpos[:] = q * scale
    mujoco.mj_forward(m, d)
    return (d.site_xpos[tip, 0] - x0) / scale


# -- the reference itself ------------------------------------------------------------

def test_timoshenko_equation_tends_to_euler_bernoulli_for_slender_beams():
    b = elastic_beam("s", length=1.0, thickness=1e-3, E=1e9, rho=1000.0)
    f_t = timoshenko_frequencies(1.0, 1e-3, 1e9, 1000.0, n=3)
    # the Timoshenko correction is O((beta_n h)^2): 1e-5 on the third mode at h/L = 1e-3
    assert f_t == pytest.approx(b.natural_frequencies(theory="euler-bernoulli"), rel=2e-5)
    for x in BETA_L:
        assert 1 + math.cos(x) * math.cosh(x) == pytest.approx(0.0, abs=1e-9)


def test_seed_plate_is_stubby_so_timoshenko_differs_from_euler_bernoulli():
    b = elastic_beam("p", **SEED)
    eb, tim = b.natural_frequencies(theory="euler-bernoulli"), b.natural_frequencies()
    assert eb == pytest.approx([6.0578, 37.963, 106.30], rel=1e-4)
    assert tim == pytest.approx([5.9704, 34.587, 87.635], rel=1e-4)
    assert (eb / tim - 1) == pytest.approx([0.0146, 0.0976, 0.2130], abs=5e-4)


# -- frequencies -----------------------------------------------------------------------

def test_seed_plate_first_three_frequencies_within_two_percent_of_timoshenko():
    b = elastic_beam("p", **SEED, n_elements=16)
    err = frequencies(b) / b.natural_frequencies() - 1
    assert np.abs(err).max() < 0.003  # measured 0.09, 0.25, 0.25 %


def test_slender_beam_first_three_frequencies_within_two_percent_of_euler_bernoulli():
    for shear in (True, False):
        b = elastic_beam("s", **SLENDER, n_elements=16, shear=shear)
        err = frequencies(b) / b.natural_frequencies(theory="euler-bernoulli") - 1
        assert np.abs(err).max() < 0.005, (shear, err)


def test_frequencies_converge_at_second_order():
    errs = []
    for n in (4, 8, 16, 32):
        b = elastic_beam("p", **SEED, n_elements=n)
        errs.append(np.abs(frequencies(b) / b.natural_frequencies() - 1))
    errs = np.array(errs)  # rows: N, columns: mode
    assert (np.diff(errs, axis=0) < 0).all()
    order = np.log2(errs[:-1] / errs[1:])
    assert order[1:].min() > 1.9 and order.max() < 2.2, order  # observed 1.98-2.07


# -- statics ---------------------------------------------------------------------------

@pytest.mark.parametrize("load", ["tip", "uniform"])
def test_seed_plate_static_tip_deflection_meets_timoshenko(load):
    errs = []
    for n in (8, 16, 32):
        b = elastic_beam("p", **SEED, n_elements=n)
        ref = b.tip_deflection_point(1.0) if load == "tip" else b.tip_deflection_uniform(1.0)
        errs.append(static_tip(b, load) / ref - 1)
    errs = np.abs(errs)
    assert errs[1] < 0.005 and (np.diff(errs) < 0).all()
    assert np.log2(errs[0] / errs[1]) == pytest.approx(2.0, abs=0.1)
    # the shear term matters here: Euler-Bernoulli alone is 1.3 % (tip) / 1.8 % (uniform) short
    b = elastic_beam("p", **SEED)
    eb = b.tip_deflection_point(1.0, "euler-bernoulli") if load == "tip" else \
        b.tip_deflection_uniform(1.0, "euler-bernoulli")
    assert abs(static_tip(b, load) / eb - 1) > 0.01


def test_chain_statics_are_exactly_the_midpoint_rule_of_the_beam_integrals():
    """Hinges at element midpoints: the bending term is the midpoint rule of the
    deflection integral, ``(1 - 1/(4 N^2))`` (tip load) and ``(1 - 1/(2 N^2))`` (uniform),
    the shear term exact (bodies/elastic.py docstring)."""
    for n in (4, 16):
        b = elastic_beam("p", **SEED, n_elements=n)
        for load, eb, tim, c in (("tip", b.tip_deflection_point(1.0, "euler-bernoulli"),
                                  b.tip_deflection_point(1.0), 4),
                                 ("uniform", b.tip_deflection_uniform(1.0, "euler-bernoulli"),
                                  b.tip_deflection_uniform(1.0), 2)):
            assert static_tip(b, load) == pytest.approx(tim - eb / (c * n * n), rel=1e-8)


@pytest.mark.parametrize("load", ["tip", "uniform"])
def test_slender_beam_static_tip_deflection_meets_euler_bernoulli(load):
    b = elastic_beam("s", **SLENDER, n_elements=16)
    ref = (b.tip_deflection_point(1.0, "euler-bernoulli") if load == "tip"
           else b.tip_deflection_uniform(1.0, "euler-bernoulli"))
    assert static_tip(b, load) == pytest.approx(ref, rel=0.005)


# -- a hanging beam: clamped at its top (Antoci et al. 2007's rubber gate) -------------------

GATE = dict(length=0.079, thickness=0.005, E=12e6, rho=1100.0, nu=0.4)  # refdata elastic_gate_antoci2007 SOURCE.txt


@pytest.mark.parametrize("load", ["tip", "uniform"])
def test_hanging_gate_static_tip_deflection_meets_timoshenko(load):
    """The gate (L/h = 15.8) hanging from its top, under a lateral load along x: the tip
    deflection meets Timoshenko within 0.5 % at N = 16, converges at second order, and is
    the upright beam's to round-off (the same chain turned half a turn about x)."""
    errs = []
    for n in (8, 16, 32):
        down = elastic_beam("g", **GATE, n_elements=n, direction="down", base=(0.1, 0.0, 0.14))
        ref = down.tip_deflection_point(1.0) if load == "tip" else down.tip_deflection_uniform(1.0)
        d = static_tip(down, load)
        assert d == pytest.approx(static_tip(elastic_beam("g", **GATE, n_elements=n), load), rel=1e-7)
        errs.append(abs(d / ref - 1))
    assert errs[1] < 0.005 and errs[0] > errs[1] > errs[2]
    assert np.log2(errs[0] / errs[1]) == pytest.approx(2.0, abs=0.1)


def test_hanging_beam_hangs_from_its_clamp():
    """Geometry: the free end L below the clamp, the corner on the -x face, the particles
    between clamp and tip; the first three frequencies (no gravity) within 0.5 % of
    Timoshenko; gravity stiffens the hanging beam and softens the upright one."""
    base = np.array([0.1, 0.0, 0.14])
    b = elastic_beam("g", **GATE, n_elements=16, direction="down", base=tuple(base))
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0), bodies=b.link_names)
    tip, corner = (body.site_positions([body.site(f"g_{s}")[0]])[0] for s in ("tip", "corner"))
    assert tip == pytest.approx(base - [0.0, 0.0, 0.079], abs=1e-12)
    assert corner == pytest.approx(base - [0.0025, 0.0, 0.079], abs=1e-12)
    pts, owner = b.boundary_particles(0.001, layers=2, dim=2)
    x, _ = place(pts, owner, body.kinematics())
    assert x[:, 2].min() == pytest.approx(0.14 - 0.079 + 0.0005, abs=1e-9) and x[:, 2].max() < 0.14
    assert np.abs(x[:, 0] - 0.1).max() == pytest.approx(0.0025 - 0.0005, abs=1e-9)
    err = frequencies(b) / b.natural_frequencies() - 1
    assert np.abs(err).max() < 0.005
    f1 = {}
    for direction in ("up", "down"):
        beam = elastic_beam("g", **GATE, n_elements=16, direction=direction)
        f1[direction] = modal_frequencies(*compiled(beam, gravity=9.81))[0]
    f0 = frequencies(b)[0]
    assert f1["up"] < f0 < f1["down"]


def test_a_direction_other_than_up_or_down_is_refused():
    with pytest.raises(InputError, match="direction must be \"up\".*\"down\""):
        elastic_beam("g", **GATE, direction="sideways")


def test_time_stepped_chain_settles_on_the_static_deflection_through_the_coupler_path():
    """MuJoCo itself (implicit damping, 1 ms) under a tip force given as a point force,
    mapped onto the tip link by link_wrenches and applied by MujocoBodies."""
    b = elastic_beam("p", **SEED, n_elements=8, beta=0.05)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0, timestep=1e-3, integrator="implicitfast"),
                        bodies=b.link_names)
    tip = body.site("p_tip")[0]
    x0 = body.site_positions([tip])[0].copy()
    P = 1e-3  # N: small, so that the linear theory holds
    t = 0.0
    for _ in range(150):
        kin = body.kinematics()
        F, T = link_wrenches(body.site_positions([tip]), [[P, 0.0, 0.0]], [b.n_elements], kin.com, len(b.link_names))
        body.set_wrenches(F, T)
        body.advance(t, 0.004)
        t += 0.004
    dx = body.site_positions([tip])[0] - x0
    assert dx[0] == pytest.approx(b.tip_deflection_point(P), rel=0.01)
    assert abs(dx[1]) < 1e-15  # stays in the x-z plane


def elastica_tip(alpha):
    """Tip (x/L, z/L) of the inextensible elastica clamped at s = 0 along z under a tip load
    of fixed direction x, ``alpha = P L^2 / (E I)``: ``theta'' = -alpha cos(theta)``,
    ``theta(0) = 0``, ``theta'(1) = 0`` (Bisshopp & Drucker 1945), by shooting."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    def shoot(k):
        rhs = lambda s, y: [y[1], -alpha * math.cos(y[0]), math.sin(y[0]), math.cos(y[0])]  # noqa: E731
        return solve_ivp(rhs, (0.0, 1.0), [0.0, k, 0.0, 0.0], rtol=1e-11, atol=1e-12).y[:, -1]

    y = shoot(brentq(lambda k: shoot(k)[1], 1e-9, alpha, xtol=1e-13))
    return y[2], y[3]


def test_large_deflection_meets_the_elastica():
    """P L^2 / (E I) = 2: the tip moves half the length sideways and drops 16 % (tip
    rotation 45 degrees, as in the dam-break case); the load keeps its direction while the
    tip link turns, applied through link_wrenches every step."""
    x_ref, z_ref = elastica_tip(2.0)
    assert (x_ref, z_ref) == pytest.approx((0.49346, 0.83936), abs=1e-5)  # alpha = 1 gives 0.30172, 0.94357
    b = elastic_beam("s", **SLENDER, n_elements=16, shear=False, beta=0.05)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0, timestep=1e-3, integrator="implicitfast"),
                        bodies=b.link_names)
    tip = body.site("s_tip")[0]
    x0 = body.site_positions([tip])[0].copy()
    P = 2.0 * b.E * b.I / b.length**2
    t = 0.0
    for _ in range(500):
        F, T = link_wrenches(body.site_positions([tip]), [[P, 0.0, 0.0]], [b.n_elements], body.kinematics().com,
                             len(b.link_names))
        body.set_wrenches(F, T)
        body.advance(t, 0.002)
        t += 0.002
    d = (body.site_positions([tip])[0] - x0) / b.length
    assert d[0] == pytest.approx(x_ref, rel=3e-3)  # measured -0.12 %
    assert 1.0 + d[2] == pytest.approx(z_ref, rel=1e-3)  # measured -0.03 % of the drop


# -- time stepping at the coupler's step -----------------------------------------------

def test_free_vibration_at_the_coupling_step_has_the_first_natural_frequency():
    b = elastic_beam("p", **SEED, n_elements=8)
    m, d = compiled(b, timestep=1e-4, integrator="RK4")
    K, _ = linearise(m, d)
    jp = np.zeros((3, m.nv))
    tip = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "p_tip")
    mujoco.mj_jacSite(m, d, jp, None, tip)
    x0 = d.site_xpos[tip, 0]
    d.qpos[:] = np.linalg.solve(K, jp[0] * 0.01)  # released from the static shape under a tip load
    x, dt = [], m.opt.timestep
    for _ in range(int(0.36 / dt)):  # a little over two periods
        mujoco.mj_step(m, d)
        x.append(d.site_xpos[tip, 0] - x0)
    x = np.array(x)
    up = np.flatnonzero((x[:-1] < 0) & (x[1:] >= 0))
    tz = (up + x[up] / (x[up] - x[up + 1])) * dt + dt  # interpolated upward zero crossings
    f1 = 1.0 / np.diff(tz).mean()
    assert f1 == pytest.approx(frequencies(b)[0], rel=0.01)
    assert f1 == pytest.approx(b.natural_frequencies()[0], rel=0.02)
    assert np.abs(x).max() < 1.01 * abs(x[0])  # no energy gained


def test_numpy_scalars_build_the_same_model():
    """nu and beta computed with numpy (np.float64) give the model plain floats give."""
    a = elastic_beam("p", **SEED, n_elements=8, nu=0.3, beta=1e-3)
    b = elastic_beam("p", **SEED, n_elements=8, nu=np.float64(0.3), beta=np.float64(1e-3))
    assert b.xml == a.xml
    m, _ = compiled(b)
    assert m.jnt_stiffness[0] > 0 and m.dof_damping[0] == pytest.approx(1e-3 * m.jnt_stiffness[0])


@pytest.mark.parametrize("beta", [0.0, 1e-3])
def test_stable_dt_is_the_rk4_limit(beta):
    """Undamped, 2 sqrt 2 / omega_max; stiffness-proportional damping (beta) is explicit
    under RK4 and shrinks it (by 3 here)."""
    b = elastic_beam("p", **SEED, n_elements=8, beta=beta)
    dt = b.stable_dt()
    assert dt > 1e-4  # the SPH step (~1e-5 to 1e-4 s) is inside it
    if beta == 0.0:
        w_max = 2 * math.pi * modal_frequencies(*compiled(b))[-1]
        assert dt == pytest.approx(2 * math.sqrt(2) / w_max, rel=1e-6)
    else:
        assert dt < 0.5 * elastic_beam("p", **SEED, n_elements=8).stable_dt()

    def peak(step):
        m, d = compiled(b, timestep=step, integrator="RK4")
        d.qvel[:] = 1e-3
        top = 0.0
        for _ in range(400):
            mujoco.mj_step(m, d)
            top = max(top, np.abs(d.qvel).max())
            if d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number:  # MuJoCo reset the state
                return math.inf
        return top

    assert peak(0.95 * dt) < 1.0  # bounded (the 1e-3 start spreads over the modes: ~0.15 rad/s peaks)
    assert not peak(1.05 * dt) < 100.0  # runs away (or overflows to inf/nan)


# -- coupling helpers ----------------------------------------------------------------

@pytest.mark.parametrize("dim", [2, 3])
def test_boundary_particles_follow_the_links_and_start_on_the_lattice(dim):
    b = elastic_beam("p", **SEED, n_elements=8, width=0.05, base=(0.3, 0.0, 0.01))
    dx = 0.0025
    pts, owner = b.boundary_particles(dx, layers=2, dim=dim)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0), bodies=b.link_names)
    x, u = place(pts, owner, body.kinematics())
    # undeformed: a cell-centred lattice over the plate, 2 layers inside the faces, foot face left out
    assert x[:, 0].min() == pytest.approx(0.3 - 0.006 + 0.0012, abs=1e-12)  # h = 0.012 m: 5 cells of 2.4 mm
    assert x[:, 2].max() == pytest.approx(0.01 + 0.08 - dx / 2, abs=1e-12)
    assert np.abs(u).max() == 0.0
    if dim == 2:
        assert (x[:, 1] == 0.0).all()
    else:
        assert np.abs(x[:, 1]).max() == pytest.approx(0.025 - dx / 2, abs=1e-12)
    assert set(np.unique(owner)) == set(range(b.n_elements + 1))
    # deformed and moving: each particle rides rigidly on its link (the tip link's particles
    # keep their distances to the tip site), velocities are the links' rigid-body velocities
    body.data.qpos[:] = 0.02
    body.data.qvel[:] = 0.3
    mujoco.mj_forward(body.model, body.data)
    x1, u1 = place(pts, owner, body.kinematics())
    on_tip = owner == b.n_elements
    tip = body.site_positions([body.site("p_tip")[0]])[0]
    rest_tip = np.array([0.3, 0.0, 0.09])
    assert np.linalg.norm(x1[on_tip] - tip, axis=1) == pytest.approx(np.linalg.norm(x[on_tip] - rest_tip, axis=1))
    h = 1e-7
    body.data.qpos[:] += h * body.data.qvel
    mujoco.mj_forward(body.model, body.data)
    x2, _ = place(pts, owner, body.kinematics())
    assert np.abs((x2 - x1) / h - u1).max() < 1e-5 * np.abs(u1).max()


def test_link_wrenches_keep_force_and_moment_exactly():
    rng = np.random.default_rng(0)
    n, n_links = 500, 9
    p = rng.normal(size=(n, 3))
    f = rng.normal(size=(n, 3))
    owner = rng.integers(0, n_links, n)
    com = rng.normal(size=(n_links, 3))
    F, T = link_wrenches(p, f, owner, com, n_links)
    assert F.sum(axis=0) == pytest.approx(f.sum(axis=0), abs=1e-12)
    # the moment about any point is kept: sum over links of T + com x F = sum over points of p x f
    assert (T + np.cross(com, F)).sum(axis=0) == pytest.approx(np.cross(p, f).sum(axis=0), abs=1e-11)


def test_elastic_body_forces_are_the_same_generalised_forces_as_point_forces():
    """One wrench per link at its centre of mass moves the chain exactly as the particle
    forces applied at the particles would (mj_applyFT each): the exchange is exact."""
    b = elastic_beam("p", **SEED, n_elements=8)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0), bodies=b.link_names)
    body.data.qpos[:] = np.linspace(0.05, 0.2, body.model.nq)  # bent
    mujoco.mj_forward(body.model, body.data)
    eb = ElasticBody(b, body, dx=0.002, layers=3, dim=2)
    x, _ = eb.place()
    f = np.random.default_rng(1).normal(size=x.shape) * [1.0, 0.0, 1.0]
    F, T = eb.wrenches(f)
    m, d = body.model, body.data
    by_point, by_link = np.zeros(m.nv), np.zeros(m.nv)
    for xi, fi, a, b, w in zip(x, f, eb.a, eb.b, eb.w):  # each split between its two links
        mujoco.mj_applyFT(m, d, w * fi, np.zeros(3), xi, int(body.body_ids[a]), by_point)
        mujoco.mj_applyFT(m, d, (1 - w) * fi, np.zeros(3), xi, int(body.body_ids[b]), by_point)
    com = body.kinematics().com
    for k, bid in enumerate(body.body_ids):
        mujoco.mj_applyFT(m, d, F[k], T[k], com[k], int(bid), by_link)
    assert by_link == pytest.approx(by_point, abs=1e-12 * np.abs(by_point).max())
    assert F.sum(axis=0) == pytest.approx(f.sum(axis=0), abs=1e-12)
    assert (T + np.cross(com, F)).sum(axis=0) == pytest.approx(np.cross(x, f).sum(axis=0), abs=1e-12)


def test_blended_particles_close_the_bent_surface_and_move_with_the_links():
    """Each particle blends its two links' frames (hat weights on nodes k l): undeformed
    they agree; bent, the outer face stays closed at every joint (rigid links alone open
    it by about h dtheta / 2), and the velocities are the time derivative of the placement."""
    b = elastic_beam("p", **SEED, n_elements=8)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0), bodies=b.link_names)
    dx = 0.001
    eb = ElasticBody(b, body, dx=dx, layers=1, dim=2)
    x0, _ = eb.place()
    assert x0[:, [0, 2]] == pytest.approx(eb.plate[:, [0, 2]], abs=1e-15)
    assert ((eb.w >= 0) & (eb.w <= 1)).all() and (eb.b == eb.a + 1).all()
    hinge = [mujoco.mj_name2id(body.model, mujoco.mjtObj.mjOBJ_JOINT, f"p_bend{k}") for k in range(1, 9)]
    body.data.qpos[body.model.jnt_qposadr[hinge]] = 0.1  # 0.1 rad per joint: 0.8 rad at the tip
    body.data.qvel[:] = np.linspace(-0.5, 0.5, body.model.nv)
    mujoco.mj_forward(body.model, body.data)
    x1, u1 = eb.place()
    pts, owner = b.boundary_particles(dx, 1, 2)
    rigid, _ = place(pts, eb.link_index[owner], body.kinematics())

    def widest_gap(x):  # along the outer (-x) face, the largest step between neighbours
        face = np.isclose(eb.plate[:, 0], eb.plate[:, 0].min()) & (eb.plate[:, 2] < b.length - dx)
        order = np.argsort(eb.plate[face, 2])
        return np.linalg.norm(np.diff(x[face][order], axis=0), axis=1).max()

    assert widest_gap(rigid) > 1.5 * dx  # the rigid links open the face at the joints ...
    # ... the blend keeps it closed: the outer fibre stretches by 1 + kappa h / 2 = 1.06 (kappa = 10 /m)
    assert widest_gap(x1) < 1.08 * dx
    eps = 1e-7
    body.data.qpos[:] += eps * body.data.qvel
    mujoco.mj_forward(body.model, body.data)
    x2, _ = eb.place()
    assert np.abs((x2 - x1) / eps - u1).max() < 1e-5 * np.abs(u1).max()


def test_elastic_body_places_particles_and_reports_the_corner():
    b = elastic_beam("p", **SEED, n_elements=8)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0), bodies=b.link_names)
    eb = ElasticBody(b, body, dx=0.0025, layers=2, dim=2)
    x, u = eb.place()
    assert len(x) == len(eb.plate) == eb.n and (u == 0).all()
    assert eb.displacement() == pytest.approx(np.zeros(3), abs=1e-15)
    body.data.qpos[:] = 0.01
    mujoco.mj_forward(body.model, body.data)
    x1, _ = eb.place()
    assert eb.displacement()[0] > 0 and eb.displacement("tip")[0] > 0
    assert (x1[:, 0] - x[:, 0]).max() == pytest.approx(eb.displacement()[0], rel=0.1)
    eb.check()  # fine
    body.data.qpos[2] = 2.0  # one hinge turned by 115 degrees
    mujoco.mj_forward(body.model, body.data)
    with pytest.raises(InstabilityError, match=r"element 2 \(body 'p_link2'\) went unstable.*timestep below"):
        eb.check()
    with pytest.raises(InputError, match="does not couple the links"):
        ElasticBody(b, MujocoBodies(builders.scene(b.xml, gravity=0.0), bodies=b.link_names[:3]), 0.0025, 2, 2)


# -- bad input -----------------------------------------------------------------------

@pytest.mark.parametrize("field,value", [("E", 0.0), ("E", -1e6), ("rho", 0.0), ("rho", -2500.0),
                                         ("thickness", 0.0), ("thickness", -0.012), ("length", 0.0),
                                         ("length", float("nan")), ("width", -1.0)])
def test_non_positive_parameters_are_refused_naming_the_field(field, value):
    kw = {**SEED, field: value}
    with pytest.raises(InputError, match=rf"elastic beam 'p': {field} must be a finite number > 0"):
        elastic_beam("p", **kw)


@pytest.mark.parametrize("n", [3, 0, 2.5, True])
def test_too_few_elements_are_refused_saying_how_many(n):
    with pytest.raises(InputError, match=r"n_elements must be a whole number >= 4"):
        elastic_beam("p", **SEED, n_elements=n)


def test_other_bad_input_is_refused():
    with pytest.raises(InputError, match="nu"):
        elastic_beam("p", **SEED, nu=0.5)
    with pytest.raises(InputError, match="beta"):
        elastic_beam("p", **SEED, beta=-1.0)
    with pytest.raises(InputError, match="base"):
        elastic_beam("p", **SEED, base=(0.0, 0.0))
    with pytest.raises(InputError, match="dx"):
        elastic_beam("p", **SEED).boundary_particles(0.0, 2)


def test_mujoco_resetting_a_blown_up_chain_stops_the_run_naming_the_body():
    """Stepped at 12 times its stable RK4 step, the chain's accelerations blow up and MuJoCo
    resets its state to the initial pose (mjWARN_BADQACC): MujocoBodies.advance says so,
    naming the body, rather than going on from a plate at rest."""
    b = elastic_beam("p", **{**SEED, "E": 1e10}, n_elements=8)
    body = MujocoBodies(builders.scene(b.xml, gravity=0.0, timestep=1e-4), bodies=b.link_names)
    assert b.stable_dt() < 1e-5
    body.data.qvel[:] = 1e-3
    with pytest.raises(InstabilityError, match=r"(reset its state|non-finite).*body '?p_link\d"):
        for k in range(200):
            body.advance(k * 1e-4, 1e-4)
