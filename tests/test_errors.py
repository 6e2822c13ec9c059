"""Every error keeps its message and fields through pickling (the planning worker sends
them across processes)."""

from __future__ import annotations

import pickle

import pytest

from taskrunner import errors

CASES = [
    errors.RobotDescriptionError("bad joint", "robot.srdf", 12),
    errors.MissingMeshError("mesh gone", "robot.urdf", None),
    errors.YamlError("duplicate key 'a'", "cell.yaml", 3),
    errors.UnknownNameError("group", "amr", ["arm", "gripper"]),
    errors.SceneError("duplicate object 'cube'"),
    errors.PlanningError("no motion"),
    errors.IkFailedError("no IK solution", best_error=0.25),
    errors.InvalidStateError("goal outside limits"),
    errors.StartInCollisionError("start collides", [("link5", "shelf")]),
    errors.GoalInCollisionError("goal collides", [("hand", "box")]),
    errors.PlanningTimeoutError("no path in 1 s"),
    errors.PlanningCancelledError("cancelled"),
]


@pytest.mark.parametrize("error", CASES, ids=lambda e: type(e).__name__)
def test_errors_survive_pickling(error):
    copy = pickle.loads(pickle.dumps(error))
    assert type(copy) is type(error)
    assert str(copy) == str(error)
    assert vars(copy) == vars(error)


def test_input_errors_start_with_their_location():
    assert str(errors.YamlError("duplicate key 'a'", "cell.yaml", 3)) == "cell.yaml:3: duplicate key 'a'"
    assert str(errors.YamlError("file not found", "cell.yaml")) == "cell.yaml: file not found"
    assert str(errors.UnknownNameError("group", "amr", ["arm"])) \
        == "unknown group 'amr'; did you mean 'arm'? (known: 'arm')"
    assert str(errors.UnknownNameError("group", "xyz", ["arm"])) == "unknown group 'xyz'; known: 'arm'"
