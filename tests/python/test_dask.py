"""exactgeo.dask on a real distributed.LocalCluster (two worker processes on loopback):
the single-process labels, one classifier build per worker, and loader errors."""

import re

import numpy as np
import pytest

import exactgeo
import exactgeo.dask

da = pytest.importorskip("dask.array")
distributed = pytest.importorskip("distributed")

from conftest import CCD, write_obj  # noqa: E402


def subdivided_cube(k: int):
    """The unit cube with each face split into k x k quads: a closed quad mesh."""
    index = {}
    vertices, faces = [], []

    def vertex(p):
        if p not in index:
            index[p] = len(vertices)
            vertices.append(p)
        return index[p]

    ticks = [i / k for i in range(k + 1)]
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0.0, 1.0):
            for i in range(k):
                for j in range(k):
                    corners = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0.0, 0.0, 0.0]
                        p[axis], p[u], p[v] = side, ticks[i + di], ticks[j + dj]
                        corners.append(vertex(tuple(p)))
                    faces.append(corners if side == 1.0 else corners[::-1])
    return np.array(vertices), np.array(faces)


def known_points(rng, n):
    """Points with known labels: uniform in [-0.5, 1.5]^3, and points on the faces."""
    points = rng.uniform(-0.5, 1.5, (n, 3))
    on_face = rng.random(n) < 0.1
    axis = rng.integers(0, 3, n)
    points[on_face, axis[on_face]] = rng.integers(0, 2, on_face.sum())
    on_face &= np.all((points >= 0) & (points <= 1), axis=1)
    inside = np.all((points > 0) & (points < 1), axis=1)
    truth = np.where(on_face, exactgeo.BOUNDARY,
                     np.where(inside, exactgeo.INSIDE, exactgeo.OUTSIDE)).astype(np.int8)
    return points, truth


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       host="127.0.0.1", dashboard_address=None)
    with distributed.Client(cluster) as client:
        yield client
    cluster.close()


@pytest.fixture
def cube_file(tmp_path):
    path = tmp_path / "cube.obj"
    write_obj(path, *subdivided_cube(4))
    return path


def test_labels_equal_the_single_process_ones(client, rng, cube_file):
    points, truth = known_points(rng, 40_000)
    local = exactgeo.Classifier(exactgeo.load_mesh(cube_file)).classify(points)
    assert np.array_equal(local, truth)
    labels = exactgeo.dask.classify(cube_file, da.from_array(points, chunks=(2_500, 3)))
    assert labels.dtype == np.int8 and labels.shape == (len(points),)
    assert np.array_equal(labels.compute(), truth)


def test_each_worker_builds_the_classifier_once(client, rng, cube_file):
    points, truth = known_points(rng, 20_000)
    before = client.run(exactgeo.dask.worker_cache)
    # Two computations (chunked differently, so that no result of the first is reused):
    # the second one reuses the first one's classifiers.
    for chunk in (1_000, 1_250):
        labels = exactgeo.dask.classify(cube_file, da.from_array(points, chunks=(chunk, 3)))
        assert np.array_equal(labels.compute(), truth)
    after = client.run(exactgeo.dask.worker_cache)
    builds = {w: after[w]["builds"] - before[w]["builds"] for w in after}
    blocks = {w: after[w]["blocks"] - before[w]["blocks"] for w in after}
    assert sum(blocks.values()) == 20 + 16
    assert all(b <= 1 for b in builds.values()), builds
    assert sum(builds.values()) >= 1
    # The cache is keyed by content: a changed file is loaded again.
    vertices, faces = subdivided_cube(2)
    write_obj(cube_file, vertices, faces)
    labels = exactgeo.dask.classify(cube_file, da.from_array(points, chunks=(10_000, 3)))
    assert np.array_equal(labels.compute(), truth)
    rebuilt = client.run(exactgeo.dask.worker_cache)
    assert sum(rebuilt[w]["builds"] - after[w]["builds"] for w in rebuilt) >= 1


