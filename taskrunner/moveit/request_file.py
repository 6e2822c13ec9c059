"""``moveit_msgs/MotionPlanRequest`` files → :class:`~taskrunner.planning.PlanRequest`.

Read (fields at the top level, or under one key ``request`` / ``motion_plan_request``):

- ``group_name`` (names mapped as :mod:`taskrunner.moveit.names` says; a name the model
  lacks maps, with a warning, to the one group whose joints are the joint goal's);
- ``start_state`` (a RobotState: joint values, attached objects; joints left out keep
  the scene's values; names read as :func:`taskrunner.moveit.messages.read_robot_state`
  says). Planning moves a start joint outside its bounds by at most
  ``start_state_max_bounds_error`` onto the bound, with a warning, as MoveIt's
  ``FixStartStateBounds`` adapter does (:mod:`taskrunner.moveit.start_bounds`);
- ``start_state_max_bounds_error`` (not a field of the message: MoveIt reads it as a
  parameter of its planning pipeline; here, at the top level of the request file, for
  this request; else the caller's setting, else 0.05);
- ``goal_constraints[]``: each Constraints is one goal, any of them will do. Joint
  constraints → a joint goal (the exact ``position`` is aimed at; it lies within any
  tolerance; a position just outside the joint's bounds aims at the bound when the
  tolerance reaches it). A goal on a joint the model lacks or has fixed is an error.
  A position constraint (``link_name``, ``target_point_offset``,
  ``constraint_region`` primitives + poses, ``header.frame_id``), with or without an
  orientation constraint on the same link (``orientation``, ``absolute_x/y/z_axis_tolerance``)
  → a pose goal: the link's ``target_point_offset`` aims at the centre of the region's
  first primitive, within an IK tolerance no larger than the region and the orientation
  tolerances. After planning :meth:`MotionPlanRequestFile.goal_violations` checks the end
  state against the constraints as written.
- ``planner_id`` (``RRTConnect``, ``RRTConnectkConfigDefault``, ``geometric::RRTConnect``;
  empty: the group's default, else RRTConnect), ``allowed_planning_time`` (0: 5 s),
  ``num_planning_attempts`` (0: 1), ``max_velocity_scaling_factor`` and
  ``max_acceleration_scaling_factor`` (0: the robot's defaults; above 1 is an error),
  ``workspace_parameters`` (checked; a fixed-base arm does not use them).

Not supported, an error: ``path_constraints`` and ``trajectory_constraints`` with
constraints (a path planned without them would be reported as a success it is not),
visibility constraints, an orientation constraint without a position constraint, a
``target_point_offset`` on a position-only goal. Warnings: an unknown planner or pipeline
(the default planner is used, as MoveIt does), ``reference_trajectories``, Cartesian speed
limits.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
import pinocchio as pin

from taskrunner.errors import InputError, InvalidStateError
from taskrunner.moveit.fields import MessageReader, Msg
from taskrunner.moveit.geometry import read_primitive
from taskrunner.moveit.messages import (
    ROBOT_STATE_FIELDS,
    ObjectEdit,
    mapped_name,
    read_robot_state,
    try_name,
    unwrap,
)
from taskrunner.moveit.names import AmbiguousName, NameMap
from taskrunner.moveit.scene_file import PlanningSceneFile, apply_object
from taskrunner.moveit.start_bounds import (
    BOUNDS_TOLERANCE,
    START_STATE_MAX_BOUNDS_ERROR,
    check_allowance,
    describe_excess,
    fix_start_bounds,
)
from taskrunner.planning.request import (
    PLANNERS,
    Goal,
    JointGoal,
    PlannerOptions,
    PlanRequest,
    PoseGoal,
    group_planner,
)
from taskrunner.planning.timing import TimingOptions
from taskrunner.robot.model import RobotModel
from taskrunner.robot.notes import LoadWarning
from taskrunner.scene import Scene
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.types import Pose
from taskrunner.yamlfile import YamlLimits, load_yaml

__all__ = ["MotionPlanRequestFile", "load_motion_plan_request", "planner_name"]

REQUEST_FIELDS = ("workspace_parameters", "start_state", "goal_constraints", "path_constraints",
                  "trajectory_constraints", "reference_trajectories", "pipeline_id", "planner_id",
                  "group_name", "num_planning_attempts", "allowed_planning_time",
                  "max_velocity_scaling_factor", "max_acceleration_scaling_factor",
                  "cartesian_speed_end_effector_link", "cartesian_speed_limited_link",
                  "max_cartesian_speed", "start_state_max_bounds_error")
CONSTRAINTS_FIELDS = ("name", "joint_constraints", "position_constraints",
                      "orientation_constraints", "visibility_constraints")
_PIPELINES = ("", "ompl", "move_group")
_IK_TOLERANCE = 1e-4  # the tightest IK tolerance asked for by default
_MIN_TOLERANCE = 1e-6


def planner_name(planner_id: str) -> str:
    """An OMPL planner id as MoveIt writes it (``RRTConnectkConfigDefault``,
    ``geometric::RRTConnect``) → the planner's name (``RRTConnect``)."""
    name = planner_id.split("::")[-1]
    return re.sub(r"kConfig\w*$", "", name)


