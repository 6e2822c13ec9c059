"""Two servo arms hand a bar over (seed 004's exercise), scripted from Python.

On the shipped ``servo_arm_pair`` cell (two arms facing each other, ``left_`` and
``right_``): the left arm picks an upright bar and holds it out at its ``HandOff`` pose,
the right arm takes the bar's lower end, the left arm goes back to ``Candle``, the right
arm lays the bar on its side on the table. Both arms move together where a ``Parallel``
says so, planned as one motion so that they cannot collide. The run's events are read
as an iterator while it runs.

    python examples/handoff.py                   # mock backend
    python examples/handoff.py --backend sim     # simulated controller, 20x real time

Exits 0 when the bar lies where it should, 1 otherwise.
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import taskrunner
from taskrunner import Go, Handoff, Object, Parallel, Pick, Place, Task

TABLE_TOP = 0.75  # m: the table's surface in the world frame of servo_arm_pair
BAR = (0.025, 0.025, 0.08)  # m: the bar's size; it stands on its small face


def build_task(bar_x: float, drop_x: float) -> Task:
    """Hand a bar standing at ``bar_x`` from the left arm to the right arm, which lays it
    down along the world x axis with its centre at ``drop_x`` (m, world frame)."""
    both_to_candle = Parallel(Go("left_arm", "Candle"), Go("right_arm", "Candle"))
    lying = {"xyz": (drop_x, 0.0, TABLE_TOP + BAR[0] / 2 + 0.001),  # 1 mm above the table
             "rpy": (0.0, math.pi / 2, 0.0)}  # the bar's long axis (its z) along world x
    return Task(
        "python_handoff",
        description="The left arm hands a bar to the right arm, which lays it down.",
        objects=[Object("bar", "box", size=BAR, at=(bar_x, 0.0, TABLE_TOP + BAR[2] / 2))],
        steps=[
            both_to_candle,
            Pick("left_arm", "bar", grasp="top", approach=0.05, retreat=0.04),
            Handoff("bar", "left_arm", "right_arm", at="HandOff", approach=0.04, retreat=0.04),
            Go("left_arm", "Candle"),
            Place("right_arm", "bar", at=lying, approach=0.03, retreat=0.04),
            both_to_candle,
        ],
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backend", choices=["mock", "sim"], default="mock",
                        help="execution backend (default: mock)")
    parser.add_argument("--speed", type=float, default=20.0,
                        help="sim: replay speed, a multiple of real time (default 20)")
    parser.add_argument("--bar-x", type=float, default=-0.10,
                        help="x of the standing bar (m, world), in front of the left arm")
    parser.add_argument("--drop-x", type=float, default=0.08,
                        help="x of the laid-down bar's centre (m, world)")
    parser.add_argument("--seed", type=int, default=0, help="planner seed (default 0)")
    args = parser.parse_args(argv)

    started = time.perf_counter()
    with taskrunner.load_workcell("servo_arm_pair") as cell:
        cell.connect(args.backend, speed=args.speed if args.backend == "sim" else None)
        run = cell.start_task(build_task(args.bar_x, args.drop_x), seed=args.seed)
        motion = 0.0
        for event in run.events(timeout=120):
            if event.kind == "planned":
                motion += event.data.get("duration", 0.0)
            elif event.kind == "node_finished":
                # event.location is the line of this script where the step was built.
                line = (event.location or "").rsplit(":", 1)[-1]
                mark = "ok  " if event.status == "SUCCESS" else "FAIL"
                tail = f": {event.message}" if event.status == "FAILURE" else ""
                print(f"{event.time:7.2f} s  {mark} line {line:>3}  {event.node}{tail}")
        result = run.wait()
        print(f"\n{result.task}: {result.status} in {result.duration:.2f} s "
              f"({len(result.events)} events, {motion:.1f} s of motion)")
        if not result.ok:
            print(f"  {result.error}", file=sys.stderr)
            return 1
        state = cell.joint_state().as_dict()
        candle = cell.model.named_state("both_arms", "Candle").as_dict()
        error = max(abs(state[name] - value) for name, value in candle.items())
        print(f"both arms back at Candle (joint error {error:.1e} rad)")
        if error > 1e-3:
            print("  the arms did not end at Candle", file=sys.stderr)
            return 1
    print(f"done in {time.perf_counter() - started:.1f} s wall ({args.backend} backend)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
