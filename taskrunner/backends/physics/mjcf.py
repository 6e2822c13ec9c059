"""A cell as a MuJoCo model: URDF links and joints, fixed furniture, free objects.

:func:`cell_mjcf` writes MJCF text from plain data (:class:`PhysicsCell`, built from a
:class:`~taskrunner.robot.cell.Cell` by :func:`physics_cell`): every link of the cell's
merged URDF becomes a body (its ``<collision>`` geometry as geoms, its ``<inertial>`` as
the body's inertia), every movable joint a hinge or slide joint with one position
actuator; fixed joints weld a body to its parent; the cell's objects are static geoms and
the task's objects are free bodies. Meshes are used as they are (STL, OBJ); DAE and other
formats are converted to STL with trimesh into the cache. :func:`compiled_model` compiles
the text, keeping the binary model in the user cache under the hash of the text.

Contacts: robot geoms touch objects and furniture but not each other (self and arm-arm
collisions are the planner's to prevent). Units: m, kg, rad.
"""

from __future__ import annotations

import hashlib
import logging
import math
import os
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from taskrunner.backends.physics.inertia import (
    DEFAULT_LINK_DENSITY,
    LinkInertia,
    estimate_link_inertias,
)
from taskrunner.errors import ArgumentError, BackendError
from taskrunner.materials import Material
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere

if TYPE_CHECKING:
    from taskrunner.robot.cell import Cell

__all__ = ["ObjectPhysics", "PhysicsCell", "PhysicsObject", "cell_mjcf", "compiled_model",
           "physics_cell"]

log = logging.getLogger(__name__)

WORLD = "world"
# contype / conaffinity bits: robot geoms (2) touch world geoms (1) but not each other.
# In a cell of several robots each robot has a bit of its own (2, 4, 8 …): its links touch
# the world and the other robots' links, never its own (``_contact_bits``).
_ROBOT_BITS = ('contype="2"', 'conaffinity="1"')
_WORLD_BITS = ('contype="1"', 'conaffinity="3"')
_MAX_ROBOTS = 30  # contype bits 1..30 (bit 0: the world)
_MIN_MASS = 1e-3  # kg: a moving link with neither <inertial> nor collision geometry
_MIN_INERTIA = 1e-6  # kg m^2


@dataclass(frozen=True)
class ObjectPhysics:
    """Mass and friction of a free object.

    Attributes:
        density: kg/m^3, used when ``mass`` is None (600: dry wood).
        mass: kg; overrides ``density``.
        friction: sliding, torsional, rolling coefficients (MuJoCo's ``friction``).
    """

    density: float = 600.0
    mass: float | None = None
    friction: tuple[float, float, float] = (1.0, 0.005, 0.0001)

    def __post_init__(self) -> None:
        if not (self.density > 0 and math.isfinite(self.density)):
            raise ArgumentError(f"'density' must be a positive number (got {self.density!r})")
        if self.mass is not None and not (self.mass > 0 and math.isfinite(self.mass)):
            raise ArgumentError(f"'mass' must be a positive number (got {self.mass!r})")
        if len(self.friction) != 3 or not all(0 <= f < math.inf for f in self.friction):
            raise ArgumentError(f"'friction' must be 3 numbers >= 0 (got {self.friction!r})")

    @classmethod
    def from_material(cls, material: Material, default: ObjectPhysics | None = None
                      ) -> ObjectPhysics:
        """``material`` (a cell's or task's object fields) over ``default``: a missing
        density, or torsional and rolling friction, come from ``default``."""
        default = default or cls()
        friction: tuple[float, ...] = default.friction
        if material.friction is not None:
            friction = (*material.friction, *default.friction[len(material.friction):])[:3]
        return cls(material.density or default.density,
                   material.mass if material.mass is not None
                   else None if material.density is not None else default.mass,
                   (friction[0], friction[1], friction[2]))


