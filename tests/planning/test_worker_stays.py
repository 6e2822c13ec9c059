"""A planning worker answers a request to stay where the group is in the caller's process:
the same answer as the planner's, at once, without waiting for the worker to load."""

from __future__ import annotations

import numpy as np
import pytest
from plan_helpers import READY

from taskrunner.errors import StartInCollisionError, UnknownNameError
from taskrunner.planning import JointGoal, MotionPlanner, PlanRequest
from taskrunner.planning.request import NamedGoal, PoseGoal
from taskrunner.planning.timing import TimingOptions
from taskrunner.planning.worker import PlanningWorker, stays
from taskrunner.shapes import Box
from taskrunner.types import Pose

MOVED = {**READY, "panda_joint1": 0.9}


@pytest.fixture
def scene(shelf_scene):
    return shelf_scene  # the Panda at 'ready' before a table and a shelf (conftest)


@pytest.fixture(scope="module")
def loading_worker(robots_dir, example_robot_data):
    """A worker whose process has just been started (not waited for)."""
    with PlanningWorker(robots_dir / "panda", wait_ready=False) as worker:
        yield worker


def test_stays_only_for_a_joint_goal_at_the_start(scene):
    arm = {name: READY[name] for name in READY if name.startswith("panda_joint")}
    assert stays(scene, PlanRequest("arm", JointGoal(arm)))
    assert stays(scene, PlanRequest("arm", JointGoal({"panda_joint3": READY["panda_joint3"]})))
    assert stays(scene, PlanRequest("arm", (JointGoal(MOVED), JointGoal(arm))))  # one of them
    start = scene.robot.state_with(scene.state, MOVED)
    assert stays(scene, PlanRequest("arm", JointGoal(MOVED), start=start))  # the request's start
    assert not stays(scene, PlanRequest("arm", JointGoal(MOVED)))
    assert not stays(scene, PlanRequest("arm", JointGoal({"panda_joint1": READY["panda_joint1"]
                                                          + 1e-6})))
    assert not stays(scene, PlanRequest("arm", NamedGoal("ready")))  # resolved by the planner
    pose = Pose((0.3, 0.0, 0.5))
    assert not stays(scene, PlanRequest("arm", (JointGoal(arm), PoseGoal(pose))))  # IK: worker
    assert not stays(scene, PlanRequest("arm", JointGoal(arm), timing=TimingOptions()))
    assert not stays(scene, PlanRequest("arm", JointGoal({"no_such_joint": 0.0})))
    assert not stays(scene, PlanRequest("arm", JointGoal(arm), start=np.zeros(3)))  # bad shape


def test_a_request_to_stay_is_answered_without_waiting_for_the_worker(loading_worker, scene):
    arm = {name: READY[name] for name in READY if name.startswith("panda_joint")}
    request = PlanRequest("arm", JointGoal(arm))
    handle = loading_worker.submit(scene, request)
    assert handle.done()
    assert not loading_worker._ready  # nothing was read from the worker process
    result = handle.result(0.0)
    expected = MotionPlanner(scene).plan(request)
    assert np.array_equal(result.path.waypoints, expected.path.waypoints)
    assert result.path.names == expected.path.names
    assert np.array_equal(result.start, expected.start)
    assert np.array_equal(result.end, expected.end)
    assert result.goal_index == expected.goal_index == 0
    assert len(result.path.waypoints) == 2
    assert np.array_equal(result.path.waypoints[0], result.path.waypoints[1])


def test_a_request_to_stay_still_gets_the_planners_errors(loading_worker, scene):
    hand = scene.link_pose("panda_hand").se3.translation
    scene.add_object("crate", Box((0.3, 0.3, 0.3)), Pose(tuple(hand)))
    arm = {name: READY[name] for name in READY if name.startswith("panda_joint")}
    handle = loading_worker.submit(scene, PlanRequest("arm", JointGoal(arm)))
    with pytest.raises(StartInCollisionError, match="crate"):
        handle.result(0.0)
    with pytest.raises(UnknownNameError):  # an unknown group: the planner's message
        loading_worker.submit(scene, PlanRequest("nope", JointGoal(arm))).result(0.0)


def test_the_worker_plans_the_other_requests_after_one_that_stayed(loading_worker, scene):
    arm = {name: READY[name] for name in READY if name.startswith("panda_joint")}
    loading_worker.submit(scene, PlanRequest("arm", JointGoal(arm))).result(0.0)
    moved = loading_worker.plan(scene, PlanRequest("arm", JointGoal(MOVED)), timeout=120.0)
    assert moved.path.waypoints[-1][0] == pytest.approx(MOVED["panda_joint1"], abs=1e-9)
    assert loading_worker._ready


def test_a_runner_goes_on_when_the_plan_it_waits_for_is_answered():
    import threading
    from types import SimpleNamespace

    from taskrunner.runtime.runner import Runner

    class Ticket:
        def __init__(self, answered: bool) -> None:
            self.answered, self.waited = answered, []

        def done(self) -> bool:
            return self.answered

        def wait(self, timeout: float) -> bool:
            self.waited.append(timeout)
            return True

    cancel = threading.Event()
    pending, answered = Ticket(False), Ticket(True)
    for leaf, waits in ((SimpleNamespace(ticket=pending), [0.01]),
                        (SimpleNamespace(ticket=answered), []),  # waits out the period
                        (SimpleNamespace(ticket=None), []), (None, [])):
        runner = SimpleNamespace(current_leaf=lambda leaf=leaf: leaf, _cancel=cancel)
        Runner._pause(runner, 0.01)  # type: ignore[arg-type]
        assert leaf is None or leaf.ticket is None or leaf.ticket.waited == waits
    cancel.set()  # cancelled: no waiting on a plan
    runner = SimpleNamespace(current_leaf=lambda: SimpleNamespace(ticket=pending), _cancel=cancel)
    Runner._pause(runner, 0.01)  # type: ignore[arg-type]
    assert pending.waited == [0.01]
