"""Two Pandas facing each other 1 m apart: arm–arm collisions between robots."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.robot import Placement, RobotModel, build_model, load_description
from taskrunner.scene import Scene
from taskrunner.shapes import Box
from taskrunner.types import Pose

SIDES = ("left_", "right_")


@pytest.fixture(scope="module")
def two_pandas(robots_dir, example_robot_data) -> RobotModel:  # type: ignore[no-untyped-def]
    desc = load_description(robots_dir / "panda")
    left = pin.SE3(np.eye(3), np.array([-0.5, 0.0, 0.0]))
    right = pin.SE3(pin.rpy.rpyToMatrix(0.0, 0.0, np.pi), np.array([0.5, 0.0, 0.0]))
    return build_model([
        Placement(desc, name="left", prefix="left_", base=left),
        Placement(desc, name="right", prefix="right_", base=right),
    ])


def both(model: RobotModel, **joints: float) -> np.ndarray:
    """Both arms in the ready pose, with ``panda_jointN`` values changed on both."""
    q = model.default_state()
    for side in SIDES:
        q = model.state_with(q, model.named_state(side + "arm_and_hand", "default"))
        q = model.state_with(q, {f"{side}panda_{n}": v for n, v in joints.items()})
    return q


def test_both_arms_ready_are_free(two_pandas: RobotModel) -> None:
    scene = Scene(two_pandas)
    assert not scene.in_collision(both(two_pandas))


def test_both_arms_reaching_to_the_middle_collide_with_each_other(two_pandas: RobotModel) -> None:
    scene = Scene(two_pandas)
    reach = both(two_pandas, joint2=1.3, joint4=-0.6)
    assert scene.in_collision(reach)
    contacts = scene.collisions(reach)
    assert contacts
    assert all(c.a.startswith("left_") and c.b.startswith("right_") for c in contacts)
    assert ("left_panda_link5", "right_panda_link5") in {(c.a, c.b) for c in contacts}


def test_one_arm_reaching_alone_is_free(two_pandas: RobotModel) -> None:
    scene = Scene(two_pandas)
    q = two_pandas.state_with(both(two_pandas), {"left_panda_joint2": 1.3, "left_panda_joint4": -0.6})
    assert not scene.in_collision(q)


def test_each_robot_keeps_its_own_srdf_allowances(two_pandas: RobotModel) -> None:
    scene = Scene(two_pandas)
    for side in SIDES:
        assert scene.collision_allowed(side + "panda_link5", side + "panda_link7")
    assert not scene.collision_allowed("left_panda_link5", "right_panda_link7")


def test_fast_check_agrees_with_the_report_on_random_dual_arm_states(two_pandas: RobotModel) -> None:
    scene = Scene(two_pandas)
    scene.add_object("table", Box((2.0, 1.0, 0.04)), Pose((0.0, 0.0, -0.03)))
    rng = np.random.default_rng(11)
    states = [two_pandas.random_state(rng) for _ in range(100)]
    verdicts = [scene.in_collision(q) for q in states]
    assert any(verdicts) and not all(verdicts)
    assert verdicts == [bool(scene.collisions(q)) for q in states]
