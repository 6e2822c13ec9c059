"""``run-task info``, ``plan``, ``demo`` and ``collision-matrix``: what a cell or robot
holds, a MoveIt request planned, the planning pipeline shown step by step."""

from __future__ import annotations

import argparse
import logging
import sys
import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, cast

from taskrunner.errors import InputError, PlanningError
from taskrunner.kinds import ExitCode

if TYPE_CHECKING:
    import numpy as np

    from taskrunner.kinematics import IkSolver
    from taskrunner.robot.cell import Cell
    from taskrunner.robot.options import LoadOptions
    from taskrunner.scene import Scene

__all__ = ["load_named_cell", "cmd_info", "cmd_plan", "cmd_demo", "cmd_collision_matrix"]


def load_named_cell(name_or_path: str, options: LoadOptions | None = None) -> Cell:
    """A cell (or a lone robot as a cell) by path or by a shipped cell's name, loaded with
    ``options`` (the command's ``--strict``, ``--package-path`` …)."""
    from taskrunner.resources import resolve_cell
    from taskrunner.robot.cell import load_cell_or_robot

    return load_cell_or_robot(resolve_cell(name_or_path), options=options)


def _fmt(values: np.ndarray) -> str:
    return "[" + ", ".join(f"{v:+.3f}" for v in values) + "]"


def cmd_info(args: argparse.Namespace) -> int:
    # The loader logs each warning; info lists them in its report instead, so that each
    # is shown once.
    robot_log = logging.getLogger("taskrunner.robot")
    quiet, propagate = logging.NullHandler(), robot_log.propagate
    robot_log.addHandler(quiet)
    robot_log.propagate = False
    try:
        cell = load_named_cell(args.path, args.load_options)
    finally:
        robot_log.removeHandler(quiet)
        robot_log.propagate = propagate
    model = cell.model
    out = [f"cell {cell.name}: {len(model.instances)} robot(s), {model.nq} joints"]
    for inst in model.instances:
        xyz = _fmt(inst.base.translation)
        out.append(f"  robot {inst.name!r} prefix {inst.prefix!r} at {xyz}  ({inst.source})")
        out += [f"    {line}" for line in inst.describe_files()]
    out.append("groups:")
    for group in model.groups.values():
        aliases = model.pose_aliases.get(group.name, {})
        poses = ", ".join(f"{n} (= {aliases[n]})" if n in aliases else n
                          for n in model.named_state_names(group.name)) or "-"
        ik = " position-only IK" if group.position_only_ik else ""
        planner = f", planner {group.default_planner}" if group.default_planner else ""
        out.append(f"  {group.name}: {len(group.joint_names)} joints, tip {group.tip_link}"
                   f"{ik}{planner}; poses: {poses}")
    if model.end_effectors:
        out.append("end effectors:")
        for eef in model.end_effectors.values():
            out.append(f"  {eef.name}: group {eef.group} on {eef.parent_link}"
                       f" (arm {eef.parent_group or '-'})")
    if cell.tools:
        out.append("tools (TCP: the tool frame's origin; y closes, z approaches):")
        out += [f"  {tool.describe()}" for tool in cell.tools.values()]
    bare = model.links_without_collision_geometry()
    if bare:
        out.append(f"links without collision geometry: {', '.join(bare)}")
    from taskrunner.scene.linkgeometry import describe_link_geometry

    out += describe_link_geometry(model)
    if cell.objects:
        out.append("objects:")
        for obj in cell.objects:
            out.append(f"  {obj.name}: {obj.shape} at {_fmt(obj.pose.translation)} in {obj.frame}")
    for warning in model.warnings:
        out.append(f"warning: {warning}")
    print("\n".join(out))
    return ExitCode.OK


def cmd_plan(args: argparse.Namespace) -> int:
    import json

    from taskrunner.moveit import plan_files

    options = args.load_options
    report, warnings = plan_files(load_named_cell(args.robot, options), args.request, args.scene,
                                  robot=args.instance, group=args.group, seed=args.seed,
                                  merge=True if args.merge else None, strict=options.strict,
                                  package_path=options.package_path)
    if args.json:
        print(json.dumps({**report.to_json(), "warnings": [str(w) for w in warnings]}, indent=2))
    else:
        for warning in warnings:
            print(f"warning: {warning}", file=sys.stderr)
        if report.success:
            print(f"plan {report.group} ({report.planner}): success\n"
                  f"  planning time {report.planning_time:.3f} s (total {report.total_time:.3f} s)"
                  f", {report.waypoints} waypoints, length {report.path_length:.3f} rad, "
                  f"duration {report.duration:.3f} s")
        else:
            print(f"plan {report.group} ({report.planner}): failed ({report.error_kind}): "
                  f"{report.message}")
    return ExitCode.OK if report.success else ExitCode.PLANNING


