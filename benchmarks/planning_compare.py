"""Side-by-side planning benchmark: our planner and roboplan's RRT-Connect on the same
MoveIt problems, in the same run, interleaved; every returned path checked by an
independent exact-mesh validator.

    python benchmarks/planning_compare.py [--per-class 100] [--classes table_pick,cage]
                                          [--seed 0] [--problem-seed 0] [--problems DIR]
                                          [--cap 5] [--roboplan-shortcut]
                                          [--roboplan-max-nodes N] [--json]
    python benchmarks/planning.py --compare ...   # the same

Problems: the seeded Panda problem sets of ``make_problems.py`` (seven classes: table pick,
under-table pick, bookshelf small / tall / thin, box, cage), regenerated into
``benchmarks/problems`` (or read from ``--problems DIR`` as they are), joint goals
(``NNNN_request.yaml``). Ours reads each problem through :mod:`taskrunner.moveit`
(``load_planning_scene(...).apply``, ``load_motion_plan_request(...).plan_request``) and
plans it with :class:`MotionPlanner` (timing off: no trajectory); roboplan gets the same
URDF (example-robot-data's Panda), our SRDF (groups, disabled pairs) and the scene file's
objects and allowed pairs, as read by the validator below. ``--robot ur5_robotiq`` /
``--robot tiago``: the same on ``make_problems.py``'s sets of that robot (its plain URDF and
SRDF in ``benchmarks/robots``, regenerated into ``benchmarks/problems_ROBOT`` unless
``--problems``). Each problem is planned by
both, one after the other, alternating which goes first; the wall time of the one plan
call is measured (``MotionPlanner.plan``: start and goal checks, search, shortcut, exact
verification; the scene's collision model, path verifier and state screen are built before the timer,
as roboplan's scene and planner are, unless ``--cold-scene``; ``RRT.plan``: search only, roboplan returns the RRT-Connect path without
shortcutting unless ``--roboplan-shortcut``). Both run with the cap as their time limit
(the request's ``allowed_planning_time``, 5 s; roboplan's ``max_planning_time``); a
problem is solved when a path comes back within the cap (and, for ours, meets the goal
constraints as written). roboplan runs with its default ``RRTOptions`` except
``rrt_connect``, ``max_planning_time`` and ``max_nodes`` (default here 1,000,000 instead
of its 1000, so that the time cap is what ends a search).

Collision geometry: roboplan checks the URDF's collision meshes as pinocchio loads them
(triangle meshes, BVH); ours checks its ``collision: auto`` geometry (a link's convex hull
where it stands at most 5 mm off the mesh, the mesh elsewhere). The validator checks the
exact meshes.

The validator (this file, not the planner's own checks): pinocchio FK and coal on the
URDF's collision meshes (``BVHModelOBBRSS``, not hulls) and the scene file's primitives,
robot against world and robot against itself, except the pairs the SRDF disables, the
URDF's parent/child link pairs and the scene file's allowed pairs. Each path segment is
interpolated on a grid on which no point of any link moves more than 0.5 mm between
neighbouring states: a geometry's displacement over a step is bounded by
``sum_j |dq_j| * r_j``, with ``r_j`` the distance from joint j's origin (a point on its
axis) to the geometry's farthest vertex, bounded without the configuration (the norms of
the joint offsets along the chain plus the vertex's norm in its joint's frame). A pair is
checked on that grid except where its exact distance proves the skipped states free (a
pair at distance d cannot touch before the bound of the motion reaches d; for a self pair
the two bounds are summed). A path is invalid when any checked state collides, leaves
the joint limits, or the path does not start at the start state and end at the goal
(within the goal's tolerance); the largest penetration depth is reported.

Output: a table per class (solved % each, median and p95 ms each, ratio of the medians
ours/roboplan, invalid paths each, median path length) and, with ``--json``, one JSON
object on the last line. Medians and p95 are over all problems of a class, an unsolved
problem counting as the cap.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import sys
import time
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

BENCH = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH))
if str(BENCH.parent) not in sys.path:
    sys.path.insert(0, str(BENCH.parent))

import coal
import make_problems
import pinocchio as pin
import yaml

from taskrunner.errors import PlanningError
from taskrunner.moveit import load_motion_plan_request, load_planning_scene
from taskrunner.planning import MotionPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel, load_robot
from taskrunner.robot.packages import example_robot_data_dir
from taskrunner.scene import Scene

try:
    import roboplan.core as rp_core
    import roboplan.rrt as rp_rrt
except ImportError:  # the bench extra: pip install taskrunner[bench]
    rp_core = rp_rrt = None

__all__ = ["CLASSES", "ExactValidator", "SceneFile", "Roboplan", "read_scene_file", "run"]

CLASSES = make_problems.CLASSES
GROUP = "arm"
RESOLUTION = 0.0005  # m: largest motion of any point of any link between checked states
ROBOPLAN_MAX_NODES = 1_000_000
PANDA_SRDF = DATA_ROOT / "robots" / "panda" / "config" / "panda.srdf"


def robot_files(robot: str) -> tuple[Path, list[Path], Path, make_problems.RobotSpec]:
    """A robot of ``make_problems.ROBOTS``: its plain URDF, the folders its ``package://``
    paths live in, its SRDF and its spec (the Panda: example-robot-data's URDF, our SRDF)."""
    spec = make_problems.robot_spec(robot)
    if robot == "panda":
        urdf, root = panda_urdf()
        return urdf, [root], PANDA_SRDF, spec
    share = example_robot_data_dir()
    if share is None:
        raise SystemExit("error: the example-robot-data wheel is not installed")
    name = spec.robot_dir.name
    return (spec.robot_dir / f"{name}.urdf", [share.parent, spec.robot_dir.parent],
            spec.robot_dir / f"{name}.srdf", spec)


def panda_urdf() -> tuple[Path, Path]:
    """example-robot-data's Panda URDF and the folder its ``package://`` paths live in."""
    share = example_robot_data_dir()
    if share is None:
        raise SystemExit("error: the example-robot-data wheel is not installed")
    return share / "robots" / "panda_description" / "urdf" / "panda.urdf", share.parent


# ------------------------------------------------------------------- scene file
@dataclass
class SceneFile:
    """The parts of a MoveIt PlanningScene file both roboplan and the validator use:
    objects as world-placed primitives, and the allowed pairs."""

    path: Path
    objects: list[tuple[str, str, tuple[float, ...], pin.SE3]]  # name, kind, dims, pose
    allowed: set[frozenset[str]]
    allowed_all: set[str] = field(default_factory=set)  # default entries: allowed with all

    def allows(self, a: str, b: str) -> bool:
        return a in self.allowed_all or b in self.allowed_all or frozenset((a, b)) in self.allowed


_KINDS = {1: "box", 2: "sphere", 3: "cylinder", 4: "cone"}


def _pose(msg: dict[str, Any], where: str) -> pin.SE3:
    try:
        p, o = msg["position"], msg["orientation"]
        quat = pin.Quaternion(float(o["w"]), float(o["x"]), float(o["y"]), float(o["z"]))
        xyz = np.array([float(p["x"]), float(p["y"]), float(p["z"])])
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"{where}: not a geometry_msgs/Pose ({exc})") from None
    if abs(quat.norm() - 1.0) > 1e-3:
        raise ValueError(f"{where}: orientation is not a unit quaternion")
    quat.normalize()
    return pin.SE3(quat.matrix(), xyz)


