"""Collision geometry as a choice: exact meshes, convex hulls, or auto (hulls where tight,
meshes where a hull stands off the mesh or makes a named pose collide)."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import InputError, SceneError, StartInCollisionError, YamlError
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import JointGoal, PlanRequest
from taskrunner.robot import RobotModel, load_robot
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, SceneOptions, hullfit
from taskrunner.scene.linkgeometry import HULL, MESH, PRIMITIVE, plan_link_geometry
from taskrunner.shapes import Box
from taskrunner.types import Pose
from taskrunner.workcell import load_workcell


@pytest.fixture(autouse=True)
def _own_cache(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A cache folder of this module's own, and no choice from the environment."""
    folder = tmp_path_factory.getbasetemp() / "cache"
    monkeypatch.setenv("XDG_CACHE_HOME", str(folder))
    monkeypatch.delenv("TASKRUNNER_COLLISION", raising=False)
    return folder


# ----------------------------------------------------------------- a U and a plunger
def _box_triangles(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> list:
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = np.array([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)])
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    return [v[list(f)] for f in faces]


def _write_stl(path: Path, triangles: list) -> None:
    lines = ["solid u"]
    for tri in triangles:
        lines.append("facet normal 0 0 0\nouter loop")
        lines += [f"vertex {x:.6f} {y:.6f} {z:.6f}" for x, y, z in tri]
        lines.append("endloop\nendfacet")
    lines.append("endsolid u")
    path.write_text("\n".join(lines) + "\n")


def make_u_robot(folder: Path, collision: str | None = None) -> Path:
    """A fixed U (a concave mesh: its hull closes the notch) and a plunger that a prismatic
    joint lowers into the notch: pose 'in' is clear of the U, but inside its hull. The
    plunger hangs from a carriage of its own, so that it is not adjacent to the U."""
    folder.mkdir(parents=True, exist_ok=True)
    triangles = (_box_triangles((-0.1, -0.05, 0.0), (0.1, 0.05, 0.03))
                 + _box_triangles((-0.1, -0.05, 0.03), (-0.05, 0.05, 0.1))
                 + _box_triangles((0.05, -0.05, 0.03), (0.1, 0.05, 0.1)))
    _write_stl(folder / "u.stl", triangles)
    (folder / "u.urdf").write_text(f"""<?xml version="1.0"?>
<robot name="u">
  <link name="base_link">
    <collision><geometry><mesh filename="{folder / 'u.stl'}"/></geometry></collision>
  </link>
  <link name="carriage">
    <collision><origin xyz="0.3 0 0"/><geometry><box size="0.02 0.02 0.02"/></geometry></collision>
  </link>
  <link name="plunger">
    <collision><geometry><box size="0.06 0.06 0.04"/></geometry></collision>
  </link>
  <joint name="lift" type="prismatic">
    <parent link="base_link"/><child link="carriage"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 -1"/>
    <limit lower="0" upper="0.25" effort="1" velocity="1"/>
  </joint>
  <joint name="rod" type="fixed"><parent link="carriage"/><child link="plunger"/></joint>
</robot>
""")
    (folder / "u.srdf").write_text("""<?xml version="1.0"?>
<robot name="u">
  <group name="arm"><joint name="lift"/></group>
  <group_state name="up" group="arm"><joint name="lift" value="0"/></group_state>
  <group_state name="in" group="arm"><joint name="lift" value="0.23"/></group_state>
</robot>
""")
    manifest = "name: u\nurdf: u.urdf\nsrdf: u.srdf\n"
    if collision is not None:
        manifest += f"collision: {collision}\n"
    (folder / "robot.yaml").write_text(manifest)
    return folder


def _wheel_triangles(rim: int, radius: float = 0.1, half: float = 0.02) -> list:
    """A wheel (a flat cylinder) of ``rim`` vertices a side, its caps fans."""
    angle = np.linspace(0.0, 2.0 * np.pi, rim, endpoint=False)
    top = np.c_[radius * np.cos(angle), radius * np.sin(angle), np.full(rim, half)]
    bottom = top * [1.0, 1.0, -1.0]
    triangles = []
    for i in range(rim):
        j = (i + 1) % rim
        triangles += [[top[i], top[j], bottom[i]], [top[j], bottom[j], bottom[i]]]
    for i in range(1, rim - 1):
        triangles += [[top[0], top[i], top[i + 1]], [bottom[0], bottom[i + 1], bottom[i]]]
    return triangles


