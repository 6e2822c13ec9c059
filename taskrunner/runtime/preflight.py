"""Check before run: a task is checked statically before anything moves.

``run-task FILE`` (and the REST API's runs) call :func:`check_before_run` first: a task
whose place is out of reach is refused with every problem at its file:line instead of
picking the object and failing with it in the gripper. The check is
:func:`~taskrunner.tree.check.check_task` (structure, names, a kinematic dry run from the
cell's start state; nothing moves): 0.1-1 s on the shipped examples (measured).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from taskrunner.folders import FolderPolicy
from taskrunner.robot.options import LoadOptions
from taskrunner.tasks.problem import raise_for_problems
from taskrunner.taught import TaughtPoses
from taskrunner.tree.check import CheckReport, check_task

__all__ = ["check_before_run"]


def check_before_run(path: str | Path, parameters: Mapping[str, object] | None = None,
                     seed: int = 0, *, policy: FolderPolicy | None = None,
                     taught: TaughtPoses | None = None,
                     options: LoadOptions | None = None) -> CheckReport:
    """Check the task file a run is about to run; returns the report when it has no problem.

    Args:
        path: the task file.
        parameters: the run's parameter overrides.
        seed: the run's seed (IK searches are seeded as the run seeds them).
        policy, taught, options: as for :func:`~taskrunner.tree.check.check_task`.

    Raises:
        TaskSpecError: the check found problems; all of them are in its ``problems``
            attribute (each with file:line), the first gives its file and line.
    """
    report = check_task(path, parameters, seed=seed, policy=policy, taught=taught,
                        options=options)
    raise_for_problems(report.problems)
    return report
