"""The planner's sphere-model search checker against the exact one, interleaved.

For every query of the chosen problems (``planning_scenes``), plans once with
``MotionPlanner(scene, fast_check=False)`` (coal at every ``longest_valid_segment``) and
once with ``fast_check=True`` (sphere model, whole edges in one compiled call, coal
where spheres touch), one after the other, same seed, so machine load hits both alike.
Reports wall and CPU time per plan (median, p95), the search's share, the checks and
the failures; then the one-off costs of the sphere checker: numba's import, building the
sphere model (covering every link), and loading or compiling the kernels, each measured
in a fresh process with empty caches (cold) and again with the caches filled (warm).

    python benchmarks/fastcheck_bench.py [--quick] [--problems a,b] [--queries N] [--json]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import planning_scenes

from taskrunner.errors import PlanningError
from taskrunner.planning import MotionPlanner, PlannerOptions, PlanRequest

DEFAULT_PROBLEMS = ("panda_table_pick", "panda_shelf", "panda_box", "panda_cage",
                    "servo_table", "servo_pair_swap")
_ONE_OFF = """
import json, sys, time
t0 = time.perf_counter()
import numba
t_numba = time.perf_counter() - t0
sys.path.insert(0, {bench!r})
import planning_scenes
from taskrunner.planning import fastcheck
problem = planning_scenes.build_problems(1, 0, ["panda_shelf"])[0]
t1 = time.perf_counter()
model = fastcheck.SphereModel(problem.scene.robot, problem.scene.checker)
t_model = time.perf_counter() - t1
group = model.group(problem.scene.robot.group(problem.group).joint_indices)
t2 = time.perf_counter()
group.warm_up(problem.queries[0].start)
t_kernels = time.perf_counter() - t2
print(json.dumps({{"numba_import_s": t_numba, "sphere_model_s": t_model,
                  "kernels_s": t_kernels, "spheres": model.sphere_count}}))
"""


def _stats(values: list[float]) -> dict:
    if not values:
        return {"median_ms": None, "p95_ms": None}
    return {"median_ms": round(float(np.median(values)) * 1e3, 2),
            "p95_ms": round(float(np.percentile(values, 95)) * 1e3, 2)}


def compare(problems: list[str], queries: int, seed: int = 0) -> list[dict]:
    rows = []
    for problem in planning_scenes.build_problems(queries, seed, problems):
        planners = {"exact": MotionPlanner(problem.scene, fast_check=False),
                    "spheres": MotionPlanner(problem.scene, fast_check=True)}
        runs: dict[str, dict[str, list]] = {k: {"wall": [], "cpu": [], "search": [],
                                                 "checks": [], "failed": []} for k in planners}
        for planner in planners.values():  # warm-up (IK solvers, the sphere model, kernels)
            query = problem.queries[0]
            try:
                planner.plan(PlanRequest(problem.group, query.goal, start=query.start,
                                         options=PlannerOptions(planner="RRTConnect",
                                                                seed=999_983)))
            except PlanningError:
                pass
        for i, query in enumerate(problem.queries):
            for k, planner in planners.items():
                options = PlannerOptions(planner="RRTConnect",
                                         planning_time=problem.planning_time, seed=seed * 1000 + i)
                request = PlanRequest(problem.group, query.goal, start=query.start,
                                      options=options)
                wall, cpu = time.perf_counter(), time.process_time()
                try:
                    result = planner.plan(request)
                except PlanningError as exc:
                    runs[k]["failed"].append(type(exc).__name__)
                    continue
                runs[k]["wall"].append(time.perf_counter() - wall)
                runs[k]["cpu"].append(time.process_time() - cpu)
                runs[k]["search"].append(result.planning_time)
                runs[k]["checks"].append(result.checks)
        for k, r in runs.items():
            rows.append({"problem": problem.name, "checker": k, "queries": len(problem.queries),
                         "failed": len(r["failed"]),
                         "wall": _stats(r["wall"]), "cpu": _stats(r["cpu"]),
                         "search": _stats(r["search"]),
                         "checks_median": float(np.median(r["checks"])) if r["checks"] else None})
    return rows


def one_off() -> dict:
    """Import, sphere model and kernel costs in fresh processes: empty caches, then filled."""
    bench = str(Path(__file__).resolve().parent)
    out = {}
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, XDG_CACHE_HOME=cache)
        env.pop("NUMBA_CACHE_DIR", None)
        for label in ("cold", "warm"):
            done = subprocess.run([sys.executable, "-c", _ONE_OFF.format(bench=bench)], env=env,
                                  capture_output=True, text=True, check=True)
            out[label] = json.loads(done.stdout.strip().splitlines()[-1])
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 queries per problem")
    parser.add_argument("--problems", help="comma-separated problem names")
    parser.add_argument("--queries", type=int)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    args = parser.parse_args(argv)
    problems = args.problems.split(",") if args.problems else list(DEFAULT_PROBLEMS)
    queries = args.queries or (3 if args.quick else 10)
    load = os.getloadavg()[0]
    rows = compare(problems, queries, args.seed)
    costs = one_off()
    print(f"load average {load:.1f} at start, {os.getloadavg()[0]:.1f} at end")
    print(f"{'problem':22s} {'checker':8s} {'fail':>4s} {'wall med':>9s} {'wall p95':>9s} "
          f"{'cpu med':>8s} {'search med':>10s} {'checks':>7s}")
    for r in rows:
        print(f"{r['problem']:22s} {r['checker']:8s} {r['failed']:4d} "
              f"{r['wall']['median_ms']!s:>9s} {r['wall']['p95_ms']!s:>9s} "
              f"{r['cpu']['median_ms']!s:>8s} {r['search']['median_ms']!s:>10s} "
              f"{r['checks_median']!s:>7s}")
    for label, c in costs.items():
        print(f"{label}: numba import {c['numba_import_s']:.2f} s, sphere model "
              f"{c['sphere_model_s']:.2f} s ({c['spheres']} spheres), kernels "
              f"{c['kernels_s']:.2f} s")
    if args.json:
        print(json.dumps({"rows": rows, "one_off": costs, "load": load}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
