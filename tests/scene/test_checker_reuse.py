"""A scene edited back to a state it had (an allowance given, then taken back) gets the
checker it had then, which answers as a fresh build does; anything else gets a new one."""

from __future__ import annotations

import numpy as np

from taskrunner.robot import RobotModel
from taskrunner.scene import Scene
from taskrunner.scene.collision import Body, CollisionChecker
from taskrunner.scene.geometry import object_geometry
from taskrunner.shapes import Box
from taskrunner.types import Pose


def _fresh(scene: Scene) -> CollisionChecker:
    bodies = list(scene._link_bodies)
    for obj in scene.objects:
        geometry = object_geometry(scene.robot, obj, scene._entries[obj.name].geometry)
        bodies.append(Body(obj.name, (geometry,), static=not obj.attached))
    return CollisionChecker(scene.robot.model, bodies, scene.allowed_collisions())


def _states(model: RobotModel, seed: int, count: int) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [model.to_pin(model.random_state(rng)) for _ in range(count)]


def test_an_allowance_taken_back_brings_back_the_checker_it_had(
        cell: Scene, panda_model: RobotModel) -> None:
    before = cell.checker
    cell.allow_collision("shelf_board", "panda_hand")
    allowed = cell.checker
    assert allowed is not before
    cell.disallow_collision("shelf_board", "panda_hand")
    assert cell.checker is before
    cell.allow_collision("shelf_board", "panda_hand")
    assert cell.checker is allowed
    fresh = _fresh(cell)
    verdicts = [allowed.in_collision(q) for q in _states(panda_model, 4, 200)]
    assert verdicts == [fresh.in_collision(q) for q in _states(panda_model, 4, 200)]
    assert any(verdicts) and not all(verdicts)


def test_a_pick_lift_off_allowance_removed_brings_back_the_attach_checker(
        cell: Scene, panda_model: RobotModel, ready: np.ndarray) -> None:
    # What a pick does: attach, allow the support to touch the object while it is lifted
    # off, then take that back.
    cell.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.0, 0.02)))
    cell.attach_object("cube", "panda_hand", touch_links=["panda_leftfinger", "panda_rightfinger"])
    attached = cell.checker
    cell.allow_collision("cube", "table")
    lifting = cell.checker
    cell.disallow_collision("cube", "table")
    assert cell.checker is attached and lifting is not attached
    states = _states(panda_model, 9, 200)
    fresh = _fresh(cell)
    assert [attached.in_collision(q) for q in states] == [fresh.in_collision(q) for q in states]


def test_moved_objects_and_copies_get_checkers_of_their_own(cell: Scene) -> None:
    before = cell.checker
    cell.move_object("shelf_top", Pose((0.75, 0.0, 0.65)))
    moved = cell.checker
    cell.move_object("shelf_top", Pose((0.75, 0.0, 0.61)))  # back where it was: a new entry
    assert cell.checker is not before and cell.checker is not moved
    copy = cell.copy()
    assert copy.checker is not cell.checker
    copy.allow_collision("shelf_board", "panda_hand")
    copy.disallow_collision("shelf_board", "panda_hand")
    assert copy.checker is not cell.checker


def test_only_the_last_few_checkers_are_kept(cell: Scene) -> None:
    first = cell.checker
    for k in range(6):  # six other allowances, each checked
        cell.allow_collision("shelf_board", f"panda_link{k + 1}")
        assert cell.checker is not first
    for k in range(6):
        cell.disallow_collision("shelf_board", f"panda_link{k + 1}")
    assert cell.checker is not first  # rebuilt: too many edits ago


def _rows_anew(verifier) -> tuple[np.ndarray, np.ndarray]:
    """The pair rows of ``verifier``'s pairs computed from scratch (no shared rows)."""
    from taskrunner.scene.advancement import _PI_JOINTS, _pair_rows

    tree, nq = verifier._tree, verifier.robot.nq
    levers = np.zeros((len(verifier._first), nq))
    rows = np.zeros((len(verifier._first), _PI_JOINTS + 4 * nq), dtype=np.int64)
    _pair_rows(verifier._first, verifier._second, verifier._levers, tree.order, tree.revolute,
               tree.state_joint, tree.supported, levers, rows)
    return levers, rows


def test_a_new_revision_with_the_same_pairs_shares_the_verifier_s_pair_rows(
        cell: Scene, panda_model: RobotModel, arm) -> None:
    cell.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.0, 0.02)))
    first = cell.path_verifier()
    # A world object moved: a new checker, the same pairs and lever arms.
    cell.move_object("cube", Pose((0.45, 0.1, 0.02)))
    moved = cell.path_verifier()
    assert moved is not first and moved._checker is not first._checker
    assert moved._pair_i is first._pair_i and moved._unit_i is first._unit_i
    for verifier in (first, moved):
        levers, rows = _rows_anew(verifier)
        assert np.array_equal(levers, verifier.pair_levers)
        assert np.array_equal(rows, verifier._pair_i)
    # Held by the hand, the cube moves with the arm: other lever arms, other rows, built
    # anew (and right).
    cell.attach_object("cube", "panda_hand", touch_links=["panda_leftfinger",
                                                           "panda_rightfinger"])
    cell.allow_collision("cube", "table")  # lifted off it
    held = cell.path_verifier()
    assert held._pair_i is not first._pair_i
    levers, rows = _rows_anew(held)
    assert np.array_equal(levers, held.pair_levers) and np.array_equal(rows, held._pair_i)
    assert not np.array_equal(held.pair_levers[:len(first.pair_levers)], first.pair_levers) \
        or len(held.pair_levers) != len(first.pair_levers)
    # The verdicts are those of a verifier that built its own pairs' rows.
    from taskrunner.scene import path_verifier

    rng = np.random.default_rng(3)
    paths = [np.stack([arm(), panda_model.random_state(rng)]) for _ in range(12)]
    shared = [held.verify(path) for path in paths]
    path_verifier._PAIR_UNITS.clear()
    alone = path_verifier.PathVerifier(panda_model, cell.checker)
    assert alone._pair_i is not held._pair_i
    for found, path in zip(shared, paths):
        again = alone.verify(path)
        assert (found.valid, found.fraction, found.pair) == \
            (again.valid, again.fraction, again.pair)
    assert {found.valid for found in shared} == {True, False}


def test_every_checker_knows_each_geometry_s_joint(cell: Scene) -> None:
    # The robot's links' joints are kept with its geometry; the objects' are each
    # checker's own (an object held by the hand moves with its joint).
    cell.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.0, 0.02)))
    for edit in (lambda: None, lambda: cell.attach_object("cube", "panda_hand"),
                 lambda: cell.detach_object("cube")):
        edit()
        checker = cell.checker
        objects = checker.geometry_model.geometryObjects
        assert checker.geometry_joints.tolist() == [int(o.parentJoint) for o in objects]
    hand = cell.robot.model.frames[cell.robot.frame_id("panda_hand")].parentJoint
    cell.attach_object("cube", "panda_hand")
    assert cell.checker.geometry_joints[-1] == hand > 0
