"""Elastic cantilevers (beams and plates in cylindrical bending) as MuJoCo chains.

Physics. A straight cantilever of length ``L``, thickness ``h`` (bending direction, world
x) and width ``W`` (world y; 1 m in 2-D scenes), clamped at its foot and rising along +z,
or (``direction="down"``) clamped at its top and hanging (the rubber gate of Antoci et al.
2007), or turned about y by ``angle`` (90 deg: horizontal). It is a discrete Timoshenko
beam: ``N`` elements of length ``l = L / N``, the compliance of each lumped at its midpoint
into a hinge about y of stiffness ``k_b = E I / l`` and (``shear=True``) a slide along the
link's x of stiffness ``k_s = kappa G A / l`` (``I = W h^3 / 12``, ``A = W h``,
``G = E / (2 (1 + nu))``, ``kappa = 5/6``). The rigid links are boxes of the beam's section
and density (mass and rotary inertia are the beam's); the first is welded to the parent
(the clamp). Joints at element midpoints make the bending compliance the midpoint rule,
second order: tip load ``delta = P L^3 / (3 E I) (1 - 1 / (4 N^2)) + P L / (kappa G A)``,
uniform load ``q L^4 / (8 E I) (1 - 1 / (2 N^2)) + q L^2 / (2 kappa G A)``. Large rotations
are MuJoCo's joints'; damping (optional) is stiffness-proportional, ``c = beta k``;
``shear=False`` is a Rayleigh beam.

References, checked by ``tests/test_elastic_beam.py``: Euler-Bernoulli clamped-free
frequencies (``beta_n L = 1.8751, 4.6941, 7.8548``); the Timoshenko clamped-free frequency
equation of Han, Benaroya & Wei (1999, J. Sound Vib. 225(5) 935-988; Huang 1961), solved in
:func:`timoshenko_frequencies`; tip deflections as above (Timoshenko & Gere).

Accuracy on Yang & Li 2020's plate (``python benchmarks/elastic_beam.py``): at N = 16 within
0.1-0.25 % of Timoshenko's first three frequencies and its tip deflection, converging at
order 2; stable RK4 step (:meth:`BeamModel.stable_dt`) 3.8e-4 s, above the SPH step. The
table, and MuJoCo's flex measured beside it and not taken: docs/benchmarks/elastic_beam_history.md.

Moving support (:class:`Support`): the clamp sits on prescribed slides or a hinge
(:meth:`bodies.mujoco_bodies.MujocoBodies.drive`): a base-excited cantilever. Self-weight
buckling (:func:`self_weight_buckling`, Greenhill 1881): :meth:`BeamModel.imperfection`
bends the chain into the buckling mode so that it buckles as a real, imperfect one would.

Limits: the chain is inextensible (the plate's first axial mode is left out). Boundary
particles (:class:`ElasticBody`) blend the frames of the two links nearest them
(:meth:`BeamModel.blend`), so the deformed surface stays closed at the joints, and their
force is split with the same weights; a plate thinner than ``dx`` gets one column.

Units: SI (m, kg, s, Pa, N). 2-D scenes live in the x-z plane: every joint turns about y
or slides along x, so the beam stays in the plane by construction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

from errors import InputError

#: the first three roots of 1 + cos(x) cosh(x) = 0 (clamped-free Euler-Bernoulli beam)
BETA_L = (1.8751040687119611, 4.6940911329741745, 7.8547574382376126)

#: fewest elements: N = 4 has the first three frequencies 1.4 / 4.2 / 4.5 % off (Yang & Li 2020's plate), fewer
#: leave the third mode to the last two or three links
MIN_ELEMENTS = 4


def _fmt(v) -> str:
    return " ".join(repr(float(x)) for x in v)


def _positive(beam: str, field: str, unit: str, value, fix: str) -> float:
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value > 0
    if not ok:
        raise InputError(f"elastic beam '{beam}': {field} must be a finite number > 0 [{unit}], got {value!r}; {fix}")
    return float(value)


#: a moving support's joints carry this many times the inertia hanging from them as
#: armature [-]: the chain's reactions change the support's acceleration by 1e-8 of
#: themselves (:meth:`bodies.mujoco_bodies.MujocoBodies.drive`)
SUPPORT_ARMATURE = 1e8

#: the tip deflection of the first-mode imperfection given to a column beyond its
#: self-weight buckling load, over its length [-] (:meth:`BeamModel.imperfection`)
IMPERFECTION = 1e-3

#: Greenhill (1881): the uniform weight per length ``q`` at which a column clamped at its
#: foot and free at its top buckles, ``(q L^3 / (E I))_cr = (9/4) j^2`` with ``j`` the first
#: zero of the Bessel function ``J_{-1/3}`` (Timoshenko & Gere 1961, Theory of Elastic
#: Stability, §2.13)
GREENHILL = 7.837347


@dataclass(frozen=True)
class Support:
    """What a clamp is fixed to when that moves (a shaken or rolling tank): joints between
    the world and the clamped link whose motion is prescribed, not integrated
    (:meth:`bodies.mujoco_bodies.MujocoBodies.drive` drives them). ``slides``: the world
    axes (unit vectors) the support translates along, one slide each; ``hinge``: ``(point
    [m], axis)`` of the world axis it turns about, or None. A support does either: the
    rigid motions of a scene's tank are translations or a turn about one axis.

    Each joint carries :data:`SUPPORT_ARMATURE` times the inertia it holds up (the chain's
    mass on a slide, its moment of inertia about the axis, bounded above, on the hinge), so
    the force that gives the support its prescribed acceleration is that armature times the
    acceleration and the chain's reactions leave the acceleration alone to 1e-8 of itself."""

    slides: tuple = ()
    hinge: tuple | None = None

    def __post_init__(self):
        axes = tuple(tuple(float(c) for c in a) for a in self.slides)
        if any(len(a) != 3 or not math.isclose(math.hypot(*a), 1.0, rel_tol=1e-9) for a in axes):
            raise InputError(f"Support: slides must be unit vectors (x, y, z), got {self.slides!r}")
        hinge = self.hinge
        if hinge is not None:
            point, axis = (tuple(float(c) for c in v) for v in hinge)
            if len(point) != 3 or len(axis) != 3 or not math.isclose(math.hypot(*axis), 1.0, rel_tol=1e-9):
                raise InputError(f"Support: hinge must be (point (x, y, z) [m], unit axis), got {self.hinge!r}")
            hinge = (point, axis)
        if axes and hinge is not None:
            raise InputError("Support: give slides or a hinge, not both")
        if not axes and hinge is None:
            raise InputError("Support: give the slides or the hinge of the moving support")
        object.__setattr__(self, "slides", axes)
        object.__setattr__(self, "hinge", hinge)

    @property
    def n_joints(self) -> int:
        return len(self.slides) if self.slides else 1


