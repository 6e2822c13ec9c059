"""What a replay needs from a run, as JSON-ready data: trajectories and scenes.

A run announces each motion it sends to the backend with a ``motion`` event holding the
timed trajectory (joint names, times, positions, velocities) and the scene as it was when
the motion started (the robot's joints, every object with its pose and what carries it);
``run_started`` and ``run_finished`` carry the first and the final scene, and the
``node_finished`` event of a moving leaf says how far its motion got (``executed``). The
events are in the run record and in the API's live stream alike, so a viewer replays a
finished run and follows a live one from the same data.

Trajectories are kept small: samples are thinned to ``max_rate_hz`` (the first and the
last kept), and numbers are rounded (positions to 10 µrad, times to 0.1 ms), which a
viewer interpolating linearly cannot tell from the full trajectory. A pick_place record
is about 100 kB.

:func:`replay_of` reads those events back out of a record. A scene's objects are written
by :func:`object_data` (rounded for a viewer here; exact in a run's checkpoints,
:mod:`taskrunner.runtime.checkpoint`) and read back by :func:`object_of`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from taskrunner.errors import InputError
from taskrunner.runtime.records import RunRecord
from taskrunner.scene.objects import SceneObject, SceneSnapshot
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere
from taskrunner.types import JointTrajectory, Pose

__all__ = ["Replay", "motion_data", "object_data", "object_of", "replay_of", "scene_data",
           "shape_data", "shape_of", "trajectory_data"]

MAX_RATE_HZ = 25.0   # samples kept per second of trajectory
_POS_DIGITS = 5      # rad or m
_TIME_DIGITS = 4     # s


def trajectory_data(trajectory: JointTrajectory, max_rate_hz: float = MAX_RATE_HZ
                    ) -> dict[str, Any]:
    """A trajectory as JSON: ``joints``, ``times`` (s), ``positions`` and ``velocities``
    (one row per sample, rad or m and per second), thinned to ``max_rate_hz``."""
    times = np.asarray(trajectory.times, dtype=float)
    keep = _thin(times, max_rate_hz)
    stamps = [round(float(t), _TIME_DIGITS) for t in times[keep]]
    # Rounded, two samples may fall on one stamp (a motion cut just after a sample, or
    # stopped at its first): the earlier goes, so that the times stay strictly increasing.
    distinct = [i for i in range(len(stamps)) if i == len(stamps) - 1 or stamps[i] < stamps[i + 1]]
    if len(distinct) < 2 <= len(stamps):  # all within one stamp: its first and last apart
        distinct = [0, len(stamps) - 1]
        stamps[-1] = round(stamps[0] + 10.0 ** -_TIME_DIGITS, _TIME_DIGITS)
    keep = keep[distinct]
    return {
        "joints": list(trajectory.names),
        "duration": round(trajectory.duration, _TIME_DIGITS),
        "times": [stamps[i] for i in distinct],
        "positions": np.round(trajectory.positions[keep], _POS_DIGITS).tolist(),
        "velocities": np.round(trajectory.velocities[keep], _POS_DIGITS).tolist(),
    }


def _thin(times: np.ndarray, rate_hz: float) -> np.ndarray:
    """Indices of samples at least 1/rate_hz apart, the first and the last always kept."""
    if len(times) <= 2:
        return np.arange(len(times))
    step = 1.0 / rate_hz
    keep = [0]
    for i in range(1, len(times) - 1):
        if times[i] - times[keep[-1]] >= step:
            keep.append(i)
    keep.append(len(times) - 1)
    return np.array(keep)


def _pose(pose: Pose, exact: bool) -> dict[str, Any]:
    if exact:
        return {"xyz": list(pose.xyz), "quat": list(pose.quat), "frame": pose.frame}
    return {"xyz": [round(v, 6) for v in pose.xyz], "quat": [round(v, 6) for v in pose.quat],
            "frame": pose.frame}


def shape_data(shape: Shape, exact: bool = False) -> dict[str, Any]:
    """A shape as JSON (``type`` and its sizes, m); a mesh by its file name, or with
    ``exact`` by its whole path (a resumed run loads it again)."""
    if isinstance(shape, Box):
        return {"type": "box", "size": list(shape.size)}
    if isinstance(shape, Cylinder):
        return {"type": "cylinder", "radius": shape.radius, "length": shape.length}
    if isinstance(shape, Sphere):
        return {"type": "sphere", "radius": shape.radius}
    if isinstance(shape, Mesh):
        return {"type": "mesh", "file": str(shape.path) if exact else shape.path.name,
                "scale": list(shape.scale)}
    raise InputError(f"a run record cannot hold a shape of type {type(shape).__name__}")


def shape_of(data: dict[str, Any]) -> Shape:
    """The shape :func:`shape_data` wrote.

    Raises:
        InputError: an unknown ``type``.
    """
    kind = data.get("type")
    if kind == "box":
        return Box(tuple(data["size"]))  # type: ignore[arg-type]
    if kind == "cylinder":
        return Cylinder(float(data["radius"]), float(data["length"]))
    if kind == "sphere":
        return Sphere(float(data["radius"]))
    if kind == "mesh":
        return Mesh(Path(data["file"]), tuple(data.get("scale", (1.0, 1.0, 1.0))))  # type: ignore[arg-type]
    raise InputError(f"'shape.type' must be box, cylinder, sphere or mesh (got {kind!r})")


def object_data(obj: SceneObject, exact: bool = False) -> dict[str, Any]:
    """One scene object: ``name``, ``shape``, ``pose`` (in the world, or in the frame of
    the link ``attached_to``), rounded to 1 µm for a viewer; with ``exact`` (a checkpoint:
    a resumed run plans from it) the numbers as they are, the links it may touch
    (``touch_links``) and a mesh's whole path."""
    data: dict[str, Any] = {"name": obj.name, "shape": shape_data(obj.shape, exact),
                            "pose": _pose(obj.pose, exact), "attached_to": obj.attached_to}
    if exact:
        data["touch_links"] = list(obj.touch_links)
    return data