@dataclass(frozen=True)
class _JointCheck:
    joint: str
    position: float
    above: float
    below: float
    where: str = ""
    line: int | None = None


@dataclass(frozen=True)
class _PoseTarget:
    """A pose goal as written: the link, the point on it, the region, the orientation."""

    link: str
    offset: tuple[float, float, float]
    centre: Pose  # frame as written in the file
    radius: float  # the largest sphere around the centre inside the region (m)
    orientation: Pose | None  # frame as written; rotation only
    axis_tolerance: tuple[float, float, float]
    where: str
    line: int | None


@dataclass
class MotionPlanRequestFile:
    """A MotionPlanRequest file read against a model; see the module docstring.

    Attributes:
        group: the planning group (model name).
        start: joint values of ``start_state`` (model names).
        options: planner, time, attempts (seed 0: :meth:`plan_request` takes a seed).
        velocity_scaling, acceleration_scaling: for timing (None: the robot's defaults).
        start_state_max_bounds_error: the file's own allowance for a start state outside
            its bounds (rad or m; None: the caller's, else MoveIt's default 0.05); see
            :mod:`taskrunner.moveit.start_bounds`.
        warnings: what was not used, by file:line; planning adds the start-state joints
            moved onto their bounds.
    """

    path: Path | None
    group: str
    start: dict[str, float]
    start_attached: tuple[ObjectEdit, ...]
    options: PlannerOptions
    velocity_scaling: float | None
    acceleration_scaling: float | None
    joint_goals: tuple[tuple[_JointCheck, ...] | None, ...]
    pose_goals: tuple[_PoseTarget | None, ...]
    warnings: list[LoadWarning]
    names: NameMap = field(repr=False)
    start_state_max_bounds_error: float | None = None
    start_line: int | None = None

    def apply_start(self, scene: Scene) -> None:
        """Put the start state's attached objects into ``scene`` (use a copy of the
        planning scene: MoveIt applies them for this request only)."""
        carrier = PlanningSceneFile(self.path, "", "", True, {}, self.start_attached, (), (), {},
                                    [], self.names, MessageReader(self.path, False))
        for edit in self.start_attached:
            apply_object(scene, edit, carrier)

    def plan_request(self, scene: Scene, *, seed: int = 0, timing: bool = True,
                     start_state_max_bounds_error: float | None = None) -> PlanRequest:
        """The request for :class:`~taskrunner.planning.MotionPlanner` on ``scene``: the
        start state is the scene's with ``start_state`` set, moved onto its joint bounds
        where it is outside them by little (MoveIt's ``FixStartStateBounds``, see
        :mod:`taskrunner.moveit.start_bounds`; each joint moved is added to
        :attr:`warnings`); pose goals are placed in the world at the start state.

        Args:
            start_state_max_bounds_error: the allowance (rad or m) when the file gives
                none; None: MoveIt's default, 0.05.

        Raises:
            InputError: a goal's frame is none of the world, a link, a scene object.
            InvalidStateError: the start outside its bounds by more than the allowance, a
                joint goal whose tolerance does not reach inside the joint's bounds.
        """
        allowance = next((a for a in (self.start_state_max_bounds_error,
                                      start_state_max_bounds_error) if a is not None),
                         START_STATE_MAX_BOUNDS_ERROR)
        check_allowance(allowance)
        try:
            start, fixes = fix_start_bounds(scene.robot, scene.robot.state_with(scene.state,
                                                                                self.start),
                                            allowance)
        except InvalidStateError as exc:
            raise InvalidStateError(f"{self.path}: {exc}") from None
        for fix in fixes:
            warning = LoadWarning(f"'start_state' {fix} (start_state_max_bounds_error "
                                  f"{allowance:g}, as MoveIt's FixStartStateBounds)",
                                  self.path, self.start_line)
            self.warnings.append(warning)
        goals: list[Goal] = []
        for checks, target in zip(self.joint_goals, self.pose_goals):
            if checks is not None:
                goals.append(JointGoal({c.joint: self._goal_value(scene, c) for c in checks}))
            else:
                assert target is not None
                world = self._target_world(scene, target, start)
                position_only = target.orientation is None
                tolerance = max(_MIN_TOLERANCE, min(_IK_TOLERANCE, target.radius,
                                                    *target.axis_tolerance))
                goals.append(PoseGoal(Pose.from_se3(world), target.link, position_only=position_only,
                                      tolerance=tolerance))
        return PlanRequest(self.group, tuple(goals) if len(goals) > 1 else goals[0], start,
                           replace(self.options, seed=seed),
                           TimingOptions(self.velocity_scaling, self.acceleration_scaling)
                           if timing else None)

    def _goal_value(self, scene: Scene, check: _JointCheck) -> float:
        """The value a joint goal aims at: its ``position``, or when that is outside the
        joint's bounds, the bound, if the constraint's tolerance reaches it (every value
        within the tolerance meets the goal, as MoveIt's goal sampler takes it)."""
        joint = scene.robot.joint(check.joint)
        low = max(joint.lower, check.position - check.below - BOUNDS_TOLERANCE)
        high = min(joint.upper, check.position + check.above + BOUNDS_TOLERANCE)
        if joint.lower <= check.position <= joint.upper:
            return check.position
        if low <= high:
            return float(np.clip(check.position, joint.lower, joint.upper))
        bound = joint.lower if check.position < joint.lower else joint.upper
        where = f"{self.path}:{check.line}" if check.line is not None else str(self.path)
        unit = "m" if joint.type == "prismatic" else "rad"
        raise InvalidStateError(f"{where}: '{check.where}.position': "
                                f"{describe_excess(check.joint, check.position, bound, unit)}, beyond "
                                f"its tolerance (+{check.above:g}/-{check.below:g})")

    def goal_violations(self, scene: Scene, start: np.ndarray, q: np.ndarray) -> list[str]:
        """How state ``q`` misses every goal's constraints as written (empty: it meets
        one of them). Frames of pose goals are taken at ``start``."""
        missed: list[str] = []
        for index, (checks, target) in enumerate(zip(self.joint_goals, self.pose_goals)):
            problems = []
            if checks is not None:
                for c in checks:
                    value = q[scene.robot.joint(c.joint).index]
                    if not c.position - c.below - 1e-9 <= value <= c.position + c.above + 1e-9:
                        problems.append(f"joint {c.joint!r} at {value:.5f}, asked "
                                        f"{c.position:.5f} (+{c.above}/-{c.below})")
            else:
                assert target is not None
                problems = self._pose_problems(scene, target, start, q)
            if not problems:
                return []
            missed.append(f"goal {index}: " + "; ".join(problems))
        return missed

    def _frame(self, scene: Scene, pose: Pose, target: _PoseTarget) -> Pose:
        frame = pose.frame.lstrip("/")
        if frame in ("", "world"):
            return Pose(pose.xyz, pose.quat, "world")
        link = _try_link(self.names, frame, self.path, target)
        if link is not None:
            return Pose(pose.xyz, pose.quat, link)
        if frame in scene:
            return Pose(pose.xyz, pose.quat, frame)
        raise InputError(f"'{target.where}.header.frame_id' names an unknown frame {frame!r} "
                         f"(the world, a link of the robot or a scene object: "
                         f"{', '.join(repr(n) for n in scene.object_names) or 'none'})",
                         self.path, target.line)

    def _target_world(self, scene: Scene, target: _PoseTarget, start: np.ndarray) -> pin.SE3:
        centre = scene.to_world(self._frame(scene, target.centre, target), start)
        rotation = (scene.to_world(self._frame(scene, target.orientation, target), start).rotation
                    if target.orientation is not None else np.eye(3))
        # The link's origin such that its point ``offset`` lands on the region's centre.
        return pin.SE3(rotation, centre.translation - rotation @ np.array(target.offset))

    def _pose_problems(self, scene: Scene, target: _PoseTarget, start: np.ndarray,
                       q: np.ndarray) -> list[str]:
        link = scene.to_world(Pose(frame=target.link), q)
        point = link.act(np.array(target.offset))
        centre = scene.to_world(self._frame(scene, target.centre, target), start).translation
        problems = []
        distance = float(np.linalg.norm(point - centre))
        if distance > target.radius + 1e-9:
            problems.append(f"link {target.link!r} {distance:.5f} m from the region's centre "
                            f"(region radius {target.radius} m)")
        if target.orientation is not None:
            wanted = scene.to_world(self._frame(scene, target.orientation, target), start).rotation
            error = np.abs(pin.log3(wanted.T @ link.rotation))
            if np.any(error > np.array(target.axis_tolerance) + 1e-9):
                problems.append(f"link {target.link!r} turned {np.round(error, 5).tolist()} rad "
                                f"from the orientation (tolerances {list(target.axis_tolerance)})")
        return problems


