"""/cells, /cells/{id}, /cells/{id}/state, /tasks/check and /health."""

from __future__ import annotations

from apitest import AUTH, wait_until_done


def test_cells_are_listed_with_their_names(client):
    cells = {c["id"]: c for c in client.get("/cells").json()}
    assert {"servo_arm_table", "servo_arm_pair"} <= set(cells)
    assert cells["servo_arm_pair"]["name"] == "servo_arm_pair"


def test_a_cell_shows_robots_groups_poses_and_objects(client):
    cell = client.get("/cells/servo_arm_pair").json()
    assert [r["name"] for r in cell["robots"]] == ["left", "right"]
    assert cell["robots"][0]["xyz"] == [-0.25, 0.0, 0.75]
    groups = {g["name"]: g for g in cell["groups"]}
    assert "HandOff" in groups["left_arm"]["poses"]
    assert groups["both_arms"]["joints"][:1] == ["left_Revolute 1"]
    assert cell["objects"][0]["name"] == "table" and cell["objects"][0]["shape"] == "box"


def test_an_unknown_cell_answers_404(client):
    for url in ("/cells/atlantis", "/cells/atlantis/state"):
        answer = client.get(url)
        assert answer.status_code == 404 and "unknown cell 'atlantis'" in answer.json()["detail"]


def test_cell_state_follows_the_runs_and_shows_attached_objects(client):
    before = client.get("/cells/servo_arm_table/state", params={"backend": "mock"}).json()
    assert before["attached"] == [] and before["running"] == []
    yaml = ("task: t\ncell: ../robots/cells/servo_arm_table.yaml\n"
            "objects:\n  - {name: cube, shape: box, size: [0.025, 0.025, 0.025], "
            "pose: {xyz: [0.19, 0.04, 0.7625]}}\n"
            "steps:\n  - pick: {arm: arm, object: cube, grasp: top}\n")
    run_id = client.post("/runs", json={"yaml": yaml, "backend": "mock"},
                         headers=AUTH).json()["run_id"]
    assert wait_until_done(client, run_id)["status"] == "succeeded"
    after = client.get("/cells/servo_arm_table/state", params={"backend": "mock"}).json()
    assert after["attached"] == [{"name": "cube", "link": after["attached"][0]["link"]}]
    assert after["joints"] != before["joints"]
    assert client.get("/cells/servo_arm_table/state",
                      params={"backend": "real"}).status_code == 422


def test_check_reports_the_problems_of_inline_yaml_at_their_lines(client):
    yaml = ("task: t\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n"
            "  - go: {group: arm, to: Candle}\n  - go: {group: arm, to: nowhere}\n")
    report = client.post("/tasks/check", json={"yaml": yaml}).json()
    assert report["ok"] is False and report["cell"] == "servo_arm_table"
    [problem] = report["problems"]
    assert problem["line"] == 5 and problem["file"].endswith("tasks/inline.yaml")
    assert problem["text"].startswith(problem["file"] + ":5: 'nowhere'")


def test_check_of_a_good_task_file_is_ok(client):
    report = client.post("/tasks/check", json={"task": "pick_place.yaml"}).json()
    assert report == {"ok": True, "cell": "servo_arm_table", "steps": report["steps"],
                      "problems": [], "schedules": []}
    assert report["steps"] > 0


def test_health_answers_without_a_token(client):
    assert client.get("/health").json() == {"status": "ok", "runs_in_flight": 0, "auth": True}
