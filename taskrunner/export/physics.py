"""A mujoco run's physics samples put on the run's task time, for ``/joint_states``.

The record's ``physics`` events (one when each motion's node ends) hold every joint of
the cell every ``period`` s of physics time ``p`` since the report before: together
they are one stream of samples, whichever motions ran at once. What places a sample on
task time ``t`` (:mod:`taskrunner.tree.clock`) is where each motion started on both
clocks, ``(p0, t0)``; ``t0`` is its ``sent`` time, and ``p0`` is the physics time the
backend reports it started at: each report lists the motions that ended since the one
before (``motions``: joints, first sample, ``start``), and a motion is the first listed,
in order of start, with its joints and first sample (within ``_SAME_SAMPLE``) not
started before the motion sent before it. Records made before the reports listed
motions have no such start; ``p0`` is then found from the other motions:

* **nothing ran when it was sent** (every motion sent before it had its physics report
  already): the world was paused since the last sample reported, so ``p0`` is that
  sample's time (0 for the run's first motion, or one ``period`` before its first sample
  if later);
* **another motion's trajectory was running** at ``t0``: if task time ran with that
  motion's progress, which is physics time, ``p0 = p0' + (t0 - t0')``; but it stands
  still while any motion settles, so this is an estimate (a two-arm run measured
  0.24 s early);
* **only settling motions ran** (after a trajectory's end the physics settles the world
  before the motion ends, and task time stands still meanwhile): ``p0`` lies between the
  last trajectory's end and the last sample; it is the start that fits the motion's
  joints to its trajectory best (least squares, on a 0.5 ms grid): an estimate too.

:attr:`PhysicsPath.how` tells, per motion, which of these placed it; the export calls
the estimates (:attr:`PhysicsPath.estimated`) a degradation.

Between two motion starts ``a`` and ``b`` (by ``p0``) a sample at ``p`` goes to
``t = t0_a + (p - p0_a)``; samples whose ``t`` would reach ``t0_b`` while ``p < p0_b`` are
the settling while task time stood still, and are left out. After the last start, the
samples run on to the end. Every sample kept is one physics state of the whole cell,
so two arms are shown as the physics had them at the same moment.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from taskrunner.errors import InputError
from taskrunner.runtime.events import RunEvent

__all__ = ["PhysicsPath", "SentMotion", "physics_path"]

_FIT_STEP = 5e-4   # s: the grid a start is fitted on
_FIT_BEFORE = 0.1  # s before a fitted start whose samples must hold still at its start
_SAME_SAMPLE = 1e-4  # rad or m: a reported first sample is the motion's (both are rounded)


@dataclass(frozen=True)
class SentMotion:
    """A motion as the record has it: sent at ``t0`` s of task time (event ``seq``),
    its trajectory (``times`` from 0, one row of ``positions`` per time) executed for
    ``until`` s."""

    seq: int
    t0: float
    joints: tuple[str, ...]
    times: np.ndarray
    positions: np.ndarray
    until: float
    name: str = ""


@dataclass(frozen=True)
class PhysicsPath:
    """The physics samples kept, on task time: ``times`` (s, strictly increasing) and
    ``positions`` (one row per time, columns ``joints``, rad or m); ``starts``: each
    motion's physics start ``p0`` (s), in the order given; ``how``: per motion, what
    gave its start (module docstring): "reported", "paused" (both exact), "running"
    or "fitted" (estimates)."""

    joints: tuple[str, ...]
    times: np.ndarray
    positions: np.ndarray
    starts: tuple[float, ...]
    how: tuple[str, ...]

    @property
    def estimated(self) -> tuple[int, ...]:
        """The motions (indices) whose start is an estimate, not exact."""
        return tuple(k for k, how in enumerate(self.how) if how in ("running", "fitted"))


def _reported_starts(motions: Sequence[SentMotion], reports: Sequence[RunEvent]
                     ) -> dict[int, float]:
    """Each motion's physics start as the reports list it (by index in ``motions``;
    motions the reports do not list are left out)."""
    listed: list[tuple[float, tuple[str, ...], np.ndarray]] = []
    for report in reports:
        for entry in report.data.get("motions") or ():
            try:
                listed.append((float(entry["start"]), tuple(str(j) for j in entry["joints"]),
                               np.asarray(entry["first"], dtype=float)))
            except (KeyError, TypeError, ValueError) as exc:
                raise InputError(f"event {report.seq} (physics of {report.node!r}): each of "
                                 f"its motions must have start, joints and first ({exc})"
                                 ) from None
    listed.sort(key=lambda item: item[0])
    used: set[int] = set()
    found: dict[int, float] = {}
    earliest = -np.inf
    for k in sorted(range(len(motions)), key=lambda k: motions[k].seq):
        motion = motions[k]
        first = motion.positions[0] if len(motion.positions) else np.zeros(0)
        for i, (start, joints, reported) in enumerate(listed):
            if (i in used or start < earliest - 1e-9 or joints != motion.joints
                    or reported.shape != first.shape
                    or not np.all(np.abs(reported - first) <= _SAME_SAMPLE)):
                continue
            used.add(i)
            found[k] = earliest = start
            break
    return found


def _samples(reports: Sequence[RunEvent]) -> tuple[tuple[str, ...], np.ndarray, np.ndarray,
                                                    float, list[float]]:
    """All reports' samples in physics-time order; also each report's last sample time."""
    joints: tuple[str, ...] | None = None
    ps, qs, ends, period = [], [], [], 0.0
    for report in reports:
        data = report.data
        try:
            names = tuple(str(j) for j in data["joints"])
            p = np.asarray(data["t"], dtype=float)
            q = np.asarray(data["q"], dtype=float).reshape(len(p), len(names))
            period = float(data["period"])
        except (KeyError, TypeError, ValueError) as exc:
            raise InputError(f"event {report.seq} (physics of {report.node!r}): it must have "
                             f"joints, t, q and period ({exc})") from None
        if joints is not None and names != joints:
            raise InputError(f"event {report.seq} (physics of {report.node!r}): its joints "
                             f"{list(names)} are not those of the reports before {list(joints)}")
        joints = names
        ps.append(p)
        qs.append(q)
        ends.append(float(p[-1]) if len(p) else -np.inf)
    assert joints is not None
    p_all, q_all = np.concatenate(ps), np.concatenate(qs)
    order = np.argsort(p_all, kind="stable")
    p_all, q_all = p_all[order], q_all[order]
    keep = np.append(True, np.diff(p_all) > 0)
    return joints, p_all[keep], q_all[keep], period, ends


def _fit_start(motion: SentMotion, columns: list[int], p: np.ndarray, q: np.ndarray,
               low: float, high: float) -> float:
    """The physics start in [low, high] at which ``motion``'s trajectory best fits the
    samples of its joints (mean squared error over its run and the moment before)."""
    grid = np.arange(low, max(low, high) + _FIT_STEP / 2, _FIT_STEP)
    measured = q[:, columns]
    best, best_error = low, np.inf
    for p0 in grid:
        window = (p >= p0 - _FIT_BEFORE) & (p <= p0 + motion.until)
        if not window.any():
            continue
        s = np.clip(p[window] - p0, 0.0, motion.until)
        planned = np.column_stack([np.interp(s, motion.times, motion.positions[:, j])
                                   for j in range(len(motion.joints))])
        error = float(np.mean((measured[window] - planned) ** 2))
        if error < best_error:
            best, best_error = float(p0), error
    return best


def physics_path(motions: Sequence[SentMotion], reports: Sequence[RunEvent]
                 ) -> PhysicsPath | str:
    """The samples of ``reports`` on task time (module docstring), or why they cannot
    be (a motion no sample covers).

    Raises:
        InputError: a report without joints, t, q and period, or with other joints.
    """
    reports = sorted(reports, key=lambda r: r.seq)
    joints, p, q, period, ends = _samples(reports)
    if len(p) == 0:
        return "the physics reports hold no samples"
    index = {name: i for i, name in enumerate(joints)}
    unknown = [j for m in motions for j in m.joints if j not in index]
    if unknown:
        return f"joint {unknown[0]!r} moved by a motion is not in the physics reports"
    starts = _reported_starts(motions, reports)
    how = {k: "reported" for k in starts}
    by_seq = sorted(range(len(motions)), key=lambda k: motions[k].seq)
    for position, k in enumerate(by_seq):
        motion, earlier = motions[k], by_seq[:position]
        if k in starts:
            continue
        reported = [end for r, end in zip(reports, ends, strict=True) if r.seq < motion.seq]
        if len(reported) >= len(earlier):  # every earlier motion's report came before
            starts[k] = max(reported) if reported else max(0.0, float(p[0]) - period)
            how[k] = "paused"
            continue
        running = [j for j in earlier
                   if motions[j].t0 <= motion.t0 < motions[j].t0 + motions[j].until]
        if running:
            j = max(running, key=lambda i: motions[i].t0)
            starts[k] = starts[j] + motion.t0 - motions[j].t0
            how[k] = "running"
            continue
        ended = max(starts[j] + motions[j].until for j in earlier)
        starts[k] = _fit_start(motion, [index[name] for name in motion.joints], p, q,
                               ended, float(p[-1]) - motion.until)
        how[k] = "fitted"
    anchors = sorted((starts[k], motions[k].t0) for k in range(len(motions)))
    times: list[float] = []
    kept: list[int] = []
    a = 0
    for i, sample in enumerate(p):
        while a + 1 < len(anchors) and sample >= anchors[a + 1][0] - 1e-9:
            a += 1
        p0, t0 = anchors[a]
        if sample < p0 - 1e-9:
            continue
        t = t0 + (sample - p0)
        if a + 1 < len(anchors) and t >= anchors[a + 1][1] - 1e-9:
            continue  # settling while task time stood still
        if times and t <= times[-1] + 1e-9:
            continue
        times.append(t)
        kept.append(i)
    for k, motion in enumerate(motions):
        covered = (p >= starts[k] - 1e-9) & (p <= starts[k] + motion.until + period)
        if not covered.any():
            return (f"{motion.name or f'the motion of event {motion.seq}'} has no physics "
                    "sample")
    return PhysicsPath(joints, np.asarray(times), q[kept],
                       tuple(starts[k] for k in range(len(motions))),
                       tuple(how[k] for k in range(len(motions))))
