"""A physics-simulated cell (MuJoCo): the fingers really have to hold what is carried.

:class:`MujocoBackend` implements the backend protocol of
:class:`~taskrunner.backends.base.BaseBackend` on a MuJoCo model of the cell
(:mod:`taskrunner.backends.physics.mjcf`). One thread steps the physics at a fixed
timestep while anything moves: every joint has a position servo (gains from its effort
limit, see :class:`MujocoOptions`) whose target follows the running trajectory (the
trajectory's velocity fed forward); joints no trajectory moves hold their last target;
a mimic joint follows its leader through an equality constraint (a coupled gripper
centres what it grasps). A motion ends ``settle`` s after its trajectory (objects come
to rest), and the world pauses until the next motion, so a task of one motion after
another gives the same result on every run (physics time depends on nothing but the
motions; motions started while another runs start when the call comes).

What the physics did is checked as it happens, and a motion fails (its handle's
``wait()`` raises :class:`~taskrunner.errors.BackendError`, the step fails with its
file:line) when:

- an object that the task's scene holds in a gripper moves away from that gripper by
  more than ``slip_distance`` or ``slip_angle``: it "slipped" when a hand touched it
  since it was last let go (while the fingers closed, say), else it "was never
  touched";
- a joint lags its trajectory by more than ``tracking_tolerance`` (finger joints are
  exempt: a finger blocked by what it grasps is the point of closing);
- a contact on the robot, other than a hand on a free object, pushes harder than
  ``contact_force_limit`` (an unplanned collision);
- a link of one robot touches a link of another (two arms of a cell), however lightly:
  the message names both links and their robots.

The task's scene is bound with :meth:`bind_scene` (the runner's context does it): the
backend then builds its world with the scene's objects, learns what the task believes
is held at each ``execute``, and reports where objects really are with
:meth:`object_poses`. ``grasp_mode`` weld for an arm (the cell's ``grasp_mode``, or
:class:`MujocoOptions`) welds a held object to the arm's grasp frame while the scene holds
it, for grippers that cannot hold by friction in the simulation; :attr:`notes` and
:meth:`physics_report` say when a weld was made and released. An object attached to a
link that is no arm's grasp frame (``attach: {link: …}``: a suction cup, a magnet) is
welded to that link the same way while it is attached. Units: m, kg, rad, s, N.
"""

from __future__ import annotations

import math
import threading
import time
from collections import deque
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from taskrunner.backends.base import BaseBackend, TrajectoryExecution
from taskrunner.backends.execution import ExecutionStatus
from taskrunner.backends.physics.mjcf import (
    MjcfOptions,
    ObjectPhysics,
    PhysicsCell,
    PhysicsObject,
    cell_mjcf,
    compiled_model,
    weld_name,
)
from taskrunner.backends.physics.options import MujocoOptions, PhysicsSample
from taskrunner.backends.physics.report import motion_entry, physics_report_of
from taskrunner.errors import BackendError
from taskrunner.types import JointState, Pose

__all__ = ["MujocoBackend"]

_JOIN_TIMEOUT = 5.0  # s
_CHUNK = 10  # physics steps between looks at the shared state (20 ms at 2 ms)
_SATURATION = {"hinge": 0.05, "slide": 0.005}  # rad / m of error at which effort saturates
_FINGER_SATURATION = {"hinge": 0.2, "slide": 0.01}  # a finger: full grip this far off
_STABLE_STEP = 0.3  # omega * dt at most: armature added where a servo would be too stiff
_DEFAULT_EFFORT = 10.0  # N m or N, for a URDF joint without an effort limit


@dataclass
class _Held:
    """An object the task's scene holds: the gripper body and the pose relative to it."""

    body: int
    link: str
    rel_pos: np.ndarray
    rel_quat: np.ndarray
    weld: int | None = None


