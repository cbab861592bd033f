#!/usr/bin/python3
"""Meshes with known truth that real files look like (parts that overlap, shells nested
both ways, repeated shells, internal faces, a closed sphere with a small hole, Spot with
closed shells pushed into it), labelled by exactgeo and by the tools people use instead:
VTK's vtkSelectEnclosedPoints (Debian's python3-vtk9), libigl's fast winding number and
its Antipodal method (built from a libigl checkout outside this repository, by the
programs in bench/libigl/). Wrong labels and points per second (one thread) per family
and tool (the fastest of three runs); docs/inside.md has the table.

Usage:
  scripts/inside-peers.py [--points N] [--seed S] [--libigl DIR]

DIR is a libigl checkout (its include/ folder is what is used); the script builds
bench/libigl/antipodal_anchor.cpp (igl::WindingNumberAntipodalScene, its rays counted by
float Embree 3) and fast_winding_anchor.cpp (igl::fast_winding_number) against it with
g++, Eigen and Embree 3 from Debian, in a temporary folder. Without DIR, or without VTK,
those columns are left out. The truth: a point is inside the
union of the closed parts it lies in (w != 0); points within 1e-6 of a face plane are
dropped, so no tool is asked about a point whose truth a double cannot carry. Needs numpy
and the built module (build/python, found from this script's folder)."""
import argparse
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

MARGIN = 1e-6
REPEATS = 3

# ---- Shapes: (vertices, triangles) counter-clockwise seen from outside -------------------


def box(lower, upper):
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    v = np.array([[(upper if c & m else lower)[i] for i, m in enumerate((1, 2, 4))]
                  for c in range(8)])
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    t = [[q[0], q[1], q[2]] for q in quads] + [[q[0], q[2], q[3]] for q in quads]
    return v, np.array(t)


def sphere(centre, radius, level=3):
    v = [np.array(p, float) for p in ([1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0],
                                      [0, 0, 1], [0, 0, -1])]
    t = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    for _ in range(level):
        middle, split = {}, []
        for a, b, c in t:
            m = []
            for x, y in ((a, b), (b, c), (c, a)):
                key = (min(x, y), max(x, y))
                if key not in middle:
                    p = v[x] + v[y]
                    middle[key] = len(v)
                    v.append(p / np.linalg.norm(p))
                m.append(middle[key])
            split += [[a, m[0], m[2]], [m[0], b, m[1]], [m[2], m[1], c], [m[0], m[1], m[2]]]
        t = split
    return np.asarray(centre) + radius * np.array(v), np.array(t)


def flipped(shape):
    return shape[0], shape[1][:, ::-1]


def joined(*shapes):
    vertices, triangles, base = [], [], 0
    for v, t in shapes:
        vertices.append(v)
        triangles.append(t + base)
        base += len(v)
    return np.vstack(vertices), np.vstack(triangles)


# ---- Truth: signed containment in convex parts, with a margin ----------------------------


def convex_side(shape, points):
    """+1 inside, -1 outside, 0 within MARGIN of a face plane, for a convex closed shape."""
    v, t = shape
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1)[:, None]
    offset = np.einsum("fk,fk->f", a, n)
    side = np.empty(len(points), int)
    for start in range(0, len(points), 4096):
        signed = points[start:start + 4096] @ n.T - offset  # > 0 outside the face's plane
        inside = np.all(signed < -MARGIN, axis=1)
        outside = np.any(signed > MARGIN, axis=1)
        side[start:start + 4096] = np.where(inside, 1, np.where(outside, -1, 0))
    return side


def winding_of(parts, points):
    """w from (convex shape, +1 or -1 for its orientation) parts; None where unsure."""
    w = np.zeros(len(points), int)
    sure = np.ones(len(points), bool)
    for shape, sign in parts:
        side = convex_side(shape, points)
        sure &= side != 0
        w += sign * (side > 0)
    return w, sure


# ---- Families ------------------------------------------------------------------------


