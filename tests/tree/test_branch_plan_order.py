"""A parallel's plans and schedule are a function of the task and its seed: not of the
order its branches' plans finish in.

The same task is run on the mock backend (which plays no time) with a planner whose
answers for one branch's arm come some ticks late: every trajectory of each branch (each
sample hashed, as ``benchmarks/trajectory_hashes.py`` hashes them), their starts on the
schedule and the waits inserted are the same as with a planner that answers at once. In
``handoff_overlap`` the right arm's ``go`` meets the left arm's pick: which of the two
waits was decided by which plan was admitted first (a left arm planned late made the
pick wait, 2.3 s later), until the branches took turns (:meth:`~taskrunner.tree.schedule.
MotionSchedule.turn`).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.request import PlanRequest
from taskrunner.planning.service import InProcessPlanner, PlanService, PlanTicket
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import Scene
from taskrunner.tasks import load_task
from taskrunner.types import JointTrajectory

FIXTURES = Path(__file__).parent / "fixtures"


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


def _run(task: Path, planner: PlanService, runs: Path) -> tuple[str, dict, list]:
    spec = load_task(task, {})
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


@pytest.mark.parametrize("ticks", [2, 40])
def test_a_slow_planner_for_one_branch_changes_no_trajectory_start_or_wait(ticks, tmp_path):
    task = FIXTURES / "handoff_overlap.yaml"
    status, lanes, waits = _run(task, InProcessPlanner(), tmp_path)
    assert status == "succeeded" and len(lanes) >= 2 and waits
    for group in ("left_arm", "right_arm"):
        slow = _run(task, _SlowFor(group, ticks), tmp_path)
        assert slow == (status, lanes, waits), group
    # As the check has it: the right arm's go (line 22) waits for the pick (line 21).
    assert [where.rsplit(":", 1)[1] for where, _ in waits] == ["22"]
