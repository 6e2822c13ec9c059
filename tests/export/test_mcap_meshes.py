"""Objects of the task file with mesh shapes are drawn in the MCAP's /scene_objects: the
record names a mesh by its file name only, the export finds the file as the task loader
does (relative to the task file's folder)."""

from __future__ import annotations

import shutil
from pathlib import Path

from rosbags.highlevel import AnyReader

from taskrunner.cli import main
from taskrunner.export.timeline import record_meshes
from taskrunner.resources import resolve_cell
from taskrunner.runtime.records import RunRecord

FIXTURES = Path(__file__).parents[1] / "fixtures"
MESH_RESOURCE = 10  # visualization_msgs/Marker


def test_a_task_files_mesh_object_is_drawn_from_its_file(tmp_path: Path) -> None:
    folder = tmp_path / "task"
    (folder / "parts").mkdir(parents=True)
    shutil.copy(FIXTURES / "moveit_scenes" / "tetra.stl", folder / "parts" / "tetra.stl")
    (folder / "with_mesh.yaml").write_text(f"""
task: with_mesh
cell: {resolve_cell("servo_arm_table")}
objects:
  - name: bracket
    shape: mesh
    file: parts/tetra.stl
    scale: [0.5, 0.5, 2.0]
    pose: {{xyz: [0.8, 0.8, 0.6]}}
steps:
  - go: {{group: arm, to: Candle}}
""")
    runs, out = tmp_path / "runs", tmp_path / "with_mesh.mcap"
    assert main(["run", str(folder / "with_mesh.yaml"), "--in-process", "--plain",
                 "--runs-dir", str(runs)]) == 0
    (record_path,) = runs.glob("*.json")
    assert main(["export", str(record_path), "--mcap", str(out)]) == 0
    arrays, warnings = [], []
    with AnyReader([out]) as reader:
        for connection, _, raw in reader.messages():
            message = reader.deserialize(raw, connection.msgtype)
            if connection.topic == "/scene_objects":
                arrays.append(message)
            elif connection.topic == "/rosout" and message.level >= 30:
                warnings.append(message.msg)
    assert arrays and not [w for w in warnings if "not drawn" in w]
    for array in arrays:
        (marker,) = [m for m in array.markers if m.ns == "bracket"]
        assert marker.type == MESH_RESOURCE
        assert marker.mesh_resource == (folder / "parts" / "tetra.stl").resolve().as_uri()
        assert (marker.scale.x, marker.scale.y, marker.scale.z) == (0.5, 0.5, 2.0)
        assert (marker.pose.position.x, marker.pose.position.y) == (0.8, 0.8)


def test_a_record_without_its_task_text_says_why_no_mesh_is_found(tmp_path: Path) -> None:
    record = RunRecord(run_id="r", task="t", task_file="", cell="c", backend="mock",
                       parameters={})
    assert record_meshes(record) == ({}, "the record keeps no task text")
    record.task_text, record.task_file = "task: [", str(tmp_path / "broken.yaml")
    meshes, why = record_meshes(record)
    assert meshes == {} and why is not None and why.startswith("its task text does not load here")
