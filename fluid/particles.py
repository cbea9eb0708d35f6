"""Struct-of-arrays particle set (DESIGN.md, Conventions).

All arrays are float64 except ``kind`` (int8), ``group`` (int32) and ``ids`` (int64).
2-D runs live in the x-z plane: a 2-D position is ``(x, z)``, gravity acts along the
last component. Every boundary particle belongs to a group (``group >= 0``); fluid
particles have ``group == -1``.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

import numpy as np
from numba import njit, prange

from errors import InputError


@njit(parallel=True, cache=True)
def _gather(perm, f2, f1, kind, group, ids, o2, o1, okind, ogroup, oids):
    """Every array of a particle set (and its companions) gathered by ``perm`` in one
    parallel pass: ``f2`` a tuple of (N, dim) float arrays, ``f1`` of (N,) float arrays."""
    dim = f2[0].shape[1]
    for i in prange(perm.shape[0]):
        j = perm[i]
        for t in range(len(f2)):
            for k in range(dim):
                o2[t][i, k] = f2[t][j, k]
        for t in range(len(f1)):
            o1[t][i] = f1[t][j]
        okind[i] = kind[j]
        ogroup[i] = group[j]
        oids[i] = ids[j]


class Kind(IntEnum):
    """What a particle is. Only ``FLUID`` particles move by the forces on them."""

    FLUID = 0
    #: wall particle at rest (dynamic boundary, Barreiro et al. 2016, §2.6)
    FIXED_WALL = 1
    #: wall particle with prescribed velocity (a moving tank, a wavemaker)
    MOVING_WALL = 2
    #: boundary particle of a body whose motion another participant decides
    BODY = 3


@dataclass
class ParticleSet:
    """N particles in ``dim`` dimensions.

    Attributes
    ----------
    pos : (N, dim) positions [m]
    vel : (N, dim) velocities [m/s]; for boundary particles the prescribed velocity
    rho : (N,) density [kg/m^3]
    mass : (N,) mass [kg]
    p : (N,) pressure [Pa] (derived from ``rho`` by the equation of state)
    kind : (N,) int8, a :class:`Kind`
    group : (N,) int32, boundary group id (>= 0) or -1 for fluid
    ids : (N,) int64, a stable particle id that survives reordering and removal
    """

    pos: np.ndarray
    vel: np.ndarray
    rho: np.ndarray
    mass: np.ndarray
    p: np.ndarray
    kind: np.ndarray
    group: np.ndarray
    ids: np.ndarray

    #: names of the per-particle arrays, in one place for permute/select/copy
    FIELDS = ("pos", "vel", "rho", "mass", "p", "kind", "group", "ids")

    @classmethod
    def create(cls, pos, rho, mass, kind=None, group=None, vel=None) -> "ParticleSet":
        """Build a set from array-likes, checking shapes, dtypes and values.

        ``pos`` (N, dim) [m]; ``rho`` [kg/m^3] and ``mass`` [kg] scalars or (N,);
        ``kind`` defaults to fluid, ``group`` to -1 for fluid and 0 for boundaries,
        ``vel`` [m/s] to zero.
        """
        pos = np.ascontiguousarray(pos, dtype=np.float64)
        if pos.ndim != 2 or pos.shape[1] not in (2, 3):
            raise InputError(
                f"particle positions must have shape (N, 2) (x, z) or (N, 3) (x, y, z), got {pos.shape}"
            )
        n, dim = pos.shape
        rho = np.ascontiguousarray(np.broadcast_to(np.asarray(rho, np.float64), (n,))).copy()
        mass = np.ascontiguousarray(np.broadcast_to(np.asarray(mass, np.float64), (n,))).copy()
        kind = np.zeros(n, np.int8) if kind is None else np.ascontiguousarray(
            np.broadcast_to(np.asarray(kind), (n,))).astype(np.int8)
        if group is None:
            group = np.where(kind == Kind.FLUID, -1, 0).astype(np.int32)
        group = np.ascontiguousarray(np.broadcast_to(np.asarray(group), (n,))).astype(np.int32)
        vel = np.zeros((n, dim)) if vel is None else np.array(
            np.broadcast_to(np.asarray(vel, np.float64), (n, dim)))
        ps = cls(pos, np.ascontiguousarray(vel), rho, mass, np.zeros(n), kind, group,
                 np.arange(n, dtype=np.int64))
        ps.check()
        return ps

    @property
    def n(self) -> int:
        return self.pos.shape[0]

    @property
    def dim(self) -> int:
        return self.pos.shape[1]

    def check(self) -> None:
        """Raise :class:`InputError` naming the first inconsistency."""
        n, dim = self.pos.shape
        for f in self.FIELDS:
            a = getattr(self, f)
            want = (n, dim) if f in ("pos", "vel") else (n,)
            if a.shape != want:
                raise InputError(f"particle array {f!r} has shape {a.shape}, expected {want}")
        for f in ("pos", "vel", "rho", "mass"):
            bad = ~np.isfinite(getattr(self, f))
            if bad.any():
                i = int(np.argwhere(bad)[0][0])
                raise InputError(f"particle {i}: {f} is not finite ({getattr(self, f)[i]}); fix the set-up")
        if (self.rho <= 0).any() or (self.mass <= 0).any():
            i = int(np.argmax((self.rho <= 0) | (self.mass <= 0)))
            raise InputError(f"particle {i}: density {self.rho[i]} kg/m^3 and mass {self.mass[i]} kg "
                             "must both be positive")
        valid = np.isin(self.kind, [k.value for k in Kind])
        if not valid.all():
            raise InputError(f"unknown particle kind {self.kind[~valid][0]}; use fluid.particles.Kind")
        fl = self.kind == Kind.FLUID
        if (self.group[fl] != -1).any() or (self.group[~fl] < 0).any():
            raise InputError("fluid particles must have group -1 and boundary particles a group >= 0")

    def permute(self, perm: np.ndarray, *extra: np.ndarray) -> list[np.ndarray]:
        """Reorder every array by ``perm`` (new[i] = old[perm[i]]), and the float arrays
        ``extra`` (each (N,) or (N, dim), e.g. an integrator's saved state) with them;
        returns the reordered ``extra``. One parallel pass for all (11 separate gathers
        cost twice as much, mostly in starting parallel regions)."""
        f2 = [self.pos, self.vel] + [a for a in extra if a.ndim == 2]
        f1 = [self.rho, self.mass, self.p] + [a for a in extra if a.ndim == 1]
        m = perm.shape[0]
        o2 = [np.empty((m, a.shape[1])) for a in f2]
        o1 = [np.empty(m) for _ in f1]
        okind = np.empty(m, self.kind.dtype)
        ogroup = np.empty(m, self.group.dtype)
        oids = np.empty(m, self.ids.dtype)
        _gather(perm, tuple(np.ascontiguousarray(a, np.float64) for a in f2),
                tuple(np.ascontiguousarray(a, np.float64) for a in f1),
                self.kind, self.group, self.ids, tuple(o2), tuple(o1), okind, ogroup, oids)
        self.pos, self.vel = o2[0], o2[1]
        self.rho, self.mass, self.p = o1[0], o1[1], o1[2]
        self.kind, self.group, self.ids = okind, ogroup, oids
        it2, it1 = iter(o2[2:]), iter(o1[3:])
        return [next(it2) if a.ndim == 2 else next(it1) for a in extra]

    def select(self, mask: np.ndarray) -> "ParticleSet":
        """A new set with the particles where ``mask`` is true."""
        return ParticleSet(*(getattr(self, f)[mask] for f in self.FIELDS))

    def copy(self) -> "ParticleSet":
        return ParticleSet(*(getattr(self, f).copy() for f in self.FIELDS))

    @staticmethod
    def concatenate(sets: list["ParticleSet"]) -> "ParticleSet":
        """Join sets of the same dimension; ids are renumbered 0..N-1."""
        if len({s.dim for s in sets}) != 1:
            raise InputError("cannot join particle sets of different dimensions")
        out = ParticleSet(*(np.concatenate([getattr(s, f) for s in sets]) for f in ParticleSet.FIELDS))
        out.ids = np.arange(out.n, dtype=np.int64)
        return out
