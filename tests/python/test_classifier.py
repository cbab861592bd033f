"""exactgeo.Classifier: the same labels as `exactgeo inside`, exact on a known solid, every
input form converted or refused with the row named, and the GIL released."""

import threading
import time

import numpy as np
import pytest

import exactgeo
from conftest import MESHES, points_text
from test_mesh import CUBE_QUADS, CUBE_VERTICES, ascii_stl, box_triangles

LABELS = {"outside": exactgeo.OUTSIDE, "inside": exactgeo.INSIDE, "boundary": exactgeo.BOUNDARY}
SOLIDS = [MESHES / "spot" / "spot_quad_cc1.ply", MESHES / "spot" / "spot_quadrangulated.obj",
          MESHES / "cgal" / "torus_quad.off", MESHES / "cgal" / "3torus.off"]


def cube_classifier():
    return exactgeo.Classifier(exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS))


def box_points(mesh: exactgeo.Mesh, rng, n: int) -> np.ndarray:
    """Uniform points in the mesh's box grown by 5%, plus every vertex and a few exact
    copies of vertices (points on the surface)."""
    lower, upper = mesh.vertices.min(axis=0), mesh.vertices.max(axis=0)
    grow = 0.05 * (upper - lower)
    uniform = rng.uniform(lower - grow, upper + grow, size=(n, 3))
    return np.concatenate([uniform, mesh.vertices])


@pytest.mark.parametrize("path", SOLIDS, ids=lambda p: p.name)
@pytest.mark.parametrize("method", ["exact", "double"])
def test_labels_match_the_command_line(cli, rng, path, method):
    mesh = exactgeo.load_mesh(path)
    points = box_points(mesh, rng, 3000)
    labels = exactgeo.Classifier(mesh).classify(points, method=method)
    done = cli.run("inside", path, "-", "--method", method, stdin=points_text(points))
    assert done.returncode == 0, done.stderr
    expected = np.array([LABELS[word] for word in done.stdout.split()], np.int8)
    assert labels.dtype == np.int8 and labels.shape == (len(points),)
    assert np.array_equal(labels, expected)
    if method == "exact":  # every vertex lies on the surface
        assert np.all(labels[-mesh.vertex_count:] == exactgeo.BOUNDARY)


@pytest.mark.parametrize("path", SOLIDS, ids=lambda p: p.name)
def test_space_cells_keep_the_labels(rng, path):
    mesh = exactgeo.load_mesh(path)
    points = box_points(mesh, rng, 3000)
    with_cells = exactgeo.Classifier(mesh).classify(points)
    without = exactgeo.Classifier(mesh, space_cells=False).classify(points)
    np.testing.assert_array_equal(with_cells, without)
    # A grid sized for few points (coarser) labels alike.
    few = exactgeo.Classifier(mesh, expected_points=len(points)).classify(points)
    np.testing.assert_array_equal(few, without)
    with pytest.raises(TypeError):
        exactgeo.Classifier(mesh, expected_points=-1)


def test_known_solid_exactly(rng):
    classifier = cube_classifier()
    inner = rng.uniform(2.0**-60, 1 - 2.0**-53, size=(500, 3))
    outer = inner.copy()
    outer[:, 0] = np.where(rng.random(500) < 0.5, -inner[:, 0], 1 + inner[:, 0])
    on_faces = inner.copy()
    on_faces[:, 2] = rng.integers(0, 2, 500)  # z = 0 or z = 1 exactly
    tiny_outside = np.array([[0.5, 0.5, -5e-324], [0.5, 0.5, np.nextafter(1, 2)]])
    tiny_inside = np.array([[0.5, 0.5, 5e-324], [0.5, 0.5, np.nextafter(1, 0)]])
    corners = CUBE_VERTICES
    assert np.all(classifier.classify(inner) == exactgeo.INSIDE)
    assert np.all(classifier.classify(outer) == exactgeo.OUTSIDE)
    assert np.all(classifier.classify(on_faces) == exactgeo.BOUNDARY)
    assert np.all(classifier.classify(corners) == exactgeo.BOUNDARY)
    assert np.all(classifier.classify(tiny_outside) == exactgeo.OUTSIDE)
    assert np.all(classifier.classify(tiny_inside) == exactgeo.INSIDE)


