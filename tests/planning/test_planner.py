"""The OMPL motion planner: goal kinds, failure reasons, planners, seeds, dual arm, cancel."""

from __future__ import annotations

import time

import numpy as np
import pinocchio as pin
import pytest
from plan_helpers import READY, dense_states

from taskrunner.errors import (
    GoalInCollisionError,
    IkFailedError,
    InvalidStateError,
    PlanningCancelledError,
    PlanningTimeoutError,
    StartInCollisionError,
    UnknownNameError,
)
from taskrunner.kinematics import frame_pose
from taskrunner.planning import (
    PLANNERS,
    JointGoal,
    MotionPlanner,
    NamedGoal,
    PlannerOptions,
    PlanRequest,
    PoseGoal,
)
from taskrunner.shapes import Box, Sphere
from taskrunner.types import Pose

# The hand under the shelf's middle board, pointing forward (+x).
UNDER_SHELF = Pose.from_se3(pin.SE3(pin.rpy.rpyToMatrix(0.0, np.pi / 2, 0.0),
                                    np.array([0.62, 0.0, 0.15])))
REACH_LEFT = {**READY, "panda_joint1": 1.2, "panda_joint2": 0.2, "panda_joint4": -1.8}


def assert_path_is_free(scene, result, resolution=0.005):
    for q in dense_states(scene, result, resolution):
        assert not scene.in_collision(q), [(c.a, c.b) for c in scene.collisions(q)]
        assert scene.robot.within_limits(q)


def test_joint_goal_path_starts_at_start_ends_at_goal_and_is_free(shelf_scene):
    result = MotionPlanner(shelf_scene).plan(PlanRequest("arm", JointGoal(REACH_LEFT)))
    idx = shelf_scene.robot.indices(result.path.names)
    assert result.path.names == shelf_scene.robot.group("arm").joint_names
    assert result.path.waypoints[0] == pytest.approx(shelf_scene.state[idx])
    assert result.path.waypoints[-1] == pytest.approx([REACH_LEFT[n] for n in result.path.names])
    assert result.end[idx] == pytest.approx(result.path.waypoints[-1])
    assert_path_is_free(shelf_scene, result)
    # The fingers were not part of the plan: they stay where the start had them.
    assert result.end[7] == shelf_scene.state[7]


def test_named_goal_moves_the_servo_arm_home_to_candle(servo_arm_model):
    from taskrunner.scene import Scene

    scene = Scene(servo_arm_model)
    scene.set_state(servo_arm_model.named_state("arm", "home"))
    result = MotionPlanner(scene).plan(PlanRequest("arm", NamedGoal("Candle")))
    assert result.path.waypoints[-1] == pytest.approx([1.5708] + [-1.5708] * 4)
    assert_path_is_free(scene, result)


def test_pose_goal_reaches_under_the_shelf(shelf_scene):
    result = MotionPlanner(shelf_scene).plan(PlanRequest("arm", PoseGoal(UNDER_SHELF)))
    reached = frame_pose(shelf_scene.robot, result.end, "panda_hand_tcp")
    assert reached.translation == pytest.approx(UNDER_SHELF.xyz, abs=2e-4)
    assert np.linalg.norm(pin.log3(reached.rotation.T @ UNDER_SHELF.se3.rotation)) < 2e-4
    assert_path_is_free(shelf_scene, result)


def test_several_goals_reach_one_even_if_another_is_out_of_reach(shelf_scene):
    far = Pose((2.0, 0.0, 0.5))
    result = MotionPlanner(shelf_scene).plan(
        PlanRequest("arm", (PoseGoal(far), JointGoal(REACH_LEFT))))
    assert result.goal_index == 1


def test_start_in_collision_names_the_pair(shelf_scene):
    start = shelf_scene.robot.state_with(shelf_scene.state, {"panda_joint2": 1.5, "panda_joint4": -0.2})
    with pytest.raises(StartInCollisionError) as err:
        MotionPlanner(shelf_scene).plan(PlanRequest("arm", JointGoal(READY), start=start))
    assert err.value.pairs
    assert any("table" in pair or "shelf_board" in pair for pair in err.value.pairs)
    assert "start state of group 'arm' is in collision" in str(err.value)


