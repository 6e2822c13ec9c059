"""``run-task firmware-sim`` and ``hw``: the host build of the ESP32 firmware, and bench
helpers for the servo arm (status, home, jog, calibrate)."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, cast

from taskrunner.commands.robots import load_named_cell
from taskrunner.errors import InputError
from taskrunner.kinds import ExitCode

if TYPE_CHECKING:

    pass

__all__ = ["cmd_bus_sim", "cmd_firmware_sim", "cmd_hw"]


def cmd_firmware_sim(args: argparse.Namespace) -> int:
    """Build the host firmware, start it, pass its two address lines through.

    SIGTERM and SIGINT are passed on to the firmware process (Ctrl-C also reaches it from
    the terminal); this command ends when it has (killing it after 5 s more of a SIGINT),
    and the firmware is sent SIGTERM when this command ends in any other way (killed):
    no firmware is left behind. Exit code: the firmware's,
    128 + N when a signal N ended it.
    """
    import signal
    import subprocess

    from taskrunner.backends.host_firmware import build_host_firmware
    from taskrunner.processes import ending_with_parent

    command = [str(build_host_firmware()), "--speedup", str(args.speedup)]
    if args.log:
        command += ["--log", args.log]
    if args.channels:
        command += ["--channels", args.channels]
    started: list[subprocess.Popen[bytes]] = []
    pending: list[int] = []

    def forward(signum: int, frame: object) -> None:
        if not started:
            pending.append(signum)  # before Popen returned: passed on right after
        elif started[0].poll() is None:
            started[0].send_signal(signum)

    # Installed before the firmware starts: it prints its address lines at once, and a
    # SIGTERM sent as soon as they appear must find the handler in place.
    previous = signal.signal(signal.SIGTERM, forward)
    process: subprocess.Popen[bytes] | None = None
    try:
        try:
            # Ended with this command however it ends (a SIGKILL included): no firmware
            # is left holding its pty and port.
            process = subprocess.Popen(command, preexec_fn=ending_with_parent())
            started.append(process)
            for signum in pending:
                process.send_signal(signum)
            code = process.wait()
        except KeyboardInterrupt:
            # From a terminal the firmware had its own SIGINT; sent to this process
            # alone (`kill -INT`), it had not: passed on, then a moment to end.
            if process is None:
                raise  # before it started: it ends with this command
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
            try:
                code = process.wait(5)
            except subprocess.TimeoutExpired:
                process.kill()
                code = process.wait()
    finally:
        signal.signal(signal.SIGTERM, previous)
    return 128 - code if code < 0 else code


def _ask_terminal_ready() -> None:
    """Refuse an interactive helper before anything moves when standard input is closed."""
    if sys.stdin is None or sys.stdin.closed:
        _ask_terminal("")


def _ask_terminal(prompt: str) -> str:
    """``input`` for an interactive helper; no input (closed, or ended) is an InputError."""
    if sys.stdin is None or sys.stdin.closed:
        raise InputError("hw calibrate asks a question for each joint: run it in a terminal "
                         "(standard input is closed)")
    try:
        return input(prompt)
    except EOFError:
        raise InputError("hw calibrate asks a question for each joint: run it in a terminal "
                         "(standard input ended before every answer was given; nothing "
                         "was written)") from None


def cmd_bus_sim(args: argparse.Namespace) -> int:
    """Serve the SO-101's Feetech bus on a pty until standard input ends."""
    from taskrunner.backends.feetech.commands import run_bus_sim

    return run_bus_sim(seed=args.seed, calibration=args.calibration, speedup=args.speedup,
                       log=args.log)


def cmd_hw(args: argparse.Namespace) -> int:
    """Bench helpers: the firmware's status, homing, jogging one joint, calibrating."""
    import math

    if getattr(args, "robot", None):  # an arm on a Feetech bus (the SO-101), not the ESP32
        from taskrunner.backends.feetech.commands import run_hw

        if not args.port:
            raise InputError(f"hw --robot {args.robot} needs --port (the bus adapter's serial "
                             "port, or run-task bus-sim's pty)")
        if args.action == "calibrate":
            _ask_terminal_ready()
        return run_hw(args.action, args.port, args.robot, args.calibration, args.joint,
                      None if args.degrees is None else str(args.degrees), ask=_ask_terminal)
    if args.action == "torque":
        raise InputError("hw torque is for a bus-servo arm: add --robot so101 --port P")

    from taskrunner.backends import ServoBackend
    from taskrunner.runtime.session import make_backend

    if args.action == "calibrate" and (sys.stdin is None or sys.stdin.closed):
        _ask_terminal("")  # refuses before anything is connected or moved
    cell = load_named_cell(args.cell, args.load_options)
    kind = "http" if args.url else "serial"
    # serial and http backends are servo backends
    backend = cast(ServoBackend, make_backend(kind, cell, None, port=args.port, url=args.url,
                                              firmware_speedup=args.firmware_speedup))
    try:
        if args.action == "calibrate":
            from taskrunner.backends.calibrate import calibrate_servos

            robot = cell.model.instances[0]
            assert robot.hardware_path is not None  # make_backend checked it
            calibrate_servos(backend, robot.hardware_path,
                             [args.joint] if args.joint else None, ask=_ask_terminal)
            return ExitCode.OK
        if args.action == "home":
            backend.command("HOME")
        elif args.action == "jog":
            if args.joint is None or args.degrees is None:
                raise InputError("jog needs JOINT and DEGREES (run-task hw jog 'Revolute 1' 10)")
            calibration = backend.calibration
            servo = calibration.servo_of(args.joint)
            state = backend.joint_state().as_dict()
            state[args.joint] += math.radians(args.degrees)
            degrees = calibration.to_servo_degrees(state)
            print(f"jog {args.joint!r} {args.degrees:+.1f}° (servo {servo}) → "
                  f"MOVE:{','.join(f'{d:.2f}' for d in degrees)}")
            backend.command("MOVE:" + ",".join(f"{d:.2f}" for d in degrees))
        status = backend.firmware_status()
        print(f"firmware {backend.version.get('firmware', '?')}: {status}")
        for name, value in backend.joint_state().as_dict().items():
            print(f"  {name}: {value:+.4f} rad ({math.degrees(value):+.1f}°)")
    finally:
        backend.close()
    return ExitCode.OK
