"""Conservative sphere models: every point of the geometry the exact check tests lies in
the union of its spheres (meshes: every vertex and dense samples of every face; solids:
samples of the surface and the inside), the looseness is what a denser measurement finds,
and fits are cached by content."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import coal
import numpy as np
import pinocchio as pin
import pytest

from taskrunner.collision import spheres
from taskrunner.collision.link_spheres import robot_spheres
from taskrunner.collision.sphere_primitives import primitive_distance
from taskrunner.collision.spheres import SphereOptions, fit_spheres, geometry_key
from taskrunner.errors import ArgumentError, SceneError
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import load_robot
from taskrunner.robot.packages import example_robot_data_dir

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
COARSE = SphereOptions(tolerance=0.02, max_spheres=16)


@pytest.fixture(autouse=True, scope="module")
def _own_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """A cache folder of this module's own, and the memory cache emptied: fits made here
    are shared by its tests (the Panda's are made once), never read from the user's."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("XDG_CACHE_HOME", str(tmp_path_factory.mktemp("cache")))
        patch.setattr(spheres, "_memory", {})
        patch.setattr(spheres, "_disk_loaded", set())
        yield


def _surface_samples(geometry: coal.CollisionGeometry, per_m2: float, rng: np.random.Generator
                     ) -> np.ndarray:
    """Every vertex, every edge's midpoint, and points spread by area over every face."""
    vertices, triangles = spheres._mesh_arrays(geometry)
    corners = vertices[triangles]
    areas = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0],
                                          corners[:, 2] - corners[:, 0]), axis=1)
    n = min(int(per_m2 * areas.sum()), 60_000) + 1
    faces = rng.choice(len(corners), n, p=areas / areas.sum())
    uv = rng.random((n, 2))
    flip = uv.sum(axis=1) > 1
    uv[flip] = 1 - uv[flip]
    c = corners[faces]
    inner = c[:, 0] + uv[:, :1] * (c[:, 1] - c[:, 0]) + uv[:, 1:] * (c[:, 2] - c[:, 0])
    middles = 0.5 * (corners + np.roll(corners, 1, axis=1)).reshape(-1, 3)
    return np.concatenate([vertices, middles, inner])


def _solid_samples(geometry: coal.CollisionGeometry, n: int, rng: np.random.Generator
                   ) -> np.ndarray:
    """Points inside the solid and on its surface (inside points pushed out to it)."""
    kind, dims = spheres._primitive(geometry)
    geometry.computeLocalAABB()
    lo, hi = np.array(geometry.aabb_local.min_), np.array(geometry.aabb_local.max_)
    points = lo + (hi - lo) * rng.random((n, 3))
    inside = points[primitive_distance(kind, dims, points) <= 0]
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                        for z in (lo[2], hi[2])])
    if kind == "box":  # the surface: each sample pushed to the nearest face, and the corners
        axis = np.argmin(np.abs(np.abs(inside) - dims), axis=1)
        surface = inside.copy()
        surface[np.arange(len(inside)), axis] = np.sign(inside[np.arange(len(inside)), axis]) * \
            np.array(dims)[axis]
        return np.concatenate([inside, surface, corners])
    if kind == "cylinder":
        radius, half = dims
        rim = inside.copy()
        rim[:, :2] *= radius / np.maximum(np.hypot(rim[:, 0], rim[:, 1]), 1e-12)[:, None]
        cap = inside.copy()
        cap[:, 2] = np.sign(cap[:, 2]) * half
        return np.concatenate([inside, rim, cap])
    if kind == "capsule":  # pushed out from the nearest point of the axis segment
        radius, half = dims
        axis = np.zeros_like(inside)
        axis[:, 2] = np.clip(inside[:, 2], -half, half)
        out = inside - axis
        out *= radius / np.maximum(np.linalg.norm(out, axis=1), 1e-12)[:, None]
        return np.concatenate([inside, axis + out])
    return np.concatenate([inside, inside / np.linalg.norm(inside, axis=1)[:, None] * dims[0]])