def test_a_vertex_copied_from_an_stl_file_is_boundary(tmp_path):
    # The file's decimals are read as the doubles they name, so a point written with the
    # same digits lies on the surface. Rounded to float32 (as assimp read STL), 0.1 moves up
    # and 0.7 down: every corner would move inside the box.
    text = ascii_stl(box_triangles(0.1, 0.7))
    stl = tmp_path / "box.stl"
    stl.write_text(text)
    classifier = exactgeo.Classifier(exactgeo.load_mesh(stl))
    copied = np.array([[float(x) for x in line.split()[1:]]
                       for line in text.splitlines() if line.startswith("vertex")])
    assert len(copied) == 36
    assert np.all(classifier.classify(copied) == exactgeo.BOUNDARY)
    rounded = copied.astype(np.float32).astype(np.float64)
    assert np.all(classifier.classify(rounded) == exactgeo.INSIDE)


def test_contains():
    classifier = cube_classifier()
    points = np.array([[0.5, 0.5, 0.5], [0.5, 0.5, 1.0], [2.0, 0.5, 0.5]])
    assert classifier.contains(points).tolist() == [True, True, False]
    assert classifier.contains(points, boundary=False).tolist() == [True, False, False]
    assert classifier.contains(points).dtype == np.bool_


def test_input_forms_are_converted(rng):
    classifier = cube_classifier()
    points = rng.uniform(-0.5, 1.5, size=(200, 3))
    expected = classifier.classify(points)
    wide = np.zeros((200, 6))
    wide[:, ::2] = points
    as_float32 = points.astype(np.float32)
    assert np.array_equal(classifier.classify(wide[:, ::2]), expected)  # not contiguous
    assert np.array_equal(classifier.classify(np.asfortranarray(points)), expected)
    assert np.array_equal(classifier.classify(points.tolist()), expected)
    assert np.array_equal(classifier.classify(as_float32),
                          classifier.classify(as_float32.astype(np.float64)))
    assert np.array_equal(classifier.classify(np.array([[2, 0, 0], [1, 1, 1]])),
                          [exactgeo.OUTSIDE, exactgeo.BOUNDARY])
    for threads in (1, 2, 7):
        assert np.array_equal(classifier.classify(points, threads=threads), expected)


def test_empty_input():
    classifier = cube_classifier()
    labels = classifier.classify(np.empty((0, 3)))
    assert labels.shape == (0,) and labels.dtype == np.int8
    assert classifier.contains(np.empty((0, 3))).shape == (0,)


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_non_finite_points_name_the_row(bad):
    points = np.full((10, 3), 0.5)
    points[7, 2] = bad
    with pytest.raises(ValueError, match=r"points\[7\] has a non-finite coordinate"):
        cube_classifier().classify(points)


@pytest.mark.parametrize("shape", [(3,), (5, 2), (5, 4), (2, 3, 1)])
def test_wrong_shapes(shape):
    with pytest.raises(ValueError, match=r"points must have shape \(n, 3\)"):
        cube_classifier().classify(np.zeros(shape))


def test_bad_options():
    classifier = cube_classifier()
    with pytest.raises(ValueError, match="method must be 'exact' or 'double'"):
        classifier.classify(np.zeros((1, 3)), method="rounded")
    with pytest.raises(ValueError, match="threads must be"):
        classifier.classify(np.zeros((1, 3)), threads=-1)
    with pytest.raises(TypeError):
        classifier.classify(np.array([["a", "b", "c"]], dtype=object))


