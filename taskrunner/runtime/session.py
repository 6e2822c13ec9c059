"""One ``run-task FILE`` session: load, build the backend and the planner, run, report.

The run itself happens on a worker thread; the main thread shows progress (a live tree in
a terminal, plain log lines otherwise) and turns Ctrl-C (SIGINT) and SIGTERM into a cancel:
the motion stops where it is, the planning worker is stopped, the summary is printed and
the run is recorded as ``cancelled`` with the reason, exit code 130 for Ctrl-C and 143
(128 + SIGTERM) for SIGTERM. A signal that arrives while the task still loads cancels the
run before anything moves. A third Ctrl-C gives up waiting for the motion to stop.
"""

from __future__ import annotations

import math
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import AbstractContextManager, ExitStack, contextmanager
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING, TextIO

from taskrunner.backends import (
    HttpBackend,
    MockBackend,
    MockOptions,
    SerialBackend,
    ServoCalibration,
    ServoOptions,
    SimBackend,
    SimOptions,
    load_calibration,
)
from taskrunner.backends.base import Backend
from taskrunner.errors import ArgumentError, InputError
from taskrunner.kinds import BackendKind, NodeStatus
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.robot.options import LoadOptions
from taskrunner.runtime.display import LiveTree
from taskrunner.runtime.events import EventLog, RunEvent
from taskrunner.runtime.preflight import check_before_run
from taskrunner.runtime.records import RunRecord
from taskrunner.runtime.runner import EXIT_CODES, Runner, RunOptions
from taskrunner.tasks.loader import load_task
from taskrunner.tree.start import task_start

if TYPE_CHECKING:
    import numpy as np

    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.planning.worker import PlanningWorker
    from taskrunner.runtime.prestart import EarlyWorker
    from taskrunner.runtime.resume import ResumePlan
    from taskrunner.tasks.spec import TaskSpec
    from taskrunner.taught import TaughtPoses
    from taskrunner.tree.check import CheckReport

__all__ = ["BACKENDS", "make_backend", "run_task_file", "servo_calibration", "warm_up_command"]


BACKENDS = tuple(kind.value for kind in BackendKind)
_FRAME_PERIOD = 0.1  # s between frames of the live tree


