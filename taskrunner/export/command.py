"""``run-task export`` and the ``--mcap`` / ``--foxglove`` options of a run."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from taskrunner.runtime.runner import Runner

__all__ = ["add_export_parser", "add_run_options", "export_command", "run_watches"]


def add_export_parser(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    export = sub.add_parser("export", help="convert a run record to an MCAP file (ROS 2 "
                                           "messages: Foxglove, ros2 bag play into RViz)")
    export.add_argument("record", help="a run record (runs/<id>.json, or its .events.jsonl)")
    export.add_argument("--mcap", required=True, metavar="FILE", help="the MCAP file to write")
    export.add_argument("--cell", default=None, metavar="NAME_OR_PATH",
                        help="the cell the run used (default: the one its task file names)")
    export.add_argument("--allow-degraded", action="store_true",
                        help="write the file even where it cannot show the run as it was (an "
                             "object whose mesh is not found left out, a mujoco run's motion "
                             "without physics samples played as sent); each is said on stderr "
                             "and /rosout. Without it, these are errors")


def add_run_options(run: argparse.ArgumentParser) -> None:
    run.add_argument("--mcap", default=None, metavar="FILE",
                     help="also write the run as an MCAP file (ROS 2 messages) when it ends")
    run.add_argument("--foxglove", nargs="?", type=int, const=8765, default=None,
                     metavar="PORT", help="stream /joint_states, /tf and /rosout live to "
                                          "Foxglove on ws://127.0.0.1:PORT (8765)")
    run.add_argument("--foxglove-wait", type=float, default=0.0, metavar="SECONDS",
                     help="with --foxglove: before the run starts, wait up to SECONDS for a "
                          "Foxglove client to subscribe (0: start at once)")
    run.add_argument("--mcap-allow-degraded", action="store_true",
                     help="with --mcap: write the file even where it cannot show the run as it "
                          "was (as run-task export --allow-degraded; each said on stderr)")


def export_command(args: argparse.Namespace) -> int:
    from taskrunner.export.mcapfile import export_mcap

    path = export_mcap(Path(args.record), Path(args.mcap), args.cell,
                       allow_degraded=bool(args.allow_degraded))
    print(f"{args.record}: written to {path} ({path.stat().st_size / 1024:.0f} KiB)")
    return 0


def run_watches(args: argparse.Namespace
                ) -> list[Callable[[Runner], AbstractContextManager[object]]]:
    """What a run's ``--foxglove`` and ``--mcap`` ask for, for ``run_task_file(watch=)``."""
    watches: list[Callable[[Runner], AbstractContextManager[object]]] = []
    if getattr(args, "foxglove", None) is not None:
        port, wait = args.foxglove, float(getattr(args, "foxglove_wait", 0.0) or 0.0)
        if not (wait >= 0 and wait < float("inf")):
            from taskrunner.errors import InputError

            raise InputError(f"'--foxglove-wait' must be a number of seconds >= 0 (got {wait})")

        @contextmanager
        def feed(runner: Runner) -> Iterator[None]:
            from taskrunner.export.live import FoxgloveFeed, FoxgloveFeedOptions

            with FoxgloveFeed(runner.cell, FoxgloveFeedOptions(port=port)) as live:
                print(f"Foxglove: open connection {live.url}", flush=True)
                if wait > 0:
                    print(f"Foxglove: waiting up to {wait:g} s for a client …", flush=True)
                    if not live.wait_for_client(wait):
                        print("Foxglove: no client yet; the run starts", flush=True)
                with live.follow(runner):
                    yield

        watches.append(feed)
    if getattr(args, "mcap", None):
        from taskrunner.errors import InputError

        out, allowed = Path(args.mcap), bool(getattr(args, "mcap_allow_degraded", False))
        if not out.parent.is_dir():  # said before anything moves, not after the run
            raise InputError(f"'--mcap' must be a file in an existing folder (got {out})")

        @contextmanager
        def mcap(runner: Runner) -> Iterator[None]:
            from taskrunner.export.mcapfile import export_mcap

            yield
            try:
                path = export_mcap(runner.record, out, runner.cell, allow_degraded=allowed)
            except InputError as exc:
                runs = runner.options.runs_dir
                kept = f" (its record: {runs / (runner.record.run_id + '.json')})" if runs else ""
                raise type(exc)(f"the run ended{kept}, but its MCAP file was not written: "
                                f"{exc}") from None
            print(f"  mcap: {path}", file=sys.stdout, flush=True)

        watches.append(mcap)
    return watches
