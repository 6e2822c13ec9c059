"""A workcell handle: load robots and cells, plan, time, execute, run tasks.

What ``moveit_py`` / MoveIt Commander give a ROS user, for a taskrunner cell::

    import taskrunner

    cell = taskrunner.load_workcell("servo_arm_table")   # a shipped name, a path, a package
    cell.connect("mock")                                  # or "sim", "serial", "http"
    plan = cell.plan("arm", to="Candle")                  # named pose, joints, pose, position
    cell.execute(plan)
    line = cell.plan_cartesian("arm", by=(0.0, 0.0, -0.03), frame="world")
    print(line.fraction)                                  # computeCartesianPath's fraction
    result = cell.run_task("pick_place", parameters={"place_y": -0.1})

A :class:`Workcell` keeps a planning scene (the cell's robots and fixed objects) whose
robot state is the *current state*: the cell's start state at first, then where the
connected backend says the joints are after every execution. Plans start there unless
given ``start=``. Frames: poses are in the world frame of the cell unless their
``frame`` names a link or a scene object; lengths in metres, angles in radians, times in
seconds.
"""

from __future__ import annotations

import logging
import os
import warnings
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Literal

import numpy as np

from taskrunner.backends.base import Backend, ExecutionHandle
from taskrunner.builder import Task
from taskrunner.errors import ArgumentError, InputError, UnknownNameError
from taskrunner.kinds import BackendKind
from taskrunner.plan import Plan
from taskrunner.planning.cartesian import CartesianOptions, CartesianPlanner, relative_pose
from taskrunner.planning.cartesian_limits import time_cartesian_path
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import (
    Goal,
    JointGoal,
    NamedGoal,
    PlannerOptions,
    PlanRequest,
    PoseGoal,
)
from taskrunner.planning.timing import TimingOptions, parameterize_path
from taskrunner.poselike import PoseLike, Position, as_pose, waypoint, waypoint_list, xyz
from taskrunner.resources import resolve_cell, resolve_task
from taskrunner.robot.cell import Cell, load_cell_or_robot
from taskrunner.robot.model import RobotModel
from taskrunner.robot.options import LoadOptions
from taskrunner.robot.packages import PackageMap
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.session import make_backend
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.taskrun import RunResult, TaskRun, start_run
from taskrunner.tasks.loader import load_task
from taskrunner.tasks.spec import TaskSpec
from taskrunner.taught import (
    TaughtPose,
    apply_taught,
    cell_key,
    cells_dir_from_env,
    check_pose_name,
    data_dir_from_env,
    read_taught_poses,
    save_taught_pose,
)
from taskrunner.types import JointPath, JointState, JointTrajectory, Pose

__all__ = ["Plan", "Workcell", "load_workcell", "run_task", "start_task"]

StateLike = JointState | Mapping[str, float]
TaskLike = str | os.PathLike[str] | Task
"""A task file, a shipped example's name, or a :class:`~taskrunner.Task`."""


def load_workcell(source: str | os.PathLike[str], *, packages: PackageMap | None = None,
                  collision: str | Mapping[str, str] | None = None, allow_missing_meshes: bool | None = None,
                  options: LoadOptions | None = None) -> Workcell:
    """Load a cell or a robot as a :class:`Workcell`.

    Args:
        source: a cell's name (``"servo_arm_table"``, ``"servo_arm_pair"``: a file of
            the cells folder ``TASKRUNNER_CELLS_DIR``, else a shipped cell, as a task
            file's ``cell:`` names it), a shipped robot's (``"panda"``), a cell file, a robot manifest
            (``robot.yaml``) or its folder, a MoveIt config package (a folder with
            ``.setup_assistant``), or a ``.urdf`` / ``.xacro`` file. A robot becomes a
            one-robot cell with no objects, at the world origin.
        packages: where ``package://`` and ``$(find pkg)`` resolve (default: the options' package
            path, then folders with a ``package.xml`` near the files).
        collision: the link geometry collisions are checked with, for every robot or by
            robot name: ``"exact"`` meshes, ``"convex"`` hulls, or ``"auto"`` (hulls
            where they are tight); None: each robot's ``collision:`` in the cell or its
            robot.yaml, else auto. ``Workcell.scene.link_geometry`` tells which link got what.
        allow_missing_meshes: load robots whose mesh files cannot be found (or with no
            collision geometry at all) without that geometry, with one warning per robot;
            None: ``options.allow_missing_meshes``. Otherwise either is a
            :class:`~taskrunner.errors.MissingMeshError` listing every missing file.
        options: how robots are loaded (``LoadOptions()``; not the environment), kept for later files.

    Raises:
        InputError: ``source`` is neither a file or folder nor a shipped name, or
            ``collision`` is not one of exact, convex, auto.
        RobotDescriptionError, YamlError: the cell or a robot's files are invalid (file:line).
    """
    cell = load_cell_or_robot(resolve_cell(source), packages, options=options,
                              allow_missing_meshes=allow_missing_meshes)
    if collision is not None:
        from taskrunner.scene.linkgeometry import set_collision_choice

        set_collision_choice(cell.model, collision)
    return Workcell(cell, options)


