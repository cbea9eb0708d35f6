"""Run by tests/test_fluid_cuda.py in a process of its own with NUMBA_ENABLE_CUDASIM=1 (the
flag must be set before numba.cuda is first imported, and must not reach the other tests):
steps small cases on the CPU path and on the GPU path (numba's CUDA simulator, or the GPU
without the flag) side by side and saves what the tests compare into an .npz file.

``python tests/cuda_sim_worker.py OUT.npz [PART ...]`` (default: :data:`ABSENT` and every
part of :data:`PARTS`). First, with numba.cuda made unimportable, where the parts name
:data:`ABSENT`, it runs the CPU path and records the error ``FluidConfig(device="cuda")``
gives (the project without numba-cuda). ``python tests/cuda_sim_worker.py OUT.npz --scene``: a coupled scene
on both paths (:func:`scene_run`).
"""

from __future__ import annotations

import sys

sys.modules["numba.cuda"] = None  # numba-cuda "absent" for the first check

import numpy as np  # noqa: E402

from cosim.errors import InputError, InstabilityError  # noqa: E402
from fluid.geometry import assemble, block, tank_walls  # noqa: E402
from fluid.particles import Kind  # noqa: E402
from fluid.solver import Fluid, FluidConfig  # noqa: E402

OUT = {}


def absent_check() -> None:
    """The CPU path without numba.cuda, and the refusal of device='cuda'."""
    ps = dam_2d()
    f = Fluid(FluidConfig(dim=2, dx=0.01, c0=20.0), ps)
    f.initialize(0.0)
    f.step(f.max_dt())
    OUT["absent_cpu_steps"] = np.array(f.counters.steps)
    try:
        FluidConfig(dim=2, dx=0.01, c0=20.0, device="cuda")
        OUT["absent_error"] = np.array("")
    except InputError as e:
        OUT["absent_error"] = np.array(str(e))


def disturbed(ps, dx: float, seed: int):
    """Fluid particles moved by up to 0.05 dx, given velocities of 0.1 m/s and densities
    within 0.5 % of rho0 (every pair term then acts: viscosity, XSPH, diffusion)."""
    rng = np.random.default_rng(seed)
    fl = ps.kind == Kind.FLUID
    ps.pos[fl] += rng.uniform(-0.05, 0.05, (fl.sum(), ps.dim)) * dx
    ps.vel[fl] = rng.uniform(-0.1, 0.1, (fl.sum(), ps.dim))
    ps.rho[fl] *= 1.0 + rng.uniform(-0.005, 0.005, fl.sum())
    return ps


#: the id of dam_2d's particle above the water (sent out of the domain in the dam2d case)
FLYER = 50


def dam_2d():
    """A 2-D dam break: a 0.05 x 0.1 m column in a 0.2 m tank, dx 0.01 m (219 particles,
    51 fluid), and one fluid particle above the water, id :data:`FLYER`."""
    dx = 0.01
    walls = tank_walls(np.zeros(2), np.array([0.2, 0.15]), dx, 3)
    fl = np.vstack([block(np.zeros(2), np.array([0.05, 0.1]), dx), [[0.15, 0.1445]]])
    return assemble(2, dx, 1000.0, fl, [(walls, Kind.FIXED_WALL, 0)]).particles


def body_2d():
    """Water 0.06 m deep in a 0.2 m tank (MOVING_WALL group 0) and a 0.04 x 0.03 m body
    (BODY group 1) across its surface, dx 0.01 m."""
    dx = 0.01
    walls = tank_walls(np.zeros(2), np.array([0.2, 0.12]), dx, 3)
    body = block(np.array([0.08, 0.045]), np.array([0.12, 0.075]), dx)
    fl = block(np.zeros(2), np.array([0.2, 0.06]), dx)
    return assemble(2, dx, 1000.0, fl, [(walls, Kind.MOVING_WALL, 0), (body, Kind.BODY, 1)]).particles


def sway(t, ref):
    """The tank's prescribed motion: 2 mm at 5 Hz along x (2 m/s^2 at most)."""
    w = 2.0 * np.pi * 5.0
    pos, vel = ref.copy(), np.zeros_like(ref)
    pos[:, 0] += 0.002 * np.sin(w * t)
    vel[:, 0] = 0.002 * w * np.cos(w * t)
    return pos, vel


