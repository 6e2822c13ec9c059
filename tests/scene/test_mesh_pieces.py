"""A mesh's convex pieces hold its surface, and their bound never exceeds the mesh's distance."""

from __future__ import annotations

from pathlib import Path

import coal
import numpy as np
import pytest
from scipy.spatial import ConvexHull

from taskrunner.robot import RobotModel
from taskrunner.scene import Scene, mesh_pieces
from taskrunner.scene.mesh_pieces import cut_mesh


def _mesh(model: RobotModel, name: str) -> coal.BVHModelBase:
    objects = model.collision_model.geometryObjects
    found = [g.geometry for g in objects if g.name.rstrip("0123456789")[:-1] == name]
    assert found and isinstance(found[0], coal.BVHModelBase)
    return found[0]


def _arrays(mesh: coal.BVHModelBase) -> tuple[np.ndarray, np.ndarray]:
    vertices = np.array(mesh.vertices(), dtype=float)
    triangles = np.array([[mesh.tri_indices(i)[k] for k in range(3)]
                          for i in range(mesh.num_tris)], dtype=np.int64)
    return vertices, triangles


def test_pieces_hold_every_point_of_the_surface_and_hug_a_concave_link(
        ur5_model: RobotModel) -> None:
    vertices, triangles = _arrays(_mesh(ur5_model, "forearm_link"))
    pieces = cut_mesh(vertices, triangles)
    assert 1 < len(pieces) <= mesh_pieces.PIECES
    hulls = [ConvexHull(p) for p in pieces]
    # Points spread over every triangle (seeded), long triangles included.
    rng = np.random.default_rng(0)
    uv = rng.random((len(triangles), 6, 2))
    uv[uv.sum(axis=2) > 1.0] = 1.0 - uv[uv.sum(axis=2) > 1.0]
    corners = vertices[triangles]
    points = (corners[:, None, 0] + uv[..., :1] * (corners[:, None, 1] - corners[:, None, 0])
              + uv[..., 1:] * (corners[:, None, 2] - corners[:, None, 0])).reshape(-1, 3)
    points = np.vstack([points, vertices])
    # Outside a hull: beyond some face plane (normal . x + offset > 0).
    outside = np.array([(h.equations[:, :3] @ points.T + h.equations[:, 3:]).max(axis=0)
                        for h in hulls])
    assert (outside.min(axis=0) <= 1e-9).all()
    # The link bends: its pieces fill far less than its one hull does.
    assert sum(h.volume for h in hulls) < 0.7 * ConvexHull(vertices).volume


def test_no_pieces_for_what_cannot_be_cut() -> None:
    assert cut_mesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)) == []
    assert cut_mesh(np.array([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0], [0.0, 1.0, 0.0]]),
                    np.array([[0, 1, 2]])) == []
    # One small triangle: one piece of its three corners.
    flat = cut_mesh(np.eye(3) * 0.01, np.array([[0, 1, 2]]))
    assert len(flat) == 1 and len(flat[0]) == 3


def test_pieces_are_cut_once_and_read_back_from_disk(ur5_model: RobotModel, tmp_path: Path,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.setattr(mesh_pieces, "_memory", {})
    mesh = _mesh(ur5_model, "upper_arm_link")
    first = mesh_pieces.mesh_pieces(mesh)
    assert len(list((tmp_path / "taskrunner" / mesh_pieces.CACHE_FOLDER).glob("*.npz"))) == 1
    monkeypatch.setattr(mesh_pieces, "_memory", {})
    monkeypatch.setattr(mesh_pieces, "cut_mesh", lambda *args: pytest.fail("cut again"))
    again = mesh_pieces.mesh_pieces(mesh)
    assert len(again) == len(first)
    assert all(np.array_equal(a, b) for a, b in zip(again, first, strict=True))
    assert mesh_pieces.mesh_pieces(mesh) is again  # then from memory


def test_piece_bounds_stay_below_the_mesh_distances_and_clear_the_link_pairs(
        ur5_model: RobotModel) -> None:
    scene = Scene(ur5_model)
    verifier = scene.path_verifier()
    assert verifier._pieces is not None  # the UR5's links are checked as meshes, cut
    checker, to_pin = scene.checker, ur5_model.to_pin
    meshes = np.array([isinstance(checker.geometry_model.geometryObjects[g].geometry,
                                  coal.BVHModelBase) for g in range(verifier._objects)])
    both = meshes[verifier._first] & meshes[verifier._second]
    assert both.sum() >= 3
    hull_only = verifier.restricted()
    hull_only._pieces = None  # each mesh bounded by its one convex hull
    rng = np.random.default_rng(1)
    distances = np.zeros(len(verifier._first))
    cleared = {"pieces": 0, "hull": 0, "apart": 0}
    for _ in range(300):
        q = ur5_model.random_state(rng)
        checker.pair_distances(to_pin(q), verifier._pair_ids.tolist(), distances)
        bounds = verifier.support_bounds(q)
        assert (bounds <= np.maximum(distances, 0.0) + 1e-9).all()
        apart = both & (distances > 0.002) & (distances < 0.03)  # near, not touching
        cleared["apart"] += int(apart.sum())
        cleared["pieces"] += int((apart & (bounds > 0.0)).sum())
        cleared["hull"] += int((apart & (hull_only.support_bounds(q) > 0.0)).sum())
    # Two meshes a few millimetres apart (random states: mostly not folded, where the hull
    # is as good): their pieces show it far more often than their hulls.
    assert cleared["apart"] >= 20
    assert cleared["pieces"] >= 0.75 * cleared["apart"], cleared
    assert cleared["pieces"] >= cleared["hull"] + 0.1 * cleared["apart"], cleared
