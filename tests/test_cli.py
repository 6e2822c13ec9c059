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
