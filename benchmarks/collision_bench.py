"""Benchmark: the Panda's state check (self + a table-and-shelf scene) in the planning scene.

``run(quick)`` times :meth:`taskrunner.scene.Scene.in_collision` on seeded random states
(uniform within the joint limits, so a mix of free and colliding ones) and reports the
median and 95th percentile in µs and the fraction in collision. The full run also times
the alternatives the scene chose between, as raw pinocchio calls on the same geometry:
link meshes as BVHs or as convex hulls, and pairwise narrow phase or a broadphase manager.
A BVH is a surface: a finger box that sinks wholly inside another link's mesh touches no
triangle and goes unseen, which the hulls catch; ``disagreements`` counts such states.

Both runs also compare the checker with the previous implementation (``FullRebuildChecker``:
every edit rebuilt the robot's geometry, pairs and both geometry data; a state check went
through pinocchio's overloaded ``computeCollisions``), interleaved in one run so that the
machine's load hits both alike: the rebuild after a seeded random scene edit (add, move,
remove, attach, detach, allow) in ms, and the state check in µs, with their verdicts
compared. ``breakdown`` splits a state check into its stages, timed cumulatively with raw
pinocchio calls: forward kinematics, geometry placements, the manager's update (poses and
AABBs), the broadphase pass with every pair switched off (AABB tests and callbacks only),
and the whole check (the rest is the narrow phase, GJK on pairs whose AABBs overlap).

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
from taskrunner.scene.collision import Body
from taskrunner.scene.geometry import object_geometry
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.types import Pose

__all__ = ["TABLE_AND_SHELF", "FullRebuildChecker", "build_cell", "random_edit", "rows", "run"]

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


class FullRebuildChecker:
    """The previous checker, kept as the reference of the comparison: it copies every
    body's geometry objects and adds its pairs one by one on each build, makes the report
    data up front, and checks a state through pinocchio's overloaded ``computeCollisions``."""

    def __init__(self, model: pin.Model, bodies: Sequence[Body], allowed) -> None:  # type: ignore[no-untyped-def]
        self._model = model
        self._geometry = pin.GeometryModel()
        owners: list[Body] = []
        for body in bodies:
            for index, geometry in enumerate(body.geometries):
                copy = pin.GeometryObject(geometry)
                copy.name = f"{body.name}/{index}"
                self._geometry.addGeometryObject(copy)
                owners.append(body)
        for i in range(len(owners)):
            for j in range(i + 1, len(owners)):
                a, b = owners[i], owners[j]
                if a.name == b.name or (a.static and b.static):
                    continue
                if frozenset((a.name, b.name)) in allowed:
                    continue
                self._geometry.addCollisionPair(pin.CollisionPair(i, j))
        self.pairs = [(p.first, p.second) for p in self._geometry.collisionPairs]
        self._data = model.createData()
        self._geometry_data = self._geometry.createData()
        self._manager = pin.BroadPhaseManager_NaiveCollisionManager(
            model, self._geometry, self._geometry_data)
        self._report_data = model.createData()
        self._report_geometry_data = self._geometry.createData()
        for request in self._report_geometry_data.collisionRequests:
            request.enable_contact = True
            request.num_max_contacts = 1

    def in_collision(self, q_pin: np.ndarray) -> bool:
        return bool(pin.computeCollisions(self._model, self._data, self._manager, q_pin, True))


def _scene_bodies(scene: Scene) -> list[Body]:
    """The scene's objects as collision bodies, as the scene builds them."""
    return [Body(o.name, (object_geometry(scene.robot, o, scene._entries[o.name].geometry),),
                 static=not o.attached) for o in scene.objects]


