"""least_clearance: the least distance between two lanes over time, bracketed, against a
dense replay measured with the exact checker."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.collision.spacetime import Lane, TimedMotion, least_clearance
from taskrunner.errors import ArgumentError
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene
from taskrunner.types import JointTrajectory

MIDDLE = [1.5708, -0.5, -1.0, -0.3, -1.5708]  # reaching to the table's middle


@pytest.fixture(scope="module")
def scene() -> Scene:
    return Scene(load_cell(DATA_ROOT / "robots/cells/servo_arm_pair.yaml").model)


def joints(side: str) -> tuple[str, ...]:
    return tuple(f"{side}_Revolute {i}" for i in range(1, 6))


def swing(side: str, base: tuple[float, float], start: float = 0.0) -> TimedMotion:
    rows = np.array([MIDDLE, MIDDLE], dtype=float)
    rows[:, 0] = base
    zeros = np.zeros_like(rows)
    return TimedMotion(JointTrajectory(joints(side), np.array([0.0, 1.0]), rows, zeros, zeros),
                       start, f"{side} swing")


def dense_least(scene: Scene, lanes: list[Lane], step: float = 0.002) -> float:
    """The least distance between the left and the right arm's links, replayed every
    ``step`` s, each pair measured with the exact checker."""
    model, checker = scene.robot, scene.checker
    geometry = checker.geometry_model
    names = [str(g.name) for g in geometry.geometryObjects]
    pairs = [k for k, p in enumerate(geometry.collisionPairs)
             if {names[p.first][:5], names[p.second][:5]} == {"left_", "right"}]
    out = np.zeros(len(pairs))
    least = np.inf
    for t in np.arange(0.0, 1.0 + step, step):
        q = scene.state.copy()
        for lane in lanes:
            (motion,) = lane.motions
            tr = motion.trajectory
            q[model.indices(tr.names)] = [np.interp(t - motion.start, tr.times,
                                                    tr.positions[:, j])
                                          for j in range(len(tr.names))]
        checker.pair_distances(model.to_pin(model.apply_mimic(q)), pairs, out)
        least = min(least, float(out.min()))
    return least


def test_the_least_clearance_of_two_swinging_arms_is_bracketed_within_the_tolerance(scene):
    # The left arm swings toward the middle while the right one swings away: close, apart.
    lanes = [Lane("left", (swing("left", (0.6, 1.1)),)),
             Lane("right", (swing("right", (2.2, 2.9)),))]
    found = least_clearance(scene, lanes)
    assert found.lower <= found.distance <= found.lower + 2e-4
    assert 0.0 < found.distance < 0.2
    assert found.bodies is not None and found.bodies[0].startswith("left_")
    assert found.motions == ("left swing", "right swing")
    assert 0.0 <= (found.time or -1) <= 1.0
    assert abs(found.distance - dense_least(scene, lanes)) < 1e-3


def test_arms_that_meet_report_their_first_contact_and_prove_nothing(scene):
    lanes = [Lane("left", (swing("left", (0.8, 2.3)),)),
             Lane("right", (swing("right", (2.3, 0.8)),))]
    found = least_clearance(scene, lanes)
    assert found.lower == -np.inf and found.distance < 1e-5
    assert dense_least(scene, lanes) < 0  # they do go through each other
    assert 0.0 < (found.time or -1) < 0.5  # on the way to the middle (crossed at 0.5 s)


def test_one_lane_alone_has_no_clearance_to_report(scene):
    found = least_clearance(scene, [Lane("left", (swing("left", (0.6, 1.1)),))])
    assert found.distance == np.inf and found.bodies is None


def test_a_tolerance_that_is_not_positive_is_refused(scene):
    with pytest.raises(ArgumentError, match="'tolerance' must be a positive number"):
        least_clearance(scene, [], tolerance=0.0)
