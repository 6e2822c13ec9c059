"""Planning in a worker process, so the caller's threads keep running.

OMPL's ``solve()`` holds the GIL for its whole run: a plan computed in-process freezes
every other Python thread (the behaviour tree, the CLI display, the API's event loop). A
:class:`PlanningWorker` owns a process that loads the robot model once, keeps a planning
scene, and answers plan requests over a pipe. The caller gets a :class:`PlanHandle` at
once and polls it (``done()``), waits for it (``result()``) or cancels it (``cancel()``,
which stops the search inside the worker within one planner iteration).

Scene updates travel with the requests: a snapshot of the caller's scene is sent only when
its objects or allowances differ from those last sent (compared by content, whichever
scene object they come from); the start state always travels in the request.
"""

from __future__ import annotations

import atexit
import gc
import itertools
import logging
import multiprocessing as mp
import os
import signal
import threading
import time
import weakref
from collections.abc import Callable
from dataclasses import replace
from multiprocessing.connection import Connection
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from taskrunner.errors import ArgumentError, PlanningError, TaskrunnerError
from taskrunner.planning.request import JointGoal, PlanRequest, PlanResult
from taskrunner.processes import cpu_seconds, start_ignoring_sigint
from taskrunner.scene import Scene

if TYPE_CHECKING:
    from typing import TypeAlias

    from taskrunner.planning.planner import MotionPlanner
    from taskrunner.robot.options import LoadOptions
    from taskrunner.scene.objects import SceneObject

    SceneContent: TypeAlias = tuple[tuple[SceneObject, ...], tuple[tuple[str, str], ...]]

__all__ = ["PlanHandle", "PlanningWorker", "WorkerDiedError", "stays"]

_NO_CANCEL = -1


class WorkerDiedError(PlanningError):
    """The planning worker process ended while a request was in flight."""


def stays(scene: Scene, request: PlanRequest) -> bool:
    """Whether ``request`` asks for no motion and no timing: its goals are all joint
    goals, one of them equal to its start state (default: the scene's), and it asks for
    no timed path. The planner answers such a request from its checks of the start and
    the goals alone (limits, collisions): no search, no path verification, no toppra."""
    if request.timing is not None or not all(isinstance(g, JointGoal) for g in request.goals):
        return False
    start = scene.state if request.start is None else np.asarray(request.start, dtype=float)
    model = scene.robot
    for goal in request.goals:
        assert isinstance(goal, JointGoal)
        try:
            q = model.state_with(start, goal.values)
        except (TaskrunnerError, IndexError, ValueError):
            return False  # the worker's planner says what is wrong
        if q.shape == start.shape and float(np.max(np.abs(q - start))) < 1e-9:
            return True
    return False


_COMPILE_TIMEOUT = 900.0  # s a loaded worker may take to warm (compile) its verifier
_STARVED = 10.0  # a worker that keeps working may take this many times its limit of wall time
_LOOK_S = 0.25  # s between two looks at a starting worker's CPU time


