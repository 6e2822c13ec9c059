"""Every returned path is collision-free, also past thin obstacles between coarse checks.

The scenes put a thin plate (1-3 mm) across the straight joint-space line from the start to
the goal, often with only an edge or corner in the hand's way, where the search's checks every 0.05 rad (centimetres of fingertip motion) step
over it. Whatever the planner returns is checked independently: every state along the
path such that no point of the arm moves more than 0.1 mm between two of them (from the
Panda's reach, not from the verifier's lever arms), with the scene's boolean check.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from plan_helpers import READY

from taskrunner.errors import PlanningError
from taskrunner.planning import JointGoal, MotionPlanner, PlannerOptions, PlanRequest
from taskrunner.scene import Scene
from taskrunner.scene.sweep import PathVerifier, lever_arms
from taskrunner.shapes import Box
from taskrunner.types import Pose

PANDA_REACH = 1.25  # m: from joint 1's axis to the fingertips, stretched out, rounded up


def _plate_scene(panda_model, rng: np.random.Generator, thickness: float
                 ) -> tuple[Scene, np.ndarray] | None:
    """The Panda at 'ready', a goal state, and a plate across the straight line between."""
    scene = Scene(panda_model)
    scene.set_state(READY)
    robot = scene.robot
    start = scene.state.copy()
    goal = robot.random_state(rng, "arm", base=start)
    if scene.in_collision(goal):
        return None
    t = rng.uniform(0.3, 0.7)
    data = robot.model.createData()
    pin.framesForwardKinematics(robot.model, data, robot.to_pin(start + t * (goal - start)))
    hand = data.oMf[robot.frame_id("panda_hand")]
    rotation = pin.rpy.rpyToMatrix(*rng.uniform(-np.pi, np.pi, 3))
    # Offset in the plate's plane so that often only its edge or corner clips the hand.
    offset = np.array([*rng.uniform(-0.2, 0.2, 2), 0.0])
    centre = hand.translation + hand.rotation @ np.array([0.0, 0.0, 0.1]) + rotation @ offset
    scene.add_object("plate", Box((0.3, 0.3, thickness)),
                     Pose.from_se3(pin.SE3(rotation, centre)))
    if scene.in_collision(start) or scene.in_collision(goal):
        return None
    return scene, goal


def _first_fine_collision(scene: Scene, start: np.ndarray, names, waypoints: np.ndarray,
                          displacement: float) -> np.ndarray | None:
    """Independent check: joint steps with sum |dq| * reach below ``displacement`` (m)."""
    robot = scene.robot
    idx = robot.indices(names)
    q = start.copy()
    for a, b in zip(waypoints[:-1], waypoints[1:]):
        steps = max(1, int(np.ceil(np.sum(np.abs(b - a)) * PANDA_REACH / displacement)))
        for t in np.linspace(0.0, 1.0, steps + 1):
            q[idx] = a + t * (b - a)
            robot.apply_mimic(q)
            if scene.in_collision(q):
                return q.copy()
    return None


def test_lever_arms_bound_every_vertex_displacement(panda_model):
    scene = Scene(panda_model)
    robot = scene.robot
    geometry = scene.checker.geometry_model
    levers = lever_arms(robot, geometry)
    data, geometry_data = robot.model.createData(), geometry.createData()
    rng = np.random.default_rng(3)
    for _ in range(100):
        a = robot.random_state(rng)
        b = a.copy()
        b[robot.active_indices] += rng.normal(0.0, 0.05, len(robot.active_indices))
        robot.apply_mimic(b)
        bound = levers @ np.abs(b - a)
        placed = []
        for q in (a, b):
            pin.updateGeometryPlacements(robot.model, data, geometry, geometry_data,
                                         robot.to_pin(q))
            placed.append([pin.SE3(m) for m in geometry_data.oMg])
        for g, obj in enumerate(geometry.geometryObjects):
            if not hasattr(obj.geometry, "points"):
                continue
            points = np.array(obj.geometry.points())
            moved = [(m[g].rotation @ points.T).T + m[g].translation for m in placed]
            assert np.linalg.norm(moved[1] - moved[0], axis=1).max() <= bound[g] + 1e-12


def test_verifier_rejects_a_straight_line_through_a_thin_plate(panda_model):
    rng = np.random.default_rng(5)
    found = None
    while found is None:
        found = _plate_scene(panda_model, rng, 0.001)
    scene, goal = found
    verifier = PathVerifier(scene.robot, scene.checker)
    result = verifier.verify(np.vstack([scene.state, goal]))
    assert not result.valid
    assert result.pair is not None and "plate/0" in result.pair
    assert result.state is not None and scene.in_collision(result.state)


@pytest.mark.slow
@settings(max_examples=12, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(seed=st.integers(0, 2**31 - 1), thickness=st.floats(0.001, 0.003))
def test_returned_paths_are_free_at_a_tenth_of_a_millimetre(panda_model, seed, thickness):
    found = _plate_scene(panda_model, np.random.default_rng(seed), thickness)
    assume(found is not None)
    assert found is not None
    scene, goal = found
    arm = scene.robot.group("arm")
    request = PlanRequest("arm", JointGoal(dict(zip(arm.joint_names, goal[arm.joint_indices]))),
                          options=PlannerOptions(seed=seed % 1000, planning_time=2.0))
    try:
        result = MotionPlanner(scene).plan(request)
    except PlanningError:
        return  # no path is a correct answer; a wrong path is not
    hit = _first_fine_collision(scene, result.start, result.path.names,
                                result.path.waypoints, 1e-4)
    assert hit is None, f"returned path collides at {hit}"
