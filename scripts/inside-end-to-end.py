#!/usr/bin/python3
"""End to end, as a user times it: `exactgeo inside MESH POINTS.npy --threads 1` as one
command (reading the mesh, building, the checks that run by default, reading the points,
classifying, writing the labels) beside libigl's fast winding number doing the same with
the same file (igl::read_triangle_mesh, its tree, |w| >= 1/2; bench/libigl/), on closed
meshes, at several point counts. Prints a markdown row per mesh and count: each tool's
whole-command seconds (the fastest of three runs) and points per second, their ratio, and
the points on which the labels differ.

Usage:
  scripts/inside-end-to-end.py --libigl DIR [--points 1000,25000,1000000] [--seed S] [--open]
                               [--exactgeo BINARY] [--before BINARY] MESH...

MESH is a file or a folder (its OFF, OBJ, PLY and STL files, recursively); meshes that
exactgeo refuses are listed as such, and open meshes too unless --open asks for them
(then only they are timed; exactgeo labels them by the generalized winding number,
certified, which the fast winding number approximates). Points are uniform in the
mesh's box grown by 5% on each side. DIR is a libigl checkout (its include/ folder); the
anchor is built with Debian's g++ and Eigen in a temporary folder. Needs numpy, the built
module (build/python) and the command line (build/bin/exactgeo), found from this
script's folder, or the command line from --exactgeo. --before times a second exactgeo
binary (an older build) in the same rounds, alternating with the first and the fast
winding number, and adds its seconds and the speed-up of the first over it. The totals
line ends with the geometric mean of the per-mesh ratios and the meshes at 2x or more."""
import argparse
import math
import os
import struct
import subprocess
import sys
import tempfile
import time
import warnings

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(HERE, "build", "python"))

import numpy as np  # noqa: E402

import exactgeo  # noqa: E402

EXACTGEO = os.path.join(HERE, "build", "bin", "exactgeo")
EXTENSIONS = (".off", ".obj", ".ply", ".stl")
REPEATS = 3


def mesh_files(paths):
    for path in paths:
        if os.path.isdir(path):
            for root, _, names in sorted(os.walk(path)):
                for name in sorted(names):
                    if name.lower().endswith(EXTENSIONS):
                        yield os.path.join(root, name)
        else:
            yield path


def fastest(commands, env=None):
    """Each command's wall time, the fastest of REPEATS runs, the commands run in turn in
    each round (so that a slow spell of a shared machine hits all of them), and each one's
    last output."""
    best, out = [float("inf")] * len(commands), [None] * len(commands)
    for _ in range(REPEATS):
        for i, command in enumerate(commands):
            start = time.perf_counter()
            out[i] = subprocess.run(command, capture_output=True, check=True, env=env)
            best[i] = min(best[i], time.perf_counter() - start)
    return best, out