def _try_link(names: NameMap, frame: str, path: Path | None, target: _PoseTarget) -> str | None:
    try:
        return names.link(frame)
    except AmbiguousName as exc:
        raise InputError(f"'{target.where}.header.frame_id': {exc}", path, target.line) from None


def _region(position: Msg) -> tuple[Pose, float]:
    region = position.msg("constraint_region", ("primitives", "primitive_poses", "meshes",
                                                "mesh_poses"), required=True)
    assert region is not None
    frame = position.frame_id()
    primitives = region.msgs("primitives", ("type", "dimensions", "polygon"))
    poses = region.msgs("primitive_poses", ("position", "orientation"))
    if not primitives:
        if region.seq("meshes"):
            raise region.error("meshes", "mesh regions are not supported: use primitives")
        raise region.error("primitives", "must give at least one primitive (the goal region)")
    if len(poses) != len(primitives):
        raise region.error("primitive_poses", f"must have one pose per primitive "
                                              f"({len(primitives)}) (got {len(poses)})")
    shape = read_primitive(primitives[0])
    if isinstance(shape, Sphere):
        radius = shape.radius
    elif isinstance(shape, Box):
        radius = min(shape.size) / 2
    elif isinstance(shape, Cylinder):
        radius = min(shape.radius, shape.length / 2)
    else:
        raise primitives[0].error("type", "a cone region is not supported: use a sphere, box or "
                                          "cylinder")
    return poses[0].as_pose(frame), radius


