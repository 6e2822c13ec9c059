"""A run record as timed ROS 2 messages: what an MCAP file of the run holds.

Time: a message's log time (and header stamp) is the record's ``started`` (UTC) plus the
run's own task time (s), the schedule the motions were put on:

* a motion starts at its ``sent`` time (when it really started; the planned ``start``
  on a backend that plays no time, the mock) and runs for the seconds of its
  trajectory it executed (``executed.until`` of its node's end, else all of it);
* any other event is at the latest of those times reached so far, or at its own clock
  time if that is later and the backend plays motions in time (sim, mujoco, servos).

So a mock run, whose motions end at once on the wall clock, still plays back at the
speed it was planned for; a run on the robot plays as it ran.

Topics (ROS 2 conventions, so Foxglove's 3D panel and RViz show them):

* ``/robot_description`` (``std_msgs/String``): the merged URDF, once, at the start.
* ``/tf_static`` (``tf2_msgs/TFMessage``): every fixed joint's transform, robot
  placements included, once.
* ``/joint_states`` (``sensor_msgs/JointState``) and ``/tf``: every joint of the cell at
  each recorded trajectory sample (the record keeps up to 25 per second) and at each
  motion's end; joints of motions running at once are each interpolated there.
* ``/scene_objects`` (``visualization_msgs/MarkerArray``): the scene's objects, at the
  start, when each motion starts (objects picked up ride on their link's frame), and at
  the end; each array starts with a DELETEALL, so objects taken away disappear.
* ``/display_planned_path`` (``moveit_msgs/DisplayTrajectory``): each motion's
  trajectory when it was sent, from the cell's state then.
* ``/rosout`` (``rcl_interfaces/Log``): every event, the tree node as the logger's name,
  the task file and line as ``file`` and ``line``, the event's kind as ``function``.

**Nothing left out quietly.** A scene object that cannot be drawn (a mesh whose file is
not found, a shape not known) and a mujoco run whose ``/joint_states`` cannot be the
physics' own samples (a motion no physics sample covers), or whose samples are placed
by a motion start estimated, not reported (a record made before the physics reports
listed the motions' starts, :mod:`taskrunner.export.physics`) make the
export an error naming the object or motion, unless the caller allows degraded output
(``allow_degraded``, ``run-task export --allow-degraded``): then each degradation is
told to ``on_degraded`` (the command line: stderr) and on ``/rosout`` as a WARN.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path
from typing import Any

import numpy as np

from taskrunner.errors import InputError, MissingMeshError, TaskrunnerError
from taskrunner.export import rosmsg
from taskrunner.export.frames import FrameTree, robot_description
from taskrunner.export.physics import SentMotion, physics_path
from taskrunner.export.rosmsg import LogLine, Marker, MessageType
from taskrunner.kinds import NodeStatus
from taskrunner.robot.cell import Cell
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.records import RunRecord
from taskrunner.shapes import Mesh
from taskrunner.tasks import AddObjectStep, load_task_text
from taskrunner.tasks.spec import TaskSpec

__all__ = ["LATCHED", "TOPICS", "TimedMessage", "display_trajectory", "log_line",
           "record_meshes", "record_messages", "scene_markers", "task_meshes"]

# topic → message type, in the order channels are declared.
TOPICS: dict[str, MessageType] = {
    "/robot_description": rosmsg.STRING,
    "/tf_static": rosmsg.TF_MESSAGE,
    "/scene_objects": rosmsg.MARKER_ARRAY,
    "/joint_states": rosmsg.JOINT_STATE,
    "/tf": rosmsg.TF_MESSAGE,
    "/display_planned_path": rosmsg.DISPLAY_TRAJECTORY,
    "/rosout": rosmsg.LOG,
}
LATCHED = frozenset({"/robot_description", "/tf_static"})  # transient local, as published


@dataclass(frozen=True)
class TimedMessage:
    """One encoded message: ``time_ns`` (UNIX ns) on ``topic``."""

    time_ns: int
    topic: str
    data: bytes


@dataclass
class _Motion:
    node: str
    t0: float                   # s of task time
    joints: tuple[str, ...]
    times: np.ndarray           # s from t0
    positions: np.ndarray       # one row per sample
    velocities: np.ndarray
    until: float                # s of trajectory executed
    measured: bool = False      # the physics' own samples, not the trajectory sent
    seq: int = 0                # its event's
    location: str = ""          # its step's file:line

    def describe(self) -> str:
        where = f", {self.location}" if self.location else ""
        return f"motion {self.node!r} (event {self.seq}{where})"

    def sample_times(self) -> np.ndarray:
        kept = self.times[self.times <= self.until]
        return self.t0 + np.append(kept, self.until)

    def at(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """Positions and velocities ``t`` s after its start (held at its end)."""
        s = min(max(t, 0.0), self.until)
        k = int(np.searchsorted(self.times, s - 1e-9))
        if self.measured and k < len(self.times) and abs(self.times[k] - s) <= 1e-9:
            # A physics sample's own time (up to the ns the stamps are rounded to): the
            # sample itself, not a blend of it and its neighbour by a rounding.
            return self.positions[k].copy(), np.zeros(len(self.joints))
        q = np.array([np.interp(s, self.times, self.positions[:, j])
                      for j in range(len(self.joints))])
        if t > self.until:
            return q, np.zeros(len(self.joints))
        qd = np.array([np.interp(s, self.times, self.velocities[:, j])
                       for j in range(len(self.joints))])
        return q, qd


@dataclass
class _Schedule:
    """The record's events placed on its task time (module docstring)."""

    times: dict[int, float] = field(default_factory=dict)  # event seq → s
    motions: list[_Motion] = field(default_factory=list)
    end: float = 0.0
    physics: list[RunEvent | None] = field(default_factory=list)  # per motion
    reports: list[RunEvent] = field(default_factory=list)  # every physics event
    measured: bool = False      # motions are the physics' samples (no velocities)