@dataclass(frozen=True)
class BeamModel:
    """A cantilever as built by :func:`elastic_beam`: its parameters, its MJCF and the
    analytic answers it is checked against. Lengths [m], E [Pa], rho [kg/m^3]."""

    name: str
    length: float  #: L [m], along +z from the clamp (-z when hanging, :attr:`direction`)
    thickness: float  #: h [m], along x (the bending direction)
    width: float  #: W [m], along y (1 m in 2-D scenes)
    E: float  #: Young's modulus [Pa]
    rho: float  #: density [kg/m^3]
    nu: float  #: Poisson's ratio (enters G only)
    kappa: float  #: shear coefficient (5/6 for a rectangle)
    n_elements: int  #: N, hinges (and shear slides) at element midpoints
    base: tuple  #: clamp point [m], (3,), the centre of the clamped end (the foot, or the top when hanging)
    shear: bool  #: shear slides (Timoshenko) or not (Rayleigh)
    beta: float  #: stiffness-proportional damping [s]
    xml: str  #: the ``<body>`` element, for :func:`bodies.builders.scene`
    #: two-sided thin-wall boundary: where fewer than two particles fit across the plate,
    #: lay two columns at +-dx/2 about its mid-plane anyway, each taking its mDBC density
    #: from the fluid on its own side (see :meth:`boundary_particles`)
    thin_wall: bool = False
    #: "up": clamped at ``base`` and rising along +z; "down": clamped at ``base`` and hanging
    #: along -z (the chain's frame turned half a turn about x: plate-frame x is world x, plate
    #: z, the arc length from the clamp, points down)
    direction: str = "up"
    #: the moving support the clamp is fixed to (None: welded to the world)
    support: Support | None = None
    #: a standing chain turned about y by this angle [deg] from +z towards +x (90: lying
    #: along +x, a horizontal cantilever; plate-frame x, the bending direction, is then
    #: world -z); 0 when hanging
    angle: float = 0.0

    @property
    def rotation(self) -> np.ndarray:
        """The clamped link's frame in the world (3, 3): columns are the plate frame's x
        (bending), y (width) and z (length, from the clamp) axes."""
        return _frame(self.direction, self.angle)

    # -- derived ---------------------------------------------------------------
    @property
    def I(self) -> float:  # noqa: E743 - the beam's symbol
        """Second moment of area about y [m^4]."""
        return self.width * self.thickness**3 / 12.0

    @property
    def A(self) -> float:
        """Section area [m^2]."""
        return self.width * self.thickness

    @property
    def G(self) -> float:
        """Shear modulus [Pa]."""
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def link_names(self) -> list[str]:
        """The chain's bodies from the clamp up; the first is clamped (welded to the world, no
        degrees of freedom; or on the joints of its moving :attr:`support`)."""
        return [f"{self.name}_link{k}" for k in range(self.n_elements + 1)]

    @property
    def support_joints(self) -> list[str]:
        """The joints of the moving support (:attr:`support`), in its order; none when welded."""
        return [] if self.support is None else [f"{self.name}_support{k}" for k in range(self.support.n_joints)]

    @property
    def link_bounds(self) -> np.ndarray:
        """``(N + 1, 2)``: each link's span ``[z0, z1]`` [m] along the beam from the clamp."""
        l = self.length / self.n_elements
        cuts = np.concatenate([[0.0], (np.arange(self.n_elements) + 0.5) * l, [self.length]])
        return np.stack([cuts[:-1], cuts[1:]], axis=1)

    # -- analytic references -----------------------------------------------------
    def tip_deflection_point(self, P: float, theory: str = "timoshenko") -> float:
        """Static tip deflection [m] under a tip load ``P`` [N] along x: ``P L^3 / (3 E I)``
        plus, for Timoshenko, ``P L / (kappa G A)``."""
        L = self.length
        d = P * L**3 / (3 * self.E * self.I)
        return d + (P * L / (self.kappa * self.G * self.A) if theory == "timoshenko" else 0.0)

    def tip_deflection_uniform(self, q: float, theory: str = "timoshenko") -> float:
        """Static tip deflection [m] under a uniform load ``q`` [N/m] along x:
        ``q L^4 / (8 E I)`` plus, for Timoshenko, ``q L^2 / (2 kappa G A)``."""
        L = self.length
        d = q * L**4 / (8 * self.E * self.I)
        return d + (q * L**2 / (2 * self.kappa * self.G * self.A) if theory == "timoshenko" else 0.0)

    def natural_frequencies(self, n: int = 3, theory: str = "timoshenko") -> np.ndarray:
        """The first ``n`` (<= 3 for Euler-Bernoulli) bending frequencies [Hz] of the
        clamped-free beam."""
        if theory == "euler-bernoulli":
            bl = np.array(BETA_L[:n])
            return bl**2 / (2 * math.pi * self.length**2) * math.sqrt(self.E * self.I / (self.rho * self.A))
        return timoshenko_frequencies(self.length, self.thickness, self.E, self.rho, self.nu, self.kappa, n)

    def stable_dt(self, integrator: str = "RK4") -> float:
        """Largest stable MuJoCo step [s] of the chain alone, from its natural frequencies
        ``omega_n`` (the beam compiled alone and linearised, :func:`modal_frequencies`).
        RK4 (explicit in stiffness and damping): the largest ``dt`` for which every mode's
        ``s dt`` lies in RK4's stability region, ``s`` the roots of ``s^2 + beta omega_n^2 s
        + omega_n^2 = 0``; undamped this is ``2 sqrt 2 / omega_max``, and stiffness-
        proportional damping (``beta``) shrinks it where ``beta omega_max`` is not small.
        ``"Euler"``/``"implicitfast"`` (MuJoCo integrates joint damping implicitly there):
        ``2 / omega_max``."""
        import mujoco

        from bodies.builders import scene

        model = mujoco.MjModel.from_xml_string(scene(self.xml, gravity=0.0))
        w = 2.0 * math.pi * modal_frequencies(model, mujoco.MjData(model))
        w = w[w > 0]
        if integrator.upper() != "RK4":
            return 2.0 / w.max()
        c = self.beta * w**2 / 2.0
        s = np.concatenate([-c + np.sqrt(c**2 - w**2 + 0j), -c - np.sqrt(c**2 - w**2 + 0j)])

        def stable(dt):
            z = s * dt
            return bool((np.abs(1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24) <= 1.0 + 1e-12).all())

        lo, hi = 0.0, 2.9 / w.max()  # RK4's region reaches 2 sqrt 2 on the imaginary axis, 2.79 on the real
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if stable(mid) else (lo, mid)
        return lo

    # -- coupling --------------------------------------------------------------
    def particles_across(self, dx: float) -> int:
        """Boundary particles across the thickness on a lattice of spacing ``dx`` [m]:
        ``max(1, round(h / dx))`` (two with :attr:`thin_wall` where that is fewer)."""
        n = max(1, int(round(self.thickness / dx)))
        return max(n, 2) if self.thin_wall else n

    def wall_thickness(self, dx: float) -> float:
        """The thickness [m] the fluid meets: ``h``, or with the thin-wall columns of a plate
        fewer than two particles thick, ``2 dx`` (the fluid stands off the plate by
        ``dx - h / 2`` on each side, under a spacing)."""
        return 2.0 * dx if self.thin_wall and round(self.thickness / dx) < 2 else self.thickness

    def boundary_particles(self, dx: float, layers: int, dim: int = 3):
        """Boundary particles on a lattice of spacing ``dx`` [m] laid over the whole
        undeformed plate (cell-centred, as :mod:`bodies.sampling` lays them), ``layers``
        deep inside its faces (all of the section where the plate is thinner than two
        bands), the clamped face left out (it stands on the floor; a hanging beam meets
        the wall it hangs from there). Each particle belongs to the link whose span holds
        it and is stored in that link's frame, so :func:`bodies.sampling.place` moves it
        with the link.

        Returns points ``(n, 3)`` [m] in their link's frame and the link index of each
        (0 = the welded foot link, ..., N = the tip link; see :attr:`link_names`)."""
        if not (isinstance(dx, (int, float)) and math.isfinite(dx) and dx > 0):
            raise InputError(f"elastic beam '{self.name}': dx must be finite and > 0 [m], got {dx!r}")
        if int(layers) != layers or layers < 1:
            raise InputError(f"elastic beam '{self.name}': layers must be a whole number >= 1, got {layers!r}")
        if dim not in (2, 3):
            raise InputError(f"elastic beam '{self.name}': dim must be 2 or 3, got {dim!r}")

        def grid(lo, hi):
            n = max(1, int(round((hi - lo) / dx)))
            return lo + (np.arange(n) + 0.5) * (hi - lo) / n

        h2, w2 = self.wall_thickness(dx) / 2, self.width / 2
        xs, zs = grid(-h2, h2), grid(0.0, self.length)
        ys = grid(-w2, w2) if dim == 3 else np.array([0.0])
        p = np.stack(np.meshgrid(xs, ys, zs, indexing="ij"), axis=-1).reshape(-1, 3)
        depth = np.minimum(h2 - np.abs(p[:, 0]), self.length - p[:, 2])  # to the sides and the top
        if dim == 3:
            depth = np.minimum(depth, w2 - np.abs(p[:, 1]))
        p = p[depth < layers * dx]
        bounds = self.link_bounds
        owner = np.clip(np.searchsorted(bounds[:, 1], p[:, 2], side="right"), 0, self.n_elements)
        p_b = p.copy()
        p_b[:, 2] -= bounds[owner, 0]  # each link's frame sits at its lower end
        return p_b, owner

    def blend(self, s):
        """The two links whose frames carry a point at arc length ``s`` [m] from the clamp,
        and the weight of the first: ``(a, b = a + 1, w)``. The weights are the linear
        (hat) shape functions of nodes at ``s_k = k l``, ``k = 0..N`` (the welded foot
        link's lower end, the centres of links 1..N-1, the tip link's upper end), so a
        point between nodes ``k`` and ``k + 1`` moves ``w = (s_{k+1} - s) / l`` with link
        ``k`` and ``1 - w`` with link ``k + 1``: the deformed surface is continuous across
        every joint (rigid links alone leave the outer face open by about ``h dtheta / 2``
        at a joint bent by ``dtheta``), and a point on a node rides on its link alone."""
        s = np.asarray(s, float)
        l = self.length / self.n_elements
        a = np.clip(np.floor(s / l).astype(np.int64), 0, self.n_elements - 1)
        w = np.clip((a + 1) - s / l, 0.0, 1.0)
        return a, a + 1, w

    def imperfection(self, slope, amplitude: float) -> dict:
        """The hinge angles [rad] that bend the chain into a shape of slope ``slope(s)`` [-]
        (a callable of the arc length ``s`` [m] from the clamp; e.g. a buckling mode,
        :func:`self_weight_buckling`) with its tip ``amplitude`` [m] along +x: link ``k``
        turned by the slope at its centre, each hinge taking the difference from the link
        below it (the welded one stays straight), the shape scaled so that the tip,
        ``sum_k l_k sin(theta_k)`` over the links' spans from joint to joint, is
        ``amplitude``; ``{joint name: angle}`` for :meth:`MujocoBodies.set_joints`. The shear
        slides stay at zero. The angles are the chain's own, whatever its :attr:`rotation`:
        "+x" is the plate frame's."""
        bounds = self.link_bounds[1:]
        theta = np.asarray(slope(bounds.mean(axis=1)), float)
        span = np.diff(np.concatenate([bounds[:, 0], [self.length]]))  # from each hinge to the next, or the tip
        theta *= amplitude / float(np.dot(span, theta))  # small angles first, then the sines' own
        for _ in range(3):  # each pass cuts the error by ~theta^2 / 6
            theta *= amplitude / float(np.dot(span, np.sin(theta)))
        hinge = np.diff(np.concatenate([[0.0], theta]))
        return {f"{self.name}_bend{k + 1}": float(a) for k, a in enumerate(hinge)}

    def blended_particles(self, dx: float, layers: int, dim: int = 3):
        """The boundary particles of :meth:`boundary_particles`, each carried by two
        links (:meth:`blend`): returns ``(plate, a, b, w, p_a, p_b)``, the undeformed
        positions in the plate's frame (x across, y along the width, z = s from the
        clamp) [m] ``(n, 3)``, the link numbers ``a``, ``b`` and the weight ``w`` of
        ``a``, and the positions in each link's frame [m] ``(n, 3)`` each."""
        pts, owner = self.boundary_particles(dx, layers, dim)
        start = self.link_bounds[:, 0]
        plate = pts.copy()
        plate[:, 2] += start[owner]
        a, b, w = self.blend(plate[:, 2])
        p_a, p_b = plate.copy(), plate.copy()
        p_a[:, 2] -= start[a]
        p_b[:, 2] -= start[b]
        return plate, a, b, w, p_a, p_b

    def ghost_offsets(self, plate, dim: int = 3, dx: float | None = None) -> np.ndarray:
        """Vectors [m] ``(n, 3)``, plate frame, from particles at ``plate`` (undeformed,
        plate frame) to their mDBC ghost nodes: the mirror images across the nearest of
        the faces the fluid touches (the two sides, the free end, in 3-D the two edges; not
        the clamped end, which stands on the floor or meets the wall a hanging beam hangs
        from: :func:`bodies.sampling.ghost_offsets` on the plate as one box reaching far
        beyond the clamp). With the thin-wall columns (give
        ``dx``) the faces are those of the band the particles fill, ``2 dx`` thick, so each
        column mirrors into the fluid on its own side."""
        from bodies.sampling import GeomShape, ghost_offsets

        below = 10.0 * self.length
        h = self.thickness if dx is None else self.wall_thickness(dx)
        box = GeomShape("box", np.array([h / 2, self.width / 2, (self.length + below) / 2]),
                        np.array([0.0, 0.0, (self.length - below) / 2]), np.eye(3))
        return ghost_offsets([box], plate, dim)


