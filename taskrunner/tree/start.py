"""Where a task starts: one answer for ``run-task check`` and for the run.

The start is the cell's start state (defaults, ``initial_positions.yaml``, the cell's
``start`` poses) with the joints of the task's ``scene:`` file's ``robot_state`` set, each
joint just outside its bounds moved onto them as MoveIt's ``FixStartStateBounds`` does
(:mod:`taskrunner.moveit.start_bounds`). The check starts there; ``run-task`` creates the
mock, sim and mujoco controllers there; a controller already somewhere (servos, a server's
live controllers) must already be there on the joints the file sets, else the run refuses
to start (:func:`start_mismatch`), before anything moves.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from taskrunner.errors import InputError, InvalidStateError
from taskrunner.moveit.scene_file import load_planning_scene
from taskrunner.moveit.start_bounds import fix_start_bounds
from taskrunner.robot.cell import Cell
from taskrunner.tasks.spec import TaskSpec

__all__ = ["START_TOLERANCE", "TaskStart", "start_mismatch", "task_start"]

START_TOLERANCE = 1e-3
"""rad or m: a controller this close to the scene file's state is there."""

_log = logging.getLogger("taskrunner.moveit")


@dataclass(frozen=True)
class TaskStart:
    """The state a task starts in.

    Attributes:
        q: every joint of the cell (rad or m).
        set_by_file: the joints the scene file's ``robot_state`` sets (empty: none).
    """

    q: np.ndarray
    set_by_file: tuple[str, ...] = ()


def task_start(spec: TaskSpec, cell: Cell) -> TaskStart:
    """The start of ``spec`` on ``cell`` (see the module docstring).

    Raises:
        InputError: the scene file is invalid, or its ``robot_state`` is outside the
            joint bounds by more than ``start_state_max_bounds_error`` (0.05 rad or m).
    """
    q = cell.start_state()
    if spec.scene is None:
        return TaskStart(q)
    loaded = load_planning_scene(spec.scene, cell.model)
    if not loaded.state:
        return TaskStart(q)
    try:
        q, moved = fix_start_bounds(cell.model, cell.model.state_with(q, loaded.state))
    except InvalidStateError as exc:
        raise InputError(f"'robot_state': {exc}", spec.scene) from None
    for fix in moved:
        _log.warning("%s: 'robot_state' %s (start_state_max_bounds_error 0.05, as MoveIt's "
                     "FixStartStateBounds)", spec.scene, fix)
    return TaskStart(q, tuple(loaded.state))


def start_mismatch(start: TaskStart, q: np.ndarray, cell: Cell, where: str) -> str | None:
    """Why a controller at ``q`` cannot start the task (None: it can): a joint the scene
    file sets that is more than :data:`START_TOLERANCE` away from the file's value."""
    model = cell.model
    off = []
    for name in start.set_by_file:
        index = model.joint(name).index
        if abs(q[index] - start.q[index]) > START_TOLERANCE:
            off.append(f"{name!r} at {q[index]:.6g}, the file's {start.q[index]:.6g}")
    if not off:
        return None
    return (f"the robot is not where the task's scene file puts it ({'; '.join(off)}): the "
            f"check starts from the file's robot_state, so the run must too; {where}")
