"""Compile every kernel of the GPU path (fluid.cuda.kernels) to PTX without a GPU: numba's
typing and lowering and NVVM's code generation, everything but running them. Not a test:
it needs NVVM and NVRTC, which the CUDA toolkit or two wheels provide (no driver, no GPU)::

    pip install --target /tmp/nv "nvidia-nvvm==13.*" "nvidia-cuda-nvrtc==13.*"
    LD_LIBRARY_PATH=/tmp/nv/nvidia/cu13/lib python benchmarks/cuda_compile_check.py --cc 9.0

Prints each kernel's PTX size and, for the pair loop's variants, its double-precision
divisions and fused multiply-adds; exits with the number of kernels that failed.
Every kernel compiles; the measured divisions per variant: docs/benchmarks/cuda_compile_check.md.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import types as _types

# run as a script, this file's folder comes first on sys.path and would shadow ``fluid``
_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _here]

import numba.cuda.dispatcher as _dispatcher  # noqa: E402
from numba import cuda  # noqa: E402
from numba import types as T  # noqa: E402

from fluid.cuda import kernels as K  # noqa: E402

def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cc", default="9.0", help="compute capability to compile for (9.0: H100, H200)")
    cc = tuple(int(v) for v in ap.parse_args().cc.split("."))
    f8, i4, i8, i1, b1 = T.float64, T.int32, T.int64, T.int8, T.boolean
    A = lambda dt, nd: T.Array(dt, nd, "C")  # noqa: E731
    f8_2, f8_1, i4_1, i1_1, i8_1 = A(f8, 2), A(f8, 1), A(i4, 1), A(i1, 1), A(i8, 1)
    # device functions are compiled for the current device's compute capability: there is none here
    _dispatcher.get_current_device = lambda: _types.SimpleNamespace(compute_capability=cc)
    sigs = {
     "k_bin": (f8_2, i8, f8_1, f8, i8, i8, i8, i4_1, i4_1),
     "k_scan_chunks": (i4_1, i8, i4_1),
     "k_scan_add": (i4_1, i8, i4_1),
     "k_copy_i4": (i4_1, i8, i4_1),
     "k_fill": (i4_1, i8, i4_1, i4_1),
     "k_order": (i4_1, i4_1, f8_2, i8),
     "k_gather2": (f8_2, f8_2, i4_1, i8),
     "k_gather1": (f8_1, f8_1, i4_1, i8),
     "k_slots": (i4_1, i8, i4_1),
     "k_place": (i4_1, i4_1, f8_2, f8_2, f8_2, f8_2),
     "k_pack": (f8_1, i8, f8, f8, f8, f8_1, f8_1),
     "k_predictor": (f8_2, f8_2, f8_1, f8_1, f8_2, i1_1, i8, f8, f8, f8_2, f8_2, f8_1, f8_2, b1),
     "k_corrector": (f8_2, f8_2, f8_1, f8_1, f8_2, i1_1, i8, f8, f8, f8_2, f8_2, f8_1, f8_2, b1),
     "k_verlet": (f8_2, f8_2, f8_1, f8_1, f8_2, i1_1, i8, f8, f8, f8_2, f8_1, b1, f8_2, b1),
     "k_damp": (f8_2, f8_2, i1_1, i8, f8),
     "k_first_non_finite": (f8_2, f8_2, f8_1, i8, i8_1),
     "k_group_sums": (f8_2, f8_1, f8_2, i4_1, i8, f8_2, f8_2, f8_2),
     "k_zero_i4": (i4_1, i8), "k_zero_f8": (f8_1, i8), "k_zero2": (f8_2, i8), "k_read_i4": (i4_1, i8, i8_1),
     "k_set_i8": (i8_1, i8),
     "k_zero_all": (f8_2,),
     "k_adami": (f8_2, f8_1, i1_1, f8_2, b1, i8, i4_1, f8_1, f8, i8, i8, i8, i8, f8, f8, f8, f8, f8, f8_1, i8, i8, f8),
     "k_place_one": (i4_1, i4_1, f8_2, f8_2),
     "k_mls": (f8_2, f8_1, f8_1, i1_1, i8, i4_1, f8_1, f8, i8, i8, i8, i8, f8, f8, f8, f8_1),
     "k_mls_apply": (f8_1, f8_1, f8_1, b1, i8),
     "k_mdbc": (f8_2, f8_1, f8_1, i1_1, i4_1, f8_2, i8, i8, i4_1, f8_1, f8, i8, i8, i8, i8, f8, f8, f8, f8),
     "k_relax": (f8_2, f8_2, f8_2, b1, i1_1, i8, i8, f8, f8, f8, f8, b1, f8, f8, f8, f8, f8, f8_1, f8_1, f8_1, f8_1,
                 f8_1, f8_1, f8, b1, f8, f8, f8, A(b1, 1), f8, f8, f8, f8, b1, T.UniTuple(f8, 9)),
     "k_surface": (f8_2, f8_2, i1_1, f8_1, f8_1, i4_1, f8_1, f8, i8, i8, i8, i8, i8, f8, f8, f8, f8_1),
    }
    bad = 0
    for name, sig in sigs.items():
        t = time.time()
        try:
            ptx, _ = cuda.compile_ptx(getattr(K, name).py_func, sig, cc=cc)
            print(f"ok  {name:22s} {len(ptx):7d} chars {time.time()-t:.1f}s")
        except Exception as e:
            bad += 1
            print(f"ERR {name}: {type(e).__name__}: {str(e)[:800]}")
    grad_sig = (f8_2, f8_1, f8_1, i1_1, f8_1, i8, i4_1, f8_1, f8, i8, i8, i8, f8_1, f8_2)
    for key in [(0, False), (1, True)]:
        try:
            ptx, _ = cuda.compile_ptx(K.make_gradient_loop(*key).py_func, grad_sig, cc=cc)
            print(f"ok  gradient_loop{key} {len(ptx)} chars")
        except Exception as e:
            bad += 1
            print(f"ERR gradient_loop{key}: {type(e).__name__}: {str(e)[:1500]}")
    pair_sig = (f8_2, f8_2, f8_1, f8_1, i1_1, f8_1, f8_1, i8, i4_1, f8_1, f8, i8, i8, i8, f8_1, f8_1, f8_2, f8_2, f8_1,
                f8_2)
    for key in [(0, False, False, False, False, False, False), (1, False, True, True, True, True, False),
                (0, True, False, True, False, False, True), (1, True, True, False, True, True, False)]:
        t = time.time()
        loop = K.make_pair_loop(*key)
        try:
            ptx, _ = cuda.compile_ptx(loop.py_func, pair_sig, cc=cc)
            fma, div = ptx.count("fma.rn.f64"), ptx.count("div.rn.f64")
            print(f"ok  pair_loop{key} {len(ptx)} chars, fma {fma}, div {div}, {time.time()-t:.1f}s")
        except Exception as e:
            bad += 1
            print(f"ERR pair_loop{key}: {type(e).__name__}: {str(e)[:1500]}")
    return bad


if __name__ == "__main__":
    sys.exit(main())