def test_an_open_mesh_is_refused_by_parity_and_labelled_by_the_winding_rules():
    open_box = exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS[:5])
    with pytest.raises(ValueError, match=r"boundary edge.*\(vertices and faces numbered from 0\)"):
        exactgeo.Classifier(open_box, rule="parity")
    with pytest.warns(UserWarning, match=r"the surface is open \(4 edges run more often one way"):
        classifier = exactgeo.Classifier(open_box)
    # CUBE_QUADS[5] is the missing face; its centre has w = 1/2 exactly.
    missing = CUBE_VERTICES[CUBE_QUADS[5]].mean(axis=0)
    deep = CUBE_VERTICES.mean(axis=0) + 0.4 * (CUBE_VERTICES.mean(axis=0) - missing)
    far = missing + 2 * (missing - CUBE_VERTICES.mean(axis=0))
    labels = classifier.classify(np.array([deep, missing, far]))
    assert list(labels) == [exactgeo.INSIDE, exactgeo.UNDECIDED, exactgeo.OUTSIDE]


def square_solid_angle(distance: float) -> float:
    """The solid angle of the unit square seen from `distance` on its axis."""
    return 4 * np.arcsin(1 / (1 + 4 * distance * distance))


def test_an_open_box_has_its_generalized_winding_numbers():
    # The unit cube without its face x = 1 (CUBE_QUADS[5]). From the centre the other five
    # faces fill 5/6 of the sphere; from the missing face's centre, half; from a point on
    # its axis outside, at distance d from it, w is the missing square's solid angle over
    # 4 pi (the closed cube's w = 0, less that face's negative share), and below the
    # opposite face, at distance d from it, minus the square's share seen from d + 1.
    with pytest.warns(UserWarning, match="the surface is open"):
        classifier = exactgeo.Classifier(exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS[:5]))
    d = 0.375
    points = np.array([[0.5, 0.5, 0.5], [1.0, 0.5, 0.5], [1 + d, 0.5, 0.5], [-d, 0.5, 0.5],
                       [0.0, 0.5, 0.5], [1.0, 1.0, 0.5]])
    truth = np.array([5 / 6, 0.5, square_solid_angle(d) / (4 * np.pi),
                      -square_solid_angle(1 + d) / (4 * np.pi), np.nan, np.nan])
    w = classifier.winding_numbers(points)
    assert w.dtype == np.float64 and w.shape == (6,)
    np.testing.assert_allclose(w[:4], truth[:4], rtol=0, atol=1e-14)
    assert np.isnan(w[4:]).all()  # on a face, on a boundary edge
    lower, upper = classifier.winding_numbers(points, bounds=True)
    assert (lower[:4] <= w[:4]).all() and (w[:4] <= upper[:4]).all()
    assert (upper[:4] - lower[:4] <= 2.0**-39).all()
    # Certified: exactly 1/2 is held, and the labels are read from the values.
    assert lower[1] <= 0.5 <= upper[1]
    labels = classifier.classify(points[:4])
    assert list(labels) == [exactgeo.INSIDE, exactgeo.UNDECIDED, exactgeo.OUTSIDE,
                            exactgeo.OUTSIDE]
    assert np.isnan(lower[4:]).all() and np.isnan(upper[4:]).all()
    # The baseline in plain doubles: one value, near the certified one.
    low, high = classifier.winding_numbers(points[:4], bounds=True, method="double")
    assert (low == high).all()
    np.testing.assert_allclose(low, truth[:4], rtol=0, atol=1e-12)


def test_bounds_of_a_closed_surface_are_its_winding_numbers():
    classifier = cube_classifier()
    points = np.array([[0.5, 0.5, 0.5], [2.0, 0.5, 0.5], [0.0, 0.5, 0.5]])
    w = classifier.winding_numbers(points)
    assert w.dtype == np.int32 and list(w) == [1, 0, exactgeo.ON_SURFACE]
    lower, upper = classifier.winding_numbers(points, bounds=True)
    assert list(lower[:2]) == [1.0, 0.0] and list(upper[:2]) == [1.0, 0.0]
    assert np.isnan(lower[2]) and np.isnan(upper[2])