def _check_covered(geometry: coal.CollisionGeometry, options: SphereOptions,
                   rng: np.random.Generator) -> spheres.GeometrySpheres:
    fit = fit_spheres(geometry, options)
    if fit.kind == "mesh":
        points = _surface_samples(geometry, 2e6, rng)  # ~2 points per mm^2
    else:
        points = _solid_samples(geometry, 20000, rng)
    uncovered = points[~fit.contains(points)]
    assert len(uncovered) == 0, f"{len(uncovered)} of {len(points)} points outside, e.g. {uncovered[0]}"
    assert fit.looseness >= 0 and np.all(fit.radii > 0)
    return fit


@pytest.mark.parametrize("robot", ["panda", "servo_arm", "so101"])
def test_every_geometry_of_a_robot_is_inside_its_spheres(robot: str) -> None:
    rng = np.random.default_rng(1)
    model = load_robot(DATA_ROOT / "robots" / robot)
    links = set()
    for g in model.collision_model.geometryObjects:
        _check_covered(g.geometry, COARSE if robot == "panda" else SphereOptions(), rng)
        links.add(model.model.frames[g.parentFrame].name)
    if robot == "panda":
        assert {"panda_hand", "panda_leftfinger", "panda_rightfinger"} <= links


def test_ur5_robotiq_gripper_and_wrist_mesh_are_inside_their_spheres() -> None:
    rng = np.random.default_rng(2)
    model = load_robot(FIXTURES / "motionbenchmaker" / "ur5_robotiq")
    frames = model.model.frames
    wanted = [g for g in model.collision_model.geometryObjects
              if frames[g.parentFrame].name.startswith("robotiq")
              or frames[g.parentFrame].name == "wrist_3_link"]
    assert any(isinstance(g.geometry, coal.BVHModelBase) for g in wanted)
    assert sum(frames[g.parentFrame].name.startswith("robotiq") for g in wanted) >= 7
    for g in wanted:
        _check_covered(g.geometry, COARSE, rng)


def test_a_mobile_manipulators_hand_and_torso_are_inside_their_spheres() -> None:
    """TIAGo (example-robot-data): a Fetch-like robot with a torso lift, a head and a hand
    of many small meshes."""
    import warnings

    share = example_robot_data_dir()
    if share is None:
        pytest.skip("the example-robot-data wheel is not installed")
    urdf = share / "robots" / "tiago_description" / "robots" / "tiago.urdf"
    model = pin.buildModelFromUrdf(str(urdf))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        geometry = pin.buildGeomFromUrdf(model, str(urdf), pin.COLLISION, [str(share.parent)])
    rng = np.random.default_rng(7)
    wanted = [g for g in geometry.geometryObjects
              if model.frames[g.parentFrame].name.startswith(("hand_", "torso_lift"))]
    assert sum(isinstance(g.geometry, coal.BVHModelBase) for g in wanted) >= 10
    for g in wanted:
        _check_covered(g.geometry, COARSE, rng)


def test_the_hulls_the_planner_checks_are_covered_as_solids() -> None:
    """Under ``collision: auto`` the Panda's links are checked as their convex hulls, which
    coal treats as solids: every point inside a hull, and on it, is in its spheres."""
    from taskrunner.scene.linkgeometry import HULL, link_hull, plan_link_geometry

    model = load_robot(DATA_ROOT / "robots" / "panda")
    plan = plan_link_geometry(model, "auto")
    objects = model.collision_model.geometryObjects
    shapes = [link_hull(model, i) if plan.kind(model.model.frames[g.parentFrame].name) == HULL
              else g.geometry for i, g in enumerate(objects)]
    hulls = [i for i, shape in enumerate(shapes) if isinstance(shape, coal.ConvexBase)]
    assert hulls
    model_spheres = robot_spheres(model, COARSE, shapes)
    rng = np.random.default_rng(8)
    for i in hulls:
        hull, fit = shapes[i], model_spheres.fits[i]
        assert fit.kind == "solid"
        vertices, triangles = spheres._mesh_arrays(hull)
        lo, hi = vertices.min(axis=0), vertices.max(axis=0)
        points = lo + (hi - lo) * rng.random((20000, 3))
        # Inside: behind every face's plane (Qhull's faces are not wound alike: each
        # normal is turned away from the centroid).
        corners = vertices[triangles]
        normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        normal *= np.sign(np.einsum("ij,ij->i", normal, corners[:, 0] - vertices.mean(axis=0)))[:, None]
        offset = np.einsum("ij,ij->i", normal, corners[:, 0])
        inside = points[np.all(points @ normal.T <= offset, axis=1)]
        surface = _surface_samples(hull, 2e5, rng)
        assert len(inside) > 2000
        assert fit.contains(np.concatenate([inside, surface])).all()
    with pytest.raises(ArgumentError, match="'shapes' must hold one geometry per collision"):
        robot_spheres(model, COARSE, shapes[:-1])