class Workcell:
    """A cell's robots and objects, ready to plan, execute and run tasks.

    Args:
        cell, options: a loaded cell and its load options (:func:`load_workcell` makes both).
    """

    def __init__(self, cell: Cell, options: LoadOptions | None = None) -> None:
        self._cell = cell
        self._options = options or LoadOptions()
        self._scene = scene_from_cell(cell)
        self._planner: MotionPlanner | None = None
        self._cartesian: CartesianPlanner | None = None
        self._backend: Backend | None = None
        self._backend_kind = BackendKind.MOCK
        self._taught: set[tuple[str, str]] = set()  # (group, name) taught or loaded here

    def __repr__(self) -> str:
        return f"Workcell({self.name!r}, groups={list(self.groups)})"

    # ------------------------------------------------------------------ description
    @property
    def name(self) -> str:
        """The cell's name (a robot's name for a robot loaded alone)."""
        return self._cell.name

    @property
    def path(self) -> Path | None:
        """The file or folder the cell was loaded from."""
        return self._cell.path

    @property
    def cell(self) -> Cell:
        """The loaded cell (robots, fixed objects, start poses)."""
        return self._cell

    @property
    def model(self) -> RobotModel:
        """The kinematic model of every robot of the cell (joints, links, groups, limits)."""
        return self._cell.model

    @property
    def scene(self) -> Scene:
        """The planning scene: robots at the current state, fixed and added objects."""
        return self._scene

    @property
    def groups(self) -> tuple[str, ...]:
        """The planning groups (SRDF groups, prefixed per robot, and the cell's own)."""
        return tuple(self.model.groups)

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Every joint of the cell, in state-vector order."""
        return tuple(self.model.joint_names)

    def named_poses(self, group: str) -> list[str]:
        """The named poses of ``group`` (SRDF ``group_state`` and the cell's poses), sorted.

        Raises:
            UnknownNameError: no such group.
        """
        return self.model.named_state_names(group)

    def link_pose(self, link: str, state: StateLike | None = None) -> Pose:
        """World pose of a link (or any model frame): at the current state, or at
        ``state`` (joints left out keep their current values).

        Raises:
            UnknownNameError: no such link or joint.
        """
        if state is None:
            return self._scene.link_pose(link)
        scene = self._scene.copy()
        scene.set_state(self._state_vector(state))
        return scene.link_pose(link)

    # ------------------------------------------------------------------ state
    @property
    def backend(self) -> Backend | None:
        """The connected backend (None before :meth:`connect`)."""
        return self._backend

    @property
    def backend_kind(self) -> BackendKind | None:
        """The kind of the connected backend (None before :meth:`connect`)."""
        return self._backend_kind if self._backend is not None else None

    def connect(self, kind: BackendKind | str = "mock", *, speed: float | None = None,
                port: str | None = None, url: str | None = None,
                firmware_speedup: float = 1.0, home: bool = False,
                calibration: str | None = None, hardware: str | None = None) -> Backend:
        """Create the backend that executes this cell's motions, and use it from now on.

        The backend is built from the cell the way ``run-task --backend`` builds it: mock
        and sim drive every joint and start at the cell's start state; serial and http
        drive the servos of the cell's one robot through its ``hardware.yaml`` and start
        where the servos are; feetech drives bus servos (the SO-101) on the buses of the
        cell's ``<cell>.hardware.yaml``. The current state then becomes the backend's. A
        backend connected before is closed.

        Args:
            kind: ``"mock"`` (motions complete at once, or replay at ``speed``),
                ``"sim"`` (a controller playing trajectories in real time, ``speed``
                times faster), ``"serial"`` or ``"http"`` (the ESP32 firmware),
                ``"feetech"`` (bus servos).
            speed: replay speed, a multiple of real time (mock: None jumps to the end).
            port: serial device (default: the one in ``hardware.yaml``).
            url: the ESP32's ``/api/command`` URL (http).
            firmware_speedup: a host build of the firmware running this much faster
                than real time (``run-task firmware-sim --speedup``).
            home: send the servos home before the first motion (serial, http).
            calibration: feetech: LeRobot's calibration file (a pair: ``ROBOT=FILE,…``;
                default the hardware file's).
            hardware: feetech: another hardware file than ``<cell>.hardware.yaml``.

        Raises:
            ArgumentError: an unknown ``kind`` (a :class:`~taskrunner.BackendKind` value).
            InputError: a servo backend on a cell without exactly one calibrated robot,
                or http without a URL.
            BackendError: the port or URL does not answer as the firmware does.
        """
        backend_kind = BackendKind.parse(kind)
        backend = make_backend(backend_kind.value, self._cell, speed, port, url,
                               firmware_speedup, home, calibration_file=calibration,
                               hardware=hardware)
        self.close()
        self._backend, self._backend_kind = backend, backend_kind
        self.sync()
        return backend

    def close(self) -> None:
        """Close the connected backend, if any (the current state stays where it was).
        :meth:`connect` connects one again; ``with load_workcell(...) as cell:`` closes
        it at the block's end."""
        if self._backend is not None:
            backend, self._backend = self._backend, None
            backend.close()

    def disconnect(self) -> None:
        """Deprecated: :meth:`close` (the same, under one name); warns and closes."""
        warnings.warn("Workcell.disconnect() is deprecated: call Workcell.close()",
                      DeprecationWarning, stacklevel=2)
        self.close()

    def __enter__(self) -> Workcell:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def sync(self) -> JointState:
        """Make the current state what the connected backend reports; returns it."""
        if self._backend is not None:
            state = self._backend.joint_state()
            self._scene.set_state(dict(zip(state.names, state.positions)))
        return self.joint_state()

    def joint_state(self) -> JointState:
        """Every joint's current position (rad or m): the backend's last report after
        an execution, else the planning state (the cell's start state at first)."""
        return JointState(self.joint_names, self._scene.state)

    def set_joint_state(self, values: StateLike) -> None:
        """Set joints of the planning state without moving anything (e.g. to plan from
        elsewhere before connecting); joints left out keep their values.

        Raises:
            UnknownNameError: a joint the cell does not have.
        """
        self._scene.set_state(self._state_vector(values))

    # ------------------------------------------------------------------ planning
    def plan(self, group: str, *, to: str | None = None,
             joints: Mapping[str, float] | None = None, pose: PoseLike | None = None,
             position: Position | None = None, link: str | None = None,
             start: StateLike | None = None, planner: str | None = None,
             planning_time: float = 5.0, seed: int = 0,
             velocity_scaling: float | None = None,
             acceleration_scaling: float | None = None) -> Plan:
        """Plan a collision-free motion of ``group`` to one target, and time it.

        Give exactly one target: ``to`` (a named pose, MoveIt's ``set_named_target``),
        ``joints`` (``set_joint_value_target``; joints of the group left out keep their
        start values), ``pose`` (``set_pose_target``: a pose of ``link`` in the world or
        in its ``frame``; a :class:`~taskrunner.Pose`, e.g. ``Pose.from_rpy(xyz, rpy)``,
        or a task file's mapping ``{"xyz": [...], "rpy": [...]}``) or ``position``
        (``set_position_target``: x, y, z of ``link`` in the world frame, orientation
        free; what a 5-DOF arm can reach). A ``pose`` for a group with
        ``position_only_ik``, or a mapping without ``rpy`` or ``quat`` (as in a task
        file), is reached in position only.

        Args:
            group: the planning group that moves.
            link: the link placed at ``pose`` / ``position`` (default: the group's tip).
            start: where the motion starts (default: the current state); joints left
                out keep their current values. ``start=previous_plan.end`` chains plans.
            planner: an OMPL planner (see :data:`taskrunner.planning.PLANNERS`); None:
                the group's default of its ``ompl_planning.yaml``, else RRTConnect.
            planning_time: seconds allowed per attempt, a cap and not a target (the
                search stops at the first path; MoveIt's default is also 5 s).
            seed: seeds OMPL and the IK goal sampling (same seed, same motion).
            velocity_scaling: fraction of the joints' velocity limits, in (0, 1]
                (default: the robot's ``default_velocity_scaling_factor``).
            acceleration_scaling: fraction of the acceleration limits, in (0, 1].

        Raises:
            ValueError: not exactly one target, or an invalid option.
            TaskSpecError: an invalid pose mapping (the message names the field).
            UnknownNameError: an unknown group, joint, link or named pose (with a
                "did you mean" when a known name is close).
            PlanningError: no motion (IkFailedError, StartInCollisionError,
                GoalInCollisionError, PlanningTimeoutError, …: the message says why).
        """
        goal = self._goal(to, joints, pose, position, link)
        timing = TimingOptions(velocity_scaling=velocity_scaling,
                               acceleration_scaling=acceleration_scaling)
        request = PlanRequest(group, goal, self._state_vector(start) if start is not None
                              else None, PlannerOptions(planner=planner or "",
                                                        planning_time=planning_time, seed=seed))
        if self._planner is None:
            self._planner = MotionPlanner(self._scene)
        result = self._planner.plan(request)
        trajectory = parameterize_path(self.model, result.path, timing)
        return Plan(group, result.path, trajectory, self._full(result.start),
                    self._full(result.end), planning_time=result.total_time)

    def load_planning_scene(self, path: str | os.PathLike[str], *, robot: str | None = None,
                            merge: bool | None = None, strict: bool | None = None) -> list[str]:
        """Apply a MoveIt ``PlanningScene`` YAML file (ROS 1 or ROS 2, MotionBenchMaker's
        format) to this cell's scene: objects, attached objects, robot state, allowed
        collisions (see :mod:`taskrunner.moveit.scene_file`).

        Args:
            robot: the cell's robot the file is for: its prefix goes before the file's
                joint and link names (needed when several robots have the name).
            merge: keep the cell's objects; None keeps them for a diff scene and
                replaces them for a full one (``is_diff: false``), as MoveIt does.
            strict: unused or unsupported fields are errors (None: ``options.strict``).

        Returns:
            the scene objects the file added or changed (an object of several shapes
            becomes ``id``, ``id/1`` …).

        Raises:
            InputError: an invalid file, an unknown joint, link or frame (file:line, field).
        """
        from taskrunner.moveit import load_planning_scene

        loaded = load_planning_scene(path, self.model, robot=robot, package_path=self._options.package_path,
                                     strict=self._options.strict if strict is None else strict)
        return loaded.apply(self._scene, merge=merge)

    def plan_request(self, path: str | os.PathLike[str], *,
                     scene: str | os.PathLike[str] | None = None, robot: str | None = None,
                     group: str | None = None, seed: int = 0, strict: bool | None = None,
                     start_state_max_bounds_error: float | None = None) -> Plan:
        """Plan a MoveIt ``MotionPlanRequest`` YAML file (group, start state, joint or pose
        goal constraints, planner, time, attempts, scaling factors) and time it.

        Args:
            scene: a ``PlanningScene`` file applied first (as :meth:`load_planning_scene`).
            robot: the cell's robot the files are for (see :meth:`load_planning_scene`).
            group: plan for this group instead of the file's ``group_name``.
            seed: seeds OMPL and the IK goal sampling.
            strict: what would be a warning is an error (a joint state naming joints
                the model does not have, an unused field); None: ``options.strict``.
            start_state_max_bounds_error: a start joint outside its bounds by at most
                this (rad or m) is moved onto the bound with a warning, as MoveIt's
                ``FixStartStateBounds`` adapter does; the request file's own
                ``start_state_max_bounds_error`` wins; None: 0.05, MoveIt's default.

        Raises:
            InputError: an invalid or unsupported request (file:line, field).
            PlanningError: no motion, or one whose end misses the goal constraints.
        """
        from taskrunner.errors import PlanningError
        from taskrunner.moveit import load_motion_plan_request, plan_request_file

        if scene is not None:
            self.load_planning_scene(scene, robot=robot, strict=strict)
        request = load_motion_plan_request(path, self.model, robot=robot, group=group,
                                           strict=self._options.strict if strict is None else strict)
        report = plan_request_file(self._scene, request, seed=seed,
                                   start_state_max_bounds_error=start_state_max_bounds_error)
        for warning in request.warnings:  # the file's, and start joints moved onto bounds
            logging.getLogger("taskrunner.moveit").warning("%s", warning)
        result = report.result
        if result is None or not report.success or result.trajectory is None:
            from taskrunner.errors import InvalidStateError

            error = InvalidStateError if report.error_kind == "InvalidStateError" else PlanningError
            raise error(report.message or "no motion")
        return Plan(request.group, result.path, result.trajectory, self._full(result.start),
                    self._full(result.end), planning_time=result.total_time)

    def plan_cartesian(self, group: str, waypoints: PoseLike | Position
                       | Sequence[PoseLike | Position] | None = None, *, by: Position | None = None,
                       frame: Literal["world", "link"] = "world", link: str | None = None,
                       start: StateLike | None = None, eef_step: float = 0.005,
                       jump_threshold: float = 0.0, avoid_collisions: bool = True,
                       velocity_scaling: float | None = None,
                       acceleration_scaling: float | None = None) -> Plan:
        """Move ``link`` in straight lines, MoveIt's ``computeCartesianPath``.

        The link moves from where it is at the start through each waypoint in turn,
        in steps of at most ``eef_step``; each step is solved by IK from the one
        before. A path that cannot be completed (no IK solution, a collision, a joint
        jump) is cut short, never raised: :attr:`Plan.fraction` says how much of the
        path's length was achieved and :attr:`Plan.message` why it stopped. The part
        achieved is timed and can be executed.

        Args:
            group: the planning group that moves.
            waypoints: a pose or several (world frame, or their ``frame``; a
                :class:`~taskrunner.Pose` or a task file's mapping), or x, y, z
                positions (world, m): a position, or a mapping without ``rpy`` or
                ``quat``, keeps the link's start orientation, or leaves it free on a
                position-only arm.
            by: instead of waypoints, one straight move by this offset (m), along the
                world's axes (``frame="world"``) or the link's (``frame="link"``).
            link: the link that follows the lines (default: the group's tip).
            start: where the path starts (default: the current state).
            eef_step: largest move of the link between IK points (m).
            jump_threshold: MoveIt's relative jump test (0 disables it).
            avoid_collisions: stop before the first state in collision.
            velocity_scaling: fraction of the velocity limits, in (0, 1].
            acceleration_scaling: fraction of the acceleration limits, in (0, 1].

        Raises:
            ValueError: neither or both of ``waypoints`` and ``by``; an invalid option.
            UnknownNameError: an unknown group, link or frame.
            StartInCollisionError: the start collides (with ``avoid_collisions``).
        """
        if (waypoints is None) == (by is None):
            raise ArgumentError("'plan_cartesian' needs one of 'waypoints' or 'by'")
        options = CartesianOptions(eef_step=eef_step, jump_threshold=jump_threshold,
                                   avoid_collisions=avoid_collisions)
        timing = TimingOptions(velocity_scaling=velocity_scaling,
                               acceleration_scaling=acceleration_scaling)
        if self._cartesian is None:
            self._cartesian = CartesianPlanner(self._scene)
        q = self._state_vector(start if start is not None else {})
        frame_link = link or self.model.group(group).tip_link
        if frame_link is None:
            raise ArgumentError(f"group {group!r} has no tip link: give 'link'")
        if by is not None:
            target = relative_pose(self._scene, frame_link, xyz("by", by), frame=frame, start=q)
            targets: list[Pose] = [target]
        else:
            here = self.link_pose(frame_link, JointState(self.joint_names, q))
            assert waypoints is not None
            targets = [waypoint(w, here, i) for i, w in enumerate(waypoint_list(waypoints))]
        result = self._cartesian.compute(group, targets, link, options, q)
        # Timed by the joint limits, and by pilz_cartesian_limits.yaml's when the robot has it.
        trajectory = time_cartesian_path(self.model, result.path, frame_link, timing)
        return Plan(group, result.path, trajectory, self._full(result.start),
                    self._full(result.end), result.fraction, result.message, result.elapsed)

    def time_path(self, path: JointPath | Plan, *, velocity_scaling: float | None = None,
                  acceleration_scaling: float | None = None,
                  sample_rate_hz: float = 100.0) -> JointTrajectory:
        """Time a path rest to rest with toppra, within the scaled joint limits.

        Args:
            path: a :class:`JointPath`, or a plan (its path is timed again: e.g. slower).
            velocity_scaling: fraction of the velocity limits, in (0, 1] (default: the
                robot's ``default_velocity_scaling_factor``).
            acceleration_scaling: fraction of the acceleration limits, in (0, 1].
            sample_rate_hz: samples per second of the trajectory (Hz).

        Raises:
            ValueError: an invalid option or path.
            PlanningError: the path cannot be timed (the message names joint and time).
        """
        joint_path = path.path if isinstance(path, Plan) else path
        return parameterize_path(self.model, joint_path, TimingOptions(
            velocity_scaling=velocity_scaling, acceleration_scaling=acceleration_scaling,
            sample_rate_hz=sample_rate_hz))

    # ------------------------------------------------------------------ execution
    def execute(self, motion: Plan | JointTrajectory, *, wait: bool = True,
                timeout: float | None = None) -> ExecutionHandle:
        """Execute a plan or a trajectory on the connected backend (a mock backend is
        connected first if there is none).

        Args:
            motion: what to execute; it must start where the joints are.
            wait: block until the motion ends, then update the current state.
            timeout: seconds to wait at most (None: as long as the motion takes).

        Returns:
            The execution's handle (done when ``wait``; else poll it, ``wait()`` on it
            or ``cancel()`` it, then call :meth:`sync`).

        Raises:
            TrajectoryRejectedError: refused before anything moved (an unknown joint, a
                start away from the current state, a servo angle out of range).
            BackendBusyError: joints already moving under another trajectory.
            BackendError: the motion failed (``wait`` only); ExecutionCancelledError
                when it was stopped.
        """
        trajectory = motion.trajectory if isinstance(motion, Plan) else motion
        backend = self._backend if self._backend is not None else self.connect("mock")
        handle = backend.execute(trajectory)
        if wait:
            try:
                handle.wait(timeout)
            finally:
                self.sync()
        return handle

    def stop(self) -> None:
        """Stop every motion of the connected backend where it is."""
        if self._backend is not None:
            self._backend.stop()
            self.sync()

    def go(self, group: str, *, to: str | None = None,
           joints: Mapping[str, float] | None = None, pose: PoseLike | None = None,
           position: Position | None = None, link: str | None = None,
           planner: str | None = None, planning_time: float = 5.0, seed: int = 0,
           velocity_scaling: float | None = None, acceleration_scaling: float | None = None,
           timeout: float | None = None) -> Plan:
        """Plan a motion of ``group`` from the current state to one target and execute it
        (MoveIt's ``move_group.go()``): :meth:`plan`, then :meth:`execute` waiting for
        the end. Takes :meth:`plan`'s arguments (no ``start``: a motion starts where the
        joints are) and :meth:`execute`'s ``timeout`` (s).

        Returns:
            The plan executed; the current state is then where the backend ended.

        Raises:
            The errors of :meth:`plan` (nothing has moved) and of :meth:`execute`.
        """
        plan = self.plan(group, to=to, joints=joints, pose=pose, position=position,
                         link=link, planner=planner, planning_time=planning_time, seed=seed,
                         velocity_scaling=velocity_scaling,
                         acceleration_scaling=acceleration_scaling)
        self.execute(plan, timeout=timeout)
        return plan

    # ------------------------------------------------------------------ taught poses
    def teach(self, group: str, name: str, joints: Mapping[str, float] | None = None, *,
              data_dir: str | os.PathLike[str] | None = None) -> TaughtPose:
        """Teach a named pose of ``group``, as ``PUT /cells/{id}/poses/{name}`` does: store
        it in the data folder's database, where ``run-task`` and ``run-task serve`` find
        it, and make it a named pose of this workcell at once (``plan(to=name)``).

        Args:
            group: the planning group.
            name: the pose's name (a letter or ``_``, then letters, digits, ``_``, ``-``).
            joints: the group's joint values (rad or m); joints left out take their
                current values; None: the group's joints where the backend reports them
                now (the planning state before :meth:`connect`).
            data_dir: the API's data folder (default: ``TASKRUNNER_DATA_DIR``, else
                ``./state``, as the command line's ``--data-dir``).

        Raises:
            ArgumentError: a bad name, a name the robot or cell files already give the
                group, a value outside the joint limits, a cell not loaded from a file.
            UnknownNameError: no such group, or a joint that is not the group's.
        """

        check_pose_name(name)
        model, spec = self.model, self.model.group(group)
        if name in model.named_states.get(spec.name, {}) and (spec.name, name) not in self._taught:
            raise ArgumentError(f"named pose {name!r} of group {spec.name!r} comes from the "
                                "robot or cell files; pick another name")
        for joint in joints or {}:
            if joint not in spec.joint_names:
                raise UnknownNameError("joint", joint, spec.joint_names)
        state = dict(zip(self.joint_names, self._state_vector(joints if joints is not None
                                                              else self.sync())))
        values = {j: float(state[j]) for j in spec.joint_names}
        bad = model.limit_violations(model.state_with(model.default_state(), values))
        if bad:
            raise ArgumentError(f"pose {name!r} is outside the joint limits: " + "; ".join(bad))
        pose = TaughtPose(spec.name, name, values)
        save_taught_pose(data_dir_from_env(data_dir) / "runs.sqlite",
                         self._cell_key(), pose)
        model.named_states.setdefault(spec.name, {})[name] = dict(values)
        self._taught.add((spec.name, name))
        return pose

    def load_taught_poses(self, *, data_dir: str | os.PathLike[str] | None = None
                          ) -> list[TaughtPose]:
        """Read the poses taught on this cell (by :meth:`teach` or the REST API) from the
        data folder's database and make them named poses of this workcell, as
        ``run-task --data-dir`` does for a run. A pose the robot or cell files give
        already, or one that no longer fits the cell, is skipped with a warning (in
        ``model.warnings``).

        Args:
            data_dir: the API's data folder (default: ``TASKRUNNER_DATA_DIR``, else
                ``./state``).

        Returns:
            the poses added (a pose taught again replaces the one loaded before).
        """
        named = self.model.named_states
        for group, name in self._taught:  # forget what was loaded, so a newer value wins
            named.get(group, {}).pop(name, None)
        self._taught.clear()
        poses = read_taught_poses(data_dir_from_env(data_dir) / "runs.sqlite", cells_dir_from_env())
        added = apply_taught(self._cell, poses)
        self._taught.update((pose.group, pose.name) for pose in added)
        return added

    # ------------------------------------------------------------------ tasks
    def start_task(self, task: TaskLike, *, parameters: Mapping[str, object] | None = None,
                   backend: BackendKind | str | None = None, speed: float | None = None,
                   seed: int = 0, runs_dir: str | os.PathLike[str] | None = None,
                   on_event: Callable[[RunEvent], None] | None = None) -> TaskRun:
        """Start a task on this cell in a background thread; returns at once.

        The task is loaded and checked first (structure, then every name it uses
        against the cell), so an invalid task raises here, before anything moves.

        Args:
            task: a task file, a shipped example's name (``"pick_place"``), or a
                :class:`~taskrunner.Task` built in Python.
            parameters: values of the task's parameters (a file task's; strings are
                parsed as on the command line).
            backend: connect this backend first (see :meth:`connect`); default the
                connected one, or mock.
            speed: with ``backend``: its replay speed.
            seed: seeds every planner call of the run.
            runs_dir: write the run record there as ``<run_id>.json`` (None: not written).
            on_event: called with every event of the run, in the run's thread.

        Raises:
            TaskSpecError: the task is invalid (every problem listed, each at its task
                file's line, or the line of the Python step).
            InputError: a task file written for another cell.
        """
        return self._start(self._spec(task, parameters), task, backend, speed, seed, runs_dir,
                           on_event)

    def _start(self, spec: TaskSpec, task: TaskLike, backend: BackendKind | str | None,
               speed: float | None, seed: int, runs_dir: str | os.PathLike[str] | None,
               on_event: Callable[[RunEvent], None] | None) -> TaskRun:
        """Every way of running a task ends here (one implementation)."""
        if backend is not None:
            self.connect(backend, speed=speed)
        machine = self._backend if self._backend is not None else self.connect("mock")
        text = task.to_text(self._cell) if isinstance(task, Task) else None
        return start_run(spec, self._cell, machine, seed=seed, backend_name=self._backend_kind,
                         runs_dir=Path(runs_dir) if runs_dir is not None else None,
                         on_event=on_event, on_end=self.sync, task_text=text,
                         load_options=self._options.as_data())

    def run_task(self, task: TaskLike, *, parameters: Mapping[str, object] | None = None,
                 backend: BackendKind | str | None = None, speed: float | None = None,
                 seed: int = 0, runs_dir: str | os.PathLike[str] | None = None,
                 on_event: Callable[[RunEvent], None] | None = None) -> RunResult:
        """Run a task on this cell to its end; returns its result (see
        :meth:`start_task` for the arguments). A failed run is a result with
        ``status == "failed"``, not an exception; an invalid task raises."""
        return self.start_task(task, parameters=parameters, backend=backend, speed=speed,
                               seed=seed, runs_dir=runs_dir, on_event=on_event).wait()

    # ------------------------------------------------------------------ internals
    def _spec(self, task: TaskLike, parameters: Mapping[str, object] | None,
              loaded: TaskSpec | None = None) -> TaskSpec:
        """``task`` loaded (unless ``loaded`` already is) and checked against this cell."""
        if isinstance(task, Task):
            if parameters:
                raise ArgumentError("'parameters' are for task files; a Task built in Python "
                                 "takes its values directly")
            return task.spec(self._cell)
        if not isinstance(task, (str, os.PathLike)):
            raise ArgumentError(f"'task' must be a task file, an example's name or a Task "
                             f"(got {task!r})")
        spec = loaded if loaded is not None else load_task(resolve_task(task), parameters)
        if self.path is None or spec.cell.resolve() != self.path.resolve():
            raise InputError(f"task {spec.name!r} is written for cell {str(spec.cell)!r}, "
                             f"not for this workcell ({self.name!r}, {self.path}); "
                             "use taskrunner.run_task() to run it in its own cell",
                             spec.path, spec.loc.line if spec.loc else None)
        from taskrunner.tasks.names import check_names
        from taskrunner.tasks.problem import raise_for_problems

        raise_for_problems(check_names(spec, self._cell))
        return spec

    def _goal(self, to: str | None, joints: Mapping[str, float] | None,
              pose: PoseLike | None, position: Position | None, link: str | None) -> Goal:
        given = [name for name, value in (("to", to), ("joints", joints), ("pose", pose),
                                          ("position", position)) if value is not None]
        if len(given) != 1:
            got = f" (got {' and '.join(repr(g) for g in given)})" if given else ""
            raise ArgumentError(f"'plan' needs exactly one of 'to', 'joints', 'pose' or "
                             f"'position'{got}")
        if to is not None:
            return NamedGoal(to)
        if joints is not None:
            return JointGoal(joints)
        if pose is not None:
            target, oriented = as_pose(pose, "pose")
            # None: the group's position_only_ik decides, as for a task file's pose
            return PoseGoal(target, link, position_only=None if oriented else True)
        assert position is not None
        return PoseGoal(Pose(xyz("position", position)), link, position_only=True)

    def _cell_key(self) -> str:
        if self.path is None:
            raise ArgumentError(f"workcell {self.name!r} was not loaded from a file: its "
                                "taught poses have nowhere to be kept")
        return cell_key(self.path, cells_dir_from_env())

    def _state_vector(self, values: StateLike) -> np.ndarray:
        return self.model.state_with(self._scene.state, values)

    def _full(self, q: np.ndarray) -> JointState:
        return JointState(self.joint_names, q)


def run_task(task: TaskLike, *, parameters: Mapping[str, object] | None = None,
             backend: BackendKind | str = BackendKind.MOCK, speed: float | None = None,
             seed: int = 0, runs_dir: str | os.PathLike[str] | None = None,
             on_event: Callable[[RunEvent], None] | None = None, options: LoadOptions | None = None,
             ) -> RunResult:
    """Run a task in its own cell, like ``run-task TASK``; returns its result.

    :func:`start_task` then :meth:`TaskRun.wait`; on a workcell you hold: :meth:`Workcell.run_task`.

    Args:
        task: a task file or a shipped example's name (the cell is the one the file
            names), or a :class:`~taskrunner.Task` built with a ``cell``.
        parameters: values of the task file's parameters.
        backend: a :class:`~taskrunner.BackendKind` (``"mock"``, ``"sim"``, ``"mujoco"``,
            ``"serial"``, ``"http"``, ``"feetech"``; servos on the port of their hardware
            file; for other settings use :meth:`Workcell.connect`).
        speed: replay speed of mock, sim or mujoco, a multiple of real time.
        seed: seeds every planner call.
        runs_dir: write the run record there (None: not written).
        on_event: called with every event of the run.
        options: how the cell's robots are loaded (default ``LoadOptions()``).

    Raises:
        TaskSpecError: the task is invalid (every problem with its file:line).
    """
    return start_task(task, parameters=parameters, backend=backend, speed=speed, seed=seed,
                      runs_dir=runs_dir, on_event=on_event, options=options).wait()


def start_task(task: TaskLike, *, parameters: Mapping[str, object] | None = None,
               backend: BackendKind | str = BackendKind.MOCK, speed: float | None = None,
               seed: int = 0, runs_dir: str | os.PathLike[str] | None = None,
               on_event: Callable[[RunEvent], None] | None = None, options: LoadOptions | None = None,
               ) -> TaskRun:
    """Start a task in its own cell in a background thread (see :func:`run_task`);
    iterate over :meth:`TaskRun.events`, ``cancel()`` or ``wait()`` for the result.
    The run's backend is closed when the run ends."""
    if isinstance(task, Task):
        if task.cell is None:
            raise ArgumentError(f"task {task.name!r} has no 'cell': build it with "
                                "Task(..., cell=...) or run it with Workcell.run_task")
        cell, loaded = load_workcell(task.cell, options=options), None
    elif isinstance(task, (str, os.PathLike)):
        loaded = load_task(resolve_task(task), parameters)  # read once: it names its cell
        cell = load_workcell(loaded.cell, options=options)
    else:
        raise ArgumentError(f"'task' must be a task file, an example's name or a Task "
                            f"(got {task!r})")
    try:
        run = cell._start(cell._spec(task, parameters, loaded), task, backend, speed, seed,
                          runs_dir, on_event)
    except BaseException:
        cell.close()
        raise
    run.add_done_callback(cell.close)
    return run