def elastic_beam(name: str, length: float, thickness: float, *, E: float, rho: float, width: float = 1.0,
                 nu: float = 0.0, kappa: float = 5.0 / 6.0, n_elements: int = 16, base=(0.0, 0.0, 0.0),
                 shear: bool = True, beta: float = 0.0, thin_wall: bool = False,
                 direction: str = "up", support: Support | None = None, angle: float = 0.0) -> BeamModel:
    """An elastic cantilever clamped at ``base`` [m] (the centre of its clamped end) and
    rising along +z (``direction="up"``, clamped at its foot) or hanging along -z
    (``direction="down"``, clamped at its top: the chain turned half a turn about x), as a
    chain of MuJoCo bodies (see the module docstring).

    Parameters: ``length`` L [m], ``thickness`` h [m] (along x), ``width`` W [m] (along y;
    1 m for 2-D scenes), ``E`` Young's modulus [Pa], ``rho`` density [kg/m^3], ``nu``
    Poisson's ratio (for ``G``; pass ``E / (1 - nu^2)`` as E for a wide plate in
    cylindrical bending), ``kappa`` shear coefficient, ``n_elements`` N >= 4, ``shear``
    Timoshenko (True) or Rayleigh (False), ``thin_wall`` the two-sided boundary for a
    plate fewer than two particles thick (:attr:`BeamModel.thin_wall`), ``support`` the
    moving support the clamp is fixed to (:class:`Support`; None: welded to the world),
    ``angle`` [deg] a standing chain turned about y from +z towards +x (90: a horizontal
    cantilever along +x, bending in the x-z plane),
    ``beta`` stiffness-proportional damping [s]
    (joint damping ``beta k``; explicit under RK4, where it shrinks the stable step once
    ``beta omega_max`` nears 1, see :meth:`BeamModel.stable_dt`: prefer ``implicitfast``
    for a heavily damped chain).

    Returns a :class:`BeamModel`; its ``xml`` is a ``<body>`` for
    :func:`bodies.builders.scene`, its links are named ``{name}_link0`` (welded) to
    ``{name}_link{N}``, with sites ``{name}_tip`` (the free end's centre: the top, or the
    bottom when hanging) and ``{name}_corner`` (the free end, -x side: the "upper left
    corner" of Yang & Li 2020, Figure 6; the lower upstream corner of a hanging gate)."""
    if not isinstance(name, str) or not name:
        raise InputError(f"elastic beam: name must be a non-empty string, got {name!r}")
    L = _positive(name, "length", "m", length, "give the cantilever's length from clamp to tip")
    h = _positive(name, "thickness", "m", thickness, "give the plate's thickness in the bending direction (x)")
    W = _positive(name, "width", "m", width, "give the width along y (1 m in a 2-D scene)")
    E = _positive(name, "E", "Pa", E, "give Young's modulus, e.g. E=1e6 for Yang & Li 2020's plate")
    rho = _positive(name, "rho", "kg/m^3", rho, "give the material density, e.g. rho=2500")
    kappa = _positive(name, "kappa", "-", kappa, "give the shear coefficient, 5/6 for a rectangular section")
    if not (isinstance(nu, (int, float)) and math.isfinite(nu) and -1.0 < nu < 0.5):
        raise InputError(f"elastic beam '{name}': nu (Poisson's ratio) must lie in (-1, 0.5), got {nu!r}")
    if not (isinstance(beta, (int, float)) and math.isfinite(beta) and beta >= 0):
        raise InputError(f"elastic beam '{name}': beta (stiffness-proportional damping) must be finite and >= 0 "
                         f"[s], got {beta!r}; give 0 for no damping")
    nu, beta = float(nu), float(beta)  # a numpy scalar passes the checks but repr()s as np.float64(...) in the XML
    if not (isinstance(n_elements, int) and not isinstance(n_elements, bool) and n_elements >= MIN_ELEMENTS):
        raise InputError(f"elastic beam '{name}': n_elements must be a whole number >= {MIN_ELEMENTS}, got "
                         f"{n_elements!r}; fewer cannot resolve the third bending mode (8 give the first three "
                         f"frequencies within 1 %, 16 within 0.3 %)")
    if direction not in ("up", "down"):
        raise InputError(f"elastic beam '{name}': direction must be \"up\" (clamped at its foot, rising along +z) or "
                         f"\"down\" (clamped at its top, hanging along -z), got {direction!r}")
    if not (isinstance(angle, (int, float)) and math.isfinite(angle) and -180.0 <= angle <= 180.0):
        raise InputError(f"elastic beam '{name}': angle must be a number of degrees in [-180, 180] (the turn about y "
                         f"from +z towards +x), got {angle!r}")
    if direction == "down" and angle != 0:
        raise InputError(f"elastic beam '{name}': a hanging chain (direction=\"down\") hangs along -z; give angle=0, "
                         f"or a standing chain (direction=\"up\") turned by the angle")
    angle = float(angle)
    base = tuple(float(c) for c in base)
    if len(base) != 3 or not all(math.isfinite(c) for c in base):
        raise InputError(f"elastic beam '{name}': base must be 3 finite coordinates (x, y, z) [m], got {base!r}")
    N = n_elements
    l = L / N
    G = E / (2.0 * (1.0 + nu))
    kb, ks = E * W * h**3 / 12.0 / l, kappa * G * W * h / l

    def geom(k, seg):
        return (f'<geom name="{name}_geom{k}" type="box" size="{_fmt([h / 2, W / 2, seg / 2])}" '
                f'pos="0 0 {seg / 2!r}" density="{rho!r}" contype="0" conaffinity="0"/>')

    if support is not None and not isinstance(support, Support):
        raise InputError(f"elastic beam '{name}': support must be a bodies.elastic.Support or None, got {support!r}")
    if direction == "down":
        turn = ' quat="0 1 0 0"'  # half a turn about x: z -> -z, y -> -y
    elif angle != 0:  # about y: z -> (sin a, 0, cos a)
        turn = f' quat="{_fmt([math.cos(math.radians(angle) / 2), 0.0, math.sin(math.radians(angle) / 2), 0.0])}"'
    else:
        turn = ""
    carried = _support_joints(name, support, base, _frame(direction, angle), rho * W * h * L, L)
    parts = [f'<body name="{name}_link0" pos="{_fmt(base)}"{turn}>{carried}{geom(0, l / 2)}']
    for k in range(1, N + 1):
        seg = l / 2 if k == N else l
        joints = (f'<joint name="{name}_bend{k}" type="hinge" axis="0 1 0" stiffness="{kb!r}" '
                  f'damping="{beta * kb!r}"/>')
        if shear:
            joints += (f'<joint name="{name}_shear{k}" type="slide" axis="1 0 0" stiffness="{ks!r}" '
                       f'damping="{beta * ks!r}"/>')
        parts.append(f'<body name="{name}_link{k}" pos="0 0 {(l / 2 if k == 1 else l)!r}">{joints}{geom(k, seg)}')
    parts.append(f'<site name="{name}_tip" pos="0 0 {l / 2!r}" size="{h / 4!r}"/>'
                 f'<site name="{name}_corner" pos="{-h / 2!r} 0 {l / 2!r}" size="{h / 4!r}"/>')
    xml = "".join(parts) + "</body>" * (N + 1)
    return BeamModel(name, L, h, W, E, rho, float(nu), kappa, N, base, bool(shear), float(beta), xml,
                     bool(thin_wall), direction, support, angle)


