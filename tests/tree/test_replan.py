"""A motion put off long, waiting for another arm's motion to end, is planned again around
that arm and the sooner of the two is admitted (:mod:`taskrunner.tree.replan`); the
schedule finds an admission without committing it, then commits it while unchanged."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
from schedule_helpers import CANDLE, LEFT, RIGHT, P, line, pair_scene

from taskrunner.collision.spacetime import Lane, TimedMotion, lanes_state
from taskrunner.kinds import WaitKind
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.replan import REPLAN_GAIN
from taskrunner.tree.schedule import Admission, Blocked, MotionSchedule

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scenarios"))
from test_parallel_generated import run_generated

# Generated two-arm tasks whose right-arm reach (a planned motion) would wait for the left
# arm's motion to end, and ends sooner planned again with that arm where they would meet.
REPLANNED = 27


@pytest.fixture(scope="module")
def scene():
    return pair_scene()


def test_an_admission_found_is_committed_only_while_the_schedule_is_unchanged(scene):
    # The right arm reaches to the middle and backs out; the left arm's reach there waits.
    schedule = MotionSchedule()
    schedule.new_instance()
    schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:1")
    schedule.admit(scene, RIGHT, line("right", P, CANDLE), "t.yaml:2")
    found = schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:3", commit=False)
    assert isinstance(found, Admission) and found.waits
    assert len(schedule.committed) == 2 and not schedule.waits  # nothing committed yet
    assert schedule.commit(found)
    assert schedule.committed[-1] is found.entry
    assert [w for _, w in schedule.waits] == list(found.waits)
    assert not schedule.commit(found)  # once
    # Found, then the schedule changes: it must be admitted again, not committed as found.
    stale = schedule.admit(scene, LEFT, line("left", P, CANDLE), "t.yaml:4", commit=False)
    assert isinstance(stale, Admission)
    schedule.admit(scene, RIGHT, line("right", CANDLE, CANDLE), "t.yaml:5")
    assert not schedule.commit(stale)
    assert all(c is not stale.entry for c in schedule.committed)


def test_finding_an_admission_changes_nothing_even_where_the_motion_is_blocked(scene):
    # The right arm ends its last motion over the middle and rests there: the left arm's
    # reach there is blocked (it holds until that branch moves on).
    schedule = MotionSchedule()
    schedule.new_instance()
    schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:1")
    changes = schedule.changes
    found = schedule.admit(scene, LEFT, line("left", CANDLE, P), "t.yaml:2", commit=False)
    assert isinstance(found, Blocked)
    assert schedule.changes == changes and len(schedule.committed) == 1
    assert not schedule.stops and not schedule.waits


def test_lanes_state_puts_each_lane_where_its_motions_have_it(scene):
    reach, back = line("right", CANDLE, P), line("right", P, CANDLE)
    lanes = [Lane("right", (TimedMotion(reach, 1.0), TimedMotion(back, 4.0)))]
    model = scene.robot
    columns = model.indices(reach.names)
    at = {t: lanes_state(scene, lanes, t)[columns] for t in (0.0, 2.0, 3.5, 5.0, 9.0)}
    assert np.allclose(at[0.0], CANDLE)  # before its first motion: where it starts
    assert np.allclose(at[2.0], np.add(CANDLE, 0.5 * np.subtract(P, CANDLE)))
    assert np.allclose(at[3.5], P)  # between its motions: where the first ended
    assert np.allclose(at[5.0], np.add(P, 0.5 * np.subtract(CANDLE, P)))
    assert np.allclose(at[9.0], CANDLE)
    left = model.indices(tuple(f"left_Revolute {i}" for i in range(1, 6)))
    assert np.array_equal(lanes_state(scene, lanes, 2.0)[left], scene.state[left])


def test_a_generated_task_ends_sooner_with_its_motion_planned_again(tmp_path):
    replanned = run_generated(REPLANNED, tmp_path)
    waited = run_generated(REPLANNED, tmp_path, replans=False)
    for runner in (replanned, waited):
        assert runner.record.status == "succeeded", runner.record.error
        assert not arm_conflicts(runner.scene.robot, runner.record.events)
    waits = [e for e in replanned.record.events if e.kind == "wait"]
    again = [e for e in waits if e.data.get("resolution") == WaitKind.REPLAN.value]
    assert len(again) == 1 and again[0].data["sooner"] >= REPLAN_GAIN
    assert "planned again around" in again[0].message
    # Its leaf planned twice; the same leaf in the run without re-planning waits until
    # the other arm's motion ends.
    leaf = again[0].node
    assert sum(e.kind == "planned" and e.node == leaf for e in replanned.record.events) == 2
    assert any(e.kind == "wait" and e.node == leaf
               and e.data.get("resolution") == WaitKind.UNTIL_END.value
               for e in waited.record.events)

    def end(runner):
        return max(float(e.data["start"]) + float(e.data["trajectory"]["duration"])
                   for e in runner.record.events if e.kind == "motion")

    assert end(replanned) <= end(waited) - REPLAN_GAIN


def test_the_check_notes_that_a_run_plans_a_long_waiting_motion_again(tmp_path, capsys):
    # The check does not search: it shows the first plan's wait, and says what a run does.
    from test_parallel_generated import generated_task

    from taskrunner.cli import main

    path = tmp_path / "generated_25.yaml"
    path.write_text(generated_task(25), encoding="utf-8")
    assert main(["check", "--json", str(path)]) == 0
    notes = [n["message"] for n in json.loads(capsys.readouterr().out)["notes"]]
    waits = [n for n in notes if "has moved" in n]
    assert waits and any(n.endswith("a run first plans it again around the other arm, and "
                                    "takes that motion where it ends sooner") for n in notes)


def test_running_beside_is_whether_another_arm_s_sent_motion_still_plays(scene):
    # What a motion held at its start asks before it is admitted again from where it
    # rests: an arm that still moves may clear its way; one at rest will not.
    schedule = MotionSchedule()
    schedule.new_instance()
    right = schedule.admit(scene, RIGHT, line("right", CANDLE, P), "t.yaml:1")
    left = schedule.admit(scene, LEFT, line("left", CANDLE, CANDLE), "t.yaml:2")
    assert isinstance(right, Admission) and isinstance(left, Admission)
    assert not schedule.running_beside(LEFT)  # admitted, not sent
    played = [0.5]
    schedule.confirm(scene, right, 0.0, progress=lambda: played[0])
    assert schedule.running_beside(LEFT) and not schedule.running_beside(RIGHT)
    played[0] = right.entry.motion.trajectory.duration  # played to its end: at rest
    assert not schedule.running_beside(LEFT)


def test_the_record_s_lanes_cut_a_motion_where_a_stop_and_go_stopped_it(scene):
    # A motion stopped 0.5 s in (its wait event's `stopped`) and its rest sent at 0.6 s:
    # the arm moved the first only up to there; replayed in full, the two would overlap.
    from taskrunner.runtime.events import RunEvent
    from taskrunner.runtime.replay import trajectory_data
    from taskrunner.tree.expect import record_lanes

    reach = line("right", CANDLE, P)
    rest = line("right", P, P, duration=1.0)
    def motion(seq: int, sent: float, trajectory) -> RunEvent:
        return RunEvent(seq, sent, "motion", "reach", "t.yaml:1", None, "", {
            "lane": [[1, 1]], "sent": sent, "start": sent,
            "trajectory": trajectory_data(trajectory)})

    events = [motion(1, 0.1, reach),
              RunEvent(2, 0.6, "wait", "reach", "t.yaml:1", None, "stops",
                       {"hold": True, "stopped": 0.5}),
              motion(3, 0.6, rest)]
    (_, lanes), = record_lanes(scene.robot, events)
    first, second = lanes[0].motions
    assert first.trajectory.duration == pytest.approx(0.5) and first.end <= second.start
    assert np.allclose(first.trajectory.positions[-1],
                       np.add(CANDLE, 0.25 * np.subtract(P, CANDLE)), atol=1e-4)
    assert second.trajectory.duration == pytest.approx(1.0)
