"""The API server's live Foxglove feeds: the runs it executes, one feed per cell.

``run-task serve --foxglove [PORT]`` gives each cell its own Foxglove WebSocket server
(:class:`~taskrunner.export.live.FoxgloveFeed`): the cells of the server's cell folder
on ``PORT``, ``PORT + 1``, … in the order of their ids (fixed when the server starts,
printed then), a cell file from elsewhere on the next free number after them, in the
order they are first run. A cell's feed opens when its first run starts and stays open.

**Why one feed per cell, not one feed with prefixed names.** Each feed is exactly what
``run-task --foxglove`` and an MCAP file of the cell carry: ``/robot_description``,
``/tf_static``, ``/tf``, ``/joint_states`` with the URDF's own link and joint names under
``world``. Foxglove's URDF layer and RViz's RobotModel apply no prefix to a
description's links, so two cells in one tf tree would need rewritten URDFs, a prefix in
every layout and non-standard topic names; two copies of one cell file (the same
robot) would collide outright. Per-cell ports keep every layout and RViz config that
works on a recorded file working live. Runs on one cell at once (disjoint arms) share
its feed: one robot, each run's arms where its backend reports them.

**Never blocking a run.** A run's thread only puts its events into a bounded queue
(``max_queued``); a full queue drops the event and counts it
(:attr:`CellFeed.dropped`). One thread per feed encodes and sends: it drains the
queue, and samples each run's backend ``rate_hz`` times a second.
"""

from __future__ import annotations

import logging
import queue
import threading
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from taskrunner.errors import ArgumentError, TaskrunnerError
from taskrunner.export.live import DEFAULT_PORT, FoxgloveFeed, FoxgloveFeedOptions
from taskrunner.robot.cell import Cell
from taskrunner.runtime.events import RunEvent

if TYPE_CHECKING:
    from taskrunner.runtime.runner import Runner

__all__ = ["CellFeed", "CellFeeds", "CellFeedsOptions"]

log = logging.getLogger("taskrunner.export")


@dataclass(frozen=True)
class CellFeedsOptions:
    """The server's feeds.

    Attributes:
        host: address every feed binds (127.0.0.1: this machine only).
        port: the first cell's port (0: each feed on a free port of its own).
        rate_hz: joint-state samples a second while runs go (1..1000).
        max_queued: events waiting to be sent, per feed, past which new ones are
            dropped (>= 1).
    """

    host: str = "127.0.0.1"
    port: int = DEFAULT_PORT
    rate_hz: float = 30.0
    max_queued: int = 1000

    def __post_init__(self) -> None:
        FoxgloveFeedOptions(self.host, self.port, self.rate_hz)  # the same checks
        if not (isinstance(self.max_queued, int) and self.max_queued >= 1):
            raise ArgumentError(f"'max_queued' must be an integer >= 1 (got {self.max_queued!r})")


@dataclass
class _Follow:
    """A run a feed follows."""

    runner: Runner
    columns: np.ndarray      # the cell's state columns of the run's backend joints
    moved: np.ndarray        # ... of the joints the run may move
    first: bool = True       # its first sample takes all the backend's joints
    ended: bool = False
    on_event: Callable[[RunEvent], None] | None = None


