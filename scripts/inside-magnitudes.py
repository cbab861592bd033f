#!/usr/bin/python3
"""Point classification far from magnitude 1 (docs/inside.md, "Far from magnitude 1:
classification time"): a mesh and uniform points in its box multiplied by 2^1000, 1e300
and 2^-1000, timed against the same mesh and points at magnitude 1 in the same run. The
labels must be those of the same doubles brought back near 1 by an exact power of two.

Usage (from the repository root, after the README's first command):
  PYTHONPATH=build/python /usr/bin/python3 scripts/inside-magnitudes.py
      [--points N] [--repeat R] [--no-space-cells] [MESH...]

MESH defaults to the Spot refinement cc3 of the shared data when present, else the
bundled cc1. Points: N uniform in the mesh's box (seed 7, default 200,000). Times are
the fastest of R rounds (default 5) over the scales in turn, one thread,
classification only."""
import argparse
import math
import os
import time

import numpy as np

import exactgeo
from spot_points import default_spot

SCALES = [("1", 1.0), ("2^1000", 2.0**1000), ("1e300", 1e300), ("2^-1000", 2.0**-1000)]


def exactly_scaled(x, factor):
    """x times a power of two, checked to be exact."""
    y = x * factor
    assert np.array_equal(y / factor, x), "not exactly scalable"
    return y


def measure(path, count, repeat, space_cells):
    mesh = exactgeo.load_mesh(path)
    vertices, faces = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    rng = np.random.default_rng(7)
    points = rng.uniform(vertices.min(axis=0), vertices.max(axis=0), (count, 3))
    scaled = [(vertices * scale, points * scale) for _, scale in SCALES]
    runs = [exactgeo.Classifier(exactgeo.Mesh(v, faces), space_cells=space_cells)
            for v, _ in scaled]
    # Rounds over the scales in turn, so that the machine's load falls on all of them alike.
    best, labels = [math.inf] * len(runs), [None] * len(runs)
    for _ in range(repeat):
        for i, (classifier, (_, p)) in enumerate(zip(runs, scaled)):
            start = time.perf_counter()
            labels[i] = classifier.classify(p, threads=1)
            best[i] = min(best[i], time.perf_counter() - start)
    for (name, scale), (v, p), seconds, got in zip(SCALES, scaled, best, labels):
        # The same doubles near magnitude 1, an exact power of two away.
        back = 2.0 ** -round(math.log2(scale))
        reference = exactgeo.Classifier(exactgeo.Mesh(exactly_scaled(v, back), faces),
                                        space_cells=space_cells)
        same = np.array_equal(got, reference.classify(exactly_scaled(p, back), threads=1))
        print(f"| {os.path.basename(path)} | {len(faces):,} | {name} | {seconds:.4f} | "
              f"{seconds / best[0]:.2f} | {same} |", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("meshes", nargs="*", metavar="MESH", default=[default_spot()])
    parser.add_argument("--points", type=int, default=200_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--no-space-cells", action="store_true")
    args = parser.parse_args()
    print(f"{args.points:,} uniform points, one thread, fastest of {args.repeat}"
          + (", no space cells" if args.no_space_cells else ""))
    print("| mesh | faces | scale | classify s | / at 1 | labels as near 1 |")
    print("|---|---:|---|---:|---:|---|")
    for path in args.meshes:
        measure(path, args.points, args.repeat, not args.no_space_cells)


if __name__ == "__main__":
    main()