def random_edit(scene: Scene, rng: np.random.Generator, serial: int) -> str:
    """One seeded random edit of ``scene``: add, move or remove a small object, attach or
    detach one, or allow a pair; returns its kind."""
    robot = scene.robot
    links = [b.name for b in scene._link_bodies]
    movable = [n for n in scene.object_names if n.startswith("thing")]
    kind = str(rng.choice(["add", "add", "move", "remove", "attach", "detach", "allow"]))
    if kind in ("move", "remove", "attach", "detach", "allow") and not movable:
        kind = "add"
    if kind == "add":
        shape = [Box(tuple(rng.uniform(0.02, 0.15, 3))), Sphere(float(rng.uniform(0.02, 0.08))),
                 Cylinder(float(rng.uniform(0.02, 0.06)), float(rng.uniform(0.05, 0.3)))][serial % 3]
        xyz = (float(rng.uniform(-0.2, 0.8)), float(rng.uniform(-0.6, 0.6)), float(rng.uniform(0.0, 0.9)))
        scene.add_object(f"thing{serial}", shape, Pose(xyz))
        return kind
    name = str(rng.choice(movable))
    attached = scene.object(name).attached
    if kind == "move":
        xyz = (float(rng.uniform(-0.2, 0.8)), float(rng.uniform(-0.6, 0.6)), float(rng.uniform(0.0, 0.9)))
        scene.move_object(name, Pose(xyz))
    elif kind == "remove":
        scene.remove_object(name)
    elif kind == "attach" and not attached:
        scene.set_state(robot.random_state(rng))
        link = str(rng.choice(links[-3:]))
        scene.attach_object(name, link, touch_links=[str(rng.choice(links))])
    elif kind in ("attach", "detach") and attached:
        scene.detach_object(name)
        kind = "detach"
    else:
        scene.allow_collision(name, str(rng.choice(links + list(scene.object_names))))
        kind = "allow"
    return kind