def _trajectory(event: RunEvent) -> tuple[tuple[str, ...], np.ndarray, np.ndarray, np.ndarray]:
    data: Any = event.data["trajectory"]
    try:
        joints = tuple(str(j) for j in data["joints"])
        times = np.asarray(data["times"], dtype=float)
        positions = np.asarray(data["positions"], dtype=float).reshape(len(times), len(joints))
        velocities = np.asarray(data.get("velocities") or np.zeros_like(positions),
                                dtype=float).reshape(len(times), len(joints))
    except (KeyError, TypeError, ValueError) as exc:
        raise InputError(f"event {event.seq} ({event.kind} of {event.node!r}): its "
                         f"'trajectory' must have joints, times and positions ({exc})") from None
    if len(times) == 0:
        raise InputError(f"event {event.seq} ({event.kind} of {event.node!r}): its "
                         f"'trajectory' has no samples")
    return joints, times, positions, velocities


def _schedule(record: RunRecord) -> _Schedule:
    motions = [e for e in record.events if e.kind == "motion" and "trajectory" in e.data]
    timed = record.backend != "mock" or any(
        e.data.get("sent", e.data.get("start")) != e.data.get("start") for e in motions)
    out = _Schedule()
    running: dict[str, _Motion] = {}
    cursor = 0.0
    for event in record.events:
        t = max(cursor, event.time) if timed else cursor
        if event.kind == "motion" and "trajectory" in event.data:
            joints, times, positions, velocities = _trajectory(event)
            t = float(event.data.get("sent", event.data.get("start", cursor)))
            motion = _Motion(event.node or "", t, joints, times, positions, velocities,
                             float(times[-1]), seq=event.seq, location=event.location or "")
            running[event.node or ""] = motion
            out.motions.append(motion)
            out.physics.append(None)
        elif event.kind == "physics" and "t" in event.data:
            out.reports.append(event)
            # Its node's motion: the latest one of that node without a report yet.
            for k in range(len(out.motions) - 1, -1, -1):
                if out.motions[k].node == (event.node or "") and out.physics[k] is None:
                    out.physics[k] = event
                    break
        elif event.kind == "node_finished" and (event.node or "") in running:
            motion = running.pop(event.node or "")
            executed = event.data.get("executed")
            if isinstance(executed, dict) and executed.get("until") is not None:
                motion.until = min(float(executed["until"]), float(motion.times[-1]))
            t = max(t, motion.t0 + motion.until)
        # Events keep their order (a motion's planned start may lie a rounding before
        # the recorded end of the one before it).
        out.times[event.seq] = max(t, cursor)
        cursor = max(cursor, t)
    out.end = max([cursor, *(m.t0 + m.until for m in out.motions)])
    return out


