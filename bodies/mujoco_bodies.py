"""MuJoCo bodies as a co-simulation participant.

MuJoCo integrates the bodies (joints, contacts, constraints, gravity); the
coupler hands them external loads once per coupling step as a world-frame wrench
per body — force, and torque about the body's centre of mass — which this
participant writes to ``xfrc_applied`` (MuJoCo applies it at the centre of mass)
and clears after the step, so it is the only writer and nothing persists
silently. Within a coupling step MuJoCo sub-steps so that its own step never
exceeds the model's ``timestep``; the loads are held constant over the step.

Hinges and slides may be driven instead (:meth:`MujocoBodies.drive`): a support that
moves as prescribed, e.g. the clamp of an elastic plate on a shaken tank, carrying what
hangs from it as a moving base does.

2-D scenes live in the x-z plane: bodies slide in x and z and hinge about y
(see :mod:`bodies.builders`), and are 1 m thick so that forces per metre of depth
from a 2-D fluid are forces on the body.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Sequence

import mujoco
import numpy as np

from bodies.sampling import BodyKinematics, GeomShape, check_mesh, sample_geoms
from errors import InputError, InstabilityError

log = logging.getLogger(__name__)


def _log_warning(message: str) -> None:
    log.warning("MuJoCo: %s", message)


def route_warnings() -> None:
    """MuJoCo's warnings (an unstable simulation, a full contact buffer) into this
    module's logger. MuJoCo's own handler also appends them to ``MUJOCO_LOG.TXT`` in the
    working folder, a file a run has no business leaving there. A handler someone else
    installed is kept."""
    if mujoco.get_mju_user_warning() is None:
        mujoco.set_mju_user_warning(_log_warning)


_GEOM_KINDS = {
    mujoco.mjtGeom.mjGEOM_BOX: "box",
    mujoco.mjtGeom.mjGEOM_SPHERE: "sphere",
    mujoco.mjtGeom.mjGEOM_CYLINDER: "cylinder",
    mujoco.mjtGeom.mjGEOM_CAPSULE: "capsule",
    mujoco.mjtGeom.mjGEOM_ELLIPSOID: "ellipsoid",
    mujoco.mjtGeom.mjGEOM_MESH: "mesh",
}

_DRIVABLE = (int(mujoco.mjtJoint.mjJNT_SLIDE), int(mujoco.mjtJoint.mjJNT_HINGE))  # joints drive() and set_joints() take


def load_spec(mjcf) -> tuple[mujoco.MjSpec | None, mujoco.MjModel]:
    """A model spec and its compiled model from an MJCF string or the path to an
    MJCF file; a ready ``mujoco.MjModel`` comes without a spec (it cannot be
    edited, e.g. to add tethers)."""
    if isinstance(mjcf, mujoco.MjModel):
        return None, mjcf
    try:
        if isinstance(mjcf, str) and mjcf.lstrip().startswith("<"):
            spec = mujoco.MjSpec.from_string(mjcf)
        else:
            path = Path(mjcf)
            if not path.is_file():
                raise InputError(f"MJCF file {str(path)!r} does not exist; give an MJCF string or an existing file")
            spec = mujoco.MjSpec.from_file(str(path))
        return spec, spec.compile()
    except ValueError as exc:  # MuJoCo's own parse and compile errors
        raise InputError(f"MuJoCo could not load the MJCF: {exc}") from None


class MujocoBodies:
    """A MuJoCo model whose bodies exchange loads and kinematics with the coupler.

    Parameters
    ----------
    mjcf:
        MJCF string, path to an MJCF file, or a ``mujoco.MjModel``.
    bodies:
        Names of the bodies that take part in the coupling (receive fluid and
        mooring loads). Default: every body that has degrees of freedom.
    name:
        Participant name.
    """

    def __init__(self, mjcf, bodies: Sequence[str] | None = None, name: str = "bodies"):
        route_warnings()
        self._spec, self.model = load_spec(mjcf)
        self.data = mujoco.MjData(self.model)
        self.tethers: list[str] = []  #: names of the tendons added by add_tethers, in order
        self.name = name
        m = self.model
        if bodies is None:
            ids = [b for b in range(1, m.nbody) if m.body_dofnum[b] > 0]
        else:
            ids = []
            for b in bodies:
                i = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, b)
                if i < 0:
                    known = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, k) for k in range(1, m.nbody)]
                    raise InputError(f"{name}: no body named {b!r} in the MJCF; bodies: {known}")
                ids.append(i)
        if not ids:
            raise InputError(f"{name}: the model has no movable body to couple (add a joint, e.g. <freejoint/>)")
        self.body_ids = np.array(ids)
        self.body_names = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, i) for i in ids]
        self.n_bodies = len(ids)
        self.dt_mujoco = float(m.opt.timestep)
        self._force = np.zeros((self.n_bodies, 3))
        self._torque = np.zeros((self.n_bodies, 3))
        self._state_spec = mujoco.mjtState.mjSTATE_INTEGRATION
        self.substeps = 0  #: MuJoCo steps taken in the last advance
        self._drives = []  # (qpos addresses, dof addresses, motion) of the driven joints (drive())
        mujoco.mj_forward(m, self.data)

    def set_gravity(self, gravity) -> None:
        """Replace the model's gravity [m/s^2] (3 components, world axes), in the compiled
        model and in its spec, so that a recompile (:meth:`add_tethers`) keeps it."""
        g = np.asarray(gravity, float)
        if g.shape != (3,) or not np.all(np.isfinite(g)):
            raise InputError(f"{self.name}: gravity must be 3 finite values [m/s^2], got {gravity!r}")
        self.model.opt.gravity[:] = g
        if self._spec is not None:
            self._spec.option.gravity = g.tolist()
        mujoco.mj_forward(self.model, self.data)

    # -- participant protocol ------------------------------------------------
    def initialize(self, t0: float) -> None:
        self.data.time = t0
        self._drive_to(t0)
        mujoco.mj_forward(self.model, self.data)
        self._check_finite(0)

    def max_dt(self) -> float:
        """Unlimited: MuJoCo sub-steps within a coupling step (at most ``timestep``)."""
        return math.inf

    def advance(self, t: float, dt: float) -> None:
        """Step MuJoCo from ``t`` to ``t + dt`` with the wrenches last set, held
        constant; ``xfrc_applied`` is cleared afterwards."""
        m, d = self.model, self.data
        n = max(1, math.ceil(dt / self.dt_mujoco * (1 - 1e-12)))
        d.xfrc_applied[:] = 0.0
        d.xfrc_applied[self.body_ids, :3] = self._force
        d.xfrc_applied[self.body_ids, 3:] = self._torque
        m.opt.timestep = dt / n
        resets = d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number
        h = dt / n
        try:
            for k in range(n):
                if self._drives:
                    self._drive_step(t + k * h, h)
                mujoco.mj_step(m, d)
        finally:
            m.opt.timestep = self.dt_mujoco
            d.xfrc_applied[:] = 0.0
            self._force[:] = 0.0
            self._torque[:] = 0.0
            for _, dofs, _ in self._drives:
                d.qfrc_applied[dofs] = 0.0
        if self._drives:
            self._drive_to(t + dt)
            mujoco.mj_forward(m, d)
        if d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > resets:
            # MuJoCo met a non-finite or huge acceleration and reset the state to the model's
            # initial pose: say so, naming the body, instead of running on from there
            dof = int(d.warning[mujoco.mjtWarning.mjWARN_BADQACC].lastinfo)
            body = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, int(m.dof_bodyid[dof])) if 0 <= dof < m.nv else "?"
            raise InstabilityError(
                f"{self.name}: MuJoCo found a non-finite or huge acceleration at degree of freedom {dof} (body "
                f"'{body}') between t = {t:.9g} and {t + dt:.9g} s and reset its state; reduce the coupling step or "
                f"the MJCF timestep (an elastic chain: below its stable step, bodies.elastic.BeamModel.stable_dt), "
                f"or check the loads given to this body")
        d.time = t + dt  # the coupler's clock, not n accumulated sub-steps
        self.substeps = n
        self._check_finite(n)

    # -- prescribed joints ------------------------------------------------------
    def drive(self, joints: Sequence[str], motion) -> None:
        """Prescribe the motion of hinge and slide ``joints`` (names; e.g. the support of a
        clamp on a shaken tank, :class:`bodies.elastic.Support`): ``motion(t)`` returns
        their positions [m or rad], velocities and accelerations at time ``t`` [s], arrays
        ``(n,)``. What hangs from them moves as it would on a support that moves so: the
        joints carry an armature of :attr:`DRIVE_ARMATURE` times the inertia they hold up
        (unless the model gives a larger one), and before every MuJoCo step they are set to
        the prescribed position and velocity and given the generalised force ``armature *
        (v(t + h) - v(t)) / h``; their acceleration is then the prescribed mean over the
        step to ``1 / DRIVE_ARMATURE`` of the reactions of what they carry, whose
        dynamics MuJoCo integrates as usual (base-excited structures: the inertial load
        ``-m a`` of the support's acceleration arises, Coriolis and centrifugal terms of a
        turning support too). After each advance they are set to the prescribed state at
        its end exactly. The loads the coupler gives a body on driven joints go into the
        support (they move it by a ``1 / DRIVE_ARMATURE`` part)."""
        m = self.model
        ids = []
        for j in joints:
            i = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, j)
            if i < 0:
                raise InputError(f"{self.name}: no joint named {j!r} to drive")
            if int(m.jnt_type[i]) not in _DRIVABLE:
                raise InputError(f"{self.name}: joint {j!r} is not a hinge or a slide; only those can be driven")
            ids.append(i)
        if not callable(motion):
            raise InputError(f"{self.name}: the motion of {list(joints)} must be a callable t -> (q, v, a)")
        dofs = m.jnt_dofadr[ids].copy()
        M = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, self.data, M)
        carried = np.diag(M)[dofs] - m.dof_armature[dofs]
        m.dof_armature[dofs] = np.maximum(m.dof_armature[dofs], self.DRIVE_ARMATURE * carried)
        mujoco.mj_setConst(m, mujoco.MjData(m))
        self._drives.append((m.jnt_qposadr[ids].copy(), dofs, motion))
        self._drive_to(float(self.data.time))
        mujoco.mj_forward(m, self.data)

    #: a driven joint's armature over the inertia it holds up [-] (:meth:`drive`)
    DRIVE_ARMATURE = 1e8

    @property
    def driven_dofs(self) -> set:
        """The degrees of freedom (``qvel`` indices) of the driven joints (:meth:`drive`)."""
        return {int(i) for _, dofs, _ in self._drives for i in dofs}

    def _prescribed(self, motion, t: float, n: int):
        q, v, a = (np.asarray(x, float).reshape(-1) for x in motion(t))
        if not (q.shape == v.shape == a.shape == (n,)) or not (np.isfinite(q).all() and np.isfinite(v).all()):
            raise InputError(f"{self.name}: a joint motion gave {q}, {v}, {a} at t = {t:.9g} s; it must give {n} "
                             f"finite positions, velocities and accelerations")
        return q, v

    def _drive_to(self, t: float) -> None:
        """The driven joints at their prescribed position and velocity at ``t`` [s]."""
        d = self.data
        for qpos, dofs, motion in self._drives:
            d.qpos[qpos], d.qvel[dofs] = self._prescribed(motion, t, len(dofs))

    def _drive_step(self, t: float, h: float) -> None:
        """The driven joints before a MuJoCo step from ``t`` to ``t + h`` [s]: their state at
        ``t`` and the force that gives them the mean acceleration over the step."""
        d, arm = self.data, self.model.dof_armature
        for qpos, dofs, motion in self._drives:
            q, v = self._prescribed(motion, t, len(dofs))
            v1 = self._prescribed(motion, t + h, len(dofs))[1]
            d.qpos[qpos], d.qvel[dofs] = q, v
            d.qfrc_applied[dofs] = arm[dofs] * (v1 - v) / h

    def set_joints(self, values: dict) -> None:
        """Set hinge and slide joints to positions [m or rad], ``{name: value}`` (e.g. the
        initial imperfection of a column, :meth:`bodies.elastic.BeamModel.imperfection`),
        and bring the derived state up to date."""
        m = self.model
        for j, v in values.items():
            i = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, j)
            if i < 0 or int(m.jnt_type[i]) not in _DRIVABLE:
                raise InputError(f"{self.name}: no hinge or slide named {j!r} to set")
            self.data.qpos[m.jnt_qposadr[i]] = float(v)
        mujoco.mj_forward(m, self.data)

    def set_velocity(self, body: int, velocity) -> None:
        """Give the coupled body ``body`` (its index) the linear velocity ``velocity`` [m/s]
        (world frame, (x, y, z)) without spin: a free joint's translational velocity, each
        slide's the component along its axis, each hinge at rest. Its derived state is
        brought up to date."""
        m, d = self.model, self.data
        v = np.asarray(velocity, float)
        b = self.body_ids[body]
        mujoco.mj_kinematics(m, d)  # the joints' axes in the world
        for j in range(int(m.body_jntadr[b]), int(m.body_jntadr[b]) + int(m.body_jntnum[b])):
            adr, kind = int(m.jnt_dofadr[j]), int(m.jnt_type[j])
            if kind == mujoco.mjtJoint.mjJNT_FREE:
                d.qvel[adr:adr + 6] = np.concatenate([v, np.zeros(3)])
            elif kind == mujoco.mjtJoint.mjJNT_SLIDE:
                d.qvel[adr] = float(d.xaxis[j] @ v)
            else:
                d.qvel[adr:adr + (3 if kind == mujoco.mjtJoint.mjJNT_BALL else 1)] = 0.0
        mujoco.mj_forward(m, d)

    def save_state(self):
        buf = np.empty(mujoco.mj_stateSize(self.model, self._state_spec))
        mujoco.mj_getState(self.model, self.data, buf, self._state_spec)
        return buf

    def load_state(self, state) -> None:
        mujoco.mj_setState(self.model, self.data, np.asarray(state, dtype=float), self._state_spec)
        mujoco.mj_forward(self.model, self.data)

    # -- exchange ------------------------------------------------------------
    def set_wrenches(self, force, torque) -> None:
        """External loads for the next step: force [N] and torque about the centre of
        mass [N m], world frame, ``(n_bodies, 3)`` each. Replaces earlier values."""
        f, tq = np.asarray(force, dtype=float), np.asarray(torque, dtype=float)
        for arr, what in ((f, "force"), (tq, "torque")):
            if arr.shape != (self.n_bodies, 3):
                raise InputError(f"{self.name}: {what} must have shape ({self.n_bodies}, 3), got {arr.shape}")
            if not np.isfinite(arr).all():
                i = int(np.argmax(~np.isfinite(arr).all(axis=1)))
                raise InstabilityError(
                    f"{self.name}: non-finite {what} {arr[i]} given for body '{self.body_names[i]}' at "
                    f"t = {self.data.time:.9g} s; the participant that produced it went unstable"
                )
        self._force[:] = f
        self._torque[:] = tq

    def kinematics(self) -> BodyKinematics:
        """Current world-frame state of the coupled bodies."""
        m, d = self.model, self.data
        vel = np.empty((self.n_bodies, 6))
        for k, b in enumerate(self.body_ids):
            mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_BODY, b, vel[k], 0)
        return BodyKinematics(
            com=d.xipos[self.body_ids].copy(),
            origin=d.xpos[self.body_ids].copy(),
            rotation=d.xmat[self.body_ids].reshape(-1, 3, 3).copy(),
            velocity=vel[:, 3:].copy(),
            omega=vel[:, :3].copy(),
        )

    def geoms(self) -> list[list[GeomShape]]:
        """The solid geoms of each coupled body, in the body frame, as plain arrays
        (so that a fluid can use them without MuJoCo). A mesh geom carries its
        vertices and faces as MuJoCo compiled them (``mesh_vert`` / ``mesh_face`` from
        ``mesh_vertadr`` / ``mesh_faceadr``), which are in the geom frame (MuJoCo moves
        a mesh to its centre of mass and principal axes and folds that offset into the
        geom's pos and quat). Planes and height fields are left out."""
        m = self.model
        out = []
        for b in self.body_ids:
            shapes = []
            for g in np.flatnonzero(m.geom_bodyid == b):
                kind = _GEOM_KINDS.get(int(m.geom_type[g]))
                if kind is None:
                    continue
                rot = np.empty(9)
                mujoco.mju_quat2Mat(rot, m.geom_quat[g])
                mesh = None
                if kind == "mesh":
                    k = int(m.geom_dataid[g])
                    va, vn = int(m.mesh_vertadr[k]), int(m.mesh_vertnum[k])
                    fa, fn = int(m.mesh_faceadr[k]), int(m.mesh_facenum[k])
                    label = (f"body '{mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b)}' geom {g - m.body_geomadr[b]} "
                             f"(mesh '{mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_MESH, k)}')")
                    mesh = check_mesh(m.mesh_vert[va:va + vn], m.mesh_face[fa:fa + fn], label)
                shapes.append(GeomShape(kind, m.geom_size[g].copy(), m.geom_pos[g].copy(), rot.reshape(3, 3), mesh))
            out.append(shapes)
        return out

    def boundary_particles(self, dx: float, layers: int, dim: int = 3):
        """Boundary particles of every coupled body (see :mod:`bodies.sampling`):
        positions [m] in body coordinates ``(n, 3)`` and the coupled-body index of
        each particle."""
        pts, owner = [], []
        for k, shapes in enumerate(self.geoms()):
            p, _ = sample_geoms(shapes, dx, layers, dim)  # the lattice keeps at least each geom's centre
            pts.append(p)
            owner.append(np.full(len(p), k))
        return np.concatenate(pts), np.concatenate(owner)

    def add_tethers(self, tethers) -> None:
        """Hold points of bodies within a length of fixed points: each tether is
        ``(name, anchor, site, length)`` with the anchor [m] in the world, the name
        of a site on a coupled body, and the length [m]. It becomes a spatial
        tendon with a length limit (a unilateral constraint: slack below the
        length, pulling along the chord at it), so several taut tethers share a
        load as statics says. The model is recompiled; the state is kept."""
        if self._spec is None:
            raise InputError(f"{self.name}: tethers need a model given as MJCF (string or file), not an MjModel")
        for name, anchor, site, length in tethers:
            self.site(site)  # exists and is on a coupled body
            if not (math.isfinite(length) and length > 0):
                raise InputError(f"{self.name}: tether '{name}' needs a length > 0 m, got {length!r}")
            self._spec.worldbody.add_site(name=f"{name}.anchor", pos=[float(c) for c in anchor])
            t = self._spec.add_tendon(name=name, limited=True, range=[0.0, float(length)])
            t.wrap_site(f"{name}.anchor")
            t.wrap_site(site)
            self.tethers.append(name)
        armature = self.model.dof_armature.copy()  # runtime additions (added mass) survive the recompile
        state = self.save_state()
        try:
            self.model = self._spec.compile()
        except ValueError as exc:
            raise InputError(f"{self.name}: MuJoCo could not add the tethers: {exc}") from None
        self.model.dof_armature[:] = armature
        mujoco.mj_setConst(self.model, mujoco.MjData(self.model))
        self.data = mujoco.MjData(self.model)
        self.dt_mujoco = float(self.model.opt.timestep)
        self.load_state(state)

    def tether_tensions(self) -> np.ndarray:
        """Tension [N] in each tether (0 when slack), in the order added, from the
        constraint forces of the last MuJoCo step."""
        m, d = self.model, self.data
        out = np.zeros(len(self.tethers))
        rows = np.flatnonzero(d.efc_type[: d.nefc] == mujoco.mjtConstraint.mjCNSTR_LIMIT_TENDON)
        ids = {mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_TENDON, n): k for k, n in enumerate(self.tethers)}
        for r in rows:
            k = ids.get(int(d.efc_id[r]))
            if k is not None:
                out[k] += d.efc_force[r]
        return out

    def release_tether(self, name: str) -> None:
        """Remove the length limit of the tether ``name`` (a broken line): from the next
        step it holds nothing. Model data, not state: release it again after loading a
        state saved after the release."""
        if name not in self.tethers:
            raise InputError(f"{self.name}: no tether named {name!r}; tethers: {self.tethers}")
        self.model.tendon_limited[mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_TENDON, name)] = 0

    def masses(self) -> np.ndarray:
        """Mass of each coupled body [kg], from MuJoCo's geometry or the MJCF's values."""
        return self.model.body_mass[self.body_ids].copy()

    def inertias(self) -> np.ndarray:
        """Principal moments of inertia of each coupled body [kg m^2], ``(n_bodies, 3)``."""
        return self.model.body_inertia[self.body_ids].copy()

    def inertia_tensors(self) -> np.ndarray:
        """Inertia tensor of each coupled body about its centre of mass, world axes [kg m^2],
        ``(n_bodies, 3, 3)``, at the current pose."""
        R = self.data.ximat[self.body_ids].reshape(-1, 3, 3)
        return np.einsum("nij,nj,nkj->nik", R, self.inertias(), R)

    def gravity_forces(self) -> np.ndarray:
        """Weight of each coupled body [N], world frame, ``(n_bodies, 3)``."""
        return self.masses()[:, None] * self.model.opt.gravity[None, :]

    def site(self, name: str) -> tuple[int, int]:
        """(site id, index of its coupled body) for a site name; raises if the site
        is missing or not on a coupled body."""
        m = self.model
        sid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, name)
        if sid < 0:
            known = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_SITE, k) for k in range(m.nsite)]
            raise InputError(f"{self.name}: no site named {name!r} in the MJCF; sites: {known}")
        hits = np.flatnonzero(self.body_ids == m.site_bodyid[sid])
        if not hits.size:
            raise InputError(f"{self.name}: site {name!r} is not on one of the coupled bodies {self.body_names}")
        return sid, int(hits[0])

    def site_positions(self, site_ids) -> np.ndarray:
        """World positions [m] of sites, ``(n, 3)``."""
        return self.data.site_xpos[np.asarray(site_ids)].copy()

    def add_armature(self, body: int, added: Sequence[float]) -> None:
        """Add inertia to the degrees of freedom of a coupled body's joints (MuJoCo
        ``dof_armature``): for a free joint 3 translational values [kg] along the
        world axes then 3 rotational [kg m^2] about the body axes; for the planar
        2-D joints (slide x, slide z, hinge y) one value per joint. Used to move an
        added-mass estimate into the implicit inertia: it adds inertia without weight."""
        b = self.body_ids[body]
        m = self.model
        start, n = m.body_dofadr[b], m.body_dofnum[b]
        added = np.asarray(added, dtype=float)
        if added.shape != (n,) or (added < 0).any() or not np.isfinite(added).all():
            raise InputError(f"{self.name}: body '{self.body_names[body]}' has {n} degrees of freedom; give {n} "
                             f"finite added inertias >= 0, got {added}")
        m.dof_armature[start:start + n] += added
        # MuJoCo caches inertia-derived constants: recompute them (on scratch data,
        # which mj_setConst overwrites) and refresh the derived state
        mujoco.mj_setConst(m, mujoco.MjData(m))
        mujoco.mj_forward(m, self.data)

    def dofs(self, body: int) -> slice:
        """The degrees of freedom of a coupled body's joints (indices into MuJoCo's ``qvel``)."""
        b = self.body_ids[body]
        start = int(self.model.body_dofadr[b])
        return slice(start, start + int(self.model.body_dofnum[b]))

    def dof_velocities(self) -> np.ndarray:
        """Generalised velocities ``qvel`` [m/s, rad/s] of the whole model, a copy."""
        return self.data.qvel.copy()

    def dof_inertia(self, body: int) -> np.ndarray:
        """The body's own inertia on each of its degrees of freedom [kg, kg m^2]: the
        diagonal of the joint-space mass matrix at the current pose, armature left out."""
        m = self.model
        M = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, self.data, M)
        s = self.dofs(body)
        return np.diag(M)[s] - m.dof_armature[s]

    def wrench_for_dof_forces(self, body: int, tau) -> tuple[np.ndarray, np.ndarray]:
        """The force [N] and torque about the centre of mass [N m], world frame, that
        act on the body's degrees of freedom as the generalised forces ``tau`` [N, N m]
        (least squares through the centre-of-mass Jacobian; exact for a free joint and
        for slide/hinge joints whose axes pass through the centre of mass)."""
        m, d = self.model, self.data
        jp, jr = np.zeros((3, m.nv)), np.zeros((3, m.nv))
        mujoco.mj_jacBodyCom(m, d, jp, jr, int(self.body_ids[body]))
        s = self.dofs(body)
        J = np.vstack([jp[:, s], jr[:, s]])  # (6, ndof): J^T w = tau
        w = np.linalg.lstsq(J.T, np.asarray(tau, float), rcond=None)[0]
        return w[:3], w[3:]

    def _check_finite(self, n_steps: int) -> None:
        d = self.data
        if np.isfinite(d.qpos).all() and np.isfinite(d.qvel).all():
            return
        bad = [self.body_names[k] for k, b in enumerate(self.body_ids)
               if not np.isfinite(d.xpos[b]).all() or not np.isfinite(d.cvel[b]).all()]
        raise InstabilityError(
            f"{self.name}: MuJoCo state became non-finite at t = {d.time:.9g} s after {n_steps} sub-steps "
            f"(bodies: {', '.join(bad) or 'unknown'}); reduce the coupling step or the MJCF timestep, "
            f"or check the loads given to these bodies"
        )
