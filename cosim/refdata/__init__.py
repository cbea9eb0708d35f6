"""Reference data of the validation cases, shipped inside the package.

One folder per dataset (named as in the reference-data collection the project started
from), holding the files that the code, tests and benchmarks read and the dataset's
``SOURCE.txt`` (where the numbers come from, the set-up, the columns and the units; read
it before comparing). ``README.md`` lists the datasets. Large tables are stored gzipped
(``name.gz``): ``np.loadtxt`` and ``np.genfromtxt`` read them as they are::

    from cosim import refdata
    roll = np.loadtxt(refdata.path("sloshing_spheric_test10", "SloshingMotionData.dat.gz"))
"""

from __future__ import annotations

from pathlib import Path, PurePosixPath

from cosim.errors import InputError

ROOT = Path(__file__).resolve().parent


def datasets() -> list[str]:
    """The dataset folders, sorted."""
    return sorted(p.name for p in ROOT.iterdir() if p.is_dir() and not p.name.startswith(("_", ".")))


def path(dataset: str, name: str = "") -> Path:
    """The path of file ``name`` of ``dataset`` (its folder when ``name`` is empty).
    :class:`InputError` naming what is missing and listing what exists when the
    dataset or the file is not there."""
    for what, part in (("dataset", dataset), ("file name", name)):
        if not isinstance(part, str):
            raise InputError(f"refdata: {what} must be a str, got {type(part).__name__}")
    parts = PurePosixPath(name).parts
    if not dataset or "/" in dataset or "\\" in dataset or dataset.startswith(".") \
            or PurePosixPath(name).is_absolute() or ".." in parts:
        raise InputError(f"refdata: {dataset!r}, {name!r}: give a dataset folder name and a file name "
                         "inside it (no absolute paths, no '..')")
    folder = ROOT / dataset
    if not folder.is_dir():
        raise InputError(f"refdata: no dataset {dataset!r} in {ROOT}; there are: {', '.join(datasets())}")
    if not name:
        return folder
    p = folder.joinpath(*parts)
    if not p.is_file():
        have = sorted(str(q.relative_to(folder)) for q in folder.rglob("*") if q.is_file())
        raise InputError(f"refdata: dataset {dataset!r} has no file {name!r}; it has: {', '.join(have)}")
    return p