def column_3d():
    """A 3-D water column 0.06 x 0.04 x 0.08 m on a floor of two layers with one side wall,
    dx 0.02 m (156 particles, 24 fluid)."""
    dx = 0.02
    floor = block(np.array([-0.04, -0.04, -0.04]), np.array([0.12, 0.08, 0.0]), dx)
    side = block(np.array([-0.04, -0.04, 0.0]), np.array([0.0, 0.08, 0.06]), dx)
    fl = block(np.zeros(3), np.array([0.06, 0.04, 0.08]), dx)
    return assemble(3, dx, 1000.0, fl, [(np.vstack([floor, side]), Kind.FIXED_WALL, 0)]).particles


def many_groups(ps):
    """The walls split into 20 groups by id (ids mod 20), more than the GPU's group sums
    keep in shared memory (fluid.cuda.kernels.GROUPS_SHARED): both of its paths add up."""
    walls = ps.group >= 0
    ps.group[walls] = ps.ids[walls] % 20
    return ps


def by_id(f, a):
    """``a`` (rows in f.ps's current order) in particle-id order."""
    return np.asarray(a)[np.argsort(f.ps.ids)]


def record(tag, cpu, gpu, pos0_cpu, pos0_gpu, loads=None):
    for name, f, pos0 in (("cpu", cpu, pos0_cpu), ("gpu", gpu, pos0_gpu)):
        ps = f.ps
        order = np.argsort(ps.ids)
        OUT[f"{tag}.{name}.ids"] = ps.ids[order]
        OUT[f"{tag}.{name}.rows"] = ps.ids  # the rows' order: the sort's
        OUT[f"{tag}.{name}.disp"] = ps.pos[order] - pos0[ps.ids[order]]
        OUT[f"{tag}.{name}.vel"] = ps.vel[order]
        OUT[f"{tag}.{name}.rho"] = ps.rho[order]
        OUT[f"{tag}.{name}.acc"] = f._acc[order]
        OUT[f"{tag}.{name}.drho"] = f._drho[order]
        OUT[f"{tag}.{name}.dt"] = np.array(f.max_dt())
        OUT[f"{tag}.{name}.limiter"] = np.array(f.limit.limiter)
        OUT[f"{tag}.{name}.removed"] = np.array([f.counters.removed[k.name] for k in Kind])
        F, M = f.group_forces_now()
        OUT[f"{tag}.{name}.F"] = F
        OUT[f"{tag}.{name}.M"] = M
        OUT[f"{tag}.{name}.bforce"] = f.boundary_forces_now()[order]
    if loads is not None:
        for name, (F, M) in zip(("cpu", "gpu"), loads):
            OUT[f"{tag}.cpu_step_F" if name == "cpu" else f"{tag}.gpu_step_F"] = F
            OUT[f"{tag}.cpu_step_M" if name == "cpu" else f"{tag}.gpu_step_M"] = M


class Both:
    """Two boundary-correction hooks in turn (as cosim.sph_fluid joins the walls' and the
    bodies' mDBC)."""

    def __init__(self, first, second):
        self.first, self.second = first, second

    def __call__(self, ps, start, grid) -> None:
        self.first(ps, start, grid)
        self.second(ps, start, grid)


def box_mdbc(ps, group: int, lo, hi, config: dict):
    """mDBC for the box-shaped group ``group`` (faces at ``lo``, ``hi`` [m]): each particle's
    ghost vector is twice its distance to the nearest face, along the face's outward
    normal (a mirror image, as bodies.sampling.ghost_offsets makes them)."""
    from fluid.boundary_correction import MDBC

    c = FluidConfig(**config)
    m = MDBC(c.dim, c.h, c.rho0, c.kernel, int(ps.ids.max()) + 1)
    sel = ps.group == group
    p = ps.pos[sel]
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    d = np.concatenate([p - lo, hi - p], axis=1)  # distances to the faces -x, -z, +x, +z
    k = np.argmin(d, axis=1)
    normal = np.zeros_like(p)
    normal[np.arange(len(p)), k % p.shape[1]] = np.where(k < p.shape[1], -1.0, 1.0)
    m.set_offsets(ps.ids[sel], 2.0 * d[np.arange(len(p)), k][:, None] * normal)
    return m


