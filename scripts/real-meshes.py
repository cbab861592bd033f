#!/usr/bin/python3
"""Every mesh in the given folders and their subfolders (OFF, OBJ, PLY and STL, the formats
read exactly), as a new user would try it: loaded with
exactgeo.load_mesh, classified against (exactgeo.Classifier with its default rule) at
uniform points of its box, or refused, and why. One row per mesh, then the counts by
outcome: closed, open (labelled by the generalized winding number), refused (the
reason's first words), does not load (the reader's message).

Usage:
  scripts/real-meshes.py [--points N] [--seed S] FOLDER...

Debian's libcgal-demo installs its meshes in /usr/share/doc/libcgal-demo/data.tar.gz
(data/meshes once unpacked); assimp-testmodels under /usr/share/assimp/models. Neither is
a build dependency. Needs numpy and the built module (build/python, found from this
script's folder)."""
import argparse
import collections
import os
import sys
import time
import warnings

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(HERE, "build", "python"))

import numpy as np  # noqa: E402

import exactgeo  # noqa: E402

SUFFIXES = (".off", ".obj", ".ply", ".stl")


def outcome(path, points, seed):
    """(kind, detail) for one mesh file."""
    try:
        mesh = exactgeo.load_mesh(path)
    except (OSError, ValueError) as e:
        return "does not load", str(e).split(": ", 1)[-1]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            classifier = exactgeo.Classifier(mesh)
        except ValueError as e:
            return "refused", str(e)
    vertices = np.asarray(mesh.vertices)
    rng = np.random.default_rng(seed)
    queries = rng.uniform(vertices.min(0), vertices.max(0), (points, 3))
    start = time.perf_counter()
    labels = classifier.classify(queries, threads=1)
    seconds = time.perf_counter() - start
    is_open = any("the surface is open" in str(w.message) for w in caught)
    undecided = int(np.count_nonzero(labels == exactgeo.UNDECIDED))
    inside = int(np.count_nonzero(labels == exactgeo.INSIDE))
    return ("open" if is_open else "closed",
            f"{len(np.asarray(mesh.faces))} faces, {inside} of {points} inside, "
            f"{undecided} undecided, {seconds:.3f} s on one thread")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--points", type=int, default=20000)
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()
    counts = collections.Counter()
    for folder in args.folders:
        paths = sorted(os.path.join(root, name) for root, _, names in os.walk(folder)
                       for name in names if name.lower().endswith(SUFFIXES))
        for path in paths:
            kind, detail = outcome(path, args.points, args.seed)
            counts[kind] += 1
            print(f"{os.path.relpath(path, folder)}: {kind}: {detail[:160]}")
    print(", ".join(f"{kind} {n}" for kind, n in counts.most_common()))


if __name__ == "__main__":
    main()
