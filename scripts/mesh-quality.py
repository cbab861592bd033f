#!/usr/bin/python3
"""The shape of a cloth frame written by `exactgeo-cloth --output`: how thin its triangles
are and where it stands in cones. Counts the cloth's triangles (the faces under `g cloth`)
by their smallest angle, the edges longer than the sheets' spacing allows, and the cone
tips: inner vertices around which the angles of their triangles add up to far less than
360 degrees, the spikes a sheet makes where it is left behind by its neighbours.

  scripts/mesh-quality.py FRAME.obj [--spacing METRES] [--json]

--spacing: the rest distance between sheet vertices (the scene's width over its
resolution minus one; edges are counted that are longer than 4/3 and 2 times it).
Needs numpy (Debian: python3-numpy).
"""

import argparse
import collections
import json

import numpy as np


def read_cloth(path):
    """Vertices (n, 3) and the cloth's triangles (m, 3)."""
    points, faces, group = [], [], "cloth"
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                points.append([float(x) for x in words[1:4]])
            elif words[0] == "g":
                group = words[1] if len(words) > 1 else ""
            elif words[0] == "f" and group == "cloth":
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:4]])
    return np.array(points), np.array(faces, dtype=np.int64)


def angles(p, q, r):
    """The angle at p of the triangles p q r, in degrees."""
    u, v = q - p, r - p
    return np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v), axis=1), (u * v).sum(1)))


def quality(points, faces, spacing):
    a, b, c = points[faces[:, 0]], points[faces[:, 1]], points[faces[:, 2]]
    corner = np.stack([angles(a, b, c), angles(b, c, a), angles(c, a, b)], 1)
    smallest = corner.min(1)
    sides = collections.defaultdict(int)
    for f in faces:
        for k in range(3):
            sides[tuple(sorted((f[k], f[(k + 1) % 3])))] += 1
    boundary = {v for e, n in sides.items() if n == 1 for v in e}
    angle_sum = np.zeros(len(points))
    np.add.at(angle_sum, faces.ravel(), corner.ravel())
    used = np.unique(faces)
    inner = [v for v in used if v not in boundary]
    lengths = np.array([np.linalg.norm(points[i] - points[j]) for i, j in sides])
    report = {
        "triangles": int(len(faces)),
        "smallest_angle_percentiles_0.1_1_5_50": np.percentile(smallest, [0.1, 1, 5, 50])
        .round(2).tolist(),
        "triangles_below_5_degrees": int((smallest < 5).sum()),
        "triangles_below_1_degree": int((smallest < 1).sum()),
        "cone_tips_below_200_degrees": int(sum(angle_sum[v] < 200 for v in inner)),
        "cone_tips_below_120_degrees": int(sum(angle_sum[v] < 120 for v in inner)),
    }
    if spacing:
        report["edges_over_4/3_spacing"] = int((lengths > 4 / 3 * spacing).sum())
        report["edges_over_2_spacing"] = int((lengths > 2 * spacing).sum())
    return report


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("frame")
    parser.add_argument("--spacing", type=float, default=0.0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    report = quality(*read_cloth(args.frame), args.spacing)
    if args.json:
        print(json.dumps(report))
    else:
        for key, value in report.items():
            print(f"{key:40} {value}")


if __name__ == "__main__":
    main()
