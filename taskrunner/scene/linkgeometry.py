"""Which geometry each robot link is checked with: its exact mesh, its convex hull, or
the primitive shapes of its URDF.

A convex hull checks several times faster than a triangle mesh and gives true signed
distances, but it is fatter than a concave mesh. Each robot chooses (``collision:`` in
its ``robot.yaml`` or in the cell per robot, ``load_workcell(..., collision=)``,
``--collision`` on the command line, ``TASKRUNNER_COLLISION``):

- ``exact``: every link mesh as its triangle mesh;
- ``convex``: every link mesh as its convex hull (a flat mesh keeps its triangles);
- ``auto`` (the default): hulls where they are tight, meshes elsewhere. A link keeps its
  mesh when a hull of its meshes stands more than ``tolerance`` (5 mm) off the mesh
  (:mod:`taskrunner.scene.hullfit`), and when, with hulls, the start state or a named pose
  has a self-collision that the meshes do not have (every link of such a pair that was a
  hull becomes a mesh, until no named pose collides through a hull alone).

The choice is made once per model and kept (the hull measurements on disk as well);
:class:`LinkGeometryPlan` says which links got what and why, for ``run-task info`` and
for collision messages ("… (exact meshes)").
"""

from __future__ import annotations

import dataclasses
import threading
import weakref
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

import coal
import numpy as np
import pinocchio as pin

from taskrunner.errors import InputError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot import RobotModel
from taskrunner.scene.hullfit import hull_excess, shared_convex_hull

__all__ = [
    "COLLISION_CHOICES",
    "DEFAULT_HULL_TOLERANCE",
    "HULL",
    "MESH",
    "PRIMITIVE",
    "LinkChoice",
    "LinkGeometryPlan",
    "check_collision_choice",
    "collision_choices",
    "describe_link_geometry",
    "link_hull",
    "plan_link_geometry",
    "set_collision_choice",
]

COLLISION_CHOICES = tuple(c.value for c in CollisionChoice)
DEFAULT_HULL_TOLERANCE = 0.005
HULL, MESH, PRIMITIVE = "convex hull", "exact mesh", "primitive"
_PLURAL = {HULL: "convex hulls", MESH: "exact meshes", PRIMITIVE: "primitive shapes"}
_MAX_ROUNDS = 10


def check_collision_choice(value: object, what: str = "collision") -> str:
    """``value`` if it is one of :data:`COLLISION_CHOICES`.

    Raises:
        InputError: it is not (the message names ``what``).
    """
    if value not in COLLISION_CHOICES:
        raise InputError(f"'{what}' must be one of {', '.join(COLLISION_CHOICES)} (got {value!r})")
    return str(value)


@dataclass(frozen=True)
class LinkChoice:
    """The geometry one link is checked with.

    Attributes:
        link: the link's name.
        kind: :data:`HULL`, :data:`MESH` or :data:`PRIMITIVE` (no mesh at all).
        choice: its robot's ``collision`` setting (exact, convex, auto).
        reason: why, in a few words.
        excess: how far the hull of its meshes stands off them (m), when measured.
    """

    link: str
    kind: str
    choice: str
    reason: str = ""
    excess: float | None = None


@dataclass(frozen=True)
class LinkGeometryPlan:
    """The geometry of every link with collision geometry, by link name."""

    links: Mapping[str, LinkChoice] = field(default_factory=dict)

    def kind(self, link: str) -> str | None:
        """:data:`HULL`, :data:`MESH`, :data:`PRIMITIVE`, or None for a name that is no
        link with geometry (a scene object)."""
        choice = self.links.get(link)
        return choice.kind if choice is not None else None

    def describe(self, names: Iterable[str]) -> str:
        """The geometry of the robot links among ``names``: ``exact meshes`` when all are
        alike, else ``link5: convex hull; link7: exact mesh``; empty when none is a link."""
        kinds = {n: k for n in dict.fromkeys(names) if (k := self.kind(n)) is not None}
        if not kinds:
            return ""
        distinct = set(kinds.values())
        if len(distinct) == 1:
            return _PLURAL[distinct.pop()]
        return "; ".join(f"{n}: {k}" for n, k in kinds.items())

    def summary(self) -> list[str]:
        """One line per kind: the links that have it, with the reason where a robot's
        ``auto`` choice kept a mesh."""
        lines = []
        for kind in (HULL, MESH, PRIMITIVE):
            links = [c for c in self.links.values() if c.kind == kind]
            if not links:
                continue
            names = ", ".join(
                f"{c.link} ({c.reason})" if kind == MESH and c.choice == CollisionChoice.AUTO else c.link
                for c in links)
            lines.append(f"{_PLURAL[kind]}: {names}")
        return lines


