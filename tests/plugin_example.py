"""A module acting as another package that plugs into cosim's scenes
(:mod:`cosim.scene.registry`): a mooring model of weightless elastic tethers. Its
``pyproject.toml`` would declare it as

    [project.entry-points."cosim.moorings"]
    tether = "plugin_example:Tether"

and ``tests/test_registry.py`` registers it both ways: by hand, with the call an entry
point makes, and through a faked entry point."""

from __future__ import annotations

import math

import numpy as np

from cosim.scene.mooring_models import MooringModel


class TetherMooring:
    """Weightless elastic tethers, a :class:`cosim.protocol.Mooring`: each line pulls its
    fairlead towards its anchor with the tension of a linear elastic rod, ``T = (EA / L)
    (s - L)`` for a span ``s`` longer than its length ``L``, none when slack (Hooke's law,
    ``T = EA strain``). Quasi-static: its force is a function of the fairleads' positions."""

    dynamic = False

    def __init__(self, lines, name: str = "tethers"):
        self.name, self.lines = name, list(lines)
        self.n_lines, self.dim = len(self.lines), len(self.lines[0].anchor)
        self.anchors = np.array([ln.anchor for ln in self.lines], float)
        self.L = np.array([ln.length for ln in self.lines], float)
        self.k = np.array([ln.EA / ln.length for ln in self.lines], float)
        self._pos = None

    def initialize(self, t0: float) -> None:
        if self._pos is None:
            raise ValueError(f"mooring '{self.name}': give the fairlead positions before the run")

    def max_dt(self) -> float:
        return math.inf

    def advance(self, t: float, dt: float) -> None:
        pass

    def save_state(self):
        return {"pos": self._pos.copy()}

    def load_state(self, state) -> None:
        self._pos = np.array(state["pos"], float)

    def set_fairlead_motion(self, positions, velocities=None) -> None:
        self._pos = np.array(positions, float)

    def fairlead_forces(self) -> np.ndarray:
        d = self.anchors - self._pos
        s = np.linalg.norm(d, axis=1)
        T = self.k * np.maximum(s - self.L, 0.0)
        return (T / s)[:, None] * d


class Tether(MooringModel):
    """The scene's side of :class:`TetherMooring`: every line needs ``EA``."""

    line_fields = ("EA",)

    def from_scene(self, scene, lines, *, level, rho, workdir):
        return TetherMooring(lines)
