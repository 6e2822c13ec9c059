"""A mujoco run whose two arms move at once exports without degradation: every
/joint_states message after the start is one physics sample of the whole cell, and /tf
is our forward kinematics of it; every motion's physics start is the one the physics
reports list, none fitted. A record made before the reports listed them (the same run
with the list taken out) still exports, the start it must fit called a degradation."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin
import pytest
from rosbags.highlevel import AnyReader

from taskrunner.cli import main
from taskrunner.errors import InputError
from taskrunner.export.mcapfile import cell_of_record
from taskrunner.export.physics import SentMotion, physics_path
from taskrunner.export.timeline import record_messages
from taskrunner.kinematics import frame_pose
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.records import RunRecord, load_record

TASK = Path(__file__).parent / "fixtures" / "two_arms_at_once.yaml"


def _se3(transform: Any) -> pin.SE3:
    t, r = transform.translation, transform.rotation
    return pin.SE3(pin.Quaternion(r.w, r.x, r.y, r.z).normalized().matrix(),
                   np.array([t.x, t.y, t.z]))


class Overlapped:
    def __init__(self, record: RunRecord, mcap: Path) -> None:
        self.record = record
        self.mcap = mcap
        self.messages: dict[str, list[tuple[int, Any]]] = {}
        with AnyReader([mcap]) as reader:
            for connection, stamp, raw in reader.messages():
                self.messages.setdefault(connection.topic, []).append(
                    (stamp, reader.deserialize(raw, connection.msgtype)))


@pytest.fixture(scope="module")
def overlapped(tmp_path_factory: pytest.TempPathFactory) -> Overlapped:
    tmp = tmp_path_factory.mktemp("overlap")
    runs, out = tmp / "runs", tmp / "run.mcap"
    # Without --mcap-allow-degraded: the export must not need it.
    assert main(["run", str(TASK), "--backend", "mujoco", "--in-process", "--plain",
                 "--runs-dir", str(runs), "--mcap", str(out)]) == 0
    return Overlapped(load_record(next(runs.glob("*.json"))), out)


def test_the_runs_motions_overlap_in_time(overlapped: Overlapped) -> None:
    motions = sorted((e.data["sent"], e.data["sent"] + e.data["trajectory"]["duration"],
                      e.data["trajectory"]["joints"][0][:5])
                     for e in overlapped.record.events if e.kind == "motion")
    assert len(motions) == 3
    (a0, a1, arm_a), (b0, _, arm_b) = motions[0], motions[1]
    # The second arm starts while the first moves (at once, when the tree sent it before
    # the physics stepped).
    assert arm_a != arm_b and a0 <= b0 < a1


def test_every_joint_state_is_a_physics_sample_and_tf_is_its_fk(overlapped: Overlapped) -> None:
    record, messages = overlapped.record, overlapped.messages
    assert not [m.msg for _, m in messages["/rosout"] if m.level >= 30]
    model = cell_of_record(record).model
    reports = [e.data for e in record.events if e.kind == "physics"]
    joints = reports[0]["joints"]
    samples = np.concatenate([np.array(r["q"]) for r in reports])
    states = messages["/joint_states"]
    assert len(states) > 0.8 * len(samples)
    names = list(states[0][1].name)
    columns = [names.index(j) for j in joints]
    static = {t.child_frame_id: (t.header.frame_id, _se3(t.transform))
              for _, m in messages["/tf_static"] for t in m.transforms}
    tfs = dict(messages["/tf"])
    links = [f.name for f in model.model.frames if f.type == pin.BODY]
    worst, last = 0.0, -1
    for stamp, state in states[1:]:  # the first: the run's start state, before any motion
        assert list(state.velocity) == []
        q = np.array(state.position)[columns]
        matches = np.flatnonzero(np.all(samples == q, axis=1))  # bit for bit
        assert matches.size, f"joint state at {stamp} is no physics sample"
        assert matches.max() >= last  # in the physics' order (a settled arm repeats)
        last = int(matches.max())
        qs = model.state_with(model.default_state(), dict(zip(joints, q)))
        edges = dict(static)
        for tf in tfs[stamp].transforms:
            edges[tf.child_frame_id] = (tf.header.frame_id, _se3(tf.transform))
        for link in links:
            pose, frame = pin.SE3.Identity(), link
            while frame in edges:
                parent, relative = edges[frame]
                pose, frame = relative * pose, parent
            expected = frame_pose(model, qs, link)
            worst = max(worst, float(np.linalg.norm(pose.translation - expected.translation)))
    assert worst < 1e-6
    # Both arms move between two consecutive messages somewhere: they are shown at once.
    positions = np.array([s.position for _, s in states])
    moving = np.abs(np.diff(positions, axis=0)) > 1e-4
    left = [i for i, n in enumerate(names) if n.startswith("left_")]
    right = [i for i, n in enumerate(names) if n.startswith("right_")]
    assert (moving[:, left].any(axis=1) & moving[:, right].any(axis=1)).any()


def test_each_arms_motion_is_a_display_trajectory_of_that_arm(overlapped: Overlapped) -> None:
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    motions = [e for e in overlapped.record.events if e.kind == "motion"]
    with open(overlapped.mcap, "rb") as f:
        second = [m for _, _, _, m in make_reader(f, decoder_factories=[DecoderFactory()])
                  .iter_decoded_messages(topics=["/display_planned_path"])]
    first = [m for _, m in overlapped.messages["/display_planned_path"]]
    assert len(first) == len(second) == len(motions) == 3
    for event, *decoded in zip(motions, first, second, strict=True):
        trajectory = event.data["trajectory"]
        for message in decoded:
            assert message.model_id == trajectory["joints"][0].split("_")[0]  # left / right
            points = message.trajectory[0].joint_trajectory.points
            assert list(message.trajectory[0].joint_trajectory.joint_names) == \
                trajectory["joints"]
            assert [list(p.positions) for p in points] == trajectory["positions"]
            assert [p.time_from_start.sec * 10**9 + p.time_from_start.nanosec
                    for p in points] == [round(t * 1e9) for t in trajectory["times"]]


def _sent(record: RunRecord) -> list[SentMotion]:
    motions = []
    for event in record.events:
        if event.kind == "motion":
            trajectory = event.data["trajectory"]
            times = np.array(trajectory["times"])
            motions.append(SentMotion(event.seq, event.data["sent"],
                                      tuple(trajectory["joints"]), times,
                                      np.array(trajectory["positions"]), float(times[-1])))
    return motions


def _without_listed_motions(record: RunRecord) -> RunRecord:
    """The record as the physics reports were before they listed the motions."""
    events = [replace(e, data={k: v for k, v in e.data.items() if k != "motions"})
              if e.kind == "physics" else e for e in record.events]
    return replace(record, events=events)


def _physics(record: RunRecord) -> list[RunEvent]:
    return [e for e in record.events if e.kind == "physics"]


def test_every_motions_physics_start_is_reported_not_fitted(overlapped: Overlapped) -> None:
    record = overlapped.record
    sent = _sent(record)
    listed = sorted((m["start"], m["joints"], m["settle"])
                    for e in _physics(record) for m in e.data["motions"])
    assert len(listed) == len(sent) == 3
    assert all(settle is not None and settle > 0 for *_, settle in listed)
    path = physics_path(sent, _physics(record))
    assert not isinstance(path, str)
    assert path.how == ("reported",) * 3 and path.estimated == ()
    by_seq = sorted(range(len(sent)), key=lambda k: sent[k].seq)
    assert [path.starts[k] for k in by_seq] == [start for start, *_ in listed]
    assert [list(sent[k].joints) for k in by_seq] == [joints for _, joints, _ in listed]


def test_an_older_record_exports_an_estimated_start_only_as_degraded(
        overlapped: Overlapped) -> None:
    # Without the list, the right arm's motion is placed after the left arm's first one,
    # running when it was sent; the left arm's second one after the right arm's, or
    # fitted while it settles, as fast as the physics ran beside the tree. Estimates,
    # each said, and nothing else.
    record, older = overlapped.record, _without_listed_motions(overlapped.record)
    sent = _sent(record)
    new, old = physics_path(sent, _physics(record)), physics_path(sent, _physics(older))
    assert not isinstance(new, str) and not isinstance(old, str)
    assert old.how[:2] == ("paused", "running") and old.how[2] in ("running", "fitted")
    assert old.starts[0] == new.starts[0] == 0.0  # exact: nothing ran before it
    if old.how[2] == "fitted":
        assert abs(old.starts[2] - new.starts[2]) < 0.05
    cell = cell_of_record(record)
    with pytest.raises(InputError, match=r"(?s)is estimated.*--allow-degraded"):
        record_messages(older, cell)
    told: list[str] = []
    messages = record_messages(older, cell, allow_degraded=True, on_degraded=told.append)
    assert len(told) == 2
    assert f"event {sent[1].seq}" in told[0] and f"event {sent[2].seq}" in told[1]
    assert any(m.topic == "/rosout" and b"is estimated" in m.data for m in messages)