@dataclass(frozen=True)
class PhysicsObject:
    """An object in the physics world.

    Attributes:
        name: the scene's name for it.
        shape: its geometry, centred on its frame.
        xyz, quat: world pose of its frame (m; x, y, z, w).
        movable: a free body (a task's object) or a static one (furniture).
        frame: the link a static object is fixed to ("world" for the world).
        physics: its mass and friction as the cell or task gives them (None: the
            backend's default; a static object uses only the friction).
    """

    name: str
    shape: Shape
    xyz: tuple[float, float, float]
    quat: tuple[float, float, float, float]
    movable: bool
    frame: str = WORLD
    physics: ObjectPhysics | None = None


@dataclass(frozen=True)
class PhysicsCell:
    """What the model is made of: the cell's merged URDF, its objects, and its hands.

    Attributes:
        name: the cell's name.
        urdf_xml: the cell's merged URDF (prefixed links and joints under ``world``).
        objects: furniture and free objects.
        hand_links: links of every end effector (fingers, palm, tool frames): their
            contacts with free objects are grasps, not collisions.
        gripper_joints: joints of end-effector groups (a blocked finger is no tracking
            error).
        grasp_frames: per arm group, the link a grasped object is attached to.
        mimic: follower joint -> (leader, multiplier, offset).
        grasp_modes: per arm group, "friction" or "weld" (the cell's ``grasp_mode``).
        frame_links: frames that are not links (tool frames) -> the link each is fixed to.
        link_inertias: for moving links without ``<inertial>``, the mass and inertia of
            their collision geometry (:mod:`taskrunner.backends.physics.inertia`).
        link_robots: in a cell of several robots, the robot (instance name) of each
            link: links of two robots touch each other in the model, and any contact
            between them is a failure of the run (the backend names both links).
    """

    name: str
    urdf_xml: str
    objects: tuple[PhysicsObject, ...] = ()
    hand_links: frozenset[str] = frozenset()
    gripper_joints: frozenset[str] = frozenset()
    grasp_frames: Mapping[str, str] = field(default_factory=dict)
    mimic: Mapping[str, tuple[str, float, float]] = field(default_factory=dict)
    grasp_modes: Mapping[str, str] = field(default_factory=dict)
    frame_links: Mapping[str, str] = field(default_factory=dict)
    link_inertias: Mapping[str, LinkInertia] = field(default_factory=dict)
    link_robots: Mapping[str, str] = field(default_factory=dict)

    def with_objects(self, objects: Iterable[PhysicsObject]) -> PhysicsCell:
        """The same cell with ``objects`` as its objects."""
        return PhysicsCell(self.name, self.urdf_xml, tuple(objects), self.hand_links,
                           self.gripper_joints, dict(self.grasp_frames), dict(self.mimic),
                           dict(self.grasp_modes), dict(self.frame_links),
                           dict(self.link_inertias), dict(self.link_robots))