def read_scene_file(path: Path, root_frames: Sequence[str]) -> SceneFile:
    """Read ``world.collision_objects`` (primitives only) and the allowed-collision matrix
    of a PlanningScene YAML file; frames must be the world or the robot's root link."""
    msg = yaml.safe_load(path.read_text())
    objects = []
    for k, obj in enumerate(msg.get("world", {}).get("collision_objects", []) or []):
        where = f"{path}: world.collision_objects[{k}]"
        frame = str(obj.get("header", {}).get("frame_id", "")).lstrip("/")
        if frame not in ("", "world", *root_frames):
            raise ValueError(f"{where}.header.frame_id: frame {frame!r} not supported here "
                             f"(the world or {', '.join(root_frames)})")
        if obj.get("meshes") or obj.get("planes"):
            raise ValueError(f"{where}: meshes and planes are not supported here")
        base = _pose(obj["pose"], f"{where}.pose") if "pose" in obj else pin.SE3.Identity()
        for m, (prim, pose) in enumerate(zip(obj.get("primitives", []), obj.get("primitive_poses", []))):
            kind = _KINDS.get(int(prim["type"]))
            if kind is None:
                raise ValueError(f"{where}.primitives[{m}].type: {prim['type']} is not a box, "
                                 f"sphere, cylinder or cone")
            dims = tuple(float(v) for v in prim["dimensions"])
            objects.append((str(obj["id"]) if m == 0 else f"{obj['id']}#{m}", kind, dims,
                            base * _pose(pose, f"{where}.primitive_poses[{m}]")))
    acm = msg.get("allowed_collision_matrix") or {}
    names = [str(n) for n in acm.get("entry_names", []) or []]
    allowed: set[frozenset[str]] = set()
    for a, row in zip(names, acm.get("entry_values", []) or []):
        for b, on in zip(names, row.get("enabled", [])):
            if on:
                allowed.add(frozenset((a, b)))
    allowed_all = {str(n) for n, on in zip(acm.get("default_entry_names", []) or [],
                                           acm.get("default_entry_values", []) or []) if on}
    return SceneFile(path, objects, allowed, allowed_all)


