"""Conservative sphere models of collision geometry, generated at load for any robot.

A broad phase that tests spheres needs spheres that *contain* the geometry the exact check
tests, or it clears pairs that collide. :func:`fit_spheres` builds such a set for one coal
geometry, in the geometry's own frame:

* a triangle mesh as coal checks it, a surface: its triangles are split until no edge is
  longer than ``options.max_edge``, centres are chosen greedily inside the mesh (the deep
  ones stick out least; see :func:`_choose_spheres`), and each triangle goes to one
  sphere, whose radius reaches all of its corners. A ball is convex, so a triangle whose
  three corners are in it lies in it: every vertex and every point of every face is
  covered by construction.
* a convex polytope (a link's hull) as coal checks it, a solid: cut into tetrahedra
  (its centroid and each face), split and grouped as a mesh's triangles are; a ball
  containing a tetrahedron's four corners contains it.
* a box, cylinder, capsule or sphere as coal checks it, a solid: grids of cells, or chains
  of spheres along the axis (:mod:`taskrunner.collision.sphere_primitives`).

Each set carries its *looseness*: how far the union of its spheres reaches outside the
geometry (m). For a mesh or a convex polytope it is a bound: a sphere of radius r about a
centre at depth delta inside lies within r - delta of the geometry (within r of it for a centre
on a mesh's surface), so the largest r - delta bounds every point of the union. For a
primitive it is measured in closed form on the union's surface: an estimate from below,
within a millimetre or two of the truth. Inside or outside a mesh is decided by its winding
number (Jacobson et al., "Robust inside-outside segmentation using generalized winding
numbers", SIGGRAPH 2013).

Results are kept in memory and in ``spheres.json`` under the user cache folder
(:func:`taskrunner.resources.user_cache_dir`), keyed by a hash of the geometry's content
(vertices and triangles, or kind and dimensions) and the options: equal geometry under
another name, or in another robot, is fitted once.
"""

from __future__ import annotations

import hashlib
import json
import logging
import math
import threading
from dataclasses import dataclass
from pathlib import Path

import coal
import numpy as np

from taskrunner.collision.sphere_primitives import GROW, fit_primitive
from taskrunner.errors import ArgumentError, SceneError
from taskrunner.resources import merge_json_cache, user_cache_dir

__all__ = ["CACHE_FILE", "GeometrySpheres", "SphereOptions", "fit_spheres", "geometry_key"]

log = logging.getLogger(__name__)

CACHE_FILE = "spheres.json"
_METHOD = "v1"  # changing the construction must not reuse cached spheres
_SHORTLIST = 8  # candidates weighed for each sphere a mesh fit adds
_MAX_CANDIDATES = 4000  # candidate centres a fit chooses among, at most
_GRID_POINTS = 1200  # about this many grid points over a mesh's box are tried as centres

_lock = threading.Lock()
_memory: dict[str, GeometrySpheres] = {}
_disk_loaded: set[Path] = set()