def test_goal_in_collision_names_the_pair(shelf_scene):
    shelf_scene.add_object("ball", Sphere(0.08), Pose((0.5, 0.0, 0.5)))
    goal = Pose.from_se3(pin.SE3(pin.rpy.rpyToMatrix(np.pi, 0.0, 0.0), np.array([0.5, 0.0, 0.5])))
    with pytest.raises(GoalInCollisionError) as err:
        MotionPlanner(shelf_scene).plan(PlanRequest("arm", PoseGoal(goal)))
    assert any("ball" in pair for pair in err.value.pairs)


def test_unreachable_pose_is_an_ik_failure(shelf_scene):
    with pytest.raises(IkFailedError, match="no IK solution for group 'arm'"):
        MotionPlanner(shelf_scene).plan(PlanRequest("arm", PoseGoal(Pose((2.0, 0.0, 0.5)))))


def test_goal_outside_the_limits_and_joints_not_in_the_group_are_refused(shelf_scene):
    planner = MotionPlanner(shelf_scene)
    with pytest.raises(InvalidStateError, match="'panda_joint4' = 0.5 is above its upper bound -0.0698 by 0.57 rad"):
        planner.plan(PlanRequest("arm", JointGoal({"panda_joint4": 0.5})))
    with pytest.raises(InvalidStateError, match="not active joints of group 'arm'"):
        planner.plan(PlanRequest("arm", JointGoal({"panda_finger_joint1": 0.02})))
    with pytest.raises(UnknownNameError, match="unknown group 'amr'"):
        planner.plan(PlanRequest("amr", JointGoal(READY)))


def test_no_path_within_the_planning_time_is_a_timeout(shelf_scene):
    # Under the shelf board is a detour: far more than 0.1 ms of search.
    with pytest.raises(PlanningTimeoutError,
                       match=r"no path for group 'arm' found by RRTConnect in 2 attempt\(s\)"):
        MotionPlanner(shelf_scene).plan(PlanRequest(
            "arm", PoseGoal(UNDER_SHELF),
            options=PlannerOptions(planning_time=1e-4, attempts=2, direct=False)))


@pytest.mark.parametrize("planner", PLANNERS)
def test_every_planner_by_name_solves_a_shelf_query(shelf_scene, planner):
    options = PlannerOptions(planner=planner, planning_time=5.0, direct=False)
    result = MotionPlanner(shelf_scene).plan(PlanRequest("arm", JointGoal(REACH_LEFT),
                                                         options=options))
    assert result.planner == planner
    assert_path_is_free(shelf_scene, result, resolution=0.01)


def test_unknown_planner_name_is_refused():
    with pytest.raises(ValueError, match="'planner' must be one of RRTConnect"):
        PlannerOptions(planner="RRTConect")


def test_the_same_seed_gives_the_same_path(shelf_scene):
    planner = MotionPlanner(shelf_scene)
    paths = [planner.plan(PlanRequest("arm", PoseGoal(UNDER_SHELF),
                                      options=PlannerOptions(seed=seed))).path.waypoints
             for seed in (7, 7, 8)]
    assert np.array_equal(paths[0], paths[1])
    assert paths[0].shape != paths[2].shape or not np.allclose(paths[0], paths[2])


def test_both_arms_swap_sides_without_touching_each_other(servo_pair_scene):
    model = servo_pair_scene.robot
    servo_pair_scene.set_state(model.named_state("both_arms", "HandOff"))
    # Left arm to the right of its base and right arm to the left: they must pass.
    goal = {"left_Revolute 1": 0.9, "right_Revolute 1": 0.9,
            **{f"{side}_Revolute {i}": v for side in ("left", "right")
               for i, v in ((2, -0.9), (3, -0.5), (4, -0.4))}}
    result = MotionPlanner(servo_pair_scene).plan(PlanRequest("both_arms", JointGoal(goal)))
    assert len(result.path.names) == 10
    assert_path_is_free(servo_pair_scene, result, resolution=0.005)


