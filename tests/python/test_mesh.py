"""exactgeo.Mesh and exactgeo.load_mesh: every format, the same report as `exactgeo info`,
and a clear error for every bad input."""

import numpy as np
import pytest

import exactgeo
from conftest import MESHES

BUNDLED = sorted(p for p in MESHES.rglob("*") if p.suffix in (".obj", ".off", ".ply"))

CUBE_VERTICES = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)
CUBE_QUADS = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4],
                       [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])


def ascii_stl(triangles: np.ndarray) -> str:
    lines = ["solid cube"]
    for t in triangles:
        lines += ["facet normal 0 0 0", "outer loop"]
        lines += [f"vertex {p[0]!r} {p[1]!r} {p[2]!r}" for p in t]
        lines += ["endloop", "endfacet"]
    return "\n".join(lines + ["endsolid cube", ""])


def binary_stl(triangles: np.ndarray, header: bytes = b"solid binary") -> bytes:
    """Binary STL of float32 coordinates; the header begins with "solid", as many do."""
    records = np.zeros(len(triangles), dtype=[("normal", "<f4", 3), ("corners", "<f4", (3, 3)),
                                              ("attribute", "<u2")])
    records["corners"] = triangles
    return header.ljust(80) + np.uint32(len(triangles)).tobytes() + records.tobytes()


def box_triangles(lower: float, upper: float) -> np.ndarray:
    """The box [lower, upper]^3 as 12 outward triangles, shape (12, 3, 3)."""
    vertices = lower + (upper - lower) * CUBE_VERTICES
    return vertices[np.array([[q[0], q[1], q[2]] for q in CUBE_QUADS] +
                             [[q[0], q[2], q[3]] for q in CUBE_QUADS])]


@pytest.mark.parametrize("path", BUNDLED, ids=lambda p: p.name)
def test_info_matches_the_command_line(cli, path):
    mesh = exactgeo.load_mesh(str(path), split_polygons=True)
    assert mesh.info() == cli.json("info", path, "--split-polygons")


def test_each_format_loads(tmp_path, cli):
    formats = {exactgeo.load_mesh(p, split_polygons=True).format.split()[0] for p in BUNDLED}
    assert {"obj", "off", "ply"} <= formats
    # STL is read exactly and always welded: the soup's 36 corners become 8 vertices, at
    # the doubles the file's decimals name (0.1, not the float nearest it).
    triangles = box_triangles(0.1, 0.7)
    stl = tmp_path / "cube.stl"
    stl.write_text(ascii_stl(triangles))
    mesh = exactgeo.load_mesh(stl)
    info = mesh.info()
    assert mesh.format == "stl ascii" and info["coordinates_via_float"] is False
    assert mesh.vertex_count == 8 and info["closed"] and info["welded_vertices"] == 28
    assert np.array_equal(np.unique(mesh.vertices, axis=0),
                          np.unique(triangles.reshape(-1, 3), axis=0))
    assert info == cli.json("info", stl)
    assert exactgeo.load_mesh(stl, weld=True).info() == cli.json("info", stl, "--weld") == info
    # Binary STL: float32 coordinates, widened bit for bit.
    floats = box_triangles(0.1, 0.7).astype(np.float32)
    binary = tmp_path / "binary.stl"
    binary.write_bytes(binary_stl(floats))
    mesh = exactgeo.load_mesh(binary)
    assert mesh.format == "stl binary" and mesh.info()["welded_vertices"] == 28
    assert np.array_equal(np.unique(mesh.vertices, axis=0),
                          np.unique(floats.reshape(-1, 3).astype(np.float64), axis=0))
    assert mesh.info() == cli.json("info", binary)


def test_format_names_what_the_file_name_does_not(tmp_path, cli):
    source = sorted(p for p in BUNDLED if p.suffix == ".obj")[0]
    nameless = tmp_path / "mesh_without_extension"
    nameless.write_bytes(source.read_bytes())
    with pytest.raises(ValueError, match="no file extension"):
        exactgeo.load_mesh(nameless)
    named = exactgeo.load_mesh(nameless, format="obj", split_polygons=True)
    by_extension = exactgeo.load_mesh(source, split_polygons=True)
    assert np.array_equal(named.vertices, by_extension.vertices)
    assert named.info() == cli.json("info", nameless, "--format", "obj", "--split-polygons")
    with pytest.raises(ValueError, match="unsupported mesh format 'xyz'"):
        exactgeo.load_mesh(nameless, format="xyz")


def test_info_counts_intersecting_faces():
    # Two unit cubes, the second moved by (1/2, 1/2, 1/2): each of the first's faces at
    # x, y or z = 1 crosses the second's faces at 1/2 on the two other axes, 6 pairs.
    offset = CUBE_VERTICES + 0.5
    mesh = exactgeo.Mesh(np.vstack([CUBE_VERTICES, offset]),
                         np.vstack([CUBE_QUADS, CUBE_QUADS + 8]))
    info = mesh.info()
    assert (info["intersecting_face_pairs"], info["undecided_face_pairs"]) == (6, 0)
    assert exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS).info()["intersecting_face_pairs"] == 0


