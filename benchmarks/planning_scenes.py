"""Scenes and seeded queries of the planning benchmark (``benchmarks/planning.py``).

Every scene is built from boxes and cylinders around a robot of ours; every query is a
start state and a goal, both checked within the joint limits and collision-free while
building, so each one is solvable. Start and goal states come from seeded inverse
kinematics on sampled target poses (positions for the servo arms), each search started
near the scene's start pose (``ready``, ``home``, ``Candle``: each joint moved by up to
``SEED_SPREAD``), so they keep a natural posture; the query set depends only on the seed,
and its first queries do not depend on the count.

Problems (world frame: z up, m; the Panda's base at the origin on its table top):

* ``panda_table_pick``: from ``ready`` to grasp poses (hand pointing down, 2-8 cm above
  the top) over five objects on the table; ``panda_table_pick_pose`` asks for the same
  poses as pose goals (the planner samples IK goal states itself).
* ``panda_under_table``: the Panda on a pedestal, a table top 10 cm above its base in
  front: from ``ready`` to the hand under the table top, pointing forward.
* ``panda_shelf``: a shelf with a middle board: from the upper compartment to the lower.
* ``panda_box``: from beside an open box (20 cm walls) to inside it, over a wall.
* ``panda_cage``: the hand starts inside a cage of 1.6 cm bars (cylinders, 6 cm apart)
  with a lid and one window facing the robot, and must get out to behind the cage.
* ``servo_table``: the servo arm on its table (``robots/cells/servo_arm_table.yaml``) plus
  a cup and a post: from ``home`` to points above the table.
* ``servo_pair_swap``: the two servo arms (``servo_arm_pair.yaml``, group ``both_arms``)
  swap sides: the left hand goes from the -y side of the table's middle to the +y side
  and the right hand the other way, both hands within 6 cm of the middle line, so the
  arms must pass each other (the straight joint-space line from start to goal collides
  in every query). The shelf and box queries are likewise never a free straight line.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError, SceneError, UnknownNameError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.planning import Goal, JointGoal, PoseGoal
from taskrunner.planning.planner import interpolate_path
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel, load_robot
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.shapes import Box, Cylinder, Shape
from taskrunner.types import Pose

__all__ = ["BUILDERS", "PROBLEM_NAMES", "Problem", "Query", "build_problems", "is_valid_state"]

ROOT = Path(__file__).resolve().parents[1]

READY = {
    "panda_joint1": 0.0, "panda_joint2": -0.785398, "panda_joint3": 0.0,
    "panda_joint4": -2.356194, "panda_joint5": 0.0, "panda_joint6": 1.570796,
    "panda_joint7": 0.785398, "panda_finger_joint1": 0.04,
}
DOWN = pin.rpy.rpyToMatrix(math.pi, 0.0, 0.0)  # tool z axis pointing down (-z)
FORWARD = pin.rpy.rpyToMatrix(0.0, math.pi / 2, 0.0)  # tool z axis pointing forward (+x)
DEFAULT_TIME = 1.0  # s: planning_time cap per query
HARD_TIME = 2.0  # s: the cage's cap
# IK for goal states starts this far (rad, per joint at most) from the scene's start pose:
# the solutions keep its elbow-up posture family, as a pick-and-place program would.
SEED_SPREAD = 0.8

# The table the Panda stands on (top at z = 0; link0 may touch it).
TABLE = ("table", Box((1.4, 1.4, 0.04)), (0.35, 0.0, -0.02))
# Objects on the table for panda_table_pick: name, shape, centre (their bottoms at z = 0).
PICK_OBJECTS = (
    ("cereal", Box((0.07, 0.18, 0.24)), (0.55, -0.28, 0.12)),
    ("can", Cylinder(0.033, 0.12), (0.42, 0.18, 0.06)),
    ("bottle", Cylinder(0.04, 0.26), (0.66, 0.06, 0.13)),
    ("block", Box((0.05, 0.05, 0.05)), (0.42, -0.06, 0.025)),
    ("book", Box((0.20, 0.15, 0.04)), (0.55, 0.36, 0.02)),
)
# The shelf of tests/planning (middle board top at z = 0.31, top board from 0.60).
SHELF = (
    ("shelf_left", Box((0.3, 0.02, 0.6)), (0.75, -0.3, 0.3)),
    ("shelf_right", Box((0.3, 0.02, 0.6)), (0.75, 0.3, 0.3)),
    ("shelf_board", Box((0.3, 0.6, 0.02)), (0.75, 0.0, 0.3)),
    ("shelf_top", Box((0.3, 0.62, 0.02)), (0.75, 0.0, 0.61)),
)
# Open box on the table: inner 0.30 x 0.30, walls 0.20 high and 1 cm thick.
BOX_CENTRE = (0.5, 0.0)
BOX_INNER, BOX_HEIGHT, BOX_WALL = 0.30, 0.20, 0.01
# Cage on the table: inner x in [0.38, 0.62], y in [-0.16, 0.16], lid at 0.36; window in
# the wall facing the robot (x = 0.38): y in [-0.12, 0.12], z in [0.12, 0.32].
CAGE_X, CAGE_Y, CAGE_TOP = (0.38, 0.62), 0.16, 0.36
CAGE_WINDOW_Y, CAGE_WINDOW_Z = 0.12, (0.12, 0.32)
CAGE_BAR_RADIUS, CAGE_SPACING = 0.008, 0.06


# An object to add: name, shape, and its centre (m, world) or pose.
Placed = tuple[str, Shape, "tuple[float, float, float] | Pose"]


@dataclass(frozen=True)
class Query:
    """One planning query.

    Attributes:
        start: full state vector the plan starts from (rad, m for fingers).
        goal: what the request asks for.
        goal_state: a full state vector satisfying ``goal`` (for a pose goal, the IK
            solution found while building), checked collision-free.
    """

    start: np.ndarray
    goal: Goal
    goal_state: np.ndarray


@dataclass(frozen=True)
class Problem:
    """A scene, the group planned for and its queries.

    Attributes:
        planning_time: cap of the search per query (s).
        description: one line for the table.
    """

    name: str
    scene: Scene
    group: str
    queries: tuple[Query, ...]
    planning_time: float
    description: str


def is_valid_state(scene: Scene, q: np.ndarray) -> bool:
    """Within the joint limits and collision-free (self, world)."""
    return bool(scene.robot.within_limits(q)) and not scene.in_collision(q)


def _straight_line_free(scene: Scene, a: np.ndarray, b: np.ndarray, step: float = 0.02) -> bool:
    """True if the joint-space segment from ``a`` to ``b`` is collision-free every ``step`` rad."""
    return all(not scene.in_collision(q) for q in interpolate_path(np.vstack([a, b]), step))


def _uniform(rng: np.random.Generator, low: Sequence[float], high: Sequence[float]) -> np.ndarray:
    return rng.uniform(np.asarray(low, dtype=float), np.asarray(high, dtype=float))


def _tilted(rotation: np.ndarray, rng: np.random.Generator, tilt: float, spin: float) -> np.ndarray:
    """``rotation`` turned about its own z by up to ``spin`` and tilted by up to ``tilt`` (rad)."""
    spin_angle = rng.uniform(-spin, spin)
    axis = rng.normal(size=2)
    axis = np.append(axis / np.linalg.norm(axis), 0.0)
    return rotation @ pin.exp3(axis * rng.uniform(0.0, tilt)) @ pin.rpy.rpyToMatrix(0, 0, spin_angle)


class _StateSampler:
    """Collision-free IK solutions of one group (its tip link) for sampled targets.

    Each IK call starts near a base state, with its own seeded restarts and a generous
    timeout, so the attempts (not the clock) end a search: the solutions depend on the
    seed only. Position-only groups (the servo arms) take positions as targets.
    """

    def __init__(self, scene: Scene, group: str) -> None:
        self.scene = scene
        self.model: RobotModel = scene.robot
        self.group = self.model.group(group)
        self.solver = IkSolver(self.model, self.group)

    def sample(self, rng: np.random.Generator, target: Callable[[np.random.Generator], object],
               base: np.ndarray, spread: float | None = SEED_SPREAD,
               tries: int = 400) -> tuple[np.ndarray, object]:
        """One valid state (full vector, other joints as in ``base``) and its target.

        IK starts from ``base`` with each joint of the group moved by up to ``spread``
        (rad; None: anywhere within the limits).
        """
        idx = self.group.joint_indices
        lower, upper = self.model.lower[idx], self.model.upper[idx]
        for _ in range(tries):
            goal = target(rng)
            seed_q = base.copy()
            if spread is None:
                seed_q[idx] = rng.uniform(lower, upper)
            else:
                seed_q[idx] = np.clip(base[idx] + rng.uniform(-spread, spread, len(idx)), lower, upper)
            options = IkOptions(tolerance=1e-5, timeout=1.0, attempts=12,
                                seed=int(rng.integers(2**31)))
            try:
                solution = self.solver.solve(goal, seed_q=seed_q, options=options)
            except IkFailedError:
                continue
            q = np.array(solution.q, dtype=float)
            if is_valid_state(self.scene, q):
                return q, goal
        raise SceneError(f"no valid state for group {self.group.name!r} in {tries} tries")


# ---------------------------------------------------------------------- Panda scenes
def _panda_scene(robot: RobotModel, objects: Sequence[Placed],
                 table: bool = True) -> Scene:
    """The Panda at ``ready`` (fingers open) among ``objects``, on its table if ``table``."""
    scene = Scene(robot)
    for name, shape, where in ([TABLE] if table else []) + list(objects):
        scene.add_object(name, shape, where if isinstance(where, Pose) else Pose(where))
    if table:
        scene.allow_collision("panda_link0", TABLE[0])
    scene.set_state(READY)
    return scene


def _grasp_target(objects: Sequence[tuple[str, Box | Cylinder, tuple[float, float, float]]]
                  ) -> Callable[[np.random.Generator], Pose]:
    """Hand pointing down over a random object's top, 2-8 cm above it, any yaw."""
    def target(rng: np.random.Generator) -> Pose:
        _, shape, (x, y, z) = objects[int(rng.integers(len(objects)))]
        top = z + (shape.size[2] / 2 if isinstance(shape, Box) else shape.length / 2)
        xyz = np.array([x, y, top + rng.uniform(0.02, 0.08)]) + np.append(rng.uniform(-0.01, 0.01, 2), 0)
        rotation = _tilted(DOWN, rng, tilt=0.2, spin=math.pi / 2)
        return Pose.from_se3(pin.SE3(rotation, xyz))
    return target


