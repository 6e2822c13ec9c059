"""A cell's Feetech hardware file: which bus drives which arm, with which IDs and calibration.

``<cell>.hardware.yaml`` next to the cell file (``run-task … --backend feetech``; another
file with ``--hardware FILE``)::

    protocol: feetech
    buses:
      left: {port: /dev/ttyACM0}            # baud: 1000000, reply_timeout: 0.04 (s)
      right: {port: /dev/ttyACM1}
    robots:                                 # the cell's robots, by name
      left: {bus: left, calibration: ~/.cache/huggingface/lerobot/calibration/robots/so101_follower/left.json}
      right: {bus: right, ids: [1, 2, 3, 4, 5, 6], calibration: right.json}

``on_fault: torque_off`` (default ``hold``) is the stop a fault sends (see
:class:`~.backend.FeetechOptions`). Each robot names its bus, its servo IDs in the arm's
motor order (default the arm's own, 1-6 for the SO-101; two arms on one bus: 1-6 and
7-12, the calibration file's ``id`` fields the same), its LeRobot calibration file
(relative to this file; ``~`` expanded) and ``arm`` (``so101``, the default).
``--port`` and ``--calibration`` override the file: a path alone where there is one bus
(one robot), else ``NAME=PATH`` pairs separated by commas.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Literal

from taskrunner.backends.feetech.backend import BusMotors, FeetechBackend, FeetechOptions
from taskrunner.backends.feetech.bus import FeetechBus
from taskrunner.backends.feetech.calibration import (
    LeRobotCalibration,
    Motor,
    load_lerobot_calibration,
)
from taskrunner.backends.feetech.commands import ARMS, LEROBOT_CALIBRATION_HINT
from taskrunner.errors import ArgumentError, InputError, YamlError
from taskrunner.yamlfile import line_of, load_yaml

__all__ = ["ArmOnBus", "BusPort", "CellRobot", "FeetechHardware", "load_feetech_hardware",
           "open_feetech_backend", "parse_overrides"]

_TOP_KEYS = frozenset({"protocol", "buses", "robots", "on_fault"})
_BUS_KEYS = frozenset({"port", "baud", "reply_timeout"})
_ROBOT_KEYS = frozenset({"bus", "ids", "calibration", "arm"})
DEFAULT_BAUD = 1_000_000
DEFAULT_REPLY_TIMEOUT = 0.04  # s: a servo answers in well under 1 ms; USB adds a few


@dataclass(frozen=True)
class CellRobot:
    """A robot of the cell: its name and the prefix of its joints (``left_``, or empty)."""

    name: str
    prefix: str = ""


@dataclass(frozen=True)
class BusPort:
    """A bus of the hardware file: its name, port, baud rate and how long a reply may take
    (s; past it, the servo's silence is a fault)."""

    name: str
    port: str
    baud: int = DEFAULT_BAUD
    reply_timeout: float = DEFAULT_REPLY_TIMEOUT


@dataclass(frozen=True)
class ArmOnBus:
    """One robot's servos: its bus, its motors (joint names with the robot's prefix, IDs
    as on the bus) and the calibration file (``line``: where the hardware file names it)."""

    robot: str
    prefix: str
    bus: str
    motors: tuple[Motor, ...]
    calibration: Path
    line: int | None = None


@dataclass(frozen=True)
class FeetechHardware:
    """A cell's hardware file, read."""

    path: Path
    buses: tuple[BusPort, ...]
    arms: tuple[ArmOnBus, ...]
    on_fault: Literal["hold", "torque_off"] = "hold"


def _fail(message: str, path: Path, node: Any, key: Any = None) -> YamlError:
    return YamlError(message, path, line_of(node, key))


def _mapping(node: Any, keys: frozenset[str], what: str, path: Path, parent: Any,
             key: Any) -> dict[str, Any]:
    if not isinstance(node, dict):
        raise _fail(f"{what} must be a mapping with {', '.join(sorted(keys))} (got {node!r})",
                    path, parent, key)
    unknown = sorted(set(node) - keys)
    if unknown:
        raise _fail(f"{what}: unknown key {unknown[0]!r}; keys: {sorted(keys)}", path, node,
                    unknown[0])
    return node


def load_feetech_hardware(path: str | Path, robots: Sequence[CellRobot]) -> FeetechHardware:
    """Read and check a cell's Feetech hardware file against the cell's robots.

    Raises:
        YamlError: unreadable or invalid YAML, a missing or unknown key, robot or bus, a bus
            without a port, IDs that are not the arm's count of distinct 1..253 or that two
            robots share on one bus (``file:line``).
    """
    path = Path(path)
    data = load_yaml(path)
    data = _mapping(data, _TOP_KEYS, "a Feetech hardware file", path, data, None)
    if data.get("protocol") != "feetech":
        raise _fail(f"'protocol' must be 'feetech' (got {data.get('protocol')!r}); an ESP32 "
                    "servo board's file is read by the serial and http backends", path, data,
                    "protocol")
    for key in ("buses", "robots"):
        if not isinstance(data.get(key), dict) or not data[key]:
            raise _fail(f"'{key}' must be a mapping of {key} by name (got {data.get(key)!r})",
                        path, data, key)
    on_fault = data.get("on_fault", "hold")
    if on_fault not in ("hold", "torque_off"):
        raise _fail(f"'on_fault' must be 'hold' or 'torque_off' (got {on_fault!r})", path, data,
                    "on_fault")
    buses = []
    for name, entry in data["buses"].items():
        entry = _mapping(entry, _BUS_KEYS, f"bus {name!r}", path, data["buses"], name)
        port, baud = entry.get("port"), entry.get("baud", DEFAULT_BAUD)
        if not isinstance(port, str) or not port:
            raise _fail(f"bus {name!r}: 'port' must be a device path (got {port!r})", path,
                        entry, "port")
        if isinstance(baud, bool) or not isinstance(baud, int) or baud <= 0:
            raise _fail(f"bus {name!r}: 'baud' must be a positive integer (got {baud!r})",
                        path, entry, "baud")
        timeout = entry.get("reply_timeout", DEFAULT_REPLY_TIMEOUT)
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) \
                or not 0 < timeout <= 1:
            raise _fail(f"bus {name!r}: 'reply_timeout' must be in (0, 1] s (got {timeout!r})",
                        path, entry, "reply_timeout")
        buses.append(BusPort(str(name), port, baud, float(timeout)))
    by_name = {r.name: r for r in robots}
    node = data["robots"]
    for name in node:
        if name not in by_name:
            raise _fail(f"unknown robot {name!r}; the cell's robots: {list(by_name)}", path,
                        node, name)
    missing = [r.name for r in robots if r.name not in node]
    if missing:
        raise _fail(f"robots {missing} have no bus in this file", path, data, "robots")
    arms = []
    taken: dict[tuple[str, int], str] = {}
    for name, entry in node.items():
        entry = _mapping(entry, _ROBOT_KEYS, f"robot {name!r}", path, node, name)
        arm = entry.get("arm", "so101")
        if arm not in ARMS:
            raise _fail(f"robot {name!r}: 'arm' must be one of {sorted(ARMS)} (got {arm!r})",
                        path, entry, "arm")
        motors = ARMS[arm]
        bus = entry.get("bus")
        if bus not in {b.name for b in buses}:
            raise _fail(f"robot {name!r}: 'bus' must be one of {[b.name for b in buses]} "
                        f"(got {bus!r})", path, entry, "bus")
        ids = entry.get("ids", [m.servo_id for m in motors])
        if (not isinstance(ids, list) or len(ids) != len(motors) or len(set(ids)) != len(ids)
                or not all(isinstance(i, int) and not isinstance(i, bool) and 1 <= i <= 253
                           for i in ids)):
            raise _fail(f"robot {name!r}: 'ids' must list {len(motors)} distinct IDs 1..253, "
                        f"one per motor {[m.joint for m in motors]} (got {ids!r})", path,
                        entry, "ids")
        for i, motor in zip(ids, motors):
            if (bus, i) in taken:
                raise _fail(f"robot {name!r}: ID {i} on bus {bus!r} is also "
                            f"{taken[(bus, i)]!r}'s", path, entry, "ids")
            taken[(bus, i)] = f"{name}.{motor.joint}"
        calibration = entry.get("calibration")
        if not isinstance(calibration, str) or not calibration:
            raise _fail(f"robot {name!r}: 'calibration' must be the path of its LeRobot "
                        f"calibration file ({LEROBOT_CALIBRATION_HINT}; got {calibration!r})",
                        path, entry, "calibration")
        prefix = by_name[name].prefix
        arms.append(ArmOnBus(
            str(name), prefix, str(bus),
            tuple(Motor(prefix + m.joint, i, m.mode, m.lower, m.upper)
                  for i, m in zip(ids, motors)),
            path.parent / Path(calibration).expanduser(), line_of(entry, "calibration")))
    return FeetechHardware(path, tuple(buses), tuple(arms), on_fault)