def _serve(source: str, conn: Connection, cancel: Any, nice: int = 0,
           timing: bool = True, options: LoadOptions | None = None) -> None:
    """The worker process: load the model, then answer requests until told to stop.

    ``options``: how the cell is loaded (strict, package path, missing meshes,
    collision), given by the process that starts this one (pickled with the process's
    arguments): the worker loads what its parent loaded, whatever its environment says.

    ``timing``: import toppra before reporting ready (requests will ask for timed paths);
    False for a caller that times its paths itself (a request that asks still gets its
    path timed: toppra is then imported at that request).

    Ctrl-C in a terminal reaches the whole process group: the worker ignores it and is
    stopped by its parent, which decides what a Ctrl-C means (cancel the run, close the
    worker). A parent in its main thread starts it with SIGINT ignored already (see
    :meth:`PlanningWorker._launch`), so one arriving while it imports is ignored too.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    # The process that started this one loaded the same cell and reported what its load
    # warned about (run-task, the API server): said once, not again from here.
    logging.getLogger("taskrunner.robot").setLevel(logging.ERROR)
    if nice and hasattr(os, "nice"):
        os.nice(nice)
    from taskrunner.planning.planner import MotionPlanner
    from taskrunner.robot.cell import load_cell_or_robot

    # No garbage collection while the model loads and numba is imported: its passes over
    # the growing heap took ~0.01 s of CPU. Collecting again for the verifier's warm-up (a
    # first one on a machine compiles its kernels, which makes much garbage); then what
    # the start left is frozen: later collections skip it (the little cyclic garbage the
    # load made, ~0.35 MB of parsed XML, stays with it).
    collecting = gc.isenabled()
    gc.disable()
    try:
        started = time.perf_counter()
        cell = load_cell_or_robot(source, options=options)
        scene = Scene(cell.model)
        planner = MotionPlanner(scene)
        scene.checker  # noqa: B018 - build the collision geometry before the first request
        if timing:
            from taskrunner.planning.timing import load_toppra

            load_toppra()  # every plan is timed: import it while the caller still loads
        import taskrunner.scene.screen  # noqa: F401 - numba (the path verifier's kernels)
        from taskrunner.planning.warmup import CompiledKernels

        if collecting:
            gc.enable()
        conn.send(("loaded", cell.model.name, time.perf_counter() - started))
        # The compiled kernels loaded from the cache; where they are not there yet (the
        # first time on a machine), compiled in the background while the planner checks
        # with coal alone ("coal"), switching to them between requests once they are in.
        kernels = CompiledKernels()
        kind = "ready" if kernels.prepare(planner) else "coal"
        gc.freeze()
        conn.send((kind, cell.model.name, time.perf_counter() - started))
    except TaskrunnerError as exc:
        conn.send(("failed", exc, 0.0))
        return
    finally:
        if collecting:
            gc.enable()
    while True:
        try:
            message = conn.recv()
        except (EOFError, OSError):
            return
        kind = message[0]
        if kind == "stop":
            return
        _, request_id, snapshot, request = message
        try:
            if snapshot is not None:
                scene.restore(snapshot)
            kernels.update(planner)
            result = planner.plan(request, should_stop=lambda: cancel.value == request_id)
            conn.send(("ok", request_id, result))
        except TaskrunnerError as exc:
            conn.send(("error", request_id, exc))
        except Exception as exc:  # report, never kill the worker silently
            conn.send(("error", request_id, PlanningError(f"{type(exc).__name__}: {exc}")))


class PlanHandle:
    """A request in flight in a :class:`PlanningWorker`."""

    def __init__(self, worker: PlanningWorker, request_id: int) -> None:
        self._worker = worker
        self.request_id = request_id
        self._outcome: tuple[str, Any] | None = None
        self.submitted = time.perf_counter()

    def done(self) -> bool:
        """True once the worker answered (never blocks)."""
        if self._outcome is None:
            self._worker._collect(self, timeout=0.0)
        return self._outcome is not None

    def wait(self, timeout: float) -> bool:
        """Wait up to ``timeout`` seconds for the answer; True once it is there (whatever
        it is: :meth:`result` gives it)."""
        if self._outcome is None:
            self._worker._collect(self, timeout=timeout)
        return self._outcome is not None

    def result(self, timeout: float | None = None) -> PlanResult:
        """The plan, waiting up to ``timeout`` seconds (None: as long as it takes).

        Raises:
            TimeoutError: no answer within ``timeout``.
            PlanningError: whatever the planner raised (same class, same message),
                :class:`WorkerDiedError` if the worker process died.
        """
        if self._outcome is None:
            self._worker._collect(self, timeout=timeout)
        if self._outcome is None:
            raise TimeoutError(f"plan request {self.request_id} not answered in {timeout} s")
        kind, payload = self._outcome
        if kind == "ok":
            return payload
        raise payload

    def cancel(self) -> None:
        """Ask the worker to stop this request; :meth:`result` then raises
        :class:`~taskrunner.errors.PlanningCancelledError` (or returns a plan that was
        finished before the cancel arrived)."""
        if self._outcome is None:
            self._worker._cancel.value = self.request_id


class PlanningWorker:
    """A process that plans for one robot model (cell or robot file).

    Args:
        source: the cell file (or robot manifest / folder / URDF) the worker loads.
        start_timeout: seconds the worker may take to load the model: of its CPU time
            (a worker starved of CPU on a busy machine, at ``nice``, goes on as long as
            it makes progress, up to ten times that of wall time); a worker that uses no
            CPU for that long is stopped as stuck.
        wait_ready: wait for the model to load now (True), or let the caller go on and
            wait at the first request (False: the load overlaps the caller's own work).
        nice: how much lower than the caller's the worker's CPU priority is (0 to 19,
            Unix ``nice``). Planning is throughput work: with 10, a busy worker leaves
            the CPU to latency work (a server answering, a trajectory being streamed)
            and still gets every cycle they leave idle.
        started: a process already serving ``source`` to adopt
            (:mod:`taskrunner.runtime.prestart`), loaded with the same ``options``.
        options: how the worker loads ``source`` (strict, package path, missing meshes,
            collision; default ``LoadOptions()``), handed to the process as an argument:
            the worker's environment plays no part.

    One request is in flight at a time; :meth:`submit` while one is running waits for it.
    Use several workers for parallel planning. Close with :meth:`close` or a ``with``.

    A request to stay where the group is (:func:`stays`) is answered in the caller's
    process, by the same planner on the caller's scene: it needs no search and no path
    verification, so it does not wait for the worker to load or warm up.
    """

    _stays_here: tuple[Scene, MotionPlanner] | None = None
    compile_time: float = 0.0
    """Seconds the worker spent compiling kernels before it was ready (0.0: loaded)."""
    planning_with_coal: bool = False
    """The worker found no compiled kernels when it started: it plans with coal alone
    until their compilation in the background is done (:mod:`taskrunner.planning.warmup`)."""

    def __init__(self, source: str | Path, start_timeout: float = 60.0,
                 wait_ready: bool = True, nice: int = 0,
                 started: tuple[Any, Connection, Any] | None = None,
                 options: LoadOptions | None = None) -> None:
        if isinstance(nice, bool) or not isinstance(nice, int) or not 0 <= nice <= 19:
            raise ArgumentError(f"'nice' must be an integer from 0 to 19 (got {nice!r})")
        self.source = str(source)
        self.nice = nice
        self.options = options
        self._ctx = mp.get_context("spawn")  # no fork: the parent may run threads
        # started: (process, connection, cancel value) of a process already serving
        # ``source`` (taskrunner.runtime.prestart), adopted instead of launching one.
        self._cancel = started[2] if started else self._ctx.Value("q", _NO_CANCEL, lock=False)
        self._ids = itertools.count(1)
        self._lock = threading.Lock()
        self._pending: PlanHandle | None = None
        # The objects and allowances the worker's scene holds (None: unknown, send all).
        self._sent_scene: SceneContent | None = None
        self._start_timeout = start_timeout
        self._ready = False
        if started is None:
            self._launch()
        else:
            self._process, self._conn = started[0], started[1]
            self._released = False  # the process's handle closed (see close())
        _OPEN.add(self)
        if wait_ready:
            self._await_ready(start_timeout)

    def _start(self, timeout: float) -> None:
        self._launch()
        self._await_ready(timeout)

    def _launch(self) -> None:
        """Start the process; it loads the model while the caller goes on."""
        self._ready = False
        self._released = False  # the process's handle closed (see close())
        self._conn, child = self._ctx.Pipe()
        # Not a daemon: loading a xacro robot runs xacro in a child process of its own,
        # which a daemon may not have. Closed by close(), and at exit (_close_all) before
        # multiprocessing joins its non-daemon children; a parent killed outright closes
        # the pipe, and the worker ends at its next read.
        self._process = self._ctx.Process(
            target=_serve, args=(self.source, child, self._cancel, self.nice, True, self.options),
            name="taskrunner-planner", daemon=False)
        start_ignoring_sigint(self._process)
        child.close()

    def _await_ready(self, timeout: float,
                     on_compile: Callable[[], None] | None = None) -> None:
        if self._ready:
            return
        kind = "loaded"
        waited = timeout
        compiling_since: float | None = None
        while kind in ("loaded", "compiling"):
            late = self._wait_for_message(waited)
            if late is not None:
                self._process.kill()
                doing = "load" if waited == timeout else "warm up (compile) its path verifier"
                raise WorkerDiedError(
                    f"planning worker did not {doing} for {self.source}: {late}")
            try:
                kind, payload, seconds = self._conn.recv()
            except (EOFError, OSError):
                self._process.join(timeout=5.0)
                raise WorkerDiedError(
                    f"planning worker for {self.source} exited while starting (exit code "
                    f"{self._process.exitcode}); a script that starts workers needs the "
                    "`if __name__ == '__main__':` guard (workers are spawned, not forked)"
                ) from None
            if kind == "compiling":
                compiling_since = time.perf_counter()
                if on_compile is not None:
                    on_compile()
            # Loaded: the verifier's kernels may compile now, the first time on a machine
            # (minutes on a busy one): wait for that as long as it takes, within reason.
            waited = max(timeout, _COMPILE_TIMEOUT)
        if kind == "failed":
            self._process.join()
            raise payload
        if compiling_since is not None:
            self.compile_time = time.perf_counter() - compiling_since
        self.planning_with_coal = kind == "coal"
        self.model_name = payload
        self.load_time = seconds
        self._sent_scene = None
        self._ready = True

    def _wait_for_message(self, limit: float) -> str | None:
        """Wait for the starting worker's next message: None once it is there, else why
        the worker is given up: it used ``limit`` s of CPU time (a runaway load), or no
        CPU time for ``limit`` s (stuck), or ``_STARVED`` times ``limit`` of wall time
        passed. A worker starved of CPU (at ``nice`` beside busy processes it gets a few %
        of a core) so goes on while it makes progress. Where the CPU time cannot be read,
        ``limit`` s of wall time."""
        pid = self._process.pid
        start = time.monotonic()
        first = last = cpu_seconds(pid)
        progressed = start
        while not self._conn.poll(min(_LOOK_S, limit)):
            now = time.monotonic()
            cpu = cpu_seconds(pid)
            if cpu is None or first is None or last is None:
                if now - start >= limit:
                    return f"no answer in {limit:g} s"
                continue
            if cpu > last:
                last, progressed = cpu, now
            if cpu - first >= limit:
                return f"it used {limit:g} s of CPU time"
            if now - progressed >= limit:
                return f"it used no CPU time for {limit:g} s (stuck?)"
            if now - start >= _STARVED * limit:
                return (f"{now - start:.0f} s passed ({cpu - first:.1f} s of CPU time: a "
                        "machine too busy?)")
        return None

    # ------------------------------------------------------------------ public
    def wait_ready(self, on_compile: Callable[[], None] | None = None) -> float:
        """Wait until the worker has loaded its model and its compiled kernels.

        Args:
            on_compile: called (in this thread) when the worker reports that it compiles
                the kernels, which it does the first time on a machine
                (:mod:`taskrunner.planning.warmup`).

        Returns:
            The seconds this worker spent compiling kernels (0.0: loaded from the cache).

        Raises:
            WorkerDiedError: the worker ended, or did not load or compile in time.
        """
        with self._lock:
            self._await_ready(self._start_timeout, on_compile)
        return self.compile_time

    def submit(self, scene: Scene, request: PlanRequest) -> PlanHandle:
        """Send a request; returns at once with a handle to poll, wait on or cancel.

        The request's start defaults to the scene's current state.
        """
        with self._lock:
            if self._pending is not None:
                self._collect(self._pending, timeout=None)
            if stays(scene, request):
                return self._answer_here(scene, request)
            self._await_ready(self._start_timeout)
            if not self._alive():
                self._start(self._start_timeout)
            if request.start is None:
                request = replace(request, start=scene.state)
            handle = PlanHandle(self, next(self._ids))
            try:
                self._send(handle, scene, request)
            except OSError:  # the worker died since the last answer: restart, send again
                self._process.join(timeout=5.0)
                self._start(60.0)
                self._send(handle, scene, request)
            self._pending = handle
            return handle

    def plan(self, scene: Scene, request: PlanRequest, timeout: float | None = None) -> PlanResult:
        """Plan and wait for the answer (the synchronous form of :meth:`submit`)."""
        return self.submit(scene, request).result(timeout)

    def _alive(self) -> bool:
        return not self._released and self._process.is_alive()

    def close(self) -> None:
        """Stop the worker process (idempotent); the next request starts it again."""
        _OPEN.discard(self)
        self._stays_here = None
        if self._alive():
            try:
                self._cancel.value = self._pending.request_id if self._pending else _NO_CANCEL
                self._conn.send(("stop",))
            except (OSError, BrokenPipeError):
                pass
            self._process.join(timeout=5.0)
            if self._alive():
                self._process.kill()
                self._process.join(timeout=5.0)
        self._conn.close()
        # The process's own handle (its sentinel pipe) is let go now, not when this object
        # is collected: a server that opens and reaps planners keeps no descriptor of theirs.
        if not self._released and self._process.exitcode is not None:
            self._process.close()
            self._released = True

    def __enter__(self) -> PlanningWorker:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------ internals
    def _answer_here(self, scene: Scene, request: PlanRequest) -> PlanHandle:
        """Plan a request that stays (:func:`stays`) in this process, on ``scene``: a
        handle answered already."""
        from taskrunner.planning.planner import MotionPlanner

        here = self._stays_here
        if here is None or here[0] is not scene:
            here = self._stays_here = (scene, MotionPlanner(scene))
        if request.start is None:
            request = replace(request, start=scene.state)
        handle = PlanHandle(self, next(self._ids))
        try:
            handle._outcome = ("ok", here[1].plan(request))
        except TaskrunnerError as exc:
            handle._outcome = ("error", exc)
        return handle

    def _send(self, handle: PlanHandle, scene: Scene, request: PlanRequest) -> None:
        # By content, not by the scene's identity and revision: another scene (a new one
        # where a freed one was, at the same revision) holds other objects.
        snapshot = scene.snapshot()
        content = (snapshot.objects, snapshot.allowed)
        self._conn.send(("plan", handle.request_id,
                         snapshot if content != self._sent_scene else None, request))
        self._sent_scene = content

    def _collect(self, handle: PlanHandle, timeout: float | None) -> None:
        """Read the worker's answer for ``handle`` if there is one within ``timeout``."""
        if handle is not self._pending or handle._outcome is not None:
            return
        deadline = None if timeout is None else time.perf_counter() + timeout
        while True:
            remaining = None if deadline is None else max(0.0, deadline - time.perf_counter())
            # Poll in slices so a dead worker is noticed even without an answer.
            if self._conn.poll(0.05 if remaining is None else min(remaining, 0.05)):
                try:
                    kind, request_id, payload = self._conn.recv()
                except (EOFError, OSError):
                    self._died(handle)
                    return
                if request_id == handle.request_id:
                    handle._outcome = (kind, payload)
                    self._pending = None
                    self._cancel.value = _NO_CANCEL
                    if kind != "ok":
                        # The worker may have failed while restoring the scene we sent:
                        # send the whole scene again with the next request, so one failed
                        # plan never leaves the worker planning in a stale world.
                        self._sent_scene = None
                    return
            elif not self._alive():
                self._died(handle)
                return
            if deadline is not None and time.perf_counter() >= deadline:
                return

    def _died(self, handle: PlanHandle) -> None:
        self._process.join(timeout=5.0)
        code = self._process.exitcode
        handle._outcome = ("error", WorkerDiedError(
            f"planning worker for {self.source} died (exit code {code}) during request "
            f"{handle.request_id}; it restarts with the next request"))
        self._pending = None
        self._sent_scene = None


_OPEN: weakref.WeakSet[PlanningWorker] = weakref.WeakSet()


@atexit.register
def _close_all() -> None:
    """Stop the workers still open at exit (registered after multiprocessing's own exit
    handler, so it runs before that joins the non-daemon workers)."""
    for worker in list(_OPEN):
        worker.close()
