"""The check and the run apply one rule to a ``parallel`` whose branches move arms at
once (:mod:`taskrunner.tree.schedule`): waits where a branch's motion would meet
another's arm, a refusal naming both steps where waiting cannot help."""

from __future__ import annotations

from pathlib import Path

import pytest
from schedule_helpers import CANDLE, LEFT, RIGHT, P, line, pair_scene

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import Admission, Blocked, MotionSchedule, concurrent

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
    assert waits and ":17 waits" in waits[0] and "to pass behind" in waits[0] and ":14" in waits[0]
    least = [n for n in notes if n.startswith("least clearance between arms")]
    assert least and "16 motions" in least[0]
    (proof,) = report.schedules
    assert proof.least.distance >= 0.005  # the schedule's clearance, kept
    assert proof.waits and proof.waits[0].step.endswith(":17")


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


# ------------------------------------------------------------------ the rule on its own
@pytest.fixture(scope="module")
def scene():
    return pair_scene()


def test_a_motion_that_would_meet_a_running_one_waits_for_its_end(scene):
    schedule = MotionSchedule()
    schedule.new_instance()
    first = schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:1")
    assert isinstance(first, Admission) and first.start == 0.0 and not first.waits
    # The right arm reaching in and back out while the left one is there: it waits until
    # the left arm's motion has ended, then meets it at rest: held (not admitted).
    found = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:2")
    assert isinstance(found, Blocked)
    assert found.other == "t.yaml:1" and found.lane == LEFT
    assert schedule.refusal(RIGHT, found, "t.yaml:2") is None  # the left branch may move on
    assert schedule.revision == 1  # nothing committed


def test_a_motion_in_the_way_of_an_ended_branch_is_refused_naming_both_steps(scene):
    schedule = MotionSchedule()
    schedule.new_instance(lambda branch: branch != 0)  # the left branch has ended
    schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:1")
    found = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:2")
    assert isinstance(found, Blocked)
    refusal = schedule.refusal(RIGHT, found, "t.yaml:2")
    assert refusal is not None and "t.yaml:1" in refusal and "waiting cannot" in refusal


def test_two_branches_holding_for_each_other_are_a_deadlock(scene):
    schedule = MotionSchedule()
    schedule.new_instance()
    schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:1")
    found = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:2")
    assert isinstance(found, Blocked)
    schedule.holding[LEFT] = RIGHT  # the left branch holds for the right one already
    refusal = schedule.refusal(RIGHT, found, "t.yaml:2")
    assert refusal is not None and "deadlock" in refusal


def test_a_motion_waits_until_the_other_arm_has_left(scene):
    # No delay tried (delays=1): it waits for the end (with delays, it passes behind the
    # arm backing out: test_delays.py).
    schedule = MotionSchedule(delays=1)
    schedule.new_instance()
    schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:1")
    schedule.admit(scene, LEFT, line("left", P, CANDLE), "t.yaml:3")  # and back out, 2-4 s
    found = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:2")
    assert isinstance(found, Admission)
    assert found.waits and found.waits[-1].other == "t.yaml:3"
    assert found.start == pytest.approx(4.0)
    assert found.least >= schedule.clearance


def test_a_stopped_motion_rests_its_arm_where_it_stopped(scene):
    schedule = MotionSchedule()
    schedule.new_instance()
    first = schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:1")
    assert isinstance(first, Admission)
    schedule.stop(first, 0.0)  # cancelled at once: the left arm stays at Candle
    found = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:2")
    assert isinstance(found, Admission) and not found.waits and found.start == 0.0
    schedule.withdraw(found)
    assert schedule.revision == 1
