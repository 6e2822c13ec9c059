"""The record's verifier sees what each arm held: a ``parallel``'s ``motion`` events
carry the scene each motion started in, its attached objects moving with their links
(:func:`taskrunner.tree.expect.record_lanes`, :func:`~taskrunner.tree.expect.arm_conflicts`).

servo_arm_pair: the left arm swings its base joint while the right one stands straight up
(Candle); the arms alone pass 10 cm apart, a 25 cm rod in the left gripper goes through
the right arm."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.replay import motion_data
from taskrunner.scene import Scene
from taskrunner.shapes import Box, Mesh
from taskrunner.tree.expect import arm_conflicts, record_lanes
from taskrunner.types import JointTrajectory, Pose

MIDDLE = [1.5708, -0.5, -1.0, -0.3, -1.5708]
CANDLE = [1.5708, -1.5708, -1.5708, -1.5708, -1.5708]
SWING = 0.8


@pytest.fixture(scope="module")
def scene() -> Scene:
    return Scene(load_cell(DATA_ROOT / "robots/cells/servo_arm_pair.yaml").model)


def joints(side: str) -> tuple[str, ...]:
    return tuple(f"{side}_Revolute {i}" for i in range(1, 6))


def at(scene: Scene, left: list[float], right: list[float]) -> Scene:
    out = scene.copy()
    q = out.state.copy()
    model = out.robot
    q[model.indices(joints("left"))] = left
    q[model.indices(joints("right"))] = right
    out.set_state(model.apply_mimic(q))
    return out


def event(seq: int, start_scene: Scene, side: str, rows: list[list[float]], branch: int,
          location: str) -> RunEvent:
    positions = np.array(rows, dtype=float)
    zeros = np.zeros_like(positions)
    trajectory = JointTrajectory(joints(side), np.linspace(0.0, 1.0, len(rows)), positions,
                                 zeros, zeros)
    data = motion_data(trajectory, start_scene.snapshot())
    return RunEvent(seq, 0.0, "motion", node=f"{side} move", location=location,
                    data={**data, "start": 0.0, "sent": 0.0, "lane": [[1, branch]]})


def swung(sign: float) -> list[float]:
    q = list(MIDDLE)
    q[0] += sign * SWING
    return q


def swing_beside_candle(scene: Scene, holding: bool, touching: tuple[str, ...] = ()
                        ) -> list[RunEvent]:
    """The two branches' motion events, the left arm holding the rod (allowed to touch
    ``touching``) or not."""
    start = at(scene, swung(-1), CANDLE)
    if holding:  # placed where it meets the right arm at the middle of the swing
        rod = at(scene, MIDDLE, CANDLE).add_object(
            "rod", Box((0.25, 0.03, 0.03)), Pose((0.15, 0.0, 0.95)),
            attach_to="left_gripper_base_1")
        start.add_object("rod", rod.shape, rod.pose, attach_to=rod.attached_to,
                         touch_links=touching)
    return [event(1, start, "left", [swung(-1), swung(1)], 0, "task.yaml:7"),
            event(2, start, "right", [CANDLE, CANDLE], 1, "task.yaml:8")]


def test_a_held_object_through_the_other_arm_is_a_contact_of_the_record(scene):
    events = swing_beside_candle(scene, holding=True)
    misses = arm_conflicts(scene.robot, events)
    assert len(misses) == 1, misses
    assert misses[0].startswith("arms collide in a parallel: rod (task.yaml:7) and right_")
    ((_, lanes),) = record_lanes(scene.robot, events)
    held = lanes[0].motions[0].held
    assert held is not None and [o.name for o in held] == ["rod"]
    assert held[0].attached_to == "left_gripper_base_1"


def test_what_the_run_allowed_the_held_object_to_touch_the_verifier_allows(scene):
    right = tuple(n for n in scene.robot.link_names if n.startswith("right_"))
    events = swing_beside_candle(scene, holding=True, touching=right)
    assert events[0].data["touch"] == {"rod": sorted(right)}
    assert arm_conflicts(scene.robot, events) == []
    # Allowed to touch the fingers only, it still meets the arm.
    fingers = ("right_finger_left_1", "right_finger_right_1")
    (miss,) = arm_conflicts(scene.robot, swing_beside_candle(scene, True, fingers))
    assert "rod (task.yaml:7) and right_" in miss and "finger" not in miss


def test_the_same_swing_holding_nothing_passes(scene):
    notes: list[str] = []
    assert arm_conflicts(scene.robot, swing_beside_candle(scene, holding=False),
                         notes=notes) == []
    assert notes == []  # the record says what was held: nothing


def test_a_record_without_objects_is_verified_on_the_links_and_says_so(scene):
    events = swing_beside_candle(scene, holding=True)
    for e in events:  # as recorded before scenes kept their objects
        del e.data["scene"]["objects"]
    notes: list[str] = []
    assert arm_conflicts(scene.robot, events, notes=notes) == []
    assert len(notes) == 1 and "does not say what the arms held" in notes[0]
    assert "task.yaml:7" in notes[0]


def test_a_held_mesh_is_taken_from_the_scene_or_the_verification_says_it_cannot(scene):
    events = swing_beside_candle(scene, holding=True)
    mesh = {"type": "mesh", "file": "rod.stl", "scale": [1.0, 1.0, 1.0]}
    for e in events:
        e.data["scene"]["objects"][0]["shape"] = mesh
    (miss,) = arm_conflicts(scene.robot, events)
    assert miss.startswith("arms not verified against each other in time: held object 'rod'")
    assert "rod.stl" in miss
    # The scene's own mesh of that name (here a file that does exist) is taken.
    stl = next((DATA_ROOT / "robots").rglob("*.stl"))
    ((_, lanes),) = record_lanes(scene.robot, [
        _with_mesh(e, stl.name) for e in events], {"rod": Mesh(stl)})
    held = lanes[0].motions[0].held
    assert held is not None and isinstance(held[0].shape, Mesh) and held[0].shape.path == stl


def _with_mesh(e: RunEvent, name: str) -> RunEvent:
    e.data["scene"]["objects"][0]["shape"] = {"type": "mesh", "file": name,
                                              "scale": [1.0, 1.0, 1.0]}
    return e
