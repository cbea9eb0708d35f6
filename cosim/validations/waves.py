"""Wave cases with SPH and moored or free bodies (VALIDATION.md, "Bodies and coupling"): moored-body with SPH, floating-box-waves."""

from __future__ import annotations
