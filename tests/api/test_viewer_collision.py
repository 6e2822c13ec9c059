"""The page's collision geometry (GET /viewer/cells/{id}/collision) is the planner's: each
shape placed in its link's frame lands where the collision core puts it, and hulls and
meshes carry their points and triangles."""

from __future__ import annotations

from pathlib import Path

import coal
import numpy as np
import pinocchio as pin

import taskrunner
from taskrunner.robot.cell import load_cell
from taskrunner.scene.geometry import link_bodies
from taskrunner.viewer.collision import _shape


def _se3(pose: dict) -> pin.SE3:
    x, y, z, w = pose["quat"]
    return pin.SE3(pin.Quaternion(w, x, y, z).matrix(), np.array(pose["xyz"]))


def test_each_shape_lands_where_the_collision_core_places_it(client):
    answer = client.get("/viewer/cells/servo_arm_pair/collision")
    assert answer.status_code == 200
    links = answer.json()["links"]
    cell = load_cell(Path(taskrunner.__file__).parent / "data" / "robots" / "cells" / "servo_arm_pair.yaml")
    model = cell.model
    rng = np.random.default_rng(0)
    q = pin.randomConfiguration(model.model, *_bounds(model.model, rng))
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, q)
    placements = {}
    for body in link_bodies(model):
        for k, geometry in enumerate(body.geometries):
            joint = data.oMi[geometry.parentJoint]
            placements[(body.name, k)] = joint * geometry.placement
    assert len(placements) == sum(len(link["shapes"]) for link in links) > 10
    for link in links:
        frame = data.oMf[model.model.getFrameId(link["link"])]
        assert link["kind"] == "primitive"
        for k, shape in enumerate(link["shapes"]):
            world = frame * _se3(shape["pose"])
            expected = placements[(link["link"], k)]
            assert np.allclose(world.translation, expected.translation, atol=2e-6)
            assert np.allclose(world.rotation, expected.rotation, atol=2e-5)
            assert shape["type"] in ("box", "cylinder")


def _bounds(model: pin.Model, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    lower = np.where(np.isfinite(model.lowerPositionLimit), model.lowerPositionLimit, -np.pi)
    upper = np.where(np.isfinite(model.upperPositionLimit), model.upperPositionLimit, np.pi)
    pin.seed(int(rng.integers(1 << 30)))
    return lower, upper


def test_an_unknown_cell_is_404(client):
    assert client.get("/viewer/cells/no_such_cell/collision").status_code == 404


def test_hulls_give_their_points_and_meshes_their_triangles_within_a_budget():
    box = coal.Box(0.1, 0.2, 0.3)
    assert _shape(box, [0]) == {"type": "box", "size": [0.1, 0.2, 0.3]}
    assert _shape(coal.Cylinder(0.05, 0.4), [0]) == {"type": "cylinder", "radius": 0.05, "length": 0.4}
    mesh = coal.BVHModelOBBRSS()
    vertices = np.array([[0, 0, 0], [0.1, 0, 0], [0, 0.2, 0], [0, 0, 0.3]], dtype=float)
    triangles = np.array([[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]])
    mesh.beginModel(4, 4)
    mesh.addVertices(vertices)
    mesh.addTriangles(triangles)
    mesh.endModel()
    budget = [10]
    sent = _shape(mesh, budget)
    assert sent["type"] == "mesh" and budget == [6]
    assert np.allclose(np.reshape(sent["vertices"], (-1, 3)), vertices)
    assert np.reshape(sent["triangles"], (-1, 3)).tolist() == triangles.tolist()
    mesh.buildConvexHull(False, "Qt")
    hull = _shape(mesh.convex, [0])
    assert hull["type"] == "hull"
    assert sorted(map(tuple, np.reshape(hull["points"], (-1, 3)).tolist())) == sorted(map(tuple, vertices.tolist()))
    # past the triangle budget: the mesh's bounding box, said so
    bounded = _shape(mesh, [3])
    assert bounded["type"] == "box" and bounded["bounded"] is True
    assert np.allclose(bounded["size"], [0.1, 0.2, 0.3]) and np.allclose(bounded["centre"], [0.05, 0.1, 0.15])
