"""The planner's sphere-model checker: covering, kinematics, conservativeness, edges, cache."""

from __future__ import annotations

import coal
import numpy as np
import pinocchio as pin
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from plan_helpers import READY, SHELF

from taskrunner.planning import MotionPlanner, PlannerOptions, PlanRequest, fastcheck, spheres
from taskrunner.planning.request import JointGoal
from taskrunner.scene import Scene
from taskrunner.shapes import Box, Cylinder, Mesh, Sphere
from taskrunner.types import Pose

SETTINGS = settings(max_examples=25, deadline=None, derandomize=True)


def _inside(geometry: coal.CollisionGeometry, points: np.ndarray) -> np.ndarray:
    """Which points lie inside (or on) a solid coal geometry."""
    probe = coal.Sphere(1e-9)
    out = np.zeros(len(points), dtype=bool)
    for k, p in enumerate(points):
        request, result = coal.DistanceRequest(), coal.DistanceResult()
        d = coal.distance(geometry, coal.Transform3s(), probe,
                          coal.Transform3s(np.eye(3), np.asarray(p, dtype=float)), request, result)
        out[k] = d <= 0.0
    return out


def _covered(cover: spheres.SphereSet, points: np.ndarray) -> np.ndarray:
    d = np.linalg.norm(points[:, None, :] - cover.centres[None], axis=2) - cover.radii
    return (d <= 0.0).any(axis=1)


def _cell_scene(scene: Scene, mesh_path) -> Scene:
    """World boxes, a cylinder, a sphere and a mesh around the robot; an attached box."""
    scene.add_object("wall", Box((0.05, 0.8, 0.6)), Pose((0.55, 0.0, 0.35)))
    scene.add_object("post", Cylinder(0.04, 0.7), Pose((-0.1, 0.45, 0.35)))
    scene.add_object("ball", Sphere(0.08), Pose((0.3, -0.35, 0.45)))
    scene.add_object("rock", Mesh(mesh_path), Pose((0.2, 0.35, 0.1)))
    return scene


@pytest.fixture(scope="module")
def link_mesh(example_robot_data):
    return (example_robot_data / "robots" / "panda_description" / "meshes" / "collision"
            / "link4.stl")


# ---------------------------------------------------------------------- covering
@pytest.mark.parametrize("geometry", [
    coal.Box(0.3, 0.05, 0.12), coal.Cylinder(0.04, 0.5), coal.Capsule(0.03, 0.2),
    coal.Cone(0.05, 0.2), coal.Sphere(0.07),
], ids=["box", "cylinder", "capsule", "cone", "sphere"])
def test_cover_contains_every_point_of_primitives(geometry):
    cover = spheres.cover(geometry, use_cache=False)
    assert 1 <= len(cover) <= 16
    geometry.computeLocalAABB()
    lo = np.asarray(geometry.aabb_local.min_) - 0.01
    hi = np.asarray(geometry.aabb_local.max_) + 0.01
    points = np.random.default_rng(3).uniform(lo, hi, (4000, 3))
    outside = points[~_covered(cover, points)]
    # Every point the spheres miss is outside the solid (the box corners included).
    assert not _inside(geometry, outside).any()


def test_cover_contains_a_link_hull_and_its_corners(panda_model):
    scene = Scene(panda_model)
    for g in scene.checker.geometry_model.geometryObjects:
        shape = g.geometry
        cover = spheres.cover(shape, use_cache=False)
        vertices = spheres.polytope_vertices(shape)
        if vertices is None:
            continue
        # The polytope's vertices, and random convex combinations of them, are covered.
        rng = np.random.default_rng(1)
        weights = rng.dirichlet(np.ones(len(vertices)) * 0.2, size=500)
        points = np.vstack([vertices, weights @ vertices])
        assert _covered(cover, points).all(), g.name


# ---------------------------------------------------------------------- kinematics
@pytest.mark.parametrize("robot", ["panda_model", "ur5_model", "servo_arm_model"])
def test_forward_kinematics_matches_pinocchio(robot, request):
    model = request.getfixturevalue(robot)
    scene = Scene(model)
    checker = fastcheck.SphereModel(model, scene.checker).group(model.active_indices)
    data = model.model.createData()
    rng = np.random.default_rng(7)
    for _ in range(50):
        q = model.random_state(rng)
        rotations, translations = checker.link_frames(q)
        pin.forwardKinematics(model.model, data, model.to_pin(q))
        for j in range(model.model.njoints):
            assert np.allclose(rotations[j], data.oMi[j].rotation, atol=1e-9, rtol=0)
            assert np.allclose(translations[j], data.oMi[j].translation, atol=1e-9, rtol=0)


