"""The planning scene: the robot, its current state, objects around it, and what may touch.

A :class:`Scene` plays the part of MoveIt's ``PlanningScene`` for one
:class:`~taskrunner.robot.RobotModel` (which may hold several robots). It owns

- the current robot state (a state vector, see :mod:`taskrunner.robot.model`), used to
  place poses given relative to a link and to carry attached objects;
- world objects, fixed in the world frame, and attached objects, carried by a link and
  allowed to touch it and the caller's ``touch_links`` (MoveIt's AttachedCollisionObject);
- the allowed-collision matrix: the robot's SRDF ``disable_collisions`` pairs plus the
  scene's own allowances (a cube resting on a table: allow ``cube``–``table``).

Collision queries are answered by a :class:`~taskrunner.scene.collision.CollisionChecker`
built lazily after each edit. A scene is not thread-safe: give each worker thread its own
:meth:`Scene.copy`, and a worker process a :meth:`Scene.snapshot`.
"""

from __future__ import annotations

import builtins
import copy
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import coal
import numpy as np
import pinocchio as pin

from taskrunner.errors import ArgumentError, SceneError, UnknownNameError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot import RobotModel
from taskrunner.scene.allowed import AllowedCollisions
from taskrunner.scene.collision import (
    VERIFY_MARGIN,
    Body,
    Clearance,
    CollisionChecker,
    Contact,
    RobotGeometry,
)
from taskrunner.scene.geometry import MeshCache, link_bodies, object_geometry, shape_geometry
from taskrunner.scene.linkgeometry import (
    COLLISION_CHOICES,
    DEFAULT_HULL_TOLERANCE,
    LinkGeometryPlan,
    plan_link_geometry,
)
from taskrunner.scene.objects import SceneObject, SceneSnapshot
from taskrunner.scene.support import Support, gap_below
from taskrunner.shapes import Shape
from taskrunner.types import JointState, Pose

if TYPE_CHECKING:  # the verifier's module loads numba: imported on first use
    from taskrunner.scene.path_verifier import PathVerifier
    from taskrunner.scene.screen import StateScreen

__all__ = ["Scene", "SceneOptions"]

WORLD = "world"
_CHECKERS_KEPT = 4  # recent checkers a scene keeps to come back to (see Scene._build)
_PAIR_VERIFIERS = 4  # sets of pairs a scene keeps a verifier for (see Scene.pair_verifier)


@dataclass(frozen=True)
class SceneOptions:
    """How a scene models the robot's geometry.

    Attributes:
        collision: ``exact``, ``convex`` or ``auto`` for every robot (see
            :mod:`taskrunner.scene.linkgeometry`); None: each robot's own choice (its
            robot.yaml or cell, else auto). Scene object meshes always keep their BVH.
        convex_robot_meshes: the older spelling: True is ``convex``, False ``exact``;
            ``collision`` wins when both are given.
        hull_tolerance: under ``auto``, how far (m) a link's hull may stand off its mesh.
    """

    collision: str | None = None
    convex_robot_meshes: bool | None = None
    hull_tolerance: float = DEFAULT_HULL_TOLERANCE

    def __post_init__(self) -> None:
        if self.convex_robot_meshes is not None and not isinstance(self.convex_robot_meshes, bool):
            raise ArgumentError(
                f"'convex_robot_meshes' must be a bool (got {self.convex_robot_meshes!r})"
            )
        if self.collision is not None and self.collision not in COLLISION_CHOICES:
            raise ArgumentError(f"'collision' must be one of {', '.join(COLLISION_CHOICES)} "
                             f"(got {self.collision!r})")
        if not self.hull_tolerance >= 0:
            raise ArgumentError(f"'hull_tolerance' must be >= 0 m (got {self.hull_tolerance})")

    @property
    def robot_collision(self) -> str | None:
        """The choice for every robot, or None for each robot's own."""
        if self.collision is not None:
            return self.collision
        if self.convex_robot_meshes is not None:
            return CollisionChoice.CONVEX if self.convex_robot_meshes else CollisionChoice.EXACT
        return None


@dataclass(frozen=True)
class _Entry:
    """A scene object with its coal geometry (shared between copies, never edited)."""

    object: SceneObject
    geometry: coal.CollisionGeometry


