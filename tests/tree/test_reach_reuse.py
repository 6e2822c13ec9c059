"""The goal choice of a straight approach (taskrunner.tree.reach) keeps IK solvers between
calls, follows a full-pose arm's lines only as far as the goal list needs, and compares a
wrist roll's candidates without forward kinematics: none of this may change a goal."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import IkFailedError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.tree import aiming, reach


def _tool_pose(model, link: str, q: np.ndarray) -> pin.SE3:
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, model.to_pin(q))
    return pin.SE3(data.oMf[model.frame_id(link)])


def _state(model, group: str, seed: int) -> np.ndarray:
    """A state with the group's joints well inside their limits."""
    rng = np.random.default_rng(seed)
    q = model.default_state()
    idx = model.indices(model.group(group).joint_names)
    lower, upper = model.lower[idx], model.upper[idx]
    q[idx] = rng.uniform(lower + 0.3 * (upper - lower), upper - 0.3 * (upper - lower))
    return q


def _contacts(model, link: str, q: np.ndarray) -> list[pin.SE3]:
    """The link's pose at ``q`` and the same turned half a turn about its z axis."""
    pose = _tool_pose(model, link, q)
    return [pose, pose * pin.SE3(pin.exp3(np.array([0.0, 0.0, math.pi])), np.zeros(3))]


def _back(i: int, pose: pin.SE3) -> np.ndarray:
    """2 cm back along the link's z axis (as a pre-grasp backs off from a grasp)."""
    return -pose.rotation[:, 2] * 0.02


def _values(goals) -> list[list[float]]:
    return [list(g.values.values()) for g in goals]


@pytest.mark.parametrize(("robot", "group", "link"),
                         [("servo_arm", "arm", "tool0"), ("panda", "arm", "panda_hand_tcp")])
def test_goals_do_not_depend_on_earlier_calls(robot, group, link, request):
    model = request.getfixturevalue(f"{robot}_model")
    start = model.default_state()
    a = _contacts(model, link, _state(model, group, 1))
    b = _contacts(model, link, _state(model, group, 2))
    reach.forget_solvers()  # a fresh solver
    first = reach.approach_goals(model, group, link, a, _back, start, seed=7)
    reach.approach_goals(model, group, link, b, _back, start, seed=8)  # another choice between
    again = reach.approach_goals(model, group, link, a, _back, start, seed=7)
    assert first and _values(first) == _values(again)
    # One solver per model, group and link in this thread, reused.
    entry = reach._SOLVERS.models[id(model)]
    assert list(entry[1]) == [(group, link)]


def test_a_full_pose_arm_gets_the_goals_of_following_every_line(panda_model):
    """Following the lines as the goal list takes them keeps the goals of following them
    all first and interleaving the contact poses' followers."""
    model, group, link = panda_model, "arm", "panda_hand_tcp"
    start = model.default_state()
    contact = _contacts(model, link, _state(model, group, 3)) + \
        _contacts(model, link, _state(model, group, 4))
    goals = reach.approach_goals(model, group, link, contact, _back, start, seed=11, keep=3)
    # The reference: every line followed first.
    solver = IkSolver(model, group, frame=link)
    options = IkOptions(position_only=False, num_solutions=reach.FULL_POSE_SOLUTIONS, seed=11,
                        timeout=1.0, attempts=20 * reach.FULL_POSE_SOLUTIONS)
    found = []
    for there in contact:
        away = pin.SE3(there.rotation, there.translation + _back(0, there))
        try:
            solutions = solver.solve_all(away, seed_q=start, options=options)
        except IkFailedError:
            continue
        found.append([np.array(s.q) for s in solutions
                      if reach._follows(solver, np.array(s.q), away, there) is not None])
    states = [q for turn in itertools.zip_longest(*found) for q in turn if q is not None]
    expected = reach._joint_goals(model, group, states, 6)
    assert len(goals) == 6
    assert _values(goals) == _values(expected)


