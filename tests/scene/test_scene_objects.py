"""Adding, moving, attaching and removing scene objects; snapshots and copies."""

from __future__ import annotations

import pickle
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import MissingMeshError, SceneError, UnknownNameError
from taskrunner.robot import RobotModel
from taskrunner.scene import Scene, SceneObject
from taskrunner.shapes import Box, Cylinder, Mesh, Sphere
from taskrunner.types import Pose, pose_from_xyz_rpy

ArmState = Callable[..., np.ndarray]
FINGERS = ("panda_leftfinger", "panda_rightfinger")
TCP = "panda_hand_tcp"


def pairs(scene: Scene, q: np.ndarray | None = None) -> set[tuple[str, str]]:
    return {(c.a, c.b) for c in scene.collisions(q)}


def assert_same_pose(a: Pose, b: Pose) -> None:
    assert a.frame == b.frame
    np.testing.assert_allclose(a.se3.homogeneous, b.se3.homogeneous, atol=1e-9)


def write_cube_stl(path: Path, half: float) -> Path:
    """An ASCII STL of a cube of side ``2 * half`` m centred on its origin."""
    signs = (-half, half)
    corners = np.array([[x, y, z] for x in signs for y in signs for z in signs])
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    lines = ["solid cube"]
    for a, b, c, d in faces:
        for tri in ((a, b, c), (a, c, d)):
            lines.append("facet normal 0 0 0\nouter loop")
            lines += [f"vertex {x} {y} {z}" for x, y, z in corners[list(tri)]]
            lines.append("endloop\nendfacet")
    lines.append("endsolid cube")
    path.write_text("\n".join(lines) + "\n")
    return path


# ------------------------------------------------------------------ adding and frames
def test_pose_relative_to_a_link_is_taken_at_the_current_state(
    empty_scene: Scene, arm: ArmState
) -> None:
    obj = empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.0, 0.0, 0.1), frame=TCP))
    assert obj.pose.frame == "world" and not obj.attached
    expected = Pose.from_se3(empty_scene.link_pose(TCP).se3 * Pose((0.0, 0.0, 0.1)).se3)
    assert_same_pose(empty_scene.object_pose("cube"), expected)
    empty_scene.set_state(arm(joint1=1.0))
    assert_same_pose(empty_scene.object_pose("cube"), expected)


def test_pose_relative_to_another_object(empty_scene: Scene) -> None:
    tray = pose_from_xyz_rpy((0.5, 0.0, 0.1), (0.0, 0.0, np.pi / 2))
    empty_scene.add_object("tray", Box((0.3, 0.3, 0.02)), tray)
    empty_scene.add_object("cup", Cylinder(0.03, 0.1), Pose((0.1, 0.0, 0.06), frame="tray"))
    assert empty_scene.object_pose("cup").xyz == pytest.approx((0.5, 0.1, 0.16))


def test_move_and_remove(empty_scene: Scene) -> None:
    empty_scene.add_object("ball", Sphere(0.05), Pose((1.0, 0.0, 0.5)))
    empty_scene.move_object("ball", Pose((0.0, 1.0, 0.5)))
    assert empty_scene.object_pose("ball").xyz == pytest.approx((0.0, 1.0, 0.5))
    empty_scene.remove_object("ball")
    assert "ball" not in empty_scene and empty_scene.object_names == ()


def test_duplicate_and_link_names_are_refused(empty_scene: Scene) -> None:
    empty_scene.add_object("ball", Sphere(0.05), Pose((1.0, 0.0, 0.5)))
    with pytest.raises(SceneError, match="'ball' already exists"):
        empty_scene.add_object("ball", Sphere(0.05), Pose((1.0, 0.0, 0.5)))
    with pytest.raises(SceneError, match="is a link of the robot with collision geometry"):
        empty_scene.add_object("panda_hand", Sphere(0.05), Pose((1.0, 0.0, 0.5)))
    with pytest.raises(SceneError, match="non-empty string"):
        empty_scene.add_object("", Sphere(0.05), Pose())


@pytest.mark.parametrize(
    ("edit", "kind"),
    [
        (lambda s: s.remove_object("nothing"), "object"),
        (lambda s: s.move_object("nothing", Pose()), "object"),
        (lambda s: s.object_pose("nothing"), "object"),
        (lambda s: s.attach_object("nothing", "panda_hand"), "object"),
        (lambda s: s.add_object("b", Sphere(0.1), Pose(frame="nowhere")), "frame"),
        (lambda s: s.add_object("b", Sphere(0.1), Pose(), attach_to="panda_hnd"), "link"),
        (lambda s: s.add_object("b", Sphere(0.1), Pose(), "panda_hand", ["fingr"]), "link"),
        (lambda s: s.allow_collision("ghost", "panda_hand"), "link or object"),
        (lambda s: s.link_pose("nolink"), "link"),
    ],
)
def test_unknown_names_raise_unknown_name_error(
    empty_scene: Scene, edit: Callable[[Scene], object], kind: str
) -> None:
    with pytest.raises(UnknownNameError) as info:
        edit(empty_scene)
    assert info.value.kind == kind


