"""A scene's checker after edits (built on the shared robot geometry) is the checker a fresh
build gives: same geometry, same pairs, same verdicts, contacts and distances; and a
checker somebody holds never changes when the scene is edited."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.robot import RobotModel
from taskrunner.scene import Scene
from taskrunner.scene.collision import Body, CollisionChecker, Contact, RobotGeometry
from taskrunner.scene.geometry import object_geometry
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.types import Pose


def _fresh(scene: Scene) -> CollisionChecker:
    """A checker built from nothing: every body's geometry, no shared robot part."""
    bodies = list(scene._link_bodies)
    for obj in scene.objects:
        geometry = object_geometry(scene.robot, obj, scene._entries[obj.name].geometry)
        bodies.append(Body(obj.name, (geometry,), static=not obj.attached))
    return CollisionChecker(scene.robot.model, bodies, scene.allowed_collisions())


def _rule_pairs(checker: CollisionChecker, scene: Scene) -> list[tuple[int, int]]:
    """The documented pair rule, spelled out: different bodies, not both world objects,
    not an allowed pair; in geometry order."""
    names = [g.name.rsplit("/", 1)[0] for g in checker.geometry_model.geometryObjects]
    world = {o.name for o in scene.objects if not o.attached}
    allowed = scene.allowed_collisions()
    return [(i, j) for i in range(len(names)) for j in range(i + 1, len(names))
            if names[i] != names[j] and not (names[i] in world and names[j] in world)
            and frozenset((names[i], names[j])) not in allowed]


def _same_contacts(found: list[Contact], expected: list[Contact]) -> bool:
    """The same body pairs, depths equal to 1e-6 m (GJK and EPA start from the previous
    query's guess, so a depth can differ in its last digits with the query history)."""
    return ({(c.a, c.b) for c in found} == {(c.a, c.b) for c in expected}
            and sorted(c.depth for c in found) == pytest.approx(
                sorted(c.depth for c in expected), abs=1e-6))


def _edit(scene: Scene, rng: np.random.Generator, serial: int) -> None:
    """One random edit: add, move, remove, attach, detach, allow or disallow."""
    links = [b.name for b in scene._link_bodies]
    things = [n for n in scene.object_names if n.startswith("thing")]
    kind = rng.choice(["add", "add", "move", "remove", "attach", "detach", "allow", "disallow"])
    if kind == "add" or not things:
        shape = (Box(tuple(rng.uniform(0.02, 0.2, 3))), Sphere(float(rng.uniform(0.02, 0.1))),
                 Cylinder(float(rng.uniform(0.02, 0.06)), float(rng.uniform(0.05, 0.3))))[serial % 3]
        xyz = tuple(float(v) for v in rng.uniform((-0.2, -0.6, 0.0), (0.8, 0.6, 0.9)))
        scene.add_object(f"thing{serial}", shape, Pose(xyz))
        return
    name = str(rng.choice(things))
    attached = scene.object(name).attached
    other = str(rng.choice(links + list(scene.object_names)))
    if kind == "move":
        xyz = tuple(float(v) for v in rng.uniform((-0.2, -0.6, 0.0), (0.8, 0.6, 0.9)))
        scene.move_object(name, Pose(xyz))
    elif kind == "remove":
        scene.remove_object(name)
    elif kind in ("attach", "detach") and not attached:
        scene.set_state(scene.robot.random_state(rng))
        scene.attach_object(name, str(rng.choice(links[-4:])), [str(rng.choice(links))])
    elif kind in ("attach", "detach"):
        scene.detach_object(name)
    elif kind == "allow" and other != name:
        scene.allow_collision(name, other)
    elif other != name and scene.allowed_collisions().get(frozenset((name, other))) == "scene":
        scene.disallow_collision(name, other)