def parse_overrides(text: str | None, names: Sequence[str], what: str
                    ) -> dict[str, str]:
    """``--port`` / ``--calibration`` as a mapping by name: ``PATH`` alone where ``names``
    has one name, else ``NAME=PATH`` pairs separated by commas.

    Raises:
        ArgumentError: a bare path where there are several names, or an unknown name.
    """
    if not text:
        return {}
    pairs = [p.strip() for p in text.split(",") if p.strip()]
    if len(pairs) == 1 and "=" not in pairs[0]:
        if len(names) != 1:
            raise ArgumentError(f"'{what}' must be NAME=PATH pairs, one per "
                                f"{'bus' if what == 'port' else 'robot'} of {list(names)} "
                                f"(got {text!r})")
        return {names[0]: pairs[0]}
    found = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or name not in names or not value:
            raise ArgumentError(f"'{what}' must be NAME=PATH pairs with NAME one of "
                                f"{list(names)} (got {pair!r})")
        found[name] = value
    return found


def read_calibrations(hardware: FeetechHardware, overrides: Mapping[str, str]
                      ) -> dict[str, LeRobotCalibration]:
    """Each robot's LeRobot calibration, from the hardware file or ``overrides`` by robot.

    Raises:
        InputError: a file that is missing, unreadable or invalid, or whose motors or IDs
            are not the arm's (names the file, and the hardware file's line that names it).
    """
    found = {}
    for arm in hardware.arms:
        given = overrides.get(arm.robot)
        path = Path(given).expanduser() if given else arm.calibration
        named = ("--calibration" if given else
                 f"{hardware.path}:{arm.line}" if arm.line else str(hardware.path))
        if not path.is_file():
            raise InputError(f"the calibration file of robot {arm.robot!r} does not exist "
                             f"(named by {named}); calibrate the arm with run-task hw "
                             f"calibrate --robot so101 --calibration {path}, or give LeRobot's "
                             f"file with --calibration ({LEROBOT_CALIBRATION_HINT})", path)
        entries = load_lerobot_calibration(path)
        # the file names motors without the robot's prefix, as LeRobot does
        renamed = {arm.prefix + name: entry for name, entry in entries.items()}
        try:
            found[arm.robot] = LeRobotCalibration(arm.motors, renamed, path)
        except InputError as exc:
            reason = exc.reason.removeprefix(f"{path}: ")  # said once, as the error's path
            reason = reason.replace(f"'{arm.prefix}", "'") if arm.prefix else reason
            raise InputError(f"robot {arm.robot!r}: {reason}", path) from None
    return found


