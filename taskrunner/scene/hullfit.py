"""How far a link mesh's convex hull stands off the mesh: the test of a tight hull.

A convex hull is exact for a convex mesh and fatter for a concave one: the UR5's upper
arm and forearm hulls bridge their hollows and stand up to 4 cm off the mesh. The
*excess* of a hull is the largest distance from a point of the hull's surface to the
mesh's surface (a one-sided Hausdorff distance: every mesh point lies on or inside the
hull). It is estimated at every hull face's centroid and at points sampled (area-weighted, seeded) on
the faces that stand off the mesh, each measured to the mesh's triangles with coal; sampling makes
the estimate a lower bound that is within a fraction of a millimetre of the true value
on the meshes measured (UR5, so_arm, z1, Panda).

Measuring costs about 10 µs per sample on a mesh of a few thousand triangles (1 to 2 s for
the so_arm's 17 meshes of up to 50 000 triangles), so results are kept in memory and in
``hull_excess.json`` under the user cache folder
(:func:`taskrunner.resources.user_cache_dir`), keyed by a hash of the mesh's vertices:
the second load of a robot reads them back.
"""

from __future__ import annotations

import hashlib
import json
import logging
import threading
from pathlib import Path

import coal
import numpy as np

from taskrunner.errors import SceneError
from taskrunner.resources import merge_json_cache, user_cache_dir

__all__ = ["CACHE_FILE", "convex_hull", "hull_excess", "measure_hull_excess", "shared_convex_hull"]

log = logging.getLogger(__name__)

CACHE_FILE = "hull_excess.json"
# Changing how the excess is measured must not reuse old numbers.
_METHOD = "v2-centroids+600"
_SAMPLES = 600
# A hull face whose centroid is this close to the mesh (m) is taken as lying on it (a
# convex mesh's hull faces are its triangles, give or take its modeller's rounding).
_ON_MESH = 5e-4

_lock = threading.Lock()
_memory: dict[str, float] = {}
_hulls: dict[str, coal.Convex | None] = {}
_disk_loaded: set[Path] = set()


def convex_hull(mesh: coal.BVHModelBase) -> coal.Convex:
    """The convex hull of a triangle mesh's vertices, as a coal convex polytope.

    Built with scipy's Qhull because this coal wheel is compiled without it
    (``coal.WITH_QHULL`` is false, so ``buildConvexHull`` would keep every vertex).

    Raises:
        SceneError: the mesh is flat or degenerate (no 3-D hull), or coal refuses the hull
            (its polytopes allow at most 255 neighbours a vertex: a wheel's flat face of
            hundreds of rim vertices, triangulated as a fan, has one vertex with more).
    """
    from scipy.spatial import ConvexHull, QhullError  # here: 40-80 ms to import, often unused

    vertices = np.array(mesh.vertices(), dtype=float)
    try:
        hull = ConvexHull(vertices)
    except (QhullError, ValueError) as exc:
        raise SceneError(f"mesh has no 3-D convex hull ({len(vertices)} vertices): {exc}") from None
    renumber = {int(v): i for i, v in enumerate(hull.vertices)}
    points = coal.StdVec_Vec3s()
    for v in hull.vertices:
        points.append(vertices[v])
    triangles = coal.StdVec_Triangle()
    for a, b, c in hull.simplices:
        triangles.append(coal.Triangle(renumber[int(a)], renumber[int(b)], renumber[int(c)]))
    try:
        return coal.Convex(points, triangles)
    except RuntimeError as exc:  # coal's own checks of the polytope ("Too many neighbors.")
        reason = str(exc).strip().splitlines()[-1].removeprefix("message: ")
        raise SceneError(f"coal cannot use the mesh's convex hull ({len(hull.vertices)} "
                         f"vertices): {reason}") from None


