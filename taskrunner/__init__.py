"""taskrunner: declarative task scripting and a behaviour-tree runtime for robot-arm cells.

The public Python API (everything else is internal and may change)::

    import taskrunner

    cell = taskrunner.load_workcell("servo_arm_table")   # a cell, a robot, a MoveIt package
    plan = cell.plan("arm", to="Candle")                  # OMPL + toppra
    cell.execute(plan)                                    # on the mock backend by default
    result = taskrunner.run_task("pick_place", parameters={"place_y": -0.1})
    print(result.status, result.duration)

Names are imported on first use, so ``import taskrunner`` stays fast (pinocchio, OMPL and
pydantic load when a workcell or a step is first made).
"""

from __future__ import annotations

import os as _os

TYPE_CHECKING = False  # typing itself takes milliseconds to import; type checkers know this name

# Small matrices everywhere: OpenBLAS spreading a product over threads costs 10-50 ms per
# call on a loaded 2-core machine (measured in toppra's setup). Set before numpy loads;
# an explicit setting in the environment wins.
_os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

__version__ = "0.1.0"

if TYPE_CHECKING:
    from typing import Any

    from taskrunner.backends.base import Backend, ExecutionHandle, ExecutionResult
    from taskrunner.builder import (
        AddObject,
        Attach,
        Detach,
        Expect,
        Fallback,
        Go,
        Gripper,
        Handoff,
        Move,
        Object,
        Parallel,
        Pick,
        Place,
        RemoveObject,
        Repeat,
        Retry,
        Sequence,
        Task,
        Timeout,
        Wait,
    )
    from taskrunner.errors import TaskrunnerError
    from taskrunner.kinds import BackendKind, CollisionChoice
    from taskrunner.plan import Plan
    from taskrunner.robot.options import LoadOptions
    from taskrunner.runtime.events import RunEvent
    from taskrunner.runtime.records import RunRecord
    from taskrunner.runtime.resume import ResumeOptions
    from taskrunner.taskrun import RunResult, TaskRun
    from taskrunner.taught import TaughtPose
    from taskrunner.types import JointPath, JointState, JointTrajectory, Pose
    from taskrunner.workcell import Workcell, load_workcell, run_task, start_task

__all__ = [
    "AddObject",
    "Attach",
    "Backend",
    "BackendKind",
    "CollisionChoice",
    "Detach",
    "ExecutionHandle",
    "ExecutionResult",
    "Expect",
    "Fallback",
    "Go",
    "Gripper",
    "Handoff",
    "JointPath",
    "JointState",
    "JointTrajectory",
    "LoadOptions",
    "Move",
    "Object",
    "Parallel",
    "Pick",
    "Place",
    "Plan",
    "Pose",
    "RemoveObject",
    "Repeat",
    "ResumeOptions",
    "Retry",
    "RunEvent",
    "RunRecord",
    "RunResult",
    "Sequence",
    "Task",
    "TaskRun",
    "TaskrunnerError",
    "TaughtPose",
    "Timeout",
    "Wait",
    "Workcell",
    "__version__",
    "load_workcell",
    "run_task",
    "start_task",
]

# Where each public name lives (imported on first access: PEP 562).
_HOMES = {
    **dict.fromkeys(("AddObject", "Attach", "Detach", "Expect", "Fallback", "Go", "Gripper", "Handoff",
                     "Move", "Object", "Parallel", "Pick", "Place", "RemoveObject", "Repeat",
                     "Retry", "Sequence", "Task", "Timeout", "Wait"), "taskrunner.builder"),
    **dict.fromkeys(("JointPath", "JointState", "JointTrajectory", "Pose"), "taskrunner.types"),
    **dict.fromkeys(("Workcell", "load_workcell", "run_task", "start_task"),
                    "taskrunner.workcell"),
    **dict.fromkeys(("Backend", "ExecutionHandle", "ExecutionResult"),
                    "taskrunner.backends.base"),
    **dict.fromkeys(("BackendKind", "CollisionChoice"), "taskrunner.kinds"),
    "LoadOptions": "taskrunner.robot.options",
    "Plan": "taskrunner.plan",
    "ResumeOptions": "taskrunner.runtime.resume",
    "RunRecord": "taskrunner.runtime.records",
    "TaughtPose": "taskrunner.taught",
    **dict.fromkeys(("RunResult", "TaskRun"), "taskrunner.taskrun"),
    "RunEvent": "taskrunner.runtime.events",
    "TaskrunnerError": "taskrunner.errors",
}


def __getattr__(name: str) -> Any:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'taskrunner' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(home), name)
    globals()[name] = value  # later lookups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