def _owner(name: str) -> str:
    """The scene object a primitive belongs to (``id#m`` for the m-th primitive)."""
    return name.split("#", 1)[0]


def _coal_shape(kind: str, dims: tuple[float, ...]) -> coal.CollisionGeometry:
    if kind == "box":
        return coal.Box(*dims)
    if kind == "sphere":
        return coal.Sphere(dims[0])
    if kind == "cylinder":  # MoveIt: [height, radius]
        return coal.Cylinder(dims[1], dims[0])
    return coal.Cone(dims[1], dims[0])


# ------------------------------------------------------------------- validator
_PRISMATIC = ("JointModelPX", "JointModelPY", "JointModelPZ", "JointModelPrismaticUnaligned")


def _prismatic(model: pin.Model, joint: int) -> bool:
    return str(model.joints[joint].shortname()) in _PRISMATIC


@dataclass
class Verdict:
    valid: bool
    reason: str = ""
    penetration: float = 0.0  # m, largest found
    states: int = 0  # states at which some pair was checked
    queries: int = 0  # pair distance / collision queries


class ExactValidator:
    """Checks joint paths against exact meshes at ≤ 0.5 mm of link motion between checks
    (see the module docstring)."""

    def __init__(self, urdf: Path, package_root: Path | Sequence[Path], srdf: Path,
                 resolution: float = RESOLUTION) -> None:
        self.resolution = resolution
        self.model = pin.buildModelFromUrdf(str(urdf))
        roots = [package_root] if isinstance(package_root, Path) else list(package_root)
        with warnings.catch_warnings():  # pinocchio's note on how package dirs are passed
            warnings.simplefilter("ignore", UserWarning)
            self.geom = pin.buildGeomFromUrdf(self.model, str(urdf), pin.COLLISION,
                                              [str(r) for r in roots])
        for g in self.geom.geometryObjects:
            if isinstance(g.geometry, coal.ConvexBase) or "Convex" in type(g.geometry).__name__:
                raise RuntimeError(f"{g.name}: loaded as a convex hull, not the mesh")
        self.links = [self.model.frames[g.parentFrame].name for g in self.geom.geometryObjects]
        self.root_links = [self.model.frames[1].name] if len(self.model.frames) > 1 else []
        self.disabled = self._disabled_pairs(urdf, srdf)
        self.lever = self._lever_arms()
        n = len(self.links)
        self.self_pairs = [(a, b) for a in range(n) for b in range(a + 1, n)
                           if self.links[a] != self.links[b]
                           and frozenset((self.links[a], self.links[b])) not in self.disabled]

    def _disabled_pairs(self, urdf: Path, srdf: Path) -> set[frozenset[str]]:
        pairs = set()
        for joint in ET.parse(urdf).getroot().iter("joint"):
            parent, child = joint.find("parent"), joint.find("child")
            if parent is not None and child is not None:
                pairs.add(frozenset((parent.get("link"), child.get("link"))))
        for dc in ET.parse(srdf).getroot().iter("disable_collisions"):
            pairs.add(frozenset((dc.get("link1"), dc.get("link2"))))
        return pairs

    def _lever_arms(self) -> np.ndarray:
        """``r[g, j]``: a bound on the distance from joint j's axis to any point of
        geometry g, over every configuration (0 where g is not downstream of j); for a
        prismatic joint, 1 (every point moves as far as the joint), its travel added to
        the reach of the joints above it."""
        model = self.model
        r = np.zeros((len(self.geom.geometryObjects), model.njoints))
        for gi, g in enumerate(self.geom.geometryObjects):
            vertices = self._vertices(g.geometry)
            local = (g.placement.rotation @ vertices.T).T + g.placement.translation
            reach = float(np.max(np.linalg.norm(local, axis=1)))  # from its joint's origin
            joint = g.parentJoint
            while joint > 0:
                if _prismatic(model, joint):
                    r[gi, joint] = 1.0
                    i = model.joints[joint].idx_q
                    reach += max(abs(model.lowerPositionLimit[i]), abs(model.upperPositionLimit[i]))
                else:
                    r[gi, joint] = reach
                reach += float(np.linalg.norm(model.jointPlacements[joint].translation))
                joint = model.parents[joint]
        return r

    @staticmethod
    def _vertices(geometry: coal.CollisionGeometry) -> np.ndarray:
        if hasattr(geometry, "vertices") and geometry.num_vertices > 0:
            return np.asarray(geometry.vertices())
        geometry.computeLocalAABB()
        lo, hi = geometry.aabb_local.min_, geometry.aabb_local.max_
        return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                         for z in (lo[2], hi[2])])

    def full_state(self, values: dict[str, float]) -> np.ndarray:
        q = pin.neutral(self.model)
        for j in range(1, self.model.njoints):
            name = self.model.names[j]
            if name not in values:
                raise ValueError(f"no value for joint {name!r}")
            q[self.model.joints[j].idx_q] = values[name]
        return q

    def check(self, scene: SceneFile, start: dict[str, float], names: Sequence[str],
              waypoints: np.ndarray, goal: dict[str, float], goal_tolerance: float) -> Verdict:
        """Check a path over joints ``names`` (rows ``waypoints``); other joints stay at
        ``start``."""
        model = self.model
        waypoints = np.asarray(waypoints, dtype=float)
        cols = []
        for name in names:
            if not model.existJointName(name):
                return Verdict(False, f"unknown joint {name!r}")
            j = model.getJointId(name)
            if model.joints[j].nq != 1 or model.joints[j].shortname() not in (
                    "JointModelRZ", "JointModelRX", "JointModelRY", "JointModelRevoluteUnaligned",
                    *_PRISMATIC):
                return Verdict(False, f"joint {name!r} is not a revolute or prismatic joint")
            cols.append(j)
        idx_q = np.array([model.joints[j].idx_q for j in cols])
        q0 = self.full_state(start)
        if len(waypoints) == 0:
            return Verdict(False, "empty path")
        for k, name in enumerate(names):
            if abs(waypoints[0, k] - start[name]) > 1e-6:
                return Verdict(False, f"starts at {name}={waypoints[0, k]:.6f}, not the start "
                                      f"{start[name]:.6f}")
            if abs(waypoints[-1, k] - goal[name]) > goal_tolerance + 1e-9:
                return Verdict(False, f"ends at {name}={waypoints[-1, k]:.6f}, not the goal "
                                      f"{goal[name]:.6f}")
        lower, upper = model.lowerPositionLimit[idx_q], model.upperPositionLimit[idx_q]
        if np.any(waypoints < lower - 1e-9) or np.any(waypoints > upper + 1e-9):
            return Verdict(False, "a waypoint leaves the joint limits")
        # The grid: on each segment, steps on which no geometry moves more than resolution.
        lever = self.lever[:, cols]  # geometry x path joint
        states, moved = [waypoints[:1]], [np.zeros((1, lever.shape[0]))]
        for a, b in zip(waypoints[:-1], waypoints[1:]):
            step = lever @ np.abs(b - a)  # bound on each geometry's motion over the segment
            n = max(1, math.ceil(float(np.max(step)) / self.resolution))
            t = np.arange(1, n + 1)[:, None] / n
            states.append(a + t * (b - a))
            moved.append(np.repeat(step[None, :] / n, n, axis=0))
        grid = np.concatenate(states)
        travel = np.cumsum(np.concatenate(moved), axis=0)  # state x geometry
        return self._sweep(scene, q0, idx_q, grid, travel)

    def _sweep(self, scene: SceneFile, q0: np.ndarray, idx_q: np.ndarray, grid: np.ndarray,
               travel: np.ndarray) -> Verdict:
        model, geom = self.model, self.geom
        data = model.createData()
        robot = [(g.geometry, gi) for gi, g in enumerate(geom.geometryObjects)]
        world = [(_coal_shape(kind, dims), coal.Transform3s(pose.rotation, pose.translation), name)
                 for name, kind, dims, pose in scene.objects]
        pairs: list[tuple[int, int, np.ndarray]] = []  # (robot geom, other, key); other<0: world
        for gi in range(len(robot)):
            for wi, (_, _, name) in enumerate(world):
                if not scene.allows(self.links[gi], _owner(name)):
                    pairs.append((gi, -1 - wi, travel[:, gi]))
        for a, b in self.self_pairs:
            if not scene.allows(self.links[a], self.links[b]):
                pairs.append((a, b, travel[:, a] + travel[:, b]))
        due = np.zeros(len(pairs), dtype=np.int64)
        last = len(grid) - 1
        dreq, creq = coal.DistanceRequest(), coal.CollisionRequest()
        creq.enable_contact, creq.num_max_contacts = True, 1000
        verdict = Verdict(True)
        placements: list[coal.Transform3s] = []
        while True:
            i = int(due.min())
            if i > last:
                break
            q = q0.copy()
            q[idx_q] = grid[i]
            pin.forwardKinematics(model, data, q)
            placements = []
            for g in geom.geometryObjects:
                m = data.oMi[g.parentJoint] * g.placement
                placements.append(coal.Transform3s(m.rotation, m.translation))
            verdict.states += 1
            for p in np.flatnonzero(due == i):
                a, b, key = pairs[p]
                if b < 0:
                    shape_b, tf_b, _ = world[-1 - b]
                else:
                    shape_b, tf_b = robot[b][0], placements[b]
                dres = coal.DistanceResult()
                distance = coal.distance(robot[a][0], placements[a], shape_b, tf_b, dreq, dres)
                verdict.queries += 1
                if distance > 1e-5:
                    nxt = int(np.searchsorted(key, key[i] + distance, side="left"))
                    due[p] = max(i + 1, nxt)
                    continue
                cres = coal.CollisionResult()
                if coal.collide(robot[a][0], placements[a], shape_b, tf_b, creq, cres):
                    depth = max((c.penetration_depth for c in cres.getContacts()), default=0.0)
                    depth = max(depth, -distance, 0.0)
                    if verdict.valid or depth > verdict.penetration:
                        other = world[-1 - b][2] if b < 0 else geom.geometryObjects[b].name
                        where = f"{geom.geometryObjects[a].name} / {other} at state {i}/{last}"
                        if verdict.valid:
                            verdict.reason = where
                        verdict.penetration = max(verdict.penetration, depth)
                    verdict.valid = False
                due[p] = i + 1
        return verdict