def families(rng, n):
    cube_a, cube_b = box([0, 0, 0], [1, 1, 1]), box([0.5, 0.3, 0.2], [1.5, 1.3, 1.2])
    ball_a, ball_b = sphere([0, 0, 0], 1.0), sphere([0.7, 0.2, 0.1], 0.8)
    outer, inner = box([0, 0, 0], [3, 3, 3]), box([1, 1, 1], [2, 2, 2])
    left, right = box([0, 0, 0], [1, 1, 1]), box([1, 0, 0], [2, 1, 1])

    def uniform(lower, upper):
        return rng.uniform(lower, upper, (n, 3))

    def convex_family(name, parts, lower, upper):
        points = uniform(lower, upper)
        w, sure = winding_of(parts, points)
        mesh = joined(*[shape if sign > 0 else flipped(shape) for shape, sign in parts])
        return name, mesh, points[sure], w[sure]

    yield convex_family("overlapping cubes", [(cube_a, 1), (cube_b, 1)], -0.2, 1.7)
    # The same at lattice points k/20: rays from them run along the lattice, through the
    # cubes' edges and corners, where float ray tracing is least sure.
    points = rng.integers(-4, 35, (n, 3)) / 20
    w, sure = winding_of([(cube_a, 1), (cube_b, 1)], points)
    yield "overlapping cubes, lattice points", joined(cube_a, cube_b), points[sure], w[sure]
    yield convex_family("overlapping spheres", [(ball_a, 1), (ball_b, 1)], -1.2, 1.6)
    yield convex_family("nested, inner reversed (cavity)", [(outer, 1), (inner, -1)], -0.3, 3.3)
    yield convex_family("nested, same orientation (w = 2)", [(outer, 1), (inner, 1)], -0.3, 3.3)
    yield convex_family("duplicated shell", [(cube_a, 1), (cube_a, 1)], -0.2, 1.2)
    yield convex_family("internal faces (two boxes sharing one)", [(left, 1), (right, 1)],
                        -0.2, 2.2)

    # A closed sphere with one small face cut out: far from the hole the label is the
    # sphere's.
    v, t = sphere([0, 0, 0], 1.0, level=4)
    hole = t[0]
    centroid = v[hole].mean(axis=0)
    points = uniform(-1.2, 1.2)
    w, sure = winding_of([((v, t), 1)], points)
    far = np.linalg.norm(points - centroid, axis=1) > 0.5
    yield "sphere with a small hole", (v, t[1:]), points[sure & far], w[sure & far]

    # Spot with closed shells pushed into it (boxes straddling its surface, and a sphere
    # inside it): the truth is Spot's exact winding number (exactgeo's closed classifier,
    # itself tested against rational oracles) plus the shells'.
    spot = exactgeo.load_mesh(os.path.join(HERE, "tests/data/meshes/spot/spot_quadrangulated.obj"))
    sv, sq = np.asarray(spot.vertices), np.asarray(spot.faces)
    st = np.vstack([sq[:, [0, 1, 2]], sq[:, [0, 2, 3]]])
    lower, upper = sv.min(0), sv.max(0)
    size = upper - lower
    shells = [(box(lower + size * [0.3, 0.3, 0.7], lower + size * [0.45, 0.5, 1.05]), 1),
              (box(lower + size * [0.6, 0.05, 0.3], lower + size * [0.7, 0.2, 0.45]), 1),
              (sphere(lower + size * 0.5, 0.1 * size.min()), 1)]
    points = uniform(lower - 0.05 * size, upper + 0.05 * size)
    w, sure = winding_of(shells, points)
    spot_only = exactgeo.Classifier(exactgeo.Mesh(sv, st))
    w += spot_only.winding_numbers(points)
    mesh = joined((sv, st), *[shape for shape, _ in shells])
    yield "Spot with shells pushed in", mesh, points[sure], w[sure]


# ---- The tools -------------------------------------------------------------------------


def run_exactgeo(mesh, points, rule):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        classifier = exactgeo.Classifier(exactgeo.Mesh(*mesh), rule=rule)
    start = time.perf_counter()
    labels = classifier.classify(points, threads=1)
    return labels == exactgeo.INSIDE, time.perf_counter() - start


