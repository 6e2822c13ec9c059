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
import select
import shutil
import signal
import subprocess
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import cKDTree

from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import RunOptions, Runner
from taskrunner.runtime.session import make_backend, servo_calibration
from taskrunner.tasks import load_task

ROOT = Path(__file__).resolve().parents[2]
FIRMWARE = ROOT / "firmware"
SPEEDUP = 50.0


@pytest.fixture(scope="module")
def host_binary() -> Path:
    missing = [tool for tool in ("make", "g++") if shutil.which(tool) is None]
    if missing:
        pytest.skip(f"the firmware host build needs {' and '.join(missing)}, not on PATH")
    built = subprocess.run(["make", "--no-print-directory", "-j2", "-C", str(FIRMWARE), "host"],
                           capture_output=True, text=True, timeout=300, check=False)
    assert built.returncode == 0, built.stdout + built.stderr
    return FIRMWARE / "build" / "taskrunner-servo-host"


@pytest.fixture
def firmware(host_binary, tmp_path):
    log = tmp_path / "ticks.csv"
    proc = subprocess.Popen([str(host_binary), "--speedup", str(SPEEDUP), "--log", str(log)],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    try:
        data, deadline = b"", time.monotonic() + 5.0
        while data.count(b"\n") < 2:
            ready, _, _ = select.select([proc.stdout], [], [], max(0.0, deadline - time.monotonic()))
            assert ready, f"host firmware printed {data!r} in 5 s"
            chunk = os.read(proc.stdout.fileno(), 4096)
            assert chunk, "host firmware exited early"
            data += chunk
        pty, url = data.decode().splitlines()[:2]
        yield pty, url, log
    finally:
        proc.terminate()
        try:
            proc.wait(5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)


def status(url: str) -> dict:
    request = urllib.request.Request(url, data=json.dumps({"cmd": "STATUS"}).encode(),
                                     headers={"Content-Type": "application/json"})
    opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))
    with opener.open(request, timeout=2.0) as response:
        return json.loads(json.loads(response.read())["reply"][3:])


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_pick_place_runs_on_the_firmware_and_the_servos_follow_the_plan(firmware, kind, tmp_path):
    pty, url, log = firmware
    spec = load_task(ROOT / "tasks" / "pick_place.yaml")
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


def test_run_task_firmware_sim_prints_the_pty_then_the_url(host_binary):
    import sys

    proc = subprocess.Popen([sys.executable, "-m", "taskrunner.cli", "firmware-sim",
                             "--speedup", "10"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, cwd=ROOT)
    try:
        data, deadline = b"", time.monotonic() + 20.0
        while data.count(b"\n") < 2:
            ready, _, _ = select.select([proc.stdout], [], [], max(0.0, deadline - time.monotonic()))
            assert ready, f"printed {data!r}"
            chunk = os.read(proc.stdout.fileno(), 4096)
            assert chunk, "exited early"
            data += chunk
        pty, url = data.decode().splitlines()[:2]
        assert pty.startswith("/dev/pts/") and url.startswith("http://127.0.0.1:")
        assert status(url)["status"] == "ok"
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)
