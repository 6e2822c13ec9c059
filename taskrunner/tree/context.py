"""What every leaf of a compiled task shares: the cell, the scene, the planner, the backend.

A :class:`TaskContext` is built by the runner for one run. Leaves read the scene (the
planning world as it is now), submit plans to the plan service, send trajectories to the
backend, and report through the event log. Arms are resolved once into :class:`Arm`
records (arm group, gripper group, the tool frame that grasps and the gripper's pose
names, from the cell's :class:`~taskrunner.robot.tools.Tool` of the arm).
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pinocchio as pin

from taskrunner.backends.base import Backend, ObjectTracking
from taskrunner.errors import BackendError, PlanningError, UnknownNameError
from taskrunner.planning.cartesian import CartesianPlanner
from taskrunner.planning.service import PlanService
from taskrunner.planning.timing import TimingOptions
from taskrunner.robot.cell import Cell
from taskrunner.robot.tools import Tool, install_tools
from taskrunner.runtime.events import EventLog
from taskrunner.scene import Scene, SceneSnapshot
from taskrunner.tree.choice import step_seed
from taskrunner.tree.clock import TaskClock
from taskrunner.tree.schedule import MotionSchedule
from taskrunner.types import JointTrajectory, Pose

__all__ = ["Arm", "ExecutedMotion", "TaskContext", "resolve_arm"]


@dataclass(frozen=True)
class Arm:
    """An arm as the task language sees it.

    Attributes:
        group: the arm's planning group (it has an end effector).
        gripper: the end effector's group (its finger joints), or None.
        tip: the group's tip link (where the end effector is mounted).
        grasp_frame: the tool frame, placed on a grasped object (its y axis closes, its z
            axis approaches; see :mod:`taskrunner.robot.tools`).
        finger_links: links that may touch a grasped object (the gripper group's links,
            the tip, and the link the tool frame is fixed to).
        tool: the arm's resolved tool (gripper pose names, how the frame was found).
        holder: the link a grasped object is attached to: the tool frame when it is a
            link, else the link it is fixed to (the scene and a physics backend attach
            objects to links).
        holder_to_tool: the tool frame in ``holder``'s frame.
    """

    group: str
    gripper: str | None
    tip: str
    grasp_frame: str
    finger_links: tuple[str, ...]
    tool: Tool | None = None
    holder: str = ""
    holder_to_tool: pin.SE3 = field(default_factory=pin.SE3.Identity)

    def grip(self, held: pin.SE3) -> pin.SE3:
        """The pose in the tool frame of an object held at ``held`` (its pose in
        :attr:`holder`'s frame, as the scene keeps it)."""
        return self.holder_to_tool.actInv(held)

    @property
    def open_pose(self) -> str:
        """The gripper's open pose name (raises RobotDescriptionError if it has none)."""
        return self._tool().gripper_pose("open")

    @property
    def closed_pose(self) -> str:
        """The gripper's closed pose name (raises RobotDescriptionError if it has none)."""
        return self._tool().gripper_pose("closed")

    def _tool(self) -> Tool:
        assert self.tool is not None
        return self.tool


def resolve_arm(cell: Cell, name: str) -> Arm:
    """The :class:`Arm` for group ``name`` of the cell.

    Raises:
        UnknownNameError: no such group, or the group has no end effector.
    """
    model = cell.model
    group = model.group(name)
    arms = [g.name for g in model.groups.values() if g.end_effector and g.tip_link]
    if not group.end_effector or not group.tip_link:
        raise UnknownNameError("arm (a group with an end effector)", name, arms)
    if group.name not in cell.tools:  # a model changed since the cell was made
        cell.tools.update(install_tools(model))
    tool = cell.tools[group.name]
    fingers = tuple(model.group(tool.gripper).links) if tool.gripper else ()
    on_link = tool.frame in model.link_names
    return Arm(group.name, tool.gripper, group.tip_link, tool.frame,
               tuple(dict.fromkeys((*fingers, group.tip_link, tool.link))), tool,
               holder=tool.frame if on_link else tool.link,
               holder_to_tool=pin.SE3.Identity() if on_link else tool.offset)


@dataclass(frozen=True)
class ExecutedMotion:
    """A trajectory sent to the backend, with the scene as it was when it started (plain
    data: objects, attachments, allowances), so the motion can be re-checked afterwards;
    its ``lane`` and ``start`` on the run's schedule (:mod:`taskrunner.tree.schedule`)."""

    node: str
    location: str | None
    trajectory: JointTrajectory
    scene: SceneSnapshot
    lane: tuple[tuple[int, int], ...] = ()
    start: float = 0.0


@dataclass
class TaskContext:
    """The shared state of one run, or of one check (``run-task check`` ticks the task's
    tree in check mode, :mod:`taskrunner.tree.checkmode`: its leaves plan but do not move).

    Attributes:
        planner: the run's plan service; None in a check's context (see
            :meth:`plan_service`).
        backend: the run's execution backend; None in a check's context (see
            :meth:`motion_backend`).
        timing: default time parameterization (scaling from the robot unless set).
        seed: seeds every planner call of the run (each call adds its own offset).
        executed: every trajectory sent to the backend, in order.
        clock: the run's task time, which ``timeout:`` counts (motions at their trajectory
            time on every backend; see :class:`~taskrunner.tree.clock.TaskClock`).
        planner_times: planned motions are timed by the planner (in a worker process,
            that work then leaves this process: a server keeps its GIL for answering);
            False: timed here (a one-run CLI, whose process waits for the plan anyway,
            spares the worker importing toppra on its critical path).
        materials: mass, density and friction the task gives its objects (by name), for a
            physics backend.
        schedule: every motion sent, on the run's clock, by branch: what a motion of one
            branch of a ``parallel`` is verified against (:mod:`taskrunner.tree.schedule`).
        branch: in a check, the path of branch indices (in the run's tree) of the
            ``parallel`` branch being checked; a run's leaves find theirs in the tree.
    """

    cell: Cell
    scene: Scene
    planner: PlanService | None = None
    backend: Backend | None = None
    events: EventLog = field(default_factory=EventLog)
    timing: TimingOptions = field(default_factory=TimingOptions)
    seed: int = 0
    executed: list[ExecutedMotion] = field(default_factory=list)
    planner_times: bool = False
    clock: TaskClock = field(default_factory=TaskClock)
    materials: dict[str, Any] = field(default_factory=dict)
    schedule: MotionSchedule = field(default_factory=MotionSchedule)
    branch: tuple[int, ...] = ()
    _arms: dict[str, Arm] = field(default_factory=dict)
    _calls: int = 0
    # Seeds drawn in branches of a parallel, by (branch, leaf); replaced, never changed in
    # place, so a copy of the context (a check's look-ahead) draws on its own.
    _streams: dict[tuple[tuple[int, ...], str], int] = field(default_factory=dict)
    _drawing: tuple[tuple[int, ...], str] | None = None
    _cartesian: dict[int, tuple[Scene, CartesianPlanner]] = field(default_factory=dict)

    def plan_service(self) -> PlanService:
        """The run's plan service.

        Raises:
            PlanningError: a check's context (it has none: the check plans no motion).
        """
        if self.planner is None:
            raise PlanningError("a check's context has no plan service (its leaves do not "
                                "plan the motions they check)")
        return self.planner

    def motion_backend(self) -> Backend:
        """The run's execution backend.

        Raises:
            BackendError: a check's context (it has none: nothing moves in a check).
        """
        if self.backend is None:
            raise BackendError("a check's context has no backend (nothing moves in a check)")
        return self.backend

    def arm(self, name: str) -> Arm:
        if name not in self._arms:
            self._arms[name] = resolve_arm(self.cell, name)
        return self._arms[name]

    def cartesian_planner(self) -> CartesianPlanner:
        """A Cartesian planner of the run's scene for this thread, kept between straight
        moves (its IK solvers and kinematics data are built once)."""
        key = threading.get_ident()
        entry = self._cartesian.get(key)
        if entry is None or entry[0] is not self.scene:
            entry = self._cartesian[key] = (self.scene, CartesianPlanner(self.scene))
        return entry[1]

    def next_seed(self) -> int:
        """A fresh, reproducible seed for the next planner call: in a branch of a
        ``parallel`` (while a leaf there draws, :meth:`drawing`), the next of that leaf's
        own stream (:func:`~taskrunner.tree.choice.step_seed`), whatever the other
        branches drew meanwhile."""
        if self._drawing is not None and self._drawing[0]:
            count = self._streams.get(self._drawing, 0) + 1
            self._streams = {**self._streams, self._drawing: count}
            return step_seed(self.seed, *self._drawing, count)
        self._calls += 1
        return self.seed * 1000 + self._calls

    @contextmanager
    def drawing(self, branch: tuple[int, ...], leaf: str) -> Iterator[None]:
        """Seeds drawn inside are leaf ``leaf``'s of the branch at path ``branch``."""
        before, self._drawing = self._drawing, (branch, leaf)
        try:
            yield
        finally:
            self._drawing = before

    def sync_from_backend(self, finished: tuple[str, str | None] | None = None) -> None:
        """Make the scene's robot state what the backend reports. ``finished``: the node
        (name, file:line) whose motion just ended: a physics backend's report of it
        becomes a ``physics`` event."""
        backend = self.motion_backend()
        state = backend.joint_state()
        self.scene.set_state(dict(zip(state.names, state.positions)))
        if isinstance(backend, ObjectTracking):  # physics: objects go where they really are
            backend.bind_scene(self.scene, self.materials)
            report = backend.physics_report() if finished is not None else None
            if report is not None and finished is not None:
                message = f"{len(report.get('t', ()))} samples of joints and objects"
                for grasp in report.get("grasps", ()):  # grasp_mode weld
                    message += (f"; {grasp['object']!r} {grasp['action']} "
                                f"{'to' if grasp['action'] == 'welded' else 'from'} "
                                f"{grasp['link']!r} at {grasp['time']:.3f} s (grasp_mode weld)")
                self.events.emit("physics", message, node=finished[0], location=finished[1],
                                 **report)
            # While a motion runs, moves under 0.1 mm are skipped; when it has ended (the
            # physics paused) objects take their exact poses, so what is planned next does
            # not depend on when the tree last looked.
            for name, pose in backend.object_poses().items():
                if name in self.scene and not self.scene.object(name).attached \
                        and _moved(self.scene.object(name).pose, pose, exact=finished is not None):
                    self.scene.move_object(name, pose)


def _moved(a: Pose, b: Pose, exact: bool = False) -> bool:
    """More than 0.1 mm or about 0.01° apart (below that, no scene edit); ``exact``: at all."""
    if exact:
        return tuple(a.xyz) != tuple(b.xyz) or tuple(a.quat) != tuple(b.quat)
    return (float(np.linalg.norm(np.subtract(a.xyz, b.xyz))) > 1e-4
            or abs(abs(float(np.dot(a.quat, b.quat))) - 1.0) > 1e-8)
