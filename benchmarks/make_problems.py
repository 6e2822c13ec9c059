"""Seeded MotionBenchMaker-style problem sets, written as MoveIt YAML files, for the Panda
and for any robot given its SRDF group, ready state and placement (:class:`RobotSpec`).

Each problem is a ``moveit_msgs/PlanningScene`` (``NNNN_scene.yaml``: the objects, the
start state, the allowed-collision matrix) and a ``moveit_msgs/MotionPlanRequest``
(``NNNN_request.yaml``: the start state and a joint goal; ``NNNN_pose_request.yaml``: the
same goal as a pose of the hand's TCP), in the layout MotionBenchMaker writes (ROS 1
field names, the whole message at the top level), so that any tool reading those files
reads these, and ``run-task plan panda --scene … --request …`` plans them.

Robots (``--robot``): ``panda`` (taskrunner's Panda, group ``arm``), ``ur5_robotiq`` (a UR5
with a Robotiq 2F-85 of collision meshes, group ``manipulator``, on the table as the Panda)
and ``tiago`` (PAL's TIAGo without its hand, group ``arm_torso``: the torso lift and the
arm; a mobile base standing on the floor in front of the table), the last two from
``benchmarks/robots`` (see its README). Both arms reach as far as the Panda's (0.85-0.87 m
against 0.855 m), so the scenes are placed, not scaled: each robot's :class:`RobotSpec`
puts the scene's origin (the point where the Panda's base stands) in the robot's frame,
drops what would stand inside its base (the pedestal under a mobile base) and starts the
table in front of a base that is not mounted on it. The Panda's files are unchanged by
this (byte for byte, for the same seed).

Classes (scene frame = the Panda's base, z up, m), after MotionBenchMaker's:

* ``table_pick``: objects on a table; ready → hand above a random object, pointing down.
* ``table_under_pick``: the Panda on a pedestal; ready → hand under a table top.
* ``bookshelf_small`` / ``bookshelf_tall`` / ``bookshelf_thin``: a shelf of 2 / 4 / 5
  compartments (the thin one with 1 cm boards and low compartments); ready → the hand
  in a random compartment, pointing in.
* ``box``: hand beside an open box → inside it, over a wall.
* ``cage``: hand inside a cage of bars → out of its window, behind the cage.

Every problem moves the whole scene by a random offset (up to 4 cm in x and y, 0.1 rad of
yaw about the scene's centre); start and goal come from seeded IK (the sampler of
``planning_scenes.py``) and are checked within limits and collision-free in their scene
before they are written; ``--check`` reads every written file back through
:mod:`taskrunner.moveit` and checks both states again. Problem ``i`` of a class depends
only on the seed, the class and ``i``.

Usage::

    python benchmarks/make_problems.py [--robot panda] [--count 100] [--seed 0]
                                       [--out benchmarks/problems]
                                       [--classes table_pick,cage] [--check]
                                       [--plan N [--pose]]   # then plan N per class
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin

BENCH = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH))
if str(BENCH.parent) not in sys.path:
    sys.path.insert(0, str(BENCH.parent))

import planning_scenes as ps

from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel, load_robot
from taskrunner.scene import Scene
from taskrunner.shapes import Box, Cylinder, Shape
from taskrunner.types import Pose

CLASSES = ("table_pick", "table_under_pick", "bookshelf_small", "bookshelf_tall",
           "bookshelf_thin", "box", "cage")
GROUP = "arm"
PLANNING_TIME = 5.0  # s, MoveIt's default; written into every request
SHIFT, YAW = 0.04, 0.1  # m, rad: how far each problem's scene moves

Placed = tuple[str, Shape, Pose]
Target = Callable[[np.random.Generator], Pose]
ROBOT_FILES = BENCH / "robots"


@dataclass(frozen=True)
class RobotSpec:
    """How a robot meets the problem classes.

    Attributes:
        robot_dir: the robot's folder (``robot.yaml``).
        group: the SRDF group planned for (its tip link is the tool point: z along the
            approach).
        ready: the start state's joints (rad, m), or the name of an SRDF group state.
        root_link: the URDF's root link (the scene file's fixed frame).
        model_name: ``robot_model_name`` of the scene files.
        mount_link: the link standing on the table or pedestal (allowed to touch it), or
            None for a robot not mounted on them.
        origin: the scene frame's origin in the robot's root frame (m).
        table_near_x: where the table starts in the scene frame (m; None: as the Panda's).
        drop: scene objects left out (they would stand inside the robot's base).
    """

    robot_dir: Path
    group: str
    ready: Mapping[str, float] | str
    root_link: str
    model_name: str
    mount_link: str | None
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)
    table_near_x: float | None = None
    drop: frozenset[str] = field(default_factory=frozenset)

    def ready_state(self, robot: RobotModel) -> Mapping[str, float]:
        if isinstance(self.ready, str):
            state = robot.named_state(self.group, self.ready)
            return {n: float(v) for n, v in zip(state.names, state.positions)}
        return self.ready


ROBOTS: dict[str, RobotSpec] = {
    "panda": RobotSpec(DATA_ROOT / "robots" / "panda", GROUP, ps.READY, "panda_link0", "panda",
                       "panda_link0"),
    # On the table as the Panda: its base link stands on the table top.
    "ur5_robotiq": RobotSpec(ROBOT_FILES / "ur5_robotiq", "manipulator", "ready", "world",
                             "ur5_robotiq85", "base_link"),
    # On the floor: the table top 0.55 m up (its shoulder 0.33-0.68 m above it over the
    # torso's travel, the Panda's 0.33 m), the scene 0.1 m forward, the table starting
    # 0.3 m in front of the base's centre (the base's radius is 0.27 m).
    "tiago": RobotSpec(ROBOT_FILES / "tiago", "arm_torso", "ready", "base_footprint", "tiago",
                       None, origin=(0.1, 0.0, 0.55), table_near_x=0.2,
                       drop=frozenset({"pedestal"})),
}


def _placed(objects: Sequence[ps.Placed]) -> list[Placed]:
    return [(n, s, w if isinstance(w, Pose) else Pose(w)) for n, s, w in objects]


def _shelf(depth: float, width: float, boards: Sequence[float], thickness: float,
           x: float = 0.75) -> list[Placed]:
    """Side panels, and a board at each height of ``boards`` (its top face there)."""
    height = boards[-1] + thickness
    objects: list[Placed] = [
        ("shelf_left", Box((depth, thickness, height)), Pose((x, width / 2, height / 2))),
        ("shelf_right", Box((depth, thickness, height)), Pose((x, -width / 2, height / 2))),
    ]
    for i, top in enumerate(boards):
        objects.append((f"shelf_board_{i}", Box((depth, width, thickness)),
                        Pose((x, 0.0, top - thickness / 2))))
    return objects


def _in_compartment(boards: Sequence[float], usable: int, x: tuple[float, float],
                    low: float, high: float) -> Target:
    """Hand pointing in (+x), in a random compartment of the first ``usable`` ones."""
    def target(rng: np.random.Generator) -> Pose:
        i = int(rng.integers(usable))
        z0, z1 = boards[i] + low, boards[i + 1] - high
        xyz = ps._uniform(rng, (x[0], -0.12, z0), (x[1], 0.12, max(z0, z1)))
        return Pose.from_se3(pin.SE3(ps._tilted(ps.FORWARD, rng, 0.15, math.pi), xyz))
    return target


def class_layout(name: str, spec: RobotSpec | None = None
                 ) -> tuple[list[Placed], list[tuple[str, str]], Target | None, Target]:
    """Objects, allowed pairs, start target (None: ready) and goal target of a class, in
    the scene frame, for ``spec``'s robot (default: the Panda)."""
    spec = spec or ROBOTS["panda"]
    ready = None
    table = _placed([ps.TABLE])
    if spec.table_near_x is not None:
        _, top, (x, y, z) = ps.TABLE
        assert isinstance(top, Box)
        size_x, size_y, size_z = top.size
        far = x + size_x / 2
        table = [("table", Box((far - spec.table_near_x, size_y, size_z)),
                  Pose(((far + spec.table_near_x) / 2, y, z)))]
    mount = spec.mount_link
    base_pair = [(mount, "table")] if mount is not None else []
    if name == "table_pick":
        return table + _placed(ps.PICK_OBJECTS), base_pair, ready, ps._grasp_target(ps.PICK_OBJECTS)
    if name == "table_under_pick":
        top_z = 0.10
        objects: list[ps.Placed] = [
            ("high_table", Box((0.60, 0.80, 0.03)), (0.70, 0.0, top_z)),
            ("floor", Box((2.0, 2.0, 0.02)), (0.3, 0.0, -0.61)),
            ("pedestal", Box((0.30, 0.30, 0.60)), (0.0, 0.0, -0.30)),
        ]
        for i, (x, y) in enumerate([(0.42, -0.38), (0.42, 0.38), (0.98, -0.38), (0.98, 0.38)]):
            objects.append((f"leg_{i}", Box((0.04, 0.04, 0.70)), (x, y, top_z - 0.015 - 0.35)))
        goal = ps._pose_target((0.48, -0.25, -0.25), (0.62, 0.25, -0.05), ps.FORWARD, tilt=0.3,
                               spin=math.pi)
        objects = [o for o in objects if o[0] not in spec.drop]
        return _placed(objects), ([(mount, "pedestal")] if mount is not None else []), ready, goal
    if name == "bookshelf_small":
        boards = (0.02, 0.31, 0.61)
        return (table + _shelf(0.3, 0.6, boards, 0.02), base_pair, ready,
                _in_compartment(boards, 2, (0.56, 0.68), 0.10, 0.10))
    if name == "bookshelf_tall":
        boards = (0.02, 0.30, 0.58, 0.86, 1.14)
        return (table + _shelf(0.3, 0.7, boards, 0.02), base_pair, ready,
                _in_compartment(boards, 3, (0.56, 0.66), 0.09, 0.09))
    if name == "bookshelf_thin":
        boards = (0.02, 0.25, 0.48, 0.71, 0.94, 1.17)
        return (table + _shelf(0.25, 0.6, boards, 0.01, x=0.72), base_pair, ready,
                _in_compartment(boards, 3, (0.58, 0.64), 0.08, 0.08))
    if name == "box":
        cx, cy = ps.BOX_CENTRE
        half, length = (ps.BOX_INNER + ps.BOX_WALL) / 2, ps.BOX_INNER + 2 * ps.BOX_WALL
        h, wall, inner = ps.BOX_HEIGHT, ps.BOX_WALL, ps.BOX_INNER
        walls: list[ps.Placed] = [
            ("box_near", Box((wall, length, h)), (cx - half, cy, h / 2)),
            ("box_far", Box((wall, length, h)), (cx + half, cy, h / 2)),
            ("box_left", Box((inner, wall, h)), (cx, cy + half, h / 2)),
            ("box_right", Box((inner, wall, h)), (cx, cy - half, h / 2)),
        ]

        def beside(rng: np.random.Generator) -> Pose:
            side = 1.0 if rng.random() < 0.5 else -1.0
            xyz = ps._uniform(rng, (cx - 0.1, cy + 0.30, 0.06), (cx + 0.1, cy + 0.40, 0.15))
            xyz[1] = cy + side * (xyz[1] - cy)
            return Pose.from_se3(pin.SE3(ps._tilted(ps.DOWN, rng, 0.2, math.pi / 2), xyz))

        inside = ps._pose_target((cx - 0.05, cy - 0.05, 0.05), (cx + 0.05, cy + 0.05, 0.12),
                                 ps.DOWN, tilt=0.15, spin=math.pi / 2)
        return table + _placed(walls), base_pair, beside, inside
    if name == "cage":
        inside = ps._pose_target((0.46, -0.06, 0.17), (0.55, 0.06, 0.27), ps.FORWARD, tilt=0.15,
                                 spin=0.5)
        behind = ps._pose_target((0.70, -0.20, 0.10), (0.78, 0.20, 0.30), ps.DOWN, tilt=0.3,
                                 spin=math.pi)
        return table + _placed(ps.cage_bars()), base_pair, inside, behind
    raise ValueError(f"'class' must be one of {', '.join(CLASSES)} (got {name!r})")


def _moved(pose: Pose, shift: pin.SE3) -> Pose:
    return Pose.from_se3(shift * pose.se3)


def _in_frame(target: Target, frame: pin.SE3) -> Target:
    """``target``'s poses, given in ``frame``, in the frame ``frame`` is given in."""
    return lambda rng: _moved(target(rng), frame)


def _shift(rng: np.random.Generator, about: tuple[float, float]) -> pin.SE3:
    """A yaw about the vertical through ``about`` and a shift in x, y."""
    yaw = rng.uniform(-YAW, YAW)
    centre = np.array([about[0], about[1], 0.0])
    rotation = pin.rpy.rpyToMatrix(0.0, 0.0, yaw)
    offset = np.append(rng.uniform(-SHIFT, SHIFT, 2), 0.0)
    return pin.SE3(rotation, centre - rotation @ centre + offset)


def make_problem(base: Scene, sampler: ps._StateSampler, name: str, rng: np.random.Generator,
                 spec: RobotSpec | None = None
                 ) -> tuple[list[Placed], list[tuple[str, str]], np.ndarray, np.ndarray, Pose]:
    """One problem: its objects (moved), allowed pairs, start, goal state and goal pose,
    in the robot's root frame."""
    spec = spec or ROBOTS["panda"]
    objects, allowed, start_target, goal_target = class_layout(name, spec)
    shift = _shift(rng, (0.6, 0.0))
    if spec.origin != (0.0, 0.0, 0.0):
        # The scene frame in the robot's: the table and the floor are placed by it too.
        origin = pin.SE3(np.eye(3), np.array(spec.origin))
        objects = [(n, s, _moved(p, origin)) for n, s, p in objects]
        shift = origin * shift * origin.inverse()
        start_target = None if start_target is None else _in_frame(start_target, origin)
        goal_target = _in_frame(goal_target, origin)
    # The table and the pedestal carry the robot: they do not move with the scene.
    fixed = {"table", "pedestal", "floor"}
    moved = [(n, s, p if n in fixed else _moved(p, shift)) for n, s, p in objects]
    scene = base.copy()
    for n, s, p in moved:
        scene.add_object(n, s, p)
    for a, b in allowed:
        scene.allow_collision(a, b)
    sampler.scene = scene
    ready = scene.state.copy()

    def shifted(target: Target) -> Target:
        return lambda r: _moved(target(r), shift)

    start = ready if start_target is None else sampler.sample(rng, shifted(start_target), ready)[0]
    if not ps.is_valid_state(scene, start):
        raise RuntimeError(f"{name}: the start state collides")
    goal, pose = sampler.sample(rng, shifted(goal_target), ready)
    assert isinstance(pose, Pose) and ps.is_valid_state(scene, goal)
    return moved, allowed, start, goal, pose


# ---------------------------------------------------------------------- YAML messages
def _header(frame: str = "world") -> dict[str, Any]:
    return {"seq": 0, "stamp": {"secs": 0, "nsecs": 0}, "frame_id": frame}


def _pose_msg(pose: Pose) -> dict[str, Any]:
    x, y, z = (round(v, 9) for v in pose.xyz)
    qx, qy, qz, qw = (round(v, 9) for v in pose.quat)
    return {"position": {"x": x, "y": y, "z": z},
            "orientation": {"x": qx, "y": qy, "z": qz, "w": qw}}


def _primitive(shape: Shape) -> dict[str, Any]:
    if isinstance(shape, Box):
        return {"type": 1, "dimensions": [round(v, 9) for v in shape.size]}
    if isinstance(shape, Cylinder):
        return {"type": 3, "dimensions": [round(shape.length, 9), round(shape.radius, 9)]}
    raise TypeError(f"no primitive for {shape!r}")


def _position(model: RobotModel, i: int, value: float) -> float:
    """``value`` of joint ``i`` to 9 decimals, rounded inward where rounding to the nearest
    would leave the joint's limits (a state at a limit stays within them when read back by
    a strict reader: roboplan refuses a start 2e-10 rad past a limit)."""
    out = round(float(value), 9)
    if out < model.lower[i]:
        out = math.ceil(float(value) * 1e9) / 1e9
    elif out > model.upper[i]:
        out = math.floor(float(value) * 1e9) / 1e9
    return out


def _joint_state(model: RobotModel, q: np.ndarray) -> dict[str, Any]:
    return {"header": _header(), "name": list(model.joint_names),
            "position": [_position(model, i, v) for i, v in enumerate(q)], "velocity": [],
            "effort": []}


def scene_message(model: RobotModel, name: str, objects: list[Placed],
                  allowed: list[tuple[str, str]], start: np.ndarray,
                  spec: RobotSpec | None = None) -> dict[str, Any]:
    spec = spec or ROBOTS["panda"]
    entries = sorted({n for pair in allowed for n in pair})
    matrix = [{"enabled": [frozenset((a, b)) in {frozenset(p) for p in allowed} for b in entries]}
              for a in entries]
    return {
        "name": name,
        "fixed_frame_transforms": [{"header": _header(), "child_frame_id": spec.root_link,
                                    "transform": {"translation": {"x": 0.0, "y": 0.0, "z": 0.0},
                                                  "rotation": {"x": 0.0, "y": 0.0, "z": 0.0,
                                                               "w": 1.0}}}],
        "robot_state": {"joint_state": _joint_state(model, start),
                        "multi_dof_joint_state": {"header": _header(), "joint_names": [],
                                                  "transforms": [], "twist": [], "wrench": []},
                        "attached_collision_objects": [], "is_diff": False},
        "robot_model_name": spec.model_name,
        "world": {"collision_objects": [
            {"header": _header(), "id": n, "type": {"key": "", "db": ""},
             "primitives": [_primitive(s)], "primitive_poses": [_pose_msg(p)],
             "meshes": [], "mesh_poses": [], "planes": [], "plane_poses": [],
             "subframe_names": [], "subframe_poses": [], "operation": 0}
            for n, s, p in objects]},
        "allowed_collision_matrix": {"entry_names": entries, "entry_values": matrix,
                                     "default_entry_names": [], "default_entry_values": []},
        "link_padding": [], "link_scale": [], "object_colors": [],
        "is_diff": False,
    }


def request_message(model: RobotModel, start: np.ndarray, goal: np.ndarray,
                    pose: Pose | None, tip: str, group_name: str = GROUP) -> dict[str, Any]:
    group = model.group(group_name)
    empty = {"name": "", "joint_constraints": [], "position_constraints": [],
             "orientation_constraints": [], "visibility_constraints": []}
    if pose is None:
        goal_constraints = {**empty, "joint_constraints": [
            {"joint_name": j, "position": _position(model, i, goal[i]), "tolerance_above": 0.001,
             "tolerance_below": 0.001, "weight": 1.0}
            for j, i in zip(group.joint_names, group.joint_indices)]}
    else:
        region_pose = _pose_msg(Pose(pose.xyz))
        goal_constraints = {**empty, "position_constraints": [{
            "header": _header(), "link_name": tip,
            "target_point_offset": {"x": 0.0, "y": 0.0, "z": 0.0},
            "constraint_region": {"primitives": [{"type": 2, "dimensions": [0.001]}],
                                  "primitive_poses": [region_pose], "meshes": [],
                                  "mesh_poses": []},
            "weight": 1.0}],
            "orientation_constraints": [{
                "header": _header(), "orientation": _pose_msg(pose)["orientation"],
                "link_name": tip, "absolute_x_axis_tolerance": 0.01,
                "absolute_y_axis_tolerance": 0.01, "absolute_z_axis_tolerance": 0.01,
                "weight": 1.0}]}
    return {
        "workspace_parameters": {"header": _header(), "min_corner": {"x": -1.5, "y": -1.5, "z": -1.5},
                                 "max_corner": {"x": 1.5, "y": 1.5, "z": 1.5}},
        "start_state": {"joint_state": _joint_state(model, start), "is_diff": False},
        "goal_constraints": [goal_constraints],
        "path_constraints": empty,
        "trajectory_constraints": {"constraints": []},
        "reference_trajectories": [],
        "pipeline_id": "ompl",
        "planner_id": "RRTConnect",
        "group_name": group_name,
        "num_planning_attempts": 1,
        "allowed_planning_time": PLANNING_TIME,
        "max_velocity_scaling_factor": 1.0,
        "max_acceleration_scaling_factor": 1.0,
    }


_PLAIN = re.compile(r"[A-Za-z_][A-Za-z0-9_./-]*")


def _scalar(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        plain = _PLAIN.fullmatch(value) and value not in ("true", "false", "null", "yes", "no")
        return value if plain else json.dumps(value)
    raise TypeError(f"cannot write {value!r}")


def _flow(value: Any) -> str | None:
    """``value`` on one line when it holds only scalars (a point, a list of numbers)."""
    if isinstance(value, dict) and all(not isinstance(v, (dict, list)) for v in value.values()):
        return "{" + ", ".join(f"{k}: {_scalar(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list) and all(not isinstance(v, (dict, list)) for v in value):
        return "[" + ", ".join(_scalar(v) for v in value) + "]"
    if not isinstance(value, (dict, list)):
        return _scalar(value)
    return None


def _lines(value: Any, indent: str) -> list[str]:
    out = []
    if isinstance(value, dict):
        for key, item in value.items():
            flow = _flow(item)
            if flow is not None:
                out.append(f"{indent}{key}: {flow}")
            else:
                out.append(f"{indent}{key}:")
                out += _lines(item, indent + "  ")
    else:
        for item in value:
            flow = _flow(item)
            if flow is not None:
                out.append(f"{indent}- {flow}")
                continue
            inner = _lines(item, indent + "  ")
            out.append(f"{indent}- {inner[0].lstrip()}")
            out += inner[1:]
    return out


def _dump(data: dict[str, Any], path: Path) -> None:
    """Write ``data`` as block YAML (scalars-only mappings and lists on one line)."""
    path.write_text("\n".join(_lines(data, "")) + "\n")


def check_problem(model: RobotModel, folder: Path, stem: str) -> None:
    """Read a written problem back and check both states in the scene it describes."""
    from taskrunner.moveit import load_motion_plan_request, load_planning_scene

    scene = Scene(model)
    loaded = load_planning_scene(folder / f"{stem}_scene.yaml", model, strict=True)
    loaded.apply(scene)
    request = load_motion_plan_request(folder / f"{stem}_request.yaml", model, strict=True)
    load_motion_plan_request(folder / f"{stem}_pose_request.yaml", model, strict=True)
    start = model.state_with(scene.state, request.start)
    checks = request.joint_goals[0]
    assert checks is not None
    goal = model.state_with(start, {c.joint: c.position for c in checks})
    for what, q in (("start", start), ("goal", goal)):
        if not ps.is_valid_state(scene, q):
            raise RuntimeError(f"{folder / stem}: the {what} state collides or is out of limits "
                               f"({scene.collisions(q)[:2]})")


def plan_problems(model: RobotModel, folder: Path, count: int, pose: bool = False
                  ) -> dict[str, Any]:
    """Plan the first ``count`` problems of a class folder (seed 0, the request's own
    planner and time cap), through :mod:`taskrunner.moveit`; success and times."""
    from taskrunner.moveit import load_motion_plan_request, load_planning_scene, plan_request_file

    base = Scene(model)
    times, lengths, failures = [], [], []
    for i in range(count):
        stem = f"{i + 1:04d}"
        scene = base.copy()
        load_planning_scene(folder / f"{stem}_scene.yaml", model).apply(scene)
        kind = "pose_request" if pose else "request"
        request = load_motion_plan_request(folder / f"{stem}_{kind}.yaml", model)
        report = plan_request_file(scene, request, seed=0)
        if report.success:
            times.append(report.total_time)
            lengths.append(report.path_length)
        else:
            failures.append(f"{stem}: {report.error_kind}")
    return {"planned": count, "solved": len(times),
            "median_total_s": round(float(np.median(times)), 4) if times else None,
            "p90_total_s": round(float(np.percentile(times, 90)), 4) if times else None,
            "median_length_rad": round(float(np.median(lengths)), 3) if lengths else None,
            "failures": failures}


def robot_spec(name: str) -> RobotSpec:
    """The :class:`RobotSpec` of a robot of ``ROBOTS``."""
    if name not in ROBOTS:
        raise SystemExit(f"error: unknown robot {name!r}; known: {', '.join(ROBOTS)}")
    return ROBOTS[name]


def generate(out: Path, count: int, seed: int = 0, classes: Sequence[str] = CLASSES,
             check: bool = False, robot_name: str = "panda") -> dict[str, Any]:
    """Write ``count`` problems per class under ``out/<class>/`` for a robot of
    ``ROBOTS``; returns a summary."""
    spec = robot_spec(robot_name)
    robot = load_robot(spec.robot_dir)
    base = Scene(robot)
    base.set_state(spec.ready_state(robot))
    if not ps.is_valid_state(base, base.state):
        raise SystemExit(f"error: {robot_name}'s ready state collides or is out of limits "
                         f"({base.collisions(base.state)[:2]})")
    sampler = ps._StateSampler(base, spec.group)
    tip = robot.group(spec.group).tip_link
    assert tip is not None
    summary: dict[str, Any] = {"robot": robot_name, "seed": seed, "count": count, "classes": {}}
    for name in classes:
        if name not in CLASSES:
            raise SystemExit(f"error: unknown class {name!r}; known: {', '.join(CLASSES)}")
        started = time.perf_counter()
        folder = out / name
        folder.mkdir(parents=True, exist_ok=True)
        for i in range(count):
            rng = np.random.default_rng([seed, CLASSES.index(name), i])
            objects, allowed, start, goal, pose = make_problem(base, sampler, name, rng, spec)
            stem = f"{i + 1:04d}"
            _dump(scene_message(robot, f"{name}_{stem}", objects, allowed, start, spec),
                  folder / f"{stem}_scene.yaml")
            _dump(request_message(robot, start, goal, None, tip, spec.group),
                  folder / f"{stem}_request.yaml")
            _dump(request_message(robot, start, goal, pose, tip, spec.group),
                  folder / f"{stem}_pose_request.yaml")
            if check:
                check_problem(robot, folder, stem)
        summary["classes"][name] = {"problems": count,
                                    "seconds": round(time.perf_counter() - started, 2)}
    return summary


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", default="panda", help=f"robot ({', '.join(ROBOTS)}; panda)")
    parser.add_argument("--count", type=int, default=100, help="problems per class (100)")
    parser.add_argument("--seed", type=int, default=0, help="seed (0)")
    parser.add_argument("--out", type=Path, default=BENCH / "problems",
                        help="output folder (benchmarks/problems)")
    parser.add_argument("--classes", default=",".join(CLASSES),
                        help=f"comma-separated classes ({','.join(CLASSES)})")
    parser.add_argument("--check", action="store_true",
                        help="read every problem back and check its states again")
    parser.add_argument("--plan", type=int, default=0, metavar="N",
                        help="then plan the first N problems of each class (joint goals) "
                             "and report success and times")
    parser.add_argument("--pose", action="store_true", help="with --plan: the pose-goal requests")
    args = parser.parse_args(argv)
    started = time.perf_counter()
    summary = generate(args.out, args.count, args.seed, args.classes.split(","), args.check,
                       args.robot)
    summary["seconds"] = round(time.perf_counter() - started, 2)
    if args.plan:
        robot = load_robot(robot_spec(args.robot).robot_dir)
        for name in summary["classes"]:
            summary["classes"][name]["plan"] = plan_problems(
                robot, args.out / name, min(args.plan, args.count), args.pose)
    print(json.dumps(summary, indent=2))
    print(f"\n{'class':<18} {'problems':>8} {'seconds':>8} {'solved':>8} {'median s':>9} {'p90 s':>7}")
    for name, row in summary["classes"].items():
        plan = row.get("plan", {})
        solved = f"{plan['solved']}/{plan['planned']}" if plan else "-"
        median = f"{plan['median_total_s']}" if plan else "-"
        p90 = f"{plan['p90_total_s']}" if plan else "-"
        print(f"{name:<18} {row['problems']:>8} {row['seconds']:>8.2f} {solved:>8} {median:>9} {p90:>7}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
