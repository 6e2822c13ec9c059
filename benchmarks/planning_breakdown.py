"""Where our planner's time goes per plan: the exact path verification against the rest
(start and goal checks, search, shortcutting), on a MoveIt problem of a robot with a
gripper; and whether VAMP can run beside it here.

    python benchmarks/planning_breakdown.py [--robot DIR] [--problem DIR/STEM] [--seeds 10]

Default problem: MotionBenchMaker's UR5 table scene and request as kept in
``tests/fixtures/motionbenchmaker`` (``ur5_table_scene.yaml`` / ``ur5_table_request.yaml``),
planned for the UR5 of ``tests/fixtures/motionbenchmaker/ur5_robotiq`` (example-robot-data's
UR5 meshes and a Robotiq-85-like gripper of boxes: not MotionBenchMaker's gripper meshes).
Each seed plans the same request once (after one untimed warm-up plan); the verification
time is the wall time spent inside :meth:`MotionPlanner.verify_states` (every exact check
of a candidate path: the returned path and the shortcut candidates).

VAMP (``vamp-planner``) is reported as importable or not; it has no model of this UR5
(VAMP's own UR5 is compiled into it), so it is not planned here.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

BENCH = Path(__file__).resolve().parent
if str(BENCH.parent) not in sys.path:
    sys.path.insert(0, str(BENCH.parent))

from taskrunner.moveit import load_motion_plan_request, load_planning_scene
from taskrunner.planning import MotionPlanner
from taskrunner.robot import load_robot
from taskrunner.scene import Scene

FIXTURES = BENCH.parent / "tests" / "fixtures" / "motionbenchmaker"


class TimedPlanner(MotionPlanner):
    """The planner, counting the time spent verifying candidate paths exactly."""

    verify_s = 0.0
    verify_calls = 0

    def verify_states(self, states: np.ndarray, margin: float) -> Any:
        t0 = time.perf_counter()
        try:
            return super().verify_states(states, margin)
        finally:
            self.verify_s += time.perf_counter() - t0
            self.verify_calls += 1


def vamp_status() -> str:
    try:
        import vamp  # type: ignore[import-not-found]
    except ImportError as exc:
        return (f"VAMP not importable ({exc}); vamp-planner 0.6.4 is an sdist whose build "
                f"fetches CPM.cmake, nigh, pdqsort and SIMDxorshift from GitHub and needs "
                f"Eigen3: skipped")
    return f"VAMP importable ({getattr(vamp, '__file__', '?')})"


def run(robot_dir: Path, problem: Path, seeds: int) -> dict[str, Any]:
    model = load_robot(robot_dir)
    base = Scene(model)
    rows = []
    for seed in range(-1, seeds):  # -1: the warm-up (compiled kernels, caches), not kept
        scene = base.copy()
        load_planning_scene(problem.with_name(problem.name + "_scene.yaml"), model).apply(scene)
        request_file = load_motion_plan_request(problem.with_name(problem.name + "_request.yaml"),
                                                model)
        request_file.apply_start(scene)
        request = request_file.plan_request(scene, seed=max(seed, 0), timing=False)
        planner = TimedPlanner(scene)
        scene.checker  # noqa: B018 - built before the timer, as planning_compare.py does
        scene.state_screen()
        t0 = time.perf_counter()
        result = planner.plan(request)
        wall = time.perf_counter() - t0
        if seed >= 0:
            rows.append({"seed": seed, "ms": wall * 1000, "verify_ms": planner.verify_s * 1000,
                         "verify_calls": planner.verify_calls,
                         "waypoints": len(result.path.waypoints)})
    ms = np.array([r["ms"] for r in rows])
    verify = np.array([r["verify_ms"] for r in rows])
    return {
        "benchmark": "planning_breakdown",
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "machine": f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, "
                   f"Python {platform.python_version()}",
        "load": " ".join(f"{v:.2f}" for v in os.getloadavg()),
        "robot": str(robot_dir), "problem": str(problem), "seeds": seeds,
        "median_ms": round(float(np.median(ms)), 2),
        "median_verify_ms": round(float(np.median(verify)), 2),
        "verify_share_median": round(float(np.median(verify / ms)), 3),
        "verify_share_range": [round(float((verify / ms).min()), 3),
                               round(float((verify / ms).max()), 3)],
        "median_verify_calls": int(np.median([r["verify_calls"] for r in rows])),
        "vamp": vamp_status(),
        "runs": rows,
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", type=Path, default=FIXTURES / "ur5_robotiq")
    parser.add_argument("--problem", type=Path, default=FIXTURES / "ur5_table",
                        help="DIR/STEM of STEM_scene.yaml and STEM_request.yaml")
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    result = run(args.robot, args.problem, args.seeds)
    print(f"{result['date']}; {result['machine']}; load {result['load']}")
    print(result["vamp"])
    print(f"{args.problem.name}: {args.seeds} plans, median {result['median_ms']} ms, of which "
          f"exact verification {result['median_verify_ms']} ms (share median "
          f"{result['verify_share_median']:.0%}, range {result['verify_share_range'][0]:.0%}-"
          f"{result['verify_share_range'][1]:.0%}; {result['median_verify_calls']} calls)")
    if args.json:
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