def physics_cell(cell: Cell, link_density: float = DEFAULT_LINK_DENSITY) -> PhysicsCell:
    """The plain-data physics description of ``cell``: its objects are static furniture,
    except world objects given a mass or density (free bodies). Moving links without
    ``<inertial>`` get the mass of their collision geometry at ``link_density`` (kg/m³),
    with one warning per robot naming them."""
    import pinocchio as pin

    model = cell.model
    objects = []
    for obj in cell.objects:
        q = pin.Quaternion(obj.pose.rotation)
        material = getattr(obj, "material", None)
        physics = ObjectPhysics.from_material(material) if material else None
        movable = bool(material and (material.mass or material.density)) and obj.frame == WORLD
        objects.append(PhysicsObject(obj.name, obj.shape, tuple(obj.pose.translation),
                                     (q.x, q.y, q.z, q.w), movable=movable, frame=obj.frame,
                                     physics=physics))
    hands: set[str] = set()
    frames: dict[str, str] = {}
    for eef in model.end_effectors.values():
        hands.add(eef.parent_link)
        hands.update(model.groups[eef.group].links)
        # The palm the fingers hang from (its children are the hand's other links).
        hands.update(model.joint(j).parent_link for j in model.groups[eef.group].joint_names)
    aliases: dict[str, str] = {}
    tools = getattr(cell, "tools", None) or {}
    for group in model.groups.values():
        if group.end_effector and group.tip_link:
            tool = tools.get(group.name)
            if tool is not None:  # the arm's tool frame, on the link it is fixed to
                frames[group.name] = tool.link
                if tool.frame != tool.link:
                    aliases[tool.frame] = tool.link
            else:
                prefix = next((i.prefix for i in model.instances if i.name == group.robot), "")
                tool0 = prefix + "tool0"
                frames[group.name] = tool0 if model.has_link(tool0) else group.tip_link
            hands.add(frames[group.name])
    hands |= _descendants(model.urdf_xml, hands)
    fingers = {j.name for j in model.joints if j.child_link in hands}
    mimic = {j.name: (j.mimic.source, j.mimic.multiplier, j.mimic.offset)
             for j in model.joints if j.mimic is not None}
    modes = dict(getattr(cell, "grasp_modes", {}) or {})
    inertias, bare = estimate_link_inertias(model.urdf_xml, _geometry_shape, _origin_transform,
                                            link_density)
    prefixes = sorted(((i.prefix, i.name) for i in model.instances), key=lambda p: -len(p[0]))
    by_robot: dict[str, list[str]] = {}
    for link in sorted([*inertias, *bare]):
        robot = next((name for prefix, name in prefixes if link.startswith(prefix)), cell.name)
        shown = (f"{link} {inertias[link].mass:.3g} kg" if link in inertias
                 else f"{link} (no geometry: {1e3 * _MIN_MASS:g} g)")
        by_robot.setdefault(robot, []).append(shown)
    for robot, names in by_robot.items():
        log.warning("robot %r: %d link(s) without <inertial> weighed from their collision "
                    "geometry at %g kg/m³ (mujoco backend): %s", robot, len(names),
                    link_density, ", ".join(names))
    link_robots: dict[str, str] = {}
    if len(model.instances) > 1:
        for link in model.link_names:
            owner = next((name for prefix, name in prefixes if link.startswith(prefix)), None)
            if owner is not None and link != WORLD:
                link_robots[link] = owner
    return PhysicsCell(cell.name, model.urdf_xml, tuple(objects), frozenset(hands),
                       frozenset(fingers), frames, mimic, modes, aliases, inertias,
                       link_robots)


def _contact_bits(cell: PhysicsCell) -> tuple[dict[str, tuple[str, str]], tuple[str, str]]:
    """contype / conaffinity of each robot's links, and of the world's geoms: one bit per
    robot, so that links of two robots touch and links of one robot do not."""
    robots = sorted(set(cell.link_robots.values()))
    if len(robots) < 2:
        return {}, _WORLD_BITS
    if len(robots) > _MAX_ROBOTS:
        raise BackendError(f"cell {cell.name!r}: the mujoco backend models at most "
                           f"{_MAX_ROBOTS} robots (got {len(robots)})")
    bit = {robot: 2 << i for i, robot in enumerate(robots)}
    every = sum(bit.values())
    per_robot = {robot: (f'contype="{b}"', f'conaffinity="{1 | (every & ~b)}"')
                 for robot, b in bit.items()}
    return per_robot, ('contype="1"', f'conaffinity="{1 | every}"')


def _geometry_shape(geometry: ET.Element) -> Shape | None:
    return _urdf_geom(geometry, None)


def _origin_transform(element: ET.Element) -> tuple[np.ndarray, np.ndarray]:
    """An element's ``<origin>``: translation and rotation matrix."""
    origin = element.find("origin")
    xyz = _floats(None if origin is None else origin.get("xyz"), 3)
    rpy = _floats(None if origin is None else origin.get("rpy"), 3)
    return np.array(xyz), _matrix(quat_from_rpy(rpy))


def _descendants(urdf_xml: str, links: set[str]) -> set[str]:
    """Links below any of ``links`` (a hand's fingers, pads and tool frames)."""
    root = ET.fromstring(urdf_xml)
    children: dict[str, list[str]] = {}
    for joint in root.findall("joint"):
        parent = joint.find("parent")
        child = joint.find("child")
        if parent is not None and child is not None:
            children.setdefault(parent.get("link", ""), []).append(child.get("link", ""))
    found: set[str] = set()
    todo = list(links)
    while todo:
        for name in children.get(todo.pop(), []):
            if name not in found:
                found.add(name)
                todo.append(name)
    return found


