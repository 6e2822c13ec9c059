"""The web view in a real browser (chromium, WebGL through SwiftShader): the two-arm cell
renders and moves to a named pose; a hand-over started from the page is followed live,
its tree nodes turning to success in order, and replayed with the bar carried from one
gripper to the other; a cancelled run shows where it stopped. No browser errors."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import pytest

from .conftest import HANG_MS, RUN_ENDED, TOKEN, wait_for_run_end

# The 3D canvas, shrunk to 96 x 60 grey values (0..255), read in the page.
_PIXELS = """() => {
  const src = document.querySelector('#view3d canvas');
  const c = document.createElement('canvas'); c.width = 96; c.height = 60;
  const g = c.getContext('2d'); g.drawImage(src, 0, 0, 96, 60);
  const d = g.getImageData(0, 0, 96, 60).data; const out = [];
  for (let i = 0; i < d.length; i += 4) out.push(Math.round((d[i] + d[i + 1] + d[i + 2]) / 3));
  return out;
}"""


# The 3D canvas at full resolution: kept in the page, then the fraction of its pixels
# that changed by more than 12 grey levels since (thin lines vanish in the 96 x 60 copy).
_KEEP_FULL = """() => {
  const src = document.querySelector('#view3d canvas');
  const c = document.createElement('canvas'); c.width = src.width; c.height = src.height;
  c.getContext('2d').drawImage(src, 0, 0);
  window.__kept = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
}"""
_CHANGED_FULL = """() => {
  const src = document.querySelector('#view3d canvas');
  const c = document.createElement('canvas'); c.width = src.width; c.height = src.height;
  c.getContext('2d').drawImage(src, 0, 0);
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data, k = window.__kept;
  let n = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (Math.abs((d[i] + d[i + 1] + d[i + 2]) - (k[i] + k[i + 1] + k[i + 2])) / 3 > 12) n++;
  }
  return n / (d.length / 4);
}"""


def enter_token(page: Any) -> None:
    """Type the token into the page, as a user does."""
    page.fill("#token", TOKEN)
    page.click("#token-form button[type=submit]")


def pixels(page: Any) -> list[int]:
    return list(page.evaluate(_PIXELS))


def changed(a: list[int], b: list[int], by: int = 12) -> float:
    return sum(abs(x - y) > by for x, y in zip(a, b)) / len(a)


def shot(page: Any, folder: Path, name: str) -> Path:
    path = folder / f"{name}.png"
    page.screenshot(path=str(path))
    return path


def test_the_two_arm_cell_renders_and_moves_to_a_named_pose(page, screenshots):
    page.goto(page.server.url + "/#/cell/servo_arm_pair")
    enter_token(page)
    page.wait_for_function("window.__viewer.firstFrame !== null", timeout=20_000)
    page.wait_for_timeout(200)
    first_frame_ms = page.evaluate("window.__viewer.firstFrame")
    print(f"first frame of the two-arm cell: {first_frame_ms:.0f} ms after navigation")
    before = pixels(page)
    shot(page, screenshots, "cell_servo_arm_pair")
    # not blank: many grey levels, the robots' colours among them
    assert len(set(before)) > 20
    assert max(before) - min(before) > 100
    page.select_option("select[name='pose:left_arm']", "HandOff")
    page.wait_for_timeout(300)
    after = pixels(page)
    shot(page, screenshots, "cell_servo_arm_pair_left_HandOff")
    assert changed(before, after) > 0.005, "the left arm's pixels did not change"
    # frames on demand: every link's axes drawn
    page.evaluate(_KEEP_FULL)
    page.check("#frames")
    page.wait_for_timeout(200)
    assert page.evaluate("window.__viewer.stage.frames.every(f => f.visible)")
    assert page.evaluate(_CHANGED_FULL) > 0.0005
    assert "token" not in page.url.lower() and TOKEN not in page.url


def _start(page: Any, task: str, backend: str, speed: float) -> str:
    page.goto(page.server.url + "/#/runs")
    enter_token(page)
    page.wait_for_selector(f"#start-task option[value='{task}']", state="attached")
    page.select_option("#start-task", task)
    page.select_option("#start-backend", backend)
    page.fill("#start-speed", str(speed))
    page.click("#start-run")
    page.wait_for_function("location.hash.startsWith('#/run/')")
    return str(page.evaluate("location.hash.split('/')[2]"))


def test_a_handoff_started_from_the_page_runs_live_and_replays_the_bar_carried(
        page, screenshots):
    run_id = _start(page, "handoff", "sim", 8)
    page.wait_for_selector("#run-tree li.st-RUNNING", timeout=30_000)
    shot(page, screenshots, "run_handoff_live")
    detail = wait_for_run_end(page, run_id, hang_ms=HANG_MS)
    assert detail["status"] == "succeeded", detail.get("error")
    shot(page, screenshots, "run_handoff_finished")
    # the tree's leaves turned to success in the order the run finished them
    expected = [f"{e['node']}@{e['location'] or ''}" for e in detail["events"]
                if e["kind"] == "node_finished" and e["status"] == "SUCCESS"]
    seen = page.evaluate("window.__viewer.successOrder")
    assert seen == expected
    leaves = page.eval_on_selector_all("#run-tree li[data-key]", "els => els.map(e => e.className)")
    assert leaves and all("st-SUCCESS" in c for c in leaves)
    # the replay: the bar rides on the left gripper, then on the right one
    carriers = page.evaluate("""window.__viewer.state.timeline.motions.map(m =>
        (m.scene.objects.find(o => o.name === 'bar') || {}).attached_to || null)""")
    left = [i for i, c in enumerate(carriers) if c and c.startswith("left_")]
    right = [i for i, c in enumerate(carriers) if c and c.startswith("right_")]
    assert left and right and max(left) < max(right)
    # scrub: the arm moves, and the bar with it
    page.evaluate("window.__viewer.state.playing = false")
    page.fill("#scrub", "0")
    page.dispatch_event("#scrub", "input")
    page.wait_for_timeout(150)
    start_pixels = pixels(page)
    bar_start = page.evaluate("window.__viewer.stage.objectWorld('bar')")
    page.fill("#scrub", "600")
    page.dispatch_event("#scrub", "input")
    page.wait_for_timeout(150)
    shot(page, screenshots, "run_handoff_replay_60pct")
    assert changed(start_pixels, pixels(page)) > 0.005, "the replay did not move the arms"
    bar_mid = page.evaluate("window.__viewer.stage.objectWorld('bar')")
    assert max(abs(a - b) for a, b in zip(bar_start, bar_mid)) > 0.02
    page.fill("#scrub", "1000")
    page.dispatch_event("#scrub", "input")
    page.wait_for_timeout(150)
    bar_end = page.evaluate("window.__viewer.stage.objectWorld('bar')")
    assert bar_end[0] > 0.0 > bar_start[0], "the bar ends on the right arm's side"
    shot(page, screenshots, "run_handoff_replay_end")
    # a motion selected: its plot is drawn
    page.click("#motions li:nth-child(2)")
    page.wait_for_timeout(150)
    shot(page, screenshots, "run_handoff_plot")


def test_a_cancelled_run_shows_where_it_stopped(page, screenshots):
    run_id = _start(page, "pick_place", "sim", 1)
    # Two motions sent, or the run over: planning them is slow on a busy machine (the
    # server's first plans), and a run that ended is reported at once, not waited for.
    page.wait_for_function("(window.__viewer.state.timeline && "
                           "window.__viewer.state.timeline.motions.length >= 2) || "
                           f"{list(RUN_ENDED)}.includes(window.__viewer.runStatus)",
                           timeout=HANG_MS)
    assert page.evaluate("window.__viewer.runStatus") not in RUN_ENDED, \
        page.server.api(f"/runs/{run_id}").get("error")
    time.sleep(0.3)  # into the second motion, most often
    page.click("text=cancel run")
    detail = wait_for_run_end(page, run_id, hang_ms=HANG_MS)
    assert detail["status"] == "cancelled", detail.get("error")
    # the node the cancel stopped, drawn as such (the tree follows the run's events)
    page.wait_for_selector("#run-tree li.st-INVALID[data-key]", timeout=HANG_MS)
    shot(page, screenshots, "run_cancelled")
    stopped = page.eval_on_selector_all("#run-tree li.st-INVALID[data-key]",
                                        "els => els.map(e => e.dataset.key)")
    last_started = [e for e in detail["events"] if e["kind"] == "node_started"][-1]
    assert stopped == [f"{last_started['node']}@{last_started['location']}"]
    banner = page.text_content(".banner")
    assert "cancelled" in banner
    # the replay stops where the arm stopped: the last motion runs as far as the record
    # says the backend took it (part of its way when the cancel came during it; all of
    # it when, on a busy machine, the cancel came between two motions)
    ran, duration = page.evaluate("""(() => { const m = window.__viewer.state.timeline.motions;
        const last = m[m.length - 1]; return [last.ran, last.trajectory.duration]; })()""")
    executed = [e["data"]["executed"]["until"] for e in detail["events"]
                if e["kind"] == "node_finished" and "executed" in (e.get("data") or {})]
    assert executed and 0 < ran <= duration
    assert ran == pytest.approx(min(executed[-1], duration), abs=1e-4)
    if ran < duration - 1e-3:
        assert "stopped at" in page.text_content("#motions")