def _frame(direction: str, angle: float) -> np.ndarray:
    """The clamped link's rotation (link frame -> world): half a turn about x when hanging,
    else ``angle`` [deg] about y."""
    if direction == "down":
        return np.diag([1.0, -1.0, -1.0])
    a = math.radians(angle)
    return np.array([[math.cos(a), 0.0, math.sin(a)], [0.0, 1.0, 0.0], [-math.sin(a), 0.0, math.cos(a)]])


def _support_joints(name: str, support: Support | None, base, frame: np.ndarray, mass: float, length: float) -> str:
    """The joints of the clamped link on its moving support (none when welded), given in
    the link's frame (``frame``: its rotation into the world), each with the armature of
    :class:`Support`: ``SUPPORT_ARMATURE`` times the chain's mass [kg] on a slide, times an
    upper bound of its moment of inertia about the axis, ``mass (d + L)^2`` [kg m^2] with
    ``d`` the clamp's distance from the axis' point, on the hinge."""
    if support is None:
        return ""
    flip = frame.T  # world -> link frame
    if support.slides:
        return "".join(f'<joint name="{name}_support{k}" type="slide" axis="{_fmt(flip @ np.asarray(a))}" '
                       f'armature="{SUPPORT_ARMATURE * mass!r}"/>' for k, a in enumerate(support.slides))
    point, axis = (np.asarray(v) for v in support.hinge)
    reach = float(np.linalg.norm(point - np.asarray(base))) + length
    return (f'<joint name="{name}_support0" type="hinge" pos="{_fmt(flip @ (point - np.asarray(base)))}" '
            f'axis="{_fmt(flip @ axis)}" armature="{SUPPORT_ARMATURE * mass * reach**2!r}"/>')


