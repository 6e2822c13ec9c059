"""IK answers do not depend on the machine's load: the default budget counts attempts.

The same seeded requests are solved on the machine as it is, then again beside CPU-spinning
processes (more of them than the machine has cores to spare), and the answers must be the
same to the bit: solutions, their attempts and iterations, failures and their best
residuals. The planner's goal sampling (:func:`pose_goal_states`) is included.
"""

from __future__ import annotations

import multiprocessing
import time

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.kinematics.ik import default_attempts
from taskrunner.planning.goal_states import pose_goal_states
from taskrunner.planning.request import PlannerOptions, PoseGoal
from taskrunner.robot.moveit_yaml import KinematicsSettings
from taskrunner.types import Pose

SPINNERS = 3


def _spin() -> None:  # pragma: no cover - runs in a child process
    x = 0
    while True:
        x = (x * 1103515245 + 12345) % 2**31


def _requests(model, group: str, count: int, seed: int, position_only: bool):  # type: ignore[no-untyped-def]
    """``count`` targets: the frame's pose at seeded random states (reachable), a few
    moved 0.5 m out (mostly not), each with its own seed state and search seed."""
    rng = np.random.default_rng(seed)
    solver = IkSolver(model, group)
    data = model.model.createData()
    frame = model.frame_id(solver.frame)
    out = []
    for k in range(count):
        q = model.random_state(rng)
        pin.framesForwardKinematics(model.model, data, model.to_pin(q))
        pose = pin.SE3(data.oMf[frame])
        if k % 5 == 4:
            pose.translation += np.array([0.5, 0.0, 0.0])
        target = pose.translation.copy() if position_only else pose
        out.append((target, model.random_state(rng), int(rng.integers(1 << 30))))
    return solver, out


def _answers(solver: IkSolver, requests, num_solutions: int = 1) -> list[tuple]:  # type: ignore[no-untyped-def]
    found: list[tuple] = []
    for target, seed_q, seed in requests:
        try:
            solutions = solver.solve_all(target, seed_q=seed_q, options=IkOptions(
                seed=seed, num_solutions=num_solutions))
        except IkFailedError as exc:
            found.append(("failed", exc.best_error))
            continue
        found.append(tuple((s.q.tobytes(), s.attempts, s.iterations) for s in solutions))
    return found


def _goal_states(model, requests) -> list[tuple]:  # type: ignore[no-untyped-def]
    solver = IkSolver(model, "arm")
    group = model.group("arm")
    out: list[tuple] = []
    for target, seed_q, seed in requests[:6]:
        goal = PoseGoal(Pose.from_se3(target))
        try:
            states = pose_goal_states(solver, group, goal, target, seed_q,
                                      PlannerOptions(seed=seed))
        except IkFailedError as exc:
            out.append(("failed", exc.best_error))
            continue
        out.append(tuple(q.tobytes() for q in states))
    return out


def _solve_everything(panda_model, servo_arm_model) -> list:  # type: ignore[no-untyped-def]
    panda, panda_requests = _requests(panda_model, "arm", 40, 11, position_only=False)
    servo, servo_requests = _requests(servo_arm_model, "arm", 40, 12, position_only=True)
    return [_answers(panda, panda_requests), _answers(panda, panda_requests[:10], 4),
            _answers(servo, servo_requests), _goal_states(panda_model, panda_requests)]


def test_ik_answers_are_the_same_on_an_idle_and_on_a_busy_machine(panda_model,
                                                                   servo_arm_model) -> None:
    idle = _solve_everything(panda_model, servo_arm_model)
    context = multiprocessing.get_context("spawn")
    spinners = [context.Process(target=_spin, daemon=True) for _ in range(SPINNERS)]
    try:
        for process in spinners:
            process.start()
        time.sleep(0.5)  # let them take the CPUs
        assert all(p.is_alive() for p in spinners)
        busy = _solve_everything(panda_model, servo_arm_model)
    finally:
        for process in spinners:
            process.kill()
        for process in spinners:
            process.join(5)
    assert busy == idle
    # Solutions and failures both among them: the comparison covers the two.
    flat = [a for group in idle for a in group]
    assert any(a and a[0] == "failed" for a in flat)
    assert any(a and a[0] != "failed" for a in flat)


def test_a_kinematics_yaml_timeout_is_read_as_attempts() -> None:
    assert default_attempts(KinematicsSettings()) == 10  # 5 ms, 10 attempts
    assert default_attempts(KinematicsSettings(timeout=0.005, attempts=50)) == 25
    assert default_attempts(KinematicsSettings(timeout=0.2, attempts=10)) == 10
    assert default_attempts(KinematicsSettings(timeout=0.0001, attempts=10)) == 1