# ------------------------------------------------------------------- roboplan
class Roboplan:
    """roboplan's RRT-Connect on a problem (see the module docstring)."""

    def __init__(self, urdf: Path, package_root: Path | Sequence[Path], srdf: Path, cap: float,
                 max_nodes: int = ROBOPLAN_MAX_NODES, shortcut: bool = False,
                 group: str = GROUP) -> None:
        if rp_core is None:
            raise RuntimeError("roboplan is not installed (pip install 'taskrunner[bench]')")
        self.urdf, self.group = urdf, group
        self.package_roots = ([package_root] if isinstance(package_root, Path)
                              else list(package_root))
        self.srdf_xml = srdf.read_text()
        self.links = sorted({str(link.get("name")) for link in ET.parse(urdf).getroot().iter("link")})
        self.cap, self.max_nodes, self.shortcut = cap, max_nodes, shortcut
        self.version = rp_core.__version__

    def scene(self, problem: SceneFile, start: dict[str, float]) -> Any:
        description = rp_core.loadUrdfSceneDescription(str(self.urdf),
                                                       [str(r) for r in self.package_roots])
        scene = rp_core.Scene(f"problem_{problem.path.stem}", description)
        scene.importSrdf(self.srdf_xml)
        scene.allowAdjacentLinkCollisions()
        colour = np.array([0.5, 0.5, 0.5, 1.0])
        names = []
        for name, kind, dims, pose in problem.objects:
            tform = pose.homogeneous
            if kind == "box":
                scene.addBoxGeometry(name, "universe", rp_core.Box(*dims), tform, colour)
            elif kind == "sphere":
                scene.addSphereGeometry(name, "universe", rp_core.Sphere(dims[0]), tform, colour)
            elif kind == "cylinder":
                scene.addCylinderGeometry(name, "universe", rp_core.Cylinder(dims[1], dims[0]),
                                          tform, colour)
            else:
                raise ValueError(f"{problem.path}: roboplan has no {kind} primitive")
            names.append(name)
        off = [(a, b) for k, a in enumerate(names) for b in names[k + 1:]]
        off += [(link, name) for name in names for link in self.links
                if problem.allows(link, _owner(name))]
        if off:
            scene.setCollisions(off, False)
        scene.setJointPositions(np.array([start[n] for n in scene.getJointNames()]))
        return scene

    def plan(self, scene: Any, start: dict[str, float], goal: dict[str, float], seed: int
             ) -> tuple[bool, float, list[str], np.ndarray | None, str]:
        options = rp_rrt.RRTOptions()
        options.group_name = self.group
        options.rrt_connect = True
        options.max_planning_time = self.cap
        options.max_nodes = self.max_nodes
        planner = rp_rrt.RRT(scene, options)
        planner.setRngSeed(seed)
        names = list(scene.getJointGroupInfo(self.group).joint_names)
        q_start = rp_core.JointConfiguration(names, np.array([start[n] for n in names]))
        q_goal = rp_core.JointConfiguration(names, np.array([goal[n] for n in names]))
        shortcutter = None
        if self.shortcut:
            shortcutter = rp_core.PathShortcutter(scene,
                                                  rp_core.PathShortcuttingOptions(self.group))
        t0 = time.perf_counter()
        try:
            path = planner.plan(q_start, q_goal)
            if path is not None and shortcutter is not None:
                path = shortcutter.shortcut(path)
        except Exception as exc:  # roboplan raises RuntimeError on timeouts
            return False, time.perf_counter() - t0, names, None, f"{type(exc).__name__}: {exc}"
        wall = time.perf_counter() - t0
        if path is None or len(path.positions) == 0:
            return False, wall, names, None, "no path"
        return True, wall, list(path.joint_names), np.array(path.positions), ""