def _pose_target(low: Sequence[float], high: Sequence[float], rotation: np.ndarray,
                 tilt: float, spin: float) -> Callable[[np.random.Generator], Pose]:
    def target(rng: np.random.Generator) -> Pose:
        return Pose.from_se3(pin.SE3(_tilted(rotation, rng, tilt, spin), _uniform(rng, low, high)))
    return target


def _queries(scene: Scene, group: str, count: int, rng: np.random.Generator,
             start: Callable[[np.random.Generator], np.ndarray],
             goal: Callable[[np.random.Generator], tuple[np.ndarray, object]],
             nontrivial: bool = False, tries: int = 50) -> tuple[Query, ...]:
    """``count`` joint-goal queries; ``nontrivial`` rejects those whose straight line is free."""
    idx = scene.robot.group(group).joint_indices
    names = scene.robot.group(group).joint_names
    queries = []
    for _ in range(count * tries):
        q_start = start(rng)
        q_goal, _ = goal(rng)
        if nontrivial and _straight_line_free(scene, q_start, q_goal):
            continue
        queries.append(Query(q_start, JointGoal(dict(zip(names, q_goal[idx]))), q_goal))
        if len(queries) == count:
            return tuple(queries)
    raise SceneError(f"only {len(queries)} of {count} queries found for group {group!r}")


