"""Where our planner's time goes per plan: the exact path verification against the rest
(start and goal checks, search, shortcutting), on a MoveIt problem of a robot with a
gripper; and whether VAMP can run beside it here.

    python benchmarks/planning_breakdown.py [--robot DIR] [--problem DIR/STEM] [--seeds 10]
    python benchmarks/planning_breakdown.py --panda-sets [--per-class 10] [--problems DIR]
    python benchmarks/planning_breakdown.py --sets ROBOT [--per-class 10] [--problems DIR]

Default problem: MotionBenchMaker's UR5 table scene and request as kept in
``tests/fixtures/motionbenchmaker`` (``ur5_table_scene.yaml`` / ``ur5_table_request.yaml``),
planned for the UR5 of ``tests/fixtures/motionbenchmaker/ur5_robotiq`` (example-robot-data's
UR5 meshes and a Robotiq-85-like gripper of boxes: not MotionBenchMaker's gripper meshes).
Each seed plans the same request once (after one untimed warm-up plan); the verification
time is the wall time spent inside :meth:`MotionPlanner.verify_states` (every exact check
of a candidate path: the returned path and the shortcut candidates).

``--panda-sets``: the seeded Panda problems of ``make_problems.py`` instead (as
``planning_compare.py`` plans them: regenerated into ``benchmarks/problems`` unless
``--problems DIR``), each planned once with its problem's seed. ``--sets ROBOT``: the same
for another robot of ``make_problems.py`` (``ur5_robotiq``: the UR5 with the Robotiq
2F-85's meshes; ``tiago``), regenerated into ``benchmarks/problems_ROBOT`` unless
``--problems DIR``.

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
sys.path.insert(0, str(BENCH))
if str(BENCH.parent) not in sys.path:
    sys.path.insert(0, str(BENCH.parent))

from taskrunner.errors import PlanningError
from taskrunner.moveit import load_motion_plan_request, load_planning_scene
from taskrunner.planning import MotionPlanner
from taskrunner.robot import RobotModel, load_robot
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


def plan_once(model: RobotModel, base: Scene, problem: Path, seed: int) -> dict[str, Any]:
    """Plan ``problem`` (``DIR/STEM``) once; its wall time and the verification's."""
    scene = base.copy()
    load_planning_scene(problem.with_name(problem.name + "_scene.yaml"), model).apply(scene)
    request_file = load_motion_plan_request(problem.with_name(problem.name + "_request.yaml"),
                                            model)
    request_file.apply_start(scene)
    request = request_file.plan_request(scene, seed=seed, timing=False)
    planner = TimedPlanner(scene)
    scene.checker  # noqa: B018 - built before the timer, as planning_compare.py does
    scene.state_screen()
    t0 = time.perf_counter()
    try:
        result = planner.plan(request)
        waypoints, error = len(result.path.waypoints), ""
    except PlanningError as exc:
        waypoints, error = 0, type(exc).__name__
    wall = time.perf_counter() - t0
    return {"problem": str(problem), "seed": seed, "ms": wall * 1000,
            "verify_ms": planner.verify_s * 1000, "verify_calls": planner.verify_calls,
            "waypoints": waypoints, "error": error}


def run(robot_dir: Path, problem: Path, seeds: int) -> dict[str, Any]:
    model = load_robot(robot_dir)
    base = Scene(model)
    plan_once(model, base, problem, 0)  # the warm-up (compiled kernels, caches), not kept
    rows = [plan_once(model, base, problem, seed) for seed in range(seeds)]
    return _header() | _summary(rows) | {"robot": str(robot_dir), "problem": str(problem),
                                         "seeds": seeds}


def run_sets(per_class: int, problems: Path | None, robot: str = "panda",
             classes: list[str] | None = None) -> dict[str, Any]:
    import make_problems

    folder = problems
    if folder is None:
        folder = BENCH / ("problems" if robot == "panda" else f"problems_{robot}")
        make_problems.generate(folder, per_class, 0, make_problems.CLASSES, robot_name=robot)
    model = load_robot(make_problems.robot_spec(robot).robot_dir)
    base = Scene(model)
    first = next(c for c in make_problems.CLASSES if not classes or c in classes)
    plan_once(model, base, folder / first / "0001", 0)  # warm-up
    out: dict[str, Any] = _header() | {"classes": {}}
    for k, c in enumerate(make_problems.CLASSES):
        if classes and c not in classes:
            continue
        rows = [plan_once(model, base, folder / c / f"{i + 1:04d}", k * 1000 + i)
                for i in range(per_class)]
        out["classes"][c] = _summary(rows)
    return out | {"per_class": per_class, "robot": robot}


def _summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    ms = np.array([r["ms"] for r in rows])
    verify = np.array([r["verify_ms"] for r in rows])
    return {
        "failed": [r["problem"] + ": " + r["error"] for r in rows if r["error"]],
        "median_ms": round(float(np.median(ms)), 2),
        "median_verify_ms": round(float(np.median(verify)), 2),
        "verify_share_median": round(float(np.median(verify / ms)), 3),
        "verify_share_range": [round(float((verify / ms).min()), 3),
                               round(float((verify / ms).max()), 3)],
        "median_verify_calls": int(np.median([r["verify_calls"] for r in rows])),
        "runs": rows,
    }


def _header() -> dict[str, Any]:
    return {
        "benchmark": "planning_breakdown",
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "machine": f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, "
                   f"Python {platform.python_version()}",
        "load": " ".join(f"{v:.2f}" for v in os.getloadavg()),
        "vamp": vamp_status(),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", type=Path, default=FIXTURES / "ur5_robotiq")
    parser.add_argument("--problem", type=Path, default=FIXTURES / "ur5_table",
                        help="DIR/STEM of STEM_scene.yaml and STEM_request.yaml")
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--panda-sets", action="store_true",
                        help="the Panda problem sets of make_problems.py instead")
    parser.add_argument("--sets", metavar="ROBOT",
                        help="the problem sets of make_problems.py for this robot instead")
    parser.add_argument("--per-class", type=int, default=10)
    parser.add_argument("--problems", type=Path, help="with --panda-sets / --sets: read them from here")
    parser.add_argument("--classes", nargs="+", metavar="CLASS",
                        help="with --panda-sets / --sets: only these classes (seeds unchanged)")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    if args.panda_sets or args.sets:
        sets = run_sets(args.per_class, args.problems, args.sets or "panda", args.classes)
        print(f"{sets['robot']}; {sets['date']}; {sets['machine']}; load {sets['load']} "
              f"(at the start)")
        print(sets["vamp"])
        for c, e in sets["classes"].items():
            print(f"{c:<17} median {e['median_ms']:7.2f} ms, exact verification "
                  f"{e['median_verify_ms']:6.2f} ms (share median {e['verify_share_median']:.0%}, "
                  f"range {e['verify_share_range'][0]:.0%}-{e['verify_share_range'][1]:.0%}; "
                  f"{e['median_verify_calls']} calls); failed {len(e['failed'])}")
        if args.json:
            print(json.dumps(sets))
        return 0
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
