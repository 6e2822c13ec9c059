"""Two arms at once, on the backends that play time and physics: the generated two-arm
tasks and the two-arm examples, each run's record checked by the independent space-time
verifier.

    python benchmarks/two_arm_suite.py [--count 200] [--backends sim,mujoco]
                                       [--no-examples] [--json]

The generated tasks are the scenario suite's (tests/scenarios/test_parallel_generated.py:
on ``servo_arm_pair`` each arm picks a cube 2-7 cm from the table's middle and places it
on its own side, both branches of one ``parallel``, seeds 0 to ``--count`` - 1); the
examples are ``tray_pair``, ``assembly_panda`` and ``handoff``, the hand-over with the bar
laid down while the other arm goes back (``benchmarks/makespan_tasks``) and the one whose
arms' approaches overlap (``tests/tree/fixtures``). Each runs once
per backend (sim at 20x real time; mujoco as fast as it steps), planning in-process with
the task's seed. Per run, the record's motions are replayed on their common clock (each
from when it was really sent) and checked arm against arm by the independent space-time
verifier (:func:`taskrunner.tree.expect.arm_conflicts`: robots' links, exact geometry):
**contacts, target 0 on every run**, whether it succeeded or failed. mujoco also fails a
run itself on any contact between two robots' bodies (counted apart, target 0).

Per backend: runs, succeeded, failed (by reason: the error after the step's file:line,
its first words), contacts by the verifier, robot contacts mujoco reported, and the wall
time. Prints a table, and with --json one JSON object as the last line.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import statistics
import sys
import tempfile
import time
from collections import Counter
from datetime import UTC, datetime
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = [ROOT / "taskrunner" / "data" / "tasks" / f"{name}.yaml"
            for name in ("tray_pair", "assembly_panda", "handoff")] + [
    ROOT / "benchmarks" / "makespan_tasks" / "handoff_parallel.yaml",  # bar laid down meanwhile
    ROOT / "tests" / "tree" / "fixtures" / "handoff_overlap.yaml",     # approaches overlapping
]
SIM_SPEED = 20.0


def run_one(path: Path, backend_kind: str, seed: int, runs_dir: Path) -> dict:
    """One run of the task file ``path`` on ``backend_kind``: its status, error, the
    verifier's contacts and the wall time."""
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.runtime.session import make_backend
    from taskrunner.tasks import load_task
    from taskrunner.tree.expect import arm_conflicts

    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    started = time.perf_counter()
    backend = make_backend(backend_kind, cell, SIM_SPEED if backend_kind == "sim" else None)
    try:
        runner = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(seed=seed, runs_dir=runs_dir, backend_name=backend_kind))
        record = runner.run()
    finally:
        backend.close()
    contacts = arm_conflicts(cell.model, record.events)
    return {"task": path.stem, "seed": seed, "status": record.status,
            "error": record.error, "contacts": contacts,
            "motions": sum(1 for e in record.events if e.kind == "motion"),
            "wall_s": time.perf_counter() - started}


def reason(error: str | None) -> str:
    """A failure's reason: its text after the step's file:line, its first words."""
    text = re.sub(r"^.*?\.yaml:\d+:\s*", "", error or "no error given")
    text = re.sub(r"'[^']*'", "'…'", text)  # names and numbers apart
    return " ".join(re.sub(r"[\d.]+", "N", text).split()[:6])


def suite(backend_kind: str, count: int, examples: bool) -> dict:
    sys.path.insert(0, str(ROOT / "tests" / "scenarios"))
    from test_parallel_generated import generated_task

    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for seed in range(count):
            path = folder / f"generated_{seed}.yaml"
            path.write_text(generated_task(seed), encoding="utf-8")
            runs.append(run_one(path, backend_kind, seed, folder / "runs"))
        if examples:
            runs += [run_one(path, backend_kind, 0, folder / "runs") for path in EXAMPLES]
    failed = Counter(reason(r["error"]) for r in runs if r["status"] != "succeeded")
    # mujoco's own failure on a contact between two robots' bodies (the physics backend).
    robot_contacts = sum(1 for r in runs if "contact between robots" in (r["error"] or ""))
    return {
        "backend": backend_kind, "runs": len(runs),
        "succeeded": sum(r["status"] == "succeeded" for r in runs),
        "failed_by_reason": dict(failed.most_common()),
        "contacts": sum(len(r["contacts"]) for r in runs),
        "runs_with_contacts": [f"{r['task']} (seed {r['seed']}): {r['contacts'][0]}"
                               for r in runs if r["contacts"]],
        "robot_contacts_reported": robot_contacts,
        "examples": {r["task"]: r["status"] for r in runs if not r["task"].startswith("generated_")},
        "wall_s_median": round(statistics.median(r["wall_s"] for r in runs), 2) if runs else None,
        "wall_s_total": round(sum(r["wall_s"] for r in runs), 1),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=200,
                        help="generated tasks per backend (seeds 0 to count - 1; 200)")
    parser.add_argument("--backends", default="sim,mujoco", help="comma-separated (sim,mujoco)")
    parser.add_argument("--no-examples", action="store_true",
                        help="the generated tasks only, not the two-arm examples")
    parser.add_argument("--json", action="store_true", help="print one JSON line at the end")
    args = parser.parse_args(argv)
    kinds = [k.strip() for k in args.backends.split(",") if k.strip()]
    load = " ".join(f"{v:.2f}" for v in os.getloadavg())
    header = {"date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
              "machine": f"{platform.machine()}, {os.cpu_count()} CPUs, "
                         f"Python {platform.python_version()}",
              "load_at_start": load, "count": args.count}
    print(f"{header['date']}; {header['machine']}; load {load} (at the start)")
    results = [suite(kind, args.count, not args.no_examples) for kind in kinds]
    print(f"{'backend':<8} {'runs':>5} {'succeeded':>9} {'contacts':>8} "
          f"{'robot contacts':>14} {'median s':>8}  failures")
    for r in results:
        failures = "; ".join(f"{n}x {why}" for why, n in r["failed_by_reason"].items()) or "-"
        print(f"{r['backend']:<8} {r['runs']:>5} {r['succeeded']:>9} {r['contacts']:>8} "
              f"{r['robot_contacts_reported']:>14} {r['wall_s_median'] or 0:>8.2f}  {failures}")
        for line in r["runs_with_contacts"]:
            print(f"  contact: {line}")
        if r["examples"]:
            print("  examples: " + ", ".join(f"{k} {v}" for k, v in r["examples"].items()))
    print("target: 0 contacts between the arms on every run, by the independent verifier")
    if args.json:
        print(json.dumps({**header, "backends": results}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
