"""A run that has no goal choice remembered from a check (a check in another process, a
physics backend's situation a little off the check's, a Python API run) still does what
the check accepted: the planner's goal state is played on to the end of its step by the
check's rule before the arm moves, and where the rest of the step fails from there, the
run takes the state the check's rule follows (taskrunner.tree.lookahead).

The case: the receiver's grasp of ``handoff_so101`` given a few millimetres off the
shipped one. ``run-task check`` accepts it (its chosen pre-grasp state lets the right
arm back off with the bar), but the run's planner, left to itself, took another
pre-grasp state from which the hand-over fails (the jaws collide, or the right arm's
back-off hits its own shoulder): exit 3.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.runtime.session import run_task_file
from taskrunner.tree import choice, lookahead
from taskrunner.tree.check import check_task

SHIPPED_GRASP = "xyz: [0, 0.005, -0.03]"


def _task(tmp_path: Path, xyz: str) -> Path:
    text = (DATA_ROOT / "tasks" / "handoff_so101.yaml").read_text()
    assert SHIPPED_GRASP in text
    text = text.replace(SHIPPED_GRASP, f"xyz: {xyz}").replace(
        "../robots/cells/so101_pair.yaml", str(DATA_ROOT / "robots" / "cells" / "so101_pair.yaml"))
    path = tmp_path / "handoff_offset.yaml"
    path.write_text(text)
    return path


def _run_without_choices(path: Path, runs: Path) -> tuple[int, str]:
    report = check_task(path, seed=0)
    assert report.ok, [p.message for p in report.problems]
    choice.forget()  # as in a process the check did not run in
    out = io.StringIO()
    code = run_task_file(path, backend="mock", seed=0, runs_dir=runs, worker=False, out=out,
                         check=False, loaded=report)
    return code, out.getvalue()


@pytest.mark.parametrize("xyz", ["[0.005, 0.005, -0.03]", "[0.01, 0.0, -0.035]"])
def test_a_run_without_the_checks_choice_succeeds_where_the_check_accepts(tmp_path, xyz):
    code, log = _run_without_choices(_task(tmp_path, xyz), tmp_path / "runs")
    assert code == 0, log[-3000:]


def test_left_to_its_planner_alone_that_run_fails(tmp_path, monkeypatch):
    # What the look-ahead prevents (so the test above is of it, not of a lucky planner).
    monkeypatch.setattr(lookahead, "rest_fails", lambda leaf, after, end: False)
    code, log = _run_without_choices(_task(tmp_path, "[0.005, 0.005, -0.03]"),
                                     tmp_path / "runs")
    assert code == 3 and "handoff_offset.yaml:23" in log, log[-3000:]  # the handoff step
