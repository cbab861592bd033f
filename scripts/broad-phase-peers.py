#!/usr/bin/python3
"""The mesh CCD broad phase against the broad phases people use (CGAL box_intersection_d,
FCL's DynamicAABBTreeCollisionManager, Bullet's btDbvtBroadphase, Embree's rtcCollide), on
the same float boxes, each peer's candidate pairs checked equal to exactgeo's
(bench/broad_phase_peers.cpp says what each time includes). Scenes: the Spot meshes under
random motion (cc0 to cc4) and the cloth example's last predicted step (10k, 100k, 1M
triangles); the step after is the first step's t1 moved on by a new random motion. One
thread for every peer, two for exactgeo and Embree (CGAL, FCL and Bullet are
single-threaded). A peer whose time on one scene (one-shot or step after), grown by the
family's step in size (4x for Spot, 10x for the cloth), would pass a minute is skipped on
the larger scenes of that family, and the output says so.

Usage:
  scripts/broad-phase-peers.py run [--quick] [--motion A] [--seed S] [--repeat R] > peers.jsonl
  scripts/broad-phase-peers.py report peers.jsonl docs/broad-phase-peers.svg > table.md

`run` needs broad_phase_peers ($BROAD_PHASE_PEERS, or bin/ of build-peers/, build-bench/
or build/, inside the checkout or next to it), configured with
-DEXACTGEO_BUILD_BENCHMARKS=ON (`cmake --build DIR --target broad_phase_peers`), and
build/bin/exactgeo-cloth for the cloth scenes. --quick: Spot cc0 and cc1 and the 10k cloth
only. `report` prints a markdown table (times, ratio peer / exactgeo at the same thread
count, whether the pairs are the same) and writes a log-log plot of the one-thread times
against triangles, one panel per family. Standard library only."""
import importlib.util
import json
import os
import re
import subprocess
import sys
import tempfile

from loglog_svg import loglog_svg

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# $BROAD_PHASE_PEERS, else the first build found (inside the checkout or next to it).
BENCH = os.environ.get("BROAD_PHASE_PEERS") or next(
    (p for p in (os.path.join(root, d, "bin", "broad_phase_peers")
                 for root in (HERE, os.path.dirname(HERE))
                 for d in ("build-peers", "build-bench", "build")) if os.path.exists(p)),
    os.path.join(HERE, "build-peers", "bin", "broad_phase_peers"))

# The Spot meshes and the cloth example's frames, as scripts/ccd-mesh-bench.py makes them.
_spec = importlib.util.spec_from_file_location(
    "ccd_mesh_bench", os.path.join(HERE, "scripts", "ccd-mesh-bench.py"))
ccd_mesh_bench = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ccd_mesh_bench)
SPOT = ccd_mesh_bench.SPOT
SPOT_MESHES = ccd_mesh_bench.SPOT_MESHES
cloth_frames = ccd_mesh_bench.cloth_frames

CLOTH_RESOLUTIONS = [72, 225, 708]  # 10k, 100k, 1M triangles
PEERS = ["exactgeo", "cgal", "fcl", "bullet", "embree"]
MULTI_THREADED = ["exactgeo", "embree"]
THREADS = [1, 2]
SLOW_SECONDS = 60


def bench(frames, scene, threads, peers, extra):
    args = [BENCH, *frames, "--scene", scene, "--threads", str(threads),
            "--peers", ",".join(peers), *extra]
    out = subprocess.run(args, check=True, stdout=subprocess.PIPE, text=True).stdout
    rows = [json.loads(line) for line in out.splitlines() if line.strip()]
    for row in rows:
        print(json.dumps(row), flush=True)
    return rows


