#!/usr/bin/python3
"""CCD far from magnitude 1 (docs/ccd.md, "Every magnitude at the speed of magnitude 1"):
the bundled query files with every coordinate multiplied by 2^k, and a Spot mesh step at
2^k, against k = 0 in the same run. The answers must not change; the times should not
either.

Usage (from the repository root, after the README's first command):
  PYTHONPATH=build/python /usr/bin/python3 scripts/ccd-magnitudes.py [--mesh MESH]
      [--motion SIGMA] [--step-only K]

--step-only K runs just the mesh step at 2^K, for counting its instructions:
  valgrind --tool=callgrind --toggle-collect='exactgeo::ccd::*_ccd(*' /usr/bin/python3 \
      scripts/ccd-magnitudes.py --mesh tests/data/meshes/spot/spot_quad_cc1.ply --step-only 1000

MESH defaults to the Spot refinement cc3 of the shared data when present, else the
bundled cc1; it is split into triangles and moved by a seeded random motion. One thread."""
import argparse
import os
import time

import numpy as np

import exactgeo
from spot_points import default_spot

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(HERE, "tests", "data")
QUERY_FILES = ["ccd/scalable-ccd-data/cloth-funnel/queries/227vf.csv",
               "ccd/scalable-ccd-data/cloth-funnel/queries/227ee.csv",
               "ccd/sample-queries/erleben-cube-cliff-edges/edge-edge"]


def scaled(x, k):
    """x 2^k, checked to be exact (so the scaled queries are the same motions)."""
    y = x * 2.0**k
    assert np.array_equal(y / 2.0**k, x), "not exactly scalable"
    return y


def queries():
    print("| queries | 2^k | ns per query | answers as at 2^0 |")
    print("|---|---:|---:|---|")
    for name in QUERY_FILES:
        q = exactgeo.read_ccd_queries(os.path.join(DATA, name))
        run = exactgeo.vertex_face_ccd if q.type == "vertex-face" else exactgeo.edge_edge_ccd
        reference = None
        for k in (0, 900, -900):
            x0, x1 = scaled(q.x0, k), scaled(q.x1, k)
            start = time.perf_counter()
            hits = run(x0, x1, threads=1)
            ns = (time.perf_counter() - start) / len(hits) * 1e9
            reference = hits if reference is None else reference
            print(f"| {name.split('/')[-1]} | {k} | {ns:,.0f} | {np.array_equal(hits, reference)} |")


def mesh_step(path, sigma, exponents):
    mesh = exactgeo.load_mesh(path)
    quads = mesh.faces
    triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    x0 = mesh.vertices
    x1 = x0 + np.random.default_rng(1).normal(0, sigma, x0.shape)
    print(f"\n{os.path.basename(path)}: {len(triangles)} triangles, random motion, one step")
    print("| 2^k | candidates | vertex-face | edge-edge | broad phase s | narrow phase s |")
    print("|---:|---:|---:|---:|---:|---:|")
    for k in exponents:
        r = exactgeo.MeshCcd(triangles).step(scaled(x0, k), scaled(x1, k), threads=1)
        print(f"| {k} | {r.vertex_face_candidates + r.edge_edge_candidates} | "
              f"{len(r.vertex_face)} | {len(r.edge_edge)} | {r.broad_phase_seconds:.2f} | "
              f"{r.narrow_phase_seconds:.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mesh", default=default_spot())
    parser.add_argument("--motion", type=float, default=2e-3,
                        help="standard deviation of each coordinate's displacement")
    parser.add_argument("--step-only", type=int, metavar="K",
                        help="only the mesh step, at 2^K")
    args = parser.parse_args()
    if args.step_only is None:
        queries()
        mesh_step(args.mesh, args.motion, (0, 1000))
    else:
        mesh_step(args.mesh, args.motion, (args.step_only,))


if __name__ == "__main__":
    main()