# ----------------------------------------------------------------------------- geometry
def _floats(text: str | None, n: int, default: float = 0.0) -> list[float]:
    if not text:
        return [default] * n
    values = [float(v) for v in text.split()]
    if len(values) != n:
        raise BackendError(f"URDF: expected {n} numbers (got {text!r})")
    return values


def quat_from_rpy(rpy: list[float]) -> list[float]:
    """URDF roll, pitch, yaw (fixed axes x, y, z) as a quaternion (w, x, y, z)."""
    r, p, y = (v / 2 for v in rpy)
    cr, sr, cp, sp, cy, sy = (math.cos(r), math.sin(r), math.cos(p), math.sin(p),
                              math.cos(y), math.sin(y))
    return [cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy]


def _matrix(quat: list[float]) -> np.ndarray:
    """Rotation matrix of a unit quaternion (w, x, y, z)."""
    w, x, y, z = quat
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def _fmt(values: Iterable[float]) -> str:
    return " ".join(f"{v:.10g}" for v in values)


def _origin(element: ET.Element | None) -> str:
    origin = None if element is None else element.find("origin")
    xyz = _floats(None if origin is None else origin.get("xyz"), 3)
    rpy = _floats(None if origin is None else origin.get("rpy"), 3)
    return f'pos="{_fmt(xyz)}" quat="{_fmt(quat_from_rpy(rpy))}"'


def _esc(name: str) -> str:
    return (name.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
            .replace(">", "&gt;"))


class _Meshes:
    """Mesh assets: files MuJoCo reads as they are, others converted to STL once."""

    def __init__(self, cache: Path) -> None:
        self.cache = cache
        self.assets: dict[tuple[str, tuple[float, ...]], str] = {}

    def asset(self, path: str, scale: tuple[float, ...]) -> str:
        key = (path, tuple(scale))
        if key not in self.assets:
            self.assets[key] = f"mesh{len(self.assets)}"
        return self.assets[key]

    def xml(self) -> str:
        lines = []
        for (path, scale), name in self.assets.items():
            lines.append(f'<mesh name="{name}" file="{_esc(self._loadable(path))}" '
                         f'scale="{_fmt(scale)}"/>')
        return "\n".join(lines)

    def _loadable(self, path: str) -> str:
        source = Path(path)
        if not source.is_file():
            raise BackendError(f"mesh file {path} does not exist")
        if source.suffix.lower() in (".stl", ".obj", ".msh"):
            return str(source)
        digest = hashlib.sha256(source.read_bytes()).hexdigest()[:20]
        target = self.cache / "meshes" / f"{digest}.stl"
        if not target.is_file():
            try:
                import trimesh
            except ImportError:
                raise BackendError(f"mesh {path}: MuJoCo reads STL and OBJ; converting "
                                   f"{source.suffix} needs trimesh (pip install trimesh)"
                                   ) from None
            mesh = trimesh.load(str(source), force="mesh")
            target.parent.mkdir(parents=True, exist_ok=True)
            partial = target.with_suffix(f".{os.getpid()}.tmp")
            mesh.export(str(partial), file_type="stl")
            partial.replace(target)
        return str(target)


def _shape_geom(shape: Shape, meshes: _Meshes, placement: str, extra: str) -> str:
    if isinstance(shape, Box):
        kind = f'type="box" size="{_fmt(v / 2 for v in shape.size)}"'
    elif isinstance(shape, Cylinder):
        kind = f'type="cylinder" size="{shape.radius:.10g} {shape.length / 2:.10g}"'
    elif isinstance(shape, Sphere):
        kind = f'type="sphere" size="{shape.radius:.10g}"'
    elif isinstance(shape, Mesh):
        kind = f'type="mesh" mesh="{meshes.asset(str(shape.path), shape.scale)}"'
    else:
        raise BackendError(f"unsupported shape {shape!r}")
    return f"<geom {kind} {placement} {extra}/>"


