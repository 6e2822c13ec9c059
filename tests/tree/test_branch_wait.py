"""A ``wait`` step in a branch of a ``parallel`` delays that branch only
(:meth:`~taskrunner.tree.schedule.MotionSchedule.pause`): on a mock that plays its
motions in time (a fake wall clock, so every run is the same) the other branch's
motions keep their planned starts, the waiting branch's next motion starts the wait
later in planned time, nothing slips, and the record passes the independent space-time
verifier."""

from __future__ import annotations

import textwrap
from pathlib import Path

from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.clock import TaskClock
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import LATE, MotionSchedule

PAIR = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
SPEED = 20.0  # trajectory seconds per (fake) wall second


class _Wall:
    def __init__(self) -> None:
        self.t = 0.0

    def __call__(self) -> float:
        return self.t


class _FakeTimeRunner(Runner):
    """Ticks at 100 Hz of the fake wall clock, with no real sleep."""

    wall: _Wall

    def _pause(self, seconds: float) -> None:
        self.wall.t += 0.01


def _task(tmp_path: Path, pause: str) -> Path:
    path = tmp_path / f"wait{len(pause)}.yaml"
    path.write_text(textwrap.dedent(f"""\
        task: branch_wait
        cell: {PAIR}
        steps:
          - parallel:
              - sequence:
                  - go: {{group: left_arm, to: PickUp}}
                  {pause}
                  - go: {{group: left_arm, to: Candle}}
              - sequence:
                  - go: {{group: right_gripper, to: closed}}
                  - go: {{group: right_gripper, to: open}}
                  - go: {{group: right_gripper, to: closed}}
                  - go: {{group: right_gripper, to: open}}
        """))
    return path


def _run(path: Path, tmp_path: Path) -> _FakeTimeRunner:
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    wall = _Wall()
    backend = MockBackend(names, dict(zip(names, cell.start_state())),
                          MockOptions(speed=SPEED), clock=wall)
    runner = _FakeTimeRunner(spec, cell, backend, InProcessPlanner(),
                             RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    runner.wall, runner.ctx.clock = wall, TaskClock(wall=wall)
    runner.run()
    return runner


def _starts(runner: Runner) -> dict[int, list[float]]:
    """Each branch's motions' planned starts (s), in order."""
    out: dict[int, list[float]] = {}
    for motion in runner.ctx.executed:
        out.setdefault(motion.lane[0][1], []).append(motion.start)
    return out


def _sent(runner: Runner) -> dict[int, list[float]]:
    """Each branch's motions' starts on the run's clock (s), in order."""
    lanes = {m.location: m.lane[0][1] for m in runner.ctx.executed}
    out: dict[int, list[float]] = {}
    for e in runner.record.events:
        if e.kind == "motion":
            out.setdefault(lanes[e.location], []).append(e.data["sent"])
    return out


def test_a_wait_in_a_branch_delays_that_branch_only(tmp_path):
    plain = _run(_task(tmp_path, "- go: {group: left_arm, to: PickUp}"), tmp_path)
    waited = _run(_task(tmp_path, "- wait: {seconds: 1.0}"), tmp_path)
    for runner in (plain, waited):
        assert runner.record.status == "succeeded", runner.record.error
        assert arm_conflicts(runner.scene.robot, runner.record.events) == []
    before, after = _starts(plain), _starts(waited)
    # The right gripper (branch 1) keeps its planned starts, and is sent no later on the
    # run's clock than without the wait: the wait slips nothing.
    assert after[1] == before[1] and len(after[1]) == 4
    assert all(w <= p + LATE for w, p in zip(_sent(waited)[1], _sent(plain)[1]))
    assert waited.ctx.schedule.slip <= plain.ctx.schedule.slip + LATE
    # The left arm's motion after the wait starts 1 s after its first motion ended.
    first = next(m for m in waited.ctx.executed if m.lane[0][1] == 0)
    assert after[0][1] == before[0][1] + 1.0
    assert after[0][1] >= after[0][0] + first.trajectory.duration + 1.0 - 1e-9
    pauses = [e.data for e in waited.record.events if e.kind == "wait"
              and e.location is not None and e.location.endswith(":7")]
    assert [round(d["until"] - d["since"], 6) for d in pauses] == [1.0]


def test_a_pause_moves_its_lanes_next_start_and_no_other():
    schedule = MotionSchedule()
    schedule.new_instance()
    left, right = ((1, 0),), ((1, 1),)
    assert schedule.pause(left, 1.5) == (0.0, 1.5)
    assert schedule.earliest(left) == 1.5 and schedule.earliest(right) == 0.0
    assert schedule.earliest(((1, 0), (2, 1))) == 1.5  # a parallel inside the branch too
    assert schedule.earliest(()) == 1.5  # what follows the parallel follows the wait
    assert schedule.pause(left, 0.5) == (1.5, 2.0)  # a second wait from where it stands


def test_the_check_schedules_a_wait_in_a_branch_as_the_run_does(tmp_path):
    path = _task(tmp_path, "- wait: {seconds: 1.0}")
    report = check_task(path)
    assert report.ok, report.problems
    notes = [n.message for n in report.notes]
    assert f"{path}:7 waits 1 s, from 2.35 s to 3.35 s (its branch only)" in notes, notes
    assert any(n.startswith(f"{path}:8 and {path}:13 move at once from 3.35 s") for n in notes)
