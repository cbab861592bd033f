"""Fill rules and winding numbers from Python: two overlapping cubes and a cube turned
inside out have known winding numbers; every rule labels by them, the same as
`exactgeo inside --rule`; parity warns about intersecting faces, the winding rules do not
need to; an unoriented mesh is labelled by parity by default (with a warning) and refused
by the winding rules with the way out named."""

import warnings

import numpy as np
import pytest

import exactgeo
from conftest import points_text
from test_mesh import CUBE_QUADS, CUBE_VERTICES

RULES = ("nonzero", "parity", "positive")


def cubes(*placements):
    """Unit cubes at the given offsets, each (offset, +1 outward or -1 inward)."""
    vertices, quads = [], []
    for offset, sign in placements:
        base = len(vertices)
        vertices += [[x + offset, y + offset, z + offset] for x, y, z in CUBE_VERTICES]
        for q in CUBE_QUADS:
            q = [base + i for i in q]
            quads.append(q if sign > 0 else q[::-1])
    return exactgeo.Mesh(np.array(vertices, np.float64), np.array(quads, np.int64))


def truth(points, placements):
    w = np.zeros(len(points), np.int64)
    for offset, sign in placements:
        inside = np.all((points > offset) & (points < offset + 1), axis=1)
        w += sign * inside
    return w


def holds(rule, w):
    return {"nonzero": w != 0, "parity": w % 2 != 0, "positive": w > 0}[rule]


@pytest.mark.parametrize("placements", [[(0.0, 1), (0.5, 1)], [(0.0, 1), (0.25, -1)],
                                        [(0.0, -1)]], ids=["overlap", "carved", "inward"])
def test_winding_numbers_and_labels_by_rule(rng, placements):
    mesh = cubes(*placements)
    # Points off every face plane (planes are at multiples of 1/4).
    points = np.floor(rng.uniform(-0.5, 2.0, size=(2000, 3)) * 8) / 8 + 1 / 16
    expected = truth(points, placements)
    for rule in RULES:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # parity warns about the overlap
            classifier = exactgeo.Classifier(mesh, rule=rule)
        assert classifier.rule == rule
        w = classifier.winding_numbers(points)
        assert w.dtype == np.int32
        np.testing.assert_array_equal(w, expected)
        labels = classifier.classify(points)
        np.testing.assert_array_equal(
            labels, np.where(holds(rule, expected), exactgeo.INSIDE, exactgeo.OUTSIDE))


def test_points_on_the_surface_have_no_winding_number():
    classifier = exactgeo.Classifier(cubes((0.0, 1)))
    w = classifier.winding_numbers([[0.0, 0.5, 0.5], [0.5, 0.5, 0.5], [2.0, 0.5, 0.5]])
    np.testing.assert_array_equal(w, [exactgeo.ON_SURFACE, 1, 0])
    assert exactgeo.ON_SURFACE == np.iinfo(np.int32).min


def test_parity_warns_about_intersecting_faces_and_nonzero_needs_not():
    mesh = cubes((0.0, 1), (0.5, 1))
    with pytest.warns(UserWarning, match="parity solid.*rule='nonzero'"):
        exactgeo.Classifier(mesh, rule="parity")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        exactgeo.Classifier(mesh)
        exactgeo.Classifier(cubes((0.0, 1)), rule="parity")  # nothing intersects


def test_unoriented_mesh_is_parity_by_default_and_refused_by_the_winding_rules():
    quads = np.array(CUBE_QUADS, np.int64)
    quads[0] = quads[0][::-1]
    mesh = exactgeo.Mesh(np.array(CUBE_VERTICES, np.float64), quads)
    for rule in ("nonzero", "positive"):
        with pytest.raises(ValueError, match="faces not oriented alike.*rule='parity'"):
            exactgeo.Classifier(mesh, rule=rule)
    with pytest.warns(UserWarning, match="not oriented alike.*crossing parity"):
        assert exactgeo.Classifier(mesh).rule == "parity"
    parity = exactgeo.Classifier(mesh, rule="parity")
    assert parity.classify([[0.5, 0.5, 0.5]])[0] == exactgeo.INSIDE
    with pytest.raises(ValueError, match="not oriented alike"):
        parity.winding_numbers([[0.5, 0.5, 0.5]])
    with pytest.raises(ValueError, match="rule must be"):
        exactgeo.Classifier(mesh, rule="even-odd")