def _rolled_by_forward_kinematics(fk, roll, q, pose, model, grasping):
    """The roll choice made with forward kinematics at every candidate: the closing axis
    (y) turned onto the wanted one's projection, either sense, within the limits."""
    index, sense = roll
    now = fk(q).rotation
    z, y = now[:, 2], now[:, 1]
    want = pose.rotation[:, 1] - (pose.rotation[:, 1] @ z) * z
    turn = math.atan2(float(np.cross(y, want) @ z), float(y @ want))
    options = []
    for extra in (0.0, math.pi, -math.pi, 2 * math.pi, -2 * math.pi):
        value = q[index] + sense * (turn + extra)
        if model.lower[index] - 1e-9 <= value <= model.upper[index] + 1e-9:
            trial = q.copy()
            trial[index] = value
            options.append((reach.orientation_error(fk(trial), pose, grasping), value))
    return options


def test_the_wrist_roll_chosen_is_the_one_forward_kinematics_finds_nearest(servo_arm_model):
    model, link = servo_arm_model, "tool0"
    fk = aiming.Frames(model, link)
    roll = reach.wrist_roll(model, "arm", link, model.default_state())
    assert roll is not None
    index = roll[0]
    rng = np.random.default_rng(5)
    compared = 0
    for k in range(60):
        q = _state(model, "arm", 100 + k)
        wanted = pin.SE3(pin.exp3(rng.normal(size=3)), np.zeros(3))
        grasping = bool(k % 2)
        chosen = aiming.rolled(fk, roll, q, wanted, model, grasping)
        others = np.delete(np.arange(len(q)), index)
        assert np.array_equal(chosen[others], q[others])
        options = _rolled_by_forward_kinematics(fk, roll, q, wanted, model, grasping)
        if not options:
            assert np.array_equal(chosen, q)
            continue
        errors = sorted(e for e, _ in options)
        if len(errors) > 1 and errors[-1] - errors[0] < 1e-6:
            continue  # a tie: either is right
        best = min(options, key=lambda o: o[0])
        # The same orientation (a whole turn apart at most) as forward kinematics' choice.
        difference = math.remainder(chosen[index] - best[1], 2 * math.pi)
        assert abs(difference) < 1e-9
        assert reach.orientation_error(fk(chosen), wanted, grasping) == pytest.approx(
            best[0], abs=1e-9)
        compared += 1
    assert compared > 40


def test_a_cell_loaded_again_reuses_the_remembered_goal_choices(servo_arm_model, robots_dir):
    """The memo is keyed by the model's content digest, as the check's goal choices are:
    a second load of the same files (a run after ``run-task check`` on a cell loaded
    again) finds every choice the first load made, and gets the same goals."""
    from taskrunner.robot import load_robot

    model, again = servo_arm_model, load_robot(robots_dir / "servo_arm")
    assert again is not model
    start = model.default_state()
    contacts = _contacts(model, "tool0", _state(model, "arm", 3))
    reach.forget()
    first = reach.approach_goals(model, "arm", "tool0", contacts, _back, start, seed=5)
    remembered = len(reach._MEMO)
    assert remembered > 0
    second = reach.approach_goals(again, "arm", "tool0", contacts, _back, start, seed=5)
    assert len(reach._MEMO) == remembered  # every choice found, none made anew
    assert _values(second) == _values(first)


def test_the_solver_cache_keeps_a_few_models_not_every_model_ever_checked(robots_dir):
    """A long-lived process (a server's check worker) loads a new model per check: the
    solvers' cache must let the old ones go (it kept every one: 31 MiB a 60 checks)."""
    import gc
    import weakref

    from taskrunner.robot import load_robot

    gone = []
    for _ in range(reach._SOLVER_MODELS + 3):
        model = load_robot(robots_dir / "servo_arm")
        reach._solver(model, "arm", "tool0")
        gone.append(weakref.ref(model))
        del model
    gc.collect()
    alive = [ref for ref in gone if ref() is not None]
    assert len(alive) == reach._SOLVER_MODELS
    assert all(ref() is not None for ref in gone[-reach._SOLVER_MODELS:])  # the recent ones


def test_a_models_digest_does_not_change_when_coal_computes_its_boxes(robots_dir):
    """coal computes a shape's local box when first asked (the path verifier asks): the
    digest that keys remembered choices must be the same before and after, else a run
    after a check on a model the verifier used misses the check's choices."""
    from taskrunner.robot import load_robot
    from taskrunner.scene import Scene
    from taskrunner.tree import choice

    model = load_robot(robots_dir / "servo_arm")
    before = choice.model_key(model)
    Scene(model).path_verifier()
    choice._MODEL_KEYS.clear()  # computed again, not the cached answer
    assert choice.model_key(model) == before