@dataclass(frozen=True)
class SphereOptions:
    """How finely geometry is covered.

    Attributes:
        tolerance: the looseness (m) a geometry's spheres aim for; it gets more spheres
            until they stick out of it by no more, or until ``max_spheres``.
        max_spheres: at most this many spheres per geometry.
        max_edge: a mesh's triangles are split until no edge is longer (m), so that one
            long triangle does not force a large sphere.
    """

    tolerance: float = 0.01
    max_spheres: int = 64
    max_edge: float = 0.02

    def __post_init__(self) -> None:
        for name in ("tolerance", "max_edge"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ArgumentError(f"'{name}' must be a positive length in m (got {value!r})")
        if not (isinstance(self.max_spheres, int) and self.max_spheres >= 1):
            raise ArgumentError(f"'max_spheres' must be an integer >= 1 (got {self.max_spheres!r})")


@dataclass(frozen=True)
class GeometrySpheres:
    """Spheres that contain one geometry, in its own frame.

    Attributes:
        centres: (n, 3) sphere centres (m).
        radii: (n,) radii (m).
        looseness: how far (m) the union reaches outside the geometry: a bound for a
            mesh or a convex polytope, a close estimate for a primitive (see the module's
            text).
        kind: ``mesh`` (its surface covered) or ``solid`` (every point inside covered).
        key: the content hash it is cached under.
    """

    centres: np.ndarray
    radii: np.ndarray
    looseness: float
    kind: str
    key: str

    def __len__(self) -> int:
        return len(self.radii)

    def contains(self, points: np.ndarray, slack: float = 0.0) -> np.ndarray:
        """Whether each of (m, 3) ``points`` lies in some sphere (grown by ``slack`` m)."""
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        inside = np.zeros(len(points), dtype=bool)
        for c, r in zip(self.centres, self.radii, strict=True):
            inside |= np.einsum("ij,ij->i", points - c, points - c) <= (r + slack) ** 2
        return inside


# ------------------------------------------------------------------- content
def _mesh_arrays(geometry: coal.CollisionGeometry) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (n, 3) and triangles (m, 3) of a coal mesh or convex polytope."""
    if isinstance(geometry, coal.BVHModelBase):
        vertices = np.array(geometry.vertices(), dtype=float).reshape(-1, 3)
        triangles = np.array([[geometry.tri_indices(i)[k] for k in range(3)]
                              for i in range(geometry.num_tris)], dtype=np.int64).reshape(-1, 3)
    else:
        vertices = np.array(geometry.points(), dtype=float).reshape(-1, 3)
        triangles = np.array([[geometry.polygons(i)[k] for k in range(3)]
                              for i in range(geometry.num_polygons)], dtype=np.int64).reshape(-1, 3)
    if len(triangles) == 0:
        raise SceneError("a mesh with no triangles has no sphere model")
    return vertices, triangles


def _is_mesh(geometry: coal.CollisionGeometry) -> bool:
    return isinstance(geometry, (coal.BVHModelBase, coal.ConvexBase))


def _swept(geometry: coal.CollisionGeometry) -> float:
    get = getattr(geometry, "getSweptSphereRadius", None)
    return float(get()) if get is not None else 0.0


def _primitive(geometry: coal.CollisionGeometry) -> tuple[str, tuple[float, ...]]:
    if isinstance(geometry, coal.Box):
        return "box", tuple(float(v) for v in geometry.halfSide)
    if isinstance(geometry, coal.Sphere):
        return "sphere", (float(geometry.radius),)
    if isinstance(geometry, coal.Capsule):
        return "capsule", (float(geometry.radius), float(geometry.halfLength))
    if isinstance(geometry, coal.Cylinder):
        return "cylinder", (float(geometry.radius), float(geometry.halfLength))
    raise SceneError(f"no sphere model for a {type(geometry).__name__}: meshes, convex "
                     f"polytopes, boxes, spheres, cylinders and capsules are covered")


def geometry_key(geometry: coal.CollisionGeometry, options: SphereOptions | None = None) -> str:
    """The content hash a geometry's spheres are cached under: its vertices and
    triangles (or kind and dimensions), its swept radius, the options and the method."""
    options = options or SphereOptions()
    digest = hashlib.blake2b(digest_size=16)
    if _is_mesh(geometry):
        vertices, triangles = _mesh_arrays(geometry)
        digest.update(b"mesh")
        digest.update(np.ascontiguousarray(vertices).tobytes())
        digest.update(np.ascontiguousarray(triangles).tobytes())
    else:
        kind, dims = _primitive(geometry)
        digest.update(f"{kind}{dims!r}".encode())
    digest.update(f"/{_swept(geometry)!r}/{options.tolerance!r}/{options.max_spheres}/"
                  f"{options.max_edge!r}/{_METHOD}".encode())
    return digest.hexdigest()


# ------------------------------------------------------------------- meshes
def _split_long_edges(corners: np.ndarray, max_edge: float) -> np.ndarray:
    """Simplices (m, k, 3): triangles (k = 3) or tetrahedra (k = 4), split at the middle of
    their longest edge until no edge is longer than ``max_edge``; their union is the input's."""
    pairs = [(a, b) for a in range(corners.shape[1]) for b in range(a + 1, corners.shape[1])]
    done = []
    while len(corners):
        edges = np.stack([np.linalg.norm(corners[:, b] - corners[:, a], axis=1)
                          for a, b in pairs], axis=1)
        longest = edges.argmax(axis=1)
        long = edges[np.arange(len(corners)), longest] > max_edge
        done.append(corners[~long])
        corners, longest = corners[long], longest[long]
        if not len(corners):
            break
        first, second = corners.copy(), corners.copy()
        rows = np.arange(len(corners))
        ends = np.array(pairs)[longest]  # (n, 2): the longest edge's two corners
        middle = 0.5 * (corners[rows, ends[:, 0]] + corners[rows, ends[:, 1]])
        first[rows, ends[:, 1]] = middle  # one half keeps the edge's first corner ...
        second[rows, ends[:, 0]] = middle  # ... the other its second
        corners = np.concatenate([first, second])
    return np.concatenate(done)


def _fit_mesh(vertices: np.ndarray, triangles: np.ndarray, mesh: coal.CollisionGeometry,
              options: SphereOptions) -> tuple[np.ndarray, np.ndarray, float]:
    """A triangle mesh's surface, as coal's BVH checks it: the candidate centres are grid
    points inside it (for a closed mesh) and its (split) triangles' centroids, at depth 0."""
    corners = _split_long_edges(vertices[triangles], options.max_edge)
    inside = _inside_points(vertices, triangles) if _closed(triangles) else np.zeros((0, 3))
    # The triangles' own centroids too: a triangle far from every inside point (a thin
    # wall, a shell) then costs at most its own circumradius.
    candidates = np.concatenate([inside, corners.mean(axis=1)])
    depth = np.concatenate([_distances(mesh, inside), np.zeros(len(corners))])
    return _choose_spheres(corners, candidates, depth, options)


def _fit_convex(vertices: np.ndarray, triangles: np.ndarray, options: SphereOptions
                ) -> tuple[np.ndarray, np.ndarray, float]:
    """A convex polytope as coal checks it, a solid: cut into tetrahedra (its centroid and
    each face), split until short; the candidate centres are grid points inside it and
    the tetrahedra's centroids, with their exact depth (the nearest face plane)."""
    centre = vertices.mean(axis=0)
    corners = vertices[triangles]
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normal /= np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]
    normal *= np.sign(np.einsum("ij,ij->i", normal, corners[:, 0] - centre))[:, None]
    offset = np.einsum("ij,ij->i", normal, corners[:, 0])
    tetrahedra = np.concatenate([np.repeat(centre[None, None], len(corners), axis=0), corners],
                                axis=1)
    # Inner tetrahedra may stay longer than the faces: deep centres cover them cheaply.
    cells = _split_long_edges(tetrahedra, 2 * options.max_edge)
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    step = float(np.prod(np.maximum(hi - lo, 1e-6)) / _GRID_POINTS) ** (1 / 3)
    grid = np.stack(np.meshgrid(*[np.arange(lo[i] + step / 2, hi[i], step) for i in range(3)],
                                indexing="ij"), axis=-1).reshape(-1, 3)
    candidates = np.concatenate([grid, cells.mean(axis=1)])
    depth = np.min(offset[None] - candidates @ normal.T, axis=1)
    keep = depth >= 0
    return _choose_spheres(cells, candidates[keep], depth[keep], options)