def _measured(schedule: _Schedule) -> tuple[str | None, list[str]]:
    """Put the physics' own samples (the record's ``physics`` events) in place of the
    trajectories sent, on task time (:mod:`taskrunner.export.physics`: every kept sample
    is the whole cell's state at one moment, motions at once included); or say why not
    (the trajectories are kept). Also the motions whose physics start was estimated
    (a record whose physics reports list no motions), each with why."""
    motions = schedule.motions
    if not motions:
        return None, []
    reports = schedule.reports
    if not reports:
        more = f" (and {len(motions) - 1} more)" if len(motions) > 1 else ""
        return f"{motions[0].describe()} has no physics report{more}", []
    sent = [SentMotion(m.seq, m.t0, m.joints, m.times, m.positions, m.until, m.describe())
            for m in motions]
    path = physics_path(sent, reports)
    if isinstance(path, str):
        return path, []
    estimated = [f"{motions[k].describe()}: its start on the physics clock "
                 f"({path.starts[k]:.4f} s) is estimated "
                 + ("by fitting its joints to its trajectory" if path.how[k] == "fitted" else
                    "from the motion running when it was sent, as if task time had run "
                    "with physics time since")
                 + " (the record's physics reports do not list the motions' starts: made "
                 "before they did), so its samples may be placed off in time"
                 for k in path.estimated]
    first = motions[min(range(len(motions)), key=lambda k: motions[k].t0)]
    t0 = float(path.times[0])
    schedule.motions = [_Motion("physics", t0, path.joints, path.times - t0, path.positions,
                                np.zeros_like(path.positions), float(path.times[-1] - t0),
                                measured=True, seq=first.seq, location=first.location)]
    schedule.measured = True
    schedule.end = max(schedule.end, float(path.times[-1]))
    return None, estimated


def _start_state(record: RunRecord, cell: Cell) -> np.ndarray:
    model = cell.model
    q = cell.start_state()
    started = next((e for e in record.events if e.kind == "run_started"), None)
    scene = started.data.get("scene") if started is not None else None
    joints = scene.get("joints") if isinstance(scene, dict) else None
    if isinstance(joints, dict):
        _check_joints(record, cell, joints)
        q = model.state_with(q, {str(k): float(v) for k, v in joints.items()})
    return q


def _check_joints(record: RunRecord, cell: Cell, joints: Any) -> None:
    unknown = [str(j) for j in joints if str(j) not in cell.model.joint_names]
    if unknown:
        raise InputError(f"run {record.run_id}: joint {unknown[0]!r} of the record is not a "
                         f"joint of cell {cell.name!r} (is it the cell the run used?)")


def _stamp(base_ns: int, t: float) -> int:
    return base_ns + int(round(t * 1e9))


def _joint_samples(schedule: _Schedule, start: np.ndarray, cell: Cell
                   ) -> Iterator[tuple[float, np.ndarray, np.ndarray]]:
    """``(t, q, qd)`` of every joint at each sample time (module docstring)."""
    model = cell.model
    times = [np.array([0.0]), *(m.sample_times() for m in schedule.motions)]
    columns = [model.indices(m.joints) for m in schedule.motions]
    ordered = sorted(range(len(schedule.motions)), key=lambda i: schedule.motions[i].t0)
    for t in np.unique(np.round(np.concatenate(times), 9)):
        q, qd = start.copy(), np.zeros(model.nq)
        for i in ordered:
            motion = schedule.motions[i]
            if t + 1e-9 < motion.t0:
                continue
            q[columns[i]], qd[columns[i]] = motion.at(float(t) - motion.t0)
        yield float(t), model.apply_mimic(q), qd


