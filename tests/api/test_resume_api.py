"""POST /runs/{id}/resume: a cancelled run continued from where it stopped; refusals."""

from __future__ import annotations

import textwrap
import time

from apitest import wait_until_done

TWO_GOES = textwrap.dedent("""\
    task: two_goes
    cell: ../robots/cells/servo_arm_table.yaml
    steps:
      - go: {group: arm, to: Candle}
      - go: {group: arm, to: home}
    """)


def test_a_cancelled_run_resumes_from_where_it_stopped_and_a_finished_one_is_refused(client):
    started = client.post("/runs", json={"yaml": TWO_GOES, "backend": "sim", "speed": 4,
                                         "check": False})
    assert started.status_code == 202, started.text
    run_id = started.json()["run_id"]
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:  # until the first go has ended
        events = client.get(f"/runs/{run_id}", params={"limit": 1000}).json()["events"]
        if any(e["kind"] == "checkpoint" for e in events):
            break
        time.sleep(0.02)
    assert client.post(f"/runs/{run_id}/cancel").status_code == 202
    assert wait_until_done(client, run_id)["status"] == "cancelled"

    resumed = client.post(f"/runs/{run_id}/resume", json={})
    while resumed.status_code == 409 and time.monotonic() < deadline:
        # The run's status says cancelled a moment before its thread lets go of the arm.
        time.sleep(0.02)
        resumed = client.post(f"/runs/{run_id}/resume", json={})
    assert resumed.status_code == 202, resumed.text
    new_id = resumed.json()["run_id"]
    run = wait_until_done(client, new_id, timeout=60)
    assert run["status"] == "succeeded", run.get("error")
    first = run["events"][0]
    assert first["kind"] == "run_started" and first["data"]["resumes"] == run_id
    started = [e["location"] for e in run["events"] if e["kind"] == "node_started"]
    assert len(started) == 1 and started[0].endswith("inline.yaml:5")  # the second go only

    # The web view's replay links the two runs both ways: one story.
    assert client.get(f"/viewer/runs/{new_id}/replay").json()["resumes"] == run_id
    story = client.get(f"/viewer/runs/{run_id}/replay").json()
    assert story["resumed_by"] == [new_id] and story["resumes"] is None

    again = client.post(f"/runs/{new_id}/resume", json={})
    assert again.status_code == 422
    assert "it succeeded: there is nothing left to do" in again.json()["detail"]
    assert client.post("/runs/nope/resume", json={}).status_code == 404
    bad = client.post(f"/runs/{run_id}/resume", json={"objects": {"cube": [1, 2]}})
    assert bad.status_code == 422 and "'objects.cube' must be [x, y, z]" in bad.json()["detail"]


def test_a_server_run_records_how_the_server_loads_robots(tmp_path):
    from apitest import AUTH, make_settings
    from fastapi.testclient import TestClient

    from taskrunner.api import create_app
    from taskrunner.robot.options import LoadOptions

    app = create_app(make_settings(tmp_path / "state", collision="convex"))
    with TestClient(app, headers=AUTH) as client:
        started = client.post("/runs", json={"yaml": TWO_GOES, "backend": "mock",
                                             "check": False})
        assert started.status_code == 202, started.text
        run_id = started.json()["run_id"]
        assert wait_until_done(client, run_id)["status"] == "succeeded"
        record = app.state.manager.record(run_id)
    # What run-task resume and export load its cell with, from the record alone.
    assert record.load_options == LoadOptions(collision="convex").as_data()
