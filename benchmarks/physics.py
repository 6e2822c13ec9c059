"""Real-time factor of the mujoco (physics) backend on shipped tasks.

For each task: the whole run (planning, behaviour tree, physics) on the mujoco backend
as fast as it steps, ``repeats`` times; figures are medians. ``rtf_run`` is physics time
over the run's wall time; ``rtf_physics`` is physics time over the wall time spent
stepping it (what the simulation alone costs). Also the model's conversion and compile
time (cache cold and warm), where each task's objects ended, and the size of the run's
``physics`` events (joints and objects at 25 Hz) in its record.

    python benchmarks/physics.py            # table
    python benchmarks/physics.py --json     # JSON
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import tempfile
import time

TASKS = {"handoff": 5.0, "pick_place_panda": 2.0, "pick_place": None, "stack": None,
         "handoff_panda": None}  # target rtf_run


def run_once(task: str, cache: str) -> dict[str, float | str]:
    from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.resources import resolve_task
    from taskrunner.robot.cell import load_cell
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.tasks.loader import load_task

    spec = load_task(resolve_task(task), {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=cache))
    try:
        runner = Runner(spec, cell, backend, InProcessPlanner(), RunOptions(seed=0))
        started = time.perf_counter()
        record = runner.run()
        wall = time.perf_counter() - started
        physics = [e.as_dict() for e in record.events if e.kind == "physics"]
        return {"physics_kb": len(json.dumps(physics)) / 1e3,"status": record.status, "sim_s": backend.sim_time, "wall_s": wall,
                "step_s": backend.step_seconds, "build_s": backend.build_seconds,
                "cache_hit": backend.cache_hit,
                "objects": {k: [round(v, 4) for v in p.xyz]
                            for k, p in backend.object_poses().items()}}
    finally:
        backend.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    import os

    import mujoco

    load_before = os.getloadavg()[0]
    results = {}
    with tempfile.TemporaryDirectory() as cache:
        for task, target in TASKS.items():
            runs = [run_once(task, cache) for _ in range(args.repeats)]
            sims = [float(r["sim_s"]) for r in runs]
            results[task] = {
                "status": sorted({str(r["status"]) for r in runs}),
                "sim_s": statistics.median(sims),
                "same_physics_every_run": max(sims) - min(sims) < 1e-9,
                "rtf_run": statistics.median(float(r["sim_s"]) / float(r["wall_s"]) for r in runs),
                "rtf_physics": statistics.median(float(r["sim_s"]) / float(r["step_s"])
                                                 for r in runs),
                "build_cold_s": float(runs[0]["build_s"]),
                "build_warm_s": statistics.median(float(r["build_s"]) for r in runs[1:]) if
                len(runs) > 1 else None,
                "objects": runs[-1]["objects"],
                "physics_record_kb": float(runs[-1]["physics_kb"]),
                "target_rtf_run": target,
            }
    meta = {"machine": f"{platform.machine()} {platform.processor() or ''}".strip(),
            "python": platform.python_version(), "mujoco": mujoco.__version__,
            "date": time.strftime("%Y-%m-%d"), "cores": os.cpu_count(),
            "load_1min": [round(load_before, 2), round(os.getloadavg()[0], 2)]}
    if args.json:
        print(json.dumps({"meta": meta, "results": results}, indent=2))
        return
    print(meta)
    print(f"{'task':18} {'status':12} {'physics s':>9} {'rtf run':>8} {'rtf physics':>11} "
          f"{'build cold/warm ms':>19} {'record kB':>9}  target")
    for task, r in results.items():
        warm = "-" if r["build_warm_s"] is None else f"{1e3 * r['build_warm_s']:.0f}"
        target = f"≥ {r['target_rtf_run']:g}x" if r["target_rtf_run"] else ""
        print(f"{task:18} {','.join(r['status']):12} {r['sim_s']:9.2f} {r['rtf_run']:8.1f} "
              f"{r['rtf_physics']:11.1f} {1e3 * r['build_cold_s']:>12.0f}/{warm:<6} "
              f"{r['physics_record_kb']:9.0f}  {target}")


if __name__ == "__main__":
    main()