# ------------------------------------------------------------------- ours
def plan_ours(model: RobotModel, base: Scene, folder: Path, stem: str, seed: int,
              warm_scene: bool = True
              ) -> tuple[bool, float, list[str], np.ndarray | None, str]:
    scene = base.copy()
    load_planning_scene(folder / f"{stem}_scene.yaml", model).apply(scene)
    request_file = load_motion_plan_request(folder / f"{stem}_request.yaml", model)
    request_file.apply_start(scene)
    request = request_file.plan_request(scene, seed=seed, timing=False)
    planner = MotionPlanner(scene)
    if warm_scene:  # the scene's collision model, verifier and state screen (bounding
        scene.checker  # noqa: B018 - volumes per object), as roboplan's scene is built
        scene.state_screen()  # before its timed call (0.1-0.2 ms per scene here)
    t0 = time.perf_counter()
    try:
        result = planner.plan(request)
    except PlanningError as exc:
        return False, time.perf_counter() - t0, [], None, type(exc).__name__
    wall = time.perf_counter() - t0
    assert request.start is not None
    missed = request_file.goal_violations(scene, request.start, result.end)
    if missed:
        return False, wall, list(result.path.names), np.asarray(result.path.waypoints), missed[0]
    return True, wall, list(result.path.names), np.asarray(result.path.waypoints), ""