def test_bad_shapes_and_misplaced_touch_links_are_scene_errors(empty_scene: Scene) -> None:
    with pytest.raises(SceneError, match="must be a Box, Cylinder, Sphere or Mesh"):
        empty_scene.add_object("thing", "box", Pose())  # type: ignore[arg-type]
    with pytest.raises(SceneError, match="need 'attach_to'"):
        empty_scene.add_object("thing", Sphere(0.1), Pose(), touch_links=FINGERS)
    assert empty_scene.object_names == ()


# ------------------------------------------------------------------ meshes
def test_mesh_object_loads_and_collides(empty_scene: Scene, tmp_path: Path) -> None:
    stl = write_cube_stl(tmp_path / "cube.stl", 0.05)
    hand = empty_scene.link_pose("panda_hand")
    empty_scene.add_object("block", Mesh(stl), hand)
    assert ("block", "panda_hand") in pairs(empty_scene)
    empty_scene.move_object("block", Pose((1.0, 1.0, 1.0)))
    assert not empty_scene.in_collision()


def test_mesh_scale_is_applied(empty_scene: Scene, tmp_path: Path) -> None:
    stl = write_cube_stl(tmp_path / "cube.stl", 0.05)
    empty_scene.add_object("slab", Mesh(stl, scale=(1.0, 1.0, 0.2)), Pose((0.0, -0.5, 0.3)))
    empty_scene.add_object("probe", Sphere(0.01), Pose((0.0, -0.5, 0.3)), attach_to="panda_link0")
    empty_scene.move_object("probe", Pose((0.0, -0.5, 0.325)))  # slab top at 0.31 m, not 0.35
    assert ("probe", "slab") not in pairs(empty_scene)
    empty_scene.move_object("probe", Pose((0.0, -0.5, 0.315)))
    assert ("probe", "slab") in pairs(empty_scene)


def test_missing_mesh_file_error_names_the_file(empty_scene: Scene, tmp_path: Path) -> None:
    missing = tmp_path / "nope" / "part.stl"
    with pytest.raises(MissingMeshError, match="part.stl") as info:
        empty_scene.add_object("part", Mesh(missing), Pose())
    assert info.value.path == missing
    assert "part" not in empty_scene


def test_unreadable_mesh_file_is_a_scene_error(empty_scene: Scene, tmp_path: Path) -> None:
    junk = tmp_path / "junk.stl"
    junk.write_text("this is not a mesh\n")
    with pytest.raises(SceneError, match="junk.stl"):
        empty_scene.add_object("part", Mesh(junk), Pose())


# ------------------------------------------------------------------ attaching
def test_object_between_the_fingers_collides_with_them_until_attached(empty_scene: Scene) -> None:
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose(frame=TCP))
    assert {("cube", f) for f in FINGERS} <= pairs(empty_scene)
    attached = empty_scene.attach_object("cube", "panda_hand", touch_links=FINGERS)
    assert attached.attached_to == "panda_hand" and attached.pose.frame == "panda_hand"
    assert not empty_scene.in_collision()
    assert empty_scene.collision_allowed("cube", "panda_leftfinger")


def test_attached_object_touching_links_outside_touch_links_collides(empty_scene: Scene) -> None:
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose(frame=TCP), attach_to="panda_hand")
    assert pairs(empty_scene) == {("cube", f) for f in FINGERS}


def test_attached_object_follows_the_gripper(empty_scene: Scene, arm: ArmState) -> None:
    grip = Pose((0.0, 0.0, 0.02), frame=TCP)
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), grip, "panda_hand", FINGERS)
    for q in (arm(joint1=1.0), arm(joint2=0.3, joint6=2.5), arm(joint7=-1.0)):
        empty_scene.set_state(q)
        tcp = empty_scene.link_pose(TCP).se3
        expected = Pose.from_se3(tcp * Pose((0, 0, 0.02)).se3)
        assert_same_pose(empty_scene.object_pose("cube"), expected)
        assert not empty_scene.in_collision()


def test_attached_stick_collides_with_the_table_but_not_the_gripper(
    cell: Scene, arm: ArmState
) -> None:
    stick = Cylinder(0.01, 0.6)  # from 5 cm inside the fingers to 55 cm past the tool point
    cell.add_object("stick", stick, Pose((0.0, 0.0, 0.25), frame=TCP), "panda_hand", FINGERS)
    assert pairs(cell) == {("stick", "table")}
    lifted = arm(joint2=-0.6, joint4=-1.2)
    assert not cell.in_collision(lifted)


