"""exactgeo.Surface: the collision-safe operations from Python, on the C++ tests' scene (a
grid sheet under a large triangle)."""
import numpy as np
import pytest

import exactgeo


def sheets(n=4, h=1.0):
    grid = np.array([(i, j, 0.0) for j in range(n + 1) for i in range(n + 1)])
    top = np.array([(-n, -n, h), (2 * n, n / 2, h), (-n, 2 * n, h)])
    at = lambda i, j: i + (n + 1) * j  # noqa: E731
    triangles = [t for j in range(n) for i in range(n)
                 for t in ((at(i, j), at(i + 1, j), at(i + 1, j + 1)),
                           (at(i, j), at(i + 1, j + 1), at(i, j + 1)))]
    m = len(grid)
    triangles.append((m, m + 2, m + 1))
    return np.vstack([grid, top]), np.array(triangles)


def test_an_operation_through_the_other_sheet_is_refused_naming_it():
    surface = exactgeo.Surface(*sheets())
    refused = surface.relocate_vertex(6, [1, 1, 1.5])
    assert refused["verdict"] == "refused_collision" and not refused["applied"]
    assert refused["blocker"] == ("triangle", (25, 27, 26))
    assert "would meet triangle 25 27 26" in refused["reason"]
    below = np.nextafter(1.0, 0.0)
    assert surface.relocate_vertex(6, [1, 1, below])["applied"]
    assert surface.vertices[6].tolist() == [1, 1, below]
    split = surface.split_edge(7, 13, [2.5, 1.5, 0.0])
    assert split["applied"] and split["new_vertex"] == 28
    assert surface.triangles.shape == (35, 3)
    assert surface.flip_edge(0, 1)["verdict"] == "refused_topology"


def test_a_smoothing_pass_refuses_only_the_colliding_moves():
    surface = exactgeo.Surface(*sheets())
    applied = surface.relocate_vertices([6, 8, 18], [[1, 1, 1.5], [3, 1, 0.5], [3, 3, 0.5]])
    assert applied.tolist() == [False, True, True]
    assert surface.vertices[6].tolist() == [1, 1, 0]


def test_fixed_vertices_and_bad_arguments():
    vertices, triangles = sheets()
    fixed = np.zeros(len(vertices), bool)
    fixed[6] = True
    surface = exactgeo.Surface(vertices, triangles, fixed=fixed)
    assert "fixed" in surface.relocate_vertex(6, [1, 1, 0.5])["reason"]
    with pytest.raises(ValueError, match="out of range"):
        surface.flip_edge(6, 99)
    with pytest.raises(ValueError, match="fixed must be"):
        exactgeo.Surface(vertices, triangles, fixed=[True])
    with pytest.raises(ValueError, match="non-finite"):
        surface.relocate_vertex(7, [1, np.nan, 0])


def test_passes_of_flips_and_splits():
    surface = exactgeo.Surface(*sheets())
    # Two far apart diagonals and one next to the first: that one waits.
    done = surface.flip_edges([[6, 12], [18, 24], [7, 13]])
    assert [d["verdict"] for d in done] == ["applied", "applied", "deferred"]
    done = surface.split_edges([[0, 1], [3, 4]], [[0.5, 0, 0], [3.5, 0, 2]])
    assert done[0]["applied"] and done[0]["new_vertex"] == 28
    assert done[1]["verdict"] == "refused_collision"
    assert done[1]["blocker"] == ("triangle", (25, 27, 26))


def test_pass_of_collapses():
    surface = exactgeo.Surface(*sheets())
    # A boundary edge into its corner; one next to it waits; one lifted through the sheet
    # above is refused.
    done = surface.collapse_edges([[0, 1], [1, 2], [23, 24]], [[0, 0, 0], [1, 0, 0], [3.5, 4, 2]])
    assert [d["verdict"] for d in done] == ["applied", "deferred", "refused_collision"]
    assert done[2]["blocker"] is not None
    assert not (surface.triangles == 1).any()  # vertex 1 is used by no triangle now
    with pytest.raises(ValueError, match="same length"):
        surface.collapse_edges([[3, 4]], [[0, 0, 0], [1, 1, 1]])