def measure_family(scene, frame_sets, growth, extra):
    """frame_sets: callables giving each scene's frame files, smallest scene first, each
    about `growth` times the triangles of the one before."""
    slow = {}  # peer -> where it took over SLOW_SECONDS
    for frames_of in frame_sets:
        newly_slow = {}
        with tempfile.TemporaryDirectory() as directory:
            frames = frames_of(directory)
            for threads in THREADS:
                peers = [p for p in PEERS if threads == 1 or p in MULTI_THREADED]
                rows = bench(frames, scene, threads, [p for p in peers if p not in slow], extra)
                triangles = rows[0]["triangles"]
                for p in (p for p in peers if p in slow):
                    print(json.dumps({"scene": scene, "triangles": triangles, "peer": p,
                                      "threads": threads, "skipped": slow[p]}), flush=True)
                for r in rows:
                    worst = max(r["one_shot_ms"], r["step_after_ms"]) / 1e3
                    if worst * growth > SLOW_SECONDS and r["peer"] != "exactgeo":
                        newly_slow.setdefault(r["peer"],
                                              f"{worst:.1f} s at {triangles:,} triangles")
        slow.update((p, why) for p, why in newly_slow.items() if p not in slow)


def run(args):
    motion, seed, quick, repeat = "0.2", "1", False, None
    while args:
        a = args.pop(0)
        if a == "--motion":
            motion = args.pop(0)
        elif a == "--seed":
            seed = args.pop(0)
        elif a == "--repeat":
            repeat = args.pop(0)
        elif a == "--quick":
            quick = True
        else:
            sys.exit(f"unknown argument {a}")
    extra = ["--motion", motion, "--seed", seed] + (["--repeat", repeat] if repeat else [])
    spot = SPOT_MESHES[:2] if quick else SPOT_MESHES
    cloth = CLOTH_RESOLUTIONS[:1] if quick else CLOTH_RESOLUTIONS
    measure_family("spot", [lambda _, n=n: [os.path.join(SPOT, n)] for n in spot], 4, extra)
    measure_family("cloth", [lambda d, r=r: cloth_frames(r, d) for r in cloth], 10, extra)


def ratio(value, reference):
    return f"{value / reference:.2f}" if reference else "-"


def report(jsonl, svg_path):
    rows = [json.loads(line) for line in open(jsonl) if line.strip()]
    reference = {(r["scene"], r["triangles"], r["threads"]): r
                 for r in rows if r["peer"] == "exactgeo"}
    print("| scene | triangles | peer | threads | one-shot ms | step-after ms | "
          "one-shot / exactgeo | step-after / exactgeo | same |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---|")
    for r in rows:
        head = f"| {r['scene']} | {r['triangles']:,} | {r['peer']} | {r['threads']} |"
        if "skipped" in r:
            print(f"{head} skipped | skipped | - | - | - (predicted over {SLOW_SECONDS} s: {r['skipped']}) |")
            continue
        e = reference[(r["scene"], r["triangles"], r["threads"])]
        print(f"{head} {r['one_shot_ms']:.1f} | {r['step_after_ms']:.1f} | "
              f"{ratio(r['one_shot_ms'], e['one_shot_ms'])} | "
              f"{ratio(r['step_after_ms'], e['step_after_ms'])} | "
              f"{'yes' if r['same'] else 'NO'} |")

    panels = []
    for scene in dict.fromkeys(r["scene"] for r in rows):
        series = {}
        for r in rows:
            if r["scene"] != scene or r["threads"] != 1 or "skipped" in r:
                continue
            series.setdefault(f"{r['peer']}, one-shot", []).append(
                (r["triangles"], r["one_shot_ms"]))
            series.setdefault(f"{r['peer']}, step after", []).append(
                (r["triangles"], r["step_after_ms"]))
        title = f"Broad phase, {TITLES.get(scene, scene)}, 1 thread"
        panels.append(loglog_svg(series, "triangles", "milliseconds", title=title))
    with open(svg_path, "w") as f:
        f.write(stacked(panels))


TITLES = {"spot": "Spot under random motion", "cloth": "cloth example steps"}


def stacked(svgs):
    """Standalone SVG texts placed one below the other in one SVG."""
    sizes = [tuple(int(v) for v in re.search(r'width="(\d+)" height="(\d+)"', s).groups())
             for s in svgs]
    width, height = max(w for w, _ in sizes), sum(h for _, h in sizes)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}">',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    y = 0
    for s, (_, h) in zip(svgs, sizes):
        out.append(s.replace("<svg ", f'<svg x="0" y="{y}" ', 1).strip())
        y += h
    out.append("</svg>")
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "run":
        run(sys.argv[2:])
    elif len(sys.argv) == 4 and sys.argv[1] == "report":
        report(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