def run_case(tag: str, ps, config: dict, steps: int = 5, body=None, motion=None, hook=None, zones=(), gpu_zones=None):
    """Initialise the case on both paths (the first pair loop), step once, then to
    ``steps`` (recorded as the stage "last"; 5 pass a density re-initialisation every 3 or
    4 steps and a Verlet reset every 4); with ``body = (group, velocity)`` the body's
    particles are placed before every step (positions at the step's time, as the coupler places them); ``motion =
    (group, motion)`` a prescribed wall motion; ``hook()`` a boundary correction made for
    each path, run after the fluid's own; ``zones`` relaxation zones (fluid.relaxation.Slab),
    ``gpu_zones`` the GPU path's where they differ (the same targets, as each path is given them)."""
    cpu = Fluid(FluidConfig(**config), ps)
    gpu = Fluid(FluidConfig(device="cuda", **config), ps)
    cpu.zones, gpu.zones = list(zones), list(zones if gpu_zones is None else gpu_zones)
    if hook is not None:
        for f in (cpu, gpu):
            own, new = f.boundary_correction, hook()
            f.boundary_correction = new if own is None else Both(own, new)
    if motion is not None:
        for f in (cpu, gpu):
            f.prescribe_motion(*motion)
    OUT[f"{tag}.gpu_class"] = np.array(type(gpu).__name__)
    pos0 = ps.pos[np.argsort(ps.ids)].copy()
    ids_b = ref_b = None
    if body is not None:
        sel = ps.group == body[0]
        ids_b, ref_b = ps.ids[sel], ps.pos[sel].copy()
    for f in (cpu, gpu):
        f.initialize(0.0)
    OUT[f"{tag}.bytes_per_particle"] = np.array(gpu.device_memory["bytes_per_particle"])
    record(f"{tag}.loop", cpu, gpu, pos0, pos0)
    t = 0.0
    for k in range(steps):
        dt = cpu.max_dt()
        OUT[f"{tag}.gpu_dt_{k}"] = np.array(gpu.max_dt())
        OUT[f"{tag}.cpu_dt_{k}"] = np.array(dt)
        if body is not None:
            v = np.broadcast_to(np.asarray(body[1], float), ref_b.shape)
            for f in (cpu, gpu):
                f.set_particle_motion(ids_b, ref_b + v * t, v)
        loads = [f.step(dt) for f in (cpu, gpu)]
        t += dt
        if k == 0:
            record(f"{tag}.step1", cpu, gpu, pos0, pos0, loads)
    record(f"{tag}.last", cpu, gpu, pos0, pos0, loads)


def nan_guard():
    """A NaN velocity put into one fluid particle: both paths stop with their message."""
    msgs = []
    for device in ("cpu", "cuda"):
        f = Fluid(FluidConfig(dim=2, dx=0.01, c0=20.0, device=device), dam_2d())
        f.initialize(0.0)
        ps = f.ps
        i = int(np.flatnonzero(ps.ids == 40)[0])
        ps.vel[i, 0] = np.nan
        try:
            f.step(f.max_dt())
            msgs.append("")
        except InstabilityError as e:
            msgs.append(str(e))
    OUT["nan.cpu"], OUT["nan.gpu"] = np.array(msgs[0]), np.array(msgs[1])


def transfers():
    """Whole-state transfers between host and device (DeviceState.pull and push) while a
    fluid steps with nothing reading its host copy: none is expected (a step brings back
    three scalars and the group loads only); reading ``Fluid.ps`` then pulls once. Both
    integrators, with a density re-initialisation every other step."""
    from fluid.cuda.state import DeviceState

    counts = {"pull": 0, "push": 0}
    for name in counts:
        def counted(self, *args, _f=getattr(DeviceState, name), _name=name):
            counts[_name] += 1
            return _f(self, *args)
        setattr(DeviceState, name, counted)
    for integrator in ("symplectic", "verlet"):
        f = Fluid(FluidConfig(dim=2, dx=0.01, c0=20.0, device="cuda", integrator=integrator, mls_every=2),
                  disturbed(dam_2d(), 0.01, 6))
        f.initialize(0.0)
        counts.update(pull=0, push=0)
        for _ in range(3):
            f.step(f.max_dt())
        OUT[f"transfers.{integrator}.steps"] = np.array([counts["pull"], counts["push"]])
        f.ps.pos.sum()
        OUT[f"transfers.{integrator}.read"] = np.array([counts["pull"], counts["push"]])


