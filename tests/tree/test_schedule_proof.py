"""What ``run-task check`` proves of a ``parallel``'s schedule, against the independent
space-time verifier on the run's record (issue 25): the least clearance between the
arms, its links and steps; the steps moving at once.

The check's number is of the motions it planned; the run's of those it executed. They
agree only where the run's planner takes the check's goal states and paths: the run asks
for the check's remembered choice, keyed by the situation and seed, and a parallel's
branches interleave in the run (another arm elsewhere, other seeds) as they do not in the
check, so inside a parallel the run finds its own goals: the same ones here, for these
examples, which this test pins."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from taskrunner.backends.mock import MockBackend
from taskrunner.cli import main
from taskrunner.collision.spacetime import SpacetimeOptions, _Timeline, _Walk, least_clearance
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tree.expect import record_lanes

TASKS = DATA_ROOT / "tasks"
HANDOFF_OVERLAP = Path(__file__).parent / "fixtures" / "handoff_overlap.yaml"
# The left arm carries a bar past the right arm: the least clearance is the bar's.
HELD_BAR = Path(__file__).parent / "fixtures" / "held_bar_carried.yaml"
MILLIMETRE = 1e-3


def run_on_mock(path: Path, tmp_path: Path) -> Runner:
    from taskrunner.tasks import load_task

    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    runner = Runner(spec, cell, MockBackend(names, dict(zip(names, cell.start_state()))),
                    InProcessPlanner(), RunOptions(seed=0, runs_dir=tmp_path / "runs",
                                                   backend_name="mock"))
    runner.run()
    return runner


def body_distance(scene, lanes, bodies, t: float) -> float:
    """The least exact distance between two bodies (link or object names) of two lanes at
    ``t`` s on the lanes' clock (m)."""
    walk = _Walk(scene, _Timeline(scene, lanes, None), SpacetimeOptions())
    pairs = [p for p in range(walk.pair_count)
             if {walk.name(g) for g in walk.bodies(p)} == set(bodies)]
    assert pairs, bodies
    return float(min(walk.measure(t, pairs)))


@pytest.mark.parametrize("path", [TASKS / "tray_pair.yaml", TASKS / "assembly_panda.yaml",
                                  HANDOFF_OVERLAP, HELD_BAR],
                         ids=["tray_pair", "assembly_panda", "handoff_overlap", "held_bar"])
def test_the_check_s_least_clearance_is_the_verifier_s_on_the_run_s_record(path, tmp_path,
                                                                           capsys):
    # The check as `run-task check --json` prints it (the run that follows in this
    # process plans to the goal states it chose, as `run-task` does after its check).
    assert main(["check", "--json", str(path)]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] is True, report["problems"]
    runner = run_on_mock(path, tmp_path)
    assert runner.record.status == "succeeded"
    recorded = record_lanes(runner.scene.robot, runner.record.events)
    assert len(report["schedules"]) == len(recorded) >= 1
    for schedule, (scene, lanes) in zip(report["schedules"], recorded):
        least = schedule["least_clearance"]
        found = least_clearance(scene, lanes)
        assert least["lower"] <= least["distance"] <= least["lower"] + MILLIMETRE
        assert least["distance"] >= 0.005  # the schedule's clearance
        assert abs(least["distance"] - found.distance) <= MILLIMETRE, (least, found)
        if set(least["links"]) != set(found.bodies or ()):
            # A tie: another pair at the very same least distance (a gripper's two
            # fingers are mirror images): the check's pair is as close on the record.
            assert body_distance(scene, lanes, least["links"], found.time or 0.0) == \
                pytest.approx(found.distance, abs=1e-5)
        # Each link's step then, as the record has it (the instants may differ: a
        # gripper's recorded motion is its controller's, not the check's estimate).
        assert tuple(least["steps"]) == found.motions
        assert schedule["overlaps"]  # the branches do move at once
        assert all(o["end"] > o["start"] for o in schedule["overlaps"])
    if path == HELD_BAR:
        # The bar the left arm holds while it goes back to Candle (line 13), as the
        # record's verifier measures it: the arms' links alone keep 7 cm apart.
        least = report["schedules"][0]["least_clearance"]
        assert least["links"][0] == "bar" and least["steps"][0].endswith(":13")
        assert least["distance"] < 0.06
    if path == HANDOFF_OVERLAP:
        # The right arm's go (line 22) would meet the left arm's pick (line 21): it starts
        # a little later, to pass behind it while it still moves (0.34 s later, where
        # waiting for its end took 2.74 s).
        (wait,) = report["schedules"][0]["waits"]
        assert wait["step"].endswith(":22") and wait["until"] > wait["since"]
        assert wait["reason"].startswith("to pass behind") and ":21" in wait["reason"]
        picks = [m for m in report["schedules"][0]["timeline"] if m["step"].endswith(":21")]
        assert wait["until"] < max(m["end"] for m in picks)
