"""run-task check and run know the poses the REST API taught (one pose store)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from taskrunner import resources
from taskrunner.api.store import RunStore
from taskrunner.cli import EXIT_INVALID, EXIT_OK, main
from taskrunner.robot import load_robot


def _bench_task(tmp_path: Path) -> Path:
    task = tmp_path / "go_bench.yaml"
    task.write_text(f"task: go_bench\ncell: {resources.cells_dir() / 'servo_arm_table.yaml'}\n"
                    "steps:\n  - go: {group: arm, to: bench}\n  - go: {group: arm, to: home}\n")
    return task


def _teach_bench(data_dir: Path) -> None:
    # "bench": Candle with the base turned a little (a pose no robot file names).
    robot = load_robot(resources.robots_dir() / "servo_arm")
    joints = dict(robot.named_state("arm", "Candle").as_dict())
    joints["Revolute 1"] += 0.3
    data_dir.mkdir(parents=True, exist_ok=True)
    store = RunStore(data_dir / "runs.sqlite")
    store.save_pose("servo_arm_table", "arm", "bench", joints)
    store.close()


def test_check_and_run_see_a_pose_taught_through_the_api(tmp_path: Path, monkeypatch, capsys):
    task = _bench_task(tmp_path)
    data = tmp_path / "data"
    monkeypatch.delenv("TASKRUNNER_DATA_DIR", raising=False)
    monkeypatch.delenv("TASKRUNNER_STATE_DIR", raising=False)
    monkeypatch.delenv("TASKRUNNER_CELLS_DIR", raising=False)
    assert main(["check", str(task), "--data-dir", str(data)]) == EXIT_INVALID
    assert "'bench'" in capsys.readouterr().err
    _teach_bench(data)
    assert main(["check", str(task), "--data-dir", str(data)]) == EXIT_OK
    # A real run in another process, planning in its worker, from the environment's folder.
    env = {**os.environ, "TASKRUNNER_DATA_DIR": str(data)}
    done = subprocess.run([sys.executable, "-m", "taskrunner.cli", str(task), "--plain",
                           "--runs-dir", str(tmp_path / "runs")], env=env, cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == EXIT_OK, done.stdout + done.stderr
    assert "go_bench: succeeded" in done.stdout