def make_backend(kind: str, cell: Cell, speed: float | None, port: str | None = None,
                 url: str | None = None, firmware_speedup: float = 1.0,
                 home: bool = False, start: np.ndarray | None = None,
                 calibration_file: str | None = None,
                 hardware: str | Path | None = None) -> Backend:
    """A backend driving every joint of the cell.

    mock, sim and mujoco (physics, :mod:`taskrunner.backends.physics`; ``speed`` None:
    as fast as it steps) start at ``start`` (every joint of the cell; None: the cell's
    start state; a task's: :func:`taskrunner.tree.start.task_start`); serial (``port``, default the one in
    hardware.yaml) and http (``url``) drive the servos through the calibration and start
    where the servos are: a cell with one robot without a prefix uses the robot's
    hardware.yaml; a cell with several robots on one servo board (``servo_arm_pair``) uses
    the cell's ``<cell>.hardware.yaml`` next to the cell file (which board channels drive
    which robot's servos; each robot's own hardware.yaml for the rest).
    ``firmware_speedup`` matches a host build of the firmware run faster than real time
    (``run-task firmware-sim --speedup``). feetech drives bus servos (the SO-101) where
    they are, on the buses of the cell's ``<cell>.hardware.yaml`` (or ``hardware``), with
    ``port`` and ``calibration_file`` overriding its ports and LeRobot calibration files
    (:mod:`taskrunner.backends.feetech.hardware`).

    Raises:
        InputError: a speed that is not a positive number, a servo backend on a cell
            without a calibration (one robot's hardware.yaml or the cell's board file),
            or http without a URL.
        BackendError: the port or URL does not answer as the firmware does.
    """
    if speed is not None and not (isinstance(speed, (int, float)) and 0 < speed < math.inf):
        raise InputError(f"'speed' must be a positive number (got {speed!r})")
    names = cell.model.joint_names
    start_q = cell.start_state() if start is None else start
    if len(start_q) != len(names):
        raise ArgumentError(f"'start' must have {len(names)} values, one per joint of the cell "
                         f"(got {len(start_q)})")
    initial = dict(zip(names, (float(v) for v in start_q)))
    if kind == "mock":
        return MockBackend(names, initial, MockOptions(speed=speed))
    if kind == "sim":
        return SimBackend(names, initial, SimOptions(speed=1.0 if speed is None else speed))
    if kind == "mujoco":
        return _mujoco_backend(cell, speed, initial)
    if kind == "feetech":
        return _feetech_backend(cell, port, calibration_file, hardware, firmware_speedup)
    if kind not in BACKENDS:
        raise ArgumentError(f"'backend' must be one of {', '.join(BACKENDS)} (got {kind!r})")
    robots = cell.model.instances
    if len(robots) == 1 and not robots[0].prefix:
        calibration = servo_calibration(cell)
    else:
        from taskrunner.backends.calibration import RobotOnBoard, load_board_calibration

        board = (cell.path.parent / f"{cell.path.stem}.hardware.yaml"
                 if cell.path is not None else None)
        if board is None or not board.is_file():
            raise InputError(f"servo backends drive cell {cell.name!r} ("
                             f"{', '.join(r.name for r in robots)}) through one servo board "
                             f"described in {board or '<cell>.hardware.yaml'}, which does not "
                             "exist (see cells/servo_arm_pair.hardware.yaml)")
        on_board = []
        for robot in robots:
            if robot.hardware_path is None:
                raise InputError(f"robot {robot.name!r} has no hardware.yaml (servo "
                                 "calibration)", robot.source)
            own = tuple(j.name[len(robot.prefix):] for j in cell.model.joints
                        if j.robot == robot.name)
            on_board.append(RobotOnBoard(robot.name, robot.prefix, robot.hardware_path, own))
        calibration = load_board_calibration(board, on_board)
    options = ServoOptions(time_scale=firmware_speedup, home_on_start=home,
                           lead_ms=min(4000, max(400, int(400 * firmware_speedup))),
                           poll_period=min(0.04, 0.04 / firmware_speedup))
    if kind == "serial":
        return SerialBackend(names, calibration, port or calibration.port or "", options)
    if not url:
        raise InputError("the http backend needs --url (the ESP32's /api/command URL)")
    return HttpBackend(names, calibration, url, options)


MUJOCO_MISSING = ("the mujoco backend needs mujoco and trimesh: pip install 'mujoco>=3.2,<4' "
                  "'trimesh>=4.0,<6' (from a checkout: pip install -e '.[mujoco]')")


def _mujoco_backend(cell: Cell, speed: float | None, start: dict[str, float]) -> Backend:
    """The physics backend (``speed`` None: as fast as the machine steps)."""
    try:
        from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell
    except ImportError as exc:
        if exc.name is not None and exc.name.split(".")[0] == "mujoco":
            raise InputError(MUJOCO_MISSING) from None
        raise
    return MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                         MujocoOptions(speed=speed))


def _feetech_backend(cell: Cell, port: str | None, calibration: str | None,
                     hardware: str | Path | None, speedup: float) -> Backend:
    """Bus servos on the buses of the cell's hardware file (``hardware``: another one);
    ``speedup``: an emulator's (``run-task bus-sim --speedup``), 1 for real servos."""
    from taskrunner.backends.feetech import FeetechOptions
    from taskrunner.backends.feetech.hardware import CellRobot, open_feetech_backend

    if hardware is None:
        if cell.path is None:
            raise InputError(f"the feetech backend needs a hardware file for cell "
                             f"{cell.name!r} (--hardware FILE): the cell was not loaded from "
                             "a file")
        hardware = cell.path.parent / f"{cell.path.stem}.hardware.yaml"
        if not hardware.is_file():
            raise InputError(f"the feetech backend drives cell {cell.name!r} through the buses "
                             f"its hardware file names: {hardware} does not exist (see "
                             "cells/so101_table.hardware.yaml; or --hardware FILE)")
    return open_feetech_backend(hardware, [CellRobot(r.name, r.prefix)
                                           for r in cell.model.instances],
                                cell.model.joint_names, port=port, calibration=calibration,
                                options=FeetechOptions(time_scale=speedup))