class MujocoBackend(BaseBackend):
    """The cell in MuJoCo (see the module docstring).

    Args:
        joint_names: every joint driven (the cell model's joints, names as in the URDF).
        cell: the physics description of the cell.
        initial_positions: positions at start (rad or m).
        options: see :class:`MujocoOptions`.

    Raises:
        BackendError: the cell cannot be made into a MuJoCo model.
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str], cell: PhysicsCell,
                 initial_positions: JointState | Mapping[str, float] | None = None,
                 options: MujocoOptions | None = None) -> None:
        self._options = options or MujocoOptions()
        super().__init__(joint_names, initial_positions,
                         start_tolerance=self._options.start_tolerance)
        from taskrunner.resources import user_cache_dir

        self._cache = (user_cache_dir() / "mujoco" if self._options.cache_dir is None
                       else _path(self._options.cache_dir))
        self._cell = cell
        self._scene: Any = None
        self._scene_names: tuple[str, ...] = ()
        self._wake = threading.Condition(self._lock)
        self._stepping = False  # a chunk is being stepped (outside the lock)
        self._history: deque[PhysicsSample] = deque(maxlen=100_000)
        self._unreported: deque[PhysicsSample] = deque(maxlen=20_000)
        self._grasp_log: list[dict[str, Any]] = []
        self._motion_log: list[dict[str, Any]] = []  # motions ended since the last report
        self._weld_changes: list[tuple[str, _Held, bool]] = []
        self._materials: dict[str, ObjectPhysics] = {}
        self._cell_physics = {o.name: o.physics for o in cell.objects if o.physics is not None}
        self._cell_static = frozenset(o.name for o in cell.objects if not o.movable)
        # Links (not an arm's grasp frame) that objects were attached to: a suction cup or
        # magnet holds by a weld, there being nothing to hold by friction.
        self._suction: frozenset[str] = frozenset()
        self._named: frozenset[str] | None = None  # objects the task handles (bind_scene)
        modes = {**cell.grasp_modes, **self._options.grasp_mode}
        unknown = sorted(set(modes) - set(cell.grasp_frames))
        if unknown:
            raise BackendError(f"grasp_mode: {', '.join(map(repr, unknown))} is not an arm of "
                               f"{cell.name!r} (arms: {', '.join(sorted(cell.grasp_frames))})")
        self._weld_arms = {cell.grasp_frames[arm]: arm for arm, mode in modes.items()
                           if mode == "weld"}
        self.notes: list[str] = []
        self.build_seconds = 0.0
        self.step_seconds = 0.0  # wall s spent stepping the physics (a benchmark's figure)
        self.cache_hit = False
        self.failures: list[str] = []
        self._build(cell)
        self._thread = threading.Thread(target=self._run, name=f"MujocoBackend-{id(self):x}",
                                        daemon=True)
        self._thread.start()

    # -- public ------------------------------------------------------------------------

    @property
    def options(self) -> MujocoOptions:
        return self._options

    @property
    def sim_time(self) -> float:
        """Seconds of physics simulated so far."""
        with self._lock:
            return float(self._data.time)

    @property
    def model(self) -> Any:
        """The compiled ``mujoco.MjModel`` (read only, please)."""
        return self._model

    def bind_scene(self, scene: Any, materials: Mapping[str, Any] | None = None) -> None:
        """Use the task's scene: its objects join the world (rebuilding it if they are new)
        and its attachments say what is held at each ``execute``. Duck-typed: anything
        with ``objects`` (name, shape, pose, attached_to) and ``object_pose(name)``.
        ``materials``: per object the task declares or handles, the mass, density and
        friction it gives it (:class:`~taskrunner.materials.Material`, empty for the
        defaults), over the cell's.

        Which objects are free bodies (MoveIt's semantics: a scene's world objects are
        fixed): those ``materials`` names, those attached to the robot, and the cell's
        objects with a mass or density. Any other object of the scene (a PlanningScene
        file's table, shelf or wall) is static where the scene has it. Without
        ``materials`` ever given, every object the cell does not fix is free.)"""
        names = tuple(scene.object_names)
        physics = {name: ObjectPhysics.from_material(m, self._options.default_object)
                   for name, m in (materials or {}).items() if m}
        named = None if materials is None else frozenset(materials)
        attached = frozenset(o.name for o in scene.objects if o.attached_to is not None)
        with self._lock:
            if (scene is self._scene and names == self._scene_names
                    and attached <= self._free_names
                    and self._suction_links(scene) <= self._suction
                    and (materials is None or (physics == self._materials
                                               and named == self._named))):
                return
            self._scene, self._scene_names = scene, names
            if materials is not None:
                self._materials, self._named = physics, named
            self._sync_objects()

    def physics_report(self) -> dict[str, Any] | None:
        """What the physics did since the last report (None: nothing): joints and free
        objects every ``history_period`` s (thinned evenly to at most 500 samples), and
        the welds made and released (``grasp_mode`` weld), and each motion that ended
        since: its joints and first sample (rad or m), the physics time it started at
        (``start``, s), its trajectory's seconds (``duration``), and the seconds of physics
        it settled after its trajectory's end (``settle``; None: it ended before, stopped
        or failed). JSON-ready::

            {"period": 0.04, "joints": [names], "t": [s], "q": [[rad or m]],
             "objects": {name: [[x, y, z, qx, qy, qz, qw] or None]},
             "grasps": [{"time", "action": "welded" | "released", "object", "link", "arm"}],
             "motions": [{"joints", "first", "start", "duration", "settle", "status"}]}
        """
        with self._lock:
            samples, grasps, motions = list(self._unreported), self._grasp_log, self._motion_log
            self._unreported.clear()
            self._grasp_log, self._motion_log = [], []
        return physics_report_of(samples, grasps, motions, self._options.history_period,
                                 self._names)

    def object_poses(self) -> dict[str, Pose]:
        """World pose of every free object, as the physics has it now."""
        with self._lock:
            return dict(self._object_poses)

    def match_scene(self, closed: Mapping[str, float] | None = None) -> list[str]:
        """Make a world started afresh the bound scene's (a new process resuming a run):
        objects where the scene has them, the held ones gripped again (``closed``: the
        finger joints' closed poses, rad or m) and checked; see
        :func:`~taskrunner.backends.physics.matching.match_scene`.

        Returns:
            What was done, one line per object held (also in :attr:`notes`).

        Raises:
            BackendError: the scene cannot be matched (with the reason).
        """
        from taskrunner.backends.physics.matching import match_scene

        return match_scene(self, closed)

    def history(self) -> list[PhysicsSample]:
        """Joints and free objects every ``history_period`` s of physics while anything
        moved, oldest first."""
        with self._lock:
            return list(self._history)

    def close(self) -> None:
        with self._lock:
            super().close()
            self._wake.notify_all()
        if threading.current_thread() is not self._thread:
            self._thread.join(_JOIN_TIMEOUT)

    # -- building ----------------------------------------------------------------------

    def _build(self, cell: PhysicsCell) -> None:
        started = time.perf_counter()
        o = self._options
        welds = frozenset(self._weld_arms) | self._suction
        xml = cell_mjcf(cell, MjcfOptions(o.timestep, o.objects, o.default_object,
                                          weld_links=welds), self._cache)
        model, self.cache_hit = compiled_model(xml, self._cache)
        old = getattr(self, "_data", None)
        data = mujoco.MjData(model)
        self._model, self._data = model, data
        self._cell = cell
        self._jnt = {}
        for name in self._names:
            jid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            if jid < 0:
                raise BackendError(f"joint {name!r} is not in the MuJoCo model of "
                                   f"{cell.name!r}")
            self._jnt[name] = jid
        self._qadr = np.array([model.jnt_qposadr[self._jnt[n]] for n in self._names])
        self._dadr = np.array([model.jnt_dofadr[self._jnt[n]] for n in self._names])
        self._act = np.array([mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, n)
                              for n in self._names])
        limited = model.jnt_limited[[self._jnt[n] for n in self._names]].astype(bool)
        ranges = model.jnt_range[[self._jnt[n] for n in self._names]]
        self._lower = np.where(limited, ranges[:, 0], -np.inf)
        self._upper = np.where(limited, ranges[:, 1], np.inf)
        self._mimic = [(self._index[f], self._index[src], mul, off)
                       for f, (src, mul, off) in cell.mimic.items()
                       if f in self._index and src in self._index]
        self._finger = np.array([n in cell.gripper_joints for n in self._names])
        self._objects = {o.name: mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, o.name)
                         for o in cell.objects if o.movable}
        self._free_names = frozenset(self._objects)
        self._object_of = {body: name for name, body in self._objects.items()}
        # Free objects a hand has touched since they were last let go (never touched or
        # slipped, when a held one comes loose).
        self._touched: set[str] = set()
        self._moving_joints: dict[int, frozenset[str]] = {}  # by running motion: joints it moves
        self._robot_bodies = {int(b) for b in range(1, model.nbody)
                              if model.body(b).name not in self._objects}
        self._hand_bodies = {mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, link)
                             for link in cell.hand_links} - {-1}
        # The robot of each link body, in a cell of several (links of two robots touch).
        self._robot_of = {b: cell.link_robots[model.body(b).name] for b in self._robot_bodies
                          if model.body(b).name in cell.link_robots}
        data.qpos[self._qadr] = self._positions
        if old is not None:  # a rebuild: the objects that were there stay where they were,
            data.time = old.time  # and the clock goes on (physics time is the run's)
            for name, body in self._objects.items():
                pose = self._object_poses.get(name)
                if pose is not None:
                    adr = model.jnt_qposadr[model.body_jntadr[body]]
                    data.qpos[adr:adr + 3] = pose.xyz
                    x, y, z, w = pose.quat
                    data.qpos[adr + 3:adr + 7] = (w, x, y, z)
        mujoco.mj_forward(model, data)
        self._set_gains()
        self._targets = self._positions.copy()
        self._velocities = np.zeros(len(self._names))
        self._held: dict[str, _Held] = {}  # a rebuilt world re-grasps at the next motion
        self._weld_changes = []
        self._object_poses: dict[str, Pose] = {}
        self._publish()
        self._starts: dict[int, float] = {}
        self._next_sample = float(data.time)
        self._finish_pending: dict[int, float] = {}
        self.build_seconds = time.perf_counter() - started

    def _set_gains(self) -> None:
        """Position servos from each joint's effort limit: full effort at ``saturation``
        error, critically damped on the joint's inertia at the start; armature (the
        reflected inertia of a geared servo) where the servo would outrun the timestep."""
        model, data = self._model, self._data
        unit, column = np.zeros(model.nv), np.zeros(model.nv)
        efforts = _urdf_efforts(self._cell.urdf_xml)
        dt = model.opt.timestep
        self.gains: dict[str, tuple[float, float, float]] = {}
        for k, name in enumerate(self._names):
            jid, dof, act = self._jnt[name], int(self._dadr[k]), int(self._act[k])
            kind = "slide" if model.jnt_type[jid] == mujoco.mjtJoint.mjJNT_SLIDE else "hinge"
            effort = self._options.effort.get(name, efforts.get(name) or _DEFAULT_EFFORT)
            saturation = _SATURATION[kind]
            if self._finger[k] and name not in self._options.effort:
                # A gripper squeezes with a grip force, not its joint's full effort (a light
                # object between two fingers at full effort crushes MuJoCo's soft contacts).
                effort = min(effort, self._options.grip_effort[kind])
                saturation = _FINGER_SATURATION[kind]
            kp = effort / self._options.saturation.get(name, saturation)
            if name in self._cell.mimic:  # the coupling drives it, not a servo of its own
                kp, effort = 0.0, 0.0
            unit[:] = 0.0
            unit[dof] = 1.0
            mujoco.mj_mulM(model, data, column, unit)
            inertia = float(column[dof])
            armature = max(0.0, kp * (dt / _STABLE_STEP) ** 2 - inertia)
            model.dof_armature[dof] += armature
            kv = 2.0 * math.sqrt(kp * (inertia + armature))
            model.actuator_ctrllimited[act] = 0
            model.actuator_gainprm[act, 0] = kp
            model.actuator_biasprm[act, :3] = (0.0, -kp, -kv)
            model.actuator_forcelimited[act] = 1
            model.actuator_forcerange[act] = (-effort, effort)
            self.gains[name] = (kp, kv, effort)

    def _sync_objects(self, beginning: TrajectoryExecution | None = None) -> None:
        """Rebuild the world if the bound scene has free objects it lacks (under the lock;
        ``beginning``: a motion accepted but not yet stepped, which a rebuild spares)."""
        scene = self._scene
        if scene is None:
            return
        static = self._cell_static
        free = {o.name for o in self._cell.objects if o.movable} | set(self._named or ())
        wanted, fixed = [], []
        for obj in scene.objects:
            if obj.name in static:
                continue
            pose = scene.object_pose(obj.name)
            physics = self._materials.get(obj.name, self._cell_physics.get(obj.name))
            if (self._named is not None and obj.name not in free
                    and obj.attached_to is None and obj.name not in self._free_names):
                fixed.append(PhysicsObject(obj.name, obj.shape, pose.xyz, pose.quat,
                                           movable=False, physics=physics))
                continue
            wanted.append(PhysicsObject(obj.name, obj.shape, pose.xyz, pose.quat, movable=True,
                                        physics=physics))
        built = {o.name: o.physics for o in self._cell.objects if o.movable}
        built_fixed = {o.name for o in self._cell.objects
                       if not o.movable and o.name not in static}
        suction = self._suction_links(scene)
        if ({o.name: o.physics for o in wanted} == built
                and {o.name for o in fixed} == built_fixed and suction <= self._suction):
            return
        self._suction |= suction
        if any(e is not beginning for e in self._executions):
            raise BackendError("objects were added to the scene while a motion runs; the "
                               "mujoco backend adds objects between motions")
        kept = [o for o in self._cell.objects if not o.movable and o.name in static] + fixed
        poses = dict(self._object_poses)
        self._build(self._cell.with_objects([*kept, *wanted]))
        self._object_poses.update({k: v for k, v in poses.items() if k in self._objects})
        self._restore_objects(poses)

    def _suction_links(self, scene: Any) -> frozenset[str]:
        """Links the scene attaches objects to that are no arm's grasp frame."""
        grasping = set(self._cell.grasp_frames.values())
        links = (self._cell.frame_links.get(o.attached_to, o.attached_to)
                 for o in scene.objects if o.attached_to is not None)
        return frozenset(link for link in links if link not in grasping)

    def _restore_objects(self, poses: Mapping[str, Pose]) -> None:
        model, data = self._model, self._data
        for name, body in self._objects.items():
            pose = poses.get(name)
            if pose is None:
                continue
            adr = model.jnt_qposadr[model.body_jntadr[body]]
            data.qpos[adr:adr + 3] = pose.xyz
            x, y, z, w = pose.quat
            data.qpos[adr + 3:adr + 7] = (w, x, y, z)
        mujoco.mj_forward(model, data)
        self._publish()

    # -- BaseBackend -------------------------------------------------------------------

    def _begin(self, execution: TrajectoryExecution) -> None:
        self._sync_objects(execution)
        self._bind_held()
        # The world is paused between motions (each ends settled), so one motion after
        # another starts at the same physics time on every run.
        self._starts[id(execution)] = float(self._data.time)
        self._wake.notify_all()

    def _bind_held(self) -> None:
        """Record what the scene holds, relative to its gripper as the physics has it."""
        scene = self._scene
        if scene is None:
            return
        model, data = self._model, self._data
        held: dict[str, _Held] = {}
        weld_links = self._weld_arms
        for obj in scene.objects:
            if obj.attached_to is None or obj.name not in self._objects:
                continue
            link = self._cell.frame_links.get(obj.attached_to, obj.attached_to)
            link_body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, link)
            if link_body < 0:  # fails the motion: nothing would check that it is held
                self.failures.append(f"object {obj.name!r} is attached to "
                                     f"{obj.attached_to!r}, which is not a link of the cell's "
                                     "MuJoCo model")
                continue
            previous = self._held.get(obj.name)
            if previous is not None and previous.body == link_body:
                held[obj.name] = previous
                continue
            rel_pos, rel_quat = _relative(data, link_body, self._objects[obj.name])
            entry = _Held(link_body, link, rel_pos, rel_quat)
            if link in weld_links or link in self._suction:
                weld = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_EQUALITY,
                                         weld_name(link, obj.name))
                if weld >= 0:
                    entry.weld = int(weld)
                    self._weld_changes.append((obj.name, entry, True))
            held[obj.name] = entry
        for name, entry in self._held.items():
            if entry.weld is not None and (name not in held or held[name] is not entry):
                self._weld_changes.append((name, entry, False))
            if name not in held:
                self._touched.discard(name)
        self._held = held

    def _apply_welds(self) -> None:
        """Make and release the welds of ``grasp_mode`` weld (the physics thread, under
        the lock, between chunks): a weld holds the object where it is relative to the
        grasp frame when it is made."""
        model, data = self._model, self._data
        for name, entry, make in self._weld_changes:
            assert entry.weld is not None
            if make:
                rel_pos, rel_quat = _relative(data, entry.body, self._objects[name])
                model.eq_data[entry.weld, 0:3] = 0.0  # anchor: the object's origin
                model.eq_data[entry.weld, 3:6] = rel_pos
                model.eq_data[entry.weld, 6:10] = rel_quat
                model.eq_data[entry.weld, 10] = 1.0  # torquescale
            data.eq_active[entry.weld] = 1 if make else 0
            arm = self._weld_arms.get(entry.link)  # None: attached to a link (suction)
            action = "welded" if make else "released"
            self._grasp_log.append({"time": round(float(data.time), 4), "action": action,
                                    "object": name, "link": entry.link, "arm": arm})
            self.notes.append(f"grasp_mode weld: {name!r} {action} "
                              f"{'to' if make else 'from'} {entry.link!r} (arm {arm!r}) at "
                              f"{data.time:.3f} s of physics")
        self._weld_changes.clear()

    # -- the physics thread ------------------------------------------------------------

    def _run(self) -> None:
        try:
            while True:
                with self._lock:
                    while not self._closed and not self._executions:
                        self._wake.wait()
                    if self._closed:
                        return
                    plan = self._plan_chunk()
                    self._stepping = True
                wall = time.perf_counter()
                self._step_chunk(plan)
                self.step_seconds += time.perf_counter() - wall
                with self._lock:
                    self._stepping = False
                    self._wake.notify_all()  # a stop waiting for the chunk's end
                    self._after_chunk(plan)
                speed = self._options.speed
                if speed is not None:
                    late = _CHUNK * self._model.opt.timestep / speed - (time.perf_counter() - wall)
                    if late > 0:
                        time.sleep(late)
                else:
                    time.sleep(0)  # let the tree and the display look in
        except Exception as exc:  # no handle may wait forever
            with self._lock:
                self._stepping = False
                self._wake.notify_all()
                self._closed = True
                self._closed_reason = f"stopped: its physics thread died ({exc!r})"
                for execution in list(self._executions):
                    message = f"physics simulation died: {exc!r}"
                    self._finish(execution, "failed", message, BackendError(message))

    def _plan_chunk(self) -> list[tuple[TrajectoryExecution, float]]:
        """The running executions and their start times (under the lock)."""
        if self._weld_changes:
            self._apply_welds()
        return [(e, self._starts.get(id(e), float(self._data.time))) for e in self._executions]

    def _step_chunk(self, plan: list[tuple[TrajectoryExecution, float]]) -> None:
        """Step the physics ``_CHUNK`` times, servos following the trajectories (no lock:
        only this thread touches the MuJoCo data while it steps)."""
        model, data = self._model, self._data
        targets, velocities = self._targets.copy(), np.zeros(len(self._names))
        kp = model.actuator_gainprm[self._act, 0]
        kv = -model.actuator_biasprm[self._act, 2]
        lead = np.divide(kv, kp, out=np.zeros_like(kp), where=kp > 0)  # s: velocity fed forward
        for _ in range(_CHUNK):
            t = float(data.time)
            for execution, start in plan:
                if t < start:
                    continue
                tr = execution.trajectory
                local = min(t - start, execution.duration) + float(tr.times[0])
                q, qd = _sample(tr, local)
                targets[execution.columns] = q
                velocities[execution.columns] = qd if t - start < execution.duration else 0.0
            for follower, leader, mul, off in self._mimic:
                targets[follower] = mul * targets[leader] + off
                velocities[follower] = mul * velocities[leader]
            data.ctrl[self._act] = targets + lead * velocities
            mujoco.mj_step(model, data)
            self._check_contacts()
        self._chunk_targets = targets

    def _check_contacts(self) -> None:
        limit = self._options.contact_force_limit
        model, data = self._model, self._data
        if data.ncon == 0:
            return
        force = np.zeros(6)
        for i in range(data.ncon):
            contact = data.contact[i]
            b1, b2 = model.geom_bodyid[contact.geom1], model.geom_bodyid[contact.geom2]
            robot1, robot2 = b1 in self._robot_bodies, b2 in self._robot_bodies
            if not (robot1 or robot2):
                continue
            if robot1 and robot2:
                first, second = self._robot_of.get(b1), self._robot_of.get(b2)
                if first != second and first is not None and second is not None:
                    if not self.failures:
                        self.failures.append(
                            f"contact between robots: {model.body(b1).name!r} ({first}) "
                            f"touched {model.body(b2).name!r} ({second}) at {data.time:.3f} s "
                            f"of physics")
                    continue
            other = b2 if robot1 else b1
            link = b1 if robot1 else b2
            other_geom = contact.geom2 if robot1 else contact.geom1
            if link in self._hand_bodies and other in self._object_of:
                self._touched.add(self._object_of[other])
                continue  # a grasp
            mujoco.mj_contactForce(model, data, i, force)
            if abs(force[0]) > limit and not self.failures:
                self.failures.append(
                    f"unplanned contact: {model.body(link).name!r} pushed against "
                    f"{(model.body(other).name if other else model.geom(other_geom).name) or 'the world'!r} "
                    f"with {abs(force[0]):.0f} N "
                    f"(limit {limit:g} N) at {data.time:.3f} s of physics")

    def _after_chunk(self, plan: list[tuple[TrajectoryExecution, float]]) -> None:
        """Publish the state, end finished motions, fail what physics broke (under the lock)."""
        data = self._data
        now = float(data.time)
        self._targets = self._chunk_targets
        self._publish()
        failure = self.failures.pop(0) if self.failures else None
        if failure is None:
            failure = self._slip(self._releasing(plan))
        for execution, start in plan:
            if execution.finished:  # cancelled while the chunk ran: hold where it is
                self._targets[execution.columns] = self._positions[execution.columns]
                self._starts.pop(id(execution), None)
                continue
            elapsed = max(0.0, now - start)
            execution.set_progress(min(elapsed, execution.duration))
            lag = np.abs(self._positions[execution.columns] - self._targets[execution.columns])
            lag[self._finger[execution.columns]] = 0.0
            if failure is None and lag.size and float(lag.max()) > self._options.tracking_tolerance:
                j = int(np.argmax(lag))
                failure = (f"tracking error: joint {execution.trajectory.names[j]!r} is "
                           f"{float(lag[j]):.3f} from its trajectory at "
                           f"{min(elapsed, execution.duration):.3f} s of "
                           f"{execution.duration:.3f} s (tolerance "
                           f"{self._options.tracking_tolerance:g})")
            if failure is not None:
                self._targets[execution.columns] = self._positions[execution.columns]
                self._finish(execution, "failed", failure, BackendError(failure))
            elif elapsed >= execution.duration + self._options.settle:
                self._finish(execution, "succeeded", "trajectory executed")
            if execution.finished:
                self._starts.pop(id(execution), None)
        if failure is not None and not plan:
            self.notes.append(f"after the motions: {failure}")
        ended = any(execution.finished for execution, _ in plan)
        if now >= self._next_sample - 1e-9 or ended:  # and the state each motion ends in
            self._next_sample = now + self._options.history_period
            sample = PhysicsSample(now, JointState(self._names, self._positions),
                                   dict(self._object_poses))
            self._history.append(sample)
            self._unreported.append(sample)

    def _releasing(self, plan: list[tuple[TrajectoryExecution, float]]) -> frozenset[str]:
        """Held objects that the running motions may let go of: their fingers move while
        nothing moves the link holding them (a gripper opening, as a place does before the
        scene lets go of the object). The object then settles on what it is set down on
        and may leave the hand: not a slip (where it ends is the place's own check).
        Their hold is checked again at the next motion that moves their holder."""
        moving: set[str] = set()
        known = self._moving_joints
        for key in set(known) - {id(execution) for execution, _ in plan}:
            del known[key]  # motions ended
        for execution, _ in plan:
            joints = known.get(id(execution))
            if joints is None:
                positions = np.asarray(execution.trajectory.positions, dtype=float)
                spread = (positions.max(axis=0) - positions.min(axis=0) if positions.size
                          else np.zeros(len(execution.trajectory.names)))
                joints = known[id(execution)] = frozenset(
                    n for n, d in zip(execution.trajectory.names, spread) if d > 1e-9)
            moving |= joints
        fingers = moving & self._cell.gripper_joints
        if not fingers:
            return frozenset()
        model = self._model
        out = []
        for name, held in self._held.items():
            carried: set[str] = set()  # joints between the world and the holding link
            body = held.body
            while body > 0:
                first, count = model.body_jntadr[body], model.body_jntnum[body]
                carried.update(model.joint(j).name for j in range(first, first + count))
                body = model.body_parentid[body]
            moved_fingers = {f for f in fingers if self._holds_finger(held.body, f)}
            if moved_fingers and not (moving & carried):
                out.append(name)
        return frozenset(out)

    def _holds_finger(self, holder: int, joint: str) -> bool:
        """Whether finger joint ``joint`` hangs from the same hand as body ``holder`` (its
        body's parent is the holder or one of the holder's ancestors' children)."""
        model = self._model
        body = model.jnt_bodyid[self._jnt[joint]] if joint in self._jnt else -1
        if body < 0:
            return False
        chain = set()
        b = holder
        while b > 0:
            chain.add(int(b))
            b = model.body_parentid[b]
        return int(model.body_parentid[body]) in chain

    def _slip(self, releasing: frozenset[str] = frozenset()) -> str | None:
        data = self._data
        for name, held in self._held.items():
            if held.weld is not None or name in releasing:
                continue
            rel_pos, rel_quat = _relative(data, held.body, self._objects[name])
            moved = float(np.linalg.norm(rel_pos - held.rel_pos))
            turned = _angle(rel_quat, held.rel_quat)
            if moved > self._options.slip_distance or turned > self._options.slip_angle:
                del self._held[name]
                how = ("slipped out of the gripper" if name in self._touched else
                       "was never touched by the gripper (no contact between the hand and "
                       "it since it was grasped)")
                return (f"object {name!r} {how}: it moved "
                        f"{1e3 * moved:.0f} mm and turned {math.degrees(turned):.0f} deg "
                        f"relative to {held.link!r} (limits "
                        f"{1e3 * self._options.slip_distance:.0f} mm, "
                        f"{math.degrees(self._options.slip_angle):.0f} deg)")
        return None

    def _publish(self) -> None:
        """Copy the measured joints and objects out of the MuJoCo data (under the lock)."""
        data, model = self._data, self._model
        # A soft joint limit gives a little (microns): report what an encoder at a hard
        # stop would, so that plans from this state start within the limits.
        self._positions = np.clip(data.qpos[self._qadr], self._lower, self._upper)
        poses = {}
        for name, body in self._objects.items():
            adr = model.jnt_qposadr[model.body_jntadr[body]]
            w, x, y, z = data.qpos[adr + 3:adr + 7]
            poses[name] = Pose(tuple(data.qpos[adr:adr + 3]), (x, y, z, w))
        self._object_poses = poses

    def _finish(self, execution: TrajectoryExecution, status: ExecutionStatus, message: str,
                error: BackendError | None = None,
                data: Mapping[str, object] | None = None) -> None:
        """Log the motion's physics start and settle for :meth:`physics_report`."""
        start = self._starts.get(id(execution))
        if start is not None and not execution.finished:
            self._motion_log.append(motion_entry(execution, start, float(self._data.time),
                                                 status))
        super()._finish(execution, status, message, error, data)

    def _cancel(self, execution: TrajectoryExecution, message: str) -> None:
        # A chunk being stepped moves the arm on for up to its 20 ms of physics: the motion
        # stops where the chunk leaves it, so that the handle's end, the joints reported
        # then and where the arm is held agree (cancelled mid-chunk, the arm went on past
        # the state the run recorded as where it stopped).
        if threading.current_thread() is not self._thread:
            while self._stepping and not execution.finished and not self._closed:
                self._wake.wait()
        super()._cancel(execution, message)
        self._targets[execution.columns] = self._positions[execution.columns]


