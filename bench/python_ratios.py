#!/usr/bin/env python3
"""The Python package's cost beside the same work in a C++ loop, measured in one process.

  PYTHONPATH=build/release/python /usr/bin/python3 bench/python_ratios.py [--smoke]

(scripts/bench runs it as the program `python`.) Two cases, each a same-run ratio, Python over
C++, median of 7 alternating repetitions with min and max:
  - 10^6 radial samples: disklab.ellipse_map("radial", ...).sample(u) against a C++ loop over
    the same u that stores the same columns (direction, point, pdf, valid) in arrays of its
    own (python/module.cpp, _bench.sample_loop); both allocate their output in the timing;
  - sequence("pmj02").points(10**6) against the concrete C++ generator (sequence::Pmj02) built
    with the same seed and capacity and read into a vector.
Targets (issue: a Python module for researchers): both ratios <= 1.3.
Google Benchmark flags (--benchmark_min_time=T below 0.01 means --smoke) are accepted.
"""
import statistics
import sys
import time

import numpy as np

import disklab
from disklab import _disklab

TARGET = 1.3


def main(argv):
    smoke = "--smoke" in argv or any(
        a.startswith("--benchmark_min_time=") and float(a.split("=")[1].rstrip("s")) < 0.01
        for a in argv)
    n, reps = (10_000, 3) if smoke else (1_000_000, 7)
    # bench_maps' near scene: a unit disk one radius away, seen off its axis.
    light = disklab.Disk((0, 0, 1), (0, 0, -1), 1.0)
    m = disklab.ellipse_map("radial", light, (0.3, 0.2, 0))
    u = disklab.sequence("sobol-owen", seed=1).points(n)
    rows, ratios = [], {}
    cases = {
        "radial_sample": (lambda: m.sample(u), lambda: _disklab._bench.sample_loop(m._m, u)[0]),
        "pmj02_points": (lambda: disklab.sequence("pmj02", seed=1).points(n),
                         lambda: _disklab._bench.pmj02_points(1, n)[0]),
    }
    for name, (py_call, cpp_call) in cases.items():
        py_t, cpp_t, r = [], [], []
        py_call(), cpp_call()  # warm: page in the code and the allocator
        for k in range(reps):
            # Alternate which side goes first, so neither always runs on a warmer cache.
            order = (0, 1) if k % 2 == 0 else (1, 0)
            t = [0.0, 0.0]
            for side in order:
                if side == 0:
                    start = time.perf_counter()
                    py_call()
                    t[0] = time.perf_counter() - start
                else:
                    t[1] = cpp_call()
            py_t.append(t[0])
            cpp_t.append(t[1])
            r.append(t[0] / t[1])
        ratios[name] = r
        for side, ts in (("python", py_t), ("cpp", cpp_t)):
            ms = statistics.median(ts) * 1e3
            rows.append(f"{side}/{name}/{n:<12} {ms:10.3f} ms {ms:10.3f} ms {reps:10d}")
    print(f"{'Benchmark':<40} {'Time':>13} {'CPU':>13} {'Iterations':>10}")
    for line in rows:
        print(line)
    print(f"Python / C++ (same-run ratios, median of {reps} [min, max]; target <= {TARGET}x):")
    for name, r in ratios.items():
        med = statistics.median(r)
        verdict = "met" if med <= TARGET else "MISSED"
        print(f"  {name:<14} {n} {med:.3f}x [{min(r):.3f}, {max(r):.3f}]  {verdict}"
              + ("  (smoke run: too short to measure)" if smoke else ""))


if __name__ == "__main__":
    main(sys.argv[1:])