class CellFeed:
    """One cell's feed: its server, its queue and its sending thread."""

    def __init__(self, cell: Cell, options: FoxgloveFeedOptions, max_queued: int) -> None:
        self.feed = FoxgloveFeed(cell, options)
        self.cell = cell
        self.dropped = 0
        self._period = 1.0 / options.rate_hz
        self._queue: queue.Queue[tuple[_Follow, RunEvent]] = queue.Queue(max_queued)
        self._follows: list[_Follow] = []
        self._lock = threading.Lock()
        self._wake = threading.Event()
        self._closed = threading.Event()
        self._q = cell.start_state()
        self._thread = threading.Thread(target=self._send, daemon=True,
                                        name=f"foxglove-{cell.name}")
        self._thread.start()

    @property
    def url(self) -> str:
        return self.feed.url

    def attach(self, runner: Runner, joints: frozenset[str]) -> _Follow:
        """Follow ``runner`` (``joints``: those it may move) from now on."""
        model = self.cell.model
        follow = _Follow(runner, model.indices(runner.backend.joint_names),
                         model.indices([j for j in model.joint_names if j in joints]))

        def on_event(event: RunEvent) -> None:  # in the run's thread: never waits
            try:
                self._queue.put_nowait((follow, event))
            except queue.Full:
                self.dropped += 1
                if self.dropped == 1 or self.dropped % 1000 == 0:
                    log.warning("Foxglove feed of %s: %d event(s) dropped (the feed is "
                                "behind; the run goes on)", self.cell.name, self.dropped)

        follow.on_event = on_event
        runner.events.subscribe(on_event)
        with self._lock:
            self._follows.append(follow)
        self._wake.set()
        return follow

    def detach(self, follow: _Follow) -> None:
        """Stop following a run; its final state is sent once more."""
        if follow.on_event is not None:
            follow.runner.events.unsubscribe(follow.on_event)
        follow.ended = True
        self._wake.set()

    def _sample(self, follow: _Follow) -> bool:
        try:
            state = follow.runner.backend.joint_state()
        except TaskrunnerError:  # the backend closed or failed: the run says so
            return False
        q = self._q.copy()
        if follow.first:
            q[follow.columns] = state.positions
            follow.first = False
        else:
            values = np.full(self.cell.model.nq, np.nan)
            values[follow.columns] = state.positions
            q[follow.moved] = np.where(np.isnan(values[follow.moved]), q[follow.moved],
                                       values[follow.moved])
        self._q = q
        return True

    def _publish(self, follow: _Follow, event: RunEvent) -> None:
        # Runs on one cell share the feed: the logger's name starts with the run's id.
        self.feed.publish_event(event, follow.runner, f"{follow.runner.record.run_id}.")

    def _send(self) -> None:
        while not self._closed.is_set():
            with self._lock:
                follows = list(self._follows)
            if not follows:
                self._wake.wait(1.0)
                self._wake.clear()
            sent = False
            while True:
                try:
                    follow, event = self._queue.get_nowait()
                except queue.Empty:
                    break
                try:
                    self._publish(follow, event)
                except (TaskrunnerError, ValueError, KeyError, TypeError) as exc:
                    log.warning("Foxglove feed of %s: event %d not sent (%s)",
                                self.cell.name, event.seq, exc)
            for follow in follows:
                sent = self._sample(follow) or sent
                if follow.ended:
                    with self._lock:
                        self._follows.remove(follow)
            if sent:
                try:
                    self.feed.publish_state(self._q)
                except TaskrunnerError as exc:
                    log.warning("Foxglove feed of %s: state not sent (%s)", self.cell.name, exc)
            if follows:
                self._closed.wait(self._period)

    def close(self) -> None:
        self._closed.set()
        self._wake.set()
        self._thread.join(5.0)
        self.feed.close()


class CellFeeds:
    """The server's feeds, one per cell (module docstring).

    Args:
        cell_ids: the ids of the server's cells, in order: cell ``i`` listens on
            ``port + i``.
        options: host, first port, rate and queue bound.
    """

    def __init__(self, cell_ids: list[str], options: CellFeedsOptions | None = None) -> None:
        self.options = options or CellFeedsOptions()
        self._ports = {cell_id: self._port(i) for i, cell_id in enumerate(cell_ids)}
        self._feeds: dict[str, CellFeed] = {}
        self._failed: set[str] = set()
        self._lock = threading.Lock()

    def _port(self, index: int) -> int:
        if self.options.port == 0:
            return 0
        port = self.options.port + index
        if port > 65535:
            raise ArgumentError(f"'foxglove_port' {self.options.port} leaves no port for the "
                                f"cell number {index + 1} (ports count up from it, one a cell)")
        return port

    def ports(self) -> dict[str, int]:
        """Cell id → the port its feed listens on (0: a free one, see :meth:`url_of`)."""
        return dict(self._ports)

    def url_of(self, cell_id: str) -> str | None:
        """``ws://host:port`` of the cell's feed, once it is open."""
        with self._lock:
            feed = self._feeds.get(cell_id)
        return None if feed is None else feed.url

    def feed(self, cell_id: str, cell: Cell) -> CellFeed | None:
        """The cell's feed, opened on first use; None if it cannot listen (said once,
        in the log, as an error: the runs go on without it)."""
        with self._lock:
            if cell_id in self._feeds:
                return self._feeds[cell_id]
            if cell_id in self._failed:
                return None
            if cell_id not in self._ports:
                self._ports[cell_id] = self._port(len(self._ports))
            port = self._ports[cell_id]
            try:
                opened = CellFeed(cell, FoxgloveFeedOptions(self.options.host, port,
                                                            self.options.rate_hz),
                                  self.options.max_queued)
            except TaskrunnerError as exc:
                self._failed.add(cell_id)
                log.error("Foxglove feed of cell %s not served: %s", cell_id, exc)
                return None
            self._feeds[cell_id] = opened
        log.info("Foxglove: cell %s live on %s", cell_id, opened.url)
        return opened

    def close(self) -> None:
        with self._lock:
            feeds = list(self._feeds.values())
            self._feeds.clear()
        for feed in feeds:
            feed.close()
