"""Numbers of robot and cell files are checked where they are read: finite poses, positive
sizes, non-negative masses and inertias, each refused with file:line and the field."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from taskrunner.errors import RobotDescriptionError, YamlError
from taskrunner.robot.cell import load_cell
from taskrunner.robot.packages import PackageMap
from taskrunner.robot.urdf import read_urdf
from taskrunner.robot.xacrofile import XacroOptions, expand_xacro

URDF = """<robot name="r">
  <link name="base"/>
  <link name="tip">
    {element}
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="tip"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


@pytest.mark.parametrize(
    ("element", "reason"),
    [
        ('<collision><geometry><box size="0.1 -0.1 0.1"/></geometry></collision>',
         "<box> 'size' must be a finite number > 0 and ≤ 1000 m (got -0.1) (got '0.1 -0.1 0.1')"),
        ('<collision><geometry><sphere radius="nan"/></geometry></collision>',
         "<sphere> 'radius' must be a finite number > 0 and ≤ 1000 m (got nan)"),
        ('<collision><geometry><cylinder radius="0.1" length="0"/></geometry></collision>',
         "<cylinder> 'length' must be a finite number > 0 and ≤ 1000 m (got 0.0)"),
        ('<inertial><mass value="-1"/></inertial>',
         "<mass> 'value' must be a finite number ≥ 0 and ≤ 1e+06 kg (got -1.0)"),
        ('<inertial><mass value="1"/><inertia ixx="inf" ixy="0" ixz="0" iyy="1" iyz="0" '
         'izz="1"/></inertial>',
         "<inertia> 'ixx' must be a finite number ≥ -1e-12 and ≤ 1e+06 kg·m² (got inf)"),
        ('<visual><origin xyz="0 1e400 0"/><geometry><sphere radius="0.1"/></geometry></visual>',
         "<origin> 'xyz' must be a finite number within ±1000 m (got inf) (got '0 1e400 0')"),
        ('<visual><origin rpy="0 -1e308 0"/><geometry><sphere radius="0.1"/></geometry></visual>',
         "<origin> 'rpy' must be a finite number within ±100 rad (got -1e+308) "
         "(got '0 -1e308 0')"),
    ],
    ids=["negative box", "nan sphere", "zero cylinder", "negative mass", "inf inertia",
         "inf origin", "huge rpy"],
)
def test_urdf_numbers_are_checked_at_their_line(tmp_path, element, reason):
    path = tmp_path / "r.urdf"
    path.write_text(URDF.format(element=element))
    with pytest.raises(RobotDescriptionError) as info:
        read_urdf(path)
    assert str(info.value) == f"{path}:4: link 'tip': {reason}"  # the element's line


def test_zero_mass_is_fine(tmp_path):
    # example-robot-data's Panda has massless links.
    path = tmp_path / "r.urdf"
    path.write_text(URDF.format(element='<inertial><mass value="0"/></inertial>'))
    assert read_urdf(path).links == ["base", "tip"]


def test_urdf_nested_too_deep_is_refused(tmp_path):
    path = tmp_path / "deep.urdf"
    path.write_text('<robot name="r"><link name="a">' + "<visual>" * 100_000
                    + "</visual>" * 100_000 + "</link></robot>\n")
    with pytest.raises(RobotDescriptionError) as info:
        read_urdf(path)
    assert str(info.value) == f"{path}:1: XML nested deeper than 64 elements"


def test_a_urdf_that_is_a_fifo_is_refused(tmp_path):
    path = tmp_path / "r.urdf"
    os.mkfifo(path)
    with pytest.raises(RobotDescriptionError) as info:
        read_urdf(path)
    assert str(info.value) == f"{path}: not a regular file (a FIFO (named pipe))"