def _constraints(msg: Msg, names: NameMap) -> tuple[tuple[_JointCheck, ...] | None, _PoseTarget | None]:
    if msg.seq("visibility_constraints"):
        raise msg.error("visibility_constraints", "are not supported")
    joints = msg.msgs("joint_constraints", ("joint_name", "position", "tolerance_above",
                                            "tolerance_below", "weight"))
    positions = msg.msgs("position_constraints", ("header", "link_name", "target_point_offset",
                                                  "constraint_region", "weight"))
    orientations = msg.msgs("orientation_constraints", (
        "header", "orientation", "link_name", "absolute_x_axis_tolerance",
        "absolute_y_axis_tolerance", "absolute_z_axis_tolerance", "parameterization", "weight"))
    if joints and (positions or orientations):
        raise msg.error(None, "mixes joint constraints with pose constraints in one goal: not "
                              "supported (give them as separate goals)")
    if joints:
        checks = []
        for joint in joints:
            written = joint.string("joint_name")
            if try_name(joint, "joint_name", names.joint, written) is None and \
                    try_name(joint, "joint_name", names.fixed_joint, written) is not None:
                raise joint.error("joint_name", f"names joint {written!r}, fixed in the model: "
                                                "a goal cannot constrain it (MoveIt rejects "
                                                "such a constraint too)")
            name = mapped_name(joint, "joint_name", names.joint, joint.string("joint_name"), "joint",
                           list(names.model.joint_names))
            above, below = joint.number("tolerance_above"), joint.number("tolerance_below")
            for key, value in (("tolerance_above", above), ("tolerance_below", below)):
                if value < 0:
                    raise joint.error(key, f"must be >= 0 (got {value})")
            checks.append(_JointCheck(name, joint.number("position", None), above, below,
                                      joint.where, joint.line))
        return tuple(checks), None
    if not positions:
        if orientations:
            raise msg.error("orientation_constraints", "without a position constraint on the "
                                                       "same link are not supported")
        raise msg.error(None, "must have joint constraints or a position constraint")
    if len(positions) > 1 or len(orientations) > 1:
        raise msg.error(None, "has several position or orientation constraints: one pose goal "
                              "per Constraints is supported")
    position = positions[0]
    link = mapped_name(position, "link_name", names.link, position.string("link_name"), "link",
                   list(names.model.link_names))
    offset = position.vector3("target_point_offset")
    centre, radius = _region(position)
    orientation, tolerance = None, (math.inf, math.inf, math.inf)
    if orientations:
        ori = orientations[0]
        other = mapped_name(ori, "link_name", names.link, ori.string("link_name"), "link",
                        list(names.model.link_names))
        if other != link:
            raise ori.error("link_name", f"must be the position constraint's link {link!r} "
                                         f"(got {other!r})")
        orientation = Pose(quat=ori.quaternion("orientation"), frame=ori.frame_id())
        values = []
        for axis in "xyz":
            key = f"absolute_{axis}_axis_tolerance"
            value = ori.number(key)
            if value <= 0:
                raise ori.error(key, f"must be > 0 rad (got {value})")
            values.append(value)
        tolerance = (values[0], values[1], values[2])
    elif any(offset):
        raise position.error("target_point_offset", "must be zero for a goal without an "
                                                    "orientation constraint (not supported)")
    if radius < _MIN_TOLERANCE:
        raise position.error("constraint_region", f"is smaller than {_MIN_TOLERANCE} m")
    return None, _PoseTarget(link, offset, centre, radius, orientation, tolerance,
                             position.where, position.line)


