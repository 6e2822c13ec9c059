"""Smoke test of benchmarks/planning.py and its scenes (the figures are not asserted here)."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.kinematics import frame_pose
from taskrunner.planning import JointGoal, PoseGoal

REPO_ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def bench():
    spec = importlib.util.spec_from_file_location(
        "planning_bench", REPO_ROOT / "benchmarks" / "planning.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while being made
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def problems(bench, example_robot_data):
    return bench.planning_scenes.build_problems(count=2, seed=0)


def test_every_problem_has_valid_start_and_goal_states(bench, problems):
    scenes = bench.planning_scenes
    assert [p.name for p in problems] == list(scenes.PROBLEM_NAMES)
    for problem in problems:
        model = problem.scene.robot
        group = model.group(problem.group)
        assert len(problem.queries) == 2
        for query in problem.queries:
            assert scenes.is_valid_state(problem.scene, query.start), problem.name
            assert scenes.is_valid_state(problem.scene, query.goal_state), problem.name
            assert np.max(np.abs(query.goal_state[group.joint_indices]
                                 - query.start[group.joint_indices])) > 0.05, problem.name
            if isinstance(query.goal, JointGoal):
                values = [query.goal.values[n] for n in group.joint_names]
                assert values == pytest.approx(query.goal_state[group.joint_indices])
            else:
                assert isinstance(query.goal, PoseGoal)
                reached = frame_pose(model, query.goal_state, group.tip_link)
                assert reached.translation == pytest.approx(query.goal.pose.xyz, abs=1e-4)
                target = query.goal.pose.se3.rotation
                assert np.linalg.norm(pin.log3(reached.rotation.T @ target)) < 1e-4


def test_query_sets_depend_only_on_the_seed(bench):
    build = bench.planning_scenes.build_problems
    [a] = build(2, seed=3, names=["panda_shelf"])
    [b] = build(2, seed=3, names=["panda_shelf"])
    [c] = build(2, seed=4, names=["panda_shelf"])
    for qa, qb in zip(a.queries, b.queries):
        assert np.array_equal(qa.start, qb.start) and np.array_equal(qa.goal_state, qb.goal_state)
    assert not np.array_equal(a.queries[0].goal_state, c.queries[0].goal_state)
    # A problem's queries do not depend on which other problems are built with it.
    [_, d] = build(2, seed=3, names=["panda_box", "panda_shelf"])
    assert np.array_equal(a.queries[1].goal_state, d.queries[1].goal_state)


def test_one_query_per_problem_is_solved_and_reported_as_json(bench, example_robot_data):
    result = bench.run(quick=True, seed=0, queries=1)
    names = [row["name"] for row in result["problems"]]
    assert names == list(bench.planning_scenes.PROBLEM_NAMES)
    for row in result["problems"]:
        assert row["planner"] == "RRTConnect"
        assert row["success"] == 1.0, row
        assert row["bad_paths"] == 0
        assert row["median_ms"] > 0 and row["path_length_rad"] > 0
        if "duration_s" in row:
            assert row["duration_s"] > 0 and row["toppra_median_ms"] > 0
    targets = bench.check_targets(result)
    assert {t["name"] for t in targets} >= {"panda_shelf RRTConnect", "panda_cage RRTConnect",
                                            "servo_pair_swap RRTConnect"}
    table = bench.rows(result)
    assert table[0][:5] == ["problem", "planner", "success", "median ms", "p95 ms"]
    assert len(table) == len(names) + 1
    json.dumps(result)


def test_prm_is_never_given_several_goal_states(bench, problems):
    pose_problem = next(p for p in problems if p.name == "panda_table_pick_pose")
    joint_problem = next(p for p in problems if p.name == "panda_table_pick")
    assert bench._planners_for(pose_problem, ["PRM", "RRTConnect"]) == ["RRTConnect"]
    assert bench._planners_for(joint_problem, ["PRM", "RRTConnect"]) == ["PRM", "RRTConnect"]
