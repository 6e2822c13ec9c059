"""Running a task: compile it, tick its tree to the end, keep the record.

A :class:`Runner` owns one run: the scene built from the cell and the task's objects, the
plan service, the backend, the event log and the run record. :meth:`Runner.run` ticks the
tree at ``tick_hz`` until it succeeds, fails or is cancelled (``cancel()`` from another
thread, or Ctrl-C / SIGTERM in the CLI): cancelling stops the tree, which cancels any plan
in flight and stops the motion where it is, and records the run as cancelled with the
reason and its exit code (130 for a cancel or Ctrl-C, 143 for SIGTERM). What ran keeps its
status: :attr:`Runner.stopped` holds each node's status as it was when the tree was stopped
(a node interrupted: ``CANCELLED``), and :meth:`Runner.snapshot` and the terminal's last
frame show that, not the reset tree. A cancel that arrives once the tree has ended (every
motion done: during the final expectations check) is too late: the run's outcome stands
and a ``message`` event says so.

With ``runs_dir`` set, every event is written to the run's journal before the step that
announced it goes on, so a run killed outright leaves everything it announced; the
journal is fsync'd before each motion is sent and when the run ends, so a power loss
keeps every event up to the last motion sent (see :mod:`taskrunner.runtime.records`).
"""

from __future__ import annotations

import threading
import time
import uuid
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

import py_trees
from py_trees.common import Status

from taskrunner.backends.base import Backend
from taskrunner.errors import (
    ArgumentError,
    BackendError,
    InputError,
    PlanningError,
    TaskrunnerError,
)
from taskrunner.kinds import ExitCode, FailureKind, NodeStatus
from taskrunner.planning.service import PlanService
from taskrunner.planning.timing import TimingOptions
from taskrunner.robot.cell import Cell
from taskrunner.runtime.checkpoint import Checkpointer, text_sha256, tree_sha256
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import RecordFile, RunRecord, new_run_id
from taskrunner.runtime.replay import scene_data
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.tasks.spec import TaskSpec
from taskrunner.tree.behaviours import TaskLeaf
from taskrunner.tree.compiler import compile_task, object_shape
from taskrunner.tree.context import TaskContext
from taskrunner.tree.expect import check_task_end
from taskrunner.tree.start import start_mismatch, task_start
from taskrunner.tree.timeout import TaskTimeout

if TYPE_CHECKING:
    from taskrunner.runtime.resume import ResumePlan

__all__ = ["CANCELLED", "EXIT_CODES", "RunOptions", "Runner", "task_scene", "tree_text"]

# Exit codes of run-task, by outcome (plain ints: records and JSON keep their bytes).
EXIT_CODES = {"succeeded": int(ExitCode.OK), "invalid": int(ExitCode.INVALID),
              "planning": int(ExitCode.PLANNING), "execution": int(ExitCode.EXECUTION),
              "cancelled": int(ExitCode.CANCELLED), "terminated": int(ExitCode.TERMINATED)}


def error_kind(exc: TaskrunnerError) -> str:
    """The outcome (a key of :data:`EXIT_CODES`) of one of our errors, as ``run-task``
    maps it: a planning failure (``PlanningError``), an execution one (``BackendError``),
    else invalid input (``InputError``, ``UnknownNameError``, ``SceneError``, …)."""
    if isinstance(exc, PlanningError):
        return FailureKind.PLANNING.value
    if isinstance(exc, BackendError):
        return FailureKind.EXECUTION.value
    return FailureKind.INVALID.value


CANCELLED = NodeStatus.CANCELLED.value
"""The status of a node that was running when the run was stopped (py_trees has none: its
``stop`` leaves every node ``INVALID``, as if it never ran)."""


