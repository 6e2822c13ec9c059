"""Execution backends: one protocol (``execute → handle``, ``joint_state``, ``stop``),
a mock that jumps to (or replays) a trajectory's end, a simulated real-time controller,
and hobby servos on an ESP32 over serial or HTTP (calibrated by ``hardware.yaml``).

Backends depend only on :mod:`taskrunner.types` and :mod:`taskrunner.errors`.
"""

from __future__ import annotations

from taskrunner.backends.base import (
    Backend,
    BaseBackend,
    ExecutionHandle,
    check_trajectory,
)
from taskrunner.backends.calibration import ServoCalibration, load_calibration
from taskrunner.backends.execution import (
    ExecutionResult,
    ExecutionStatus,
    TrajectoryExecution,
    sample_positions,
)
from taskrunner.backends.http import HttpBackend
from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.backends.serial import SerialBackend
from taskrunner.backends.servo_backend import ServoBackend, ServoOptions
from taskrunner.backends.sim import SimBackend, SimOptions

__all__ = [
    "Backend",
    "BaseBackend",
    "ExecutionHandle",
    "ExecutionResult",
    "ExecutionStatus",
    "HttpBackend",
    "MockBackend",
    "MockOptions",
    "SerialBackend",
    "ServoBackend",
    "ServoCalibration",
    "ServoOptions",
    "SimBackend",
    "SimOptions",
    "TrajectoryExecution",
    "check_trajectory",
    "load_calibration",
    "sample_positions",
]
