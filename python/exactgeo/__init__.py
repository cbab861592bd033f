"""exactgeo: geometrically exact predicates for Python.

Point-in-volume classification against closed meshes of quads (bilinear patches) and
triangles, continuous collision detection (vertex-face, edge-edge, whole meshes) and
orient3d, on NumPy arrays. Every answer of the default method ("exact") is exact for
every finite input; the other methods are there to measure what exactness costs.

    >>> import exactgeo, numpy as np
    >>> mesh = exactgeo.load_mesh("spot.obj")
    >>> classifier = exactgeo.Classifier(mesh)
    >>> labels = classifier.classify(np.random.rand(1000, 3))   # OUTSIDE, INSIDE, BOUNDARY (UNDECIDED: open surfaces)

exactgeo.dask runs the same classification over Dask arrays on a cluster.
"""

from typing import NamedTuple, Optional

import numpy as np

from ._exactgeo import (
    BOUNDARY,
    INSIDE,
    ON_SURFACE,
    OUTSIDE,
    UNDECIDED,
    Classifier,
    Mesh,
    MeshCcd,
    MeshCcdStep,
    Surface,
    __version__,
    _read_ccd_queries,
    edge_edge_ccd,
    load_mesh,
    orient3d,
    vertex_face_ccd,
)

__all__ = [
    "BOUNDARY",
    "INSIDE",
    "ON_SURFACE",
    "OUTSIDE",
    "UNDECIDED",
    "CcdQueries",
    "Classifier",
    "Mesh",
    "MeshCcd",
    "MeshCcdStep",
    "Surface",
    "__version__",
    "edge_edge_ccd",
    "load_mesh",
    "orient3d",
    "read_ccd_queries",
    "vertex_face_ccd",
]


class CcdQueries(NamedTuple):
    """The queries of a CCD benchmark file, ready for vertex_face_ccd / edge_edge_ccd."""

    type: str  #: "vertex-face" or "edge-edge"
    x0: np.ndarray  #: (n, 4, 3) float64, positions at the start of the step
    x1: np.ndarray  #: (n, 4, 3) float64, positions at the end of the step
    truth: Optional[np.ndarray]  #: (n,) bool ground truth, or None when the file has none


def read_ccd_queries(path, type: Optional[str] = None) -> CcdQueries:
    """Reads a CCD query file of the public benchmark (Wang et al. 2021), or every *.csv
    of a folder of one query type.

    Each query is 8 rows of exact rationals (x_num, x_den, y_num, ...); every coordinate
    must be exactly a double. The type comes from the path (a `vertex-face` or `edge-edge`
    folder, or a file stem ending in vf/ee) unless `type` names it. The ground truth is
    the 7th column, else the published `../mma_bool/<stem>_mma_bool.json`, else None.

    Raises OSError when the file cannot be opened, ValueError with the file and line for
    malformed content.
    """
    kind, x0, x1, truth = _read_ccd_queries(path, type)
    return CcdQueries(kind, x0, x1, truth)


def __getattr__(name):
    # `exactgeo.dask` is imported on first use, so that `import exactgeo` needs no Dask.
    if name == "dask":
        import importlib

        return importlib.import_module(".dask", __name__)
    raise AttributeError(f"module 'exactgeo' has no attribute {name!r}")
