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


def test_a_checked_task_shows_each_arms_timeline_as_the_check_planned_it(page, screenshots):
    """tray_pair in the Task view, before anything runs: the check's schedule of its
    parallel drawn as both arms' Gantt rows, every motion at its planned start and end; a
    plan-only preview keeps it."""
    from .test_viewer_browser import enter_token, shot

    page.goto(page.server.url + "/#/task/tray_pair")
    enter_token(page)
    page.wait_for_function("window.__viewer.checkGantts && window.__viewer.checkGantts.length > 0",
                           timeout=60_000)
    report = page.evaluate("window.__viewer.check")
    assert report["ok"], report["problems"]
    (schedule,) = [s for s in report["schedules"] if s["timeline"]]
    timeline = schedule["timeline"]
    assert len(timeline) == schedule["motions"] and max(m["end"] for m in timeline) == \
        pytest.approx(schedule["makespan"], abs=1e-6)
    robot_of = {j["name"]: j["robot"] for j in page.server.api("/viewer/cells/servo_arm_pair")["joints"]}
    expected: dict[str, list[tuple[float, float]]] = {}
    for m in timeline:
        for arm in {robot_of[j] for j in m["joints"]}:
            expected.setdefault(arm, []).append((m["start"], m["end"]))
    assert sorted(expected) == ["left", "right"]
    # the arms move at once (the check's overlaps), each arm's motions one after another
    for spans in expected.values():
        spans.sort()
        assert all(b[0] >= a[1] - 1e-6 for a, b in zip(spans, spans[1:]))
    assert any(a0 < b1 and b0 < a1 for a0, a1 in expected["left"] for b0, b1 in expected["right"])

    def drawn() -> dict[str, list[tuple[float, float, float]]]:
        rects = page.eval_on_selector_all(
            "#gantt rect.motion", "rs => rs.map(r => [r.dataset.arm, +r.dataset.start, +r.dataset.end, "
                                  "+r.getAttribute('x'), r.getBoundingClientRect().width])")
        out: dict[str, list[tuple[float, float, float]]] = {}
        for arm, start, end, x, shown in rects:
            assert shown > 0, (arm, start)  # laid out on the page, not only in the DOM
            out.setdefault(arm, []).append((start, end, x))
        return {arm: sorted(bars) for arm, bars in out.items()}

    def assert_drawn_as_planned() -> None:
        bars = drawn()
        assert sorted(bars) == ["left", "right"]
        for arm, spans in expected.items():
            assert len(bars[arm]) == len(spans), arm
            assert [t for s, e, _ in bars[arm] for t in (s, e)] == \
                pytest.approx([t for span in spans for t in span], abs=1e-6), arm
        # on one time axis: x is linear in the planned start, for both rows
        points = [(s, x) for arm_bars in bars.values() for s, _, x in arm_bars]
        (s0, x0), (s1, x1) = min(points), max(points)
        assert s1 > s0 + 1 and x1 > x0
        scale = (x1 - x0) / (s1 - s0)
        assert all(abs(x0 + (s - s0) * scale - x) < 0.01 for s, x in points)
        assert page.is_visible("#gantt") and "planned by the check" in page.text_content("#gantt")

    assert_drawn_as_planned()
    shot(page, screenshots, "task_tray_pair_check_gantt")
    page.click("text=plan only (preview)")
    page.wait_for_function("window.__viewer.preview !== undefined", timeout=60_000)
    assert_drawn_as_planned()


_PAIR_WAIT = """\
task: branch_wait
cell: {cell}
steps:
  - parallel:
      - sequence:
          - go: {{group: left_arm, to: PickUp}}
          - wait: {{seconds: 1.0}}
          - go: {{group: left_arm, to: Candle}}
      - sequence:
          - go: {{group: right_arm, to: PickUp}}
          - go: {{group: right_arm, to: home}}
  - wait: {{seconds: 0.5}}
  - go: {{group: left_arm, to: home}}
"""


def _cell_rows(cell_dict: dict[str, Any], events: list[dict[str, Any]],
               schedule: dict[str, Any] | None = None) -> dict[str, list[dict[str, Any]]]:
    node = shutil.which("node")
    if node is None:
        pytest.skip("no node on this machine (it builds the web view)")
    script = ("import { createRequire } from 'node:module'; const require = createRequire(import.meta.url);"
              + _SCRIPT.replace("for (const e of input.events) g.apply(e);",
                                "if (input.schedule) g.applySchedule(input.schedule); "
                                "for (const e of input.events) g.apply(e);"))
    done = subprocess.run([node, "--input-type=module", "-e", script, _GANTT.as_uri()],
                          input=json.dumps({"cell": cell_dict, "events": events,
                                            "schedule": schedule}),
                          capture_output=True, text=True, timeout=30, check=False)
    assert done.returncode == 0, done.stderr
    return dict(json.loads(done.stdout))


def test_a_wait_step_is_drawn_on_its_branchs_arm_in_the_run_and_in_the_check(tmp_path):
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot.cell import load_cell
    from taskrunner.tree.check import check_task

    cell_file = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
    path = tmp_path / "branch_wait.yaml"
    path.write_text(_PAIR_WAIT.format(cell=cell_file))
    model = load_cell(cell_file).model
    cell = {"joints": [{"name": j.name, "robot": j.robot} for j in model.joints],
            "robots": [{"name": i.name} for i in model.instances]}
    result = taskrunner.run_task(path, backend="mock")
    assert result.status == "succeeded", result.error
    events = [e.as_dict() for e in result.events]
    # The wait steps (the others: where the schedule held an arm for the other one).
    waits = [e for e in events if e["kind"] == "wait" and "lane" in e["data"]]
    assert [e["data"]["lane"] != [] for e in waits] == [True, False]  # a branch's, the task's
    rows = _cell_rows(cell, events)
    left, right = (rows[n] for n in ("left", "right"))
    branch, whole = (e["data"] for e in waits)
    # The branch's wait on the left arm's row only; the task's on both.
    assert ("wait", branch["since"], branch["until"]) in [(b["kind"], b["start"], b["end"])
                                                         for b in left]
    for row in (left, right):
        assert ("wait", whole["since"], whole["until"]) in [(b["kind"], b["start"], b["end"])
                                                            for b in row]
    def spans(row: list[dict[str, Any]]) -> list[tuple[float, float]]:
        return [(b["start"], b["end"]) for b in row if b["kind"] == "wait"]

    assert (branch["since"], branch["until"]) not in spans(right)
    # The check's schedule of the parallel: its wait step on the left arm's row too.
    report = check_task(path)
    assert report.ok, report.problems
    (proof,) = [s.to_dict() for s in report.schedules]
    (planned,) = [w for w in proof["waits"] if w["reason"] == "a wait step of 1 s"]
    assert planned["joints"] and all(j.startswith("left_") for j in planned["joints"])
    checked = _cell_rows(cell, [], proof)
    assert (planned["since"], planned["until"]) in spans(checked["left"])
    assert (planned["since"], planned["until"]) not in spans(checked["right"])
