"""Tasks built in Python: step objects over the task language's models.

Each step class here is a thin constructor over the model of a YAML verb (``Go`` is a
:class:`~taskrunner.tasks.GoStep`, ``Pick`` a :class:`~taskrunner.tasks.PickStep`, …):
positional arguments for what a step is about, keywords for the rest, the same fields,
defaults and checks as in a task file. A step remembers the Python file and line where
it was built, so every error about it, when it is built, checked or run, names that
line the way a task file's errors name ``file:line``::

    from taskrunner import Go, Gripper, Object, Pick, Place, Task

    task = Task("pick_place", cell="servo_arm_table", objects=[
        Object("cube", "box", size=(0.025, 0.025, 0.025), at=(0.19, 0.04, 0.7625)),
    ], steps=[
        Go("arm", "home"),
        Pick("arm", "cube", approach=0.04),
        Place("arm", "cube", at=(0.14, -0.12, 0.7635)),
        Go("arm", "home"),
    ])

Poses (``at=``, ``pose=``) are a :class:`~taskrunner.Pose` (position and orientation),
three numbers x, y, z (a position: the orientation is left to the step, as a YAML pose
without ``rpy``), or a mapping written as in YAML (``{"xyz": …, "rpy": …, "frame": …}``).
Units: metres, radians, seconds.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Iterable, Mapping
from collections.abc import Sequence as Seq
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, PrivateAttr, ValidationError, model_validator

from taskrunner.robot.cell import Cell
from taskrunner.tasks.expect import Expectation, TaskExpectation
from taskrunner.tasks.loader import apply_defaults
from taskrunner.tasks.names import check_names
from taskrunner.tasks.nodes import Location, ObjectSpec
from taskrunner.tasks.problem import Problem, problems_error, problems_from_validation
from taskrunner.tasks.spec import TaskSpec
from taskrunner.tasks.steps import (
    AddObjectStep,
    AttachStep,
    DetachStep,
    ExpectStep,
    FallbackStep,
    GoStep,
    GripperStep,
    HandoffStep,
    MotionOptions,
    MoveStep,
    ParallelStep,
    PickStep,
    PlaceStep,
    RemoveObjectStep,
    RepeatStep,
    RetryStep,
    SequenceStep,
    StepNode,
    TimeoutStep,
    WaitStep,
    walk_steps,
)
from taskrunner.types import Pose

__all__ = [
    "AddObject", "Attach", "Detach", "Expect", "Fallback", "Go", "Gripper", "Handoff", "Move",
    "Object", "Parallel", "Pick", "Place", "RemoveObject", "Repeat", "Retry", "Sequence",
    "Task", "Timeout", "Wait",
]

PoseLike = Pose | Seq[float] | Mapping[str, Any]
"""A pose: a :class:`Pose`, x, y, z (m, no orientation) or a YAML-style mapping."""

_PACKAGE = os.path.dirname(os.path.abspath(__file__)) + os.sep


def _caller() -> Location | None:
    """Where the step is being built: the first frame outside the taskrunner package."""
    frame = sys._getframe(1)
    while frame is not None:
        file = frame.f_code.co_filename
        if not os.path.abspath(file).startswith(_PACKAGE):
            return Location(Path(file), frame.f_lineno)
        frame = frame.f_back  # type: ignore[assignment]
    return None


def _pose(value: PoseLike | None, **extra: Any) -> dict[str, Any] | None:
    """The YAML form of a pose argument (None stays None)."""
    if value is None:
        return None
    if isinstance(value, Pose):
        data: dict[str, Any] = {"xyz": value.xyz, "quat": value.quat, "frame": value.frame}
    elif isinstance(value, Mapping):
        data = dict(value)
    else:
        data = {"xyz": tuple(value)}
    return data | {k: v for k, v in extra.items() if v is not None}


def _motion(planner: str | None, velocity_scaling: float | None,
            acceleration_scaling: float | None, planning_time: float | None) -> dict[str, Any]:
    return {"planner": planner, "velocity_scaling": velocity_scaling,
            "acceleration_scaling": acceleration_scaling, "planning_time": planning_time}


def _init(step: BaseModel, data: dict[str, Any]) -> None:
    """Validate ``data`` into ``step`` (a step model); errors name the Python line."""
    where = _caller()
    fields = {k: v for k, v in data.items() if v is not None}
    verb = getattr(step, "verb", type(step).__name__)
    try:
        BaseModel.__init__(step, **fields)
    except ValidationError as exc:
        problems = problems_from_validation(exc, fields, where.file if where else None,
                                            (verb,), type(step), where.line if where else None)
        raise problems_error(problems) from None
    step._loc = where  # type: ignore[attr-defined]


def _steps(verb: str, steps: Iterable[Any], least: int = 1) -> tuple[StepNode, ...]:
    items = tuple(steps)
    where = _caller()
    file, line = (where.file, where.line) if where else (None, None)
    for i, item in enumerate(items):
        if not isinstance(item, StepNode):
            raise problems_error([Problem(file, line, f"'{verb}' step {i + 1} must be a step "
                                          f"(Go, Pick, Sequence …) (got {item!r})")])
    if len(items) < least:
        raise problems_error([Problem(file, line, f"'{verb}' needs at least {least} step"
                                      f"{'s' * (least > 1)} (got {len(items)})")])
    return items


# ------------------------------------------------------------------------------- leaves
class Go(GoStep):
    """Move a group to a named pose, joint values, or a pose of its tip (planned, OMPL).

    Args:
        group: the group to move.
        to: a named pose of the group (``"home"``).
        joints: joint values {joint: rad or m}; the group's other joints keep theirs.
        pose: a pose for the group's tip (or ``link``), world frame unless it says.
        link: the link placed at ``pose`` (default: the group's tip).
        position_only: reach the position only (default: the group's IK setting, or
            True for a pose without orientation).
        name: a label for displays and events.
        planner: OMPL planner name (default: the task's, else RRTConnect).
        velocity_scaling: fraction in (0, 1] of the joint velocity limits.
        acceleration_scaling: fraction in (0, 1] of the joint acceleration limits.
        planning_time: seconds the planner may search.
    """

    def __init__(self, group: str, to: str | None = None, *,
                 joints: Mapping[str, float] | None = None, pose: PoseLike | None = None,
                 link: str | None = None, position_only: bool | None = None,
                 name: str | None = None, planner: str | None = None,
                 velocity_scaling: float | None = None,
                 acceleration_scaling: float | None = None,
                 planning_time: float | None = None) -> None:
        _init(self, {"group": group, "to": to, "joints": joints,
                     "pose": _pose(pose, link=link, position_only=position_only),
                     "name": name} | _motion(planner, velocity_scaling, acceleration_scaling,
                                             planning_time))


class Move(MoveStep):
    """Move a link to a pose, or by an offset (then in a straight line by default).

    Args:
        group: the group to move.
        pose: the absolute target pose (planned; ``cartesian=True`` for a straight line).
        by: a relative motion x, y, z (m), or a mapping ``{"xyz", "rpy"}``.
        by_frame: axes of ``by``: the moved link's (``"tool"``) or the world's.
        link: the link to move (default: the group's tip).
        cartesian: straight line in Cartesian space (default: True with ``by``).
        name: a label for displays and events.
        planner: OMPL planner name (default: the task's, else RRTConnect).
        velocity_scaling: fraction in (0, 1] of the joint velocity limits.
        acceleration_scaling: fraction in (0, 1] of the joint acceleration limits.
        planning_time: seconds the planner may search.
    """

    def __init__(self, group: str, pose: PoseLike | None = None, *,
                 by: Seq[float] | Mapping[str, Any] | None = None,
                 by_frame: Literal["tool", "world"] = "tool", link: str | None = None,
                 cartesian: bool | None = None, name: str | None = None,
                 planner: str | None = None, velocity_scaling: float | None = None,
                 acceleration_scaling: float | None = None,
                 planning_time: float | None = None) -> None:
        offset = None
        if by is not None:
            offset = (dict(by) if isinstance(by, Mapping) else {"xyz": tuple(by)}) | {
                "frame": by_frame}
        _init(self, {"group": group, "pose": _pose(pose), "by": offset, "link": link,
                     "cartesian": cartesian, "name": name}
              | _motion(planner, velocity_scaling, acceleration_scaling, planning_time))


class Gripper(GripperStep):
    """Open, close or set the gripper of an arm (or a gripper group).

    Args:
        arm: an arm whose end effector has a gripper group (or give ``group``).
        action: ``"open"`` or ``"close"`` (or give ``to`` or ``width``).
        group: a gripper group, instead of ``arm``.
        to: a named pose of the gripper group.
        width: opening between the fingers (m), for prismatic fingers.
        name: a label for displays and events.
    """

    def __init__(self, arm: str | None = None, action: Literal["open", "close"] | None = None,
                 *, group: str | None = None, to: str | None = None,
                 width: float | None = None, name: str | None = None) -> None:
        _init(self, {"arm": arm, "action": action, "group": group, "to": to, "width": width,
                     "name": name})


class Pick(PickStep):
    """Approach an object, grasp it, attach it to the arm and lift it.

    Args:
        arm: the arm that picks.
        object: the object to pick.
        grasp: ``"top"``, ``"side"``, or the tool's pose in the object's frame.
        approach: length of the straight approach to the grasp (m).
        retreat: length of the straight retreat after grasping (m).
        name: a label for displays and events.
        planner: OMPL planner name (default: the task's, else RRTConnect).
        velocity_scaling: fraction in (0, 1] of the joint velocity limits.
        acceleration_scaling: fraction in (0, 1] of the joint acceleration limits.
        planning_time: seconds the planner may search.
    """

    def __init__(self, arm: str, object: str, *,
                 grasp: Literal["top", "side"] | PoseLike = "top", approach: float = 0.05,
                 retreat: float = 0.05, name: str | None = None, planner: str | None = None,
                 velocity_scaling: float | None = None,
                 acceleration_scaling: float | None = None,
                 planning_time: float | None = None) -> None:
        shown = grasp if isinstance(grasp, str) else _transform(grasp)
        _init(self, {"arm": arm, "object": object, "grasp": shown, "approach": approach,
                     "retreat": retreat, "name": name}
              | _motion(planner, velocity_scaling, acceleration_scaling, planning_time))


class Place(PlaceStep):
    """Carry a held object to a pose (or onto a surface object) and release it.

    Args:
        arm: the arm holding the object.
        object: the object to place.
        at: the object's pose where it is released (x, y, z alone: upright, as held).
        on: a surface object to put it on top of, instead of ``at``.
        offset: with ``on``: x, y from the surface's centre (m, surface frame).
        approach: length of the straight approach to the release pose (m).
        retreat: length of the straight retreat after releasing (m).
        name: a label for displays and events.
        planner: OMPL planner name (default: the task's, else RRTConnect).
        velocity_scaling: fraction in (0, 1] of the joint velocity limits.
        acceleration_scaling: fraction in (0, 1] of the joint acceleration limits.
        planning_time: seconds the planner may search.
    """

    def __init__(self, arm: str, object: str, at: PoseLike | None = None, *,
                 on: str | None = None, offset: Seq[float] | None = None,
                 approach: float = 0.05, retreat: float = 0.05, name: str | None = None,
                 planner: str | None = None, velocity_scaling: float | None = None,
                 acceleration_scaling: float | None = None,
                 planning_time: float | None = None) -> None:
        _init(self, {"arm": arm, "object": object, "at": _pose(at), "on": on,
                     "offset": tuple(offset) if offset is not None else None,
                     "approach": approach, "retreat": retreat, "name": name}
              | _motion(planner, velocity_scaling, acceleration_scaling, planning_time))


class Handoff(HandoffStep):
    """Pass a held object from one arm to another.

    Args:
        object: the object handed over.
        from_arm: the arm holding it.
        to_arm: the arm taking it.
        at: a named pose of the giving arm (``"HandOff"``), or the object's pose at
            the hand-over.
        approach: length of the taking arm's straight approach (m).
        retreat: length both arms retreat after the exchange (m).
        name: a label for displays and events.
        planner: OMPL planner name (default: the task's, else RRTConnect).
        velocity_scaling: fraction in (0, 1] of the joint velocity limits.
        acceleration_scaling: fraction in (0, 1] of the joint acceleration limits.
        planning_time: seconds the planner may search.
    """

    def __init__(self, object: str, from_arm: str, to_arm: str, at: str | PoseLike, *,
                 approach: float = 0.05, retreat: float = 0.05, name: str | None = None,
                 planner: str | None = None, velocity_scaling: float | None = None,
                 acceleration_scaling: float | None = None,
                 planning_time: float | None = None) -> None:
        _init(self, {"object": object, "from": from_arm, "to": to_arm,
                     "at": at if isinstance(at, str) else _pose(at), "approach": approach,
                     "retreat": retreat, "name": name}
              | _motion(planner, velocity_scaling, acceleration_scaling, planning_time))


class Attach(AttachStep):
    """Attach a scene object to an arm's tool (or to ``link``) without moving."""

    def __init__(self, object: str, arm: str | None = None, *, link: str | None = None,
                 name: str | None = None) -> None:
        _init(self, {"object": object, "arm": arm, "link": link, "name": name})


class Detach(DetachStep):
    """Detach an attached object, leaving it where it is in the world."""

    def __init__(self, object: str, *, name: str | None = None) -> None:
        _init(self, {"object": object, "name": name})


class Object(ObjectSpec):
    """A scene object: for :class:`Task` ``objects`` or an :class:`AddObject` step.

    Args:
        name: unique name of the object.
        shape: ``"box"`` (``size``), ``"cylinder"`` (``radius``, ``length`` along z),
            ``"sphere"`` (``radius``) or ``"mesh"`` (``file``, ``scale``).
        size: full lengths of a box along x, y, z (m).
        radius: radius of a cylinder or sphere (m).
        length: length of a cylinder (m).
        file: a mesh file (a path, or a ``package://`` URI).
        scale: scale of a mesh along x, y, z.
        at: the pose of the object's centre (world frame unless it says).
        touch_links: links allowed to touch the object.
    """

    def __init__(self, name: str, shape: Literal["box", "cylinder", "sphere", "mesh"], *,
                 size: Seq[float] | None = None, radius: float | None = None,
                 length: float | None = None, file: str | os.PathLike[str] | None = None,
                 scale: Seq[float] | None = None, at: PoseLike | None = None,
                 touch_links: Seq[str] = ()) -> None:
        _init(self, {"name": name, "shape": shape,
                     "size": tuple(size) if size is not None else None, "radius": radius,
                     "length": length, "file": os.fspath(file) if file is not None else None,
                     "scale": tuple(scale) if scale is not None else None, "pose": _pose(at),
                     "touch_links": tuple(touch_links)})


class AddObject(AddObjectStep):
    """Add an object to the scene (an :class:`Object`)."""

    def __init__(self, object: ObjectSpec) -> None:
        _init(self, {"object": object})


class RemoveObject(RemoveObjectStep):
    """Remove an object from the scene."""

    def __init__(self, object: str) -> None:
        _init(self, {"object": object})


class Wait(WaitStep):
    """Do nothing for ``seconds`` (s)."""

    def __init__(self, seconds: float, *, name: str | None = None) -> None:
        _init(self, {"seconds": seconds, "name": name})


class Expect(ExpectStep):
    """What must be true: a step (checked when the run reaches it; FAILURE at its line
    when it does not hold) or, as :class:`Task`'s ``expect=``, at the run's end. The
    fields of a task file's ``expect:`` (see :mod:`taskrunner.tasks.expect`).

    Args:
        objects: by object name, its ``pose`` (a :class:`~taskrunner.Pose`, x, y, z or
            a mapping), ``orientation`` (free, yaw, full), ``tolerance``
            (``{"position": m, "angle_deg": degrees}``), ``held_by`` (an arm or a
            link), ``released`` (True) and ``on`` (an object it rests on).
        groups: by group name, ``at`` (a named pose) or ``joints`` (rad or m), and
            ``tolerance`` (rad or m).
        duration: task time since the run started (s): at most this many seconds, or
            ``{"min": s, "max": s}``.
        step_duration: task time of the step just before (s), as ``duration``.
        motion_time: the task time since the run started during which a motion ran
            (s), as ``duration``: planning and waits left out.
        collision_free: re-check every motion executed so far for collisions.
        status: the task's end only: ``"succeeded"`` (default) or ``"failed"``.
        error: the task's end only, with ``status="failed"``: text the error contains.
        name: label for displays.

    Raises:
        TaskSpecError: an invalid expectation (at this line).
    """

    _outcome: dict[str, Any] = PrivateAttr(default_factory=dict)

    @model_validator(mode="after")
    def _something(self) -> Expect:  # replaces Expectation's: checked in __init__, knowing status
        return self

    def __init__(self, *, objects: Mapping[str, Mapping[str, Any]] | None = None,
                 groups: Mapping[str, Mapping[str, Any]] | None = None,
                 duration: float | Mapping[str, float] | None = None,
                 step_duration: float | Mapping[str, float] | None = None,
                 motion_time: float | Mapping[str, float] | None = None,
                 collision_free: bool | None = None,
                 status: Literal["succeeded", "failed"] | None = None,
                 error: str | None = None, name: str | None = None) -> None:
        _init(self, {"objects": {k: _expected_object(v) for k, v in (objects or {}).items()},
                     "groups": {k: dict(v) for k, v in (groups or {}).items()},
                     "duration": _bounds(duration), "step_duration": _bounds(step_duration),
                     "motion_time": _bounds(motion_time),
                     "collision_free": collision_free or None, "name": name})
        self._outcome = {k: v for k, v in (("status", status), ("error", error))
                         if v is not None}
        model = TaskExpectation if self._outcome else Expectation
        fields = self._fields()
        try:
            model.model_validate(fields)
        except ValidationError as exc:
            where = self.loc
            raise problems_error(problems_from_validation(
                exc, fields, where.file if where else None, ("expect",), model,
                where.line if where else None)) from None

    def as_task_expectation(self) -> TaskExpectation:
        """This as a task's ``expect:``, with its ``status`` and ``error``."""
        return TaskExpectation.model_validate(self._fields())

    def _fields(self) -> dict[str, Any]:
        return self.model_dump(mode="json", by_alias=True, exclude_defaults=True,
                               exclude={"name"}) | self._outcome


def _expected_object(value: Mapping[str, Any]) -> dict[str, Any]:
    data = dict(value)
    if "pose" in data and not isinstance(data["pose"], Mapping):
        data["pose"] = _pose(data["pose"])
    return data


def _bounds(value: float | Mapping[str, float] | None) -> dict[str, float] | None:
    if value is None or isinstance(value, Mapping):
        return None if value is None else dict(value)
    return {"max": value}


# --------------------------------------------------------------------------- composites
class Sequence(SequenceStep):
    """Run the steps in order; fail at the first failure."""

    def __init__(self, *steps: StepNode) -> None:
        _init(self, {"steps": _steps("sequence", steps)})


class Fallback(FallbackStep):
    """Try the steps in order until one succeeds."""

    def __init__(self, *steps: StepNode) -> None:
        _init(self, {"steps": _steps("fallback", steps)})


class Parallel(ParallelStep):
    """Run the steps at once: ``Go`` steps of different arms become one motion planned
    in a group spanning those arms, so they cannot collide."""

    def __init__(self, *steps: StepNode) -> None:
        _init(self, {"steps": _steps("parallel", steps, least=2)})


class Retry(RetryStep):
    """Run the steps (as a sequence) until they succeed, at most ``times`` attempts."""

    def __init__(self, times: int, *steps: StepNode, name: str | None = None) -> None:
        _init(self, {"times": times, "do": _steps("retry", steps), "name": name})


class Timeout(TimeoutStep):
    """Run the steps (as a sequence); fail if they take longer than ``seconds`` (s)."""

    def __init__(self, seconds: float, *steps: StepNode, name: str | None = None) -> None:
        _init(self, {"seconds": seconds, "do": _steps("timeout", steps), "name": name})


class Repeat(RepeatStep):
    """Run the steps (as a sequence) ``times`` times; fail at the first failure."""

    def __init__(self, times: int, *steps: StepNode, name: str | None = None) -> None:
        _init(self, {"times": times, "do": _steps("repeat", steps), "name": name})


def _transform(value: PoseLike) -> dict[str, Any]:
    data = _pose(value) or {}
    data.pop("frame", None)
    return data


# --------------------------------------------------------------------------------- task
class Task:
    """A task built in Python: steps run as a sequence, with the objects they use.

    Run it with :meth:`Workcell.run_task` (on that workcell's cell and backend) or
    :func:`taskrunner.run_task` (on ``cell``). Before anything moves it gets the checks
    a task file gets (every group, pose, joint, link and object it names must be in
    the cell); errors name the Python line of the step.

    Args:
        name: the task's name (shown in events and the run record).
        steps: the steps, run in order.
        objects: objects added to the scene before the first step.
        cell: the cell it is written for (a shipped name or a path), for
            :func:`taskrunner.run_task`; a workcell runs it on its own cell.
        description: what the task does.
        planner: default OMPL planner of every motion step that sets none (a task
            file's ``defaults``).
        velocity_scaling: default velocity scaling, in (0, 1].
        acceleration_scaling: default acceleration scaling, in (0, 1].
        planning_time: default planning time of a motion step (s).
        expect: what must be true when the run ends (an :class:`Expect`, which may
            give the run's ``status`` and ``error``); checked after the last step.

    Raises:
        TaskSpecError: a step is not a step, ``expect`` not an :class:`Expect`, or an
            invalid default (at this line).
    """

    def __init__(self, name: str, steps: Iterable[StepNode], *,
                 objects: Iterable[ObjectSpec] = (), cell: str | os.PathLike[str] | None = None,
                 description: str = "", planner: str | None = None,
                 velocity_scaling: float | None = None,
                 acceleration_scaling: float | None = None,
                 planning_time: float | None = None, expect: Expect | None = None) -> None:
        self.name = name
        self.description = description
        self.cell = cell
        self.steps = _steps("steps", steps)
        self.objects = tuple(objects)
        where = _caller()
        self.location = where
        for i, obj in enumerate(self.objects):
            if not isinstance(obj, ObjectSpec):
                raise problems_error([Problem(where.file if where else None,
                                              where.line if where else None,
                                              f"'objects' item {i + 1} must be an Object "
                                              f"(got {obj!r})")])
        if expect is not None and not isinstance(expect, Expect):
            raise problems_error([Problem(where.file if where else None,
                                          where.line if where else None,
                                          f"'expect' must be an Expect (got {expect!r})")])
        self.expect = expect
        options = _motion(planner, velocity_scaling, acceleration_scaling, planning_time)
        try:
            self.defaults = MotionOptions(**{k: v for k, v in options.items() if v is not None})
        except ValidationError as exc:
            raise problems_error(problems_from_validation(
                exc, options, where.file if where else None, (), MotionOptions,
                where.line if where else None)) from None

    def __repr__(self) -> str:
        return f"Task({self.name!r}, {len(self.steps)} steps)"

    def spec(self, cell: Cell) -> TaskSpec:
        """The task as a loaded task file would be, for ``cell``, with its names checked.

        Raises:
            TaskSpecError: a name the cell does not have, or an object declared twice
                (every problem, each at its step's Python line).
        """
        where = self.location
        seen: dict[str, ObjectSpec] = {}
        for obj in self.objects:
            if obj.name in seen and seen[obj.name] != obj:
                loc = obj.loc or where
                raise problems_error([Problem(loc.file if loc else None,
                                              loc.line if loc else None,
                                              f"object {obj.name!r} is declared twice")])
            seen[obj.name] = obj
        for step in walk_steps(self.steps):
            if isinstance(step, Expect) and step._outcome:
                loc = step.loc
                raise problems_error([Problem(
                    loc.file if loc else None, loc.line if loc else None,
                    "'status' and 'error' are for a task's end (Task(..., expect=Expect(...))), "
                    "not for an expect step")])
        spec = TaskSpec(name=self.name, description=self.description, path=None,
                        cell=Path(cell.path) if cell.path is not None else Path(cell.name),
                        objects=tuple(seen.values()), defaults=self.defaults,
                        steps=tuple(apply_defaults(s, self.defaults)  # type: ignore[arg-type]
                                    for s in self.steps),
                        expect=self.expect.as_task_expectation() if self.expect else None,
                        ).located(where)

        problems = check_names(spec, cell)
        if problems:
            raise problems_error(problems)
        return spec

    def to_text(self, cell: Cell) -> str:
        """The task as task-file text (JSON, which is YAML) for ``cell``: what a run
        record keeps, and what ``run-task`` can run when saved to a file."""
        return json.dumps(self.spec(cell).to_document(), indent=2) + "\n"
