"""Serial vs process-pool time of a pick_place sweep (``run-task sweep``'s machinery).

Runs the sweep ``place_y=-0.15:0.15:COUNT`` x seeds ``0..SEEDS-1`` of the shipped
``pick_place`` on the mock backend twice: one case after another in this process
(``jobs=1``), then in a process pool of ``--jobs`` workers (default: every core), and
checks that both give the same verdicts. Prints a table, then one JSON line.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time

from taskrunner import resources
from taskrunner.runtime.sweep import SweepReport, parse_axis, sweep_cases
from taskrunner.runtime.testing import run_cases


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=31, help="place_y values (31)")
    parser.add_argument("--seeds", type=int, default=3, help="seeds per value (3)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="pool workers (every core)")
    args = parser.parse_args()
    path = resources.resolve_task("pick_place")
    axis = parse_axis(f"place_y=-0.15:0.15:{args.count}", {"place_y": "float"})
    cases = sweep_cases(path, "pick_place", [axis], args.seeds, ["mock"], None)
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    serial = run_cases(cases, jobs=1)
    serial_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    pool = run_cases(cases, jobs=args.jobs)
    pool_s = time.perf_counter() - t0
    same = [(r.verdict, r.status) for r in serial] == [(r.verdict, r.status) for r in pool]
    report = SweepReport("pick_place", ((axis[0], tuple(axis[1])),), tuple(pool), pool_s)
    passed = sum(r.passed for r in pool)
    print(f"pick_place sweep: {len(cases)} runs (place_y x {args.count}, seeds "
          f"x {args.seeds}, mock); {os.cpu_count()} cores, load {load:.1f} at start")
    print(f"{'mode':<22}{'wall s':>9}{'per run s':>11}")
    print(f"{'serial (jobs=1)':<22}{serial_s:>9.1f}{serial_s / len(cases):>11.2f}")
    print(f"{f'pool (jobs={args.jobs})':<22}{pool_s:>9.1f}{pool_s / len(cases):>11.2f}")
    print(f"speed-up {serial_s / pool_s:.2f}x; {passed}/{len(cases)} passed; same verdicts: "
          f"{same}; success by place_y: "
          + " ".join(f"{v:+.3f}:{p}/{n}" for v, p, n in report.rates("place_y")))
    print(json.dumps({"runs": len(cases), "jobs": args.jobs, "serial_s": round(serial_s, 2),
                      "pool_s": round(pool_s, 2), "speedup": round(serial_s / pool_s, 3),
                      "passed": passed, "same_verdicts": same, "load_at_start": round(load, 2),
                      "cores": os.cpu_count(), "python": platform.python_version()}))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
