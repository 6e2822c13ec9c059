"""The hand-over task (servo_arm_pair, mock backend) started from the page and watched:
its behaviour tree drawn as a graph shows every node of the task with its final status,
a node's file:line on hover and a leaf's feedback and motion on click; each arm's timeline
(a Gantt of the run's schedule) shows both arms' motions where the run's events put them;
the 3D view fits the robots, labels their tool and base frames, and draws the planner's
collision geometry on its links."""

from __future__ import annotations

from typing import Any

from .conftest import HANG_MS, wait_for_run_end
from .test_viewer_browser import _start, shot


def _nodes(tree: dict[str, Any]) -> list[dict[str, Any]]:
    return [tree, *(n for c in tree["children"] for n in _nodes(c))]


def test_the_handoff_tree_graph_and_both_arms_timelines(page, screenshots):
    run_id = _start(page, "handoff", "mock", 1)
    page.click("#tree-graph")
    detail = wait_for_run_end(page, run_id, hang_ms=HANG_MS)
    assert detail["status"] == "succeeded", detail.get("error")
    page.wait_for_timeout(200)
    shot(page, screenshots, "run_handoff_graph")
    compiled = page.server.api(f"/viewer/runs/{run_id}/tree")["tree"]
    detail = page.server.api(f"/runs/{run_id}")
    events = detail["events"]
    assert not detail["events_more"]

    # every node of the task is drawn, in the compiled tree's order, each with its status
    nodes = _nodes(compiled)
    drawn = page.evaluate("window.__viewer.graph.entries.map(e => [e.node.name, e.node.location, e.status])")
    assert [(n["name"], n["location"]) for n in nodes] == [(d[0], d[1]) for d in drawn]
    finished = {(e["node"], e["location"]): e["status"] for e in events if e["kind"] == "node_finished"}
    leaves = [n for n in nodes if not n["children"]]
    assert len(leaves) > 20 and all((n["name"], n["location"]) in finished for n in leaves)
    for name, location, status in drawn:
        if (name, location) in finished:
            assert status == finished[(name, location)], (name, location, status)
    assert {d[2] for d in drawn} == {"SUCCESS"}  # the composites rolled up too
    assert page.locator("#graph-pane g.gnode").count() == len(nodes)
    assert page.locator("#graph-pane g.gnode.st-SUCCESS").count() == len(nodes)

    # hover: the node's file:line; click on a leaf that moved: its feedback and motion,
    # and the timeline jumps to that motion
    moved = next(e for e in events if e["kind"] == "motion" and "right_arm" in e["node"])
    key = f"{moved['node']}@{moved['location']}"
    page.evaluate(f"window.__viewer.graph.reveal(window.__viewer.graph.byKey.get({key!r}))")
    leaf = page.locator(f"#graph-pane g.gnode[data-key={key!r}]")
    leaf.hover()
    assert moved["location"] in page.text_content("#graph-pane .graph-tip")
    leaf.click()
    detail_text = page.text_content("#graph-pane .graph-detail")
    assert "planned" in detail_text and "motion" in detail_text and "feedback" in detail_text
    assert f"at {moved['data']['sent']:.2f} s on the schedule" in detail_text
    selected = page.evaluate("(() => { const v = window.__viewer; return v.state.timeline.motions[v.state.selected].seq; })()")
    assert selected == moved["seq"]
    shot(page, screenshots, "run_handoff_graph_leaf")

    # each arm's timeline: every motion on the row of each robot whose joints it moves,
    # from its schedule time for as long as it ran
    cell = page.server.api("/viewer/cells/servo_arm_pair")
    robot_of = {j["name"]: j["robot"] for j in cell["joints"]}
    ran = {(e["node"], e["location"]): e["data"]["executed"]["until"] for e in events
           if e["kind"] == "node_finished" and "executed" in e["data"]}
    expected: dict[str, list[tuple[float, float]]] = {}
    for e in events:
        if e["kind"] != "motion":
            continue
        start = e["data"]["sent"]
        end = start + ran[(e["node"], e["location"])]
        for robot in sorted({robot_of[j] for j in e["data"]["trajectory"]["joints"]}):
            expected.setdefault(robot, []).append((start, end))
    assert len(expected) == 2, expected  # both arms moved
    rows = page.evaluate("window.__viewer.gantt.rows()")
    for robot, spans in expected.items():
        bars = [(b["start"], b["end"]) for b in rows[robot] if b["kind"] == "motion"]
        assert len(bars) == len(spans)
        assert all(abs(a - c) < 1e-6 and abs(b - d) < 1e-6 for (a, b), (c, d) in zip(bars, sorted(spans)))
    assert page.locator("#gantt rect.motion").count() == sum(len(s) for s in expected.values())
    page.click(f"#gantt rect.motion[data-seq='{moved['seq']}']")
    assert page.evaluate("(() => { const v = window.__viewer; return v.state.timeline.motions[v.state.selected].seq; })()") == moved["seq"]

    # the camera fits the robots, frames are labelled, the planner's geometry is drawn
    page.evaluate("window.__viewer.stage.controls.target.set(3, 3, 3)")
    page.click("#fit")
    target = page.evaluate("window.__viewer.stage.controls.target.toArray()")
    box = page.evaluate("(() => { const b = window.__viewer.stage.robotBox(); return [b.min.toArray(), b.max.toArray()]; })()")
    assert all(lo <= t <= hi for t, lo, hi in zip(target, *box)), (target, box)
    for group in cell["groups"]:
        if group["tip_link"]:
            x, y, _ = page.evaluate(f"window.__viewer.stage.onScreen({group['tip_link']!r})")
            assert -1 < x < 1 and -1 < y < 1, group["tip_link"]
    page.check("#labels")
    page.wait_for_timeout(150)
    labels = page.eval_on_selector_all(".frame-label", "els => els.filter(e => e.style.display !== 'none').map(e => e.textContent)")
    tips = {g["tip_link"] for g in cell["groups"] if g["tip_link"]}
    assert tips <= {t.split(" · ")[0] for t in labels}
    assert sum(t.endswith(" · base") for t in labels) == len(cell["robots"])
    page.check("#collision")
    page.wait_for_function("window.__viewer.collision && window.__viewer.stage.collision.every(g => g.visible)")
    served = page.server.api("/viewer/cells/servo_arm_pair/collision")
    assert page.evaluate("window.__viewer.stage.collision.length") == sum(len(link["shapes"]) for link in served["links"])
    shot(page, screenshots, "run_handoff_collision_labels")
