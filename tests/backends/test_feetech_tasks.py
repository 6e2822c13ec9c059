"""The SO-101's tasks on the feetech backend over ``run-task bus-sim``, end to end.

Each emulated bus is a ``run-task bus-sim`` process (its own interpreter: the run's
collision checks never hold up the servos' replies), its servos calibrated as the LeRobot
file says and resting folded, moving ``SPEEDUP`` times faster than real time (the
backend's time scale the same) to keep the motions short. The streaming rate is measured
on the bus's side, from the emulator's log of the SYNC WRITEs it received, in the servos'
own time; tracking error per joint is read from the run's record.
"""

from __future__ import annotations

import io
import json
import re
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path

import numpy as np
import pytest

from taskrunner.backends.feetech import FeetechBus
from taskrunner.kinds import ExitCode
from taskrunner.resources import DATA_ROOT
from taskrunner.runtime.session import run_task_file

FIXTURE = Path(__file__).parent / "fixtures" / "so101_lerobot_calibration.json"
SPEEDUP = 2.0
GOALS = 41  # the goal block's first address (Acceleration, Goal_Position, …)
# goal writes before the fault: go ready (1.07 s), the gripper opened (0.39 s), then the
# move to the pre-grasp under way
INJECT_AFTER = 110
ROBOT = ["shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll", "gripper"]


@contextmanager
def bus_sims(*buses: tuple[str, Path]) -> Iterator[list[tuple[subprocess.Popen[str], str]]]:
    """``run-task bus-sim`` processes (calibration files, log file), started at once, and
    their ptys."""
    procs = [subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "bus-sim", "--calibration", calibration,
         "--speedup", str(SPEEDUP), "--log", str(log)],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True) for calibration, log in buses]
    try:
        found = []
        for proc in procs:
            assert proc.stdout is not None
            port = proc.stdout.readline().strip()
            assert port.startswith("/dev/"), f"bus-sim printed {port!r}"
            found.append((proc, port))
        yield found
    finally:
        for proc in procs:
            try:
                assert proc.stdin is not None
                proc.stdin.write("quit\n")
                proc.stdin.close()
                proc.wait(10)
            except (OSError, subprocess.TimeoutExpired):
                proc.kill()
                proc.wait()


@contextmanager
def bus_sim(calibration: str, log: Path) -> Iterator[tuple[subprocess.Popen[str], str]]:
    """One ``run-task bus-sim`` process and its pty."""
    with bus_sims((calibration, log)) as found:
        yield found[0]


def goal_writes(log: Path) -> list[tuple[float, tuple[int, ...]]]:
    """(model time, IDs) of the goal SYNC WRITEs in a bus-sim log."""
    found = []
    for line in log.read_text().splitlines():
        clock, _, address, ids = line.split()
        if int(address) == GOALS:
            found.append((float(clock), tuple(int(i) for i in ids.split(","))))
    return found


def goal_write_times(log: Path) -> np.ndarray:
    """``time.monotonic()`` (the machine's clock, the same in every process) of the goal
    SYNC WRITEs in a bus-sim log."""
    return np.array([float(line.split()[1]) for line in log.read_text().splitlines()
                     if int(line.split()[2]) == GOALS])


def streaming_rate(log: Path) -> float:
    """The rate goals were streamed at, in the servos' time (Hz): one over the median gap
    between goal writes within a motion (gaps over 0.1 s are between motions)."""
    times = np.array([t for t, _ in goal_writes(log)])
    gaps = np.diff(times)
    gaps = gaps[gaps < 0.1]
    assert len(gaps) > 50, f"only {len(gaps)} gaps between goal writes"
    return float(1.0 / np.median(gaps))


