"""Task benchmark: planning time of every example task, and the wall time of a mock run.

    python benchmarks/tasks.py [--quick] [--json] [--seed N]

For each task in tasks/*.yaml: the run on the mock backend (motions complete at once,
planning in-process so the figure is pure planning work), repeated; "planning" is, summed
over the motion steps, the time from the step starting to its trajectory being ready
(IK goal sampling, OMPL search, shortcut, fine re-check, Cartesian paths and toppra
timing). Then the wall time of ``run-task tasks/pick_place.yaml --backend mock`` measured
from taskrunner.resources import DATA_ROOT
from process start to exit (planning in a worker process, as a user runs it).

Prints a table and, as its last line with --json, one JSON object:
``{"tasks": [{"name", "success", "planning_ms_median", "motions"}, ...],
"pick_place_mock_wall_s_median": ...}``.
Targets on the 2-core reference machine: pick_place planned in ≤ 150 ms, handoff ≤ 500 ms,
the mock run ≤ 3 s wall.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TASKS = ROOT / "taskrunner" / "data" / "tasks"
TARGETS = {"pick_place": 150.0, "handoff": 500.0}
WALL_TARGET_S = 3.0


def _planning_ms(record) -> tuple[float, int]:  # type: ignore[no-untyped-def]
    """Sum over motion steps of (trajectory ready - step started), and the motion count."""
    started: dict[str, float] = {}
    total, motions = 0.0, 0
    for event in record.events:
        if event.kind == "node_started":
            started[event.node] = event.time
        elif event.kind == "planned" and event.node in started:
            total += event.time - started[event.node]
            motions += 1
    return 1e3 * total, motions


def bench_task(path: Path, repeats: int, seed: int) -> dict:
    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.tasks import load_task

    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    times, ok, motions = [], 0, 0
    planner = InProcessPlanner()
    for i in range(repeats + 1):  # the first run warms caches (IK seed tables, imports)
        backend = MockBackend(names, dict(zip(names, cell.start_state())))
        runner = Runner(spec, cell, backend, planner, RunOptions(seed=seed + i))
        record = runner.run()
        if i == 0:
            continue
        ms, motions = _planning_ms(record)
        times.append(ms)
        ok += record.status == "succeeded"
    return {"name": path.stem, "success": ok / repeats,
            "planning_ms_median": round(statistics.median(times), 2),
            "planning_ms_max": round(max(times), 2), "motions": motions}


def bench_wall(repeats: int) -> list[float]:
    walls = []
    with tempfile.TemporaryDirectory() as runs:
        for _ in range(repeats):
            started = time.perf_counter()
            done = subprocess.run(
                [sys.executable, "-m", "taskrunner.cli", str(TASKS / "pick_place.yaml"),
                 "--backend", "mock", "--plain", "--runs-dir", runs],
                capture_output=True, text=True, cwd=ROOT)
            walls.append(time.perf_counter() - started)
            if done.returncode != 0:
                raise RuntimeError(f"run-task failed ({done.returncode}): {done.stderr[-500:]}")
    return walls


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    repeats = 2 if args.quick else 5
    paths = sorted(p for p in TASKS.glob("*.yaml"))
    rows = [bench_task(p, repeats, args.seed) for p in paths]
    walls = bench_wall(2 if args.quick else 5)
    wall = statistics.median(walls)

    print(f"{'task':<22} {'success':>8} {'motions':>8} {'planning ms (median)':>21} {'max':>8}")
    for r in rows:
        print(f"{r['name']:<22} {100 * r['success']:>7.0f}% {r['motions']:>8} "
              f"{r['planning_ms_median']:>21.1f} {r['planning_ms_max']:>8.1f}")
    print(f"\nrun-task tasks/pick_place.yaml --backend mock, process start to exit: "
          f"median {wall:.2f} s over {len(walls)} runs")
    for name, limit in TARGETS.items():
        row = next((r for r in rows if r["name"] == name), None)
        if row is not None:
            met = row["planning_ms_median"] <= limit and row["success"] == 1.0
            print(f"target {name} planned in <= {limit:.0f} ms: {row['planning_ms_median']:.1f} "
                  f"{'met' if met else 'MISSED'}")
    print(f"target mock run <= {WALL_TARGET_S} s wall: {wall:.2f} "
          f"{'met' if wall <= WALL_TARGET_S else 'MISSED'}")
    if args.json:
        print(json.dumps({"tasks": rows, "pick_place_mock_wall_s_median": round(wall, 3),
                          "quick": args.quick, "seed": args.seed}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
