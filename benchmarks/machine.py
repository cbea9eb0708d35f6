"""What the benchmarks print about the machine they ran on (every figure names its CPU)."""

import platform


def cpu_name() -> str:
    """The CPU's model name as /proc/cpuinfo gives it (``platform.processor()`` elsewhere)."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


#: the vector instruction sets worth naming beside a speed figure, narrowest first
VECTOR_FLAGS = ("sse4_2", "avx", "avx2", "fma", "avx512f", "avx512dq", "avx512vl", "avx512bw", "avx512_fp16",
                "neon", "asimd", "sve")


def vector_extensions() -> list[str]:
    """The vector extensions of :data:`VECTOR_FLAGS` that /proc/cpuinfo lists for this CPU
    (empty elsewhere): ``avx512f`` means 8 float64 lanes per instruction, ``avx2`` 4."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith(("flags", "Features")):
                    have = set(line.split(":", 1)[1].split())
                    return [v for v in VECTOR_FLAGS if v in have]
    except OSError:
        pass
    return []
