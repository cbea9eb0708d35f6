"""Earthquake records (Wang et al. 2022, §4.2): the PEER ``.AT2`` reader on the shipped 1940 El
Centro records, their baseline correction, the refusal of bad files, and base motion of
several components at once (``fluid.motion.Combined``, the scene's ``GroundMotion``): the
walls move by exactly the integrated record in both directions, and a small tank under
horizontal + vertical El Centro stays stable."""

import math

import numpy as np
import pytest

from cosim import refdata
from cosim.errors import InputError
from cosim.scene import SPH, Earthquake, GroundMotion, Probes, Record, Scene, SceneError, Tank, World
from fluid.motion import G_STANDARD, Combined, Harmonic, Tabulated, Translation, baseline_correct, read_at2

DATASET = "earthquake_el_centro_1940"
NS = refdata.path(DATASET, "RSN6_IMPVALL.I_I-ELC180-hor1.AT2")
EW = refdata.path(DATASET, "RSN6_IMPVALL.I_I-ELC270-hor2.AT2")
UP = refdata.path(DATASET, "RSN6_IMPVALL.I_I-ELC-UP.AT2")


def _exact_double_integral(a, dt):
    """Velocity and displacement at the samples of a piecewise-linear acceleration ``a``
    [m/s^2] sampled every ``dt`` [s], from rest: the closed-form step of Newmark's linear
    acceleration method (beta = 1/6, gamma = 1/2), summed sample by sample; an oracle
    independent of :class:`Tabulated`'s splines."""
    v, d = np.zeros_like(a), np.zeros_like(a)
    for k in range(a.size - 1):
        v[k + 1] = v[k] + dt * (a[k] + a[k + 1]) / 2
        d[k + 1] = d[k] + dt * v[k] + dt * dt * (2 * a[k] + a[k + 1]) / 6
    return v, d


# ------------------------------------------------------------------------ the reader
@pytest.mark.parametrize("path, npts, first, pga, t_pga", [
    (NS, 5372, 0.9984852e-03, 0.2808, 2.18),
    (EW, 5346, -0.9429229e-03, 0.2107, 11.51),
    (UP, 5378, -0.8338791e-03, 0.1781, 3.37),
])
def test_el_centro_reads_as_the_file_says(path, npts, first, pga, t_pga):
    """NPTS, DT, the first sample and the peak ground acceleration of each component (the
    PEER NGA-West2 processing: 0.281 g for NS, not the 0.319 g of the older digitisation;
    refdata SOURCE.txt)."""
    rec = read_at2(path, baseline_degree=None)
    t, a = np.asarray(rec.times), np.asarray(rec.values) / G_STANDARD
    assert t.size == npts and np.diff(t) == pytest.approx(np.full(npts - 1, 0.01), abs=1e-12)
    assert a[0] == pytest.approx(first, rel=1e-7)
    k = int(np.abs(a).argmax())
    assert abs(a[k]) == pytest.approx(pga, abs=5e-5) and t[k] == pytest.approx(t_pga)


def test_the_shipped_records_end_at_rest_and_the_correction_keeps_them():
    """PEER's records are baseline-corrected already: integrated exactly they end at rest
    (velocity < 0.1 mm/s, displacement < 0.2 mm); our correction changes their
    acceleration by less than 5e-5 g (measured 0.7, 3.4, 0.1e-5 g for NS, EW, UP) and their
    displacement by less than 2 % of its peak (1.0, 1.7, 0.5 %: the least-squares fit also
    takes some of the records' slowest content, the known cost of the method)."""
    for path in (NS, EW, UP):
        raw, cor = read_at2(path, None), read_at2(path)
        t = np.asarray(raw.times)
        tt = np.linspace(t[0], t[-1] - 1e-9, 50001)
        d, v, a = raw.sample(tt)
        dc, vc, ac = cor.sample(tt)
        assert abs(v[-1]) < 1e-4 and abs(d[-1]) < 2e-4
        assert abs(vc[-1]) < 1e-5 and abs(dc[-1]) < 1e-9
        assert np.abs(ac - a).max() < 5e-5 * G_STANDARD and np.abs(dc - d).max() < 0.02 * np.abs(d).max()


