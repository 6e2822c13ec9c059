"""Exact path verification benchmark: cost per path, and an independent fine re-check.

    python benchmarks/verify_bench.py [--quick] [--json] [--seed N] [--baseline REV]
                                      [--problems P,Q] [--repeats N]
    python benchmarks/verify_bench.py --moveit benchmarks/problems [--classes C,D]
                                      [--per-class N] [--baseline REV] [--fine] [--json]
    python benchmarks/verify_bench.py --planner-paths benchmarks/problems [--classes C,D]
                                      [--per-class N] [--baseline REV] [--repeats N] [--json]

Collects the paths the planner returns (RRTConnect, seeded) on the thin-plate scenes of
``tests/planning/test_path_guarantee.py`` (a 1-3 mm plate across the straight line from the
Panda's ready pose to a random goal) and on the problems of ``benchmarks/planning_scenes.py``
(``panda_table_pick``, ``panda_shelf``, ``panda_box``, ``panda_cage`` by default), plus the
toppra trajectory sampled from each path (what ``timing`` verifies), plus straight lines
through the plates (which must be rejected). Then it times
:meth:`taskrunner.scene.path_verifier.PathVerifier.verify` on every one, interleaved with the
verifier of git revision ``--baseline`` if one is given (loaded from ``git show
REV:taskrunner/scene/sweep.py``, so a revision from before the verifier was split into
``scene/path_verifier.py`` and its kernels' modules; one without that file is refused, never
skipped; the default ``none`` compares with nothing), alternating which runs first, ``--repeats`` times each
(the fastest run counts). Margin 0.5 mm, as the planner's default.

Every path the current verifier accepts is re-checked independently: the scene's boolean
collision check at states so dense that no point of the Panda moves more than 0.1 mm between
two (1.25 m, the Panda's reach, times the sum of the joint steps; not the verifier's lever
arms). ``fine_invalid`` counts accepted paths that collide there (must be 0); ``rejected_free``
counts rejected paths the fine check finds free (a rejection within the margin is allowed,
listed for information). Verdicts of the two verifiers are compared too.

``--planning`` times whole :meth:`MotionPlanner.plan` calls instead (RRTConnect, the
problems' queries, seeded, one attempt each): every query is planned with the current
verifier and with the baseline's (set as the scene's verifier), alternating which goes first;
per problem the median wall time of ``plan`` and the median verification time
(``PlanResult.verify_time``) of each. The search is the same for both (same seed), so
the difference is the verification's.

``--moveit DIR`` takes the MoveIt problem sets of ``benchmarks/make_problems.py`` instead
(``DIR/<class>/NNNN_{scene,request}.yaml``, the first ``--per-class`` problems of each of
``--classes``): each is planned once (seeded, RRTConnect, timing off) and its returned path
verified by both verifiers, interleaved as above (fastest of ``--repeats``), with the cheap
bounds and compiled states each took, and whether their verdicts differ. It also times the
verifier's build after a scene edit, both ways interleaved: the problem's first object moved
by 1 cm (a new scene revision, so a new collision checker), then ``PathVerifier(robot,
checker)`` built (the checker's own build not timed); the current code keeps the robot's
rows between builds, as it does between a scene's revisions. ``--fine`` re-checks accepted
paths at 0.1 mm as above (slow).

``--planner-paths DIR`` takes the same problem sets and records every path the planner
verifies while planning each problem (``MotionPlanner(scene).plan(request)``, seed = problem
index, timing off: the returned path and the shortcut candidates it checked, rejected ones
included), then verifies each recorded path with the current verifier and the baseline's,
interleaved (alternating which goes first), ``--repeats`` times each, and reports per class
the median CPU time (``time.process_time``; the median of the repeats per path, then the
median over paths), the compiled walk's calls (:func:`taskrunner.scene.advancement._walk`: one
more than the rounds of exact distances) and coal's distance queries per path, the
rejections of each and the verdicts that differ, with the load average along the run.

Output: a table per class (paths, median and p90 ms per path, median distance queries, old
and new), and with ``--json`` one JSON line at the end.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin

BENCH = Path(__file__).resolve().parent
ROOT = BENCH.parent
sys.path.insert(0, str(BENCH))
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import planning_scenes

from taskrunner.errors import PlanningError
from taskrunner.planning import JointGoal, MotionPlanner, PlannerOptions, PlanRequest
from taskrunner.planning.timing import parameterize_path
from taskrunner.scene import Scene
from taskrunner.scene.path_verifier import PathVerifier
from taskrunner.shapes import Box
from taskrunner.types import Pose

PANDA_REACH = 1.25  # m: joint 1's axis to the fingertips, stretched out, rounded up
FINE = 1e-4  # m: displacement between two states of the independent check
MARGIN = 5e-4  # m: the planner's default verify_margin
READY = {"panda_joint1": 0.0, "panda_joint2": -0.785, "panda_joint3": 0.0,
         "panda_joint4": -2.356, "panda_joint5": 0.0, "panda_joint6": 1.571,
         "panda_joint7": 0.785}
DEFAULT_PROBLEMS = ("panda_table_pick", "panda_shelf", "panda_box", "panda_cage")


def load_baseline(rev: str) -> Any:
    """The ``sweep`` module of git revision ``rev`` (the path verifier was that one module
    until it was split into ``scene/path_verifier.py`` and its kernels' modules).

    Raises:
        SystemExit: ``rev`` has no ``taskrunner/scene/sweep.py`` (or git cannot read it):
            a comparison asked for is never skipped silently.
    """
    try:
        text = subprocess.run(["git", "-C", str(ROOT), "show", f"{rev}:taskrunner/scene/sweep.py"],
                              check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as exc:
        detail = getattr(exc, "stderr", "") or str(exc)
        raise SystemExit(f"--baseline {rev}: cannot read taskrunner/scene/sweep.py there "
                         f"({detail.strip()}); the baseline must be a revision whose path "
                         f"verifier was that one module, or 'none'") from None
    folder = Path(tempfile.mkdtemp(prefix="verify_bench_"))
    path = folder / "sweep_baseline.py"
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location("sweep_baseline", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["sweep_baseline"] = module
    spec.loader.exec_module(module)
    return module


def plate_scene(robot, rng: np.random.Generator, thickness: float
                ) -> tuple[Scene, np.ndarray] | None:
    """The Panda at 'ready', a goal state and a plate across the straight line between
    (the construction of ``tests/planning/test_path_guarantee.py``)."""
    scene = Scene(robot)
    scene.set_state(READY)
    start = scene.state.copy()
    goal = robot.random_state(rng, "arm", base=start)
    if scene.in_collision(goal):
        return None
    t = rng.uniform(0.3, 0.7)
    data = robot.model.createData()
    pin.framesForwardKinematics(robot.model, data, robot.to_pin(start + t * (goal - start)))
    hand = data.oMf[robot.frame_id("panda_hand")]
    rotation = pin.rpy.rpyToMatrix(*rng.uniform(-np.pi, np.pi, 3))
    offset = np.array([*rng.uniform(-0.2, 0.2, 2), 0.0])
    centre = hand.translation + hand.rotation @ np.array([0.0, 0.0, 0.1]) + rotation @ offset
    scene.add_object("plate", Box((0.3, 0.3, thickness)),
                     Pose.from_se3(pin.SE3(rotation, centre)))
    if scene.in_collision(start) or scene.in_collision(goal):
        return None
    return scene, goal


def full_states(scene: Scene, start: np.ndarray, names, rows: np.ndarray) -> np.ndarray:
    robot = scene.robot
    states = np.repeat(start[None, :], len(rows), axis=0)
    states[:, robot.indices(names)] = rows
    for q in states:
        robot.apply_mimic(q)
    return states


def fine_collision(scene: Scene, states: np.ndarray) -> bool:
    """True if the polyline collides at a state of the 0.1 mm check."""
    robot = scene.robot
    for a, b in zip(states[:-1], states[1:]):
        steps = max(1, int(np.ceil(np.sum(np.abs(b - a)) * PANDA_REACH / FINE)))
        for t in np.linspace(0.0, 1.0, steps + 1):
            if scene.in_collision(robot.apply_mimic(a + t * (b - a))):
                return True
    return False


def collect(quick: bool, seed: int, problems: list[str]) -> list[dict]:
    """Cases: ``{"cls", "scene", "states"}``, one per path, trajectory or straight line."""
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot import load_robot

    cases: list[dict] = []
    robot = load_robot(DATA_ROOT / "robots" / "panda")

    def add(cls: str, scene: Scene, result) -> None:  # type: ignore[no-untyped-def]
        states = full_states(scene, result.start, result.path.names, result.path.waypoints)
        cases.append({"cls": cls, "scene": scene, "states": states})
        try:
            trajectory = parameterize_path(scene.robot, result.path)
        except PlanningError:
            return
        cases.append({"cls": cls + "/traj", "scene": scene,
                      "states": full_states(scene, result.start, trajectory.names,
                                            trajectory.positions)})

    rng = np.random.default_rng(seed)
    plates = 0
    while plates < (6 if quick else 16):
        found = plate_scene(robot, rng, float(rng.uniform(0.001, 0.003)))
        if found is None:
            continue
        plates += 1
        scene, goal = found
        cases.append({"cls": "plate_line", "scene": scene, "states": np.vstack([scene.state, goal])})
        arm = robot.group("arm")
        request = PlanRequest("arm", JointGoal(dict(zip(arm.joint_names, goal[arm.joint_indices]))),
                              options=PlannerOptions(seed=plates, planning_time=2.0))
        try:
            add("plate", scene, MotionPlanner(scene).plan(request))
        except PlanningError:
            pass
    for problem in planning_scenes.build_problems(3 if quick else 8, seed, problems):
        planner = MotionPlanner(problem.scene)
        for i, query in enumerate(problem.queries):
            options = PlannerOptions(planning_time=problem.planning_time, seed=seed + i)
            try:
                result = planner.plan(PlanRequest(problem.group, query.goal, start=query.start,
                                                  options=options))
            except PlanningError:
                continue
            add(problem.name.removeprefix("panda_"), problem.scene, result)
    return cases


def run(args: argparse.Namespace) -> dict:
    problems = args.problems.split(",") if args.problems else list(DEFAULT_PROBLEMS)
    baseline = None if args.baseline == "none" else load_baseline(args.baseline)
    cases = collect(args.quick, args.seed, problems)
    rows: list[dict] = []
    for n, case in enumerate(cases):
        scene, states = case["scene"], case["states"]
        new = PathVerifier(scene.robot, scene.checker, MARGIN)
        verifiers = [("new", new)]
        if baseline is not None:
            verifiers.append(("old", baseline.PathVerifier(scene.robot, scene.checker, MARGIN)))
        if n % 2:
            verifiers.reverse()
        best: dict[str, Any] = {}
        for _ in range(args.repeats):
            for name, verifier in verifiers:
                t0 = time.perf_counter()
                result = verifier.verify(states)
                seconds = time.perf_counter() - t0
                if name not in best or seconds < best[name][0]:
                    best[name] = (seconds, result)
        row = {"cls": case["cls"], "waypoints": len(states)}
        for name, (seconds, result) in best.items():
            row[f"{name}_ms"] = seconds * 1000
            row[f"{name}_queries"] = result.distance_queries
            row[f"{name}_valid"] = bool(result.valid)
        fine_hit = fine_collision(scene, states)
        row["fine_collides"] = fine_hit
        rows.append(row)
    return summarize(rows, baseline is not None, args)


def summarize(rows: list[dict], with_old: bool, args: argparse.Namespace) -> dict:
    classes = sorted({r["cls"] for r in rows}, key=lambda c: (c.endswith("/traj"), c))
    table = []
    for cls in classes:
        rs = [r for r in rows if r["cls"] == cls]
        entry: dict[str, Any] = {"cls": cls, "paths": len(rs)}
        for name in ("new", "old") if with_old else ("new",):
            ms = [r[f"{name}_ms"] for r in rs]
            entry[f"{name}_median_ms"] = round(float(np.median(ms)), 3)
            entry[f"{name}_p90_ms"] = round(float(np.percentile(ms, 90)), 3)
            entry[f"{name}_median_queries"] = int(np.median([r[f"{name}_queries"] for r in rs]))
            entry[f"{name}_accepted"] = sum(r[f"{name}_valid"] for r in rs)
        entry["fine_invalid"] = sum(r["new_valid"] and r["fine_collides"] for r in rs)
        entry["rejected_free"] = sum((not r["new_valid"]) and not r["fine_collides"] for r in rs)
        if with_old:
            entry["verdicts_differ"] = sum(r["new_valid"] != r["old_valid"] for r in rs)
        table.append(entry)
    return {"machine": f"{platform.node()} {platform.processor() or platform.machine()}, "
                       f"{os.cpu_count()} cores",
            "load": os.getloadavg()[0], "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "quick": args.quick, "seed": args.seed, "baseline": args.baseline, "classes": table}


def print_table(report: dict) -> None:
    with_old = "old_median_ms" in report["classes"][0] if report["classes"] else False
    head = f"{'class':<18}{'paths':>6}{'new ms':>9}{'p90':>8}{'queries':>9}"
    if with_old:
        head += f"{'old ms':>9}{'p90':>8}{'queries':>9}{'differ':>8}"
    head += f"{'accepted':>10}{'fine bad':>10}{'rej. free':>10}"
    print(head)
    for e in report["classes"]:
        line = (f"{e['cls']:<18}{e['paths']:>6}{e['new_median_ms']:>9.2f}{e['new_p90_ms']:>8.2f}"
                f"{e['new_median_queries']:>9}")
        if with_old:
            line += (f"{e['old_median_ms']:>9.2f}{e['old_p90_ms']:>8.2f}"
                     f"{e['old_median_queries']:>9}{e['verdicts_differ']:>8}")
        line += f"{e['new_accepted']:>10}{e['fine_invalid']:>10}{e['rejected_free']:>10}"
        print(line)
    print(f"machine {report['machine']}, load {report['load']:.2f}, {report['date']}")


def run_planning(args: argparse.Namespace) -> dict:
    """Whole ``plan`` calls, current verifier against the baseline's, interleaved."""
    problems = args.problems.split(",") if args.problems else list(DEFAULT_PROBLEMS)
    if args.baseline == "none":
        raise SystemExit("--planning needs --baseline REV (a revision whose path "
                         "verifier was taskrunner/scene/sweep.py)")
    baseline = load_baseline(args.baseline)
    current = PathVerifier
    table = []
    for problem in planning_scenes.build_problems(5 if args.quick else 20, args.seed, problems):
        planner = MotionPlanner(problem.scene)
        scene = problem.scene
        # One verifier of each per scene, as the scene keeps one between edits.
        verifiers = {"new": current(scene.robot, scene.checker, MARGIN),
                     "old": baseline.PathVerifier(scene.robot, scene.checker, MARGIN)}
        for verifier in verifiers.values():  # load the compiled kernels before timing
            verifier.verify(np.vstack([problem.queries[0].start, problem.queries[0].goal_state]))
        runs: dict[str, list[tuple[float, float, bool]]] = {"new": [], "old": []}
        for i, query in enumerate(problem.queries):
            order = ["new", "old"]
            if i % 2:
                order.reverse()
            for name in order:
                scene._verifier = (scene.checker, verifiers[name])
                options = PlannerOptions(planning_time=problem.planning_time, seed=args.seed + i)
                request = PlanRequest(problem.group, query.goal, start=query.start,
                                      options=options)
                t0 = time.perf_counter()
                try:
                    result = planner.plan(request)
                    runs[name].append((time.perf_counter() - t0, result.verify_time, True))
                except PlanningError:
                    runs[name].append((time.perf_counter() - t0, 0.0, False))
        scene._verifier = None
        entry: dict[str, Any] = {"problem": problem.name, "queries": len(problem.queries)}
        for name, rs in runs.items():
            entry[f"{name}_solved"] = sum(ok for *_, ok in rs)
            entry[f"{name}_plan_median_ms"] = round(float(np.median([w for w, _, _ in rs])) * 1e3, 3)
            entry[f"{name}_verify_median_ms"] = round(
                float(np.median([v for _, v, ok in rs if ok] or [0.0])) * 1e3, 3)
        table.append(entry)
    return {"machine": f"{platform.node()} {platform.processor() or platform.machine()}, "
                       f"{os.cpu_count()} cores",
            "load": os.getloadavg()[0], "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "quick": args.quick, "seed": args.seed, "baseline": args.baseline, "planning": table}


def run_moveit(args: argparse.Namespace) -> dict:
    """MoveIt problem sets: verification per returned path and the build after an edit."""
    from taskrunner.moveit import load_motion_plan_request, load_planning_scene
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot import load_robot

    baseline = None if args.baseline == "none" else load_baseline(args.baseline)
    folder = Path(args.moveit)
    robot = load_robot(DATA_ROOT / "robots" / "panda")
    base = Scene(robot)
    names = ["new", "old"] if baseline is not None else ["new"]
    classes = args.classes.split(",")
    table = []
    for cls in classes:
        rows: list[dict[str, Any]] = []
        for i in range(args.per_class):
            stem = f"{i + 1:04d}"
            if not (folder / cls / f"{stem}_scene.yaml").exists():
                raise SystemExit(f"error: {folder / cls / stem}_scene.yaml is missing "
                                 f"(python benchmarks/make_problems.py --count {args.per_class})")
            scene = base.copy()
            load_planning_scene(folder / cls / f"{stem}_scene.yaml", robot).apply(scene)
            request_file = load_motion_plan_request(folder / cls / f"{stem}_request.yaml", robot)
            request_file.apply_start(scene)
            request = request_file.plan_request(scene, seed=args.seed + i, timing=False)
            try:
                result = MotionPlanner(scene).plan(request)
            except PlanningError:
                continue
            states = full_states(scene, result.start, result.path.names, result.path.waypoints)
            modules = {"new": PathVerifier}
            if baseline is not None:
                modules["old"] = baseline.PathVerifier
            verifiers = {n: modules[n](scene.robot, scene.checker, MARGIN) for n in names}
            order = names if i % 2 == 0 else names[::-1]
            row: dict[str, Any] = {"waypoints": len(states)}
            best: dict[str, tuple[float, Any]] = {}
            for name in order:
                verifiers[name].verify(states)              # compiled code loaded
            for _ in range(args.repeats):
                for name in order:
                    t0 = time.perf_counter()
                    verdict = verifiers[name].verify(states)
                    seconds = time.perf_counter() - t0
                    if name not in best or seconds < best[name][0]:
                        best[name] = (seconds, verdict)
            for name, (seconds, verdict) in best.items():
                row[f"{name}_ms"] = seconds * 1e3
                row[f"{name}_valid"] = bool(verdict.valid)
                row[f"{name}_queries"] = verdict.distance_queries
                row[f"{name}_bounds"] = verdict.bounds
                row[f"{name}_states"] = verdict.states
            # A scene edit: the first object moved by 1 cm; then the verifier built.
            edited = scene.copy()
            world = [obj for obj in edited.objects if obj.attached_to is None]
            if world:
                se3 = world[0].pose.se3
                edited.move_object(world[0].name,
                                   Pose.from_se3(pin.SE3(se3.rotation, se3.translation + 0.01)))
            checker = edited.checker
            builds: dict[str, float] = {}
            for _ in range(args.repeats):
                for name in order:
                    t0 = time.perf_counter()
                    modules[name](edited.robot, checker, MARGIN)
                    seconds = time.perf_counter() - t0
                    builds[name] = min(builds.get(name, np.inf), seconds)
            for name, seconds in builds.items():
                row[f"{name}_build_ms"] = seconds * 1e3
            if args.fine and row["new_valid"]:
                row["fine_collides"] = fine_collision(scene, states)
            rows.append(row)
        entry: dict[str, Any] = {"cls": cls, "paths": len(rows)}
        for name in names:
            for key in ("ms", "build_ms"):
                values = [r[f"{name}_{key}"] for r in rows]
                entry[f"{name}_{key}_median"] = round(float(np.median(values)), 3) if values else None
                entry[f"{name}_{key}_p90"] = round(float(np.percentile(values, 90)), 3) \
                    if values else None
            for key in ("queries", "bounds", "states"):
                entry[f"{name}_{key}_median"] = int(np.median([r[f"{name}_{key}"] for r in rows])) \
                    if rows else None
            entry[f"{name}_accepted"] = sum(r[f"{name}_valid"] for r in rows)
        if baseline is not None:
            entry["verdicts_differ"] = sum(r["new_valid"] != r["old_valid"] for r in rows)
        if args.fine:
            entry["fine_invalid"] = sum(bool(r.get("fine_collides")) for r in rows)
        table.append(entry)
    return {"machine": f"{platform.node()} {platform.processor() or platform.machine()}, "
                       f"{os.cpu_count()} cores",
            "load": os.getloadavg()[0], "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "seed": args.seed, "baseline": args.baseline, "moveit": table}


def run_planner_paths(args: argparse.Namespace) -> dict:
    """Every path the planner verified on the MoveIt problems, current verifier against the
    baseline's, interleaved, CPU time per path."""
    from taskrunner.moveit import load_motion_plan_request, load_planning_scene
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot import load_robot
    from taskrunner.scene import path_verifier as sweep

    if args.baseline == "none":
        raise SystemExit("--planning needs --baseline REV (a revision whose path "
                         "verifier was taskrunner/scene/sweep.py)")
    baseline = load_baseline(args.baseline)
    modules = {"new": sweep, "old": baseline}
    folder = Path(args.planner_paths)
    robot = load_robot(DATA_ROOT / "robots" / "panda")
    base = Scene(robot)
    recorded: list[np.ndarray] = []
    verify = sweep.PathVerifier.verify

    def recording(verifier: PathVerifier, states: np.ndarray) -> Any:
        recorded.append(np.array(states, dtype=float))
        return verify(verifier, states)

    loads = [os.getloadavg()[0]]
    table = []
    for cls in args.classes.split(","):
        rows: list[dict[str, Any]] = []
        for i in range(args.per_class):
            stem = f"{i + 1:04d}"
            if not (folder / cls / f"{stem}_scene.yaml").exists():
                raise SystemExit(f"error: {folder / cls / stem}_scene.yaml is missing "
                                 f"(python benchmarks/make_problems.py)")
            scene = base.copy()
            load_planning_scene(folder / cls / f"{stem}_scene.yaml", robot).apply(scene)
            request_file = load_motion_plan_request(folder / cls / f"{stem}_request.yaml", robot)
            request_file.apply_start(scene)
            request = request_file.plan_request(scene, seed=i, timing=False)
            recorded.clear()
            sweep.PathVerifier.verify = recording  # type: ignore[method-assign]
            try:
                MotionPlanner(scene).plan(request)
            except PlanningError:
                pass
            finally:
                sweep.PathVerifier.verify = verify  # type: ignore[method-assign]
            checker = scene.checker
            verifiers = {name: module.PathVerifier(robot, checker) for name, module in modules.items()}
            for n, states in enumerate(list(recorded)):
                row: dict[str, Any] = {}
                for name, module in modules.items():      # counts (not timed)
                    walk, calls = module._walk, [0]

                    def counted(*walked: Any, _walk: Any = walk, _calls: list = calls) -> Any:
                        _calls[0] += 1
                        return _walk(*walked)

                    module._walk = counted
                    try:
                        verdict = verifiers[name].verify(states)
                    finally:
                        module._walk = walk
                    row[f"{name}_walks"] = calls[0]
                    row[f"{name}_queries"] = verdict.distance_queries
                    row[f"{name}_valid"] = bool(verdict.valid)
                times: dict[str, list[float]] = {"new": [], "old": []}
                order = ["new", "old"] if (i + n) % 2 == 0 else ["old", "new"]
                for _ in range(args.repeats):
                    for name in order:
                        t0 = time.process_time()
                        verifiers[name].verify(states)
                        times[name].append(time.process_time() - t0)
                    order.reverse()
                for name, values in times.items():
                    row[f"{name}_us"] = float(np.median(values)) * 1e6
                rows.append(row)
            loads.append(os.getloadavg()[0])
        entry: dict[str, Any] = {"cls": cls, "paths": len(rows)}
        for name in ("new", "old"):
            entry[f"{name}_cpu_us_median"] = round(float(np.median([r[f"{name}_us"] for r in rows])), 1) \
                if rows else None
            for key in ("walks", "queries"):
                entry[f"{name}_{key}_mean"] = round(float(np.mean([r[f"{name}_{key}"] for r in rows])), 2) \
                    if rows else None
            entry[f"{name}_rejected"] = sum(not r[f"{name}_valid"] for r in rows)
        entry["verdicts_differ"] = sum(r["new_valid"] != r["old_valid"] for r in rows)
        table.append(entry)
    return {"machine": f"{platform.node()} {platform.processor() or platform.machine()}, "
                       f"{os.cpu_count()} cores",
            "load_min": min(loads), "load_max": max(loads),
            "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
            "baseline": args.baseline, "repeats": args.repeats, "planner_paths": table}


def print_planner_paths(report: dict) -> None:
    print(f"{'class':<18}{'paths':>6}{'old us':>9}{'new us':>9}{'ratio':>7}{'walks old':>10}"
          f"{'new':>6}{'queries old':>12}{'new':>6}{'rejected old':>13}{'new':>5}{'differ':>7}")
    for e in report["planner_paths"]:
        if not e["paths"]:
            continue
        print(f"{e['cls']:<18}{e['paths']:>6}{e['old_cpu_us_median']:>9.0f}{e['new_cpu_us_median']:>9.0f}"
              f"{e['new_cpu_us_median'] / e['old_cpu_us_median']:>7.2f}{e['old_walks_mean']:>10.1f}"
              f"{e['new_walks_mean']:>6.1f}{e['old_queries_mean']:>12.1f}{e['new_queries_mean']:>6.1f}"
              f"{e['old_rejected']:>13}{e['new_rejected']:>5}{e['verdicts_differ']:>7}")
    print(f"machine {report['machine']}, load {report['load_min']:.2f}-{report['load_max']:.2f}, "
          f"{report['date']} (CPU us per path: median of {report['repeats']} repeats, then over paths;"
          f" walks, queries: mean per path)")


def print_moveit(report: dict) -> None:
    rows = report["moveit"]
    with_old = bool(rows) and "old_ms_median" in rows[0]
    head = f"{'class':<17}{'paths':>6}{'verify new':>11}{'p90':>7}{'bounds':>7}{'states':>7}" \
           f"{'queries':>8}{'build new':>10}"
    if with_old:
        head += f"{'verify old':>11}{'p90':>7}{'bounds':>7}{'states':>7}{'build old':>10}{'differ':>7}"
    print(head)
    for e in rows:
        line = (f"{e['cls']:<17}{e['paths']:>6}{e['new_ms_median']:>11.3f}{e['new_ms_p90']:>7.3f}"
                f"{e['new_bounds_median']:>7}{e['new_states_median']:>7}{e['new_queries_median']:>8}"
                f"{e['new_build_ms_median']:>10.3f}")
        if with_old:
            line += (f"{e['old_ms_median']:>11.3f}{e['old_ms_p90']:>7.3f}{e['old_bounds_median']:>7}"
                     f"{e['old_states_median']:>7}{e['old_build_ms_median']:>10.3f}"
                     f"{e['verdicts_differ']:>7}")
        print(line)
    print(f"machine {report['machine']}, load {report['load']:.2f}, {report['date']} "
          f"(ms: fastest of the repeats per path, then the median and p90 over paths)")


def print_planning(report: dict) -> None:
    print(f"{'problem':<20}{'queries':>8}{'plan new':>10}{'plan old':>10}"
          f"{'verify new':>12}{'verify old':>12}{'solved':>10}")
    for e in report["planning"]:
        print(f"{e['problem']:<20}{e['queries']:>8}{e['new_plan_median_ms']:>10.2f}"
              f"{e['old_plan_median_ms']:>10.2f}{e['new_verify_median_ms']:>12.3f}"
              f"{e['old_verify_median_ms']:>12.3f}{e['new_solved']:>5}/{e['old_solved']}")
    print(f"machine {report['machine']}, load {report['load']:.2f}, {report['date']}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer paths")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--baseline", default="none",
                        help="git revision of the verifier to compare with, one whose "
                             "verifier was taskrunner/scene/sweep.py ('none', the default: "
                             "no comparison)")
    parser.add_argument("--problems", help="comma-separated problems of planning_scenes")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--planning", action="store_true",
                        help="time whole plan calls with each verifier instead")
    parser.add_argument("--moveit", metavar="DIR",
                        help="MoveIt problem sets of make_problems.py (e.g. benchmarks/problems)")
    parser.add_argument("--classes", default="table_pick,box,bookshelf_small,bookshelf_thin",
                        help="with --moveit: comma-separated classes")
    parser.add_argument("--per-class", type=int, default=10, help="with --moveit")
    parser.add_argument("--fine", action="store_true",
                        help="with --moveit: re-check accepted paths at 0.1 mm (slow)")
    parser.add_argument("--planner-paths", metavar="DIR",
                        help="every path the planner verifies on the MoveIt problem sets of DIR")
    args = parser.parse_args(argv)
    if args.planner_paths:
        report = run_planner_paths(args)
        print_planner_paths(report)
        if args.json:
            print(json.dumps(report))
        return 0
    if args.moveit:
        report = run_moveit(args)
        print_moveit(report)
        if args.json:
            print(json.dumps(report))
        return 1 if any(e.get("fine_invalid") for e in report["moveit"]) else 0
    if args.planning:
        report = run_planning(args)
        print_planning(report)
        if args.json:
            print(json.dumps(report))
        return 0
    report = run(args)
    print_table(report)
    if args.json:
        print(json.dumps(report))
    bad = sum(e["fine_invalid"] for e in report["classes"])
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
