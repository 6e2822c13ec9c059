"""A parallel's schedule is kept in planned time on a backend that plays time
(:mod:`taskrunner.tree.schedule`, *Planned time*): a plan that finishes late makes the
whole schedule slip, never a different plan.

``assembly_panda`` runs twice on a mock that plays its motions in time on a fake wall
clock (so every run is the same): once with a planner that answers at once, once with
the right arm's plans answered 30 polls late. Both give the same
trajectories, the same planned starts and the same waits; the late one is only later on
the run's clock, each delay recorded as a slip, and its record passes the independent
space-time verifier.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from taskrunner.backends.mock import MockBackend, MockOptions
from taskrunner.planning.request import PlanRequest
from taskrunner.planning.service import InProcessPlanner, PlanService, PlanTicket
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import Scene
from taskrunner.tasks import load_task
from taskrunner.tree.clock import TaskClock
from taskrunner.tree.expect import arm_conflicts

ASSEMBLY = DATA_ROOT / "tasks" / "assembly_panda.yaml"
SPEED = 20.0  # trajectory seconds per (fake) wall second: one 10 ms tick is 0.2 s


class _Wall:
    """The fake wall clock every part of the run reads (s)."""

    def __init__(self) -> None:
        self.t = 0.0

    def __call__(self) -> float:
        return self.t


class _FakeTimeRunner(Runner):
    """Ticks at 100 Hz of the fake wall clock, with no real sleep."""

    wall: _Wall

    def _pause(self, seconds: float) -> None:
        self.wall.t += 0.01


class _LateTicket:
    """A plan answered ``ticks`` polls late (the deterministic planning delay)."""

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


def _run(planner: PlanService, runs: Path) -> _FakeTimeRunner:
    spec = load_task(ASSEMBLY, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    wall = _Wall()
    backend = MockBackend(names, dict(zip(names, cell.start_state())),
                          MockOptions(speed=SPEED), clock=wall)
    runner = _FakeTimeRunner(spec, cell, backend, planner, RunOptions(seed=0, runs_dir=runs))
    runner.wall, runner.ctx.clock = wall, TaskClock(wall=wall)
    runner.run()
    return runner


def _plan(runner: _FakeTimeRunner) -> tuple[dict, list]:
    """Per lane, each motion's trajectory (every sample hashed) and planned start; the
    waits the schedule inserted (step, until)."""
    lanes: dict[tuple, list[tuple[str, float]]] = {}
    for motion in runner.ctx.executed:
        digest = hashlib.sha256(repr(motion.trajectory.names).encode())
        for values in (motion.trajectory.times, motion.trajectory.positions,
                       motion.trajectory.velocities, motion.trajectory.accelerations):
            digest.update(np.ascontiguousarray(values, dtype=float).tobytes())
        lanes.setdefault(tuple(i for _, i in motion.lane), []).append(
            (digest.hexdigest(), round(motion.start, 6)))
    waits = [(e.location, e.data["until"]) for e in runner.record.events
             if e.kind == "wait" and "until" in e.data]
    return lanes, waits


def test_a_late_plan_slips_the_schedule_and_changes_no_trajectory_or_planned_start(tmp_path):
    prompt = _run(InProcessPlanner(), tmp_path)
    late = _run(_SlowFor("right_arm", 30), tmp_path)
    for runner in (prompt, late):
        assert runner.record.status == "succeeded", runner.record.error
        assert arm_conflicts(runner.scene.robot, runner.record.events) == []
    lanes, waits = _plan(prompt)
    assert len(lanes) == 2 and all(len(motions) >= 5 for motions in lanes.values())
    assert _plan(late) == (lanes, waits)
    # The delay is a slip of the whole schedule, recorded as such: the late run's first
    # right-arm motion was due at 0 s and went more than a second later.
    slips = [e for e in late.record.events if e.kind == "wait" and "slip" in e.data]
    assert slips and max(e.data["slip"] for e in slips) > 1.0
    assert late.ctx.schedule.slip > prompt.ctx.schedule.slip + 1.0
    sent = {e.location: e.data["sent"] - e.data["start"] for e in late.record.events
            if e.kind == "motion"}
    assert all(offset >= -1e-6 for offset in sent.values())
