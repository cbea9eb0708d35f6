"""Whether a change to the coupler keeps every result to the last bit: runs short scenes
through every coupling path and saves every recorded series, then compares two such files.

    python benchmarks/coupling_bit_for_bit.py before.npz      # on the old code
    python benchmarks/coupling_bit_for_bit.py after.npz       # on the new code
    python benchmarks/coupling_bit_for_bit.py --compare before.npz after.npz

The paths: the predictor-corrector (with and without an incident sea) and the explicit
scheme on the analytic fluid; SPH-cable lines sub-iterated with the bodies and held
explicitly; MoorDyn lines; a line that breaks and is released; the catenary FMU; the SPH
fluid's fluid-first scheme, and its sub-iterated light body. Run both files with numba's
cache warm (a first run that compiles the SPH cable's kernels has differed from later
runs by 1e-14)."""

import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
BOX, WAVES = ROOT / "examples" / "moored_box.toml", ROOT / "examples" / "moored_box_waves.toml"
CASES = {
    "pc": (BOX, ["world.duration=3.0"]),
    "explicit": (BOX, ["world.duration=3.0", "coupling.scheme=explicit"]),
    "pc_waves": (BOX, ["world.duration=3.0", 'waves={kind="linear", height=0.5, period=5.0, depth=50.0}']),
    "sph_cable": (BOX, ["world.duration=1.0", "moorings.model=sph-cable"]),
    "sph_cable_explicit_lines": (BOX, ["world.duration=1.0", "moorings.model=sph-cable", "coupling.lines=explicit"]),
    "moordyn": (BOX, ["world.duration=1.0", "moorings.model=moordyn"]),
    "breaking": (BOX, ["world.duration=3.0", "moorings.lines[1].break_load=500.0", "moorings.release_broken=true"]),
    "fmu": (BOX, ["world.duration=1.0", "moorings.model=fmu"]),
    "sph_fluid_first": (WAVES, ["world.duration=0.3", "fluid.dx=0.04"]),
    "sph_subiterate": (WAVES, ["world.duration=0.2", "fluid.dx=0.04", "bodies[0].density=100.0"]),
}


def record(out: str) -> None:
    from cosim.scene import Scene

    data = {}
    for name, (path, sets) in CASES.items():
        with tempfile.TemporaryDirectory() as d:
            res = Scene.from_toml(path).with_values(sets).run(Path(d) / "out", progress=False)
        data[f"{name}/t"] = res.t
        data.update({f"{name}/{k}": res[k] for k in res.names})
        print(f"{name}: {len(res.t)} samples of {len(res.names)} series", flush=True)
    np.savez(out, **data)


def compare(a_path: str, b_path: str) -> int:
    a, b = np.load(a_path), np.load(b_path)
    if sorted(a.files) != sorted(b.files):
        print("the files hold other series:", sorted(set(a.files) ^ set(b.files)))
        return 1
    differ = [k for k in a.files if not np.array_equal(a[k], b[k], equal_nan=True)]
    for k in differ:
        print(f"{k}: largest difference {np.nanmax(np.abs(a[k] - b[k])):.3g}")
    print(f"{len(a.files)} series, {len(differ)} differ")
    return 1 if differ else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["--compare"]:
        sys.exit(compare(*sys.argv[2:4]))
    record(sys.argv[1])