def test_the_rule_reaches_the_workers(client, tmp_path):
    # Two unit cubes overlapping in [0.5, 1]^3: inside by nonzero, outside by parity.
    cube_vertices = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)
    quads = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4],
                      [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])
    path = tmp_path / "two_cubes.obj"
    write_obj(path, np.vstack([cube_vertices, cube_vertices + 0.5]), np.vstack([quads, quads + 8]))
    points = da.from_array(np.array([[0.75, 0.75, 0.75], [0.25, 0.25, 0.25]]), chunks=(1, 3))
    union = exactgeo.dask.classify(path, points).compute()
    assert list(union) == [exactgeo.INSIDE, exactgeo.INSIDE]
    parity = exactgeo.dask.classify(path, points, rule="parity").compute()  # warns on a worker
    assert list(parity) == [exactgeo.OUTSIDE, exactgeo.INSIDE]


def test_a_bad_mesh_fails_with_the_loaders_message(client, tmp_path):
    points = da.zeros((100, 3), chunks=(50, 3))
    with pytest.raises(FileNotFoundError, match="no-such-mesh.obj"):
        exactgeo.dask.classify(tmp_path / "no-such-mesh.obj", points).compute()
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 zero\n")
    with pytest.raises(ValueError, match="bad.obj:2: "):
        exactgeo.dask.classify(bad, points).compute()
    with pytest.raises(ValueError, match=r"points must have shape \(n, 3\)"):
        exactgeo.dask.classify(bad, da.zeros((10, 2)))


def test_coordinates_are_exact_or_refused(client, cube_file):
    # A list's Python ints stay exact (NumPy alone would round 2^53 + 1 beside a float).
    with pytest.raises(ValueError, match=r"points\[1\] has a coordinate that is not exactly"):
        exactgeo.dask.classify(cube_file, [[0.5, 0.5, 0.5], [2**53 + 1, 0.5, 0]]).compute()
    labels = exactgeo.dask.classify(cube_file, [[0.5, 0.5, 0.5], [2**53 + 2, 0.5, 0], [1, 0, 0]])
    assert labels.compute().tolist() == [exactgeo.INSIDE, exactgeo.OUTSIDE, exactgeo.BOUNDARY]
    int64 = da.from_array(np.array([[0, 0, 0], [2**53 + 1, 0, 0]]), chunks=(1, 3))
    with pytest.raises(ValueError, match=r"points\[1\] has a coordinate that is not exactly"):
        exactgeo.dask.classify(cube_file, int64).compute()


@pytest.mark.parametrize("chunk", [1, 2, 3, 5])
def test_errors_name_the_row_of_the_whole_array(client, cube_file, chunk):
    # A bad point in a later block is named by its row in the whole array, not in its block
    # (a NaN at row 4 was once "points[0]").
    for row, value in ((4, np.nan), (6, np.inf), (7, -np.inf)):
        points = np.full((9, 3), 0.5)
        points[row, 1] = value
        with pytest.raises(ValueError, match=re.escape(f"points[{row}] has a non-finite")):
            exactgeo.dask.classify(cube_file, da.from_array(points, chunks=(chunk, 3))).compute()
    rows = [[0.5, 0.5, 0.5]] * 8
    rows[5] = [0.5, 2**53 + 1, 0.5]
    with pytest.raises(ValueError, match=re.escape("points[5] has a coordinate that is not")):
        exactgeo.dask.classify(cube_file, da.from_array(np.array(rows, dtype=object),
                                                        chunks=(chunk, 3))).compute()


def test_ccd_files_count_as_the_command_line(client, cli):
    folder = CCD / "sample-queries"
    counts = exactgeo.dask.ccd_files([folder])
    expected = cli.json("ccd", folder)
    for kind, key in (("vertex-face", "vertex_face"), ("edge-edge", "edge_edge")):
        for name in ("queries", "positives", "truth_positives", "false_positives",
                     "false_negatives"):
            assert counts[kind][name] == expected[key][name], (kind, name)
    assert counts["vertex-face"]["queries"] > 0 and counts["edge-edge"]["queries"] > 0


