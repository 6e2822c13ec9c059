"""First compilation of the compiled collision kernels, on a fresh numba cache.

Each run is a fresh process with ``NUMBA_CACHE_DIR`` pointing at a new empty folder: it
builds the servo arm's scene, then times (process CPU and wall) the path verifier's build
and first verification (the kernels both compile, and numba's one-time set-up of its
compiler) and the state screen's first scans (every scan kernel), one after the other in
that process, as :func:`taskrunner.scene.screen.warm_kernels`
would without its second process. Then the same again with the cache filled (loads).

    python benchmarks/kernel_compile.py [--runs 1] [--json] [--coal]

``--coal`` adds what planning beside the compilation costs: the recorded paths of
``tests/scene/collision_verdicts.json`` (MoveIt problem sets of every class and a servo arm
cell) verified by the compiled verifier and by the one with coal alone
(:mod:`taskrunner.scene.coalpath`, what a planner uses while the kernels compile), with
their verdicts compared, in this process (the kernels loaded from the cache first).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

_CHILD = """
import json, time
import numpy as np
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import load_robot
from taskrunner.scene import Scene
from taskrunner.scene.screen import StateScreen, _scan_both
scene = Scene(load_robot(DATA_ROOT / "robots" / "servo_arm"))
q = scene.state
robot = scene.robot
states = np.ascontiguousarray(np.stack([q, np.clip(q + 1e-3, robot.lower, robot.upper)]))
c0, w0 = time.process_time(), time.perf_counter()
verifier = scene.path_verifier()
verifier.verify(states)
c1, w1 = time.process_time(), time.perf_counter()
_scan_both(StateScreen(verifier), states)
c2, w2 = time.process_time(), time.perf_counter()
print(json.dumps({"verifier_cpu_s": c1 - c0, "verifier_wall_s": w1 - w0,
                  "screen_cpu_s": c2 - c1, "screen_wall_s": w2 - w1}))
"""


def measure(runs: int) -> list[dict]:
    out = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as cache:
            env = dict(os.environ, NUMBA_CACHE_DIR=cache)
            row = {}
            for label in ("cold", "warm"):
                done = subprocess.run([sys.executable, "-c", _CHILD], env=env, check=True,
                                      capture_output=True, text=True)
                row[label] = json.loads(done.stdout.strip().splitlines()[-1])
            out.append(row)
    return out


def measure_coal() -> dict:
    """Both verifiers on the recorded paths: total seconds, coal distances, verdicts."""
    import numpy as np

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "scene"))
    from verdict_cases import FIXTURE, MARGIN, build_scene

    from taskrunner.scene.coalpath import CoalPathVerifier

    cases = json.loads(FIXTURE.read_text())["cases"]
    totals = {"paths": 0, "compiled_s": 0.0, "coal_s": 0.0, "compiled_queries": 0,
              "coal_queries": 0, "same_verdicts": 0}
    for case in cases:
        scene = build_scene(case)
        compiled = scene.path_verifier(MARGIN)
        compiled.verify(np.ascontiguousarray(case["start"], dtype=float))  # loaded
        coal = CoalPathVerifier(scene.robot, scene.checker, MARGIN)
        for path in case["paths"]:
            states = np.ascontiguousarray(path, dtype=float)
            t0 = time.perf_counter()
            a = compiled.verify(states)
            t1 = time.perf_counter()
            b = coal.verify(states)
            t2 = time.perf_counter()
            totals["paths"] += 1
            totals["compiled_s"] += t1 - t0
            totals["coal_s"] += t2 - t1
            totals["compiled_queries"] += a.distance_queries
            totals["coal_queries"] += b.distance_queries
            totals["same_verdicts"] += int(a.valid == b.valid)
    return totals


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--coal", action="store_true",
                        help="also time the verifier with coal alone on the recorded paths")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    rows = measure(args.runs)
    coal = measure_coal() if args.coal else None
    print(f"load average {load:.1f} at start, {os.getloadavg()[0]:.1f} at end")
    for row in rows:
        for label, r in row.items():
            print(f"{label}: verifier {r['verifier_cpu_s']:.2f} s CPU ({r['verifier_wall_s']:.2f} "
                  f"wall), screen {r['screen_cpu_s']:.2f} s CPU ({r['screen_wall_s']:.2f} wall), "
                  f"total {r['verifier_cpu_s'] + r['screen_cpu_s']:.2f} s CPU")
    if coal is not None:
        print(f"recorded paths ({coal['paths']}): compiled {coal['compiled_s']:.3f} s "
              f"({coal['compiled_queries']} coal distances), coal alone {coal['coal_s']:.3f} s "
              f"({coal['coal_queries']} coal distances); same verdict on "
              f"{coal['same_verdicts']} of {coal['paths']}")
    if args.json:
        print(json.dumps({"runs": rows, "load": load, "coal": coal}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