def self_weight_buckling(length: float, EI: float, loads, n: int = 8):
    """The buckling of a column clamped at its foot and free at its top under distributed
    axial loads: Greenhill's problem (Greenhill 1881; Timoshenko & Gere 1961, Theory of
    Elastic Stability, §2.13: a uniform weight ``q`` buckles it at ``q L^3 / (E I) =
    7.837``, :data:`GREENHILL`), for loads that change along it (a plate's weight in air
    above the water, its weight less its buoyancy below).

    ``length`` L [m], ``EI`` bending stiffness [N m^2]; ``loads``: ``((s0, s1, q), ...)``,
    a weight ``q`` [N/m] per length pulling the column towards its clamp (negative: away
    from it, as the buoyancy of a plate lighter than water) over ``s0 .. s1`` [m] from the
    clamp. The axial compression at ``s`` is ``N(s) = int_s^L q``; the straight column
    buckles when the loads are multiplied by the smallest ``lambda`` for which ``E I w''''
    + lambda (N w')' = 0`` (``w = w' = 0`` at the clamp, ``w'' = w''' = 0`` at the top) has
    a solution. Solved by Rayleigh-Ritz on the energy ``E I / 2 int w''^2 - lambda / 2 int
    N w'^2`` with ``w'' = sum c_k P_k(2 s / L - 1)``, ``n`` shifted Legendre polynomials
    (the clamp's conditions hold by construction), integrated exactly by Gauss-Legendre
    between the loads' ends: an upper bound that meets Greenhill's 7.837347 to 10 digits at
    n = 8 (``tests/test_plate_buckling.py``).

    Returns ``(factor, slope)``: ``lambda`` (``math.inf`` when no compression can buckle
    it, e.g. a column in tension) and the buckling mode's slope ``w'(s)`` [-] as a
    callable of ``s`` [m], scaled to a tip deflection ``w(L) = 1`` (None with an infinite
    factor)."""
    from numpy.polynomial import Legendre, Polynomial
    from scipy.linalg import eigh

    L = _positive("column", "length", "m", length, "give the column's length")
    EI = _positive("column", "EI", "N m^2", EI, "give the bending stiffness E I")
    pieces = [(float(a) / L, float(b) / L, float(q)) for a, b, q in loads]
    if any(not (0.0 <= a < b <= 1.0 + 1e-12) or not math.isfinite(q) for a, b, q in pieces):
        raise InputError(f"column buckling: loads must be (s0, s1, q) with 0 <= s0 < s1 <= L = {L} m and q finite, "
                         f"got {list(loads)!r}")
    # x = s / L; the basis f_k'' = P_k(2x - 1), f_k' its integral from the clamp
    ddf = [Legendre.basis(k, domain=[0.0, 1.0]).convert(kind=Polynomial) for k in range(n)]
    df = [p.integ(lbnd=0.0) for p in ddf]
    K = np.diag(1.0 / (2.0 * np.arange(n) + 1.0))  # int_0^1 P_i P_j dx

    def compression(x):  # N(x L) [N]
        return sum(q * L * np.clip(b - np.maximum(x, a), 0.0, None) for a, b, q in pieces)

    cuts = np.unique(np.clip([0.0, 1.0] + [c for a, b, _ in pieces for c in (a, b)], 0.0, 1.0))
    gx, gw = np.polynomial.legendre.leggauss(n + 2)
    G = np.zeros((n, n))
    for a, b in zip(cuts[:-1], cuts[1:]):
        x = 0.5 * (b - a) * gx + 0.5 * (a + b)
        d = np.array([p(x) for p in df])
        G += (d * (0.5 * (b - a) * gw * compression(x))) @ d.T
    # E I / L^3 K c = lambda / L G c  <=>  G c = (1 / lambda) (E I / L^2) K c
    mu, vec = eigh(G, EI / L**2 * K)
    if mu[-1] <= 0.0:
        return math.inf, None
    c = vec[:, -1] / (L * sum(ck * p.integ(lbnd=0.0)(1.0) for ck, p in zip(vec[:, -1], df)))  # w(L) = 1

    def slope(s):
        x = np.asarray(s, float) / L
        return sum(ck * p(x) for ck, p in zip(c, df))

    return 1.0 / mu[-1], slope


