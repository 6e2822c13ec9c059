"""Execution backends: one protocol (``execute → handle``, ``joint_state``, ``stop``),
a mock that jumps to (or replays) a trajectory's end and a simulated real-time controller.

Backends depend only on :mod:`taskrunner.types` and :mod:`taskrunner.errors`.
"""

from __future__ import annotations

from taskrunner.backends.base import (
    Backend,
    BaseBackend,
    ExecutionHandle,
    check_trajectory,
)
from taskrunner.backends.execution import (
    ExecutionResult,
    ExecutionStatus,
    TrajectoryExecution,
    sample_positions,
)
from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.backends.sim import SimBackend, SimOptions

__all__ = [
    "Backend",
    "BaseBackend",
    "ExecutionHandle",
    "ExecutionResult",
    "ExecutionStatus",
    "MockBackend",
    "MockOptions",
    "SimBackend",
    "SimOptions",
    "TrajectoryExecution",
    "check_trajectory",
    "sample_positions",
]