@pytest.mark.parametrize("shape", [
    coal.Box(0.3, 0.2, 0.01),        # a thin slab
    coal.Box(0.005, 0.005, 0.4),     # a rod
    coal.Cylinder(0.2, 0.02),        # a wide disc: a grid of cells
    coal.Cylinder(0.015, 0.3),       # a thin one: a chain on its axis
    coal.Capsule(0.03, 0.25),
    coal.Sphere(0.07),
], ids=["slab", "rod", "disc", "thin-cylinder", "capsule", "sphere"])
def test_primitive_solids_are_inside_their_spheres(shape: coal.CollisionGeometry) -> None:
    _check_covered(shape, SphereOptions(), np.random.default_rng(3))


@pytest.mark.parametrize("shape", [coal.Box(0.3, 0.2, 0.01), coal.Cylinder(0.2, 0.02),
                                   coal.Capsule(0.03, 0.25)], ids=["box", "cylinder", "capsule"])
def test_one_sphere_when_only_one_is_allowed(shape: coal.CollisionGeometry) -> None:
    fit = _check_covered(shape, SphereOptions(max_spheres=1), np.random.default_rng(9))
    assert len(fit) == 1


def test_looseness_is_what_a_denser_measurement_finds() -> None:
    for shape in (coal.Box(0.1, 0.06, 0.02), coal.Cylinder(0.05, 0.2)):
        fit = fit_spheres(shape, SphereOptions(tolerance=0.008))
        kind, dims = spheres._primitive(shape)
        unit = np.random.default_rng(4).normal(size=(4000, 3))
        unit /= np.linalg.norm(unit, axis=1)[:, None]
        probes = np.concatenate([c + r * unit for c, r in zip(fit.centres, fit.radii, strict=True)])
        probes = probes[~fit.contains(probes, slack=-1e-7)]  # on the union's surface only
        dense = float(primitive_distance(kind, dims, probes).max())
        assert fit.looseness <= dense + 1e-9  # an estimate from fewer probes: never more
        assert fit.looseness >= dense - 0.002
    box = fit_spheres(coal.Box(0.1, 0.06, 0.02), SphereOptions(tolerance=0.005, max_spheres=200))
    assert box.looseness <= 0.005


def test_a_mesh_fits_looseness_bounds_how_far_its_spheres_reach_out() -> None:
    model = load_robot(DATA_ROOT / "robots" / "panda")
    hand = next(g for g in model.collision_model.geometryObjects
                if model.model.frames[g.parentFrame].name == "panda_hand").geometry
    fit = fit_spheres(hand, COARSE)
    vertices, triangles = spheres._mesh_arrays(hand)
    unit = np.random.default_rng(6).normal(size=(400, 3))
    unit /= np.linalg.norm(unit, axis=1)[:, None]
    probes = np.concatenate([c + r * unit for c, r in zip(fit.centres, fit.radii, strict=True)])
    probes = probes[~fit.contains(probes, slack=-1e-7)]  # on the union's surface
    outside = probes[np.abs(spheres._winding(probes, vertices, triangles)) < 0.5]
    reach = spheres._distances(hand, outside)
    assert len(outside) > 100
    assert reach.max() <= fit.looseness
    assert reach.max() >= 0.5 * fit.looseness  # a bound, not a wild one


