"""A task run started from Python: a background thread, its events, its result.

:func:`start_run` compiles a loaded task for a cell and a backend and ticks it in a
thread of its own; the :class:`TaskRun` it returns follows the run (events as a callback
or an iterator, ``cancel()``, ``wait()``) and ends with a :class:`RunResult`.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from taskrunner.backends.base import Backend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import Cell
from taskrunner.runtime.events import EventLog, RunEvent
from taskrunner.runtime.records import RunRecord
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks.spec import TaskSpec

if TYPE_CHECKING:
    from taskrunner.runtime.resume import ResumeOptions

__all__ = ["RunResult", "TaskRun", "start_run"]


@dataclass(frozen=True)
class RunResult:
    """How a run ended.

    Attributes:
        run_id: the run's id (also the name of its record file, ``<run_id>.json``).
        task: the task's name.
        status: ``"succeeded"``, ``"failed"`` or ``"cancelled"``.
        exit_code: what ``run-task`` exits with for this outcome: 0 succeeded,
            3 planning failure, 4 execution failure, 130 cancelled.
        error: the failure's message, starting with the failed step's ``file:line``
            (a task file's line, or the line of the Python step); None on success.
        duration: wall time of the run (s), from its start to its end.
        events: every event of the run, in order.
        record: the full run record (what ``runs_dir`` and the REST API keep).
    """

    run_id: str
    task: str
    status: str
    exit_code: int
    error: str | None
    duration: float
    events: tuple[RunEvent, ...]
    record: RunRecord

    @property
    def ok(self) -> bool:
        """True when the run succeeded."""
        return self.status == "succeeded"


class TaskRun:
    """A task running in a background thread (made by ``start_task``).

    Events reach ``on_event`` callbacks as they happen (in the run's thread), and
    :meth:`events` iterates over them from the first, from any thread.
    """

    def __init__(self, runner: Runner) -> None:
        self._runner = runner
        self._changed = threading.Condition()
        self._result: RunResult | None = None
        self._error: BaseException | None = None
        self._done_callbacks: list[Callable[[], object]] = []
        runner.events.subscribe(self._notify)
        self._thread = threading.Thread(target=self._run, name=f"task-{runner.spec.name}",
                                        daemon=True)

    def __repr__(self) -> str:
        return f"TaskRun({self.task!r}, status={self.status!r})"

    @property
    def task(self) -> str:
        """The task's name."""
        return self._runner.spec.name

    @property
    def run_id(self) -> str:
        """The run's id."""
        return self._runner.record.run_id

    @property
    def status(self) -> str:
        """``"running"`` until the run ends, then its final status."""
        return self._runner.record.status

    def done(self) -> bool:
        """True once the run has ended (its result is ready)."""
        with self._changed:
            return self._result is not None or self._error is not None

    def cancel(self) -> None:
        """Stop the run (from any thread): the motion stops where it is, and the run
        ends as ``"cancelled"``."""
        self._runner.cancel()

    def wait(self, timeout: float | None = None) -> RunResult:
        """Wait for the run to end; returns its result.

        Raises:
            TimeoutError: the run has not ended within ``timeout`` seconds.
        """
        with self._changed:
            if not self._changed.wait_for(lambda: self._result is not None
                                          or self._error is not None, timeout):
                raise TimeoutError(f"task {self.task!r} still running after {timeout} s")
            if self._error is not None:
                raise self._error
            assert self._result is not None
            return self._result

    def events(self, timeout: float | None = None) -> Iterator[RunEvent]:
        """Every event of the run, from the first, as they happen; ends after the
        ``run_finished`` event.

        Args:
            timeout: seconds to wait for each next event at most.

        Raises:
            TimeoutError: no event within ``timeout``.
        """
        seen = 0
        while True:
            with self._changed:
                ready = self._changed.wait_for(
                    lambda: len(self._runner.events) > seen or self.done(), timeout)
                if not ready:
                    raise TimeoutError(f"no event of task {self.task!r} in {timeout} s")
                new = self._runner.events.events(seen)
            for event in new:
                seen = event.seq
                yield event
                if event.kind == "run_finished":
                    return
            if not new and self.done():
                return

    def resume(self, options: ResumeOptions | None = None, *, runs_dir: Path | None = None,
               on_event: Callable[[RunEvent], None] | None = None) -> TaskRun:
        """A new run continuing this one, ended (failed, cancelled), from where it stopped,
        on the same backend (the joints as it reports them) and with the same planner
        (see :mod:`taskrunner.runtime.resume`; its record's ``resumes`` is this run's id).

        Args:
            options: what the operator says about held objects, and ``from_step``.
            runs_dir: where the new record goes (default: where this run's went).
            on_event: called with every event of the new run.

        Raises:
            InputError: refused (the run still runs or succeeded, its task file changed,
                a held object's state is unknown on this backend), with what to do.
        """
        from taskrunner.runtime.resume import plan_resume

        old = self._runner
        plan = plan_resume(old.record, old.spec, options, same_world=True)
        events = EventLog()
        if on_event is not None:
            events.subscribe(on_event)
        runner = Runner(old.spec, old.cell, old.backend, old.ctx.plan_service(),
                        replace(old.options, runs_dir=runs_dir or old.options.runs_dir),
                        events=events, resume=plan)
        runner.record.task_text = old.record.task_text
        run = TaskRun(runner)
        run._start()
        return run

    def add_done_callback(self, callback: Callable[[], object]) -> None:
        """Call ``callback()`` when the run ends (at once if it has)."""
        with self._changed:
            if not self.done():
                self._done_callbacks.append(callback)
                return
        callback()

    # ------------------------------------------------------------------ internals
    def _start(self) -> None:
        self._thread.start()

    def _notify(self, event: RunEvent) -> None:
        with self._changed:
            self._changed.notify_all()

    def _run(self) -> None:
        result: RunResult | None = None
        error: BaseException | None = None
        try:
            record = self._runner.run()
            result = _result(record)
        except BaseException as exc:  # handed to wait(): a run's thread must not die silently
            error = exc
        while True:  # callbacks added while others run are called too, before wait() returns
            with self._changed:
                callbacks, self._done_callbacks = self._done_callbacks, []
                if not callbacks:
                    self._result, self._error = result, error
                    self._changed.notify_all()
                    return
            for callback in callbacks:
                try:
                    callback()
                except Exception as exc:  # e.g. reading a dead backend: wait() raises it
                    error = error or exc


def _result(record: RunRecord) -> RunResult:
    events = tuple(record.events)
    started = next((e.time for e in events if e.kind == "run_started"), 0.0)
    finished = next((e.time for e in reversed(events) if e.kind == "run_finished"), started)
    return RunResult(record.run_id, record.task, record.status,
                     record.exit_code if record.exit_code is not None else 3, record.error,
                     finished - started, events, record)


def start_run(spec: TaskSpec, cell: Cell, backend: Backend, *, seed: int = 0,
              backend_name: str = "mock", runs_dir: Path | None = None,
              on_event: Callable[[RunEvent], None] | None = None,
              on_end: Callable[[], object] | None = None,
              task_text: str | None = None,
              load_options: Mapping[str, Any] | None = None) -> TaskRun:
    """Compile ``spec`` for ``cell`` and ``backend`` and start ticking it in a thread.

    Plans are computed in the run's thread (:class:`InProcessPlanner`).

    Args:
        seed: seeds every planner call.
        backend_name: recorded in the run record.
        runs_dir: write the record there when the run starts and ends.
        on_event: called with every event (subscribed before the run starts).
        on_end: called when the run ends, before :meth:`TaskRun.wait` returns.
        task_text: the task's source for the record, when it has no file.
        load_options: how ``cell``'s robots were loaded
            (:meth:`~taskrunner.robot.options.LoadOptions.as_data`), for the record.

    Raises:
        TaskSpecError: a step names something the cell does not have.
    """
    events = EventLog()
    if on_event is not None:
        events.subscribe(on_event)
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=seed, runs_dir=runs_dir, backend_name=backend_name,
                               load_options=None if load_options is None
                               else dict(load_options)),
                    events=events)
    if task_text is not None and not runner.record.task_text:
        runner.record.task_text = task_text
    run = TaskRun(runner)
    if on_end is not None:
        run.add_done_callback(on_end)
    run._start()
    return run