def object_of(data: dict[str, Any]) -> SceneObject:
    """The scene object :func:`object_data` wrote."""
    pose = data["pose"]
    return SceneObject(data["name"], shape_of(data["shape"]),
                       Pose(tuple(pose["xyz"]), tuple(pose["quat"]),  # type: ignore[arg-type]
                            pose.get("frame", "world")),
                       data.get("attached_to"), tuple(data.get("touch_links", ())))


def scene_data(snapshot: SceneSnapshot) -> dict[str, Any]:
    """A scene as JSON: ``joints`` (every joint of the model, rad or m) and ``objects``."""
    return {
        "joints": {n: round(float(v), _POS_DIGITS)
                   for n, v in zip(snapshot.state.names, snapshot.state.positions)},
        "objects": [object_data(o) for o in snapshot.objects],
    }


def motion_data(trajectory: JointTrajectory, snapshot: SceneSnapshot) -> dict[str, Any]:
    """The data of a ``motion`` event: the ``trajectory``, the ``scene`` it starts in and,
    where an object is attached then, ``touch``: per attached object the bodies it may
    touch (its touch links, and the scene's allowances naming it), which the record's
    verifier allows as the run did (:func:`taskrunner.tree.expect.record_lanes`)."""
    data = {"trajectory": trajectory_data(trajectory), "scene": scene_data(snapshot)}
    touch = {o.name: sorted({*o.touch_links, *(b if a == o.name else a
                                               for a, b in snapshot.allowed if o.name in (a, b))})
             for o in snapshot.objects if o.attached}
    if touch:
        data["touch"] = touch
    return data


@dataclass(frozen=True)
class Motion:
    """One motion of a run as recorded: its node, the trajectory, the scene it started
    in, and how much of it ran (``executed``: seconds of trajectory, None if unknown)."""

    seq: int
    node: str | None
    location: str | None
    time: float
    trajectory: dict[str, Any]
    scene: dict[str, Any]
    executed: float | None


@dataclass(frozen=True)
class Replay:
    """The motions of a run in order, its first and final scenes."""

    motions: tuple[Motion, ...]
    first_scene: dict[str, Any] | None
    final_scene: dict[str, Any] | None


def replay_of(record: RunRecord) -> Replay:
    """The replay data of a record (runs recorded before motions were kept have none)."""
    motions: list[Motion] = []
    first = final = None
    pending: dict[str, int] = {}  # node -> index in motions of its motion still running
    for event in record.events:
        if event.kind == "run_started":
            first = event.data.get("scene")
        elif event.kind == "run_finished":
            final = event.data.get("scene")
        elif event.kind == "motion" and "trajectory" in event.data:
            pending[event.node or ""] = len(motions)
            motions.append(Motion(event.seq, event.node, event.location, event.time,
                                  event.data["trajectory"], event.data.get("scene") or {},
                                  None))
        elif event.kind == "node_finished" and (event.node or "") in pending:
            index = pending.pop(event.node or "")
            executed = event.data.get("executed")
            if isinstance(executed, dict) and executed.get("until") is not None:
                m = motions[index]
                motions[index] = Motion(m.seq, m.node, m.location, m.time, m.trajectory,
                                        m.scene, float(executed["until"]))
    return Replay(tuple(motions), first, final)
