"""Conservative sphere models of collision geometry.

:func:`cover` returns spheres whose union contains every point of a coal collision
geometry (solid: boxes, cylinders, capsules, cones, spheres, convex polytopes; a triangle
mesh is covered through its convex hull, which contains it). "Spheres apart" therefore
implies "geometry apart", which is what lets the planner's search check spheres
(:mod:`taskrunner.planning.fastcheck`) and consult coal only where spheres touch.

Construction. The geometry is first replaced by a convex polytope containing it (a box
by its corners, a cylinder by the circumscribed prism, a mesh by its hull's vertices,
anything else by its bounding box). The polytope is split recursively by planes across
its longest principal axis, largest piece first, until every piece is small enough or the
sphere budget is spent. A piece of a convex polytope cut by a plane is the convex hull of
its vertices on that side and of the points where segments between vertices on
opposite sides cross the plane, so every piece stays an exact convex polytope; a ball
containing a piece's vertices contains the piece (a ball is convex). Each sphere is a
small enclosing ball of its piece's vertices (its radius is the largest vertex distance,
so the containment does not depend on how well the centre is chosen), padded by
:data:`PADDING` and by the geometry's swept-sphere radius.

Models are cached per geometry content (type, dimensions or vertices, parameters) in
memory and on disk (``user_cache_dir()/spheres``), so a robot's links are covered once
per machine.
"""

from __future__ import annotations

import hashlib
import heapq
import os
from dataclasses import dataclass
from pathlib import Path

import coal
import numpy as np
from scipy.spatial import ConvexHull, QhullError

__all__ = ["PADDING", "SphereSet", "cache_dir", "cover", "polytope_vertices"]

PADDING = 1e-6  # m added to every radius (rounding of the transforms and distances)
_VERSION = 1  # bump when the construction changes: cached models are keyed by it
_PRISM_SIDES = 16  # a cylinder's circumscribed prism
_memory: dict[str, SphereSet] = {}


@dataclass(frozen=True)
class SphereSet:
    """Spheres in a geometry's own frame: ``centres`` ``(n, 3)`` (m), ``radii`` ``(n,)``."""

    centres: np.ndarray
    radii: np.ndarray

    def __len__(self) -> int:
        return len(self.radii)


def cache_dir() -> Path:
    """Where sphere models are kept between runs."""
    from taskrunner.resources import user_cache_dir

    return user_cache_dir() / "spheres"


def polytope_vertices(geometry: coal.CollisionGeometry) -> np.ndarray | None:
    """Vertices of a convex polytope containing ``geometry`` (its own frame), or None for a
    sphere (covered exactly by itself)."""
    if isinstance(geometry, coal.Sphere):
        return None
    if isinstance(geometry, coal.Box):
        half = np.asarray(geometry.halfSide, dtype=float)
        return np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * half
    if isinstance(geometry, (coal.Cylinder, coal.Capsule, coal.Cone)):
        r = float(geometry.radius)
        h = float(geometry.halfLength)
        if isinstance(geometry, coal.Capsule):
            h += r  # the capsule lies inside the cylinder of its full length
        # The prism's faces touch the circle: its corners lie at r / cos(pi / n).
        corner = r / np.cos(np.pi / _PRISM_SIDES)
        angles = 2 * np.pi * np.arange(_PRISM_SIDES) / _PRISM_SIDES
        ring = np.column_stack([corner * np.cos(angles), corner * np.sin(angles)])
        return np.vstack([np.column_stack([ring, np.full(_PRISM_SIDES, z)]) for z in (-h, h)])
    if isinstance(geometry, coal.ConvexBase):
        return _convex_points(geometry)
    if isinstance(geometry, coal.BVHModelBase):
        return np.array(geometry.vertices(), dtype=float).reshape(-1, 3)
    geometry.computeLocalAABB()
    lo = np.asarray(geometry.aabb_local.min_, dtype=float)
    hi = np.asarray(geometry.aabb_local.max_, dtype=float)
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                     for z in (lo[2], hi[2])])


def _convex_points(geometry: coal.ConvexBase) -> np.ndarray:
    points = geometry.points()
    if isinstance(points, np.ndarray):
        return np.asarray(points, dtype=float).reshape(-1, 3)
    return np.array([np.asarray(p, dtype=float) for p in points]).reshape(-1, 3)


def _key(geometry: coal.CollisionGeometry, max_spheres: int, max_radius: float) -> str:
    digest = hashlib.sha256()
    digest.update(f"v{_VERSION}:{type(geometry).__name__}:{max_spheres}:{max_radius!r}:".encode())
    digest.update(repr(_swept(geometry)).encode())
    if isinstance(geometry, coal.Sphere):
        digest.update(repr(float(geometry.radius)).encode())
    else:
        vertices = polytope_vertices(geometry)
        assert vertices is not None
        digest.update(np.ascontiguousarray(vertices, dtype=np.float64).tobytes())
    return digest.hexdigest()[:32]


