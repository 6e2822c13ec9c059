"""Benchmark: the Panda's state check (self + a table-and-shelf scene) in the planning scene.

``run(quick)`` times :meth:`taskrunner.scene.Scene.in_collision` on seeded random states
(uniform within the joint limits, so a mix of free and colliding ones) and reports the
median and 95th percentile in µs and the fraction in collision. The full run also times
the alternatives the scene chose between, as raw pinocchio calls on the same geometry:
link meshes as BVHs or as convex hulls, and pairwise narrow phase or a broadphase manager.
A BVH is a surface: a finger box that sinks wholly inside another link's mesh touches no
triangle and goes unseen, which the hulls catch; ``disagreements`` counts such states.

Run alone::

    python benchmarks/collision_bench.py [--quick] [--json] [--seed S]
"""

from __future__ import annotations

import argparse
import gc
import json
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from taskrunner.resources import DATA_ROOT

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import pinocchio as pin

from taskrunner.robot import RobotModel, load_robot
from taskrunner.scene import Scene, SceneOptions
from taskrunner.shapes import Box
from taskrunner.types import Pose

__all__ = ["TABLE_AND_SHELF", "build_cell", "rows", "run"]

# The table the Panda stands on (base bolted to it: link0–table allowed) and a shelf with
# a middle board in front of it: (name, full size in m, centre in the world frame in m).
TABLE_AND_SHELF = (
    ("table", (1.2, 1.2, 0.04), (0.3, 0.0, -0.02)),
    ("shelf_left", (0.3, 0.02, 0.6), (0.75, -0.3, 0.3)),
    ("shelf_right", (0.3, 0.02, 0.6), (0.75, 0.3, 0.3)),
    ("shelf_board", (0.3, 0.6, 0.02), (0.75, 0.0, 0.3)),
    ("shelf_top", (0.3, 0.62, 0.02), (0.75, 0.0, 0.61)),
)

# Raw pinocchio alternatives timed in the full run: (label, robot meshes as hulls, manager).
VARIANTS = (
    ("hull + naive broadphase (chosen)", True, "Naive"),
    ("hull + pairwise", True, None),
    ("hull + dynamic AABB tree", True, "DynamicAABBTree"),
    ("mesh + naive broadphase", False, "Naive"),
    ("mesh + pairwise", False, None),
    ("mesh + dynamic AABB tree", False, "DynamicAABBTree"),
)


def build_cell(robot: RobotModel, options: SceneOptions | None = None) -> Scene:
    """The Panda in its table-and-shelf cell (five boxes), at its default state."""
    scene = Scene(robot, options)
    for name, size, xyz in TABLE_AND_SHELF:
        scene.add_object(name, Box(size), Pose(xyz))
    scene.allow_collision("panda_link0", "table")
    return scene


def _time_calls(check: Callable[[np.ndarray], bool], states: Sequence[np.ndarray],
                repeats: int) -> tuple[np.ndarray, np.ndarray]:
    """Per-call times (µs) and verdicts of ``check`` over ``states``, ``repeats`` times."""
    for q in states[:100]:  # warm caches and branch predictors
        check(q)
    times = np.empty(len(states) * repeats)
    verdicts = np.empty(len(states), dtype=bool)
    clock = time.perf_counter_ns
    enabled = gc.isenabled()
    gc.disable()
    try:
        k = 0
        for rep in range(repeats):
            for i, q in enumerate(states):
                start = clock()
                verdict = check(q)
                times[k] = clock() - start
                k += 1
                if rep == 0:
                    verdicts[i] = verdict
    finally:
        if enabled:
            gc.enable()
    return times / 1000.0, verdicts


def _summary(times: np.ndarray, verdicts: np.ndarray) -> dict[str, float]:
    return {
        "us_median": float(np.median(times)),
        "us_p95": float(np.percentile(times, 95)),
        "collision_fraction": float(np.mean(verdicts)),
    }


