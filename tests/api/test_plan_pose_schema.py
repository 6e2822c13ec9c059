"""/plan's pose is the task file's: ``rpy`` or ``quat`` (one pose model)."""

from __future__ import annotations

import warnings

from taskrunner.api.schemas import PoseTarget
from taskrunner.posespec import PoseFields


def test_the_plan_pose_is_the_one_pose_model():
    assert issubclass(PoseTarget, PoseFields)


def test_plan_to_a_pose_given_by_quat_is_the_plan_given_by_rpy(client):
    body = {"cell": "servo_arm_table", "group": "arm", "backend": "mock", "seed": 3}
    by_rpy = client.post("/plan", json={**body, "pose": {"xyz": [0.19, 0.04, 0.85],
                                                         "rpy": [0, 0, 0]}})
    by_quat = client.post("/plan", json={**body, "pose": {"xyz": [0.19, 0.04, 0.85],
                                                          "quat": [0, 0, 0, 1]}})
    assert by_rpy.status_code == by_quat.status_code == 200, by_quat.text
    assert by_quat.json()["positions"] == by_rpy.json()["positions"]


def test_a_plan_pose_with_rpy_and_quat_or_without_xyz_is_refused(client):
    body = {"cell": "servo_arm_table", "group": "arm"}
    both = client.post("/plan", json={**body, "pose": {"xyz": [0.19, 0.04, 0.85],
                                                       "rpy": [0, 0, 0], "quat": [0, 0, 0, 1]}})
    assert both.status_code == 422 and "takes only one of 'rpy' or 'quat'" in both.text
    no_xyz = client.post("/plan", json={**body, "pose": {"rpy": [0, 0, 0]}})
    assert no_xyz.status_code == 422 and "xyz" in no_xyz.text


def test_plan_with_huge_pose_numbers_is_a_422_naming_the_field_without_a_warning(client):
    body = {"cell": "servo_arm_table", "group": "arm", "backend": "mock"}
    for pose, field, message in [
        ({"xyz": [1e308, 0, 0.8]}, "xyz", "must be a finite number within ±1000 m"),
        ({"xyz": [0.1, 0, 0.8], "rpy": [0, 1e308, 0]}, "rpy",
         "must be a finite number within ±100 rad"),
        ({"xyz": [0.1, 0, 0.8], "quat": [1e308, 0, 0, 0]}, "quat",
         "must be a unit quaternion [x, y, z, w] (got norm 1e+308)"),
        ({"xyz": [0.1, 0, 0.8], "quat": [1e200, 1e200, 1e200, 1e200]}, "quat",
         "must be a unit quaternion [x, y, z, w] (got norm 2e+200)"),
    ]:
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # numpy's "overflow encountered in dot" fails it
            answer = client.post("/plan", json={**body, "pose": pose})
        assert answer.status_code == 422, answer.text
        detail = answer.json()["detail"][0]
        assert detail["loc"][:3] == ["body", "pose", field], detail
        assert message in detail["msg"], detail