def panda_table_pick(robot: RobotModel, count: int, rng: np.random.Generator,
                     pose_goals: bool = False) -> Problem:
    scene = _panda_scene(robot, PICK_OBJECTS)
    sampler = _StateSampler(scene, "arm")
    ready = scene.state.copy()
    target = _grasp_target(PICK_OBJECTS)
    names = robot.group("arm").joint_names
    idx = robot.group("arm").joint_indices
    queries = []
    for _ in range(count):
        q_goal, pose = sampler.sample(rng, target, ready)
        goal: Goal = (PoseGoal(pose) if pose_goals  # type: ignore[arg-type]
                      else JointGoal(dict(zip(names, q_goal[idx]))))
        queries.append(Query(ready, goal, q_goal))
    name = "panda_table_pick_pose" if pose_goals else "panda_table_pick"
    kind = "pose goals, IK sampled by the planner" if pose_goals else "joint goals"
    return Problem(name, scene, "arm", tuple(queries), DEFAULT_TIME,
                   f"Panda ready -> over 5 objects on a table ({kind})")


def panda_under_table(robot: RobotModel, count: int, rng: np.random.Generator) -> Problem:
    top_z, legs = 0.10, []
    for i, (x, y) in enumerate([(0.42, -0.38), (0.42, 0.38), (0.98, -0.38), (0.98, 0.38)]):
        legs.append((f"leg_{i}", Box((0.04, 0.04, 0.70)), (x, y, top_z - 0.015 - 0.35)))
    objects = [
        ("high_table", Box((0.60, 0.80, 0.03)), (0.70, 0.0, top_z)),
        ("floor", Box((2.0, 2.0, 0.02)), (0.3, 0.0, -0.61)),
        *legs,
    ]
    scene = _panda_scene(robot, objects, table=False)
    scene.add_object("pedestal", Box((0.30, 0.30, 0.60)), Pose((0.0, 0.0, -0.30)))
    scene.allow_collision("panda_link0", "pedestal")
    sampler = _StateSampler(scene, "arm")
    ready = scene.state.copy()
    target = _pose_target((0.48, -0.25, -0.25), (0.62, 0.25, -0.05), FORWARD, tilt=0.3,
                          spin=math.pi)
    queries = _queries(scene, "arm", count, rng, lambda r: ready,
                       lambda r: sampler.sample(r, target, ready))
    return Problem("panda_under_table", scene, "arm", queries, DEFAULT_TIME,
                   "Panda on a pedestal, ready -> hand under a table top")


