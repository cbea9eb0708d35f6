"""The fluid's step on an NVIDIA GPU with numba-cuda (``FluidConfig(device="cuda")``).

This package's ``__init__`` never imports ``numba.cuda``: the CPU path runs without
numba-cuda installed, and :func:`check_config` refuses ``device="cuda"`` with a clear
error before any work where it cannot run. The kernels (:mod:`fluid.cuda.kernels`), the
device state (:mod:`fluid.cuda.state`) and the ``Fluid`` that steps on it
(:mod:`fluid.cuda.fluid`) are imported only when a fluid is built with
``device="cuda"``.

What the GPU path covers (the same equations as the CPU path, :mod:`fluid.equations`
and :mod:`fluid.integrator`, term for term and in the same order; float64 throughout):
the cell build and sort (a counting sort by cell with atomics, then each cell's
particles ordered by x as the CPU orders them, so both paths hold the particles in the
same order), the pair loop with both kernels (Wendland, cubic), artificial viscosity
with ``alpha_wall``, laminar viscosity, the Fourtakas and Molteni density diffusions and
their fade under the free surface (``diffusion_at_surface=False``), the renormalised
diffusion of Antuono et al. (``"antuono"``: its gradient loop first), plain dynamic
boundaries (DBC) for walls and bodies, the tank walls of ``walls="adami"`` (with the
prescribed walls' accelerations), XSPH, the symplectic and Verlet integrators, the
time-step reductions of Sunara et al. 2021, Eq. 14 with the diffusion limit, the
NaN guard (the CPU path's message), particles leaving the domain, the group loads on
the device, boundary particles placed by id (bodies, prescribed motions), and the
bodies' mDBC densities (fluid.boundary_correction, the hook cosim.sph_fluid sets; its
diagnostic ``MDBC.low_order`` is not filled on the GPU), the MLS density
re-initialisation (``mls_every``, fluid.mls), the relaxation zones (``Fluid.zones``:
towards rest, a linear sea summed at each particle (one the CPU tabulates included), or a
Stokes-2 regular wave) and the free surface's height at
gauges (fluid.probes.surface_elevation: wave gauges, absorbing end walls' readings).

Not on the GPU yet, refused with the setting to change: ``precision="float32"`` (the
CPU's float32 pair terms; float64 is the GPU's default and reference), a symmetry plane
(``symmetry_y``: the mirror images of :mod:`fluid.mirror`) and particle shifting
(:mod:`fluid.shifting`), by :func:`check_config`; boundary-correction hooks other than the
Adami walls and mDBC, at the first rate evaluation.

Checked against the CPU path, term for term, on numba's CUDA simulator
(tests/test_fluid_cuda.py) and on an NVIDIA H200; to what tolerance, what is not yet run on
a GPU, device memory and the costs outside the kernels: docs/fluid_cuda.md.
"""

from __future__ import annotations

import os

from errors import InputError

_SIM_HINT = ("set NUMBA_ENABLE_CUDASIM=1 in the environment before starting Python to run the GPU path on numba's "
             "CUDA simulator (slow: tiny cases only), or use device='cpu'")


def availability() -> str | None:
    """None where ``device="cuda"`` can run (a CUDA GPU numba sees, or numba's CUDA
    simulator enabled with NUMBA_ENABLE_CUDASIM=1); else why not and what to do."""
    try:
        from numba import cuda
    except ImportError as e:  # numba-cuda absent (numba >= 0.61 no longer ships the CUDA target)
        return (f"numba-cuda is not installed ({e}); pip install numba-cuda (or the project's extra: "
                f"pip install -e '.[gpu]'), then either run on a machine with an NVIDIA GPU or {_SIM_HINT}")
    if simulator():
        return None
    try:
        ok = cuda.is_available()
    except Exception as e:  # noqa: BLE001 - a broken driver reads as no GPU
        return f"numba.cuda found no usable GPU ({type(e).__name__}: {e}); {_SIM_HINT}"
    if not ok:
        return f"numba.cuda finds no CUDA GPU or driver on this machine; {_SIM_HINT}"
    return None


def simulator() -> bool:
    """True when numba's CUDA simulator runs the kernels (NUMBA_ENABLE_CUDASIM=1)."""
    try:
        from numba import config
        return bool(getattr(config, "ENABLE_CUDASIM", 0)) or os.environ.get("NUMBA_ENABLE_CUDASIM", "0") == "1"
    except ImportError:
        return False


def check_config(config) -> None:
    """Refuse a ``FluidConfig(device="cuda")`` the GPU path cannot run, naming the field
    and the fix (called from its validation, before any work)."""
    bad = []
    if getattr(config, "precision", "float64") != "float64":
        bad.append((f"precision={config.precision!r}", "use precision='float64' (the GPU path's pair loop is float64)"))
    if getattr(config, "symmetry_y", None) is not None:
        bad.append((f"symmetry_y={config.symmetry_y!r}", "leave symmetry_y unset and simulate the whole domain (the "
                    "symmetry plane's mirror images, fluid.mirror, are made on the CPU only)"))
    if getattr(config, "shifting", "none") != "none":
        bad.append((f"shifting={config.shifting!r}", "use shifting='none' (particle shifting, fluid.shifting, runs on "
                    "the CPU only)"))
    if bad:
        what, fix = bad[0]
        raise InputError(f"FluidConfig: {what} is not available with device='cuda'; {fix}, or device='cpu'")
    why = availability()
    if why is not None:
        raise InputError(f"FluidConfig: device='cuda' cannot run here: {why}")