def test_a_mesh_fit_meets_its_tolerance_with_more_spheres() -> None:
    model = load_robot(DATA_ROOT / "robots" / "panda")
    hand = next(g for g in model.collision_model.geometryObjects
                if model.model.frames[g.parentFrame].name == "panda_hand").geometry
    coarse = fit_spheres(hand, SphereOptions(tolerance=0.03, max_spheres=64))
    fine = fit_spheres(hand, SphereOptions(tolerance=0.012, max_spheres=64))
    assert len(fine) > len(coarse)
    assert fine.looseness < coarse.looseness
    assert coarse.looseness <= 0.03 and fine.looseness <= 0.012


def test_fits_are_cached_by_content_not_by_object() -> None:
    a, b = coal.Box(0.1, 0.2, 0.3), coal.Box(0.1, 0.2, 0.3)
    assert fit_spheres(a) is fit_spheres(b)
    assert geometry_key(a) != geometry_key(coal.Box(0.1, 0.2, 0.31))
    assert geometry_key(a) != geometry_key(a, SphereOptions(tolerance=0.02))

    tetrahedron = [[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1]]
    mesh, copy = _mesh(tetrahedron), _mesh(tetrahedron)
    assert fit_spheres(mesh) is fit_spheres(copy)
    assert geometry_key(_mesh([[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.101]])) != \
        geometry_key(mesh)


def _mesh(vertices: list[list[float]]) -> coal.BVHModelOBBRSS:
    mesh = coal.BVHModelOBBRSS()
    mesh.beginModel(4, 4)
    mesh.addVertices(np.array(vertices, dtype=float))
    mesh.addTriangles(np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    mesh.endModel()
    return mesh


def test_a_second_process_reads_the_fit_from_disk(monkeypatch: pytest.MonkeyPatch) -> None:
    first = fit_spheres(coal.Cylinder(0.04, 0.3))
    assert (Path(os.environ["XDG_CACHE_HOME"]) / "taskrunner" / spheres.CACHE_FILE).is_file()
    monkeypatch.setattr(spheres, "_memory", {})
    monkeypatch.setattr(spheres, "_disk_loaded", set())

    def refit(*args: object) -> None:
        raise AssertionError("fitted again instead of read from the cache")

    monkeypatch.setattr(spheres, "fit_primitive", refit)
    again = fit_spheres(coal.Cylinder(0.04, 0.3))
    np.testing.assert_array_equal(again.centres, first.centres)
    np.testing.assert_array_equal(again.radii, first.radii)
    assert again.looseness == first.looseness


def test_robot_spheres_contain_the_hand_at_a_configuration() -> None:
    model = load_robot(DATA_ROOT / "robots" / "panda")
    model_spheres = robot_spheres(model, COARSE)
    assert len(model_spheres.spheres) == sum(len(f) for f in model_spheres.fits)
    q = model.default_state()
    rng = np.random.default_rng(5)
    lower, upper = model.model.lowerPositionLimit, model.model.upperPositionLimit
    pin_q = model.to_pin(q)
    pin_q[:7] = lower[:7] + (upper[:7] - lower[:7]) * rng.random(7)
    q = model.from_pin(pin_q)
    centres, radii = model_spheres.world_spheres(model, q)
    data = model.model.createData()
    pin.forwardKinematics(model.model, data, model.to_pin(q))
    for index, g in enumerate(model.collision_model.geometryObjects):
        if model.model.frames[g.parentFrame].name != "panda_hand":
            continue
        placed = data.oMi[g.parentJoint] * g.placement
        local = _surface_samples(g.geometry, 2e5, rng)
        world = local @ placed.rotation.T + placed.translation
        mine = model_spheres.spheres["geometry"] == index
        gap = np.linalg.norm(world[:, None] - centres[mine][None], axis=2) - radii[mine][None]
        assert np.all(gap.min(axis=1) <= 1e-9)


def test_shapes_without_a_model_and_bad_options_are_refused() -> None:
    with pytest.raises(SceneError, match="Cone"):
        fit_spheres(coal.Cone(0.1, 0.2))
    with pytest.raises(ArgumentError, match="'tolerance' must be a positive length"):
        SphereOptions(tolerance=0.0)
    with pytest.raises(ArgumentError, match="'max_spheres' must be an integer >= 1"):
        SphereOptions(max_spheres=0)
