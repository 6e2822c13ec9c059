"""Work a request makes the server do, bounded: loading and checking the tasks it sends.

A request can send a task that takes the loader a long time or a lot of memory (a YAML
alias bomb, an include diamond, a deep nesting). Such work runs in a worker process
(:class:`RequestWork` with ``isolation="process"``) under an address-space limit, and a
worker that has not answered within the time limit is killed and replaced; the request
answers 422 (:class:`WorkLimitError`) and the server never held the memory nor spent
its own CPU. With ``isolation="inprocess"`` (tests) the work runs in a thread: the
answer still comes within the time limit, but the work runs on to its end.

The work is done under the server's :class:`~taskrunner.folders.FolderPolicy`, made the
active one in the worker, so the loaders refuse files outside its folders there too.
"""

from __future__ import annotations

import atexit
import logging
import multiprocessing
import threading
import time
import weakref
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from taskrunner.errors import ServiceError
from taskrunner.folders import FolderPolicy
from taskrunner.robot.options import LoadOptions
from taskrunner.taught import TaughtPoses

__all__ = ["RequestWork", "WorkLimitError", "check_request", "load_request"]

log = logging.getLogger(__name__)

INLINE_NAME = "inline.yaml"


class WorkLimitError(ServiceError):
    """A request's work went past the server's time or memory limit (HTTP 422)."""


@dataclass(frozen=True)
class _Failure:
    """An exception raised in a worker, with the ``problems`` a pickled
    :class:`~taskrunner.errors.TaskSpecError` would lose."""

    error: BaseException
    problems: Any = None


def _serve(conn: Any, memory_bytes: int) -> None:
    """A worker's loop: run each ``(function, args)`` received, send back its result."""
    import resource

    # Imports first (they are shared by every request): the limit bounds what requests add.
    import taskrunner.tree.check  # noqa: F401

    try:
        _, hard = resource.getrlimit(resource.RLIMIT_AS)
        limit = memory_bytes if hard == resource.RLIM_INFINITY else min(memory_bytes, hard)
        resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    except (ValueError, OSError):  # a platform without it: the time limit still holds
        pass
    while True:
        try:
            function, args = conn.recv()
        except (EOFError, OSError):
            return
        try:
            outcome: Any = ("ok", function(*args))
        except MemoryError:
            outcome = ("err", _Failure(WorkLimitError("the request's task needs more memory "
                                                      "than the server allows")))
        except Exception as exc:
            outcome = ("err", _Failure(exc, getattr(exc, "problems", None)))
        try:
            conn.send(outcome)
        except Exception as exc:
            conn.send(("err", _Failure(WorkLimitError(f"the answer could not be sent ({exc})"))))


class _Worker:
    def __init__(self, memory_bytes: int) -> None:
        context = multiprocessing.get_context("spawn")
        self.conn, child = context.Pipe()
        # Not a daemon: a check loads xacro in a child process of its own. Workers are
        # killed by close(), and at exit (below) before multiprocessing joins them.
        self.process = context.Process(target=_serve, args=(child, memory_bytes),
                                       name="taskrunner-request-work", daemon=False)
        self.process.start()
        child.close()

    def kill(self) -> None:
        self.process.kill()
        self.process.join(5.0)
        self.conn.close()