def wall_accelerations():
    """The swaying tank's wall accelerations as each path hands them to the Adami walls, by
    particle id, after one step: the motion's own ``particle_acceleration`` (here a
    constant, which no difference of its velocity gives) where it has one, on both paths."""
    def motion(t, ref):
        return sway(t, ref)

    motion.particle_acceleration = lambda t, ref: np.broadcast_to(np.array([3.0, -1.0]), ref.shape)
    for device in ("cpu", "cuda"):
        f = Fluid(FluidConfig(dim=2, dx=0.01, c0=20.0, walls="adami", device=device), body_2d())
        f.prescribe_motion(0, motion)
        f.initialize(0.0)
        f.step(f.max_dt())
        if device == "cpu":
            acc, ids = f.prescribed_acceleration(), f.ps.ids
        else:
            dev = f._to_device()
            acc, ids = dev.accw.copy_to_host()[:, :dev.n].T, dev.a["ids"].copy_to_host()[:dev.n]
        moving = np.isin(ids, f.ps.ids[f.ps.kind == int(Kind.MOVING_WALL)])
        OUT[f"wallacc.{device}"] = acc[moving][np.argsort(ids[moving])]


def scene_run(out: str) -> None:
    """A coupled scene on both paths: a 0.1 x 0.06 m box of 500 kg/m^3 released 15 mm above
    its floating height in a 0.4 m tank (centred at the still water, it floats: it would
    hardly move), 2-D, dx 0.02 m, 10 ms (the coupler, MuJoCo, the bodies' mDBC
    and set_particle_motion every exchange); its motion probes."""
    import tempfile

    from numba import cuda  # noqa: F401  (the simulator)

    from cosim.scene import SPH, Box, Scene, Tank, World

    for device in ("cpu", "cuda"):
        scene = Scene(name="gpu_scene", world=World(dim=2, duration=0.01, sample_every=0.005),
                      fluid=SPH(dx=0.02, device=device, c0=15.0), domain=Tank(length=0.4, height=0.3, depth=0.16),
                      bodies=[Box("box", size=(0.1, 0.06), density=500.0, pos=(0.2, 0.175))])
        with tempfile.TemporaryDirectory() as d:
            r = scene.run(d)
            for k in ("box.surge", "box.heave", "box.pitch"):
                OUT[f"scene.{device}.{k}"] = np.asarray(r[k], float)
    np.savez(out, **OUT)


def _dam2d():
    dam = disturbed(dam_2d(), 0.01, 1)
    dam.vel[dam.ids == FLYER] = (0.0, 6.0)  # out through the domain's top within the steps
    run_case("dam2d", dam,
             dict(dim=2, dx=0.01, c0=20.0, nu=1e-3, xsph_eps=0.1, mls_every=4, domain_lo=(-0.05, -0.05),
                  domain_hi=(0.25, 0.146)))


def _body2d():
    body = disturbed(body_2d(), 0.01, 2)
    cfg = dict(dim=2, dx=0.01, c0=20.0, kernel="cubic", diffusion="molteni", alpha=0.05, alpha_wall=0.3,
               diffusion_at_surface=False, integrator="verlet", verlet_reset=4, walls="adami", mls_every=3)
    run_case("body2d", body, cfg, body=(1, (0.1, -0.05)), motion=(0, sway),
             hook=lambda: box_mdbc(body, 1, (0.075, 0.04), (0.125, 0.08), cfg))