def servo_calibration(cell: Cell) -> ServoCalibration:
    """The hardware.yaml calibration of the cell's one robot."""
    robots = cell.model.instances
    if len(robots) != 1 or robots[0].prefix:
        raise InputError(f"servo backends drive one robot without a name prefix; cell "
                         f"{cell.name!r} has {', '.join(r.name for r in robots)}")
    if robots[0].hardware_path is None:
        raise InputError(f"robot {robots[0].name!r} has no hardware.yaml (servo calibration)",
                         robots[0].source)
    return load_calibration(robots[0].hardware_path, cell.model.joint_names)


def _can_redraw() -> bool:
    """Whether the terminal moves its cursor (not so for TERM=dumb: log lines there)."""
    return os.environ.get("TERM", "") != "dumb"


def _import_toppra() -> None:
    from taskrunner.planning.timing import load_toppra

    load_toppra()


WARM_UP_NOTE = "preparing the planner's compiled kernels (first run on this machine, ~5 s)"
COAL_NOTE = ("the planner's compiled kernels are compiling in the background (first run on "
             "this machine); planning with coal alone meanwhile (as exact, slower)")


def _prepare_kernels(planner: PlanningWorker | InProcessPlanner, out: TextIO,
                     stop: _StopSignals, live: bool) -> float | None:
    """Wait until the planner's compiled kernels are loaded, compiling them if this
    machine has none yet (:mod:`taskrunner.planning.warmup`), with a line that says so and,
    in a terminal, the seconds going by. A Ctrl-C or SIGTERM meanwhile ends the wait (the
    run is then cancelled before it starts).

    Returns:
        The seconds spent compiling, None when the kernels were in the cache.
    """
    from taskrunner.planning.worker import PlanningWorker

    progress = _Progress(out, WARM_UP_NOTE, live)
    if isinstance(planner, PlanningWorker):
        waiting = threading.Thread(target=_wait_ready, args=(planner, progress),
                                   name="kernel-warm-up", daemon=True)
        waiting.start()
        while waiting.is_alive() and stop.pending is None:
            waiting.join(0.2)
            progress.tick()
        if stop.pending is not None:
            progress.end("stopped")
            return None
        if progress.failure is not None:
            raise progress.failure
        if planner.planning_with_coal:
            print(COAL_NOTE, file=out, flush=True)
        seconds = planner.compile_time
    else:
        from taskrunner.planning.warmup import kernels_ready, warm_up_kernels

        if kernels_ready():
            return None  # loaded by the first plan, in a fraction of a second
        seconds = warm_up_kernels(on_compile=progress.start)
    if not progress.started:
        return None
    progress.end(f"ready in {seconds:.1f} s (not counted as task time)")
    return round(seconds, 3)


def warm_up_command(out: TextIO | None = None) -> int:
    """``run-task warm-up``: compile the planner's kernels into the user cache (or say
    they are there already), with a progress line; exit code 0."""
    from taskrunner.planning.warmup import kernels_ready, warm_up_kernels
    from taskrunner.resources import kernel_cache_dir

    out = out or sys.stdout
    if kernels_ready():
        print(f"the planner's compiled kernels are ready (cache: {kernel_cache_dir()})",
              file=out)
        return 0
    progress = _Progress(out, "compiling the planner's kernels (once per machine, ~5 s)",
                         _can_redraw() and out.isatty())
    ticking = threading.Event()

    def tick() -> None:
        while not ticking.wait(0.5):
            progress.tick()

    threading.Thread(target=tick, name="warm-up-progress", daemon=True).start()
    try:
        seconds = warm_up_kernels(on_compile=progress.start)
    finally:
        ticking.set()
    progress.end(f"done in {seconds:.1f} s (cache: {kernel_cache_dir()})")
    return 0


def _wait_ready(worker: PlanningWorker, progress: _Progress) -> None:
    try:
        worker.wait_ready(on_compile=progress.start)
    except BaseException as exc:  # raised in the main thread
        progress.failure = exc


