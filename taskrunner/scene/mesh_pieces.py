"""Convex pieces that together hold a triangle mesh's surface: a lower bound on its distance.

One convex hull of a concave mesh (the UR5's upper arm and forearm) bridges its hollows:
its distance to the link beyond a joint is 0 in nearly every folded state, where the
meshes themselves are 1-3 cm apart. Cut into a few compact parts, the mesh's pieces hug it:
each triangle lies in the convex hull of its piece's points, so the least distance from
any piece to another body is at most the mesh's distance to it (a point of the mesh is a
point of a piece). The path verifier and the search's state screen take that least
distance, bounded through the pieces' support functions
(:func:`taskrunner.scene.distance_bounds._pieces_bound`), before they ask coal; coal's
distance on the mesh stays the final word wherever the pieces cannot decide.

The cut (:func:`cut_mesh`): triangles longer than :data:`EDGE` are halved along their
longest edge until none is (a long side triangle of a tube would tie the two ends of the
tube into one piece; its halves lie on it), then the triangles are split at the median of
their centroids along the longest side of the widest part, part by part, until there are
:data:`PIECES` parts or none is wider than :data:`WIDTH`. Each piece is the vertex set of
its part's convex hull (scipy's Qhull; a flat part keeps all its points: the same support
function). On the UR5's links 4 pieces already bound the self pairs a joint apart within
0.89-1.0 of their distance (median over the search's states), against 0 for the hull.

Cutting a mesh of about a thousand triangles takes 5-50 ms, so the pieces are kept in memory
and on disk (one ``.npz`` file per mesh in ``mesh_pieces/`` under the user cache folder,
:func:`taskrunner.resources.user_cache_dir`), keyed by a hash of the mesh's vertices and
triangles and of the cut's settings: two copies of an arm, the verifiers of every scene
revision and the next process share them.
"""

from __future__ import annotations

import hashlib
import logging
import os
import tempfile
import threading
from pathlib import Path

import coal
import numpy as np

from taskrunner.resources import user_cache_dir

__all__ = ["CACHE_FOLDER", "EDGE", "PIECES", "WIDTH", "cut_mesh", "mesh_pieces"]

EDGE = 0.02
"""m: triangles are halved until no edge is longer than this before the cut."""
PIECES = 4
"""The most pieces a mesh is cut into."""
WIDTH = 0.05
"""m: a part no wider than this (its centroids' extent along every axis) is not cut."""
_MIN_TRIANGLES = 8  # nor is a part of fewer triangles
_MAX_TRIANGLES = 200_000  # a mesh of more (after halving) is not cut: coal's BVH serves it

CACHE_FOLDER = "mesh_pieces"
_METHOD = "v1"  # how the pieces are cut: a change must not reuse old files

log = logging.getLogger(__name__)
_lock = threading.Lock()
_memory: dict[str, tuple[np.ndarray, ...]] = {}


def _triangles(mesh: coal.BVHModelBase) -> tuple[np.ndarray, np.ndarray]:
    """The mesh's vertices ``(n, 3)`` and triangles ``(m, 3)`` (vertex indices)."""
    vertices = np.array(mesh.vertices(), dtype=float).reshape(-1, 3)
    triangles = np.array([[t[0], t[1], t[2]] for t in
                          (mesh.tri_indices(i) for i in range(mesh.num_tris))],
                         dtype=np.int64).reshape(-1, 3)
    return vertices, triangles


def _halve_long(corners: np.ndarray, edge: float) -> np.ndarray:
    """``corners`` (``(m, 3, 3)``: each triangle's corners), each triangle longer than
    ``edge`` replaced by the two halves of it cut at its longest edge's midpoint, until
    none is longer (or the count passes :data:`_MAX_TRIANGLES`)."""
    while len(corners) <= _MAX_TRIANGLES:
        lengths = np.linalg.norm(corners[:, [1, 2, 0]] - corners, axis=2)  # edge i: i -> i+1
        longest = lengths.argmax(axis=1)
        long = lengths[np.arange(len(corners)), longest] > edge
        if not long.any():
            break
        cut = corners[long]
        k = longest[long]
        rows = np.arange(len(cut))
        u = cut[rows, k]                      # the long edge u -> v, and the third corner w
        v = cut[rows, (k + 1) % 3]
        w = cut[rows, (k + 2) % 3]
        middle = 0.5 * (u + v)
        halves = np.concatenate([np.stack([u, middle, w], axis=1),
                                 np.stack([middle, v, w], axis=1)])
        corners = np.concatenate([corners[~long], halves])
    return corners


