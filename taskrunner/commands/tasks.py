"""``run-task FILE`` (``run``) and ``run-task check FILE``: a task checked, then run on a
backend; or only checked, every problem at once with its file:line."""

from __future__ import annotations

import argparse
import gc
import math
import os
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from taskrunner.errors import InputError
from taskrunner.kinds import ExitCode

if TYPE_CHECKING:
    from taskrunner.runtime.prestart import EarlyWorker
    from taskrunner.taught import TaughtPoses
    from taskrunner.tree.check import CheckReport

__all__ = ["cmd_check", "cmd_run"]


def _parameters(pairs: Sequence[str]) -> dict[str, str]:
    out: dict[str, str] = {}
    for pair in pairs:
        key, sep, value = pair.partition("=")
        if not sep or not key:
            raise InputError(f"'--param' must be KEY=VALUE (got {pair!r})")
        out[key] = value
    return out


def _taught_poses(args: argparse.Namespace) -> TaughtPoses:
    """The poses the API taught (its data folder's database), so that the command line
    knows the same named poses as ``run-task serve``: ``--data-dir``, else
    ``TASKRUNNER_DATA_DIR`` (or ``TASKRUNNER_STATE_DIR``), else ``./state``; cells by id
    from ``TASKRUNNER_CELLS_DIR``, else the shipped cells. No database: none."""
    from taskrunner.taught import cells_dir_from_env, data_dir_from_env, read_taught_poses

    return read_taught_poses(data_dir_from_env(args.data_dir) / "runs.sqlite",
                             cells_dir_from_env())


def cmd_check(args: argparse.Namespace) -> int:
    from taskrunner.resources import resolve_task
    from taskrunner.tree.check import check_task

    report = check_task(resolve_task(args.file), _parameters(args.param), seed=args.seed,
                        taught=_taught_poses(args), options=args.load_options)
    if getattr(args, "json", False):
        import json

        def problem(p: object) -> dict[str, object]:
            path, line = getattr(p, "path", None), getattr(p, "line", None)
            return {"file": str(path) if path is not None else None, "line": line,
                    "message": getattr(p, "message", str(p)), "text": str(p)}

        print(json.dumps({"ok": report.ok, "cell": report.cell, "steps": report.steps,
                          "problems": [problem(p) for p in report.problems],
                          "notes": [problem(n) for n in report.notes],
                          "schedules": [s.to_dict() for s in report.schedules]}, indent=2))
        return ExitCode.OK if report.ok else ExitCode.INVALID
    for note in report.notes:
        print(f"note: {note}")
    if report.problems:
        _print_problems(args.file, report.problems)
        return ExitCode.INVALID
    print(f"{args.file}: ok ({report.steps} steps checked against cell {report.cell!r})")
    return ExitCode.OK


def _print_problems(file: str, problems: Sequence[object], tail: str = "") -> None:
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{file}: {len(problems)} problem(s){tail}", file=sys.stderr)


def cmd_run(args: argparse.Namespace) -> int:
    from taskrunner.resources import resolve_task

    if args.speed is not None and not (args.speed > 0 and math.isfinite(args.speed)):
        raise InputError(f"'--speed' must be a positive number (got {args.speed})")
    path = resolve_task(args.file)
    parameters = _parameters(args.param)
    # No garbage collection from here until the run starts (_collecting_again): the
    # imports and the check make long-lived modules, classes and models, which its passes
    # walked again and again (~0.01-0.02 s of CPU before the first motion).
    collecting = gc.isenabled()
    frozen = gc.get_freeze_count()
    gc.disable()
    early = None
    try:
        # The planning worker loads the cell while this process imports and checks.
        if not args.in_process:
            from taskrunner.runtime.prestart import start_worker_early

            early = start_worker_early(path, options=args.load_options)
        return _check_and_run(args, path, parameters, early, collecting)
    finally:
        if collecting:
            gc.enable()
        if frozen == 0:
            # What the start froze goes back to the collector (a caller in the same
            # process keeps its heap collectable; nothing is left for the interpreter's
            # exit to skip). A caller's own earlier freeze is left as it was.
            gc.unfreeze()
        if early is not None:
            early.close()  # a no-op once the run adopted it


def _collecting_again(collecting: bool) -> None:
    """The start is over (the task checked, the run about to start): what it left is
    frozen (later collections skip it; the little cyclic garbage the check made, ~0.4 MB,
    stays with it) and garbage is collected again (if it was before ``run-task``)."""
    if collecting:
        gc.freeze()
        gc.enable()


def _check_and_run(args: argparse.Namespace, path: Path, parameters: dict[str, str],
                   early: EarlyWorker | None = None, collecting: bool = False) -> int:
    from taskrunner.errors import TaskSpecError
    from taskrunner.runtime.preflight import check_before_run
    from taskrunner.runtime.session import run_task_file

    report: CheckReport | None = None
    taught = _taught_poses(args)
    if not args.no_check:
        started = time.perf_counter()
        try:
            report = check_before_run(path, parameters, seed=args.seed, taught=taught,
                                      options=args.load_options)
        except TaskSpecError as exc:
            problems = getattr(exc, "problems", None) or [exc]
            _print_problems(args.file, problems, "; nothing moved (--no-check runs anyway)")
            return ExitCode.INVALID
        print(f"{args.file}: checked {report.steps} steps in "
              f"{time.perf_counter() - started:.2f} s", flush=True)
    runs_dir = Path(args.runs_dir or os.environ.get("TASKRUNNER_RUNS_DIR") or "runs")
    _collecting_again(collecting)
    return run_task_file(path, backend=args.backend, parameters=parameters,
                         speed=args.speed, seed=args.seed, runs_dir=runs_dir,
                         live=sys.stdout.isatty() and not args.plain, worker=not args.in_process,
                         port=args.port, url=args.url, calibration=args.calibration,
                         hardware=args.hardware, firmware_speedup=args.firmware_speedup,
                         home=args.home, check=False, early=early,
                         loaded=report, watch=_watches(args), taught=taught,
                         options=args.load_options)


def _watches(args: argparse.Namespace) -> list:  # type: ignore[type-arg]
    """``--mcap`` and ``--foxglove`` (taskrunner.export, imported only when asked for)."""
    if args.mcap is None and args.foxglove is None:
        return []
    from taskrunner.export.command import run_watches

    return run_watches(args)
