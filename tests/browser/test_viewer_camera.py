"""The 3D view's camera orbits the cell's robots: its centre is on the arms (above the
table top), and three wheel notches in keep every arm's base and tool on the canvas."""

from __future__ import annotations

import pytest

from .test_viewer_browser import enter_token


@pytest.mark.parametrize("cell", ["servo_arm_table", "servo_arm_pair"])
def test_the_camera_orbits_the_robots_and_zooming_in_keeps_them(page, cell):
    described = page.server.api(f"/viewer/cells/{cell}")
    tips = [g["tip_link"] for g in described["groups"] if g["tip_link"] and "arm" in g["name"]]
    assert tips
    page.goto(page.server.url + f"/#/cell/{cell}")
    enter_token(page)
    page.wait_for_function("window.__viewer.firstFrame !== null", timeout=20_000)
    # three.js is y-up: the orbit's centre's y is the world's z
    centre_z = page.evaluate("window.__viewer.stage.controls.target.y")
    table_top = 0.75
    assert centre_z > table_top, f"the camera orbits z = {centre_z:.3f}, inside the table"
    box = page.locator("#view3d canvas").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    for _ in range(3):
        page.mouse.wheel(0, -120)
        page.wait_for_timeout(100)
    page.wait_for_timeout(200)
    for tip in tips:
        x, y, z = page.evaluate(f"window.__viewer.stage.onScreen({tip!r})")
        assert -1 < x < 1 and -1 < y < 1 and z < 1, f"{tip} left the view: {x:.2f}, {y:.2f}"
