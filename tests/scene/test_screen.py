"""The search's screened state check gives the checker's verdict on every state."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.scene.screen import StateScreen
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.types import Pose


def _screen(scene: Scene) -> StateScreen:
    return StateScreen(scene.path_verifier())


def _boundary_states(scene: Scene, rng: np.random.Generator, count: int) -> np.ndarray:
    """States 1e-4 rad (max over joints) either side of where a random free state's
    straight line to a colliding one first collides: bodies a fraction of a millimetre
    apart or into each other, the hardest states for a screen."""
    robot = scene.robot
    out = []
    tries = 0
    while len(out) < count and tries < 50 * count:
        tries += 1
        a, b = robot.random_state(rng), robot.random_state(rng)
        if scene.in_collision(a) or not scene.in_collision(b):
            continue
        lo, hi = 0.0, 1.0
        while np.max(np.abs(b - a)) * (hi - lo) > 1e-5:
            mid = 0.5 * (lo + hi)
            if scene.in_collision(robot.apply_mimic(a + mid * (b - a))):
                hi = mid
            else:
                lo = mid
        step = 1e-4 / np.max(np.abs(b - a))
        out += [robot.apply_mimic(a + (lo - step) * (b - a)),
                robot.apply_mimic(a + min(1.0, hi + step) * (b - a))]
    assert len(out) >= count  # the scene has obstacles to find
    return np.array(out)


def _agrees(scene: Scene, states: np.ndarray) -> None:
    screen = _screen(scene)
    checker, to_pin = scene.checker, scene.robot.to_pin
    # Within coal's tolerance of touching, coal's verdict depends on its warm start (the
    # pair checked before): compare the states where its broadphase path and its report
    # (every pair, other data) agree.
    stable = [checker.in_collision(to_pin(q)) == bool(checker.collisions(to_pin(q)))
              for q in states]
    assert sum(stable) > 0.9 * len(states)
    states = states[np.array(stable)]
    verdicts = [checker.in_collision(to_pin(q)) for q in states]
    screened = [screen.first_in_collision(np.ascontiguousarray(q[None, :])) == 0 for q in states]
    assert screened == verdicts
    assert any(verdicts) and not all(verdicts)
    # Rows: the first in collision, as the checker finds it.
    for start in range(0, len(states) - 8, 7):
        rows = np.ascontiguousarray(states[start:start + 8])
        assert screen.first_in_collision(rows) == checker.first_in_collision(to_pin(rows))


def _panda_cell(panda_model: RobotModel) -> Scene:
    scene = Scene(panda_model)
    scene.add_object("table", Box((1.2, 1.2, 0.04)), Pose((0.3, 0.0, -0.02)))
    scene.allow_collision("panda_link0", "table")
    scene.add_object("post", Cylinder(0.04, 0.5), Pose((0.45, -0.25, 0.25)))
    scene.add_object("ball", Sphere(0.06), Pose((0.35, 0.3, 0.45)))
    tilted = pin.SE3(pin.rpy.rpyToMatrix(0.2, 0.1, 0.3), np.array([0.6, 0.0, 0.35]))
    scene.add_object("shelf", Box((0.3, 0.6, 0.02)), Pose.from_se3(tilted))
    return scene


def test_panda_cell_with_boxes_cylinder_and_ball(panda_model: RobotModel) -> None:
    scene = _panda_cell(panda_model)
    rng = np.random.default_rng(3)
    random = np.array([panda_model.random_state(rng) for _ in range(300)])
    _agrees(scene, np.vstack([random, _boundary_states(scene, rng, 60)]))


def test_an_object_in_the_hand_is_screened_with_the_hand(panda_model: RobotModel) -> None:
    scene = _panda_cell(panda_model)
    # Between the fingers, 10 cm out from the hand's frame.
    held = scene.link_pose("panda_hand").se3 * pin.SE3(np.eye(3), np.array([0.0, 0.0, 0.1]))
    scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose.from_se3(held), attach_to="panda_hand",
                     touch_links=("panda_hand", "panda_leftfinger", "panda_rightfinger"))
    rng = np.random.default_rng(4)
    random = np.array([panda_model.random_state(rng) for _ in range(300)])
    _agrees(scene, np.vstack([random, _boundary_states(scene, rng, 40)]))


def test_ur5_and_servo_arm_alone(ur5_model: RobotModel, servo_arm_model: RobotModel) -> None:
    for model, seed in ((ur5_model, 5), (servo_arm_model, 6)):
        scene = Scene(model)
        rng = np.random.default_rng(seed)
        random = np.array([model.random_state(rng) for _ in range(300)])
        _agrees(scene, np.vstack([random, _boundary_states(scene, rng, 30)]))


@pytest.mark.parametrize("cell", ["panda_pair", "servo_arm_table"])
def test_shipped_cells(cell: str) -> None:
    scene = scene_from_cell(load_cell(DATA_ROOT / "robots" / "cells" / f"{cell}.yaml"))
    rng = np.random.default_rng(7)
    random = np.array([scene.robot.random_state(rng) for _ in range(200)])
    _agrees(scene, np.vstack([random, _boundary_states(scene, rng, 30)]))


def test_clear_states_never_reach_coal(panda_model: RobotModel) -> None:
    # The screen's point: where the bounding volumes clear every pair, coal is not asked.
    scene = _panda_cell(panda_model)
    screen = _screen(scene)
    asked = []
    narrow = scene.checker.pairs_collide

    def counting(q_pin: np.ndarray, pairs: np.ndarray) -> bool:
        asked.append(len(pairs))
        return narrow(q_pin, pairs)

    screen.checker = type("Counting", (), {"pairs_collide": staticmethod(counting),
                                           "first_in_collision": scene.checker.first_in_collision})()
    ready = panda_model.state_with(panda_model.default_state(),
                                   panda_model.named_state("arm_and_hand", "default"))
    rows = np.ascontiguousarray(np.repeat(ready[None, :], 5, axis=0))
    assert screen.first_in_collision(rows) == -1
    assert len(asked) < 5  # at most the states where a pair is within the volumes
    assert sum(asked) < scene.checker.pair_count


def test_line_scan_is_the_scan_of_the_interpolated_rows(panda_model: RobotModel) -> None:
    scene = _panda_cell(panda_model)
    screen = _screen(scene)
    scan, line = screen.scanner(), screen.line_scanner()
    arm = scene.robot.group("arm").joint_indices
    first = int(arm[0])
    assert np.array_equal(arm, np.arange(first, first + len(arm)))
    rng = np.random.default_rng(8)
    base = scene.state.copy()
    hits = []
    for _ in range(60):
        a, b = (panda_model.random_state(rng)[arm] for _ in range(2))
        fractions = np.concatenate([[1.0], rng.permutation(np.arange(1, 20)) / 20])
        rows = np.repeat(base[None, :], len(fractions), axis=0)
        for begin in (0, 1):
            expected = rows.copy()
            expected[:, first:first + len(arm)] = a + fractions[:, None] * (b - a)
            expected[0, first:first + len(arm)] = b
            hit = scan(np.ascontiguousarray(expected[begin:]))
            want = hit if hit < 0 else begin + hit
            got = line(rows, fractions, a, b, first, begin)
            assert got == want
            # The rows scanned hold their states (the one returned, and those before it).
            stop = len(rows) if got < 0 else got + 1
            assert np.array_equal(rows[begin:stop], expected[begin:stop])
            hits.append(got)
    assert any(h < 0 for h in hits) and any(h >= 0 for h in hits)


def test_segment_scan_counts_its_steps_and_is_the_line_scan_of_its_table_row(
        panda_model: RobotModel) -> None:
    scene = _panda_cell(panda_model)
    screen = _screen(scene)
    line = screen.line_scanner()
    arm = scene.robot.group("arm").joint_indices
    first = int(arm[0])
    rng = np.random.default_rng(10)
    base = scene.state.copy()
    resolution = 0.07
    table = np.zeros((41, 40))  # rows up to 40 steps, filled as they come
    segment = screen.segment_scanner(base, first, table, resolution)
    assert segment is not None
    seen = {"free": 0, "hit": 0, "unfilled": 0, "too long": 0}
    for _ in range(80):
        a = panda_model.random_state(rng)[arm]
        b = a + rng.choice([-1.0, 1.0]) * rng.uniform(0.0, 3.5, len(arm))
        steps = max(1, int(np.ceil(np.max(np.abs(b - a)) / resolution)))
        hit, counted = segment(a, b, 0)
        assert counted == steps
        if steps > 40:
            assert hit == -2
            seen["too long"] += 1
            continue
        if table[steps, 0] != 1.0:
            assert hit == -2  # the row is not filled yet
            seen["unfilled"] += 1
            table[steps, :steps] = np.concatenate([[1.0], rng.permutation(np.arange(1, steps))
                                                   / steps])
        fractions = table[steps, :steps].copy()
        for begin in (0, 1):
            rows = np.repeat(base[None, :], steps, axis=0)
            want = line(rows, fractions, a, b, first, begin) if begin < steps else -1
            got, counted = segment(a, b, begin)
            assert (got, counted) == (want, steps)
            seen["free" if got < 0 else "hit"] += 1
    assert all(count > 0 for count in seen.values()), seen
    with pytest.raises(ValueError, match="row of fractions per step count"):
        screen.segment_scanner(base, first, np.zeros((5, 2)), resolution)


def test_without_compiled_kinematics_the_scans_are_the_checkers(panda_model: RobotModel) -> None:
    scene = _panda_cell(panda_model)
    screen = _screen(scene)
    screen.supported = False  # as for a robot with joints the kernels do not cover
    checker, to_pin = scene.checker, panda_model.to_pin
    arm = scene.robot.group("arm").joint_indices
    first = int(arm[0])
    rng = np.random.default_rng(9)
    fractions = np.concatenate([[1.0], np.arange(1, 12) / 12])
    for _ in range(30):
        a, b = (panda_model.random_state(rng)[arm] for _ in range(2))
        rows = np.repeat(scene.state[None, :], len(fractions), axis=0)
        got = screen.line_scanner()(rows, fractions, a, b, first, 1)
        hit = checker.first_in_collision(to_pin(rows[1:]))
        assert got == (hit if hit < 0 else hit + 1)
        assert screen.scanner()(rows) == checker.first_in_collision(to_pin(rows))


def test_the_scene_keeps_its_screen_until_an_edit(panda_model: RobotModel) -> None:
    scene = _panda_cell(panda_model)
    screen = scene.state_screen()
    assert scene.state_screen() is screen
    assert screen.checker is scene.checker
    scene.add_object("crate", Box((0.1, 0.1, 0.1)), Pose((0.5, 0.0, 0.05)))
    rebuilt = scene.state_screen()
    assert rebuilt is not screen and rebuilt.checker is scene.checker
    assert scene.copy().state_screen() is not rebuilt  # a copy builds its own