def panda_shelf(robot: RobotModel, count: int, rng: np.random.Generator) -> Problem:
    scene = _panda_scene(robot, SHELF)
    sampler = _StateSampler(scene, "arm")
    ready = scene.state.copy()
    upper = _pose_target((0.56, -0.15, 0.40), (0.70, 0.15, 0.50), FORWARD, tilt=0.15, spin=math.pi)
    lower = _pose_target((0.56, -0.15, 0.10), (0.70, 0.15, 0.20), FORWARD, tilt=0.15, spin=math.pi)
    queries = _queries(scene, "arm", count, rng, lambda r: sampler.sample(r, upper, ready)[0],
                       lambda r: sampler.sample(r, lower, ready), nontrivial=True)
    return Problem("panda_shelf", scene, "arm", queries, DEFAULT_TIME,
                   "Panda hand above a shelf board -> under it")


def panda_box(robot: RobotModel, count: int, rng: np.random.Generator) -> Problem:
    cx, cy = BOX_CENTRE
    half = (BOX_INNER + BOX_WALL) / 2
    length = BOX_INNER + 2 * BOX_WALL
    walls = [
        ("box_near", Box((BOX_WALL, length, BOX_HEIGHT)), (cx - half, cy, BOX_HEIGHT / 2)),
        ("box_far", Box((BOX_WALL, length, BOX_HEIGHT)), (cx + half, cy, BOX_HEIGHT / 2)),
        ("box_left", Box((BOX_INNER, BOX_WALL, BOX_HEIGHT)), (cx, cy + half, BOX_HEIGHT / 2)),
        ("box_right", Box((BOX_INNER, BOX_WALL, BOX_HEIGHT)), (cx, cy - half, BOX_HEIGHT / 2)),
    ]
    scene = _panda_scene(robot, walls)
    sampler = _StateSampler(scene, "arm")
    ready = scene.state.copy()
    inside = _pose_target((cx - 0.05, cy - 0.05, 0.05), (cx + 0.05, cy + 0.05, 0.12), DOWN,
                          tilt=0.15, spin=math.pi / 2)

    def beside(rng: np.random.Generator) -> Pose:
        side = 1.0 if rng.random() < 0.5 else -1.0
        xyz = _uniform(rng, (cx - 0.1, cy + 0.30, 0.06), (cx + 0.1, cy + 0.40, 0.15))
        xyz[1] = cy + side * (xyz[1] - cy)
        return Pose.from_se3(pin.SE3(_tilted(DOWN, rng, 0.2, math.pi / 2), xyz))

    queries = _queries(scene, "arm", count, rng, lambda r: sampler.sample(r, beside, ready)[0],
                       lambda r: sampler.sample(r, inside, ready), nontrivial=True)
    return Problem("panda_box", scene, "arm", queries, DEFAULT_TIME,
                   "Panda hand beside an open box -> inside it, over a wall")


