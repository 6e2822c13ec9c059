"""Run records a replay can use: every motion's trajectory and the scene it started in,
the first and the final scene, small enough to keep (pick_place < 2 MB)."""

from __future__ import annotations

import json
import threading

import numpy as np
import pytest

import taskrunner
from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.records import load_record
from taskrunner.runtime.replay import replay_of
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task


@pytest.fixture(scope="module")
def pick_place_record(tmp_path_factory):
    runs = tmp_path_factory.mktemp("runs")
    result = taskrunner.run_task("pick_place", runs_dir=runs)
    assert result.status == "succeeded"
    (path,) = runs.glob("*.json")
    return path


def test_a_pick_place_record_holds_every_motion_with_its_trajectory_and_scene(
        pick_place_record):
    record = load_record(pick_place_record)
    replay = replay_of(record)
    planned = [e for e in record.events if e.kind == "planned"]
    # every planned motion that moved was sent, and is in the record with its trajectory
    assert len(replay.motions) >= 8
    assert len(replay.motions) <= len(planned)
    for motion in replay.motions:
        traj = motion.trajectory
        n = len(traj["joints"])
        assert n >= 1 and all(isinstance(j, str) for j in traj["joints"])
        assert len(traj["times"]) >= 2 and traj["times"][0] == 0.0
        assert np.all(np.diff(traj["times"]) > 0)
        assert traj["times"][-1] == pytest.approx(traj["duration"], abs=1e-3)
        assert np.asarray(traj["positions"]).shape == (len(traj["times"]), n)
        assert np.asarray(traj["velocities"]).shape == (len(traj["times"]), n)
        # the scene before the motion: the robot where the trajectory starts, the objects
        scene = motion.scene
        start = [scene["joints"][j] for j in traj["joints"]]
        assert start == pytest.approx(traj["positions"][0], abs=1e-3)
        assert {"table", "cube"} <= {o["name"] for o in scene["objects"]}
        assert motion.executed == pytest.approx(traj["duration"], abs=1e-3)


def test_the_record_shows_the_cube_carried_then_released_where_it_was_placed(
        pick_place_record):
    replay = replay_of(load_record(pick_place_record))
    carried = [m for m in replay.motions
               if any(o["name"] == "cube" and o["attached_to"] for o in m.scene["objects"])]
    assert carried, "some motion starts with the cube attached to the gripper"
    assert replay.first_scene is not None and replay.final_scene is not None
    first = next(o for o in replay.first_scene["objects"] if o["name"] == "cube")
    final = next(o for o in replay.final_scene["objects"] if o["name"] == "cube")
    assert first["attached_to"] is None and final["attached_to"] is None
    assert first["pose"]["xyz"] == pytest.approx([0.19, 0.04, 0.7625], abs=1e-6)
    assert final["pose"]["xyz"][:2] == pytest.approx([0.14, -0.12], abs=5e-3)


def test_a_pick_place_record_is_under_2_mb(pick_place_record):
    size = pick_place_record.stat().st_size
    assert size < 2_000_000, size
    json.loads(pick_place_record.read_text())  # one JSON document


def test_a_cancelled_motion_records_how_far_it_got(tmp_path):
    path = tmp_path / "task.yaml"
    cell_file = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    path.write_text(f"task: t\ncell: {cell_file}\nsteps:\n"
                    "  - go: {group: arm, to: Candle, velocity_scaling: 0.02}\n"
                    "  - go: {group: arm, to: home, velocity_scaling: 0.02}\n")
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = SimBackend(names, dict(zip(names, cell.start_state())), SimOptions(speed=1.0))
    runner = Runner(spec, cell, backend, InProcessPlanner(), RunOptions(runs_dir=tmp_path))
    seen = threading.Event()
    runner.events.subscribe(lambda e: seen.set() if e.kind == "motion" else None)
    thread = threading.Thread(target=runner.run)
    thread.start()
    assert seen.wait(30)
    threading.Event().wait(0.3)
    runner.cancel()
    thread.join(30)
    record = load_record(tmp_path / f"{runner.record.run_id}.json")
    assert record.status == "cancelled"
    replay = replay_of(record)
    (motion,) = replay.motions
    assert motion.executed is not None
    assert 0.0 < motion.executed < motion.trajectory["duration"]
    # the final scene holds the arm where it stopped: on the trajectory, short of its end
    final = [replay.final_scene["joints"][j] for j in motion.trajectory["joints"]]
    end = motion.trajectory["positions"][-1]
    assert not np.allclose(final, end, atol=1e-3)


@pytest.mark.parametrize("times", [[0.0, 0.5, 1.0, 1.00004], [0.0, 0.00003], [0.0, 0.4, 0.40002]])
def test_a_recorded_trajectory_s_times_stay_strictly_increasing_when_rounded(times):
    # A motion cut just after a sample (or stopped at its first) has two samples within
    # the record's 0.1 ms: the record keeps one, and the trajectory reads back.
    from taskrunner.runtime.replay import trajectory_data
    from taskrunner.types import JointTrajectory

    t = np.array(times)
    rows = np.column_stack([t, 2 * t])
    data = trajectory_data(JointTrajectory(("a", "b"), t, rows, np.zeros_like(rows),
                                           np.zeros_like(rows)))
    assert np.all(np.diff(data["times"]) > 0) and len(data["times"]) >= 2
    assert len(data["positions"]) == len(data["times"])
    assert data["positions"][-1] == pytest.approx([times[-1], 2 * times[-1]], abs=1e-5)
    back = JointTrajectory(tuple(data["joints"]), np.asarray(data["times"]),
                           np.asarray(data["positions"]), np.asarray(data["velocities"]),
                           np.zeros((len(data["times"]), 2)))
    assert back.duration == pytest.approx(data["times"][-1])
