"""shape_msgs geometry as taskrunner shapes.

``shape_msgs/SolidPrimitive`` types and their ``dimensions`` (full lengths, m)::

    BOX = 1       [x, y, z]
    SPHERE = 2    [radius]
    CYLINDER = 3  [height, radius]        axis along local z, centred
    CONE = 4      [height, radius]        axis along local z, centred, apex at +z
    PRISM = 5     (polygon + [height]: not supported, an error)

A cone becomes a triangle mesh of :data:`CONE_SIDES` sides whose flat faces touch the
cone's surface (circumscribed), so it covers the cone; a ``shape_msgs/Mesh`` (vertices and
triangles written out in the message) becomes a binary STL file. Both files are written
once, named by a hash of their content, under :func:`mesh_folder`, and loaded like any
mesh file of a scene object.
"""

from __future__ import annotations

import hashlib
import math
import os
import struct
import tempfile
from pathlib import Path

import numpy as np

from taskrunner.moveit.fields import Msg
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere
from taskrunner.yamlfile import LineList, line_of

__all__ = ["CONE_SIDES", "PRIMITIVE_TYPES", "mesh_folder", "read_mesh", "read_primitive",
           "ros2_byte", "triangle_mesh_file"]

PRIMITIVE_TYPES = {1: "BOX", 2: "SPHERE", 3: "CYLINDER", 4: "CONE", 5: "PRISM"}
_DIMENSIONS = {1: ("x", "y", "z"), 2: ("radius",), 3: ("height", "radius"), 4: ("height", "radius")}
CONE_SIDES = 32
MAX_LENGTH = 1e4  # m: a size or coordinate beyond this is a mistake (and overflows an STL)
_MAX_TRIANGLES = 200_000
MESH_FOLDER_ENV = "TASKRUNNER_MESH_CACHE"


def mesh_folder() -> Path:
    """Where meshes written out from messages go: ``TASKRUNNER_MESH_CACHE``, else
    ``$XDG_CACHE_HOME/taskrunner/meshes`` (``~/.cache/…``), else the temp folder."""
    explicit = os.environ.get(MESH_FOLDER_ENV)
    if explicit:
        return Path(explicit)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    folder = Path(base) / "taskrunner" / "meshes"
    try:
        folder.mkdir(parents=True, exist_ok=True)
        return folder
    except OSError:
        return Path(tempfile.gettempdir()) / "taskrunner-meshes"


def read_primitive(msg: Msg) -> Shape:
    """A ``shape_msgs/SolidPrimitive`` as a shape.

    Raises:
        InputError: an unknown or unsupported type, or dimensions that do not fit it.
    """
    raw = msg.raw("type")
    kind = _primitive_type(raw)
    if kind is None:
        raise msg.error("type", "must be a shape_msgs/SolidPrimitive type: 1 (BOX), 2 (SPHERE), "
                                f"3 (CYLINDER), 4 (CONE) (got {raw!r})")
    if kind == 5:
        raise msg.error("type", "5 (PRISM) is not supported: write the prism as a mesh")
    dims = msg.numbers("dimensions")
    names = _DIMENSIONS[kind]
    if len(dims) != len(names) or not all(0 < d <= MAX_LENGTH for d in dims):
        raise msg.error("dimensions", f"must be {len(names)} positive lengths "
                                      f"[{', '.join(names)}] (m, at most {MAX_LENGTH:g}) for a "
                                      f"{PRIMITIVE_TYPES[kind]} (got {dims})")
    if kind == 1:
        return Box((dims[0], dims[1], dims[2]))
    if kind == 2:
        return Sphere(dims[0])
    if kind == 3:
        return Cylinder(radius=dims[1], length=dims[0])
    return Mesh(triangle_mesh_file(*_cone(dims[0], dims[1])))


def _primitive_type(raw: object) -> int | None:
    if isinstance(raw, str):
        by_name = {name: number for number, name in PRIMITIVE_TYPES.items()}
        if raw.upper() in by_name:
            return by_name[raw.upper()]
        raw = ros2_byte(raw)
    if isinstance(raw, int) and not isinstance(raw, bool) and raw in PRIMITIVE_TYPES:
        return raw
    return None


def ros2_byte(text: str) -> int | None:
    """``b'\\x01'`` (how ``ros2 topic echo`` prints a byte field) as 1."""
    if len(text) >= 4 and text[:2] in ("b'", 'b"') and text[-1] == text[1]:
        body = text[2:-1]
        if body.startswith("\\x") and len(body) == 4:
            try:
                return int(body[2:], 16)
            except ValueError:
                return None
        if len(body) == 1:
            return ord(body)
    return None


