"""example-robot-data: its URDFs load directly with ``load_robot(path_to_urdf)``, and every
robot of it that ships an SRDF loads unchanged (warnings allowed) from a manifest naming
its own files, and plans between every pair of its collision-free named poses."""

from __future__ import annotations

import itertools
import logging
import re
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import MissingMeshError, PlanningError, RobotDescriptionError
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import NamedGoal, PlannerOptions, PlanRequest
from taskrunner.robot import load_description, load_robot
from taskrunner.scene import Scene

SO_ARM_JOINTS = ("shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll", "gripper")


@pytest.fixture(scope="module")
def erd_robots(example_robot_data):
    return example_robot_data / "robots"


def test_panda_urdf_loads_with_its_mimic_finger(erd_robots):
    m = load_robot(erd_robots / "panda_description" / "urdf" / "panda.urdf")
    assert m.joint_names == (
        *(f"panda_joint{i}" for i in range(1, 8)),
        "panda_finger_joint1",
        "panda_finger_joint2",
    )
    assert m.joint("panda_finger_joint2").mimic.source == "panda_finger_joint1"
    assert m.groups == {}  # its SRDF is in srdf/, not beside the URDF
    assert m.has_link("panda_hand_tcp")
    assert m.collision_model.ngeoms > 0
    # No SRDF, so no collision matrix: its default state touches itself, as in MoveIt.
    assert len(m.warnings) == 1
    assert "the default state (every joint at 0, clipped to its limits) is in self-collision (" in m.warnings[0]
    assert "run `run-task collision-matrix ROBOT --write SRDF`" in m.warnings[0]


def test_ur5_robot_urdf_loads(erd_robots):
    m = load_robot(erd_robots / "ur_description" / "urdf" / "ur5_robot.urdf")
    assert m.nq == 6
    assert m.joint_names[0] == "shoulder_pan_joint" and m.joint_names[-1] == "wrist_3_joint"
    assert m.has_link("tool0")
    assert np.all(np.isfinite(m.lower))


def test_so101_urdf_loads_and_drops_its_transmissions(erd_robots):
    path = erd_robots / "so_arm_description" / "urdf" / "so101.urdf"
    assert "<transmission" in path.read_text()
    description = load_description(path)
    assert description.urdf.root.find("transmission") is None
    m = load_robot(path)
    assert set(m.joint_names) == set(SO_ARM_JOINTS)
    assert all(j.type == "revolute" for j in m.joints)
    assert m.collision_model.ngeoms > 0


def test_so100_urdf_with_a_link_and_a_joint_of_the_same_name_loads(erd_robots):
    m = load_robot(erd_robots / "so_arm_description" / "urdf" / "so100.urdf")
    assert set(m.joint_names) == set(SO_ARM_JOINTS)
    assert m.has_link("gripper")


def test_so100_description_reads_and_drops_its_transmissions(erd_robots):
    """so100 names a link and a joint 'gripper': both survive reading."""
    description = load_description(erd_robots / "so_arm_description" / "urdf" / "so100.urdf")
    assert description.urdf.root.find("transmission") is None
    assert "gripper" in description.urdf.links and "gripper" in description.urdf.joints
    assert description.srdf is None


