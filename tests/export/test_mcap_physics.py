"""A mujoco run's MCAP: /joint_states are the physics' own samples (the record's
``physics`` events), put on task time, and /tf is our forward kinematics of them."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin
from rosbags.highlevel import AnyReader

from taskrunner.cli import main
from taskrunner.export.mcapfile import cell_of_record
from taskrunner.kinematics import frame_pose
from taskrunner.resources import DATA_ROOT
from taskrunner.runtime.records import load_record


def _se3(transform: Any) -> pin.SE3:
    t, r = transform.translation, transform.rotation
    return pin.SE3(pin.Quaternion(r.w, r.x, r.y, r.z).normalized().matrix(),
                   np.array([t.x, t.y, t.z]))


def test_a_mujoco_runs_joint_states_are_the_physics_samples(tmp_path: Path) -> None:
    runs, out = tmp_path / "runs", tmp_path / "go_home.mcap"
    assert main(["run", str(DATA_ROOT / "tasks" / "go_home.yaml"), "--backend", "mujoco",
                 "--in-process", "--plain", "--runs-dir", str(runs), "--mcap", str(out)]) == 0
    record = load_record(next(runs.glob("*.json")))
    model = cell_of_record(record).model
    messages: dict[str, list[tuple[int, Any]]] = {}
    with AnyReader([out]) as reader:
        for connection, stamp, raw in reader.messages():
            messages.setdefault(connection.topic, []).append(
                (stamp, reader.deserialize(raw, connection.msgtype)))
    assert not [m.msg for _, m in messages["/rosout"] if "not the physics" in m.msg]
    states = messages["/joint_states"]
    names = list(states[0][1].name)
    base = states[0][0]
    motions = [e for e in record.events if e.kind == "motion"]
    reports = [e for e in record.events if e.kind == "physics"]
    assert len(reports) == len(motions) == 2
    static = {t.child_frame_id: (t.header.frame_id, _se3(t.transform))
              for _, m in messages["/tf_static"] for t in m.transforms}
    tfs = dict(messages["/tf"])
    links = [f.name for f in model.model.frames if f.type == pin.BODY]
    worst, at = 0.0, 0
    for n, (motion, report) in enumerate(zip(motions, reports, strict=True)):
        columns = [names.index(j) for j in report.data["joints"]]
        t, q = np.array(report.data["t"]), np.array(report.data["q"])
        found = []  # (index of the sample, its message)
        for i, sample in enumerate(q):
            # Each in a message of its own, in order, spaced on task time as the samples
            # on the physics clock. The settling that the next motion's start cuts off is
            # left out: an arm at rest can equal the next motion's first samples to the
            # last bit, so a later message with its positions is not this sample's.
            match = next((k for k in range(at, len(states)) if np.allclose(
                np.array(states[k][1].position)[columns], sample, rtol=0, atol=1e-12)), None)
            if match is None or (found and abs((states[match][0] - found[-1][1][0]) / 1e9
                                               - (t[i] - t[i - 1])) > 2e-9):
                break
            found.append((i, states[match]))
            at = match + 1
        # Every sample, but the settling that the next motion's start cuts off.
        assert len(found) == len(t) if n == len(motions) - 1 else len(found) >= 0.8 * len(t)
        # On task time: the first one period at most after the motion was sent.
        stamps = np.array([stamp for _, (stamp, _) in found])
        first = (stamps[0] - base) / 1e9 - motion.data["sent"]
        assert 0 < first <= report.data["period"] + 1e-6
        for i, (stamp, state) in found:
            assert list(state.velocity) == []  # the physics reports none
            qs = model.state_with(model.default_state(), dict(zip(report.data["joints"], q[i])))
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
