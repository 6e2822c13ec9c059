"""/tasks/check of a parallel whose branches move at once: what its schedule proves."""

from __future__ import annotations


def test_check_answers_the_least_clearance_overlaps_and_waits_of_a_parallel(client):
    report = client.post("/tasks/check", json={"task": "assembly_panda.yaml"}).json()
    assert report["ok"] is True, report["problems"]
    (schedule,) = report["schedules"]
    least = schedule["least_clearance"]
    # The schedule keeps the arms 5 mm apart (tree.schedule.CLEARANCE); the least distance
    # lies in [lower, distance], a bracket at most 1 mm wide, so the measured distance is
    # at least the clearance and the bracket's lower end within the bracket of it.
    assert least["lower"] <= least["distance"] <= least["lower"] + 0.001
    assert least["distance"] >= 0.005 and least["lower"] >= 0.005 - 0.001
    assert len(least["links"]) == 2 and all(link.startswith(("left_", "right_"))
                                            for link in least["links"])
    assert least["time"] >= 0 and all(s is None or ".yaml:" in s for s in least["steps"])
    assert schedule["overlaps"] and all(o["end"] > o["start"] for o in schedule["overlaps"])
    # The stacking waits for the base to be down ('wait_for' at line 25).
    (wait,) = [w for w in schedule["waits"] if w["step"].endswith("assembly_panda.yaml:25")]
    assert wait["until"] > wait["since"] and "'base down'" in wait["reason"]
    assert schedule["motions"] == 18 and schedule["makespan"] > 0
