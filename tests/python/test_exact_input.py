"""Numbers in, exactly or refused. A coordinate that is not exactly a double (a 64-bit
integer beyond 2^53 with too many significant bits, a long double between two doubles, a
Python int of any size) is refused with the argument, the row and the value, never rounded;
a corner index that is not an integer (a float, a Fraction, a Decimal) or beyond every
index (a uint64 of 2^63 or more) is refused with the value as given, never truncated or
wrapped. Seeded tests compare every decision with Python's exact one (fractions)."""

import math
import re
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import exactgeo
from test_mesh import CUBE_QUADS, CUBE_VERTICES

Z = 2**53
SIGNED = [np.int8, np.int16, np.int32, np.int64]
UNSIGNED = [np.uint8, np.uint16, np.uint32, np.uint64]
LONG_DOUBLE_IS_WIDER = np.finfo(np.longdouble).nmant > np.finfo(np.float64).nmant
wider_long_double = pytest.mark.skipif(not LONG_DOUBLE_IS_WIDER,
                                       reason="long double is double on this platform")


def as_fraction(x) -> Fraction:
    """x (a Python or NumPy number) as an exact rational."""
    if isinstance(x, (int, np.integer)):
        return Fraction(int(x))
    return Fraction(*x.as_integer_ratio())


def exactly_double(x) -> bool:
    """Python's own exact decision: the double nearest x equals x, compared as rationals."""
    try:
        nearest = float(x)
    except OverflowError:
        return False
    return math.isfinite(nearest) and Fraction(nearest) == as_fraction(x)


def not_exactly(where: str, value: str) -> str:
    """The message's start for a refused coordinate, as a regular expression."""
    return re.escape(f"{where} has a coordinate that is not exactly a double: {value}")


def converted(vertices) -> np.ndarray:
    """The coordinates as the bindings read them (a mesh of no faces keeps them as read)."""
    return exactgeo.Mesh(vertices, []).vertices


# The reproducers.

def test_orient3d_of_python_ints_is_exact_or_refused():
    # 2^53 + 1 is no double: it read as 2^53 and the sign came out 0 (exactly it is +1).
    with pytest.raises(ValueError, match=not_exactly("d[2]", "9007199254740993 (")):
        exactgeo.orient3d([0, 0, Z], [1, 0, Z], [0, 1, Z], [0, 0, Z + 1])
    # Python ints that are doubles are taken exactly: 2^53 + 2, 2^60, -2^63, 2^1000.
    assert exactgeo.orient3d([0, 0, Z], [1, 0, Z], [0, 1, Z], [0, 0, Z + 2]) == 1
    assert exactgeo.orient3d([0, 0, 2**60], [1, 0, 2**60], [0, 1, 2**60], [0, 0, -2**63]) == -1
    assert exactgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2**1000]) == 1


def test_orient3d_of_a_long_double_between_doubles_is_refused():
    d = np.array([0, 0, 1], dtype=np.longdouble)
    d[2] += np.longdouble(2) ** -60  # read as 1: the sign came out 0
    if LONG_DOUBLE_IS_WIDER:
        with pytest.raises(ValueError, match=not_exactly("d[2]", "the long double 1.0000000000")):
            exactgeo.orient3d([0, 0, 1], [1, 0, 1], [0, 1, 1], d)
    # A long double that is a double is taken: 1.5 above the plane z = 1.
    above = np.array([0, 0, 1.5], dtype=np.longdouble)
    assert exactgeo.orient3d([0, 0, 1], [1, 0, 1], [0, 1, 1], above) == 1


@pytest.mark.parametrize("make", [
    lambda p: p,                                  # Python ints
    lambda p: np.array(p, dtype=np.int64),
    lambda p: np.array(p, dtype=np.uint64),
    lambda p: np.array(p, dtype=object),
    lambda p: [[x, 1.0, 1.0] for x, _, _ in p],   # NumPy alone would make float64 of these
], ids=["list", "int64", "uint64", "object", "mixed list"])
def test_a_point_beyond_the_cube_is_refused_not_boundary(make):
    classifier = exactgeo.Classifier(exactgeo.Mesh(CUBE_VERTICES * Z, CUBE_QUADS))
    points = [[1, 1, 1]] * 3 + [[Z + 1, 1, 1]]
    with pytest.raises(ValueError, match=not_exactly("points[3]", "9007199254740993 (")):
        classifier.classify(make(points))
    # The doubles on either side are exact, and labelled exactly.
    labels = classifier.classify(make([[Z, 1, 1], [Z + 2, 1, 1], [Z - 1, 1, 1]]))
    assert labels.tolist() == [exactgeo.BOUNDARY, exactgeo.OUTSIDE, exactgeo.INSIDE]