def run_vtk(mesh, points):
    import vtk
    from vtk.util import numpy_support

    surface = vtk.vtkPolyData()
    vp = vtk.vtkPoints()
    vp.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(mesh[0]), deep=True))
    surface.SetPoints(vp)
    cells = vtk.vtkCellArray()
    for a, b, c in mesh[1]:
        cells.InsertNextCell(3, (int(a), int(b), int(c)))
    surface.SetPolys(cells)
    query = vtk.vtkPolyData()
    qp = vtk.vtkPoints()
    qp.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(points), deep=True))
    query.SetPoints(qp)
    select = vtk.vtkSelectEnclosedPoints()
    select.SetInputData(query)
    select.SetSurfaceData(surface)
    start = time.perf_counter()
    select.Update()
    seconds = time.perf_counter() - start
    marks = numpy_support.vtk_to_numpy(select.GetOutput().GetPointData().GetArray("SelectedPoints"))
    return marks.astype(bool), seconds


def run_anchor(program, mesh, points, folder):
    mesh_path, points_path, out_path = (os.path.join(folder, f) for f in ("m.bin", "p.bin", "w.bin"))
    v, t = mesh
    with open(mesh_path, "wb") as f:
        f.write(struct.pack("<qq", len(v), len(t)))
        f.write(np.ascontiguousarray(v, "<f8").tobytes())
        f.write(np.ascontiguousarray(t, "<i4").tobytes())
    with open(points_path, "wb") as f:
        f.write(struct.pack("<q", len(points)))
        f.write(np.ascontiguousarray(points, "<f8").tobytes())
    result = subprocess.run([program, mesh_path, points_path, out_path], capture_output=True,
                            text=True, check=True, env={**os.environ, "IGL_NUM_THREADS": "1"})
    query = float(result.stdout.split("query")[1].split("s")[0])
    w = np.fromfile(out_path, "<f8")
    return np.abs(w) >= 0.5, query


def build_anchor(libigl, source, libraries, folder):
    program = os.path.join(folder, source)
    # libigl warns about its own use of std::iterator: not ours to mend.
    subprocess.run(["g++", "-O3", "-DNDEBUG", "-std=c++17", "-Wno-deprecated-declarations",
                    "-I", os.path.join(libigl, "include"),
                    "-I", "/usr/include/eigen3",
                    os.path.join(HERE, "bench", "libigl", source + ".cpp"), "-o", program,
                    *libraries, "-lpthread"], check=True)
    return program


def report(tools, cases, folder):
    print("| family | triangles | points | " + " | ".join(f"{t} wrong, Mpts/s" for t, _ in tools)
          + " |")
    print("|---|---|---|" + "---|" * len(tools))
    for name, mesh, points, w in cases:
        truth = w != 0
        cells = []
        for _, run in tools:
            try:
                labels, seconds = run(mesh, points, folder)
                for _ in range(REPEATS - 1):  # the fastest of a few runs: the machine is shared
                    seconds = min(seconds, run(mesh, points, folder)[1])
                wrong = int(np.count_nonzero(labels != truth))
                cells.append(f"{wrong}, {len(points) / seconds / 1e6:.2f}")
            except (ValueError, subprocess.CalledProcessError) as e:
                cells.append("refused: " + str(e).split(":")[0][:40])
        print(f"| {name} | {len(mesh[1])} | {len(points)} | " + " | ".join(cells) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=100000)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--libigl")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    tools = [("exactgeo nonzero", lambda m, p, d: run_exactgeo(m, p, "nonzero")),
             ("exactgeo parity", lambda m, p, d: run_exactgeo(m, p, "parity"))]
    try:
        import vtk  # noqa: F401

        tools.append(("VTK", lambda m, p, d: run_vtk(m, p)))
    except ImportError:
        print("VTK not found (Debian: python3-vtk9): left out", file=sys.stderr)
    with tempfile.TemporaryDirectory() as folder:
        if args.libigl:
            for name, source, libraries in (("libigl Antipodal", "antipodal_anchor", ["-lembree3"]),
                                            ("libigl fast WN", "fast_winding_anchor", [])):
                path = build_anchor(args.libigl, source, libraries, folder)
                tools.append((name, lambda m, p, d, path=path: run_anchor(path, m, p, d)))
        report(tools, families(rng, args.points), folder)


if __name__ == "__main__":
    main()