def test_checkers_after_random_edits_equal_fresh_ones(cell: Scene, panda_model: RobotModel) -> None:
    rng = np.random.default_rng(7)
    states = [panda_model.to_pin(panda_model.random_state(rng)) for _ in range(40)]
    colliding = free = 0
    for serial in range(40):
        _edit(cell, rng, serial)
        checker, fresh = cell.checker, _fresh(cell)
        restored = Scene.from_snapshot(panda_model, cell.snapshot()).checker
        names = [g.name for g in checker.geometry_model.geometryObjects]
        assert names == [g.name for g in fresh.geometry_model.geometryObjects]
        pairs = [(p.first, p.second) for p in checker.geometry_model.collisionPairs]
        assert pairs == [(p.first, p.second) for p in fresh.geometry_model.collisionPairs]
        assert pairs == _rule_pairs(checker, cell) == list(checker._pairs)
        assert restored.pair_count == checker.pair_count
        for g, h in zip(checker.geometry_model.geometryObjects, fresh.geometry_model.geometryObjects):
            assert g.parentJoint == h.parentJoint
            assert g.placement.isApprox(h.placement, 0.0)
        for k, q in enumerate(states):
            verdict = checker.in_collision(q)
            assert verdict == fresh.in_collision(q) == restored.in_collision(q)
            colliding += verdict
            free += not verdict
            if k % 8 == 0:
                # GJK and EPA start from the previous query's guess: the same to ~1e-7 m.
                contacts = checker.collisions(q)
                assert _same_contacts(contacts, fresh.collisions(q))
                assert verdict == bool(contacts)
                distance, pair = checker.min_distance(q)
                assert distance == pytest.approx(fresh.min_distance(q).distance, abs=1e-6)
                assert pair == fresh.min_distance(q).pair
    assert colliding > 100 and free > 100  # the comparison saw both verdicts


def test_the_fast_check_starts_afresh_on_every_state(cell: Scene, panda_model: RobotModel) -> None:
    rng = np.random.default_rng(3)
    checker, fresh = cell.checker, _fresh(cell)
    states = [panda_model.to_pin(panda_model.random_state(rng)) for _ in range(300)]
    verdicts = [checker.in_collision(q) for q in states]  # colliding and free interleaved
    assert any(verdicts) and not all(verdicts)
    assert verdicts == [fresh.in_collision(q) for q in reversed(states)][::-1]
    # Rows at once: the first colliding row, or -1.
    rows = np.array(states)
    for start in range(0, 40):
        expected = next((i for i, v in enumerate(verdicts[start:]) if v), -1)
        assert checker.first_in_collision(rows[start:]) == expected
    free = rows[[not v for v in verdicts]]
    assert checker.first_in_collision(free) == -1 and checker.first_in_collision(rows[:0]) == -1


def test_a_held_checker_is_not_changed_by_later_edits(cell: Scene, panda_model: RobotModel) -> None:
    rng = np.random.default_rng(11)
    states = [panda_model.to_pin(panda_model.random_state(rng)) for _ in range(60)]
    held = cell.checker
    names = [g.name for g in held.geometry_model.geometryObjects]
    pairs = [(p.first, p.second) for p in held.geometry_model.collisionPairs]
    verdicts = [held.in_collision(q) for q in states]
    contacts = [held.collisions(q) for q in states[:10]]
    template_size = cell._robot_geometry._template.ngeoms
    for serial in range(15):
        _edit(cell, rng, serial)
        assert cell.checker is not held
    cell.remove_object("table")
    cell.add_object("post", Cylinder(0.05, 1.0), Pose((0.3, 0.0, 0.5)))
    assert cell.checker is not held
    assert [g.name for g in held.geometry_model.geometryObjects] == names
    assert [(p.first, p.second) for p in held.geometry_model.collisionPairs] == pairs
    assert [held.in_collision(q) for q in states] == verdicts
    assert all(_same_contacts(held.collisions(q), c) for q, c in zip(states[:10], contacts))
    assert cell._robot_geometry._template.ngeoms == template_size
    assert len(cell._robot_geometry._template.collisionPairs) == 0


def test_copies_share_the_robot_geometry_and_build_their_own_checkers(cell: Scene) -> None:
    other = cell.copy()
    assert other._robot_geometry is cell._robot_geometry
    other.add_object("ball", Sphere(0.05), Pose((0.4, 0.0, 0.3)))
    assert other.checker is not cell.checker
    assert "ball" not in {g.name.split("/")[0] for g in cell.checker.geometry_model.geometryObjects}


def test_moving_an_object_keeps_its_pairs_and_moves_its_geometry(cell: Scene) -> None:
    before = cell.checker
    cell.move_object("shelf_top", Pose((0.75, 0.0, 0.71)))
    after = cell.checker
    assert after._pairs == before._pairs
    index = [g.name for g in after.geometry_model.geometryObjects].index("shelf_top/0")
    moved = after.geometry_model.geometryObjects[index].placement.translation
    assert moved[2] == pytest.approx(0.71)
    kept = before.geometry_model.geometryObjects[index].placement.translation
    assert kept[2] == pytest.approx(0.61)


def test_robot_geometry_of_another_model_is_refused(panda_model: RobotModel) -> None:
    robot = RobotGeometry(panda_model.model, ())
    with pytest.raises(ValueError, match="another pinocchio model"):
        CollisionChecker(pin.Model(), [], [], robot=robot)