# Every coordinate argument: the rule and the message are the same everywhere.

def coordinate_calls():
    classifier = exactgeo.Classifier(exactgeo.Mesh(CUBE_VERTICES, CUBE_QUADS))
    ccd = exactgeo.MeshCcd([[0, 1, 2], [1, 2, 3]])
    frame = np.zeros((4, 3), dtype=np.int64)
    queries = np.zeros((2, 4, 3), dtype=np.int64)
    points = np.zeros((4, 3), dtype=np.int64)
    return {
        "classify points": (lambda x: classifier.classify(x), points),
        "contains points": (lambda x: classifier.contains(x), points),
        "vertex_face_ccd x0": (lambda x: exactgeo.vertex_face_ccd(x, queries), queries),
        "vertex_face_ccd x1": (lambda x: exactgeo.vertex_face_ccd(queries, x), queries),
        "edge_edge_ccd x0": (lambda x: exactgeo.edge_edge_ccd(x, queries), queries),
        "edge_edge_ccd x1": (lambda x: exactgeo.edge_edge_ccd(queries, x), queries),
        "orient3d a": (lambda x: exactgeo.orient3d(x, points, points, points), points),
        "orient3d d": (lambda x: exactgeo.orient3d(points, points, points, x), points),
        "Mesh vertices": (lambda x: exactgeo.Mesh(x, [[0, 1, 2]]), points),
        "MeshCcd.step x0": (lambda x: ccd.step(x, frame), frame),
        "MeshCcd.step x1": (lambda x: ccd.step(frame, x), frame),
    }


@pytest.mark.parametrize("call", sorted(coordinate_calls()))
def test_every_coordinate_argument_is_exact_or_refused(call):
    run, valid = coordinate_calls()[call]
    name = call.split()[1]
    run(valid)  # integers that are doubles are taken
    for dtype, bad in ((np.int64, Z + 1), (np.uint64, 2**64 - 1), (np.longdouble, None)):
        x = valid.astype(dtype)
        if bad is None:
            if not LONG_DOUBLE_IS_WIDER:
                continue
            x.flat[-1] = np.longdouble(1) / 3
        else:
            x.flat[-1] = bad
        row = len(x) - 1
        with pytest.raises(ValueError, match=re.escape(f"{name}[{row}] has a coordinate that "
                                                       "is not exactly a double")):
            run(x)
    as_list = valid.tolist()
    as_list[-1] = (np.array(as_list[-1]) * 0 + Z + 1).tolist()
    with pytest.raises(ValueError, match=not_exactly(f"{name}[{len(valid) - 1}]",
                                                      "9007199254740993 (")):
        run(as_list)


def test_the_row_is_found_in_strided_and_fortran_arrays():
    points = np.ones((6, 3), dtype=np.int64, order="F")
    points[4, 2] = -(Z + 1)
    with pytest.raises(ValueError, match=not_exactly("vertices[4]", "-9007199254740993")):
        converted(points)
    with pytest.raises(ValueError, match=not_exactly("vertices[2]", "-9007199254740993")):
        converted(points[::2])
    assert converted(points[::-1][2:]).tolist() == [[1.0, 1.0, 1.0]] * 4


def test_integers_that_are_doubles_convert_exactly():
    values = [0, -1, Z, -Z, Z + 2, 2**60 + 2**8, 2**62, 2**63 - 2**10, -2**63]
    for dtype in (np.int64, object):
        points = np.array([values[i:i + 3] for i in range(0, len(values), 3)], dtype=dtype)
        assert [as_fraction(x) for x in converted(points).ravel()] == values
    points = np.array([[2**63, 2**64 - 2**11, Z + 4]], dtype=np.uint64)
    assert [int(x) for x in converted(points).ravel()] == [2**63, 2**64 - 2**11, Z + 4]
    assert converted([[2**64, -2**100, 2**1023]]).tolist() == [[2.0**64, -2.0**100, 2.0**1023]]
    with pytest.raises(ValueError, match=re.escape("an int of 1025 bits (beyond the largest")):
        converted([[2**1024, 0, 0]])