def build_anchor(libigl, folder):
    program = os.path.join(folder, "fast_winding_anchor")
    subprocess.run(["g++", "-O3", "-DNDEBUG", "-std=c++17", "-Wno-deprecated-declarations",
                    "-I", os.path.join(libigl, "include"), "-I", "/usr/include/eigen3",
                    os.path.join(HERE, "bench", "libigl", "fast_winding_anchor.cpp"), "-o",
                    program, "-lpthread"], check=True)
    return program


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--libigl", required=True)
    parser.add_argument("--points", default="1000,25000,1000000")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--open", action="store_true", help="time the open meshes instead")
    parser.add_argument("--exactgeo", default=EXACTGEO, help="the command line to time")
    parser.add_argument("--before", help="another exactgeo binary, timed in the same rounds")
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    counts = [int(n) for n in args.points.split(",")]
    rng = np.random.default_rng(args.seed)
    before_columns = " before s | speed-up over before |" if args.before else ""
    print("| mesh | faces | points | exactgeo s (Mpts/s) | fast WN s (Mpts/s) "
          "| exactgeo / fast WN speed | labels differ |" + before_columns)
    print("|---|---|---|---|---|---|---|" + ("---|---|" if args.before else ""))
    totals = {n: [0.0, 0.0, 0.0] for n in counts}
    ratios = {n: [] for n in counts}
    speedups = {n: [] for n in counts}
    with tempfile.TemporaryDirectory() as folder:
        anchor = build_anchor(args.libigl, folder)
        env = {**os.environ, "IGL_NUM_THREADS": "1"}
        for path in mesh_files(args.meshes):
            name = os.path.relpath(path)
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    mesh = exactgeo.load_mesh(path)
                    exactgeo.Classifier(mesh)  # refused or not
            except (ValueError, OSError) as e:
                print(f"| {name} | | | not classified: {str(e)[:60]} | | | |")
                continue
            if mesh.info()["closed"] == args.open:
                kind = "closed" if args.open else "open"
                print(f"| {name} | {len(np.asarray(mesh.faces))} | | {kind}: not timed | | | |")
                continue
            v = np.asarray(mesh.vertices)
            lower, upper = v.min(0), v.max(0)
            grow = 0.05 * (upper - lower)
            for n in counts:
                points = rng.uniform(lower - grow, upper + grow, (n, 3))
                npy = os.path.join(folder, "points.npy")
                np.save(npy, points)
                binary = os.path.join(folder, "points.bin")
                with open(binary, "wb") as f:
                    f.write(struct.pack("<q", n))
                    f.write(np.ascontiguousarray(points, "<f8").tobytes())
                answers = os.path.join(folder, "w.bin")
                ours_command = [args.exactgeo, "inside", path, npy, "--threads", "1"]
                commands = [ours_command, [anchor, path, binary, answers]]
                if args.before:
                    commands.append([args.before] + ours_command[1:])
                try:
                    seconds, outs = fastest(commands, env)
                except subprocess.CalledProcessError as e:
                    print(f"| {name} | {len(np.asarray(mesh.faces))} | {n} | failed: "
                          f"{os.path.basename(e.cmd[0])} ({e.returncode}) | | | |", flush=True)
                    continue
                ours, theirs = seconds[0], seconds[1]
                inside = np.array(outs[0].stdout.split()) == b"inside"
                w = np.fromfile(answers, "<f8")
                differ = int(np.count_nonzero(inside != (np.abs(w) >= 0.5)))
                totals[n][0] += ours
                totals[n][1] += theirs
                ratios[n].append(theirs / ours)
                row = (f"| {name} | {len(np.asarray(mesh.faces))} | {n} | {ours:.3f} "
                       f"({n / ours / 1e6:.2f}) | {theirs:.3f} ({n / theirs / 1e6:.2f}) "
                       f"| {theirs / ours:.2f} | {differ} |")
                if args.before:
                    same = outs[2].stdout == outs[0].stdout
                    totals[n][2] += seconds[2]
                    speedups[n].append(seconds[2] / ours)
                    row += (f" {seconds[2]:.3f} | {seconds[2] / ours:.2f}"
                            f"{'' if same else ' (labels differ)'} |")
                print(row, flush=True)
    for n, (ours, theirs, before) in totals.items():
        if ours > 0:
            mean = math.exp(sum(math.log(r) for r in ratios[n]) / len(ratios[n]))
            twice = sum(r >= 2 for r in ratios[n])
            row = (f"| all timed meshes ({len(ratios[n])}) | | {n} each | {ours:.2f} "
                   f"| {theirs:.2f} | {theirs / ours:.2f} (geometric mean {mean:.2f}; "
                   f"{twice} at 2x or more) | |")
            if args.before:
                up = math.exp(sum(math.log(r) for r in speedups[n]) / len(speedups[n]))
                row += f" {before:.2f} | {before / ours:.2f} (geometric mean {up:.2f}) |"
            print(row)


if __name__ == "__main__":
    main()
