#!/usr/bin/env python3
"""The mesh-level CCD benchmark (docs/ccd.md): step time, time per broad-phase candidate,
candidates per collision and thread scaling, on the Spot meshes under random motion and on
the steps of the cloth example, with `exact` and `parity`, 1 and 2 threads, in one run.

Usage:
  scripts/ccd-mesh-bench.py run [--motion A] [--seed S] > ccd-mesh.jsonl
  scripts/ccd-mesh-bench.py report ccd-mesh.jsonl docs/ccd-mesh-bench.svg > table.md

`run` needs ccd_mesh_bench in build-bench/bin (`cmake -S . -B build-bench
-DEXACTGEO_BUILD_BENCHMARKS=ON && cmake --build build-bench --target ccd_mesh_bench`) or
build/bin, and build/bin/exactgeo-cloth. Spot: every vertex moves by up to A mean edge lengths per
coordinate (uniform, seeded); the quads are split into two triangles. Cloth: the example
writes the predicted step (before collision filtering) of its last step at each
resolution, which ccd_mesh_bench then times. Times are the tools' own clocks (the best of
3 runs; loading excluded). Each row also times the broad phase alone on a following step
against the previous broad phase (bench/baseline/), in the same process, and says whether
both found the same candidates. Standard library only."""
import json
import os
import subprocess
import sys
import tempfile

from loglog_svg import loglog_svg

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# build-bench/ as the docs build it, or build/ when that was configured with benchmarks.
BENCH = next((p for p in (os.path.join(HERE, d, "bin", "ccd_mesh_bench") for d in ("build-bench", "build"))
              if os.path.exists(p)), os.path.join(HERE, "build-bench", "bin", "ccd_mesh_bench"))
CLOTH = os.path.join(HERE, "build", "bin", "exactgeo-cloth")
SPOT = os.path.join(HERE, "..", "shared", "data", "meshes", "spot")
SPOT_MESHES = ["spot_quadrangulated.obj", "spot_quad_cc1.ply", "spot_quad_cc2.ply",
               "spot_quad_cc3.ply", "spot_quad_cc4.ply"]
# Cloth resolutions n (n x n vertices, 2 (n - 1)^2 triangles): about 1k, 10k, 100k, 1M.
CLOTH_RESOLUTIONS = [23, 72, 225, 708]
COMPARE_UP_TO_TRIANGLES = 400_000  # sweep and prune beyond this takes minutes


def bench(args, scene):
    out = subprocess.run([BENCH, *args], check=True, capture_output=True, text=True).stdout
    row = json.loads(out)
    row["scene"] = scene
    print(json.dumps(row), flush=True)
    return row


def measure(frames, scene, extra):
    first = None
    for method in ("exact", "parity"):
        for threads in (1, 2):
            args = [*frames, "--method", method, "--threads", str(threads), *extra]
            row = bench(args, scene)
            first = first or row
    if first["triangles"] <= COMPARE_UP_TO_TRIANGLES:
        bench([*frames, "--threads", "1", "--repeat", "1", "--compare", *extra], scene + " compare")


def cloth_frames(resolution, directory):
    """Runs the cloth example and returns its last predicted step (t0, t1)."""
    steps = 12  # the sheet reaches the post after about 8 steps
    subprocess.run([CLOTH, "--resolution", str(resolution), "--steps", str(steps), "--every",
                    str(steps), "--queries", directory, "--output", directory, "--json"],
                   check=True, capture_output=True)
    names = sorted(n for n in os.listdir(directory) if n.endswith("_t0.obj"))
    last = names[-1]
    return [os.path.join(directory, last), os.path.join(directory, last.replace("_t0", "_t1"))]


def run(args):
    motion, seed = "0.2", "1"
    while args:
        a = args.pop(0)
        if a == "--motion":
            motion = args.pop(0)
        elif a == "--seed":
            seed = args.pop(0)
        else:
            sys.exit(f"unknown argument {a}")
    for name in SPOT_MESHES:
        measure([os.path.join(SPOT, name)], "spot", ["--motion", motion, "--seed", seed])
    for resolution in CLOTH_RESOLUTIONS:
        with tempfile.TemporaryDirectory() as directory:
            measure(cloth_frames(resolution, directory), "cloth", [])


def report(jsonl, svg_path):
    rows = [json.loads(line) for line in open(jsonl) if line.strip()]
    runs = [r for r in rows if not r["scene"].endswith("compare")]
    print("| scene | triangles | method | threads | step ms | broad ms | narrow ms | "
          "ns / candidate | candidates | collisions | candidates / collision |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in runs:
        step = r["broad_phase_seconds"] + r["narrow_phase_seconds"]
        collisions = r["vertex_face"] + r["edge_edge"]
        candidates = r["vertex_face_candidates"] + r["edge_edge_candidates"]
        print(f"| {r['scene']} | {r['triangles']:,} | {r['method']} | {r['threads']} | "
              f"{1e3 * step:.1f} | {1e3 * r['broad_phase_seconds']:.1f} | "
              f"{1e3 * r['narrow_phase_seconds']:.1f} | {r['ns_per_candidate']:.0f} | "
              f"{candidates:,} | {collisions:,} | {r['candidates_per_collision']:.1f} |")
    print()
    print("| scene | triangles | threads | candidates | baseline broad ms | broad ms | speedup | "
          "same candidates | rebuilt |")
    print("|---|---:|---:|---:|---:|---:|---:|---|---|")
    for r in runs:
        if r["method"] != "exact":
            continue
        print(f"| {r['scene']} | {r['triangles']:,} | {r['threads']} | "
              f"{r['next_step_candidates']:,} | "
              f"{1e3 * r['next_step_baseline_broad_phase_seconds']:.1f} | "
              f"{1e3 * r['next_step_broad_phase_seconds']:.1f} | {r['broad_phase_speedup']:.2f} | "
              f"{'yes' if r['same_candidates_as_baseline'] else 'NO'} | "
              f"{'yes' if r['next_step_rebuilt'] else 'no'} |")
    print()
    print("| scene | triangles | box overlaps | all pairs ms | sweep and prune ms | tree ms |")
    print("|---|---:|---:|---:|---:|---:|")
    for r in rows:
        if not r["scene"].endswith("compare"):
            continue
        brute = f"{1e3 * r['all_pairs_seconds']:.1f}" if "all_pairs_seconds" in r else "-"
        print(f"| {r['scene'].split()[0]} | {r['triangles']:,} | {r['tree_overlaps']:,} | {brute} | "
              f"{1e3 * r['sweep_and_prune_seconds']:.1f} | {1e3 * r['tree_seconds']:.1f} |")

    series = {}
    for r in runs:
        name = f"{r['scene']} {r['method']} ({r['threads']} thr)"
        step = r["broad_phase_seconds"] + r["narrow_phase_seconds"]
        series.setdefault(name, []).append((r["triangles"], 1e3 * step))
    with open(svg_path, "w") as f:
        f.write(loglog_svg(series, "triangles", "milliseconds per step"))


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "run":
        run(sys.argv[2:])
    elif len(sys.argv) == 4 and sys.argv[1] == "report":
        report(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
