#!/usr/bin/python3
"""The point-in-volume benchmark (docs/inside.md): `exactgeo inside` with `exact` (space
cells on and off), `double` and the float ray baseline `embree`, on the Spot refinements,
1 and 2 threads, on uniform points and on points near the surface, and CGAL's
Side_of_triangle_mesh on the same meshes split into triangles (uniform points, one
thread), all in one run.

Usage:
  PYTHONPATH=build/python /usr/bin/python3 scripts/inside-bench.py run \\
      [--points N] [--seed S] [MESH...] > inside.jsonl
  /usr/bin/python3 scripts/inside-bench.py report inside.jsonl docs/inside-bench.svg > table.md

`run` needs build/bin/exactgeo and the exactgeo Python module (to read the meshes for the
near-surface points) with numpy. The CGAL anchor (cgal_inside_anchor, built when Debian's
libcgal-dev is installed and benchmarks are on) is used when present in build/bin or
build-bench/bin.

Points (seeded):
  uniform  uniform in the mesh's bounding box grown by 5% per side;
  near     a uniform random face, a uniform point of it (bilinear for quads, barycentric
           for triangles), moved by a random vector of length below 1e-3 of the box's
           largest extent: every point within that distance of the surface.
Times come from the tools' own clocks (classification only, loading and parsing
excluded); build is checking the mesh and building the search structures; memory is
each process's peak resident set (/usr/bin/time, when installed). Every method's labels are compared with
`exact`'s: the count of differing labels is reported."""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(HERE, "scripts"))
EXACTGEO = os.path.join(HERE, "build", "bin", "exactgeo")
ANCHORS = [os.path.join(HERE, d, "bin", "cgal_inside_anchor") for d in ("build", "build-bench")]
SPOT = os.path.join(HERE, "..", "shared", "data", "meshes", "spot")
DEFAULT_MESHES = [os.path.join(SPOT, n) for n in (
    "spot_quadrangulated.obj", "spot_quad_cc1.ply", "spot_quad_cc2.ply",
    "spot_quad_cc3.ply", "spot_quad_cc4.ply")]
NEAR = 1e-3

# (label in the report, exactgeo inside options)
METHODS = [("exact", ["--method", "exact"]),
           ("exact, no cells", ["--method", "exact", "--no-space-cells"]),
           ("double", ["--method", "double"]),
           ("embree", ["--method", "embree"])]


def run_measured(command):
    """Runs `command`, returns (stdout, peak RSS in MiB, or None without /usr/bin/time).

    The peak comes from /usr/bin/time (Debian package `time`), which forks the command
    from its own small process: a process forked from this one would inherit this
    interpreter's peak (Linux keeps the high-water mark across exec)."""
    timed = os.path.exists("/usr/bin/time")
    with tempfile.TemporaryFile() as out, tempfile.NamedTemporaryFile("r") as peak:
        prefix = ["/usr/bin/time", "-f", "%M", "-o", peak.name] if timed else []
        if subprocess.run(prefix + command, stdout=out).returncode != 0:
            sys.exit(f"failed: {' '.join(command)}")
        out.seek(0)
        kib = peak.read().split()[-1] if timed else None
        return out.read().decode(), int(kib) / 1024.0 if kib else None


def uniform_points(vertices, count, rng):
    import numpy as np
    lower, upper = vertices.min(axis=0), vertices.max(axis=0)
    grow = 0.05 * (upper - lower)
    return rng.uniform(lower - grow, upper + grow, (count, 3))


def near_points(vertices, faces, count, rng):
    """Points within NEAR * (largest extent) of a uniform point of a uniform face."""
    import numpy as np
    extent = float((vertices.max(axis=0) - vertices.min(axis=0)).max())
    chosen = faces[rng.integers(0, len(faces), count)]
    u, v = rng.random(count), rng.random(count)
    c = [vertices[chosen[:, k].clip(min=0)] for k in range(4)]
    quad = (((1 - u) * (1 - v))[:, None] * c[0] + (u * (1 - v))[:, None] * c[1]
            + (u * v)[:, None] * c[2] + ((1 - u) * v)[:, None] * c[3])
    # Triangles (fourth index -1): fold (u, v) into the triangle, barycentric.
    fold = u + v > 1
    s, t = np.where(fold, 1 - u, u), np.where(fold, 1 - v, v)
    triangle = c[0] + s[:, None] * (c[1] - c[0]) + t[:, None] * (c[2] - c[0])
    on_face = np.where((chosen[:, 3] < 0)[:, None], triangle, quad)
    direction = rng.normal(size=(count, 3))
    direction /= np.linalg.norm(direction, axis=1)[:, None]
    radius = NEAR * extent * rng.random(count)
    return on_face + radius[:, None] * direction