# ----------------------------------------------------------------- every robot with an SRDF
# Each SRDF of the package with the URDF it describes (folder-relative paths). An SRDF's
# URDF shares its stem, else the table says which one (same <robot name>).
SRDF_URDF = {
    "a1_description/srdf/a1.srdf": "a1_description/urdf/a1.urdf",
    "alex_description/srdf/alex_nub_hands.srdf": "alex_description/urdf/alex_nub_hands.urdf",
    "alex_description/srdf/alex_psyonic_hands.srdf": "alex_description/urdf/alex_psyonic_hands.urdf",
    "alex_description/srdf/alex_sake_hands.srdf": "alex_description/urdf/alex_sake_hands.urdf",
    "alexander_description/srdf/alexander.srdf":
        "alexander_description/urdf/alexander_v1.lowerBodyOnly.urdf",
    "anymal_b_simple_description/srdf/anymal-kinova.srdf":
        "anymal_b_simple_description/robots/anymal-kinova.urdf",
    "anymal_b_simple_description/srdf/anymal.srdf": "anymal_b_simple_description/robots/anymal.urdf",
    "anymal_c_simple_description/srdf/anymal.srdf": "anymal_c_simple_description/urdf/anymal.urdf",
    "b1_description/srdf/b1-z1.srdf": "b1_description/urdf/b1-z1.urdf",
    "b1_description/srdf/b1.srdf": "b1_description/urdf/b1.urdf",
    "baxter_description/srdf/baxter_manipulation.srdf": "baxter_description/urdf/baxter.urdf",
    "bolt_description/srdf/bolt.srdf": "bolt_description/robots/bolt.urdf",
    "borinot_description/srdf/borinot_flying_arm_2.srdf":
        "borinot_description/urdf/borinot_flying_arm_2.urdf",
    "centauro_description/srdf/centauro.srdf": "centauro_description/urdf/centauro.urdf",
    "finger_edu_description/srdf/finger_edu.srdf": "finger_edu_description/robots/finger_edu.urdf",
    "go1_description/srdf/go1.srdf": "go1_description/urdf/go1.urdf",
    "go2_description/srdf/go2.srdf": "go2_description/urdf/go2.urdf",
    "hextilt_description/srdf/hextilt_flying_arm_5.srdf":
        "hextilt_description/urdf/hextilt_flying_arm_5.urdf",
    "hyq_description/srdf/hyq.srdf": "hyq_description/robots/hyq_no_sensors.urdf",
    "icub_description/srdf/icub.srdf": "icub_description/robots/icub.urdf",
    "kinova_description/srdf/kinova.srdf": "kinova_description/robots/kinova.urdf",
    "panda_description/srdf/panda.srdf": "panda_description/urdf/panda.urdf",
    "pr2_description/srdf/pr2.srdf": "pr2_description/urdf/pr2.urdf",
    "pr2_description/srdf/pr2_manipulation.srdf": "pr2_description/urdf/pr2.urdf",
    "romeo_description/srdf/romeo.srdf": "romeo_description/urdf/romeo.urdf",
    "romeo_description/srdf/romeo_moveit.srdf": "romeo_description/urdf/romeo.urdf",
    "romeo_description/srdf/romeo_small.srdf": "romeo_description/urdf/romeo_small.urdf",
    "simple_humanoid_description/srdf/simple_humanoid.srdf":
        "simple_humanoid_description/urdf/simple_humanoid.urdf",
    "simple_humanoid_description/srdf/simple_humanoid_classical.srdf":
        "simple_humanoid_description/urdf/simple_humanoid_classical.urdf",
    "solo_description/srdf/solo.srdf": "solo_description/robots/solo.urdf",
    "talos_data/srdf/talos.srdf": "talos_data/robots/talos_full_v2.urdf",
    "ur_description/srdf/ur3_gripper.srdf": "ur_description/urdf/ur3_gripper.urdf",
    "ur_description/srdf/ur5.srdf": "ur_description/urdf/ur5_robot.urdf",
    "ur_description/srdf/ur5_gripper.srdf": "ur_description/urdf/ur5_gripper.urdf",
    "ur_description/srdf/ur5_joint_limited_robot.srdf":
        "ur_description/urdf/ur5_joint_limited_robot.urdf",
    "xarm_description/srdf/xarm7.srdf": "xarm_description/urdf/xarm7.urdf",
    "z1_description/srdf/z1.srdf": "z1_description/urdf/z1.urdf",
}
# Robots MoveIt cannot load either (urdfdom refuses a revolute joint without <limit>, or a
# <limit> without effort= and velocity=): none in the package. Centauro's wheels give a
# <limit> with no lower= or upper=: URDF's default 0 for both, so they cannot move (a
# located warning each), as MoveIt loads them.
REFUSED: dict[str, str] = {}
# Ships its SRDF with an SDF model only (no URDF).
WITHOUT_URDF = {"cassie_description/srdf/cassie_v2.srdf"}
# URDFs without a single <collision> (dynamics models): refused unless explicitly allowed.
NO_COLLISION_GEOMETRY = {"alexander_description/srdf/alexander.srdf",
                         "simple_humanoid_description/srdf/simple_humanoid_classical.srdf"}


def test_the_table_names_every_srdf_of_the_package(erd_robots):
    found = {str(p.relative_to(erd_robots)) for p in erd_robots.rglob("*.srdf")}
    assert found == set(SRDF_URDF) | WITHOUT_URDF
    assert all((erd_robots / urdf).is_file() for urdf in SRDF_URDF.values())


@pytest.mark.slow
@pytest.mark.parametrize("srdf", sorted(SRDF_URDF))
def test_robot_with_an_srdf_loads_and_plans_between_its_named_poses(
        erd_robots, tmp_path, srdf, caplog):
    caplog.set_level(logging.ERROR)  # the warnings are the model's, checked below
    (tmp_path / "robot.yaml").write_text(
        f"name: {Path(srdf).stem}\nurdf: {erd_robots / SRDF_URDF[srdf]}\n"
        f"srdf: {erd_robots / srdf}\n")
    if srdf in REFUSED:
        with pytest.raises(RobotDescriptionError, match=re.escape(REFUSED[srdf])):
            load_robot(tmp_path)
        return
    if srdf in NO_COLLISION_GEOMETRY:
        with pytest.raises(MissingMeshError, match="has no collision geometry at all"):
            load_robot(tmp_path)
        model = load_robot(tmp_path, allow_missing_meshes=True)
        assert "has no collision geometry at all (--allow-missing-meshes)" in model.warnings[0]
    else:
        model = load_robot(tmp_path)
    assert model.nq > 0
    assert all(isinstance(w, str) and w for w in model.warnings)
    scene = Scene(model)
    planner = MotionPlanner(scene)
    start = model.default_state()
    if model.initial_values:
        start = model.state_with(start, model.initial_values)
    failures = []
    for group, poses in model.named_states.items():
        if not model.groups[group].joint_names:
            continue  # an SRDF group whose members are all missing (hyq, solo): a warning
        aliases = model.pose_aliases.get(group, {})
        states = {name: model.state_with(start, model.named_state(group, name))
                  for name in poses if name not in aliases}
        free = [name for name, q in states.items() if not scene.in_collision(q)]
        for a, b in itertools.permutations(free, 2):
            request = PlanRequest(group, NamedGoal(b), start=states[a],
                                  options=PlannerOptions(seed=0, planning_time=5.0))
            try:
                result = planner.plan(request)
            except PlanningError as exc:
                failures.append(f"{group}: {a} -> {b}: {exc}")
                continue
            reached = model.state_with(start, dict(zip(result.path.names,
                                                       result.path.waypoints[-1])))
            np.testing.assert_allclose(reached[model.group(group).joint_indices],
                                       states[b][model.group(group).joint_indices], atol=1e-6)
    assert not failures, failures