def test_floats_widen_exactly_and_non_finite_values_are_named():
    for dtype in (np.float16, np.float32):
        points = np.array([[0.1, 1 / 3, 65504]], dtype=dtype)
        assert converted(points).tobytes() == points.astype(np.float64).tobytes()
    for dtype in (np.longdouble, object):
        points = np.array([[0, 0, 0], [1, np.inf, 0]], dtype=dtype)
        with pytest.raises(ValueError, match=re.escape("vertices[1] has a non-finite coordinate")):
            converted(points)
    assert converted(np.array([[0.5, -0.0, 2.0**-1074]], np.longdouble)).tolist() == \
        [[0.5, -0.0, 2.0**-1074]]


@wider_long_double
def test_long_doubles_beyond_the_double_range_are_refused():
    huge = np.array([[np.longdouble("1e400"), 0, 0]])
    with pytest.raises(ValueError, match=not_exactly("vertices[0]", "the long double 1e+400 "
                                                   "(beyond the largest double)")):
        converted(huge)
    tiny = np.array([[np.longdouble(2.0**-1074) / 2, 0, 0]])
    with pytest.raises(ValueError, match="it lies between two doubles"):
        converted(tiny)


@pytest.mark.parametrize("value", [Fraction(1, 2), Decimal("0.5"), True, np.bool_(False),
                                   1 + 2j, "1", None], ids=repr)
def test_other_objects_are_not_real_numbers(value):
    with pytest.raises(TypeError, match=r"vertices must hold real numbers, got .* in vertices\[1\]"):
        converted(np.array([[0, 0, 0], [0, value, 0]], dtype=object))
    with pytest.raises(TypeError, match="must hold real numbers"):
        converted([[0, 0, 0], [0, value, 0]])


# Seeded: the decision for random values of every dtype against Python's exact one.

def random_magnitudes(rng, bits: int, n: int):
    """n random integers of at most `bits` bits, most beyond 2^53, each with a random
    number of trailing zeros (so that about half are doubles)."""
    values = []
    for _ in range(n):
        width = int(rng.integers(max(1, bits - 16), bits + 1))
        value = int(rng.integers(0, 2**62)) << max(0, width - 62)
        value = (value | (1 << (width - 1))) & ((1 << width) - 1)
        zeros = int(rng.integers(0, width + 1))
        values.append(value >> zeros << zeros)
    return values


@pytest.mark.parametrize("dtype", SIGNED + UNSIGNED, ids=lambda d: np.dtype(d).name)
def test_random_integers_of_every_dtype(rng, dtype):
    info = np.iinfo(dtype)
    values = random_magnitudes(rng, info.bits - (info.min < 0), 300)
    if info.min < 0:
        values += [-v for v in random_magnitudes(rng, info.bits - 1, 100)]
    values += [info.min, info.max, min(info.max, Z + 1), min(info.max, Z + 2)]
    values = [v for v in values if info.min <= v <= info.max]
    accepted = 0
    for value in values:
        x = np.array([[0, value, 0]], dtype=dtype)
        if exactly_double(value):
            assert as_fraction(converted(x)[0, 1]) == value
            accepted += 1
        else:
            with pytest.raises(ValueError, match=not_exactly("vertices[0]", str(value))):
                converted(x)
    if info.bits < 64:  # every value of a small integer is a double
        assert accepted == len(values)
    else:
        assert 0 < accepted < len(values)


def test_random_python_ints_in_lists(rng):
    values = random_magnitudes(rng, 70, 200) + random_magnitudes(rng, 1100, 100)
    values += [-v for v in random_magnitudes(rng, 64, 100)]
    for value in values:
        # Alone, beside a float (NumPy would make float64 of it) and in a tuple.
        for points, (row, column) in (([[value, 0, 0]], (0, 0)), ([[1, 2, 3], [0.5, -1, value]], (1, 2)),
                                      (((0, 0, value),), (0, 2))):
            if exactly_double(value):
                assert as_fraction(converted(points)[row, column]) == value
            else:
                with pytest.raises(ValueError, match=re.escape(
                        f"vertices[{row}] has a coordinate that is not exactly a double")):
                    converted(points)