def cut_mesh(vertices: np.ndarray, triangles: np.ndarray, pieces: int = PIECES,
             width: float = WIDTH, edge: float = EDGE) -> list[np.ndarray]:
    """The pieces of a triangle mesh (vertices ``(n, 3)``, triangles ``(m, 3)`` of vertex
    indices, in one frame): the points ``(k_i, 3)`` whose convex hulls together hold every
    triangle (see the module's text). An empty list for a mesh with no finite triangle or
    too many to cut."""
    vertices = np.asarray(vertices, dtype=float)
    triangles = np.asarray(triangles, dtype=np.int64)
    if (vertices.ndim != 2 or vertices.shape[1] != 3 or triangles.ndim != 2
            or triangles.shape[1] != 3 or not len(triangles)
            or not np.isfinite(vertices).all()
            or triangles.min() < 0 or triangles.max() >= len(vertices)):
        return []
    corners = _halve_long(vertices[triangles], edge)
    if len(corners) > _MAX_TRIANGLES:
        return []
    centroids = corners.mean(axis=1)
    parts = [np.arange(len(corners))]
    while len(parts) < pieces:
        extents = [float(np.ptp(centroids[p], axis=0).max()) if len(p) >= _MIN_TRIANGLES else 0.0
                   for p in parts]
        widest = int(np.argmax(extents))
        if not extents[widest] > width:
            break
        part = parts.pop(widest)
        axis = int(np.argmax(np.ptp(centroids[part], axis=0)))
        order = np.argsort(centroids[part, axis], kind="stable")
        half = len(order) // 2
        parts += [part[order[:half]], part[order[half:]]]
    return [_hull_points(corners[p].reshape(-1, 3)) for p in parts]


def _hull_points(points: np.ndarray) -> np.ndarray:
    """The vertices of the convex hull of ``points`` (all of them, without duplicates,
    where the hull is flat or degenerate: the same support function)."""
    from scipy.spatial import ConvexHull, QhullError  # here: only where a mesh is verified

    points = np.unique(points, axis=0)
    try:
        kept = points[ConvexHull(points).vertices]
    except (QhullError, ValueError):
        kept = points
    return np.ascontiguousarray(kept, dtype=float)


def mesh_pieces(mesh: coal.BVHModelBase) -> tuple[np.ndarray, ...]:
    """:func:`cut_mesh` of a coal triangle mesh (its own frame), from the memory or disk
    cache when the same mesh was cut before. Never edit the arrays."""
    vertices, triangles = _triangles(mesh)
    digest = hashlib.blake2b(digest_size=16)
    digest.update(np.ascontiguousarray(vertices).tobytes())
    digest.update(np.ascontiguousarray(triangles).tobytes())
    digest.update(f"{_METHOD}/{PIECES}/{WIDTH}/{EDGE}".encode())
    key = digest.hexdigest()
    with _lock:
        found = _memory.get(key)
    if found is None:
        path = user_cache_dir() / CACHE_FOLDER / f"{key}.npz"
        found = _read(path)
        if found is None:
            found = tuple(cut_mesh(vertices, triangles))
            _write(path, found)
        for piece in found:
            piece.flags.writeable = False
        with _lock:
            if len(_memory) > 1024:
                _memory.clear()
            _memory[key] = found
    return found


def _read(path: Path) -> tuple[np.ndarray, ...] | None:
    """The pieces cached at ``path``, or None (no file, or one that does not hold them)."""
    try:
        with np.load(path) as data:
            points, counts = data["points"], data["counts"]
    except (OSError, ValueError, KeyError):
        return None
    if (points.ndim != 2 or points.shape[1] != 3 or counts.ndim != 1 or counts.sum() != len(points)
            or (counts < 1).any() or not np.isfinite(points).all()):
        return None
    return tuple(np.ascontiguousarray(p, dtype=float)
                 for p in np.split(points, np.cumsum(counts)[:-1]))


def _write(path: Path, pieces: tuple[np.ndarray, ...]) -> None:
    """Cache ``pieces`` at ``path`` (a temporary file beside it, then renamed: readers see
    the whole file or none; a failure only costs a cut next time)."""
    points = np.vstack(pieces) if pieces else np.zeros((0, 3))
    counts = np.array([len(p) for p in pieces], dtype=np.int64)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=".mesh_pieces.", suffix=".npz",
                                             dir=path.parent)
        try:
            with os.fdopen(handle, "wb") as out:
                np.savez(out, points=points, counts=counts)
            os.replace(temporary, path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
    except OSError as exc:
        log.debug("mesh pieces not cached (%s): %s", path, exc)
