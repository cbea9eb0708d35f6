"""The SPH cable at the extremes: few/many particles, stiff lines, slack-and-snap, blow-up."""

import math

import numpy as np
import pytest

from cosim.errors import InstabilityError
from moorings.sph_cable import SPHCable


def _energy(c):
    ke = c.kinetic_energy()
    pe = -float((c.fext[:, -1] * c.x[:, -1]).sum())  # constant weights: potential = -F·z
    ell = np.linalg.norm(np.diff(c.x, axis=0), axis=1)
    eps = np.maximum(ell / c.ds - 1.0, 0.0)
    return ke + pe + float((0.5 * c.EA * c.ds * eps**2).sum())


def test_five_particles_hang_in_equilibrium():
    c = SPHCable(1.272, 5, 2.0e4, 0.027, (0, 0), (1.2, -0.22), weight_per_length=0.2656, omega=30.0)
    while c.t < 2.0:
        c.advance(c.t, 0.1)
    F = c.end_forces()
    assert -F[:, 1].sum() == pytest.approx(0.2656 * 1.272, rel=1e-6)
    assert F[0, 0] == pytest.approx(-F[1, 0], rel=1e-6)


def test_free_fall_slack_then_taut_keeps_energy_bookkept():
    """Dinçer & Demir 2020, Experiment 1 set-up: released at one end, the cable swings down, goes slack
    and snaps taut; without damping, total energy may only decrease (artificial viscosity)."""
    n, L = 41, 1.0
    x = np.stack([np.linspace(0.0, 0.88, n), np.zeros(n)], axis=1)  # 12 % slack, straight
    c = SPHCable(L, n, 2.0e3, 0.0285, x[0], x[-1], free_end="b", positions=x, omega=0.0)
    E0 = _energy(c)
    Es, strain, z_low = [], 0.0, 0.0
    while c.t < 1.0:
        c.advance(c.t, 0.01)
        Es.append(_energy(c))
        z_low = min(z_low, c.x[-1, 1])
        strain = max(strain, float((np.linalg.norm(np.diff(c.x, axis=0), axis=1) / c.ds - 1).max()))
    Es = np.array(Es)
    scale = 0.0285 * L * 9.80665 * L
    assert np.all(Es <= E0 + 1e-6 * scale)
    assert Es[-1] < E0  # the snap dissipated some
    # the free end swung down through the bottom (a pendulum of length ~1 m) and the
    # line never overstretched
    assert z_low < -0.75 and strain < 0.01


@pytest.mark.long
def test_stiff_short_steel_wire_is_stable():
    EA = 200e9 * math.pi / 4 * 1e-3**2  # 1 mm steel wire, 157 kN
    c = SPHCable(1.0, 51, EA, 0.00617, (0, 0), (0.9, 0.1), omega=20.0)
    while c.t < 0.5:
        c.advance(c.t, 0.05)
    F = c.end_forces()
    assert -F[:, 1].sum() == pytest.approx(0.00617 * 9.80665, rel=1e-4)


def test_5000_particles_run():
    c = SPHCable(150.0, 5000, 1e9, 107.7, (0, -50), (130, 0), weight_per_length=918.75, seabed_z=-50.0)
    c.advance(0.0, 2e-3)
    assert np.all(np.isfinite(c.x)) and c.steps >= 1


def test_blow_up_is_reported_with_particle_and_step():
    c = SPHCable(1.0, 21, 1e4, 0.1, (0, 0), (0.9, 0))
    c.cfl, c.safety = 20.0, 1e9  # bypass the input checks to force the explicit scheme past its limits
    with pytest.raises(InstabilityError, match=r"particle \d+ .*cfl"):
        for _ in range(200):
            c.advance(c.t, 0.01)


def test_overstretching_is_warned_once(caplog):
    c = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (1.0, 0), weight_per_length=0.0, max_strain=0.05)
    c.set_end_motion("b", (1.2, 0.0))
    with caplog.at_level("WARNING", logger="moorings.sph_cable"):
        c.advance(0.0, 0.5)
        c.advance(0.5, 0.5)
    msgs = [r.getMessage() for r in caplog.records if "max_strain" in r.getMessage()]
    assert len(msgs) == 1 and "segment" in msgs[0]


# -- the automatic step (SPHCable.step_limit; moorings.sph_cable, "Time stepping") ----------------

def test_step_limit_terms_by_hand():
    c = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (1.0, 0), weight_per_length=0.0)  # straight, unstretched
    c0, ds = math.sqrt(1e4 / 0.1), 0.1  # 316.23 m/s
    w_hm = 2 * c0 / ds  # highest axial mode, 6324.6 1/s
    g_visc = 15 / 8 * 1.0 * c0 / ds  # 5929.2 1/s: the pair dashpot (15/32) sqrt(EA m), four times on m ds
    zeta = (g_visc + 0.04) / (2 * w_hm)  # 0.46875
    damped = 2 / w_hm * (math.sqrt(zeta**2 + 1) - zeta)  # 2.0101e-4 s: 0.636 ds / c0
    lim = c.step_limit()
    assert lim.limits["courant"] == pytest.approx(0.4 * ds / c0, rel=1e-12)
    assert lim.limits["damped_mode"] == pytest.approx(damped, rel=1e-12)
    assert lim.limits["viscosity"] == pytest.approx(2 / g_visc, rel=1e-12)
    assert lim.limits["mass_damping"] == pytest.approx(2 / 0.04, rel=1e-12)
    assert lim.limits["drag"] == lim.limits["density_diffusion"] == math.inf
    assert (lim.limiter, lim.dt) == ("courant", pytest.approx(0.4 * ds / c0, rel=1e-12))  # 0.4 < 0.8 * 0.636
    c.cfl = 1.0
    assert (c.dt_limit.limiter, c.stable_dt()) == ("viscosity", pytest.approx(0.8 * damped, rel=1e-12))
    # drag, linearised at the held end's coming speed: 2 U max(kn / (m + ma_n), kt / (m + ma_t))
    c = SPHCable(1.0, 11, 1e4, 0.1, (0, 0), (1.0, 0), weight_per_length=0.0, diameter=0.01, delta=0.1)
    c.set_end_motion("b", (1.0, 0.0), (0.0, 3.0))
    kn_m = 0.5 * 1025 * 0.01 * 1.2 / (0.1 + 1025 * math.pi / 4 * 0.01**2 * 1.0)  # 34.07 1/m
    assert c.step_limit().limits["drag"] == pytest.approx(2 / (2 * 3.0 * kn_m), rel=1e-12)
    assert c.step_limit().limits["density_diffusion"] == pytest.approx(ds / (2 * 0.1 * c0), rel=1e-12)


