"""A parallel's plans and schedule are a function of the task and its seed: not of the
order its branches' plans finish in.

The same task is run on the mock backend (which plays no time) with a planner whose
answers for one branch's arm come some ticks late: every trajectory of each branch (each
sample hashed, as ``benchmarks/trajectory_hashes.py`` hashes them), their starts on the
schedule and the waits inserted are the same as with a planner that answers at once.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.request import PlanRequest
from taskrunner.planning.service import InProcessPlanner, PlanService, PlanTicket
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import Scene
from taskrunner.tasks import load_task
from taskrunner.types import JointTrajectory

TASK = DATA_ROOT / "tasks" / "assembly_panda.yaml"


class _LateTicket:
    """A plan answered ``ticks`` polls late."""

    def __init__(self, ticket: PlanTicket, ticks: int) -> None:
        self.ticket, self.ticks = ticket, ticks

    def done(self) -> bool:
        self.ticks -= 1
        return self.ticks < 0 and self.ticket.done()

    def result(self, timeout: float | None = None):  # type: ignore[no-untyped-def]
        return self.ticket.result(timeout)

    def cancel(self) -> None:
        self.ticket.cancel()


class _SlowFor:
    """Plans in process; the plans of ``group`` answer ``ticks`` polls late."""

    def __init__(self, group: str, ticks: int) -> None:
        self.inner, self.group, self.ticks = InProcessPlanner(), group, ticks

    def submit(self, scene: Scene, request: PlanRequest) -> PlanTicket:
        ticket = self.inner.submit(scene, request)
        return _LateTicket(ticket, self.ticks) if request.group == self.group else ticket


def _digest(trajectory: JointTrajectory) -> str:
    digest = hashlib.sha256(repr(trajectory.names).encode())
    for values in (trajectory.times, trajectory.positions, trajectory.velocities,
                   trajectory.accelerations):
        digest.update(np.ascontiguousarray(values, dtype=float).tobytes())
    return digest.hexdigest()


def _run(planner: PlanService, runs: Path) -> tuple[str, dict, list]:
    spec = load_task(TASK, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, planner, RunOptions(seed=0, runs_dir=runs))
    record = runner.run()
    lanes: dict[tuple, list[tuple[str, float]]] = {}
    for motion in runner.ctx.executed:
        lanes.setdefault(motion.lane and tuple(i for _, i in motion.lane), []).append(
            (_digest(motion.trajectory), round(motion.start, 6)))
    waits = sorted((e.location or "", e.data.get("until")) for e in record.events
                   if e.kind == "wait" and e.data.get("until") is not None)
    return str(record.status), lanes, waits


def test_a_slow_planner_for_one_branch_changes_no_trajectory_start_or_wait(tmp_path):
    status, lanes, waits = _run(InProcessPlanner(), tmp_path)
    assert status == "succeeded" and len(lanes) >= 2 and waits
    for group in ("left_arm", "right_arm"):
        slow = _run(_SlowFor(group, 5), tmp_path)
        assert slow == (status, lanes, waits), group
