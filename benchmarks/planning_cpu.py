"""Planning CPU of a task, trees compared in alternating fresh processes.

    python benchmarks/planning_cpu.py [--trees DIR,DIR ...] [--rounds N] [--seeds 1-8]
                                      [--task pick_place] [--after-check] [--json]

Each tree is a directory holding a ``taskrunner/`` package (e.g. from ``git archive``;
default: this checkout). In every round, each tree runs in a fresh process (the order
alternating between rounds): the task once to warm up, then once per seed on the mock
backend with the planner in-process (as ``benchmarks/tasks.py``). "Planning" is, summed
over the motion steps, the span from the step starting to its trajectory being ready;
its CPU figure is the thread's CPU time over those spans (the machine's load changes the
wall figure far more). With ``--after-check`` each run is preceded by ``run-task
check``'s dry run with the same seed and runs the task and cell that check loaded, as
``run-task`` does.

Prints one line per process, a table of medians and, with --json, one JSON object:
``{"trees": [{"tree", "cpu_ms_median", "cpu_ms_min", "wall_ms_median", "runs",
"succeeded"}, ...]}``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _seeds(text: str) -> list[int]:
    if "-" in text:
        first, last = text.split("-")
        return list(range(int(first), int(last) + 1))
    return [int(s) for s in text.split(",")]


def _measure(task: str, seeds: list[int], after_check: bool) -> dict:
    """Run in the measuring process: per seed, (planning CPU ms, planning wall ms, status)."""
    import taskrunner
    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime import events
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.tasks import load_task
    from taskrunner.tree.check import check_task

    spans: dict[str | None, tuple[float, float]] = {}
    total = {"cpu": 0.0, "wall": 0.0}
    emit = events.EventLog.emit

    def timed_emit(self, kind, message="", **data):  # type: ignore[no-untyped-def]
        if kind == "node_started":
            spans[data.get("node")] = (time.thread_time(), time.perf_counter())
        elif kind == "planned" and data.get("node") in spans:
            cpu, wall = spans.pop(data.get("node"))
            total["cpu"] += time.thread_time() - cpu
            total["wall"] += time.perf_counter() - wall
        return emit(self, kind, message, **data)

    events.EventLog.emit = timed_emit  # type: ignore[method-assign]
    path = Path(taskrunner.__file__).parent / "data" / "tasks" / f"{task}.yaml"
    planner = InProcessPlanner()
    spec = cell = None
    rows = []
    for i, seed in enumerate([0, *seeds]):  # the first run warms caches
        if after_check:
            report = check_task(path, seed=seed)
            if report.problems:
                raise RuntimeError(f"check of {path}: {report.problems[0]}")
            spec, cell = report.task, report.loaded_cell
        elif spec is None:
            spec = load_task(path)
            cell = load_cell(spec.cell)
        assert spec is not None and cell is not None
        names = cell.model.joint_names
        backend = MockBackend(names, dict(zip(names, cell.start_state())))
        total["cpu"] = total["wall"] = 0.0
        record = Runner(spec, cell, backend, planner, RunOptions(seed=seed)).run()
        if i:
            rows.append((1e3 * total["cpu"], 1e3 * total["wall"], record.status))
    return {"package": taskrunner.__file__, "runs": rows}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trees", default=str(ROOT), help="comma-separated tree directories")
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--seeds", default="1-8", help="'1-8' or '1,2,5'")
    parser.add_argument("--task", default="pick_place")
    parser.add_argument("--after-check", action="store_true")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    seeds = _seeds(args.seeds)
    if args.measure:
        print(json.dumps(_measure(args.task, seeds, args.after_check)))
        return 0
    trees = [str(Path(t).resolve()) for t in args.trees.split(",")]
    found: dict[str, list[tuple[float, float, str]]] = {t: [] for t in trees}
    for r in range(args.rounds):
        for tree in trees if r % 2 == 0 else trees[::-1]:
            load = os.getloadavg()[0]
            command = [sys.executable, __file__, "--measure", "--task", args.task,
                       "--seeds", ",".join(map(str, seeds))] + (
                ["--after-check"] if args.after_check else [])
            done = subprocess.run(command, capture_output=True, text=True, cwd="/",
                                  env={**os.environ, "PYTHONPATH": tree})
            if done.returncode != 0:
                raise RuntimeError(f"{tree}: {done.stderr[-800:]}")
            result = json.loads(done.stdout.strip().splitlines()[-1])
            if not result["package"].startswith(tree):
                raise RuntimeError(f"{tree}: imported {result['package']} instead")
            found[tree] += [tuple(row) for row in result["runs"]]
            cpu = statistics.median(row[0] for row in result["runs"])
            print(f"round {r}  {tree}  load {load:.2f}  planning CPU median {cpu:.2f} ms",
                  flush=True)
    summary = []
    for tree, rows in found.items():
        summary.append({"tree": tree, "runs": len(rows),
                        "succeeded": sum(row[2] == "succeeded" for row in rows),
                        "cpu_ms_median": round(statistics.median(r[0] for r in rows), 2),
                        "cpu_ms_min": round(min(r[0] for r in rows), 2),
                        "wall_ms_median": round(statistics.median(r[1] for r in rows), 2)})
    print(f"\n{args.task}{' (after the check)' if args.after_check else ''}: planning per run")
    print(f"{'tree':<40} {'runs':>5} {'ok':>4} {'CPU median ms':>14} {'CPU min':>8} "
          f"{'wall median':>12}")
    for row in summary:
        print(f"{row['tree'][-40:]:<40} {row['runs']:>5} {row['succeeded']:>4} "
              f"{row['cpu_ms_median']:>14.2f} {row['cpu_ms_min']:>8.2f} "
              f"{row['wall_ms_median']:>12.2f}")
    if args.json:
        print(json.dumps({"task": args.task, "after_check": args.after_check,
                          "trees": summary}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