def test_a_hull_coal_refuses_is_an_error_of_ours_and_its_mesh_is_checked_as_it_is(
        tmp_path: Path) -> None:
    """coal's polytopes allow a vertex at most 255 neighbours; Qhull's triangulated caps of
    a wheel of 300 rim vertices give one more (example-robot-data's centauro wheels). The
    hull is refused with our error, not coal's RuntimeError from deep inside, and the link
    keeps its mesh whatever the collision choice; the scene checks it."""
    folder = tmp_path / "wheel"
    folder.mkdir()
    _write_stl(folder / "wheel.stl", _wheel_triangles(300))
    _write_stl(folder / "hub.stl", _wheel_triangles(64))
    (folder / "w.urdf").write_text(f"""<?xml version="1.0"?>
<robot name="w">
  <link name="base_link">
    <collision><geometry><mesh filename="{folder / 'hub.stl'}"/></geometry></collision>
  </link>
  <link name="wheel">
    <collision><geometry><mesh filename="{folder / 'wheel.stl'}"/></geometry></collision>
  </link>
  <joint name="spin" type="continuous">
    <parent link="base_link"/><child link="wheel"/><origin xyz="0 0 0.3"/><axis xyz="0 0 1"/>
  </joint>
</robot>
""")
    for choice in ("auto", "convex"):
        (folder / "robot.yaml").write_text(f"name: w\nurdf: w.urdf\ncollision: {choice}\n")
        robot = load_robot(folder)
        links = plan_link_geometry(robot).links
        assert links["wheel"].kind == MESH, choice
        assert links["wheel"].reason.startswith("no convex hull coal can use"), links["wheel"]
        assert links["base_link"].kind == HULL, choice  # 64 rim vertices: coal takes its hull
        scene = Scene(robot)
        assert not scene.in_collision(scene.state)
        scene.add_object("block", Box((0.05, 0.05, 0.05)), Pose((0.1, 0.0, 0.3)))
        assert scene.in_collision(scene.state)  # the wheel's rim reaches x = 0.1
    wheel = robot.collision_model.geometryObjects[1].geometry
    with pytest.raises(SceneError, match=r"coal cannot use the mesh's convex hull \(\d+ "
                                         r"vertices\): Too many neighbors"):
        hullfit.convex_hull(wheel)


def _kinds(robot: RobotModel, **kwargs: object) -> dict[str, str]:
    return {c.link: c.kind for c in plan_link_geometry(robot, **kwargs).links.values()}  # type: ignore[arg-type]


# ----------------------------------------------------------------- auto on real robots
def test_auto_keeps_the_ur5_meshes_whose_hulls_stand_centimetres_off(robots_dir: Path):
    ur5 = load_robot(robots_dir / "ur5")
    plan = plan_link_geometry(ur5)
    upper = plan.links["upper_arm_link"]
    assert upper.kind == MESH and upper.choice == "auto"
    assert upper.excess is not None and 0.03 < upper.excess < 0.045  # "up to 4 cm fatter"
    assert "hull up to" in upper.reason and "mm off the mesh" in upper.reason
    assert plan.links["forearm_link"].kind == MESH
    assert plan.links["ee_link"].kind == PRIMITIVE
    # With a tolerance past every excess, every mesh becomes a hull.
    assert set(_kinds(ur5, tolerance=0.1).values()) == {HULL, PRIMITIVE}


def test_auto_gives_the_panda_hulls_because_its_collision_meshes_are_convex(panda_model):
    plan = plan_link_geometry(panda_model)
    assert {plan.kind(f"panda_link{i}") for i in range(8)} == {HULL}
    assert all(c.excess is not None and c.excess < 0.001 for c in plan.links.values()
               if c.kind == HULL)
    assert plan.kind("panda_leftfinger") == PRIMITIVE


