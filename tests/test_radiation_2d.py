"""benchmarks/radiation_2d.py: the 2-D sections' boundary-element reference (its damping is
the energy its waves carry; converged in the panels and the box), the scene it runs and
the reading of a run's force and gauges."""

import math

import numpy as np
import pytest

from benchmarks.radiation_2d import (DEPTH, GAUGES, PERIOD, RADIUS, contour, figures, print_split, run_name,
                                     scene_2d, section_coefficients)
from fluid.waves import group_velocity, wavenumbers

OMEGA = 2.0 * math.pi / PERIOD


@pytest.mark.parametrize("hull", ["box", "circle", "diamond"])
def test_a_sections_damping_is_the_energy_flux_of_its_waves(hull):
    """B33 from the body's pressure equals B33 from the outgoing waves' energy flux at the
    open boundaries (energy conservation), the gap closing in proportion to the panels."""
    coarse = section_coefficients(contour(hull), DEPTH, OMEGA, panel=RADIUS / 20)
    fine = section_coefficients(contour(hull), DEPTH, OMEGA, panel=RADIUS / 40)
    gap_coarse, gap_fine = (1.0 - c["B33_far"] / c["B33"] for c in (coarse, fine))
    assert 0.0 < gap_fine < 0.03
    assert gap_fine == pytest.approx(0.5 * gap_coarse, rel=0.1)
    assert fine["A33"] > 0.0 and fine["B33"] > 0.0


def test_a_sections_damping_tends_to_the_long_wave_limit():
    """In long waves a section of beam b heaving at velocity V sends b V / 2 of water each
    way as a wave of speed c = sqrt(g h), so B33 -> rho g b^2 / (2 c) (the energy flux of
    the two waves); the BEM's damping of a thin box (draft h / 10) approaches it as k h
    falls, its error about quartering as k h halves."""
    g, h, beam = 9.81, DEPTH, 2.0 * RADIUS
    limit = 1000.0 * g * beam**2 / (2.0 * math.sqrt(g * h))
    section = [(RADIUS, 0.0), (RADIUS, -0.1 * h), (-RADIUS, -0.1 * h), (-RADIUS, 0.0)]
    errors = []
    for kh in (0.2, 0.1):
        k = kh / h
        errors.append(abs(section_coefficients(section, h, math.sqrt(g * k * math.tanh(kh)))["B33"] / limit - 1.0))
    assert errors[1] < 2e-3
    assert errors[1] < 0.4 * errors[0]


def test_the_sections_coefficients_converge_in_the_panels_and_do_not_depend_on_the_box():
    """Halving the panels from R / 20 moves A33 and B33 of the box by under 0.5 %; the open
    boundaries at 0.8 m instead of 1.2 m by under 0.3 % (the evanescent modes have decayed
    there; what is left is the surface panels' own dispersion over the longer way)."""
    ref = section_coefficients(contour("box"), DEPTH, OMEGA, panel=RADIUS / 20)
    finer = section_coefficients(contour("box"), DEPTH, OMEGA, panel=RADIUS / 40)
    nearer = section_coefficients(contour("box"), DEPTH, OMEGA, panel=RADIUS / 20, half_length=0.8)
    for other, tol in ((finer, 5e-3), (nearer, 3e-3)):
        assert other["A33"] == pytest.approx(ref["A33"], rel=tol)
        assert other["B33"] == pytest.approx(ref["B33"], rel=tol)


def test_the_2d_scene_heaves_its_hull_about_the_still_water():
    """The box drawing ``draft`` radii is centred on the still water and twice as high as
    its draft; the amplitude is in radii; the gauges stand on both sides; dx = R / r_over_dx."""
    s = scene_2d("box", 0.5, 8.0, 0.1, 3)
    b = s.bodies[0]
    assert s.world.dim == 2 and s.fluid.dx == pytest.approx(RADIUS / 8)
    assert b.pos[-1] == pytest.approx(DEPTH) and b.size[-1] == pytest.approx(RADIUS)
    assert b.motion.amplitude == pytest.approx(0.1 * RADIUS) and b.motion.period == pytest.approx(PERIOD)
    assert s.world.duration == pytest.approx(4 * PERIOD)
    assert sorted(s.probes.gauges) == sorted([-x for x in GAUGES] + list(GAUGES))
    with pytest.raises(ValueError, match="hull"):
        scene_2d("wedge", 1.0, 4.0, 0.1, 3)