def run(args):
    import numpy as np
    import exactgeo
    count, seed, meshes = 1_000_000, 1, []
    while args:
        a = args.pop(0)
        if a == "--points":
            count = int(args.pop(0))
        elif a == "--seed":
            seed = int(args.pop(0))
        else:
            meshes.append(a)
    anchor = next((a for a in ANCHORS if os.path.exists(a)), None)
    for mesh_path in meshes or DEFAULT_MESHES:
        mesh = exactgeo.load_mesh(mesh_path)
        vertices = np.asarray(mesh.vertices)
        faces = np.asarray(mesh.faces).astype(np.int64)
        for kind in ("uniform", "near"):
            rng = np.random.default_rng(seed)
            points = (uniform_points(vertices, count, rng) if kind == "uniform"
                      else near_points(vertices, faces, count, rng))
            with tempfile.TemporaryDirectory() as tmp:
                npy = os.path.join(tmp, "points.npy")
                np.save(npy, points)
                base = {"mesh": os.path.basename(mesh_path), "faces": len(faces),
                        "points": count, "kind": kind}
                exact_labels = None
                for threads in (1, 2):
                    for name, options in METHODS:
                        out, rss = run_measured([EXACTGEO, "inside", "--json", "--labels",
                                                 "--threads", str(threads), *options,
                                                 mesh_path, npy])
                        r = json.loads(out)
                        labels = r.pop("labels")
                        if exact_labels is None:
                            exact_labels = labels  # the first method is exact
                        differ = sum(a != b for a, b in zip(labels, exact_labels))
                        print(json.dumps({**base, "tool": "exactgeo", "method": name,
                                          "threads": threads,
                                          "build_seconds": r["build_seconds"],
                                          "seconds": r["seconds"], "inside": r["inside"],
                                          "boundary": r["boundary"], "differ": differ,
                                          "space_cells": r.get("space_cells"),
                                          "peak_mib": rss and round(rss, 1)}), flush=True)
                if anchor and kind == "uniform":
                    text = os.path.join(tmp, "points.txt")
                    np.savetxt(text, points, fmt="%.17g")
                    cgal_labels = os.path.join(tmp, "cgal.txt")
                    out, rss = run_measured([anchor, mesh_path, text, cgal_labels])
                    r = json.loads(out)
                    labels = open(cgal_labels).read().split()
                    differ = sum(a != b for a, b in zip(labels, exact_labels))
                    print(json.dumps({**base, "tool": "cgal", "method": "Side_of_triangle_mesh",
                                      "threads": 1, "build_seconds": r["build_seconds"],
                                      "seconds": r["seconds"], "inside": r["inside"],
                                      "boundary": r["boundary"], "differ": differ,
                                      "peak_mib": rss and round(rss, 1)}), flush=True)


def name_of(r):
    return r["method"] if r["tool"] == "exactgeo" else f"cgal {r['method']}"


def report(jsonl, svg_path):
    from loglog_svg import loglog_svg
    rows = [json.loads(line) for line in open(jsonl) if line.strip()]
    print("| mesh | faces | points | method | threads | build s | Mpoints/s | time / embree's "
          "| labels differing from exact | peak MiB |")
    print("|---|---:|---|---|---:|---:|---:|---:|---:|---:|")
    embree_time = {(r["mesh"], r["kind"], r["threads"]): r["seconds"] for r in rows
                   if r["method"] == "embree"}
    for r in rows:
        rate = r["points"] / r["seconds"] / 1e6
        ratio = r["seconds"] / embree_time.get((r["mesh"], r["kind"], r["threads"]), float("nan"))
        print(f"| {r['mesh']} | {r['faces']:,} | {r['kind']} | {name_of(r)} | {r['threads']} | "
              f"{r['build_seconds']:.3f} | {rate:.2f} | {ratio:.2f} | {r['differ']:,} | "
              f"{'-' if r['peak_mib'] is None else round(r['peak_mib'])} |")
    # Ratios against the targets, one thread.
    print()
    print("| mesh | faces | uniform: exact / embree time | uniform: CGAL / exact time "
          "| near: exact / double time | near: cells on / off time |")
    print("|---|---:|---:|---:|---:|---:|")
    one = {(r["mesh"], r["kind"], name_of(r)): r for r in rows if r["threads"] == 1}
    for mesh in dict.fromkeys(r["mesh"] for r in rows):
        def t(kind, method):
            r = one.get((mesh, kind, method))
            return r["seconds"] if r else float("nan")
        faces = next(r["faces"] for r in rows if r["mesh"] == mesh)
        print(f"| {mesh} | {faces:,} | {t('uniform', 'exact') / t('uniform', 'embree'):.2f} | "
              f"{t('uniform', 'cgal Side_of_triangle_mesh') / t('uniform', 'exact'):.2f} | "
              f"{t('near', 'exact') / t('near', 'double'):.2f} | "
              f"{t('near', 'exact') / t('near', 'exact, no cells'):.2f} |")

    # The plot: Mpoints/s against faces, one thread, one line per method and point set.
    series = {}
    for r in rows:
        if r["threads"] != 1:
            continue
        series.setdefault(f"{name_of(r)}, {r['kind']}", []).append(
            (r["faces"], r["points"] / r["seconds"] / 1e6))
    with open(svg_path, "w") as f:
        f.write(loglog_svg(series, "faces (log scale)", "million points per second (log scale)",
                           "Point-in-volume throughput, one thread (one run)"))


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "run":
        run(sys.argv[2:])
    elif len(sys.argv) == 4 and sys.argv[1] == "report":
        report(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
