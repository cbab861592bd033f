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

For a data set of many meshes, `classify_meshes` runs one task per mesh and writes one
labels file per mesh:

    >>> results = exactgeo.dask.classify_meshes("/shared/shapes", grid, "/shared/labels")
"""

import hashlib
import os
import threading
from typing import Dict, Iterable, List, Optional, Tuple, Union

import dask
import dask.array as da
import numpy as np

from . import (BOUNDARY, INSIDE, OUTSIDE, UNDECIDED, Classifier, edge_edge_ccd, load_mesh,
               read_ccd_queries, vertex_face_ccd)

__all__ = ["classify", "classify_meshes", "ccd_files", "worker_cache"]


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


#: The extensions a folder's files are taken as meshes by (lower case): the formats read
#: exactly, then assimp's common ones.
MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl", ".glb", ".gltf", ".fbx", ".dae", ".3ds",
                   ".amf", ".3mf")
LABELS_SUFFIX = ".labels.npy"


def _mesh_outputs(meshes, output_dir: str) -> List[Tuple[str, str]]:
    """(mesh path, labels file) for every mesh: a file as given, a folder's mesh files
    (MESH_EXTENSIONS, walked recursively, sorted), each labels file named after the mesh,
    under the folder's relative path for a folder's meshes. Two meshes whose labels files
    would be one are refused before anything runs."""
    pairs: List[Tuple[str, str]] = []
    for given in map(os.fspath, [meshes] if isinstance(meshes, (str, os.PathLike)) else meshes):
        if os.path.isdir(given):
            found = sorted(os.path.join(root, name) for root, _, names in os.walk(given)
                           for name in names if os.path.splitext(name)[1].lower()
                           in MESH_EXTENSIONS)
            if not found:
                raise ValueError(f"{given}: no mesh file in this folder (extensions: "
                                 f"{', '.join(MESH_EXTENSIONS)})")
            for path in found:
                relative = os.path.splitext(os.path.relpath(path, given))[0]
                pairs.append((path, os.path.join(output_dir, relative + LABELS_SUFFIX)))
        else:
            stem = os.path.splitext(os.path.basename(given))[0]
            pairs.append((given, os.path.join(output_dir, stem + LABELS_SUFFIX)))
    seen: Dict[str, str] = {}
    for mesh, labels in pairs:
        if labels in seen:
            raise ValueError(f"{seen[labels]} and {mesh} would both write {labels}: give "
                             "their folder instead (labels files then keep the folders' "
                             "relative paths)")
        seen[labels] = mesh
    return pairs


def _classify_mesh_to_file(mesh_path: str, labels_path: str, points, method: str,
                           threads: int, options: Tuple[bool, bool, bool, Optional[str]]) -> dict:
    """One mesh's task: its labels written whole to `labels_path` (int8 .npy, in the
    points' order), or nothing written and the error returned."""
    weld, split_polygons, allow_non_manifold, rule = options
    summary = {"mesh": mesh_path, "labels": None}
    try:
        if isinstance(points, str):  # a pattern: this mesh's own points file
            points = np.load(points.format(mesh=os.path.splitext(mesh_path)[0]))
        mesh = load_mesh(mesh_path, weld=weld, split_polygons=split_polygons)
        classifier = Classifier(mesh, rule=rule, allow_non_manifold=allow_non_manifold)
        labels = classifier.classify(points, method=method, threads=threads)
        os.makedirs(os.path.dirname(labels_path) or ".", exist_ok=True)
        temporary = f"{labels_path}.{os.getpid()}.{threading.get_ident()}.tmp"
        try:
            with open(temporary, "wb") as f:
                np.save(f, labels)
            os.replace(temporary, labels_path)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
    except Exception as e:  # noqa: BLE001 - reported per mesh, the others go on
        summary["error"] = f"{type(e).__name__}: {e}"
        return summary
    summary["labels"] = labels_path
    summary["points"] = int(len(labels))
    for name, value in (("inside", INSIDE), ("outside", OUTSIDE), ("boundary", BOUNDARY),
                        ("undecided", UNDECIDED)):
        summary[name] = int(np.count_nonzero(labels == value))
    return summary


def classify_meshes(meshes, points: Union[str, np.ndarray], output_dir, *,
                    method: str = "exact", threads: int = 1, weld: bool = False,
                    split_polygons: bool = False, allow_non_manifold: bool = False,
                    rule: Optional[str] = None, errors: str = "raise") -> List[dict]:
    """Classifies points against every mesh of a data set, one task per mesh, and writes
    one labels file per mesh: what `exactgeo.dask.classify` does for one large mesh and
    point set, for many meshes.

    meshes: mesh files and/or folders (every file with an extension of MESH_EXTENSIONS,
        in every subfolder, sorted), readable by every worker.
    points: the same (n, 3) points for every mesh (an array, sent to the workers once),
        or a pattern naming each mesh's own .npy points file, "{mesh}" standing for the
        mesh's path without its extension: "{mesh}.points.npy" reads chair.points.npy for
        chair.obj.
    output_dir: where the labels go: for each mesh an int8 .npy array (OUTSIDE, INSIDE,
        BOUNDARY, UNDECIDED) in the points' order, named after the mesh with the suffix
        ".labels.npy" (chair.obj: chair.labels.npy), a folder's meshes under their path
        relative to it (so that a data set's many model.obj files do not collide). Each
        file is written whole or not at all. It must be writable by every worker.
    method, threads, weld, split_polygons, allow_non_manifold, rule: as for classify.
    errors: "raise" (default): once every mesh has been tried, a ValueError naming each
        mesh that failed and why (the other meshes' files are written); "report": no
        exception, the failures are in the returned list.

    Returns one dict per mesh, in order: "mesh", "labels" (the file, None when it failed),
    "points" and the count of each label, or "error" (the exception's type and message).
    """
    if errors not in ("raise", "report"):
        raise ValueError(f"errors must be 'raise' or 'report', not {errors!r}")
    output_dir = os.fspath(output_dir)
    pairs = _mesh_outputs(meshes, output_dir)
    if not isinstance(points, str):
        points = np.asarray(points)
        if points.ndim != 2 or points.shape[1] != 3:
            raise ValueError(f"points must have shape (n, 3), got {points.shape}")
        points = dask.delayed(points, pure=True)  # one copy in the graph, not one per mesh
    options = (weld, split_polygons, allow_non_manifold, rule)
    tasks = [dask.delayed(_classify_mesh_to_file, pure=False)(mesh, labels, points, method,
                                                                threads, options)
             for mesh, labels in pairs]
    results = list(dask.compute(*tasks))
    failed = [r for r in results if "error" in r]
    if failed and errors == "raise":
        written = f" (the others' labels are in {output_dir})" if len(failed) < len(results) else ""
        raise ValueError(f"{len(failed)} of {len(results)} meshes failed{written}: " +
                         "; ".join(f"{r['mesh']}: {r['error']}" for r in failed))
    return results


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
