"""exactgeo on a Dask cluster: point sets and query sets larger than one machine.

    >>> from dask.distributed import Client
    >>> import dask.array as da, exactgeo.dask
    >>> client = Client("tcp://scheduler:8786")          # or Client() for a local cluster
    >>> points = da.from_zarr("points.zarr")              # (n, 3), chunked along n
    >>> labels = exactgeo.dask.classify("/shared/spot.obj", points)
    >>> counts = np.bincount(labels.compute(), minlength=3)

Each worker process loads the mesh and builds its classifier once, the first time one of
its tasks needs it, and reuses it for every later block: the search structure is never
pickled or sent over the network, only the mesh path. The cache is keyed by the file's
path, its content hash and the loading options, so a mesh file that changes between
computations is loaded again. The path must name the same file on every worker (a shared
or copied file system).
"""

import hashlib
import os
import threading
from typing import Dict, Iterable, Optional, Tuple

import dask
import dask.array as da
import numpy as np

from . import Classifier, edge_edge_ccd, load_mesh, read_ccd_queries, vertex_face_ccd

__all__ = ["classify", "ccd_files", "worker_cache"]


class _ClassifierCache:
    """This process's classifiers, by (path, content hash, options). A lock makes the
    first block that needs a mesh build it while the others wait for it."""

    def __init__(self):
        self._lock = threading.Lock()
        self._classifiers: Dict[tuple, Classifier] = {}
        self._hashes: Dict[tuple, str] = {}  # (path, size, mtime) -> content hash
        self.builds = 0
        self.blocks = 0

    def _content_hash(self, path: str) -> str:
        status = os.stat(path)
        key = (path, status.st_size, status.st_mtime_ns)
        if key not in self._hashes:
            digest = hashlib.sha256()
            with open(path, "rb") as f:
                for chunk in iter(lambda: f.read(1 << 20), b""):
                    digest.update(chunk)
            self._hashes[key] = digest.hexdigest()
        return self._hashes[key]

    def get(self, path: str, weld: bool, split_polygons: bool,
            allow_non_manifold: bool, rule: Optional[str]) -> Classifier:
        path = os.path.abspath(path)
        with self._lock:
            self.blocks += 1
            key = (path, self._content_hash(path), weld, split_polygons, allow_non_manifold,
                   rule)
            classifier = self._classifiers.get(key)
            if classifier is None:
                mesh = load_mesh(path, weld=weld, split_polygons=split_polygons)
                classifier = Classifier(mesh, rule=rule, allow_non_manifold=allow_non_manifold)
                self._classifiers[key] = classifier
                self.builds += 1
            return classifier


_cache = _ClassifierCache()


def worker_cache() -> dict:
    """This process's cache: classifiers built, blocks served, meshes held. On a cluster,
    `client.run(exactgeo.dask.worker_cache)` asks every worker."""
    return {"builds": _cache.builds, "blocks": _cache.blocks,
            "meshes": sorted({key[0] for key in _cache._classifiers})}


def _classify_block(block: np.ndarray, mesh_path: str, method: str, threads: int,
                    options: Tuple[bool, bool, bool, Optional[str]],
                    block_info: Optional[dict] = None) -> np.ndarray:
    classifier = _cache.get(mesh_path, *options)
    # Messages name a point by its row in the whole array, not in its block.
    first_row = block_info[0]["array-location"][0][0] if block_info else 0
    return classifier.classify(block, method=method, threads=threads, first_row=first_row)


_LIST_CHUNK = 1_000_000  # points per task when the points come as a list


def classify(mesh_path, points, *, method: str = "exact", threads: int = 1, weld: bool = False,
             split_polygons: bool = False, allow_non_manifold: bool = False,
             rule: Optional[str] = None) -> da.Array:
    """The location of every point (OUTSIDE, INSIDE, BOUNDARY; UNDECIDED against an open
    surface) as a lazy (n,) int8 array.

    mesh_path: a mesh file every worker can read (OBJ, OFF, PLY, STL exactly; others via
        assimp).
    points: a dask array (or anything dask.array.asarray takes) of shape (n, 3); its chunks
        along n become the tasks (a few hundred thousand to a few million points each).
        Coordinates are converted exactly or refused, as by Classifier.classify.
    method: "exact" (default) or "double".
    threads: threads per task; 1 by default, since Dask already runs one task per worker
        thread. Use 0 (all cores) with one worker thread per machine.
    weld, split_polygons, rule, allow_non_manifold: as for load_mesh and Classifier.

    A mesh that cannot be read or does not bound a solid fails the computation with the
    loader's or the classifier's message.
    """
    if isinstance(points, (list, tuple)):
        # NumPy would round a list's numbers into their common type (a Python int beside a
        # float becomes float64); as objects, each block reaches the binding as given and is
        # converted exactly or refused there. (Dask sizes no chunks of objects itself.)
        points = da.from_array(np.asarray(points, dtype=object), chunks=(_LIST_CHUNK, -1))
    points = da.asarray(points)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError(f"points must have shape (n, 3), got {points.shape}")
    points = points.rechunk({1: 3})
    return points.map_blocks(_classify_block, os.fspath(mesh_path), method, threads,
                             (weld, split_polygons, allow_non_manifold, rule), drop_axis=1,
                             dtype=np.int8, meta=np.empty((0,), np.int8))


_COUNTS = ("queries", "positives", "truth_positives", "false_positives", "false_negatives")


def _ccd_file(path: str, method: str, query_type: Optional[str]) -> Tuple[str, dict]:
    queries = read_ccd_queries(path, query_type)
    run = vertex_face_ccd if queries.type == "vertex-face" else edge_edge_ccd
    hits = run(queries.x0, queries.x1, method=method, threads=1)
    counts = dict.fromkeys(_COUNTS, 0)
    counts["queries"] = len(hits)
    counts["positives"] = int(hits.sum())
    if queries.truth is not None:
        counts["truth_positives"] = int(queries.truth.sum())
        counts["false_positives"] = int((hits & ~queries.truth).sum())
        counts["false_negatives"] = int((~hits & queries.truth).sum())
    return queries.type, counts


def _query_files(paths: Iterable) -> list:
    files = []
    for path in map(os.fspath, [paths] if isinstance(paths, (str, os.PathLike)) else paths):
        if os.path.isdir(path):
            files += sorted(os.path.join(root, name) for root, _, names in os.walk(path)
                            for name in names if name.endswith(".csv"))
        else:
            files.append(path)
    return files


def ccd_files(paths, *, method: str = "exact", type: Optional[str] = None) -> dict:
    """Runs CCD benchmark query files across the cluster, one task per file, and returns
    the counts per query type, as `exactgeo ccd --json` reports them:
    {"vertex-face": {"queries", "positives", "truth_positives", "false_positives",
    "false_negatives"}, "edge-edge": {...}}.

    paths: files, or folders whose *.csv files are all run (sorted), readable by every
        worker. The query type comes from each path unless `type` names it.
    """
    tasks = [dask.delayed(_ccd_file)(f, method, type) for f in _query_files(paths)]
    totals = {t: dict.fromkeys(_COUNTS, 0) for t in ("vertex-face", "edge-edge")}
    for query_type, counts in dask.compute(*tasks):
        for key, value in counts.items():
            totals[query_type][key] += value
    return totals