class RequestWork:
    """Runs a request's work with a time limit (and, in a process, a memory limit).

    Args:
        isolation: ``process`` (workers killed past the limit) or ``inprocess`` (threads).
        timeout_s: the time limit of one call, waiting for a free worker included (s).
        memory_mb: the address-space limit of a worker process (MiB).
        workers: how many calls run at once.
        setting: the setting that sets the time limit (named in messages).
        what: what took too long, for messages (``{s}``: the limit).
    """

    def __init__(self, isolation: str, timeout_s: float, memory_mb: int, workers: int,
                 setting: str = "check_timeout_s",
                 what: str = "the request's task took longer than {s} s to load and check"
                 ) -> None:
        self.isolation = isolation
        self.what = what
        self.timeout_s = timeout_s
        self.memory_bytes = memory_mb * 1024 * 1024
        self.setting = setting
        self._slots = threading.BoundedSemaphore(workers)
        self._idle: list[_Worker] = []
        self._lock = threading.Lock()
        self._closed = False
        _OPEN.add(self)

    def start(self) -> None:
        """Start one worker now, so that the first request does not wait for it."""
        if self.isolation == "process":
            with self._lock:
                self._idle.append(_Worker(self.memory_bytes))

    def call(self, function: Callable[..., Any], *args: Any) -> Any:
        """``function(*args)``, run within the limits (blocks; call it off the event loop).

        Raises:
            WorkLimitError: past the time limit, out of memory, or the worker died.
            Whatever ``function`` raised (a :class:`~taskrunner.errors.TaskSpecError`
            keeps its ``problems``).
        """
        deadline = time.monotonic() + self.timeout_s
        if not self._slots.acquire(timeout=self.timeout_s):
            raise self._too_long("waiting for the requests before it")
        try:
            if self.isolation == "inprocess":
                return self._in_thread(function, args, deadline)
            return self._in_process(function, args, deadline)
        finally:
            self._slots.release()

    def _too_long(self, detail: str = "") -> WorkLimitError:
        extra = f", {detail}" if detail else ""
        what = self.what.replace("{s}", f"{self.timeout_s:g}")
        return WorkLimitError(f"{what}{extra}; it was stopped (server setting "
                              f"{self.setting!r})")

    def _in_thread(self, function: Callable[..., Any], args: tuple[Any, ...],
                   deadline: float) -> Any:
        box: list[tuple[str, Any]] = []

        def work() -> None:
            try:
                box.append(("ok", function(*args)))
            except BaseException as exc:
                box.append(("err", exc))

        thread = threading.Thread(target=work, daemon=True, name="request-work")
        thread.start()
        thread.join(max(0.0, deadline - time.monotonic()))
        if not box:
            raise self._too_long()
        kind, value = box[0]
        if kind == "err":
            raise value
        return value

    def _in_process(self, function: Callable[..., Any], args: tuple[Any, ...],
                    deadline: float) -> Any:
        with self._lock:
            if self._closed:
                raise WorkLimitError("the server is shutting down")
            worker = self._idle.pop() if self._idle else None
        if worker is None or not worker.process.is_alive():
            worker = _Worker(self.memory_bytes)
        try:
            worker.conn.send((function, args))
            ready = worker.conn.poll(max(0.0, deadline - time.monotonic()))
            outcome = worker.conn.recv() if ready else None
        except (EOFError, OSError):
            worker.kill()
            raise WorkLimitError("the request's task made the checking process fail (out "
                                 "of memory?); it was stopped") from None
        if outcome is None:
            worker.kill()
            raise self._too_long()
        with self._lock:
            if self._closed:
                worker.kill()
            else:
                self._idle.append(worker)
        kind, value = outcome
        if kind == "ok":
            return value
        assert isinstance(value, _Failure)
        if value.problems is not None:
            value.error.problems = value.problems  # type: ignore[attr-defined]
        raise value.error

    def close(self) -> None:
        with self._lock:
            self._closed = True
            idle, self._idle = self._idle, []
        for worker in idle:
            worker.kill()


_OPEN: weakref.WeakSet[RequestWork] = weakref.WeakSet()


@atexit.register
def _close_all() -> None:
    """Kill the workers still running at exit (registered after multiprocessing's own
    exit handler, so it runs before that joins the non-daemon workers)."""
    for work in list(_OPEN):
        work.close()


# --------------------------------------------------------------- the work itself
def inline_path(tasks_dir: Path) -> Path:
    """The path inline YAML stands for: messages name it; relative paths start there."""
    return tasks_dir / INLINE_NAME


def load_request(policy: FolderPolicy, tasks_dir: Path, task: str | None, yaml: str | None,
                 parameters: dict[str, Any]) -> tuple[Any, str, str]:
    """The task of a request: ``(spec, task_file, task_text)``, loaded under ``policy``.

    An inline task is held in memory (never written anywhere); its spec has no path.

    Raises:
        InputError: no such task file; TaskSpecError: an invalid task (file:line);
        PathNotAllowedError: a file outside the policy's folders.
    """
    from taskrunner.tasks import load_task, load_task_text

    if task is not None:
        path = resolve_task_file(tasks_dir, task)
        spec = load_task(path, parameters, policy=policy)
        return spec, str(path), path.read_text(encoding="utf-8")
    assert yaml is not None
    shown = inline_path(tasks_dir)
    spec = load_task_text(yaml, shown, parameters, policy=policy.with_memory({shown: yaml}))
    return spec.model_copy(update={"path": None}), str(shown), yaml