def collision_choices(robot: RobotModel, override: str | Mapping[str, str] | None = None
                      ) -> dict[str, str]:
    """Each robot instance's choice: ``override`` (one for all, or by instance name), else
    the instance's own (``TASKRUNNER_COLLISION`` when the model was loaded, else its
    cell's or robot.yaml's word, else auto).

    Raises:
        InputError: a choice is not exact, convex or auto.
    """
    out = {}
    for inst in robot.instances:
        if isinstance(override, str):
            value = check_collision_choice(override)
        elif override is not None and inst.name in override:
            value = check_collision_choice(override[inst.name], f"collision of {inst.name}")
        else:
            value = check_collision_choice(getattr(inst, "collision", None) or CollisionChoice.AUTO,
                                           f"collision of {inst.name}")
        out[inst.name] = value
    return out


def set_collision_choice(robot: RobotModel, collision: str | Mapping[str, str]) -> None:
    """Set the robots' choice in the model (one for all, or by instance name): every
    scene made of the model afterwards checks its links that way.

    Raises:
        InputError: a choice is not exact, convex or auto, or names no robot.
    """
    if not isinstance(collision, str):
        unknown = [n for n in collision if n not in {i.name for i in robot.instances}]
        if unknown:
            raise InputError(f"'collision' names no robot of the cell: {', '.join(unknown)} "
                             f"(robots: {', '.join(i.name for i in robot.instances)})")
    choices = collision_choices(robot, collision)
    robot.instances = tuple(dataclasses.replace(inst, collision=choices[inst.name])
                            for inst in robot.instances)


class _RobotCache:
    """What is computed once per model: hulls by geometry index, plans by choice."""

    def __init__(self) -> None:
        self.hulls: dict[int, coal.Convex | None] = {}
        self.plans: dict[tuple[tuple[tuple[str, str], ...], float], LinkGeometryPlan] = {}


_lock = threading.RLock()
_caches: dict[int, tuple[weakref.ref[RobotModel], _RobotCache]] = {}


def _cache(robot: RobotModel) -> _RobotCache:
    with _lock:
        entry = _caches.get(id(robot))
        if entry is None or entry[0]() is not robot:
            for key in [k for k, (ref, _) in _caches.items() if ref() is None]:
                del _caches[key]
            entry = (weakref.ref(robot), _RobotCache())
            _caches[id(robot)] = entry
        return entry[1]


def link_hull(robot: RobotModel, index: int) -> coal.Convex | None:
    """The convex hull of the robot's collision geometry object ``index`` (a mesh), or
    None where coal can use none (a flat mesh; see :func:`shared_convex_hull`); computed
    once per model."""
    cache = _cache(robot)
    with _lock:
        if index not in cache.hulls:
            cache.hulls[index] = shared_convex_hull(
                robot.collision_model.geometryObjects[index].geometry)
        return cache.hulls[index]


def _instance_of(robot: RobotModel, link: str) -> str:
    """The instance a link belongs to: the one with the longest prefix the name has."""
    best = robot.instances[0]
    for inst in robot.instances:
        if link.startswith(inst.prefix) and len(inst.prefix) > len(best.prefix):
            best = inst
    return best.name


def plan_link_geometry(robot: RobotModel, collision: str | Mapping[str, str] | None = None,
                       tolerance: float = DEFAULT_HULL_TOLERANCE) -> LinkGeometryPlan:
    """Choose each link's geometry (see the module docstring); kept per model.

    Args:
        robot: the model.
        collision: exact, convex or auto for every robot, or by instance name; None: each
            robot's own choice (see :func:`collision_choices`).
        tolerance: how far (m) a hull may stand off its mesh and still count as tight.

    Raises:
        InputError: a choice is not exact, convex or auto.
    """
    if not tolerance >= 0:
        raise InputError(f"'tolerance' must be >= 0 m (got {tolerance})")
    choices = collision_choices(robot, collision)
    key = (tuple(sorted(choices.items())), float(tolerance))
    cache = _cache(robot)
    with _lock:
        if key in cache.plans:
            return cache.plans[key]
    objects = robot.collision_model.geometryObjects
    frames = robot.model.frames
    by_link: dict[str, list[int]] = {}
    for i, g in enumerate(objects):
        by_link.setdefault(frames[g.parentFrame].name, []).append(i)
    links: dict[str, LinkChoice] = {}
    for link, indices in by_link.items():
        choice = choices[_instance_of(robot, link)]
        meshes = [i for i in indices if isinstance(objects[i].geometry, coal.BVHModelBase)]
        if not meshes:
            links[link] = LinkChoice(link, PRIMITIVE, choice, "no mesh")
        elif choice == CollisionChoice.EXACT:
            links[link] = LinkChoice(link, MESH, choice, "collision: exact")
        elif any(link_hull(robot, i) is None for i in meshes):
            links[link] = LinkChoice(link, MESH, choice, "no convex hull coal can use (a flat "
                                                         "mesh, or a vertex of over 255 faces)")
        elif choice == CollisionChoice.CONVEX:
            links[link] = LinkChoice(link, HULL, choice, "collision: convex")
        else:
            excess = max(hull_excess([objects[i].geometry for i in meshes]))
            mm = excess * 1000.0
            if excess > tolerance:
                links[link] = LinkChoice(link, MESH, choice, f"hull up to {mm:.0f} mm off the mesh",
                                         excess)
            else:
                links[link] = LinkChoice(link, HULL, choice, f"hull within {mm:.1f} mm of the mesh",
                                         excess)
    if any(c.kind == HULL and c.choice == CollisionChoice.AUTO for c in links.values()):
        _keep_named_poses_free(robot, by_link, links)
    plan = LinkGeometryPlan(links)
    with _lock:
        cache.plans[key] = plan
    return plan


