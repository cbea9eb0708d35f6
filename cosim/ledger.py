"""The per-step book of the loads the coupler put on each body.

Outputs: :meth:`Ledger.write_csv` (one row per step and body; its header names each
column's unit, ``t [s],body,fluid_force_x [N],...``) and :meth:`Ledger.write_h5`, which
appends to a :class:`fluid.output.H5Output` one series per body,
``/series/ledger/BODY/{t, fluid_force, fluid_torque, mooring_force, mooring_torque,
gravity}`` (each (n, 3), world frame, each dataset's ``units`` attribute from
:data:`UNITS`). Both signatures are stable.
"""

from __future__ import annotations

import numpy as np

from cosim.errors import InputError

#: the quantities booked for each body and step, world frame (torques about the CoM)
FIELDS = ("fluid_force", "fluid_torque", "mooring_force", "mooring_torque", "gravity")
#: the unit of each field
UNITS = {"fluid_force": "N", "fluid_torque": "N m", "mooring_force": "N", "mooring_torque": "N m", "gravity": "N"}


class Ledger:
    """Loads on each body at the start of each coupling step [N, N m].

    Kept in arrays that double when full: 8 + 120 n_bodies bytes per step (128 for one
    body, up to twice that just after a doubling: 168 measured over 10^5 steps with
    tracemalloc), where a list of small arrays per step took 962 (benchmarks/soak.py)."""

    def __init__(self, body_names):
        self.body_names = list(body_names)
        self._n = 0
        self._alloc(64)

    def _alloc(self, cap: int) -> None:
        n_b = len(self.body_names)
        t = np.empty(cap)
        rows = {f: np.empty((cap, n_b, 3)) for f in FIELDS}
        if hasattr(self, "_t"):
            t[:self._n] = self._t[:self._n]
            for f in FIELDS:
                rows[f][:self._n] = self._rows[f][:self._n]
        self._t, self._rows = t, rows

    def __len__(self) -> int:
        return self._n

    def record(self, t, fluid_force, fluid_torque, mooring_force, mooring_torque, gravity) -> None:
        if self._n == len(self._t):
            self._alloc(2 * len(self._t))
        k = self._n
        self._t[k] = float(t)
        for f, v in zip(FIELDS, (fluid_force, fluid_torque, mooring_force, mooring_torque, gravity)):
            self._rows[f][k] = v
        self._n += 1

    def last(self) -> dict[str, np.ndarray]:
        """The loads of the last step, each field (n_bodies, 3); empty before the first."""
        return {f: rows[self._n - 1].copy() for f, rows in self._rows.items()} if self._n else {}

    def truncate(self, n: int) -> None:
        """Forget the steps after the first ``n`` (a checkpoint was restored)."""
        self._n = min(self._n, max(int(n), 0))

    def restore(self, arrays: dict[str, np.ndarray]) -> None:
        """Hold exactly the steps of ``arrays`` (from :meth:`arrays` of a ledger of the same
        bodies), e.g. read back with a checkpoint file."""
        n_b = len(self.body_names)
        n = len(arrays["t"])
        for f in FIELDS:
            a = np.asarray(arrays[f], dtype=float)
            if a.ndim != 3 or a.shape[1:] != (n_b, 3) or len(a) != n:
                raise InputError(f"ledger field {f!r} has shape {a.shape}; expected ({n}, {n_b}, 3) "
                                 f"for the bodies {self.body_names}")
        self._n = 0
        self._alloc(max(64, n))
        self._t[:n] = np.asarray(arrays["t"], dtype=float)
        for f in FIELDS:
            self._rows[f][:n] = np.asarray(arrays[f], dtype=float)
        self._n = n

    def arrays(self) -> dict[str, np.ndarray]:
        """``t`` (n_steps,) and each field as (n_steps, n_bodies, 3) (copies)."""
        out = {"t": self._t[:self._n].copy()}
        for f, rows in self._rows.items():
            out[f] = rows[:self._n].copy()
        return out

    def write_csv(self, path) -> None:
        """One row per step and body: t, body, then the x, y, z of each field."""
        a = self.arrays()
        cols = [f"{f}_{c} [{UNITS[f]}]" for f in FIELDS for c in "xyz"]
        with open(path, "w") as fh:
            fh.write("t [s],body," + ",".join(cols) + "\n")
            for k, t in enumerate(a["t"]):
                for j, name in enumerate(self.body_names):
                    vals = np.concatenate([a[f][k, j] for f in FIELDS])
                    fh.write(f"{float(t)!r},{name}," + ",".join(repr(float(v)) for v in vals) + "\n")

    def write_h5(self, out, name: str = "ledger", start: int = 0) -> int:
        """Append steps ``start`` .. ``len(self)`` to ``out`` (a :class:`fluid.output.H5Output`,
        or a path: a new file) as one series per body, ``NAME/BODY`` with keys ``FIELDS``
        (each (n, 3) [N, N m]). Returns ``len(self)``: pass it as ``start`` next time to
        write a long run in pieces (after :meth:`truncate`, rewrite into a new file)."""
        from fluid.output import H5Output  # h5py only where HDF5 is written

        n = len(self)
        if not isinstance(start, int) or not 0 <= start <= n:
            raise InputError(f"Ledger.write_h5: start={start!r}; give a step index in 0 .. {n}")
        own = not isinstance(out, H5Output)
        if own:
            out = H5Output(out, dim=3)
        try:
            if n > start:  # only the new rows: a long run writes its ledger in pieces at O(rows)
                for j, body in enumerate(self.body_names):
                    for f in FIELDS:
                        out.annotate(f"{name}/{body}", f, units=UNITS[f])
                    out.series_block(f"{name}/{body}", self._t[start:n],
                                     **{f: self._rows[f][start:n, j] for f in FIELDS})
        finally:
            if own:
                out.close()
        return n
