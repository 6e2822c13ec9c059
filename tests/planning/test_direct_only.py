"""PlannerOptions.direct_only: a straight line to a goal state, or NoDirectPathError
without a search (a caller then asks again with more goals)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from plan_helpers import READY

from taskrunner.errors import NoDirectPathError, PlanningError
from taskrunner.kinematics import frame_pose
from taskrunner.planning import JointGoal, MotionPlanner, PlannerOptions, PlanRequest
from taskrunner.shapes import Sphere
from taskrunner.types import Pose

ONLY = PlannerOptions(direct_only=True)


def _blocked(scene):
    """A copy of ``scene`` with a ball where the hand passes halfway through a 1.2 rad
    turn of joint 1 (the straight line to READY + 1.2 is blocked, a detour is not)."""
    model = scene.robot
    middle = scene.state.copy()
    middle[model.group("arm").joint_indices[0]] += 0.6
    hand = frame_pose(model, middle, "panda_hand_tcp")
    blocked = scene.copy()
    blocked.add_object("post", Sphere(0.04), Pose(tuple(hand.translation)))
    return blocked


def test_a_free_line_is_the_answer_with_or_without_direct_only(shelf_scene):
    goal = JointGoal({**READY, "panda_joint1": READY["panda_joint1"] + 0.3})
    planner = MotionPlanner(shelf_scene)
    only = planner.plan(PlanRequest("arm", goal, options=ONLY))
    usual = planner.plan(PlanRequest("arm", goal))
    assert only.direct and only.goal_index == usual.goal_index == 0
    assert np.array_equal(only.path.waypoints, usual.path.waypoints)


def test_blocked_lines_raise_without_a_search(shelf_scene):
    scene = _blocked(shelf_scene)
    far = JointGoal({**READY, "panda_joint1": READY["panda_joint1"] + 1.2})
    near = JointGoal({**READY, "panda_joint1": READY["panda_joint1"] - 0.3})
    planner = MotionPlanner(scene)
    with pytest.raises(NoDirectPathError, match="1 goal states of group 'arm' is blocked"):
        planner.plan(PlanRequest("arm", far, options=ONLY))
    # Another goal's free line is taken, in the request's order.
    result = planner.plan(PlanRequest("arm", (far, near), options=ONLY))
    assert result.direct and result.goal_index == 1
    # Without direct_only, the same request searches.
    assert not planner.plan(PlanRequest("arm", far)).direct


def test_the_error_crosses_a_process_boundary_and_is_a_planning_error():
    error = pickle.loads(pickle.dumps(NoDirectPathError("blocked")))
    assert isinstance(error, PlanningError) and str(error) == "blocked"


def test_direct_only_needs_the_direct_attempt():
    with pytest.raises(ValueError, match="'direct_only' needs 'direct'"):
        PlannerOptions(direct=False, direct_only=True)
