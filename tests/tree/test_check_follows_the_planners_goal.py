"""``run-task check`` follows, at each goal of several states, the one the run's planner
goes to when left to itself (the first whose straight line is free), so that later steps
are judged from where a run stands (taskrunner.tree.leafcheck).

The case: the receiver's grasp of ``handoff_so101`` given a few millimetres off the
shipped one. Following the first collision-free pre-grasp of the pick instead, the
check had the left arm take the bar rolled another way than any run does; from there
the hand-over's back-off or the set-down was blocked, and the check refused 12 of 36
offsets whose run succeeds. Now it accepts them, and a run that follows the check's
choices succeeds (a check pass still means a run pass).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.runtime.session import run_task_file
from taskrunner.tree import leafcheck
from taskrunner.tree.check import check_task

SHIPPED_GRASP = "xyz: [0, 0.005, -0.03]"
# Receiver grasp offsets (m, in the bar's frame) the check refused while the run succeeded.
REFUSED_BEFORE = ["[-0.005, 0.0, -0.035]", "[-0.005, 0.005, -0.025]", "[0.0, 0.0, -0.025]",
                  "[0.01, 0.005, -0.025]"]


def _task(tmp_path: Path, xyz: str) -> Path:
    text = (DATA_ROOT / "tasks" / "handoff_so101.yaml").read_text()
    assert SHIPPED_GRASP in text
    text = text.replace(SHIPPED_GRASP, f"xyz: {xyz}").replace(
        "../robots/cells/so101_pair.yaml", str(DATA_ROOT / "robots" / "cells" / "so101_pair.yaml"))
    path = tmp_path / "handoff_offset.yaml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("xyz", REFUSED_BEFORE)
def test_the_check_accepts_a_handover_offset_the_run_does_and_the_run_follows(tmp_path, xyz):
    path = _task(tmp_path, xyz)
    report = check_task(path, seed=0)
    assert report.ok, [f"{p.line}: {p.message}" for p in report.problems]
    out = io.StringIO()
    code = run_task_file(path, backend="mock", seed=0, runs_dir=tmp_path / "runs", worker=False,
                         out=out, check=False, loaded=report, speed=1000.0)
    assert code == 0, out.getvalue()[-3000:]


def test_following_the_first_collision_free_state_the_check_refused_it(tmp_path, monkeypatch):
    # What the planner's order changes (so the test above is of it, not of a lucky seed).
    monkeypatch.setattr(leafcheck, "_planners_first", lambda states, start, options, scene: states)
    report = check_task(_task(tmp_path, REFUSED_BEFORE[0]), seed=0)
    assert [(p.line, "place bar: descend blocked" in p.message) for p in report.problems] \
        == [(29, True)], [f"{p.line}: {p.message}" for p in report.problems]
