"""``run-task check`` ticks the task's own compiled tree in check mode
(:mod:`taskrunner.tree.checkmode`): the run's py_trees composites, check-mode steps."""

from __future__ import annotations

from pathlib import Path
from typing import Any, cast

import py_trees
import pytest

from taskrunner.errors import BackendError, PlanningError
from taskrunner.robot.cell import load_cell
from taskrunner.scene import scene_from_cell
from taskrunner.tasks import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.checkmode import (
    CheckBranch,
    Checker,
    CheckFallback,
    CheckMode,
    CheckStep,
    ScheduledParallel,
    StepSpan,
)
from taskrunner.tree.compiler import compile_task
from taskrunner.tree.context import TaskContext

FIXTURES = Path(__file__).parent / "fixtures"
CELL = Path(__file__).parents[2] / "taskrunner" / "data" / "robots" / "cells"


def _check_tree(text: str, tmp_path: Path) -> py_trees.behaviour.Behaviour:
    path = tmp_path / "task.yaml"
    path.write_text(text)
    spec = load_task(path)
    cell = load_cell(spec.cell)
    ctx = TaskContext(cell, scene_from_cell(cell))
    # Compiling builds the behaviours only: nothing of the checker is called before a tick.
    return compile_task(spec, ctx, check=CheckMode(cast(Checker, object())))


_TASK = f"""
task: composites
cell: {CELL / 'servo_arm_pair.yaml'}
steps:
  - fallback:
      - go: {{group: left_arm, to: Candle}}
      - go: {{group: left_arm, to: home}}
  - retry:
      times: 3
      do:
        - go: {{group: left_arm, to: home}}
  - repeat:
      times: 4
      do:
        - go: {{group: right_arm, to: Candle}}
        - go: {{group: right_arm, to: home}}
  - parallel:
      - sequence:
          - go: {{group: left_arm, to: Candle}}
      - go: {{group: right_arm, to: Candle}}
"""


def test_check_mode_builds_the_runs_composites_around_check_mode_steps(tmp_path: Path):
    tree = _check_tree(_TASK, tmp_path)
    nodes = list(tree.iterate())
    kinds = {type(n) for n in nodes}
    assert {py_trees.composites.Sequence, py_trees.composites.Selector,
            py_trees.composites.Parallel, py_trees.decorators.Retry,
            py_trees.decorators.Repeat} <= kinds
    # Every leaf is a check-mode step, and every step records its span.
    leaves = [n for n in nodes if not n.children]
    assert leaves and all(isinstance(n, CheckStep) or n.name.endswith("(one motion)")
                          for n in leaves)
    assert sum(isinstance(n, CheckStep) for n in leaves) == 7
    spans = [n for n in nodes if isinstance(n, StepSpan)]
    assert len(spans) == 4 + 7 + 1  # top-level steps, leaf steps, the parallel's sequence
    # Retry and repeat bodies run once in check mode.
    retry = next(n for n in nodes if isinstance(n, py_trees.decorators.Retry))
    repeat = next(n for n in nodes if isinstance(n, py_trees.decorators.Repeat))
    assert retry.num_failures == 1 and repeat.num_success == 1
    fallback = next(n for n in nodes if isinstance(n, CheckFallback))
    assert isinstance(fallback.decorated, py_trees.composites.Selector)
    assert all(isinstance(c, CheckBranch) for c in fallback.decorated.children)
    scheduled = next(n for n in nodes if isinstance(n, ScheduledParallel))
    assert isinstance(scheduled.decorated, py_trees.composites.Parallel)
    assert len(scheduled.decorated.children) == 2


def test_a_repeated_or_retried_body_is_checked_once(tmp_path: Path):
    path = tmp_path / "task.yaml"
    path.write_text(_TASK)
    report = check_task(path)
    # 2 fallback branches (the first succeeds: 1 checked), 1 retried, 2 repeated, and the
    # parallel's two go steps in two branches (checked one by one, then scheduled).
    assert report.ok, report.problems
    assert report.steps == 1 + 1 + 2 + 2


def test_a_retried_pick_that_fails_is_reported_once():
    report = check_task(FIXTURES / "edge_pick_retry.yaml")
    assert [p.line for p in report.problems] == [12]
    assert report.steps == 3


def test_a_checks_context_has_no_planner_and_no_backend():
    cell = load_cell(CELL / "servo_arm_table.yaml")
    ctx = TaskContext(cell, scene_from_cell(cell))
    with pytest.raises(PlanningError, match="no plan service"):
        ctx.plan_service()
    with pytest.raises(BackendError, match="no backend"):
        ctx.motion_backend()
    dummy: Any = object()
    assert TaskContext(cell, ctx.scene, dummy, dummy).plan_service() is dummy