def test_exact_and_convex_are_taken_as_said(robots_dir: Path):
    ur5 = load_robot(robots_dir / "ur5")
    assert set(_kinds(ur5, collision="exact").values()) == {MESH, PRIMITIVE}
    assert set(_kinds(ur5, collision="convex").values()) == {HULL, PRIMITIVE}
    with pytest.raises(InputError, match="'collision' must be one of exact, convex, auto"):
        plan_link_geometry(ur5, collision="hulls")


# ----------------------------------------------------------------- the named-pose rule
def test_auto_keeps_a_mesh_where_a_named_pose_collides_only_as_hulls(tmp_path: Path):
    robot = load_robot(make_u_robot(tmp_path / "u"))
    assert not [w for w in robot.warnings if "self-collision" in w]  # meshes: 'in' is clear
    # The notch is 5 cm deep: the hull's excess alone keeps the mesh.
    plan = plan_link_geometry(robot)
    assert plan.links["base_link"].kind == MESH
    assert plan.links["base_link"].excess == pytest.approx(0.05, abs=0.005)
    # A tolerance that takes the hull: the named pose 'in' collides as hulls, so not.
    lenient = plan_link_geometry(robot, tolerance=1.0)
    assert lenient.links["base_link"].kind == MESH
    assert lenient.links["base_link"].reason == \
        "named pose 'in' collides as hulls (base_link–plunger), not as meshes"
    # convex is taken as said: the pose then collides, and planning says with what.
    scene = Scene(robot, SceneOptions(collision="convex"))
    q_in = robot.state_with(robot.default_state(), robot.named_state("arm", "in"))
    assert scene.in_collision(q_in)
    assert not Scene(robot, SceneOptions(collision="auto", hull_tolerance=1.0)).in_collision(q_in)
    assert not Scene(robot).in_collision(q_in)


def test_start_in_collision_names_the_geometry_it_was_checked_with(tmp_path: Path):
    robot = load_robot(make_u_robot(tmp_path / "u"))
    q_in = robot.state_with(robot.default_state(), robot.named_state("arm", "in"))
    request = PlanRequest("arm", (JointGoal({"lift": 0.0}),), start=q_in)
    with pytest.raises(StartInCollisionError) as info:
        MotionPlanner(Scene(robot, SceneOptions(collision="convex"))).plan(request)
    assert str(info.value).endswith("base_link–plunger (base_link: convex hull; plunger: primitive)")
    # An object where the plunger is: the link's geometry is named, the object's is its own.
    scene = Scene(robot, SceneOptions(collision="exact"))
    scene.add_object("nail", Box((0.02, 0.02, 0.02)), Pose((0.0, 0.0, 0.3)))
    q_up = robot.state_with(robot.default_state(), {"lift": 0.0})
    with pytest.raises(StartInCollisionError) as info:
        MotionPlanner(scene).plan(PlanRequest("arm", (JointGoal({"lift": 0.1}),), start=q_up))
    assert str(info.value).endswith("nail–plunger (primitive shapes)")
    assert scene.geometry_note([("base_link", "nail")]) == " (exact meshes)"
    assert scene.geometry_note([("nail", "table")]) == ""


# ----------------------------------------------------------------- where the choice is made
def test_robot_yaml_cell_and_load_workcell_choose_and_the_latest_word_wins(tmp_path: Path):
    folder = make_u_robot(tmp_path / "robots" / "u", collision="convex")
    robot = load_robot(folder)
    assert robot.instances[0].collision == "convex"
    assert Scene(robot).link_geometry.kind("base_link") == HULL
    cells = tmp_path / "cells"
    cells.mkdir()
    (cells / "u_cell.yaml").write_text(
        "name: u_cell\nrobots:\n  - {name: u, robot: robots/u, collision: exact}\n")
    cell = load_cell(cells / "u_cell.yaml")
    assert cell.model.instances[0].collision == "exact"
    workcell = load_workcell(cells / "u_cell.yaml", collision="auto")
    assert workcell.model.instances[0].collision == "auto"
    assert workcell.scene.link_geometry.links["base_link"].reason.startswith("hull up to 49 mm")
    with pytest.raises(InputError, match="'collision' names no robot of the cell: v"):
        load_workcell(cells / "u_cell.yaml", collision={"v": "exact"})


