"""Two arms of servo_arm_pair moving at once on one board (the host build of the
firmware, run 10x faster than real time): one stream, one firmware clock (issue 25). Over
HTTP (the serial backend streams through the same code; opening the host's pty waits
2 s for a boot banner)."""

from __future__ import annotations

import csv
import time
from pathlib import Path

import numpy as np
import pytest
from firmware_host import build_host, running_host

from taskrunner.errors import ExecutionCancelledError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.runtime.session import make_backend
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts, record_lanes
from taskrunner.types import JointTrajectory

SPEEDUP = 10.0  # at 50x a loaded machine misses a streaming reply (50 ms of wall time)
PAIR_BOARD = [0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13]  # cells/servo_arm_pair.hardware.yaml
CELL = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
CANDLE = np.array([1.5708, -1.5708, -1.5708, -1.5708, -1.5708])
OFFSET = np.array([0.3, 0.2, -0.25, 0.15, 0.1])


@pytest.fixture(scope="module")
def host_binary() -> Path:
    return build_host()


def arm(side: str) -> tuple[str, ...]:
    return tuple(f"{side}_Revolute {i}" for i in range(1, 6))


def line(side: str, start: np.ndarray, end: np.ndarray, duration: float) -> JointTrajectory:
    t = np.linspace(0.0, duration, 101)
    positions = start + np.outer(t / duration, end - start)
    zeros = np.zeros_like(positions)
    return JointTrajectory(arm(side), t, positions, zeros, zeros)


def ticks(path: Path) -> np.ndarray:
    with path.open(newline="") as stream:
        return np.array([[float(v) for v in row[1:]] for row in list(csv.reader(stream))[1:]])


def test_a_second_arm_s_trajectory_joins_the_stream_and_both_end_where_planned(
        host_binary, tmp_path):
    cell = load_cell(CELL)
    with running_host(host_binary, SPEEDUP, tmp_path / "ticks.csv", PAIR_BOARD) as host:
        backend = make_backend("http", cell, None, port=host.pty, url=host.url,
                               firmware_speedup=SPEEDUP)
        try:
            left = backend.execute(line("left", CANDLE, CANDLE + OFFSET, 3.0))
            deadline = time.monotonic() + 2.0
            while left.progress < 0.5 and time.monotonic() < deadline:
                time.sleep(0.002)
            right = backend.execute(line("right", CANDLE, CANDLE - OFFSET, 2.0))
            assert right.progress == 0.0 and not left.done()
            assert left.wait(5.0).status == "succeeded"
            assert right.wait(5.0).status == "succeeded"
            state = dict(zip(backend.joint_names, backend.joint_state().positions))
        finally:
            backend.close()
    np.testing.assert_allclose([state[n] for n in arm("left")], CANDLE + OFFSET, atol=0.02)
    np.testing.assert_allclose([state[n] for n in arm("right")], CANDLE - OFFSET, atol=0.02)
    rows = ticks(tmp_path / "ticks.csv")
    moving = np.abs(np.diff(rows, axis=0)) > 1e-6
    # Ticks where servos of both arms moved: the two trajectories played at once.
    assert np.any(moving[:, :6].any(axis=1) & moving[:, 6:].any(axis=1))


def test_cancelling_one_arm_stops_it_and_the_other_goes_on_to_its_end(host_binary, tmp_path):
    cell = load_cell(CELL)
    with running_host(host_binary, SPEEDUP, tmp_path / "ticks.csv", PAIR_BOARD) as host:
        backend = make_backend("http", cell, None, port=host.pty, url=host.url,
                               firmware_speedup=SPEEDUP)
        try:
            left = backend.execute(line("left", CANDLE, CANDLE + OFFSET, 3.0))
            right = backend.execute(line("right", CANDLE, CANDLE - OFFSET, 3.0))
            deadline = time.monotonic() + 2.0
            while left.progress < 1.0 and time.monotonic() < deadline:
                time.sleep(0.002)
            left.cancel()
            with pytest.raises(ExecutionCancelledError):
                left.wait(1.0)
            stopped = dict(zip(backend.joint_names, backend.joint_state().positions))
            assert right.wait(5.0).status == "succeeded"
            state = dict(zip(backend.joint_names, backend.joint_state().positions))
        finally:
            backend.close()
    at_stop = np.array([stopped[n] for n in arm("left")])
    assert np.abs(at_stop - CANDLE).max() > 0.05 and np.abs(at_stop - CANDLE - OFFSET).max() > 0.05
    np.testing.assert_allclose([state[n] for n in arm("left")], at_stop, atol=0.02)
    np.testing.assert_allclose([state[n] for n in arm("right")], CANDLE - OFFSET, atol=0.02)


def test_tray_pair_runs_both_arms_at_once_on_one_board_and_they_never_touch(
        host_binary, tmp_path):
    spec = load_task(DATA_ROOT / "tasks" / "tray_pair.yaml")
    cell = load_cell(spec.cell)
    with running_host(host_binary, SPEEDUP, tmp_path / "ticks.csv", PAIR_BOARD) as host:
        backend = make_backend("http", cell, None, port=host.pty, url=host.url,
                               firmware_speedup=SPEEDUP)
        try:
            runner = Runner(spec, cell, backend, InProcessPlanner(),
                            RunOptions(runs_dir=tmp_path / "runs", backend_name="http"))
            record = runner.run()
        finally:
            backend.close()
    assert record.status == "succeeded", record.error
    assert arm_conflicts(cell.model, record.events) == []  # includes collision_free in time
    # The branches' motions overlapped on the run's clock (as really started) ...
    ((_, lanes),) = record_lanes(cell.model, record.events)
    spans = [[(m.start, m.end) for m in lane.motions] for lane in lanes]
    together = sum(max(0.0, min(a1, b1) - max(a0, b0))
                   for a0, a1 in spans[0] for b0, b1 in spans[1])
    assert together > 2.0
    # ... and on the firmware's: ticks where servos of both arms moved.
    rows = ticks(tmp_path / "ticks.csv")
    moving = np.abs(np.diff(rows, axis=0)) > 1e-6
    assert (moving[:, :6].any(axis=1) & moving[:, 6:].any(axis=1)).sum() > 10
