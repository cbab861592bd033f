"""exactgeo.MeshCcd: the pairs and time of impact of `exactgeo ccd-mesh` on the same
frames, and every input checked."""

import numpy as np
import pytest

import exactgeo
from conftest import write_obj


def grid(n: int, z: float, shift: float = 0.0):
    """An n x n grid of squares split into triangles, at height z."""
    xs, ys = np.meshgrid(np.linspace(0, 1, n + 1) + shift, np.linspace(0, 1, n + 1))
    vertices = np.column_stack([xs.ravel(), ys.ravel(), np.full(xs.size, z)])
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return vertices, np.array(faces)


def two_sheets(rng, n=8):
    """A sheet falling through a standing sheet, its vertices jittered."""
    low, faces = grid(n, 0.0)
    high, _ = grid(n, 0.05, shift=0.013)
    x0 = np.concatenate([low, high])
    x1 = np.concatenate([low, high - [0, 0, 0.1]]) + rng.normal(0, 1e-3, (2 * len(low), 3))
    x1[: len(low)] = low  # the lower sheet stands still
    faces = np.concatenate([faces, faces + len(low)])
    return faces, x0, x1


@pytest.mark.parametrize("toi", [False, True])
@pytest.mark.parametrize("method", ["exact", "parity"])
def test_pairs_match_the_command_line(cli, rng, tmp_path, method, toi):
    if toi and method != "exact":
        pytest.skip("time of impact is exact only")
    faces, x0, x1 = two_sheets(rng)
    write_obj(tmp_path / "frame0.obj", x0, faces)
    write_obj(tmp_path / "frame1.obj", x1, faces)
    args = ["ccd-mesh", tmp_path / "frame0.obj", tmp_path / "frame1.obj", "--method", method]
    expected = cli.json(*args, *(["--toi"] if toi else []))

    step = exactgeo.MeshCcd(faces).step(x0, x1, method=method, toi=toi)
    assert step.collision
    assert step.vertex_face.tolist() == expected["vertex_face"]
    assert step.edge_edge.tolist() == expected["edge_edge"]
    assert step.vertex_face_candidates == expected["vertex_face_candidates"]
    assert step.edge_edge_candidates == expected["edge_edge_candidates"]
    if toi:
        assert list(step.time_of_impact) == expected["time_of_impact"]
        start, end = step.time_of_impact
        assert 0 <= start <= end <= 1 and end - start <= 1e-6
    else:
        assert step.time_of_impact is None


def test_steps_and_threads_agree(rng):
    faces, x0, x1 = two_sheets(rng)
    ccd = exactgeo.MeshCcd(faces)
    one = ccd.step(x0, x1, threads=1)
    again = ccd.step(x0, x1, threads=2)  # the standing sheet's tree is kept between steps
    assert np.array_equal(one.vertex_face, again.vertex_face)
    assert np.array_equal(one.edge_edge, again.edge_edge)
    assert ccd.vertex_count == len(x0)
    assert ccd.edges.shape[1] == 2 and np.all(ccd.edges[:, 0] < ccd.edges[:, 1])
    nothing = ccd.step(x0, x0)
    assert not nothing.collision and nothing.vertex_face.shape == (0, 2)
    assert nothing.edge_edge.shape == (0, 4)


def test_errors(rng):
    faces, x0, x1 = two_sheets(rng, n=2)
    ccd = exactgeo.MeshCcd(faces)
    with pytest.raises(ValueError, match=r"x1 has 17 rows, the mesh has 18 vertices"):
        ccd.step(x0, x1[1:])
    with pytest.raises(ValueError, match=r"x0 must have shape \(n, 3\)"):
        ccd.step(x0[:, :2], x1)
    bad = x1.copy()
    bad[4, 0] = np.inf
    with pytest.raises(ValueError, match=r"x1\[4\] has a non-finite coordinate"):
        ccd.step(x0, bad)
    with pytest.raises(ValueError, match="toi needs method='exact'"):
        ccd.step(x0, x1, method="parity", toi=True)
    with pytest.raises(ValueError, match="toi must be"):
        ccd.step(x0, x1, toi=2.0)
    with pytest.raises(TypeError, match="toi must be"):
        ccd.step(x0, x1, toi="soon")
    with pytest.raises(ValueError, match="method must be"):
        ccd.step(x0, x1, method="fast")
    with pytest.raises(ValueError, match=r"faces\[1\] has corner index -2"):
        exactgeo.MeshCcd([[0, 1, 2], [0, -2, 1]])
    with pytest.raises(ValueError):
        exactgeo.MeshCcd([[0, 1, 1]])  # a repeated corner
    with pytest.raises(ValueError):
        exactgeo.MeshCcd([[0, 1, 5]], vertex_count=4)
    with pytest.raises(ValueError, match="faces must hold integers"):
        exactgeo.MeshCcd(np.array([[0, 1, 2.5]]))


def test_min_separation_matches_the_command_line(cli, rng, tmp_path):
    faces, x0, x1 = two_sheets(rng)
    write_obj(tmp_path / "frame0.obj", x0, faces)
    write_obj(tmp_path / "frame1.obj", x1, faces)
    expected = cli.json("ccd-mesh", tmp_path / "frame0.obj", tmp_path / "frame1.obj",
                        "--min-separation", "0.01", "--toi")
    ccd = exactgeo.MeshCcd(faces)
    step = ccd.step(x0, x1, min_separation=0.01, toi=True)
    assert step.vertex_face.tolist() == expected["vertex_face"]
    assert step.edge_edge.tolist() == expected["edge_edge"]
    assert list(step.time_of_impact) == expected["time_of_impact"]
    contacts = exactgeo.MeshCcd(faces).step(x0, x1)
    # Every contact is within the separation, and the separation finds more.
    assert set(map(tuple, contacts.vertex_face.tolist())) <= set(map(tuple, step.vertex_face.tolist()))
    assert len(step.vertex_face) + len(step.edge_edge) > len(contacts.vertex_face) + len(contacts.edge_edge)
    for bad in (-1.0, float("nan")):
        with pytest.raises(ValueError, match="min_separation"):
            ccd.step(x0, x1, min_separation=bad)
    with pytest.raises(ValueError, match="min_separation needs"):
        ccd.step(x0, x1, method="parity", min_separation=0.01)
