"""``run-task``: the command line.

Subcommands:

- ``run-task FILE [--backend mock|sim] [--param k=v]... [--speed X] [--seed N]``: check a
  task as ``check`` does (``--no-check`` skips it; nothing moves when it finds a problem),
  then run it; a live tree in a terminal, plain log lines otherwise, a summary at the end.
- ``run-task check FILE``: report every problem of a task at once, with file:line.
- ``run-task export RECORD --mcap FILE``: a run record as an MCAP file of ROS 2 messages
  (Foxglove, ``ros2 bag play`` into RViz); a run takes ``--mcap FILE`` and ``--foxglove
  [PORT]`` (a live feed) too.
- ``run-task test [PATHS…] [--jobs N] [--junit FILE] [--ray [ADDRESS]]``: run task files
  and their scenarios in parallel, each judged by its ``expect:``; exit 0 when all pass.
- ``run-task sweep TASK --param NAME=START:STOP:COUNT [--seeds N] [--backend mock,sim]``:
  success over a parameter space (CSV, PNG, HTML).
- ``run-task demo [CELL]``: load a cell, solve IK for a point in front of the arm, check
  it for collisions, plan a collision-free path there and time it.
- ``run-task info CELL_OR_ROBOT``: robots, groups, named poses and objects of a cell or robot.
- ``run-task plan ROBOT --request R.yaml [--scene S.yaml] [--json]``: plan a MoveIt
  MotionPlanRequest file in a PlanningScene file (MotionBenchMaker's format) and report.
- ``run-task collision-matrix ROBOT``: generate the SRDF self-collision matrix.
- ``run-task firmware-sim [--speedup X]``: build and start the host build of the ESP32
  firmware; prints the pseudo-terminal path, then the HTTP URL.
- ``run-task hw status|home|jog JOINT DEGREES|calibrate [JOINT] (--port P | --url U)``:
  bench helpers for the servo arm on its ESP32 (calibrate writes zero_rad and direction to
  hardware.yaml); with ``--robot so101 --port P [--calibration FILE]``: ``status``,
  ``jog JOINT DEGREES``, ``torque on|off``, ``calibrate`` on the SO-101's Feetech bus
  (LeRobot's calibration file).
- ``run-task bus-sim``: the SO-101's Feetech bus emulated on a pty (prints its path; reads
  ``inject KIND [ID]`` / ``clear`` on standard input).
- ``run-task serve [--host 127.0.0.1] [--port 8000] [--token T | --no-auth]``: the REST API
  (``api/``); with no token given or in ``TASKRUNNER_TOKEN``, one is made and printed.

Exit codes: 0 success, 2 invalid task or input, 3 planning failure, 4 execution failure,
130 cancelled (Ctrl-C), 143 cancelled by SIGTERM.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from taskrunner.commands.examples import cmd_examples
from taskrunner.commands.options import add_robot_options, load_options
from taskrunner.commands.resume import add_resume_parser, cmd_resume
from taskrunner.commands.robots import cmd_collision_matrix, cmd_demo, cmd_info, cmd_plan
from taskrunner.commands.server import cmd_serve, cmd_view
from taskrunner.commands.servos import cmd_bus_sim, cmd_firmware_sim, cmd_hw
from taskrunner.commands.tasks import cmd_check, cmd_run
from taskrunner.errors import (
    BackendError,
    InputError,
    PlanningError,
    TaskrunnerError,
    UnknownNameError,
)
from taskrunner.kinds import BackendKind, CollisionChoice, ExitCode

__all__ = ["main"]

DEFAULT_CELL = "servo_arm_table"  # a shipped cell (taskrunner/data/robots/cells)

EXIT_OK, EXIT_INVALID, EXIT_PLANNING, EXIT_EXECUTION, EXIT_CANCELLED = (
    ExitCode.OK, ExitCode.INVALID, ExitCode.PLANNING, ExitCode.EXECUTION, ExitCode.CANCELLED)
COMMANDS = ("run", "check", "examples", "demo", "info", "collision-matrix", "serve",
            "firmware-sim", "bus-sim", "hw", "view", "test", "sweep", "plan", "warm-up", "export",
            "resume")


def cmd_export(args: argparse.Namespace) -> int:
    from taskrunner.export.command import export_command

    return export_command(args)


def cmd_warm_up(args: argparse.Namespace) -> int:
    from taskrunner.runtime.session import warm_up_command

    return warm_up_command()


def cmd_test(args: argparse.Namespace) -> int:
    from taskrunner.runtime.testing import test_command

    return test_command(args.paths, args.jobs, args.junit, args.ray,
                        load_options=args.load_options.as_data())


def cmd_sweep(args: argparse.Namespace) -> int:
    from taskrunner.runtime.sweep import sweep_command

    return sweep_command(args)


def _add_test_sweep_parsers(sub) -> None:  # type: ignore[no-untyped-def]
    ray_help = ("run on Ray: a cluster address (ray://host:10001), 'auto', or 'local' "
                "(default when given alone: start one here); pip install 'ray[default]>=2.40,<3'")
    test = sub.add_parser("test", help="run task files with their expectations (and "
                                       "scenarios) in parallel; a table and JUnit XML")
    test.add_argument("paths", nargs="*", help="task files or folders (default: the shipped "
                                               "examples)")
    test.add_argument("--jobs", "-j", type=int, default=None,
                      help="worker processes (default: every core)")
    test.add_argument("--junit", metavar="FILE", help="write JUnit XML there")
    test.add_argument("--ray", nargs="?", const="local", default=None, metavar="ADDRESS",
                      help=ray_help)
    sweep = sub.add_parser("sweep", help="run a task over parameter ranges, seeds and "
                                         "backends; success rates, CSV, a plot")
    sweep.add_argument("task", help="task file or a shipped example's name")
    sweep.add_argument("--param", action="append", default=[], metavar="NAME=RANGE",
                       help="NAME=START:STOP:COUNT (inclusive) or NAME=A,B,C (repeatable)")
    sweep.add_argument("--seeds", type=int, default=1, help="seeds 0..N-1 per point (1)")
    sweep.add_argument("--backend", default="mock", help="backends, comma-separated (mock)")
    sweep.add_argument("--speed", type=float, default=None, help="speed of sim or mujoco")
    sweep.add_argument("--jobs", "-j", type=int, default=None,
                       help="worker processes (default: every core)")
    sweep.add_argument("--out", default=None,
                       help="folder for results.csv, success.png, sweep.html "
                            "(default: sweeps/<task>-<time>)")
    sweep.add_argument("--ray", nargs="?", const="local", default=None, metavar="ADDRESS",
                       help=ray_help)
    for loads_robots in (test, sweep):
        add_robot_options(loads_robots)


def _parser() -> argparse.ArgumentParser:
    from taskrunner import __version__

    # Help is plain text (the module's docstring is reStructuredText, for the API docs).
    parser = argparse.ArgumentParser(
        prog="run-task",
        description="Check and run robot-cell task files (run-task FILE is run-task run "
                    "FILE), serve the REST API and the web view. run-task COMMAND --help "
                    "for a command's options.",
        epilog="exit codes: 0 success, 2 invalid task or input, 3 planning failure, "
               "4 execution failure, 130 cancelled (Ctrl-C), 143 cancelled by SIGTERM")
    parser.add_argument("--version", action="version", version=f"run-task {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    run = sub.add_parser("run", help="run a task file (also: run-task FILE)")
    run.add_argument("file", help="task file (YAML), or a shipped example's name (pick_place)")
    run.add_argument("--backend", choices=[kind.value for kind in BackendKind],
                     default="mock", help="where the motion goes (mock); mujoco: physics, "
                     "pip install 'mujoco>=3.2,<4' 'trimesh>=4.0,<6'")
    run.add_argument("--port", help="serial port of the ESP32 (serial backend; default: "
                                    "the robot's hardware.yaml); feetech: of the bus (a "
                                    "pair on two buses: BUS=PORT,BUS=PORT)")
    run.add_argument("--url", help="the ESP32's /api/command URL (http backend)")
    run.add_argument("--calibration", default=None, metavar="FILE",
                     help="feetech: LeRobot's calibration file (default: the hardware file's; "
                          "a pair: ROBOT=FILE,ROBOT=FILE)")
    run.add_argument("--hardware", default=None, metavar="FILE",
                     help="feetech: the buses and IDs of the cell's arms (default: "
                          "<cell>.hardware.yaml next to the cell file)")
    run.add_argument("--home", action="store_true",
                     help="serial/http: home the servos before the task starts")
    run.add_argument("--firmware-speedup", type=float, default=1.0,
                     help="the host firmware's --speedup (firmware-sim), 1 for real hardware")
    run.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                     help="override a task parameter (repeatable)")
    run.add_argument("--speed", type=float, default=None,
                     help="time scale of the motion (sim: 2 = twice real time; mock: replay "
                          "this many times faster instead of jumping to the end)")
    run.add_argument("--seed", type=int, default=0, help="planner seed (0)")
    run.add_argument("--data-dir", default=None,
                     help="the API's data folder, for poses it taught (TASKRUNNER_DATA_DIR, "
                          "else ./state)")
    run.add_argument("--runs-dir", default=None,
                     help="where run records go (TASKRUNNER_RUNS_DIR, else ./runs)")
    run.add_argument("--plain", action="store_true", help="log lines even in a terminal")
    run.add_argument("--in-process", action="store_true",
                     help="plan in this process instead of a worker process")
    from taskrunner.export.command import add_export_parser, add_run_options

    add_run_options(run)
    add_export_parser(sub)
    run.add_argument("--no-check", action="store_true",
                     help="skip the check run before anything moves (run-task check)")
    add_resume_parser(sub)
    check = sub.add_parser("check", help="check a task file; nothing moves")
    check.add_argument("file", help="task file (YAML), or a shipped example's name")
    check.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                       help="override a task parameter (repeatable)")
    check.add_argument("--seed", type=int, default=0, help="IK and planner seed (0)")
    check.add_argument("--json", action="store_true",
                       help="print the report as JSON (as /tasks/check answers, with notes)")
    check.add_argument("--data-dir", default=None,
                       help="the API's data folder, for poses it taught (TASKRUNNER_DATA_DIR, "
                            "else ./state)")
    examples = sub.add_parser("examples", help="list the shipped example tasks "
                                               "(run one with: run-task NAME)")
    examples.add_argument("--paths", action="store_true", help="also print each file's path")
    sim = sub.add_parser("firmware-sim", help="start the host build of the ESP32 firmware")
    sim.add_argument("--speedup", type=float, default=1.0, help="run its clock X times faster")
    sim.add_argument("--log", help="CSV of every tick's servo angles")
    sim.add_argument("--channels",
                     help="the board's servo channels in MOVE/TRAJ order (default: one arm, "
                          "0,3,6,9,12,15; servo_arm_pair's board: 0,1,2,3,4,5,8,9,10,11,12,13)")
    hw = sub.add_parser("hw", help="bench helpers for the servo arm's ESP32")
    hw.add_argument("action", choices=("status", "home", "jog", "calibrate", "torque"),
                    help="status: firmware and joint angles; home; jog JOINT DEGREES; "
                         "calibrate [JOINT]: write zero_rad and direction to hardware.yaml")
    hw.add_argument("joint", nargs="?", help="joint to jog, e.g. 'Revolute 1'; on|off for "
                                             "torque (--robot)")
    hw.add_argument("degrees", nargs="?", type=float, help="how far to jog (degrees)")
    hw.add_argument("--port", help="serial port (default: the robot's hardware.yaml)")
    hw.add_argument("--url", help="the ESP32's /api/command URL instead of serial")
    hw.add_argument("--cell", default=str(DEFAULT_CELL),
                    help=f"cell of the servo arm: a path or a shipped cell's name ({DEFAULT_CELL})")
    hw.add_argument("--firmware-speedup", type=float, default=1.0, help=argparse.SUPPRESS)
    hw.add_argument("--robot", choices=("so101",), default=None,
                    help="an arm on a Feetech servo bus instead of the ESP32 servo arm: "
                         "status, jog, torque on|off, calibrate (LeRobot's file)")
    hw.add_argument("--calibration", default=None,
                    help="with --robot: LeRobot's calibration file (calibrate writes it)")
    bus_sim = sub.add_parser("bus-sim", help="emulate the SO-101's Feetech servo bus on a pty")
    bus_sim.add_argument("--seed", type=int, default=0, help="varies the servos' start (0)")
    bus_sim.add_argument("--calibration", default=None, metavar="FILE[,FILE]",
                         help="servos calibrated as these LeRobot files say (their IDs), "
                              "at rest; two files: two arms on one bus")
    bus_sim.add_argument("--speedup", type=float, default=1.0,
                         help="the servos move this many times faster than real time (tests; "
                              "run-task FILE --backend feetech --firmware-speedup the same)")
    bus_sim.add_argument("--log", default=None, metavar="FILE",
                         help="append a line per SYNC WRITE received (model time, monotonic "
                              "time, address, IDs): the rate a backend streams at")
    demo = sub.add_parser("demo", help="load a cell, solve IK, check collisions, plan")
    demo.add_argument("cell", nargs="?", default=str(DEFAULT_CELL),
                      help=f"cell or robot: a path or a shipped cell's name ({DEFAULT_CELL})")
    demo.add_argument("--target", nargs=3, type=float, default=(0.2, 0.05, 0.08),
                      metavar=("X", "Y", "Z"),
                      help="IK target in the first robot's base frame, m (0.2 0.05 0.08)")
    demo.add_argument("--seed", type=int, default=0, help="IK and planner seed (0)")
    info = sub.add_parser("info", help="describe a cell or robot")
    info.add_argument("path", help="cell file, robot folder or file, MoveIt config package, "
                                   "or a shipped cell's or robot's name")
    plan = sub.add_parser("plan", help="plan a MoveIt MotionPlanRequest file in a "
                                       "PlanningScene file, and report")
    plan.add_argument("robot", help="robot or cell: a path or a shipped name (panda)")
    plan.add_argument("--request", required=True, metavar="R.yaml",
                      help="moveit_msgs/MotionPlanRequest YAML")
    plan.add_argument("--scene", metavar="S.yaml", help="moveit_msgs/PlanningScene YAML")
    plan.add_argument("--robot", dest="instance", default=None, metavar="NAME",
                      help="the cell's robot the files are for (its prefix goes before names)")
    plan.add_argument("--group", default=None, help="plan for this group instead of group_name")
    plan.add_argument("--merge", action="store_true",
                      help="keep the cell's objects even when the scene is a full one")
    plan.add_argument("--seed", type=int, default=0, help="planner and IK seed (0)")
    plan.add_argument("--json", action="store_true", help="print the report as JSON")
    for loads_robots in (run, check, demo, hw, info, plan):
        add_robot_options(loads_robots)
    serve = sub.add_parser("serve", help="serve the REST API with uvicorn")
    serve.add_argument("--host", default="127.0.0.1", help="address to bind (127.0.0.1)")
    serve.add_argument("--port", type=int, default=8000, help="port (8000)")
    serve.add_argument("--control-port", type=int, default=None,
                       help="also serve cancel and run state (only) on this port, on a "
                            "listener of its own that no load on --port can delay")
    serve.add_argument("--token", default=None,
                       help="bearer token (default: TASKRUNNER_TOKEN, else a new one, printed)")
    serve.add_argument("--no-auth", action="store_true",
                       help="run open: no endpoint needs a token")
    serve.add_argument("--data-dir", "--state-dir", dest="data_dir", default=None,
                       help="where the server keeps its data, the run database "
                            "(TASKRUNNER_DATA_DIR, else state/)")
    serve.add_argument("--collision", choices=tuple(CollisionChoice), default=None,
                       help="link geometry of every robot the server loads (default: each "
                            "robot's own choice: its cell's or robot.yaml's collision:, else auto)")
    serve.add_argument("--package-path", action="append", default=[], metavar="DIR",
                       help="also look for ROS packages (and load robots) under DIR "
                            "(repeatable; default: TASKRUNNER_PACKAGE_PATH)")
    serve.add_argument("--planner", choices=("worker", "inprocess"), default=None,
                       help="plan in a worker process per run (default) or in-process")
    serve.add_argument("--foxglove", nargs="?", type=int, const=8765, default=None,
                       metavar="PORT", help="stream the runs live to Foxglove, one feed per "
                                            "cell on ws://127.0.0.1:PORT (8765), PORT+1, …")
    serve.add_argument("--log-level", default="info", help="uvicorn's log level (info)",
                       choices=("critical", "error", "warning", "info", "debug"))
    view = sub.add_parser("view", help="serve the web view on 127.0.0.1: replay a run "
                                       "record, check and preview a task, or see the cells")
    view.add_argument("target", nargs="?", default=None,
                      help="a run record (runs/<id>.json), a task file or shipped task name "
                           "(none: the runs of ./runs, TASKRUNNER_RUNS_DIR)")
    view.add_argument("--port", type=int, default=0, help="port (default: a free one)")
    view.add_argument("--token", default=None,
                      help="bearer token (default: TASKRUNNER_TOKEN, else a new one, printed)")
    view.add_argument("--package-path", action="append", default=[], metavar="DIR",
                      help="also look for ROS packages (and load robots) under DIR "
                           "(repeatable; default: as the record's run did, else "
                           "TASKRUNNER_PACKAGE_PATH)")
    view.add_argument("--collision", choices=tuple(CollisionChoice), default=None,
                      help="link geometry of every robot (default: as the record's run "
                           "did, else each robot's own choice)")
    view.add_argument("--log-level", default="warning", help="uvicorn's log level (warning)",
                      choices=("critical", "error", "warning", "info", "debug"))
    sub.add_parser("warm-up", help="compile the planner's kernels into the user cache "
                                   "(once per machine; a first run does it by itself)")
    sub.add_parser("collision-matrix", add_help=False,
                   help="generate a robot's self-collision matrix (see --help)")
    _add_test_sweep_parsers(sub)
    return parser


def _json_error(args: argparse.Namespace | None, exc: BaseException, code: int,
                kind: str | None = None) -> int:
    """With ``--json`` (``args`` None: it was given): the error as the command's JSON
    report on stdout (``success`` false, ``error_kind``, ``message``, ``file``, ``line``,
    ``exit_code``); returns ``code``."""
    if args is None or getattr(args, "json", False):
        import json

        path = getattr(exc, "path", None)
        print(json.dumps({"success": False, "error_kind": kind or type(exc).__name__,
                          "message": getattr(exc, "reason", None) or str(exc),
                          "file": str(path) if path is not None else None,
                          "line": getattr(exc, "line", None), "exit_code": code,
                          "warnings": []}, indent=2))
    return code


def _parse(parser: argparse.ArgumentParser, argv: list[str]) -> argparse.Namespace | int:
    """``parser.parse_args(argv)``; with ``--json``, a usage error is also a JSON report
    (``error_kind`` ``UsageError``, argparse's exit code 2)."""
    if "--json" not in argv:
        return parser.parse_args(argv)
    import contextlib
    import io

    usage = io.StringIO()
    try:
        with contextlib.redirect_stderr(usage):
            parsed = parser.parse_args(argv)
    except SystemExit as exc:
        sys.stderr.write(usage.getvalue())
        if not exc.code:
            raise
        lines = usage.getvalue().strip().splitlines()
        return _json_error(None, InputError(lines[-1] if lines else "invalid arguments"),
                           int(exc.code), kind="UsageError")
    sys.stderr.write(usage.getvalue())
    return parsed


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = _parser()
    if argv and argv[0] == "collision-matrix":
        return cmd_collision_matrix(argparse.Namespace(), argv[1:])
    if argv and argv[0] not in COMMANDS and not argv[0].startswith("-"):
        argv = ["run", *argv]
    args = _parse(parser, argv)
    if isinstance(args, int):
        return args
    commands = {"run": cmd_run, "check": cmd_check, "examples": cmd_examples, "view": cmd_view,
                "demo": cmd_demo, "info": cmd_info, "plan": cmd_plan,
                "firmware-sim": cmd_firmware_sim, "bus-sim": cmd_bus_sim, "hw": cmd_hw,
                "serve": cmd_serve, "test": cmd_test, "sweep": cmd_sweep,
                "warm-up": cmd_warm_up, "export": cmd_export, "resume": cmd_resume}
    try:
        if hasattr(args, "allow_missing_meshes"):  # a command that loads robots
            args.load_options = load_options(args)
        return commands[args.command](args)
    except (InputError, UnknownNameError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return _json_error(args, exc, EXIT_INVALID)
    except PlanningError as exc:
        print(f"planning failed: {exc}", file=sys.stderr)
        return _json_error(args, exc, EXIT_PLANNING)
    except BackendError as exc:
        print(f"backend failed: {exc}", file=sys.stderr)
        return _json_error(args, exc, EXIT_EXECUTION)
    except TaskrunnerError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return _json_error(args, exc, EXIT_INVALID)
    except Exception as exc:  # a bug: the traceback goes to stderr, JSON still to stdout
        _json_error(args, exc, 1)
        raise
    except KeyboardInterrupt:  # a run turns Ctrl-C into a cancel; this is anything else
        print("interrupted", file=sys.stderr)
        return EXIT_CANCELLED


if __name__ == "__main__":
    sys.exit(main())