class Scene:
    """See the module docstring.

    Args:
        robot: the robot model; its state starts at :meth:`RobotModel.default_state`.
        options: geometry options.
    """

    def __init__(self, robot: RobotModel, options: SceneOptions | None = None) -> None:
        self.robot = robot
        self.options = options or SceneOptions()
        self._link_bodies = link_bodies(robot, self.options.robot_collision,
                                        self.options.hull_tolerance)
        # The robot's part of every checker, shared by copies: an edit adds only objects.
        self._robot_geometry = RobotGeometry(robot.model, self._link_bodies)
        self._link_set = frozenset(robot.link_names)
        self._bare_links = frozenset(robot.links_without_collision_geometry())
        self._meshes = MeshCache()
        self._entries: dict[str, _Entry] = {}
        self._allowed = AllowedCollisions(robot.disabled_collisions)
        self._q = robot.default_state()
        self._data = robot.model.createData()
        self._fk_done = False
        self._checker: CollisionChecker | None = None
        self._verifier: tuple[CollisionChecker, PathVerifier] | None = None
        # The checker's geometry rows (a verifier of no pairs): every verifier of it shares them.
        self._rows: tuple[CollisionChecker, PathVerifier] | None = None
        self._screen: tuple[PathVerifier, StateScreen] | None = None
        # Verifiers of some pairs only (two arms against each other), by the pairs' bytes.
        self._pair_verifiers: tuple[CollisionChecker, dict[bytes, PathVerifier]] | None = None
        self._revision = 0
        # The last checkers built, with the entries and allowed pairs they were built for.
        self._built: tuple[tuple[tuple[_Entry, ...], frozenset[frozenset[str]],
                                 CollisionChecker], ...] = ()

    # ----------------------------------------------------------------- copies
    def copy(self) -> Scene:
        """An independent scene with the same objects, allowances and state."""
        other = copy.copy(self)
        other._entries = dict(self._entries)
        other._allowed = self._allowed.copy()
        other._q = self._q.copy()
        other._data = self.robot.model.createData()
        other._fk_done = False
        other._checker = None
        other._verifier = None
        other._rows = None
        other._screen = None
        other._pair_verifiers = None
        other._built = ()  # a checker is not thread-safe: a copy builds its own
        return other

    def snapshot(self) -> SceneSnapshot:
        """A plain-data description: objects, poses, attachments, allowances and state."""
        return SceneSnapshot(
            robot=self.robot.name,
            state=JointState(self.robot.joint_names, self._q.copy()),
            objects=tuple(e.object for e in self._entries.values()),
            allowed=self._allowed.scene_pairs,
        )

    @classmethod
    def from_snapshot(
        cls, robot: RobotModel, snapshot: SceneSnapshot, options: SceneOptions | None = None
    ) -> Scene:
        """Rebuild a scene from :meth:`snapshot` on the same robot model.

        Raises:
            SceneError: the snapshot was taken on another model.
            MissingMeshError: a mesh file of an object is gone.
        """
        if snapshot.robot != robot.name:
            raise SceneError(
                f"snapshot of robot model {snapshot.robot!r} cannot be restored on {robot.name!r}"
            )
        scene = cls(robot, options)
        scene.restore(snapshot)
        return scene

    def restore(self, snapshot: SceneSnapshot) -> None:
        """Replace this scene's objects, allowances and state with a snapshot's, keeping
        the robot geometry already built (cheaper than :meth:`from_snapshot`).

        Raises:
            SceneError: the snapshot was taken on another model.
            MissingMeshError: a mesh file of an object is gone.
        """
        if snapshot.robot != self.robot.name:
            raise SceneError(
                f"snapshot of robot model {snapshot.robot!r} cannot be restored on "
                f"{self.robot.name!r}"
            )
        self._entries = {}
        self._allowed = AllowedCollisions(self.robot.disabled_collisions)
        self.set_state(snapshot.state)
        for obj in snapshot.objects:
            self._check_new_name(obj.name)
            if obj.attached_to is not None:
                self._check_links([obj.attached_to, *obj.touch_links])
            self._entries[obj.name] = _Entry(obj, shape_geometry(obj.shape, self._meshes))
        for a, b in snapshot.allowed:
            self.allow_collision(a, b)
        self._edited()

    # ----------------------------------------------------------------- state
    @property
    def state(self) -> np.ndarray:
        """The current robot state vector (a read-only copy; rad or m)."""
        q = self._q.copy()
        q.setflags(write=False)
        return q

    def set_state(self, q: np.ndarray | JointState | Mapping[str, float]) -> None:
        """Set the robot state: a full state vector, or some joints by name.

        Mimic joints follow their source joints. Attached objects move with their links.

        Raises:
            ValueError: a vector of the wrong length or with non-finite values.
            UnknownNameError: a joint name the model does not have.
        """
        if isinstance(q, (JointState, Mapping)):
            new = self.robot.state_with(self._q, q)
        else:
            new = self._as_state(q)
            self.robot.apply_mimic(new)
        if not np.all(np.isfinite(new)):
            raise ArgumentError(f"'q' must be finite (got {new})")
        self._q = new
        self._fk_done = False

    def link_pose(self, link: str) -> Pose:
        """World pose of a robot link (or any model frame) at the current state."""
        return Pose.from_se3(self._frame_transform(self.robot.frame_id(link)))

    # ----------------------------------------------------------------- objects
    @property
    def object_names(self) -> tuple[str, ...]:
        """Names of all objects, world and attached, in the order they were added."""
        return tuple(self._entries)

    @property
    def objects(self) -> tuple[SceneObject, ...]:
        return tuple(e.object for e in self._entries.values())

    def __contains__(self, name: builtins.object) -> bool:
        return name in self._entries

    def object(self, name: str) -> SceneObject:
        """The object ``name``, its pose in the world or in its link's frame."""
        return self._entry(name).object

    def object_pose(self, name: str) -> Pose:
        """World pose of object ``name``'s frame at the current state."""
        return Pose.from_se3(self._object_transform(self._entry(name).object))

    def attached_objects(self, link: str | None = None) -> tuple[SceneObject, ...]:
        """Attached objects, all or those carried by ``link``."""
        return tuple(
            e.object for e in self._entries.values()
            if e.object.attached and (link is None or e.object.attached_to == link)
        )

    def add_object(
        self,
        name: str,
        shape: Shape,
        pose: Pose,
        attach_to: str | None = None,
        touch_links: Iterable[str] = (),
    ) -> SceneObject:
        """Add an object.

        Args:
            name: unique among objects and robot links.
            shape: its geometry (centred on the object's frame).
            pose: where its frame is, in any frame: ``world``, a robot link (taken at the
                current state) or another object.
            attach_to: a link to attach it to (it then moves with the link); None keeps
                it fixed in the world.
            touch_links: links besides ``attach_to`` it may touch while attached.

        Raises:
            SceneError: the name is taken, or the shape is invalid.
            UnknownNameError: ``pose.frame``, ``attach_to`` or a touch link is unknown.
            MissingMeshError: a mesh file does not exist.
        """
        self._check_new_name(name)
        touch = tuple(touch_links)
        if attach_to is None and touch:
            raise SceneError(f"'touch_links' need 'attach_to' (object {name!r})")
        if attach_to is not None:
            self._check_links([attach_to, *touch])
        world = self._pose_transform(pose)
        geometry = shape_geometry(shape, self._meshes)
        obj = self._placed(name, shape, world, attach_to, touch)
        self._entries[name] = _Entry(obj, geometry)
        self._edited()
        return obj

    def move_object(self, name: str, pose: Pose) -> SceneObject:
        """Move object ``name`` to ``pose`` (any frame); an attached object stays attached."""
        entry = self._entry(name)
        old = entry.object
        world = self._pose_transform(pose)
        obj = self._placed(name, old.shape, world, old.attached_to, old.touch_links)
        self._entries[name] = _Entry(obj, entry.geometry)
        self._edited()
        return obj

    def remove_object(self, name: str) -> None:
        """Remove object ``name`` (world or attached) and the allowances naming it."""
        self._entry(name)
        del self._entries[name]
        self._allowed.forget(name)
        self._edited()

    def attach_object(self, name: str, link: str, touch_links: Iterable[str] = ()) -> SceneObject:
        """Attach world object ``name`` to ``link`` where it is now.

        It then moves with the link and may touch ``link`` and ``touch_links`` (e.g. the
        fingers), but collides with everything else, including the table it was taken from
        unless the scene allows that pair.

        Raises:
            UnknownNameError: unknown object or link.
            SceneError: the object is already attached.
        """
        entry = self._entry(name)
        if entry.object.attached:
            raise SceneError(
                f"object {name!r} is already attached to {entry.object.attached_to!r}; "
                "detach it first"
            )
        touch = tuple(touch_links)
        self._check_links([link, *touch])
        world = self._object_transform(entry.object)
        obj = self._placed(name, entry.object.shape, world, link, touch)
        self._entries[name] = _Entry(obj, entry.geometry)
        self._edited()
        return obj

    def detach_object(self, name: str) -> SceneObject:
        """Detach ``name``: it stays where it is now, as a world object.

        Raises:
            UnknownNameError: unknown object.
            SceneError: the object is not attached.
        """
        entry = self._entry(name)
        if not entry.object.attached:
            raise SceneError(f"object {name!r} is not attached")
        world = self._object_transform(entry.object)
        obj = self._placed(name, entry.object.shape, world, None, ())
        self._entries[name] = _Entry(obj, entry.geometry)
        self._edited()
        return obj

    def support(self, name: str) -> Support:
        """What world object ``name`` rests on: the nearest other world object below it
        and how far it could be lowered before touching it (see
        :mod:`taskrunner.scene.support`). Attached objects and robot links are not
        supports.

        Raises:
            UnknownNameError: unknown object.
            SceneError: the object is attached.
        """
        entry = self._entry(name)
        if entry.object.attached:
            raise SceneError(f"object {name!r} is attached to {entry.object.attached_to!r}; "
                             "it rests on nothing")
        others = [(e.object.name, e.geometry, e.object.pose.se3)
                  for e in self._entries.values() if e.object.name != name
                  and not e.object.attached]
        return gap_below(entry.geometry, entry.object.pose.se3, others)

    # ----------------------------------------------------------------- allowances
    def allow_collision(self, a: str, b: str, reason: str = "scene") -> None:
        """Allow bodies ``a`` and ``b`` (link or object names) to touch."""
        self._check_body(a)
        self._check_body(b)
        self._allowed.allow(a, b, reason)
        self._edited()

    def disallow_collision(self, a: str, b: str) -> None:
        """Withdraw a scene allowance between ``a`` and ``b`` (nothing if there is none).

        Raises:
            SceneError: the pair is allowed by the robot's SRDF or by an attachment,
                which the scene cannot withdraw.
        """
        self._check_body(a)
        self._check_body(b)
        if self._allowed.withdraw(a, b, self.attached_objects()):
            self._edited()

    def collision_allowed(self, a: str, b: str) -> bool:
        """True if bodies ``a`` and ``b`` may touch (SRDF, attachment or scene allowance)."""
        self._check_body(a)
        self._check_body(b)
        return frozenset((a, b)) in self.allowed_collisions()

    def allowed_collisions(self) -> dict[frozenset[str], str]:
        """Every allowed body pair and why: SRDF reasons, ``attached`` or the scene's."""
        return self._allowed.pairs(self.attached_objects())

    # ----------------------------------------------------------------- checks
    def in_collision(self, q: np.ndarray | None = None) -> bool:
        """True if state ``q`` (default: the current state) collides, self or world.

        This is the fast call for planners: no validation of ``q`` beyond pinocchio's.
        """
        checker = self._checker or self._build()
        return checker.in_collision(self.robot.to_pin(self._q if q is None else q))

    def is_valid(self, q: np.ndarray | None = None) -> bool:
        """True if ``q`` is collision-free (joint limits are the planner's bounds, not checked)."""
        checker = self._checker or self._build()
        return not checker.in_collision(self.robot.to_pin(self._q if q is None else q))

    def collisions(self, q: np.ndarray | None = None) -> list[Contact]:
        """The colliding body pairs at ``q`` by name, deepest first (slower; for messages)."""
        checker = self._checker or self._build()
        return checker.collisions(self.robot.to_pin(self._as_state(self._q if q is None else q)))

    def min_distance(self, q: np.ndarray | None = None) -> Clearance:
        """The closest non-allowed body pair at ``q``: ``(distance in m, (a, b))``."""
        checker = self._checker or self._build()
        return checker.min_distance(
            self.robot.to_pin(self._as_state(self._q if q is None else q))
        )

    @property
    def link_geometry(self) -> LinkGeometryPlan:
        """Which links are checked as convex hulls, exact meshes or primitives, and why."""
        return plan_link_geometry(self.robot, self.options.robot_collision,
                                  self.options.hull_tolerance)

    def geometry_note(self, pairs: Iterable[Contact | tuple[str, str]]) -> str:
        """`` (exact meshes)``, `` (convex hulls)`` or per link: the geometry the robot
        links of these colliding pairs were checked with, for messages ("" for none)."""
        names = [n for p in pairs for n in ((p.a, p.b) if isinstance(p, Contact) else p)]
        described = self.link_geometry.describe(names)
        return f" ({described})" if described else ""

    @property
    def checker(self) -> CollisionChecker:
        """The collision checker for the scene as it is now (rebuilt after edits)."""
        return self._checker or self._build()

    def path_verifier(self, margin: float = VERIFY_MARGIN) -> PathVerifier:
        """The exact path verifier (conservative advancement, see
        :mod:`taskrunner.scene.path_verifier`) for the scene as it is now; ``margin`` in m.
        Kept until the next edit of objects or allowances."""
        checker = self.checker
        cached = self._verifier
        if cached is None or cached[0] is not checker or cached[1].margin != margin:
            cached = (checker, self._verifier_rows().restricted(margin=margin))
            self._verifier = cached
        return cached[1]

    def _verifier_rows(self) -> PathVerifier:
        """A verifier of no pairs of the current checker: its geometry rows (lever arms,
        bounding volumes, hull points) and kinematics, which the verifiers of this
        checker (:meth:`path_verifier`, :meth:`pair_verifier`) share."""
        from taskrunner.scene.path_verifier import PathVerifier  # numba: only where verified

        checker = self.checker
        cached = self._rows
        if cached is None or cached[0] is not checker:
            cached = self._rows = (checker, PathVerifier(self.robot, checker,
                                                         pairs=np.zeros(0, dtype=np.int64)))
        return cached[1]

    def pair_verifier(self, pairs: np.ndarray) -> PathVerifier:
        """A path verifier (:meth:`path_verifier`'s margin) of only ``pairs``, indices
        into the checker's collision pairs: e.g. the pairs of bodies of two arms moving at
        once (:mod:`taskrunner.collision.spacetime`). Kept, per set of pairs (the
        :data:`_PAIR_VERIFIERS` latest), until the next edit of objects or allowances.
        Each pair is walked on its own (no grouping into units)."""
        checker = self.checker
        key = np.ascontiguousarray(pairs, dtype=np.int64).tobytes()
        cached = self._pair_verifiers
        if cached is None or cached[0] is not checker:
            cached = self._pair_verifiers = (checker, {})
        kept = cached[1]
        found = kept.get(key)
        if found is None:
            if len(kept) >= _PAIR_VERIFIERS:
                kept.pop(next(iter(kept)))
            found = kept[key] = self._verifier_rows().restricted(
                np.frombuffer(key, dtype=np.int64), grouped=False)
        return found

    def state_screen(self, margin: float = VERIFY_MARGIN) -> StateScreen:
        """The planner's screened state check (:class:`taskrunner.scene.screen.StateScreen`:
        the checker's verdicts, coal asked only where bounding volumes cannot settle them)
        for the scene as it is now, built on :meth:`path_verifier` with ``margin``. Kept
        with that verifier."""
        from taskrunner.scene.screen import StateScreen

        verifier = self.path_verifier(margin)
        cached = self._screen
        if cached is None or cached[0] is not verifier:
            cached = (verifier, StateScreen(verifier))
            self._screen = cached
        return cached[1]

    # ----------------------------------------------------------------- internals
    @property
    def revision(self) -> int:
        """Counts edits of objects and allowances (not state changes): a copy of the scene
        made at the same revision has the same objects."""
        return self._revision

    def _edited(self) -> None:
        self._checker = None
        self._revision += 1

    def _build(self) -> CollisionChecker:
        entries = tuple(self._entries.values())
        allowed = self.allowed_collisions()
        # An edit undone (an allowance given, then taken back) comes back to a scene a
        # checker was built for: the very same entries (objects never change in place) and
        # allowed pairs.
        for built, pairs, checker in self._built:
            if (len(built) == len(entries) and all(a is b for a, b in zip(built, entries))
                    and pairs == allowed.keys()):
                self._checker = checker
                return checker
        bodies = []
        for entry in entries:
            geometry = object_geometry(self.robot, entry.object, entry.geometry)
            bodies.append(Body(entry.object.name, (geometry,), static=not entry.object.attached))
        self._checker = self._robot_geometry.checker(bodies, allowed)
        self._built = (*self._built[-(_CHECKERS_KEPT - 1):],
                       (entries, frozenset(allowed), self._checker))
        return self._checker

    def _as_state(self, q: np.ndarray | list[float]) -> np.ndarray:
        array = np.array(q, dtype=float)
        if array.shape != (self.robot.nq,):
            raise ArgumentError(
                f"'q' must be a state vector of {self.robot.nq} values "
                f"({', '.join(self.robot.joint_names)}) (got shape {array.shape})"
            )
        return array

    def _entry(self, name: str) -> _Entry:
        try:
            return self._entries[name]
        except KeyError:
            raise UnknownNameError("object", name, list(self._entries)) from None

    def _check_new_name(self, name: str) -> None:
        if not isinstance(name, str) or not name:
            raise SceneError(f"'name' must be a non-empty string (got {name!r})")
        if name in self._entries:
            raise SceneError(f"object {name!r} already exists; remove it or move it instead")
        if name == WORLD:
            raise SceneError(f"object name {name!r} is the world frame")
        # Object ids and robot frames are separate namespaces (as in MoveIt), but collision
        # checks and allowances name bodies by one string (MoveIt's ACM does too): an object
        # may share its name with a robot frame only when that frame is never a body there.
        if name in self._link_set and (name not in self._bare_links
                                       or any(name in pair for pair in self.robot.disabled_collisions)):
            raise SceneError(f"object name {name!r} is a link of the robot with collision "
                             "geometry or allowed collisions: collision checks and allowances "
                             "would confuse the two; give the object another name")

    def _check_links(self, links: Iterable[str]) -> None:
        for link in links:
            if link not in self._link_set or link == WORLD:
                raise UnknownNameError(
                    "link", link, [n for n in self.robot.link_names if n != WORLD]
                )

    def _check_body(self, name: str) -> None:
        if name not in self._entries and (name not in self._link_set or name == WORLD):
            known = list(self._entries) + [n for n in self.robot.link_names if n != WORLD]
            raise UnknownNameError("link or object", name, known)

    def _placed(
        self, name: str, shape: Shape, world: pin.SE3, link: str | None, touch: tuple[str, ...]
    ) -> SceneObject:
        """The object at world transform ``world``, expressed in its link frame if attached."""
        if link is None:
            return SceneObject(name, shape, Pose.from_se3(world, WORLD))
        local = self._frame_transform(self.robot.frame_id(link)).actInv(world)
        return SceneObject(name, shape, Pose.from_se3(local, link), link, touch)

    def _frame_transform(self, frame_id: int) -> pin.SE3:
        if not self._fk_done:
            pin.framesForwardKinematics(self.robot.model, self._data, self.robot.to_pin(self._q))
            self._fk_done = True
        return pin.SE3(self._data.oMf[frame_id])

    def _object_transform(self, obj: SceneObject) -> pin.SE3:
        if obj.attached_to is None:
            return obj.pose.se3
        return self._frame_transform(self.robot.frame_id(obj.attached_to)) * obj.pose.se3

    def to_world(self, pose: Pose, q: np.ndarray | None = None) -> pin.SE3:
        """World transform of ``pose``, whose frame is the world, a link or an object;
        links (and the objects they carry) taken at state ``q`` (default: the current one).

        Raises:
            UnknownNameError: the frame is none of those.
        """
        if q is None:
            return self._pose_transform(pose)
        saved = self._q
        self._q, self._fk_done = self._as_state(q), False
        try:
            return self._pose_transform(pose)
        finally:
            self._q, self._fk_done = saved, False

    def _pose_transform(self, pose: Pose) -> pin.SE3:
        """World transform of ``pose``, whose frame is the world, a link or an object."""
        if not isinstance(pose, Pose):
            raise SceneError(f"'pose' must be a taskrunner.types.Pose (got {type(pose).__name__})")
        if pose.frame == WORLD:
            return pose.se3
        # A robot frame first, then an object of that name (MoveIt's frame lookup order).
        if self.robot.model.existFrame(pose.frame):
            return self._frame_transform(self.robot.frame_id(pose.frame)) * pose.se3
        if pose.frame in self._entries:
            return self._object_transform(self._entries[pose.frame].object) * pose.se3
        known = [WORLD, *self._entries, *self.robot.link_names]
        raise UnknownNameError("frame", pose.frame, known)
