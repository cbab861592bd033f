#!/usr/bin/env python3
"""The point-in-volume benchmark (docs/inside.md): `exactgeo inside` with `exact` and
`double` on the Spot refinements, 1 and 2 threads, and CGAL's Side_of_triangle_mesh on the
same meshes split into triangles, all on the same points, in one run.

Usage:
  scripts/inside-bench.py run [--points N] [--seed S] [MESH...] > inside.jsonl
  scripts/inside-bench.py report inside.jsonl docs/inside-bench.svg > table.md

`run` needs build/bin/exactgeo; the CGAL anchor (build-bench/bin/cgal_inside_anchor, from
`cmake -S . -B build-bench -DEXACTGEO_BUILD_BENCHMARKS=ON` with libcgal-dev installed) is
used when present. Points: uniform in the mesh's bounding box grown by 5% per side,
printed as shortest round-trip decimals, seeded. Times come from the tools' own clocks
(classification only, loading and parsing excluded); memory is each process's peak
resident set (wait4). Standard library only."""
import json
import os
import random
import subprocess
import sys
import tempfile

from loglog_svg import loglog_svg

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXACTGEO = os.path.join(HERE, "build", "bin", "exactgeo")
ANCHOR = os.path.join(HERE, "build-bench", "bin", "cgal_inside_anchor")
SPOT = os.path.join(HERE, "..", "shared", "data", "meshes", "spot")
DEFAULT_MESHES = [os.path.join(SPOT, n) for n in (
    "spot_quadrangulated.obj", "spot_quad_cc1.ply", "spot_quad_cc2.ply",
    "spot_quad_cc3.ply", "spot_quad_cc4.ply")]


def run_measured(command):
    """Runs `command`, returns (stdout, peak RSS in MiB)."""
    with tempfile.TemporaryFile() as out:
        process = subprocess.Popen(command, stdout=out)
        _, status, usage = os.wait4(process.pid, 0)
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit(f"failed: {' '.join(command)}")
        out.seek(0)
        return out.read().decode(), usage.ru_maxrss / 1024.0


def run(args):
    count, seed, meshes = 1_000_000, 1, []
    while args:
        a = args.pop(0)
        if a == "--points":
            count = int(args.pop(0))
        elif a == "--seed":
            seed = int(args.pop(0))
        else:
            meshes.append(a)
    for mesh in meshes or DEFAULT_MESHES:
        info = json.loads(subprocess.run([EXACTGEO, "info", "--json", mesh], check=True,
                                         capture_output=True, text=True).stdout)
        lower, upper = info["bounding_box"]["lower"], info["bounding_box"]["upper"]
        rng = random.Random(seed)
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
            points = f.name
            for _ in range(count):
                f.write(" ".join(repr(lo - 0.05 * (hi - lo) + rng.random() * 1.1 * (hi - lo))
                                 for lo, hi in zip(lower, upper)) + "\n")
        base = {"mesh": os.path.basename(mesh), "faces": info["faces"], "points": count}
        for threads in (1, 2):
            for method in ("double", "exact"):
                out, rss = run_measured([EXACTGEO, "inside", "--json", "--method", method,
                                         "--threads", str(threads), mesh, points])
                r = json.loads(out)
                print(json.dumps({**base, "tool": "exactgeo", "method": method,
                                  "threads": threads, "build_seconds": r["build_seconds"],
                                  "seconds": r["seconds"], "inside": r["inside"],
                                  "boundary": r["boundary"], "peak_mib": round(rss, 1)}),
                      flush=True)
        if os.path.exists(ANCHOR):
            out, rss = run_measured([ANCHOR, mesh, points])
            r = json.loads(out)
            print(json.dumps({**base, "tool": "cgal", "method": "Side_of_triangle_mesh",
                              "threads": 1, "build_seconds": r["build_seconds"],
                              "seconds": r["seconds"], "inside": r["inside"],
                              "boundary": r["boundary"], "peak_mib": round(rss, 1)}),
                  flush=True)
        os.unlink(points)


def report(jsonl, svg_path):
    rows = [json.loads(line) for line in open(jsonl) if line.strip()]
    print("| mesh | faces | tool / method | threads | build s | Mpoints/s | time / exact's | inside | peak MiB |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|")
    # CGAL runs on one thread: compare it with exact on one thread.
    exact_time = {(r["mesh"], r["threads"]): r["seconds"] for r in rows
                  if r["tool"] == "exactgeo" and r["method"] == "exact"}
    for r in rows:
        rate = r["points"] / r["seconds"] / 1e6
        ratio = r["seconds"] / exact_time.get((r["mesh"], r["threads"]), float("nan"))
        print(f"| {r['mesh']} | {r['faces']:,} | {r['tool']} {r['method']} | {r['threads']} | "
              f"{r['build_seconds']:.3f} | {rate:.2f} | {ratio:.2f} | {r['inside']:,} | "
              f"{r['peak_mib']:.0f} |")

    # The plot: Mpoints/s against faces (both log scale), one line per tool/method/threads.
    series = {}
    for r in rows:
        series.setdefault(f"{r['tool']} {r['method']} ({r['threads']} thr)", []).append(
            (r["faces"], r["points"] / r["seconds"] / 1e6))
    with open(svg_path, "w") as f:
        f.write(loglog_svg(series, "faces", "million points per second"))

if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "run":
        run(sys.argv[2:])
    elif len(sys.argv) == 4 and sys.argv[1] == "report":
        report(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
