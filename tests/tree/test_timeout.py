"""``timeout:`` counts task time: the same verdict on mock and on the sim at any speed."""

from __future__ import annotations

import pytest

from taskrunner.backends.mock import MockBackend
from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import EXIT_CODES, Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.clock import TaskClock

CELL = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
MOTION_S = 5.9  # the go to Candle below at 5 % scaling (about 5.92 s)


def _run(tmp_path, seconds: float, backend: str, speed: float = 1.0):
    path = tmp_path / f"timeout_{seconds}.yaml"
    path.write_text(f"""task: t
cell: {CELL}
steps:
  - timeout:
      seconds: {seconds}
      do:
        - go: {{group: arm, to: Candle, velocity_scaling: 0.05, acceleration_scaling: 0.05}}
""")
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    start = dict(zip(names, cell.start_state()))
    machine = MockBackend(names, start) if backend == "mock" else SimBackend(
        names, start, SimOptions(speed=speed))
    try:
        return path, Runner(spec, cell, machine, InProcessPlanner(), RunOptions()).run()
    finally:
        machine.close()


@pytest.mark.parametrize(("backend", "speed"), [("mock", 1.0), ("sim", 20.0), ("sim", 3.0)])
def test_a_timeout_shorter_than_the_motion_fails_on_every_backend_with_file_line(
        tmp_path, backend, speed):
    path, record = _run(tmp_path, 4.0, backend, speed)
    assert record.status == "failed", (backend, speed)
    assert record.exit_code == EXIT_CODES["execution"]
    assert record.error.startswith(f"{path}:4: timeout after 4 s (")


@pytest.mark.parametrize(("backend", "speed"), [("mock", 1.0), ("sim", 20.0), ("sim", 3.0)])
def test_a_timeout_longer_than_the_motion_passes_on_every_backend(tmp_path, backend, speed):
    _, record = _run(tmp_path, MOTION_S + 4.0, backend, speed)
    assert record.status == "succeeded", (backend, speed, record.error)


class _Handle:
    """An execution whose progress and end the test sets."""

    def __init__(self) -> None:
        self.progress = 0.0
        self.finished = False

    def done(self) -> bool:
        return self.finished


def test_the_task_clock_counts_motion_at_trajectory_time_and_the_rest_at_wall_time():
    wall = [100.0]
    clock = TaskClock(wall=lambda: wall[0])
    wall[0] += 1.0  # planning: 1 s of wall time
    assert clock.now() == pytest.approx(1.0)
    a, b = _Handle(), _Handle()
    clock.track(a)
    clock.track(b)  # two arms at once: the one furthest along sets the pace
    wall[0] += 0.5
    a.progress, b.progress = 10.0, 4.0  # a sim at x20
    assert clock.now() == pytest.approx(11.0)
    wall[0] += 0.1
    a.progress, a.finished, b.progress = 12.0, True, 5.0
    assert clock.now() == pytest.approx(13.0)
    wall[0] += 0.2
    b.progress = 5.5
    assert clock.now() == pytest.approx(13.5)
    b.finished = True
    clock.update()  # the leaf saw its motion end
    wall[0] += 2.0  # a wait of 2 s
    assert clock.now() == pytest.approx(15.5)
    c = _Handle()
    clock.track(c)
    c.progress, c.finished = 0.2, True  # ended long before anyone looked: the wall time counts
    wall[0] += 3.0
    assert clock.now() == pytest.approx(18.5)
    # The motion time: 12 s while a ran (b beside it counted once), b's last 0.5 s alone, c's
    # 0.2 s; not the 1 s of planning, the wait, or the wall time after c.
    assert clock.motion_time() == pytest.approx(12.7)