def test_baseline_correction_removes_a_drift_from_a_real_record():
    """El Centro NS with an offset of 0.002 g and a trend of 1e-4 g/s (a tilted or
    mis-zeroed instrument): integrated raw it ends at 2.47 m/s, 53.6 m off; corrected
    (polynomial fit to the displacement, constrained to end at rest: Boore 2001, BSSA 91(5)
    1199-1211; fluid.motion module docstring) it ends at rest, and its displacement is the
    clean record's within 3 % of the clean peak (measured 1.0 %: the fit also takes some
    of the record's own slow content), its acceleration within 1e-3 of the PGA (2.5e-5)."""
    clean = read_at2(NS, None)
    t = np.asarray(clean.times)
    drift = (0.002 + 1e-4 * t) * G_STANDARD
    raw = Tabulated(clean.times, tuple(np.asarray(clean.values) + drift), "acceleration")
    end = t[-1] - 1e-9
    assert abs(raw.state(end)[1]) > 2.0 and abs(raw.state(end)[0]) > 50.0
    cor = baseline_correct(raw, 6)
    assert abs(cor.state(end)[1]) < 1e-5 and abs(cor.state(t[-1])[0]) < 1e-9
    tt = np.linspace(0.0, end, 20001)
    d0, _, a0 = clean.sample(tt)
    d1, _, a1 = cor.sample(tt)
    assert np.abs(d1 - d0).max() < 0.03 * np.abs(d0).max()
    assert np.abs(a1 - a0).max() < 1e-3 * np.abs(a0).max()


def test_the_record_integrates_exactly_at_its_samples():
    """Velocity and displacement of the raw NS record at its samples against the closed
    form of the piecewise-linear acceleration (:func:`_exact_double_integral`)."""
    rec = read_at2(NS, None)
    t, a = np.asarray(rec.times), np.asarray(rec.values)
    v, d = _exact_double_integral(a, 0.01)
    inner = slice(1, -1)  # at the last sample the record is over (at rest)
    s, ds, dds = rec.sample(t[inner])
    np.testing.assert_allclose(dds, a[inner], atol=1e-12)
    np.testing.assert_allclose(ds, v[inner], atol=1e-12)
    np.testing.assert_allclose(s, d[inner], atol=1e-11)


# ------------------------------------------------------------------------ bad files
HEAD = "PEER NGA STRONG MOTION DATABASE RECORD\nSynthetic, 1/1/2000, Station, 000\n"
ACC = "ACCELERATION TIME SERIES IN UNITS OF G\n"
ROWS = "  .1000000E-02  .2000000E-02  .1000000E-02  .0000000E+00 -.1000000E-02\n"


def _write(tmp_path, text, name="rec.AT2"):
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.mark.parametrize("text, says", [
    ("time,acc\n0.0,0.001\n0.01,0.002\n0.02,0.001\n0.03,0.0\n0.04,-0.001\n",
     "line 3 of .*rec.AT2 is '0.01,0.002': not an .AT2 file"),
    (HEAD + "VELOCITY TIME SERIES IN UNITS OF CM/SEC\nNPTS=   10, DT=   .0100 SEC\n" + ROWS * 2,
     "a velocity record \\(.VT2\\)"),
    (HEAD + "ACCELERATION TIME SERIES IN UNITS OF CM/SEC/SEC\nNPTS=   10, DT=   .0100 SEC\n" + ROWS * 2,
     "in CM/SEC/SEC, not in g"),
    (HEAD + ACC + "10 samples at 100 per second\n" + ROWS * 2, "line 4 of .* should give NPTS and DT"),
    ("short\n", "has 1 lines; a PEER .AT2 file has 4 header lines"),
], ids=["csv-table", "velocity-record", "cm-per-s2", "no-npts-dt", "one-line"])
def test_a_file_that_is_not_an_at2_accelerogram_is_refused(tmp_path, text, says):
    with pytest.raises(InputError, match=says):
        read_at2(_write(tmp_path, text))