def tree_text(root: py_trees.behaviour.Behaviour,
              statuses: dict[uuid.UUID, tuple[str, str]]) -> str:
    """The tree as :func:`py_trees.display.unicode_tree` draws it with ``show_status``,
    each node's status and message taken from ``statuses`` (node id: ``(status,
    message)``, a status a :class:`~py_trees.common.Status` value or :data:`CANCELLED`,
    drawn ``[-] -- <message>``)."""
    symbols = py_trees.display.unicode_symbols
    marks = {s.value: symbols[s] for s in Status} | {CANCELLED: symbols[Status.INVALID]}

    def kind(node: py_trees.behaviour.Behaviour) -> str:
        if isinstance(node, py_trees.composites.Parallel):
            return "parallel"
        if isinstance(node, py_trees.decorators.Decorator):
            return "decorator"
        if isinstance(node, py_trees.composites.Sequence):
            return "sequence_with_memory" if node.memory else "sequence_without_memory"
        if isinstance(node, py_trees.composites.Selector):
            return "selector_with_memory" if node.memory else "selector_without_memory"
        return "behaviour"

    lines: list[str] = []

    def draw(node: py_trees.behaviour.Behaviour, depth: int) -> None:
        status, message = statuses.get(node.id, (node.status.value, node.feedback_message))
        name = node.name.replace("\n", " ")
        lines.append(f"{'    ' * depth}{symbols[kind(node)]} {name} [{marks[status]}]"
                     + (f" -- {message}" if message else ""))
        for child in node.children:
            draw(child, depth + 1)

    draw(root, 0)
    return "".join(line + "\n" for line in lines)


@dataclass(frozen=True)
class RunOptions:
    """How to run.

    Attributes:
        tick_hz: behaviour-tree ticks per second.
        seed: seeds every planner call of the run.
        runs_dir: where run records are written (None: not written).
        backend_name: recorded in the run record.
        timing: default time parameterization (velocity / acceleration scaling).
        planner_times: the planner times planned motions too (see
            :class:`~taskrunner.tree.context.TaskContext`).
        load_options: how the cell's robots were loaded
            (:meth:`~taskrunner.robot.options.LoadOptions.as_data`), kept in the record for
            a resume. None: not said.
    """

    tick_hz: float = 100.0
    seed: int = 0
    runs_dir: Path | None = None
    backend_name: str = "mock"
    timing: TimingOptions = field(default_factory=TimingOptions)
    planner_times: bool = False
    load_options: dict[str, Any] | None = None

    def __post_init__(self) -> None:
        if not self.tick_hz > 0:
            raise ArgumentError(f"'tick_hz' must be > 0 (got {self.tick_hz})")


def task_scene(spec: TaskSpec, cell: Cell) -> Scene:
    """The scene a task starts in: the cell's objects and robots, the objects of its
    ``scene:`` file (a MoveIt PlanningScene), then the task's objects."""
    scene = scene_from_cell(cell)
    if spec.scene is not None:
        from taskrunner.moveit import apply_scene_file

        apply_scene_file(scene, spec.scene)
    for obj in spec.objects:
        scene.add_object(obj.name, object_shape(obj), obj.pose.to_pose())
        for link in obj.touch_links:
            scene.allow_collision(obj.name, link, reason="task")
    return scene


