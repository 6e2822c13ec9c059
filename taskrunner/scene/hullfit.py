"""How far a link mesh's convex hull stands off the mesh: the test of a tight hull.

A convex hull is exact for a convex mesh and fatter for a concave one: the UR5's upper
arm and forearm hulls bridge their hollows and stand up to 4 cm off the mesh. The
*excess* of a hull is the largest distance from a point of the hull's surface to the
mesh's surface (a one-sided Hausdorff distance: every mesh point lies on or inside the
hull). It is estimated on points sampled on the hull's faces (area-weighted, seeded, plus
every face's centroid), each measured to the mesh's triangles with coal; sampling makes
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
import os
import tempfile
import threading
from pathlib import Path

import coal
import numpy as np
from scipy.spatial import ConvexHull, QhullError

from taskrunner.errors import SceneError
from taskrunner.resources import user_cache_dir

__all__ = ["CACHE_FILE", "convex_hull", "hull_excess", "measure_hull_excess"]

log = logging.getLogger(__name__)

CACHE_FILE = "hull_excess.json"
# Changing how the excess is measured must not reuse old numbers.
_METHOD = "v1-faces800"
_SAMPLES = 800

_lock = threading.Lock()
_memory: dict[str, float] = {}
_disk_loaded: set[Path] = set()


def convex_hull(mesh: coal.BVHModelBase) -> coal.Convex:
    """The convex hull of a triangle mesh's vertices, as a coal convex polytope.

    Built with scipy's Qhull because this coal wheel is compiled without it
    (``coal.WITH_QHULL`` is false, so ``buildConvexHull`` would keep every vertex).

    Raises:
        SceneError: the mesh is flat or degenerate (no 3-D hull).
    """
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
    return coal.Convex(points, triangles)


def measure_hull_excess(mesh: coal.BVHModelBase, samples: int = _SAMPLES) -> float:
    """The largest distance (m) from the mesh's convex hull surface to the mesh surface,
    estimated on ``samples`` seeded points of the hull's faces plus their centroids.

    Returns:
        The excess in m; ``inf`` for a mesh with no 3-D hull (flat or degenerate).
    """
    vertices = np.array(mesh.vertices(), dtype=float)
    try:
        hull = ConvexHull(vertices)
    except (QhullError, ValueError):
        return float("inf")
    corners = vertices[hull.simplices]  # (faces, 3, 3)
    edges1 = corners[:, 1] - corners[:, 0]
    edges2 = corners[:, 2] - corners[:, 0]
    areas = 0.5 * np.linalg.norm(np.cross(edges1, edges2), axis=1)
    if not areas.sum() > 0:
        return float("inf")
    rng = np.random.default_rng(0)
    faces = rng.choice(len(corners), samples, p=areas / areas.sum())
    uv = rng.random((samples, 2))
    flip = uv.sum(axis=1) > 1.0
    uv[flip] = 1.0 - uv[flip]
    points = corners[faces, 0] + uv[:, :1] * edges1[faces] + uv[:, 1:] * edges2[faces]
    points = np.vstack([points, corners.mean(axis=1)])
    probe = coal.Sphere(0.0)
    request = coal.DistanceRequest()
    result = coal.DistanceResult()
    identity = coal.Transform3s()
    at = coal.Transform3s()
    worst = 0.0
    for point in points:
        result.clear()
        at.setTranslation(point)
        worst = max(worst, coal.distance(mesh, identity, probe, at, request, result))
    return float(worst)


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
        path.parent.mkdir(parents=True, exist_ok=True)
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
            if not isinstance(data, dict):
                data = {}
        except (OSError, ValueError):
            data = {}
        data.update({k: (v if np.isfinite(v) else 1e9) for k, v in new.items()})
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".hull_excess.", suffix=".json")
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            json.dump(data, out)
        os.replace(tmp, path)
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
