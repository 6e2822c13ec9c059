"""run-task serve --foxglove: the API's runs live over Foxglove's WebSocket protocol, one
feed per cell; a run's thread never waits for the feed."""

from __future__ import annotations

import sys
import time
from pathlib import Path
from types import SimpleNamespace

import pytest
from fastapi.testclient import TestClient

from taskrunner.api import create_app
from taskrunner.errors import ArgumentError
from taskrunner.export.cellfeeds import CellFeed, CellFeeds, CellFeedsOptions
from taskrunner.export.live import FoxgloveFeedOptions
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.events import EventLog

sys.path.insert(0, str(Path(__file__).parents[1] / "api"))
from apitest import AUTH, make_settings, wait_until_done
from foxglove_client import Listener


def test_a_client_receives_joint_states_of_a_run_started_over_rest(tmp_path: Path) -> None:
    settings = make_settings(tmp_path / "state", foxglove_port=0, sim_speed=2.0)
    with TestClient(create_app(settings), headers=AUTH) as client:
        feeds = client.app.state.feeds  # type: ignore[attr-defined]
        assert feeds.url_of("servo_arm_table") is None  # opened by the cell's first run
        answer = client.post("/runs", json={"task": "go_home", "backend": "sim"})
        assert answer.status_code == 202, answer.text
        run_id = answer.json()["run_id"]
        url = feeds.url_of("servo_arm_table")
        assert url is not None and url.startswith("ws://127.0.0.1:")
        listener = Listener(url, ["/joint_states", "/tf", "/rosout"])
        assert listener.ready.wait(15)
        run = wait_until_done(client, run_id)
        time.sleep(0.3)  # the last state reaches the client
        listener.stop()
    assert run["status"] == "succeeded"
    states = listener.messages("/joint_states")
    assert len(states) >= 10
    cell = load_cell(resolve_cell("servo_arm_table"))
    assert all(m.name == list(cell.model.joint_names) for m in states)
    joint = cell.model.joint_names.index("Revolute 2")
    assert len({round(float(m.position[joint]), 4) for m in states}) >= 5  # it moved
    assert listener.messages("/tf")
    loggers = {m.name for m in listener.messages("/rosout")}
    assert loggers and all(name.startswith(f"{run_id}.") for name in loggers)


def test_each_cell_of_the_folder_has_its_own_port() -> None:
    feeds = CellFeeds(["handoff_cell", "servo_arm_table"], CellFeedsOptions(port=9000))
    assert feeds.ports() == {"handoff_cell": 9000, "servo_arm_table": 9001}
    with pytest.raises(ArgumentError, match="leaves no port for the cell number 2"):
        CellFeeds(["a", "b"], CellFeedsOptions(port=65535))
    with pytest.raises(ArgumentError, match="'max_queued' must be an integer >= 1"):
        CellFeedsOptions(max_queued=0)


def test_a_run_never_waits_for_a_feed_that_is_behind() -> None:
    cell = load_cell(resolve_cell("servo_arm_table"))
    feed = CellFeed(cell, FoxgloveFeedOptions(port=0), max_queued=10)
    feed.close()  # nothing drains its queue any more: the worst case of a slow feed
    events = EventLog()
    runner = SimpleNamespace(events=events, backend=SimpleNamespace(
        joint_names=cell.model.joint_names), record=SimpleNamespace(run_id="r1"))
    follow = feed.attach(runner, frozenset())  # type: ignore[arg-type]
    for i in range(50):
        events.emit("message", f"event {i}")
    assert feed.dropped == 40
    assert len(events.events(0)) == 50  # the run's own log has them all
    feed.detach(follow)