def test_forward_kinematics_of_a_two_arm_cell(servo_pair_scene):
    model = servo_pair_scene.robot
    checker = fastcheck.SphereModel(model, servo_pair_scene.checker).group(model.active_indices)
    data = model.model.createData()
    rng = np.random.default_rng(8)
    for _ in range(20):
        q = model.random_state(rng)
        rotations, translations = checker.link_frames(q)
        pin.forwardKinematics(model.model, data, model.to_pin(q))
        for j in range(model.model.njoints):
            assert np.allclose(translations[j], data.oMi[j].translation, atol=1e-9, rtol=0)
            assert np.allclose(rotations[j], data.oMi[j].rotation, atol=1e-9, rtol=0)


# ---------------------------------------------------------------------- conservativeness
def _conservative(scene: Scene, group: str, seed: int, count: int) -> tuple[int, int]:
    """Random states of ``group``: spheres free must mean exact free. Returns the number of
    sphere-free and of exactly free states."""
    model = scene.robot
    idx = model.group(group).joint_indices
    checker = fastcheck.SphereModel(model, scene.checker).group(idx)
    rng = np.random.default_rng(seed)
    base = scene.state.copy()
    sphere_free = exact_free = 0
    for _ in range(count):
        q = model.random_state(rng, group, base)
        fast = checker.state_free(base, q[idx])
        exact = not scene.in_collision(q)
        assert not (fast and not exact), f"spheres free but {scene.collisions(q)} at {q}"
        sphere_free += fast
        exact_free += exact
    return sphere_free, exact_free


@SETTINGS
@given(seed=st.integers(0, 2**31 - 1))
def test_spheres_free_implies_exact_free_panda_cell(panda_model, link_mesh, seed):
    scene = _cell_scene(Scene(panda_model), link_mesh)
    scene.set_state(READY)
    _conservative(scene, "arm", seed, 40)


@SETTINGS
@given(seed=st.integers(0, 2**31 - 1))
def test_spheres_free_implies_exact_free_ur5_and_servo_arm(ur5_model, servo_arm_model,
                                                           link_mesh, seed):
    for model, group in ((ur5_model, "manipulator"), (servo_arm_model, "arm")):
        scene = _cell_scene(Scene(model), link_mesh)
        _conservative(scene, group, seed, 20)


def test_spheres_free_implies_exact_free_two_arms(servo_pair_scene):
    _conservative(servo_pair_scene, "both_arms", 5, 300)


def test_spheres_free_implies_exact_free_with_an_attached_object(panda_model):
    scene = Scene(panda_model)
    for name, size, xyz in SHELF:
        scene.add_object(name, Box(size), Pose(xyz))
    scene.allow_collision("panda_link0", "table")
    scene.set_state(READY)
    hand = scene.link_pose("panda_hand")
    below = tuple(float(v) for v in np.asarray(hand.xyz) + np.array([0.0, 0.0, -0.15]))
    scene.add_object("carried", Cylinder(0.03, 0.2), Pose(below))
    scene.attach_object("carried", "panda_hand", ["panda_leftfinger", "panda_rightfinger"])
    sphere_free, exact_free = _conservative(scene, "arm", 11, 300)
    # The model is useful, not only safe: most free states are recognised as free.
    assert sphere_free > 0.5 * exact_free


# ---------------------------------------------------------------------- edges
def test_edge_walk_agrees_with_dense_exact_sampling(shelf_scene):
    model = shelf_scene.robot
    idx = model.group("arm").joint_indices
    checker = fastcheck.SphereModel(model, shelf_scene.checker).group(idx)
    base = shelf_scene.state.copy()
    rng = np.random.default_rng(4)
    cleared = stopped = 0
    for _ in range(60):
        a = model.random_state(rng, "arm", base)[idx]
        b = np.clip(a + rng.normal(0.0, 0.4, len(idx)), model.lower[idx], model.upper[idx])
        s, checks = checker.edge(base, a, b, 0.002)
        assert checks >= 1
        # Everything before s is free for the exact geometry, whatever the verdict.
        for t in np.linspace(0.0, min(s, 1.0), 150) if s > 0.0 else ():
            q = base.copy()
            q[idx] = a + t * (b - a)
            assert not shelf_scene.in_collision(model.apply_mimic(q)), (s, t)
        # The states the scan leaves out are sphere-free, hence free.
        touching = set(np.round(checker.touching(base, a, b, 0.0, 20), 12))
        for i in range(21):
            t = i / 20
            q = base.copy()
            q[idx] = a + t * (b - a)
            if round(t, 12) not in touching:
                assert not shelf_scene.in_collision(model.apply_mimic(q))
        cleared += s >= 1.0
        stopped += s < 1.0
    assert cleared > 5 and stopped > 5  # both verdicts were exercised


