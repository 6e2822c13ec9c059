"""``run-task view`` with no target: the runs of ``./runs`` (a record that cannot be read
named on stderr, the others served)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
import urllib.request

import taskrunner


def test_run_task_view_alone_lists_the_runs_of_the_runs_folder(tmp_path):
    result = taskrunner.run_task("go_home", runs_dir=tmp_path / "runs")
    (record,) = (tmp_path / "runs").glob("*.json")
    (tmp_path / "runs" / "broken.json").write_text("{not json")
    env = {k: v for k, v in os.environ.items() if k != "TASKRUNNER_RUNS_DIR"}
    token = "view-runs-token-0123456789"
    process = subprocess.Popen(
        [sys.executable, "-c", "import sys; from taskrunner.cli import main; sys.exit(main())",
         "view", "--token", token],
        cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        line = process.stdout.readline()
        assert line.startswith("taskrunner view at http://127.0.0.1:"), line
        url = line.split(" at ", 1)[1].strip()
        assert url.endswith("/#/runs")
        base = url.split("/#", 1)[0]
        request = urllib.request.Request(f"{base}/runs",
                                         headers={"Authorization": f"Bearer {token}"})
        deadline = time.monotonic() + 30
        while True:
            try:
                runs = json.loads(urllib.request.urlopen(request, timeout=2).read())
                break
            except OSError:
                assert time.monotonic() < deadline and process.poll() is None
                time.sleep(0.1)
        assert [r["run_id"] for r in runs] == [record.stem]
        assert runs[0]["status"] == result.status == "succeeded"
    finally:
        process.terminate()
        _, err = process.communicate(timeout=20)
    assert "broken.json: not shown:" in err


def test_run_task_view_loads_a_records_robots_as_its_run_did(tmp_path):
    import argparse

    import pytest

    from taskrunner.api import Settings
    from taskrunner.cli import main
    from taskrunner.commands.server import view_load_settings
    from taskrunner.errors import InputError
    from taskrunner.runtime.records import load_record

    runs = tmp_path / "runs"
    assert main(["run", "go_home", "--backend", "mock", "--in-process", "--plain",
                 "--no-check", "--runs-dir", str(runs), "--collision", "exact",
                 "--package-path", str(tmp_path)]) == 0
    record = load_record(next(runs.glob("*.json")))
    plain = argparse.Namespace(package_path=[], collision=None)
    loads = view_load_settings(plain, record)
    settings = Settings.from_env({}, **loads)
    assert settings.collision == "exact" and settings.package_path == (tmp_path.resolve(),)
    assert settings.load_options() == settings.load_options().from_data(record.load_options)
    # Its own flags win; without a record, the defaults.
    given = argparse.Namespace(package_path=[], collision="convex")
    assert view_load_settings(given, record) == {"package_path": None, "collision": "convex"}
    assert view_load_settings(plain, None) == {"package_path": None, "collision": None}
    record.load_options = {"strict": "yes"}
    with pytest.raises(InputError, match="its load_options: 'strict' and"):
        view_load_settings(plain, record)