class _Progress:
    """One line of output for a wait: said when it starts, redrawn with the seconds
    going by in a terminal, ended with an outcome."""

    def __init__(self, out: TextIO, text: str, live: bool) -> None:
        self.out, self.text, self.live = out, text, live
        self.started: float | None = None
        self.failure: BaseException | None = None
        self._shown = ""

    def start(self) -> None:
        self.started = time.perf_counter()
        print(f"{self.text} …", end="" if self.live else "\n", file=self.out, flush=True)

    def tick(self) -> None:
        if self.live and self.started is not None:
            seconds = f"{time.perf_counter() - self.started:.0f}"
            if seconds != self._shown:  # redrawn once a second
                self._shown = seconds
                print(f"\r{self.text} … {seconds} s", end="", file=self.out, flush=True)

    def end(self, outcome: str) -> None:
        if self.started is None:
            return
        if self.live:
            print(f"\r{self.text}: {outcome}\x1b[K", file=self.out, flush=True)
        else:
            print(f"  {outcome}", file=self.out, flush=True)


def _log_line(event: RunEvent) -> str | None:
    where = f"  ({event.location})" if event.location else ""
    if event.kind == "node_started":
        return f"{event.time:8.2f}s  ▶ {event.node}{where}"
    if event.kind == "planned":
        d = event.data
        return (f"{event.time:8.2f}s    planned in {1e3 * d.get('planning_time', 0):.0f} ms, "
                f"motion {d.get('duration', 0):.2f} s")
    if event.kind == "node_finished":
        marks: dict[str, str] = {NodeStatus.SUCCESS: "✔", NodeStatus.FAILURE: "✘"}
        mark = marks.get(event.status or "", "■")
        took = event.data.get("seconds")
        timing = f" in {took:.2f} s" if took is not None else ""
        tail = f": {event.message}" if event.message and event.status == NodeStatus.FAILURE else ""
        return f"{event.time:8.2f}s  {mark} {event.node}{timing}{tail}"
    if event.kind in ("run_started", "run_finished", "message"):
        return f"{event.time:8.2f}s  {event.message}"
    if event.kind == "physics" and event.data.get("grasps"):  # grasp_mode weld made/released
        return f"{event.time:8.2f}s    physics: {event.message}"
    return None