def test_classify_meshes_writes_one_labels_file_per_mesh(client, rng, tmp_path):
    # A data set: two cubes in nested folders (the same file name twice), an open box, and
    # a broken file. Each good mesh gets its labels file, the same labels as one process
    # gives; the broken one gets none, and the error names it after every other mesh ran.
    shapes = tmp_path / "shapes"
    for folder in ("a", "b"):
        (shapes / folder).mkdir(parents=True)
        write_obj(shapes / folder / "model.obj", *subdivided_cube(2))
    vertices, faces = subdivided_cube(1)
    write_obj(shapes / "open_box.obj", vertices, faces[:-1])
    (shapes / "notes.txt").write_text("not a mesh, skipped by its extension\n")
    points, truth = known_points(rng, 3_000)
    out = tmp_path / "labels"
    results = exactgeo.dask.classify_meshes(shapes, points, out)
    assert [r["mesh"] for r in results] == [str(shapes / "a" / "model.obj"),
                                            str(shapes / "b" / "model.obj"),
                                            str(shapes / "open_box.obj")]
    for folder in ("a", "b"):
        labels = np.load(out / folder / "model.labels.npy")
        assert labels.dtype == np.int8 and np.array_equal(labels, truth)
    with pytest.warns(UserWarning, match="the surface is open"):
        open_box = exactgeo.Classifier(exactgeo.load_mesh(shapes / "open_box.obj"))
    assert np.array_equal(np.load(out / "open_box.labels.npy"), open_box.classify(points))
    assert results[0]["points"] == len(points)
    assert results[0]["inside"] == np.count_nonzero(truth == exactgeo.INSIDE)
    assert results[0]["boundary"] == np.count_nonzero(truth == exactgeo.BOUNDARY)

    # A broken mesh: the others are written, then the error names it.
    (shapes / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    again = tmp_path / "again"
    with pytest.raises(ValueError, match=r"1 of 4 meshes failed .*broken\.off: ValueError: "):
        exactgeo.dask.classify_meshes(shapes, points, again)
    assert not (again / "broken.labels.npy").exists()
    assert (again / "open_box.labels.npy").exists()
    assert sorted(p.name for p in again.rglob("*")) == ["a", "b", "model.labels.npy",
                                                        "model.labels.npy", "open_box.labels.npy"]
    reported = exactgeo.dask.classify_meshes(shapes, points, again, errors="report")
    assert [r["labels"] is None for r in reported] == [False, False, True, False]
    assert "broken.off" in reported[2]["error"]


def test_the_command_lines_npy_labels_files_are_classify_meshes_own(client, cli, rng, tmp_path):
    # The same data set through both: `exactgeo inside --output-dir --labels-format npy`
    # writes the files classify_meshes writes, byte for byte after loading.
    shapes = tmp_path / "shapes"
    (shapes / "a").mkdir(parents=True)
    write_obj(shapes / "a" / "cube.obj", *subdivided_cube(2))
    vertices, faces = subdivided_cube(1)
    write_obj(shapes / "open_box.obj", vertices, faces[:-1])
    points, _ = known_points(rng, 2_000)
    np.save(tmp_path / "points.npy", points)
    exactgeo.dask.classify_meshes(shapes, points, tmp_path / "dask")
    done = cli.run("inside", shapes, tmp_path / "points.npy", "--output-dir", tmp_path / "cli",
                   "--labels-format", "npy")
    assert done.returncode == 0, done.stderr
    for name in ("a/cube.labels.npy", "open_box.labels.npy"):
        from_cli = np.load(tmp_path / "cli" / name)
        assert from_cli.dtype == np.int8 and from_cli.shape == (len(points),)
        assert np.array_equal(from_cli, np.load(tmp_path / "dask" / name)), name


def test_classify_meshes_reads_each_meshs_own_points(client, rng, tmp_path):
    write_obj(tmp_path / "small.obj", *subdivided_cube(1))
    points, truth = known_points(rng, 500)
    np.save(tmp_path / "small.points.npy", points)
    results = exactgeo.dask.classify_meshes([tmp_path / "small.obj"], "{mesh}.points.npy",
                                            tmp_path / "out")
    assert results[0]["labels"] == str(tmp_path / "out" / "small.labels.npy")
    assert np.array_equal(np.load(tmp_path / "out" / "small.labels.npy"), truth)


def test_classify_meshes_refuses_names_that_collide_before_running(tmp_path):
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        write_obj(tmp_path / folder / "model.obj", *subdivided_cube(1))
    with pytest.raises(ValueError, match=r"a/model\.obj and .*b/model\.obj would both write"):
        exactgeo.dask.classify_meshes([tmp_path / "a" / "model.obj", tmp_path / "b" / "model.obj"],
                                      np.zeros((1, 3)), tmp_path / "out")
    assert not (tmp_path / "out").exists()
    (tmp_path / "empty").mkdir()
    with pytest.raises(ValueError, match="empty: no mesh file in this folder"):
        exactgeo.dask.classify_meshes(tmp_path / "empty", np.zeros((1, 3)), tmp_path / "x")
