"""``run-task view``: serves the web view on 127.0.0.1, prints the URL, opens a CLI run's
record for replay (no browser needed for this test)."""

from __future__ import annotations

import json
import subprocess
import sys
import time
import urllib.request

import taskrunner


def test_run_task_view_serves_a_cli_record_for_replay(tmp_path):
    result = taskrunner.run_task("pick_place", runs_dir=tmp_path / "runs")
    (record,) = (tmp_path / "runs").glob("*.json")
    token = "view-test-token-0123456789"
    process = subprocess.Popen(
        [sys.executable, "-c", "import sys; from taskrunner.cli import main; sys.exit(main())",
         "view", str(record), "--token", token],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        line = process.stdout.readline()
        assert line.startswith("taskrunner view at http://127.0.0.1:"), line
        url = line.split(" at ", 1)[1].strip()
        assert url.endswith(f"/#/run/{record.stem}") and token not in url
        base = url.split("/#", 1)[0]
        deadline = time.monotonic() + 30
        while True:
            try:
                page = urllib.request.urlopen(base + "/", timeout=2).read().decode()
                break
            except OSError:
                assert time.monotonic() < deadline and process.poll() is None
                time.sleep(0.1)
        assert "viewer.js" in page
        request = urllib.request.Request(f"{base}/viewer/runs/{record.stem}/replay",
                                         headers={"Authorization": f"Bearer {token}"})
        replay = json.loads(urllib.request.urlopen(request, timeout=10).read())
        assert replay["status"] == result.status == "succeeded"
        assert len(replay["motions"]) >= 8 and replay["final_scene"]
    finally:
        process.terminate()
        process.wait(20)
