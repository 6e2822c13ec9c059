"""What each collision geometry choice costs per state check, and what it changes.

    python benchmarks/collision_geometry.py [--robot ur5] [--states N] [--seed S] [--json]

The robot (a shipped name or a path) stands on a table with a wall in front of it; every
choice (exact meshes, convex hulls, auto) checks the same seeded random states, the
choices interleaved state by state so machine load hits them alike. Prints the median and
p95 check time, the share of states in collision, how many states collide as hulls but
not as meshes, and which links ``auto`` gave hulls.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np

from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import Scene, SceneOptions
from taskrunner.scene.linkgeometry import HULL
from taskrunner.shapes import Box
from taskrunner.types import Pose

CHOICES = ("exact", "convex", "auto")


def run(robot: str, states: int, seed: int) -> dict[str, object]:
    model = load_cell_or_robot(resolve_cell(robot)).model
    rng = np.random.default_rng(seed)
    qs = [model.random_state(rng) for _ in range(states)]
    scenes = {}
    for choice in CHOICES:
        scene = Scene(model, SceneOptions(collision=choice))
        scene.add_object("table", Box((1.2, 1.2, 0.04)), Pose((0.3, 0.0, -0.03)))
        scene.add_object("wall", Box((0.02, 1.0, 1.0)), Pose((0.6, 0.0, 0.5)))
        scene.checker  # noqa: B018 - built before timing
        scenes[choice] = scene
    times: dict[str, list[float]] = {c: [] for c in CHOICES}
    hits: dict[str, list[bool]] = {c: [] for c in CHOICES}
    for q in qs:
        for choice, scene in scenes.items():
            started = time.perf_counter()
            hit = scene.in_collision(q)
            times[choice].append(time.perf_counter() - started)
            hits[choice].append(hit)
    exact, convex = np.array(hits["exact"]), np.array(hits["convex"])
    plan = scenes["auto"].link_geometry
    return {
        "robot": robot, "states": states, "seed": seed,
        **{f"{c}_us_median": float(np.median(times[c]) * 1e6) for c in CHOICES},
        **{f"{c}_us_p95": float(np.percentile(times[c], 95) * 1e6) for c in CHOICES},
        **{f"{c}_in_collision": float(np.mean(hits[c])) for c in CHOICES},
        "hull_only_collisions": int(np.sum(convex & ~exact)),
        "auto_hull_links": sorted(c.link for c in plan.links.values() if c.kind == HULL),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--robot", default="ur5", help="shipped name or path (ur5)")
    parser.add_argument("--states", type=int, default=2000, help="random states (2000)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    args = parser.parse_args(argv)
    result = run(args.robot, args.states, args.seed)
    print(f"{'choice':<7}  median µs  p95 µs  in collision")
    for choice in CHOICES:
        print(f"{choice:<7}  {result[f'{choice}_us_median']:9.1f}  {result[f'{choice}_us_p95']:6.1f}"
              f"  {100 * result[f'{choice}_in_collision']:11.1f} %")  # type: ignore[operator]
    print(f"states colliding as hulls but not as meshes: {result['hull_only_collisions']} of "
          f"{args.states}; auto's hull links: {', '.join(result['auto_hull_links']) or 'none'}"  # type: ignore[arg-type]
          f" (load average {os.getloadavg()[0]:.1f})")
    if args.json:
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
