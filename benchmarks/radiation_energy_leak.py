"""Where the work of a heaving hull's force goes: the power the hull puts into the water
through its pair forces, against the part of it that no energy of the fluid receives,
the boundary particles' compression work ``sum_b m_b p_b / rho_b^2 (drho_b/dt)``
(:meth:`fluid.solver.Fluid.boundary_compression_power_now`; mDBC sets their densities by
extrapolation, so this work is stored nowhere). Both are averaged over whole periods
after the ramp and given as the linear damping that would spend them, ``2 <P> / (omega
a)^2`` [kg/s], beside B33 fitted from the force and Capytaine's. docs/validation/
nearfield.md, "Not the weak compressibility, the density diffusion, the re-initialisation
or the seabed".

    python benchmarks/radiation_energy_leak.py [--hull cylinder|hemisphere] [--draft 3]
        [--r-over-dx 4] [--periods 6] [--amplitude 0.6] [--depth D] [--set KEY=VALUE ...]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from cosim.validations import case_scene
from cosim.validations.radiation import added_mass_damping, hull_reference
from radiation_hull import add_scene_arguments, reference_hull, scene_for  # benchmarks/radiation_hull.py, beside this script

#: samples a period of the forced motion
SAMPLES_A_PERIOD = 20


def powers(scene, extra=None, on_built=None) -> dict:
    """``{"t", "fz", "w", "p_in", "leak"}`` at :data:`SAMPLES_A_PERIOD` samples a period after
    the ramp: the fluid's vertical force on the body [N], its heave velocity [m/s], the power
    [W] the body puts into the fluid (``-F . v``) and the boundary particles' compression
    work [W] (module docstring), each body particle counted as in its load. ``extra(fluid)``:
    called at each sample after the rates are taken, its results listed in ``"extra"``;
    ``on_built(fluid)``: called once, before the run starts (``fluid`` the
    :class:`fluid.solver.Fluid`)."""
    m = scene.bodies[0].motion
    ramp_end = m.ramp * m.period
    n = round((scene.world.duration - ramp_end) / m.period * SAMPLES_A_PERIOD)
    times = ramp_end + np.arange(1, n + 1) * m.period / SAMPLES_A_PERIOD
    rows_out, extras, cpu = [], [], time.process_time()
    with case_scene.built(scene) as built:
        sph = built.fluid
        if on_built is not None:
            on_built(sph.fluid)
        for t in times:
            built.coupler.run(float(t))
            fz_all = sph.fluid.boundary_forces_now()[:, -1]  # takes the rates, and the order rows refers to
            rows, shares = sph.body_particle_rows(0)
            w = float(sph.fluid.ps.vel[rows, -1].mean())  # a rigid body moving in heave: every particle's
            fz = float((shares * fz_all[rows]).sum())
            leak = float((shares * sph.fluid.boundary_compression_power_now()[rows]).sum())
            rows_out.append((fz, w, -fz * w, leak))
            if extra is not None:
                extras.append(extra(sph.fluid))
    a = np.array(rows_out)
    return {"t": times, "fz": a[:, 0], "w": a[:, 1], "p_in": a[:, 2], "leak": a[:, 3], "extra": extras,
            "cpu_s": time.process_time() - cpu}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_scene_arguments(ap, hull="cylinder", draft=3.0, amplitude=0.6)
    args = ap.parse_args(argv)
    s = scene_for(args.hull, args.draft, args.r_over_dx, args.periods, False, args.amplitude, args.settings,
                  args.depth)
    m, d = s.bodies[0].motion, s.domain
    w = 2.0 * math.pi / m.period
    a_ref, b_ref, c33 = hull_reference(reference_hull(args.hull, args.draft), d.depth, w, s.fluid.rho0,
                                      s.world.gravity, name=f"radiation-{args.hull}")
    r = powers(s)
    a33, b33 = added_mass_damping(r["t"], r["fz"], m.amplitude, w, c33)
    to_b = 2.0 / (w * m.amplitude) ** 2
    per = SAMPLES_A_PERIOD
    by_period = lambda x: ", ".join(f"{to_b * x[i * per:(i + 1) * per].mean() / 1e3:.1f}"
                                    for i in range(len(x) // per))
    print(f"{args.hull}, draft {args.draft:g} m, depth {d.depth:g} m, R/dx = {args.r_over_dx:g}, amplitude "
          f"{m.amplitude:g} m, {' '.join(args.settings) + ', ' if args.settings else ''}{args.periods} periods after "
          f"the ramp, untared; {r['cpu_s']:.0f} CPU-s")
    print(f"Capytaine B33 {b_ref / 1e3:.2f} kN s/m; SPH B33 from the force's fit {b33 / 1e3:.2f} kN s/m")
    print(f"as dampings [kN s/m]: the body's power into the fluid {to_b * r['p_in'].mean() / 1e3:.2f} "
          f"(by period {by_period(r['p_in'])}); the boundary's compression work {to_b * r['leak'].mean() / 1e3:.2f} "
          f"(by period {by_period(r['leak'])}); the fluid receives "
          f"{to_b * (r['p_in'] - r['leak']).mean() / 1e3:.2f}")


if __name__ == "__main__":
    main()
