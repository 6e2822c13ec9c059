"""A motion that would meet another arm's running motion starts a little later, to pass
behind it (a delay), before it waits for that motion's end (:mod:`taskrunner.tree.schedule`):
the start chosen is verified, earlier ones tried are not, and runs keep the arms apart."""

from __future__ import annotations

from pathlib import Path

import pytest
from schedule_helpers import CANDLE, LEFT, RIGHT, P, line, pair_scene

from taskrunner.backends.mock import MockBackend
from taskrunner.collision.spacetime import Lane, SpacetimeOptions, TimedMotion, verify_lanes
from taskrunner.kinds import WaitKind
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import CLEARANCE, Admission, MotionSchedule, lanes_of

HANDOFF_OVERLAP = Path(__file__).parent / "fixtures" / "handoff_overlap.yaml"


@pytest.fixture(scope="module")
def scene():
    return pair_scene()


def left_reach(scene, delays: int) -> tuple[MotionSchedule, Admission]:
    """The right arm reaches to the middle (0-2 s) and backs out (2-4 s); then the left
    arm's reach there is admitted."""
    schedule = MotionSchedule(delays=delays)
    schedule.new_instance()
    schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:1")
    schedule.admit(scene, RIGHT, line("right", P, CANDLE), "t.yaml:2")
    left = schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:3")
    assert isinstance(left, Admission)
    return schedule, left


def test_a_motion_passes_behind_the_arm_backing_out_instead_of_waiting_for_its_end(scene):
    _, waited = left_reach(scene, delays=1)
    assert waited.start == pytest.approx(4.0)  # after the right arm has backed out
    assert [w.kind for w in waited.waits] == [WaitKind.UNTIL_END, WaitKind.UNTIL_END]
    schedule, left = left_reach(scene, delays=4)
    # It meets the reach (0-2 s): after it; then it would meet the arm backing out (2-4 s)
    # and starts a little later instead, behind it.
    assert [w.kind for w in left.waits] == [WaitKind.UNTIL_END, WaitKind.DELAY]
    delay = left.waits[-1]
    assert delay.since == pytest.approx(2.0) and 2.0 < left.start == delay.until < 4.0
    assert "to pass behind t.yaml:2" in delay.describe("t.yaml:3")
    # The start committed keeps the clearance at every instant (the verifier, on its own,
    # every measurement exact) ...
    lanes = lanes_of(schedule.committed)
    found = verify_lanes(scene, lanes, options=SpacetimeOptions(clearance=CLEARANCE,
                                                               exact=True))
    assert found.ok, found.conflict
    # ... and the last start the search tried before it, an eighth of the way less, does
    # not: the delay is the search's earliest.
    earlier = left.start - 0.5 / 4
    moved = [Lane(lane.name, tuple(TimedMotion(m.trajectory, earlier, m.label)
                                   if m.label == "t.yaml:3" else m for m in lane.motions))
             for lane in lanes]
    assert verify_lanes(scene, moved, options=SpacetimeOptions(clearance=CLEARANCE)).conflict


def test_a_run_s_delay_is_an_event_and_its_arms_never_meet(tmp_path):
    spec = load_task(HANDOFF_OVERLAP, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    runner = Runner(spec, cell, MockBackend(names, dict(zip(names, cell.start_state()))),
                    InProcessPlanner(), RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    record = runner.run()
    assert record.status == "succeeded", record.error
    (wait,) = [e for e in record.events if e.kind == "wait"]
    assert wait.data["resolution"] == "delay"
    assert 0.0 < wait.data["until"] - wait.data["since"] < 1.0  # waiting for the end: 2.7 s
    assert "to pass behind" in wait.message
    assert arm_conflicts(runner.scene.robot, record.events) == []