def test_one_arm_plans_around_the_other_holding_an_object(servo_pair_scene):
    model = servo_pair_scene.robot
    servo_pair_scene.set_state(model.named_state("both_arms", "HandOff"))
    servo_pair_scene.set_state(model.named_state("left_arm", "Candle"))
    servo_pair_scene.add_object("part", Box((0.04, 0.04, 0.04)), Pose((0.0, 0.0, 0.0), frame="right_tool0"),
                                attach_to="right_tool0",
                                touch_links=["right_finger_left_1", "right_finger_right_1"])
    result = MotionPlanner(servo_pair_scene).plan(
        PlanRequest("left_arm", NamedGoal("HandOff")))
    assert_path_is_free(servo_pair_scene, result)
    # The right arm held still for the whole path.
    right = model.group("right_arm").joint_indices
    assert all(np.array_equal(q[right], result.start[right])
               for q in dense_states(servo_pair_scene, result))


def test_cancelling_stops_an_in_flight_plan(shelf_scene):
    polls = []

    def should_stop():
        polls.append(1)
        return len(polls) >= 3

    with pytest.raises(PlanningCancelledError, match="planning for group 'arm' was cancelled"):
        MotionPlanner(shelf_scene).plan(
            PlanRequest("arm", PoseGoal(UNDER_SHELF), options=PlannerOptions(planning_time=30.0, direct=False)),
            should_stop=should_stop)
    assert len(polls) >= 3


def test_pose_goal_in_the_tool_frame_is_taken_at_the_start_state(shelf_scene):
    start_tcp = frame_pose(shelf_scene.robot, shelf_scene.state, "panda_hand_tcp")
    goal = PoseGoal(Pose((0.0, 0.0, 0.1), frame="panda_hand_tcp"))  # 10 cm along the tool's z
    result = MotionPlanner(shelf_scene).plan(PlanRequest("arm", goal))
    reached = frame_pose(shelf_scene.robot, result.end, "panda_hand_tcp")
    expected = start_tcp * pin.SE3(np.eye(3), np.array([0.0, 0.0, 0.1]))
    assert reached.translation == pytest.approx(expected.translation, abs=2e-4)


@pytest.mark.parametrize("planner", ["PRM", "PRMstar"])
def test_prm_with_several_goals_plans_to_one_instead_of_deadlocking(shelf_scene, planner):
    other = {**REACH_LEFT, "panda_joint1": -1.2}
    options = PlannerOptions(planner=planner, planning_time=2.0, direct=False)
    result = MotionPlanner(shelf_scene).plan(
        PlanRequest("arm", (JointGoal(REACH_LEFT), JointGoal(other)), options=options))
    assert result.goal_index in (0, 1)
    assert_path_is_free(shelf_scene, result, resolution=0.01)


def test_a_free_straight_line_is_returned_without_a_search(shelf_scene):
    # In front of the shelf, a small joint move: nothing in the way.
    goal = {**READY, "panda_joint1": READY["panda_joint1"] + 0.3}
    result = MotionPlanner(shelf_scene).plan(PlanRequest("arm", JointGoal(goal)))
    assert result.direct and result.planning_time == 0.0 and result.searches == 0
    assert len(result.path.waypoints) == 2
    assert result.checks > 0 and result.verify_time > 0.0
    assert_path_is_free(shelf_scene, result)


def test_a_blocked_straight_line_falls_back_to_the_search(shelf_scene):
    # A box straddling the straight line's middle: the line is blocked, a detour is not.
    model = shelf_scene.robot
    idx = model.group("arm").joint_indices
    goal = {**READY, "panda_joint1": READY["panda_joint1"] + 1.2}
    middle = shelf_scene.state.copy()
    middle[idx[0]] += 0.6
    hand = frame_pose(model, middle, "panda_hand_tcp")
    scene = shelf_scene.copy()
    scene.add_object("post", Sphere(0.04), Pose(tuple(hand.translation)))
    result = MotionPlanner(scene).plan(PlanRequest("arm", JointGoal(goal)))
    assert not result.direct and result.planning_time > 0.0 and result.searches >= 1
    assert len(result.path.waypoints) > 2
    assert_path_is_free(scene, result)
    # Without the direct attempt the same request searches from the start.
    searched = MotionPlanner(scene).plan(PlanRequest("arm", JointGoal(goal),
                                                     options=PlannerOptions(direct=False)))
    assert not searched.direct
    assert_path_is_free(scene, searched)


