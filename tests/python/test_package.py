"""The package as a whole: its version, its type stub, its docstrings."""

import ast
import inspect
import re
from pathlib import Path

import exactgeo
from exactgeo import _exactgeo


def stub_names() -> dict:
    """Top-level names of the stub, and the members of each class it declares."""
    tree = ast.parse(Path(_exactgeo.__file__).with_name("_exactgeo.pyi").read_text())
    names = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        elif isinstance(node, ast.FunctionDef):
            names[node.name] = None
        elif isinstance(node, ast.AnnAssign):
            names[node.target.id] = None
    return names


def test_version():
    assert re.fullmatch(r"\d+\.\d+\.\d+", exactgeo.__version__)


def test_the_stub_declares_exactly_what_the_module_defines():
    stub = stub_names()
    module = {n for n in dir(_exactgeo) if not n.startswith("__") or n == "__version__"}
    assert set(stub) == module
    for name, members in stub.items():
        if members is None:
            continue
        defined = {n for n in vars(getattr(_exactgeo, name)) if not n.startswith("_")}
        assert members - {"__init__"} == defined, name


def prose(doc: str) -> str:
    """A docstring without the signature lines pybind11 writes into every one (a function
    bound without a docstring still has those)."""
    return "\n".join(line for line in (doc or "").splitlines()
                     if not re.match(r"^\s*(\d+\. )?\w+\(.*\)( -> .*)?$", line)).strip()


def test_every_public_name_is_documented():
    undocumented = []
    for name in exactgeo.__all__:
        obj = getattr(exactgeo, name)
        if not callable(obj):
            continue
        if not prose(inspect.getdoc(obj)):
            undocumented.append(name)
        if inspect.isclass(obj):
            for member, value in vars(obj).items():
                if not member.startswith("_") and callable(value) and not prose(value.__doc__):
                    undocumented.append(f"{name}.{member}")
    assert not undocumented
    assert not prose("orient3d(a: object) -> int\n"), "a bare signature must not count"


def test_the_tour_in_the_docs_runs(monkeypatch, capsys):
    """docs/python.md's tour is executed as written, from the repository root."""
    root = Path(__file__).resolve().parents[2]
    text = (root / "docs" / "python.md").read_text()
    tour = re.search(r"```python\n(import numpy as np\nimport exactgeo\n.*?)```", text, re.S)
    assert tour, "docs/python.md has no tour"
    monkeypatch.chdir(root)
    exec(compile(tour.group(1), "docs/python.md", "exec"), {})
    printed = capsys.readouterr().out.split("\n")
    assert printed[0] == "True"
    assert printed[-2].endswith(", 0.5)")  # contact at t = 0.5: the bracket ends there


def test_the_readme_example_runs(monkeypatch):
    root = Path(__file__).resolve().parents[2]
    example = re.search(r"```python\n(.*?)```", (root / "README.md").read_text(), re.S)
    assert example, "README.md has no Python example"
    monkeypatch.chdir(root)
    scope = {}
    exec(compile(example.group(1), "README.md", "exec"), scope)
    assert scope["labels"].shape == (1_000_000,)
    assert set(scope["labels"].tolist()) == {exactgeo.OUTSIDE, exactgeo.INSIDE}
