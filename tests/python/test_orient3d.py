"""exactgeo.orient3d on arrays against an exact rational oracle (Python's fractions),
on random, near-degenerate, exactly degenerate and extreme-magnitude inputs."""

from fractions import Fraction

import numpy as np
import pytest

import exactgeo


def oracle(a, b, c, d) -> int:
    """The sign of det[b - a, c - a, d - a] in exact rationals."""
    a, b, c, d = ([Fraction(float(x)) for x in p] for p in (a, b, c, d))
    u, v, w = ([p[k] - a[k] for k in range(3)] for p in (b, c, d))
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)


def cases(rng, n=400):
    """Rows of (a, b, c, d): random, d on the plane (a, b, c) exactly, d one ulp off a
    plane, tiny and huge magnitudes."""
    a, b, c, d = (rng.uniform(-1, 1, (n, 3)) for _ in range(4))
    groups = [(a, b, c, d)]
    # Exactly coplanar: d = a + (b - a) + (c - a) with small integer coordinates.
    ia, ib, ic = (rng.integers(-8, 8, (n, 3)).astype(float) for _ in range(3))
    groups.append((ia, ib, ic, ib + ic - ia))
    # One ulp from coplanar.
    near = ib + ic - ia
    groups.append((ia, ib, ic, np.nextafter(near, np.inf)))
    groups.append((ia, ib, ic, np.nextafter(near, -np.inf)))
    for scale in (2.0**-1060, 2.0**-1000, 2.0**500, 2.0**1000 / 64):
        groups.append((ia * scale, ib * scale, ic * scale, np.nextafter(near * scale, np.inf)))
        groups.append((a * scale, b * scale, c * scale, d * scale))
    return [np.concatenate(g) for g in zip(*groups)]


def test_exact_against_rationals(rng):
    a, b, c, d = cases(rng)
    signs = exactgeo.orient3d(a, b, c, d)
    assert signs.dtype == np.int8 and signs.shape == (len(a),)
    expected = np.array([oracle(*row) for row in zip(a, b, c, d)])
    assert np.array_equal(signs, expected)
    assert (expected == 0).sum() > 0 and (expected != 0).sum() > 0
    assert np.array_equal(exactgeo.orient3d(a, b, c, d, threads=1), signs)


def test_plain_double_is_not_exact(rng):
    """What the exact method is for: plain doubles get some near-degenerate signs wrong."""
    a, b, c, d = cases(rng)
    plain = exactgeo.orient3d(a, b, c, d, method="double")
    assert not np.array_equal(plain, exactgeo.orient3d(a, b, c, d))


def test_single_points():
    assert exactgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]) == 1
    assert exactgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, -1]) == -1
    assert exactgeo.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 7, 0]) == 0


def test_errors():
    ok = np.zeros((4, 3))
    with pytest.raises(ValueError, match=r"d has 3 rows, a has 4"):
        exactgeo.orient3d(ok, ok, ok, ok[:3])
    with pytest.raises(ValueError, match=r"c must have shape \(n, 3\)"):
        exactgeo.orient3d(ok, ok, ok[:, :2], ok)
    bad = ok.copy()
    bad[2, 0] = np.nan
    with pytest.raises(ValueError, match=r"b\[2\] has a non-finite coordinate"):
        exactgeo.orient3d(ok, bad, ok, ok)
    with pytest.raises(ValueError, match="method must be"):
        exactgeo.orient3d(ok, ok, ok, ok, method="rational")
