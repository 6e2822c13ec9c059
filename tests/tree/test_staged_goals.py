"""A pre-grasp's goal list computed as far as the planner uses it (reach.StagedGoals): the
first goal alone is asked for by its straight line, the whole list only when that fails;
the plan must be the one the whole list gives at once."""

from __future__ import annotations

import numpy as np
import pytest
from test_reach_reuse import _back, _contacts, _state, _values

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.request import JointGoal, PlannerOptions
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.scene import scene_from_cell
from taskrunner.shapes import Box
from taskrunner.tree import reach
from taskrunner.tree.behaviours import MoveToGoal
from taskrunner.tree.context import TaskContext
from taskrunner.types import Pose

ARMS = [("servo_arm", "arm", "tool0"), ("panda", "arm", "panda_hand_tcp")]


def _contact(model, group, link, seed):
    return (_contacts(model, link, _state(model, group, seed))
            + _contacts(model, link, _state(model, group, seed + 1)))


@pytest.mark.parametrize(("robot", "group", "link"), ARMS)
@pytest.mark.parametrize("seed", [3, 6])
def test_the_first_goal_is_the_whole_lists_first(robot, group, link, seed, request):
    model = request.getfixturevalue(f"{robot}_model")
    start = model.default_state()
    contact = _contact(model, group, link, seed)
    whole = reach.approach_goals(model, group, link, contact, _back, start, seed=seed)
    staged = reach.staged_approach_goals(model, group, link, contact, _back, start, seed=seed)
    assert not staged.complete
    first = staged.first()
    assert len(first) == 1 and _values(first) == _values(whole[:1])
    assert not staged.complete  # the rest not computed yet
    assert _values(staged.all()) == _values(whole)  # computed on from where first() stopped
    assert staged.complete and len(whole) > 1


@pytest.mark.parametrize(("robot", "group", "link"), ARMS)
def test_a_start_state_among_later_goals_gets_the_whole_list_at_once(robot, group, link,
                                                                       request):
    """A planner answers "already there" before it tries the first goal's line: where the
    start may be a later goal, the first goal alone would give another plan."""
    model = request.getfixturevalue(f"{robot}_model")
    contact = _contact(model, group, link, 3)
    goals = reach.approach_goals(model, group, link, contact, _back, model.default_state(),
                                 seed=11)
    idx = model.indices(model.group(group).joint_names)
    later = 0
    for goal in goals[1:]:
        start = model.state_with(model.default_state(), goal.values)
        staged = reach.staged_approach_goals(model, group, link, contact, _back, start, seed=11)
        found = [np.max(np.abs(np.array(list(g.values.values())) - start[idx]))
                 for g in staged.all()]
        assert min(found) < 1e-9  # the start is one of its own list's goals
        later += int(np.argmin(found)) > 0
        assert staged.complete and _values(staged.first()) == _values(staged.all())
    assert later  # some of them after the first


def test_an_empty_list_gives_what_is_planned_instead(servo_arm_model):
    staged = reach.StagedGoals(servo_arm_model, "arm", iter([]), 6,
                               lambda: (JointGoal({"shoulder_pan": 0.1}),))
    assert _values(staged.first()) == [[0.1]] and staged.complete


# ----------------------------------------------------------------------------- the leaf
@pytest.fixture
def panda_cell(robots_dir):
    return load_cell(robots_dir / "cells" / "panda_table.yaml")


def _plan_with(cell, goals, staged: bool, options: PlannerOptions | None = None):
    """Run a MoveToGoal leaf to ``goals`` (a staged list or the tuple) on the mock backend:
    its trajectory, and the leaf's events."""
    scene = scene_from_cell(cell)
    # A post in the hand's way when the arm turns left (joint 1 at 0.6 rad).
    scene.add_object("post", Box((0.04, 0.04, 0.5)), Pose((0.253, 0.173, 1.35)))
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, scene.state)))
    ctx = TaskContext(cell, scene, InProcessPlanner(), backend)
    model = scene.robot
    idx = model.indices(model.group("arm").joint_names)

    def goal(c):
        if not staged:
            return tuple(goals)
        states = [model.state_with(c.scene.state, g.values) for g in goals]
        return reach.StagedGoals(model, "arm", iter(states), len(goals), tuple)

    leaf = MoveToGoal("to goal", None, ctx, "arm", goal, options)
    leaf.initialise()
    status = leaf.update()
    assert status.value in ("RUNNING", "SUCCESS"), leaf.feedback_message
    assert ctx.executed, leaf.feedback_message
    trajectory = ctx.executed[-1].trajectory
    return trajectory.positions[:, :], trajectory.times, idx, ctx


