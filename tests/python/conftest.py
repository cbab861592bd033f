"""Shared fixtures: the package under test, the command-line tool of the same build (the
reference the bindings are compared with), the bundled data, and a printed seed."""

import json
import os
import random
import subprocess
from pathlib import Path

import numpy as np
import pytest

DATA = Path(os.environ.get("EXACTGEO_TEST_DATA", Path(__file__).resolve().parents[1] / "data"))
MESHES = DATA / "meshes"
CCD = DATA / "ccd"


def pytest_report_header(config):
    return f"EXACTGEO_TEST_SEED={_seed()} (set it to repeat a run)"


def _seed() -> int:
    if "EXACTGEO_TEST_SEED" not in os.environ:
        os.environ["EXACTGEO_TEST_SEED"] = str(random.SystemRandom().randrange(2**32))
    return int(os.environ["EXACTGEO_TEST_SEED"])


@pytest.fixture
def rng(request):
    """A generator seeded from EXACTGEO_TEST_SEED and the test's name, printed on failure."""
    seed = _seed()
    print(f"EXACTGEO_TEST_SEED={seed}")
    return np.random.default_rng([seed, sum(map(ord, request.node.name))])


class Cli:
    """The exactgeo command-line tool of the same build."""

    def __init__(self, path: str):
        self.path = path

    def run(self, *args, stdin: str = None) -> subprocess.CompletedProcess:
        return subprocess.run([self.path, *map(str, args)], input=stdin, capture_output=True,
                              text=True, check=False)

    def json(self, *args, stdin: str = None):
        done = self.run(*args, "--json", stdin=stdin)
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("EXACTGEO_CLI")
    if not path:
        pytest.skip("EXACTGEO_CLI is not set (ctest sets it)")
    return Cli(path)


def points_text(points: np.ndarray) -> str:
    """Points as text the CLI reads back bit for bit (hexfloats)."""
    return "".join(" ".join(float(x).hex() for x in p) + "\n" for p in points)


def write_obj(path: Path, vertices: np.ndarray, faces) -> None:
    """An OBJ file holding exactly these coordinates (repr round-trips a double)."""
    with open(path, "w") as f:
        for v in vertices:
            f.write("v " + " ".join(repr(float(x)) for x in v) + "\n")
        for face in faces:
            f.write("f " + " ".join(str(int(i) + 1) for i in face) + "\n")
