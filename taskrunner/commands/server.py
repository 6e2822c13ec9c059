"""``run-task serve`` and ``view``: the REST API, and the browser view of a task or of
run records on a server of its own."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from taskrunner.errors import TaskrunnerError
from taskrunner.kinds import ExitCode

if TYPE_CHECKING:

    from taskrunner.runtime.records import RunRecord

__all__ = ["cmd_serve", "cmd_view", "view_load_settings"]


def cmd_serve(args: argparse.Namespace) -> int:
    import shlex

    from taskrunner.api import Settings, create_app
    from taskrunner.api.serving import serve

    try:
        settings = Settings.from_env(token=args.token, planner=args.planner,
                                     data_dir=args.data_dir, collision=args.collision,
                                     package_path=tuple(args.package_path) or None)
        if args.foxglove is not None:
            settings = settings.replaced(foxglove_port=args.foxglove)
        if args.no_auth:
            settings = settings.replaced(auth=False, token=None)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return ExitCode.INVALID
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
    if settings.foxglove_port is not None:
        _print_foxglove_ports(settings.cells_dir, settings.foxglove_port)
    if args.control_port is not None:
        print(f"  control port: http://{args.host}:{args.control_port} (cancel and run state "
              "only, on a listener of its own)", flush=True)
    serve(app, settings, args.host, args.port, args.log_level, control_port=args.control_port)
    return ExitCode.OK


def view_load_settings(args: argparse.Namespace, record: RunRecord | None
                       ) -> dict[str, object]:
    """How ``run-task view`` loads robots, as :class:`~taskrunner.api.Settings` fields:
    its ``--package-path`` and ``--collision`` when it has either, else the way the run of
    ``record`` loaded them (its record's ``load_options``), else nothing (the defaults).

    Raises:
        InputError: the record's load options are not valid.
    """

    folders = tuple(getattr(args, "package_path", None) or ())
    collision = getattr(args, "collision", None)
    recorded = None if folders or collision is not None or record is None \
        else record.loaded_with()
    if recorded is None:
        return {"package_path": folders or None, "collision": collision}
    return {"package_path": recorded.package_path or None, "collision": recorded.collision,
            "strict": recorded.strict, "allow_missing_meshes": recorded.allow_missing_meshes}


def _print_foxglove_ports(cells_dir: Path, port: int) -> None:
    """Which port each cell's live Foxglove feed takes (see
    :mod:`taskrunner.export.cellfeeds`)."""
    from taskrunner.resources import cell_files

    ids = list(cell_files(cells_dir))
    print(f"  Foxglove: one feed per cell, open when the cell's first run starts "
          f"(127.0.0.1 only; a cell from elsewhere takes the next port after {port + len(ids) - 1}):"
          if port else "  Foxglove: one feed per cell on a free port (in the log)", flush=True)
    for i, cell_id in enumerate(ids if port else ()):
        print(f"    {cell_id}: ws://127.0.0.1:{port + i}", flush=True)


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
        loads = view_load_settings(args, record if args.target and
                                   args.target.endswith(".json") else None)
        settings = Settings.from_env(None, data_dir=data_dir, token=token,
                                     tasks_dir=tasks_dir, cells_dir=cells_dir, **loads)
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
        return ExitCode.INVALID
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
    return ExitCode.OK
