"""A test client of Foxglove's WebSocket protocol (``foxglove.sdk.v1``): subscribes to
topics and decodes their ROS 2 messages, with rosbags' Humble types or, for a type that
is not one (``moveit_msgs``), with ``mcap-ros2-support`` from the schema the channel
advertises (imported by the feed tests)."""

from __future__ import annotations

import json
import struct
import threading
import time
from typing import Any

from rosbags.typesys import Stores, get_typestore
from websockets.sync.client import connect

HUMBLE = get_typestore(Stores.ROS2_HUMBLE)


def decode(data: bytes, schema: str, definition: str) -> Any:
    """A CDR message of type ``schema`` (its ROS 2 message ``definition``, as advertised)."""
    if schema in HUMBLE.fielddefs:
        return HUMBLE.deserialize_cdr(data, schema)
    from mcap.records import Schema
    from mcap_ros2.decoder import DecoderFactory

    decoder = DecoderFactory().decoder_for("cdr", Schema(
        id=1, name=schema, encoding="ros2msg", data=definition.encode()))
    assert decoder is not None
    return decoder(data)


def subscribe(ws: Any, topics: list[str]) -> dict[int, tuple[str, str, str]]:
    """Read the server's hello and channels; subscribe to ``topics``: subscription id →
    (topic, schema name, schema text)."""
    channels: dict[str, dict[str, Any]] = {}
    deadline = time.monotonic() + 10
    while not set(topics) <= set(channels) and time.monotonic() < deadline:
        message = json.loads(ws.recv(timeout=10))
        if message["op"] == "advertise":
            channels.update({c["topic"]: c for c in message["channels"]})
    subscriptions = {i: channels[t] for i, t in enumerate(topics, start=1)}
    ws.send(json.dumps({"op": "subscribe", "subscriptions": [
        {"id": i, "channelId": c["id"]} for i, c in subscriptions.items()]}))
    for channel in subscriptions.values():
        assert (channel["encoding"], channel["schemaEncoding"]) == ("cdr", "ros2msg")
    return {i: (c["topic"], c["schemaName"], c["schema"]) for i, c in subscriptions.items()}


class Listener:
    """A client in a thread: ``received`` collects (monotonic s, topic, message) of
    ``topics`` from ``url`` until :meth:`stop`."""

    def __init__(self, url: str, topics: list[str]) -> None:
        self.url, self.topics = url, topics
        self.received: list[tuple[float, str, Any]] = []
        self.ready, self._done = threading.Event(), threading.Event()
        self._thread = threading.Thread(target=self._listen, daemon=True)
        self._thread.start()

    def _listen(self) -> None:
        with connect(self.url, subprotocols=["foxglove.sdk.v1"]) as ws:
            subscriptions = subscribe(ws, self.topics)
            self.ready.set()
            while not self._done.is_set():
                try:
                    frame = ws.recv(timeout=0.2)
                except TimeoutError:
                    continue
                if isinstance(frame, bytes) and frame[0] == 1:  # message data
                    sub, _ = struct.unpack_from("<IQ", frame, 1)
                    topic, schema, definition = subscriptions[sub]
                    self.received.append((time.monotonic(), topic,
                                          decode(frame[13:], schema, definition)))

    def stop(self) -> None:
        self._done.set()
        self._thread.join(5)

    def messages(self, topic: str) -> list[Any]:
        return [m for _, t, m in list(self.received) if t == topic]