def _plate_across_the_turn(scene, turn: float, t: float, size: float):  # type: ignore[no-untyped-def]
    """A copy of ``scene`` with a 2 mm plate (``size`` square) across the hand's way at
    fraction ``t`` of a ``turn`` of joint 1, and the states of that turn by fraction."""
    model = scene.robot
    first = model.group("arm").joint_indices[0]

    def along(f: float) -> np.ndarray:
        q = scene.state.copy()
        q[first] += f * turn
        return q

    here, ahead = (frame_pose(model, along(f), "panda_hand").translation for f in (t, t + 0.01))
    normal = (ahead - here) / np.linalg.norm(ahead - here)
    up = np.array([0.0, 0.0, 1.0]) - normal[2] * normal
    up /= np.linalg.norm(up)
    rotation = np.column_stack([normal, np.cross(up, normal), up])
    plated = scene.copy()
    plated.add_object("plate", Box((0.002, size, size)), Pose.from_se3(pin.SE3(rotation, here)))
    return plated, along


def test_the_direct_line_is_verified_exactly_not_only_sampled(shelf_scene):
    # Sampled every 0.8 rad, the straight line steps over a 2 mm plate across the hand's
    # way; the exact verification finds it, and the search plans around it.
    turn = 1.6
    goal = {**READY, "panda_joint1": READY["panda_joint1"] + turn}
    options = PlannerOptions(longest_valid_segment=turn / 2)
    scene, along = _plate_across_the_turn(shelf_scene, turn, 0.25, 0.1)
    assert scene.in_collision(along(0.25))
    assert not any(scene.in_collision(along(t)) for t in (0.0, 0.5, 1.0))  # the samples miss it
    result = MotionPlanner(scene).plan(PlanRequest("arm", JointGoal(goal), options=options))
    assert not result.direct and result.searches >= 1
    assert_path_is_free(scene, result)


def test_a_path_the_verification_turns_down_is_searched_again_finer(shelf_scene):
    # Checked every 0.4 rad, the search's first path steps through a 2 mm plate across
    # the hand's way; the verification turns it down and a finer search goes around.
    goal = {**READY, "panda_joint1": READY["panda_joint1"] + 1.6}
    scene, _ = _plate_across_the_turn(shelf_scene, 1.6, 0.5, 0.12)
    result = MotionPlanner(scene).plan(PlanRequest("arm", JointGoal(goal), options=PlannerOptions(
        longest_valid_segment=0.4, direct=False, seed=0)))
    assert result.searches >= 2
    assert_path_is_free(scene, result)


def test_finer_searches_share_the_requests_search_time(shelf_scene, monkeypatch):
    # Every path found is turned down: the finer searches run only while the request's
    # search time lasts, and the error says so.
    from taskrunner.planning import planner as planner_module
    from taskrunner.scene.path_verifier import PathVerification

    calls = []

    def refuse(self, states, margin):  # type: ignore[no-untyped-def]
        calls.append(1)
        time.sleep(0.6)  # past the request's 0.5 s
        return PathVerification(False, 0, 1, 0.6, 0.5, ("panda_hand/0", "shelf/0"),
                                states[0], 0)

    monkeypatch.setattr(planner_module.MotionPlanner, "verify_states", refuse)
    goal = {**READY, "panda_joint1": READY["panda_joint1"] + 0.3}  # a free straight line
    with pytest.raises(PlanningTimeoutError, match=r"search ran out before a finer search"):
        MotionPlanner(shelf_scene).plan(PlanRequest("arm", JointGoal(goal), options=PlannerOptions(
            planning_time=0.5, direct=False)))
    assert len(calls) <= 2  # the first search's path (shortcut and raw), no finer search


