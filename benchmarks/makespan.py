"""Makespan benchmark: two arms at once against one after the other.

    python benchmarks/makespan.py [--runs N] [--seed S] [--pairs NAME,...] [--json]

For each pair below, the parallel task and its sequential version (the same steps, one
arm after the other; the versions not shipped in taskrunner/data/tasks are in
benchmarks/makespan_tasks) are run on the mock backend, planning in-process, ``--runs``
times each with seeds ``S, S+1, …``, the two alternating (a change in the machine's load
falls on both alike). Per task:

- *makespan*: the task time the run's schedule gives, from the first motion's start to the
  last one's end (s; each ``motion`` event's ``start`` plus its trajectory's duration; on
  the mock backend this is the schedule's own clock: what a backend that plays time
  follows, waits included);
- *planning per motion*: the planner's time (``planned`` events' ``planning_time``) plus
  the space-time admission of the motion against the other branches (``motion`` events'
  ``verify_time``), over the motions planned (ms).

The table gives the speed-up (sequential makespan / parallel makespan, target >= 1.6 on
the two examples) and the planning overhead of a motion in the parallel task against a
motion in the sequential one, whose motions are single-arm plans with nothing to verify
against (target <= 2x).

With ``--generated N`` it also runs the first N generated two-arm tasks of the scenario
suite (tests/scenarios/test_parallel_generated.py: each arm picks a cube near the table's
middle and places it on its own side, in one ``parallel``) three times each, alternating:
as a run schedules them (``replans``: a motion that would meet the other arm's running
motion starts a little later, to pass behind it, and a planned motion that would still
wait long for that motion's end is planned again around the other arm), with the delays
only (``delays``: ``MotionSchedule(replans=False)``), and with neither (``until_end``: it
waits for that motion's end, ``delays=1``). Per mode: runs succeeded, the sum and median
of the makespans, the waits by resolution, and the arm-against-arm contacts the
independent verifier finds on the records (target 0).

Prints a table, and with --json one JSON object as the last line.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TASKS = ROOT / "taskrunner" / "data" / "tasks"
SEQUENTIAL = Path(__file__).resolve().parent / "makespan_tasks"
PAIRS = [
    ("tray_pair", TASKS / "tray_pair.yaml", SEQUENTIAL / "tray_pair_sequential.yaml"),
    ("assembly_panda", TASKS / "assembly_panda.yaml",
     SEQUENTIAL / "assembly_panda_sequential.yaml"),
    # The shipped handoff is the sequential one here: its parallel version lays the bar
    # down while the other arm goes back to Candle.
    ("handoff", SEQUENTIAL / "handoff_parallel.yaml", TASKS / "handoff.yaml"),
]
SPEEDUP_TARGET = 1.6
OVERHEAD_TARGET = 2.0


def run_once(path: Path, seed: int, runs_dir: Path) -> dict:
    """One mock run of ``path``: its status, makespan (s), motions and planning (s)."""
    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.tasks import load_task

    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=seed, runs_dir=runs_dir))
    record = runner.run()
    spans, planning, verifying, planned, waits = [], 0.0, 0.0, 0, 0
    for event in record.events:
        if event.kind == "motion":
            start = float(event.data["start"])
            spans.append((start, start + float(event.data["trajectory"]["duration"])))
            verifying += float(event.data.get("verify_time", 0.0))
        elif event.kind == "planned":
            planning += float(event.data.get("planning_time", 0.0))
            planned += 1
        elif event.kind == "wait":
            waits += 1
    makespan = (max(e for _, e in spans) - min(s for s, _ in spans)) if spans else 0.0
    return {"status": record.status, "makespan_s": makespan, "motions": len(spans),
            "planned": planned, "planning_s": planning, "verify_s": verifying,
            "waits": waits}


def bench_pair(parallel: Path, sequential: Path, runs: int, seed: int) -> tuple[dict, dict]:
    """Both tasks ``runs`` times, alternating (parallel, sequential, parallel, ...: a
    change of the machine's load falls on both alike), after a warm-up run of each."""
    found: dict[Path, list[dict]] = {parallel: [], sequential: []}
    with tempfile.TemporaryDirectory() as tmp:
        for path in found:
            run_once(path, seed, Path(tmp))  # warm-up: imports, IK seed tables, kernels
        for i in range(runs):
            for path, done in found.items():
                done.append(run_once(path, seed + i, Path(tmp)))
    return summary(parallel, found[parallel]), summary(sequential, found[sequential])


def summary(path: Path, found: list[dict]) -> dict:
    """The medians of one task's runs."""
    ok = [r for r in found if r["status"] == "succeeded"]
    per_motion = [1e3 * (r["planning_s"] + r["verify_s"]) / max(r["planned"], 1) for r in ok]
    return {
        "task": path.stem, "runs": len(found), "succeeded": len(ok),
        "makespan_s_median": round(statistics.median(r["makespan_s"] for r in ok), 3)
        if ok else None,
        "motions": ok[0]["motions"] if ok else None,
        "waits_median": statistics.median(r["waits"] for r in ok) if ok else None,
        "plan_ms_per_motion_median": round(statistics.median(per_motion), 2) if ok else None,
        "verify_ms_per_motion_median": round(statistics.median(
            1e3 * r["verify_s"] / max(r["planned"], 1) for r in ok), 2) if ok else None,
    }


def run_generated(seed: int, delays: int, runs_dir: Path, replans: bool = True) -> dict:
    """One mock run of generated two-arm task ``seed`` with the schedule's ``delays`` and
    ``replans``."""
    sys.path.insert(0, str(ROOT / "tests" / "scenarios"))
    from test_parallel_generated import generated_task

    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.tasks import load_task
    from taskrunner.tree.expect import arm_conflicts

    path = runs_dir / f"generated_{seed}.yaml"
    path.write_text(generated_task(seed), encoding="utf-8")
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    runner = Runner(spec, cell, MockBackend(names, dict(zip(names, cell.start_state()))),
                    InProcessPlanner(), RunOptions(seed=seed, runs_dir=runs_dir))
    runner.ctx.schedule.delays = delays
    runner.ctx.schedule.replans = replans
    record = runner.run()
    spans = [(float(e.data["start"]), float(e.data["start"])
              + float(e.data["trajectory"]["duration"]))
             for e in record.events if e.kind == "motion"]
    waits: dict[str, int] = {}
    for e in record.events:
        if e.kind == "wait" and "resolution" in e.data:
            waits[e.data["resolution"]] = waits.get(e.data["resolution"], 0) + 1
    contacts = (len(arm_conflicts(runner.scene.robot, record.events))
                if record.status == "succeeded" else 0)
    return {"status": record.status, "waits": waits, "contacts": contacts,
            "makespan_s": max(e for _, e in spans) - min(s for s, _ in spans) if spans else 0.0}


def bench_generated(count: int) -> dict:
    """The generated tasks with and without delays (module text)."""
    from taskrunner.tree.schedule import DELAYS

    modes = {"replans": (DELAYS, True), "delays": (DELAYS, False), "until_end": (1, False)}
    found: dict[str, list[dict]] = {mode: [] for mode in modes}
    with tempfile.TemporaryDirectory() as tmp:
        run_generated(0, DELAYS, Path(tmp))  # warm-up
        for seed in range(count):
            for mode, (delays, replans) in modes.items():
                found[mode].append(run_generated(seed, delays, Path(tmp), replans))
    out = {}
    for mode, runs in found.items():
        ok = [r["makespan_s"] for r in runs if r["status"] == "succeeded"]
        waits: dict[str, int] = {}
        for r in runs:
            for kind, n in r["waits"].items():
                waits[kind] = waits.get(kind, 0) + n
        out[mode] = {"runs": len(runs), "succeeded": len(ok),
                     "makespan_s_sum": round(sum(ok), 3),
                     "makespan_s_median": round(statistics.median(ok), 3) if ok else None,
                     "waits": waits, "contacts": sum(r["contacts"] for r in runs)}
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="runs of each task (3)")
    parser.add_argument("--seed", type=int, default=0, help="first planner seed (0)")
    parser.add_argument("--json", action="store_true", help="print one JSON line at the end")
    parser.add_argument("--pairs", default=None, metavar="NAME,...",
                        help="only these pairs (" + ", ".join(n for n, _, _ in PAIRS)
                        + "; default: all)")
    parser.add_argument("--generated", type=int, default=0, metavar="N",
                        help="also the first N generated two-arm tasks, with and without "
                             "delays (0)")
    args = parser.parse_args(argv)
    chosen = PAIRS
    if args.pairs is not None:
        names = [n.strip() for n in args.pairs.split(",") if n.strip()]
        unknown = sorted(set(names) - {n for n, _, _ in PAIRS})
        if unknown:
            parser.error(f"--pairs: no pair named {', '.join(unknown)} (known: "
                         f"{', '.join(n for n, _, _ in PAIRS)})")
        chosen = [p for p in PAIRS if p[0] in names]
    rows = []
    for name, parallel, sequential in chosen:
        par, seq = bench_pair(parallel, sequential, args.runs, args.seed)
        speedup = overhead = None
        if par["makespan_s_median"] and seq["makespan_s_median"]:
            speedup = round(seq["makespan_s_median"] / par["makespan_s_median"], 3)
        if par["plan_ms_per_motion_median"] and seq["plan_ms_per_motion_median"]:
            overhead = round(par["plan_ms_per_motion_median"]
                             / seq["plan_ms_per_motion_median"], 3)
        rows.append({"name": name, "parallel": par, "sequential": seq,
                     "speedup": speedup, "planning_overhead": overhead})
    print(f"{'task':<16} {'ok':>5} {'parallel s':>10} {'sequential s':>12} {'speed-up':>8} "
          f"{'waits':>5} {'plan+verify ms/motion':>21} {'single-arm ms':>13} {'overhead':>8}")
    for row in rows:
        par, seq = row["parallel"], row["sequential"]
        ok = f"{par['succeeded']}+{seq['succeeded']}/{2 * par['runs']}"
        print(f"{row['name']:<16} {ok:>5} {par['makespan_s_median'] or 0:>10.2f} "
              f"{seq['makespan_s_median'] or 0:>12.2f} {row['speedup'] or 0:>7.2f}x "
              f"{par['waits_median'] or 0:>5} "
              f"{par['plan_ms_per_motion_median'] or 0:>7.1f} "
              f"(verify {par['verify_ms_per_motion_median'] or 0:>4.1f}) "
              f"{seq['plan_ms_per_motion_median'] or 0:>13.1f} "
              f"{row['planning_overhead'] or 0:>7.2f}x")
    print(f"targets: speed-up >= {SPEEDUP_TARGET}x on tray_pair and assembly_panda; planning "
          f"per motion <= {OVERHEAD_TARGET}x a single-arm plan")
    generated = bench_generated(args.generated) if args.generated > 0 else None
    if generated is not None:
        print(f"\ngenerated two-arm tasks (seeds 0-{args.generated - 1}):")
        print(f"{'schedule':<10} {'ok':>7} {'makespan sum s':>14} {'median s':>8} "
              f"{'waits':<24} {'contacts':>8}")
        for mode, g in generated.items():
            waits = ", ".join(f"{k} {v}" for k, v in sorted(g["waits"].items())) or "-"
            print(f"{mode:<10} {g['succeeded']:>3}/{g['runs']:<3} {g['makespan_s_sum']:>14.2f} "
                  f"{g['makespan_s_median'] or 0:>8.2f} {waits:<24} {g['contacts']:>8}")
    if args.json:
        print(json.dumps({"seed": args.seed, "runs": args.runs, "pairs": rows,
                          "generated": generated}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