def test_planner_paths_with_and_without_spheres_verify(shelf_scene):
    goal = JointGoal({"panda_joint1": 0.6, "panda_joint2": 0.3, "panda_joint4": -1.9})
    for fast_check in (True, False):
        planner = MotionPlanner(shelf_scene, fast_check=fast_check)
        result = planner.plan(PlanRequest("arm", goal, options=PlannerOptions(seed=3, direct=False)))
        states = np.array([result.start] * len(result.path.waypoints))
        states[:, shelf_scene.robot.indices(result.path.names)] = result.path.waypoints
        assert planner.verify_states(states, 5e-4).valid
        assert (planner._spheres is not None) == fast_check


@pytest.mark.parametrize("planner", ["RRT", "KPIECE1", "PRM", "BITstar"])
def test_other_planners_search_with_the_edge_validator(shelf_scene, planner):
    goal = JointGoal({"panda_joint1": 0.6, "panda_joint2": 0.3, "panda_joint4": -1.9})
    motion_planner = MotionPlanner(shelf_scene, fast_check=True)
    result = motion_planner.plan(PlanRequest("arm", goal, options=PlannerOptions(
        planner=planner, seed=2, planning_time=3.0, direct=False)))
    states = np.array([result.start] * len(result.path.waypoints))
    states[:, shelf_scene.robot.indices(result.path.names)] = result.path.waypoints
    assert motion_planner.verify_states(states, 5e-4).valid


def test_a_model_the_compiled_kinematics_cannot_handle_plans_exactly(shelf_scene, monkeypatch):
    def unsupported(*args, **kwargs):  # type: ignore[no-untyped-def]
        raise fastcheck.UnsupportedModelError("joint 'base' (JointModelFreeFlyer)")

    monkeypatch.setattr(fastcheck, "SphereModel", unsupported)
    planner = MotionPlanner(shelf_scene, fast_check=True)
    goal = JointGoal({"panda_joint1": 0.6, "panda_joint2": 0.3, "panda_joint4": -1.9})
    planner.plan(PlanRequest("arm", goal, options=PlannerOptions(seed=3, direct=False)))
    assert planner.fast_check is False and planner._spheres is None


def test_a_free_flyer_is_reported_unsupported(panda_model):
    model = pin.Model()
    model.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3.Identity(), "base")

    class Fake:
        pass

    robot = Fake()
    robot.model = model  # type: ignore[attr-defined]
    robot.joints = ()  # type: ignore[attr-defined]
    with pytest.raises(fastcheck.UnsupportedModelError, match="base"):
        fastcheck._joint_table(robot)  # type: ignore[arg-type]


# ---------------------------------------------------------------------- cache
def test_sphere_models_are_cached_on_disk(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.setattr(spheres, "_memory", {})
    box = coal.Box(0.2, 0.1, 0.4)
    first = spheres.cover(box)
    files = list((tmp_path / "taskrunner" / "spheres").glob("*.npz"))
    assert len(files) == 1
    monkeypatch.setattr(spheres, "_memory", {})
    monkeypatch.setattr(spheres, "_split_cover", _refuse)
    again = spheres.cover(box)  # read from disk: no construction
    assert np.array_equal(first.centres, again.centres)
    assert np.array_equal(first.radii, again.radii)
    # Other dimensions are another model.
    monkeypatch.undo()
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.setattr(spheres, "_memory", {})
    spheres.cover(coal.Box(0.2, 0.1, 0.41))
    assert len(list((tmp_path / "taskrunner" / "spheres").glob("*.npz"))) == 2


def test_a_damaged_cache_file_is_rebuilt(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.setattr(spheres, "_memory", {})
    box = coal.Box(0.3, 0.1, 0.1)
    first = spheres.cover(box)
    (path,) = (tmp_path / "taskrunner" / "spheres").glob("*.npz")
    path.write_bytes(b"not an npz file")
    monkeypatch.setattr(spheres, "_memory", {})
    again = spheres.cover(box)
    assert np.array_equal(first.radii, again.radii)


def _refuse(*args, **kwargs):  # type: ignore[no-untyped-def]
    raise AssertionError("the sphere model should have come from the cache")
