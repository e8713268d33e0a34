#!/usr/bin/env python3
"""The overhead of the Python call: ssfx.aa on a 1920x1080 image against the C++ call on
the same image in the same run (ssfx bench: median of interleaved repetitions, the output
allocated once). Python: median of as many calls, into a preallocated `out` and allocating.
Usage: PYTHONPATH=build/release/python scripts/bench_python.py [SSFX] [METHOD...]
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import ssfx

cli = sys.argv[1] if len(sys.argv) > 1 else "build/release/ssfx"
methods = sys.argv[2:] or ["ddaa2", "fxaa3c", "blur"]
reps = 40
with tempfile.TemporaryDirectory() as d:
    subprocess.run([cli, "testscene", "--out", d, "--width", "1920", "--height", "1080"], check=True,
                   capture_output=True)
    path = os.path.join(d, "scene.png")
    img = ssfx.io.read_png(path)
    for m in methods:
        r = subprocess.run([cli, "bench", "--image", path, "--methods", m, "--reps", str(reps), "--json", "-"],
                           check=True, capture_output=True, text=True)
        cpp = json.loads(r.stdout)["methods"][m]["median_ms"]
        out = ssfx.aa(img, m)
        into, alloc = [], []
        for _ in range(3):
            ssfx.aa(img, m, out=out)
        for _ in range(reps):
            t = time.perf_counter()
            ssfx.aa(img, m, out=out)
            into.append((time.perf_counter() - t) * 1e3)
            t = time.perf_counter()
            ssfx.aa(img, m)
            alloc.append((time.perf_counter() - t) * 1e3)
        a, b = statistics.median(into), statistics.median(alloc)
        print(f"{m}: C++ {cpp:.3f} ms, Python into out {a:.3f} ms ({(a / cpp - 1) * 100:+.1f} %), "
              f"allocating {b:.3f} ms ({(b / cpp - 1) * 100:+.1f} %)")
