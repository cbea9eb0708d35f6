#!/bin/bash
# Issue 20's GPU measurements in one call of the device tool, for a session lent a GPU (the
# device image has numba, numba-cuda, numpy, scipy, pytest and hypothesis; nothing else this
# needs). From the repository root:
#
#     run(command="bash benchmarks/gpu_session.sh", timeout_s=560)
#
# At most 9 minutes (the parts' timeouts add up to 540 s; about 3 when all goes well), each
# part under its own timeout so that one failure leaves the others' figures; everything goes
# to $OUT/gpu_session.log. In order:
#   1. the machine: GPU, driver, CPU, numba and numba-cuda versions;
#   2. tests/test_fluid_cuda.py's long tier on the GPU (COSIM_CUDA_TESTS=gpu): the GPU path
#      against the CPU path to round-off, as CI checks it on the simulator (the relaxation
#      zones towards linear, Stokes-2 and irregular seas, the free surface's readings, the
#      walls' accelerations, nearfield-waves' scene), and no whole-state transfer in a
#      step; the scenes with bodies need MuJoCo, which the image lacks: deselected (carry
#      its wheel to run them); eight workers, one a test, each compiling both paths;
#   3. benchmarks/fluid_throughput.py --device cuda: the 3-D dam break of the CPU figures
#      (107 012 particles, 200 steps), then 3-D and 2-D at about 1 and 4 M particles (16 M
#      measured in session 51: the rate flat from 1 M up);
#   4. benchmarks/cuda_step_profile.py: each kernel's share of a 3-D step at ~2.6 M;
#   5. the CPU path on the same machine (all its cores): the 3-D dam break and ~1 M.
# Read the log for particle_steps_per_s and bytes_per_particle of each size; the history
# (docs/benchmarks/fluid_throughput_history.md, "The GPU path") has the figures so far.
# The image's NumPy (2.5) lacks np.row_stack, which its numba-cuda registers on import: a
# sitecustomize puts the alias back for this script's processes.
set -u
export PYTHONPATH=$PWD PYTHONUNBUFFERED=1 NUMBA_CUDA_LOW_OCCUPANCY_WARNINGS=0
OUTDIR=${OUT:-/tmp}
exec > >(tee "$OUTDIR/gpu_session.log") 2>&1
part() { echo "=== $1 ($(date -u +%T))"; }
PY=python3
mkdir -p /tmp/shim && printf 'import numpy as _np\nif not hasattr(_np, "row_stack"):\n    _np.row_stack = _np.vstack\n' > /tmp/shim/sitecustomize.py
export PYTHONPATH=/tmp/shim:$PYTHONPATH
TP=benchmarks/fluid_throughput.py

part "machine"
nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.max.sm --format=csv,noheader
lscpu | grep -E "Model name|^CPU\(s\)"
$PY -c "import numba, numba_cuda; print('numba', numba.__version__, 'numba-cuda', numba_cuda.__version__)"

part "the GPU path against the CPU path, on the GPU"
COSIM_CUDA_TESTS=gpu timeout 260 $PY -m pytest -q -m long -n 8 -p no:cacheprovider -p no:benchmark \
    tests/test_fluid_cuda.py -k "not moves_its_body" 2>&1 | tail -25

part "GPU: the 3-D dam break of the CPU figures"
timeout 60 $PY $TP --device cuda --case 3d --dp 0.017 --steps 200

# particles ~ 107 012 (0.017 / dp)^3 in 3-D, 22 008 (0.01 / dp)^2 in 2-D
part "GPU: 3-D scaling, ~1 and 4 M particles"
timeout 80 $PY $TP --device cuda --case 3d --dp 0.008 --dp 0.00505 --steps 50
part "GPU: 2-D scaling, ~1 and 4 M particles"
timeout 60 $PY $TP --device cuda --case 2d --dp 0.00148 --dp 0.00074 --steps 50
part "GPU: where a 3-D step's time goes (~2.6 M particles)"
timeout 40 $PY benchmarks/cuda_step_profile.py --case 3d --dp 0.00505 --steps 20

part "CPU path, same machine, all cores"
timeout 40 $PY $TP --device cpu --case 3d --dp 0.017 --dp 0.008 --steps 10
part "done"
