"""Load benchmark: a cold load of two-arm cells and MoveIt config packages.

    python benchmarks/loading.py [--runs N] [--json] [--profile NAME]

Each run is a fresh Python process that first imports what loading uses (timed apart),
then loads the configuration (``load_cell_or_robot``: files read, xacro expanded, model
built, self-collision checked) and builds its planning scene (link geometry chosen,
hulls, the collision checker) -- the "load" time. Every configuration is measured with
the hull-measurement cache warm (the usual case: a robot loaded before on this machine)
and cold (an empty cache folder: the first load ever). Medians over ``--runs`` processes.

Target (2-core reference machine): a two-arm config loads in at most 0.5 s cold, imports
excluded. ``--profile NAME`` prints the top of a cProfile of one cold load instead.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "tests" / "robot" / "fixtures" / "moveit" / "src"
CONFIGS = {
    "servo_arm_pair": "servo_arm_pair",
    "panda_pair": "panda_pair",
    "ur5": "ur5",
    "arm3_moveit_config (ROS 2, xacro)": str(FIXTURES / "arm3_moveit_config"),
    "arm3_ros2_moveit_config": str(FIXTURES / "arm3_ros2_moveit_config"),
    "arm3_ros1_moveit_config": str(FIXTURES / "arm3_ros1_moveit_config"),
}
TWO_ARM = ("servo_arm_pair", "panda_pair")
TARGET_S = 0.5

_CHILD = r"""
import json, sys, time
t0 = time.perf_counter()
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import scene_from_cell
import taskrunner.scene.linkgeometry, taskrunner.scene.hullfit, xacro  # noqa: F401
t1 = time.perf_counter()
cell = load_cell_or_robot(resolve_cell(sys.argv[1]))
t2 = time.perf_counter()
scene = scene_from_cell(cell)
scene.checker
t3 = time.perf_counter()
print(json.dumps({"imports": t1 - t0, "model": t2 - t1, "scene": t3 - t2, "load": t3 - t1}))
"""

_PROFILE = r"""
import cProfile, pstats, sys
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import scene_from_cell
import taskrunner.scene.linkgeometry, taskrunner.scene.hullfit, xacro  # noqa: F401
profile = cProfile.Profile()
profile.enable()
scene_from_cell(load_cell_or_robot(resolve_cell(sys.argv[1]))).checker
profile.disable()
pstats.Stats(profile).sort_stats("cumulative").print_stats(30)
"""


def _run(code: str, source: str, cache: str | None) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ)
    env.pop("TASKRUNNER_COLLISION", None)
    if cache is not None:
        env["XDG_CACHE_HOME"] = cache
    done = subprocess.run([sys.executable, "-c", code, source], capture_output=True, text=True,
                          env=env, cwd=ROOT, check=False)
    if done.returncode != 0:
        raise SystemExit(f"loading {source} failed:\n{done.stderr[-2000:]}")
    return done


def measure(source: str, runs: int) -> dict[str, float]:
    """Medians (s) of ``runs`` warm-cache and ``runs`` cold-cache fresh processes."""
    warm: list[dict[str, float]] = []
    cold: list[dict[str, float]] = []
    _run(_CHILD, source, None)  # fill the user's cache: the warm case
    for _ in range(runs):  # interleaved, so machine load affects both alike
        warm.append(json.loads(_run(_CHILD, source, None).stdout.strip().splitlines()[-1]))
        with tempfile.TemporaryDirectory() as empty:
            cold.append(json.loads(_run(_CHILD, source, empty).stdout.strip().splitlines()[-1]))

    def median(rows: list[dict[str, float]], key: str) -> float:
        return statistics.median(r[key] for r in rows)

    return {
        "imports_s": median(warm, "imports"),
        "model_s": median(warm, "model"),
        "scene_s": median(warm, "scene"),
        "load_s": median(warm, "load"),
        "cold_cache_load_s": median(cold, "load"),
        "cold_cache_scene_s": median(cold, "scene"),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="fresh processes per case (5)")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    parser.add_argument("--profile", metavar="NAME", choices=sorted(CONFIGS),
                        help="print a cProfile of one cold load of NAME instead")
    args = parser.parse_args(argv)
    if args.profile:
        with tempfile.TemporaryDirectory() as empty:
            print(_run(_PROFILE, CONFIGS[args.profile], empty).stdout)
        return 0
    started = time.perf_counter()
    results = {name: measure(source, args.runs) for name, source in CONFIGS.items()}
    width = max(map(len, results))
    print(f"{'config':<{width}}  imports  model  scene  load (warm cache)  load (cold cache)")
    for name, r in results.items():
        print(f"{name:<{width}}  {r['imports_s']:7.2f}  {r['model_s']:5.3f}  {r['scene_s']:5.3f}  "
              f"{r['load_s']:17.3f}  {r['cold_cache_load_s']:17.3f}")
    worst = max(max(results[n]["load_s"], results[n]["cold_cache_load_s"]) for n in TWO_ARM)
    verdict = "met" if worst <= TARGET_S else "MISSED"
    print(f"\ntwo-arm load, worst of warm/cold cache medians: {worst:.3f} s "
          f"(target <= {TARGET_S} s): {verdict}")
    print(f"({args.runs} runs each, {time.perf_counter() - started:.0f} s, "
          f"{platform.node()}, load average {os.getloadavg()[0]:.1f})")
    if args.json:
        print(json.dumps({"configs": results, "two_arm_worst_load_s": worst,
                          "target_s": TARGET_S, "met": worst <= TARGET_S, "runs": args.runs}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