def test_a_binary_file_is_refused(tmp_path):
    p = tmp_path / "rec.AT2"
    p.write_bytes(bytes(range(256)) * 4)
    with pytest.raises(InputError, match="is not a text file"):
        read_at2(p)


@pytest.mark.parametrize("body, says", [
    (ROWS + "  .1000000E-02  .2000000E-02\n" + ROWS, "line 6 of .* holds 2 value\\(s\\) where the other data lines "
                                                     "hold 5: a gap"),
    (ROWS + "\n" + ROWS, "line 6 of .* holds 0 value\\(s\\) .*: a gap"),
    (ROWS, "declares NPTS=10 but holds 5 values; the record is cut short"),
    (ROWS * 3, "declares NPTS=10 but holds 15 values; correct NPTS"),
], ids=["short-line", "blank-line", "too-few", "too-many"])
def test_a_record_with_gaps_or_a_wrong_npts_is_refused(tmp_path, body, says):
    with pytest.raises(InputError, match=says):
        read_at2(_write(tmp_path, HEAD + ACC + "NPTS=   10, DT=   .0100 SEC\n" + body))


@pytest.mark.parametrize("dt", ["0.0", "-.0100"])
def test_a_non_positive_dt_is_refused(tmp_path, dt):
    with pytest.raises(InputError, match=f"gives NPTS=10, DT={float(dt)} s; need NPTS >= 2 and DT > 0"):
        read_at2(_write(tmp_path, HEAD + ACC + f"NPTS=   10, DT=   {dt} SEC\n" + ROWS * 2))


@pytest.mark.parametrize("bad", ["NaN", "inf", "-Infinity"])
def test_non_finite_values_are_refused(tmp_path, bad):
    body = ROWS + ROWS.replace(".2000000E-02", bad, 1)
    with pytest.raises(InputError, match="non-finite value .* at sample 6 \\(t = 6 DT\\)"):
        read_at2(_write(tmp_path, HEAD + ACC + "NPTS=   10, DT=   .0100 SEC\n" + body))


def test_a_value_that_is_not_a_number_is_refused(tmp_path):
    with pytest.raises(InputError, match="line 6 of .* holds '0.1D-02', not a number"):
        read_at2(_write(tmp_path, HEAD + ACC + "NPTS=   10, DT=   .0100 SEC\n" + ROWS
                        + ROWS.replace(".1000000E-02", "0.1D-02", 1)))


# ------------------------------------------------------------------------ several components at once
def test_combined_motion_is_the_sum_of_its_components_with_exact_derivatives():
    ns, up = read_at2(NS), read_at2(UP)
    m = Combined((Translation((1.0, 0.0), ns), Translation((0.0, 1.0), up)))
    ref = np.array([[0.0, 0.0], [1.0, 0.5], [-0.3, 2.0]])
    for t in (0.0, 1.234, 2.18, 20.005, 53.0, 60.0):
        pos, vel = m(t, ref)
        (dx, vx, ax), (dz, vz, az) = ns.state(t), up.state(t)
        np.testing.assert_allclose(pos - ref, np.broadcast_to([dx, dz], ref.shape), rtol=0, atol=1e-15)
        np.testing.assert_array_equal(vel, np.broadcast_to([vx, vz], ref.shape))
        np.testing.assert_array_equal(m.acceleration(t), [ax, az])
    d, v, a = m.sample([1.234, 2.18])
    np.testing.assert_allclose(d[1], m.state(2.18)[0], atol=1e-15)
    # oblique directions add as vectors; 3-D components too
    e = np.array([1.0, 1.0]) / math.sqrt(2)
    m2 = Combined((Translation((1.0, 1.0), ns), Translation((1.0, 0.0), Harmonic(0.01, 0.5))))
    np.testing.assert_allclose(m2.state(3.0)[0], ns.state(3.0)[0] * e + [Harmonic(0.01, 0.5).state(3.0)[0], 0.0])
    m3 = Combined((Translation((1, 0, 0), ns), Translation((0, 1, 0), read_at2(EW)), Translation((0, 0, 1), up)))
    assert m3.state(5.0)[0].shape == (3,)
    with pytest.raises(InputError, match="directions have \\[2, 3\\] coordinates"):
        Combined((Translation((1.0, 0.0), ns), Translation((0.0, 0.0, 1.0), up)))
    with pytest.raises(InputError, match="non-empty list of Translation"):
        Combined(())