class Runner:
    """Runs one task on one backend (see the module docstring)."""

    def __init__(self, spec: TaskSpec, cell: Cell, backend: Backend, planner: PlanService,
                 options: RunOptions | None = None, events: EventLog | None = None,
                 resume: ResumePlan | None = None) -> None:
        """``resume``: continue the run it was made from (:mod:`taskrunner.runtime.resume`):
        the scene restored and the tree brought to where that run stopped."""
        self.spec = spec
        self.cell = cell
        self.backend = backend
        self.options = options or RunOptions()
        self.events = events if events is not None else EventLog()
        self.scene = task_scene(spec, cell)
        self.ctx = TaskContext(cell, self.scene, planner, backend, self.events,
                               self.options.timing, self.options.seed,
                               planner_times=self.options.planner_times,
                               materials=spec.object_materials())
        self.ctx.sync_from_backend()
        # The check started from the scene file's robot_state: the run starts there or not at all.
        self._start_problem = start_mismatch(
            task_start(spec, cell), self.scene.state, cell,
            "move the robot there first (run-task starts mock, sim and mujoco there)")
        self.tree = compile_task(spec, self.ctx)
        self._cancel = threading.Event()
        self._cancel_reason = ("cancelled", EXIT_CODES["cancelled"])
        self._ended = threading.Event()  # the tree has ended: nothing more moves
        self.stopped: dict[uuid.UUID, tuple[str, str]] | None = None
        self.late_cancel: str | None = None
        self._file: RecordFile | None = None
        self.record = RunRecord(
            run_id=new_run_id(), task=spec.name, task_file=str(spec.path or ""),
            cell=cell.name, backend=self.options.backend_name,
            parameters={k: p.value for k, p in spec.parameters.items()},
            task_text=spec.path.read_text(encoding="utf-8") if spec.path else "",
            load_options=self.options.load_options)
        self.events.subscribe(self.record.events.append)
        self.record.tree_sha256 = tree_sha256(self.tree)
        # After the record's subscriber: a checkpoint is kept after its node_finished.
        self.checkpointer = Checkpointer(self.tree, self.ctx, self.events)
        self.resume_notes: list[str] = []
        self._resume = resume
        if resume is not None:
            self.resume_notes = resume.apply(self)
            self.record.resumes = resume.run_id
            self._start_problem = None  # it starts where the run it resumes stopped
        self.failure_kind: str | None = None
        self.expectations_met: bool | None = None

    def cancel(self, reason: str = "cancelled", exit_code: int = EXIT_CODES["cancelled"]) -> bool:
        """Stop the run (safe from any thread, and from a signal handler): the motion stops
        where it is and the run ends ``cancelled`` with ``reason`` as its error and
        ``exit_code``. The first cancel's reason is kept.

        Returns:
            False when it is too late: the tree has ended (every motion done), the run
            ends as it would have and says the cancel came too late (see
            :attr:`late_cancel`).
        """
        if not self._cancel.is_set():
            self._cancel_reason = (reason, exit_code)
        self._cancel.set()
        return not self._ended.is_set()

    @property
    def cancelled(self) -> bool:
        """Whether :meth:`cancel` was called."""
        return self._cancel.is_set()

    def _pause(self, seconds: float) -> None:
        """Wait for the next tick: ``seconds``, or until :meth:`cancel`. When the running
        leaf waits for a plan from a worker: until that plan is answered, if sooner (the
        leaf then goes on at once, not at the next period); a cancel is seen at the next
        tick, within the period."""
        if seconds <= 0.0:
            return
        ticket = getattr(self.current_leaf(), "ticket", None)
        wait = getattr(ticket, "wait", None)
        if ticket is not None and callable(wait) and not ticket.done() \
                and not self._cancel.is_set():
            wait(seconds)
        else:
            self._cancel.wait(seconds)

    def current_leaf(self) -> TaskLeaf | None:
        """The leaf running now, if any."""
        tip = self.tree.tip()
        return tip if isinstance(tip, TaskLeaf) else None

    def snapshot(self) -> str:
        """The tree as text, with each node's status (once stopped: as it was when the
        run was stopped, see :attr:`stopped`)."""
        stopped = self.stopped
        if stopped is not None:
            return tree_text(self.tree, stopped)
        return py_trees.display.unicode_tree(self.tree, show_status=True)

    def _stop_tree(self, interrupted: str, message: str) -> None:
        """Stop the tree (its motion stops where it is, a plan in flight is dropped),
        first keeping each node's status in :attr:`stopped`: a node running now becomes
        ``interrupted`` with ``message``."""
        statuses = {}
        for node in self.tree.iterate():
            running = node.status == Status.RUNNING
            statuses[node.id] = ((interrupted, message) if running
                                 else (node.status.value, node.feedback_message))
        self.stopped = statuses  # before the stop: a frame drawn meanwhile shows these
        self.tree.stop(Status.INVALID)

    def run(self) -> RunRecord:
        """Tick the tree to the end; returns the finished record.

        Raises:
            InputError: the backend is not where the task's scene file puts the robot
                (nothing moved).
        """
        if self._start_problem is not None:
            raise InputError(self._start_problem, self.spec.scene)
        self.record.task_sha256 = text_sha256(self.record.task_text)  # as run (set late by
        # start_run for a task without a file)
        self.events.emit("run_started", f"task {self.spec.name!r} on cell {self.cell.name!r}",
                         status="running", task=self.spec.name, cell=self.cell.name,
                         backend=self.options.backend_name,
                         parameters=dict(self.record.parameters),
                         scene=scene_data(self.scene.snapshot()), resumes=self.record.resumes)
        self._open_record()
        for note in self.resume_notes:
            self.events.emit("message", note, resumes=self.record.resumes)
        if self._resume is not None:  # the record resumable alone: the outcomes replayed
            self._resume.emit_replayed(self.events)
        period = 1.0 / self.options.tick_hz
        status = Status.RUNNING
        try:
            while True:
                started = time.monotonic()
                if self._cancel.is_set():
                    self._stop_tree(CANCELLED, self._cancel_reason[0])
                    break
                self.tree.tick_once()
                status = self.tree.status
                if status in (Status.SUCCESS, Status.FAILURE):
                    self._ended.set()
                    break
                self._pause(period - (time.monotonic() - started))
        except TaskrunnerError as exc:  # a leaf let one of ours escape: fail, don't crash
            self._stop_tree(Status.FAILURE.value, str(exc))
            self.failure_kind = error_kind(exc)
            return self._finish("failed", EXIT_CODES[self.failure_kind], str(exc))
        except Exception as exc:  # a bug: stop the motion and record it, then let it show
            self._stop_tree(Status.FAILURE.value, f"internal error: {type(exc).__name__}")
            self._finish("failed", EXIT_CODES["planning"],
                         f"internal error: {type(exc).__name__}: {exc}")
            raise
        if self._cancel.is_set() and status not in (Status.SUCCESS, Status.FAILURE):
            reason, code = self._cancel_reason
            return self._finish("cancelled", code, reason)
        if status == Status.SUCCESS:
            return self._finish(*self._expectations("succeeded", 0, None))
        leaf = self._failed_leaf()
        kind = leaf.failure_kind if leaf is not None and leaf.failure_kind else "planning"
        self.failure_kind = kind
        message = leaf.feedback_message if leaf is not None else "the task failed"
        return self._finish(*self._expectations("failed", EXIT_CODES[kind], message))

    def _expectations(self, status: str, code: int, error: str | None
                      ) -> tuple[str, int, str | None]:
        """Check the task's ``expect:`` on the run as it ended; a ``message`` event with
        data ``expectations: {met, failures}`` says whether they are met. A run that succeeded but
        misses one fails (exit code 4) with the first miss as its error."""
        expect = self.spec.expect
        where = str(expect.loc) if expect is not None and expect.loc is not None else None
        # A resumed run's duration counts the runs it resumes too (their story).
        ctx = self._resume.story_context(self.ctx) if self._resume is not None else self.ctx
        try:
            misses = check_task_end(expect, ctx, status, error, where)
        except TaskrunnerError as exc:
            misses = [f"{where}: expectation not checked: {exc}" if where else str(exc)]
        self.expectations_met = not misses
        covers = self._resume.covers(self.ctx, expect) if self._resume is not None else ""
        self.events.emit("message", ("expectations met" if not misses else misses[0]) + covers,
                         expectations={"met": not misses, "failures": misses,
                                       "status": {"expected": expect.status if expect
                                                  else "succeeded", "observed": status}})
        if misses and status == "succeeded":
            self.failure_kind = "execution"
            return "failed", EXIT_CODES["execution"], misses[0]
        return status, code, error

    def _failed_leaf(self) -> TaskLeaf | TaskTimeout | None:
        """The node whose failure ended the run: the last leaf (or ``timeout:``) that failed."""
        failed = [e for e in self.record.events
                  if e.kind == "node_finished" and e.status == Status.FAILURE.value]
        if not failed:
            return None
        for node in self.tree.iterate():
            if isinstance(node, TaskLeaf | TaskTimeout) and node.name == failed[-1].node \
                    and node.feedback_message == failed[-1].message:
                return node
        return None

    def _finish(self, status: str, code: int, error: str | None) -> RunRecord:
        self._ended.set()
        if status != "cancelled" and self._cancel.is_set():
            # Asked after the tree's last tick: every motion was done. One outcome.
            self.late_cancel = (f"{self._cancel_reason[0]} too late: every step had ended; "
                                f"the run {status}")
            self.events.emit("message", self.late_cancel, late_cancel=True)
        # The event first, then the record's status: a reader that sees the run ended
        # (polls of GET /runs/{id}, TaskRun) finds its run_finished event there too.
        self.events.emit("run_finished", error or status, status=status, exit_code=code,
                         scene=scene_data(self.scene.snapshot()),
                         task_time=round(self.ctx.clock.now(), 6),
                         motion_time=round(self.ctx.clock.motion_time(), 6))
        self.record.exit_code = code
        self.record.error = error
        self.record.finished = datetime.now(UTC).isoformat()
        self.record.status = status
        if self._file is not None:
            self.events.set_journal(None)
            self._file.finish()
        return self.record

    def _open_record(self) -> None:
        """Write the record as it starts and journal every event from now on."""
        if self.options.runs_dir is not None:
            self._file = RecordFile(self.record, self.options.runs_dir)
            # The journal, not a subscriber: written before any display prints the event.
            self.events.set_journal(self._file.append)
