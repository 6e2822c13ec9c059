"""A held object in a ``parallel``: ``run-task check`` admits each motion holding what
its arm holds then, as the run does, so that the two agree where a carried object (not
the arm's links) meets the other arm. Before, the check verified a parallel's motions
with the objects attached as the parallel started and passed this task, which the run
refused."""

from __future__ import annotations

import json
from pathlib import Path

from taskrunner.backends.mock import MockBackend
from taskrunner.cli import main
from taskrunner.kinds import ExitCode
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts

BLOCKED = Path(__file__).parent / "fixtures" / "held_bar_blocked.yaml"


def test_check_refuses_the_held_bar_the_run_refuses(tmp_path, capsys):
    assert main(["check", "--json", str(BLOCKED)]) == ExitCode.INVALID
    report = json.loads(capsys.readouterr().out)
    (problem,) = report["problems"]
    # The left arm's go to HandOff (line 15), holding the bar, meets the right arm
    # resting at HandOff (line 16): waiting cannot help.
    assert f"{BLOCKED}:15: meets the arm of {BLOCKED}:16" in problem["message"]
    assert f"bar ({BLOCKED}:15) and right_" in problem["message"]
    assert "waiting cannot resolve it" in problem["message"]

    spec = load_task(BLOCKED, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    runner = Runner(spec, cell, MockBackend(names, dict(zip(names, cell.start_state()))),
                    InProcessPlanner(), RunOptions(seed=0, runs_dir=tmp_path / "runs",
                                                   backend_name="mock"))
    runner.run()
    record = runner.record
    assert record.status == "failed"
    assert record.error is not None
    assert f"{BLOCKED}:15: meets the arm of {BLOCKED}:16" in record.error
    assert f"bar ({BLOCKED}:15) and right_" in record.error
    # What did move kept apart, the bar included.
    assert arm_conflicts(runner.scene.robot, record.events) == []
