"""exactgeo.vertex_face_ccd / edge_edge_ccd and read_ccd_queries: the command line's
answer for every bundled query and method, and every input form checked."""

import csv
from fractions import Fraction

import numpy as np
import pytest

import exactgeo
from conftest import CCD

QUERY_FILES = sorted(CCD.rglob("*.csv"))
CCD_FUNCTIONS = {"vertex-face": exactgeo.vertex_face_ccd, "edge-edge": exactgeo.edge_edge_ccd}


def cli_answers(cli, path, method, tmp_path):
    """The command line's answer for every query of the file, in order."""
    per_query = tmp_path / "per-query.csv"
    done = cli.run("ccd", path, "--method", method, "--per-query", per_query)
    assert done.returncode in (0, 1), done.stderr  # 1: some answer disagrees with the truth
    with open(per_query) as f:
        return np.array([row["result"] == "1" for row in csv.DictReader(f)])


@pytest.mark.parametrize("path", QUERY_FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
@pytest.mark.parametrize("method", ["exact", "parity", "double", "cubic"])
def test_answers_match_the_command_line(cli, tmp_path, path, method):
    queries = exactgeo.read_ccd_queries(path)
    assert queries.x0.shape == queries.x1.shape == (len(queries.x0), 4, 3)
    answers = CCD_FUNCTIONS[queries.type](queries.x0, queries.x1, method=method)
    assert answers.dtype == np.bool_
    assert np.array_equal(answers, cli_answers(cli, path, method, tmp_path))
    if method == "exact":  # exact: no false positive, no false negative
        assert queries.truth is not None
        assert np.array_equal(answers, queries.truth)


def test_a_folder_reads_as_its_files_in_order():
    folder = CCD / "sample-queries" / "unit-tests" / "edge-edge"
    whole = exactgeo.read_ccd_queries(folder)
    parts = [exactgeo.read_ccd_queries(p) for p in sorted(folder.glob("*.csv"))]
    assert whole.type == "edge-edge"
    assert np.array_equal(whole.x0, np.concatenate([p.x0 for p in parts]))
    assert np.array_equal(whole.truth, np.concatenate([p.truth for p in parts]))
    with pytest.raises(ValueError, match="both vertex-face and edge-edge"):
        exactgeo.read_ccd_queries(CCD / "sample-queries" / "unit-tests")


def test_time_of_impact_brackets():
    queries = exactgeo.read_ccd_queries(CCD / "scalable-ccd-data" / "cloth-funnel" / "queries" /
                                        "227vf.csv")
    hits, brackets = exactgeo.vertex_face_ccd(queries.x0, queries.x1, toi_width=1e-4)
    assert np.array_equal(hits, exactgeo.vertex_face_ccd(queries.x0, queries.x1))
    assert brackets.shape == (len(hits), 2)
    assert np.all(np.isnan(brackets[~hits]))
    start, end = brackets[hits].T
    assert np.all((0 <= start) & (start <= end) & (end <= 1) & (end - start <= 1e-4))
    # The bracket's promise, checked on the step cut at its ends: no contact in [0, start],
    # none missed, a contact in [0, end]. The cut positions x0 + t (x1 - x0) are used only
    # where they are exact doubles (checked in rationals), so each cut step is the same
    # motion as the original one.
    checked = 0
    for i in np.flatnonzero(hits & (brackets[:, 0] > 0)):
        cuts = [exact_position(queries.x0[i], queries.x1[i], t) for t in brackets[i]]
        if any(c is None for c in cuts):
            continue
        x0 = queries.x0[i][None]
        assert not exactgeo.vertex_face_ccd(x0, cuts[0][None])[0]
        assert exactgeo.vertex_face_ccd(x0, cuts[1][None])[0]
        checked += 1
    assert checked > 0


def exact_position(x0: np.ndarray, x1: np.ndarray, t: float):
    """x0 + t (x1 - x0) as doubles, or None where that is not exactly representable."""
    t = Fraction(t)
    exact = [Fraction(a) + t * (Fraction(b) - Fraction(a)) for a, b in zip(x0.ravel(), x1.ravel())]
    rounded = np.array([float(x) for x in exact])
    if any(Fraction(r) != x for r, x in zip(rounded, exact)):
        return None
    return rounded.reshape(x0.shape)


def test_input_forms_and_errors():
    queries = exactgeo.read_ccd_queries(CCD / "sample-queries" / "unit-tests" / "vertex-face")
    expected = exactgeo.vertex_face_ccd(queries.x0, queries.x1)
    assert np.array_equal(exactgeo.vertex_face_ccd(queries.x0.tolist(), queries.x1.tolist()),
                          expected)
    assert np.array_equal(exactgeo.vertex_face_ccd(np.asfortranarray(queries.x0), queries.x1,
                                                   threads=1), expected)
    empty = exactgeo.vertex_face_ccd(np.empty((0, 4, 3)), np.empty((0, 4, 3)))
    assert empty.shape == (0,) and empty.dtype == np.bool_

    x0 = queries.x0.copy()
    x0[3, 1, 2] = np.nan
    with pytest.raises(ValueError, match=r"x0\[3\] has a non-finite coordinate"):
        exactgeo.vertex_face_ccd(x0, queries.x1)
    with pytest.raises(ValueError, match=r"x1 must have shape \(n, 4, 3\), got"):
        exactgeo.vertex_face_ccd(queries.x0, queries.x1[:, :3])
    with pytest.raises(ValueError, match="x0 has .* queries, x1 has"):
        exactgeo.edge_edge_ccd(queries.x0, queries.x1[1:])
    with pytest.raises(ValueError, match="method must be"):
        exactgeo.vertex_face_ccd(queries.x0, queries.x1, method="fast")
    with pytest.raises(ValueError, match="toi_width needs method='exact'"):
        exactgeo.vertex_face_ccd(queries.x0, queries.x1, method="parity", toi_width=1e-3)
    with pytest.raises(ValueError, match="toi_width must be in"):
        exactgeo.vertex_face_ccd(queries.x0, queries.x1, toi_width=0.0)


def test_query_file_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        exactgeo.read_ccd_queries(tmp_path / "missing-vf.csv")
    bad = tmp_path / "bad_vf.csv"
    bad.write_text("1,1,2,1,3,1\n" * 7 + "1,3,2,1,3,1\n")  # 1/3 is not a double
    with pytest.raises(ValueError, match=r"bad_vf.csv:8: "):
        exactgeo.read_ccd_queries(bad)
    with pytest.raises(ValueError, match="type must be"):
        exactgeo.read_ccd_queries(bad, type="vf")


def test_command_line_query_times_cover_every_query_once(cli):
    """`exactgeo ccd --json`: each type's time distribution counts that type's queries, and
    the per-stage distributions count the queries each stage decided."""
    report = cli.json("ccd", CCD)
    for scope in (report, report["vertex_face"], report["edge_edge"]):
        times = scope["query_ns"]
        assert times["all"]["queries"] == scope["queries"]
        for stage, count in scope["stages"].items():
            assert (times[stage]["queries"] if stage in times else 0) == count, stage
        assert times["all"]["median"] <= times["all"]["p99"] <= times["all"]["max"]


def test_min_separation_matches_the_command_line_and_contains_every_contact(cli, tmp_path):
    for path in QUERY_FILES:
        queries = exactgeo.read_ccd_queries(path)
        run = CCD_FUNCTIONS[queries.type]
        per_query = tmp_path / "per-query.csv"
        done = cli.run("ccd", path, "--min-separation", "0.01", "--per-query", per_query)
        assert done.returncode == 0, done.stderr
        with open(per_query) as f:
            expected = np.array([row["result"] == "1" for row in csv.DictReader(f)])
        within = run(queries.x0, queries.x1, min_separation=0.01)
        np.testing.assert_array_equal(within, expected, err_msg=str(path))
        contacts = run(queries.x0, queries.x1)
        assert np.all(within[contacts]), path  # a contact is within every separation
        hits, brackets = run(queries.x0, queries.x1, min_separation=0.01, toi_width=1e-3)
        np.testing.assert_array_equal(hits, within)
        assert np.all(brackets[hits, 1] - brackets[hits, 0] <= 1e-3)


def test_min_separation_errors():
    x = np.zeros((1, 4, 3))
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="min_separation"):
            exactgeo.vertex_face_ccd(x, x, min_separation=bad)
    with pytest.raises(ValueError, match="min_separation needs"):
        exactgeo.edge_edge_ccd(x, x, method="parity", min_separation=0.1)
    # A vertex 0.3 above a face: within 0.3, not within the double just below.
    x0 = np.array([[[0.2, 0.2, 0.3], [0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    assert exactgeo.vertex_face_ccd(x0, x0, min_separation=0.3)[0]
    assert not exactgeo.vertex_face_ccd(x0, x0, min_separation=np.nextafter(0.3, 0))[0]
