"""Kinematics benchmark: collision checking and IK for the Panda, the UR5 and the servo arm.

    python benchmarks/kinematics.py [--quick] [--json] [--seed N]

Prints a readable table, then (with --json) one JSON object as the last line with at least
``panda_collision_us_median``, ``panda_ik_success``, ``panda_ik_ms_mean``,
``ur5_ik_success``, ``ur5_ik_ms_mean``, ``arm5_ik_position_success`` and
``arm5_ik_position_ms_mean``. Everything is seeded; --quick runs smaller counts.

IK follows TRAC-IK's protocol (see ik_bench.py): 2000 random joint configurations within
the limits (150 with --quick), their FK as targets, a 5 ms timeout, the seed at
mid-range, tolerance 1e-5 m and 1e-5 rad, mean over all calls. The collision check is
the Panda in a table-and-shelf scene (five boxes), self + world, on random states.
Targets on the 2-core reference machine: collision ≤ 25 µs median; Panda and UR5 IK
≥ 99.8 % at ≤ 0.35 ms mean (TRAC-IK publishes 99.88 % at 0.37 ms); servo arm
position-only ≥ 99.5 % at ≤ 0.3 ms mean.
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import collision_bench
import ik_bench

TARGETS = {
    "panda_collision_us_median": ("<=", 25.0),
    "panda_ik_success": (">=", 0.998),
    "panda_ik_ms_mean": ("<=", 0.35),
    "ur5_ik_success": (">=", 0.998),
    "ur5_ik_ms_mean": ("<=", 0.35),
    "arm5_ik_position_success": (">=", 0.995),
    "arm5_ik_position_ms_mean": ("<=", 0.3),
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller counts")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)

    started = time.perf_counter()
    collision = collision_bench.run(args.quick, args.seed)
    ik = ik_bench.run(args.quick, args.seed)
    rows = collision_bench.rows(collision) + ik_bench.rows(ik)
    width = max(len(what) for what, _ in rows)
    print(f"{'what':<{width}}  figure")
    for what, figure in rows:
        print(f"{what:<{width}}  {figure}")
    result = {k: v for k, v in collision.items() if not isinstance(v, dict)}
    result.update(ik)
    print()
    for key, (op, limit) in TARGETS.items():
        value = result[key]
        met = value <= limit if op == "<=" else value >= limit
        print(f"target {key} {op} {limit}: {value:.4g} {'met' if met else 'MISSED'}")
    result["quick"] = args.quick
    result["seed"] = args.seed
    result["python"] = platform.python_version()
    result["seconds"] = round(time.perf_counter() - started, 1)
    if args.json:
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