def run_task_file(path: Path, backend: str = "mock", parameters: dict[str, str] | None = None,
                  speed: float | None = None, seed: int = 0, runs_dir: Path | None = None,
                  live: bool = False, worker: bool = True, out: TextIO | None = None,
                  port: str | None = None, url: str | None = None,
                  calibration: str | None = None, hardware: str | None = None,
                  firmware_speedup: float = 1.0, home: bool = False,
                  check: bool = True, early: EarlyWorker | None = None,
                  loaded: CheckReport | None = None,
                  watch: Sequence[Callable[[Runner], AbstractContextManager[object]]] = (),
                  resume: ResumePlan | None = None,
                  taught: TaughtPoses | None = None,
                  options: LoadOptions | None = None) -> int:
    """Run a task file; returns the exit code (see :data:`EXIT_CODES`).

    With ``check``, the task is checked first (:func:`check_before_run`) and nothing
    moves when the check finds a problem. Called from the main thread, Ctrl-C and
    SIGTERM cancel the run (see the module docstring) instead of raising. ``early``: a
    planning worker process started beforehand (:mod:`taskrunner.runtime.prestart`),
    adopted when it loads the task's cell, else stopped; closed at the end either way.
    ``loaded``: the report of a check of this same file with these same ``parameters``
    (:func:`check_before_run`, ``check`` False): the run starts from the task and the
    cell the check loaded instead of loading them again (the same objects a second load
    gives: the check changes neither). ``watch``: each called with the runner, the run
    goes inside the context it returns (a live feed; an export when the run has ended).
    ``resume``: continue the run it was made from (:mod:`taskrunner.runtime.resume`;
    ``check`` is then not done: the task is not at its start); mock and sim start where
    that run left the arm. ``taught``: taught poses added to the cell's named poses
    (:mod:`taskrunner.taught`; None: none), for the check and the run alike. ``options``:
    how the cell's robots are loaded (:mod:`taskrunner.robot.options`), here and in the
    planning worker, for the check and the run alike.

    Raises:
        InputError (TaskSpecError, YamlError, RobotDescriptionError): an invalid task or
            cell, or a check that found problems (all in the TaskSpecError's
            ``problems``); the CLI maps it to exit code 2.
    """
    out = out or sys.stdout
    live = live and _can_redraw()
    if check:
        loaded = check_before_run(path, parameters, seed=seed, taught=taught, options=options)
    reused = _from_check(loaded, path)
    stop = _StopSignals(out)
    with stop.installed():
        spec = reused[0] if reused is not None else load_task(path, parameters or {})
        # toppra takes 0.3-0.5 s to import: do it while the rest loads.
        threading.Thread(target=_import_toppra, daemon=True).start()
        planner_service: PlanningWorker | InProcessPlanner | None = None  # one or the other
        if worker:
            from taskrunner.planning.worker import PlanningWorker

            started = early.take(spec.cell, options) if early is not None else None
            planner_service = PlanningWorker(spec.cell, wait_ready=False, started=started,
                                             options=options)
        elif early is not None:
            early.close()
        try:
            cell = reused[1] if reused is not None else _checked_cell(loaded, spec)
            if cell is None:
                cell = load_cell(spec.cell, taught=taught, options=options)
            if not worker:
                from taskrunner.planning.service import InProcessPlanner

                planner_service = InProcessPlanner()
            start = resume.start_state(cell) if resume is not None else task_start(spec, cell).q
            machine = make_backend(backend, cell, speed, port, url, firmware_speedup, home,
                                   start=start, calibration_file=calibration,
                                   hardware=hardware)
        except BaseException:
            # A cell that fails to load before the in-process planner exists leaves none.
            if planner_service is not None:
                planner_service.close()
            raise
        assert planner_service is not None  # set in the try above, or it raised
        try:
            # The run's clocks (its events', its task time) start once the planner's
            # kernels are ready: compiling them (the first run on a machine) is said,
            # waited for, and recorded apart.
            warm_up_s = _prepare_kernels(planner_service, out, stop, live)
            events = EventLog()
            runner = Runner(spec, cell, machine, planner_service,
                            RunOptions(seed=seed, runs_dir=runs_dir, backend_name=backend,
                                       load_options=None if options is None
                                       else options.as_data()),
                            events=events, resume=resume)
            runner.record.warm_up_s = warm_up_s
            if not live:
                def log(event: RunEvent) -> None:
                    line = _log_line(event)
                    if line:
                        print(line, file=out, flush=True)
                events.subscribe(log)
            stop.attach(runner)
            with ExitStack() as watching:
                for each in watch:
                    watching.enter_context(each(runner))
                record = _run_with_display(runner, live, out, stop)
        finally:
            machine.close()
            planner_service.close()
    _summary(record, runner, runs_dir, out)
    return record.exit_code if record.exit_code is not None else EXIT_CODES["planning"]


def _from_check(report: CheckReport | None, path: Path) -> tuple[TaskSpec, Cell] | None:
    """The task and cell a check of ``path`` loaded, when it loaded them from that very
    path (the check resolves it: a relative path is loaded again, so that messages name
    the file as given)."""
    if report is None or report.task is None or report.loaded_cell is None \
            or report.task.path != Path(path):
        return None
    return report.task, report.loaded_cell


def _checked_cell(report: CheckReport | None, spec: TaskSpec) -> Cell | None:
    """The cell the check loaded, when the task (loaded again: a relative path) names the
    same cell file: loaded once, and its warnings said once."""
    if report is None or report.task is None or report.loaded_cell is None:
        return None
    try:
        same = Path(report.task.cell).resolve() == Path(spec.cell).resolve()
    except (OSError, RuntimeError, ValueError):
        return None
    return report.loaded_cell if same else None