def test_the_load_options_choice_wins_over_the_files(tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch):
    from taskrunner.errors import ArgumentError
    from taskrunner.robot import LoadOptions

    folder = make_u_robot(tmp_path / "u", collision="convex")
    assert load_robot(folder, options=LoadOptions(collision="exact")).instances[0].collision \
        == "exact"
    # The variable is read where a program starts (LoadOptions.from_env), not by a loader.
    monkeypatch.setenv("TASKRUNNER_COLLISION", "exact")
    assert load_robot(folder).instances[0].collision == "convex"
    monkeypatch.setenv("TASKRUNNER_COLLISION", "bogus")
    with pytest.raises(ArgumentError,
                       match="'TASKRUNNER_COLLISION' must be one of exact, convex, auto"):
        LoadOptions.from_env()
    with pytest.raises(ArgumentError, match="'collision' must be one of exact, convex, auto"):
        LoadOptions(collision="bogus")  # type: ignore[arg-type]


def test_a_bad_collision_word_in_robot_yaml_is_reported_at_its_line(tmp_path: Path):
    folder = make_u_robot(tmp_path / "u", collision="hull")
    with pytest.raises(YamlError) as info:
        load_robot(folder)
    assert str(info.value) == (f"{folder / 'robot.yaml'}:4: 'collision' must be one of exact, "
                               "convex, auto (got 'hull')")


# ----------------------------------------------------------------- the measurement cache
def test_hull_excess_is_measured_once_and_read_back_from_the_cache_file(
        tmp_path: Path, _own_cache: Path, monkeypatch: pytest.MonkeyPatch):
    robot = load_robot(make_u_robot(tmp_path / "u"))
    mesh = robot.collision_model.geometryObjects[0].geometry
    first = hullfit.hull_excess([mesh])
    data = json.loads((_own_cache / "taskrunner" / hullfit.CACHE_FILE).read_text())
    assert pytest.approx(first[0]) in data.values()
    # A fresh process (no memory) reads the file instead of measuring.
    monkeypatch.setattr(hullfit, "_memory", {})
    monkeypatch.setattr(hullfit, "_disk_loaded", set())

    def no_measuring(*_: object) -> float:
        raise AssertionError("measured again")

    monkeypatch.setattr(hullfit, "measure_hull_excess", no_measuring)
    assert hullfit.hull_excess([mesh]) == first


def test_cli_info_lists_the_link_geometry_and_collision_overrides_it(tmp_path: Path, capsys):
    from taskrunner.cli import main

    folder = make_u_robot(tmp_path / "u")
    before = dict(os.environ)
    assert main(["info", str(folder)]) == 0
    out = capsys.readouterr().out
    assert "collision geometry (u auto):" in out
    assert "  exact meshes: base_link (hull up to 49 mm off the mesh)" in out
    assert "  primitive shapes: carriage, plunger" in out
    assert main(["info", str(folder), "--collision", "convex"]) == 0
    out = capsys.readouterr().out
    assert "collision geometry (u convex):" in out and "  convex hulls: base_link" in out
    assert dict(os.environ) == before  # the flag reached the loader as an argument


def test_run_task_check_names_the_geometry_of_a_target_in_collision(repo_root: Path):
    from taskrunner.tree.check import check_task

    path = repo_root / "tests" / "tree" / "fixtures" / "candle_blocked.yaml"
    (problem,) = check_task(path).problems
    assert problem.message.endswith("target in collision (gripper_base_1–lamp, "
                                    "lamp–wrist_link_1; primitive shapes)")


def test_collision_matrix_checks_the_geometry_it_is_told(tmp_path: Path, capsys):
    from taskrunner.scene.acm import main as collision_matrix

    folder = make_u_robot(tmp_path / "u")
    # The plunger reaches into the U's notch: as meshes they never touch, as a hull they do.
    assert collision_matrix([str(folder), "--samples", "200", "--collision", "exact"]) == 0
    exact = capsys.readouterr().out
    assert collision_matrix([str(folder), "--samples", "200", "--collision", "convex"]) == 0
    convex = capsys.readouterr().out
    pair = '<disable_collisions link1="base_link" link2="plunger" reason="Never"/>'
    assert pair in exact and pair not in convex
