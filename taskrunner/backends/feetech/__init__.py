"""Bus servos: the Feetech STS protocol (the SO-101's STS3215), its bus emulator, the
backend that streams trajectories over it, and LeRobot's calibration file.

Layers, bottom up: :mod:`.protocol` (packets, control table) → :mod:`.bus` (the
:class:`ServoBus` a backend needs; :class:`FeetechBus` over pyserial) →
:mod:`.backend` (:class:`FeetechBackend`, one bus or several on one clock);
:mod:`.hardware` reads a cell's hardware file (which bus drives which arm) and opens the
backend for ``run-task … --backend feetech``. :mod:`.calibration` converts ticks and joint
positions as LeRobot does; :mod:`.emulator` answers on a pty as the servos do;
:mod:`.bench` holds the ``run-task hw`` helpers for the arm.
"""

from __future__ import annotations

from taskrunner.backends.feetech.backend import (
    BusMotors,
    FaultRecord,
    FeetechBackend,
    FeetechOptions,
    JointTracking,
)
from taskrunner.backends.feetech.bus import FaultKind, FeetechBus, ServoBus, ServoState
from taskrunner.backends.feetech.calibration import (
    SO101_MOTORS,
    LeRobotCalibration,
    Motor,
    MotorCalibration,
    load_lerobot_calibration,
    write_lerobot_calibration,
)
from taskrunner.backends.feetech.emulator import (
    BusEmulator,
    ServoModel,
    SyncWrite,
    calibrated_servos,
    so101_servos,
)

__all__ = [
    "SO101_MOTORS",
    "BusEmulator",
    "BusMotors",
    "FaultKind",
    "FaultRecord",
    "FeetechBackend",
    "FeetechBus",
    "FeetechOptions",
    "JointTracking",
    "LeRobotCalibration",
    "Motor",
    "MotorCalibration",
    "ServoBus",
    "ServoModel",
    "ServoState",
    "SyncWrite",
    "calibrated_servos",
    "load_lerobot_calibration",
    "so101_servos",
    "write_lerobot_calibration",
]
