"""The kept state columns of joint sets, and the lanes of joints kept by them
(taskrunner.collision.samples, owners.joint_lanes)."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.collision.owners import joint_lanes as _joint_lanes
from taskrunner.collision.samples import state_columns
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene


@pytest.fixture(scope="module")
def scene() -> Scene:
    return Scene(load_cell(DATA_ROOT / "robots/cells/servo_arm_pair.yaml").model)


def test_the_same_joints_give_the_same_read_only_columns(scene):
    model = scene.robot
    names = tuple(model.joint_names[2:5])
    columns = state_columns(model, names)
    assert np.array_equal(columns, model.indices(names))
    assert state_columns(model, list(names)) is columns
    assert not columns.flags.writeable
    with pytest.raises(ValueError):
        columns[0] = 0
    assert len(state_columns(model, ())) == 0
    assert np.array_equal(state_columns(model, names[::-1]), columns[::-1])


def test_lanes_of_joints_kept_by_their_columns_match_equal_arrays(scene):
    model, checker = scene.robot, scene.checker
    half = len(model.joint_names) // 2
    left = state_columns(model, model.joint_names[:half])
    right = state_columns(model, model.joint_names[half:])
    kept = _joint_lanes(model, checker, [left, right])
    assert _joint_lanes(model, checker, [left, right])[0] is kept[0]
    # Arrays of the same columns that are not the kept ones: the same lanes, made anew.
    fresh = _joint_lanes(model, checker, [left.copy(), right.copy()])
    assert fresh[0] is not kept[0]
    assert np.array_equal(fresh[0], kept[0]) and np.array_equal(fresh[1], kept[1])
    swapped = _joint_lanes(model, checker, [right, left])
    moved = kept[0][kept[0] >= 0]
    assert np.array_equal(swapped[0][kept[0] >= 0], 1 - moved)
    assert {0, 1} <= set(kept[0].tolist())
