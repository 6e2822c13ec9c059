"""Matching a MuJoCo world started afresh to a run's scene: a new process resuming a run
(:mod:`taskrunner.runtime.resume`) puts every object where the scene has it and what the
scene holds back in its grip, checked as a motion checks a grip.

:meth:`MujocoBackend.match_scene <taskrunner.backends.physics.backend.MujocoBackend.match_scene>`
is the entry point; this module is its body, on the backend's state (under its lock,
between motions). Units: m, kg, rad, s, N.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from taskrunner.backends.physics.backend import _CHUNK
from taskrunner.errors import BackendError

if TYPE_CHECKING:
    from taskrunner.backends.physics.backend import MujocoBackend

__all__ = ["match_scene"]


def match_scene(backend: MujocoBackend, closed: Mapping[str, float] | None = None) -> list[str]:
    """Make a world started afresh the bound scene's (a new process resuming a run):
    every free object of the scene at rest where the scene has it, one the scene holds
    where its gripper holds it (its attachment pose, at the joints now). With objects
    held, the finger joints' targets become ``closed`` (rad or m: the grippers' closed
    poses) and the fingers close on them for ``settle`` s, the held objects' weight
    compensated; then ``settle`` s with their weight, and each grip is checked as a
    motion checks it (touched by a hand, within ``slip_distance`` and ``slip_angle``
    of where it was put).

    Returns:
        What was done, one line per object held (also in :attr:`MujocoBackend.notes`).

    Raises:
        BackendError: a motion runs, ``closed`` names a joint that is not a finger,
            or a held object is not held after (with the reason).
    """
    closed = closed or {}
    others = sorted(set(closed) - {n for n in backend._names if backend._finger[backend._index[n]]})
    if others:
        raise BackendError(f"match_scene: {', '.join(map(repr, others))} is no finger "
                           "joint of the cell")
    with backend._lock:
        if backend._executions:
            raise BackendError("match_scene: a motion runs; match the scene between motions")
        scene, model, data = backend._scene, backend._model, backend._data
        poses = {o.name: scene.object_pose(o.name) for o in (scene.objects if scene else ())
                 if o.name in backend._objects}
        held = [o.name for o in (scene.objects if scene else ())
                if o.attached_to is not None and o.name in backend._objects]
        backend._restore_objects(poses)
        for name in poses:  # at rest where it is put
            dof = model.jnt_dofadr[model.body_jntadr[backend._objects[name]]]
            data.qvel[dof:dof + 6] = 0.0
        said = [f"the simulated world's {len(poses)} objects put where the scene has them"]
        if not held:
            backend.notes.extend(said)
            return said
        for name, value in closed.items():
            backend._targets[backend._index[name]] = value
        backend._held.clear()  # held where it was put: the slip checks' reference
        backend._touched -= set(held)
        backend._bind_held()
        backend._apply_welds()
        bodies = [backend._objects[name] for name in held]
        chunks = max(1, math.ceil(backend._options.settle / (_CHUNK * model.opt.timestep)))
        weight = model.body_mass[bodies, None] * model.opt.gravity[None, :]  # N
        try:
            data.xfrc_applied[bodies, :3] = -weight  # at their centres of mass
            for k in range(2 * chunks):  # closing on them weightless, then holding them
                if k == chunks:
                    data.xfrc_applied[bodies, :3] = 0.0
                backend._step_chunk([])
                backend._targets[:] = backend._chunk_targets
        finally:
            data.xfrc_applied[bodies, :3] = 0.0
        backend._publish()
        failure = backend.failures.pop(0) if backend.failures else backend._slip()
        loose = [] if failure is not None else [
            n for n in held if n not in backend._touched and backend._held[n].weld is None]
        if loose:  # a weld holds without a touch; fingers do not
            failure = (f"object {loose[0]!r}, put back where the scene holds it, is not "
                       "touched by the hand after its fingers closed")
        if failure is not None:
            raise BackendError(failure)
        seconds = 2 * chunks * _CHUNK * model.opt.timestep
        for name in held:
            gap = float(np.linalg.norm(np.subtract(backend._object_poses[name].xyz,
                                                   poses[name].xyz)))
            said.append(f"{name!r} put back in the grip of {backend._held[name].link!r} and "
                        f"held: {1e3 * gap:.1f} mm from where it was put after "
                        f"{seconds:.2f} s of physics")
        backend.notes.extend(said)
        return said