def _noisy_taut_wire(cfl, old_step=False):
    """A 1 mm steel wire (EA = 157 kN), 51 particles, stretched 1 %, with position and velocity noise
    that excites its highest axial mode; 0.5 s at ``cfl``. ``old_step``: only the Courant step."""
    EA = 200e9 * math.pi / 4 * 1e-3**2
    c = SPHCable(1.0, 51, EA, 0.00617, (0, 0), (1.0, 0), weight_per_length=0.0, cfl=cfl)
    if old_step:
        c.safety = 1e9
    c.set_end_motion("b", (1.01, 0.0))
    c.advance(0.0, 0.02)
    rng = np.random.default_rng(0)
    c.x[1:-1, 0] += 1e-4 * rng.standard_normal(49)
    c.v[1:-1, 1] += 1e-3 * rng.standard_normal(49)
    for _ in range(25):
        c.advance(c.t, 0.02)
    return c


def test_courant_number_one_is_stable_on_a_stiff_taut_wire():
    """cfl <= 1 is accepted, but the artificial viscosity (alpha = 1) on the highest axial mode of
    leap-frog allows only cfl <= 0.636; the step now obeys that bound too."""
    EA = 200e9 * math.pi / 4 * 1e-3**2
    c = _noisy_taut_wire(1.0)
    assert c.dt_limit.limiter == "viscosity"
    assert c.max_speed() < 0.01 and np.all(np.abs(c.tension / (0.01 * EA) - 1) < 0.01)
    with pytest.raises(InstabilityError, match="runaway"):  # the step as it was: blows up by t = 0.08 s
        _noisy_taut_wire(1.0, old_step=True)


def test_heavy_mass_damping_settles():
    """Eq. 12's omega [1/s] is explicit in the kick: omega dt <= 2. A soft line (c0 = 3.2 m/s, 5
    particles, Courant step 0.032 s) settled with omega = 100 1/s needs dt <= 0.02 s."""
    def run(old_step):
        c = SPHCable(1.0, 5, 10.0, 1.0, (0, 0), (0.8, 0), omega=100.0, max_strain=1.0)
        if old_step:
            c.safety = 1e9
        for _ in range(100):
            c.advance(c.t, 0.05)
        return c

    c = run(False)
    assert c.dt_limit.limiter == "mass_damping"
    assert c.max_speed() < 0.02  # measured 0.007 m/s (still creeping towards rest at 5 s, overdamped)
    # the supports carry the weight, less what the mass damping -omega m v still holds while it creeps
    assert -c.end_forces()[:, 1].sum() == pytest.approx(9.80665, rel=0.05)  # measured 3 % short
    assert run(True).max_speed() > 0.5  # the old step: 1.1 m/s after 5 s, never settles


@pytest.mark.long
def test_many_particles_heavy_seabed_contact_with_defaults():
    """1000 particles of the Johanning chain (EA = 1e4 N, 0.12 kg/m), X = 5.5 m: half the line on the
    seabed with Coulomb friction 1; 0.2 s of a 2 mm surge at the defaults."""
    from moorings.catenary_mooring import CatenaryMooring
    from moorings.line import MooringLine
    from moorings.sph_cable import SPHCableMooring

    ln = MooringLine((0.0, 0.0), 6.98, 1.036, EA=1e4, mass_per_length=0.12, name="chain")
    fl = np.array([[5.5, 2.651]])
    m = SPHCableMooring([ln], fairleads=fl, n_particles=1000, seabed_friction=1.0)
    m.initialize(0.0)
    t_cat = CatenaryMooring([ln], fairleads=fl).fairlead_tensions()[0]  # 3.929 N
    w, dt, dev = 2 * math.pi, 0.01, []
    for k in range(20):
        t1 = (k + 1) * dt
        m.set_fairlead_motion(fl + [[0.002 * (1 - math.cos(w * t1)), 0]], [[0.002 * w * math.sin(w * t1), 0]])
        m.advance(k * dt, dt)
        dev.append(m.fairlead_tensions()[0] / t_cat - 1)
    c = m.cables[0]
    assert c.dt_limit.limiter == "courant" and np.all(np.isfinite(c.x))
    assert np.sum(c.x[:, -1] <= 1e-9) > 400  # resting on the seabed
    # the surge moves the static tension by < 1 % (measured max deviation 0.6 %); an instability of the
    # stiff line (c0 = 289 m/s, ds = 7 mm, 20 660 sub-steps) would leave this by orders of magnitude
    assert np.max(np.abs(dev)) < 0.03
