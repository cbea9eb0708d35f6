"""Record a coupled run into one HDF5 file (:class:`fluid.output.H5Output`): body
kinematics, fairlead forces and tensions, fluid probes, fluid particle snapshots, and the
coupler's load ledger.

    from cosim.recorder import record_run
    steps = record_run(coupler, 10.0, "run.h5", sample_every=0.01, snapshot_every=0.1,
                       probes=[WaveGauge([0.5])])

or, to keep control of the loop::

    with H5Output("run.h5", dim=2) as out:
        rec = RunRecorder(coupler, out, sample_every=0.01, snapshot_every=0.1)
        coupler.run(10.0, callback=rec)
        rec.finish()

Series written (``/series/...``, one row per sample; the layout is stable):

* ``bodies/BODY``: ``com`` (3,) [m], ``velocity`` (3,) [m/s], ``omega`` (3,) [rad/s],
  ``rotation`` (9,) the body frame's 3x3 orientation, row-major (``p_w = origin + R p_b``);
* ``moorings/MOORING``: ``fairlead_force`` (n_lines * dim,) [N] the force of each line on
  its fairlead, line after line; ``tension`` (n_lines,) [N] its magnitude;
* ``tethers``: one key per length constraint, its tension [N] (inextensible lines);
* each fluid probe under its own name (see :mod:`fluid.probes`; SPH fluids only);
* ``ledger/BODY``: the loads the coupler applied at every step (:meth:`cosim.ledger.Ledger.write_h5`),
  written at each snapshot and at :meth:`RunRecorder.finish`.

Samples are taken at the end of the first coupling step that reaches each sample time
(the coupler's step is set by the participants, so rows carry the time actually reached);
``sample_every=None`` samples every step. Snapshots likewise, of the SPH fluid's
particles (``fluid.run.SNAPSHOT_FIELDS``). If the run raises, :func:`record_run` still
writes the ledger so far and closes the file, so it stays readable.
"""

from __future__ import annotations

import math

import numpy as np

from cosim.errors import InputError
from fluid.output import H5Output
from fluid.run import SNAPSHOT_FIELDS


def sph_of(coupler):
    """The :class:`fluid.solver.Fluid` inside the coupler's fluid, or None (no fluid, or
    one without particles such as the analytic fluid)."""
    f = coupler.fluid
    f = getattr(f, "fluid", f)  # cosim.sph_fluid.SPHFluid wraps a Fluid
    return f if hasattr(f, "ps") and hasattr(f, "max_dt") else None


def _interval(v, what: str):
    if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
        raise InputError(f"RunRecorder: {what}={v!r} s; give a positive interval in seconds or None")
    return v


