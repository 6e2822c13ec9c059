"""``run-task resume RECORD``: continue a run that stopped, from where it stopped.

See :mod:`taskrunner.runtime.resume` for what is resumed and what is refused.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

from taskrunner.errors import InputError

if TYPE_CHECKING:
    from taskrunner.robot.options import LoadOptions
    from taskrunner.types import Pose  # pinocchio: imported when a pose is parsed

__all__ = ["add_resume_parser", "cmd_resume", "parse_object_pose"]


def add_resume_parser(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    resume = sub.add_parser(
        "resume", help="continue a run that stopped (a fault, a stop, a killed process) "
        "from its record")
    resume.add_argument("record", help="the run's record (<runs>/<run_id>.json, or its "
                                       ".events.jsonl journal)")
    resume.add_argument("--object", action="append", default=[], metavar="NAME=POSE",
                        help="the object lies there now (world frame, m): X,Y,Z or "
                             "X,Y,Z,QX,QY,QZ,QW (repeatable)")
    resume.add_argument("--released", action="append", default=[], metavar="NAME",
                        help="the object held when the run stopped is no longer held "
                             "(repeatable)")
    resume.add_argument("--held", action="append", default=[], metavar="NAME",
                        help="the object held when the run stopped still is (repeatable)")
    resume.add_argument("--from", dest="from_step", default=None, metavar="STEP",
                        help="resume at this step (its name, or file:line) instead")
    resume.add_argument("--port", help="serial port of the ESP32 (serial backend)")
    resume.add_argument("--url", help="the ESP32's /api/command URL (http backend)")
    resume.add_argument("--firmware-speedup", type=float, default=1.0,
                        help="the host firmware's --speedup (firmware-sim)")
    resume.add_argument("--speed", type=float, default=None,
                        help="time scale of the motion, as for run-task run")
    resume.add_argument("--seed", type=int, default=0, help="planner seed (0)")
    resume.add_argument("--runs-dir", default=None,
                        help="where the new run's record goes (default: beside the record)")
    resume.add_argument("--plain", action="store_true", help="log lines even in a terminal")
    resume.add_argument("--in-process", action="store_true",
                        help="plan in this process instead of a worker process")
    # How the robots are loaded: as the run recorded it, unless one of these is given.
    from taskrunner.commands.options import add_robot_options

    add_robot_options(resume, " (default: as the run loaded them, from its record)")


def parse_object_pose(text: str) -> tuple[str, Pose]:
    """``NAME=X,Y,Z`` or ``NAME=X,Y,Z,QX,QY,QZ,QW`` (m, world frame).

    Raises:
        InputError: not of that form.
    """
    name, sep, values = text.partition("=")
    try:
        numbers = [float(v) for v in values.split(",")] if sep else []
    except ValueError:
        numbers = []
    if not name or len(numbers) not in (3, 7) or not all(math.isfinite(v) for v in numbers):
        raise InputError(f"'--object' must be NAME=X,Y,Z or NAME=X,Y,Z,QX,QY,QZ,QW "
                         f"(got {text!r})")
    quat = tuple(numbers[3:]) if len(numbers) == 7 else (0.0, 0.0, 0.0, 1.0)
    from taskrunner.types import Pose

    return name, Pose(tuple(numbers[:3]), quat)  # type: ignore[arg-type]


def cmd_resume(args: argparse.Namespace) -> int:
    """Load the record, plan the resume (refused with the reason), run from there."""
    import sys

    from taskrunner.runtime.records import load_record
    from taskrunner.runtime.resume import ResumeOptions, plan_resume
    from taskrunner.runtime.session import run_task_file
    from taskrunner.tasks.loader import load_task

    if args.speed is not None and not (args.speed > 0 and math.isfinite(args.speed)):
        raise InputError(f"'--speed' must be a positive number (got {args.speed})")
    path = Path(args.record)
    try:
        record = load_record(path)
    except FileNotFoundError:
        raise InputError("no run record (nor its journal) there", path) from None
    if not record.task_file:
        raise InputError(f"run {record.run_id} was not run from a task file: resume it "
                         "from Python (TaskRun.resume)", path)
    options = ResumeOptions(objects=dict(parse_object_pose(o) for o in args.object),
                            released=tuple(args.released), held=tuple(args.held),
                            from_step=args.from_step)
    spec = load_task(record.task_file, record.parameters)
    plan = plan_resume(record, spec, options)
    load = _load_options(args, record, path)
    runs_dir = Path(args.runs_dir) if args.runs_dir else path.parent
    live = not args.plain and sys.stdout.isatty()
    return run_task_file(Path(record.task_file), backend=record.backend,
                         parameters=record.parameters, speed=args.speed, seed=args.seed,
                         runs_dir=runs_dir, live=live, worker=not args.in_process,
                         port=args.port, url=args.url,
                         firmware_speedup=args.firmware_speedup, check=False, resume=plan,
                         options=load)


def _load_options(args: argparse.Namespace, record: Any, path: Path) -> LoadOptions:
    """How to load the cell's robots: as the command line says when it says anything
    (flags or TASKRUNNER_* variables), else as the record says the run loaded them (the
    geometry the run was checked against, its packages)."""
    from taskrunner.robot.options import LoadOptions

    given = getattr(args, "load_options", None) or LoadOptions()
    if given != LoadOptions():
        return given
    try:
        return record.loaded_with() or given
    except InputError as exc:
        raise InputError(str(exc), path) from None
