"""Mass and inertia of URDF links that give no ``<inertial>``, from their collision geometry.

MoveIt needs no masses, so many MoveIt config packages' URDFs (the upstream
``panda_moveit_config``'s among them) have links without ``<inertial>``. A physics
simulation needs them: a 1 g finger is shoved aside by the object it closes on. Such a
link gets the mass and inertia of its ``<collision>`` geometry filled with a uniform
material of :data:`DEFAULT_LINK_DENSITY`:

- boxes, cylinders and spheres exactly (coal's volume and inertia of the primitive);
- a mesh from its triangles (coal's volume integrals, the divergence theorem) when it is
  closed (every edge shared by two triangles), else from its convex hull (an open shell
  has no volume; the hull bounds it from above);
- several collision elements add up (parallel-axis theorem), overlaps counted twice.

Units: m, kg, kg m². Poses are in the link frame.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass

import coal
import numpy as np

from taskrunner.errors import BackendError
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere

__all__ = ["DEFAULT_LINK_DENSITY", "LinkInertia", "estimate_link_inertias", "shape_inertia"]

DEFAULT_LINK_DENSITY = 1000.0
"""kg/m³ for a link without ``<inertial>``: water, the average of an arm link's hollow
aluminium or plastic shell with its motor and gearing inside (the Panda's links, with
inertials, weigh 0.9-1.3 times their collision volume at this density)."""


@dataclass(frozen=True)
class LinkInertia:
    """A body's inertial properties in its link frame.

    Attributes:
        mass: kg.
        com: centre of mass (m, link frame).
        inertia: 3x3 inertia tensor about the centre of mass, link axes (kg m²).
        volume: m³ of geometry the mass was computed from.
        hull: True when a mesh's convex hull stood in for an open mesh.
    """

    mass: float
    com: np.ndarray
    inertia: np.ndarray
    volume: float
    hull: bool = False


def _closed(tris: np.ndarray) -> bool:
    """Every edge of the triangles ``tris`` (n x 3 vertex indices) shared by exactly two."""
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    return bool(len(counts)) and bool(np.all(counts == 2))


def _bvh(vertices: np.ndarray, tris: np.ndarray) -> coal.BVHModelOBBRSS:
    model = coal.BVHModelOBBRSS()
    model.beginModel(len(tris), len(vertices))
    model.addVertices(np.asarray(vertices, dtype=float))
    model.addTriangles(np.asarray(tris, dtype=np.int64))
    model.endModel()
    return model


def _hull(vertices: np.ndarray) -> coal.BVHModelOBBRSS:
    """The convex hull of ``vertices`` as a closed, outward-facing triangle mesh."""
    from scipy.spatial import ConvexHull

    hull = ConvexHull(vertices)
    tris = hull.simplices.copy()
    centre = vertices[hull.vertices].mean(axis=0)
    for k, (a, b, c) in enumerate(tris):
        normal = np.cross(vertices[b] - vertices[a], vertices[c] - vertices[a])
        if normal @ (vertices[a] - centre) < 0:
            tris[k] = (a, c, b)
    return _bvh(vertices, tris)


def _mesh_geometry(mesh: Mesh) -> tuple[coal.CollisionGeometry, bool]:
    """The mesh as a closed coal BVH (its own triangles, or its hull) and whether it is
    the hull."""
    path = mesh.path.expanduser()
    if not path.is_file():
        raise BackendError(f"mesh file {path} does not exist")
    try:
        loaded = coal.MeshLoader().load(str(path), np.array(mesh.scale, dtype=float))
    except Exception as exc:  # coal raises ValueError with assimp's text
        raise BackendError(f"{path}: coal could not load the mesh ({exc})") from None
    vertices = np.array(loaded.vertices(), dtype=float)
    tris = np.array([[t[0], t[1], t[2]] for t in
                     (loaded.tri_indices(k) for k in range(loaded.num_tris))], dtype=np.int64)
    if len(tris) and _closed(tris):
        bvh = _bvh(vertices, tris)
        if bvh.computeVolume() < 0:  # inward-facing triangles
            bvh = _bvh(vertices, tris[:, [0, 2, 1]])
        if bvh.computeVolume() > 0:
            return bvh, False
    if len(vertices) < 4:
        raise BackendError(f"{path}: mesh has no volume")
    return _hull(vertices), True


def shape_inertia(shape: Shape) -> tuple[float, np.ndarray, np.ndarray, bool]:
    """Volume (m³), centre (m) and inertia about the centre at unit density (m⁵) of a
    shape in its own frame, and whether a convex hull stood in for an open mesh.

    Raises:
        BackendError: a mesh that cannot be read or has no volume.
    """
    hull = False
    geometry: coal.CollisionGeometry
    if isinstance(shape, Box):
        geometry = coal.Box(*shape.size)
    elif isinstance(shape, Cylinder):
        geometry = coal.Cylinder(shape.radius, shape.length)
    elif isinstance(shape, Sphere):
        geometry = coal.Sphere(shape.radius)
    elif isinstance(shape, Mesh):
        geometry, hull = _mesh_geometry(shape)
    else:
        raise BackendError(f"unsupported shape {shape!r}")
    volume = float(geometry.computeVolume())
    return (volume, np.array(geometry.computeCOM(), dtype=float),
            np.array(geometry.computeMomentofInertiaRelatedToCOM(), dtype=float), hull)


def _combine(parts: list[tuple[float, np.ndarray, np.ndarray]]
             ) -> tuple[float, np.ndarray, np.ndarray]:
    """Volume, centre and inertia about it of several bodies (parallel-axis theorem)."""
    volume = float(sum(v for v, _, _ in parts))
    centre = np.sum([v * c for v, c, _ in parts], axis=0) / volume
    inertia = np.zeros((3, 3))
    for v, c, tensor in parts:
        d = c - centre
        inertia += tensor + v * (float(d @ d) * np.eye(3) - np.outer(d, d))
    return volume, centre, inertia


def _moving_links(root: ET.Element) -> tuple[set[str], set[str]]:
    """Links below a joint that moves (their mass matters to the simulation), and those
    whose own joint moves (the simulation needs them to have a mass)."""
    children: dict[str, list[tuple[str, bool]]] = {}
    parents: set[str] = set()
    kids: set[str] = set()
    for joint in root.findall("joint"):
        parent_el, child_el = joint.find("parent"), joint.find("child")
        if parent_el is None or child_el is None:
            continue
        moves = joint.get("type", "fixed") not in ("fixed",)
        parent, child = parent_el.get("link", ""), child_el.get("link", "")
        children.setdefault(parent, []).append((child, moves))
        parents.add(parent)
        kids.add(child)
    moving: set[str] = set()
    jointed: set[str] = set()
    todo = [(name, False) for name in parents - kids]
    while todo:
        name, below = todo.pop()
        for kid, moves in children.get(name, []):
            if below or moves:
                moving.add(kid)
            if moves:
                jointed.add(kid)
            todo.append((kid, below or moves))
    return moving, jointed


def estimate_link_inertias(urdf_xml: str,
                           read_shape: Callable[[ET.Element], Shape | None],
                           origin: Callable[[ET.Element], tuple[np.ndarray, np.ndarray]],
                           density: float = DEFAULT_LINK_DENSITY
                           ) -> tuple[dict[str, LinkInertia], list[str]]:
    """Inertias for the links of ``urdf_xml`` that move and give no ``<inertial>``.

    Args:
        urdf_xml: the URDF text (mesh paths absolute).
        read_shape: a ``<geometry>`` element as a shape (None: none it can read).
        origin: an element's ``<origin>`` as (translation, rotation matrix).
        density: kg/m³.

    Returns:
        The inertias by link, and the links on a moving joint without ``<inertial>``
        that have no collision geometry either (they keep a token mass).
    """
    if not (density > 0 and math.isfinite(density)):
        raise BackendError(f"'density' must be a positive number (got {density!r})")
    root = ET.fromstring(urdf_xml)
    moving, jointed = _moving_links(root)
    found: dict[str, LinkInertia] = {}
    bare: list[str] = []
    for link in root.findall("link"):
        name = link.get("name", "")
        if name not in moving or link.find("inertial") is not None:
            continue
        parts = []
        hull = False
        for collision in link.findall("collision"):
            geometry = collision.find("geometry")
            shape = None if geometry is None else read_shape(geometry)
            if shape is None:
                continue
            volume, centre, tensor, is_hull = shape_inertia(shape)
            if volume <= 0:
                continue
            hull |= is_hull
            xyz, rotation = origin(collision)
            parts.append((volume, rotation @ centre + xyz, rotation @ tensor @ rotation.T))
        if not parts:
            if name in jointed:
                bare.append(name)
            continue
        volume, centre, tensor = _combine(parts)
        found[name] = LinkInertia(density * volume, centre, density * tensor, volume, hull)
    return found, bare
