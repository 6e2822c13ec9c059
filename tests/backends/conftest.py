"""Trajectory builders and a fake clock for the backend tests."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
import pytest

from taskrunner.types import JointTrajectory


def make_ramp(names: Sequence[str], start: Sequence[float], end: Sequence[float],
              duration: float = 1.0, rate_hz: float = 100.0) -> JointTrajectory:
    """Straight line from ``start`` to ``end`` (rad) in ``duration`` s, sampled at ``rate_hz``."""
    times = np.linspace(0.0, duration, round(duration * rate_hz) + 1)
    s = (times / duration)[:, None]
    start_, end_ = np.asarray(start, float), np.asarray(end, float)
    positions = start_ + s * (end_ - start_)
    velocities = np.tile((end_ - start_) / duration, (len(times), 1))
    return JointTrajectory(tuple(names), times, positions, velocities, np.zeros_like(positions))


class FakeClock:
    """A monotonic clock that moves only when told to (s)."""

    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now

    def advance(self, seconds: float) -> None:
        self.now += seconds


@pytest.fixture
def ramp() -> Callable[..., JointTrajectory]:
    """``ramp(names, start, end, duration=1.0, rate_hz=100.0)``: a straight-line trajectory."""
    return make_ramp


@pytest.fixture
def clock() -> FakeClock:
    """A fake clock starting at 100 s."""
    return FakeClock()
