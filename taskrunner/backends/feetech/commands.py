"""What ``run-task bus-sim`` and ``run-task hw … --robot so101`` do (the CLI only parses).

``bus-sim`` prints the pty's path, then reads commands on standard input until it ends
(or a signal): ``inject KIND [ID]`` (:data:`~.emulator.FAULTS`), ``clear``, ``quit``.
With ``--calibration FILE[,FILE]`` its servos are calibrated arms (the files' IDs and
homing offsets) resting folded; two files: two arms on one bus (IDs 1-6 and 7-12).
"""

from __future__ import annotations

import contextlib
import sys
import threading
from collections.abc import Callable
from pathlib import Path
from typing import TextIO

from taskrunner.backends.feetech.bench import calibrate_arm, jog_joint, set_torque, status_lines
from taskrunner.backends.feetech.bus import FeetechBus
from taskrunner.backends.feetech.calibration import (
    SO101_MOTORS,
    LeRobotCalibration,
    Motor,
    load_lerobot_calibration,
)
from taskrunner.backends.feetech.emulator import (
    FAULTS,
    SO101_FOLDED,
    BusEmulator,
    ServoModel,
    calibrated_servos,
    so101_servos,
)
from taskrunner.errors import ArgumentError, InputError, UnknownNameError

__all__ = ["ARMS", "LEROBOT_CALIBRATION_HINT", "arm_motors", "run_bus_sim", "run_hw"]

ARMS: dict[str, tuple[Motor, ...]] = {"so101": SO101_MOTORS}
LEROBOT_CALIBRATION_HINT = ("LeRobot keeps it in ~/.cache/huggingface/lerobot/calibration/"
                            "robots/so101_follower/<id>.json")


def arm_motors(robot: str) -> tuple[Motor, ...]:
    """The motors of a known bus-servo arm.

    Raises:
        UnknownNameError: not a known arm.
    """
    if robot not in ARMS:
        raise UnknownNameError("bus-servo arm", robot, list(ARMS))
    return ARMS[robot]


def calibrated_arms(files: str) -> list[ServoModel]:
    """The servos of SO-101s calibrated as LeRobot's files (comma-separated) say, folded.

    Raises:
        InputError: a file that is missing or invalid, a motor missing from it, or an ID
            that two files give.
    """
    servos: list[ServoModel] = []
    for k, name in enumerate(f.strip() for f in files.split(",") if f.strip()):
        entries = load_lerobot_calibration(name)
        prefix = f"arm{k}_"
        missing = [m.joint for m in SO101_MOTORS if m.joint not in entries]
        if missing:
            raise InputError(f"no calibration for motor(s) {missing} (an SO-101's file names "
                             f"{[m.joint for m in SO101_MOTORS]})", name)
        motors = tuple(Motor(prefix + m.joint, entries[m.joint].id, m.mode, m.lower, m.upper)
                       for m in SO101_MOTORS)
        taken = {s.servo_id for s in servos}
        twice = sorted(taken & {m.servo_id for m in motors})
        if twice:
            raise InputError(f"IDs {twice} are another file's too: two arms on one bus need "
                             "IDs apart (1-6 and 7-12)", name)
        calibration = LeRobotCalibration(
            motors, {prefix + j: e for j, e in entries.items()}, Path(name))
        servos += calibrated_servos(calibration, {prefix + j: q for j, q in SO101_FOLDED.items()})
    return servos


def run_bus_sim(seed: int = 0, out: TextIO | None = None, inp: TextIO | None = None,
                calibration: str | None = None, speedup: float = 1.0,
                log: str | None = None) -> int:
    """Serve the SO-101's six servos on a pty until standard input ends or ``quit``
    (``calibration``: see :func:`calibrated_arms`; else uncalibrated, near the middle;
    ``speedup``: the servos' time scale; ``log``: a file that gets a line per SYNC WRITE).
    """
    out = out or sys.stdout
    inp = inp or sys.stdin
    servos = calibrated_arms(calibration) if calibration else so101_servos(seed)
    with contextlib.ExitStack() as stack:
        stream = stack.enter_context(open(log, "a", encoding="utf-8")) if log else None
        emulator = stack.enter_context(BusEmulator(servos, speedup, stream))
        return _serve_commands(emulator, out, inp)


