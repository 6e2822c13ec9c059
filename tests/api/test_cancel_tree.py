"""``GET /runs/{id}`` after a cancel: the tree shows what ran (done steps succeeded, the
interrupted one cancelled), not a tree reset to never-started."""

from __future__ import annotations

from apitest import AUTH, wait_for_event, wait_until_done

SLOW_SECOND = (
    "task: wait_then_go\n"
    "cell: servo_arm_table\n"
    "steps:\n"
    "  - wait: {seconds: 0.01}\n"
    "  - go: {group: arm, to: Candle, velocity_scaling: 0.02, acceleration_scaling: 0.02}\n"
    "  - go: {group: arm, to: home}\n")


def test_the_rest_tree_after_a_cancel_keeps_the_finished_and_the_cancelled_steps(client):
    answer = client.post("/runs", json={"yaml": SLOW_SECOND, "backend": "sim"}, headers=AUTH)
    assert answer.status_code == 202, answer.text
    run_id = answer.json()["run_id"]
    wait_for_event(client, run_id, "motion")  # the slow go moves (the wait is done)
    assert client.post(f"/runs/{run_id}/cancel", headers=AUTH).status_code == 202
    run = wait_until_done(client, run_id)
    assert run["status"] == "cancelled"
    leaves = [line.strip() for line in run["tree"].splitlines()
              if line.strip().startswith("-->")]
    assert leaves[0] == "--> wait [✓]"
    assert leaves[1].startswith("--> go arm [-] -- cancelled")
    assert leaves[2] == "--> go arm [-]"
    again = client.get(f"/runs/{run_id}").json()  # from the store, as saved
    assert again["tree"] == run["tree"]
