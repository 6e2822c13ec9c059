"""A run record as an MCAP file with ROS 2 messages (``ros2`` profile, ``cdr``).

The file opens in Foxglove (its 3D panel shows the robot from ``/robot_description``
moving with ``/tf``) and plays into RViz with ``ros2 bag play`` (rosbag2's MCAP storage
plugin): see ``docs/foxglove.md``. Channels carry the QoS rosbag2 replays them with
(``offered_qos_profiles``): ``/robot_description`` and ``/tf_static`` transient local
(latched, as ``robot_state_publisher`` offers them), the others volatile.

Writing needs the ``mcap`` package (``pip install 'taskrunner-robotics[foxglove]'``).
"""

from __future__ import annotations

import os
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

from taskrunner.errors import InputError, TaskrunnerError
from taskrunner.export.timeline import LATCHED, TOPICS, TimedMessage, record_messages
from taskrunner.robot.cell import Cell
from taskrunner.runtime.records import RunRecord, load_record

__all__ = ["cell_of_record", "export_mcap", "write_mcap"]

# rmw's QoS as rosbag2 (Humble and later) stores it: history 1 keep last, reliability 1
# reliable, durability 1 transient local / 2 volatile; 0 s: the policy's default.
_QOS = ("- history: 1\n  depth: {depth}\n  reliability: 1\n  durability: {durability}\n"
        "  deadline:\n    sec: 0\n    nsec: 0\n  lifespan:\n    sec: 0\n    nsec: 0\n"
        "  liveliness: 1\n  liveliness_lease_duration:\n    sec: 0\n    nsec: 0\n"
        "  avoid_ros_namespace_conventions: false\n")


def _qos(topic: str) -> str:
    if topic in LATCHED:
        return _QOS.format(depth=1, durability=1)
    return _QOS.format(depth=100, durability=2)


def write_mcap(messages: list[TimedMessage], path: str | Path,
               metadata: dict[str, str] | None = None) -> Path:
    """Write ``messages`` (in time order) to the MCAP file ``path`` (replaced
    atomically: a reader never sees half a file); returns the path.

    Raises:
        TaskrunnerError: the ``mcap`` package is not installed.
        InputError: the file cannot be written there.
    """
    try:
        from mcap.writer import CompressionType, Writer
    except ImportError:
        raise TaskrunnerError("writing MCAP files needs the 'mcap' package: pip install "
                              "'taskrunner-robotics[foxglove]'") from None
    from taskrunner import __version__

    path = Path(path)
    folder = path.parent if str(path.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{path.name}-", suffix=".tmp")
    except OSError as exc:
        raise InputError(f"{path}: cannot write the MCAP file there ({exc.strerror})") from None
    try:
        with os.fdopen(fd, "wb") as out:
            writer = Writer(out, compression=CompressionType.ZSTD)
            writer.start(profile="ros2", library=f"taskrunner {__version__}")
            channels: dict[str, int] = {}
            schemas: dict[str, int] = {}
            for topic, kind in TOPICS.items():
                if kind.name not in schemas:
                    schemas[kind.name] = writer.register_schema(
                        kind.name, "ros2msg", kind.definition.encode())
                channels[topic] = writer.register_channel(
                    topic, "cdr", schemas[kind.name], metadata={"offered_qos_profiles": _qos(topic)})
            sequence = dict.fromkeys(channels, 0)
            for message in messages:
                sequence[message.topic] += 1
                writer.add_message(channels[message.topic], log_time=message.time_ns,
                                   data=message.data, publish_time=message.time_ns,
                                   sequence=sequence[message.topic])
            if metadata:
                writer.add_metadata("taskrunner", metadata)
            writer.finish()
        os.chmod(tmp, 0o644)  # mkstemp's 0600 is for the temporary name only
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def cell_of_record(record: RunRecord, cell: str | Path | None = None) -> Cell:
    """The cell a run used: ``cell`` (a name or path) if given, else the ``cell:`` of the
    task text the record keeps, found from the task file's folder; its robots loaded as
    the record says the run loaded them (``load_options``: its package path, its
    collision choice).

    Raises:
        InputError: the cell cannot be found (give ``cell``), or is not the one named in
            the record, or the record's load options are not valid.
    """
    from taskrunner.resources import resolve_cell
    from taskrunner.robot.cell import load_cell_or_robot
    options = record.loaded_with()
    if cell is None:
        import yaml

        try:
            text = yaml.safe_load(record.task_text) if record.task_text else None
        except yaml.YAMLError:
            text = None
        named = text.get("cell") if isinstance(text, dict) else None
        if not isinstance(named, str):
            raise InputError(f"run {record.run_id}: the record's task text names no cell; "
                             f"give the cell (--cell NAME_OR_PATH)")
        folder = Path(record.task_file).parent if record.task_file else None
        try:
            path = resolve_cell(named, relative_to=folder)
        except InputError:
            path = resolve_cell(named)
    else:
        path = resolve_cell(cell)
    loaded = load_cell_or_robot(path, options=options)
    if loaded.name != record.cell:
        raise InputError(f"run {record.run_id} ran on cell {record.cell!r}, but {path} is "
                         f"cell {loaded.name!r}; give the run's cell (--cell NAME_OR_PATH)")
    return loaded


def _tell_stderr(text: str) -> None:
    print(f"warning: degraded MCAP: {text}", file=sys.stderr, flush=True)


def export_mcap(record: str | Path | RunRecord, out: str | Path,
                cell: str | Path | Cell | None = None, *, allow_degraded: bool = False,
                on_degraded: Callable[[str], None] | None = _tell_stderr) -> Path:
    """Convert a run record (its JSON, or its journal while it runs) to an MCAP file.

    Args:
        record: the record's path (``runs/<run_id>.json``) or the record.
        out: the MCAP file to write.
        cell: the cell the run used (default: the one its task names).
        allow_degraded: write the file even where it cannot show the run as it was (a
            scene object whose mesh is not found is left out; a mujoco run's motion
            without a physics report plays the trajectory sent). Each degradation is
            told to ``on_degraded`` (default: a line on stderr) and on ``/rosout``.

    Returns:
        The path written.

    Raises:
        MissingMeshError: without ``allow_degraded``, a scene object's mesh is not
            found (names the object, its file and the record).
        InputError: without ``allow_degraded``, a mujoco run's motion has no physics
            report (names the motion and the record); or the record cannot be read.
    """
    source: str | Path = f"run {record.run_id}" if isinstance(record, RunRecord) else record
    if not isinstance(record, RunRecord):
        try:
            record = load_record(record)
        except FileNotFoundError:
            raise InputError(f"{record}: no such run record") from None
        except (ValueError, TypeError) as exc:
            raise InputError(f"{record}: not a run record ({exc})") from None
    loaded = cell if isinstance(cell, Cell) else cell_of_record(record, cell)
    metadata = {"run_id": record.run_id, "task": record.task, "task_file": record.task_file,
                "cell": record.cell, "backend": record.backend, "status": record.status,
                "started": record.started, "finished": record.finished or ""}
    messages = record_messages(record, loaded, allow_degraded=allow_degraded,
                               on_degraded=on_degraded, source=source)
    return write_mcap(messages, out, metadata)
