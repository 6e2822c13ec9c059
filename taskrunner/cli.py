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
  hardware.yaml).
- ``run-task serve [--host 127.0.0.1] [--port 8000] [--token T | --no-auth]``: the REST API
  (``api/``); with no token given or in ``TASKRUNNER_TOKEN``, one is made and printed.

Exit codes: 0 success, 2 invalid task or input, 3 planning failure, 4 execution failure,
130 cancelled (Ctrl-C), 143 cancelled by SIGTERM.
"""

from __future__ import annotations

import argparse
import gc
import logging
import math
import os
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, cast

from taskrunner.errors import (
    BackendError,
    InputError,
    PlanningError,
    TaskrunnerError,
    UnknownNameError,
)

if TYPE_CHECKING:
    import numpy as np

    from taskrunner.kinematics import IkSolver
    from taskrunner.runtime.prestart import EarlyWorker
    from taskrunner.runtime.records import RunRecord
    from taskrunner.scene import Scene
    from taskrunner.tree.check import CheckReport

__all__ = ["main"]

DEFAULT_CELL = "servo_arm_table"  # a shipped cell (taskrunner/data/robots/cells)

EXIT_OK, EXIT_INVALID, EXIT_PLANNING, EXIT_EXECUTION, EXIT_CANCELLED = 0, 2, 3, 4, 130
COMMANDS = ("run", "check", "examples", "demo", "info", "collision-matrix", "serve",
            "firmware-sim", "hw", "view", "test", "sweep", "plan", "warm-up", "export")


def _load(name_or_path: str):  # type: ignore[no-untyped-def]
    from taskrunner.resources import resolve_cell
    from taskrunner.robot.cell import load_cell_or_robot

    return load_cell_or_robot(resolve_cell(name_or_path))


def _fmt(values: np.ndarray) -> str:
    return "[" + ", ".join(f"{v:+.3f}" for v in values) + "]"


def _add_robot_options(parser: argparse.ArgumentParser) -> None:
    """``--package-path`` and ``--strict``, for every command that loads robots."""
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        help="also look for ROS packages under DIR (repeatable; before "
                             "TASKRUNNER_PACKAGE_PATH, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH)")
    parser.add_argument("--strict", action="store_true",
                        help="robot file warnings (what MoveIt would skip) are errors")
    parser.add_argument("--allow-missing-meshes", action="store_true",
                        help="load robots whose mesh files cannot be found (or that have "
                             "no collision geometry) without that geometry, with a warning")
    parser.add_argument("--collision", choices=("exact", "convex", "auto"), default=None,
                        help="link geometry of every robot: exact meshes, convex hulls, or "
                             "auto (hulls where tight; default: each robot's own choice)")


# The variables of taskrunner.robot.notes.STRICT_ENV, taskrunner.robot.packages.PACKAGE_PATH_ENV
# and taskrunner.scene.linkgeometry.COLLISION_ENV, named here: importing taskrunner.robot
# takes 0.3 s, and run-task starts its planning worker (which inherits them) before that.
STRICT_ENV, PACKAGE_PATH_ENV, COLLISION_ENV = (
    "TASKRUNNER_STRICT", "TASKRUNNER_PACKAGE_PATH", "TASKRUNNER_COLLISION")
# taskrunner.robot.missing_meshes.ALLOW_MISSING_MESHES_ENV
ALLOW_MISSING_MESHES_ENV = "TASKRUNNER_ALLOW_MISSING_MESHES"


def _apply_robot_options(args: argparse.Namespace) -> None:
    """Hand ``--package-path`` and ``--strict`` to every robot loader, in this process and
    in the worker processes it starts, through the environment."""
    folders = [Path(p).expanduser().resolve() for p in getattr(args, "package_path", [])]
    missing = [str(f) for f in folders if not f.is_dir()]
    if missing:
        raise InputError(f"'--package-path' must be a folder (got {', '.join(missing)})")
    if folders:
        before = os.environ.get(PACKAGE_PATH_ENV)
        os.environ[PACKAGE_PATH_ENV] = os.pathsep.join(
            [*map(str, folders), *([before] if before else [])])
    if getattr(args, "strict", False):
        os.environ[STRICT_ENV] = "1"
    if getattr(args, "allow_missing_meshes", False):
        os.environ[ALLOW_MISSING_MESHES_ENV] = "1"
    if getattr(args, "collision", None):
        os.environ[COLLISION_ENV] = args.collision


def cmd_info(args: argparse.Namespace) -> int:
    # The loader logs each warning; info lists them in its report instead, so that each
    # is shown once.
    robot_log = logging.getLogger("taskrunner.robot")
    quiet, propagate = logging.NullHandler(), robot_log.propagate
    robot_log.addHandler(quiet)
    robot_log.propagate = False
    try:
        cell = _load(args.path)
    finally:
        robot_log.removeHandler(quiet)
        robot_log.propagate = propagate
    model = cell.model
    out = [f"cell {cell.name}: {len(model.instances)} robot(s), {model.nq} joints"]
    for inst in model.instances:
        xyz = _fmt(inst.base.translation)
        out.append(f"  robot {inst.name!r} prefix {inst.prefix!r} at {xyz}  ({inst.source})")
        out += [f"    {line}" for line in inst.describe_files()]
    out.append("groups:")
    for group in model.groups.values():
        aliases = model.pose_aliases.get(group.name, {})
        poses = ", ".join(f"{n} (= {aliases[n]})" if n in aliases else n
                          for n in model.named_state_names(group.name)) or "-"
        ik = " position-only IK" if group.position_only_ik else ""
        planner = f", planner {group.default_planner}" if group.default_planner else ""
        out.append(f"  {group.name}: {len(group.joint_names)} joints, tip {group.tip_link}"
                   f"{ik}{planner}; poses: {poses}")
    if model.end_effectors:
        out.append("end effectors:")
        for eef in model.end_effectors.values():
            out.append(f"  {eef.name}: group {eef.group} on {eef.parent_link}"
                       f" (arm {eef.parent_group or '-'})")
    if cell.tools:
        out.append("tools (TCP: the tool frame's origin; y closes, z approaches):")
        out += [f"  {tool.describe()}" for tool in cell.tools.values()]
    bare = model.links_without_collision_geometry()
    if bare:
        out.append(f"links without collision geometry: {', '.join(bare)}")
    from taskrunner.scene.linkgeometry import describe_link_geometry

    out += describe_link_geometry(model)
    if cell.objects:
        out.append("objects:")
        for obj in cell.objects:
            out.append(f"  {obj.name}: {obj.shape} at {_fmt(obj.pose.translation)} in {obj.frame}")
    for warning in model.warnings:
        out.append(f"warning: {warning}")
    print("\n".join(out))
    return EXIT_OK


def cmd_plan(args: argparse.Namespace) -> int:
    import json

    from taskrunner.moveit import plan_files

    report, warnings = plan_files(_load(args.robot), args.request, args.scene,
                                  robot=args.instance, group=args.group, seed=args.seed,
                                  merge=True if args.merge else None)
    if args.json:
        print(json.dumps({**report.to_json(), "warnings": [str(w) for w in warnings]}, indent=2))
    else:
        for warning in warnings:
            print(f"warning: {warning}", file=sys.stderr)
        if report.success:
            print(f"plan {report.group} ({report.planner}): success\n"
                  f"  planning time {report.planning_time:.3f} s (total {report.total_time:.3f} s)"
                  f", {report.waypoints} waypoints, length {report.path_length:.3f} rad, "
                  f"duration {report.duration:.3f} s")
        else:
            print(f"plan {report.group} ({report.planner}): failed ({report.error_kind}): "
                  f"{report.message}")
    return EXIT_OK if report.success else EXIT_PLANNING


def _demo_below_surface(scene: Scene, solver: IkSolver, target: np.ndarray,
                        seed_q: np.ndarray) -> None:
    """The demo's collision example: IK to 2 cm below the surface under ``target`` (found
    by lowering a probe onto it), and what that pose hits."""
    from taskrunner.errors import IkFailedError
    from taskrunner.kinematics import IkOptions
    from taskrunner.shapes import Sphere
    from taskrunner.types import Pose

    probe = "__demo_probe__"
    scene.add_object(probe, Sphere(0.001), Pose(xyz=(float(target[0]), float(target[1]), float(target[2]))))
    try:
        support = scene.support(probe)
    finally:
        scene.remove_object(probe)
    if support.below is None:
        print("nothing below the target within 1 m: no surface to reach into")
        return
    surface = float(target[2]) - support.gap - 0.001
    import numpy as np

    below = np.array([target[0], target[1], surface - 0.02])
    try:
        sunk = solver.solve(below, seed_q=seed_q, options=IkOptions(position_only=True))
    except IkFailedError:
        print(f"2 cm below the top of {support.below!r}: out of reach")
        return
    hits = scene.collisions(sunk.q)
    pairs = ", ".join(f"{c.a}–{c.b} ({1e3 * c.depth:.1f} mm deep)" for c in hits[:3])
    print(f"IK 2 cm below the top of {support.below!r}: reachable, "
          + (f"but in collision: {pairs}" if hits else "and (unexpectedly) collision-free"))


def cmd_demo(args: argparse.Namespace) -> int:
    from taskrunner.kinematics import IkOptions, IkSolver, frame_pose
    from taskrunner.planning import JointGoal, MotionPlanner, PlannerOptions, PlanRequest
    from taskrunner.scene import scene_from_cell

    t0 = time.perf_counter()
    cell = _load(args.cell)
    model = cell.model
    scene = scene_from_cell(cell)
    print(f"loaded cell {cell.name!r} ({model.nq} joints, {len(cell.objects)} objects) "
          f"in {1e3 * (time.perf_counter() - t0):.0f} ms")
    arm = next((g for g in model.groups.values() if g.tip_link and g.end_effector), None)
    if arm is None:
        raise InputError(f"cell {cell.name!r} has no arm group with an end effector")
    tip = arm.tip_link
    assert tip is not None
    start = scene.state
    here = frame_pose(model, start, tip)
    print(f"group {arm.name!r} at start {_fmt(start[arm.joint_indices])}: "
          f"{tip} at {_fmt(here.translation)} m")
    clearance = scene.min_distance()
    pair = cast(tuple[str, str], clearance.pair)  # an arm's links give body pairs to check
    print(f"start state collision-free; closest pair {pair[0]}–{pair[1]} "
          f"at {1e3 * clearance.distance:.1f} mm")

    # A point in front of the arm's base, a hand's height above the table.
    base = model.instances[0].base
    import numpy as np

    target = base.act(np.array(args.target, dtype=float))
    # Aim the grasp point between the fingers: the arm's tool frame.
    frame = cell.tools[arm.name].frame if arm.name in cell.tools else tip
    solver = IkSolver(model, arm.name, frame=frame)
    t0 = time.perf_counter()
    solutions = solver.solve_all(target, seed_q=start, options=IkOptions(
        position_only=True, seed=args.seed, num_solutions=8, timeout=0.05))
    ik_ms = 1e3 * (time.perf_counter() - t0)
    free = [s for s in solutions if not scene.in_collision(s.q)]
    print(f"IK (position only) of {frame} to {_fmt(target)} m: {len(solutions)} distinct "
          f"solutions in {ik_ms:.2f} ms, {len(free)} collision-free")
    if not free:
        pairs = ", ".join(f"{c.a}–{c.b}" for c in scene.collisions(solutions[0].q))
        raise PlanningError(f"every IK solution collides (first: {pairs})")
    solution = free[0]
    print(f"  chose {_fmt(solution.joint_state.positions)} rad, error "
          f"{1e3 * solution.position_error:.4f} mm")

    _demo_below_surface(scene, solver, target, solution.q)

    planner = MotionPlanner(scene)
    request = PlanRequest(arm.name, JointGoal(solution.joint_state.as_dict()),
                          options=PlannerOptions(seed=args.seed))
    result = planner.plan(request)
    print(f"planned {arm.name!r} start → IK solution: {len(result.path)} waypoints, "
          f"{1e3 * result.planning_time:.1f} ms search + {1e3 * result.simplify_time:.1f} ms "
          f"shortcut, {result.checks} collision checks, re-checked every "
          f"{request.options.validation_resolution} rad")
    return EXIT_OK


def _parameters(pairs: Sequence[str]) -> dict[str, str]:
    out: dict[str, str] = {}
    for pair in pairs:
        key, sep, value = pair.partition("=")
        if not sep or not key:
            raise InputError(f"'--param' must be KEY=VALUE (got {pair!r})")
        out[key] = value
    return out


def _taught_poses(args: argparse.Namespace):  # type: ignore[no-untyped-def]
    """The poses the API taught (its data folder's database), so that the command line
    knows the same named poses as ``run-task serve``: ``--data-dir``, else
    ``TASKRUNNER_DATA_DIR`` (or ``TASKRUNNER_STATE_DIR``), else ``./state``; cells by id
    from ``TASKRUNNER_CELLS_DIR``, else the shipped cells. No database: none."""
    from taskrunner import resources
    from taskrunner.taught import read_taught_poses

    data = Path(args.data_dir or os.environ.get("TASKRUNNER_DATA_DIR")
                or os.environ.get("TASKRUNNER_STATE_DIR") or "state")
    cells = Path(os.environ.get("TASKRUNNER_CELLS_DIR") or resources.cells_dir())
    return read_taught_poses(data / "runs.sqlite", cells)


def cmd_check(args: argparse.Namespace) -> int:
    from taskrunner.resources import resolve_task
    from taskrunner.tree.check import check_task

    with _taught_poses(args).active():
        report = check_task(resolve_task(args.file), _parameters(args.param), seed=args.seed)
    for note in report.notes:
        print(f"note: {note}")
    if report.problems:
        _print_problems(args.file, report.problems)
        return EXIT_INVALID
    print(f"{args.file}: ok ({report.steps} steps checked against cell {report.cell!r})")
    return EXIT_OK


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

            early = start_worker_early(path)
        with _taught_poses(args).active():
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
    if not args.no_check:
        started = time.perf_counter()
        try:
            report = check_before_run(path, parameters, seed=args.seed)
        except TaskSpecError as exc:
            problems = getattr(exc, "problems", None) or [exc]
            _print_problems(args.file, problems, "; nothing moved (--no-check runs anyway)")
            return EXIT_INVALID
        print(f"{args.file}: checked {report.steps} steps in "
              f"{time.perf_counter() - started:.2f} s", flush=True)
    runs_dir = Path(args.runs_dir or os.environ.get("TASKRUNNER_RUNS_DIR") or "runs")
    _collecting_again(collecting)
    return run_task_file(path, backend=args.backend, parameters=parameters,
                         speed=args.speed, seed=args.seed, runs_dir=runs_dir,
                         live=sys.stdout.isatty() and not args.plain, worker=not args.in_process,
                         port=args.port, url=args.url, firmware_speedup=args.firmware_speedup,
                         home=args.home, check=False, early=early,
                         loaded=report, watch=_watches(args))


def _watches(args: argparse.Namespace) -> list:  # type: ignore[type-arg]
    """``--mcap`` and ``--foxglove`` (taskrunner.export, imported only when asked for)."""
    if args.mcap is None and args.foxglove is None:
        return []
    from taskrunner.export.command import run_watches

    return run_watches(args)


def cmd_firmware_sim(args: argparse.Namespace) -> int:
    """Build the host firmware, start it, pass its two address lines through.

    SIGTERM is passed on to the firmware process (Ctrl-C reaches it from the terminal);
    this command ends when it has: no firmware is left behind. Exit code: the firmware's,
    128 + N when a signal N ended it.
    """
    import signal
    import subprocess

    from taskrunner.backends.host_firmware import build_host_firmware

    command = [str(build_host_firmware()), "--speedup", str(args.speedup)]
    if args.log:
        command += ["--log", args.log]
    if args.channels:
        command += ["--channels", args.channels]
    started: list[subprocess.Popen[bytes]] = []
    pending: list[int] = []

    def forward(signum: int, frame: object) -> None:
        if not started:
            pending.append(signum)  # before Popen returned: passed on right after
        elif started[0].poll() is None:
            started[0].send_signal(signum)

    # Installed before the firmware starts: it prints its address lines at once, and a
    # SIGTERM sent as soon as they appear must find the handler in place.
    previous = signal.signal(signal.SIGTERM, forward)
    try:
        process = subprocess.Popen(command)
        started.append(process)
        for signum in pending:
            process.send_signal(signum)
        while True:
            try:
                code = process.wait()
                break
            except KeyboardInterrupt:  # the firmware had its own SIGINT: give it a moment
                try:
                    code = process.wait(5)
                except subprocess.TimeoutExpired:
                    process.kill()
                    code = process.wait()
                break
    finally:
        signal.signal(signal.SIGTERM, previous)
    return 128 - code if code < 0 else code


def _ask_terminal(prompt: str) -> str:
    """``input`` for an interactive helper; no input (closed, or ended) is an InputError."""
    if sys.stdin is None or sys.stdin.closed:
        raise InputError("hw calibrate asks a question for each joint: run it in a terminal "
                         "(standard input is closed)")
    try:
        return input(prompt)
    except EOFError:
        raise InputError("hw calibrate asks a question for each joint: run it in a terminal "
                         "(standard input ended before every answer was given; nothing "
                         "was written)") from None


def cmd_hw(args: argparse.Namespace) -> int:
    """Bench helpers: the firmware's status, homing, jogging one joint, calibrating."""
    import math

    from taskrunner.backends import ServoBackend
    from taskrunner.runtime.session import make_backend

    if args.action == "calibrate" and (sys.stdin is None or sys.stdin.closed):
        _ask_terminal("")  # refuses before anything is connected or moved
    cell = _load(args.cell)
    kind = "http" if args.url else "serial"
    # serial and http backends are servo backends
    backend = cast(ServoBackend, make_backend(kind, cell, None, port=args.port, url=args.url,
                                              firmware_speedup=args.firmware_speedup))
    try:
        if args.action == "calibrate":
            from taskrunner.backends.calibrate import calibrate_servos

            robot = cell.model.instances[0]
            assert robot.hardware_path is not None  # make_backend checked it
            calibrate_servos(backend, robot.hardware_path,
                             [args.joint] if args.joint else None, ask=_ask_terminal)
            return EXIT_OK
        if args.action == "home":
            backend.command("HOME")
        elif args.action == "jog":
            if args.joint is None or args.degrees is None:
                raise InputError("jog needs JOINT and DEGREES (run-task hw jog 'Revolute 1' 10)")
            calibration = backend.calibration
            servo = calibration.servo_of(args.joint)
            state = backend.joint_state().as_dict()
            state[args.joint] += math.radians(args.degrees)
            degrees = calibration.to_servo_degrees(state)
            print(f"jog {args.joint!r} {args.degrees:+.1f}° (servo {servo}) → "
                  f"MOVE:{','.join(f'{d:.2f}' for d in degrees)}")
            backend.command("MOVE:" + ",".join(f"{d:.2f}" for d in degrees))
        status = backend.firmware_status()
        print(f"firmware {backend.version.get('firmware', '?')}: {status}")
        for name, value in backend.joint_state().as_dict().items():
            print(f"  {name}: {value:+.4f} rad ({math.degrees(value):+.1f}°)")
    finally:
        backend.close()
    return EXIT_OK


def cmd_serve(args: argparse.Namespace) -> int:
    import shlex

    from taskrunner.api import Settings, create_app
    from taskrunner.api.serving import serve

    try:
        settings = Settings.from_env(token=args.token, planner=args.planner,
                                     data_dir=args.data_dir)
        if args.no_auth:
            settings = settings.replaced(auth=False, token=None)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_INVALID
    app = create_app(settings)
    base = f"http://{args.host}:{args.port}"
    if app.state.token is None:
        print(f"taskrunner API at {base} (docs: {base}/docs), OPEN: no token needed "
              "(--no-auth)", flush=True)
    else:
        made = "" if settings.token else " (made for this session; set TASKRUNNER_TOKEN to fix it)"
        reads = ("reads are open (TASKRUNNER_OPEN_READS)" if settings.open_reads
                 else "every endpoint but /health and /docs needs it")
        print(f"taskrunner API at {base} (docs: {base}/docs)\n"
              f"  token{made}; {reads}; for curl, paste:\n"
              f"export TASKRUNNER_TOKEN={shlex.quote(app.state.token)}", flush=True)
    if args.control_port is not None:
        print(f"  control port: http://{args.host}:{args.control_port} (cancel and run state "
              "only, on a listener of its own)", flush=True)
    serve(app, settings, args.host, args.port, args.log_level, control_port=args.control_port)
    return EXIT_OK


def _records_in(folder: Path) -> list[RunRecord]:
    """The run records of ``folder`` (``*.json``); one that cannot be read is named on
    stderr and left out."""
    from taskrunner.runtime.records import load_record

    records = []
    for path in sorted(folder.glob("*.json")) if folder.is_dir() else []:
        try:
            records.append(load_record(path))
        except (OSError, ValueError, TypeError, KeyError, TaskrunnerError) as exc:
            print(f"warning: {path}: not shown: {exc}", file=sys.stderr)
    return records


def cmd_view(args: argparse.Namespace) -> int:
    """Serve the web view on 127.0.0.1 and print its URL: a run record (``.json``) opens
    for replay, a task (file or shipped name) for its check and plan-only preview, nothing
    the runs of ``./runs`` (``TASKRUNNER_RUNS_DIR``; the cells when there are none). The
    server keeps its data in a temporary folder (records are copied into it); it needs a
    token like ``serve`` (printed, typed into the page, never in a URL)."""
    import shlex
    import socket
    import tempfile

    from taskrunner.api import Settings, create_app
    from taskrunner.api.app import new_token
    from taskrunner.api.serving import serve
    from taskrunner.api.store import RunStore
    from taskrunner.resources import resolve_task
    from taskrunner.runtime.records import load_record

    data_dir = Path(tempfile.mkdtemp(prefix="taskrunner-view-"))
    token = args.token or os.environ.get("TASKRUNNER_TOKEN") or new_token()
    tasks_dir: Path | None = None
    cells_dir: Path | None = None
    fragment = "#/cell"
    try:
        if args.target and args.target.endswith(".json"):
            record = load_record(args.target)
            fragment = f"#/run/{record.run_id}"
        elif args.target:
            from taskrunner.tasks import load_task

            task_file = resolve_task(args.target)
            spec = load_task(task_file)
            tasks_dir, cells_dir = task_file.parent, Path(spec.cell).parent
            fragment = f"#/task/{task_file.stem}"
        settings = Settings.from_env(data_dir=data_dir, token=token, tasks_dir=tasks_dir,
                                     cells_dir=cells_dir)
        if args.target and args.target.endswith(".json"):
            records = [record]
        elif args.target:
            records = []
        else:
            records = _records_in(Path(os.environ.get("TASKRUNNER_RUNS_DIR") or "runs"))
            fragment = "#/runs" if records else fragment
        if records:
            store = RunStore(settings.db_path)
            for each in records:
                store.save(each)
            store.close()
    except (OSError, ValueError, TaskrunnerError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_INVALID
    port = args.port
    if not port:
        with socket.socket() as probe:
            probe.bind(("127.0.0.1", 0))
            port = int(probe.getsockname()[1])
    app = create_app(settings)
    print(f"taskrunner view at http://127.0.0.1:{port}/{fragment}\n"
          f"  the page asks for the token: {app.state.token}\n"
          f"export TASKRUNNER_TOKEN={shlex.quote(str(app.state.token))}", flush=True)
    serve(app, settings, "127.0.0.1", port, args.log_level)
    return EXIT_OK


def cmd_examples(args: argparse.Namespace) -> int:
    """The shipped example tasks: name, cell, first line of the description."""
    from taskrunner.resources import example_tasks
    from taskrunner.yamlfile import load_yaml

    rows = []
    for name, path in example_tasks().items():
        try:
            data = load_yaml(path)
        except TaskrunnerError as exc:  # a broken shipped file is a bug: say so, go on
            rows.append((name, "?", f"unreadable: {exc}"))
            continue
        cell = Path(str(data.get("cell", "?"))).stem if isinstance(data, dict) else "?"
        lines = str(data.get("description", "")).strip().splitlines() if isinstance(
            data, dict) else []
        rows.append((name, cell, lines[0] if lines else ""))
    width = max(len(r[0]) for r in rows)
    cell_width = max(len(r[1]) for r in rows)
    for name, cell, about in rows:
        print(f"{name:<{width}}  {cell:<{cell_width}}  {about}".rstrip())
    if args.paths:
        for name, path in example_tasks().items():
            print(f"{name}: {path}")
    return EXIT_OK


def cmd_export(args: argparse.Namespace) -> int:
    from taskrunner.export.command import export_command

    return export_command(args)


def cmd_warm_up(args: argparse.Namespace) -> int:
    from taskrunner.runtime.session import warm_up_command

    return warm_up_command()


def cmd_collision_matrix(args: argparse.Namespace, rest: Sequence[str]) -> int:
    from taskrunner.scene import acm

    return acm.main(list(rest))


def cmd_test(args: argparse.Namespace) -> int:
    from taskrunner.runtime.testing import test_command

    return test_command(args.paths, args.jobs, args.junit, args.ray)


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
    run.add_argument("--backend", choices=("mock", "sim", "mujoco", "serial", "http"),
                     default="mock", help="where the motion goes (mock); mujoco: physics, "
                     "pip install 'mujoco>=3.2,<4' 'trimesh>=4.0,<6'")
    run.add_argument("--port", help="serial port of the ESP32 (serial backend; default: "
                                    "the robot's hardware.yaml)")
    run.add_argument("--url", help="the ESP32's /api/command URL (http backend)")
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
    check = sub.add_parser("check", help="check a task file; nothing moves")
    check.add_argument("file", help="task file (YAML), or a shipped example's name")
    check.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                       help="override a task parameter (repeatable)")
    check.add_argument("--seed", type=int, default=0, help="IK and planner seed (0)")
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
    hw.add_argument("action", choices=("status", "home", "jog", "calibrate"),
                    help="status: firmware and joint angles; home; jog JOINT DEGREES; "
                         "calibrate [JOINT]: write zero_rad and direction to hardware.yaml")
    hw.add_argument("joint", nargs="?", help="joint to jog, e.g. 'Revolute 1'")
    hw.add_argument("degrees", nargs="?", type=float, help="how far to jog (degrees)")
    hw.add_argument("--port", help="serial port (default: the robot's hardware.yaml)")
    hw.add_argument("--url", help="the ESP32's /api/command URL instead of serial")
    hw.add_argument("--cell", default=str(DEFAULT_CELL),
                    help=f"cell of the servo arm: a path or a shipped cell's name ({DEFAULT_CELL})")
    hw.add_argument("--firmware-speedup", type=float, default=1.0, help=argparse.SUPPRESS)
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
        _add_robot_options(loads_robots)
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
    serve.add_argument("--collision", choices=("exact", "convex", "auto"), default=None,
                       help="link geometry of every robot the server loads (default: each "
                            "robot's own choice: its cell's or robot.yaml's collision:, else auto)")
    serve.add_argument("--planner", choices=("worker", "inprocess"), default=None,
                       help="plan in a worker process per run (default) or in-process")
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
                "firmware-sim": cmd_firmware_sim, "hw": cmd_hw,
                "serve": cmd_serve, "test": cmd_test, "sweep": cmd_sweep,
                "warm-up": cmd_warm_up, "export": cmd_export}
    try:
        _apply_robot_options(args)
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