@wider_long_double
def test_random_long_doubles(rng):
    nmant = np.finfo(np.longdouble).nmant + 1  # significand bits, the leading one included
    values = []
    for _ in range(400):
        significand = random_magnitudes(rng, nmant, 1)[0] | (1 << (nmant - 1))
        zeros = int(rng.integers(0, nmant))
        significand = significand >> zeros << zeros
        # Built from two halves that are doubles: np.longdouble(int) may round through one.
        exact = (np.longdouble(significand >> 32) * 2**32
                 + np.longdouble(significand & 0xFFFFFFFF))
        exponent = int(rng.integers(-1090, 1030))
        sign = 1 if rng.random() < 0.5 else -1
        values.append(sign * np.ldexp(exact, exponent - nmant + 1))
    decisions = [exactly_double(x) for x in values]
    assert any(decisions) and not all(decisions)
    for x, exact in zip(values, decisions):
        points = np.array([[1, 2, x]], dtype=np.longdouble)
        if exact:
            assert as_fraction(converted(points)[0, 2]) == as_fraction(x)
        else:
            with pytest.raises(ValueError, match=not_exactly("vertices[0]", "the long double")):
                converted(points)


# Corner indices: integers only, and the value as given when out of range.

@pytest.mark.parametrize("value", [np.float32(2.9), np.float16(2.9), Fraction(29, 10),
                                   Decimal("2.9"), 2.0, np.float64(2.0), Fraction(2),
                                   Decimal(2), True, np.bool_(True)],
                         ids=lambda v: f"{type(v).__name__}({v})")
def test_a_corner_that_is_not_an_integer_is_refused(value):
    message = re.escape(f"faces[1] holds a corner that is not an integer: {value!r}")
    faces = [[0, 1, 2], [0, 1, value]]
    with pytest.raises(ValueError, match=message):
        exactgeo.Mesh(CUBE_VERTICES, faces)
    with pytest.raises(ValueError, match=message):
        exactgeo.Mesh(CUBE_VERTICES, np.array(faces, dtype=object))
    with pytest.raises(ValueError, match=message):
        exactgeo.MeshCcd(faces)


@pytest.mark.parametrize("dtype", [np.float16, np.float32, np.float64, bool])
def test_an_index_array_of_another_dtype_is_refused(dtype):
    faces = np.array([[0, 1, 2]], dtype=dtype)
    with pytest.raises(ValueError, match="faces must hold integers, got dtype"):
        exactgeo.Mesh(CUBE_VERTICES, faces)
    with pytest.raises(ValueError, match="faces must hold integers, got dtype"):
        exactgeo.MeshCcd(faces)


@pytest.mark.parametrize("value", [2**63, 2**64 - 1])
def test_a_uint64_index_is_refused_as_given(value):
    faces = np.array([[0, 1, 2], [0, 1, value]], dtype=np.uint64)
    with pytest.raises(ValueError, match=re.escape(
            f"faces[1] has corner index {value}, but the vertices are 0..7")):
        exactgeo.Mesh(CUBE_VERTICES, faces)
    with pytest.raises(ValueError, match=re.escape(
            f"faces[1] has corner index {value}, but a vertex index is at most 4294967294")):
        exactgeo.MeshCcd(faces)
    with pytest.raises(ValueError, match=re.escape(f"faces[1] has corner index {value},")):
        exactgeo.Mesh(CUBE_VERTICES, [[0, 1, 2], [0, 1, value]])
    with pytest.raises(ValueError, match=re.escape(f"faces[0] has corner index {value},")):
        exactgeo.MeshCcd([[0, 1, value]], vertex_count=4)


def test_integer_indices_of_every_form_are_taken():
    quads = [[0, 2, 3, 1], [4, 5, 7, 6]]
    forms = [quads, [[np.int64(0), np.uint8(2), np.int16(3), np.uint64(1)], [4, 5, 7, 6]],
             np.array(quads, dtype=object)] + [np.array(quads, dtype=d) for d in SIGNED + UNSIGNED]
    for faces in forms:
        assert exactgeo.Mesh(CUBE_VERTICES, faces).faces.tolist() == quads
    triangles = [[0, 2, 3], [4, 5, 7]]
    forms = [triangles, [[np.int64(0), np.uint8(2), np.int16(3)], [4, np.uint64(5), 7]],
             np.array(triangles, dtype=object)]
    forms += [np.array(triangles, dtype=d) for d in SIGNED + UNSIGNED]
    for faces in forms:
        ccd = exactgeo.MeshCcd(faces)
        assert ccd.vertex_count == 8
        assert ccd.edges.tolist() == [[0, 2], [0, 3], [2, 3], [4, 5], [4, 7], [5, 7]]


