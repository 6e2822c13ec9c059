"""An MCAP file that cannot show the run as it was is an error naming what is missing,
unless degraded output is allowed (``--allow-degraded``, ``allow_degraded=True``): then
each degradation is said on stderr and on /rosout. Records built by hand."""

from __future__ import annotations

from pathlib import Path

import pytest
from rosbags.typesys import Stores, get_typestore

from taskrunner.cli import main
from taskrunner.errors import InputError, MissingMeshError
from taskrunner.export.mcapfile import export_mcap
from taskrunner.export.timeline import record_messages
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.records import RunRecord, save_record

HUMBLE = get_typestore(Stores.ROS2_HUMBLE)
_BRACKET: dict[str, object] = {"name": "bracket", "shape": {"type": "mesh", "file": "parts/bracket.stl"},
            "pose": {"frame": "world", "xyz": [0.1, 0.2, 0.8]}}


@pytest.fixture(scope="module")
def pair() -> Cell:
    return load_cell(resolve_cell("servo_arm_pair"))


def _record(cell: Cell, backend: str, objects: list[dict[str, object]]) -> RunRecord:
    joint = "left_Revolute 1"
    start = RunEvent(1, 0.0, "run_started", None, None, "running", "",
                     {"scene": {"joints": dict.fromkeys(cell.model.joint_names, 0.0),
                                "objects": objects}})
    motion = RunEvent(2, 0.01, "motion", "go home", "/t/task.yaml:7", None, "",
                      {"start": 0.0, "sent": 0.0,
                       "trajectory": {"joints": [joint], "duration": 0.2, "times": [0.0, 0.1, 0.2],
                                      "positions": [[0.0], [0.1], [0.2]],
                                      "velocities": [[0.0], [1.0], [0.0]]}})
    return RunRecord("r1", "t", "/t/task.yaml", cell.name, backend, {},
                     started="2026-01-01T00:00:00+00:00", events=[start, motion])


def _warnings(messages: list) -> list[str]:  # type: ignore[type-arg]
    logs = [HUMBLE.deserialize_cdr(m.data, "rcl_interfaces/msg/Log")
            for m in messages if m.topic == "/rosout"]
    return [log.msg for log in logs if log.level == 30]


def test_a_mujoco_motion_without_physics_is_an_error_naming_the_motion(pair: Cell) -> None:
    record = _record(pair, "mujoco", [])
    with pytest.raises(InputError, match=r"^runs/r1\.json: .*motion 'go home' \(event 2, "
                                         r"/t/task\.yaml:7\) has no physics report.*"
                                         r"--allow-degraded"):
        record_messages(record, pair, source="runs/r1.json")
    told: list[str] = []
    messages = record_messages(record, pair, allow_degraded=True, on_degraded=told.append)
    (said,) = told
    assert "run r1: " in said and "motion 'go home' (event 2" in said
    assert [w for w in _warnings(messages) if "motion 'go home' (event 2" in w]
    assert any(m.topic == "/joint_states" for m in messages)  # the trajectory sent, as allowed


def test_an_object_whose_mesh_is_not_found_is_an_error_naming_it_and_its_file(pair: Cell) -> None:
    record = _record(pair, "mock", [_BRACKET])
    with pytest.raises(MissingMeshError, match=r"object 'bracket' \(mesh\) not drawn: its mesh "
                                               r"file 'parts/bracket\.stl'.*/t/task\.yaml"):
        record_messages(record, pair)
    told: list[str] = []
    messages = record_messages(record, pair, allow_degraded=True, on_degraded=told.append)
    assert len(told) == 1 and "'bracket'" in told[0]  # said once, not at each scene
    assert len([w for w in _warnings(messages) if "'bracket'" in w]) == 1
    scenes = [HUMBLE.deserialize_cdr(m.data, "visualization_msgs/msg/MarkerArray")
              for m in messages if m.topic == "/scene_objects"]
    assert scenes and not [mk for s in scenes for mk in s.markers if mk.ns == "bracket"]
    # Objects that can be drawn give no degradation at all.
    told.clear()
    box: dict[str, object] = {"name": "box", "shape": {"type": "box", "size": [0.1, 0.1, 0.1]}, "pose": {}}
    assert _warnings(record_messages(_record(pair, "mock", [box]), pair,
                                     on_degraded=told.append)) == [] and told == []


def test_the_export_command_refuses_a_degraded_file_unless_allowed(
        pair: Cell, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = save_record(_record(pair, "mujoco", [_BRACKET]), tmp_path)
    out = tmp_path / "run.mcap"
    assert main(["export", str(path), "--mcap", str(out), "--cell", "servo_arm_pair"]) != 0
    err = capsys.readouterr().err
    assert f"{path}: " in err and "motion 'go home'" in err and "--allow-degraded" in err
    assert not out.exists()
    assert main(["export", str(path), "--mcap", str(out), "--cell", "servo_arm_pair",
                 "--allow-degraded"]) == 0
    err = capsys.readouterr().err
    assert "warning: degraded MCAP" in err and "motion 'go home'" in err and "'bracket'" in err
    assert out.stat().st_size > 0
    # The Python API: the same error, and the same opt-in.
    with pytest.raises(InputError, match="no physics report"):
        export_mcap(path, tmp_path / "api.mcap", pair)
    assert export_mcap(path, tmp_path / "api.mcap", pair, allow_degraded=True,
                       on_degraded=None).exists()


def test_a_runs_mcap_names_the_kept_record_when_degraded_and_not_allowed(
        pair: Cell, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from argparse import Namespace
    from types import SimpleNamespace

    from taskrunner.export.command import run_watches

    runner = SimpleNamespace(record=_record(pair, "mujoco", []), cell=pair,
                             options=SimpleNamespace(runs_dir=tmp_path))
    out = tmp_path / "run.mcap"
    (watch,) = run_watches(Namespace(mcap=str(out), foxglove=None))
    with pytest.raises(InputError, match=rf"the run ended \(its record: {tmp_path}/r1\.json\), "
                                         r"but its MCAP file was not written: .*'go home'"):
        with watch(runner):  # type: ignore[arg-type]
            pass
    assert not out.exists()
    (watch,) = run_watches(Namespace(mcap=str(out), foxglove=None, mcap_allow_degraded=True))
    with watch(runner):  # type: ignore[arg-type]
        pass
    assert out.exists() and "warning: degraded MCAP" in capsys.readouterr().err