class ReferenceCadence:
    """A bare cycle at the backend's rate (60 Hz in the servos' time), run in this process
    beside a run: each tick sends a bus-sized message to another process (``cat``) and
    waits for it back, as the backend's cycle waits for the servos' replies from the
    emulator's process. The rate it keeps is what the machine allows such a cycle at that
    moment, the reference a streaming rate is compared with (a loaded host stretches every
    sleep and every round trip, the backend's and this one's alike)."""

    def __init__(self) -> None:
        self._halt = threading.Event()
        self._gaps: list[float] = []
        self._echo = subprocess.Popen(["cat"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      bufsize=0)
        self._thread = threading.Thread(target=self._loop, daemon=True)

    def _loop(self) -> None:
        assert self._echo.stdin is not None and self._echo.stdout is not None
        message = bytes(64)
        period = 1.0 / (60.0 * SPEEDUP)  # wall s, as the backend's cycle
        last = next_cycle = time.monotonic()
        while not self._halt.is_set():
            self._echo.stdin.write(message)
            received = 0
            while received < len(message):
                received += len(self._echo.stdout.read(len(message) - received))
            next_cycle += period
            delay = next_cycle - time.monotonic()
            if delay < 0:
                next_cycle, delay = time.monotonic(), 0.0
            self._halt.wait(delay)
            now = time.monotonic()
            self._gaps.append(now - last)
            last = now

    def __enter__(self) -> ReferenceCadence:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._halt.set()
        self._thread.join(5)
        self._echo.kill()
        self._echo.wait()

    def rate(self) -> float:
        """The rate the loop kept, in the servos' time (Hz): one over its median gap."""
        assert len(self._gaps) > 50
        return float(1.0 / (np.median(self._gaps) * SPEEDUP))


def assert_streamed_at_50_hz(rate: float, reference: ReferenceCadence, what: str) -> None:
    """At least 50 Hz on a machine that lets a bare cycle keep 60 Hz; on a loaded one, at
    least the same share (5/6) of what the reference cycle kept in the same minutes."""
    kept = reference.rate()
    assert rate >= 50.0 * min(1.0, kept / 60.0), (
        f"{what}: goals streamed at {rate:.1f} Hz; a bare 60 Hz cycle kept {kept:.1f} Hz")


def pair_calibrations(tmp_path: Path) -> tuple[Path, Path]:
    """The fixture as the left arm's (IDs 1-6) and the right arm's re-IDed to 7-12."""
    left = tmp_path / "left.json"
    left.write_text(FIXTURE.read_text())
    entries = json.loads(FIXTURE.read_text())
    for entry in entries.values():
        entry["id"] += 6
    right = tmp_path / "right_7_12.json"
    right.write_text(json.dumps(entries, indent=4))
    return left, right


def hardware_file(tmp_path: Path, buses: dict[str, str], robots: dict[str, tuple[str, list[int], Path]]
                  ) -> Path:
    lines = ["protocol: feetech", "buses:"]
    # a loaded test host wakes the reader late now and then: a lenient reply timeout (the
    # fault test's flag is read in the next reply, whatever the timeout)
    lines += [f"  {name}: {{port: {port}, reply_timeout: 0.5}}" for name, port in buses.items()]
    lines.append("robots:")
    lines += [f"  {name}: {{bus: {bus}, ids: {ids}, calibration: {cal}}}"
              for name, (bus, ids, cal) in robots.items()]
    path = tmp_path / "cell.hardware.yaml"
    path.write_text("\n".join(lines) + "\n")
    return path


def run(task: str, hardware: Path, tmp_path: Path) -> tuple[int, dict, str]:
    out = io.StringIO()
    code = run_task_file(DATA_ROOT / "tasks" / f"{task}.yaml", backend="feetech",
                         hardware=str(hardware), firmware_speedup=SPEEDUP,
                         runs_dir=tmp_path / "runs", check=False, out=out)
    record = json.loads(next((tmp_path / "runs").glob("*.json")).read_text())
    return code, record, out.getvalue()


def tracking_by_joint(record: dict) -> dict[str, tuple[float, float]]:
    """The largest tracking error and the largest RMS of one motion (rad) of each joint
    over the run's motions, from the record's node events."""
    found: dict[str, tuple[float, float]] = {}
    for event in record["events"]:
        executed = (event.get("data") or {}).get("executed") or {}
        for joint, t in (executed.get("tracking") or {}).items():
            assert t["rms"] <= t["max"] + 1e-9 and t["samples"] > 0
            largest, rms = found.get(joint, (0.0, 0.0))
            found[joint] = (max(largest, t["max"]), max(rms, t["rms"]))
    return found


def assert_tracked(tracking: dict[str, tuple[float, float]], joints: set[str]) -> None:
    """Every joint reported; the servos followed: RMS within 6° (the error is the goal sent
    a cycle before minus the position read: about a cycle of motion, the backlash on a
    reversal; a late cycle on a loaded host adds a peak, not an RMS), every error under
    the backend's fault limit; a joint that did not move reads 0."""
    assert set(tracking) == joints
    assert all(rms < 0.1 and largest < 0.35 for largest, rms in tracking.values()), tracking
    assert sum(largest > 0.0 for largest, _ in tracking.values()) >= len(joints) - 2, tracking


@pytest.mark.parametrize("layout", ["two_buses", "one_bus"])
def test_handoff_so101_drives_both_arms_on_one_clock(tmp_path: Path, layout: str) -> None:
    left, right = pair_calibrations(tmp_path)
    with ExitStack() as stack:
        if layout == "two_buses":
            logs = [tmp_path / "left.log", tmp_path / "right.log"]
            (_, left_port), (_, right_port) = stack.enter_context(
                bus_sims((str(left), logs[0]), (str(FIXTURE), logs[1])))
            hardware = hardware_file(
                tmp_path, {"left": left_port, "right": right_port},
                {"left": ("left", [1, 2, 3, 4, 5, 6], left),
                 "right": ("right", [1, 2, 3, 4, 5, 6], FIXTURE)})
        else:
            logs = [tmp_path / "both.log"]
            _, port = stack.enter_context(bus_sim(f"{left},{right}", logs[0]))
            hardware = hardware_file(
                tmp_path, {"both": port},
                {"left": ("both", [1, 2, 3, 4, 5, 6], left),
                 "right": ("both", [7, 8, 9, 10, 11, 12], right)})
        with ReferenceCadence() as reference:
            code, record, out = run("handoff_so101", hardware, tmp_path)
    assert code == ExitCode.OK, out
    assert record["status"] == "succeeded"
    for log in logs:
        assert_streamed_at_50_hz(streaming_rate(log), reference, log.name)
    assert_tracked(tracking_by_joint(record),
                   {f"{side}_{j}" for side in ("left", "right") for j in ROBOT})
    if layout == "one_bus":
        # one sync write carries all twelve goals
        assert {ids for _, ids in goal_writes(logs[0])} == {tuple(range(1, 13))}
    else:
        # one clock: while both arms move (the first step, in parallel), each cycle writes
        # both buses, one right after the other
        left, right = goal_write_times(logs[0]), goal_write_times(logs[1])
        # the first 40 cycles of the right arm's first motion (its first write holds the arm
        # at connect; the step moves both arms in one 1.07 s motion: 64 cycles or more, a
        # late cycle on a loaded host makes more, never fewer: counted by cycles, not by the
        # wall clock)
        start = int(np.argmax(np.diff(right) < 0.05))
        first = right[start:start + 40]
        after = np.searchsorted(left, first).clip(1, len(left) - 1)
        nearest = np.minimum(np.abs(left[after] - first), np.abs(left[after - 1] - first))
        period = 1.0 / (60.0 * SPEEDUP)  # the backend's cycle, wall-clock s
        assert len(first) == 40 and np.median(nearest) < period / 2, nearest


def test_pick_place_so101_on_one_bus_streams_then_a_fault_stops_the_arm_at_the_step(
        tmp_path: Path) -> None:
    """pick_place_so101 on one bus; the elbow's servo overheats once the arm has streamed
    a few motions: the run ends with exit code 4 at the step's file:line, the arm held."""
    log = tmp_path / "bus.log"
    with bus_sim(str(FIXTURE), log) as (proc, port):
        hardware = hardware_file(tmp_path, {"arm": port},
                                 {"arm": ("arm", [1, 2, 3, 4, 5, 6], FIXTURE)})
        assert proc.stdin is not None
        inject = proc.stdin

        def overheat_while_moving() -> None:
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                if log.exists() and len(goal_writes(log)) > INJECT_AFTER:
                    inject.write("inject overheat 3\n")
                    inject.flush()
                    return
                time.sleep(0.005)

        injector = threading.Thread(target=overheat_while_moving, daemon=True)
        injector.start()
        with ReferenceCadence() as reference:
            code, record, out = run("pick_place_so101", hardware, tmp_path)
        injector.join(5)
        written = goal_writes(log)
        # the arm stands still: every servo where it was, the others' goals where they are
        bus = FeetechBus(port, reply_timeout=0.5)
        try:
            before = bus.read_states(list(range(1, 7)))
            time.sleep(0.2)
            still = bus.read_states(list(range(1, 7)))
            goals = {i: bus.read(i, "Goal_Position") for i in range(1, 7)}
        finally:
            bus.close()
        after = goal_writes(log)
    # streamed at 50 Hz or more, every goal write for the six servos
    assert_streamed_at_50_hz(streaming_rate(log), reference, log.name)
    assert {ids for _, ids in written} == {(1, 2, 3, 4, 5, 6)}
    # the motions that ended before the fault report their tracking error per joint
    assert_tracked(tracking_by_joint(record), set(ROBOT))
    # the fault ends the run at the step that was moving, with the execution's exit code
    assert code == ExitCode.EXECUTION, out
    assert record["status"] == "failed"
    error = record["error"]
    task = DATA_ROOT / "tasks" / "pick_place_so101.yaml"
    assert error.startswith(f"{task}:"), error
    line = int(error[len(f"{task}:"):].split(":")[0])
    assert task.read_text().splitlines()[line - 1].lstrip().startswith("- "), line  # a step
    assert "overheat" in error and "'elbow_flex'" in error and "stopped: hold" in error, error
    # nothing streamed after the run ended, nothing moves, the others hold where they are
    assert after == written
    assert all(abs(still[i].position - before[i].position) <= 2 for i in before)
    assert all(abs(goals[i] - still[i].position) <= 3 for i in before if i != 3), goals
    assert still[3].flags == ["overheat"]


def test_pick_place_so101_on_one_bus_places_the_cube_from_read_back_states(tmp_path: Path) -> None:
    """pick_place_so101 over one emulated bus to its end: the expectations met (the cube's
    pose at the drop spot, released, on the table; the arm at rest), tracking reported
    per joint. The motions after a settle start from the servos' read-back positions, up
    to a tick (2π/4096 rad) off the goal sent, plus the backlash; the place still puts
    the cube within 2 mm and 1° (earlier, from such a start, the 5-joint arm's goal
    choice set it down 13° off)."""
    log = tmp_path / "bus.log"
    with bus_sim(str(FIXTURE), log) as (_, port):
        hardware = hardware_file(tmp_path, {"arm": port},
                                 {"arm": ("arm", [1, 2, 3, 4, 5, 6], FIXTURE)})
        code, record, out = run("pick_place_so101", hardware, tmp_path)
    assert code == ExitCode.OK, out
    assert record["status"] == "succeeded"
    met = [e["data"]["expectations"] for e in record["events"]
           if (e.get("data") or {}).get("expectations")]
    assert met and met[-1]["met"] and not met[-1]["failures"], met
    # (its streaming rate on one bus: the fault test above)
    assert {ids for _, ids in goal_writes(log)} == {(1, 2, 3, 4, 5, 6)}
    assert_tracked(tracking_by_joint(record), set(ROBOT))
    # started from read-back states: some motion's start is off the last goal sent
    offsets, previous = [], None
    for event in record["events"]:
        if event["kind"] != "motion":
            continue
        trajectory, scene = event["data"]["trajectory"], event["data"]["scene"]["joints"]
        if previous is not None:
            offsets += [abs(scene[j] - previous[j]) for j in trajectory["joints"] if j in previous]
        previous = dict(zip(trajectory["joints"], trajectory["positions"][-1]))
    assert max(offsets) > 0.5 * 2 * np.pi / 4096, offsets
    placed = [re.search(r"error ([\d.]+) mm, ([\d.]+)°", e["message"])
              for e in record["events"]
              if e["node"] == "place cube: check outcome" and "at its target" in e["message"]]
    assert len(placed) == 1 and placed[0] is not None, out
    assert float(placed[0][1]) <= 2.0 and float(placed[0][2]) <= 1.0, placed[0][0]
