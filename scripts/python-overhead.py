#!/usr/bin/python3
"""What the Python binding costs: the same points classified against the same mesh by
exactgeo.Classifier.classify (points already in a NumPy array) and by the C++ library
inside `exactgeo inside` (its own clock: classification only, reading excluded), in one
run, interleaved, fastest of --repeat passes each, for 1 and 2 threads.

Usage (from the repository root, after the README's first command):
  PYTHONPATH=build/python scripts/python-overhead.py [--points N] [--repeat R] [--seed S] [MESH]

MESH defaults to the Spot refinement cc3 of the shared data when present, else the bundled
cc1. Points: uniform in the mesh's box grown by 5% per side. Prints a Markdown table."""
import argparse
import json
import os
import subprocess
import tempfile
import time

import numpy as np

import exactgeo
from spot_points import box_points, default_spot

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = os.path.join(HERE, "build", "bin", "exactgeo")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh", nargs="?", default=default_spot())
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    mesh = exactgeo.load_mesh(args.mesh)
    points = box_points(mesh, args.points, np.random.default_rng(args.seed))
    classifier = exactgeo.Classifier(mesh)

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "points.npy")
        np.save(path, points)
        fastest = {}
        for _ in range(args.repeat):
            for threads in (1, 2):
                start = time.perf_counter()
                labels = classifier.classify(points, threads=threads)
                python = time.perf_counter() - start
                done = subprocess.run([CLI, "inside", args.mesh, path, "--json", "--threads",
                                       str(threads)], capture_output=True, text=True, check=True)
                report = json.loads(done.stdout)
                counts = np.bincount(labels, minlength=3)
                assert [report["outside"], report["inside"], report["boundary"]] == \
                    counts.tolist(), "the binding and the command line disagree"
                for key, seconds in (("python", python), ("c++", report["seconds"])):
                    fastest[key, threads] = min(fastest.get((key, threads), seconds), seconds)

    print(f"mesh: {os.path.basename(args.mesh)} ({mesh.face_count} faces), "
          f"{args.points} points, fastest of {args.repeat}")
    print("| threads | C++ library (s) | Python binding (s) | binding / library |")
    print("|---:|---:|---:|---:|")
    for threads in (1, 2):
        cpp, python = fastest["c++", threads], fastest["python", threads]
        print(f"| {threads} | {cpp:.3f} | {python:.3f} | {python / cpp:.3f} |")


if __name__ == "__main__":
    main()
