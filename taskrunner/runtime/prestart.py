"""Start the planning worker before the run knows it needs one.

A planning worker (:class:`~taskrunner.planning.worker.PlanningWorker`) takes 0.5-0.8 s
to start: a new interpreter imports the planner, loads the cell and builds its
collision geometry. ``run-task FILE`` used to start it after its own imports and the
check before the run, so the two waits added up. :func:`start_worker_early` starts it
first, on the cell the task file names (read with a plain YAML parse, before any
taskrunner module that takes time to import), and the run adopts it
(:meth:`EarlyWorker.take`) when the loaded task's cell is that file; otherwise the early
process is stopped and the run starts its own. Whatever happens, nothing is planned
before the task is loaded and checked: the early process only loads the cell.

On Linux, when this process runs a single thread (``run-task`` at its start), it imports
what both processes need (numpy, pinocchio, coal, scipy; taskrunner's robot, scene,
kinematics and planning modules) and then forks: the child starts with all that, where a
spawned one would start an interpreter, import it all again and have multiprocessing
start its resource tracker (a third interpreter). Both processes needed those imports
before either could go on, so the first motion comes no later, and the two processes
burn 0.5-0.7 s less CPU before it (what counts on two cores shared with other work;
``benchmarks/RESULTS.md``). With other threads running (a test, an embedding program)
the process is spawned, as :class:`~taskrunner.planning.worker.PlanningWorker` spawns
its own, and nothing is imported beforehand.

This module imports only the standard library and PyYAML: it is imported first.
"""

from __future__ import annotations

import atexit
import gc
import importlib
import multiprocessing as mp
import sys
import threading
import weakref
from multiprocessing.connection import Connection
from pathlib import Path
from typing import TYPE_CHECKING, Any

from taskrunner.processes import start_ignoring_sigint

if TYPE_CHECKING:
    from taskrunner.robot.options import LoadOptions

__all__ = ["EarlyWorker", "start_worker_early", "task_cell"]

_NO_CANCEL = -1  # as taskrunner.planning.worker's


def task_cell(task: Path) -> Path | None:
    """The cell file a task file names, resolved, when it is a plain relative or
    absolute path to an existing file; None otherwise (not YAML, no ``cell``, a
    ``${parameter}`` in it …: the task loader decides and reports, not this)."""
    try:
        import yaml

        loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
        text = task.read_text(encoding="utf-8")
        if len(text) > 1_000_000:
            return None
        tree = yaml.load(text, Loader=loader)  # a safe loader (the C one when built)
    except (OSError, UnicodeDecodeError, ValueError, ImportError, yaml.YAMLError):
        return None
    value = tree.get("cell") if isinstance(tree, dict) else None
    if not isinstance(value, str) or not value or "${" in value:
        return None
    # A name the file system refuses (NUL, too long, a symlink loop) is the loader's to
    # report, at its line: the early worker is simply not started.
    from taskrunner.textfile import file_problem, path_problem

    cell = task.parent / value
    if path_problem(cell) is not None or file_problem(cell) is not None:
        return None
    try:
        return cell.resolve()
    except (OSError, RuntimeError, ValueError):
        return None


def _serve(source: str, conn: Connection, cancel: Any, timing: bool,
           parent_end: Connection | None = None, options: LoadOptions | None = None) -> None:
    """The early process: the planning worker's own loop (imported here, in the child).
    ``parent_end``: the parent's end of the pipe, which a forked child holds too: closed,
    so that the child sees the pipe close when the parent dies."""
    if parent_end is not None:
        parent_end.close()
    from taskrunner.planning.worker import _serve as serve_requests

    serve_requests(source, conn, cancel, 0, timing, options)


