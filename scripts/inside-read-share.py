#!/usr/bin/python3
"""How much of an `exactgeo inside` run is reading the points (docs/inside.md): the same
points as .npy, raw f64 and text, 1 and 2 threads, and read_seconds as a share of
read_seconds + build_seconds + seconds (the command's own clocks), with each run's wall
time and peak resident set.

Usage:
  scripts/inside-read-share.py [--points N] [--seed S] [--exactgeo PATH] [--keep DIR] [MESH]

Defaults: 10,000,000 points uniform in the mesh's bounding box grown by 5% per side
(seed 1), build/bin/exactgeo, tests/data/meshes/spot/spot_quad_cc1.ply. The files go to a
temporary directory (or DIR with --keep). Needs numpy (Debian's python3-numpy), in a
child process: peak memory comes from wait4, and a child's peak includes what its parent
held when it forked, so this process stays small."""
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


GENERATE = """
import json, sys
import numpy as np
count, seed, box, npy, f64, text = sys.argv[1:]
lower, upper = (np.array(b) for b in json.loads(box))
grow = 0.05 * (upper - lower)
points = np.random.default_rng(int(seed)).uniform(lower - grow, upper + grow, (int(count), 3))
np.save(npy, points)
points.tofile(f64)
np.savetxt(text, points, fmt="%.17g")
"""


def run_measured(command):
    """Runs `command`; returns (its JSON output, wall seconds, peak RSS in MiB)."""
    start = time.monotonic()
    with tempfile.TemporaryFile() as out:
        process = subprocess.Popen(command, stdout=out)
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.monotonic() - start
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit(f"failed: {' '.join(command)}")
        out.seek(0)
        return json.loads(out.read()), wall, usage.ru_maxrss / 1024.0


def main(args):
    count, seed, keep = 10_000_000, 1, None
    exactgeo = os.path.join(HERE, "build", "bin", "exactgeo")
    mesh = os.path.join(HERE, "tests", "data", "meshes", "spot", "spot_quad_cc1.ply")
    while args:
        a = args.pop(0)
        if a == "--points":
            count = int(args.pop(0))
        elif a == "--seed":
            seed = int(args.pop(0))
        elif a == "--exactgeo":
            exactgeo = args.pop(0)
        elif a == "--keep":
            keep = args.pop(0)
        else:
            mesh = a
    info = json.loads(subprocess.run([exactgeo, "info", "--json", mesh], check=True,
                                     capture_output=True, text=True).stdout)
    directory = keep or tempfile.mkdtemp(prefix="exactgeo-read-share-")
    os.makedirs(directory, exist_ok=True)
    files = {
        "npy": os.path.join(directory, "points.npy"),
        "f64": os.path.join(directory, "points.f64"),
        "text": os.path.join(directory, "points.txt"),
    }
    box = json.dumps([info["bounding_box"]["lower"], info["bounding_box"]["upper"]])
    subprocess.run([sys.executable, "-c", GENERATE, str(count), str(seed), box, files["npy"],
                    files["f64"], files["text"]], check=True)

    print(f"{count:,} points, {os.path.basename(mesh)}, seed {seed}\n")
    print("| format | threads | read s | build s | classify s | read share | wall s | peak MiB |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, path in files.items():
        for threads in (1, 2):
            command = [exactgeo, "inside", "--json", "--threads", str(threads),
                       "--points-format", name, mesh, path]
            report, wall, peak = run_measured(command)
            assert report["points"] == count, report
            read, build, classify = (report["read_seconds"], report["build_seconds"],
                                     report["seconds"])
            share = read / (read + build + classify)
            print(f"| {name} | {threads} | {read:.3f} | {build:.3f} | {classify:.3f} | "
                  f"{100 * share:.1f}% | {wall:.2f} | {peak:.0f} |")
    own_peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"\n(this script's own peak: {own_peak:.0f} MiB, a floor under every peak above)")
    if not keep:
        for path in files.values():
            os.remove(path)
        os.rmdir(directory)


if __name__ == "__main__":
    main(sys.argv[1:])
