"""A live Foxglove feed: a cell's robots streamed over Foxglove's WebSocket protocol.

:class:`FoxgloveFeed` serves the topics of an MCAP export (:mod:`.timeline`) live, with
the same ROS 2 messages and bytes: ``/joint_states`` and ``/tf`` from the backend's
joint state polled ``rate_hz`` times a second while a run goes (what the controller
reports, not the plan), ``/rosout`` for each event, ``/scene_objects`` and
``/display_planned_path`` (the trajectory sent, from the cell's state then) when a motion
starts, and ``/robot_description`` and ``/tf_static`` once, sent again to each client
that subscribes to them (the protocol keeps no latched messages).

The server is Foxglove's own SDK (``foxglove-sdk``, a Rust server behind a Python API,
protocol ``foxglove.sdk.v1``): the older pure-Python ``foxglove-websocket`` package is
deprecated in its favour and no longer released. It binds to 127.0.0.1 unless told
otherwise. Open it in Foxglove with "Open connection" → ``ws://127.0.0.1:PORT``.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from taskrunner.errors import ArgumentError, TaskrunnerError
from taskrunner.export import rosmsg
from taskrunner.export.frames import FrameTree, robot_description
from taskrunner.export.timeline import (
    LATCHED,
    TOPICS,
    display_trajectory,
    log_line,
    scene_markers,
    task_meshes,
)
from taskrunner.robot.cell import Cell
from taskrunner.runtime.events import RunEvent

if TYPE_CHECKING:
    from taskrunner.runtime.runner import Runner

__all__ = ["FoxgloveFeed", "FoxgloveFeedOptions"]

DEFAULT_PORT = 8765  # Foxglove's usual port

log = logging.getLogger("taskrunner.export")


@dataclass(frozen=True)
class FoxgloveFeedOptions:
    """Where the feed listens and how often it samples.

    Attributes:
        host: address to bind (127.0.0.1: this machine only).
        port: TCP port (0: a free one; see :attr:`FoxgloveFeed.port`).
        rate_hz: joint-state samples a second while a run goes (1..1000).
    """

    host: str = "127.0.0.1"
    port: int = DEFAULT_PORT
    rate_hz: float = 30.0

    def __post_init__(self) -> None:
        if not (isinstance(self.port, int) and 0 <= self.port <= 65535):
            raise ArgumentError(f"'port' must be 0..65535 (got {self.port!r})")
        if not (1.0 <= self.rate_hz <= 1000.0):
            raise ArgumentError(f"'rate_hz' must be 1..1000 (got {self.rate_hz!r})")


class FoxgloveFeed:
    """A Foxglove WebSocket server streaming ``cell``'s robots (module docstring).

    Raises:
        TaskrunnerError: ``foxglove-sdk`` is not installed, or the server cannot listen
            on the address.
    """

    def __init__(self, cell: Cell, options: FoxgloveFeedOptions | None = None) -> None:
        try:
            import foxglove
            from foxglove.websocket import ServerListener
        except ImportError:
            raise TaskrunnerError("the live Foxglove feed needs the 'foxglove-sdk' package: "
                                  "pip install 'taskrunner-robotics[foxglove]'") from None
        self.options = options or FoxgloveFeedOptions()
        self.cell = cell
        self.tree = FrameTree(cell.model)
        self._lock = threading.Lock()  # one FK pass at a time (the tree's data)
        self._q = cell.start_state()
        self._sent = self._q  # the state last sent on /joint_states
        self._context = foxglove.Context()
        self._channels = {
            topic: foxglove.Channel(topic, message_encoding="cdr", context=self._context,
                                    schema=foxglove.Schema(name=kind.name, encoding="ros2msg",
                                                           data=kind.definition.encode()))
            for topic, kind in TOPICS.items()}
        feed = self

        self._subscribed = threading.Event()

        class Latched(ServerListener):
            def on_subscribe(self, client: Any, channel: Any) -> None:
                feed._subscribed.set()
                if channel.topic in LATCHED:
                    feed._send_latched(channel.topic)

        try:
            self.server = foxglove.start_server(
                name=f"taskrunner {cell.name}", host=self.options.host, port=self.options.port,
                context=self._context, server_listener=Latched())
        except Exception as exc:  # the SDK raises its own RuntimeError kinds
            raise TaskrunnerError(f"Foxglove feed: cannot listen on {self.options.host}:"
                                  f"{self.options.port} ({exc})") from None
        self._description = rosmsg.encode_string(robot_description(cell.model))

    @property
    def port(self) -> int:
        """The TCP port it listens on."""
        return int(self.server.port)

    @property
    def url(self) -> str:
        """``ws://host:port``, what Foxglove's "Open connection" takes."""
        return f"ws://{self.options.host}:{self.port}"

    def wait_for_client(self, timeout: float) -> bool:
        """Wait until a client has subscribed to a topic (``timeout`` s at most);
        whether one has."""
        return self._subscribed.wait(timeout)

    def _send_latched(self, topic: str) -> None:
        now = time.time_ns()
        if topic == "/robot_description":
            self._channels[topic].log(self._description, log_time=now)
        else:
            with self._lock:
                transforms = self.tree.static_transforms(now)
            self._channels[topic].log(rosmsg.encode_tf_message(transforms), log_time=now)

    def publish_state(self, q: np.ndarray, stamp_ns: int | None = None) -> None:
        """Send ``/joint_states`` and ``/tf`` for state vector ``q`` (rad or m)."""
        stamp = time.time_ns() if stamp_ns is None else stamp_ns
        q = self.cell.model.apply_mimic(np.asarray(q, dtype=float))
        with self._lock:
            transforms = self.tree.moving_transforms(q, stamp)
            self._sent = q
        self._channels["/joint_states"].log(
            rosmsg.encode_joint_state(stamp, self.cell.model.joint_names, q), log_time=stamp)
        self._channels["/tf"].log(rosmsg.encode_tf_message(transforms), log_time=stamp)

    def publish_event(self, event: RunEvent, runner: Runner, logger_prefix: str = "") -> None:
        """Send an event as ``/rosout`` (and the scene's objects, if it carries them; a
        motion's trajectory on ``/display_planned_path``, as an MCAP export has it);
        ``logger_prefix`` goes before the logger's name (the node's).

        Raises:
            InputError: a motion's trajectory cannot be read (nothing of it is sent).
        """
        stamp = time.time_ns()
        scene = event.data.get("scene")
        if event.kind == "motion" and "trajectory" in event.data:
            with self._lock:
                start = self._sent
            self._channels["/display_planned_path"].log(
                display_trajectory(event, stamp, self.cell, start), log_time=stamp)
        if isinstance(scene, dict):
            markers, _ = scene_markers(scene.get("objects"), stamp, self.cell, self.tree.root,
                                       task_meshes(runner.spec))
            self._channels["/scene_objects"].log(rosmsg.encode_marker_array(markers),
                                                 log_time=stamp)
        line = log_line(event, stamp, runner.record)
        if logger_prefix:
            line = replace(line, name=logger_prefix + line.name)
        self._channels["/rosout"].log(rosmsg.encode_log(line), log_time=stamp)

    @contextmanager
    def follow(self, runner: Runner) -> Iterator[None]:
        """While in the block, stream ``runner``'s backend state and events."""
        model = self.cell.model
        backend = runner.backend
        columns = model.indices(backend.joint_names)
        stop = threading.Event()

        def sample() -> None:
            period = 1.0 / self.options.rate_hz
            while True:
                try:
                    state = backend.joint_state()
                except TaskrunnerError as exc:  # the backend closed or failed: the run says so
                    log.warning("Foxglove feed: no joint state from the backend (%s); "
                                "the feed stops sampling", exc)
                    return
                q = self._q.copy()
                q[columns] = state.positions
                self._q = q
                self.publish_state(q)
                if stop.wait(period):
                    return

        failed: list[str] = []

        def on_event(event: RunEvent) -> None:
            # In the run's thread: a viewer's feed must not end the run; it says so once.
            try:
                self.publish_event(event, runner)
            except (TaskrunnerError, ValueError, KeyError, TypeError) as exc:
                if not failed:
                    failed.append(str(exc))
                    log.warning("Foxglove feed: event %d not sent (%s)", event.seq, exc)

        runner.events.subscribe(on_event)
        thread = threading.Thread(target=sample, name="foxglove-feed", daemon=True)
        thread.start()
        try:
            yield
        finally:
            stop.set()
            thread.join()
            runner.events.unsubscribe(on_event)
            self._publish_last(runner, columns)

    def _publish_last(self, runner: Runner, columns: np.ndarray) -> None:
        """Send the state the run ended in (none if the backend cannot tell)."""
        try:
            state = runner.backend.joint_state()
        except TaskrunnerError:
            return
        self._q[columns] = state.positions
        self.publish_state(self._q)

    def close(self) -> None:
        """Stop the server (idempotent)."""
        self.server.stop()

    def __enter__(self) -> FoxgloveFeed:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
