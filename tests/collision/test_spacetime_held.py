"""The space-time verifier with held objects: what an arm holds during each motion is
one of its lane's bodies, checked against the other arm over time (servo_arm_pair)."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.collision.spacetime import Lane, TimedMotion, least_clearance, verify_lanes
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, SceneObject
from taskrunner.shapes import Box
from taskrunner.types import JointTrajectory, Pose

# The left arm reaching toward the table's middle, the right one straight up (candle):
# swinging its base joint, the left arm passes 10 cm or more from the right arm.
MIDDLE = [1.5708, -0.5, -1.0, -0.3, -1.5708]
CANDLE = [1.5708, -1.5708, -1.5708, -1.5708, -1.5708]
SWING = 0.8  # rad either side of MIDDLE


@pytest.fixture(scope="module")
def scene() -> Scene:
    return Scene(load_cell(DATA_ROOT / "robots/cells/servo_arm_pair.yaml").model)


def joints(side: str) -> tuple[str, ...]:
    return tuple(f"{side}_Revolute {i}" for i in range(1, 6))


def motion(side: str, rows: list[list[float]], start: float, label: str,
           held: tuple[SceneObject, ...] | None = None) -> TimedMotion:
    positions = np.array(rows, dtype=float)
    zeros = np.zeros_like(positions)
    trajectory = JointTrajectory(joints(side), np.linspace(0.0, 1.0, len(rows)), positions,
                                 zeros, zeros)
    return TimedMotion(trajectory, start, label, held)


def swung(sign: float) -> list[float]:
    q = list(MIDDLE)
    q[0] += sign * SWING
    return q


@pytest.fixture(scope="module")
def rod(scene: Scene) -> SceneObject:
    """A 25 cm rod in the left gripper, reaching out toward the right arm: at the middle
    of the swing it goes through the right arm's upper links."""
    probe = scene.copy()
    q = probe.state.copy()
    model = probe.robot
    q[model.indices(joints("left"))] = MIDDLE
    q[model.indices(joints("right"))] = CANDLE
    probe.set_state(model.apply_mimic(q))
    return probe.add_object("rod", Box((0.25, 0.03, 0.03)), Pose((0.15, 0.0, 0.95)),
                            attach_to="left_gripper_base_1")


def lanes(held: tuple[SceneObject, ...] | None) -> list[Lane]:
    return [Lane("left", (motion("left", [swung(-1), swung(1)], 0.0, "left swing", held),)),
            Lane("right", (motion("right", [CANDLE, CANDLE], 0.0, "right rests", ()),))]


def test_the_arms_alone_keep_apart(scene):
    for held in (None, ()):
        found = verify_lanes(scene, lanes(held))
        assert found.ok, found.conflict


def test_an_object_held_through_the_other_arm_is_a_conflict(scene, rod):
    found = verify_lanes(scene, lanes((rod,)))
    assert found.conflict is not None
    assert found.conflict.bodies[0] == "rod"
    assert found.conflict.bodies[1].startswith("right_")
    assert found.conflict.motions == ("left swing", "right rests")
    assert 0.0 < found.conflict.time < 0.5  # on its way to the middle
    # The scene given is left as it is: no rod in it.
    assert "rod" not in scene.object_names
    least = least_clearance(scene, lanes((rod,)))
    assert least.lower == -np.inf and least.bodies is not None and "rod" in least.bodies


def test_what_is_held_is_each_motion_s_own(scene, rod):
    # The left arm swings through without the rod, rests, picks it up, and swings back
    # with it after the right arm has left (2 s on): no conflict. Swinging back before
    # the right arm leaves, the rod meets it in the second motion only.
    up = [1.5708, -1.5708, -1.5708, -1.5708, -1.5708]
    away = [-1.5708, -0.5, -1.0, -0.3, -1.5708]  # reaching outward

    def left(back: float) -> Lane:
        return Lane("left", (motion("left", [swung(-1), swung(1)], 0.0, "out", ()),
                             motion("left", [swung(1), swung(-1)], back, "back", (rod,))))

    right = Lane("right", (motion("right", [up, up], 0.0, "stays", ()),
                           motion("right", [up, away], 2.0, "leaves", ())))
    late = verify_lanes(scene, [left(3.5), right])
    assert late.ok, late.conflict
    early = verify_lanes(scene, [left(1.2), right])
    assert early.conflict is not None and early.conflict.bodies[0] == "rod"
    assert early.conflict.motions[0] == "back" and early.conflict.time > 1.2


def test_a_held_object_of_the_other_lane_is_not_this_lane_s(scene, rod):
    # The right arm's motion lists the rod (all attached objects of the scene it
    # started in): it is attached to a left link, so only the left lane's own say counts.
    right = Lane("right", (motion("right", [CANDLE, CANDLE], 0.0, "right rests", (rod,)),))
    left = Lane("left", (motion("left", [swung(-1), swung(1)], 0.0, "left swing", ()),))
    assert verify_lanes(scene, [left, right]).ok


def test_an_arm_at_rest_after_its_last_motion_holds_what_the_scene_has_attached(scene, rod):
    # The left arm reached the middle holding nothing, then took the rod (attached in the
    # scene now, its next motion not on the schedule yet); the right arm comes back to
    # Candle, its motion listing what the scene has attached (as a run's admission
    # does): the rod, resting in the left hand, is in its way.
    holding = scene.copy()
    holding.add_object("rod", rod.shape, rod.pose, attach_to=rod.attached_to)
    away = [-1.5708, -0.5, -1.0, -0.3, -1.5708]
    left = Lane("left", (motion("left", [swung(-1), MIDDLE], 0.0, "to the middle", ()),))
    right = Lane("right", (motion("right", [away, CANDLE], 1.0, "back up",
                                  holding.attached_objects()),))
    found = verify_lanes(holding, [left, right])
    assert found.conflict is not None and found.conflict.bodies[0] == "rod"
    assert found.conflict.motions == (None, "back up") and found.conflict.time > 1.0
    # Holding nothing, the arms pass.
    assert verify_lanes(scene, [left, right]).ok
