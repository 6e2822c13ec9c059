"""Planning benchmark: OMPL planners on our own Panda and servo-arm scenes.

    python benchmarks/planning.py [--quick] [--json] [--seed N] [--planners A,B]
                                  [--problems P,Q] [--queries N] [--profile]
    python benchmarks/planning.py --compare [--per-class N] ...  # planning_compare.py:
        # the MoveIt problem sets of make_problems.py, ours against roboplan's RRT-Connect

The scenes and their seeded queries are in ``benchmarks/planning_scenes.py``: a Panda
picking over a table, under a table, in a shelf, in an open box and out of a cage; the
servo arm on its table; two servo arms swapping sides. Every query is one
:meth:`MotionPlanner.plan` call (joint goals, except ``panda_table_pick_pose``), capped
at the problem's ``planning_time`` (1 s, 2 s for the cage), one attempt, seeded.

Per problem and planner: success rate; median and p95 of the wall time of ``plan`` (the
whole request: start and goal checks, IK goal sampling, the straight line tried first,
search, shortcut, exact verification;
failures count with the time they took); search-only time (``PlanResult.planning_time``,
solved queries); joint-space path length (rad, Euclidean); trajectory duration (s) and
toppra time per path (``parameterize_path``, 100 Hz). Every returned path is re-checked
here every 0.01 rad (not timed); ``bad_paths`` counts any that collide.

Default planners: RRTConnect on every problem; RRTstar, PRM, BITstar and KPIECE1 on the
joint-goal problems (PRM is never run with several goal states: OMPL's PRM then calls the
Python validity checker from its second thread and deadlocks). --quick runs 5 queries,
RRTConnect only. --profile adds a breakdown of where ``plan`` (with toppra timing) spends
its time on the shelf, the cage and the pose-goal pick (timers around the planner's
phases: start, goals, straight line, search, shortcut, exact verification, timing; see
:func:`run_profile`). Times on a shared machine drift (up to 2x over minutes; see
``calibration_us``); the collision-check counts are the same on every run of a seed.

Targets on the 2-core reference machine: RRTConnect solves every Panda table, under-table,
shelf and box query at a median ≤ 10 ms, every cage query at ≤ 300 ms; the dual-arm swap
100 % at ≤ 100 ms median; toppra ≤ 5 ms per path (median). The last line (with --json)
is one JSON object: ``{"problems": [{"name", "planner", "success", "median_ms",
"p95_ms", ...}], "targets": [...], ...}``.
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

BENCH = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH))
if str(BENCH.parent) not in sys.path:
    sys.path.insert(0, str(BENCH.parent))

import ik_bench
import planning_scenes

from taskrunner.errors import PlanningError
from taskrunner.planning import MotionPlanner, PlannerOptions, PlanRequest, PoseGoal
from taskrunner.planning.planner import interpolate_path

try:  # toppra timing is optional: without it the duration columns are left out
    from taskrunner.planning.timing import parameterize_path
except ImportError:  # pragma: no cover
    parameterize_path = None  # type: ignore[assignment]

__all__ = ["TARGETS", "check_targets", "describe_profile", "rows", "run", "run_profile"]

FULL_QUERIES, QUICK_QUERIES = 20, 5
DEFAULT_PLANNERS = ("RRTConnect", "RRTstar", "PRM", "BITstar", "KPIECE1")
MULTI_THREADED = {"PRM", "PRMstar"}  # deadlock with several goal states (see the docstring)
CHECK_RESOLUTION = 0.01  # rad: independent re-check of every returned path

# (what, problems, planner, least success, largest median ms); and toppra's median ms.
TARGETS = (
    ("Panda table/shelf/box", ("panda_table_pick", "panda_under_table", "panda_shelf",
                               "panda_box"), "RRTConnect", 1.0, 10.0),
    ("Panda cage", ("panda_cage",), "RRTConnect", 1.0, 300.0),
    ("dual-arm swap", ("servo_pair_swap",), "RRTConnect", 1.0, 100.0),
)
TOPPRA_TARGET_MS = 5.0


def _planners_for(problem: planning_scenes.Problem, planners: Sequence[str] | None) -> list[str]:
    chosen = list(planners) if planners else [
        p for p in DEFAULT_PLANNERS
        if p == "RRTConnect" or problem.name != "panda_table_pick_pose"]
    several_goals = any(isinstance(q.goal, PoseGoal) for q in problem.queries)
    return [p for p in chosen if not (several_goals and p in MULTI_THREADED)]


def _path_is_free(problem: planning_scenes.Problem, result) -> bool:  # type: ignore[no-untyped-def]
    scene, model = problem.scene, problem.scene.robot
    idx = model.indices(result.path.names)
    q = result.start.copy()
    for values in interpolate_path(np.asarray(result.path.waypoints), CHECK_RESOLUTION):
        q[idx] = values
        if not planning_scenes.is_valid_state(scene, model.apply_mimic(q)):
            return False
    return True


def _run_query(problem: planning_scenes.Problem, planner: MotionPlanner, query, name: str,
               seed: int) -> dict:  # type: ignore[no-untyped-def]
    options = PlannerOptions(planner=name, planning_time=problem.planning_time, seed=seed)
    request = PlanRequest(problem.group, query.goal, start=query.start, options=options)
    t0 = time.perf_counter()
    try:
        result = planner.plan(request)
    except PlanningError as exc:
        return {"ok": False, "wall": time.perf_counter() - t0, "error": type(exc).__name__}
    wall = time.perf_counter() - t0
    waypoints = np.asarray(result.path.waypoints)
    out: dict[str, Any] = {"ok": True, "wall": wall, "search": result.planning_time,
           "simplify": result.simplify_time, "checks": result.checks,
           "length": float(np.sum(np.linalg.norm(np.diff(waypoints, axis=0), axis=1))),
           "free": _path_is_free(problem, result)}
    if parameterize_path is not None:
        t0 = time.perf_counter()
        try:
            trajectory = parameterize_path(problem.scene.robot, result.path)
            out["toppra"] = time.perf_counter() - t0
            out["duration"] = float(trajectory.times[-1])
        except PlanningError as exc:
            out["toppra_error"] = str(exc)
    return out


def _stats(problem: planning_scenes.Problem, planner: str, runs: list[dict]) -> dict:
    def ms(values: list[float], q: float) -> float | None:
        return round(float(np.percentile(values, q)) * 1000, 3) if values else None

    solved = [r for r in runs if r["ok"]]
    wall = [r["wall"] for r in runs]
    errors: dict[str, int] = {}
    for r in runs:
        if not r["ok"]:
            errors[r["error"]] = errors.get(r["error"], 0) + 1
    row = {
        "name": problem.name, "planner": planner, "queries": len(runs),
        "success": len(solved) / len(runs),
        "median_ms": ms(wall, 50), "p95_ms": ms(wall, 95),
        "search_median_ms": ms([r["search"] for r in solved], 50),
        "search_p95_ms": ms([r["search"] for r in solved], 95),
        "simplify_median_ms": ms([r["simplify"] for r in solved], 50),
        "checks_median": float(np.median([r["checks"] for r in solved])) if solved else None,
        "path_length_rad": (round(float(np.median([r["length"] for r in solved])), 3)
                            if solved else None),
        "bad_paths": sum(not r["free"] for r in solved),
        "time_cap_s": problem.planning_time, "errors": errors,
    }
    if parameterize_path is not None:
        timed = [r for r in solved if "toppra" in r]
        row["duration_s"] = (round(float(np.median([r["duration"] for r in timed])), 3)
                             if timed else None)
        row["toppra_median_ms"] = ms([r["toppra"] for r in timed], 50)
        row["toppra_p95_ms"] = ms([r["toppra"] for r in timed], 95)
        row["toppra_failures"] = sum("toppra_error" in r for r in solved)
    return row


def run(quick: bool, seed: int = 0, planners: Sequence[str] | None = None,
        problems: Sequence[str] | None = None, queries: int | None = None) -> dict:
    """Plan every query of every problem with every planner chosen.

    Args:
        quick: 5 queries and RRTConnect only (unless ``planners``/``queries`` say otherwise).
        seed: seeds the query sets and the planners (query ``i`` uses seed ``seed * 1000 + i``).
        planners: OMPL planner names; default :data:`DEFAULT_PLANNERS` (see the docstring).
        problems: problem names (``planning_scenes.PROBLEM_NAMES``); default all.
        queries: queries per problem; default 20 (5 with ``quick``).

    Returns:
        ``{"problems": [row, ...], "toppra_median_ms", "toppra_p95_ms", "skipped"}``; a
        row holds ``name, planner, queries, success`` (fraction), ``median_ms, p95_ms``
        (wall time of ``plan``), ``search_median_ms, search_p95_ms``, ``simplify_median_ms`` (shortcut:
        ``PlanResult.simplify_time``, the exact verification excluded),
        ``checks_median``, ``path_length_rad``, ``bad_paths``, ``duration_s``,
        ``toppra_median_ms, toppra_p95_ms``, ``errors`` (failure class → count).
    """
    count = queries or (QUICK_QUERIES if quick else FULL_QUERIES)
    if quick and not planners:
        planners = ("RRTConnect",)
    built = planning_scenes.build_problems(count, seed, problems)
    rows_out, skipped, toppra_times = [], [], []
    for problem in built:
        chosen = _planners_for(problem, planners)
        skipped += [f"{p} on {problem.name}" for p in (planners or DEFAULT_PLANNERS)
                    if p not in chosen and (planners or problem.name != "panda_table_pick_pose")]
        planner = MotionPlanner(problem.scene)
        _run_query(problem, planner, problem.queries[0], "RRTConnect", seed + 999_983)  # warm-up
        for name in chosen:
            runs = [_run_query(problem, planner, query, name, seed * 1000 + i)
                    for i, query in enumerate(problem.queries)]
            toppra_times += [r["toppra"] for r in runs if "toppra" in r]
            rows_out.append(_stats(problem, name, runs))
    result: dict = {"problems": rows_out, "skipped": skipped, "queries": count,
                    "descriptions": {p.name: (p.description, p.planning_time) for p in built}}
    if toppra_times:
        result["toppra_median_ms"] = round(float(np.median(toppra_times)) * 1000, 3)
        result["toppra_p95_ms"] = round(float(np.percentile(toppra_times, 95)) * 1000, 3)
    return result


def check_targets(result: dict) -> list[dict]:
    """The targets (see the docstring) with the measured values and whether they are met."""
    out = []
    found = {(r["name"], r["planner"]): r for r in result["problems"]}
    for what, names, planner, success, limit in TARGETS:
        for name in names:
            row = found.get((name, planner))
            if row is None:
                continue
            met = row["success"] >= success and row["median_ms"] <= limit
            out.append({"name": f"{name} {planner}", "what": what, "success": row["success"],
                        "median_ms": row["median_ms"], "search_median_ms": row["search_median_ms"],
                        "limit_ms": limit, "met": bool(met)})
    if "toppra_median_ms" in result:
        value = result["toppra_median_ms"]
        out.append({"name": "toppra per path", "what": "toppra", "median_ms": value,
                    "p95_ms": result["toppra_p95_ms"], "limit_ms": TOPPRA_TARGET_MS,
                    "met": value <= TOPPRA_TARGET_MS})
    return out


def rows(result: dict) -> list[list[str]]:
    """Table rows (header first) of a :func:`run` result."""
    timing = "toppra_median_ms" in result

    def f(value: float | None, digits: int = 1) -> str:
        return "-" if value is None else f"{value:.{digits}f}"

    header = ["problem", "planner", "success", "median ms", "p95 ms", "search ms", "search p95",
              "simplify ms", "checks", "path rad", "bad"]
    if timing:
        header += ["duration s", "toppra ms"]
    out = [header]
    for r in result["problems"]:
        line = [r["name"], r["planner"], f"{100 * r['success']:.0f} %", f(r["median_ms"]),
                f(r["p95_ms"]), f(r["search_median_ms"]), f(r["search_p95_ms"]),
                f(r["simplify_median_ms"]), f(r["checks_median"], 0), f(r["path_length_rad"], 2),
                str(r["bad_paths"])]
        if timing:
            line += [f(r.get("duration_s"), 2), f(r.get("toppra_median_ms"), 2)]
        out.append(line)
    return out


def _target_lines(targets: list[dict]) -> list[str]:
    lines = []
    for t in targets:
        verdict = "met" if t["met"] else "MISSED"
        if t["what"] == "toppra":
            lines.append(f"target toppra median <= {t['limit_ms']:g} ms per path: "
                         f"{t['median_ms']:.2f} ms (p95 {t['p95_ms']:.2f}) {verdict}")
            continue
        ratio = t["median_ms"] / t["limit_ms"]
        search = t["search_median_ms"]
        lines.append(
            f"target {t['name']}: 100 % at median <= {t['limit_ms']:g} ms: "
            f"{100 * t['success']:.0f} %, {t['median_ms']:.1f} ms ({ratio:.2f}x the limit; "
            f"search only {'-' if search is None else f'{search:.1f}'} ms) {verdict}")
    return lines


# ---------------------------------------------------------------------- profile
PROFILED = ("panda_table_pick_pose", "panda_shelf", "panda_cage")
# phase -> (owner in taskrunner.planning.planner, function): the planner's own steps.
PHASES = {
    "start": ("MotionPlanner", "_start_state"),      # start state: limits, collision
    "goals": ("MotionPlanner", "_goal_states"),      # goal states: IK sampling, checks
    "direct": ("MotionPlanner", "_direct"),          # the straight line tried first
    "search": ("MotionPlanner", "_search"),          # OMPL: problem setup and solve
    "shortcut": ("module", "shortcut_path"),         # shortcutting the path found
    "verify": ("MotionPlanner", "verify_states"),    # exact verification (path, trajectory)
    "timing": ("module", "parameterize_path"),       # toppra, with the request's timing
}


def run_profile(seed: int = 0, count: int = FULL_QUERIES,
                problems: Sequence[str] = PROFILED) -> dict:
    """Where RRTConnect's ``plan`` spends its time, from timers wrapped around its phases.

    Default problems: the shelf, the cage, and the pose-goal pick (IK goal sampling). Each
    query is planned and timed (``PlanRequest.timing``: toppra at 100 Hz), as ``run-task``
    asks for a motion.

    The phases (:data:`PHASES`) are the planner's own functions. Times are exclusive: a
    phase called inside another (the exact verification inside the straight-line try,
    toppra inside the timing step) counts in the inner one only; ``other`` is the rest of
    the wall time of ``plan`` (building the checks, the OMPL import on the first call,
    bookkeeping). The wrappers are removed afterwards. The counts come from the
    ``PlanResult``: states checked by the search and the straight line (``checks``),
    distances computed by the exact verification (``verify_queries``), searches run.

    Returns:
        ``{problem: {"queries", "solved", "wall_ms": [...], "solve_ms": [...], "checks":
        [...], "verify_queries": [...], "searches": [...], "straight": [...], phase:
        {"ms": [per query], "calls": [per query]}}}`` over the solved queries (phases
        :data:`PHASES` and ``other``).
    """
    import taskrunner.planning.planner as planner_module
    from taskrunner.planning.timing import TimingOptions

    clock = time.perf_counter_ns
    # phase -> [exclusive ns, calls]; the stack holds [phase, ns spent in nested phases]
    tally: dict[str, list[int]] = {p: [0, 0] for p in PHASES}
    stack: list[list] = []

    def wrapped(original, phase: str):  # type: ignore[no-untyped-def]
        def timed(*args, **kwargs):  # type: ignore[no-untyped-def]
            frame = [phase, 0]
            stack.append(frame)
            t0 = clock()
            try:
                return original(*args, **kwargs)
            finally:
                elapsed = clock() - t0
                stack.pop()
                tally[phase][0] += elapsed - frame[1]
                tally[phase][1] += 1
                if stack:
                    stack[-1][1] += elapsed

        return timed

    owners = {"MotionPlanner": planner_module.MotionPlanner, "module": planner_module}
    originals = []
    out: dict = {}
    try:
        for phase, (owner_name, name) in PHASES.items():
            owner = owners[owner_name]
            original = getattr(owner, name)
            originals.append((owner, name, original))
            setattr(owner, name, wrapped(original, phase))
        for problem in planning_scenes.build_problems(count, seed, problems):
            planner = MotionPlanner(problem.scene)
            _run_query(problem, planner, problem.queries[0], "RRTConnect", seed + 999_983)
            record: dict = {"queries": count, "solved": 0, "wall_ms": [], "solve_ms": [],
                            "checks": [], "verify_queries": [], "searches": [], "straight": [],
                            **{p: {"ms": [], "calls": []} for p in (*PHASES, "other")}}
            for i, query in enumerate(problem.queries):
                tally.clear()
                tally.update({p: [0, 0] for p in PHASES})
                options = PlannerOptions(planner="RRTConnect", planning_time=problem.planning_time,
                                         seed=seed * 1000 + i)
                request = PlanRequest(problem.group, query.goal, query.start, options,
                                      timing=TimingOptions())
                t0 = clock()
                try:
                    result = planner.plan(request)
                except PlanningError:
                    continue
                wall = clock() - t0
                record["wall_ms"].append(wall / 1e6)
                record["solve_ms"].append(result.planning_time * 1000)
                record["checks"].append(result.checks)
                record["verify_queries"].append(result.verify_queries)
                record["searches"].append(result.searches)
                record["straight"].append(result.direct)
                record["solved"] += 1
                for p in PHASES:
                    record[p]["ms"].append(tally[p][0] / 1e6)
                    record[p]["calls"].append(tally[p][1])
                record["other"]["ms"].append((wall - sum(t[0] for t in tally.values())) / 1e6)
                record["other"]["calls"].append(1)
            out[problem.name] = record
    finally:
        for owner, name, original in originals:
            setattr(owner, name, original)
    return out


def describe_profile(profile: dict) -> list[str]:
    """Readable lines of a :func:`run_profile` result (medians per solved query)."""
    lines = []
    for name, rec in profile.items():
        if not rec["solved"]:
            lines.append(f"profile {name}: no query solved")
            continue
        total = sum(rec["wall_ms"])
        lines.append(f"profile {name} (RRTConnect + toppra, {rec['solved']}/{rec['queries']} "
                     f"solved, {sum(rec['straight'])} by the straight line): plan median "
                     f"{np.median(rec['wall_ms']):.1f} ms; exclusive time per phase:")
        for p in (*PHASES, "other"):
            ms, calls = rec[p]["ms"], rec[p]["calls"]
            lines.append(f"  {p:<9} {100 * sum(ms) / total:5.1f} % of the summed wall time, "
                         f"median {np.median(ms):7.2f} ms, mean {np.mean(calls):5.2f} calls")
        searched = [s for s, d in zip(rec["solve_ms"], rec["straight"]) if not d]
        solve = f"{np.median(searched):.2f} ms median" if searched else "none (all straight)"
        lines.append(f"  OMPL solve (PlanResult.planning_time, searched queries): {solve}; "
                     f"states checked {np.median(rec['checks']):.0f} median; exact "
                     f"verification {np.median(rec['verify_queries']):.0f} distances median; "
                     f"searches per plan {np.mean(rec['searches']):.2f} (more than 1: the "
                     f"exact verification turned a path down and a finer search ran)")
    return lines


def _split(text: str | None) -> list[str] | None:
    return [s.strip() for s in text.split(",") if s.strip()] if text else None


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if "--compare" in argv:  # the MoveIt problem sets, side by side with roboplan
        import planning_compare

        return planning_compare.main([a for a in argv if a != "--compare"])
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="5 queries, RRTConnect only")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--planners", help="comma-separated OMPL planners")
    parser.add_argument("--problems", help="comma-separated problems: "
                        + ", ".join(planning_scenes.PROBLEM_NAMES))
    parser.add_argument("--queries", type=int, help="queries per problem")
    parser.add_argument("--profile", action="store_true",
                        help="also break down RRTConnect's time (with toppra timing) into the "
                        "planner's phases on the shelf, the cage and the pose-goal pick")
    args = parser.parse_args(argv)

    started = time.perf_counter()
    calibration = ik_bench._calibration_us()
    result = run(args.quick, args.seed, _split(args.planners), _split(args.problems), args.queries)
    for name, (description, cap) in result["descriptions"].items():
        print(f"{name}: {description} (cap {cap:g} s)")
    print()
    table = rows(result)
    widths = [max(len(row[k]) for row in table) for k in range(len(table[0]))]
    for row in table:
        print("  ".join(cell.ljust(w) if k < 2 else cell.rjust(w)
                        for k, (cell, w) in enumerate(zip(row, widths))))
    if parameterize_path is None:
        print("(taskrunner.planning.timing is missing: no trajectory durations)")
    for note in result["skipped"]:
        print(f"skipped {note}: OMPL's PRM deadlocks with several goal states")
    targets = check_targets(result)
    print()
    print("\n".join(_target_lines(targets)))
    if args.profile:
        profile = run_profile(args.seed, 5 if args.quick else FULL_QUERIES)
        print()
        print("\n".join(describe_profile(profile)))
        result["profile"] = profile
    result.update(targets=targets, seed=args.seed, quick=args.quick,
                  calibration_us=round(calibration, 3), python=platform.python_version(),
                  seconds=round(time.perf_counter() - started, 1))
    if args.json:
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
