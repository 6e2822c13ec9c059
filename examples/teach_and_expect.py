"""Teach a pose from Python, then run a task that goes there and checks where it ended.

The arm is moved MoveIt Commander style (``go``: plan and execute), the pose it reached is
taught (stored in a data folder's database, where ``run-task --data-dir`` and
``run-task serve`` find it too), and a task built from step objects uses the taught pose
by name, with ``Expect`` checks after a step and at the task's end.

    python examples/teach_and_expect.py                  # mock backend, a temporary data folder
    python examples/teach_and_expect.py --data-dir state # keep the taught pose there

Exits 0 when every expectation held, 1 otherwise.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time

import taskrunner
from taskrunner import BackendKind, Expect, Go, Gripper, Task


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data-dir", default=None,
                        help="the data folder the pose is taught into (default: a temporary one)")
    parser.add_argument("--seed", type=int, default=0, help="planner seed (default 0)")
    args = parser.parse_args(argv)
    data_dir = args.data_dir or tempfile.mkdtemp(prefix="taskrunner-teach-")

    started = time.perf_counter()
    with taskrunner.load_workcell("servo_arm_table") as cell:
        backend: taskrunner.Backend = cell.connect(BackendKind.MOCK)
        plan = cell.go("arm", joints={"Revolute 1": 0.5}, seed=args.seed)  # plan + execute
        print(f"go: a {plan.duration:.2f} s motion; {len(backend.joint_names)} joints driven")
        pose = cell.teach("arm", "side", data_dir=data_dir)  # the arm's joints, now
        print(f"taught {pose.group}/{pose.name} in {data_dir}: "
              + ", ".join(f"{j}={v:.3f}" for j, v in pose.joints.items()))
        cell.go("arm", to="home", seed=args.seed)

        task = Task("visit_side", steps=[
            Gripper("arm", "open"),
            Go("arm", "side"),                                  # the taught pose, by name
            Expect(groups={"arm": {"at": "side"}}, step_duration=10),
            Go("arm", "home"),
        ], expect=Expect(groups={"arm": {"at": "home"}}, duration={"max": 60}))
        result = cell.run_task(task, seed=args.seed)
        print(f"{result.task}: {result.status} in {result.duration:.2f} s "
              f"({len(result.events)} events)")
        if not result.ok:
            print(f"  {result.error}", file=sys.stderr)
            return 1
    print(f"done in {time.perf_counter() - started:.1f} s wall")
    return 0


if __name__ == "__main__":
    sys.exit(main())
