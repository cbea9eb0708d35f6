"""Line states (Barreiro et al. 2016, Fig. 5: resting, partly lifted, fully lifted, taut) from every
mooring model: the catenary law's own, the exported catenary FMU's ``<line>.state``
output, and the SPH cable's and MoorDyn's nodes (moorings.line_events.node_states): one
line 20 m long, its fairlead 10 m above the anchor, at four spans across the law's
boundaries (resting X <= L - h = 10 m; lift-off 16.48 m; taut 17.32 m, inextensible), then
pulled from slack to taut, the taut event logged within the step the chord reaches L."""

import math

import numpy as np
import pytest

from conftest import requires_cc
from moorings import CatenaryMooring, MooringLine
from moorings.catenary import FULLY_LIFTED, PARTLY_LIFTED, RESTING, TAUT, lift_off_distance, taut_distance

H, L, RHO, G = 10.0, 20.0, 1025.0, 9.81
M, D, EA = 12.0, 0.05, 1e7  # kg/m, m, N: 0.8 % stretch at the taut span's 80 kN
W = (M - RHO * math.pi / 4 * D * D) * G  # submerged weight [N/m]
SPANS = (8.0, 13.0, 16.9, 17.6)  # m: one per state
STATES = [RESTING, PARTLY_LIFTED, FULLY_LIFTED, TAUT]


def lines():
    return [MooringLine((0.0, 0.0), L, W, EA=EA, mass_per_length=M, diameter=D, name=f"x{X:g}") for X in SPANS]


def fairleads(extra=0.0):
    return np.array([(X + extra, H) for X in SPANS])


def sph_cable():
    from moorings.sph_cable import SPHCableMooring

    return SPHCableMooring(lines(), fairleads=fairleads(), n_particles=40, water_z=20.0, rho_water=RHO, gravity=G)


def moordyn():
    pytest.importorskip("moordyn")
    from moorings.moordyn_mooring import MoorDynMooring

    return MoorDynMooring(lines(), fairleads=fairleads(), water_level=20.0, rho=RHO, g=G, segments=20)


def test_the_spans_straddle_the_laws_boundaries():
    assert L - H < SPANS[1] and lift_off_distance(H, L) < SPANS[2] < taut_distance(H, L) < SPANS[3]
    assert SPANS[0] <= L - H and math.hypot(SPANS[3], H) > L * (1 + 0.0075)  # taut, stretched 0.8 %
    cat = CatenaryMooring(lines(), fairleads=fairleads())
    assert cat.line_states().tolist() == STATES


@pytest.mark.parametrize("make", [sph_cable, moordyn], ids=["sph-cable", "moordyn"])
def test_a_dynamic_models_states_agree_with_the_law_and_a_line_pulled_taut_is_logged(make):
    m = make()
    m.initialize(0.0)
    assert m.line_states().tolist() == STATES  # the quasi-static start (SPH cable) or MoorDyn's own statics
    m.advance(0.0, 0.05)
    assert m.line_states().tolist() == STATES
    log = m.state_log
    assert log.initial.tolist() == STATES and all(not e["taut"] for e in log.events.values())
    # the partly lifted line (X = 13 m) pulled out at 2 m/s: its chord reaches L at X = 17.32 m
    v, t, dt = 2.0, 0.05, 0.05
    t_taut = 0.05 + (taut_distance(H, L) - SPANS[1]) / v
    while t < t_taut + 3 * dt:
        p = fairleads()
        p[1, 0] = SPANS[1] + v * (t + dt - 0.05)
        m.set_fairlead_motion(p)
        m.advance(t, dt)
        t += dt
    s = log.summary()["x13"]
    assert s["first_fully_lifted_s"] is not None and s["first_fully_lifted_s"] < s["first_taut_s"]
    assert abs(s["first_taut_s"] - t_taut) <= 2 * dt, (s, t_taut)  # the geometry's own boundary, to a step
    assert log.summary()["x17.6"]["state"] == "TAUT" and log.summary()["x8"]["state"] == "RESTING"
    snap, before = m.save_state(), log.summary()  # the log travels with the model's state (checkpoints)
    p[1, 0] = SPANS[1]
    m.set_fairlead_motion(p, np.zeros_like(p))
    m.advance(t, 0.5)  # back to slack: a "slack" event
    assert log.summary()["x13"]["slack_s"]
    m.load_state(snap)
    assert log.summary() == before


@requires_cc
def test_the_catenary_fmu_reports_the_laws_states(tmp_path):
    from moorings.fmu_export import catenary_fmu_variable_map, export_catenary_fmu
    from moorings.fmu_mooring import FMUMooring

    ls = lines()
    fmu = FMUMooring(export_catenary_fmu(ls, tmp_path / "l.fmu"), ls, catenary_fmu_variable_map(ls),
                     fairleads=fairleads())
    fmu.initialize(0.0)
    assert fmu.line_states().tolist() == STATES
    p = fairleads()
    p[1, 0] = 17.5  # the partly lifted line pulled taut
    fmu.set_fairlead_motion(p)
    fmu.advance(0.0, 0.1)
    assert fmu.state_log.summary()["x13"]["first_taut_s"] == pytest.approx(0.1)
    k = fmu.fairlead_stiffness().k  # the law's tangent stiffness through the FMU, as the native law's
    cat = CatenaryMooring(ls, fairleads=p)
    np.testing.assert_allclose(k, cat.fairlead_stiffness().k, rtol=1e-4, atol=1e-3 * np.abs(k).max())
    fmu.close()
