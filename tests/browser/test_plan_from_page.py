"""Plan and execute from the page, as in RViz's MotionPlanning panel: on a fresh server,
the servo arm's tool-frame handle is dragged with the mouse (solved by IK on the server
as it moves), an obstacle is added, Plan draws the trajectory's trail, Execute runs it on
the mock backend, and the arm drawn on the page moves to the goal; a joint is jogged and
the state taught; a goal dragged into the table turns red with the reason. The Task view shows the task's objects
before anything is planned."""

from __future__ import annotations

from typing import Any

from .test_viewer_browser import enter_token, shot

_ANSWERS = "window.__viewer.plan ? window.__viewer.plan.answers : 0"


def _handle_pixel(page: Any) -> tuple[float, float]:
    x, y, _ = page.evaluate("window.__viewer.goal.handleOnScreen()")
    box = page.locator("#view3d canvas").bounding_box()
    return box["x"] + (x + 1) / 2 * box["width"], box["y"] + (1 - y) / 2 * box["height"]


def test_a_dragged_goal_is_planned_and_executed_and_the_arm_moves(page, screenshots):
    page.goto(page.server.url + "/#/cell/servo_arm_table")
    enter_token(page)
    page.wait_for_function(f"window.__viewer.firstFrame !== null && {_ANSWERS} > 0",
                           timeout=30_000)
    page.select_option("#plan-backend", "mock")
    # The solid robot drawn where the mock backend says it is (the sim's state, drawn
    # before, can differ: the page reads the mock's once the choice is made).
    mock = page.server.api("/cells/servo_arm_table/state?backend=mock")["joints"]
    page.wait_for_function("([want]) => Object.entries(want).every(([j, v]) => "
                           "Math.abs(window.__viewer.stage.jointValue(j) - v) < 1e-9)", arg=[mock])
    page.wait_for_function("window.__viewer.plan.answer && window.__viewer.plan.answer.ok")
    joints = list(page.evaluate("Object.keys(window.__viewer.plan.answer.joints)"))
    robot_before = {j: page.evaluate(f"window.__viewer.stage.jointValue({j!r})") for j in joints}
    answers = page.evaluate(_ANSWERS)
    # drag the handle's centre (it moves in the view's plane) up and toward the base: away
    # from the table, so the goal stays free however the view was fitted when it started
    # (dragged down, the fingers could end in the table)
    x, y = _handle_pixel(page)
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 9):
        page.mouse.move(x - 2 * k, y - 3 * k)
        page.wait_for_timeout(30)
    page.mouse.up()
    page.wait_for_function(f"{_ANSWERS} > {answers} && !window.__viewer.goal.dragging")
    page.wait_for_timeout(300)  # the last answer of the drag
    answer = page.evaluate("window.__viewer.plan.answer")
    assert answer["ok"], answer["reason"]
    goal = answer["joints"]
    assert max(abs(goal[j] - robot_before[j]) for j in joints) > 0.02, "the drag moved no joint"
    # the ghost shows the goal; the solid robot has not moved
    ghost = {j: page.evaluate(f"window.__viewer.goal.jointValue({j!r})") for j in joints}
    assert all(abs(ghost[j] - goal[j]) < 1e-6 for j in joints)
    assert all(abs(page.evaluate(f"window.__viewer.stage.jointValue({j!r})") - robot_before[j])
               < 1e-6 for j in joints)
    # an obstacle added on the page: drawn, and sent with the checks, the plan and the run
    answers = page.evaluate(_ANSWERS)
    page.click("button[data-add='box']")
    page.wait_for_function(f"{_ANSWERS} > {answers} && window.__viewer.plan.answer.ok")
    box = page.evaluate("window.__viewer.plan.obstacles[0]")
    drawn = page.evaluate("window.__viewer.stage.objectWorld('box_1')")
    assert max(abs(a - b) for a, b in zip(drawn, box["xyz"])) < 1e-6
    page.click("#plan-plan")
    page.wait_for_function("window.__viewer.plan.planned", timeout=30_000)
    assert page.evaluate("window.__viewer.goal.trail.geometry.attributes.position.count") > 2
    shot(page, screenshots, "plan_servo_arm_planned")
    page.click("#plan-execute")
    page.wait_for_function("window.__viewer.plan.run && window.__viewer.plan.run.done",
                           timeout=30_000)
    run = page.evaluate("window.__viewer.plan.run")
    assert run["status"] == "succeeded", run
    robot_after = {j: page.evaluate(f"window.__viewer.stage.jointValue({j!r})") for j in joints}
    assert all(abs(robot_after[j] - goal[j]) < 2e-3 for j in joints), (robot_after, goal)
    shown = page.eval_on_selector_all("#plan-sliders .robot-value", "els => els.map(e => e.textContent)")
    assert [float(v) for v in shown] == [round(goal[j], 3) for j in joints]
    detail = page.server.api(f"/runs/{run['id']}")
    assert detail["backend"] == "mock" and detail["task"] == "goal_from_view"
    first = page.server.api(f"/viewer/runs/{run['id']}/replay")["first_scene"]
    assert "box_1" in [o["name"] for o in first["objects"]]
    shot(page, screenshots, "plan_servo_arm_executed")
    # jog: one joint of the robot a step further; teach: its state as a named pose
    before = page.evaluate("window.__viewer.stage.jointValue('Revolute 1')")
    page.click("button[data-jog='Revolute 1:1']")
    page.wait_for_function("window.__viewer.plan.run.jog && window.__viewer.plan.run.done",
                           timeout=30_000)
    assert page.evaluate("window.__viewer.plan.run.status") == "succeeded"
    jogged = page.evaluate("window.__viewer.stage.jointValue('Revolute 1')")
    assert abs(jogged - before - 0.05) < 2e-3, (before, jogged)
    page.fill("#teach-name", "from_the_page")
    page.click("#teach")
    page.wait_for_function("window.__viewer.plan.taught")
    assert abs(page.evaluate("window.__viewer.plan.taught.joints['Revolute 1']") - jogged) < 1e-6
    assert page.locator("select[name='pose:arm'] option[value='from_the_page']").count() == 1
    # dragged down into the table: the ghost turns red and the page says why
    answers = page.evaluate(_ANSWERS)
    x, y = _handle_pixel(page)
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(x, y + 25 * k)
        page.wait_for_timeout(30)
    page.mouse.up()
    page.wait_for_function(f"{_ANSWERS} > {answers} && !window.__viewer.goal.dragging")
    page.wait_for_function("window.__viewer.plan.answer && !window.__viewer.plan.answer.ok")
    page.wait_for_timeout(300)
    reason = page.evaluate("window.__viewer.plan.answer.reason")
    assert "collision" in reason or "no IK solution" in reason, reason
    assert reason in page.text_content("#plan-status")
    assert page.evaluate("window.__viewer.goal.material.color.getHex()") == 0xD83A3A
    assert page.is_disabled("#plan-plan")
    shot(page, screenshots, "plan_servo_arm_goal_refused")


def test_the_task_view_shows_the_tasks_objects_before_planning(page):
    page.goto(page.server.url + "/#/task/pick_place")
    enter_token(page)
    page.wait_for_function("window.__viewer.taskScene && window.__viewer.stage.objectWorld('cube')",
                           timeout=30_000)
    cube = page.evaluate("window.__viewer.stage.objectWorld('cube')")
    assert [round(v, 4) for v in cube] == [0.19, 0.04, 0.7625]
    assert page.evaluate("window.__viewer.preview === undefined")  # nothing planned