def _demo_below_surface(scene: Scene, solver: IkSolver, target: np.ndarray,
                        seed_q: np.ndarray) -> None:
    """The demo's collision example: IK to 2 cm below the surface under ``target`` (found
    by lowering a probe onto it), and what that pose hits."""
    from taskrunner.errors import IkFailedError
    from taskrunner.kinematics import IkOptions
    from taskrunner.shapes import Sphere
    from taskrunner.types import Pose

    probe = "__demo_probe__"
    scene.add_object(probe, Sphere(0.001), Pose(xyz=(float(target[0]), float(target[1]), float(target[2]))))
    try:
        support = scene.support(probe)
    finally:
        scene.remove_object(probe)
    if support.below is None:
        print("nothing below the target within 1 m: no surface to reach into")
        return
    surface = float(target[2]) - support.gap - 0.001
    import numpy as np

    below = np.array([target[0], target[1], surface - 0.02])
    try:
        sunk = solver.solve(below, seed_q=seed_q, options=IkOptions(position_only=True))
    except IkFailedError:
        print(f"2 cm below the top of {support.below!r}: out of reach")
        return
    hits = scene.collisions(sunk.q)
    pairs = ", ".join(f"{c.a}–{c.b} ({1e3 * c.depth:.1f} mm deep)" for c in hits[:3])
    print(f"IK 2 cm below the top of {support.below!r}: reachable, "
          + (f"but in collision: {pairs}" if hits else "and (unexpectedly) collision-free"))


def cmd_demo(args: argparse.Namespace) -> int:
    from taskrunner.kinematics import IkOptions, IkSolver, frame_pose
    from taskrunner.planning import JointGoal, MotionPlanner, PlannerOptions, PlanRequest
    from taskrunner.scene import scene_from_cell

    t0 = time.perf_counter()
    cell = load_named_cell(args.cell, args.load_options)
    model = cell.model
    scene = scene_from_cell(cell)
    print(f"loaded cell {cell.name!r} ({model.nq} joints, {len(cell.objects)} objects) "
          f"in {1e3 * (time.perf_counter() - t0):.0f} ms")
    arm = next((g for g in model.groups.values() if g.tip_link and g.end_effector), None)
    if arm is None:
        raise InputError(f"cell {cell.name!r} has no arm group with an end effector")
    tip = arm.tip_link
    assert tip is not None
    start = scene.state
    here = frame_pose(model, start, tip)
    print(f"group {arm.name!r} at start {_fmt(start[arm.joint_indices])}: "
          f"{tip} at {_fmt(here.translation)} m")
    clearance = scene.min_distance()
    pair = cast(tuple[str, str], clearance.pair)  # an arm's links give body pairs to check
    print(f"start state collision-free; closest pair {pair[0]}–{pair[1]} "
          f"at {1e3 * clearance.distance:.1f} mm")

    # A point in front of the arm's base, a hand's height above the table.
    base = model.instances[0].base
    import numpy as np

    target = base.act(np.array(args.target, dtype=float))
    # Aim the grasp point between the fingers: the arm's tool frame.
    frame = cell.tools[arm.name].frame if arm.name in cell.tools else tip
    solver = IkSolver(model, arm.name, frame=frame)
    t0 = time.perf_counter()
    solutions = solver.solve_all(target, seed_q=start, options=IkOptions(
        position_only=True, seed=args.seed, num_solutions=8, timeout=0.05))
    ik_ms = 1e3 * (time.perf_counter() - t0)
    free = [s for s in solutions if not scene.in_collision(s.q)]
    print(f"IK (position only) of {frame} to {_fmt(target)} m: {len(solutions)} distinct "
          f"solutions in {ik_ms:.2f} ms, {len(free)} collision-free")
    if not free:
        pairs = ", ".join(f"{c.a}–{c.b}" for c in scene.collisions(solutions[0].q))
        raise PlanningError(f"every IK solution collides (first: {pairs})")
    solution = free[0]
    print(f"  chose {_fmt(solution.joint_state.positions)} rad, error "
          f"{1e3 * solution.position_error:.4f} mm")

    _demo_below_surface(scene, solver, target, solution.q)

    planner = MotionPlanner(scene)
    request = PlanRequest(arm.name, JointGoal(solution.joint_state.as_dict()),
                          options=PlannerOptions(seed=args.seed))
    result = planner.plan(request)
    print(f"planned {arm.name!r} start → IK solution: {len(result.path)} waypoints, "
          f"{1e3 * result.planning_time:.1f} ms search + {1e3 * result.simplify_time:.1f} ms "
          f"shortcut, {result.checks} collision checks, re-checked every "
          f"{request.options.validation_resolution} rad")
    return ExitCode.OK


def cmd_collision_matrix(args: argparse.Namespace, rest: Sequence[str]) -> int:
    from taskrunner.scene import acm

    return acm.main(list(rest))