def _import_shared() -> None:
    """Import what the worker imports to load its cell and plan, and this process to
    check and run the task (numpy, pinocchio, coal, scipy; taskrunner's robot, scene,
    kinematics and planning modules: 0.4-0.5 s of CPU): before a fork, so that two
    processes do not both pay for them.

    The garbage collector is off meanwhile (its passes over the growing heap of modules,
    classes and functions, which all live as long as the process, took 0.08 s), and what
    exists then is frozen (:func:`gc.freeze`): no later collection in either process
    walks it again (a full one took 0.03 s), nor writes to its pages, which the fork
    shares until one of the processes writes to them (what Python's documentation of
    :func:`gc.freeze` recommends before a fork). Nothing of the imported libraries is
    changed: they are imported as any program imports them."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        for name in ("taskrunner.planning.planner", "taskrunner.robot.cell"):
            importlib.import_module(name)
    finally:
        gc.freeze()
        if enabled:
            gc.enable()


def _start_method() -> str:
    """``fork`` on Linux in a process with one thread, else ``spawn`` (macOS's system
    libraries are not safe to use in a forked child: Python spawns there by default)."""
    if sys.platform.startswith("linux") and threading.active_count() == 1:
        return "fork"
    return "spawn"


class EarlyWorker:
    """A planning worker process started on a cell before the run needs it.

    Args:
        source: the cell file it loads (resolved).
        timing: the worker imports toppra before it reports ready (False: the run
            times its paths in its own process, as ``run-task`` does).
        options: how it loads the cell (passed to the process, not through the
            environment): those the run loads the cell with.

    Attributes:
        source: the cell file it loads (resolved).
        start_method: ``fork`` or ``spawn`` (see the module docstring).
    """

    def __init__(self, source: Path, timing: bool = True,
                 options: LoadOptions | None = None) -> None:
        self.source = source
        self.options = options
        self.start_method = _start_method()
        context = mp.get_context("fork") if self.start_method == "fork" else mp.get_context("spawn")
        if self.start_method == "fork":
            _import_shared()
        self.cancel = context.Value("q", _NO_CANCEL, lock=False)
        self.conn, child = context.Pipe()
        parent_end = self.conn if self.start_method == "fork" else None
        self.process = context.Process(
            target=_serve, args=(str(source), child, self.cancel, timing, parent_end, options),
            name="taskrunner-planner", daemon=False)
        start_ignoring_sigint(self.process)  # as PlanningWorker starts its own
        child.close()
        self._taken = False
        _OPEN.add(self)

    def take(self, cell: str | Path, options: LoadOptions | None = None
             ) -> tuple[Any, Connection, Any] | None:
        """``(process, connection, cancel value)`` for a PlanningWorker to adopt when
        ``cell`` is the file this process loads, with the same ``options``; otherwise
        stop it and return None."""
        from taskrunner.robot.options import LoadOptions

        if self._taken:
            return None
        try:
            same = Path(cell).resolve() == self.source
        except (OSError, RuntimeError, ValueError):  # a symlink loop, a NUL, a name too long
            same = False
        same = same and (options or LoadOptions()) == (self.options or LoadOptions())
        if not same or not self.process.is_alive():
            self.close()
            return None
        self._taken = True
        _OPEN.discard(self)
        return self.process, self.conn, self.cancel

    def close(self) -> None:
        """Stop the process unless a PlanningWorker adopted it (idempotent)."""
        _OPEN.discard(self)
        if self._taken:
            return
        self._taken = True
        if self.process.is_alive():
            self.process.kill()  # it only loads the cell: nothing to finish
        self.process.join(timeout=5.0)
        self.conn.close()


def start_worker_early(task: Path, timing: bool = False,
                       options: LoadOptions | None = None) -> EarlyWorker | None:
    """An :class:`EarlyWorker` on the task's cell, or None when the task file does not
    name one plainly (see :func:`task_cell`). For the command line only: the worker
    loads the cell with no folder policy (a contained server checks every path before
    it is read, and does not call this). ``timing``: as :class:`EarlyWorker`'s;
    False by default: ``run-task`` times its motions in its own process
    (``RunOptions.planner_times``). ``options``: how it loads the cell."""
    cell = task_cell(task)
    return EarlyWorker(cell, timing, options) if cell is not None else None


_OPEN: weakref.WeakSet[EarlyWorker] = weakref.WeakSet()


@atexit.register
def _close_all() -> None:
    """Stop early workers nobody adopted (registered after multiprocessing's exit handler,
    so it runs before that joins the non-daemon processes)."""
    for worker in list(_OPEN):
        worker.close()