def timoshenko_frequencies(length: float, thickness: float, E: float, rho: float, nu: float = 0.0,
                           kappa: float = 5.0 / 6.0, n: int = 3) -> np.ndarray:
    """The first ``n`` bending frequencies [Hz] of a clamped-free Timoshenko beam of
    rectangular section (thickness h along the bending direction), the roots ``b`` of
    Han, Benaroya & Wei (1999), fixed-free frequency equation, below the second
    spectrum (``b < 1 / (r s)``)::

        2 + (b^2 (r^2 - s^2)^2 + 2) cosh(b a) cos(b c)
          - b (r^2 + s^2) / sqrt(1 - b^2 r^2 s^2) sinh(b a) sin(b c) = 0,
        a, c = sqrt(( -/+ (r^2 + s^2) + sqrt((r^2 - s^2)^2 + 4 / b^2)) / 2),

    with ``b^2 = rho A L^4 omega^2 / (E I)``, ``r^2 = I / (A L^2)``, ``s^2 = E I /
    (kappa G A L^2)``. Reduces to ``1 + cos cosh = 0`` as r, s -> 0."""
    from scipy.optimize import brentq

    I_A = thickness**2 / 12.0  # I / A
    G = E / (2.0 * (1.0 + nu))
    r2 = I_A / length**2
    s2 = E * I_A / (kappa * G * length**2)

    def F(b):  # the frequency equation divided by cosh(b a), which keeps it finite
        t = math.sqrt((r2 - s2) ** 2 + 4.0 / b**2)
        a, c = math.sqrt(0.5 * (t - (r2 + s2))), math.sqrt(0.5 * (t + (r2 + s2)))
        return (2.0 / math.cosh(min(b * a, 700.0)) + (b**2 * (r2 - s2) ** 2 + 2.0) * math.cos(b * c)
                - b * (r2 + s2) / math.sqrt(1.0 - b**2 * r2 * s2) * math.tanh(b * a) * math.sin(b * c))

    x_max = (1.0 / math.sqrt(r2 * s2)) ** 0.5 * (1 - 1e-9)  # sqrt(b) ~ beta L: roots about pi apart
    b_max = x_max**2
    roots, x0, f0 = [], 0.5, F(0.25)
    while len(roots) < n and x0 < x_max:
        x1 = min(x0 + 0.05, x_max)
        f1 = F(x1**2)
        if f0 * f1 < 0:
            roots.append(brentq(F, x0**2, x1**2, xtol=1e-13, rtol=1e-14))
        x0, f0 = x1, f1
    if len(roots) < n:
        raise InputError(f"Timoshenko beam: only {len(roots)} frequencies lie below the second spectrum "
                         f"(b < {b_max:.4g}); ask for fewer")
    omega = np.array(roots) * math.sqrt(E * thickness**2 / 12.0 / (rho * length**4))
    return omega / (2.0 * math.pi)