def _urdf_geom(geometry: ET.Element, meshes: _Meshes | None) -> Shape | None:
    box = geometry.find("box")
    if box is not None:
        size = _floats(box.get("size"), 3)
        return Box((size[0], size[1], size[2]))
    cyl = geometry.find("cylinder")
    if cyl is not None:
        return Cylinder(float(cyl.get("radius", 0)), float(cyl.get("length", 0)))
    sphere = geometry.find("sphere")
    if sphere is not None:
        return Sphere(float(sphere.get("radius", 0)))
    mesh = geometry.find("mesh")
    if mesh is not None:
        filename = mesh.get("filename", "")
        if filename.startswith("file://"):
            filename = filename[len("file://"):]
        scale = _floats(mesh.get("scale"), 3, 1.0)
        return Mesh(Path(filename), (scale[0], scale[1], scale[2]))
    return None


# ----------------------------------------------------------------------------- MJCF
@dataclass(frozen=True)
class MjcfOptions:
    """Model-wide settings written into the MJCF.

    Attributes:
        timestep: s per physics step.
        object_physics: per object name, its mass and friction (others: the default).
        default_object: the default :class:`ObjectPhysics`.
        gravity_compensation: the robots' links carry their own weight (as their
            controllers' gravity terms would), so position gains only track motion.
        weld_links: links that hold grasped objects by a weld (``grasp_mode`` weld):
            an inactive weld ``grasp/<link>/<object>`` per link and free object.
    """

    timestep: float = 0.002
    object_physics: Mapping[str, ObjectPhysics] = field(default_factory=dict)
    default_object: ObjectPhysics = field(default_factory=ObjectPhysics)
    gravity_compensation: bool = True
    weld_links: frozenset[str] = frozenset()


