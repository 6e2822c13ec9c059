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
