"""/plan: a timed trajectory from the cell's current state; nothing moves."""

from __future__ import annotations

import pytest

from taskrunner.api.schemas import PlanResponse


def test_plan_to_a_named_pose_returns_a_timed_trajectory_and_nothing_moves(client):
    before = client.get("/cells/servo_arm_table/state").json()["joints"]
    answer = client.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                        "to": "Candle"})
    assert answer.status_code == 200, answer.text
    assert answer.headers["content-type"] == "application/json"
    plan = answer.json()
    PlanResponse.model_validate(plan)  # the documented model, field for field
    assert set(plan) == set(PlanResponse.model_fields)
    assert len(plan["velocities"]) == len(plan["times"]) and plan["waypoints"] >= 2
    assert plan["joint_names"] == ["Revolute 1", "Revolute 2", "Revolute 3", "Revolute 4",
                                   "Revolute 5"]
    assert plan["times"][0] == 0.0 and plan["times"][-1] == pytest.approx(plan["duration"])
    assert len(plan["positions"]) == len(plan["times"])
    assert plan["positions"][0] == pytest.approx([before[n] for n in plan["joint_names"]])
    assert client.get("/cells/servo_arm_table/state").json()["joints"] == before


def test_plan_to_joint_values_and_to_a_pose(client):
    joints = client.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                        "joints": {"Revolute 1": 0.3}})
    assert joints.status_code == 200
    assert joints.json()["positions"][-1][0] == pytest.approx(0.3)
    pose = client.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                      "pose": {"xyz": [0.19, 0.04, 0.85]}})
    assert pose.status_code == 200, pose.text


def test_plan_samples_the_trajectory_at_the_rate_asked_for(client):
    body = {"cell": "servo_arm_table", "group": "arm", "to": "Candle", "backend": "mock"}
    fine = client.post("/plan", json=body).json()
    coarse = client.post("/plan", json={**body, "sample_rate_hz": 10}).json()
    assert coarse["duration"] == pytest.approx(fine["duration"])
    assert coarse["positions"][-1] == pytest.approx(fine["positions"][-1])
    steps = [b - a for a, b in zip(coarse["times"], coarse["times"][1:])]
    assert max(steps) == pytest.approx(0.1, abs=1e-6)
    assert len(coarse["times"]) < len(fine["times"]) / 5


@pytest.mark.parametrize("body, code, fragment", [
    ({"cell": "servo_arm_table", "group": "leg", "to": "home"}, 422, "unknown group 'leg'"),
    ({"cell": "servo_arm_table", "group": "arm", "to": "nowhere"}, 422, "'nowhere'"),
    ({"cell": "servo_arm_table", "group": "arm", "pose": {"xyz": [3.0, 0, 1]}}, 422,
     "planning failed"),
    ({"cell": "servo_arm_table", "group": "arm"}, 422, "exactly one goal"),
    ({"cell": "atlantis", "group": "arm", "to": "home"}, 404, "unknown cell"),
    ({"cell": "servo_arm_table", "group": "arm", "to": "home", "sample_rate_hz": 0}, 422,
     "sample_rate_hz"),
])
def test_bad_plan_requests_answer_4xx_with_the_reason(client, body, code, fragment):
    answer = client.post("/plan", json=body)
    assert answer.status_code == code
    assert fragment in str(answer.json()["detail"])