def test_refusals_number_as_the_file_does(tmp_path):
    # An OBJ counts from 1: the message says so, as `exactgeo inside` does.
    path = tmp_path / "open.obj"
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in CUBE_VERTICES) +
                    "".join("f " + " ".join(str(i + 1) for i in q) + "\n" for q in CUBE_QUADS[:5]))
    with pytest.raises(ValueError, match=r"\(vertices and faces numbered from 1, as in the file\)"):
        exactgeo.Classifier(exactgeo.load_mesh(path), rule="parity")


def test_a_refusal_says_what_the_command_line_says(cli, tmp_path):
    # A fin on the cube's edge 1-2: not closed and non-manifold at once, nonzero takes it.
    path = tmp_path / "fin.obj"
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in CUBE_VERTICES) + "v 2 2 2\n" +
                    "".join("f " + " ".join(str(i + 1) for i in q) + "\n" for q in CUBE_QUADS) +
                    "f 1 2 9\n")
    done = cli.run("inside", "--rule", "parity", path, stdin="0 0 0\n")
    assert done.returncode == 2 and done.stdout == ""
    prefix = f"exactgeo inside: {path}: "
    assert done.stderr.startswith(prefix)
    said = done.stderr[len(prefix):].rstrip("\n")
    assert "non-manifold" in said and "odd number of faces" in said and "--rule nonzero" in said
    with pytest.raises(ValueError) as refused:
        exactgeo.Classifier(exactgeo.load_mesh(path), rule="parity")
    assert str(refused.value) == said.replace("--rule nonzero", "rule='nonzero'")


def test_a_face_soup_is_refused_with_the_way_out():
    soup_vertices = CUBE_VERTICES[CUBE_QUADS].reshape(-1, 3)
    soup = exactgeo.Mesh(soup_vertices, np.arange(24).reshape(6, 4))
    with pytest.raises(ValueError, match=r"with weld=True, which merges the 16 vertices"):
        exactgeo.Classifier(soup)


def test_threads_can_be_set_once_for_every_call(rng):
    mesh = exactgeo.load_mesh(MESHES / "spot" / "spot_quad_cc1.ply")
    points = box_points(mesh, rng, 20_000)
    one = exactgeo.Classifier(mesh, threads=1)
    assert one.threads == 1 and exactgeo.Classifier(mesh).threads == 0
    labels = one.classify(points)
    assert np.array_equal(labels, one.classify(points, threads=2))
    assert np.array_equal(labels, exactgeo.Classifier(mesh).classify(points))
    assert np.array_equal(one.contains(points), labels != exactgeo.OUTSIDE)
    with pytest.raises(ValueError, match="threads must be"):
        exactgeo.Classifier(mesh, threads=-1)
    with pytest.raises(ValueError, match="threads must be"):
        one.classify(points, threads=-2)


def test_the_gil_is_released_while_classifying():
    """A second Python thread keeps running while one classifies: with the GIL held, it
    would stall for the whole call."""
    mesh = exactgeo.load_mesh(MESHES / "spot" / "spot_quad_cc1.ply")
    classifier = exactgeo.Classifier(mesh)
    points = box_points(mesh, np.random.default_rng(1), 200_000)
    results = {}

    def classify(name):
        start = time.perf_counter()
        results[name] = classifier.classify(points, threads=1)
        results[name + " seconds"] = time.perf_counter() - start

    worker = threading.Thread(target=classify, args=("worker",))
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    gaps = np.diff(ticks)
    assert len(ticks) > 10, "the worker ended too fast to tell"
    assert gaps.max() < 0.5 * results["worker seconds"], (gaps.max(), results["worker seconds"])

    # Two threads classifying at once get the labels of one thread alone.
    both = [threading.Thread(target=classify, args=(name,)) for name in ("a", "b")]
    for t in both:
        t.start()
    for t in both:
        t.join()
    assert np.array_equal(results["a"], results["worker"])
    assert np.array_equal(results["b"], results["worker"])
