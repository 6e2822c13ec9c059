"""The path verifier's per-robot cache and its compiled walk.

A verifier built from the robot's kept tree and link rows (a scene edit) must decide and
count exactly as one built from scratch; and on seeded random paths through a cluttered
scene its verdicts must agree with an independent dense check (accepted paths free at
0.1 mm of arm motion, rejected paths naming a state in contact).
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from taskrunner.collision.tree import lever_arms
from taskrunner.scene import Scene, geometry_records
from taskrunner.scene.path_verifier import PathVerifier
from taskrunner.shapes import Box, Cylinder
from taskrunner.types import Pose

PANDA_REACH = 1.25  # m: from joint 1's axis to the fingertips, stretched out, rounded up


def _pose(x: float, y: float, z: float, rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> Pose:
    return Pose.from_se3(pin.SE3(pin.rpy.rpyToMatrix(*rpy), np.array([x, y, z])))


def _cluttered(panda_model) -> Scene:
    scene = Scene(panda_model)
    scene.add_object("table", Box((1.0, 1.2, 0.04)), _pose(0.4, 0.0, -0.03))
    scene.add_object("post", Cylinder(0.03, 0.5), _pose(0.45, -0.25, 0.25))
    scene.add_object("crate", Box((0.15, 0.2, 0.12)), _pose(0.5, 0.2, 0.3, (0.0, 0.0, 0.4)))
    scene.add_object("shelf", Box((0.3, 0.6, 0.02)), _pose(0.1, 0.55, 0.45, (0.2, 0.0, 0.0)))
    return scene


def _random_paths(scene: Scene, rng: np.random.Generator, count: int, spread: float
                  ) -> list[np.ndarray]:
    """Free start states and short polylines (2-3 waypoints) around them."""
    robot = scene.robot
    paths: list[np.ndarray] = []
    while len(paths) < count:
        start = robot.random_state(rng, "arm")
        if scene.in_collision(start):
            continue
        states = [start]
        for _ in range(int(rng.integers(1, 3))):
            q = states[-1].copy()
            q[robot.active_indices] += rng.normal(0.0, spread, len(robot.active_indices))
            q = np.clip(q, robot.lower, robot.upper)
            states.append(robot.apply_mimic(q))
        paths.append(np.array(states))
    return paths


def _same(a, b) -> None:
    assert (a.valid, a.distance_queries, a.states, a.bounds, a.fraction, a.pair) == \
        (b.valid, b.distance_queries, b.states, b.bounds, b.fraction, b.pair)


def test_a_build_from_the_kept_robot_rows_decides_as_one_from_scratch(panda_model):
    scene = _cluttered(panda_model)
    robot = scene.robot
    PathVerifier(robot, scene.checker)                  # the robot's rows are kept
    assert id(robot) in geometry_records._TREES
    kept = PathVerifier(robot, scene.checker)
    geometry_records._TREES.clear()
    fresh = PathVerifier(robot, scene.checker)
    for name in ("_pair_levers", "_pair_i", "_geometries", "_levers"):
        assert np.array_equal(getattr(kept, name), getattr(fresh, name)), name
    assert np.array_equal(kept._levers, lever_arms(robot, scene.checker.geometry_model))
    # A scene edit: an object added and one moved; the links' rows come from the cache.
    scene.add_object("bar", Box((0.6, 0.03, 0.03)), _pose(0.35, 0.0, 0.55))
    scene.move_object("crate", _pose(0.45, 0.3, 0.25))
    edited = scene.path_verifier()
    geometry_records._TREES.clear()
    rebuilt = PathVerifier(robot, scene.checker)
    assert np.array_equal(edited._pair_i, rebuilt._pair_i)
    assert np.array_equal(edited._geometries, rebuilt._geometries)
    rng = np.random.default_rng(21)
    verdicts = set()
    for states in _random_paths(scene, rng, 12, 0.6):
        first, second = edited.verify(states), rebuilt.verify(states)
        _same(first, second)
        verdicts.add(first.valid)
    assert verdicts == {True, False}


def _dense_collision(scene: Scene, states: np.ndarray) -> bool:
    """Independent check: states no more than 0.1 mm of arm motion apart."""
    robot = scene.robot
    for a, b in zip(states[:-1], states[1:]):
        steps = max(1, int(np.ceil(np.sum(np.abs(b - a)) * PANDA_REACH / 1e-4)))
        for t in np.linspace(0.0, 1.0, steps + 1):
            if scene.in_collision(robot.apply_mimic(a + t * (b - a))):
                return True
    return False


def test_verdicts_on_random_paths_agree_with_a_dense_check(panda_model):
    scene = _cluttered(panda_model)
    verifier = scene.path_verifier()
    rng = np.random.default_rng(4)
    accepted = rejected = 0
    for states in _random_paths(scene, rng, 14, 0.25):
        result = verifier.verify(states)
        if result.valid:
            accepted += 1
            assert not _dense_collision(scene, states)
        else:
            rejected += 1
            assert result.state is not None and result.pair is not None
            assert scene.min_distance(result.state).distance < 1e-5
            assert _dense_collision(scene, states[: int(result.fraction) + 2])
    assert accepted > 0 and rejected > 0


def test_a_single_state_and_a_standing_path_are_checked_there(panda_model):
    scene = _cluttered(panda_model)
    verifier = scene.path_verifier()
    q = scene.state.copy()
    assert verifier.verify(q).valid
    assert verifier.verify(np.vstack([q, q, q])).valid
    rng = np.random.default_rng(2)
    inside = scene.robot.random_state(rng, "arm")
    while not scene.in_collision(inside):
        inside = scene.robot.random_state(rng, "arm")
    result = verifier.verify(np.vstack([inside, inside]))
    assert not result.valid and result.fraction == 0.0


def test_a_primitive_edited_in_place_gets_new_rows(panda_model):
    scene = _cluttered(panda_model)
    geometry_model = scene.checker.geometry_model
    index = next(i for i, obj in enumerate(geometry_model.geometryObjects)
                 if obj.name == "crate/0")
    before = PathVerifier(scene.robot, scene.checker)
    box = geometry_model.geometryObjects[index].geometry
    box.halfSide = np.asarray(box.halfSide) * 2.0
    after = PathVerifier(scene.robot, scene.checker)
    row = after._geometries[index]
    assert not np.array_equal(before._geometries[index], row)
    geometry_records._TREES.clear()
    assert np.array_equal(PathVerifier(scene.robot, scene.checker)._geometries[index], row)
