"""Hashes of every trajectory sample the example tasks send to the mock backend.

Runs every shipped example task (``taskrunner/data/tasks/*.yaml``) on the mock backend
(seed 0, replay speed 1000) and hashes each trajectory the backend is asked to execute
(joint names, times, positions, velocities, accelerations: the float64 bytes), so that a
change meant to be a pure refactoring of the planning and collision code can be checked
bit for bit: record before, compare after.

    python benchmarks/trajectory_hashes.py --out before.json
    python benchmarks/trajectory_hashes.py --compare before.json   # exit 1 on a difference

Two arms' branches send their motions from their own threads, so a task's trajectories
may arrive in another order: that is reported, and is not a difference.

The hash is taken by wrapping the execute method of this process's backend classes
(ours) for the duration of the script.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from pathlib import Path
from typing import Any

import numpy as np

import taskrunner.backends.base as base
from taskrunner.resources import DATA_ROOT
from taskrunner.workcell import run_task


def record() -> dict[str, Any]:
    digests: list[str] = []
    classes = [c for c in vars(base).values() if isinstance(c, type) and "execute" in vars(c)
               and c.__name__ != "Backend"]

    def wrapped(original: Any) -> Any:
        def execute(self: Any, trajectory: Any) -> Any:
            digest = hashlib.sha256(repr(trajectory.names).encode())
            for values in (trajectory.times, trajectory.positions, trajectory.velocities,
                           trajectory.accelerations):
                digest.update(np.ascontiguousarray(values, dtype=float).tobytes())
            digests.append(digest.hexdigest()[:16])
            return original(self, trajectory)
        return execute

    originals = {c: c.execute for c in classes}
    out: dict[str, Any] = {}
    try:
        for c in classes:
            c.execute = wrapped(c.execute)
        for task in sorted(p.stem for p in (DATA_ROOT / "tasks").glob("*.yaml")):
            digests.clear()
            result = run_task(task, backend="mock", speed=1000.0, seed=0)
            out[task] = {"status": str(result.status), "trajectories": list(digests)}
    finally:
        for c, original in originals.items():
            c.execute = original
    return out


def compare(before: dict[str, Any], after: dict[str, Any]) -> tuple[list[str], list[str]]:
    """Tasks whose trajectories differ, and tasks with the same trajectories in another order."""
    differ: list[str] = []
    reordered: list[str] = []
    for task in sorted(set(before) | set(after)):
        old, new = before.get(task), after.get(task)
        if old == new:
            continue
        if (old is not None and new is not None and old["status"] == new["status"]
                and sorted(old["trajectories"]) == sorted(new["trajectories"])):
            reordered.append(task)
        else:
            differ.append(task)
    return differ, reordered


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, help="write the hashes here")
    parser.add_argument("--compare", type=Path, help="compare with hashes written before")
    args = parser.parse_args(argv)
    hashes = record()
    for task, row in hashes.items():
        print(f"{task:20s} {row['status']:10s} {len(row['trajectories']):3d} trajectories")
    if args.out:
        args.out.write_text(json.dumps(hashes, indent=1) + "\n")
    if args.compare:
        before = json.loads(args.compare.read_text())
        differ, reordered = compare(before, hashes)
        if reordered:
            # Branches of a `parallel` send their motions from their own threads, so the
            # order in which the backend receives them can change run to run while every
            # trajectory stays the same.
            print(f"same trajectories, received in another order: {', '.join(reordered)}")
        print("bit-identical" if not differ else f"differ: {', '.join(differ)}")
        return 1 if differ else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
