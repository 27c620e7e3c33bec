#!/usr/bin/env python3
# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Benchmark of point_set_curvatures.dask.estimate_curvatures_file (issue 13).

Writes a Fibonacci sphere of N points (x y z nx ny nz, float64 .npy; in index order, which is
spatially coherent like a scan, or shuffled with --shuffle), runs it on a LocalCluster of
--workers worker processes of one thread each, then the single-process
point_set_curvatures.estimate_curvatures (all cores) in a child process, and prints:
wall times, peak resident memory of every worker process and of the single process, the
per-tile costs (read, compute, write; and the scheduling overhead: the time the worker slots
spent outside tile tasks during the tile phase, per tile), and whether the results are
bitwise equal.

    PYTHONPATH=build/python python3 python/benchmarks/dask_benchmark.py --points 2000000
"""

import argparse
import multiprocessing
import os
import resource
import statistics
import sys
import tempfile
import time

import numpy as np


def write_sphere(path, n, shuffle, chunk=1 << 20):
    """A unit Fibonacci sphere of n points with outward normals, written chunk by chunk."""
    out = np.lib.format.open_memmap(path, mode="w+", dtype=np.float64, shape=(n, 6))
    order = np.random.default_rng(1).permutation(n) if shuffle else None
    for start in range(0, n, chunk):
        i = (np.arange(start, min(n, start + chunk)) if order is None else order[start:start + chunk]) + 0.5
        phi = np.arccos(1 - 2 * i / n)
        theta = np.pi * (1 + 5**0.5) * i
        nrm = np.stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)], axis=1)
        out[start:start + len(i), :3] = nrm
        out[start:start + len(i), 3:] = nrm
    out.flush()
    del out


def single_process(input_path, radius, dask_output, queue):
    """In a child process (own peak memory): the whole-cloud run, compared with the Dask output."""
    import point_set_curvatures as psc
    import point_set_curvatures.dask as psc_dask

    data = np.load(input_path)
    points, normals = np.ascontiguousarray(data[:, :3]), np.ascontiguousarray(data[:, 3:])
    del data
    t = time.perf_counter()
    r = psc.estimate_curvatures(points, normals, radius=radius)
    seconds = time.perf_counter() - t
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    same = None
    if dask_output:
        d = psc_dask.read_result(dask_output)
        same = all(np.array_equal(np.ascontiguousarray(d[k]).view(np.uint8), r[k].view(np.uint8)) for k in r)
    queue.put((seconds, peak, same))


def _worker_memory():
    import resource as res

    try:
        import psutil

        rss = psutil.Process().memory_info().rss
    except ImportError:
        rss = 0
    return os.getpid(), res.getrusage(res.RUSAGE_SELF).ru_maxrss * 1024, rss


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--points", type=int, default=20_000_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--tile-size", type=float, default=None, help="tile side (default: the module's)")
    ap.add_argument("--shuffle", action="store_true", help="random input order (no block pruning)")
    ap.add_argument("--dir", default=None, help="directory of the input and output files (default: a temporary one)")
    ap.add_argument("--no-single", action="store_true", help="skip the single-process run")
    args = ap.parse_args()

    import distributed
    import point_set_curvatures.dask as psc_dask

    n = args.points
    radius = 3.6 * np.sqrt(4 * np.pi / n)  # about 41 neighbours
    tmp = tempfile.TemporaryDirectory(dir=args.dir)
    input_path = os.path.join(tmp.name, "cloud.npy")
    output_path = os.path.join(tmp.name, "curvatures.npy")
    t = time.perf_counter()
    write_sphere(input_path, n, args.shuffle)
    print(f"points {n}, radius {radius:.6g}, order {'shuffled' if args.shuffle else 'scan-like'}, "
          f"input {os.path.getsize(input_path) / 1e6:.0f} MB written in {time.perf_counter() - t:.1f} s")

    cluster = distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                       dashboard_address=None, silence_logs=40)
    client = distributed.Client(cluster)
    client.run(lambda: __import__("point_set_curvatures.dask"))  # imports not timed
    t = time.perf_counter()
    report = psc_dask.estimate_curvatures_file(client, input_path, output_path, radius=radius,
                                               tile_size=args.tile_size)
    wall = time.perf_counter() - t
    memory = client.run(_worker_memory)
    tiles = report["tile_reports"]
    sec = report["seconds"]
    nthreads = sum(client.nthreads().values())
    task = [tr["stop"] - tr["start"] for tr in tiles]
    overhead = (sec["tiles"] * nthreads - sum(task)) / len(tiles)
    halo_points = sum(tr["halo_points"] for tr in tiles)
    print(f"dask: {args.workers} workers x 1 thread, {report['tiles']} tiles (grid {report['grid_counts']}, "
          f"side {report['tile_side']:.4g}), wall {wall:.2f} s: scan {sec['scan']:.2f}, count {sec['count']:.2f}, "
          f"tiles {sec['tiles']:.2f}")
    print(f"  halo overhead: {halo_points / report['finite_points'] - 1:.2%} more points read than owned (halo) "
          f"({halo_points} read for {report['finite_points']} own)")
    print(f"  per tile (mean): task {statistics.mean(task):.3f} s = read {statistics.mean(tr['read_seconds'] for tr in tiles):.3f}"
          f" + compute {statistics.mean(tr['compute_seconds'] for tr in tiles):.3f}"
          f" + write {statistics.mean(tr['write_seconds'] for tr in tiles):.3f};"
          f" task minus compute {statistics.mean(tr['stop'] - tr['start'] - tr['compute_seconds'] for tr in tiles):.3f} s;"
          f" scheduling gap {overhead:.3f} s")
    for addr, (pid, peak, rss) in sorted(memory.items()):
        print(f"  worker {pid}: peak RSS {peak / 1e6:.0f} MB (now {rss / 1e6:.0f} MB)")
    client.close()
    cluster.close()

    if not args.no_single:
        ctx = multiprocessing.get_context("spawn")
        queue = ctx.Queue()
        p = ctx.Process(target=single_process, args=(input_path, radius, output_path, queue))
        p.start()
        seconds, peak, same = queue.get()
        p.join()
        print(f"single process (estimate_curvatures, {os.cpu_count()} threads): {seconds:.2f} s compute "
              f"(arrays loaded beforehand), peak RSS {peak / 1e6:.0f} MB; bitwise equal to dask: {same}")
    tmp.cleanup()


if __name__ == "__main__":
    sys.exit(main())