def test_restarts_are_counted_in_checks_so_a_seed_gives_the_same_path(shelf_scene, monkeypatch):
    # Restart after very few checks: the search starts over many times (new seeds, twice
    # the checks each time) and still finds a free path; the same options give the same
    # path, whatever the time it took.
    from ompl import geometric as og

    created = []
    original = og.RRTConnect.__init__

    def counting(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        created.append(1)
        original(self, *args, **kwargs)

    monkeypatch.setattr(og.RRTConnect, "__init__", counting)
    request = PlanRequest("arm", PoseGoal(UNDER_SHELF), options=PlannerOptions(
        direct=False, restart=1, seed=0))
    first = MotionPlanner(shelf_scene).plan(request)
    assert len(created) > 1  # it restarted
    assert_path_is_free(shelf_scene, first)
    created.clear()
    again = MotionPlanner(shelf_scene).plan(request)
    assert np.array_equal(first.path.waypoints, again.path.waypoints)
    # Never restarting: one planner.
    created.clear()
    MotionPlanner(shelf_scene).plan(PlanRequest("arm", PoseGoal(UNDER_SHELF), options=PlannerOptions(
        direct=False, restart=0, seed=0)))
    assert len(created) == 1


@pytest.mark.parametrize("value", [-1, 0.5, True])
def test_a_bad_restart_count_is_refused(value):
    with pytest.raises(ValueError, match="'restart' must be an integer >= 0"):
        PlannerOptions(restart=value)


def test_a_straight_timed_trajectory_is_not_verified_twice(shelf_scene, monkeypatch):
    # The closed-form timing of a straight line keeps every sample on the segment that
    # was verified; a path with a bend is timed by a spline and its samples are verified.
    from taskrunner.planning import planner as planner_module
    from taskrunner.planning.timing import TimingOptions

    calls = []
    real = planner_module.MotionPlanner.verify_states

    def counted(self, states, margin):  # type: ignore[no-untyped-def]
        calls.append(len(states))
        return real(self, states, margin)

    monkeypatch.setattr(planner_module.MotionPlanner, "verify_states", counted)
    goal = {**READY, "panda_joint1": READY["panda_joint1"] + 0.3}
    straight = MotionPlanner(shelf_scene).plan(
        PlanRequest("arm", JointGoal(goal), timing=TimingOptions()))
    assert straight.direct and calls == [2]  # the segment only
    assert planner_module._on_segment(np.asarray(straight.path.waypoints),
                                      straight.trajectory.positions)
    calls.clear()
    bent = MotionPlanner(shelf_scene).plan(
        PlanRequest("arm", PoseGoal(UNDER_SHELF), options=PlannerOptions(direct=False),
                    timing=TimingOptions()))
    assert len(bent.path.waypoints) > 2 and len(calls) >= 2
    assert calls[-1] == len(bent.trajectory.positions)  # the samples were verified


def test_an_edge_ending_at_a_state_known_valid_does_not_check_it_again(shelf_scene):
    planner = MotionPlanner(shelf_scene)
    group = shelf_scene.robot.group("arm")
    idx = group.joint_indices
    a = shelf_scene.state[idx].copy()
    b = a.copy()
    b[0] += 0.01  # one step: only the end would be checked
    count = [0]
    known: set[bytes] = set()
    edge = planner._edge_validity(group, shelf_scene.state, 0.05, count, known)
    assert edge(a, b) and count == [1] and b.tobytes() in known
    assert edge(a, b) and count == [1]  # known now
    # Without the set, every call checks it; a colliding end is never remembered.
    plain = planner._edge_validity(group, shelf_scene.state, 0.05, count)
    assert plain(a, b) and plain(a, b) and count == [3]
    scene = shelf_scene.copy()
    model = scene.robot
    hand = frame_pose(model, model.state_with(scene.state, dict(zip(group.joint_names, b))),
                      "panda_hand").translation
    scene.add_object("post", Sphere(0.03), Pose(tuple(hand)))
    blocked = MotionPlanner(scene)._edge_validity(group, scene.state, 0.05, count, known := set())
    assert not blocked(a, b) and not known


def test_the_finer_searches_halve_the_segment_down_to_the_finest():
    from taskrunner.planning.planner import FINEST_SEGMENT, refined_segments

    assert refined_segments(0.1) == pytest.approx([0.1, 0.05, 0.025, 0.0125])
    assert refined_segments(0.05) == pytest.approx([0.05, 0.025, 0.0125])
    assert refined_segments(0.01) == pytest.approx([0.01, 0.005, 0.0025])  # three at least
    assert refined_segments(0.4)[-1] == pytest.approx(FINEST_SEGMENT)
