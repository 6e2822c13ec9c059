"""Pick and place with the servo arm, scripted from Python (seed 001's exercise).

The task is built from step objects (the Python form of a task file's steps), checked
against the shipped ``servo_arm_table`` cell and run on a backend; every event of the run
is printed as it happens. Then the arm is moved once more the MoveIt Commander way: plan
to a named pose, execute, read the joint state.

    python examples/pick_place.py                      # mock backend: motions complete at once
    python examples/pick_place.py --backend sim        # simulated controller, 20x real time
    python examples/pick_place.py --place-y -0.08      # another drop spot (m, world y)

Exits 0 when the cube was placed, 1 otherwise.
"""

from __future__ import annotations

import argparse
import sys
import time

import taskrunner
from taskrunner import Go, Gripper, Object, Pick, Place, RunEvent, Task

TABLE_TOP = 0.75  # m: the table's surface in the world frame of servo_arm_table
CUBE = 0.025  # m: edge of the cube


def build_task(pick_xy: tuple[float, float], place_xy: tuple[float, float]) -> Task:
    """Pick a cube from ``pick_xy`` and put it down at ``place_xy`` (m, world frame)."""
    cube_z = TABLE_TOP + CUBE / 2
    return Task(
        "python_pick_place",
        description="Pick a 2.5 cm cube and place it elsewhere on the table.",
        objects=[Object("cube", "box", size=(CUBE, CUBE, CUBE), at=(*pick_xy, cube_z))],
        steps=[
            Gripper("arm", "open"),
            Go("arm", "home"),
            Pick("arm", "cube", grasp="top", approach=0.04, retreat=0.05),
            # 1 mm above the table: the cube is released just before it touches.
            Place("arm", "cube", at=(*place_xy, cube_z + 0.001), approach=0.04, retreat=0.05),
            Go("arm", "home"),
        ],
    )


def show(event: RunEvent) -> None:
    """Print the events worth a line: steps starting and ending, motions planned."""
    if event.kind == "node_finished":
        mark = {"SUCCESS": "ok  ", "FAILURE": "FAIL"}.get(event.status or "", "--  ")
        tail = f": {event.message}" if event.status == "FAILURE" else ""
        print(f"{event.time:7.2f} s  {mark} {event.node}{tail}")
    elif event.kind == "planned":
        print(f"{event.time:7.2f} s         planned: {event.message}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backend", choices=["mock", "sim"], default="mock",
                        help="execution backend (default: mock)")
    parser.add_argument("--speed", type=float, default=20.0,
                        help="sim: replay speed, a multiple of real time (default 20)")
    parser.add_argument("--pick-x", type=float, default=0.19, help="cube x (m, world)")
    parser.add_argument("--pick-y", type=float, default=0.04, help="cube y (m, world)")
    parser.add_argument("--place-x", type=float, default=0.14, help="drop spot x (m, world)")
    parser.add_argument("--place-y", type=float, default=-0.12, help="drop spot y (m, world)")
    parser.add_argument("--seed", type=int, default=0, help="planner seed (default 0)")
    args = parser.parse_args(argv)

    started = time.perf_counter()
    with taskrunner.load_workcell("servo_arm_table") as cell:
        cell.connect(args.backend, speed=args.speed if args.backend == "sim" else None)
        task = build_task((args.pick_x, args.pick_y), (args.place_x, args.place_y))
        result = cell.run_task(task, seed=args.seed, on_event=show)
        print(f"\n{result.task}: {result.status} in {result.duration:.2f} s "
              f"({len(result.events)} events)")
        if not result.ok:
            print(f"  {result.error}", file=sys.stderr)
            return 1

        # The same arm, MoveIt Commander style: plan to a named pose, execute, read back.
        plan = cell.plan("arm", to="ready", seed=args.seed)
        cell.execute(plan)
        reached = cell.joint_state().as_dict()
        wanted = dict(zip(plan.path.names, plan.path.waypoints[-1]))
        error = max(abs(reached[name] - value) for name, value in wanted.items())
        print(f"go ready: a {plan.duration:.2f} s motion planned in {plan.planning_time:.2f} s; "
              f"joint error after execution {error:.1e} rad")
        if error > 1e-3:
            print("  the arm did not reach 'ready'", file=sys.stderr)
            return 1
    print(f"done in {time.perf_counter() - started:.1f} s wall ({args.backend} backend)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