def cover(geometry: coal.CollisionGeometry, max_spheres: int = 16,
          max_radius: float = 0.03, use_cache: bool = True) -> SphereSet:
    """Spheres covering ``geometry`` (see the module docstring).

    Args:
        geometry: a coal collision geometry, in its own frame.
        max_spheres: at most this many spheres.
        max_radius: m; pieces are split until their spheres are this small (or the
            budget is spent).
        use_cache: read and write the memory and disk caches.
    """
    key = _key(geometry, max_spheres, max_radius)
    if use_cache:
        cached = _memory.get(key) or _load(key)
        if cached is not None:
            _memory[key] = cached
            return cached
    swept = _swept(geometry)
    if isinstance(geometry, coal.Sphere):
        spheres = SphereSet(np.zeros((1, 3)), np.array([float(geometry.radius) + swept + PADDING]))
    else:
        vertices = polytope_vertices(geometry)
        assert vertices is not None
        centres, radii = _split_cover(vertices, max_spheres, max_radius)
        spheres = SphereSet(centres, radii + swept + PADDING)
    if use_cache:
        _memory[key] = spheres
        _store(key, spheres)
    return spheres


def _load(key: str) -> SphereSet | None:
    path = cache_dir() / f"{key}.npz"
    try:
        with np.load(path) as data:
            centres = np.array(data["centres"], dtype=float)
            radii = np.array(data["radii"], dtype=float)
    except (OSError, KeyError, ValueError):
        return None
    if centres.ndim != 2 or centres.shape[1] != 3 or radii.shape != (len(centres),):
        return None
    return SphereSet(centres, radii)


def _store(key: str, spheres: SphereSet) -> None:
    folder = cache_dir()
    try:
        folder.mkdir(parents=True, exist_ok=True)
        temporary = folder / f".{key}.{os.getpid()}.npz"
        np.savez(temporary, centres=spheres.centres, radii=spheres.radii)
        os.replace(temporary, folder / f"{key}.npz")
    except OSError:
        pass  # a read-only cache only costs the construction next time


def _reduce(points: np.ndarray) -> np.ndarray:
    """The hull's vertices of ``points`` (all of them when flat: still a superset)."""
    points = np.unique(np.round(points, 12), axis=0)
    if len(points) <= 4:
        return points
    try:
        return points[ConvexHull(points).vertices]
    except (QhullError, ValueError):
        return points


def _ball(points: np.ndarray) -> tuple[np.ndarray, float]:
    """A small ball containing ``points``: Bădoiu–Clarkson iterations from the box centre;
    the radius is the largest distance from the centre found (so it always contains them)."""
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    for i in range(1, 80):
        far = points[np.argmax(np.sum((points - centre) ** 2, axis=1))]
        centre = centre + (far - centre) / (i + 1)
    box_centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    candidates = [(float(np.sqrt(np.max(np.sum((points - c) ** 2, axis=1)))), c)
                  for c in (centre, box_centre)]
    radius, chosen = min(candidates, key=lambda item: item[0])
    return chosen, radius


def _halves(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The two pieces of the polytope hull(points) cut across its longest principal axis
    through the middle of its extent there."""
    centred = points - points.mean(axis=0)
    _, _, axes = np.linalg.svd(centred, full_matrices=False)
    axis = axes[0]
    s = centred @ axis
    cut = 0.5 * (s.min() + s.max())
    below, above = s <= cut, s >= cut
    # Crossing points of every segment from a vertex strictly below to one strictly above.
    lo, hi = points[s < cut], points[s > cut]
    slo, shi = s[s < cut], s[s > cut]
    t = (cut - slo[:, None]) / (shi[None, :] - slo[:, None])
    crossings = (lo[:, None, :] + t[:, :, None] * (hi[None, :, :] - lo[:, None, :])).reshape(-1, 3)
    return (_reduce(np.vstack([points[below], crossings])),
            _reduce(np.vstack([points[above], crossings])))


def _split_cover(vertices: np.ndarray, max_spheres: int, max_radius: float
                 ) -> tuple[np.ndarray, np.ndarray]:
    pieces: list[tuple[float, int, np.ndarray, np.ndarray]] = []
    counter = 0

    def push(points: np.ndarray) -> None:
        nonlocal counter
        centre, radius = _ball(points)
        heapq.heappush(pieces, (-radius, counter, points, centre))
        counter += 1

    push(_reduce(np.asarray(vertices, dtype=float)))
    while len(pieces) < max_spheres:
        negative_radius, _, points, _ = pieces[0]
        if -negative_radius <= max_radius or len(points) < 2:
            break
        heapq.heappop(pieces)
        first, second = _halves(points)
        push(first)
        push(second)
    centres = np.array([p[3] for p in pieces], dtype=float).reshape(-1, 3)
    radii = np.array([-p[0] for p in pieces], dtype=float)
    return centres, radii


def _swept(geometry: coal.CollisionGeometry) -> float:
    """The swept-sphere radius coal inflates a shape by (BVH meshes have none)."""
    getter = getattr(geometry, "getSweptSphereRadius", None)
    return float(getter()) if getter is not None else 0.0