def cage_bars() -> list[Placed]:
    """The cage's bars (vertical cylinders), window rails and lid."""
    (x0, x1), y, top = CAGE_X, CAGE_Y, CAGE_TOP
    bars: list[Placed] = []

    def vertical(name: str, x: float, yy: float, z0: float, z1: float) -> None:
        bars.append((name, Cylinder(CAGE_BAR_RADIUS, z1 - z0), (x, yy, (z0 + z1) / 2)))

    for i, yy in enumerate(np.linspace(-y, y, round(2 * y / CAGE_SPACING) + 1)):
        vertical(f"bar_far_{i}", x1, float(yy), 0.0, top)
        inside_window = abs(yy) < CAGE_WINDOW_Y
        vertical(f"bar_near_{i}", x0, float(yy), 0.0, CAGE_WINDOW_Z[0] if inside_window else top)
    for i, xx in enumerate(np.linspace(x0, x1, round((x1 - x0) / CAGE_SPACING) + 1)[1:-1]):
        vertical(f"bar_left_{i}", float(xx), y, 0.0, top)
        vertical(f"bar_right_{i}", float(xx), -y, 0.0, top)
    rail = pin.rpy.rpyToMatrix(math.pi / 2, 0.0, 0.0)  # cylinder axis along y
    for name, z in (("rail_low", CAGE_WINDOW_Z[0]), ("rail_high", CAGE_WINDOW_Z[1])):
        bars.append((name, Cylinder(CAGE_BAR_RADIUS, 2 * y),
                     Pose.from_se3(pin.SE3(rail, np.array([x0, 0.0, z])))))
    bars.append(("cage_lid", Box((x1 - x0 + 0.04, 2 * y + 0.04, 0.01)),
                 ((x0 + x1) / 2, 0.0, top + 0.005)))
    return bars


def panda_cage(robot: RobotModel, count: int, rng: np.random.Generator) -> Problem:
    scene = _panda_scene(robot, cage_bars())
    sampler = _StateSampler(scene, "arm")
    ready = scene.state.copy()
    inside = _pose_target((0.46, -0.06, 0.17), (0.55, 0.06, 0.27), FORWARD, tilt=0.15, spin=0.5)
    behind = _pose_target((0.70, -0.20, 0.10), (0.78, 0.20, 0.30), DOWN, tilt=0.3, spin=math.pi)
    queries = _queries(scene, "arm", count, rng, lambda r: sampler.sample(r, inside, ready)[0],
                       lambda r: sampler.sample(r, behind, ready))
    return Problem("panda_cage", scene, "arm", queries, HARD_TIME,
                   "Panda hand inside a cage of bars -> out of its window, behind the cage")


# ---------------------------------------------------------------------- servo arms
def servo_table(count: int, rng: np.random.Generator) -> Problem:
    cell = load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml")
    scene = scene_from_cell(cell)
    scene.add_object("cup", Cylinder(0.035, 0.10), Pose((0.22, 0.09, 0.80)))
    scene.add_object("post", Cylinder(0.012, 0.30), Pose((0.16, -0.10, 0.90)))
    home = scene.state.copy()
    sampler = _StateSampler(scene, "arm")

    def point(rng: np.random.Generator) -> np.ndarray:
        radius, angle = rng.uniform(0.12, 0.30), rng.uniform(-1.3, 1.3)
        return np.array([radius * math.cos(angle), radius * math.sin(angle), rng.uniform(0.80, 0.92)])

    queries = _queries(scene, "arm", count, rng, lambda r: home,
                       lambda r: sampler.sample(r, point, home))
    return Problem("servo_table", scene, "arm", queries, DEFAULT_TIME,
                   "servo arm home -> points above its table (cup, post, tray)")


