"""Each arm's timeline (the web view's gantt.js, run by node on the source file): motions,
waits and holds of a run land on the rows of the arms they belong to, at their times on
the run's schedule. Events of a real two-Panda assembly run (a ``wait_for``: the right arm
waits for the left one's base to be down), and a motion held for another arm."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

import taskrunner

_GANTT = Path(taskrunner.__file__).parent / "viewer" / "src" / "gantt.js"
_FIXTURE = Path(__file__).parents[1] / "fixtures" / "viewer" / "assembly_panda_schedule.json"
_SCRIPT = """
globalThis.requestAnimationFrame = () => {};
const { Gantt } = await import(process.argv[1]);
const input = JSON.parse(require_stdin());
const g = new Gantt(null, input.cell);
for (const e of input.events) g.apply(e);
console.log(JSON.stringify(g.rows()));
function require_stdin() { return require('node:fs').readFileSync(0, 'utf8'); }
"""


def _rows(events: list[dict[str, Any]], joints: list[str]) -> dict[str, list[dict[str, Any]]]:
    node = shutil.which("node")
    if node is None:
        pytest.skip("no node on this machine (it builds the web view)")
    cell = {"joints": [{"name": j, "robot": j.split("_")[0]} for j in joints],
            "robots": [{"name": "left"}, {"name": "right"}]}
    script = "import { createRequire } from 'node:module'; const require = createRequire(import.meta.url);" + _SCRIPT
    done = subprocess.run([node, "--input-type=module", "-e", script, _GANTT.as_uri()],
                          input=json.dumps({"cell": cell, "events": events}), capture_output=True,
                          text=True, timeout=30, check=False)
    assert done.returncode == 0, done.stderr
    return dict(json.loads(done.stdout))


def test_a_wait_for_is_drawn_on_the_waiting_arm_between_its_motions():
    events = json.loads(_FIXTURE.read_text())["events"]
    joints = sorted({j for e in events if e["kind"] == "motion" for j in e["data"]["trajectory"]["joints"]})
    rows = _rows(events, joints)
    timed = [e for e in events if e["kind"] == "wait" and "since" in e["data"]]
    assert len(timed) == 1
    wait = timed[0]["data"]
    right = rows["right"]
    waits = [b for b in right if b["kind"] != "motion"]
    assert [(b["kind"], b["start"], b["end"]) for b in waits] == [("wait", wait["since"], wait["until"])]
    assert not [b for b in rows["left"] if b["kind"] != "motion"]
    # the waiting arm's next motion starts when the wait ends; its last one before ends at its start
    after = min((b for b in right if b["kind"] == "motion" and b["start"] >= wait["until"] - 1e-6),
                key=lambda b: b["start"])
    assert after["start"] == pytest.approx(wait["until"], abs=1e-6)
    assert max(b["end"] for b in right if b["kind"] == "motion" and b["end"] <= wait["since"] + 1e-4) \
        == pytest.approx(wait["since"], abs=1e-4)  # executed.until: 0.1 ms
    # every motion on the row of the arm whose joints it moves, for as long as it ran
    for e in (e for e in events if e["kind"] == "motion"):
        arms = {j.split("_")[0] for j in e["data"]["trajectory"]["joints"]}
        for arm in arms:
            assert [b for b in rows[arm] if b["kind"] == "motion" and b["seq"] == e["seq"]
                    and b["start"] == e["data"]["sent"]], (arm, e["node"])


def test_a_held_motion_shows_its_hold_from_where_its_arm_stopped():
    traj = {"joints": ["right_j1"], "times": [0.0, 1.0]}
    events = [
        {"seq": 1, "kind": "motion", "node": "a", "location": "t.yaml:3", "data": {"start": 0.0, "sent": 0.0, "trajectory": traj}},
        {"seq": 2, "kind": "node_finished", "node": "a", "location": "t.yaml:3", "status": "SUCCESS", "data": {"executed": {"until": 1.0}}},
        {"seq": 3, "kind": "wait", "node": "b", "location": "t.yaml:4", "message": "held for the left arm", "data": {"hold": True}},
        {"seq": 4, "kind": "motion", "node": "b", "location": "t.yaml:4", "data": {"start": 2.5, "sent": 2.5, "trajectory": traj}},
        {"seq": 5, "kind": "node_finished", "node": "b", "location": "t.yaml:4", "status": "SUCCESS", "data": {"executed": {"until": 0.4}}},
    ]
    rows = _rows(events, ["right_j1"])
    assert [(b["kind"], b["start"], b["end"]) for b in rows["right"]] == [
        ("motion", 0.0, 1.0), ("hold", 1.0, 2.5), ("motion", 2.5, 2.9)]
    assert rows["left"] == []
