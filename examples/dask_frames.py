#!/usr/bin/env python3
"""A frame sequence anti-aliased on a Dask distributed cluster: each frame is an independent
task (read the PNG, ssfx.aa, write the PNG) on whichever worker is free, so scaling out to
more machines is Dask's business, not ssfx's. Locally: a cluster of worker processes.

    PYTHONPATH=build/release/python python3 examples/dask_frames.py in/ out/ --method ddaa2 --workers 2
    # or on a running cluster: --scheduler tcp://host:8786 (every worker needs ssfx importable)
"""
import argparse
import os
import time


def process(src, dst, method, params):
    """One frame on a worker: one thread each (the workers are the parallelism)."""
    import ssfx  # imported on the worker

    ssfx.io.write_png(dst, ssfx.aa(ssfx.io.read_png(src), method, threads=1, **params))
    return dst


def run(in_dir, out_dir, method="ddaa2", workers=2, scheduler=None, params=None):
    from dask.distributed import Client, LocalCluster

    names = sorted(n for n in os.listdir(in_dir) if n.lower().endswith(".png"))
    if not names:
        raise SystemExit(f"{in_dir}: no PNG files")
    os.makedirs(out_dir, exist_ok=True)
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
    with Client(scheduler or cluster) as client:
        t = time.perf_counter()
        futures = client.map(process, [os.path.join(in_dir, n) for n in names],
                             [os.path.join(out_dir, n) for n in names], method=method, params=params or {})
        done = client.gather(futures)  # an error on a worker is raised here, naming the frame's file
        seconds = time.perf_counter() - t
    if cluster is not None:
        cluster.close()
    return done, seconds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("input", help="folder of PNG frames")
    ap.add_argument("output", help="folder for the anti-aliased frames (same names)")
    ap.add_argument("--method", default="ddaa2")
    ap.add_argument("--workers", type=int, default=2, help="local worker processes (without --scheduler)")
    ap.add_argument("--scheduler", help="address of a running Dask scheduler")
    args = ap.parse_args()
    done, seconds = run(args.input, args.output, args.method, args.workers, args.scheduler)
    print(f"{len(done)} frames in {seconds:.2f} s ({len(done) / seconds:.1f} frames/s)")


if __name__ == "__main__":
    main()
