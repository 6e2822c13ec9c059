"""benchmarks/planning_compare.py: its exact-mesh validator, and a smoke run of the
side-by-side benchmark (the figures are not asserted here)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

ROOT = Path(__file__).resolve().parents[2]
ARM = [f"panda_joint{i}" for i in range(1, 8)]
READY = [0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398]


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
    urdf, package_root = compare.panda_urdf()
    return compare.ExactValidator(urdf, package_root, compare.PANDA_SRDF)


def _state(values) -> dict[str, float]:
    state = dict(zip(ARM, values))
    state.update(panda_finger_joint1=0.04, panda_finger_joint2=0.04)
    return state


def _scene(compare, objects=(), allowed=()):
    return compare.SceneFile(Path("test_scene.yaml"), list(objects),
                             {frozenset(p) for p in allowed})


def test_lever_arm_bound_holds_for_every_vertex(validator) -> None:
    """No vertex of any geometry moves farther than the bound, over random steps."""
    model, geom = validator.model, validator.geom
    data = model.createData()
    rng = np.random.default_rng(5)
    arm = [model.getJointId(n) for n in ARM]
    vertices = [validator._vertices(g.geometry) for g in geom.geometryObjects]

    def world_vertices(q):
        pin.forwardKinematics(model, data, q)
        out = []
        for g, v in zip(geom.geometryObjects, vertices):
            m = data.oMi[g.parentJoint] * g.placement
            out.append(v @ m.rotation.T + m.translation)
        return out

    tight = 0.0
    for _ in range(40):
        q0 = pin.randomConfiguration(model)
        dq = np.zeros(model.nq)
        dq[[model.joints[j].idx_q for j in arm]] = rng.uniform(-0.05, 0.05, 7)
        q1 = q0 + dq
        bound = validator.lever[:, arm] @ np.abs(dq[[model.joints[j].idx_q for j in arm]])
        for k, (a, b) in enumerate(zip(world_vertices(q0), world_vertices(q1))):
            moved = float(np.max(np.linalg.norm(b - a, axis=1)))
            assert moved <= bound[k] + 1e-12, geom.geometryObjects[k].name
            tight = max(tight, moved / bound[k] if bound[k] else 0.0)
    assert tight > 0.3  # a bound, not a wild overestimate


def test_a_collision_between_free_waypoints_is_found(compare, validator) -> None:
    """Start and goal clear of a post; the straight segment between them sweeps the arm
    through it."""
    start, goal = READY.copy(), READY.copy()
    start[0], goal[0] = -1.2, 1.2
    model, data = validator.model, validator.model.createData()
    pin.framesForwardKinematics(model, data, validator.full_state(_state(READY)))
    hand = data.oMf[model.getFrameId("panda_hand")].translation
    post = ("post", "box", (0.05, 0.05, 0.2), pin.SE3(np.eye(3), hand))
    scene = _scene(compare, [post])
    path = np.array([start, goal])
    for q in (start, goal):  # the ends alone are free
        assert validator.check(scene, _state(q), ARM, np.array([q, q]), _state(q), 1e-3).valid
    verdict = validator.check(scene, _state(start), ARM, path, _state(goal), 1e-3)
    assert not verdict.valid
    assert "post" in verdict.reason and verdict.penetration > 0.01
    # Moved out of the sweep, the same path is free.
    far = ("post", "box", (0.05, 0.05, 0.2), pin.SE3(np.eye(3), hand * [-1, 1, 1]))
    assert validator.check(_scene(compare, [far]), _state(start), ARM, path, _state(goal), 1e-3).valid
    # An allowed pair is not checked.
    allowed = _scene(compare, [post], [(link, "post") for link in set(validator.links)])
    assert validator.check(allowed, _state(start), ARM, path, _state(goal), 1e-3).valid


def test_a_graze_of_a_millimetre_is_found_and_a_millimetre_of_clearance_passes(compare, validator) -> None:
    """A segment whose arm reaches farthest forward mid-way (brute force: the largest x of
    any vertex over 2001 states); a wall 1 mm inside that reach is hit, 1 mm beyond it is
    clear, and the clear verdict visits far fewer states than the 0.5 mm grid holds."""
    start, goal = READY.copy(), READY.copy()
    start[1], goal[1] = -0.6, 0.6
    start[3], goal[3] = -1.2, -2.6
    model, data, geom = validator.model, validator.model.createData(), validator.geom
    vertices = [validator._vertices(g.geometry) for g in geom.geometryObjects]
    reach, at = -np.inf, 0.0
    for t in np.linspace(0.0, 1.0, 2001):
        pin.forwardKinematics(model, data, validator.full_state(
            _state(np.add(start, t * np.subtract(goal, start)))))
        for g, v in zip(geom.geometryObjects, vertices):
            m = data.oMi[g.parentJoint] * g.placement
            x = float(np.max(v @ m.rotation.T[:, 0] + m.translation[0]))
            if x > reach:
                reach, at = x, t
    assert 0.2 < at < 0.8  # mid-segment: found only by interpolating
    path = np.array([start, goal])
    lever = validator.lever[:, [model.getJointId(n) for n in ARM]]
    grid = int(np.ceil(np.max(lever @ np.abs(np.subtract(goal, start))) / compare.RESOLUTION))
    for gap, expected in ((-0.001, False), (0.001, True)):
        wall = ("wall", "box", (0.02, 0.6, 1.0),
                pin.SE3(np.eye(3), np.array([reach + gap + 0.01, 0.0, 0.5])))
        verdict = validator.check(_scene(compare, [wall]), _state(start), ARM, path, _state(goal), 1e-3)
        assert verdict.valid is expected, verdict
        if expected:
            assert verdict.states < grid / 5
        else:
            assert "wall" in verdict.reason and 0.0 < verdict.penetration < 0.002


def test_paths_that_do_not_start_or_end_where_asked_are_invalid(compare, validator) -> None:
    scene = _scene(compare)
    start, goal = READY.copy(), READY.copy()
    goal[0] = 0.5
    path = np.array([start, goal])
    assert validator.check(scene, _state(start), ARM, path, _state(goal), 1e-3).valid
    moved_goal = _state(goal)
    moved_goal["panda_joint1"] = 0.51
    verdict = validator.check(scene, _state(start), ARM, path, moved_goal, 1e-3)
    assert not verdict.valid and "not the goal" in verdict.reason
    off = path.copy()
    off[0, 0] = 0.01
    assert "not the start" in validator.check(scene, _state(start), ARM, off, _state(goal), 1e-3).reason
    outside = np.array([start, [3.5, *goal[1:]], goal])
    assert "limits" in validator.check(scene, _state(start), ARM, outside, _state(goal), 1e-3).reason


def test_scene_file_reader_names_what_it_cannot_read(compare, tmp_path: Path) -> None:
    path = tmp_path / "scene.yaml"
    path.write_text("world:\n  collision_objects:\n    - id: mesh\n      header: {frame_id: world}\n"
                    "      meshes: [{triangles: []}]\n")
    with pytest.raises(ValueError, match=r"collision_objects\[0\]: meshes"):
        compare.read_scene_file(path, ["panda_link0"])
    path.write_text("world:\n  collision_objects:\n    - id: b\n      header: {frame_id: camera}\n")
    with pytest.raises(ValueError, match="frame 'camera'"):
        compare.read_scene_file(path, ["panda_link0"])


@pytest.mark.slow
def test_side_by_side_smoke_run(compare, tmp_path: Path) -> None:
    """Two problems of two classes, both planners when roboplan is installed (the bench
    extra), our planner alone otherwise."""
    with_roboplan = compare.rp_core is not None
    result = compare.run(2, ["table_pick", "box"], seed=1, problems=None, roboplan=with_roboplan,
                         problem_dir=tmp_path)
    sides = ["ours", "roboplan"] if with_roboplan else ["ours"]
    for name in ("table_pick", "box"):
        entry = result["classes"][name]
        for side in sides:
            stats = entry[side]
            assert stats["problems"] == 2 and stats["solved"] == 2, (side, stats)
            assert all(r["valid"] is not None for r in entry["runs"][side])
        assert entry["ours"]["invalid_paths"] == 0
        if with_roboplan:
            assert entry["ratio"] == pytest.approx(
                entry["ours"]["median_ms"] / entry["roboplan"]["median_ms"], rel=1e-2)
    lines = compare.table(result)
    assert any(line.startswith("table_pick") for line in lines)
