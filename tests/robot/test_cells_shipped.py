"""The cells shipped in robots/cells load, compose their robots and keep their promises."""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import RobotDescriptionError, YamlError
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.shapes import Box

ROOT = Path(__file__).resolve().parents[2]
CELLS = DATA_ROOT / "robots" / "cells"


def tool_position(cell, q, frame):
    model = cell.model
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, model.to_pin(q))
    return data.oMf[model.frame_id(frame)].translation.copy()


@pytest.fixture(scope="module")
def servo_pair():
    return load_cell(CELLS / "servo_arm_pair.yaml")


def test_servo_arm_table_places_the_arm_on_the_table():
    cell = load_cell(CELLS / "servo_arm_table.yaml")
    assert cell.model.joint_names == tuple(f"Revolute {i}" for i in range(1, 8))
    table = cell.object("table")
    assert isinstance(table.shape, Box)
    top = table.pose.translation[2] + table.shape.size[2] / 2
    base = cell.model.instances[0].base.translation
    assert base[2] == pytest.approx(top)
    assert "base_link" in table.touch_links
    q = cell.start_state()
    assert q[:5] == pytest.approx([0.8, -0.8, -1.2, -0.8, -2.6])
    # PickUp puts the grasp point a few centimetres above the table top.
    q = cell.model.state_with(q, cell.model.named_state("arm", "PickUp"))
    assert 0.0 < tool_position(cell, q, "tool0")[2] - top < 0.06


def test_servo_arm_pair_prefixes_both_arms_and_spans_them(servo_pair):
    model = servo_pair.model
    assert model.nq == 14
    assert "left_Revolute 1" in model.joint_names and "right_Revolute 7" in model.joint_names
    assert model.group("left_arm").joint_names == tuple(f"left_Revolute {i}" for i in range(1, 6))
    both = model.group("both_arms")
    assert len(both.joint_names) == 10
    assert set(both.joint_names) == set(model.group("left_arm").joint_names) | set(
        model.group("right_arm").joint_names
    )
    # A pose that both arms have is a pose of the spanning group too.
    for pose in ("Candle", "HandOff", "PickUp"):
        assert pose in model.named_state_names("both_arms")
    assert model.group("left_arm").position_only_ik


def test_servo_arm_pair_faces_the_arms_at_hand_off(servo_pair):
    model = servo_pair.model
    q = model.state_with(servo_pair.start_state(), model.named_state("both_arms", "HandOff"))
    left = tool_position(servo_pair, q, "left_tool0")
    right = tool_position(servo_pair, q, "right_tool0")
    # Mirror images across the table's centre, a hand's width apart, well above the table.
    assert left[0] == pytest.approx(-right[0], abs=1e-6)
    assert 0.05 < right[0] - left[0] < 0.2
    assert left[2] > 0.9
    # At Candle every joint is at its servo centre: the tools point straight up.
    q = model.state_with(q, model.named_state("both_arms", "Candle"))
    assert tool_position(servo_pair, q, "left_tool0")[:2] == pytest.approx([-0.25, 0.0], abs=1e-3)


@pytest.mark.parametrize("name", ["panda_table", "panda_pair"])
def test_panda_cells_load(name):
    cell = load_cell(CELLS / f"{name}.yaml")
    arms = [g for g in cell.model.groups if g.endswith("arm")]
    assert arms
    for arm in arms:
        assert len(cell.model.group(arm).joint_names) == 7
        assert cell.model.group(arm).tip_link.endswith("panda_hand_tcp")
    assert cell.model.within_limits(cell.start_state())


def test_panda_pair_mirrors_the_handoff_pose():
    cell = load_cell(CELLS / "panda_pair.yaml")
    q = cell.model.state_with(cell.start_state(), cell.model.named_state("both_arms", "handoff"))
    left = tool_position(cell, q, "left_panda_hand_tcp")
    right = tool_position(cell, q, "right_panda_hand_tcp")
    assert left == pytest.approx(right * np.array([-1, 1, 1]), abs=1e-6)
    assert 0.2 < right[0] - left[0] < 0.4


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "cells" / "cell.yaml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def test_cell_with_a_typo_names_the_field_and_line(tmp_path):
    path = write(tmp_path, f"""\
        name: bad
        robots:
          - name: arm
            robot: {DATA_ROOT / 'robots' / 'servo_arm'}
            bsae: {{xyz: [0, 0, 0]}}
        """)
    with pytest.raises(YamlError) as err:
        load_cell(path)
    assert str(err.value) == f"{path}:5: robots[0].bsae: unknown field"


def test_cell_with_two_robots_sharing_a_prefix_is_refused(tmp_path):
    arm = DATA_ROOT / "robots" / "servo_arm"
    path = write(tmp_path, f"""\
        name: clash
        robots:
          - {{name: a, robot: {arm}}}
          - {{name: b, robot: {arm}, base: {{xyz: [1, 0, 0]}}}}
        """)
    with pytest.raises(RobotDescriptionError, match="give the robots different prefixes"):
        load_cell(path)


def test_cell_pose_outside_the_limits_names_the_line(tmp_path):
    path = write(tmp_path, f"""\
        name: bad_pose
        robots:
          - name: arm
            robot: {DATA_ROOT / 'robots' / 'servo_arm'}
            poses:
              arm:
                Reach: {{"Revolute 2": 0.5}}
        """)
    with pytest.raises(RobotDescriptionError) as err:
        load_cell(path)
    message = str(err.value)
    assert message.startswith(f"{path}:7:")
    assert "joint 'Revolute 2' = 0.5 is above its upper bound" in message


def test_cell_object_needs_the_fields_of_its_shape(tmp_path):
    path = write(tmp_path, f"""\
        name: bad_object
        robots:
          - {{name: arm, robot: {DATA_ROOT / 'robots' / 'servo_arm'}}}
        objects:
          - name: post
            shape: cylinder
            radius: 0.02
        """)
    with pytest.raises(YamlError) as err:
        load_cell(path)
    assert "needs 'length' for a cylinder" in str(err.value)
    assert str(err.value).startswith(f"{path}:5:")


def test_cell_start_pose_must_exist(tmp_path):
    path = write(tmp_path, f"""\
        name: bad_start
        robots:
          - {{name: arm, robot: {DATA_ROOT / 'robots' / 'servo_arm'}}}
        start: {{arm: hoem}}
        """)
    with pytest.raises(YamlError, match=r"cell.yaml:4: start.arm: unknown named pose .*'home'"):
        load_cell(path)


def test_cell_spanning_group_with_unknown_subgroup_is_refused(tmp_path):
    path = write(tmp_path, f"""\
        name: bad_group
        robots:
          - {{name: arm, robot: {DATA_ROOT / 'robots' / 'servo_arm'}}}
        groups:
          everything: [arm, elbow]
        """)
    with pytest.raises(YamlError, match=r"group 'everything': unknown subgroups \['elbow'\]"):
        load_cell(path)
