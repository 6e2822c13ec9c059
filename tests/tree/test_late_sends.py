"""Motions sent later than the schedule admitted them, and arms that lag their schedule
(:mod:`taskrunner.tree.schedule`): replayed on one fake clock, so the lateness is
injected, not hoped for, and every run is the same.

A loaded machine running the simulator fast shows two things: ``execute`` returns after
the simulator has already played part of the motion, and a motion starts well after its
admitted start. The backend here does either on the sends the test names; the run's
record must then still pass the independent space-time verifier, and no motion may run
where it was not verified.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from schedule_helpers import CANDLE, LEFT, RIGHT, P, line, pair_scene

from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.collision.spacetime import Lane, TimedMotion, verify_lanes
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import scene_from_cell
from taskrunner.tasks import load_task
from taskrunner.tree.clock import TaskClock
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import LATE, Admission, MotionSchedule

TRAY_PAIR = DATA_ROOT / "tasks" / "tray_pair.yaml"
SPEED = 20.0  # trajectory seconds per (fake) wall second: one 10 ms tick is 0.2 s of task time


class _Wall:
    """The fake wall clock every part of the run reads (s)."""

    def __init__(self) -> None:
        self.t = 0.0

    def __call__(self) -> float:
        return self.t


class _LoadedMock(MockBackend):
    """A mock that plays motions at ``SPEED`` on the fake wall clock, and on the sends
    numbered in ``ahead`` returns only after ``delay`` s of wall time (the motion already
    played meanwhile), on those in ``late`` starts the motion only after ``delay``."""

    def __init__(self, names, start, wall: _Wall, ahead=(), late=(), delay=0.0) -> None:
        super().__init__(names, start, MockOptions(speed=SPEED), clock=wall)
        self.wall, self.ahead, self.late, self.delay = wall, set(ahead), set(late), delay
        self.sends = 0

    def execute(self, trajectory):  # type: ignore[no-untyped-def]
        self.sends += 1
        if self.sends in self.late:
            self.wall.t += self.delay
        handle = super().execute(trajectory)
        if self.sends in self.ahead:
            self.wall.t += self.delay
        return handle


class _FakeTimeRunner(Runner):
    """Ticks at 100 Hz of the fake wall clock, with no real sleep."""

    wall: _Wall

    def _pause(self, seconds: float) -> None:
        self.wall.t += 0.01


def run_loaded(tmp_path: Path, **faults) -> _FakeTimeRunner:
    spec = load_task(TRAY_PAIR, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    wall = _Wall()
    backend = _LoadedMock(names, dict(zip(names, cell.start_state())), wall, **faults)
    runner = _FakeTimeRunner(spec, cell, backend, InProcessPlanner(),
                             RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    runner.wall = wall
    runner.ctx.clock = TaskClock(wall=wall)
    runner.run()
    return runner


def motions(runner: Runner) -> list:
    return [e for e in runner.record.events if e.kind == "motion"]


def lanes_in_order(runner: Runner) -> None:
    """Per lane, every motion recorded as starting after the one before it ended."""
    by_lane: dict[tuple, list[tuple[float, float]]] = {}
    for e in motions(runner):
        duration = float(e.data["trajectory"]["times"][-1])
        by_lane.setdefault(tuple(map(tuple, e.data["lane"])), []).append(
            (float(e.data["sent"]), duration))
    for lane, timed in by_lane.items():
        for (s0, d0), (s1, _) in zip(timed, timed[1:]):
            assert s1 >= s0 + d0 - 1e-3, (lane, s0, d0, s1)


def test_a_send_that_returns_after_the_simulator_played_on_keeps_its_real_start(tmp_path):
    # Every third send returns 25 ms (0.5 s of task time) after the motion started: its
    # record used to start it 0.5 s late, before the next motion of its arm ended.
    runner = run_loaded(tmp_path, ahead=range(3, 40, 3), delay=0.025)
    assert runner.record.status == "succeeded", runner.record.error
    lanes_in_order(runner)
    assert arm_conflicts(runner.scene.robot, runner.record.events) == []


def test_a_motion_started_late_is_verified_at_its_real_start_never_sent_unverified(tmp_path):
    # Every second send starts 0.6 s of task time after it was admitted (a loaded
    # machine): each is verified again where it really started, and stopped there at
    # once if that meets the other arm; the record passes the independent verifier.
    runner = run_loaded(tmp_path, late=range(2, 40, 2), delay=0.03)
    assert runner.record.status == "succeeded", runner.record.error
    sent = motions(runner)
    late = [e for e in sent if e.data["sent"] - e.data["start"] > LATE]
    assert late, "the injected delays made no motion late"
    lanes_in_order(runner)
    assert arm_conflicts(runner.scene.robot, runner.record.events) == []


# ------------------------------------------------------------------ the rule on its own
@pytest.fixture(scope="module")
def scene():
    return pair_scene()


def in_and_out(scene) -> tuple[MotionSchedule, Admission, Admission, Admission]:
    """The right arm reaches to the middle (0-2 s) and backs out (2-4 s); the left arm's
    reach there waits until it has left (4 s): no delays tried (``delays=1``), so that
    these tests' motions meet where they say (a delay would send it behind the backing
    arm, see test_delays.py)."""
    schedule = MotionSchedule(delays=1)
    schedule.new_instance()
    reach = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:1")
    back = schedule.admit(scene, RIGHT, line("right", P, CANDLE), "t.yaml:2")
    left = schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:3")
    assert isinstance(reach, Admission) and isinstance(back, Admission)
    assert isinstance(left, Admission) and left.start == pytest.approx(4.0)
    return schedule, reach, back, left


def test_a_motion_sent_within_late_of_its_start_is_on_time_and_not_verified_again(scene):
    schedule, reach, _, _ = in_and_out(scene)
    sent, conflict = schedule.confirm(scene, reach, LATE / 2)
    assert conflict is None and sent.entry is not None and sent.entry.sent
    assert sent.start == 0.0 and sent.entry.offset == LATE / 2
    assert schedule.slip == 0.0 and schedule.retractions == 0


def test_a_motion_sent_late_slips_the_whole_schedule_and_keeps_the_plan(scene):
    schedule, reach, back, left = in_and_out(scene)
    schedule.confirm(scene, reach, 0.0)
    # Backing out 2 s late: the left arm's reach, not sent yet, goes 2 s later too, so
    # the two keep their planned places against each other (they would meet otherwise).
    late, conflict = schedule.confirm(scene, back, 4.0)
    assert conflict is None and schedule.slip == pytest.approx(2.0)
    assert schedule.slips == [("t.yaml:2", 2.0, pytest.approx(2.0))]
    assert late.start == 2.0 and late.entry is not None and late.entry.offset == 2.0
    assert not schedule.stale(left) and schedule.due(left) == pytest.approx(6.0)


def test_a_motion_running_when_the_schedule_slipped_is_verified_against_the_next(scene):
    # The right arm reaches in (0-2 s) and backs out (2-4 s); the left arm reaches in
    # from 4 s, its plan a second late: the schedule slips 1 s, the right arm's back-out
    # sent before the slip runs a second earlier against it: still clear.
    schedule, reach, back, left = in_and_out(scene)
    schedule.confirm(scene, reach, 0.0)
    back, _ = schedule.confirm(scene, back, 2.0)
    assert schedule.slip_to(left, 5.0) == pytest.approx(1.0)
    assert schedule.clear_to_send(scene, left, 5.0) is None


def test_another_arm_overdue_holds_a_motion_until_its_branch_admits_it_again(scene):
    schedule, reach, back, _ = in_and_out(scene)
    schedule.confirm(scene, reach, 0.0)
    assert schedule.overdue(LEFT, 2.0 + LATE / 2) is None
    assert schedule.overdue(LEFT, 2.5) is back.entry  # due at 2 s, not sent
    schedule.withdraw(back)
    assert schedule.overdue(LEFT, 2.5) is None


def test_a_lagging_arm_stops_the_motion_that_relied_on_its_schedule(scene):
    schedule, reach, back, left = in_and_out(scene)
    schedule.confirm(scene, reach, 0.0)
    back, _ = schedule.confirm(scene, back, 2.0, progress=lambda: 0.3)
    left, _ = schedule.confirm(scene, left, 4.0)
    # At 4.5 s the right arm has played 0.3 s of its 2 s back-out, due by 4 s: 1.7 s behind.
    found = schedule.lagging(LEFT, 4.5, 0.05)
    assert found is not None and found[0] is back.entry and found[1] == pytest.approx(1.7)
    schedule.retime(back, 4.5 - 0.3)
    assert schedule.stale(left)
    left, conflict = schedule.recheck(scene, left, 4.5)
    assert conflict is not None and conflict.motions[0] is not None  # stop the left arm
    assert not schedule.stale(left)


def test_a_running_motion_clear_of_a_slightly_lagging_arm_goes_on(scene):
    schedule, reach, back, left = in_and_out(scene)
    schedule.confirm(scene, reach, 0.0)
    back, _ = schedule.confirm(scene, back, 2.0)
    left, _ = schedule.confirm(scene, left, 5.0)  # the left arm started a second later
    schedule.retime(back, 2.3)  # the right arm 0.3 s behind: out by 4.3 s
    _, conflict = schedule.recheck(scene, left, 5.0)
    assert conflict is None


class _LaggingMock(_LoadedMock):
    """The right arm plays its motions at half the speed it was sent them at (a physics
    arm that cannot follow): it falls behind its schedule while the left keeps to it."""

    def _refresh(self) -> None:
        now = self._now()
        for execution in list(self._executions):
            slow = 0.5 if execution.trajectory.names[0].startswith("right") else 1.0
            self._step(execution, (now - execution.start_time) * SPEED * slow)


def test_a_lagging_arm_makes_the_cell_slower_and_the_schedule_follows_it(tmp_path):
    spec = load_task(TRAY_PAIR, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    wall = _Wall()
    backend = _LaggingMock(names, dict(zip(names, cell.start_state())), wall)
    runner = _FakeTimeRunner(spec, cell, backend, InProcessPlanner(),
                             RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    runner.wall, runner.ctx.clock = wall, TaskClock(wall=wall)
    runner.run()
    assert runner.record.status == "succeeded", runner.record.error
    events = runner.record.events
    lagged = [e for e in events if e.kind == "message" and "behind its schedule" in e.message]
    assert lagged and all(e.location.endswith(("tray_pair.yaml:21", "tray_pair.yaml:22"))
                          for e in lagged)
    # The left arm's motions go as much later as the right arm's lag (the schedule slips).
    assert any(e.kind == "wait" and e.data.get("slip", 0.0) > 0.5 for e in events)
    # The schedule, retimed to where the arms were (each motion at its offset), keeps
    # them apart all along.
    schedule = runner.ctx.schedule
    by_instance: dict[int, dict[tuple, list]] = {}
    for c in schedule.committed:
        if c.lane:
            real = TimedMotion(c.motion.trajectory, c.motion.start + c.offset, c.motion.label)
            by_instance.setdefault(c.lane[0][0], {}).setdefault(c.lane, []).append(real)
    for lanes in by_instance.values():
        found = verify_lanes(scene_from_cell(cell),  # the robots alone: links against links
                             [Lane(str(k), tuple(m)) for k, m in lanes.items()])
        assert found.conflict is None, found.conflict.describe()