def open_feetech_backend(path: str | Path, robots: Sequence[CellRobot],
                         joint_names: Sequence[str], port: str | None = None,
                         calibration: str | None = None,
                         options: FeetechOptions | None = None) -> FeetechBackend:
    """The Feetech backend of a cell: its hardware file read, the calibrations read, the
    buses opened, the servos pinged and checked.

    Args:
        path: the cell's hardware file.
        robots: the cell's robots.
        joint_names: the cell's joints: every one must be driven by a servo.
        port: ``--port`` (see :func:`parse_overrides`), by bus name.
        calibration: ``--calibration``, by robot name.
        options: see :class:`FeetechOptions`; its ``on_fault`` is the hardware file's.

    Raises:
        YamlError / InputError: the hardware file, a calibration file, a joint of the cell
            that no servo drives (or a servo joint the cell lacks), a bad override.
        BusFaultError: a port that does not open, a servo that does not answer.
    """
    hardware = load_feetech_hardware(path, robots)
    ports = parse_overrides(port, [b.name for b in hardware.buses], "port")
    calibrations = read_calibrations(hardware, parse_overrides(
        calibration, [a.robot for a in hardware.arms], "calibration"))
    driven = [m.joint for a in hardware.arms for m in a.motors]
    extra = [j for j in driven if j not in joint_names]
    if extra:
        raise InputError(f"the servos drive joints {extra} that the cell does not have "
                         f"(its joints: {list(joint_names)})", hardware.path)
    undriven = [j for j in joint_names if j not in driven]
    if undriven:
        raise InputError(f"no servo drives the cell's joints {undriven}", hardware.path)
    links: list[BusMotors] = []
    try:
        for bus in hardware.buses:
            arms = [a for a in hardware.arms if a.bus == bus.name]
            if not arms:
                continue
            motors = tuple(m for a in arms for m in a.motors)
            entries = {j: e for a in arms for j, e in calibrations[a.robot].entries.items()}
            merged = LeRobotCalibration(motors, entries,
                                        calibrations[arms[0].robot].path if len(arms) == 1
                                        else None)
            opened = FeetechBus(ports.get(bus.name, bus.port), bus.baud,
                                reply_timeout=bus.reply_timeout)
            links.append(BusMotors(opened, merged, bus.name))
    except BaseException:
        for link in links:
            link.bus.close()
        raise
    return FeetechBackend(links, replace(options or FeetechOptions(), on_fault=hardware.on_fault))
