"""Recorded verdicts of the path verifier and the state screen (what
``test_recorded_verdicts.py`` replays).

``collision_verdicts.json`` holds scenes (a robot, primitive objects in the world, a start
state), paths and states, with what the verifier and the screen said about them when the
file was written: every field of :class:`~taskrunner.scene.path_verifier.PathVerification` but its
time, and for the screen each state's verdict and the pairs it left to coal. Written
before the compiled kernels moved to :mod:`taskrunner.collision` (2026-11-28, tree
55c9b36) from the MoveIt problem sets of ``benchmarks/make_problems.py --count 3 --seed 0``
(the first two problems of each class: objects, start, the planner's path, seeded) and a
servo arm cell of random boxes; a change of the kernels that moves a verdict, a measured
state or a pair handed to coal fails the replay.

    python tests/scene/verdict_cases.py PROBLEMS_DIR   # write the file anew
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import numpy as np

from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel, load_robot
from taskrunner.scene import Scene
from taskrunner.shapes import Box, Cylinder, Shape, Sphere
from taskrunner.types import Pose

FIXTURE = Path(__file__).with_name("collision_verdicts.json")
MARGIN = 0.0005  # m: the planner's default verification margin
_ROBOTS: dict[str, RobotModel] = {}


def robot_named(name: str) -> RobotModel:
    if name not in _ROBOTS:
        _ROBOTS[name] = load_robot(DATA_ROOT / "robots" / name)
    return _ROBOTS[name]


def _shape_data(shape: Shape) -> dict[str, Any]:
    if isinstance(shape, Box):
        return {"box": list(shape.size)}
    if isinstance(shape, Cylinder):
        return {"cylinder": [shape.radius, shape.length]}
    if isinstance(shape, Sphere):
        return {"sphere": shape.radius}
    raise TypeError(f"not a primitive: {shape!r}")


def _shape(data: dict[str, Any]) -> Shape:
    if "box" in data:
        return Box(tuple(data["box"]))
    if "cylinder" in data:
        return Cylinder(*data["cylinder"])
    return Sphere(data["sphere"])


def build_scene(case: dict[str, Any]) -> Scene:
    """The case's scene: its robot, objects and allowances, at its start state."""
    scene = Scene(robot_named(case["robot"]))
    for obj in case["objects"]:
        scene.add_object(obj["name"], _shape(obj["shape"]),
                         Pose(tuple(obj["xyz"]), tuple(obj["quat"])))
    for a, b in case["allowed"]:
        scene.allow_collision(a, b)
    scene.set_state(np.array(case["start"]))
    return scene


def observe(scene: Scene, case: dict[str, Any]) -> dict[str, Any]:
    """What the verifier and the screen say about the case's paths and states."""
    verifier = scene.path_verifier(MARGIN)
    paths = []
    for path in case["paths"]:
        found = verifier.verify(np.ascontiguousarray(path, dtype=float))
        paths.append({"valid": found.valid, "fraction": found.fraction,
                      "pair": list(found.pair) if found.pair else None,
                      "states": found.states, "distance_queries": found.distance_queries,
                      "bounds": found.bounds})
    screen = scene.state_screen(MARGIN)
    checker = screen.checker
    asked: list[list[int]] = []
    collide = checker.pairs_collide

    def counting(q: np.ndarray, pairs: Any) -> bool:
        asked.append([int(k) for k in pairs])
        return collide(q, pairs)

    checker.pairs_collide = counting  # type: ignore[method-assign]  # this checker only
    try:
        scan = screen.scanner()
        states = []
        for q in case["states"]:
            asked.clear()
            row = scan(np.ascontiguousarray(np.array(q, dtype=float)[None, :]))
            states.append({"row": row, "asked": list(asked)})
        asked.clear()
        whole = scan(np.ascontiguousarray(case["states"], dtype=float))
        rows = {"row": whole, "asked": list(asked)}
    finally:
        del checker.pairs_collide
    return {"paths": paths, "states": states, "rows": rows}


def _cases(problems: Path) -> list[dict[str, Any]]:
    from taskrunner.errors import PlanningError
    from taskrunner.moveit import load_motion_plan_request, load_planning_scene
    from taskrunner.planning import MotionPlanner

    robot = robot_named("panda")
    rng = np.random.default_rng(24)
    cases = []
    for cls in sorted(p.name for p in problems.iterdir() if p.is_dir()):
        for i in range(2):
            stem = problems / cls / f"{i + 1:04d}"
            scene = Scene(robot)
            load_planning_scene(Path(f"{stem}_scene.yaml"), robot).apply(scene)
            request_file = load_motion_plan_request(Path(f"{stem}_request.yaml"), robot)
            request_file.apply_start(scene)
            case = _case_of(scene, f"{cls}/{i + 1:04d}", "panda")
            request = request_file.plan_request(scene, seed=i, timing=False)
            start = scene.state
            try:
                result = MotionPlanner(scene).plan(request)
                full = [robot.state_with(start, dict(zip(result.path.names, w)))
                        for w in result.path.waypoints]
                case["paths"].append([list(map(float, q)) for q in full])
            except PlanningError:
                pass
            _add_random(case, robot, rng)
            cases.append(case)
    servo = robot_named("servo_arm")
    scene = Scene(servo)
    scene.set_state(servo.random_state(rng))
    while scene.in_collision():  # a start off the base (its zero pose folds onto it)
        scene.set_state(servo.random_state(rng))
    while len(scene.object_names) < 6:  # boxes clear of the arm at its start
        size = tuple(float(v) for v in rng.uniform(0.02, 0.12, 3))
        xyz = (float(rng.uniform(-0.25, 0.25)), float(rng.uniform(-0.25, 0.25)),
               float(rng.uniform(0.02, 0.3)))
        name = f"box{len(scene.object_names)}"
        scene.add_object(name, Box(size), Pose(xyz))
        if scene.in_collision():
            scene.remove_object(name)
    case = _case_of(scene, "servo_arm/boxes", "servo_arm")
    _add_random(case, servo, rng)
    cases.append(case)
    return cases


def _case_of(scene: Scene, name: str, robot: str) -> dict[str, Any]:
    snapshot = scene.snapshot()
    objects = [{"name": o.name, "shape": _shape_data(o.shape), "xyz": list(o.pose.xyz),
                "quat": list(o.pose.quat)} for o in snapshot.objects if not o.attached]
    return {"name": name, "robot": robot, "objects": objects,
            "allowed": [list(p) for p in snapshot.allowed],
            "start": [float(v) for v in scene.state], "paths": [], "states": []}


def _add_random(case: dict[str, Any], robot: RobotModel, rng: np.random.Generator) -> None:
    """Straight lines from the start to random states (most cross something), a path
    through two random states, and random states plus states along the first line."""
    start = np.array(case["start"])
    ends = [robot.random_state(rng) for _ in range(3)]
    for end in ends[:2]:
        case["paths"].append([list(map(float, start)), list(map(float, end))])
    case["paths"].append([list(map(float, q)) for q in (start, ends[0], ends[2])])
    states = [robot.random_state(rng) for _ in range(12)]
    states += [robot.apply_mimic(start + t * (ends[0] - start)) for t in np.linspace(0, 1, 12)]
    case["states"] = [list(map(float, q)) for q in states]


def main(argv: list[str]) -> int:
    cases = _cases(Path(argv[0]))
    for case in cases:
        case["expected"] = observe(build_scene(case), case)
    FIXTURE.write_text(json.dumps({"cases": cases}, separators=(",", ":")) + "\n")
    print(f"{len(cases)} cases -> {FIXTURE}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