def _scaling(msg: Msg, key: str) -> float | None:
    value = msg.number(key)
    if value == 0:
        return None
    if not 0 < value <= 1:
        raise msg.error(key, f"must be in (0, 1] (0: the robot's default) (got {value})")
    return value


def load_motion_plan_request(path: str | os.PathLike[str], model: RobotModel, *, robot: str | None = None,
                             group: str | None = None, strict: bool | None = None,
                             limits: YamlLimits | None = None) -> MotionPlanRequestFile:
    """Read a ``moveit_msgs/MotionPlanRequest`` YAML file for ``model``.

    Args:
        path: the file.
        model: the robot or cell model.
        robot: the cell's robot instance the file is for (see :mod:`taskrunner.moveit.names`).
        group: plan for this group instead of ``group_name`` (a model group name).
        strict: warnings are errors (None: no).

    Raises:
        YamlError: the file does not parse.
        InputError: an invalid or unsupported field, an unknown group, joint or link
            (file:line and field); in strict mode, the first warning.
    """
    reader = MessageReader(Path(path), strict)
    names = NameMap(model, robot)
    msg = unwrap(load_yaml(Path(path), limits), ("request", "motion_plan_request", "MotionPlanRequest",
                                           "moveit_msgs/MotionPlanRequest",
                                           "moveit_msgs/msg/MotionPlanRequest"),
                 reader, REQUEST_FIELDS, "MotionPlanRequest")
    if group is not None:
        model.group(group)
        group_name = group
    else:
        written = msg.string("group_name")
        if not written:
            raise msg.error("group_name", "must name the planning group")
        found = try_name(msg, "group_name", names.group, written)
        group_name = found or ""
    start = read_robot_state(msg.msg("start_state", ROBOT_STATE_FIELDS), names)
    goals = [_constraints(c, names) for c in msg.msgs("goal_constraints", CONSTRAINTS_FIELDS)]
    if not goals:
        raise msg.error("goal_constraints", "must give at least one goal")
    if not group_name:
        group_name = _group_of_joints(msg, model, goals)
    for key in ("path_constraints",):
        constraints = msg.msg(key, CONSTRAINTS_FIELDS)
        if constraints is not None and any(constraints.seq(k) for k in CONSTRAINTS_FIELDS[1:]):
            raise constraints.error(None, "(path constraints) are not supported: the planner "
                                          "would ignore them; remove them to plan without")
    trajectory = msg.msg("trajectory_constraints", ("constraints",))
    if trajectory is not None and trajectory.seq("constraints"):
        raise trajectory.error("constraints", "(trajectory constraints) are not supported")
    if msg.seq("reference_trajectories"):
        msg.warn("reference_trajectories", "are not supported; ignored")
    for key in ("max_cartesian_speed",):
        if msg.number(key) != 0:
            msg.warn(key, "(a Cartesian speed limit) is not supported; ignored")
    workspace = msg.msg("workspace_parameters", ("header", "min_corner", "max_corner"))
    if workspace is not None:
        low, high = workspace.vector3("min_corner"), workspace.vector3("max_corner")
        if any(a > b for a, b in zip(low, high)):
            raise workspace.error("max_corner", f"must be >= 'min_corner' (got {high} < {low})")
    pipeline = msg.string("pipeline_id")
    if pipeline not in _PIPELINES:
        msg.warn("pipeline_id", f"is {pipeline!r}; only OMPL planners are available: planning "
                                "with OMPL")
    planner = _planner(msg, model, group_name)
    time_cap = msg.number("allowed_planning_time")
    attempts = msg.integer("num_planning_attempts")
    if time_cap < 0:
        raise msg.error("allowed_planning_time", f"must be >= 0 s (got {time_cap})")
    if attempts < 0:
        raise msg.error("num_planning_attempts", f"must be >= 0 (got {attempts})")
    options = PlannerOptions(planner=planner, planning_time=time_cap or 5.0, attempts=attempts or 1)
    allowance = None
    if msg.has("start_state_max_bounds_error"):
        allowance = msg.number("start_state_max_bounds_error")
        if allowance < 0:
            raise msg.error("start_state_max_bounds_error", f"must be >= 0 (rad or m) "
                                                            f"(got {allowance})")
    return MotionPlanRequestFile(
        Path(path), group_name, start.values, start.attached, options,
        _scaling(msg, "max_velocity_scaling_factor"), _scaling(msg, "max_acceleration_scaling_factor"),
        tuple(g[0] for g in goals), tuple(g[1] for g in goals), reader.warnings, names,
        allowance, msg.line_of("start_state"))