def test_the_slab_is_the_2d_box_in_3d_spanning_its_width():
    """--slab: the box spans a 3-D slab ROWS spacings wide between side walls, centred across
    it, its section and motion the 2-D scene's, the gauges across the slab's middle; only a
    box can span it."""
    flat, slab = scene_2d("box", 1.0, 4.0, 0.2, 3), scene_2d("box", 1.0, 4.0, 0.2, 3, slab=6)
    width = 6 * RADIUS / 4.0
    b = slab.bodies[0]
    assert slab.world.dim == 3 and slab.domain.width == pytest.approx(width) and slab.domain.sides == "walls"
    assert not slab.domain.symmetry and not slab.domain.side_zones
    assert b.size == pytest.approx([2.0 * RADIUS, width, 2.0 * RADIUS]) and b.pos == pytest.approx([0.0, width / 2, DEPTH])
    assert b.motion == flat.bodies[0].motion
    assert [g[0] for g in slab.probes.gauges] == pytest.approx(list(flat.probes.gauges))
    assert all(g[1] == pytest.approx(width / 2) for g in slab.probes.gauges)
    with pytest.raises(ValueError, match="slab"):
        scene_2d("circle", 1.0, 4.0, 0.2, 3, slab=6)


def test_each_variant_of_a_run_is_kept_in_its_own_folder():
    """--out: runs that differ in any argument of the scene (the slab and --set too) are kept
    in different folders, each one path component."""
    base = ("box", 1.0, 8.0, 0.2, 8, 0, ())
    variants = [base, ("circle",) + base[1:], base[:1] + (0.5,) + base[2:], base[:2] + (16.0,) + base[3:],
                base[:3] + (0.1,) + base[4:], base[:4] + (5,) + base[5:], base[:5] + (4, ()),
                base[:6] + (("fluid.nu=0",),), base[:6] + (("fluid.nu=0", "fluid.delta=0"),)]
    names = [run_name(*v) for v in variants]
    assert len(set(names)) == len(variants)
    assert all("/" not in n and n == n.strip() for n in names)


def test_the_reading_recovers_a_known_force_and_outgoing_waves():
    """A force ``-(C - A w^2) z - B w a cos`` and waves travelling out on both sides of
    known amplitude give back A, B, the waves' damping and the excess as a drag."""
    s = scene_2d("box", 1.0, 4.0, 0.2, 6)
    m = s.bodies[0].motion
    g, rho = s.world.gravity, s.fluid.rho0
    k = float(wavenumbers(OMEGA, DEPTH, g))
    a33, b33, amp = 20.0, 60.0, 0.004
    t = np.arange(0.0, s.world.duration, PERIOD / 40)
    z = m.amplitude * np.sin(OMEGA * t)
    c = rho * g * 2.0 * RADIUS
    series = {"body.fluid_Fz": -(c - a33 * OMEGA**2) * z - b33 * OMEGA * m.amplitude * np.cos(OMEGA * t)}
    for i, x in enumerate([-x for x in GAUGES] + list(GAUGES)):
        series[f"gauge{i + 1}.eta"] = amp * np.cos(OMEGA * t - k * abs(x))
    res = type("Res", (), {"t": t, "__getitem__": lambda self, key: series[key]})()
    f = figures(res, s, {"B33": 40.0})
    assert f["A33"] == pytest.approx(a33, rel=1e-9) and f["B33"] == pytest.approx(b33, rel=1e-9)
    assert f["B33_wave"] == pytest.approx(2 * rho * g * amp**2 * float(group_velocity(k, DEPTH, g))
                                          / (OMEGA * m.amplitude)**2, rel=1e-6)
    assert f["reflection"] < 1e-6
    drag = (8.0 / (3.0 * math.pi)) * 0.5 * rho * 2.0 * RADIUS * OMEGA * m.amplitude
    assert f["Cd_of_excess"] == pytest.approx(20.0 / drag, rel=1e-9)


def test_the_split_gives_the_drag_as_the_beams_coefficient(capsys):
    """An excess ``L + Cd``'s equivalent damping (Lorentz's linearisation on the beam 2R)
    at three amplitudes is printed back as L and that Cd."""
    drag_per_radius = (8.0 / (3.0 * math.pi)) * 0.5 * 1000.0 * 2.0 * RADIUS * OMEGA * RADIUS
    amps = [0.05, 0.1, 0.2]
    print_split(amps, {8.0: [8.0 + 2.5 * drag_per_radius * x for x in amps]}, 40.0)
    row = capsys.readouterr().out.strip().splitlines()[-1].split("|")
    assert row[1].strip() == "8" and row[2].strip().startswith("8.0 +- 0.0") and row[3].strip() == "+20%"
    assert row[5].strip().startswith("2.50 +- 0.00")