def _scene(components, duration=0.3, height=0.4, **kw):
    return Scene(name="quake_tank", world=World(dim=2, duration=duration, sample_every=0.05, snapshot_every=0),
                 fluid=SPH(dx=0.025), domain=Tank(length=0.5, height=height, depth=0.2),
                 base_motion=GroundMotion(components=components, **kw), probes=Probes(energy=True))


def test_the_walls_move_by_exactly_the_integrated_record_in_both_directions(tmp_path):
    """A 2-D tank under El Centro NS (x) and vertical (z), scaled by 2 and 3: after a
    short SPH run every wall particle is at its start plus the double integral of the
    scaled records at the fluid's time (the Newmark closed form at the samples, linear
    acceleration between them), in x and in z, to 1e-12 m; its velocity is the single
    integral."""
    from cosim.scene.build import build
    from fluid.particles import Kind

    scene = _scene([Record(file=str(NS), direction=(1.0, 0.0), scale=2.0),
                    Record(file=str(UP), direction=(0.0, 1.0), scale=3.0)], baseline_degree=6)
    b = build(scene, tmp_path)
    ps = b.sph.ps
    walls = ps.kind == Kind.MOVING_WALL
    ids = ps.ids[walls]
    start = ps.pos[walls].copy()
    b.coupler.run(0.3)
    t = b.sph.t
    assert t == pytest.approx(0.3, abs=1e-12)
    now = {i: k for k, i in enumerate(ps.ids)}
    rows = [now[i] for i in ids]
    moved, vel = ps.pos[rows] - start, ps.vel[rows]
    for axis, (path, k) in enumerate(((NS, 2.0), (UP, 3.0))):
        rec = read_at2(path)  # baseline-corrected, as the scene reads it
        a = k * np.asarray(rec.values)
        v, d = _exact_double_integral(a, 0.01)
        j = int(t // 0.01)
        tau = t - 0.01 * j
        slope = (a[j + 1] - a[j]) / 0.01
        v_t = v[j] + a[j] * tau + slope * tau**2 / 2
        d_t = d[j] + v[j] * tau + a[j] * tau**2 / 2 + slope * tau**3 / 6
        q = np.polynomial.Polynomial(k * np.asarray(rec.baseline))
        assert np.abs(moved[:, axis] - (d_t - q(t))).max() < 1e-12
        assert np.abs(vel[:, axis] - (v_t - q.deriv()(t))).max() < 1e-12
        assert abs(d_t - q(t)) > 1e-6  # it did move


@pytest.mark.long
def test_a_small_tank_under_horizontal_and_vertical_el_centro_stays_stable(tmp_path):
    """A 0.5 m tank (walls 0.6 m high), 0.2 m of water, dx = 25 mm (160 fluid particles),
    under El Centro NS (x) and vertical (z) scaled by 3 for the first 2.5 s (the NS peak,
    0.84 g scaled, is at 2.18 s; the water climbs the walls by about 0.2 m): at the end
    (the last snapshot of run.h5) the fluid is finite, inside the moving tank, its density
    within 3 % of rho0, and it sloshes; the energy probe is finite throughout. (With
    walls 0.4 m high the water leaves the open tank.)"""
    from fluid.output import read_snapshot
    from fluid.particles import Kind

    scene = _scene([Record(file=str(NS), direction=(1.0, 0.0), scale=3.0),
                    Record(file=str(UP), direction=(0.0, 1.0), scale=3.0)], duration=2.5, height=0.6)
    scene = scene.replace(world=scene.world.replace(snapshot_every=2.5))
    r = scene.run(tmp_path / "run", progress=False)
    assert r.summary["t_reached_s"] == pytest.approx(2.5)
    kinetic = r["fluid.kinetic"]
    assert np.isfinite(kinetic).all() and np.isfinite(r["fluid.potential"]).all()
    snap = read_snapshot(tmp_path / "run" / "run.h5", -1)
    assert snap["t"] == pytest.approx(2.5)
    pos, vel, kind = snap["pos"], snap["vel"], snap["kind"]
    fl = kind == int(Kind.FLUID)
    assert fl.sum() == 160 and np.isfinite(pos).all() and np.isfinite(vel).all()
    walls = pos[kind == int(Kind.MOVING_WALL)]
    lo, hi = walls.min(axis=0), walls.max(axis=0)
    assert ((pos[fl] > lo) & (pos[fl] < hi)).all()
    assert np.abs(snap["rho"][fl] / 1000.0 - 1.0).max() < 0.03
    assert np.abs(vel[fl]).max() > 0.3 and kinetic.max() > 1.0


@pytest.mark.long
def test_gauges_and_wall_patches_move_with_the_tank(tmp_path):
    """A tank carried 0.1 m sideways and 0.05 m up (4 and 2 dx) by one smooth 2 s pulse of
    displacement along (2, 1) (a table, so that no baseline correction touches it;
    accelerations 0.05 g and 0.025 g): the wall patch on the left wall stays on it,
    reading its hydrostatic pressure within 20 % (fixed in the world it would be off the
    face and refused); the gauge in the middle of the tank (the first mode's node) reads
    the surface's height above the moved still level within 5 mm (fixed in the world it
    would read the 0.05 m lift)."""
    from cosim.scene import Patch, TableMotion

    t = np.linspace(0.0, 2.0, 201)
    path = tmp_path / "pulse.txt"
    np.savetxt(path, np.column_stack([t, math.hypot(0.1, 0.05) * 0.5 * (1 - np.cos(np.pi * t))]))
    scene = Scene(world=World(dim=2, duration=1.2, sample_every=0.2, snapshot_every=0), fluid=SPH(dx=0.025),
                  domain=Tank(length=0.5, height=0.4, depth=0.2),
                  base_motion=TableMotion(file=str(path), direction=(2.0, 1.0)),
                  probes=Probes(gauges=[0.25], pressure=[Patch("left", (0.0, 0.05), (1.0, 0.0), 0.05)]))
    r = scene.run(tmp_path / "run", progress=False)
    lift = 0.025 * (1 - np.cos(np.pi * r.t))
    assert lift.max() > 0.045
    assert np.abs(r["gauge1.eta"]).max() < 0.005
    p = r["left.p"]
    assert (np.abs(p / p[0] - 1.0) < 0.2).all() and p[0] == pytest.approx(1000.0 * 9.81 * 0.15, rel=0.1)


# ------------------------------------------------------------------------ scene checks
def test_a_scaled_earthquake_keeps_its_baseline_correction(tmp_path):
    """A scaled record is scaled with its baseline (the correction is linear): the tank
    ends at rest (before, ``scale`` dropped the correction)."""
    from cosim.scene.build import _base_motion

    path = tmp_path / "drift.AT2"
    t = np.arange(0.0, 5.0, 0.01)
    g = 0.05 * np.sin(2 * np.pi * t) + 0.002
    path.write_text(HEAD + ACC + f"NPTS=  {t.size}, DT=   .0100 SEC\n"
                    + "\n".join(" ".join(f"{x: .7E}" for x in g[i:i + 5]) for i in range(0, t.size, 5)) + "\n")
    scene = Scene(world=World(dim=2, duration=0.1), fluid=SPH(dx=0.025), domain=Tank(length=0.5, height=0.4, depth=0.2),
                  base_motion=Earthquake(file=str(path), scale=0.5))
    m = _base_motion(scene)
    end = m.signal.state(t[-1] - 1e-9)
    assert abs(end[1]) < 1e-8 and abs(end[0]) < 1e-6


def test_scene_refuses_a_record_shorter_than_the_run_unless_held():
    with pytest.raises(SceneError, match=r"base_motion.components\[0\].file: the record ends at 53.71 s, before "
                                         r"world.duration = 60 s; shorten world.duration to at most 53.71 s, or set "
                                         r"base_motion.hold = true"):
        _scene([Record(file=str(NS), direction=(1.0, 0.0)), Record(file=str(UP), direction=(0.0, 1.0))], 60.0)
    with pytest.raises(SceneError, match=r"components\[1\].file: the record ends at 53.71 s"):
        _scene([Record(file=str(UP), direction=(0.0, 1.0)), Record(file=str(NS), direction=(1.0, 0.0))], 53.75)
    held = _scene([Record(file=str(NS), direction=(1.0, 0.0))], 60.0, hold=True)
    assert held.base_motion.hold


def test_scene_refuses_a_record_too_coarse_for_the_first_sloshing_period(tmp_path):
    """A 0.5 m tank with 0.2 m of water sloshes first at T1 = 0.868 s (linear theory); a
    record sampled every 0.1 s has fewer than 10 samples in it."""
    from cosim.scene.checks import first_sloshing_period

    t1 = first_sloshing_period(_scene([Record(file=str(NS), direction=(1.0, 0.0))]))
    k = math.pi / 0.5
    assert t1 == pytest.approx(2 * math.pi / math.sqrt(9.81 * k * math.tanh(k * 0.2)))
    coarse = _write(tmp_path, HEAD + ACC + "NPTS=   10, DT=   .1000 SEC\n" + ROWS * 2)
    with pytest.raises(SceneError, match=r"components\[0\].file: sampled every 0.1 s: too coarse for the water's "
                                         r"first sloshing period of 0.868 s"):
        _scene([Record(file=str(coarse), direction=(1.0, 0.0))], 0.5)


def test_scene_refuses_more_records_than_axes_and_a_direction_of_the_wrong_size():
    with pytest.raises(SceneError, match="has 3 records; a 2-D scene moves along at most 2 axes"):
        _scene([Record(file=str(p), direction=(1.0, 0.0)) for p in (NS, EW, UP)])
    with pytest.raises(SceneError, match=r"components\[1\].direction: \[0.0, 0.0, 1.0\] has 3 coordinates"):
        _scene([Record(file=str(NS), direction=(1.0, 0.0)), Record(file=str(UP), direction=(0.0, 0.0, 1.0))])
    with pytest.raises(SceneError, match="components: is empty"):
        GroundMotion(components=[])


def test_three_components_move_a_3d_tank(tmp_path):
    """3-D: NS along x, EW along y, UP along z at once; the built motion is their sum and
    the tank's walls are moving walls."""
    from cosim.scene.build import build
    from fluid.particles import Kind

    scene = Scene(world=World(dim=3, duration=0.01, sample_every=0.005, snapshot_every=0), fluid=SPH(dx=0.05),
                  domain=Tank(length=0.3, width=0.2, height=0.3, depth=0.15),
                  base_motion=GroundMotion(components=[Record(file=str(NS), direction=(1.0, 0.0, 0.0)),
                                                       Record(file=str(EW), direction=(0.0, 1.0, 0.0)),
                                                       Record(file=str(UP), direction=(0.0, 0.0, 1.0))], scale=2.0))
    b = build(scene, tmp_path)
    assert (b.sph.ps.kind == Kind.MOVING_WALL).any()
    d, v, a = b.base_motion.state(2.18)
    want = [2.0 * read_at2(p).state(2.18)[0] for p in (NS, EW, UP)]
    np.testing.assert_allclose(d, want, rtol=1e-12, atol=1e-15)
    with pytest.raises(SceneError, match=r"components\[2\].direction: \[0.0, 1.0\] has 2 coordinates"):
        scene.replace(base_motion=GroundMotion(components=[Record(file=str(NS), direction=(1.0, 0.0, 0.0)),
                                                           Record(file=str(EW), direction=(0.0, 1.0, 0.0)),
                                                           Record(file=str(UP), direction=(0.0, 1.0))]))


def test_ground_motion_round_trips_through_toml(tmp_path):
    scene = _scene([Record(file=str(NS), direction=(1.0, 0.0), scale=0.5),
                    Record(file=str(UP), direction=(0.0, 1.0))], scale=2.0, hold=True)
    text = scene.to_toml()
    assert 'kind = "ground_motion"' in text
    p = tmp_path / "s.toml"
    p.write_text(text)
    assert Scene.from_toml(p) == scene