def _group_of_joints(msg: Msg, model: RobotModel,
                     goals: list[tuple[tuple[_JointCheck, ...] | None, _PoseTarget | None]]) -> str:
    """The group for a ``group_name`` the model does not have (a MoveIt config's own
    name, ``panda_arm`` for our ``arm``): the one group whose joints are exactly those of
    the joint goals, with a warning; else an error."""
    written = msg.string("group_name")
    joint_sets = {frozenset(c.joint for c in checks) for checks, _ in goals if checks is not None}
    matches = [g.name for g in model.groups.values()
               if len(joint_sets) == 1 and set(g.joint_names) == next(iter(joint_sets))]
    if len(matches) != 1 or len(joint_sets) != 1 or any(c is None for c, _ in goals):
        raise msg.error("group_name", f"names an unknown group {written!r}; known: "
                                      f"{', '.join(repr(g) for g in model.groups)} "
                                      "(--group chooses one)")
    msg.warn("group_name", f"names {written!r}, not a group of the model; planning for group "
                           f"{matches[0]!r}, whose joints are exactly the goal's")
    return matches[0]


def _planner(msg: Msg, model: RobotModel, group: str) -> str:
    written = msg.string("planner_id")
    fallback = group_planner(model.group(group))
    if not written:
        return fallback
    name = planner_name(written)
    if name in PLANNERS:
        return name
    msg.warn("planner_id", f"names {written!r}, not an available planner ({', '.join(PLANNERS)}); "
                           f"planning with {fallback}")
    return fallback
