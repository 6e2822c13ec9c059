"""State checks, contact reports and distances on the Panda in a table-and-shelf cell."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from taskrunner.errors import SceneError
from taskrunner.robot import RobotModel
from taskrunner.scene import Scene, SceneOptions
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.types import Pose

ArmState = Callable[..., np.ndarray]



def pairs(scene: Scene, q: np.ndarray | None = None) -> set[tuple[str, str]]:
    return {(c.a, c.b) for c in scene.collisions(q)}


def test_ready_pose_is_free_in_the_cell(cell: Scene) -> None:
    assert not cell.in_collision()
    assert cell.is_valid()
    assert cell.collisions() == []


def test_folding_the_arm_into_itself_collides_fingers_with_link1(cell: Scene, arm: ArmState) -> None:
    folded = arm(joint2=0.0, joint4=-3.0)
    assert cell.in_collision(folded)
    assert not cell.is_valid(folded)
    assert ("panda_leftfinger", "panda_link1") in pairs(cell, folded)


def test_arm_pushed_into_the_table_collides_hand_with_table(cell: Scene, arm: ArmState) -> None:
    down = arm(joint2=1.6, joint4=-0.5)
    assert cell.in_collision(down)
    found = pairs(cell, down)
    assert ("panda_hand", "table") in found
    assert all("table" in pair for pair in found)


def test_contacts_report_positive_depths_deepest_first(cell: Scene, arm: ArmState) -> None:
    contacts = cell.collisions(arm(joint2=1.6, joint4=-0.5))
    depths = [c.depth for c in contacts]
    assert all(d > 0 for d in depths)
    assert depths == sorted(depths, reverse=True)


def test_fast_check_agrees_with_the_contact_report_on_random_states(
    cell: Scene, panda_model: RobotModel
) -> None:
    rng = np.random.default_rng(7)
    states = [panda_model.random_state(rng) for _ in range(150)]
    verdicts = [cell.in_collision(q) for q in states]
    assert any(verdicts) and not all(verdicts)
    assert verdicts == [bool(cell.collisions(q)) for q in states]


def test_min_distance_names_the_closest_pair_and_goes_negative_in_collision(
    cell: Scene, arm: ArmState
) -> None:
    distance, pair = cell.min_distance()
    assert 0.0 < distance < 0.5
    assert pair is not None and pair[0] < pair[1]
    distance, pair = cell.min_distance(arm(joint2=1.6, joint4=-0.5))
    assert distance < 0.0
    assert pair == ("panda_hand", "table")


def test_pair_distances_are_the_signed_distances_of_the_report(
    cell: Scene, panda_model: RobotModel, arm: ArmState
) -> None:
    # The path verifier's exact distances: the fast path's data, no second copy.
    checker = cell.checker
    pairs_all = np.arange(checker.pair_count)
    for q in (cell.state, arm(joint2=1.6, joint4=-0.5)):
        out = np.full(checker.pair_count, np.nan)
        checker.pair_distances(panda_model.to_pin(q), pairs_all, out)
        distance, _ = checker.min_distance(panda_model.to_pin(q))
        assert np.isfinite(out).all()
        assert out.min() == pytest.approx(distance, abs=1e-9)
    assert out.min() < 0.0  # pushed into the table: negative, not clipped at zero
    assert not checker.in_collision(panda_model.to_pin(cell.state))  # the fast path still works


def test_min_distance_to_a_ball_shrinks_by_at_most_how_far_it_moves(empty_scene: Scene) -> None:
    empty_scene.add_object("ball", Sphere(0.05), Pose((-0.3, 0.0, 0.05)))
    far, pair = empty_scene.min_distance()
    assert pair == ("ball", "panda_link0")
    assert 0.05 < far < 0.13  # link0 reaches about 0.15 m behind the base
    empty_scene.move_object("ball", Pose((-0.25, 0.0, 0.05)))
    near, pair = empty_scene.min_distance()
    assert pair == ("ball", "panda_link0")
    assert 0.04 < far - near <= 0.05 + 1e-9


def test_allowing_a_pair_removes_it_from_the_checks(cell: Scene, arm: ArmState) -> None:
    down = arm(joint2=1.6, joint4=-0.5)
    for link in ("panda_hand", "panda_link7"):
        cell.allow_collision(link, "table")
    assert cell.collision_allowed("table", "panda_hand")
    assert not cell.in_collision(down)
    cell.disallow_collision("panda_hand", "table")
    assert pairs(cell, down) == {("panda_hand", "table")}


def test_srdf_allowances_cannot_be_withdrawn_by_the_scene(cell: Scene) -> None:
    assert cell.collision_allowed("panda_link5", "panda_link7")
    with pytest.raises(SceneError, match="'Default'"):
        cell.disallow_collision("panda_link5", "panda_link7")


def test_cube_resting_on_the_table_collides_once_carried_unless_allowed(cell: Scene) -> None:
    cell.add_object("cube", Box((0.05, 0.05, 0.05)), Pose((0.5, 0.3, 0.02)))
    assert cell.collisions() == []  # world objects are never checked against each other
    cell.attach_object("cube", "panda_hand")
    assert pairs(cell) == {("cube", "table")}
    cell.allow_collision("cube", "table")
    assert not cell.in_collision()


def test_world_objects_overlapping_each_other_are_not_a_collision(cell: Scene) -> None:
    cell.add_object("crate", Box((0.2, 0.2, 0.2)), Pose((0.75, 0.0, 0.3)))
    assert cell.collisions() == []


def test_state_check_uses_the_current_state_by_default(cell: Scene, arm: ArmState) -> None:
    cell.set_state(arm(joint2=1.6, joint4=-0.5))
    assert cell.in_collision()
    assert cell.in_collision(arm()) is False


def test_mesh_robot_geometry_gives_the_same_verdicts_on_the_panda(
    panda_model: RobotModel, cell: Scene, arm: ArmState
) -> None:
    meshes = Scene.from_snapshot(panda_model, cell.snapshot(), SceneOptions(convex_robot_meshes=False))
    for q in (arm(), arm(joint2=0.0, joint4=-3.0), arm(joint2=1.6, joint4=-0.5)):
        assert meshes.in_collision(q) == cell.in_collision(q)


def test_edits_rebuild_the_checker(cell: Scene, arm: ArmState) -> None:
    before = cell.checker
    cell.add_object("post", Cylinder(0.03, 0.5), Pose((0.3, 0.0, 0.25)))
    assert cell.checker is not before
    assert ("panda_hand", "post") in pairs(cell) or ("panda_leftfinger", "post") in pairs(cell)
    cell.remove_object("post")
    assert not cell.in_collision()


def test_a_wrong_length_state_is_rejected_in_the_reports(cell: Scene) -> None:
    with pytest.raises(ValueError, match="state vector of 9 values"):
        cell.collisions(np.zeros(7))
    with pytest.raises(ValueError, match="state vector of 9 values"):
        cell.set_state(np.zeros(7))


def test_public_names_of_the_scene_package() -> None:
    import taskrunner.scene

    assert sorted(taskrunner.scene.__all__) == [
        "Clearance", "Contact", "Scene", "SceneObject", "SceneOptions", "SceneSnapshot",
        "scene_from_cell",
    ]