def sea_zones(dim: int, heading: float, kind: str = "linear", reach=None):
    """Two relaxation zones across a water column 0.1 m (2-D) or 0.08 m (3-D) deep: towards a
    sea with its return current (from x = 0.03 m down to 0) and towards rest (from x = 0.03 m
    up to 0.06 m), each over part of the column. ``kind``: the sea, a "linear" regular wave
    fading in over 0.2 s, or at full height from the start (so that the second order's
    terms, faded in with the square, act in the first steps) a "stokes2" regular wave or an
    "irregular" one of 12 components; ``reach``:
    the (lo, hi) [m] over which the CPU would read that from a table (fluid.sea_tables)."""
    from fluid.nearfield import sea_velocity
    from fluid.relaxation import Slab
    from fluid.waves import RegularWave, SpectralSea

    depth = 0.1 if dim == 2 else 0.08
    ramp = 0.2 if kind == "linear" else 0.0
    if kind == "irregular":
        sea = SpectralSea(0.01, 0.5, depth, n_components=12, seed=3, direction=heading, ramp=ramp, level=depth)
    else:
        sea = RegularWave(0.01, 0.5, depth, direction=heading, ramp=ramp, level=depth, theory=kind)
    return (Slab(0, 0.03, 0.0, 30.0, sea_velocity(sea, reach=reach)), Slab(0, 0.03, 0.06, 10.0, None))


def near_field_scene(walls: str) -> None:
    """A 2-D near field (relaxation zones towards a linear regular wave, its end walls on
    the wave's orbits, ``walls = "orbits"``, or absorbing ones, ``"absorbing"``) round a
    floating box, dx = 0.05 m, four steps, on both paths: the box's heave, surge and
    pitch, and the gauges' elevations."""
    import tempfile

    from cosim.scene import SPH, Box, NearField, RegularWaves, Scene, World

    for device in ("cpu", "cuda"):
        scene = Scene(name="gpu_near_field", world=World(dim=2, duration=0.004, sample_every=0.002),
                      fluid=SPH(dx=0.05, device=device),
                      domain=NearField(depth=0.3, absorbing_walls=walls == "absorbing"),
                      waves=RegularWaves(height=0.04, period=1.0, depth=0.3),
                      bodies=[Box("box", size=(0.2, 0.1), density=500.0, pos=(1.2,), place="floating")])
        scene = scene.with_values(["probes.gauges=[0.8, 1.6]"])
        with tempfile.TemporaryDirectory() as d:
            r = scene.run(d, progress=False)
            for k in ("box.surge", "box.heave", "box.pitch", "gauge1.eta", "gauge2.eta"):
                OUT[f"near.{walls}.{device}.{k}"] = np.asarray(r[k], float)


def near_waves() -> None:
    """nearfield-waves' scene (a 2-D near field with no body) at dx = 0.06 m, its Stokes-2
    wave at full height from the start (so that the second order acts in the first steps),
    absorbing end walls, no settling, five steps on both paths: the elevations at three
    gauges in its relaxation zones."""
    import tempfile
    from pathlib import Path

    from cosim.scene import Scene

    path = Path(__file__).parents[1] / "cosim" / "validations" / "scenes" / "nearfield-waves.toml"
    for device in ("cpu", "cuda"):
        scene = Scene.from_toml(path).with_values(
            ["fluid.dx=0.06", "world.duration=0.006", "world.sample_every=0.002", "fluid.settle=0",
             "waves.ramp=0", "domain.absorbing_walls=true", "probes.gauges=[0.3, 0.6, 2.9]",
             f"fluid.device='{device}'"])
        with tempfile.TemporaryDirectory() as d:
            r = scene.run(d, progress=False)
            for k in ("gauge1.eta", "gauge2.eta", "gauge3.eta"):
                OUT[f"nearwaves.{device}.{k}"] = np.asarray(r[k], float)


def surfaces() -> None:
    """The free surface's height at gauges across the dam break (2-D) and the column (3-D),
    one of them dry, after two steps, read on both paths (fluid.probes.surface_elevation)."""
    from fluid.probes import surface_elevation

    for tag, ps, config, gauges in (
            ("2d", disturbed(dam_2d(), 0.01, 10), dict(dim=2, dx=0.01, c0=20.0, domain_lo=(-0.05, -0.05),
                                                          domain_hi=(0.25, 0.2)), [0.005, 0.024, 0.047, 0.12]),
            ("3d", disturbed(column_3d(), 0.02, 11), dict(dim=3, dx=0.02, c0=20.0),
             [[0.01, 0.01], [0.03, 0.02], [0.055, 0.035], [0.1, 0.02]])):
        for device in ("cpu", "cuda"):
            f = Fluid(FluidConfig(device=device, **config), ps)
            f.initialize(0.0)
            for _ in range(2):
                f.step(f.max_dt())
            OUT[f"surface.{tag}.{device}"] = surface_elevation(f, gauges)


