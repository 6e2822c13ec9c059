"""benchmarks/planning_compare.py on the robots of benchmarks/robots: the exact-mesh
validator's motion bound over a prismatic joint (TIAGo's torso lift), and a lift into an
object found."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

ROOT = Path(__file__).resolve().parents[2]
GROUP = ["torso_lift_joint"] + [f"arm_{i}_joint" for i in range(1, 8)]
READY = [0.15, 0.2, -1.34, -0.2, 1.94, -1.57, 1.37, 0.0]


@pytest.fixture(scope="module")
def compare(example_robot_data):
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import planning_compare
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    return planning_compare


@pytest.fixture(scope="module")
def validator(compare):
    urdf, roots, srdf, _ = compare.robot_files("tiago")
    return compare.ExactValidator(urdf, roots, srdf)


def _state(values) -> dict[str, float]:
    return {**dict(zip(GROUP, values)), "head_1_joint": 0.0, "head_2_joint": 0.0}


def test_motion_bound_holds_over_the_torso_lift_and_the_arm(validator) -> None:
    model, geom = validator.model, validator.geom
    data = model.createData()
    rng = np.random.default_rng(2)
    joints = [model.getJointId(n) for n in GROUP]
    cols = [model.joints[j].idx_q for j in joints]
    vertices = [validator._vertices(g.geometry) for g in geom.geometryObjects]

    def world_vertices(q):
        pin.forwardKinematics(model, data, q)
        return [v @ (data.oMi[g.parentJoint] * g.placement).rotation.T
                + (data.oMi[g.parentJoint] * g.placement).translation
                for g, v in zip(geom.geometryObjects, vertices)]

    for _ in range(20):
        q0 = pin.randomConfiguration(model)
        dq = np.zeros(model.nq)
        dq[cols] = rng.uniform(-0.05, 0.05, len(cols))
        bound = validator.lever[:, joints] @ np.abs(dq[cols])
        for k, (a, b) in enumerate(zip(world_vertices(q0), world_vertices(q0 + dq))):
            assert float(np.max(np.linalg.norm(b - a, axis=1))) <= bound[k] + 1e-12


def test_a_torso_lift_into_a_board_above_the_head_is_found(compare, validator) -> None:
    model, data = validator.model, validator.model.createData()
    pin.forwardKinematics(model, data, validator.full_state(_state(READY)))
    gdata = pin.GeometryData(validator.geom)
    pin.updateGeometryPlacements(model, data, validator.geom, gdata)
    top = max(float(np.max(v @ m.rotation.T + m.translation, axis=0)[2]) for v, m in zip(
        (validator._vertices(g.geometry) for g in validator.geom.geometryObjects), gdata.oMg))
    board = ("board", "box", (2.0, 2.0, 0.02), pin.SE3(np.eye(3), np.array([0, 0, top + 0.06])))
    scene = compare.SceneFile(Path("board.yaml"), [board], set())
    low, high = list(READY), list(READY)
    high[0] = 0.18
    verdict = validator.check(scene, _state(low), GROUP, np.array([low, high]), _state(high), 1e-3)
    assert verdict.valid  # 3 cm of lift: 2 cm of clearance left
    high[0] = 0.35
    verdict = validator.check(scene, _state(low), GROUP, np.array([low, high]), _state(high), 1e-3)
    assert not verdict.valid and "board" in verdict.reason
