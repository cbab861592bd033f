# Type stub of the compiled extension (python/src); tests/python/test_package.py checks
# that it names exactly what the module defines.
from os import PathLike
from typing import Any, Dict, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
OUTSIDE: int
INSIDE: int
BOUNDARY: int
UNDECIDED: int
ON_SURFACE: int

_Path = Union[str, PathLike[str]]
_Points = npt.ArrayLike

class Mesh:
    def __init__(
        self, vertices: _Points, faces: Union[npt.ArrayLike, Sequence[Sequence[int]]]
    ) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def face_count(self) -> int: ...
    @property
    def format(self) -> str: ...
    def info(self) -> dict[str, Any]: ...

def load_mesh(
    path: _Path, *, weld: bool = False, split_polygons: bool = False, format: str | None = None
) -> Mesh: ...

class Classifier:
    def __init__(
        self, mesh: Mesh, *, rule: Optional[str] = None, allow_non_manifold: bool = False,
        space_cells: bool = True, threads: int = 0
    ) -> None: ...
    @property
    def rule(self) -> str: ...
    @property
    def threads(self) -> int: ...
    def winding_numbers(
        self, points: _Points, *, method: str = "exact", threads: Optional[int] = None
    ) -> npt.NDArray[np.int32]: ...
    def classify(
        self, points: _Points, *, method: str = "exact", threads: Optional[int] = None
    ) -> npt.NDArray[np.int8]: ...
    def contains(
        self, points: _Points, *, boundary: bool = True, method: str = "exact",
        threads: Optional[int] = None
    ) -> npt.NDArray[np.bool_]: ...

@overload
def vertex_face_ccd(
    x0: _Points, x1: _Points, *, method: str = "exact", toi_width: None = None,
    cubic_tolerance: float = 1e-6, threads: int = 0, min_separation: float = 0.0,
) -> npt.NDArray[np.bool_]: ...
@overload
def vertex_face_ccd(
    x0: _Points, x1: _Points, *, method: str = "exact", toi_width: float,
    cubic_tolerance: float = 1e-6, threads: int = 0, min_separation: float = 0.0,
) -> Tuple[npt.NDArray[np.bool_], npt.NDArray[np.float64]]: ...
@overload
def edge_edge_ccd(
    x0: _Points, x1: _Points, *, method: str = "exact", toi_width: None = None,
    cubic_tolerance: float = 1e-6, threads: int = 0, min_separation: float = 0.0,
) -> npt.NDArray[np.bool_]: ...
@overload
def edge_edge_ccd(
    x0: _Points, x1: _Points, *, method: str = "exact", toi_width: float,
    cubic_tolerance: float = 1e-6, threads: int = 0, min_separation: float = 0.0,
) -> Tuple[npt.NDArray[np.bool_], npt.NDArray[np.float64]]: ...
def _read_ccd_queries(
    path: _Path, type: Optional[str] = None
) -> Tuple[str, npt.NDArray[np.float64], npt.NDArray[np.float64], Optional[npt.NDArray[np.bool_]]]: ...

class MeshCcdStep:
    @property
    def vertex_face(self) -> npt.NDArray[np.uint32]: ...
    @property
    def edge_edge(self) -> npt.NDArray[np.uint32]: ...
    @property
    def time_of_impact(self) -> Optional[Tuple[float, float]]: ...
    @property
    def vertex_face_candidates(self) -> int: ...
    @property
    def edge_edge_candidates(self) -> int: ...
    @property
    def broad_phase_seconds(self) -> float: ...
    @property
    def narrow_phase_seconds(self) -> float: ...
    @property
    def collision(self) -> bool: ...

class MeshCcd:
    def __init__(self, faces: npt.ArrayLike, vertex_count: Optional[int] = None) -> None: ...
    def step(
        self, x0: _Points, x1: _Points, *, method: str = "exact",
        toi: Union[bool, float] = False, threads: int = 0, min_separation: float = 0.0,
    ) -> MeshCcdStep: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def edges(self) -> npt.NDArray[np.uint32]: ...

# orient3d: the sign of det[b - a, c - a, d - a]. Positive when d lies on the side of the
# plane (a, b, c) from which a, b, c appear counter-clockwise (the side (b - a) x (c - a)
# points to): orient3d((0,0,0), (1,0,0), (0,1,0), (0,0,1)) is positive.
@overload
def orient3d(a: Sequence[float], b: Sequence[float], c: Sequence[float], d: Sequence[float], *,
             method: str = "exact", threads: int = 0) -> int: ...
@overload
def orient3d(a: _Points, b: _Points, c: _Points, d: _Points, *,
             method: str = "exact", threads: int = 0) -> npt.NDArray[np.int8]: ...

_Outcome = Dict[str, Any]

class Surface:
    def __init__(
        self, vertices: _Points, triangles: npt.ArrayLike, *,
        fixed: Optional[npt.ArrayLike] = None
    ) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def triangles(self) -> npt.NDArray[np.uint32]: ...
    def relocate_vertex(self, vertex: int, to: Sequence[float]) -> _Outcome: ...
    def relocate_vertices(self, indices: npt.ArrayLike, targets: _Points) -> npt.NDArray[np.bool_]: ...
    def collapse_edge(self, a: int, b: int, to: Sequence[float]) -> _Outcome: ...
    def flip_edge(self, a: int, b: int) -> _Outcome: ...
    def split_edge(self, a: int, b: int, at: Sequence[float]) -> _Outcome: ...