#: what the worker runs, by name: the cases, and the NaN guard. Gravity tilted off -z (tilt*):
#: the Fourtakas diffusion's hydrostatic part along g, Adami walls in 2-D
PARTS = {
    "dam2d": _dam2d,
    "body2d": _body2d,
    "col3d": lambda: run_case("col3d", disturbed(column_3d(), 0.02, 3),
                              dict(dim=3, dx=0.02, c0=20.0, xsph_eps=0.1, diffusion="antuono")),
    "tilt2d": lambda: run_case("tilt2d", disturbed(dam_2d(), 0.01, 4),
                               dict(dim=2, dx=0.01, c0=20.0, g=(2.5, -9.5), walls="adami", domain_lo=(-0.05, -0.05),
                                    domain_hi=(0.25, 0.2))),
    "tilt3d": lambda: run_case("tilt3d", disturbed(column_3d(), 0.02, 5),
                               dict(dim=3, dx=0.02, c0=20.0, g=(1.5, -1.0, -9.6))),
    "groups2d": lambda: run_case("groups2d", many_groups(disturbed(dam_2d(), 0.01, 7)),
                                 dict(dim=2, dx=0.01, c0=20.0, domain_lo=(-0.05, -0.05), domain_hi=(0.25, 0.2))),
    "zones2d": lambda: run_case("zones2d", disturbed(dam_2d(), 0.01, 8),
                                dict(dim=2, dx=0.01, c0=20.0, integrator="verlet", verlet_reset=4,
                                     domain_lo=(-0.05, -0.05), domain_hi=(0.25, 0.2)), zones=sea_zones(2, 0.0)),
    "zones3d": lambda: run_case("zones3d", disturbed(column_3d(), 0.02, 9), dict(dim=3, dx=0.02, c0=20.0),
                                zones=sea_zones(3, 30.0)),
    "stokes2d": lambda: run_case("stokes2d", disturbed(dam_2d(), 0.01, 11),
                                 dict(dim=2, dx=0.01, c0=20.0, domain_lo=(-0.05, -0.05), domain_hi=(0.25, 0.2)),
                                 zones=sea_zones(2, 0.0, "stokes2")),
    "irregular3d": lambda: run_case("irregular3d", disturbed(column_3d(), 0.02, 12), dict(dim=3, dx=0.02, c0=20.0),
                                    zones=sea_zones(3, 20.0, "irregular"),
                                    gpu_zones=sea_zones(3, 20.0, "irregular", reach=(-0.5, 0.5))),
    "near_orbits": lambda: near_field_scene("orbits"),
    "near_absorbing": lambda: near_field_scene("absorbing"),
    "nearwaves": near_waves,
    "surface": surfaces,
    "nan": nan_guard,
    "transfers": transfers,
    "wallacc": wall_accelerations,
}