def _choose_spheres(corners: np.ndarray, candidates: np.ndarray, depth: np.ndarray,
                    options: SphereOptions) -> tuple[np.ndarray, np.ndarray, float]:
    """Spheres over simplices (m, k, 3), centred at some of the candidates (each of depth
    ``delta`` in the geometry), and their looseness bound.

    A ball of radius r about a centre of depth delta lies within r - delta of the inscribed
    ball, hence of the geometry: a simplex's *cost* at a centre is its farthest corner's
    distance minus the depth. Each simplex goes to the chosen centre where its cost is
    least; while the worst simplex's cost exceeds the tolerance, a candidate where that
    simplex's cost is least is added (of those nearly as good, the one that brings the most
    simplices within reach; a simplex whose best candidate is already in is as good as it
    gets, and is passed over from then on). Each radius reaches its simplices' farthest
    corner: a ball is convex, so it contains every simplex whose corners it contains."""
    if len(candidates) > _MAX_CANDIDATES:  # a seeded subset: enough to choose among
        pick = np.random.default_rng(0).choice(len(candidates), _MAX_CANDIDATES, replace=False)
        candidates, depth = candidates[pick], depth[pick]

    def cost_at(j: int) -> np.ndarray:  # every simplex's cost at candidate j
        gap = corners - candidates[j]
        return np.sqrt(np.einsum("mki,mki->mk", gap, gap).max(axis=1)) - depth[j]

    first = corners.reshape(-1, 3).mean(axis=0)
    chosen = [int(np.argmin(np.linalg.norm(candidates - first, axis=1) - depth))]
    best = cost_at(chosen[0])
    owner = np.zeros(len(corners), dtype=np.int64)
    settled = np.zeros(len(corners), dtype=bool)  # at the least cost any candidate gives
    while len(chosen) < options.max_spheres:
        open_cost = np.where(settled, -np.inf, best)
        t = int(np.argmax(open_cost))
        if not open_cost[t] > options.tolerance:
            break
        at_t = np.linalg.norm(corners[t][None] - candidates[:, None], axis=2).max(axis=1) - depth
        j = int(np.argmin(at_t))
        if j in chosen:  # no candidate does better for this triangle: go on with the others
            settled[t] = True
            continue
        # Of the candidates nearly as good for this triangle, the one that brings the most
        # triangles within reach (the tolerance, or what this triangle can get at best).
        goal = max(options.tolerance, float(at_t[j]))
        shortlist = [k for k in np.argsort(at_t)[:_SHORTLIST] if at_t[k] <= goal + 1e-12]
        gains = [int(np.count_nonzero((cost_at(int(k)) <= goal) & (best > goal)))
                 for k in shortlist]
        j = int(shortlist[int(np.argmax(gains))])
        cost = cost_at(j)
        better = cost < best
        best[better], owner[better] = cost[better], len(chosen)
        chosen.append(j)
    centres, radii, depths = [], [], []
    for k, j in enumerate(chosen):
        mine = corners[owner == k].reshape(-1, 3)
        if len(mine):
            centres.append(candidates[j])
            radii.append(float(np.linalg.norm(mine - candidates[j], axis=1).max()) * (1 + 1e-9)
                         + GROW)
            depths.append(depth[j])
    r = np.array(radii)
    return np.array(centres), r, float(max(0.0, np.max(r - np.array(depths))))