# ------------------------------------------------------------------- the run
def _request_states(path: Path) -> tuple[dict[str, float], dict[str, float], float]:
    msg = yaml.safe_load(path.read_text())
    joint_state = msg["start_state"]["joint_state"]
    start = {str(n): float(v) for n, v in zip(joint_state["name"], joint_state["position"])}
    checks = msg["goal_constraints"][0]["joint_constraints"]
    if not checks:
        raise ValueError(f"{path}: not a joint goal")
    goal = {str(c["joint_name"]): float(c["position"]) for c in checks}
    tolerance = min(min(float(c["tolerance_above"]), float(c["tolerance_below"])) for c in checks)
    return start, goal, tolerance


def _length(waypoints: np.ndarray | None) -> float | None:
    if waypoints is None or len(waypoints) < 2:
        return None
    return float(np.sum(np.linalg.norm(np.diff(waypoints, axis=0), axis=1)))


def _stats(runs: list[dict[str, Any]], cap: float) -> dict[str, Any]:
    solved = [r for r in runs if r["solved"]]
    times = np.array([r["ms"] if r["solved"] else cap * 1000.0 for r in runs])
    lengths = [r["length"] for r in solved if r["length"] is not None]
    invalid = [r for r in runs if r["valid"] is False]
    return {
        "problems": len(runs),
        "solved": len(solved),
        "solved_pct": round(100.0 * len(solved) / len(runs), 1) if runs else None,
        "median_ms": round(float(np.median(times)), 3) if runs else None,
        "p95_ms": round(float(np.percentile(times, 95)), 3) if runs else None,
        "median_solved_ms": round(float(np.median([r["ms"] for r in solved])), 3) if solved else None,
        "median_length_rad": round(float(np.median(lengths)), 3) if lengths else None,
        "median_waypoints": int(np.median([r["waypoints"] for r in solved])) if solved else None,
        "invalid_paths": len(invalid),
        "max_penetration_mm": round(1000 * max((r["penetration"] for r in invalid), default=0.0), 3),
        "invalid_examples": [f"{r['problem']}: {r['reason']}" for r in invalid[:3]],
        "failures": [f"{r['problem']}: {r['error']}" for r in runs if not r["solved"]][:5],
    }


def _load() -> str:
    try:
        return " ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:  # pragma: no cover
        return "n/a"