def cell_mjcf(cell: PhysicsCell, options: MjcfOptions, cache: Path) -> str:
    """MJCF text for ``cell`` (see the module docstring).

    Every movable URDF joint gets a position actuator named like the joint; its gains are
    placeholders that the backend sets from the joint's limits after compiling.

    Raises:
        BackendError: a malformed URDF, a missing mesh, a mesh format without trimesh.
    """
    root = ET.fromstring(cell.urdf_xml)
    links = {link.get("name", ""): link for link in root.findall("link")}
    children: dict[str, list[ET.Element]] = {}
    for joint in root.findall("joint"):
        parent = joint.find("parent")
        if parent is None or joint.find("child") is None:
            raise BackendError(f"URDF joint {joint.get('name')!r} needs a parent and a child")
        children.setdefault(parent.get("link", ""), []).append(joint)
    meshes = _Meshes(cache)
    attached: dict[str, list[PhysicsObject]] = {}
    for obj in cell.objects:
        if not obj.movable and obj.frame != WORLD:
            attached.setdefault(obj.frame, []).append(obj)
    actuated: list[str] = []
    gravcomp = ' gravcomp="1"' if options.gravity_compensation else ""
    robot_bits, world_bits = _contact_bits(cell)

    def body(joint: ET.Element, depth: int) -> list[str]:
        child = joint.find("child")
        assert child is not None
        name = child.get("link", "")
        link = links.get(name)
        pad = "  " * depth
        out = [f'{pad}<body name="{_esc(name)}" {_origin(joint)}{gravcomp}>']
        kind = joint.get("type", "fixed")
        jname = joint.get("name", "")
        if kind in ("revolute", "continuous", "prismatic"):
            axis_el = joint.find("axis")
            axis = _floats(axis_el.get("xyz"), 3) if axis_el is not None else [1.0, 0.0, 0.0]
            limit = joint.find("limit")
            rng = ""
            if kind != "continuous" and limit is not None:
                rng = (f' range="{float(limit.get("lower", 0)):.10g} '
                       f'{float(limit.get("upper", 0)):.10g}" limited="true"')
            dyn = joint.find("dynamics")
            damping = float(dyn.get("damping", 0) or 0) if dyn is not None else 0.0
            friction = float(dyn.get("friction", 0) or 0) if dyn is not None else 0.0
            mj_type = "slide" if kind == "prismatic" else "hinge"
            out.append(f'{pad}  <joint name="{_esc(jname)}" type="{mj_type}" '
                       f'axis="{_fmt(axis)}"{rng} damping="{damping:.6g}" '
                       f'frictionloss="{friction:.6g}"/>')
            actuated.append(jname)
        elif kind != "fixed":
            raise BackendError(f"URDF joint {jname!r}: type {kind!r} is not supported "
                               "by the mujoco backend")
        bits = robot_bits.get(cell.link_robots.get(name, ""), _ROBOT_BITS)
        out.extend(pad + "  " + line for line in _link_body(name, link, meshes, kind != "fixed",
                                                             cell.link_inertias.get(name), bits))
        for obj in attached.get(name, []):
            out.append(pad + "  " + _static_geom(obj, meshes, world_bits))
        for sub in children.get(name, []):
            out.extend(body(sub, depth + 1))
        out.append(f"{pad}</body>")
        return out

    world_lines: list[str] = []
    for joint in children.get(WORLD, []):
        world_lines.extend(body(joint, 2))
    for obj in cell.objects:
        if not obj.movable and obj.frame == WORLD:
            world_lines.append("    " + _static_geom(obj, meshes, world_bits))
    for obj in cell.objects:
        if obj.movable:
            physics = options.object_physics.get(obj.name) or obj.physics or options.default_object
            inertia = (f'mass="{physics.mass:.10g}"' if physics.mass is not None
                       else f'density="{physics.density:.10g}"')
            geom = _shape_geom(obj.shape, meshes, 'pos="0 0 0"',
                               f'name="{_esc(obj.name)}" {world_bits[0]} {world_bits[1]} '
                               f'condim="4" friction="{_fmt(physics.friction)}" {inertia} '
                               f'solref="{2 * options.timestep:.6g} 1"')
            world_lines.append(
                f'    <body name="{_esc(obj.name)}" pos="{_fmt(obj.xyz)}" '
                f'quat="{_fmt((obj.quat[3], obj.quat[0], obj.quat[1], obj.quat[2]))}">\n'
                f'      <freejoint name="{_esc(obj.name)}"/>\n      {geom}\n    </body>')
    actuators = [f'    <general name="{_esc(j)}" joint="{_esc(j)}" gaintype="fixed" '
                 f'biastype="affine" gainprm="1" biasprm="0 -1 0"/>' for j in actuated]
    equalities = [f'    <joint joint1="{_esc(follower)}" joint2="{_esc(leader)}" '
                  f'polycoef="{offset:.10g} {mul:.10g} 0 0 0" solref="{2 * options.timestep:.6g} 1"/>'
                  for follower, (leader, mul, offset) in cell.mimic.items()
                  if follower in actuated and leader in actuated]
    # Welds for grasp_mode weld: made (relative pose set, activated) when the task grasps.
    equalities += [f'    <weld name="{_esc(weld_name(link, obj.name))}" body1="{_esc(link)}" '
                   f'body2="{_esc(obj.name)}" active="false" relpose="0 0 0 1 0 0 0"/>'
                   for link in sorted(options.weld_links) if link in links
                   for obj in cell.objects if obj.movable]
    return "\n".join([
        f'<mujoco model="{_esc(cell.name)}">',
        '  <compiler angle="radian" autolimits="true" balanceinertia="true" '
        'boundmass="1e-4" boundinertia="1e-7"/>',
        f'  <option timestep="{options.timestep:.6g}" integrator="implicitfast" '
        'cone="elliptic" impratio="10"/>',
        '  <size memory="20M"/>',
        "  <asset>", meshes.xml(), "  </asset>",
        "  <worldbody>",
        *world_lines,
        "  </worldbody>",
        "  <actuator>", *actuators, "  </actuator>",
        "  <equality>", *equalities, "  </equality>",
        "</mujoco>",
    ])


def weld_name(link: str, obj: str) -> str:
    """The name of the weld that holds ``obj`` to ``link`` (grasp_mode weld)."""
    return f"grasp/{link}/{obj}"