def servo_pair_swap(count: int, rng: np.random.Generator) -> Problem:
    cell = load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml")
    scene = scene_from_cell(cell)
    model = scene.robot
    base = scene.state.copy()
    # Each arm is solved with the other one out of the way; the pair is checked after.
    alone = _arm_alone(cell)
    left, right = _StateSampler(alone, "left_arm"), _StateSampler(alone, "right_arm")
    right_idx = model.group("right_arm").joint_indices

    def front_back(side: float, sign: float) -> Callable[[np.random.Generator], np.ndarray]:
        def point(rng: np.random.Generator) -> np.ndarray:
            return np.array([side * rng.uniform(-0.03, 0.06), sign * rng.uniform(0.05, 0.15),
                             rng.uniform(0.78, 0.88)])
        return point

    def pair(rng: np.random.Generator, left_sign: float) -> tuple[np.ndarray, object]:
        for _ in range(200):
            q_left, _ = left.sample(rng, front_back(-1.0, left_sign), base)
            q_right, _ = right.sample(rng, front_back(1.0, -left_sign), base)
            q = q_left.copy()
            q[right_idx] = q_right[right_idx]
            if is_valid_state(scene, q):
                return q, None
        raise SceneError("no valid two-arm state found")

    queries = _queries(scene, "both_arms", count, rng, lambda r: pair(r, -1.0)[0],
                       lambda r: pair(r, 1.0), nontrivial=True)
    return Problem("servo_pair_swap", scene, "both_arms", queries, DEFAULT_TIME,
                   "two servo arms swap sides (-y <-> +y) across the table's middle")


def _arm_alone(cell) -> Scene:  # type: ignore[no-untyped-def]
    """The pair's scene with the arms allowed to touch each other (to solve one at a time)."""
    scene = scene_from_cell(cell)
    left = [n for n in scene.robot.link_names if n.startswith("left_")]
    right = [n for n in scene.robot.link_names if n.startswith("right_")]
    for a in left:
        for b in right:
            scene.allow_collision(a, b)
    return scene


BUILDERS: dict[str, Callable[..., Problem]] = {
    "panda_table_pick": lambda robot, n, rng: panda_table_pick(robot, n, rng),
    "panda_table_pick_pose": lambda robot, n, rng: panda_table_pick(robot, n, rng, pose_goals=True),
    "panda_under_table": panda_under_table,
    "panda_shelf": panda_shelf,
    "panda_box": panda_box,
    "panda_cage": panda_cage,
    "servo_table": lambda robot, n, rng: servo_table(n, rng),
    "servo_pair_swap": lambda robot, n, rng: servo_pair_swap(n, rng),
}
PROBLEM_NAMES = tuple(BUILDERS)


def build_problems(count: int, seed: int = 0, names: Sequence[str] | None = None) -> list[Problem]:
    """The problems ``names`` (default all), ``count`` queries each, from ``seed``.

    Each problem draws from its own generator (seeded by ``seed`` and its position in
    :data:`PROBLEM_NAMES`), so a problem's queries do not depend on which others are built.

    Raises:
        UnknownNameError: an unknown problem name.
        SceneError: a scene did not yield enough valid queries.
    """
    names = list(PROBLEM_NAMES if names is None else names)
    for name in names:
        if name not in BUILDERS:
            raise UnknownNameError("problem", name, list(PROBLEM_NAMES))
    robot = load_robot(DATA_ROOT / "robots" / "panda")
    problems = []
    for name in names:
        # panda_table_pick_pose shares panda_table_pick's poses: same generator.
        key = "panda_table_pick" if name == "panda_table_pick_pose" else name
        rng = np.random.default_rng([seed, PROBLEM_NAMES.index(key)])
        problems.append(BUILDERS[name](robot, count, rng))
    return problems