class RunRecorder:
    """A ``Coupler.run`` callback that writes the run to ``out`` (an :class:`H5Output`).

    ``sample_every`` [s] between samples of bodies, moorings and probes (None: every step);
    ``snapshot_every`` [s] between fluid particle snapshots (None: none); ``probes`` fluid
    probes (:mod:`fluid.probes`, need an SPH fluid). The initial state is recorded on
    construction (the coupler is initialised then). Call :meth:`finish` after the run.
    """

    def __init__(self, coupler, out: H5Output, *, sample_every: float | None = None,
                 snapshot_every: float | None = None, probes=(), snapshot_fields=SNAPSHOT_FIELDS):
        if not isinstance(out, H5Output):
            raise InputError(f"RunRecorder: out={out!r}; give an open fluid.output.H5Output")
        self.coupler, self.out = coupler, out
        self.sample_every = _interval(sample_every, "sample_every")
        self.snapshot_every = _interval(snapshot_every, "snapshot_every")
        self.probes = list(probes)
        self.snapshot_fields = tuple(snapshot_fields)
        coupler.initialize()  # idempotent; an SPH fluid builds its particles here
        self.sph = sph_of(coupler)
        if (self.probes or self.snapshot_every is not None) and self.sph is None:
            raise InputError("RunRecorder: fluid probes and snapshots need an SPH fluid in the coupler "
                             "(cosim.sph_fluid.SPHFluid); this coupler has none")
        if self.sph is not None and self.sph.config.dim != out.dim:
            raise InputError(f"RunRecorder: the output is {out.dim}-D but the fluid is {self.sph.config.dim}-D; "
                             f"open the H5Output with dim={self.sph.config.dim}")
        self.t0 = coupler.t
        self._n_sample = self._n_snap = 0
        self._ledger_done = len(coupler.ledger)
        self._tol = 1e-9
        self.sample(self.t0)
        self._n_sample = 1
        if self.snapshot_every is not None:
            self.snapshot(self.t0)
            self._n_snap = 1

    # ------------------------------------------------------------------ callback
    def __call__(self, info) -> None:
        t = info.t
        if self.sample_every is None:
            self.sample(t)
        elif t >= self.t0 + self._n_sample * self.sample_every - self._tol:
            self.sample(t)
            self._n_sample = int(math.floor((t - self.t0 + self._tol) / self.sample_every)) + 1
        if self.snapshot_every is not None and t >= self.t0 + self._n_snap * self.snapshot_every - self._tol:
            self.snapshot(t)
            self._n_snap = int(math.floor((t - self.t0 + self._tol) / self.snapshot_every)) + 1

    def sample(self, t: float) -> None:
        """Write one row of every series at time ``t`` [s] (the coupler's current state)."""
        c, out = self.coupler, self.out
        if c.bodies is not None:
            kin = c.bodies.kinematics()
            for j, body in enumerate(c.bodies.body_names):
                out.series(f"bodies/{body}", t, com=kin.com[j], velocity=kin.velocity[j], omega=kin.omega[j],
                           rotation=kin.rotation[j].ravel())
        for a in c.moorings:
            f = np.asarray(a.mooring.fairlead_forces(), dtype=float)
            out.series(f"moorings/{a.mooring.name}", t, fairlead_force=f.ravel(), tension=np.linalg.norm(f, axis=1))
        tethers = c.tether_tensions()
        if tethers:
            out.series("tethers", t, **tethers)
        for p in self.probes:
            out.series(p.name, t, **p.sample(self.sph))

    def snapshot(self, t: float) -> None:
        """Write the SPH fluid's particles at time ``t`` [s], and the ledger so far."""
        ps = self.sph.ps
        self.out.snapshot(t, ps.pos, **{f: getattr(ps, f) for f in self.snapshot_fields})
        self._write_ledger()

    def _write_ledger(self) -> None:
        led = self.coupler.ledger
        if len(led) < self._ledger_done:
            raise InputError("RunRecorder: the ledger was truncated (a checkpoint was restored) after rows were "
                             "written; record the restored run into a new file")
        self._ledger_done = led.write_h5(self.out, start=self._ledger_done)

    def finish(self) -> None:
        """Write the rest of the ledger and flush the file."""
        self._write_ledger()
        self.out.flush()


def record_run(coupler, t_end: float, out, *, sample_every: float | None = None,
               snapshot_every: float | None = None, probes=(), attrs: dict | None = None,
               progress: bool | None = None, callback=None) -> int:
    """Run ``coupler`` to ``t_end`` [s], recording it into ``out`` (an :class:`H5Output`,
    left open, or a path: a new file with ``attrs``, closed at the end) with a
    :class:`RunRecorder`. ``callback(info)`` is called after each step as well.
    Returns the number of steps. The file is readable after an error too."""
    own = not isinstance(out, H5Output)
    if own:
        coupler.initialize()
        sph = sph_of(coupler)
        out = H5Output(out, dim=sph.config.dim if sph is not None else 3, attrs=attrs)
    elif attrs:
        raise InputError("record_run: attrs go into a file record_run opens; give them to H5Output(..., attrs=)")
    try:
        rec = RunRecorder(coupler, out, sample_every=sample_every, snapshot_every=snapshot_every, probes=probes)

        def step(info):
            rec(info)
            if callback is not None:
                callback(info)

        try:
            return coupler.run(t_end, callback=step, progress=progress)
        finally:
            rec.finish()
    finally:
        if own:
            out.close()