def run(per_class: int, classes: Sequence[str] = CLASSES, seed: int = 0, problem_seed: int = 0,
        problems: Path | None = None, cap: float = 5.0,
        roboplan: bool = True, roboplan_shortcut: bool = False,
        roboplan_max_nodes: int = ROBOPLAN_MAX_NODES, progress: bool = False,
        cold_scene: bool = False,
        problem_dir: Path | None = None, robot: str = "panda") -> dict[str, Any]:
    """Plan ``per_class`` problems of each class with both planners; see the docstring.
    ``roboplan=False`` runs our side only (no ratios). Without ``problems``, the problems
    are generated into ``problem_dir`` (default ``benchmarks/problems``)."""
    for name in classes:
        if name not in CLASSES:
            raise SystemExit(f"error: unknown class {name!r}; known: {', '.join(CLASSES)}")
    folder = problems
    if folder is None:
        folder = problem_dir or BENCH / ("problems" if robot == "panda" else f"problems_{robot}")
        make_problems.generate(folder, per_class, problem_seed, classes, robot_name=robot)
    urdf, package_roots, srdf, spec = robot_files(robot)
    model = load_robot(spec.robot_dir)
    base = Scene(model)
    validator = ExactValidator(urdf, package_roots, srdf)
    other = Roboplan(urdf, package_roots, srdf, cap, roboplan_max_nodes,
                     roboplan_shortcut, spec.group) if roboplan else None
    sides = ["ours", "roboplan"] if other is not None else ["ours"]
    started = time.time()
    load_before = _load()
    runs: dict[str, dict[str, list[dict[str, Any]]]] = {c: {s: [] for s in sides} for c in classes}
    validate_s = 0.0
    warmed = False
    for c in classes:
        for i in range(per_class):
            stem = f"{i + 1:04d}"
            where = folder / c
            if not (where / f"{stem}_request.yaml").exists():
                raise SystemExit(f"error: {where / stem}_request.yaml is missing "
                                 f"(make_problems.py --count {per_class})")
            scene_file = read_scene_file(where / f"{stem}_scene.yaml", validator.root_links)
            start, goal, tolerance = _request_states(where / f"{stem}_request.yaml")
            rp_scene = other.scene(scene_file, start) if other is not None else None
            problem_seed_i = seed * 100_003 + CLASSES.index(c) * 1000 + i

            def run_side(side: str) -> tuple[bool, float, list[str], np.ndarray | None, str]:
                if side == "ours":
                    return plan_ours(model, base, where, stem, problem_seed_i,
                                     warm_scene=not cold_scene)
                assert other is not None
                return other.plan(rp_scene, start, goal, problem_seed_i)

            if not warmed:  # first calls: imports, compiled code, caches (not recorded)
                for side in sides:
                    run_side(side)
                warmed = True
            order = sides if i % 2 == 0 else sides[::-1]
            for side in order:
                ok, wall, names, waypoints, error = run_side(side)
                row: dict[str, Any] = {"problem": f"{c}/{stem}", "ms": round(wall * 1000, 3),
                                       "solved": ok and wall <= cap, "error": error or (
                                           f"over the cap ({wall:.2f} s)" if wall > cap else ""),
                                       "length": _length(waypoints),
                                       "waypoints": 0 if waypoints is None else len(waypoints),
                                       "valid": None, "reason": "", "penetration": 0.0}
                if waypoints is not None:
                    t0 = time.perf_counter()
                    verdict = validator.check(scene_file, start, names, waypoints, goal, tolerance)
                    validate_s += time.perf_counter() - t0
                    row.update(valid=verdict.valid, reason=verdict.reason,
                               penetration=verdict.penetration)
                runs[c][side].append(row)
            if progress:
                print(f"\r{c} {i + 1}/{per_class}", end="", file=sys.stderr, flush=True)
        if progress:
            print(file=sys.stderr)
    result: dict[str, Any] = {
        "benchmark": "planning_compare", "robot": robot,
        "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(started)),
        "machine": f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, "
                   f"Python {platform.python_version()}",
        "load_before": load_before, "load_after": _load(),
        "per_class": per_class, "seed": seed, "problem_seed": problem_seed, "cap_s": cap,
        "roboplan": None if other is None else {
            "version": other.version, "planner": "RRT-Connect",
            "shortcut": roboplan_shortcut, "max_nodes": roboplan_max_nodes,
            "geometry": "URDF collision meshes (BVH)"},
        "ours": {"planner": "MotionPlanner (request's planner: RRTConnect)",
                 "geometry": "collision: auto (hull or mesh per link)",
                 "scene_setup_timed": cold_scene},
        "validator": {"resolution_mm": RESOLUTION * 1000, "geometry": "URDF collision meshes (BVH)",
                      "seconds": round(validate_s, 1)},
        "classes": {},
    }
    for c in classes:
        entry = {side: _stats(runs[c][side], cap) for side in sides}
        if other is not None:
            a, b = entry["ours"]["median_ms"], entry["roboplan"]["median_ms"]
            entry["ratio"] = round(a / b, 3) if a is not None and b else None
        entry["runs"] = runs[c]
        result["classes"][c] = entry
    result["seconds"] = round(time.time() - started, 1)
    return result


