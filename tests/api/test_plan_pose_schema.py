"""/plan's pose is the task file's: ``rpy`` or ``quat`` (one pose model)."""

from __future__ import annotations

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
