"""Seeded two-arm work with overlapping workspaces (issue 25), many cases cheaply and a
sample end to end.

- 200 generated cases on ``servo_arm_pair``: each arm goes from Candle through two
  random states reaching over the table's middle (where the arms' workspaces overlap)
  and back; each arm's motions are admitted in turn to a :class:`MotionSchedule` (the
  rule run and check share), and the schedule is then verified by the independent
  space-time verifier, robots' links alone, no clearance asked: 0 contacts; the least
  distance at least the schedule's 5 mm. The same motions back to back without the
  schedule do collide in many cases (the generator is not vacuous).
- A seeded sample of generated pick-and-place tasks (tests/scenarios/
  test_parallel_generated.py's generator) run on the simulator and on mujoco: a run that
  succeeds has 0 contacts between the arms in its record, and mujoco reports none
  (benchmarks/two_arm_suite.py runs 200 of them on each).

Cost (a loaded 2-core machine): about 8 s for the 200 schedules, 3 s for the sample.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_parallel_generated import generated_task

from taskrunner.collision.spacetime import Lane, TimedMotion, verify_lanes
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.runtime.session import make_backend
from taskrunner.scene import Scene
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts
from taskrunner.tree.schedule import CLEARANCE, Admission, MotionSchedule, lanes_of
from taskrunner.types import JointTrajectory

CASES = 200
SIM_SAMPLE = (3,)  # seeds of the generated tasks run on the simulator
MUJOCO_SAMPLE = (1, 2)  # and on mujoco (benchmarks/two_arm_suite.py runs 200 on each)
CANDLE = np.array([1.5708, -1.5708, -1.5708, -1.5708, -1.5708])
MIDDLE = np.array([1.5708, -0.5, -1.0, -0.3, -1.5708])  # the arms overlap by ~2 cm here
SPEED = 1.5  # rad/s of the joint moving most


@pytest.fixture(scope="module")
def scene() -> Scene:
    cell = load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml")
    scene = Scene(cell.model)  # the robots alone
    scene.set_state(cell.model.state_with(scene.state, {
        **{f"left_Revolute {i + 1}": v for i, v in enumerate(CANDLE)},
        **{f"right_Revolute {i + 1}": v for i, v in enumerate(CANDLE)}}))
    return scene


def line(side: str, start: np.ndarray, end: np.ndarray) -> JointTrajectory:
    duration = max(float(np.abs(end - start).max()) / SPEED, 0.05)
    t = np.array([0.0, duration])  # a straight joint line: two samples are exact
    positions = start + np.outer(t / duration, end - start)
    zeros = np.zeros_like(positions)
    return JointTrajectory(tuple(f"{side}_Revolute {i}" for i in range(1, 6)), t, positions,
                           zeros, zeros)


def generated_lanes(seed: int) -> list[list[JointTrajectory]]:
    """Each arm: Candle, two states over the middle (base turned +-0.5 rad, the others
    +-0.25 rad about MIDDLE), Candle."""
    rng = np.random.default_rng(seed)
    lanes = []
    for side in ("left", "right"):
        states = [CANDLE]
        for _ in range(2):
            q = MIDDLE + rng.uniform(-0.25, 0.25, size=5)
            q[0] = MIDDLE[0] + rng.uniform(-0.5, 0.5)
            states.append(q)
        states.append(CANDLE)
        lanes.append([line(side, a, b) for a, b in zip(states, states[1:])])
    return lanes


def schedule_case(scene: Scene, seed: int) -> tuple[MotionSchedule | str, int]:
    """The case's motions admitted an arm's motion in turn (held while blocked, as the
    check does), or why the schedule refuses them; and how many waits it inserted."""
    schedule = MotionSchedule()
    instance = schedule.new_instance()
    queues = {((instance, i),): motions for i, motions in enumerate(generated_lanes(seed))}
    waits = 0
    while any(queues.values()):
        progressed = False
        for lane, queue in queues.items():
            if not queue:
                continue
            found = schedule.admit(scene, lane, queue[0], f"case {seed} arm {lane[0][1]}")
            if not isinstance(found, Admission):
                refusal = schedule.refusal(lane, found, None)
                if refusal is not None:
                    return refusal, waits
                schedule.holding[lane] = found.lane
                continue
            schedule.holding.pop(lane, None)
            queue.pop(0)
            waits += len(found.waits)
            progressed = True
        if not progressed:
            return "no arm can move", waits
    return schedule, waits


def test_200_generated_schedules_never_bring_the_arms_into_contact(scene):
    admitted, refused, waited, collide_unscheduled = 0, [], 0, 0
    for seed in range(CASES):
        schedule, waits = schedule_case(scene, seed)
        if seed % 4 == 0:
            # The same motions, each arm's back to back from 0 s: do they meet?
            naive = [Lane(side, tuple(TimedMotion(t, s) for t, s in zip(
                         motions, np.cumsum([0.0] + [m.duration for m in motions[:-1]]))))
                     for side, motions in zip(("left", "right"), generated_lanes(seed))]
            collide_unscheduled += not verify_lanes(scene, naive).ok
        if isinstance(schedule, str):
            refused.append(schedule)
            continue
        admitted += 1
        waited += waits > 0
        found = verify_lanes(scene, lanes_of(schedule.committed))
        assert found.ok, f"seed {seed}: {found.conflict.describe()}"  # type: ignore[union-attr]
        assert found.min_distance >= CLEARANCE - 1e-4, (seed, found.min_distance)
    # Refused: both arms resting over the middle, each in the other's next motion's way
    # (waiting cannot resolve it; the check and the run refuse it naming both steps).
    assert all("each wait for the other's arm to move (a deadlock)" in r for r in refused)
    assert admitted >= 0.75 * CASES, (admitted, refused)
    # Not vacuous: without the schedule many cases collide, and the schedule waited there.
    assert collide_unscheduled >= 0.2 * CASES / 4, collide_unscheduled
    assert waited >= 0.2 * CASES, waited


@pytest.mark.parametrize(("kind", "seed"), [("sim", seed) for seed in SIM_SAMPLE]
                         + [("mujoco", seed) for seed in MUJOCO_SAMPLE])
def test_a_sample_of_generated_tasks_on_sim_and_mujoco_never_touches(kind, seed, tmp_path):
    # mujoco: the arms lag behind their trajectories in physics, and the backend itself
    # fails a run on any contact between the two robots' bodies.
    path = tmp_path / f"generated_{seed}.yaml"
    path.write_text(generated_task(seed), encoding="utf-8")
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    backend = make_backend(kind, cell, 20.0 if kind == "sim" else None)
    try:
        runner = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(seed=seed, runs_dir=tmp_path / "runs", backend_name=kind))
        record = runner.run()
    finally:
        backend.close()
    assert "contact between robots" not in (record.error or "")
    misses = arm_conflicts(cell.model, record.events)
    if record.status == "succeeded":
        assert not misses, misses
    else:  # refused cleanly, at a step's file:line
        assert record.error and ".yaml:" in record.error, record.error
    assert any(e.kind == "motion" and e.data.get("lane") for e in record.events)


def test_the_generated_cases_are_the_same_for_a_seed():
    a, b = generated_lanes(7), generated_lanes(7)
    assert all(np.array_equal(x.positions, y.positions) for la, lb in zip(a, b)
               for x, y in zip(la, lb))
    assert not np.array_equal(generated_lanes(8)[0][0].positions, a[0][0].positions)
