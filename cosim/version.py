"""Which code is running: the release number and a hash of the source files.

The hash (:func:`code_version`) tells apart two installations whose results may differ
bit for bit: a study reuses a cached run only under the same hash, and ``--resume``
refuses a checkpoint written under another (``cosim.checkpoint``).
"""

from __future__ import annotations

import functools
import hashlib
from pathlib import Path

from cosim import __version__

#: the packages whose sources make the hash
SOURCES = ("cosim", "fluid", "bodies", "moorings")


@functools.lru_cache(maxsize=1)
def code_version() -> str:
    """A hash of the package's source files (Python and the FMU's C), 16 hex digits."""
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for pkg in SOURCES:
        for p in sorted((root / pkg).rglob("*")):
            if p.suffix in (".py", ".c", ".h") and "__pycache__" not in p.parts:
                h.update(str(p.relative_to(root)).encode())
                h.update(p.read_bytes())
    return h.hexdigest()[:16]


__all__ = ["SOURCES", "__version__", "code_version"]