def yielding_simulator() -> None:
    """Make numba's CUDA simulator give up the GIL each time it polls a block's threads,
    call a device function without the module swap it already is in, and read an array in
    a kernel with one call.

    The simulator runs a block's threads as Python threads while its main thread polls
    them in a loop that never releases the GIL, so a thread woken from ``syncthreads``
    waits for the interpreter's forced switch (5 ms) each time, and a case's time grows
    with the machine's load, by up to ten times (docs/development.md). A ``time.sleep(0)``
    in the poll (the simulator's ``BlockThread.is_alive``) hands the GIL over at once. No
    result changes (the threads still run one at a time under the GIL)."""
    import threading
    import time

    from fluid.cuda import simulator

    if not simulator():  # a GPU
        return
    from numba.cuda.simulator import kernel

    def is_alive(thread) -> bool:
        time.sleep(0)
        return threading.Thread.is_alive(thread)

    kernel.BlockThread.is_alive = is_alive

    # Every call of a device function enters the simulator's swap of its module's ``cuda``
    # for the fake one, under a lock that every thread of the block contends for (most of a
    # case's time). The swap changes nothing where the module is already swapped (by the
    # running kernel, for as long as it runs) or holds no ``cuda`` (the shared physics
    # terms): call the function.
    from numba import cuda
    from numba.cuda.simulator import kernelapi

    device_call = kernel.FakeCUDAKernel.__call__
    swaps = kernelapi._swap_refcount

    def call(self, *args):
        # found once per function: None for a kernel; True where its module holds no cuda;
        # else the id of its module's globals, which a running kernel of that module swapped
        try:
            module = self._module_swap
        except AttributeError:
            g = self.fn.__globals__
            module = self._module_swap = (None if not self._device
                                          else not any(v is cuda for v in g.values()) or id(g))
        if module is True or (module is not None and swaps.get(module, 0) > 0):
            return self.fn(*args)
        return device_call(self, *args)

    kernel.FakeCUDAKernel.__call__ = call

    # An array read in a kernel goes through two wrappers' methods (the in-kernel array's,
    # then the array's, which builds a list to test the item's type): a quarter to a half of
    # a case's CPU time. Read the NumPy array under both, wrapping what is still an array as
    # they would.
    from numba.cuda.simulator.cudadrv import devicearray

    fake, within = devicearray.FakeCUDAArray, devicearray.FakeWithinKernelCUDAArray
    arrays = (np.ndarray, np.void)

    def read(self, idx):
        inner = self._item
        item = inner._ary[idx]
        if type(item) in arrays:
            return within(fake(item, stream=inner.stream))
        return item

    def write(self, idx, value):
        self._item._ary[idx] = value

    within.__getitem__, within.__setitem__ = read, write


#: what a kernel's code names where its threads must run side by side: the block's barriers,
#: its shared memory, warp and cooperative-group functions (:func:`sequential_blocks`)
SIDE_BY_SIDE = frozenset({
    "syncthreads", "syncthreads_count", "syncthreads_and", "syncthreads_or", "shared", "cg", "this_grid", "sync",
    "syncwarp", "activemask", "lanemask_lt", "all_sync", "any_sync", "eq_sync", "ballot_sync", "shfl_sync",
    "shfl_up_sync", "shfl_down_sync", "shfl_xor_sync", "match_any_sync", "match_all_sync"})


