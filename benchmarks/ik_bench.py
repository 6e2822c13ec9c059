"""IK benchmark: success rate and time per call on the Panda, the UR5 and the servo arm.

TRAC-IK's protocol (Beeson & Ames 2015, and its ``ik_tests`` benchmark): 2000 random
joint configurations drawn uniformly within the limits (seeded ``np.random.default_rng``;
continuous joints in [-pi, pi]), the forward kinematics of the group's tip as targets,
every search seeded at the middle of the joint ranges (never at the answer), a 5 ms
timeout per call, tolerance 1e-5 m on the position and 1e-5 rad on the orientation.
The attempts are the group's kinematics.yaml setting (50 for the Panda and the UR5, 10
for the servo arm); in practice the timeout binds first. Each call is timed on the wall
clock and the mean is over all targets, failures included at the time they took; every
solution is checked again here (limits, tolerances) so a wrong answer counts as a
failure. Before timing, each solver builds its seed table (a one-time ~10 ms setup, as
TRAC-IK's solver construction is not timed) and makes 20 warm-up calls on other targets
(a separate draw).

The solver's 5 ms are its thread's CPU time, capped at 20 ms of wall time
(:mod:`taskrunner.kinematics.deadline`); TRAC-IK's are wall time. On an idle machine the
two agree; on a loaded one the wall times here include waiting for a CPU, and
``_over_timeout`` counts the calls that took longer than 5 ms of wall time (solved or
not), ``_cpu_ms_mean`` the calls' own CPU time.

This machine's speed drifts by 2-3x over minutes (a shared host), so the result also
carries ``calibration_us``, the time of a fixed small workload measured just before,
and the load average.

* Panda, group ``arm`` (7 joints, ``panda_hand_tcp``), full pose;
* UR5, group ``manipulator`` (6 joints, ``tool0``), full pose;
* servo arm, group ``arm`` (5 joints, ``gripper_base_1``), position only (its
  kinematics.yaml says ``position_only_ik``).

Usage::

    python benchmarks/ik_bench.py [--quick] [--targets N] [--json] [--seed N]

or from Python: ``run(quick, seed) -> dict`` and ``rows(result)`` for a table.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np
import pinocchio as pin

REPO_ROOT = Path(__file__).resolve().parents[1]
if str(REPO_ROOT) not in sys.path:
    sys.path.insert(0, str(REPO_ROOT))

from taskrunner.errors import IkFailedError
from taskrunner.kinematics import IkOptions, IkSolver, frame_pose
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel, load_robot

__all__ = ["CASES", "rows", "run"]

TIMEOUT = 0.005  # s per call
TOLERANCE = 1e-5  # m and rad
FULL_TARGETS = 2000
QUICK_TARGETS = 150
WARM_UP_CALLS = 20

# (result key prefix, robot folder, group, label)
CASES = (
    ("panda_ik", "robots/panda", "arm", "Panda arm, full pose"),
    ("ur5_ik", "robots/ur5", "manipulator", "UR5 manipulator, full pose"),
    ("arm5_ik_position", "robots/servo_arm", "arm", "servo arm (5 DOF), position only"),
)


def _mid_range_seed(model: RobotModel, group: str) -> np.ndarray:
    q = model.default_state()
    idx = model.group(group).joint_indices
    lower, upper = model.lower[idx], model.upper[idx]
    q[idx] = np.where(np.isfinite(lower) & np.isfinite(upper), 0.5 * (lower + upper), 0.0)
    return model.apply_mimic(q)


def _is_valid(model: RobotModel, solver: IkSolver, q: np.ndarray, target: pin.SE3,
              position_only: bool) -> bool:
    """Independent check of a returned solution: limits and tolerance."""
    if not model.within_limits(q, tolerance=0.0):
        return False
    pose = frame_pose(model, q, solver.frame)
    if np.linalg.norm(pose.translation - target.translation) > TOLERANCE:
        return False
    if position_only:
        return True
    angle = np.linalg.norm(pin.log3(pose.rotation.T @ target.rotation))
    return bool(angle <= TOLERANCE)


def _bench_case(path: Path, group: str, n_targets: int, seed: int) -> dict[str, float]:
    model = load_robot(path)
    solver = IkSolver(model, group)
    position_only = model.group(group).position_only_ik
    options = IkOptions(timeout=TIMEOUT, tolerance=TOLERANCE, seed=seed)
    rng = np.random.default_rng(seed)
    targets = [
        frame_pose(model, model.random_state(rng, group), solver.frame) for _ in range(n_targets)
    ]
    warm_rng = np.random.default_rng([seed, 1])  # warm-up targets: not the timed ones
    warm_up = [frame_pose(model, model.random_state(warm_rng, group), solver.frame)
               for _ in range(WARM_UP_CALLS)]
    seed_q = _mid_range_seed(model, group)
    solver.seed_table()  # one-time setup of the solver (~10 ms), not part of a call
    for target in warm_up:
        try:
            solver.solve(target, seed_q, options)
        except IkFailedError:
            pass
    times = np.empty(n_targets)
    cpu = np.empty(n_targets)
    successes = 0
    attempts, iterations = [], []
    started = time.perf_counter()
    for k, target in enumerate(targets):
        start, start_cpu = time.perf_counter(), time.thread_time()
        try:
            solution = solver.solve(target, seed_q, options)
        except IkFailedError:
            times[k] = time.perf_counter() - start
            cpu[k] = time.thread_time() - start_cpu
            continue
        times[k] = time.perf_counter() - start
        cpu[k] = time.thread_time() - start_cpu
        if _is_valid(model, solver, solution.q, target, position_only):
            successes += 1
            attempts.append(solution.attempts)
            iterations.append(solution.iterations)
    seconds = time.perf_counter() - started
    ms = times * 1e3
    return {
        "success": successes / n_targets,
        "failures": n_targets - successes,
        "ms_mean": float(ms.mean()),
        "ms_median": float(np.median(ms)),
        "ms_p95": float(np.percentile(ms, 95)),
        "ms_p99": float(np.percentile(ms, 99)),
        "ms_max": float(ms.max()),
        "cpu_ms_mean": float(cpu.mean() * 1e3),
        "over_timeout": int(np.sum(times > TIMEOUT)),
        "first_attempt": float(np.mean(np.asarray(attempts) == 1)) * successes / n_targets
        if attempts else 0.0,
        "attempts_mean": float(np.mean(attempts)) if attempts else float("nan"),
        "iterations_mean": float(np.mean(iterations)) if iterations else float("nan"),
        "targets": n_targets,
        "seconds": seconds,
    }


def _calibration_us() -> float:
    """Median time (µs) of a fixed small workload: one pinocchio FK of the Panda and two
    6x7 numpy products, the kind of call an IK iteration is made of."""
    model = load_robot(DATA_ROOT / "robots" / "panda").model
    data = model.createData()
    q = np.zeros(model.nq)
    J = np.ones((6, 7))
    A = np.empty((6, 6))
    samples = []
    for _ in range(20):
        start = time.perf_counter()
        for _ in range(200):
            pin.forwardKinematics(model, data, q)
            np.dot(J, J.T, out=A)
            np.dot(A, J)
        samples.append((time.perf_counter() - start) / 200 * 1e6)
    return float(np.median(samples))


def run(quick: bool = False, seed: int = 0, targets: int | None = None) -> dict[str, float]:
    """Run every case.

    Args:
        quick: 150 targets per robot instead of 2000.
        seed: seeds the targets and the solver's restarts.
        targets: number of targets per robot, overriding ``quick`` (for smoke tests).

    Returns:
        For each case key (``panda_ik``, ``ur5_ik``, ``arm5_ik_position``):
        ``<key>_success`` (fraction) and ``_failures`` (count), ``<key>_ms_mean``,
        ``_ms_median``, ``_ms_p95``, ``_ms_p99``, ``_ms_max`` (ms per call, failures
        included), ``_cpu_ms_mean`` (the calls' own CPU time: what is left of the mean
        when the machine's load is taken out), ``_over_timeout`` (calls whose wall time
        passed the timeout: on a loaded machine, a call descheduled near its deadline
        fails), ``_first_attempt`` (fraction of targets solved from the seed state),
        ``_attempts_mean``, ``_iterations_mean`` (over successes), ``_targets`` and
        ``_seconds`` (the timed loop); ``calibration_us``, the time of a fixed small
        workload measured just before (see ``_calibration_us``), and ``load_average``.
    """
    n_targets = targets if targets is not None else QUICK_TARGETS if quick else FULL_TARGETS
    result: dict[str, float] = {"calibration_us": _calibration_us(),
                                "load_average": os.getloadavg()[0]}
    for key, folder, group, _ in CASES:
        for name, value in _bench_case(DATA_ROOT / folder, group, n_targets, seed).items():
            result[f"{key}_{name}"] = value
    return result


def rows(result: dict[str, float]) -> list[tuple[str, str]]:
    """``(what, figure)`` rows for a readable table of a :func:`run` result."""
    out = []
    if "calibration_us" in result:
        load = f", load average {result['load_average']:.2f}" if "load_average" in result else ""
        out.append(("machine speed: Panda FK + two 6x7 numpy products (lower is faster)",
                    f"{result['calibration_us']:.2f} µs{load}"))
    for key, _, _, label in CASES:
        if f"{key}_success" not in result:
            continue
        what = (f"IK {label}, {int(result[f'{key}_targets'])} random reachable targets, "
                f"{TIMEOUT * 1e3:g} ms timeout, tol {TOLERANCE:g}")
        figure = (f"{result[f'{key}_success'] * 100:.2f} % success, "
                  f"{result[f'{key}_ms_mean']:.3f} ms mean "
                  f"({result[f'{key}_cpu_ms_mean']:.3f} CPU), "
                  f"{result[f'{key}_ms_median']:.3f} ms p50, "
                  f"{result[f'{key}_ms_p99']:.3f} ms p99")
        out.append((what, figure))
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=f"{QUICK_TARGETS} targets per robot")
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument("--targets", type=int, default=None,
                        help=f"targets per robot ({FULL_TARGETS}; --quick: {QUICK_TARGETS})")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    result = run(quick=args.quick, seed=args.seed, targets=args.targets)
    if args.json:
        print(json.dumps(result, indent=2, sort_keys=True))
    else:
        width = max(len(what) for what, _ in rows(result))
        for what, figure in rows(result):
            print(f"{what:<{width}}  {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
