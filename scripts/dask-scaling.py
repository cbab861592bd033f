#!/usr/bin/python3
"""How exactgeo.dask scales: 20M points stored as chunked .npy files, classified by the
library in one process (loading each chunk, then Classifier.classify on one thread) and
by exactgeo.dask on a local cluster of 1 and 2 worker processes (one thread each), in one
run. Also measures what the engine costs per task (many small chunks against few large
ones) and per worker (the mesh load and classifier build on first use).

Usage (from the repository root, after the README's first command):
  PYTHONPATH=build/python scripts/dask-scaling.py [--points N] [--chunk C] [MESH]

MESH defaults to the Spot refinement cc3 of the shared data when present, else the bundled
cc1. Prints a Markdown table and the per-task and per-worker costs."""
import argparse
import os
import tempfile
import time

import dask
import dask.array as da
import numpy as np
from distributed import Client, LocalCluster

import exactgeo
import exactgeo.dask
from spot_points import box_points, default_spot



def write_chunks(folder, mesh, count, chunk, seed):
    """count points uniform in the mesh's box grown by 5%, as .npy files of `chunk` rows."""
    rng = np.random.default_rng(seed)
    os.makedirs(folder)
    files = []
    for start in range(0, count, chunk):
        rows = min(chunk, count - start)
        files.append(os.path.join(folder, f"points-{start // chunk:05d}.npy"))
        np.save(files[-1], box_points(mesh, rows, rng))
    return files


def lazy_points(files):
    """The chunk files as one dask array, each chunk read by the worker that classifies it."""
    shapes = [np.load(f, mmap_mode="r").shape for f in files]
    parts = [da.from_delayed(dask.delayed(np.load)(f), shape=s, dtype=np.float64)
             for f, s in zip(files, shapes)]
    return da.concatenate(parts)


def single_process(mesh_path, files):
    start = time.perf_counter()
    classifier = exactgeo.Classifier(exactgeo.load_mesh(mesh_path))
    build = time.perf_counter() - start
    start = time.perf_counter()
    labels = np.concatenate([classifier.classify(np.load(f), threads=1) for f in files])
    return labels, build, time.perf_counter() - start


def timed_compute(mesh_path, files):
    start = time.perf_counter()
    labels = exactgeo.dask.classify(mesh_path, lazy_points(files)).compute()
    return labels, time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", nargs="?", default=default_spot())
    parser.add_argument("--points", type=int, default=20_000_000)
    parser.add_argument("--chunk", type=int, default=1_000_000)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    mesh = exactgeo.load_mesh(args.mesh)
    with tempfile.TemporaryDirectory() as tmp:
        files = write_chunks(os.path.join(tmp, "big"), mesh, args.points, args.chunk, args.seed)
        small_count = min(args.points, 2_000_000)
        few = write_chunks(os.path.join(tmp, "few"), mesh, small_count, small_count // 2, 2)
        many = write_chunks(os.path.join(tmp, "many"), mesh, small_count, 4_000, 2)

        reference, build, alone = single_process(args.mesh, files)
        rows = [("library, one process", 1, alone, None)]
        costs = {}
        for workers in (1, 2):
            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                              host="127.0.0.1", dashboard_address=None) as cluster, \
                    Client(cluster):
                labels, cold = timed_compute(args.mesh, files)  # includes each worker's build
                assert np.array_equal(labels, reference), "dask and the library disagree"
                labels, warm = timed_compute(args.mesh, files)
                assert np.array_equal(labels, reference)
                rows.append((f"dask, {workers} worker{'s' if workers > 1 else ''} (first run)",
                             workers, cold, None))
                rows.append((f"dask, {workers} worker{'s' if workers > 1 else ''}", workers, warm,
                             None))
                if workers == 2:
                    _, few_seconds = timed_compute(args.mesh, few)
                    _, many_seconds = timed_compute(args.mesh, many)
                    costs["task"] = (many_seconds - few_seconds) * workers / (len(many) - len(few))
                    costs["cold"] = cold - warm

    rate = args.points / alone
    print(f"mesh: {os.path.basename(args.mesh)} ({mesh.face_count} faces); {args.points} points "
          f"in {len(files)} .npy chunks of {args.chunk}; classifier build {build:.2f} s")
    print("| run | workers | seconds | points/s | per worker vs one process |")
    print("|---|---:|---:|---:|---:|")
    for name, workers, seconds, _ in rows:
        per_worker = args.points / seconds / workers
        print(f"| {name} | {workers} | {seconds:.2f} | {args.points / seconds:,.0f} | "
              f"{per_worker / rate:.2f} |")
    print(f"\nengine cost per task (2 workers, {len(many)} chunks of 4,000 against {len(few)} "
          f"of {small_count // 2:,}): {costs['task'] * 1e3:.2f} ms of worker time")
    print(f"first run's extra time (mesh load and build on each worker): {costs['cold']:.2f} s")


if __name__ == "__main__":
    main()