def sequential_blocks() -> None:
    """Run the blocks of a kernel that never waits for its block's other threads one thread
    after another in the main thread, with no Python threads.

    The simulator starts a Python thread for every thread of every block and polls them
    until they end (``kernel.BlockManager.run``): for the many small kernels of a step
    (cell build and sort, gathers, integrators) starting, polling and handing the GIL
    between the threads costs more than their work (docs/development.md). A thread that
    never meets a barrier can as well run to its end before the next starts, as the
    threads run one at a time under the GIL anyway. Which kernels qualify is found once per
    kernel function, from its code: neither it nor any device function it calls (the
    names in their code objects, nested ones included, looked up in their globals, closures
    and the namespaces they name, such as ``tm``) names a barrier, shared memory, warp or
    cooperative-group function (:data:`SIDE_BY_SIDE`); the others, and every kernel
    launched with ``debug=True``, run on the simulator's threads as before. While a block
    runs, kernelapi's ``threading`` is a stand-in whose ``current_thread()`` gives the
    running thread's indices (a barrier there raises), restored after, also on an
    exception; each thread runs under NumPy's floating-point error state as a new thread
    has it. An exception in a kernel is raised as the simulator raises it (its type, the
    message prefixed with ``tid=[...] ctaid=[...]``). Atomics take their lock as before.

    Limits: the threads of a block run in index order, so where they race (the fill of a
    cell by atomics, which the sort then orders; floating-point sums by atomics) the
    result is one of the orders the threaded run may give, but always the same one; a
    kernel reading another thread's writes to global memory without a barrier (wrong on a
    GPU as well) would see every earlier thread's writes; and a name is all the check
    sees: a barrier reached through something it does not look into (a function passed as
    an argument, a device function named through an object other than a module or
    namespace) is not found, and would raise there."""
    import threading
    import types as pytypes

    from fluid.cuda import simulator

    if not simulator():  # a GPU
        return
    from numba import cuda
    from numba.cuda.simulator import kernel, kernelapi

    device = kernel.FakeCUDAKernel
    Dim3 = kernelapi.Dim3

    def side_by_side(fn, seen) -> bool:
        """Whether ``fn`` or a function it calls names one of SIDE_BY_SIDE."""
        if fn in seen:
            return False
        seen.add(fn)
        code = fn.__code__
        scope = dict(fn.__globals__)
        for name, cell in zip(code.co_freevars, fn.__closure__ or ()):
            try:
                scope[name] = cell.cell_contents
            except ValueError:  # an empty cell
                pass
        todo = [code]
        while todo:
            c = todo.pop()
            if SIDE_BY_SIDE.intersection(c.co_names):
                return True
            todo.extend(k for k in c.co_consts if isinstance(k, pytypes.CodeType))
            for name in c.co_names + c.co_freevars:
                v = scope.get(name)
                if v is None or v is cuda:
                    continue
                if isinstance(v, (pytypes.ModuleType, pytypes.SimpleNamespace)):  # tm.term(...)
                    for attr in c.co_names:
                        w = vars(v).get(attr)
                        if isinstance(w, device) and side_by_side(w.fn, seen):
                            return True
                elif isinstance(v, device) and side_by_side(v.fn, seen):
                    return True
                elif isinstance(v, pytypes.FunctionType) and side_by_side(v, seen):
                    return True
        return False

    decided = {}  # kernel function: whether its blocks run in the main thread

    class Thread:
        """What ``threading.current_thread()`` gives kernelapi while a block runs here."""

        __slots__ = ("blockIdx", "threadIdx", "thread_id")

        def syncthreads(self, *args):
            raise RuntimeError("syncthreads in a kernel run one thread after another (tests/cuda_sim_worker.py)")

        syncthreads_count = syncthreads_and = syncthreads_or = syncthreads

    current = Thread()
    stand_in = pytypes.SimpleNamespace(current_thread=lambda: current)

    fresh = []  # NumPy's error state in a new thread (the simulator's threads run under it)
    t = threading.Thread(target=lambda: fresh.append(np.geterr()))
    t.start()
    t.join()
    fresh = fresh[0]

    threaded, own = kernel.BlockManager.run, kernelapi.threading

    def run(self, grid_point, *args):
        f = self._f
        one = decided.get(f)
        if one is None:
            one = decided[f] = not side_by_side(f, set())
        if not one or self._debug:
            return threaded(self, grid_point, *args)
        bx, by, _ = self._block_dim
        current.blockIdx = Dim3(*grid_point)
        error = None
        kernelapi.threading = stand_in
        try:
            with np.errstate(**fresh):
                for x, y, z in np.ndindex(*self._block_dim):  # the order the simulator starts them in
                    current.threadIdx = Dim3(x, y, z)
                    current.thread_id = x + bx * (y + by * z)
                    f(*args)
        except Exception as e:  # as kernel.BlockThread.run words it
            tid, ctaid = "tid=%s" % list(current.threadIdx), "ctaid=%s" % list(current.blockIdx)
            error = (type(e)("%s %s" % (tid, ctaid) if str(e) == "" else "%s %s: %s" % (tid, ctaid, e)),
                     e.__traceback__)
        finally:
            kernelapi.threading = own
        if error is not None:  # raised outside the handler, as the simulator's main thread does
            raise error[0].with_traceback(error[1])

    kernel.BlockManager.run = run


#: the part that runs :func:`absent_check` first (a third of a second: asked for by its test only)
ABSENT = "absent"


def main(out: str, parts) -> None:
    """The check without numba.cuda where ``parts`` name :data:`ABSENT`, which simulator
    ran, then each of the other ``parts`` (names of :data:`PARTS`), into ``out``."""
    if ABSENT in parts:
        absent_check()
    del sys.modules["numba.cuda"]
    from numba import cuda  # noqa: F401  (the simulator where NUMBA_ENABLE_CUDASIM=1, else the GPU)

    yielding_simulator()
    sequential_blocks()

    from fluid.cuda import simulator
    OUT["simulator"] = np.array(simulator())
    for part in parts:
        if part != ABSENT:
            PARTS[part]()
    np.savez(out, **OUT)


if __name__ == "__main__":
    if sys.argv[2:] == ["--scene"]:
        del sys.modules["numba.cuda"]
        yielding_simulator()
        sequential_blocks()
        scene_run(sys.argv[1])
    else:
        main(sys.argv[1], sys.argv[2:] or [ABSENT, *PARTS])