def _robot_of(cell: Cell, joints: tuple[str, ...]) -> str:
    """The name of the robot whose joints ``joints`` are (the longest prefix that fits)."""
    fits = [i for i in cell.model.instances if all(j.startswith(i.prefix) for j in joints)]
    return max(fits, key=lambda i: len(i.prefix)).name if fits else cell.name


def display_trajectory(event: RunEvent, stamp_ns: int, cell: Cell, start: np.ndarray) -> bytes:
    """A ``motion`` event's trajectory as RViz's MotionPlanning display takes it
    (``/display_planned_path``): the trajectory as sent (the record's samples;
    accelerations are not recorded, so none is sent, as ROS allows), from the whole
    cell's state when it started (its event's scene, over ``start``: a state vector).

    Raises:
        InputError: the event's trajectory cannot be read.
    """
    joints, times, positions, velocities = _trajectory(event)
    if not event.data["trajectory"].get("velocities"):
        velocities = np.zeros((len(times), 0))  # not recorded: none, not zeros
    model = cell.model
    scene = event.data.get("scene")
    q = start.copy()
    if isinstance(scene, dict) and isinstance(scene.get("joints"), dict):
        q = model.state_with(q, {str(k): float(v) for k, v in scene["joints"].items()
                                 if str(k) in model.joint_names})
    # trajectory_start.attached_collision_objects stays empty: the record keeps an
    # attached object's shape and pose but not its touch links or weight, and
    # /scene_objects already shows it riding on its link.
    return rosmsg.encode_display_trajectory(
        stamp_ns, _robot_of(cell, joints), joints, times, positions, velocities,
        np.zeros((len(times), 0)), model.joint_names, model.apply_mimic(q))


# Marker colours (r, g, b, a): objects in the world, and objects a link carries.
_WORLD_COLOUR = (0.55, 0.6, 0.7, 1.0)
_CARRIED_COLOUR = (0.95, 0.55, 0.15, 1.0)


def _triple(values: Any) -> tuple[float, float, float]:
    x, y, z = (float(v) for v in values)
    return (x, y, z)


def task_meshes(spec: TaskSpec) -> dict[str, Mesh]:
    """The mesh objects a task declares (its ``objects:`` and ``add_object`` steps; the
    first declaration of a name wins), by name, their files as the task loader resolved
    them (relative to the task file's folder)."""
    found: dict[str, Mesh] = {}
    declared = [*spec.objects, *(s.object for s in spec.walk() if isinstance(s, AddObjectStep))]
    for obj in declared:
        if obj.name not in found and obj.shape == "mesh" and obj.file:
            found[obj.name] = Mesh(Path(obj.file), _triple(obj.scale or (1.0, 1.0, 1.0)))
    return found


def record_meshes(record: RunRecord) -> tuple[dict[str, Mesh], str | None]:
    """The mesh objects of the task a record ran (:func:`task_meshes`), from the task
    text it keeps, loaded as the task loader loads it: at its ``task_file`` (relative
    paths start from its folder) with its parameters. Also why none could be found, if
    so (the text missing, or not loading here)."""
    if not record.task_text or not record.task_file:
        return {}, "the record keeps no task text"
    try:
        spec = load_task_text(record.task_text, record.task_file, record.parameters or None)
    except TaskrunnerError as exc:
        first = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        return {}, f"its task text does not load here ({first})"
    return task_meshes(spec), None


def _mesh_uri(mesh: Mesh) -> str:
    text = str(mesh.path)
    return text if "://" in text else mesh.path.resolve().as_uri()