def _path(text: str) -> Any:
    from pathlib import Path

    return Path(text)


def _urdf_efforts(urdf_xml: str) -> dict[str, float]:
    import xml.etree.ElementTree as ET

    efforts = {}
    for joint in ET.fromstring(urdf_xml).findall("joint"):
        limit = joint.find("limit")
        if limit is not None and float(limit.get("effort", 0) or 0) > 0:
            efforts[joint.get("name", "")] = float(limit.get("effort", 0))
    return efforts


def _sample(trajectory: Any, t: float) -> tuple[np.ndarray, np.ndarray]:
    """Position and velocity of ``trajectory`` at ``t`` (its own clock): linear position
    between samples, the samples' velocities interpolated."""
    times, positions, velocities = trajectory.times, trajectory.positions, trajectory.velocities
    if t <= times[0]:
        return positions[0], velocities[0]
    if t >= times[-1]:
        return positions[-1], velocities[-1]
    k = int(np.searchsorted(times, t, side="right")) - 1
    s = (t - times[k]) / (times[k + 1] - times[k])
    return (positions[k] + s * (positions[k + 1] - positions[k]),
            velocities[k] + s * (velocities[k + 1] - velocities[k]))


def _relative(data: Any, link_body: int, obj_body: int) -> tuple[np.ndarray, np.ndarray]:
    """Pose of ``obj_body`` in the frame of ``link_body``: position, quaternion (w x y z)."""
    rot = data.xmat[link_body].reshape(3, 3)
    pos = rot.T @ (data.xpos[obj_body] - data.xpos[link_body])
    inverse = np.zeros(4)
    mujoco.mju_negQuat(inverse, data.xquat[link_body])
    quat = np.zeros(4)
    mujoco.mju_mulQuat(quat, inverse, data.xquat[obj_body])
    return pos, quat


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    """Angle (rad) between two rotations given as unit quaternions."""
    dot = abs(float(np.dot(a, b)))
    return 2.0 * math.acos(min(1.0, dot))
