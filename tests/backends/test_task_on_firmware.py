"""tasks/pick_place.yaml run on the servo backends against the host build of the firmware.

The firmware runs its 80 ms tick 50 times faster than real time. After the run, the
simulated servos must sit at the plan's final joints (through hardware.yaml), and at every
logged tick their angles must lie on the commanded motion (within one degree of a sample
of the trajectories that were sent).
"""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from firmware_host import build_host, read_address_lines, running_host, stop_process
from scipy.spatial import cKDTree

from taskrunner.errors import InputError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.runtime.session import make_backend, servo_calibration
from taskrunner.tasks import load_task

ROOT = Path(__file__).resolve().parents[2]
# Firmware seconds per wall-clock second. At 50 a streaming reply had 50 ms of wall time
# before the servos ran out of points, which a loaded machine missed ("no reply within
# 50 ms"); at 10 the margin is five times that, and a task costs a few seconds more.
SPEEDUP = 10.0


@pytest.fixture(scope="module")
def host_binary() -> Path:
    return build_host()


@pytest.fixture
def firmware(host_binary, tmp_path):
    with running_host(host_binary, SPEEDUP, tmp_path / "ticks.csv") as host:
        yield host.pty, host.url, host.log


def status(url: str) -> dict:
    request = urllib.request.Request(url, data=json.dumps({"cmd": "STATUS"}).encode(),
                                     headers={"Content-Type": "application/json"})
    opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))
    with opener.open(request, timeout=2.0) as response:
        return json.loads(json.loads(response.read())["reply"][3:])


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_pick_place_runs_on_the_firmware_and_the_servos_follow_the_plan(firmware, kind, tmp_path):
    pty, url, log = firmware
    spec = load_task(DATA_ROOT / "tasks" / "pick_place.yaml")
    cell = load_cell(spec.cell)
    backend = make_backend(kind, cell, None, port=pty, url=url, firmware_speedup=SPEEDUP)
    try:
        runner = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(runs_dir=tmp_path / "runs", backend_name=kind))
        record = runner.run()
    finally:
        backend.close()
    assert record.status == "succeeded", record.error
    calibration = servo_calibration(cell)
    names = cell.model.joint_names

    # The servos stopped at the plan's final joints.
    final = calibration.to_servo_degrees(dict(zip(names, runner.scene.state)))
    reported = status(url)
    assert not reported["moving"]
    assert np.abs(np.array(reported["pos"]) - final).max() < 1.0

    # Every tick lies on the commanded motion: near a sample of a trajectory that was sent.
    commanded = []
    for motion in runner.ctx.executed:
        base = dict(zip(motion.scene.state.names, motion.scene.state.positions))
        for values in motion.trajectory.positions:
            base.update(zip(motion.trajectory.names, values))
            commanded.append(calibration.to_servo_degrees(base))
    with log.open(newline="") as stream:
        ticks = np.array([[float(v) for v in row[1:]] for row in list(csv.reader(stream))[1:]])
    assert len(ticks) > 100
    distance, _ = cKDTree(np.array(commanded)).query(ticks)
    assert distance.max() < 1.0, f"a tick strays {distance.max():.2f}° from the commanded motion"


def _start_firmware_sim() -> subprocess.Popen[bytes]:
    """``run-task firmware-sim --speedup 10``, its address lines to be read."""
    import sys

    return subprocess.Popen([sys.executable, "-m", "taskrunner.cli", "firmware-sim",
                             "--speedup", "10"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, cwd=ROOT)


def _only_child(proc: subprocess.Popen[bytes]) -> int:
    """The one child process of ``proc`` (its firmware)."""
    children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children").read_text().split()
    assert len(children) == 1
    return int(children[0])


def test_run_task_firmware_sim_prints_the_pty_then_the_url(host_binary):
    proc = _start_firmware_sim()
    firmware = None
    try:
        pty, url = read_address_lines(proc, timeout=20.0)
        assert pty.startswith("/dev/pts/") and url.startswith("http://127.0.0.1:")
        assert status(url)["status"] == "ok"
        firmware = _only_child(proc)
    finally:
        stop_process(proc, signal.SIGINT)  # to the command alone, as `kill -INT PID` does
    # It passed the SIGINT on: no firmware is left behind.
    assert firmware is not None and _ended(firmware)


def _ended(pid: int, within: float = 20.0) -> bool:
    """Whether process ``pid`` is gone (or a zombie) within ``within`` s."""
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        try:
            state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        except (FileNotFoundError, ProcessLookupError):
            return True
        if state in ("Z", "X"):
            return True
        time.sleep(0.05)
    return False


def test_run_task_firmware_sim_killed_leaves_no_firmware_behind(host_binary):
    """A SIGKILL cannot be passed on: the firmware is sent SIGTERM by the kernel when the
    command ends (it would otherwise keep its pty and port open, orphaned)."""
    proc = _start_firmware_sim()
    firmware = None
    try:
        pty, url = read_address_lines(proc, timeout=20.0)
        assert status(url)["status"] == "ok"
        firmware = _only_child(proc)
        proc.kill()
        proc.wait(10)
        assert _ended(firmware), f"firmware {firmware} outlived its killed command"
    finally:
        stop_process(proc)
        if firmware is not None and not _ended(firmware, 0.0):
            os.kill(firmware, signal.SIGKILL)


PAIR_BOARD = [0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13]  # cells/servo_arm_pair.hardware.yaml


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_handoff_runs_on_one_board_driving_both_arms_of_the_pair(host_binary, kind, tmp_path):
    spec = load_task(DATA_ROOT / "tasks" / "handoff.yaml")
    cell = load_cell(spec.cell)
    assert len(cell.model.instances) == 2
    with running_host(host_binary, SPEEDUP, tmp_path / "ticks.csv", PAIR_BOARD) as host:
        backend = make_backend(kind, cell, None, port=host.pty, url=host.url,
                               firmware_speedup=SPEEDUP)
        try:
            assert backend.version["servos"] == 12
            assert backend.calibration.channels == tuple(PAIR_BOARD)
            runner = Runner(spec, cell, backend, InProcessPlanner(),
                            RunOptions(runs_dir=tmp_path / "runs", backend_name=kind))
            record = runner.run()
        finally:
            backend.close()
        assert record.status == "succeeded", record.error
        final = backend.calibration.to_servo_degrees(
            dict(zip(cell.model.joint_names, runner.scene.state)))
        reported = status(host.url)
    assert not reported["moving"] and reported["crc_errors"] == 0
    assert np.abs(np.array(reported["pos"]) - final).max() < 1.0
    # Both arms moved: each one's servos left the start pose at some tick.
    with (tmp_path / "ticks.csv").open(newline="") as stream:
        ticks = np.array([[float(v) for v in row[1:]] for row in list(csv.reader(stream))[1:]])
    assert np.ptp(ticks[:, :6], axis=0).max() > 10 and np.ptp(ticks[:, 6:], axis=0).max() > 10


def test_a_two_arm_cell_without_a_board_file_is_refused_naming_the_file(tmp_path):
    cell = load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml")
    cell.path = tmp_path / "pair.yaml"  # a copy of the cell without its board file
    with pytest.raises(InputError, match=r"pair\.hardware\.yaml, which does not exist"):
        make_backend("serial", cell, None, port="/dev/null")