def test_vertex_count_is_an_integer():
    for value in (np.float32(3.9), 4.0, Fraction(4), Decimal(4)):
        with pytest.raises(TypeError, match=re.escape(f"vertex_count must be an integer, got "
                                                      f"{value!r}")):
            exactgeo.MeshCcd([[0, 1, 2]], vertex_count=value)
    for value in (-1, 2**32, 2**64):
        with pytest.raises(ValueError, match=f"vertex_count must be in 0..4294967295, got {value}"):
            exactgeo.MeshCcd([[0, 1, 2]], vertex_count=value)
    assert exactgeo.MeshCcd([[0, 1, 2]], vertex_count=np.uint8(5)).vertex_count == 5


# Numeric options: converted as coordinates are, exactly or refused, naming the option.

_X = np.zeros((1, 4, 3))
_SHEET = [[0, 1, 2]]
_SHEET_X = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
OPTIONS = {
    "min_separation": lambda v: exactgeo.vertex_face_ccd(_X, _X, min_separation=v),
    "toi_width": lambda v: exactgeo.edge_edge_ccd(_X, _X, toi_width=v),
    "cubic_tolerance": lambda v: exactgeo.vertex_face_ccd(_X, _X, method="cubic",
                                                          cubic_tolerance=v),
    "toi": lambda v: exactgeo.MeshCcd(_SHEET).step(_SHEET_X, _SHEET_X, toi=v),
    "min_separation ": lambda v: exactgeo.MeshCcd(_SHEET).step(_SHEET_X, _SHEET_X,
                                                               min_separation=v),
}


@pytest.mark.parametrize("option", sorted(OPTIONS))
def test_numeric_options_are_exact_or_refused(option):
    call, name = OPTIONS[option], option.strip()
    # Not real numbers to the conversion, whatever their value: refused by type, never
    # rounded (Decimal("1e-400") once ran as 0).
    for value in (Decimal("1e-400"), Decimal("0.5"), Fraction(1, 3), Fraction(1, 2), "0.5",
                  1j, [0.5]):
        with pytest.raises(TypeError, match=re.escape(f"{name} must be a real number")):
            call(value)
    # Real numbers that are not exactly doubles: refused by value, with the way out.
    inexact = [2**53 + 1, np.int64(2**53 + 1), np.uint64(2**64 - 1), 10**400]
    if LONG_DOUBLE_IS_WIDER:
        inexact.append(np.longdouble(1) / 3)
    for value in inexact:
        with pytest.raises(ValueError, match=re.escape(f"{name} is not exactly a double")):
            call(value)
    for value in (float("nan"), np.float32("inf")):
        with pytest.raises(ValueError, match=f"{name} "):
            call(value)


def test_numeric_options_that_are_doubles_run_as_the_float():
    x0 = np.array([[[0.2, 0.2, 0.25], [0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    x1 = x0.copy()
    x1[0, 0, 2] = -0.25  # the vertex passes through the triangle
    for value in (np.float32(0.25), np.float16(0.25), np.longdouble(0.25), np.array(0.25)):
        assert exactgeo.vertex_face_ccd(x0, x0, min_separation=value)[0]
    assert not exactgeo.vertex_face_ccd(x0, x0, min_separation=np.float32(0.125))[0]
    # An int that is a double is taken as that double.
    assert exactgeo.vertex_face_ccd(x0 * 2**60, x0 * 2**60, min_separation=2**58)[0]
    hits, brackets = exactgeo.vertex_face_ccd(x0, x1, toi_width=np.float32(2**-10))
    same, reference = exactgeo.vertex_face_ccd(x0, x1, toi_width=2**-10)
    assert hits.tolist() == same.tolist() == [True]
    assert brackets.tolist() == reference.tolist()
    assert brackets[0, 0] <= 0.5 <= brackets[0, 1] and brackets[0, 1] - brackets[0, 0] <= 2**-10
    step = exactgeo.MeshCcd(_SHEET).step(_SHEET_X, _SHEET_X, toi=np.float64(0.5))
    assert not step.collision
