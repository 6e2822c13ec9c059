"""run-task's demo, info and collision-matrix commands, and its exit codes."""

from __future__ import annotations

from taskrunner.cli import EXIT_INVALID, EXIT_OK, EXIT_PLANNING, main
from taskrunner.resources import DATA_ROOT


def test_demo_solves_ik_checks_collisions_and_plans(capsys):
    assert main(["demo"]) == EXIT_OK
    out = capsys.readouterr().out
    assert "loaded cell 'servo_arm_table'" in out
    assert "collision-free" in out
    assert "in collision: " in out and "table" in out
    assert "planned 'arm'" in out


def test_demo_with_an_unreachable_target_is_a_planning_failure(capsys):
    assert main(["demo", "--target", "1.0", "0", "0.1"]) == EXIT_PLANNING
    err = capsys.readouterr().err
    assert "no IK solution for group 'arm', frame 'tool0'" in err
    assert "best residual 0.6" in err


def test_info_lists_groups_poses_and_objects(repo_root, capsys):
    assert main(["info", str(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml")]) == EXIT_OK
    out = capsys.readouterr().out
    assert "robot 'left' prefix 'left_'" in out
    assert "both_arms: 10 joints" in out and "HandOff" in out
    assert "table: Box" in out


def test_info_on_a_bad_file_names_it_and_exits_2(tmp_path, capsys):
    bad = tmp_path / "cell.yaml"
    bad.write_text("name: x\nrobots: []\n")
    assert main(["info", str(bad)]) == EXIT_INVALID
    err = capsys.readouterr().err
    assert f"{bad}:2:" in err and "robots" in err


def test_collision_matrix_prints_srdf_entries(repo_root, capsys):
    code = main(["collision-matrix", str(DATA_ROOT / "robots" / "servo_arm"), "--samples", "300"])
    assert code == EXIT_OK
    out = capsys.readouterr().out
    assert '<disable_collisions link1="arm_link_1" link2="base_link_upper_1" reason="Adjacent"/>' in out


def _far_place_task(tmp_path):
    path = tmp_path / "far.yaml"
    cell = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    path.write_text(f"""task: far
cell: {cell}
objects:
  - {{name: cube, shape: box, size: [0.025, 0.025, 0.025], pose: {{xyz: [0.19, 0.04, 0.7625]}}}}
steps:
  - pick: {{arm: arm, object: cube, grasp: top, approach: 0.04, retreat: 0.05}}
  - place: {{arm: arm, object: cube, at: {{xyz: [0.9, 0.3, 0.7635]}}}}
""")
    return path


def test_run_checks_first_and_moves_nothing_when_the_place_is_out_of_reach(tmp_path, capsys):
    path = _far_place_task(tmp_path)
    runs = tmp_path / "runs"
    assert main(["run", str(path), "--runs-dir", str(runs)]) == EXIT_INVALID
    err = capsys.readouterr().err
    assert f"{path}:7: place cube: pre-place out of reach" in err
    assert "1 problem(s); nothing moved" in err
    assert not runs.exists()  # no run started: no record, no motion


def test_run_with_no_check_runs_and_fails_where_the_check_would_have_said(tmp_path, capsys):
    path = _far_place_task(tmp_path)
    runs = tmp_path / "runs"
    assert main(["run", str(path), "--no-check", "--in-process", "--plain",
                 "--runs-dir", str(runs)]) == EXIT_PLANNING
    assert len(list(runs.glob("*.json"))) == 1
    assert "✔ pick cube" in capsys.readouterr().out  # it did pick the cube first


def test_a_speed_that_is_not_positive_is_a_clean_error_on_every_backend(tmp_path, capsys):
    for backend in ("mock", "sim"):
        for speed in ("0", "-2"):
            code = main(["run", "go_home", "--backend", backend, "--speed", speed,
                         "--runs-dir", str(tmp_path / "runs")])
            assert code == EXIT_INVALID, (backend, speed)
            assert "'--speed' must be a positive number" in capsys.readouterr().err


class _Board:
    """Stands in for a servo backend: hw calibrate only needs it closed at the end."""

    closed = False

    def close(self) -> None:
        self.closed = True


def test_hw_calibrate_without_input_is_a_clean_error(monkeypatch, capsys):
    import io

    import taskrunner.backends.calibrate
    import taskrunner.runtime.session

    board = _Board()
    monkeypatch.setattr(taskrunner.runtime.session, "make_backend", lambda *a, **k: board)

    def calibrate(backend, path, joints, ask=input, say=print):
        ask("  angle of Revolute 1 now, in degrees: ")

    monkeypatch.setattr(taskrunner.backends.calibrate, "calibrate_servos", calibrate)
    monkeypatch.setattr("sys.stdin", io.StringIO(""))  # input ended: EOF at the first question
    assert main(["hw", "calibrate", "--port", "/dev/null"]) == EXIT_INVALID
    err = capsys.readouterr().err
    assert "error: hw calibrate asks a question for each joint: run it in a terminal" in err
    assert board.closed
    monkeypatch.setattr("sys.stdin", None)  # started with stdin closed: refused up front
    assert main(["hw", "calibrate", "--port", "/dev/null"]) == EXIT_INVALID
    assert "standard input is closed" in capsys.readouterr().err


def test_the_straight_move_fallback_note_does_not_read_like_an_error(monkeypatch):
    from types import SimpleNamespace

    from taskrunner.planning.cartesian import CartesianOptions
    from taskrunner.runtime.events import EventLog
    from taskrunner.tree import behaviours

    results = iter([SimpleNamespace(stop_reason="ik", message="no IK solution at 40 %"),
                    SimpleNamespace(stop_reason=None, message="")])

    class Planner:
        def compute(self, group, waypoints, link=None, options=None):
            return next(results)

    planner = Planner()
    ctx = SimpleNamespace(events=EventLog(), scene=None, timing=None,
                          cartesian_planner=lambda: planner)
    leaf = behaviours.MoveStraight("retreat", "task.yaml:9", ctx, "arm", lambda c: [],
                                   fallback=CartesianOptions(position_only=True))
    leaf.compute(ctx)
    (note,) = ctx.events.events()
    assert note.message == ("note: the tool's full pose cannot be held along this line (no IK "
                            "solution at 40 %); following the line by the position of its "
                            "tool only")


def test_a_bad_parameter_default_or_value_is_one_problem_not_two(tmp_path, capsys):
    cell = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    cases = [("{default: 0.5, type: float, min: -0.15, max: 0.15}", [],
              "default of 'place_y' must be <= 0.15 (got 0.5)"),
             ("{default: abc, type: float, min: -0.15, max: 0.15}", [],
              "default of 'place_y' must be a float (got 'abc')"),
             ("{type: float, min: -0.15, max: 0.15}", [],
              "parameter 'place_y' has no default and is not given (--param)"),
             ("{type: float}", ["--param", "place_y=abc"], "'place_y' must be a float (got 'abc')")]
    for declaration, extra, message in cases:
        path = tmp_path / "task.yaml"
        path.write_text(f"task: p\ncell: {cell}\nparameters:\n  place_y: {declaration}\n"
                        "steps:\n  - go: {group: arm, pose: {xyz: [0.14, \"${place_y}\", 0.8]}}\n")
        assert main(["check", str(path), *extra]) == EXIT_INVALID
        err = capsys.readouterr().err
        assert f"{path}:4: {message}" in err
        assert "1 problem(s)" in err, err


def test_firmware_sim_passes_sigterm_on_and_leaves_no_firmware_behind():
    import os
    import select
    import shutil
    import signal
    import subprocess
    import sys
    import time
    from pathlib import Path

    import pytest

    if shutil.which("make") is None or shutil.which("g++") is None:
        pytest.skip("the firmware host build needs make and g++")
    from taskrunner.backends.host_firmware import build_host_firmware

    build_host_firmware(timeout_s=300)  # built (or cached) before the clock starts
    proc = subprocess.Popen([sys.executable, "-m", "taskrunner.cli", "firmware-sim",
                             "--speedup", "10"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True)
    try:
        data, deadline = b"", time.monotonic() + 60
        while data.count(b"\n") < 2 and time.monotonic() < deadline:  # its pty, its URL
            ready, _, _ = select.select([proc.stdout], [], [], 1.0)
            if ready:
                chunk = os.read(proc.stdout.fileno(), 4096)
                assert chunk, f"firmware-sim exited early: {data!r}"
                data += chunk
        assert data.count(b"\n") >= 2, data
        children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children").read_text().split()
        assert len(children) == 1
        firmware = int(children[0])
        proc.send_signal(signal.SIGTERM)  # to the CLI only, as `kill PID` does
        assert proc.wait(30) in (0, 128 + signal.SIGTERM)  # the firmware's own exit code
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            try:
                state = Path(f"/proc/{firmware}/stat").read_text().rpartition(")")[2].split()[0]
            except OSError:
                break  # gone
            if state == "Z":
                break  # ended, waiting to be reaped by init
            time.sleep(0.05)
        else:
            pytest.fail(f"firmware process {firmware} still runs after firmware-sim ended")
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(10)
