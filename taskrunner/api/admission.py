"""Bounded heavy work, and a control path nothing else can starve.

The server has two kinds of requests that must not share a queue:

* **control**: cancelling a run and reading the state of a run (``POST /runs/{id}/cancel``,
  ``GET /runs/{id}``). A robot may be moving; the operator's stop must get through
  whatever else clients ask. Cancelling a run in flight is answered on the event loop
  itself (it sets an event the run's thread watches); what needs the database runs on
  :class:`ControlExecutor`'s own threads, never on the shared thread pool that the
  framework gives plain ``def`` routes.
* **heavy work**: loading and checking a request's task, previews, ``/plan``. Each may take
  seconds to a minute and a planning process. :class:`Admission` lets at most
  ``capacity`` of them run at once and ``queue`` more wait; a waiting request waits on the
  event loop (it holds no thread), and one more is refused at once with 503 and
  ``Retry-After`` (:class:`ServerBusyError`), as is one that waited longer than
  ``wait_s``. So a burst of slow requests costs at most ``capacity`` threads and
  processes, and the rest of the server answers as before.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import math
from collections.abc import AsyncIterator, Callable
from contextlib import asynccontextmanager
from typing import Any, TypeVar

from taskrunner.errors import ArgumentError, UnavailableError

__all__ = ["Admission", "ControlExecutor", "ServerBusyError"]

T = TypeVar("T")


class ServerBusyError(UnavailableError):
    """The server runs as much of a kind of work as it allows and its queue is full (HTTP
    503, with ``Retry-After``: ``retry_after_s``)."""

    def __init__(self, message: str, retry_after_s: float) -> None:
        super().__init__(message)
        self.retry_after_s = retry_after_s


class Admission:
    """At most ``capacity`` requests' work at once, at most ``queue`` more waiting.

    Args:
        what: the kind of work, for messages ("plans and previews").
        capacity: how many run at once (>= 1).
        queue: how many more may wait (>= 0).
        wait_s: the longest a request waits for its turn (s); then 503.
        setting: the server setting that sets ``capacity``, named in messages.

    Use it on the event loop only (it is not thread-safe, and need not be).
    """

    def __init__(self, what: str, capacity: int, queue: int, wait_s: float,
                 setting: str) -> None:
        if capacity < 1:
            raise ArgumentError(f"'capacity' must be >= 1 (got {capacity})")
        if queue < 0:
            raise ArgumentError(f"'queue' must be >= 0 (got {queue})")
        if not (math.isfinite(wait_s) and wait_s > 0):
            raise ArgumentError(f"'wait_s' must be a positive number of seconds (got {wait_s})")
        self.what = what
        self.capacity = capacity
        self.queue = queue
        self.wait_s = wait_s
        self.setting = setting
        self.running = 0
        self.waiting = 0
        self.refused = 0  # requests answered 503 (for stats and tests)
        self._turns: asyncio.Semaphore | None = None  # made on the loop that uses it

    def _busy(self, detail: str) -> ServerBusyError:
        self.refused += 1
        return ServerBusyError(
            f"the server is busy: {self.running} {self.what} running (server setting "
            f"{self.setting!r}: {self.capacity}) and {detail}; try again later",
            retry_after_s=max(1.0, min(self.wait_s, 5.0)))

    @asynccontextmanager
    async def slot(self) -> AsyncIterator[None]:
        """Hold one of the ``capacity`` turns for the body of the ``async with``.

        Raises:
            ServerBusyError: the queue is full, or the turn did not come within ``wait_s``.
        """
        if self._turns is None:
            self._turns = asyncio.Semaphore(self.capacity)
        turns = self._turns
        if turns.locked():
            if self.waiting >= self.queue:
                raise self._busy(f"{self.waiting} more waiting (at most {self.queue})")
            self.waiting += 1
            try:
                async with asyncio.timeout(self.wait_s):
                    await turns.acquire()
            except TimeoutError:
                raise self._busy(f"this request waited {self.wait_s:g} s for its turn") \
                    from None
            finally:
                self.waiting -= 1
        else:
            await turns.acquire()
        self.running += 1
        try:
            yield
        finally:
            self.running -= 1
            turns.release()

    def stats(self) -> dict[str, int]:
        return {"capacity": self.capacity, "queue": self.queue, "running": self.running,
                "waiting": self.waiting, "refused": self.refused}


class ControlExecutor:
    """A few threads of the server's own, for the blocking part of control requests
    (reading a run from the database, rebuilding a live run's body): they never wait
    behind previews, checks or file downloads in the framework's shared pool."""

    def __init__(self, workers: int = 4) -> None:
        self._pool = concurrent.futures.ThreadPoolExecutor(
            max_workers=workers, thread_name_prefix="taskrunner-control")

    async def run(self, function: Callable[..., T], *args: Any) -> T:
        """``function(*args)`` on a control thread, awaited."""
        return await asyncio.get_running_loop().run_in_executor(self._pool, function, *args)

    def close(self) -> None:
        self._pool.shutdown(wait=False, cancel_futures=True)
