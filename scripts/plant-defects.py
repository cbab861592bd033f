#!/usr/bin/python3
"""Plants one defect of each kind that `exactgeo info --mark` colours into a closed OBJ
quad mesh, for the pictures in docs/inspection.md:

  scripts/plant-defects.py IN.obj OUT.obj

- a hole: the faces around the vertex with the largest x, and around its neighbours, are
  removed (boundary edges);
- a bar: a closed box through the middle of the mesh that sticks out on the +x side, so
  its faces cross the mesh's (intersecting pairs);
- a fin: a triangle on an edge already shared by two faces (non-manifold edge);
- a degenerate face: a triangle with a repeated corner.
"""

import sys


def main():
    source, target = sys.argv[1:3]
    vertices, faces = [], []
    with open(source) as f:
        for line in f:
            words = line.split()
            if words[:1] == ["v"]:
                vertices.append([float(x) for x in words[1:4]])
            elif words[:1] == ["f"]:
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])

    lower = [min(v[k] for v in vertices) for k in range(3)]
    upper = [max(v[k] for v in vertices) for k in range(3)]
    size = max(u - l for l, u in zip(lower, upper))
    middle = [(l + u) / 2 for l, u in zip(lower, upper)]

    rightmost = max(range(len(vertices)), key=lambda v: vertices[v][0])
    ring = {v for f in faces if rightmost in f for v in f}
    faces = [f for f in faces if not ring & set(f)]

    def nearest_face(point):
        def distance(face):
            centre = [sum(vertices[v][k] for v in face) / len(face) for k in range(3)]
            return sum((c - p) ** 2 for c, p in zip(centre, point))
        return min(faces, key=distance)

    # Both on the +x side, above and below the bar.
    a, b = nearest_face([upper[0], middle[1] - 0.2 * size, middle[2] - 0.1 * size])[:2]
    mid = [(x + y) / 2 for x, y in zip(vertices[a], vertices[b])]
    vertices.append([mid[0] + 0.1 * size, mid[1], mid[2]])
    faces.append([a, b, len(vertices) - 1])

    c = nearest_face([upper[0], middle[1] + 0.2 * size, middle[2]])
    faces.append([c[0], c[1], c[1]])

    first = len(vertices)
    bar_lower = [middle[0], middle[1] - 0.06 * size, middle[2] - 0.06 * size]
    bar_upper = [upper[0] + 0.15 * size, middle[1] + 0.06 * size, middle[2] + 0.06 * size]
    for c in range(8):
        vertices.append([(bar_upper if c >> k & 1 else bar_lower)[k] for k in range(3)])
    for quad in ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2),
                 (1, 3, 7, 5)):
        faces.append([first + c for c in quad])

    with open(target, "w") as f:
        f.write(f"# {source} with a hole, a bar through it, a fin and a degenerate face\n")
        for v in vertices:
            f.write("v {!r} {!r} {!r}\n".format(*v))
        for face in faces:
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")


if __name__ == "__main__":
    main()
