"""The story of a resumed run: the runs it continues, and what they took.

A run resumed from another (:mod:`taskrunner.runtime.resume`) is one more chapter of a
single task's story. Its record carries the story so far (a ``message`` event with
``story``: the runs before it, their task time summed, their motions), so a run resumed
in turn carries it on without the records before it. At the end, the task's ``duration``
expectation reads a :class:`StoryClock`: the task time of the runs before plus the run's
own (the time between a stop and its resume, the operator's, is not task time); its
``motion_time``, the runs' motion times summed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from taskrunner.tree.clock import TaskClock

if TYPE_CHECKING:
    from taskrunner.runtime.records import RunRecord

__all__ = ["Story", "StoryClock", "story_of"]


@dataclass(frozen=True)
class Story:
    """The runs a resumed run continues, oldest first, and what they did: ``task_time``
    (s, the task clock of each, summed), ``motions`` sent, ``motion_time`` (s of task
    time while a motion ran, summed). Kept in the resumed run's record (a ``message``
    with ``story``), so a run resumed in turn carries it on."""

    runs: tuple[str, ...]
    task_time: float
    motions: int
    motion_time: float = 0.0


def story_of(record: RunRecord) -> Story:
    """The story up to and including ``record``'s run: the story its record carries (if
    it resumed another) and its own task time and motion time (its end's clocks; a
    killed run's: the end of its last motion, and the time its motions cover, each as
    sent) and motions."""
    before = Story((), 0.0, 0)
    own_time = own_moving = None
    motions = 0
    spans: list[tuple[float, float]] = []
    for event in record.events:
        if event.kind == "message" and isinstance(event.data.get("story"), dict):
            data = event.data["story"]
            before = Story(tuple(data["runs"]), float(data["task_time"]), int(data["motions"]),
                           float(data.get("motion_time", 0.0)))
        elif event.kind == "motion":
            motions += 1
            # Where it started on the task clock ("sent"; a record made before motions
            # said it: its place on the schedule).
            start = float(event.data.get("sent", event.data.get("start", 0.0)))
            end = start + float((event.data.get("trajectory") or {}).get("duration", 0.0))
            spans.append((start, end))
            own_time = max(own_time or 0.0, end)
        elif event.kind == "run_finished" and "task_time" in event.data:
            own_time = float(event.data["task_time"])
            if "motion_time" in event.data:
                own_moving = float(event.data["motion_time"])
    if own_moving is None:
        own_moving = _covered(spans)
    return Story((*before.runs, record.run_id), before.task_time + (own_time or 0.0),
                 before.motions + motions, before.motion_time + own_moving)


def _covered(spans: list[tuple[float, float]]) -> float:
    """Seconds the union of the ``(start, end)`` spans covers."""
    total, reach = 0.0, -float("inf")
    for start, end in sorted(spans):
        if end > reach:
            total += end - max(start, reach)
            reach = end
    return total


class StoryClock(TaskClock):
    """A run's task clock read on from the task time (and motion time) of the runs
    before it."""

    def __init__(self, clock: TaskClock, before: float, moving_before: float = 0.0) -> None:
        super().__init__()
        self._clock, self._before, self._moving_before = clock, before, moving_before

    def now(self) -> float:
        return self._before + self._clock.now()

    def motion_time(self) -> float:
        return self._moving_before + self._clock.motion_time()