@pytest.mark.parametrize("rule", RULES)
def test_rules_match_the_command_line(cli, tmp_path, rng, rule):
    placements = [(0.0, 1), (0.5, 1), (0.25, -1)]
    mesh = cubes(*placements)
    path = tmp_path / "cubes.off"
    with open(path, "w") as f:
        f.write(f"OFF\n{mesh.vertex_count} {len(mesh.faces)} 0\n")
        for v in mesh.vertices:
            f.write(" ".join(float(x).hex() for x in v) + "\n")
        for q in mesh.faces:
            f.write("4 " + " ".join(str(i) for i in q) + "\n")
    points = np.floor(rng.uniform(-0.5, 2.0, size=(500, 3)) * 8) / 8 + 1 / 16
    done = cli.run("inside", path, "-", "--rule", rule, "--no-self-intersection-check",
                   stdin=points_text(points))
    assert done.returncode == 0, done.stderr
    expected = np.where(holds(rule, truth(points, placements)), "inside", "outside")
    assert done.stdout.split() == list(expected)
    done = cli.run("inside", path, "-", "--rule", rule, "--winding",
                   "--no-self-intersection-check", stdin=points_text(points))
    assert done.returncode == 0, done.stderr
    assert [int(w) for w in done.stdout.split()] == list(truth(points, placements))


def test_zero_area_faces_are_dropped_with_a_warning(rng):
    # The cube as triangles, and a flat triangle on three collinear points with its reverse:
    # they bound nothing, so the labels are the cube's.
    triangles = [[q[0], q[1], q[2]] for q in CUBE_QUADS] + [[q[0], q[2], q[3]] for q in CUBE_QUADS]
    line = np.array([[0.5, 0.5, -1.0], [0.5, 0.5, 0.5], [0.5, 0.5, 2.0]])
    vertices = np.vstack([CUBE_VERTICES, line])
    triangles += [[8, 9, 10], [8, 10, 9]]
    mesh = exactgeo.Mesh(vertices, np.array(triangles, np.int64))
    assert mesh.info()["zero_area_faces"] == 2
    with pytest.warns(UserWarning, match=r"2 faces of zero area \(first: 12, 13\) bound "
                                         r"nothing: dropped \(faces numbered from 0\)"):
        classifier = exactgeo.Classifier(mesh)
    points = np.vstack([rng.uniform(-0.5, 1.5, (500, 3)), line])
    expected = np.where(np.all((points > 0) & (points < 1), axis=1), exactgeo.INSIDE,
                        exactgeo.OUTSIDE)
    expected[-2] = exactgeo.INSIDE  # the line's middle point: inside the cube, off the faces
    assert np.array_equal(classifier.classify(points), expected)


def test_intersecting_faces_are_named_as_the_file_numbers_them_after_faces_of_zero_area(tmp_path):
    # A flat pillow (two triangles on three collinear points: zero area, dropped) before two
    # overlapping cubes: the pairs are named by the file's face numbers, the pillow's two
    # faces counted (the check once ran on the mesh without them and named other faces).
    lines = ["v 5 0 0", "v 6 0 0", "v 7 0 0", "f 1 2 3", "f 1 3 2"]
    for offset in (0.0, 0.5):
        lines += [f"v {x + offset} {y + offset} {z + offset}"
                  for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    for first in (4, 12):
        lines += ["f " + " ".join(str(i + first) for i in q) for q in quads]
    path = tmp_path / "pillow_and_cubes.obj"
    path.write_text("\n".join(lines) + "\n")
    with pytest.warns(UserWarning) as caught:
        exactgeo.Classifier(exactgeo.load_mesh(path), rule="parity")
    said = [str(w.message) for w in caught]
    assert any("6 pairs of faces intersect (first: 4-11, " in m for m in said), said
