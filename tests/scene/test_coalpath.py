"""The checks with coal alone (what a planner uses while its kernels compile) say what the
compiled ones said on the recorded cases (``verdict_cases.py``), and a contact they report
is one."""

from __future__ import annotations

import json

import numpy as np
import pytest
from verdict_cases import FIXTURE, MARGIN, build_scene

from taskrunner.scene.coalpath import CoalPathVerifier, CoalScreen

_CASES = json.loads(FIXTURE.read_text())["cases"]


@pytest.mark.parametrize("case", _CASES, ids=[case["name"] for case in _CASES])
def test_coal_checks_give_the_recorded_verdicts_of_the_compiled_ones(case: dict) -> None:
    scene = build_scene(case)
    checker = scene.checker
    verifier = CoalPathVerifier(scene.robot, checker, MARGIN)
    names = [obj.name for obj in checker.geometry_model.geometryObjects]
    pair_index = {(names[p.first], names[p.second]): k
                  for k, p in enumerate(checker.geometry_model.collisionPairs)}
    for path, recorded in zip(case["paths"], case["expected"]["paths"], strict=True):
        found = verifier.verify(np.ascontiguousarray(path, dtype=float))
        assert found.valid == recorded["valid"]
        assert found.bounds == 0 and found.distance_queries > 0
        if not found.valid:
            # The contact named is one: that pair, at that state, within coal's tolerance.
            assert found.state is not None and found.pair is not None
            assert 0.0 <= found.fraction <= len(path) - 1
            distance = np.zeros(1)
            checker.pair_distances(scene.robot.to_pin(found.state), [pair_index[found.pair]],
                                   distance)
            assert distance[0] <= 1e-6
    scan = CoalScreen(scene.robot, checker).scanner()
    for q, recorded in zip(case["states"], case["expected"]["states"], strict=True):
        assert scan(np.ascontiguousarray(np.array(q, dtype=float)[None, :])) == recorded["row"]
    assert scan(np.ascontiguousarray(case["states"], dtype=float)) == \
        case["expected"]["rows"]["row"]


def test_a_path_through_an_obstacle_fails_at_its_first_contact_and_a_clear_one_passes() -> None:
    from taskrunner.resources import DATA_ROOT
    from taskrunner.robot import load_robot
    from taskrunner.scene import Scene
    from taskrunner.shapes import Box
    from taskrunner.types import Pose

    scene = Scene(load_robot(DATA_ROOT / "robots" / "servo_arm"))
    robot = scene.robot
    start = robot.state_with(scene.state, robot.named_state("arm", "home").as_dict())
    scene.set_state(start)
    end = start.copy()
    end[0] = start[0] + 1.5  # the base joint swings the arm around
    verifier = CoalPathVerifier(robot, scene.checker)
    clear = verifier.verify(np.vstack([start, end]))
    assert clear.valid and clear.states > 1
    # A wall across the swing, found along the path where the compiled verifier finds it.
    scene.set_state(start + 0.5 * (end - start))
    tip = scene.link_pose("tool0").xyz
    scene.set_state(start)
    scene.add_object("wall", Box((0.02, 0.02, 0.6)), Pose(tuple(float(v) for v in tip)))
    blocked = CoalPathVerifier(robot, scene.checker).verify(np.vstack([start, end]))
    compiled = scene.path_verifier().verify(np.vstack([start, end]))
    assert not blocked.valid and not compiled.valid
    assert "wall" in blocked.pair[1] or "wall" in blocked.pair[0]
    assert 0.0 < blocked.fraction < 1.0
    assert blocked.fraction == pytest.approx(compiled.fraction, abs=0.05)
    with pytest.raises(ValueError, match="state 1 of the path to verify is not finite"):
        verifier.verify(np.vstack([start, np.full_like(start, np.nan)]))
