"""The story of a resumed run: the runs it continues, and what they took.

A run resumed from another (:mod:`taskrunner.runtime.resume`) is one more chapter of a
single task's story. Its record carries the story so far (a ``message`` event with
``story``: the runs before it, their task time summed, their motions), so a run resumed
in turn carries it on without the records before it. At the end, the task's ``duration``
expectation reads a :class:`StoryClock`: the task time of the runs before plus the run's
own (the time between a stop and its resume, the operator's, is not task time).
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
    (s, the task clock of each, summed), ``motions`` sent. Kept in the resumed run's
    record (a ``message`` with ``story``), so a run resumed in turn carries it on."""

    runs: tuple[str, ...]
    task_time: float
    motions: int


def story_of(record: RunRecord) -> Story:
    """The story up to and including ``record``'s run: the story its record carries (if
    it resumed another) and its own task time (its end's clock; a killed run's: the end
    of its last motion) and motions."""
    before = Story((), 0.0, 0)
    own_time, motions = None, 0
    for event in record.events:
        if event.kind == "message" and isinstance(event.data.get("story"), dict):
            data = event.data["story"]
            before = Story(tuple(data["runs"]), float(data["task_time"]), int(data["motions"]))
        elif event.kind == "motion":
            motions += 1
            end = float(event.data.get("start", 0.0)) + float(
                (event.data.get("trajectory") or {}).get("duration", 0.0))
            own_time = max(own_time or 0.0, end)
        elif event.kind == "run_finished" and "task_time" in event.data:
            own_time = float(event.data["task_time"])
    return Story((*before.runs, record.run_id), before.task_time + (own_time or 0.0),
                 before.motions + motions)


class StoryClock(TaskClock):
    """A run's task clock read on from the task time of the runs before it."""

    def __init__(self, clock: TaskClock, before: float) -> None:
        super().__init__()
        self._clock, self._before = clock, before

    def now(self) -> float:
        return self._before + self._clock.now()