def table(result: dict[str, Any]) -> list[str]:
    both = result["roboplan"] is not None
    head = (f"{'class':<17} {'solved %':>13} {'median ms':>17} {'p95 ms':>17} {'ratio':>6} "
            f"{'invalid':>9} {'length rad':>11}" if both else
            f"{'class':<17} {'solved %':>8} {'median ms':>10} {'p95 ms':>9} {'invalid':>7} "
            f"{'length':>7}")
    lines = [head, "-" * len(head)]
    if both:
        lines.insert(0, f"{'':<17} {'ours / rp':>13} {'ours / rp':>17} {'ours / rp':>17} "
                        f"{'o/rp':>6} {'ours / rp':>9} {'ours / rp':>11}")

    def f(v: Any, digits: int = 1) -> str:
        return "-" if v is None else f"{v:.{digits}f}"

    for c, e in result["classes"].items():
        o = e["ours"]
        if both:
            r = e["roboplan"]
            lines.append(
                f"{c:<17} {f(o['solved_pct'], 0):>6}/{f(r['solved_pct'], 0):<6} "
                f"{f(o['median_ms'], 2):>8}/{f(r['median_ms'], 2):<8} "
                f"{f(o['p95_ms'], 1):>8}/{f(r['p95_ms'], 1):<8} {f(e['ratio'], 2):>6} "
                f"{o['invalid_paths']:>4}/{r['invalid_paths']:<4} "
                f"{f(o['median_length_rad'], 2):>5}/{f(r['median_length_rad'], 2):<5}")
        else:
            lines.append(f"{c:<17} {f(o['solved_pct'], 0):>8} {f(o['median_ms'], 2):>10} "
                         f"{f(o['p95_ms'], 1):>9} {o['invalid_paths']:>7} "
                         f"{f(o['median_length_rad'], 2):>7}")
    for side in ("ours", "roboplan"):
        worst = max((e[side]["max_penetration_mm"] for e in result["classes"].values()
                     if side in e), default=None)
        if worst is not None:
            lines.append(f"{side}: largest penetration of an invalid path {worst:.3f} mm")
    return lines


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", default="panda",
                        help=f"robot of make_problems.py ({', '.join(make_problems.ROBOTS)}; panda)")
    parser.add_argument("--per-class", type=int, default=100, help="problems per class (100)")
    parser.add_argument("--classes", default=",".join(CLASSES),
                        help=f"comma-separated classes ({','.join(CLASSES)})")
    parser.add_argument("--seed", type=int, default=0, help="planners' seed (0)")
    parser.add_argument("--problem-seed", type=int, default=0,
                        help="make_problems.py seed of the problems (0)")
    parser.add_argument("--problems", type=Path,
                        help="read the problems from this folder as they are (default: "
                             "regenerate them into benchmarks/problems)")
    parser.add_argument("--cap", type=float, default=5.0, help="time cap per plan call, s (5)")
    parser.add_argument("--roboplan-shortcut", action="store_true",
                        help="roboplan: shortcut its path (PathShortcutter, default options) "
                             "inside the timed call")
    parser.add_argument("--roboplan-max-nodes", type=int, default=ROBOPLAN_MAX_NODES,
                        help=f"roboplan's RRTOptions.max_nodes ({ROBOPLAN_MAX_NODES})")
    parser.add_argument("--ours-only", action="store_true", help="run our planner only")
    parser.add_argument("--cold-scene", action="store_true",
                        help="ours: build the scene's collision model and path verifier inside "
                             "the timed call (default: before it, as roboplan's scene is)")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--runs", action="store_true", help="with --json: every problem's row")
    args = parser.parse_args(argv)
    if not args.ours_only and rp_core is None:
        parser.error("roboplan is not installed (pip install 'taskrunner[bench]'), "
                     "or run --ours-only")
    result = run(args.per_class, [c for c in args.classes.split(",") if c], args.seed,
                 args.problem_seed, args.problems, args.cap,
                 not args.ours_only, args.roboplan_shortcut, args.roboplan_max_nodes,
                 progress=sys.stderr.isatty(), cold_scene=args.cold_scene, robot=args.robot)
    print(f"{result['robot']}; {result['date']}; {result['machine']}; load {result['load_before']} -> "
          f"{result['load_after']}; {result['per_class']} problems per class, seed "
          f"{result['seed']}, cap {result['cap_s']} s; {result['seconds']} s")
    if result["roboplan"] is not None:
        rp = result["roboplan"]
        print(f"roboplan {rp['version']} RRT-Connect (shortcut: {rp['shortcut']}, max_nodes "
              f"{rp['max_nodes']}) on {rp['geometry']}; ours on {result['ours']['geometry']}; "
              f"validator: {result['validator']['geometry']} at "
              f"{result['validator']['resolution_mm']} mm")
    print("\n".join(table(result)))
    for e in result["classes"].values():
        for side in ("ours", "roboplan"):
            if side in e:
                for line in e[side]["invalid_examples"] + e[side]["failures"]:
                    print(f"  {side} {line}")
    if args.json:
        if not args.runs:
            for e in result["classes"].values():
                e.pop("runs")
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