def compare(robot: RobotModel, states: Sequence[np.ndarray], edits: int, rounds: int,
            seed: int) -> dict:
    """Previous against current checker, interleaved: rebuild after each of ``edits``
    random edits (ms; each build timed ``rounds`` times, alternating; the current one with
    its pair cache emptied, and again with the pairs cached, as after moving an object) and
    the state check over ``states`` (µs; alternating blocks of states, ``rounds`` passes)."""
    rng = np.random.default_rng(seed)
    scene = build_cell(robot)
    link_bodies = list(scene._link_bodies)
    clock = time.perf_counter_ns
    before_ms: list[float] = []
    after_ms: list[float] = []
    cached_ms: list[float] = []
    kinds: dict[str, int] = {}
    robot_geometry = scene._robot_geometry
    for serial in range(edits):
        kind = random_edit(scene, rng, serial)
        kinds[kind] = kinds.get(kind, 0) + 1
        for turn in range(rounds):
            bodies, allowed = _scene_bodies(scene), scene.allowed_collisions()
            start = clock()
            FullRebuildChecker(robot.model, link_bodies + bodies, allowed)
            before_ms.append((clock() - start) / 1e6)
            # A structure not seen before (pairs computed) and one seen before (as after a
            # move: pairs cached), in alternating order.
            robot_geometry.checker(bodies, allowed)
            for times in ((cached_ms, after_ms) if turn % 2 else (after_ms, cached_ms)):
                if times is after_ms:
                    robot_geometry._masks.clear()
                bodies, allowed = _scene_bodies(scene), scene.allowed_collisions()
                start = clock()
                robot_geometry.checker(bodies, allowed)
                times.append((clock() - start) / 1e6)
    cell = build_cell(robot)
    before = FullRebuildChecker(robot.model, link_bodies + _scene_bodies(cell),
                                cell.allowed_collisions())
    after = cell.checker
    q_pin = [robot.to_pin(q) for q in states]
    block = 100
    before_us: list[np.ndarray] = []
    after_us: list[np.ndarray] = []
    disagreements = 0
    for rep in range(rounds):
        for start_index in range(0, len(q_pin), block):
            chunk = q_pin[start_index:start_index + block]
            first, second = (before, after) if (rep + start_index // block) % 2 else (after, before)
            results = {}
            for checker in (first, second):
                times, verdicts = _time_calls(checker.in_collision, chunk, 1, warm=False)
                results[id(checker)] = verdicts
                (before_us if checker is before else after_us).append(times)
            disagreements += int(np.sum(results[id(before)] != results[id(after)]))
    b_us, a_us = np.concatenate(before_us), np.concatenate(after_us)
    return {
        "edits": edits,
        "edit_kinds": kinds,
        "rebuild_ms_before": float(np.median(before_ms)),
        "rebuild_ms_after": float(np.median(after_ms)),
        "rebuild_ms_after_pairs_cached": float(np.median(cached_ms)),
        "passes": rounds,
        "state_us_before": float(np.median(b_us)),
        "state_us_after": float(np.median(a_us)),
        "state_us_p95_before": float(np.percentile(b_us, 95)),
        "state_us_p95_after": float(np.percentile(a_us, 95)),
        "verdict_disagreements": disagreements,
        "pairs_after_edits": scene.checker.pair_count,
    }


def breakdown(robot: RobotModel, scene: Scene, states: Sequence[np.ndarray],
              repeats: int) -> dict[str, float]:
    """Median µs of the state check's stages, cumulative, with raw pinocchio calls on the
    scene's geometry (own data, so the scene's checker is left alone)."""
    model, geometry = robot.model, scene.checker.geometry_model
    data, geometry_data = model.createData(), geometry.createData()
    manager = pin.BroadPhaseManager_NaiveCollisionManager(model, geometry, geometry_data)
    callback = pin.CollisionCallBackDefault(manager.getGeometryModel(),
                                            manager.getGeometryData(), True)
    idle_data = geometry.createData()
    idle_data.deactivateAllCollisionPairs()
    idle_manager = pin.BroadPhaseManager_NaiveCollisionManager(model, geometry, idle_data)
    idle_callback = pin.CollisionCallBackDefault(idle_manager.getGeometryModel(),
                                                 idle_manager.getGeometryData(), True)
    place = pin.updateGeometryPlacements

    def idle(q: np.ndarray) -> bool:
        place(model, data, geometry, idle_data, q)
        idle_manager.update(False)
        idle_manager.collide(idle_callback)
        return bool(idle_callback.collision)

    def placed(q: np.ndarray) -> bool:
        place(model, data, geometry, geometry_data, q)
        return False

    def updated(q: np.ndarray) -> bool:
        place(model, data, geometry, geometry_data, q)
        manager.update(False)
        return False

    def whole(q: np.ndarray) -> bool:
        place(model, data, geometry, geometry_data, q)
        manager.update(False)
        manager.collide(callback)
        return bool(callback.collision)

    stages = {
        "call_overhead": lambda q: False,
        "forward_kinematics": lambda q: pin.forwardKinematics(model, data, q) is None and False,
        "placements": placed,
        "manager_update": updated,
        "broadphase_no_pairs": idle,
        "whole_check": whole,
    }
    q_pin = [robot.to_pin(q) for q in states]
    medians = {name: [] for name in stages}  # type: dict[str, list[float]]
    for _ in range(repeats):  # interleaved passes
        for name, check in stages.items():
            times, _ = _time_calls(check, q_pin, 1)
            medians[name].append(float(np.median(times)))
    return {name: float(np.median(values)) for name, values in medians.items()}


def _time_calls(check: Callable[[np.ndarray], bool], states: Sequence[np.ndarray],
                repeats: int, warm: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Per-call times (µs) and verdicts of ``check`` over ``states``, ``repeats`` times."""
    for q in states[:100] if warm else ():  # warm caches and branch predictors
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
        (disagreements: states whose verdict differs from the scene's); ``compare``:
        previous against current checker (``rebuild_ms_before/after``,
        ``state_us_before/after``, ``verdict_disagreements``, see :func:`compare`) and
        ``breakdown``: ``{stage: µs}`` cumulative (see :func:`breakdown`).
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
    result["compare"] = compare(robot, states, 20 if quick else 60, 2 if quick else 3, seed)
    result["breakdown"] = breakdown(robot, scene, states, 2 if quick else 5)
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
    if "compare" in result:
        c = result["compare"]
        out += [
            (f"Rebuild after a scene edit ({c['edits']} random edits), median",
             f"{1e3 * c['rebuild_ms_before']:.0f} -> {1e3 * c['rebuild_ms_after']:.0f} µs "
             f"({1e3 * c['rebuild_ms_after_pairs_cached']:.0f} µs with its pairs cached)"),
            ("State check, previous -> current (interleaved), median",
             f"{c['state_us_before']:.2f} -> {c['state_us_after']:.2f} µs"),
            ("  p95", f"{c['state_us_p95_before']:.2f} -> {c['state_us_p95_after']:.2f} µs"),
            ("  verdicts differing",
             f"{c['verdict_disagreements']} in {c['passes']} passes over {result['states']} states "
             f"({100 * c['verdict_disagreements'] / (c['passes'] * result['states']):.0f} %)"),
        ]
    for stage, us in result.get("breakdown", {}).items():
        out.append((f"  stage (cumulative): {stage}", f"{us:.2f} µs"))
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
