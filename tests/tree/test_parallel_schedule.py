"""The check and the run apply one rule to a ``parallel`` whose branches move arms at
once (:mod:`taskrunner.tree.schedule`): waits where a branch's motion would meet
another's arm, a refusal naming both steps where waiting cannot help."""

from __future__ import annotations

from pathlib import Path

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import concurrent

FIXTURES = Path(__file__).parent / "fixtures"
PROBE = Path(__file__).parents[1] / "scenarios" / "fixtures" / "meet_in_the_middle.yaml"
BLOCKED = FIXTURES / "parallel_blocked.yaml"


def run(path: Path, tmp_path: Path) -> Runner:
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    runner.run()
    return runner


def test_lanes_are_concurrent_only_in_different_branches_of_one_parallel():
    assert concurrent(((1, 0),), ((1, 1),))
    assert concurrent(((1, 0), (2, 1)), ((1, 1),))
    assert not concurrent(((1, 0),), ((1, 0),))
    assert not concurrent(((1, 0),), ((2, 1),))      # two parallels, one after the other
    assert not concurrent((), ((1, 0),))             # before or after the parallel
    assert not concurrent(((1, 0),), ((1, 0), (3, 1)))  # a parallel inside the branch


def test_check_schedules_the_probe_with_a_wait_and_its_least_clearance():
    report = check_task(PROBE)
    assert report.ok, report.problems
    notes = [n.message for n in report.notes]
    waits = [n for n in notes if " waits " in n]
    assert waits and ":17 waits" in waits[0] and ":14 has moved" in waits[0]
    least = [n for n in notes if n.startswith("arms at least")]
    assert least and "16 motions" in least[0]


def test_check_refuses_an_arm_that_stays_in_the_other_branch_s_way_naming_both_lines():
    report = check_task(BLOCKED)
    assert len(report.problems) == 1
    problem = report.problems[0]
    assert problem.line == 7  # the parallel
    assert f"{BLOCKED}:11: meets the arm of {BLOCKED}:8" in problem.message
    assert "waiting cannot resolve it" in problem.message


def test_a_run_of_the_blocked_task_never_succeeds_with_the_arms_in_each_other(tmp_path):
    # The run's planner may go around the resting arm (the check's straight line cannot):
    # then it succeeds, and its record passes the independent verifier.
    runner = run(BLOCKED, tmp_path)
    misses = arm_conflicts(runner.scene.robot, runner.record.events)
    assert runner.record.status == "failed" or not misses, misses
    motions = [e for e in runner.record.events if e.kind == "motion"]
    assert all("start" in e.data and e.data["lane"] for e in motions)
