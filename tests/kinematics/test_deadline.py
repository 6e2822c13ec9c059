"""The IK time budget: the thread's CPU time, capped in wall time (clocks simulated)."""

from __future__ import annotations

import pytest

from taskrunner.kinematics import deadline as module
from taskrunner.kinematics.deadline import WALL_CAP, Deadline


class Clocks:
    def __init__(self) -> None:
        self.wall = 100.0
        self.cpu = 7.0

    def run(self, seconds: float) -> None:  # the thread computes
        self.wall += seconds
        self.cpu += seconds

    def wait(self, seconds: float) -> None:  # the process waits for a CPU
        self.wall += seconds


@pytest.fixture
def clocks(monkeypatch) -> Clocks:
    clocks = Clocks()
    monkeypatch.setattr(module.time, "perf_counter", lambda: clocks.wall)
    monkeypatch.setattr(module.time, "thread_time", lambda: clocks.cpu)
    return clocks


def test_the_budget_is_cpu_time_waiting_for_a_cpu_does_not_use_it(clocks):
    deadline = Deadline(0.005)
    clocks.run(0.002)
    clocks.wait(0.010)  # descheduled: 12 ms of wall time, 2 ms of work
    assert not deadline.passed()
    assert deadline.wall == pytest.approx(clocks.wall + 0.003)
    clocks.run(0.0029)
    assert not deadline.passed()
    clocks.run(0.0002)
    assert deadline.passed()


def test_the_wall_time_is_capped(clocks):
    deadline = Deadline(0.005)
    clocks.run(0.001)
    clocks.wait(WALL_CAP * 0.005)
    assert deadline.passed()
    other = Deadline(0.005)
    clocks.run(0.001)
    clocks.wait(WALL_CAP * 0.005 - 0.0015)
    assert not other.passed()
    assert other.wall == pytest.approx(clocks.wall + 0.0005)  # the cap, before the CPU left


def test_an_idle_machine_sees_a_plain_timeout(clocks):
    deadline = Deadline(0.005)
    clocks.run(0.0049)
    assert not deadline.passed()
    clocks.run(0.0002)
    assert deadline.passed()


def test_excluded_setup_time_is_not_charged(clocks):
    deadline = Deadline(0.005)
    clocks.run(0.004)
    clocks.run(0.010)  # the seed table, built once per solver
    deadline.exclude(0.010, 0.010)
    assert not deadline.passed()
    clocks.run(0.0011)
    assert deadline.passed()
