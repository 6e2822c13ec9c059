"""``run-task info`` shows each robot-loading warning once (the loader logs it, and info's
report lists it: one of the two is silenced), and the missing-mesh opt-out on the command
line."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path


def run_info(folder: Path, packages: Path, *flags: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items()
           if k not in ("TASKRUNNER_ALLOW_MISSING_MESHES", "TASKRUNNER_STRICT")}
    return subprocess.run(
        [sys.executable, "-m", "taskrunner.cli", "info", str(folder),
         "--package-path", str(packages), *flags],
        capture_output=True, text=True, timeout=300, check=False, env=env)


def test_info_prints_a_skipped_content_warning_once(make_mini):
    robot = make_mini({"mini.urdf": (
        '<limit effort="10" lower="0" upper="0.1" velocity="0.2"/>',
        '<limit effort="10" lower="0" upper="0.1" velocity="0.2"/>\n    <mimic joint="j7"/>')})
    result = run_info(robot.folder, robot.packages.find("mini_description").parent)
    assert result.returncode == 0, result.stderr
    both = result.stdout + result.stderr
    assert both.count("joint 'j3' mimics 'j7', which is not a joint") == 1
    assert "warning: " in result.stdout  # in info's report


def test_info_refuses_a_missing_mesh_and_loads_it_with_the_flag_warning_once(make_mini):
    robot = make_mini({"mini.urdf": ('tetra.stl" scale', 'nope.stl" scale')})
    packages = robot.packages.find("mini_description").parent
    refused = run_info(robot.folder, packages)
    assert refused.returncode == 2
    assert "link 'link2': collision mesh 'package://mini_description/meshes/nope.stl'" \
        in refused.stderr
    allowed = run_info(robot.folder, packages, "--allow-missing-meshes")
    assert allowed.returncode == 0, allowed.stderr
    both = allowed.stdout + allowed.stderr
    assert both.count("robot 'mini' loaded WITHOUT 1 mesh file(s)") == 1


def test_a_run_prints_its_robots_load_warning_once(tmp_path: Path):
    """run-task loads the cell in its check, in its run and in its planning worker: the
    warning is said once (the run takes the check's cell, the worker stays quiet)."""
    import shutil

    from taskrunner import resources

    robot = tmp_path / "servo_arm"
    shutil.copytree(resources.robots_dir() / "servo_arm", robot)
    srdf = robot / "config" / "servo_arm.srdf"
    srdf.write_text(srdf.read_text().replace(
        "</robot>", '  <disable_collisions link1="no_such_link" link2="base_link" '
                    'reason="Never"/>\n</robot>'))
    (tmp_path / "cell.yaml").write_text("name: mine\nrobots:\n  - name: arm\n"
                                         "    robot: servo_arm\n")
    (tmp_path / "task.yaml").write_text("task: t\ncell: cell.yaml\nsteps:\n"
                                         "  - go: {group: arm, to: home}\n")
    result = subprocess.run([sys.executable, "-m", "taskrunner.cli", "task.yaml", "--plain"],
                            cwd=tmp_path, capture_output=True, text=True, timeout=300,
                            check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    assert (result.stdout + result.stderr).count("names unknown link(s) ['no_such_link']") == 1