def _raw_check(
    robot: RobotModel, scene: Scene, manager: str | None
) -> Callable[[np.ndarray], bool]:
    model = robot.model
    geometry = scene.checker.geometry_model
    data, geometry_data = model.createData(), geometry.createData()
    if manager is None:
        return lambda q: pin.computeCollisions(model, data, geometry, geometry_data, q, True)
    broadphase = getattr(pin, f"BroadPhaseManager_{manager}CollisionManager")(
        model, geometry, geometry_data
    )
    check = lambda q: pin.computeCollisions(model, data, broadphase, q, True)
    check.keep_alive = (geometry, geometry_data, broadphase)  # type: ignore[attr-defined]
    return check


def run(quick: bool, seed: int = 0) -> dict:
    """Time the Panda's state check in the table-and-shelf cell.

    Args:
        quick: 1000 states once (about a second) instead of 5000 states three times
            plus the alternatives.
        seed: seed of the random states.

    Returns:
        ``panda_collision_us_median``, ``panda_collision_us_p95`` (µs per
        ``Scene.in_collision`` call), ``panda_collision_fraction`` (share of states in
        collision), ``panda_collision_free_us_median`` / ``…_colliding_us_median``,
        ``states``, ``pairs`` (geometry pairs checked) and, in the full run,
        ``variants``: ``{label: {us_median, us_p95, collision_fraction, disagreements}}``
        (disagreements: states whose verdict differs from the scene's).
    """
    robot = load_robot(DATA_ROOT / "robots" / "panda")
    scene = build_cell(robot)
    rng = np.random.default_rng(seed)
    count, repeats = (1000, 1) if quick else (5000, 3)
    states = [robot.random_state(rng) for _ in range(count)]
    times, verdicts = _time_calls(scene.in_collision, states, repeats)
    per_state = times.reshape(repeats, count)
    result: dict = {
        "panda_collision_us_median": float(np.median(times)),
        "panda_collision_us_p95": float(np.percentile(times, 95)),
        "panda_collision_fraction": float(np.mean(verdicts)),
        "panda_collision_free_us_median": float(np.median(per_state[:, ~verdicts])),
        "panda_collision_colliding_us_median": (
            float(np.median(per_state[:, verdicts])) if verdicts.any() else float("nan")
        ),
        "states": count,
        "pairs": scene.checker.pair_count,
        "quick": quick,
        "seed": seed,
    }
    if not quick:
        scenes = {True: scene, False: build_cell(robot, SceneOptions(convex_robot_meshes=False))}
        q_pin = [robot.to_pin(q) for q in states]
        variants = {}
        for label, hull, manager in VARIANTS:
            check = _raw_check(robot, scenes[hull], manager)
            variant_times, variant_verdicts = _time_calls(check, q_pin, repeats)
            variants[label] = _summary(variant_times, variant_verdicts)
            variants[label]["disagreements"] = int(np.sum(variant_verdicts != verdicts))
        result["variants"] = variants
    return result


def rows(result: dict) -> list[tuple[str, str]]:
    """``(what, figure)`` rows for a results table."""
    out = [
        ("Panda self + 5-box cell, state check median",
         f"{result['panda_collision_us_median']:.1f} µs"),
        ("Panda self + 5-box cell, state check p95", f"{result['panda_collision_us_p95']:.1f} µs"),
        ("  free / colliding states, median",
         f"{result['panda_collision_free_us_median']:.1f} / "
         f"{result['panda_collision_colliding_us_median']:.1f} µs"),
        ("  random states in collision",
         f"{100 * result['panda_collision_fraction']:.0f} % of {result['states']} "
         f"({result['pairs']} geometry pairs)"),
    ]
    for label, figures in result.get("variants", {}).items():
        differ = figures.get("disagreements", 0)
        flag = f", {differ} verdicts differ" if differ else ""
        out.append((f"  raw pinocchio: {label}",
                    f"{figures['us_median']:.1f} µs median, {figures['us_p95']:.1f} p95{flag}"))
    return out


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer states, no alternatives")
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    result = run(args.quick, args.seed)
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        width = max(len(what) for what, _ in rows(result))
        for what, figure in rows(result):
            print(f"{what:<{width}}  {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