def _keep_named_poses_free(robot: RobotModel, by_link: Mapping[str, list[int]],
                           links: dict[str, LinkChoice]) -> None:
    """Under ``auto``, make meshes of the hull links of every pair that collides at the
    start state or a named pose with hulls but not with meshes.

    Only pairs with an ``auto`` hull can differ, so only those are checked: first with the
    current geometry, then, for the pairs that collide, with meshes."""
    states = _named_states(robot)
    for _ in range(_MAX_ROUNDS):
        movable = {link for link, c in links.items() if c.kind == HULL and c.choice == CollisionChoice.AUTO}
        names = sorted(by_link)
        pairs = [(a, b) for i, a in enumerate(names) for b in names[i + 1:]
                 if (a in movable or b in movable)
                 and frozenset((a, b)) not in robot.disabled_collisions]
        if not pairs:
            return
        current = _PairCheck(robot, by_link, pairs, links)
        exact = _PairCheck(robot, by_link, pairs, None)
        changed = False
        for name, q in states:
            touching = current.colliding(q)
            if not touching:
                continue
            for a, b in sorted(touching - exact.colliding(q)):
                for link in (a, b):
                    old = links[link]
                    if old.kind == HULL and old.choice == CollisionChoice.AUTO:
                        links[link] = LinkChoice(
                            link, MESH, old.choice,
                            f"{name} collides as hulls ({a}–{b}), not as meshes", old.excess)
                        changed = True
        if not changed:
            return


class _PairCheck:
    """Which of some link pairs collide at a state, with the links' chosen geometry (or
    their meshes when ``links`` is None)."""

    def __init__(self, robot: RobotModel, by_link: Mapping[str, list[int]],
                 pairs: list[tuple[str, str]], links: Mapping[str, LinkChoice] | None) -> None:
        self._robot = robot
        objects = robot.collision_model.geometryObjects
        self._geometry = pin.GeometryModel()
        slots: dict[str, list[int]] = {}
        for link in sorted({n for pair in pairs for n in pair}):
            for i in by_link[link]:
                source = objects[i]
                shape = source.geometry
                if (links is not None and links[link].kind == HULL
                        and isinstance(shape, coal.BVHModelBase)):
                    shape = link_hull(robot, i) or shape
                slots.setdefault(link, []).append(self._geometry.addGeometryObject(
                    pin.GeometryObject(source.name, source.parentJoint, source.parentFrame,
                                       source.placement, shape)))
        self._pairs: list[tuple[str, str]] = []
        for a, b in pairs:
            for i in slots[a]:
                for j in slots[b]:
                    self._geometry.addCollisionPair(pin.CollisionPair(i, j))
                    self._pairs.append((a, b))
        self._data = robot.model.createData()
        self._geometry_data = self._geometry.createData()

    def colliding(self, q: np.ndarray) -> set[tuple[str, str]]:
        if not pin.computeCollisions(self._robot.model, self._data, self._geometry,
                                     self._geometry_data, self._robot.to_pin(q), False):
            return set()
        results = self._geometry_data.collisionResults
        return {self._pairs[k] for k in range(len(self._pairs)) if results[k].isCollision()}


def _named_states(robot: RobotModel) -> list[tuple[str, np.ndarray]]:
    """The start state (initial_positions.yaml applied) and every named pose set on it."""
    start = robot.default_state()
    if robot.initial_values:
        start = robot.state_with(start, robot.initial_values)
    states = [("the start state", start)]
    seen = {start.tobytes()}
    for group, poses in robot.named_states.items():
        aliases = robot.pose_aliases.get(group, {})
        for name, values in poses.items():
            q = robot.state_with(start, values)
            if name not in aliases and q.tobytes() not in seen:
                seen.add(q.tobytes())
                states.append((f"named pose {name!r}", q))
    return states


def describe_link_geometry(robot: RobotModel) -> list[str]:
    """Lines for ``run-task info``: each robot's choice, then which links are checked as
    hulls, exact meshes (and why, under auto) or primitives."""
    choices = ", ".join(f"{inst.name} {inst.collision}" for inst in robot.instances)
    return [f"collision geometry ({choices}):",
            *(f"  {line}" for line in plan_link_geometry(robot).summary())]
