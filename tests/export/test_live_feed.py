"""The live Foxglove feed: a WebSocket client speaking Foxglove's protocol receives
/joint_states while a run goes (the servo arm's go_home on the mock backend played at
4x), each motion's /display_planned_path as it is sent, and /robot_description when it
subscribes, after it was first sent."""

from __future__ import annotations

import io
import struct
import threading
import time
from pathlib import Path
from typing import Any

import pytest
from foxglove_client import decode, subscribe
from websockets.sync.client import connect

from taskrunner.errors import ArgumentError
from taskrunner.export.live import FoxgloveFeed, FoxgloveFeedOptions
from taskrunner.resources import DATA_ROOT, resolve_cell
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.records import load_record
from taskrunner.runtime.session import run_task_file


def test_a_client_receives_joint_states_during_a_run(tmp_path: Path) -> None:
    cell = load_cell(resolve_cell("servo_arm_table"))
    received: list[tuple[float, str, Any]] = []  # (monotonic s, topic, message)
    ready, done = threading.Event(), threading.Event()
    with FoxgloveFeed(cell, FoxgloveFeedOptions(port=0, rate_hz=50)) as feed:
        def client() -> None:
            with connect(feed.url, subprotocols=["foxglove.sdk.v1"]) as ws:
                subscriptions = subscribe(ws, ["/joint_states", "/robot_description",
                                               "/display_planned_path"])
                ready.set()
                while not done.is_set():
                    try:
                        frame = ws.recv(timeout=0.2)
                    except TimeoutError:
                        continue
                    if isinstance(frame, bytes) and frame[0] == 1:  # message data
                        sub, _ = struct.unpack_from("<IQ", frame, 1)
                        topic, schema, definition = subscriptions[sub]
                        received.append((time.monotonic(), topic,
                                         decode(frame[13:], schema, definition)))

        listener = threading.Thread(target=client, daemon=True)
        listener.start()
        assert ready.wait(15)
        time.sleep(0.2)  # the subscription reaches the server
        started = time.monotonic()
        code = run_task_file(DATA_ROOT / "tasks" / "go_home.yaml", backend="mock", speed=4.0,
                             runs_dir=tmp_path, worker=False, out=io.StringIO(),
                             watch=[feed.follow])
        ended = time.monotonic()
        time.sleep(0.3)
        done.set()
        listener.join(5)
    assert code == 0
    states = [(t, m) for t, topic, m in received if topic == "/joint_states"]
    during = [m for t, m in states if started < t < ended]
    assert len(during) >= 10
    assert all(m.name == list(cell.model.joint_names) for _, m in states)
    joint = cell.model.joint_names.index("Revolute 2")
    assert len({round(float(m.position[joint]), 4) for m in during}) >= 5  # it moved
    descriptions = [m for _, topic, m in received if topic == "/robot_description"]
    assert descriptions and descriptions[0].data.startswith("<robot")
    # One /display_planned_path per motion, as sent: the record's trajectory, from the
    # cell's state then.
    record = load_record(next(tmp_path.glob("*.json")))
    motions = [e for e in record.events if e.kind == "motion"]
    planned = [(t, m) for t, topic, m in received if topic == "/display_planned_path"]
    assert len(motions) == len(planned) == 2
    for event, (t, message) in zip(motions, planned, strict=True):
        assert t > started
        trajectory = event.data["trajectory"]
        sent = message.trajectory[0].joint_trajectory
        assert message.model_id == cell.model.instances[0].name
        assert list(sent.joint_names) == trajectory["joints"]
        assert [list(p.positions) for p in sent.points] == trajectory["positions"]
        assert [p.time_from_start.sec * 10**9 + p.time_from_start.nanosec
                for p in sent.points] == [round(s * 1e9) for s in trajectory["times"]]
        state = message.trajectory_start.joint_state
        assert list(state.name) == list(cell.model.joint_names)
        start = dict(zip(state.name, state.position))
        assert [start[j] for j in trajectory["joints"]] == pytest.approx(
            trajectory["positions"][0], abs=1e-6)


def test_feed_options_are_checked() -> None:
    with pytest.raises(ArgumentError, match="'port' must be 0..65535"):
        FoxgloveFeedOptions(port=70000)
    with pytest.raises(ArgumentError, match="'rate_hz' must be 1..1000"):
        FoxgloveFeedOptions(rate_hz=0)