def test_detached_object_stays_where_it_was_released(empty_scene: Scene, arm: ArmState) -> None:
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose(frame=TCP), "panda_hand", FINGERS)
    empty_scene.set_state(arm(joint1=0.8))
    released = empty_scene.object_pose("cube")
    obj = empty_scene.detach_object("cube")
    assert obj == SceneObject("cube", obj.shape, obj.pose) and not obj.attached
    assert_same_pose(empty_scene.object_pose("cube"), released)
    assert empty_scene.attached_objects() == ()
    empty_scene.set_state(arm(joint1=-0.8))  # the gripper leaves; the cube does not follow
    assert_same_pose(empty_scene.object_pose("cube"), released)
    assert not empty_scene.collision_allowed("cube", "panda_leftfinger")


def test_attach_and_detach_refuse_the_wrong_state(empty_scene: Scene) -> None:
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((1.0, 0.0, 0.0)))
    with pytest.raises(SceneError, match="not attached"):
        empty_scene.detach_object("cube")
    empty_scene.attach_object("cube", "panda_hand")
    with pytest.raises(SceneError, match="already attached to 'panda_hand'"):
        empty_scene.attach_object("cube", "panda_link7")


def test_moving_an_attached_object_keeps_it_attached(empty_scene: Scene) -> None:
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose(frame=TCP), "panda_hand", FINGERS)
    obj = empty_scene.move_object("cube", Pose((0.0, 0.0, 0.05), frame=TCP))
    assert obj.attached_to == "panda_hand"
    tcp = empty_scene.link_pose(TCP).se3
    assert_same_pose(empty_scene.object_pose("cube"), Pose.from_se3(tcp * Pose((0, 0, 0.05)).se3))


def test_removing_an_object_drops_its_allowances(empty_scene: Scene) -> None:
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.0, 0.0)))
    empty_scene.allow_collision("cube", "panda_hand")
    empty_scene.remove_object("cube")
    empty_scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.0, 0.0)))
    assert not empty_scene.collision_allowed("cube", "panda_hand")


# ------------------------------------------------------------------ state, snapshots, copies
def test_state_is_a_read_only_copy_and_partial_updates_keep_other_joints(
    empty_scene: Scene, ready: np.ndarray
) -> None:
    state = empty_scene.state
    with pytest.raises(ValueError):
        state[0] = 1.0
    empty_scene.set_state({"panda_joint1": 0.5, "panda_finger_joint1": 0.03})
    expected = ready.copy()
    expected[0], expected[7], expected[8] = 0.5, 0.03, 0.03  # finger_joint2 mimics joint1
    np.testing.assert_allclose(empty_scene.state, expected)
    with pytest.raises(UnknownNameError):
        empty_scene.set_state({"panda_joint9": 0.0})


def test_snapshot_round_trip_rebuilds_the_same_scene(
    panda_model: RobotModel, cell: Scene, arm: ArmState
) -> None:
    cell.add_object("cube", Box((0.04, 0.04, 0.04)), Pose(frame=TCP), "panda_hand", FINGERS)
    cell.allow_collision("cube", "shelf_board")
    cell.set_state(arm(joint1=0.4))
    snapshot = pickle.loads(pickle.dumps(cell.snapshot()))
    rebuilt = Scene.from_snapshot(panda_model, snapshot)
    assert rebuilt.objects == cell.objects
    np.testing.assert_array_equal(rebuilt.state, cell.state)
    assert rebuilt.allowed_collisions() == cell.allowed_collisions()
    assert_same_pose(rebuilt.object_pose("cube"), cell.object_pose("cube"))
    rng = np.random.default_rng(3)
    for q in (panda_model.random_state(rng) for _ in range(50)):
        assert rebuilt.in_collision(q) == cell.in_collision(q)


def test_snapshot_of_another_model_is_refused(ur5_model: RobotModel, cell: Scene) -> None:
    with pytest.raises(SceneError, match="cannot be restored"):
        Scene.from_snapshot(ur5_model, cell.snapshot())


def test_copy_is_independent(cell: Scene, arm: ArmState) -> None:
    other = cell.copy()
    other.add_object("ball", Sphere(0.05), Pose((0.0, 0.5, 0.5)))
    other.remove_object("shelf_top")
    other.set_state(arm(joint1=1.0))
    other.allow_collision("panda_hand", "table")
    assert "ball" not in cell and "shelf_top" in cell
    assert cell.state[0] == 0.0
    assert not cell.collision_allowed("panda_hand", "table")
    assert cell.in_collision(arm(joint2=1.6, joint4=-0.5))
