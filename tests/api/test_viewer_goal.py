"""The page's interactive goal and Execute: a dragged tool frame solved by IK on the
server (unreachable and colliding goals answered with the reason), hostile bodies
refused with the field named, Execute moving the arm on the backend as a run (token
needed, a stale plan refused), and the Task view's objects before planning."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest
from apitest import AUTH, NO_TOKEN, make_settings, wait_for_event, wait_until_done
from fastapi.testclient import TestClient

from taskrunner.api import create_app

CELL = "/viewer/cells/servo_arm_table"


@pytest.fixture(scope="module")
def reader(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TestClient]:
    """One app for the tests that move nothing (goal checks)."""
    settings = make_settings(tmp_path_factory.mktemp("goal") / "state")
    with TestClient(create_app(settings), headers=AUTH) as c:
        yield c


def _home(client) -> dict[str, float]:
    cell = client.get(CELL).json()
    return next(g for g in cell["groups"] if g["name"] == "arm")["poses"]["home"]


def test_a_dragged_tool_frame_is_solved_and_its_tip_lands_on_the_target(reader):
    home = _home(reader)
    at_home = reader.post(CELL + "/goal", json={"group": "arm", "joints": home}).json()
    assert at_home["ok"] and at_home["link"] == "gripper_base_1"
    target = [at_home["xyz"][0] + 0.02, at_home["xyz"][1] + 0.02, at_home["xyz"][2] - 0.05]
    answer = reader.post(CELL + "/goal", json={
        "group": "arm", "pose": {"xyz": target, "quat": at_home["quat"]}, "seed": home})
    body = answer.json()
    assert answer.status_code == 200, body
    assert body["reachable"] and body["ok"] and body["reason"] is None
    assert math.dist(body["xyz"], target) < 1e-4  # the 5-DOF arm aims its position
    assert body["joints"] != home and set(body["joints"]) == set(home)
    # the answer's joints put the tip there: checked again as a joint goal
    again = reader.post(CELL + "/goal", json={"group": "arm", "joints": body["joints"]}).json()
    assert math.dist(again["xyz"], target) < 1e-4


def test_an_unreachable_or_colliding_goal_says_why(reader):
    home = _home(reader)
    far = reader.post(CELL + "/goal", json={
        "group": "arm", "pose": {"xyz": [0.2, -0.17, 0.0], "quat": [0, 0, 0, 1]},
        "seed": home}).json()
    assert not far["reachable"] and not far["ok"]
    assert "no IK solution for group 'arm'" in far["reason"]
    assert far["joints"] == pytest.approx(home)  # the seed's joints, unchanged
    low = reader.post(CELL + "/goal", json={
        "group": "arm", "pose": {"xyz": [0.2088, -0.1737, 0.8059], "quat": [0, 0, 0, 1]},
        "seed": home}).json()
    assert low["reachable"] and not low["collision_free"] and not low["ok"]
    assert "in collision" in low["reason"] and "table" in low["reason"]


@pytest.mark.parametrize(("body", "expected"), [
    ({"group": "arm", "pose": {"xyz": [0, 0, 1], "quat": [0, 0, 0, 1]}, "joints": {}},
     "exactly one goal"),
    ({"group": "arm"}, "exactly one goal"),
    ({"group": "wing", "joints": {"Revolute 1": 0}}, "wing"),
    ({"group": "arm", "joints": {"Revolute 9": 0}}, "Revolute 9"),
    ({"group": "arm", "joints": {"Revolute 6": 0}}, "not a joint of group 'arm'"),
    ({"group": "arm", "pose": {"xyz": [0, 0, 1e9], "quat": [0, 0, 0, 1]}}, "xyz"),
    ({"group": "arm", "pose": {"xyz": [0, 0, 1], "quat": [0, 0, 0, 0]}}, "quat"),
    ({"group": "arm", "pose": {"xyz": [0, 1], "quat": [0, 0, 0, 1]}}, "xyz"),
    ({"group": "arm", "pose": {"xyz": [0, 0, 1], "quat": [0, 0, 0, 1], "link": "nowhere"}},
     "nowhere"),
    ({"group": "arm", "joints": {"Revolute 1": "0.1"}}, "Revolute 1"),
    ({"group": "arm", "joints": {"Revolute 1": 0}, "extra": 1}, "extra"),
])
def test_a_hostile_goal_is_refused_naming_the_field(reader, body, expected):
    answer = reader.post(CELL + "/goal", json=body)
    assert answer.status_code == 422, answer.text
    assert expected in answer.text


def test_a_goal_with_nan_is_refused(reader):
    answer = reader.post(CELL + "/goal", content=b'{"group": "arm", "joints": '
                         b'{"Revolute 1": NaN}}', headers={"content-type": "application/json"})
    assert answer.status_code == 422


def _goal_off_home(client, dz: float) -> dict[str, float]:
    home = _home(client)
    at_home = client.post(CELL + "/goal", json={"group": "arm", "joints": home}).json()
    target = [at_home["xyz"][0] + 0.02, at_home["xyz"][1] + 0.02, at_home["xyz"][2] + dz]
    return client.post(CELL + "/goal", json={
        "group": "arm", "pose": {"xyz": target, "quat": at_home["quat"]}, "seed": home}).json()


def test_execute_moves_the_arm_on_the_backend_as_a_run(client):
    goal = _goal_off_home(client, -0.05)
    assert goal["ok"], goal
    body = {"group": "arm", "joints": goal["joints"], "backend": "mock",
            "velocity_scaling": 0.5}
    assert client.post(CELL + "/execute", json=body, headers=NO_TOKEN).status_code == 401
    before = client.get("/cells/servo_arm_table/state?backend=mock").json()["joints"]
    # a plan made from elsewhere than where the arm is: refused, nothing moves
    stale = {**body, "start": {**before, "Revolute 1": before["Revolute 1"] + 0.3}}
    refused = client.post(CELL + "/execute", json=stale)
    assert refused.status_code == 409 and "plan again" in refused.text
    answer = client.post(CELL + "/execute", json={**body, "start": before})
    assert answer.status_code == 202, answer.text
    run = wait_until_done(client, answer.json()["run_id"])
    assert run["status"] == "succeeded" and run["cell"] == "servo_arm_table"
    after = client.get("/cells/servo_arm_table/state?backend=mock").json()["joints"]
    assert max(abs(after[n] - before[n]) for n in goal["joints"]) > 0.05
    assert all(after[n] == pytest.approx(v, abs=1e-3) for n, v in goal["joints"].items())


def test_stop_cancels_an_execute_and_the_arm_stays_where_it_stopped(client):
    cell = client.get(CELL).json()
    candle = next(g for g in cell["groups"] if g["name"] == "arm")["poses"]["Candle"]
    answer = client.post(CELL + "/execute", json={
        "group": "arm", "joints": candle, "backend": "sim", "velocity_scaling": 0.05})
    assert answer.status_code == 202, answer.text
    run_id = answer.json()["run_id"]
    wait_for_event(client, run_id, "motion")
    assert client.post(f"/runs/{run_id}/cancel").status_code == 202
    run = wait_until_done(client, run_id)
    assert run["status"] == "cancelled"
    stopped = client.get("/cells/servo_arm_table/state?backend=sim").json()["joints"]
    assert abs(stopped["Revolute 2"] - candle["Revolute 2"]) > 0.05  # not at the goal


def test_execute_refuses_a_goal_in_collision(client):
    low = _goal_off_home(client, -0.16)
    assert low["reachable"] and not low["collision_free"], low
    answer = client.post(CELL + "/execute", json={"group": "arm", "backend": "mock",
                                                  "joints": low["joints"]})
    assert answer.status_code == 422, answer.text
    assert "cannot be planned to" in answer.text and "table" in answer.text


def test_the_task_tree_carries_the_tasks_objects_before_planning(client):
    answer = client.post("/viewer/tasks/tree", json={"task": "pick_place"}).json()
    objects = {o["name"]: o for o in answer["scene"]["objects"]}
    assert objects["cube"]["shape"] == {"type": "box", "size": [0.025, 0.025, 0.025]}
    assert objects["cube"]["pose"]["xyz"] == pytest.approx([0.19, 0.04, 0.7625])
    assert "table" in objects  # the cell's own objects too
    assert answer["scene"]["joints"]


def _block_at(xyz: list[float], name: str = "block") -> dict:
    return {"name": name, "shape": "box", "size": [0.04, 0.04, 0.04], "xyz": xyz}


def test_an_obstacle_added_on_the_page_is_in_the_goal_check_the_plan_and_the_run(client):
    goal = _goal_off_home(client, -0.05)
    block = _block_at(goal["xyz"])
    # the goal's tool is inside the block: the check names it, the plan is refused
    blocked = client.post(CELL + "/goal", json={"group": "arm", "joints": goal["joints"],
                                                "obstacles": [block]}).json()
    assert not blocked["ok"] and "block" in blocked["reason"]
    plan = {"cell": "servo_arm_table", "group": "arm", "joints": goal["joints"],
            "backend": "mock"}
    refused = client.post("/viewer/plan", json={**plan, "obstacles": [block]})
    assert refused.status_code == 422 and "block" in refused.text
    refused = client.post(CELL + "/execute", json={
        "group": "arm", "joints": goal["joints"], "backend": "mock", "obstacles": [block]})
    assert refused.status_code == 422 and "block" in refused.text
    # elsewhere, it is planned around and the run's scene holds it
    aside = _block_at([0.0, 0.15, 0.8], "pillar")
    planned = client.post("/viewer/plan", json={**plan, "obstacles": [aside]})
    assert planned.status_code == 200, planned.text
    assert planned.json()["joint_names"] and planned.json()["duration"] > 0
    body = {"group": "arm", "joints": goal["joints"], "backend": "mock", "obstacles": [aside]}
    answer = client.post(CELL + "/execute", json=body)
    assert answer.status_code == 202, answer.text
    run_id = answer.json()["run_id"]
    assert wait_until_done(client, run_id)["status"] == "succeeded"
    first = client.get(f"/viewer/runs/{run_id}/replay").json()["first_scene"]
    pillar = next(o for o in first["objects"] if o["name"] == "pillar")
    assert pillar["pose"]["xyz"] == pytest.approx([0.0, 0.15, 0.8])


@pytest.mark.parametrize(("obstacles", "expected"), [
    ([_block_at([0.3, 0.0, 1.0], "table")], "taken"),
    ([_block_at([0.3, 0.0, 1.0]), _block_at([0.3, 0.1, 1.0])], "unique"),
    ([{"name": "b", "shape": "box", "radius": 0.1, "xyz": [0, 0, 1]}], "a box takes size"),
    ([{"name": "b", "shape": "cylinder", "radius": 0.1, "xyz": [0, 0, 1]}], "length"),
    ([{"name": "b", "shape": "mesh", "xyz": [0, 0, 1]}], "shape"),
    ([{"name": "b", "shape": "sphere", "radius": 1e6, "xyz": [0, 0, 1]}], "radius"),
    ([{"name": "../b", "shape": "sphere", "radius": 0.1, "xyz": [0, 0, 1]}], "name"),
    ([_block_at([0.3, 0.0, 1.0], f"b{k}") for k in range(33)], "obstacles"),
])
def test_a_hostile_obstacle_is_refused_naming_the_field(reader, obstacles, expected):
    answer = reader.post(CELL + "/goal", json={"group": "arm", "joints": {"Revolute 1": 0.8},
                                               "obstacles": obstacles})
    assert answer.status_code == 422, answer.text
    assert expected in answer.text


# The same bad poses as /plan's and a task file's (tests/test_pose_bounds.py): the same
# field, the same message, the same 422.
SHARED_POSE_ERRORS = [
    ({"xyz": [1e308, 0, 0.8], "quat": [0, 0, 0, 1]}, "xyz",
     "must be a finite number within ±1000 m (got 1e+308)"),
    ({"xyz": [0.1, 0, 0.8], "quat": [1e308, 0, 0, 0]}, "quat",
     "must be a unit quaternion [x, y, z, w] (got norm 1e+308)"),
    ({"xyz": [0.1, 0, 0.8], "quat": [0, 0, 0, 0.5]}, "quat",
     "must be a unit quaternion [x, y, z, w] (got norm 0.5)"),
    ({"xyz": [0.1, 0, 0.8], "rpy": [0, 1e308, 0]}, "rpy",
     "must be a finite number within ±100 rad (got 1e+308)"),
]


def test_the_goal_pose_is_the_one_pose_model_with_its_bounds_and_messages(reader):
    from taskrunner.api.routers.viewer_goal import GoalPose, ObstacleBody
    from taskrunner.posespec import TransformFields

    assert issubclass(GoalPose, TransformFields) and issubclass(ObstacleBody, TransformFields)
    for pose, field, message in SHARED_POSE_ERRORS:
        goal = reader.post(CELL + "/goal", json={"group": "arm", "pose": pose})
        plan = reader.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                          "pose": pose})
        assert goal.status_code == plan.status_code == 422, goal.text
        got, planned = goal.json()["detail"][0], plan.json()["detail"][0]
        assert got["loc"][:3] == ["body", "pose", field], got
        assert message in got["msg"] and got["msg"] == planned["msg"], (got, planned)
    both = reader.post(CELL + "/goal", json={"group": "arm", "pose": {
        "xyz": [0.2, 0, 0.8], "rpy": [0, 0, 0], "quat": [0, 0, 0, 1]}})
    assert both.status_code == 422 and "takes only one of 'rpy' or 'quat'" in both.text


def test_a_goal_given_by_rpy_is_the_goal_given_by_quat(reader):
    home = _home(reader)
    at_home = reader.post(CELL + "/goal", json={"group": "arm", "joints": home}).json()
    x, y, z, w = at_home["quat"]
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    target = [at_home["xyz"][0] + 0.02, at_home["xyz"][1], at_home["xyz"][2] - 0.03]
    by_quat = reader.post(CELL + "/goal", json={
        "group": "arm", "pose": {"xyz": target, "quat": at_home["quat"]}, "seed": home}).json()
    by_rpy = reader.post(CELL + "/goal", json={
        "group": "arm", "pose": {"xyz": target, "rpy": [roll, pitch, yaw]}, "seed": home}).json()
    assert by_quat["reachable"] and by_rpy["reachable"]
    assert by_rpy["joints"] == pytest.approx(by_quat["joints"], abs=1e-6)


def test_an_obstacle_pose_outside_the_shared_bounds_is_refused_naming_the_field(reader):
    far = {"name": "b", "shape": "sphere", "radius": 0.1, "xyz": [0, 0, 1e4]}
    answer = reader.post(CELL + "/goal", json={"group": "arm", "joints": {"Revolute 1": 0.8},
                                               "obstacles": [far]})
    assert answer.status_code == 422, answer.text
    detail = answer.json()["detail"][0]
    assert detail["loc"][:4] == ["body", "obstacles", 0, "xyz"], detail
    assert "must be a finite number within ±1000 m (got 10000.0)" in detail["msg"]
