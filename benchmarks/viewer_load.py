"""Time from navigation to the first rendered frame of the two-arm cell page.

Starts ``run-task serve`` (a token, its own data folder), then loads
``/#/cell/servo_arm_pair`` ``--loads`` times in Debian's chromium (headless, WebGL
through SwiftShader), each in a fresh browser context (empty HTTP cache, the token in the
tab's session storage as if typed before). The page records ``performance.now()`` (ms
since navigation started) when the first frame with the robots has been drawn
(``window.__viewer.firstFrame``). Prints a table, then one JSON line.

Needs chromium (``apt-get install chromium``) and the ``playwright`` Python package; the
target is a median of at most 1500 ms.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import random
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request

TOKEN = "viewer-bench-token-0123456789"
ARGS = ["--headless=new", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
        "--use-angle=swiftshader", "--disable-background-networking",
        "--disable-component-update", "--no-first-run", "--disable-sync"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--loads", type=int, default=15, help="page loads (15)")
    parser.add_argument("--seed", type=int, default=0, help="seeds the pauses between loads")
    parser.add_argument("--cell", default="servo_arm_pair")
    parser.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    rng = random.Random(args.seed)
    port = _free_port()
    data = tempfile.mkdtemp(prefix="viewer-bench-")
    env = {**os.environ, "TASKRUNNER_TOKEN": TOKEN, "TASKRUNNER_DATA_DIR": data}
    server = subprocess.Popen(
        [sys.executable, "-c", "import sys; from taskrunner.cli import main; sys.exit(main())",
         "serve", "--port", str(port), "--log-level", "warning"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                urllib.request.urlopen(url + "/health", timeout=1)
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise SystemExit("the server did not start") from None
                time.sleep(0.1)
        times: list[float] = []
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=args.chromium, args=ARGS)
            version = browser.version
            for i in range(args.loads + 1):  # the first load warms the server's cell cache
                context = browser.new_context(viewport={"width": 1280, "height": 800})
                context.add_init_script(f"sessionStorage.setItem('taskrunner.token', {TOKEN!r})")
                page = context.new_page()
                page.goto(f"{url}/#/cell/{args.cell}")
                page.wait_for_function("window.__viewer && window.__viewer.firstFrame !== null",
                                       timeout=30_000)
                ms = float(page.evaluate("window.__viewer.firstFrame"))
                context.close()
                if i:
                    times.append(ms)
                    print(f"load {i:3d}  first frame {ms:7.0f} ms")
                time.sleep(rng.uniform(0.05, 0.25))
            browser.close()
    finally:
        server.terminate()
        server.wait(20)
        shutil.rmtree(data, ignore_errors=True)
    times.sort()
    median = statistics.median(times)
    p90 = times[min(len(times) - 1, int(0.9 * len(times)))]
    print()
    print("| figure | result | target |")
    print("| --- | --- | --- |")
    print(f"| first frame of /#/cell/{args.cell}, median of {len(times)} | **{median:.0f} ms** "
          f"(min {times[0]:.0f}, p90 {p90:.0f}, max {times[-1]:.0f}) | <= 1500 ms |")
    print(json.dumps({"benchmark": "viewer_load", "cell": args.cell, "loads": len(times),
                      "seed": args.seed, "median_ms": round(median, 1),
                      "min_ms": round(times[0], 1), "p90_ms": round(p90, 1),
                      "max_ms": round(times[-1], 1), "chromium": version,
                      "cpus": os.cpu_count(), "python": platform.python_version()}))
    return 0 if median <= 1500 else 1


if __name__ == "__main__":
    sys.exit(main())
