"""Sloshing and base-excitation cases of the SPH fluid (VALIDATION.md, "Fluid"): westergaard, sloshing-frequency, sloshing-spheric10."""

from __future__ import annotations
