"""Every entry point, given inputs of every wrong kind: a ValueError or TypeError (or an
answer), never a crash, never a NaN-derived label."""

import itertools
from fractions import Fraction

import numpy as np
import pytest

import exactgeo
from test_mesh import CUBE_QUADS, CUBE_VERTICES

WRONG = [None, "points", 3.0, [], [[]], [1, 2, 3], np.float64(1.0), np.zeros(()),
         np.zeros((0,)), np.zeros((2, 0)), np.zeros((4, 3, 1)), np.zeros((1, 4, 3, 1)),
         np.array([[1, 2, 3]], dtype=object), np.array([["1", "2", "3"]]),
         np.array([[1 + 2j, 0, 0]]), np.full((2, 3), np.nan), np.full((2, 4, 3), -np.inf),
         {"x": 1}, np.zeros((3, 3), dtype=np.float16), np.ones((5, 4, 3), dtype=bool),
         np.array([[1, Fraction(1, 2), 3]], dtype=object), [[1, "2", 3.0]],
         np.full((2, 4, 3), 2**53 + 1), [[2**64 + 1, 0, 0.5]], np.full((1, 3), 1 / 3, np.longdouble)]


# Not real numbers: refused (TypeError) wherever coordinates are expected. (An object array
# of Python ints, 12, is real numbers: converted exactly.)
NOT_REAL = {13, 14, 19}
COORDINATE_CALLS = {"classify", "contains", "vertex_face_ccd x0", "edge_edge_ccd x1",
                    "orient3d", "Mesh vertices", "MeshCcd.step"}


def calls():
    classifier = exactgeo.Classifier(exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS))
    ccd = exactgeo.MeshCcd([[0, 1, 2], [1, 2, 3]])
    ok3 = np.zeros((4, 3))
    ok43 = np.zeros((2, 4, 3))
    return {
        "classify": lambda x: classifier.classify(x),
        "contains": lambda x: classifier.contains(x),
        "vertex_face_ccd x0": lambda x: exactgeo.vertex_face_ccd(x, ok43),
        "edge_edge_ccd x1": lambda x: exactgeo.edge_edge_ccd(ok43, x),
        "orient3d": lambda x: exactgeo.orient3d(x, x, x, x),
        "Mesh vertices": lambda x: exactgeo.Mesh(x, [[0, 1, 2]]),
        "Mesh faces": lambda x: exactgeo.Mesh(CUBE_VERTICES, x),
        "MeshCcd faces": lambda x: exactgeo.MeshCcd(x),
        "MeshCcd.step": lambda x: ccd.step(x, ok3),
        "load_mesh": lambda x: exactgeo.load_mesh(x),
        "read_ccd_queries": lambda x: exactgeo.read_ccd_queries(x),
    }


@pytest.mark.parametrize("name, index", itertools.product(sorted(calls()), range(len(WRONG))))
def test_wrong_input_is_refused_or_answered(name, index):
    value = WRONG[index]
    if name in COORDINATE_CALLS and index in NOT_REAL:
        with pytest.raises(TypeError, match="must hold real numbers"):
            calls()[name](value)
        return
    try:
        result = calls()[name](value)
    except (ValueError, TypeError, OSError):
        return
    # Accepted: only when the input really is valid (an empty set, say), and then the
    # answer holds no NaN.
    if isinstance(result, np.ndarray) and result.dtype.kind == "f":
        assert not np.isnan(result).any()
