"""First compilation of the compiled collision kernels, on a fresh numba cache.

Each run is a fresh process with ``NUMBA_CACHE_DIR`` pointing at a new empty folder: it
builds the servo arm's scene, then times (process CPU and wall) the path verifier's first
verification (compiles its kernels) and the state screen's first scans (every scan
kernel), one after the other in that process, as :func:`taskrunner.scene.screen.warm_kernels`
would without its second process. Then the same again with the cache filled (loads).

    python benchmarks/kernel_compile.py [--runs 1] [--json]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

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
verifier = scene.path_verifier()
c0, w0 = time.process_time(), time.perf_counter()
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


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    rows = measure(args.runs)
    print(f"load average {load:.1f} at start, {os.getloadavg()[0]:.1f} at end")
    for row in rows:
        for label, r in row.items():
            print(f"{label}: verifier {r['verifier_cpu_s']:.2f} s CPU ({r['verifier_wall_s']:.2f} "
                  f"wall), screen {r['screen_cpu_s']:.2f} s CPU ({r['screen_wall_s']:.2f} wall), "
                  f"total {r['verifier_cpu_s'] + r['screen_cpu_s']:.2f} s CPU")
    if args.json:
        print(json.dumps({"runs": rows, "load": load}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