def _check_report(policy: FolderPolicy, tasks_dir: Path, task: str | None,
                  yaml: str | None, parameters: dict[str, Any], seed: int,
                  taught: TaughtPoses | None, options: LoadOptions | None = None) -> Any:
    """``check_task`` of a request's task under ``policy``: a file of the tasks folder, or
    inline YAML held in memory as ``inline.yaml`` of the tasks folder, with the ``taught``
    poses of its cell as a run would have them, its robots loaded with ``options``."""
    from taskrunner.tree.check import check_task

    if task is not None:
        path = resolve_task_file(tasks_dir, task)
        given = policy
    else:
        assert yaml is not None
        path = inline_path(tasks_dir)
        given = policy.with_memory({path: yaml})
    return check_task(path, parameters, seed=seed, policy=given, taught=taught,
                      options=options)


def precheck_request(policy: FolderPolicy, tasks_dir: Path, task: str | None,
                     yaml: str | None, parameters: dict[str, Any], seed: int,
                     taught: TaughtPoses | None = None,
                     options: LoadOptions | None = None) -> list[Any]:
    """The problems (:class:`~taskrunner.tasks.problem.Problem`) the static check finds in
    the task a run request names, checked as ``/tasks/check`` checks it; empty when the
    run may start. ``POST /runs`` calls this first so that nothing moves for a task that
    cannot succeed (as ``run-task`` does)."""
    return list(_check_report(policy, tasks_dir, task, yaml, parameters, seed,
                              taught, options).problems)


def check_request(policy: FolderPolicy, tasks_dir: Path, task: str | None, yaml: str | None,
                  parameters: dict[str, Any], seed: int,
                  taught: TaughtPoses | None = None,
                  options: LoadOptions | None = None) -> dict[str, Any]:
    """The ``/tasks/check`` answer (``ok``, ``cell``, ``steps``, ``problems``, what each
    parallel's ``schedules`` prove) for a
    task file of the tasks folder or inline YAML, checked under ``policy`` (an inline
    task is a file held in memory: ``inline.yaml`` of the tasks folder), with the
    ``taught`` poses of its cell as a run would have them."""
    from taskrunner.api.handlers import problem_out

    report = _check_report(policy, tasks_dir, task, yaml, parameters, seed, taught, options)
    problems = [problem_out(p) for p in report.problems]
    return {"ok": not problems, "cell": report.cell, "steps": report.steps,
            "problems": problems, "schedules": [p.to_dict() for p in report.schedules]}


def resolve_task_file(tasks_dir: Path, name: str) -> Path:
    """The task file ``name`` (a plain file name, ``.yaml`` optional) in ``tasks_dir``.

    Raises:
        InputError: a path rather than a file name, or no such file.
    """
    from taskrunner.errors import InputError

    if not name or "/" in name or "\\" in name or name.startswith(".") or "\0" in name:
        raise InputError(f"'task' must be a file name in the tasks folder (got {name!r})")
    if len(name.encode("utf-8", "surrogatepass")) > 250:  # file names end at 255 bytes
        raise InputError(f"'task' must be a file name of at most 250 bytes "
                         f"(got {len(name.encode('utf-8', 'surrogatepass'))} bytes)")
    path = tasks_dir / name
    if not path.suffix:
        path = path.with_suffix(".yaml")
    try:
        found = path.is_file()
    except (OSError, ValueError):  # a name the file system refuses is no task file
        found = False
    if not found:
        known = ", ".join(sorted(p.name for p in tasks_dir.glob("*.yaml"))) or "none"
        raise InputError(f"'task' must name a task file of the tasks folder (got {name!r}; "
                         f"known: {known})")
    return path