def scene_markers(objects: Any, stamp_ns: int, cell: Cell, root: str,
                  meshes: Mapping[str, Mesh] | None = None
                  ) -> tuple[list[Marker], list[str]]:
    """The scene's objects as markers (after a DELETEALL; ``root``: the tf tree's root,
    the world); and the objects that could not be drawn, with why. ``meshes``: the mesh
    objects of the task (:func:`task_meshes`), beside those of the cell: a record names
    a mesh by its file name only, so an object is drawn from the task's or the cell's
    object of its name with that file name."""
    markers = [Marker(stamp_ns, root, "", 0, action=rosmsg.DELETEALL)]
    skipped = []
    known = {o.name: o.shape for o in cell.objects if isinstance(o.shape, Mesh)}
    known.update(meshes or {})
    for i, obj in enumerate(objects or [], start=1):
        shape, pose = obj.get("shape") or {}, obj.get("pose") or {}
        name, kind = str(obj.get("name", "")), shape.get("type")
        resource = ""
        if kind == "box":
            marker_type, scale = rosmsg.CUBE, _triple(shape["size"])
        elif kind == "sphere":
            d = 2 * float(shape["radius"])
            marker_type, scale = rosmsg.SPHERE, (d, d, d)
        elif kind == "cylinder":
            d = 2 * float(shape["radius"])
            marker_type, scale = rosmsg.CYLINDER, (d, d, float(shape["length"]))
        elif kind == "mesh" and name in known and known[name].path.name == \
                Path(str(shape.get("file", ""))).name:
            mesh = known[name]
            marker_type, scale = rosmsg.MESH_RESOURCE, _triple(mesh.scale)
            resource = _mesh_uri(mesh)
        else:
            skipped.append(f"object {name!r} ({kind}) not drawn: "
                           + (f"its mesh file {shape.get('file')!r} is not that of an object "
                              f"{name!r} of the task or the cell" if kind == "mesh"
                              else "unknown shape"))
            continue
        frame = obj.get("attached_to") or pose.get("frame") or "world"
        x, y, z, w = (float(v) for v in pose.get("quat", (0, 0, 0, 1)))
        markers.append(Marker(
            stamp_ns, root if frame == "world" else str(frame), name, i, marker_type,
            xyz=_triple(pose.get("xyz", (0, 0, 0))), quat=(x, y, z, w), scale=scale,
            color=_CARRIED_COLOUR if obj.get("attached_to") else _WORLD_COLOUR, text=name,
            mesh_resource=resource))
    return markers, skipped


def _log_level(event: RunEvent) -> int:
    if event.kind == "run_finished":
        return {"succeeded": rosmsg.INFO, "failed": rosmsg.ERROR}.get(event.status or "",
                                                                       rosmsg.WARN)
    if event.kind == "node_finished" and event.status == NodeStatus.FAILURE:
        return rosmsg.WARN
    if event.kind == "node_started":
        return rosmsg.DEBUG
    return rosmsg.INFO


def log_line(event: RunEvent, stamp_ns: int, record: RunRecord) -> LogLine:
    file, line = record.task_file, 0
    if event.location:
        head, sep, tail = event.location.rpartition(":")
        if sep and tail.isdigit():
            file, line = head, int(tail)
        else:
            file = event.location
    text = event.message or event.kind
    if event.status and event.kind in ("node_finished", "run_finished"):
        text = f"{event.status}: {text}" if event.message and event.message != event.status \
            else event.status
    return LogLine(stamp_ns, _log_level(event), event.node or record.task, text, file,
                   event.kind, line)