# ---------------------------------------------------------------------------- cells
@pytest.fixture
def cell_file(tmp_path: Path, robots_dir: Path):
    def write(old: str, new: str) -> Path:
        text = (robots_dir / "cells" / "servo_arm_table.yaml").read_text()
        assert old in text
        folder = tmp_path / "cells"
        folder.mkdir(exist_ok=True)
        if not (tmp_path / "servo_arm").exists():
            os.symlink(robots_dir / "servo_arm", tmp_path / "servo_arm")
        path = folder / "cell.yaml"
        path.write_text(text.replace(old, new))
        return path
    return write


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("xyz: [0.0, 0.0, 0.75]", "xyz: [0.0, .nan, 0.75]",
         "7: 'robots[0].base.xyz[1]' must be a finite number (got nan)"),
        ("xyz: [0.0, 0.0, 0.75]", "xyz: [0.0, 0.0, -1e308]",
         "7: 'robots[0].base.xyz[2]' must be a finite number within ±1000 m (got -1e+308)"),
        ("xyz: [0.0, 0.0, 0.75]", "xyz: [0.0, 0.0, 0.75], rpy: [0, .inf, 0]",
         "7: 'robots[0].base.rpy[1]' must be a finite number (got inf)"),
        ("size: [0.60, 0.40, 0.75]", "size: [0.60, -0.40, 0.75]",
         "16: 'objects[0].size[1]' must be a finite number > 0 and ≤ 1000 m (got -0.4)"),
    ],
    ids=["nan base", "huge base", "inf rpy", "negative size"],
)
def test_cell_numbers_are_checked_at_their_line(cell_file, old, new, message):
    path = cell_file(old, new)
    with pytest.raises(YamlError) as info:
        load_cell(path)
    assert str(info.value) == f"{path}:{message}"


# ---------------------------------------------------------------------------- xacro
def write_xacro(folder: Path, body: str, name: str = "r.urdf.xacro") -> Path:
    path = folder / name
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    f'{body}\n<link name="base"/>\n</robot>\n')
    return path


def test_a_runaway_xacro_expression_is_stopped_at_the_time_limit(tmp_path):
    path = write_xacro(tmp_path, '<xacro:property name="b" value="${10**10**8}"/>'
                                 '<link name="${b}"/>')
    with pytest.raises(RobotDescriptionError) as info:
        expand_xacro(path, PackageMap(), options=XacroOptions(time_limit_s=0.5))
    # Stopped by its CPU limit (the message says which limit), however busy the machine.
    assert str(info.value) == (f"{path}: xacro expansion took more than 0.5 s of CPU time "
                               "(a runaway expression or macro?)")


def test_a_xacro_macro_fan_out_is_stopped(tmp_path):
    macros = '<xacro:macro name="m0"><link name="x"/></xacro:macro>' + "".join(
        f'<xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>'
        for i in range(1, 25))
    path = write_xacro(tmp_path, macros + "<xacro:m24/>")
    # Stopped by its CPU or memory limit, whichever comes first (in wall-clock time, as
    # late as the machine is busy: 4.1 s beside 4 spinning processes).
    with pytest.raises(RobotDescriptionError,
                       match="xacro expansion (took more than 1 s of CPU|needs more memory"
                             "|failed: its process ended)"):
        expand_xacro(path, PackageMap(), options=XacroOptions(time_limit_s=1.0))


def test_a_xacro_string_of_a_gigabyte_runs_out_of_memory_not_the_machine(tmp_path):
    path = write_xacro(tmp_path, """<xacro:property name="s" value="${'x' * 10**9}"/>"""
                                 '<link name="${s}"/>')
    with pytest.raises(RobotDescriptionError) as info:
        expand_xacro(path, PackageMap(), options=XacroOptions(memory_limit_mb=128))
    assert str(info.value).startswith(f"{path}: xacro expansion")


def test_a_xacro_include_of_a_fifo_is_refused_at_once(tmp_path):
    os.mkfifo(tmp_path / "fifo.xacro")
    path = write_xacro(tmp_path, '<xacro:include filename="fifo.xacro"/>')
    start = time.perf_counter()
    with pytest.raises(RobotDescriptionError) as info:
        expand_xacro(path, PackageMap())
    assert time.perf_counter() - start < 1
    assert str(info.value) == (f"{tmp_path / 'fifo.xacro'}: xacro expansion failed: not a "
                               f"regular file (a FIFO (named pipe)) (included from {path})")


def test_the_servo_arm_expands_the_same_in_the_child(robots_dir):
    path = robots_dir / "servo_arm" / "urdf" / "servo_arm.urdf.xacro"
    packages = PackageMap(search_roots=[robots_dir])
    assert expand_xacro(path, packages) == expand_xacro(
        path, packages, options=XacroOptions(in_process=True))
