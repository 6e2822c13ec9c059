"""``wait_for`` in a run and in the check: a step of one branch starts, on the schedule's
clock, when the named step of another branch has finished (one rule,
:mod:`taskrunner.tree.schedule`)."""

from __future__ import annotations

import textwrap
from pathlib import Path

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import MotionSchedule

ASSEMBLY = DATA_ROOT / "tasks" / "assembly_panda.yaml"  # run on mujoco: tests/backends
PAIR = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
LEFT, RIGHT = ((1, 0),), ((1, 1),)


def run(path: Path, tmp_path: Path) -> Runner:
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    runner.run()
    return runner


def test_a_lane_that_waited_for_a_step_starts_its_motions_no_earlier_than_its_end():
    schedule = MotionSchedule()
    instance = schedule.new_instance()
    assert schedule.earliest(RIGHT) == 0.0
    assert schedule.finish_step(LEFT, "base down") == 0.0  # nothing moved yet: from the start
    schedule.finished[(instance, "base down", "finished")] = 4.5
    schedule.not_before(RIGHT, 4.5)
    assert schedule.earliest(RIGHT) == 4.5
    assert schedule.earliest(((1, 1), (2, 0))) == 4.5  # a parallel inside the branch too
    assert schedule.earliest(LEFT) == 0.0  # not the other branch
    schedule.not_before(RIGHT, 2.0)  # an earlier wait does not undo a later one
    assert schedule.earliest(RIGHT) == 4.5


def test_the_check_schedules_the_stacking_once_the_base_is_released():
    report = check_task(ASSEMBLY)
    assert report.ok, report.problems
    notes = [n.message for n in report.notes]
    assert any(f"{ASSEMBLY}:25 waits until step 'base down' has released its object, at " in n
               for n in notes), notes


def test_a_step_waiting_for_a_step_its_branch_skipped_fails_at_its_line(tmp_path):
    # The fallback's first branch succeeds (the arm is at Candle already), so the step
    # named 'reach' never runs: the right arm's step cannot start, and says why.
    path = tmp_path / "skipped.yaml"
    path.write_text(textwrap.dedent(f"""\
        task: skipped
        cell: {PAIR}
        steps:
          - parallel:
              - fallback:
                  - go: {{group: left_arm, to: Candle}}
                  - go: {{group: left_arm, to: HandOff, name: reach}}
              - sequence:
                  - go: {{group: right_arm, to: HandOff, wait_for: {{step: reach}}}}
        """))
    runner = run(path, tmp_path)
    assert runner.record.status == "failed"
    assert f"{path}:9: 'wait_for': the branch of step 'reach' ended without it finishing" \
        in runner.record.error


def test_the_stacking_starts_once_the_base_is_released_while_its_arm_retreats(tmp_path):
    # assembly_panda waits for 'base down' until: released: the right arm's place starts
    # when the left gripper has opened, before the left arm's retreat has ended, and the
    # space-time admission keeps the two arms apart (the independent verifier agrees).
    runner = run(ASSEMBLY, tmp_path)
    assert runner.record.status == "succeeded", runner.record.error
    assert arm_conflicts(runner.scene.robot, runner.record.events) == []
    by_node = {m.node: m for m in runner.ctx.executed}
    opened = by_node["base down: open"]
    retreat = by_node["base down: retreat"]
    first = min((m for m in runner.ctx.executed if m.location == f"{ASSEMBLY}:25"),
                key=lambda m: m.start)
    released = opened.start + opened.trajectory.duration
    assert released - 1e-9 <= first.start < retreat.start + retreat.trajectory.duration
    waits = [e.data for e in runner.record.events if e.kind == "wait"
             and e.data.get("step") == "base down" and "until" in e.data]
    assert [d["moment"] for d in waits] == ["released"]
    assert abs(waits[0]["until"] - released) < 1e-6