def link_wrenches(points_w, forces_w, owner, com_w, n_links: int):
    """Sum point forces onto the links that carry them: force [N] and torque about each
    link's centre of mass [N m], world frame, ``(n_links, 3)`` each (what
    :meth:`bodies.mujoco_bodies.MujocoBodies.set_wrenches` takes; the welded link's share
    goes into the clamp). ``points_w`` and ``forces_w`` are ``(n, 3)``, ``owner`` the link
    index of each point, ``com_w`` the links' centres of mass ``(n_links, 3)``. The sum of
    the forces is kept exactly (one ``np.add.at`` per component), so the momentum the
    fluid loses the chain gains."""
    p, f = np.asarray(points_w, float), np.asarray(forces_w, float)
    owner = np.asarray(owner)
    F, T = np.zeros((n_links, 3)), np.zeros((n_links, 3))
    np.add.at(F, owner, f)
    np.add.at(T, owner, np.cross(p - np.asarray(com_w, float)[owner], f))
    return F, T


def linearise(model, data, eps: float = 1e-7):
    """Stiffness ``K`` and mass ``M`` ``(nv, nv)`` of a MuJoCo model about the state in
    ``data`` (velocities zeroed): ``M`` from ``mj_fullM``, ``K = -d(qfrc_passive -
    qfrc_bias)/dq`` by central differences of MuJoCo's own forces (run with gravity off
    for the elastic stiffness alone). Needs ``nq == nv`` (hinges and slides, as the
    chain and flex vertices have). The state in ``data`` is restored."""
    import mujoco

    if model.nq != model.nv:
        raise InputError(f"linearise: the model has nq = {model.nq} != nv = {model.nv} (free or ball joints); "
                         f"linearise a model of hinges and slides only")
    q0, v0 = data.qpos.copy(), data.qvel.copy()
    data.qvel[:] = 0.0
    mujoco.mj_forward(model, data)
    M = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, M)

    def force(q):
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        return data.qfrc_passive - data.qfrc_bias

    K = np.zeros((model.nv, model.nv))
    for j in range(model.nv):
        dq = np.zeros(model.nq)
        dq[j] = eps
        K[:, j] = -(force(q0 + dq) - force(q0 - dq)) / (2 * eps)
    data.qpos[:], data.qvel[:] = q0, v0
    mujoco.mj_forward(model, data)
    return 0.5 * (K + K.T), M


def modal_frequencies(model, data) -> np.ndarray:
    """Natural frequencies [Hz] of the model linearised about ``data`` (:func:`linearise`),
    ascending; rigid-body and zero-stiffness modes come out as 0."""
    from scipy.linalg import eigh

    K, M = linearise(model, data)
    w2 = eigh(K, M, eigvals_only=True)
    return np.sqrt(np.clip(w2, 0.0, None)) / (2.0 * math.pi)


@numba.njit(cache=True)
def _place_blended(a, b, w, p_a, p_b, origin, R, com, V, Om, x, u):
    """``x_i = w (o_a + R_a p_a) + (1 - w) (o_b + R_b p_b)`` and the same blend of the
    two links' rigid-body velocities ``V + Omega x (x_k - com)`` at their own points."""
    for i in range(a.shape[0]):
        for side in range(2):
            k = a[i] if side == 0 else b[i]
            wt = w[i] if side == 0 else 1.0 - w[i]
            p = p_a[i] if side == 0 else p_b[i]
            q0 = origin[k, 0] + R[k, 0, 0] * p[0] + R[k, 0, 1] * p[1] + R[k, 0, 2] * p[2]
            q1 = origin[k, 1] + R[k, 1, 0] * p[0] + R[k, 1, 1] * p[1] + R[k, 1, 2] * p[2]
            q2 = origin[k, 2] + R[k, 2, 0] * p[0] + R[k, 2, 1] * p[1] + R[k, 2, 2] * p[2]
            r0, r1, r2 = q0 - com[k, 0], q1 - com[k, 1], q2 - com[k, 2]
            x[i, 0] += wt * q0
            x[i, 1] += wt * q1
            x[i, 2] += wt * q2
            u[i, 0] += wt * (V[k, 0] + Om[k, 1] * r2 - Om[k, 2] * r1)
            u[i, 1] += wt * (V[k, 1] + Om[k, 2] * r0 - Om[k, 0] * r2)
            u[i, 2] += wt * (V[k, 2] + Om[k, 0] * r1 - Om[k, 1] * r0)


@numba.njit(cache=True)
def _split_wrenches(a, b, w, F, M, com, F_out, T_out):
    """Each particle's force ``F_i`` and its moment about the world origin ``M_i``
    (``x_i x F_i``, or its time average) go to links ``a`` and ``b`` with weights ``w`` and
    ``1 - w``: ``F_k += w F_i``, ``T_k += w (M_i - com_k x F_i)`` (about the link's centre
    of mass). Sum over links of ``F_k`` and of ``T_k + com_k x F_k`` = the particles' sums."""
    for i in range(a.shape[0]):
        for side in range(2):
            k = a[i] if side == 0 else b[i]
            wt = w[i] if side == 0 else 1.0 - w[i]
            f0, f1, f2 = wt * F[i, 0], wt * F[i, 1], wt * F[i, 2]
            F_out[k, 0] += f0
            F_out[k, 1] += f1
            F_out[k, 2] += f2
            T_out[k, 0] += wt * M[i, 0] - (com[k, 1] * f2 - com[k, 2] * f1)
            T_out[k, 1] += wt * M[i, 1] - (com[k, 2] * f0 - com[k, 0] * f2)
            T_out[k, 2] += wt * M[i, 2] - (com[k, 0] * f1 - com[k, 1] * f0)


