"""MCAP files of recorded runs: every message decodes with ROS 2 readers, and /tf gives
the links the poses our forward kinematics gives.

Two runs on the mock backend, one per robot: the servo arm's pick_place written by
``run-task --mcap`` during the run, the Panda's converted afterwards by ``run-task
export``. Each file is decoded by rosbags (its own CDR reader, the file's embedded
definitions, and again with its copy of ROS 2 Humble's types) and by mcap-ros2-support.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections import defaultdict
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin
import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbags.highlevel import AnyReader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from taskrunner.cli import main
from taskrunner.export import rosmsg
from taskrunner.export.mcapfile import cell_of_record
from taskrunner.kinematics import frame_pose
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import Cell
from taskrunner.runtime.records import RunRecord, load_record

TASKS = DATA_ROOT / "tasks"
HUMBLE = get_typestore(Stores.ROS2_HUMBLE)
# moveit_msgs is not in rosbags' Humble store: registered from our definition, which
# register() refuses if any type it uses differs from Humble's own.
HUMBLE.register(get_types_from_msg(rosmsg.DISPLAY_TRAJECTORY.definition,
                                   rosmsg.DISPLAY_TRAJECTORY.name))


class Exported:
    def __init__(self, record: RunRecord, mcap: Path) -> None:
        self.record = record
        self.mcap = mcap
        self.cell: Cell = cell_of_record(record)
        # topic -> [(log time ns, message)], decoded by rosbags from the embedded definitions
        self.messages: dict[str, list[tuple[int, Any]]] = defaultdict(list)
        with AnyReader([mcap]) as reader:
            for connection, stamp, raw in reader.messages():
                self.messages[connection.topic].append(
                    (stamp, reader.deserialize(raw, connection.msgtype)))


def _run_and_export(tmp: Path, task: str, during_run: bool) -> Exported:
    runs = tmp / "runs"
    out = tmp / f"{task}.mcap"
    args = ["run", str(TASKS / f"{task}.yaml"), "--in-process", "--plain", "--runs-dir", str(runs)]
    assert main([*args, "--mcap", str(out)] if during_run else args) == 0
    (record_path,) = runs.glob("*.json")
    if not during_run:
        assert main(["export", str(record_path), "--mcap", str(out)]) == 0
    return Exported(load_record(record_path), out)


@pytest.fixture(scope="module")
def servo(tmp_path_factory: pytest.TempPathFactory) -> Exported:
    return _run_and_export(tmp_path_factory.mktemp("servo"), "pick_place", during_run=True)


@pytest.fixture(scope="module")
def panda(tmp_path_factory: pytest.TempPathFactory) -> Exported:
    return _run_and_export(tmp_path_factory.mktemp("panda"), "pick_place_panda",
                           during_run=False)


@pytest.fixture(params=["servo", "panda"])
def exported(request: pytest.FixtureRequest) -> Exported:
    return request.getfixturevalue(request.param)


def test_every_message_decodes_with_two_ros2_readers_and_humble_types(exported: Exported) -> None:
    with open(exported.mcap, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        summary = reader.get_summary()
        assert summary is not None and summary.statistics is not None
        assert reader.get_header().profile == "ros2"
        decoded = sum(1 for _ in reader.iter_decoded_messages())
    assert decoded == summary.statistics.message_count
    assert sum(len(v) for v in exported.messages.values()) == decoded
    with AnyReader([exported.mcap]) as reader:
        types = {c.topic: c.msgtype for c in reader.connections}
        for connection, _, raw in reader.messages():  # the bytes as ROS 2 Humble reads them
            HUMBLE.deserialize_cdr(raw, connection.msgtype)
    assert types == {"/robot_description": "std_msgs/msg/String",
                     "/tf_static": "tf2_msgs/msg/TFMessage",
                     "/scene_objects": "visualization_msgs/msg/MarkerArray",
                     "/joint_states": "sensor_msgs/msg/JointState",
                     "/tf": "tf2_msgs/msg/TFMessage", "/rosout": "rcl_interfaces/msg/Log",
                     "/display_planned_path": "moveit_msgs/msg/DisplayTrajectory"}


def _se3(transform: Any) -> pin.SE3:
    t, r = transform.translation, transform.rotation
    return pin.SE3(pin.Quaternion(r.w, r.x, r.y, r.z).normalized().matrix(),
                   np.array([t.x, t.y, t.z]))


def test_tf_link_poses_equal_our_forward_kinematics(exported: Exported) -> None:
    model = exported.cell.model
    static = {t.child_frame_id: (t.header.frame_id, _se3(t.transform))
              for _, m in exported.messages["/tf_static"] for t in m.transforms}
    tfs = dict(exported.messages["/tf"])
    states = exported.messages["/joint_states"]
    assert len(states) == len(tfs) > 20
    links = [f.name for f in model.model.frames if f.type == pin.BODY]
    worst = 0.0
    for stamp, state in states:
        q = model.state_with(model.default_state(), dict(zip(state.name, state.position)))
        edges = dict(static)
        for t in tfs[stamp].transforms:
            assert t.header.stamp.sec * 10**9 + t.header.stamp.nanosec == stamp
            edges[t.child_frame_id] = (t.header.frame_id, _se3(t.transform))
        for link in links:
            pose, frame = pin.SE3.Identity(), link
            while frame in edges:  # up the tree to its root, the world
                parent, relative = edges[frame]
                pose, frame = relative * pose, parent
            assert frame == "world"
            expected = frame_pose(model, q, link)
            worst = max(worst, float(np.linalg.norm(pose.translation - expected.translation)))
            assert np.allclose(pose.rotation, expected.rotation, atol=1e-6), link
    assert worst < 1e-6


def test_robot_placements_and_fixed_joints_are_static(exported: Exported) -> None:
    (only,) = exported.messages["/tf_static"]
    static = {t.child_frame_id: t for t in only[1].transforms}
    urdf = ET.fromstring(exported.messages["/robot_description"][0][1].data)
    fixed = {j.find("child").get("link") for j in urdf.findall("joint")  # type: ignore[union-attr]
             if j.get("type") == "fixed"}
    assert set(static) == fixed
    for robot in exported.cell.model.instances:
        base = static[robot.prefix + ("base_link" if "servo" in str(robot.source) else
                                      "panda_link0")]
        assert base.header.frame_id == "world"
        assert np.allclose(_se3(base.transform).translation, robot.base.translation, atol=1e-9)
    for mesh in urdf.iter("mesh"):
        filename = mesh.get("filename", "")
        assert filename.startswith("file:///") and Path(filename[7:]).is_file(), filename


def test_each_motion_ends_where_its_trajectory_ends(exported: Exported) -> None:
    record = exported.record
    started = exported.messages["/joint_states"][0][0]
    by_time = {stamp - started: state for stamp, state in exported.messages["/joint_states"]}
    motions = [e for e in record.events if e.kind == "motion"]
    assert motions
    for event in motions:
        trajectory = event.data["trajectory"]
        end_ns = round((event.data["sent"] + trajectory["duration"]) * 1e9)
        state = by_time[min(by_time, key=lambda t: abs(t - end_ns))]
        values = dict(zip(state.name, state.position))
        for joint, value in zip(trajectory["joints"], trajectory["positions"][-1]):
            # The record keeps positions to 10 µrad and times to 0.1 ms: the next motion
            # may start a rounding (< 0.1 ms) before this one's recorded end.
            assert values[joint] == pytest.approx(value, abs=1e-5), (event.node, joint)


def test_events_are_logged_with_node_and_task_file_line(exported: Exported) -> None:
    logs = [m for _, m in exported.messages["/rosout"]]
    record = exported.record
    assert len(logs) == len(record.events)
    for log, event in zip(logs, record.events):
        assert log.function == event.kind
        assert log.name == (event.node or record.task)
        if event.location:
            assert f"{log.file}:{log.line}" == event.location
    assert logs[-1].msg == "succeeded" and logs[-1].level == 20


def test_the_picked_object_rides_on_a_link_while_carried(exported: Exported) -> None:
    frames = set()
    for _, array in exported.messages["/scene_objects"]:
        assert array.markers[0].action == 3  # DELETEALL first
        frames |= {m.header.frame_id for m in array.markers[1:] if m.ns == "cube"}
    assert "world" in frames
    assert frames - {"world"} <= set(exported.cell.model.link_names)
    assert len(frames) == 2  # the world, then the gripper's link


def _two_readers(mcap: Path, topic: str) -> list[tuple[Any, Any]]:
    """Each message of ``topic`` as rosbags and as mcap-ros2-support decode it."""
    with AnyReader([mcap]) as reader:
        first = [reader.deserialize(raw, c.msgtype) for c, _, raw in reader.messages()
                 if c.topic == topic]
    with open(mcap, "rb") as f:
        second = [m for _, _, _, m in make_reader(f, decoder_factories=[DecoderFactory()])
                  .iter_decoded_messages(topics=[topic])]
    return list(zip(first, second, strict=True))


def test_each_motion_is_a_display_trajectory_of_its_robot(exported: Exported) -> None:
    record, model = exported.record, exported.cell.model
    motions = [e for e in record.events if e.kind == "motion"]
    decoded = _two_readers(exported.mcap, "/display_planned_path")
    assert len(decoded) == len(motions) > 0
    stamps = [stamp for stamp, _ in exported.messages["/display_planned_path"]]
    base = exported.messages["/robot_description"][0][0]
    for event, stamp, pair in zip(motions, stamps, decoded, strict=True):
        trajectory = event.data["trajectory"]
        assert stamp - base == round(event.data["sent"] * 1e9)  # when it was sent
        for message in pair:
            (robot_trajectory,) = message.trajectory
            points = robot_trajectory.joint_trajectory.points
            assert list(robot_trajectory.joint_trajectory.joint_names) == trajectory["joints"]
            assert robot_trajectory.multi_dof_joint_trajectory.points == []
            assert [list(p.positions) for p in points] == trajectory["positions"]  # bit for bit
            assert [list(p.velocities) for p in points] == trajectory["velocities"]
            assert [p.time_from_start.sec * 10**9 + p.time_from_start.nanosec
                    for p in points] == [round(t * 1e9) for t in trajectory["times"]]
            start = message.trajectory_start
            assert not start.is_diff and list(start.joint_state.name) == list(model.joint_names)
            expected = event.data["scene"]["joints"]
            for name, value in zip(start.joint_state.name, start.joint_state.position):
                if name in expected:
                    assert value == expected[name], name
            assert np.allclose([expected.get(n, v) for n, v in zip(
                start.joint_state.name, start.joint_state.position)],
                start.joint_state.position)
            robot = model.instances[0] if len(model.instances) == 1 else next(
                i for i in model.instances if trajectory["joints"][0].startswith(i.prefix))
            assert message.model_id == robot.name


def test_the_cell_of_a_record_is_loaded_as_its_run_loaded_it(tmp_path: Path) -> None:
    from taskrunner.errors import InputError

    runs = tmp_path / "runs"
    assert main(["run", str(TASKS / "go_home.yaml"), "--backend", "mock", "--in-process",
                 "--plain", "--no-check", "--runs-dir", str(runs), "--collision",
                 "convex"]) == 0
    record = load_record(next(runs.glob("*.json")))
    assert record.load_options is not None and record.load_options["collision"] == "convex"
    assert cell_of_record(record).name == record.cell
    record.load_options = {"collision": "mesh"}  # read, so checked
    with pytest.raises(InputError, match=f"run {record.run_id}: its load_options: "
                                         "'collision' must be one of"):
        cell_of_record(record)
