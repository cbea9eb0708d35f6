"""Floating-body cases with the SPH fluid (VALIDATION.md, "Bodies and coupling"): floating-box-draft, floating-heave-period, sinking-cylinder."""

from __future__ import annotations