class _StopSignals:
    """Ctrl-C and SIGTERM as a cancel of the run (main thread only; elsewhere a no-op).

    The handlers never raise (a KeyboardInterrupt in the middle of ``Thread.join`` leaves
    the thread's lock in a state where the next ``join`` returns at once, CPython 3.11):
    they ask the runner to stop, or remember the request until there is a runner.
    """

    _REASONS = {signal.SIGINT: ("cancelled (Ctrl-C)", EXIT_CODES["cancelled"]),
                signal.SIGTERM: ("cancelled (SIGTERM)", EXIT_CODES["terminated"])}

    def __init__(self, out: TextIO) -> None:
        self.out = out
        self.runner: Runner | None = None
        self.pending: tuple[str, int] | None = None
        self.count = 0
        self.display: LiveTree | None = None  # while a live tree is drawn: notices go there

    def say(self, text: str) -> None:
        """Tell the user (on the live tree's last line, or as a line of output)."""
        if self.display is not None:
            self.display.note = text
        else:
            print(f"\n{text}", file=self.out, flush=True)

    @contextmanager
    def installed(self) -> Iterator[None]:
        if threading.current_thread() is not threading.main_thread():
            yield
            return
        previous: dict[int, Callable[[int, FrameType | None], object] | int | None] = {}
        for signum in self._REASONS:
            previous[signum] = signal.signal(signum, self._handle)
        try:
            yield
        finally:
            for number, handler in previous.items():
                signal.signal(number, handler)

    def attach(self, runner: Runner) -> None:
        self.runner = runner
        if self.pending is not None:
            runner.cancel(*self.pending)

    def _handle(self, signum: int, frame: FrameType | None) -> None:
        self.count += 1
        reason, code = self._REASONS[signal.Signals(signum)]
        if signum == signal.SIGINT and self.count >= 3:
            raise KeyboardInterrupt  # the user insists: stop waiting for the motion to stop
        in_time = True
        if self.runner is not None:
            in_time = self.runner.cancel(reason, code)
        elif self.pending is None:
            self.pending = (reason, code)
        if not in_time:  # the tree has ended: nothing left to stop, the run ends as it ended
            self.say(f"{reason} too late: every step has ended")
        elif self.count == 1:
            self.say(f"{reason}: stopping the motion where it is …")
        else:
            self.say("still stopping the motion (Ctrl-C twice more to stop waiting) …")


def _run_with_display(runner: Runner, live: bool, out: TextIO,
                      stop: _StopSignals | None = None) -> RunRecord:
    result: list[RunRecord] = []
    failure: list[BaseException] = []

    def run() -> None:
        try:
            result.append(runner.run())
        except BaseException as exc:  # handed to the main thread, raised there
            failure.append(exc)

    display = LiveTree(out) if live else None
    if stop is not None:
        stop.display = display
    thread = threading.Thread(target=run, name="task-run", daemon=True)
    thread.start()
    try:
        while thread.is_alive():
            thread.join(_FRAME_PERIOD if live else 0.2)
            if display is not None:
                display.update(runner)
        if display is not None:
            display.update(runner)
    except KeyboardInterrupt:
        runner.cancel(*_StopSignals._REASONS[signal.SIGINT])
        raise
    finally:
        if display is not None:
            display.close()
        if stop is not None:
            stop.display = None
    if failure:
        raise failure[0]
    return result[0]


def _summary(record: RunRecord, runner: Runner, runs_dir: Path | None, out: TextIO) -> None:
    steps = [e for e in record.events if e.kind == "node_finished"]
    planned = [e for e in record.events if e.kind == "planned"]
    plan_s = sum(e.data.get("planning_time", 0.0) for e in planned)
    motion_s = sum(e.data.get("duration", 0.0) for e in planned)
    wall = record.events[-1].time if record.events else 0.0
    # Two lines: each fits an 80-column terminal.
    print(f"\n{record.task}: {record.status} (exit {record.exit_code}) in {wall:.2f} s wall\n"
          f"  {len(steps)} steps, {len(planned)} motions planned in {plan_s:.3f} s, "
          f"{motion_s:.1f} s of motion", file=out)
    if record.warm_up_s is not None:
        print(f"  before it: {record.warm_up_s:.1f} s preparing the planner's compiled kernels "
              "(once per machine)", file=out)
    if record.error:
        print(f"  {record.error}", file=out)
    if runner.late_cancel:
        print(f"  {runner.late_cancel}", file=out)
    if runs_dir is not None:
        print(f"  record: {runs_dir / (record.run_id + '.json')}", file=out)