def read_mesh(msg: Msg) -> Mesh:
    """A ``shape_msgs/Mesh`` (``vertices``: points, ``triangles``: ``vertex_indices``) as a
    mesh; also robowflex's forms: ``[x, y, z]`` vertices, ``[a, b, c]`` triangles, and
    ``resource`` (a mesh file: ``package://``, ``file://`` or a path relative to the
    file) scaled by ``dimensions``.

    Raises:
        InputError: no triangles, an index outside the vertices, a non-finite vertex, a
            resource that cannot be found.
    """
    if msg.has("resource"):
        return _resource_mesh(msg)
    vertices = [_point(msg, "vertices", i, v) for i, v in enumerate(msg.seq("vertices"))]
    items = msg.seq("triangles")
    if not items:
        raise msg.error("triangles", "must list at least one triangle")
    if len(items) > _MAX_TRIANGLES:
        raise msg.error("triangles", f"must have at most {_MAX_TRIANGLES} triangles (got {len(items)})")
    triangles = []
    for index, item in enumerate(items):
        line = line_of(items, index) or msg.line_of("triangles")
        where = f"{msg.field('triangles')}[{index}]"
        if isinstance(item, LineList):
            raw, name = list(item), where
        else:
            triangle = msg.reader.msg(item, where, ("vertex_indices",), line)
            raw, name = list(triangle.seq("vertex_indices")), f"{where}.vertex_indices"
            line = triangle.line_of("vertex_indices") or line
        if (len(raw) != 3 or any(isinstance(i, bool) or not isinstance(i, int) for i in raw)
                or not all(0 <= i < len(vertices) for i in raw)):
            raise msg.reader.error(f"'{name}' must be 3 indices of 'vertices' (0 to "
                                   f"{len(vertices) - 1}) (got {raw})", line)
        triangles.append((int(raw[0]), int(raw[1]), int(raw[2])))
    return Mesh(triangle_mesh_file(np.array(vertices, dtype=float), np.array(triangles, dtype=int)))


def _point(msg: Msg, key: str, index: int, item: object) -> tuple[float, float, float]:
    items = msg.seq(key)
    line = line_of(items, index) or msg.line_of(key)
    where = f"{msg.field(key)}[{index}]"
    if isinstance(item, LineList):
        if len(item) != 3 or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                     and math.isfinite(v) for v in item):
            raise msg.reader.error(f"'{where}' must be 3 finite numbers [x, y, z] (got {list(item)})",
                                   line)
        point = (float(item[0]), float(item[1]), float(item[2]))
    else:
        point = msg.reader.msg(item, where, ("x", "y", "z"), line).point()
    if max(abs(v) for v in point) > MAX_LENGTH:
        raise msg.reader.error(f"'{where}' must be within {MAX_LENGTH:g} m of the origin "
                               f"(got {point})", line)
    return point


def _resource_mesh(msg: Msg) -> Mesh:
    from taskrunner.errors import RobotDescriptionError
    from taskrunner.robot.packages import default_package_map

    resource = msg.string("resource")
    base = msg.reader.path.parent if msg.reader.path is not None else Path.cwd()
    try:
        path = default_package_map(base, msg.reader.package_path).resolve(resource, base)
    except RobotDescriptionError as exc:
        raise msg.error("resource", f"cannot be found: {exc.reason}") from None
    if not path.is_file():
        raise msg.error("resource", f"names a mesh file that does not exist ({path})")
    scale = (1.0, 1.0, 1.0)
    if msg.has("dimensions"):
        values = msg.numbers("dimensions")
        if len(values) != 3 or not all(0 < v <= MAX_LENGTH for v in values):
            raise msg.error("dimensions", f"must be 3 positive scale factors (got {values})")
        scale = (values[0], values[1], values[2])
    return Mesh(path, scale)


def _cone(height: float, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of a cone along z (apex at +height/2) that covers the cone."""
    outer = radius / math.cos(math.pi / CONE_SIDES)
    angles = np.arange(CONE_SIDES) * 2 * math.pi / CONE_SIDES
    rim = np.column_stack([outer * np.cos(angles), outer * np.sin(angles),
                           np.full(CONE_SIDES, -height / 2)])
    apex, centre = CONE_SIDES, CONE_SIDES + 1
    vertices = np.vstack([rim, [[0.0, 0.0, height / 2]], [[0.0, 0.0, -height / 2]]])
    triangles = []
    for i in range(CONE_SIDES):
        j = (i + 1) % CONE_SIDES
        triangles.append((i, j, apex))
        triangles.append((j, i, centre))
    return vertices, np.array(triangles, dtype=int)


def triangle_mesh_file(vertices: np.ndarray, triangles: np.ndarray) -> Path:
    """A binary STL file of the mesh, written once under :func:`mesh_folder` (named by
    the hash of its content) and reused."""
    corners = vertices[triangles]  # (n, 3, 3)
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, lengths, out=np.zeros_like(normals), where=lengths > 0)
    body = bytearray(struct.pack("<80sI", b"taskrunner shape_msgs mesh", len(triangles)))
    for normal, corner in zip(normals, corners):
        body += struct.pack("<12fH", *normal, *corner.ravel(), 0)
    data = bytes(body)
    folder = mesh_folder()
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{hashlib.sha256(data).hexdigest()[:32]}.stl"
    if not path.is_file():
        fd, temporary = tempfile.mkstemp(dir=folder, suffix=".tmp")
        with os.fdopen(fd, "wb") as out:
            out.write(data)
        os.replace(temporary, path)
    return path