def test_mesh_from_arrays_keeps_what_it_was_given():
    mesh = exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS)
    assert np.array_equal(mesh.vertices, CUBE_VERTICES)
    assert np.array_equal(mesh.faces, CUBE_QUADS)
    info = mesh.info()
    assert info["closed"] and info["manifold"] and info["problem"] is None
    assert (info["quads"], info["triangles"], info["file"]) == (6, 0, None)
    assert info["bounding_box"] == {"lower": [0.0, 0.0, 0.0], "upper": [1.0, 1.0, 1.0]}


def test_mixed_faces_from_a_list():
    # A square pyramid: one quad and four triangles.
    vertices = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]]
    faces = [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    mesh = exactgeo.Mesh(vertices, faces)
    assert mesh.faces.shape == (5, 4)
    assert list(mesh.faces[:, 3]) == [1, -1, -1, -1, -1]
    info = mesh.info()
    assert (info["quads"], info["triangles"], info["closed"]) == (1, 4, True)
    assert exactgeo.Mesh(vertices, faces[1:]).faces.shape == (4, 3)


def test_coordinates_stay_exact(tmp_path):
    tiny, huge = 5e-324, 1.7976931348623157e308
    vertices = np.array([[tiny, -0.0, 0.1], [huge, 1 / 3, -tiny], [2.0**-1000, 3.0, 7.0]])
    mesh = exactgeo.Mesh(vertices, [[0, 1, 2]])
    assert mesh.vertices.tobytes() == vertices.tobytes()
    obj = tmp_path / "exact.obj"
    obj.write_text("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices) + "f 1 2 3\n")
    assert exactgeo.load_mesh(obj).vertices.tobytes() == vertices.tobytes()


@pytest.mark.parametrize(
    "faces, message",
    [
        ([[0, 1, 8]], r"faces\[0\] has corner index 8"),
        ([[0, 1, 2], [0, -1, 2]], r"faces\[1\] has corner index -1"),
        ([[0, 1]], r"faces\[0\] has 2 corners"),
        ([[0, 1, 2, 3, 4]], r"faces\[0\] has 5 corners"),
        ([[0, 1, 2], list(range(7))], r"faces\[1\] has 7 corners"),
        ([[0, 1, 2], 5], r"faces\[1\] is not a sequence"),
        ([[0, 1, 2.5]], r"faces\[0\] holds a corner that is not an integer"),
        (np.array([[0, 1, 2.0]]), r"faces must hold integers"),
        (np.zeros((2, 5), int), r"faces must have shape \(m, 3\) or \(m, 4\), got \(2, 5\)"),
        ("012", r"faces must be"),
    ],
)
def test_bad_faces_name_the_row(faces, message):
    with pytest.raises(ValueError, match=message):
        exactgeo.Mesh(CUBE_VERTICES, faces)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_vertices_name_the_row(bad):
    vertices = CUBE_VERTICES.copy()
    vertices[5, 1] = bad
    with pytest.raises(ValueError, match=r"vertices\[5\] has a non-finite coordinate"):
        exactgeo.Mesh(vertices, CUBE_QUADS)


def test_vertex_shape_is_checked():
    with pytest.raises(ValueError, match=r"vertices must have shape \(n, 3\), got \(8, 2\)"):
        exactgeo.Mesh(CUBE_VERTICES[:, :2], CUBE_QUADS)


def test_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(FileNotFoundError) as raised:
        exactgeo.load_mesh(tmp_path / "nothing.obj")
    assert "nothing.obj" in str(raised.value)


def test_malformed_file_names_file_and_line(tmp_path):
    path = tmp_path / "bad.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n")
    with pytest.raises(ValueError, match=r"bad.obj:3: "):
        exactgeo.load_mesh(path)
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
    with pytest.raises(ValueError, match=r"bad.obj:4: "):
        exactgeo.load_mesh(path)


def test_polygons_are_split_and_crossing_ones_only_when_asked(tmp_path):
    path = tmp_path / "pentagon.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 2 0\nv 0 1 0\nf 1 2 3 4 5\n")
    mesh = exactgeo.load_mesh(path)
    assert mesh.faces.shape == (3, 3)
    assert mesh.info()["split_polygons"] == 1
    star = tmp_path / "star.obj"
    star.write_text("v 0 10 0\nv 6 -8 0\nv -10 3 0\nv 10 3 0\nv -6 -8 0\nf 1 2 3 4 5\n")
    with pytest.raises(ValueError, match=r"star.obj:6: face 1: .*split_polygons=True"):
        exactgeo.load_mesh(star)
    with pytest.warns(UserWarning, match="made fans of triangles from the first corner"):
        fan = exactgeo.load_mesh(star, split_polygons=True)
    assert fan.faces.tolist() == [[0, 1, 2], [0, 2, 3], [0, 3, 4]]


def test_a_skipped_ply_header_line_is_a_warning(tmp_path):
    path = tmp_path / "created.ply"
    path.write_text("ply\nformat ascii 1.0\nCreated by an exporter\nelement vertex 3\n"
                    "property double x\nproperty double y\nproperty double z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    with pytest.warns(UserWarning, match=r"created.ply:3: skipped header line 'Created by"):
        mesh = exactgeo.load_mesh(path)
    assert mesh.faces.shape == (1, 3)
