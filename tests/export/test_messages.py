"""The exported messages' definitions and bytes against ROS 2 Humble's types (rosbags'
copy), and the timeline of a record built by hand: motions at once, a motion stopped
early, bad records."""

from __future__ import annotations

import pytest
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from taskrunner.errors import InputError
from taskrunner.export import rosmsg
from taskrunner.export.mcapfile import export_mcap
from taskrunner.export.timeline import TOPICS, record_messages
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.records import RunRecord

HUMBLE = get_typestore(Stores.ROS2_HUMBLE)


@pytest.mark.parametrize("kind", sorted({t.name: t for t in TOPICS.values()}.values(),
                                        key=lambda t: t.name), ids=lambda t: t.name)
def test_definitions_are_ros2_humbles(kind: rosmsg.MessageType) -> None:
    parsed = get_types_from_msg(kind.definition, kind.name)
    assert kind.name in parsed
    for name, (constants, fields) in parsed.items():
        if name.startswith(("moveit_msgs/", "object_recognition_msgs/")):
            continue  # not in rosbags' Humble store; test_mcap_export registers them
        assert fields == HUMBLE.fielddefs[name][1], name
        assert constants == HUMBLE.fielddefs[name][0], name


def test_bytes_decode_as_humble_types_with_every_field() -> None:
    state = HUMBLE.deserialize_cdr(rosmsg.encode_joint_state(
        1_700_000_000_123_456_789, ["Revolute 1", "j2"], [0.5, -1.25], [0.1, 0.0]),
        "sensor_msgs/msg/JointState")
    assert (state.header.stamp.sec, state.header.stamp.nanosec) == (1_700_000_000, 123_456_789)
    assert state.name == ["Revolute 1", "j2"] and list(state.position) == [0.5, -1.25]
    assert list(state.velocity) == [0.1, 0.0] and len(state.effort) == 0
    log = HUMBLE.deserialize_cdr(rosmsg.encode_log(rosmsg.LogLine(
        5, rosmsg.WARN, "pick cube: approach", "blocked", "task.yaml", "wait", 12)),
        "rcl_interfaces/msg/Log")
    assert (log.level, log.name, log.msg, log.file, log.function, log.line) == (
        30, "pick cube: approach", "blocked", "task.yaml", "wait", 12)
    array = HUMBLE.deserialize_cdr(rosmsg.encode_marker_array([
        rosmsg.Marker(1, "world", "", 0, action=rosmsg.DELETEALL),
        rosmsg.Marker(1, "tool0", "cube", 1, type=rosmsg.CYLINDER, xyz=(1, 2, 3),
                      quat=(0, 0, 1, 0), scale=(0.1, 0.1, 0.3))]),
        "visualization_msgs/msg/MarkerArray")
    cube = array.markers[1]
    assert (cube.header.frame_id, cube.type, cube.pose.position.z, cube.pose.orientation.z,
            cube.scale.z) == ("tool0", 3, 3.0, 1.0, 0.3)
    with pytest.raises(ValueError, match="NUL"):
        rosmsg.encode_string("a\x00b")


@pytest.fixture(scope="module")
def pair() -> Cell:
    return load_cell(resolve_cell("servo_arm_pair"))


def _motion(seq: int, node: str, joint: str, sent: float, values: list[float]) -> RunEvent:
    times = [0.1 * i for i in range(len(values))]
    return RunEvent(seq, 0.01 * seq, "motion", node, f"/t/task.yaml:{seq}", None, "",
                    {"start": sent, "sent": sent,
                     "trajectory": {"joints": [joint], "duration": times[-1], "times": times,
                                    "positions": [[v] for v in values],
                                    "velocities": [[0.0] for _ in values]}})


def _record(cell: Cell, *events: RunEvent) -> RunRecord:
    start = RunEvent(1, 0.0, "run_started", None, None, "running", "",
                     {"scene": {"joints": dict.fromkeys(cell.model.joint_names, 0.0),
                                "objects": []}})
    return RunRecord("r1", "t", "/t/task.yaml", cell.name, "mock", {},
                     started="2026-01-01T00:00:00+00:00", events=[start, *events])


def _states(cell: Cell, record: RunRecord) -> dict[float, dict[str, float]]:
    out = {}
    for message in record_messages(record, cell):
        if message.topic == "/joint_states":
            state = HUMBLE.deserialize_cdr(message.data, "sensor_msgs/msg/JointState")
            t = round((message.time_ns - 1_767_225_600 * 10**9) * 1e-9, 6)
            out[t] = dict(zip(state.name, state.position))
    return out


def test_motions_at_once_are_each_interpolated_at_every_sample(pair: Cell) -> None:
    left, right = "left_Revolute 1", "right_Revolute 1"
    record = _record(pair, _motion(2, "left go", left, 0.0, [0.0, 0.1, 0.2, 0.3]),
                     _motion(3, "right go", right, 0.05, [0.0, -0.2, -0.4]))
    states = _states(pair, record)
    # 0.15 s is a sample of the right arm's motion only: the left one's is interpolated
    assert states[0.15][left] == pytest.approx(0.15)
    assert states[0.15][right] == pytest.approx(-0.2)
    assert states[0.3][left] == pytest.approx(0.3) and states[0.3][right] == pytest.approx(-0.4)


def test_a_motion_stopped_early_ends_where_it_stopped(pair: Cell) -> None:
    joint = "left_Revolute 2"
    stopped = RunEvent(3, 0.05, "node_finished", "go", "/t/task.yaml:2", "INVALID", "",
                       {"executed": {"until": 0.15, "status": "cancelled"}})
    states = _states(pair, _record(pair, _motion(2, "go", joint, 0.0, [0.0, 0.1, 0.2, 0.3]),
                                   stopped))
    assert max(states) == pytest.approx(0.15)
    assert states[max(states)][joint] == pytest.approx(0.15)


def test_a_record_from_another_cell_is_refused_naming_the_joint(pair: Cell) -> None:
    record = _record(pair, _motion(2, "go", "panda_joint1", 0.0, [0.0, 0.1]))
    with pytest.raises(InputError, match="'panda_joint1' of the record is not a joint of "
                                         "cell 'servo_arm_pair'"):
        record_messages(record, pair)


def test_a_missing_record_is_an_input_error(tmp_path) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InputError, match="no such run record"):
        export_mcap(tmp_path / "nope.json", tmp_path / "out.mcap")
    assert not list(tmp_path.iterdir())  # nothing half written


def test_definitions_concatenate_each_dependency_once() -> None:
    text = rosmsg.MARKER_ARRAY.definition
    lines = text.splitlines()
    headers = [line for line in lines if line.startswith("MSG: ")]
    assert all(lines[lines.index(h) - 1] == "=" * 80 for h in headers)
    reference, _ = HUMBLE.generate_msgdef("visualization_msgs/msg/MarkerArray", ros_version=2)
    expected = {line.replace("/", "/msg/", 1) for line in reference.splitlines()
                if line.startswith("MSG: ")}
    assert len(headers) == len(set(headers)) and set(headers) == expected