class ElasticBody:
    """A beam's boundary particles and loads inside a :class:`MujocoBodies` participant
    whose coupled bodies include the beam's links (``bodies=[..., *beam.link_names]``,
    the welded foot link too).

    Particles (:meth:`BeamModel.blended_particles`) are stored in the frames of the two
    links that carry them and placed every step as the blend of both rigid placements
    (:meth:`BeamModel.blend`), ``x = w (o_a + R_a p_a) + (1 - w) (o_b + R_b p_b)``, with
    the same blend of the links' rigid-body velocities ``V + Omega x (x_k - com)``
    (Barreiro et al. 2016, Eq. 13 on each link), so they never drift and the surface stays closed at the
    joints. The force on a particle is split with the same weights (:func:`_split_wrenches`):
    link ``a`` gets ``w f`` and link ``b`` ``(1 - w) f``, both acting at the particle, one
    wrench per link about its centre of mass; the sums of force and of moment about any
    point are the particles' (momentum is exchanged exactly), and the power ``f . u`` the
    fluid puts in is what the links take (the velocity is the same blend). The welded
    foot link's share goes into the clamp."""

    def __init__(self, beam: BeamModel, bodies, dx: float, layers: int, dim: int = 3):
        names = list(bodies.body_names)
        missing = [n for n in beam.link_names if n not in names]
        if missing:
            raise InputError(f"elastic beam '{beam.name}': the MuJoCo participant does not couple the links "
                             f"{missing[:3]}{'...' if len(missing) > 3 else ''}; build it with "
                             f"bodies=[..., *beam.link_names]")
        self.beam, self.bodies = beam, bodies
        self.dim = dim
        self.link_index = np.array([names.index(n) for n in beam.link_names])  #: coupled-body index per link
        #: undeformed positions in the plate frame [m] (x across, y along the width, z from the clamp)
        self.plate, a, b, self.w, self.p_a, self.p_b = beam.blended_particles(dx, layers, dim)
        #: coupled-body indices of the two links that carry each particle; ``w``: the weight of ``a``
        self.a, self.b = self.link_index[a], self.link_index[b]
        self.owner = np.where(self.w >= 0.5, self.a, self.b)  #: the link that carries most of each particle
        self.n = len(self.plate)
        self._sites = {s: bodies.site(f"{beam.name}_{s}")[0] for s in ("tip", "corner")}
        self._site0 = {s: bodies.site_positions([i])[0].copy() for s, i in self._sites.items()}

    def place(self, kin=None):
        """World positions [m] and velocities [m/s] of the particles, ``(n, 3)`` each, for
        the links' kinematics ``kin`` (default: the bodies' now)."""
        kin = self.bodies.kinematics() if kin is None else kin
        x, u = np.zeros((self.n, 3)), np.zeros((self.n, 3))
        _place_blended(self.a, self.b, self.w, self.p_a, self.p_b, kin.origin, kin.rotation, kin.com,
                       kin.velocity, kin.omega, x, u)
        return x, u

    def rotate(self, v_plate, kin=None) -> np.ndarray:
        """Vectors given in the plate frame ``(n, 3)`` (e.g. ghost-node offsets), turned
        with the particles' blended frames into the world frame."""
        kin = self.bodies.kinematics() if kin is None else kin
        w = self.w[:, None]
        return (w * np.einsum("nij,nj->ni", kin.rotation[self.a], v_plate)
                + (1.0 - w) * np.einsum("nij,nj->ni", kin.rotation[self.b], v_plate))

    def split(self, forces_w, moments_w, com_w):
        """Link wrenches from particle loads: forces [N] ``(n, 3)`` and their moments about
        the world origin [N m] ``(n, 3)`` (world frame; time averages over a step are fine,
        which is what a fluid exchanged), about the centres of mass ``com_w`` ``(n_bodies,
        3)``; returns force and torque ``(n_bodies, 3)`` each, zero rows for the bodies
        that are not this beam's."""
        n_b = self.bodies.n_bodies
        F, T = np.zeros((n_b, 3)), np.zeros((n_b, 3))
        _split_wrenches(self.a, self.b, self.w, np.ascontiguousarray(forces_w, dtype=np.float64),
                        np.ascontiguousarray(moments_w, dtype=np.float64),
                        np.ascontiguousarray(com_w, dtype=np.float64), F, T)
        return F, T

    def wrenches(self, forces_w, points_w=None):
        """The force [N] and torque about the centre of mass [N m] of every coupled body,
        ``(n_bodies, 3)`` each, from the forces on this beam's particles ``(n, 3)``
        (world frame; at ``points_w``, by default where :meth:`place` puts them now),
        split between the two links that carry each (:meth:`split`). Zero rows for the
        bodies that are not this beam's: add the arrays of several bodies before
        :meth:`MujocoBodies.set_wrenches`."""
        kin = self.bodies.kinematics()
        if points_w is None:
            points_w = self.place(kin)[0]
        f = np.asarray(forces_w, float)
        if f.shape != (self.n, 3):
            raise InputError(f"elastic beam '{self.beam.name}': give one force per particle, shape "
                             f"{(self.n, 3)}, got {f.shape}")
        return self.split(f, np.cross(np.asarray(points_w, float), f), kin.com)

    def displacement(self, site: str = "corner") -> np.ndarray:
        """Displacement [m] ``(3,)`` from the start of the ``"tip"`` (the free end's centre)
        or ``"corner"`` (the free end, -x face: Yang & Li 2020, Figure 6's upper left corner) site."""
        i = self._sites[site]
        return self.bodies.site_positions([i])[0] - self._site0[site]

    def check(self, kin=None) -> None:
        """Raise :class:`InstabilityError` naming the first element whose link left the
        finite numbers or turned more than 90 degrees against its neighbour (a chain
        that went unstable), with a remedy."""
        from errors import InstabilityError

        kin = self.bodies.kinematics() if kin is None else kin
        R = kin.rotation[self.link_index]
        x = kin.origin[self.link_index]
        bad = ~np.isfinite(x).all(axis=1) | ~np.isfinite(R).all(axis=(1, 2))
        axis = R[:, :, 2]  # each link's own z, along the beam
        kink = np.einsum("ij,ij->i", axis[1:], axis[:-1]) < 0.0
        bad[1:] |= kink
        if bad.any():
            k = int(np.argmax(bad))
            raise InstabilityError(
                f"elastic beam '{self.beam.name}': element {k} (body '{self.beam.link_names[k]}') went unstable at "
                f"t = {self.bodies.data.time:.9g} s (non-finite, or bent more than 90 degrees against its "
                f"neighbour); use a MuJoCo timestep below {self.beam.stable_dt():.3g} s (the chain's stable RK4 "
                f"step), add damping (beta), or check the loads")