def _turned(cell, angles):
    start = scene_from_cell(cell).state
    names = cell.model.group("arm").joint_names
    values = dict(zip(names, start[cell.model.indices(names)]))
    return [JointGoal({**values, "panda_joint1": a}) for a in angles]


@pytest.mark.parametrize("angles", [(1.2, -0.5, 1.0), (1.2, 1.0), (-0.5, 1.2)],
                         ids=["first-blocked", "all-blocked", "first-free"])
def test_the_leaf_plans_what_the_whole_list_gives(panda_cell, angles):
    goals = _turned(panda_cell, angles)
    positions, times, _, ctx = _plan_with(panda_cell, goals, staged=False)
    again, again_times, _, staged_ctx = _plan_with(panda_cell, goals, staged=True)
    assert np.array_equal(positions, again) and np.array_equal(times, again_times)
    planned = [e.data["waypoints"] for e in ctx.events.events() if e.kind == "planned"]
    assert planned == [e.data["waypoints"] for e in staged_ctx.events.events()
                       if e.kind == "planned"]
    assert (planned[0] > 2) == (angles == (1.2, 1.0))  # searched only where every line is blocked


def test_a_failed_plan_fails_as_the_whole_list_does(panda_cell):
    goals = _turned(panda_cell, (0.6, 0.62))  # the hand in the post
    messages = []
    for staged in (False, True):
        scene = scene_from_cell(panda_cell)
        scene.add_object("post", Box((0.04, 0.04, 0.5)), Pose((0.253, 0.173, 1.35)))
        names = panda_cell.model.joint_names
        ctx = TaskContext(panda_cell, scene, InProcessPlanner(),
                          MockBackend(names, dict(zip(names, scene.state))))
        model = scene.robot

        def goal(c, staged=staged):
            states = [model.state_with(c.scene.state, g.values) for g in goals]
            return (reach.StagedGoals(model, "arm", iter(states), 2, tuple) if staged
                    else tuple(goals))

        leaf = MoveToGoal("to goal", None, ctx, "arm", goal)
        leaf.initialise()
        assert leaf.update().value == "FAILURE"
        messages.append(leaf.feedback_message)
    assert "in collision" in messages[0] and messages[0] == messages[1]


def test_a_blocked_first_line_asks_again_with_every_goal(panda_cell):
    goals = _turned(panda_cell, (1.2, -0.5))
    positions, _, idx, _ = _plan_with(panda_cell, goals, staged=True)
    # The second goal, by its straight line.
    assert positions.shape[0] >= 2
    assert positions[-1][list(idx).index(0)] == pytest.approx(-0.5)


# ----------------------------------------------------------------------------- memo
@pytest.mark.parametrize(("robot", "group", "link"), ARMS)
def test_a_remembered_choice_is_the_choice_made_afresh(robot, group, link, request,
                                                         monkeypatch):
    """``run-task check`` and the run choose with the same inputs: the second gets the
    first's answers, which are what a fresh choice gives."""
    model = request.getfixturevalue(f"{robot}_model")
    start = model.default_state()
    contact = _contact(model, group, link, 6)
    reach.forget()
    first = reach.approach_goals(model, group, link, contact, _back, start, seed=5)
    solves = []
    monkeypatch.setattr(reach, "_follows", lambda *a, **k: solves.append(a))
    again = reach.approach_goals(model, group, link, contact, _back, start, seed=5)
    assert _values(again) == _values(first) and not solves  # nothing solved again
    monkeypatch.undo()
    reach.forget()
    reach.forget_solvers()  # fresh solvers too
    fresh = reach.approach_goals(model, group, link, contact, _back, start, seed=5)
    assert _values(fresh) == _values(first)
    # Other inputs are another choice: computed, not taken from this one's.
    for other_seed, poses in ((6, contact), (5, contact[1:])):
        known = len(reach._MEMO)
        reach.approach_goals(model, group, link, poses, _back, start, seed=other_seed)
        assert len(reach._MEMO) > known


def test_remembered_states_are_read_only(servo_arm_model):
    model = servo_arm_model
    contact = _contact(model, "arm", "tool0", 3)
    reach.forget()
    found = reach.approximate(model, "arm", "tool0", contact, model.default_state(), 4)
    assert found and not any(a.q.flags.writeable for a in found)
    again = reach.approximate(model, "arm", "tool0", contact, model.default_state(), 4)
    assert [a.q.tobytes() for a in again] == [a.q.tobytes() for a in found]