def record_messages(record: RunRecord, cell: Cell, *, allow_degraded: bool = False,
                    on_degraded: Callable[[str], None] | None = None,
                    source: str | Path | None = None) -> list[TimedMessage]:
    """Every message of ``record``'s MCAP file, in time order (module docstring).

    Args:
        record: a run record (:func:`taskrunner.runtime.records.load_record`).
        cell: the cell the run used (its model gives the links' poses).
        allow_degraded: write the messages even where they cannot be what the run was:
            an object not drawn, a mujoco run's trajectories sent in place of its
            physics' samples, or its samples placed by an estimated start. Each such
            degradation is then told to ``on_degraded`` (once) and on ``/rosout`` (WARN).
        source: the record's file, for messages (default: the run's id).

    Raises:
        InputError: the record names a joint the cell does not have, or holds a
            trajectory that cannot be read; or (without ``allow_degraded``) a mujoco
            run's motion has no physics report, or its physics start is estimated (an
            older record), naming the motion.
        MissingMeshError: (without ``allow_degraded``) a scene object's mesh cannot be
            found, naming the object and its file.
    """
    where = str(source) if source is not None else f"run {record.run_id}"
    told: list[str] = []

    def degraded(reason: str, error: type[InputError] = InputError) -> None:
        if not allow_degraded:
            raise error(f"{where}: {reason}; the MCAP file is not written (allow degraded "
                        "output: run-task export --allow-degraded, or "
                        "export_mcap(allow_degraded=True))")
        if reason not in told:
            told.append(reason)
            if on_degraded is not None:
                on_degraded(f"{where}: {reason}")

    tree = FrameTree(cell.model)
    base_ns = int(datetime.fromisoformat(record.started).timestamp() * 1e9)
    meshes, no_meshes = record_meshes(record)
    schedule = _schedule(record)
    planned = [(e, m.t0) for m in schedule.motions for e in record.events if e.seq == m.seq]
    not_measured, estimated = _measured(schedule) if record.backend == "mujoco" else (None, [])
    for motion in schedule.motions:
        _check_joints(record, cell, motion.joints)
    out: list[tuple[int, int, TimedMessage]] = []
    order = {topic: i for i, topic in enumerate(TOPICS)}

    def add(t: float, topic: str, data: bytes) -> None:
        stamp = _stamp(base_ns, t)
        out.append((stamp, order[topic], TimedMessage(stamp, topic, data)))

    if not_measured is not None:
        not_measured = (f"/joint_states and /tf would be the trajectories sent, not the "
                        f"physics' own samples of the mujoco run: {not_measured}")
        degraded(not_measured)
        add(0.0, "/rosout", rosmsg.encode_log(LogLine(
            base_ns, rosmsg.WARN, "taskrunner.export", not_measured)))
    for reason in estimated:
        degraded(reason)
        add(0.0, "/rosout", rosmsg.encode_log(LogLine(
            base_ns, rosmsg.WARN, "taskrunner.export", reason)))
    add(0.0, "/robot_description", rosmsg.encode_string(robot_description(cell.model)))
    add(0.0, "/tf_static", rosmsg.encode_tf_message(tree.static_transforms(base_ns)))
    names = cell.model.joint_names
    start = _start_state(record, cell)
    for t, q, qd in _joint_samples(schedule, start, cell):
        stamp = _stamp(base_ns, t)
        # The physics reports no velocities: none is sent rather than a made-up one.
        add(t, "/joint_states", rosmsg.encode_joint_state(
            stamp, names, q, () if schedule.measured else qd))
        add(t, "/tf", rosmsg.encode_tf_message(tree.moving_transforms(q, stamp)))
    for event, t in planned:
        add(t, "/display_planned_path", display_trajectory(event, _stamp(base_ns, t), cell,
                                                           start))
    for event in record.events:
        t = schedule.times[event.seq]
        stamp = _stamp(base_ns, t)
        scene = event.data.get("scene")
        if event.kind in ("run_started", "motion", "run_finished") and isinstance(scene, dict):
            markers, skipped = scene_markers(scene.get("objects"), stamp, cell, tree.root,
                                             meshes)
            add(t, "/scene_objects", rosmsg.encode_marker_array(markers))
            if skipped and no_meshes:
                skipped = [f"{reason}; the task's meshes: {no_meshes}" for reason in skipped]
            for reason in skipped:
                degraded(f"{reason} (task file {record.task_file or 'not kept'})",
                         MissingMeshError)
                add(t, "/rosout", rosmsg.encode_log(
                    LogLine(stamp, rosmsg.WARN, "taskrunner.export", reason)))
        add(t, "/rosout", rosmsg.encode_log(log_line(event, stamp, record)))
    out.sort(key=lambda item: (item[0], item[1]))
    return [message for _, _, message in out]
