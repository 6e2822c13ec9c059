"""The space-time verifier: two arms of servo_arm_pair moving at once, checked against
each other over time, exactly at measurements and conservatively between them."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.collision.spacetime import (
    Lane,
    SpacetimeOptions,
    TimedMotion,
    verify_lanes,
)
from taskrunner.errors import InvalidStateError
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene
from taskrunner.types import JointTrajectory

# Reaching toward the table's middle: the two arms in this pose overlap by about 2 cm.
MIDDLE = [1.5708, -0.5, -1.0, -0.3, -1.5708]
CANDLE = [1.5708, -1.5708, -1.5708, -1.5708, -1.5708]
SWING = 0.8  # rad of the base joint either side of MIDDLE: the arms clear each other there


@pytest.fixture(scope="module")
def scene() -> Scene:
    cell = load_cell(DATA_ROOT / "robots/cells/servo_arm_pair.yaml")
    return Scene(cell.model)


def arm_joints(side: str) -> tuple[str, ...]:
    return tuple(f"{side}_Revolute {i}" for i in range(1, 6))


def trajectory(side: str, rows: list[list[float]], duration: float) -> JointTrajectory:
    positions = np.array(rows, dtype=float)
    times = np.linspace(0.0, duration, len(rows))
    zeros = np.zeros_like(positions)
    return JointTrajectory(arm_joints(side), times, positions, zeros, zeros)


def swing(side: str, start: float = 0.0, duration: float = 1.0) -> TimedMotion:
    """The base joint from MIDDLE - SWING to MIDDLE + SWING, two samples only."""
    a, b = list(MIDDLE), list(MIDDLE)
    a[0] -= SWING
    b[0] += SWING
    return TimedMotion(trajectory(side, [a, b], duration), start, f"{side} swing")


def hold(side: str, pose: list[float], start: float = 0.0, duration: float = 1.0
         ) -> TimedMotion:
    return TimedMotion(trajectory(side, [pose, pose], duration), start, f"{side} hold")


def full_state(scene: Scene, left: list[float], right: list[float]) -> np.ndarray:
    model = scene.robot
    q = scene.state.copy()
    q[model.indices(arm_joints("left"))] = left
    q[model.indices(arm_joints("right"))] = right
    return model.apply_mimic(q)


def test_crafted_arms_collide_in_the_middle_but_not_at_the_samples(scene):
    left_ends = [list(MIDDLE), list(MIDDLE)]
    left_ends[0][0] -= SWING
    left_ends[1][0] += SWING
    for ends in left_ends:  # the samples themselves are free: a sample check passes
        assert not scene.in_collision(full_state(scene, ends, MIDDLE))
    assert scene.in_collision(full_state(scene, MIDDLE, MIDDLE))


def test_a_collision_between_samples_is_found_with_its_time_and_bodies(scene):
    found = verify_lanes(scene, [Lane("left", (swing("left"),)),
                                 Lane("right", (hold("right", MIDDLE),))])
    assert not found.ok
    conflict = found.conflict
    assert conflict is not None
    assert 0.0 < conflict.time < 0.5  # on its way to the middle (reached at 0.5 s)
    assert conflict.bodies[0].startswith("left_") and conflict.bodies[1].startswith("right_")
    assert conflict.lanes == ("left", "right")
    assert conflict.motions == ("left swing", "right hold")
    assert "left swing" in conflict.describe()
    # It is a real contact: the state just after collides, the state just before does not.
    model = scene.robot

    def left_at(t: float) -> np.ndarray:
        q = full_state(scene, MIDDLE, MIDDLE)
        q[model.indices(arm_joints("left"))[0]] = MIDDLE[0] + (2 * t - 1) * SWING
        return model.apply_mimic(q)

    assert conflict.distance < 1e-5  # touching (within coal's tolerance) or deeper
    assert scene.in_collision(left_at(conflict.time + 0.01))
    assert not scene.in_collision(left_at(conflict.time - 0.01))


def test_arms_that_never_meet_pass_with_their_least_distance(scene):
    lanes = [Lane("left", (swing("left"),)), Lane("right", (hold("right", CANDLE),))]
    found = verify_lanes(scene, lanes, options=SpacetimeOptions(exact=True))
    assert found.ok, found.conflict
    assert 0.0 < found.min_distance < 0.5
    assert found.closest is not None and found.distance_queries > 0
    # Without exact measurements, pairs this far apart take cheap bounds: the same
    # verdict, with fewer of coal's distances (and no least distance measured).
    fast = verify_lanes(scene, lanes)
    assert fast.ok
    assert fast.distance_queries < found.distance_queries
    assert fast.min_distance >= found.min_distance


def test_clearance_makes_a_near_miss_a_conflict(scene):
    near = verify_lanes(scene, [Lane("left", (swing("left"),)),
                                Lane("right", (hold("right", CANDLE),))],
                        options=SpacetimeOptions(exact=True))
    wide = SpacetimeOptions(clearance=near.min_distance + 0.01)
    found = verify_lanes(scene, [Lane("left", (swing("left"),)),
                                 Lane("right", (hold("right", CANDLE),))], options=wide)
    assert found.conflict is not None and found.conflict.distance >= 0.0


def test_the_same_paths_apart_in_time_pass_and_overlapping_in_time_collide(scene):
    # The right arm reaches the middle during [0, 1] s, stays 1 s, and leaves by 3 s.
    out_ = list(CANDLE)
    right = (TimedMotion(trajectory("right", [out_, MIDDLE], 1.0), 0.0, "right in"),
             TimedMotion(trajectory("right", [MIDDLE, out_], 1.0), 2.0, "right out"))
    later = verify_lanes(scene, [Lane("left", (swing("left", start=3.5),)),
                                 Lane("right", right)])
    assert later.ok, later.conflict
    during = verify_lanes(scene, [Lane("left", (swing("left", start=1.0),)),
                                  Lane("right", right)])
    assert during.conflict is not None
    assert 1.0 < during.conflict.time < 1.5
    assert during.conflict.motions == ("left swing", None)  # the right arm rests there


def test_the_verification_is_deterministic(scene):
    lanes = [Lane("left", (swing("left"),)), Lane("right", (hold("right", MIDDLE),))]
    first, second = verify_lanes(scene, lanes), verify_lanes(scene, lanes)
    assert first.conflict == second.conflict
    assert first.distance_queries == second.distance_queries


def test_lanes_moving_the_same_joint_are_refused(scene):
    with pytest.raises(InvalidStateError, match="both move joint"):
        verify_lanes(scene, [Lane("a", (swing("left"),)), Lane("b", (swing("left", 2.0),))])


def test_overlapping_motions_of_one_lane_are_refused(scene):
    with pytest.raises(InvalidStateError, match="before"):
        verify_lanes(scene, [Lane("left", (swing("left"), swing("left", 0.5))),
                             Lane("right", (hold("right", CANDLE),))])


def test_a_negative_clearance_is_refused():
    with pytest.raises(ValueError, match="'clearance' must be"):
        SpacetimeOptions(clearance=-0.001)


def test_an_arm_and_its_own_gripper_may_be_two_lanes(scene):
    """A gripper opening while its arm swings: the fingers are the gripper's lane, the
    arm's links the arm's; they are checked against each other, not refused."""
    names = ("left_Revolute 6",)
    times = np.array([0.0, 1.0])
    positions = np.array([[0.0], [0.01]])
    gripper = TimedMotion(JointTrajectory(names, times, positions, np.zeros_like(positions),
                                          np.zeros_like(positions)), 0.0, "open")
    lanes = [Lane("arm", (swing("left"),)), Lane("gripper", (gripper,))]
    assert verify_lanes(scene, lanes).ok
    found = verify_lanes(scene, lanes, options=SpacetimeOptions(exact=True))
    assert found.ok, found.conflict
    assert found.distance_queries > 0  # fingers against the arm's links were measured
