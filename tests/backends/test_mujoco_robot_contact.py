"""Two robots on the mujoco backend (issue 25): a motion in which two robots' links touch
fails, naming both links (arms of one cell are bodies to each other, an arm's own links
are not); the shipped two-Panda assembly, whose stacking waits for the base to be down,
runs on it with the arms apart."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.errors import BackendError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts
from taskrunner.types import JointTrajectory

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell  # noqa: E402
from taskrunner.backends.physics.mjcf import MjcfOptions, cell_mjcf  # noqa: E402

PAIR = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
ASSEMBLY = DATA_ROOT / "tasks" / "assembly_panda.yaml"
# Both arms reaching down to the middle of the table: their grippers meet there.
MIDDLE = [1.5708, -0.7, -0.9, -0.6, -1.5708]


def test_each_robot_of_a_pair_has_a_contact_bit_of_its_own(tmp_path):
    physics = physics_cell(load_cell(PAIR))
    assert physics.link_robots["left_base_link"] == "left"
    assert physics.link_robots["right_gripper_base_1"] == "right"
    xml = cell_mjcf(physics, MjcfOptions(), tmp_path)
    # left: bit 2, touching the world (1) and right (4); right: bit 4, world and left.
    assert 'contype="2" conaffinity="5"' in xml and 'contype="4" conaffinity="3"' in xml
    assert 'contype="1" conaffinity="7"' in xml  # the table touches both
    assert 'contype="2" conaffinity="1"' not in xml


def test_two_arms_driven_into_each_other_fail_the_motion_naming_both_links(tmp_path):
    cell = load_cell(PAIR)
    names = cell.model.joint_names
    start = cell.start_state()
    arms = [*cell.model.group("left_arm").joint_names, *cell.model.group("right_arm").joint_names]
    goal = dict(zip(names, start))
    for prefix in ("left_", "right_"):
        for i, value in enumerate(MIDDLE, 1):
            goal[f"{prefix}Revolute {i}"] = value
    columns = [names.index(n) for n in arms]
    q0 = np.asarray(start)[columns]
    q1 = np.array([goal[n] for n in arms])
    times = np.linspace(0.0, 2.0, 41)
    positions = q0 + (q1 - q0) * (times / times[-1])[:, None]
    zeros = np.zeros_like(positions)
    trajectory = JointTrajectory(tuple(arms), times, positions, zeros, zeros)
    with MujocoBackend(names, physics_cell(cell), dict(zip(names, start)),
                       MujocoOptions(cache_dir=str(tmp_path))) as backend:
        handle = backend.execute(trajectory)
        with pytest.raises(BackendError) as caught:
            handle.wait(60.0)
    message = str(caught.value)
    assert "contact between robots" in message
    left, right = message.index("(left)"), message.index("(right)")
    assert "'left_" in message[:left] and "'right_" in message[left:right]


def test_the_assembly_stacks_when_the_base_is_down_with_the_arms_apart(tmp_path):
    spec = load_task(ASSEMBLY, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    with MujocoBackend(names, physics_cell(cell), dict(zip(names, cell.start_state())),
                       MujocoOptions(cache_dir=str(tmp_path))) as backend:
        runner = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(seed=0, runs_dir=tmp_path / "runs", backend_name="mujoco"))
        record = runner.run()
    assert record.status == "succeeded", record.error  # expectations met, no robot contact
    events = record.events
    motions = [e for e in events if e.kind == "motion"]

    def span(line: int) -> tuple[float, float]:  # when the motions really ran ('sent')
        mine = [e for e in motions if e.location == f"{ASSEMBLY}:{line}"]
        assert mine, line
        return (min(e.data["sent"] for e in mine),
                max(e.data["sent"] + e.data["trajectory"]["duration"] for e in mine))

    base_down, stack = span(21), span(25)  # the left Panda's place, the right one's
    # 'wait_for: {step: base down, until: released}': the stacking starts once the left
    # gripper has opened on the plate (the place's motions: to pre-place, descend, open,
    # retreat), while the left hand's retreat may still be under way.
    placing = sorted((e for e in motions if e.location == f"{ASSEMBLY}:21"),
                     key=lambda e: e.data["sent"])
    opened = placing[-2]
    assert stack[0] >= opened.data["sent"] + opened.data["trajectory"]["duration"] - 1e-4
    # On the schedule's clock (admitted starts), the stacking's floor is the opening's end.
    admitted_end = opened.data["start"] + opened.data["trajectory"]["duration"]
    waits = [e for e in events if e.kind == "wait" and e.data.get("step") == "base down"]
    # The hold lasted until the base was down at least (later when, on a busy machine, a
    # late motion was re-timed after the wait was recorded).
    assert waits[0].data.get("hold") and waits[-1].data["until"] >= admitted_end - 1e-4
    assert span(24)[0] < base_down[0]  # the right Panda picked while the left one carried
    assert arm_conflicts(runner.scene.robot, events) == []