def measure_hull_excess(mesh: coal.BVHModelBase, samples: int = _SAMPLES) -> float:
    """The largest distance (m) from the mesh's convex hull surface to the mesh surface,
    estimated at every hull face's centroid and at ``samples`` seeded points spread by
    area over the faces that stand off the mesh (a face whose centroid lies within 0.5 mm
    of the mesh is taken as one of its triangles: a convex mesh costs one probe per hull
    face).

    Returns:
        The excess in m; ``inf`` for a mesh with no 3-D hull (flat or degenerate).
    """
    from scipy.spatial import ConvexHull, QhullError

    vertices = np.array(mesh.vertices(), dtype=float)
    try:
        hull = ConvexHull(vertices)
    except (QhullError, ValueError):
        return float("inf")
    corners = vertices[hull.simplices]  # (faces, 3, 3)
    areas = 0.5 * np.linalg.norm(
        np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    if not areas.sum() > 0:
        return float("inf")
    probe = _Probe(mesh)
    centroid_distance = np.array([probe.distance(c) for c in corners.mean(axis=1)])
    off = np.flatnonzero(centroid_distance > _ON_MESH)
    worst = float(centroid_distance.max())
    if len(off) == 0:
        return worst
    rng = np.random.default_rng(0)
    faces = off[rng.choice(len(off), samples, p=areas[off] / areas[off].sum())]
    uv = rng.random((samples, 2))
    flip = uv.sum(axis=1) > 1.0
    uv[flip] = 1.0 - uv[flip]
    edges1 = corners[faces, 1] - corners[faces, 0]
    edges2 = corners[faces, 2] - corners[faces, 0]
    points = corners[faces, 0] + uv[:, :1] * edges1 + uv[:, 1:] * edges2
    return max(worst, max(probe.distance(p) for p in points))


class _Probe:
    """Distance from a point to a mesh's triangles (coal, a zero-radius sphere)."""

    def __init__(self, mesh: coal.BVHModelBase) -> None:
        self._mesh = mesh
        self._point = coal.Sphere(0.0)
        self._request = coal.DistanceRequest()
        self._result = coal.DistanceResult()
        self._identity = coal.Transform3s()
        self._at = coal.Transform3s()

    def distance(self, point: np.ndarray) -> float:
        self._result.clear()
        self._at.setTranslation(point)
        return float(coal.distance(self._mesh, self._identity, self._point, self._at,
                                   self._request, self._result))


def _key(mesh: coal.BVHModelBase) -> str:
    vertices = np.ascontiguousarray(np.array(mesh.vertices(), dtype=np.float64))
    digest = hashlib.blake2b(vertices.tobytes(), digest_size=16)
    digest.update(f"{mesh.num_tris}/{_METHOD}".encode())
    return digest.hexdigest()


def _cache_path() -> Path:
    return user_cache_dir() / CACHE_FILE


def _read_disk(path: Path) -> None:
    if path in _disk_loaded:
        return
    _disk_loaded.add(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return  # no cache yet, or a broken one: measure again
    if isinstance(data, dict):
        for key, value in data.items():
            if isinstance(key, str) and isinstance(value, (int, float)):
                _memory.setdefault(key, float(value))


def _write_disk(path: Path, new: dict[str, float]) -> None:
    """Merge ``new`` into the cache file (atomically replaced; a failure only costs a
    measurement next time)."""
    try:
        merge_json_cache(path, {k: (v if np.isfinite(v) else 1e9) for k, v in new.items()},
                         ".hull_excess.")
    except OSError as exc:
        log.debug("hull excess cache not written (%s): %s", path, exc)


def hull_excess(meshes: list[coal.BVHModelBase]) -> list[float]:
    """:func:`measure_hull_excess` of each mesh (m), from the memory or disk cache when
    the same mesh was measured before."""
    path = _cache_path()
    with _lock:
        _read_disk(path)
        keys = [_key(mesh) for mesh in meshes]
        new: dict[str, float] = {}
        for key, mesh in zip(keys, meshes, strict=True):
            if key not in _memory and key not in new:
                new[key] = measure_hull_excess(mesh)
        if new:
            _memory.update(new)
            _write_disk(path, new)
        return [_memory[key] for key in keys]


def shared_convex_hull(mesh: coal.BVHModelBase) -> coal.Convex | None:
    """:func:`convex_hull` of ``mesh``, computed once per process for equal meshes (two
    copies of an arm share their hulls), or None where there is none coal can use (a flat
    mesh, or a vertex of too many faces): the mesh is then checked as it is. Never edit
    the result."""
    key = _key(mesh)
    with _lock:
        if key not in _hulls:
            try:
                _hulls[key] = convex_hull(mesh)
            except SceneError:
                _hulls[key] = None
        return _hulls[key]