def _inside_points(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Points of a grid over the mesh's box that lie inside the closed mesh."""
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    step = float(np.prod(np.maximum(hi - lo, 1e-6)) / _GRID_POINTS) ** (1 / 3)
    axes = [np.arange(lo[i] + step / 2, hi[i], step) for i in range(3)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    return grid[np.abs(_winding(grid, vertices, triangles)) > 0.5]


def _closed(triangles: np.ndarray) -> bool:
    """Every edge is shared by exactly two triangles."""
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                    triangles[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(np.all(counts == 2))


def _winding(points: np.ndarray, vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Generalised winding number of a closed mesh at each point (1 inside, 0 outside)."""
    out = np.zeros(len(points))
    tri = vertices[triangles]  # (m, 3, 3)
    for start in range(0, len(points), 256):
        p = points[start:start + 256]
        a, b, c = (tri[None, :, k, :] - p[:, None, :] for k in range(3))
        la, lb, lc = (np.linalg.norm(v, axis=2) for v in (a, b, c))
        det = np.einsum("pmi,pmi->pm", a, np.cross(b, c))
        den = (la * lb * lc + np.einsum("pmi,pmi->pm", a, b) * lc
               + np.einsum("pmi,pmi->pm", b, c) * la + np.einsum("pmi,pmi->pm", c, a) * lb)
        out[start:start + 256] = np.arctan2(det, den).sum(axis=1) / (2 * math.pi)
    return out


def _distances(mesh: coal.CollisionGeometry, points: np.ndarray) -> np.ndarray:
    """Distance (m) from each point to the mesh's triangles (coal, a zero-radius sphere)."""
    point, at, identity = coal.Sphere(0.0), coal.Transform3s(), coal.Transform3s()
    request, result = coal.DistanceRequest(), coal.DistanceResult()
    out = np.empty(len(points))
    for i, p in enumerate(points):
        result.clear()
        at.setTranslation(p)
        out[i] = coal.distance(mesh, identity, point, at, request, result)
    return out


def fit_spheres(geometry: coal.CollisionGeometry, options: SphereOptions | None = None
                ) -> GeometrySpheres:
    """Spheres containing ``geometry`` (see the module's text), from the memory or disk
    cache when equal geometry was fitted before with equal options.

    Raises:
        SceneError: a shape with no sphere model here (cone, plane, half-space, ellipsoid),
            or a mesh with no triangles.
    """
    options = options or SphereOptions()
    key = geometry_key(geometry, options)
    path = user_cache_dir() / CACHE_FILE
    with _lock:
        _read_disk(path)
        if key in _memory:
            return _memory[key]
    swept = _swept(geometry)  # the geometry is its core grown by this: so are the spheres
    if isinstance(geometry, coal.ConvexBase):
        vertices, triangles = _mesh_arrays(geometry)
        centres, radii, looseness = _fit_convex(vertices, triangles, options)
        kind = "solid"
    elif _is_mesh(geometry):
        vertices, triangles = _mesh_arrays(geometry)
        centres, radii, looseness = _fit_mesh(vertices, triangles, geometry, options)
        kind = "mesh"
    else:
        shape, dims = _primitive(geometry)
        centres, radii, looseness = fit_primitive(shape, dims, options.tolerance,
                                                  options.max_spheres)
        kind = "solid"
    radii = radii + swept
    fitted = GeometrySpheres(centres, radii, looseness, kind, key)
    with _lock:
        _memory[key] = fitted
        _write_disk(path, key, fitted)
    return fitted


def _read_disk(path: Path) -> None:
    if path in _disk_loaded:
        return
    _disk_loaded.add(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return  # no cache yet, or a broken one: fit again
    if not isinstance(data, dict):
        return
    for key, entry in data.items():
        try:
            centres = np.array(entry["centres"], dtype=float).reshape(-1, 3)
            radii = np.array(entry["radii"], dtype=float).reshape(-1)
            if len(centres) != len(radii) or not len(radii):
                continue
            _memory.setdefault(key, GeometrySpheres(centres, radii, float(entry["looseness"]),
                                                    str(entry["kind"]), key))
        except (KeyError, TypeError, ValueError):
            continue


def _write_disk(path: Path, key: str, fitted: GeometrySpheres) -> None:
    """Merge one entry into the cache file (atomically replaced; a failure only costs a
    fit next time)."""
    try:
        merge_json_cache(path, {key: {"centres": fitted.centres.tolist(),
                                      "radii": fitted.radii.tolist(),
                                      "looseness": fitted.looseness, "kind": fitted.kind}},
                         ".spheres.")
    except OSError as exc:
        log.debug("sphere cache not written (%s): %s", path, exc)