def _link_body(name: str, link: ET.Element | None, meshes: _Meshes, moving: bool,
               estimated: LinkInertia | None = None,
               bits: tuple[str, str] = _ROBOT_BITS) -> list[str]:
    lines: list[str] = []
    if link is None:
        return lines
    if estimated is not None and link.find("inertial") is None:
        tensor = estimated.inertia
        diag = [max(float(tensor[k, k]), _MIN_INERTIA) for k in range(3)]
        lines.append(f'<inertial pos="{_fmt(estimated.com)}" mass="{estimated.mass:.10g}" '
                     f'fullinertia="{_fmt([*diag, tensor[0, 1], tensor[0, 2], tensor[1, 2]])}"/>')
    inertial = link.find("inertial")
    if inertial is not None:
        mass_el = inertial.find("mass")
        mass = float(mass_el.get("value", 0)) if mass_el is not None else 0.0
        i = inertial.find("inertia")
        full = ([float(i.get(k, 0)) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")]
                if i is not None else [0.0] * 6)
        if mass > 0:
            origin = inertial.find("origin")
            xyz = _floats(None if origin is None else origin.get("xyz"), 3)
            rpy = _floats(None if origin is None else origin.get("rpy"), 3)
            ixx, iyy, izz, ixy, ixz, iyz = full
            tensor = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
            rot = _matrix(quat_from_rpy(rpy))
            tensor = rot @ tensor @ rot.T  # MJCF wants it in the body frame
            diag = [max(float(tensor[k, k]), _MIN_INERTIA) for k in range(3)]
            lines.append(f'<inertial pos="{_fmt(xyz)}" mass="{mass:.10g}" fullinertia="'
                         f'{_fmt([*diag, tensor[0, 1], tensor[0, 2], tensor[1, 2]])}"/>')
    if not lines and moving:
        lines.append(f'<inertial pos="0 0 0" mass="{_MIN_MASS}" '
                     f'diaginertia="{_MIN_INERTIA} {_MIN_INERTIA} {_MIN_INERTIA}"/>')
    for k, collision in enumerate(link.findall("collision")):
        geometry = collision.find("geometry")
        shape = None if geometry is None else _urdf_geom(geometry, meshes)
        if shape is None:
            continue
        lines.append(_shape_geom(shape, meshes, _origin(collision),
                                 f'name="{_esc(name)}/{k}" {bits[0]} {bits[1]} '
                                 'condim="4" friction="1 0.005 0.0001" group="3" '
                                 'density="0"'))
    return lines


def _static_geom(obj: PhysicsObject, meshes: _Meshes,
                 bits: tuple[str, str] = _WORLD_BITS) -> str:
    quat = (obj.quat[3], obj.quat[0], obj.quat[1], obj.quat[2])
    friction = "" if obj.physics is None else f' friction="{_fmt(obj.physics.friction)}"'
    return _shape_geom(obj.shape, meshes, f'pos="{_fmt(obj.xyz)}" quat="{_fmt(quat)}"',
                       f'name="{_esc(obj.name)}" {bits[0]} {bits[1]}{friction}')


def compiled_model(xml: str, cache: Path) -> tuple[Any, bool]:
    """The MuJoCo model of ``xml``: loaded from the cache (``<sha256>.mjb`` under
    ``cache``) when compiled before, else compiled and cached. Returns ``(model, hit)``.

    Raises:
        BackendError: MuJoCo refuses the model (its message, the cached MJCF's path).
    """
    import mujoco

    digest = hashlib.sha256(f"{mujoco.__version__}\n{xml}".encode()).hexdigest()[:32]
    binary = cache / f"{digest}.mjb"
    if binary.is_file():
        try:
            return mujoco.MjModel.from_binary_path(str(binary)), True
        except Exception:  # a stale or partial file: compile again
            pass
    cache.mkdir(parents=True, exist_ok=True)
    text = cache / f"{digest}.xml"
    text.write_text(xml, encoding="utf-8")
    try:
        model = mujoco.MjModel.from_xml_string(xml)
    except ValueError as exc:
        raise BackendError(f"MuJoCo refused the cell's model ({text}): {exc}") from None
    partial = binary.with_suffix(f".{os.getpid()}.tmp")
    mujoco.mj_saveModel(model, str(partial), None)
    partial.replace(binary)
    return model, False


def body_pose(data: Any, body_id: int) -> tuple[np.ndarray, np.ndarray]:
    """World position and quaternion (w, x, y, z) of a body (copies)."""
    return data.xpos[body_id].copy(), data.xquat[body_id].copy()