def _serve_commands(emulator: BusEmulator, out: TextIO, inp: TextIO) -> int:
    """Print the pty's path, then answer commands on ``inp`` until it ends or ``quit``."""
    print(emulator.port, file=out, flush=True)
    print(f"# STS bus: servos {sorted(emulator.servos)} at 1 Mbaud; commands: "
          f"inject {'|'.join(FAULTS)} [ID], clear, quit", file=out, flush=True)
    for line in inp:
        words = line.split()
        if not words:
            continue
        try:
            if words[0] == "quit":
                break
            if words[0] == "clear":
                emulator.clear()
            elif words[0] == "inject" and len(words) in (2, 3):
                emulator.inject(words[1], int(words[2]) if len(words) == 3 else None)
            else:
                raise ArgumentError(f"unknown command {line.strip()!r}")
            print(f"ok {line.strip()}", file=out, flush=True)
        except (ArgumentError, ValueError) as exc:
            print(f"err {exc}", file=out, flush=True)
    return 0


def _stdin_line_seen() -> Callable[[], bool]:
    """A ``range_done`` for a terminal: True once a line was read on standard input."""
    seen = threading.Event()

    def read() -> None:
        sys.stdin.readline()
        seen.set()

    threading.Thread(target=read, daemon=True).start()
    return seen.is_set


def run_hw(action: str, port: str, robot: str = "so101", calibration: str | None = None,
           joint: str | None = None, amount: str | None = None,
           ask: Callable[[str], str] = input, range_done: Callable[[], bool] | None = None,
           say: Callable[[str], None] = print) -> int:
    """``hw status | jog JOINT DEGREES | torque on|off | calibrate`` on a bus-servo arm.

    Raises:
        InputError: a missing or bad argument (names it), or no calibration file where one
            is needed.
        BusFaultError: the port or a servo does not answer.
    """
    motors = arm_motors(robot)
    if action == "calibrate" and not calibration:
        raise InputError(f"hw calibrate --robot {robot} needs --calibration FILE (the file "
                         f"to write; {LEROBOT_CALIBRATION_HINT})")
    if action == "jog" and not calibration:
        raise InputError(f"hw jog --robot {robot} needs --calibration FILE "
                         f"({LEROBOT_CALIBRATION_HINT})")
    arm = None
    if calibration and action != "calibrate":
        arm = LeRobotCalibration(motors, load_lerobot_calibration(calibration),
                                 Path(calibration))
    bus = FeetechBus(port)
    try:
        if action == "calibrate":
            assert calibration is not None
            calibrate_arm(bus, motors, calibration, wait_enter=ask,
                          range_done=range_done or _stdin_line_seen(), say=say)
            return 0
        if action == "torque":
            if amount is not None or joint not in ("on", "off"):
                raise InputError(f"torque takes 'on' or 'off' (got {joint!r})")
            set_torque(bus, motors, joint == "on")
            say(f"torque {joint} on servos {', '.join(str(m.servo_id) for m in motors)}")
        elif action == "jog":
            assert arm is not None
            try:
                degrees = float(amount) if amount is not None else None
            except ValueError:
                degrees = None
            if joint is None or degrees is None:
                raise InputError(f"jog needs JOINT and DEGREES, e.g. run-task hw jog elbow_flex "
                                 f"5 --robot {robot} (got {joint!r} {amount!r})")
            goal_q, goal = jog_joint(bus, arm, joint, degrees)
            say(f"jog {joint!r} {degrees:+.1f}° → {goal_q:+.4f} rad ({goal} ticks)")
        elif action != "status":
            raise InputError(f"'{action}' is not a bench action for a bus-servo arm "
                             "(status, jog, torque, calibrate)")
        for line in status_lines(bus, motors, arm):
            say(line)
    finally:
        bus.close()
    return 0
