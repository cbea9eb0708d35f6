"""The GPU path (fluid.cuda) against the CPU path, on numba's CUDA simulator.

The cases run in a process of their own (tests/cuda_sim_worker.py) with
NUMBA_ENABLE_CUDASIM=1, which must be set before numba.cuda is first imported and must not
reach the other tests; the simulator runs each kernel in Python, so the cases are tiny
(156-274 particles), and take 5-30 s each (the 3-D ones the longest; the worker makes
the simulator yield the GIL as it polls its threads, without which a case took up to ten
times longer on a loaded machine, and call device functions without the per-call swap of
their module's ``cuda`` under a lock that every thread contends for, which took three
quarters of a case's time); each runs once, in the one test that checks it.
Skipped, with the reason, where numba-cuda is not installed. Each starts from a disturbed state (positions moved by up to
0.05 dx, velocities of 0.1 m/s, densities within 0.5 %), so that every term acts:

* ``dam2d``: a 2-D dam break, 219 particles (51 fluid), Wendland, Fourtakas diffusion,
  laminar viscosity (nu = 1e-3 m^2/s), XSPH 0.1, MLS re-initialisation every 4 steps, the
  symplectic scheme, DBC walls; one particle flies out of the domain (removal).
* ``body2d``: a 2-D tank (274 particles) swaying at 5 Hz (a prescribed MOVING_WALL motion)
  with Adami walls and their accelerations, a body (BODY group) placed by
  set_particle_motion before every step with mDBC densities, the cubic kernel, Molteni
  diffusion faded under the free surface, alpha 0.05 with alpha_wall 0.3, MLS every 3
  steps (Verlet's n-1 density shifted with it), Verlet with an Euler step every 4.
* ``col3d``: a 3-D column (156 particles, 24 fluid) on a floor beside a wall, Wendland,
  the renormalised (Antuono) diffusion, XSPH, symplectic.
* ``groups2d``: the dam break with its walls in 20 groups, more than a block sums in
  shared memory (``fluid.cuda.kernels.GROUPS_SHARED``).
* ``zones2d``, ``zones3d``: the dam break (Verlet, its n-1 velocity relaxed too) and the
  column (symplectic) with two relaxation zones over the water, one towards a linear wave
  fading in with its return current (heading 0 and 30 deg), one towards rest.
* ``stokes2d``, ``irregular3d``: the same zones towards a Stokes-2 regular wave (the dam
  break, symplectic) and towards an irregular sea of 12 components (the column, heading
  20 deg), which the GPU is given as the CPU would read it from a table
  (``fluid.sea_tables``) and sums at each particle, as the CPU path given it without the
  table does.
* ``tilt2d``, ``tilt3d``: the dam break with Adami walls and the column, under gravity
  tilted off -z (g = (2.5, -9.5) and (1.5, -1.0, -9.6) m/s^2): the Fourtakas diffusion's
  hydrostatic part taken along g.

Tolerance: every compared field (accelerations, density rates, displacements, velocities,
densities, group forces and moments, per-particle boundary forces) agrees within
``RTOL = 1e-10`` of the field's largest magnitude over the particles. Why not bit for bit:
the CPU pair loop sums a particle's neighbour terms in vector lanes (fastmath lets LLVM
reassociate), the GPU's in sequence, and the group loads are summed with atomics in any
order. Why 1e-10: a pair sum holds up to ~100 terms, each up to ~100 times the result where
pressure terms cancel (hydrostatic columns), so reordering moves it by ~100 x 100 x 1.1e-16
~ 1e-12 of its scale per evaluation, and the worker's five steps accumulate five of those; a wrong or
missing term (viscosity, XSPH, diffusion, the fade) moves a field by 1e-6 of its scale or
more. Measured (2026-11-25): at most 2.0e-13 over all fields and steps (body2d after one step).
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from cosim.errors import InputError
from fluid.solver import FluidConfig

HAVE_NUMBA_CUDA = importlib.util.find_spec("numba_cuda") is not None
requires_numba_cuda = pytest.mark.skipif(not HAVE_NUMBA_CUDA,
                                         reason="numba-cuda is not installed (pip install -e '.[gpu]')")

WORKER = Path(__file__).with_name("cuda_sim_worker.py")
RTOL = 1e-10
CASES = ("dam2d", "body2d", "col3d", "tilt2d", "tilt3d", "groups2d", "zones2d", "zones3d", "stokes2d", "irregular3d")
STAGES = ("loop", "step1", "last")
FIELDS = ("acc", "drho", "disp", "vel", "rho", "F", "M", "bforce")


#: ``COSIM_CUDA_TESTS=gpu``: the worker runs the GPU path on the machine's GPU instead of the
#: simulator, and every comparison below holds on the hardware (benchmarks/gpu_session.sh)
ON_GPU = os.environ.get("COSIM_CUDA_TESTS") == "gpu"


def _worker(out: Path, *args) -> dict:
    env = dict(os.environ)
    env.pop("NUMBA_ENABLE_CUDASIM", None)
    if not ON_GPU:
        env["NUMBA_ENABLE_CUDASIM"] = "1"
    r = subprocess.run([sys.executable, str(WORKER), str(out), *args], env=env, capture_output=True, text=True,
                       timeout=900)
    assert r.returncode == 0, r.stderr[-4000:]
    return dict(np.load(out))


def _close(d, key_a, key_b):
    a, b = d[key_a], d[key_b]
    assert a.shape == b.shape, (key_a, a.shape, b.shape)
    scale = np.abs(a).max()
    return np.abs(a - b).max() <= RTOL * scale, f"{key_a}: {np.abs(a - b).max():.3g} against scale {scale:.3g}"


def _case_mismatches(d: dict, case: str) -> list[str]:
    """What differs between the CPU and GPU paths in one case's results: at each stage
    (the first pair loop, one step, the last of the worker's steps) the particles' rows (the sort mirrors the
    CPU's), every field within RTOL of its scale, the stable step (1e-12), the limiter and
    the removals; after the first and the last steps the group loads ``step`` returned (at
    the half step, or at the start with Verlet)."""
    bad = []
    for stage in STAGES:
        p = f"{case}.{stage}"
        if not np.array_equal(d[f"{p}.cpu.rows"], d[f"{p}.gpu.rows"]):
            bad.append(f"{p}: the sort's order differs")
        for field in FIELDS:
            ok, msg = _close(d, f"{p}.cpu.{field}", f"{p}.gpu.{field}")
            if not ok:
                bad.append(msg)
        if abs(d[f"{p}.cpu.dt"] - d[f"{p}.gpu.dt"]) > 1e-12 * d[f"{p}.cpu.dt"]:
            bad.append(f"{p}: stable step {d[f'{p}.cpu.dt']} (CPU) against {d[f'{p}.gpu.dt']} (GPU)")
        if str(d[f"{p}.cpu.limiter"]) != str(d[f"{p}.gpu.limiter"]):
            bad.append(f"{p}: limiter {d[f'{p}.cpu.limiter']} (CPU) against {d[f'{p}.gpu.limiter']} (GPU)")
        if not np.array_equal(d[f"{p}.cpu.removed"], d[f"{p}.gpu.removed"]):
            bad.append(f"{p}: the removals differ")
    for stage in ("step1", "last"):
        for q in ("F", "M"):
            ok, msg = _close(d, f"{case}.{stage}.cpu_step_{q}", f"{case}.{stage}.gpu_step_{q}")
            if not ok:
                bad.append(msg)
    return bad


def _table(dim: int, saved: tuple, xsph: bool) -> int:
    """Bytes per particle of the device state's arrays, as fluid.cuda.state allocates them
    (and fluid.cuda's docstring lists them)."""
    vec, f8 = 8 * dim, 8
    state = 2 * vec + 2 * f8 + 1 + 4 + 4  # positions, velocities, density, mass, kind, group, id
    saved_b = sum(vec if k in ("pos", "vel") else f8 for k in saved)
    scratch = vec + f8 + 4 + 1  # the sort's gather buffers
    rates = 3 * f8 + vec + (vec if xsph else 0)  # drho, sound speed, p/rho^2, acceleration, XSPH
    sort = 4 + 4 + 4  # cell, permutation, the id map (ids run 0..N-1 in these cases)
    return state + saved_b + scratch + rates + sort


def _bytes_per_particle(case: str) -> float | None:
    """Bytes per particle of a case's device state by :func:`_table`: 2-D symplectic with
    XSPH 194 B; 2-D Verlet 162 B with the moving Adami walls' accelerations (16 B) and the
    body's mDBC ghost vectors (16 B for each of its 12 of 274 particles); 3-D symplectic
    with XSPH 250 B (the aim: at most 250 B) and the renormalised diffusion's gradients
    (24 B)."""
    return {"dam2d": _table(2, ("pos", "vel", "rho"), True),
            "body2d": _table(2, ("vel", "rho"), False) + 16 + 16 * 12 / 274,
            "col3d": _table(3, ("pos", "vel", "rho"), True) + 24}.get(case)


@pytest.mark.long  # the simulator: up to a minute a case
@requires_numba_cuda
@pytest.mark.parametrize("case", CASES)
def test_gpu_matches_cpu_to_round_off(case, tmp_path):
    """One case on both paths (its own process: each case runs once, in the test that
    checks it): every stage and load agrees (:func:`_case_mismatches`); the simulator ran
    (the GPU with ``COSIM_CUDA_TESTS=gpu``); the fluid moved; the dam break's flying
    particle left the domain on both paths; the body case's body carries a load; the
    device state takes the bytes per particle its table says."""
    d = _worker(tmp_path / f"{case}.npz", case)
    assert str(d[f"{case}.gpu_class"]) == "CudaFluid"
    assert bool(d["simulator"]) != ON_GPU
    bad = _case_mismatches(d, case)
    assert not bad, f"{case}: " + "; ".join(bad)
    assert np.abs(d[f"{case}.last.cpu_step_F"]).max() > 0.0
    assert np.abs(d[f"{case}.last.gpu.disp"]).max() > 1e-5  # [m]
    if case == "dam2d":
        assert d["dam2d.last.gpu.removed"][0] == 1 and d["dam2d.last.gpu.removed"].sum() == 1
    if case == "body2d":
        assert np.abs(d["body2d.last.gpu.F"][1]).max() > 0.1  # [N] on the body (group 1)
    table = _bytes_per_particle(case)
    if case in ("dam2d", "col3d"):  # the table's own figures
        assert table == {"dam2d": 194, "col3d": 274}[case]
    if table is not None:
        assert d[f"{case}.bytes_per_particle"] == pytest.approx(table, rel=1e-12)


@pytest.mark.long  # the simulator
@requires_numba_cuda
def test_a_near_field_in_stokes2_waves_reads_its_gauges_as_on_the_cpu(tmp_path):
    """nearfield-waves' scene (no body, absorbing end walls) in its Stokes-2 wave on the
    GPU path and on the CPU: the gauges' elevations agree within 1e-10 of their scale (the
    zones, the end walls' readings and motions, the gauges), and the wave moved them."""
    d = _worker(tmp_path / "nearwaves.npz", "nearwaves")
    for k in ("gauge1.eta", "gauge2.eta", "gauge3.eta"):
        cpu, gpu = d[f"nearwaves.cpu.{k}"], d[f"nearwaves.cuda.{k}"]
        assert cpu.shape == gpu.shape and len(cpu) >= 3
        moved = np.abs(cpu - cpu[0]).max()
        assert moved > 1e-7, k  # [m]
        assert np.abs(cpu - gpu).max() <= RTOL * max(np.abs(cpu).max(), 1e-3), k


@pytest.mark.long  # the simulator
@requires_numba_cuda
def test_the_walls_take_a_motions_own_acceleration_on_both_paths(tmp_path):
    """A prescribed wall motion that states its acceleration (``particle_acceleration``, as
    the near field's end walls do) gives the Adami walls that acceleration on the GPU too,
    not a difference of its velocity (``fluid.solver.motion_acceleration``)."""
    d = _worker(tmp_path / "wallacc.npz", "wallacc")
    cpu, gpu = d["wallacc.cpu"], d["wallacc.cuda"]
    assert cpu.shape == gpu.shape and cpu.shape[0] > 50
    assert np.array_equal(cpu, np.broadcast_to([3.0, -1.0], cpu.shape))
    assert np.array_equal(gpu, cpu)


@pytest.mark.long  # the simulator: about 10 s of CPU
@requires_numba_cuda
def test_nan_guard_and_the_project_without_numba_cuda(tmp_path):
    """The GPU path's NaN guard stops with the CPU's message. And in the worker, before
    numba.cuda could be imported: a CPU step ran, and device='cuda' was refused saying
    what to install and how to use the simulator."""
    nan = _worker(tmp_path / "nan.npz", "absent", "nan")
    msg = str(nan["nan.gpu"])
    assert msg and msg == str(nan["nan.cpu"])
    assert "non-finite state" in msg and "particle id 40" in msg
    assert int(nan["absent_cpu_steps"]) == 1
    msg = str(nan["absent_error"])
    assert "numba-cuda is not installed" in msg and "pip install numba-cuda" in msg
    assert "NUMBA_ENABLE_CUDASIM=1" in msg and "device='cpu'" in msg


@pytest.mark.long  # the simulator: about 10 s of CPU
@requires_numba_cuda
def test_a_step_leaves_the_state_on_the_device(tmp_path):
    """Stepping with nothing reading the host copy moves no whole state between host and
    device (each round trip costs more than the step itself on a GPU: 9.4 M particles,
    1.6 s a step with one, docs/fluid_cuda.md); reading ``Fluid.ps`` brings it back once,
    and the next step sends it once."""
    d = _worker(tmp_path / "transfers.npz", "transfers")
    for integrator in ("symplectic", "verlet"):
        assert d[f"transfers.{integrator}.steps"].tolist() == [0, 0], integrator  # [pulls, pushes]
        assert d[f"transfers.{integrator}.read"].tolist() == [1, 0], integrator


@pytest.mark.long  # the simulator: about 10 s of CPU
@requires_numba_cuda
@pytest.mark.parametrize("walls", ["orbits", "absorbing"])
def test_a_near_field_scene_moves_its_body_as_on_the_cpu(walls, tmp_path):
    """A 2-D near field (its zones towards a linear wave on the GPU, k_relax; its end walls on
    the sea's orbits, or absorbing ones that read the surface on the device, k_surface)
    round a floating box, four steps on each path: the box's heave and the gauges within
    RTOL of their largest values, surge and pitch within 1e-12 m and deg."""
    d = _worker(tmp_path / "near.npz", f"near_{walls}")
    cpu, gpu = d[f"near.{walls}.cpu.box.heave"], d[f"near.{walls}.cuda.box.heave"]
    assert np.abs(cpu).max() > 1e-6  # [m] it moved
    assert np.abs(cpu - gpu).max() <= RTOL * np.abs(cpu).max()
    for q in ("gauge1.eta", "gauge2.eta"):
        a, b = d[f"near.{walls}.cpu.{q}"], d[f"near.{walls}.cuda.{q}"]
        assert np.isfinite(a).all() and np.abs(a - b).max() <= RTOL * np.abs(a).max(), q
    for q in ("surge", "pitch"):
        assert np.abs(d[f"near.{walls}.cpu.box.{q}"] - d[f"near.{walls}.cuda.box.{q}"]).max() <= 1e-12


@pytest.mark.long  # the simulator: about 10 s of CPU
@requires_numba_cuda
def test_the_free_surface_is_read_on_the_device_as_on_the_cpu(tmp_path):
    """fluid.probes.surface_elevation on a GPU fluid (kernels.k_surface, one thread a gauge)
    against the CPU's, 2-D and 3-D, a dry gauge among them: within 1e-12 m."""
    d = _worker(tmp_path / "surface.npz", "surface")
    for tag in ("2d", "3d"):
        cpu, gpu = d[f"surface.{tag}.cpu"], d[f"surface.{tag}.cuda"]
        assert np.isfinite(cpu).all(), cpu
        assert np.abs(cpu - gpu).max() <= 1e-12, (tag, cpu, gpu)


@pytest.mark.slow
@requires_numba_cuda
def test_a_coupled_scene_moves_its_body_as_on_the_cpu(tmp_path):
    """A scene with a floating box (MuJoCo, the coupler, mDBC, the body placed every
    exchange) run with fluid.device = "cuda" on the simulator and on the CPU: the box's
    heave within RTOL of its largest value (measured: equal to the last digit the probes
    keep), surge and pitch (zero by symmetry) within 1e-9 m and 1e-9 deg. About 25 s of
    CPU, hence slow."""
    d = _worker(tmp_path / "scene.npz", "--scene")
    cpu, gpu = d["scene.cpu.box.heave"], d["scene.cuda.box.heave"]
    assert np.abs(cpu).max() > 1e-4  # [m] it moved
    assert np.abs(cpu - gpu).max() <= RTOL * np.abs(cpu).max()
    assert np.abs(d["scene.cpu.box.surge"] - d["scene.cuda.box.surge"]).max() <= 1e-9
    assert np.abs(d["scene.cpu.box.pitch"] - d["scene.cuda.box.pitch"]).max() <= 1e-9


def test_device_is_validated_with_a_clear_error():
    with pytest.raises(InputError, match="device='gpu'.*'cpu'.*'cuda'"):
        FluidConfig(c0=20.0, device="gpu")
    with pytest.raises(InputError, match=r"symmetry_y=0.0 is not available with device='cuda'; leave symmetry_y "
                                         r"unset .* fluid.mirror, are made on the CPU only"):
        FluidConfig(dim=3, c0=20.0, device="cuda", symmetry_y=0.0)
    if "precision" in FluidConfig.__dataclass_fields__:  # the CPU's float32 pair terms
        with pytest.raises(InputError, match="precision='float32' is not available with device='cuda'"):
            FluidConfig(c0=20.0, device="cuda", precision="float32")


def test_the_scene_passes_the_device_to_the_fluid():
    from cosim.scene import SPH, Scene, Tank, World
    from cosim.scene.setup import choose

    scene = Scene(world=World(dim=2, duration=0.1), fluid=SPH(dx=0.02, device="cuda"),
                  domain=Tank(length=0.5, height=0.3, depth=0.2))
    assert choose(scene).config["device"] == "cuda"
    assert "device" not in choose(scene.with_values(["fluid.dx=0.02"]).replace(fluid=SPH(dx=0.02))).config
    with pytest.raises(InputError, match="fluid.device"):
        scene.with_values(["fluid.device='gpu'"])


def test_a_near_field_on_the_gpu_takes_every_sea_and_refuses_other_zones():
    """A near-field scene with fluid.device = "cuda" is accepted in linear, Stokes-2 and
    irregular seas (the GPU relaxes its zones towards each: cases stokes2d, irregular3d);
    the fluid refuses a zone towards anything else, naming it and the way out."""
    from cosim.scene import SPH, Box, NearField, RegularWaves, Scene, World
    from fluid.cuda.fluid import _zone_on_device
    from fluid.nearfield import SeaVelocity
    from fluid.relaxation import Slab
    from fluid.waves import RegularWave, Sea

    scene = Scene(world=World(dim=2, duration=0.1), fluid=SPH(dx=0.05, device="cuda"), domain=NearField(depth=0.3),
                  waves=RegularWaves(height=0.04, period=1.0, depth=0.3, theory="stokes2"),
                  bodies=[Box("box", size=(0.2, 0.1), density=500.0, pos=(1.2,), place="floating")])
    irregular = scene.with_values(['waves={kind="irregular", hs=0.04, tp=1.0, depth=0.3}'])
    assert irregular.waves.hs == 0.04 and scene.waves.theory == "stokes2"

    wave = RegularWave(0.01, 0.5, 0.1, level=0.1, theory="stokes2")
    assert _zone_on_device(Slab(0, 0.03, 0.0, 30.0, SeaVelocity(wave)), 0).sea is wave

    class Cubic(Sea):  # a sea with terms beyond linear superposition that the GPU does not sum
        def _add_higher_order(self, sums, s, zeta, t, want):
            pass

    odd = object.__new__(Cubic)
    with pytest.raises(InputError, match="relaxation zone 1 relaxes towards a Cubic with terms beyond linear theory; "
                                         "the GPU relaxes towards rest, a linear sea or a Stokes-2 regular wave; use "
                                         "device='cpu'"):
        _zone_on_device(Slab(0, 0.03, 0.0, 30.0, SeaVelocity(odd)), 1)
    with pytest.raises(InputError, match="relaxation zone 2 relaxes towards a function"):
        _zone_on_device(Slab(0, 0.03, 0.0, 30.0, lambda pos, t: pos), 2)
