"""The MuJoCo backend's physics report (:meth:`MujocoBackend.physics_report
<taskrunner.backends.physics.backend.MujocoBackend.physics_report>`): what the physics did
since the last report, JSON-ready, on the physics clock (s). The run's record keeps each as a
``physics`` event; the viewer and the MCAP export (:mod:`taskrunner.export.physics`) read it.
Units: m, rad, s.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from taskrunner.backends.base import TrajectoryExecution
from taskrunner.backends.execution import ExecutionStatus
from taskrunner.backends.physics.options import PhysicsSample
from taskrunner.types import Pose

__all__ = ["motion_entry", "physics_report_of"]

_REPORT_SAMPLES = 500  # at most this many samples in one physics_report (thinned evenly)
_REPORT_DECIMALS = 5  # 10 um, 1e-5 rad


def physics_report_of(samples: Sequence[PhysicsSample], grasps: list[dict[str, Any]],
                      motions: list[dict[str, Any]], period: float,
                      joints: Sequence[str]) -> dict[str, Any] | None:
    """The report of ``samples`` (oldest first, thinned evenly to at most 500), the welds
    made and released (``grasps``) and the motions ended (``motions``, each from
    :func:`motion_entry`) since the last one; ``period``: the samples' (s); ``joints``: the
    samples' joint names. None: nothing to report. The format is
    :meth:`~taskrunner.backends.physics.backend.MujocoBackend.physics_report`'s."""
    if not samples and not grasps and not motions:
        return None
    if len(samples) > _REPORT_SAMPLES:
        step = len(samples) / _REPORT_SAMPLES
        samples = [samples[int(k * step)] for k in range(_REPORT_SAMPLES - 1)] + [samples[-1]]
    names = sorted({name for sample in samples for name in sample.objects})
    r = _REPORT_DECIMALS

    def pose(p: Pose | None) -> list[float] | None:
        return None if p is None else [round(float(v), r) for v in (*p.xyz, *p.quat)]

    return {
        "period": period,
        "joints": list(joints),
        "t": [round(sample.time, 4) for sample in samples],
        "q": [[round(float(v), r) for v in sample.joints.positions] for sample in samples],
        "objects": {name: [pose(sample.objects.get(name)) for sample in samples]
                    for name in names},
        "grasps": grasps,
        "motions": motions,
    }


def motion_entry(execution: TrajectoryExecution, start: float, now: float,
                 status: ExecutionStatus) -> dict[str, Any]:
    """A motion's line of the report, as it ends at physics time ``now``: its joints and
    first sample (rad or m), the physics time it ``start``-ed at, its trajectory's seconds
    (``duration``), the seconds it settled after its trajectory's end (``settle``; None: it
    ended before) and its ``status``."""
    end = start + execution.duration
    r = _REPORT_DECIMALS
    return {
        "joints": list(execution.trajectory.names),
        "first": [round(float(v), r) for v in execution.trajectory.positions[0]],
        "start": round(start, 6), "duration": round(execution.duration, 6),
        "settle": round(now - end, 6) if now >= end - 1e-9 else None,
        "status": status}
