"""The browser view's routes: the page loads without a token, data needs it, meshes are
served only from the mesh folders of loaded robots (no traversal out of them)."""

from __future__ import annotations

import http.client
from pathlib import Path

import pytest
from apitest import AUTH, NO_TOKEN, make_settings, served, wait_until_done
from fastapi.testclient import TestClient

from taskrunner.api import create_app

# A robot whose links are drawn from mesh files: one STL triangle.
_STL = b"\0" * 80 + (1).to_bytes(4, "little") + bytes(50)  # binary STL, one triangle
_URDF = """<robot name="meshy">
  <link name="base_link">
    <visual><geometry><mesh filename="meshes/base.stl"/></geometry></visual>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
  <link name="arm_link">
    <visual><geometry><mesh filename="meshes/arm.stl" scale="0.001 0.001 0.001"/></geometry></visual>
    <collision><geometry><box size="0.05 0.05 0.2"/></geometry></collision>
  </link>
  <joint name="j1" type="revolute"><parent link="base_link"/><child link="arm_link"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" velocity="1" effort="1"/></joint>
</robot>
"""
_SRDF = """<robot name="meshy">
  <group name="arm"><joint name="j1"/></group>
  <group_state name="zero" group="arm"><joint name="j1" value="0"/></group_state>
  <group_state name="turned" group="arm"><joint name="j1" value="0.8"/></group_state>
</robot>
"""


@pytest.fixture
def mesh_world(tmp_path: Path) -> dict[str, Path]:
    robots = tmp_path / "robots"
    robot = robots / "meshy"
    (robot / "meshes").mkdir(parents=True)
    (robot / "meshy.urdf").write_text(_URDF)
    (robot / "meshy.srdf").write_text(_SRDF)
    (robot / "robot.yaml").write_text("name: meshy\nurdf: meshy.urdf\nsrdf: meshy.srdf\n")
    for name in ("base.stl", "arm.stl"):
        (robot / "meshes" / name).write_bytes(_STL)
    (robot / "meshes" / "notes.txt").write_text("not a mesh")
    secret = tmp_path / "secret"
    secret.mkdir()
    (secret / "key.stl").write_text("SECRET")
    (robot / "meshes" / "escape.stl").symlink_to(secret / "key.stl")
    (robot / "meshes" / "up").symlink_to(secret)
    cells = tmp_path / "cells"
    cells.mkdir()
    (cells / "meshy_cell.yaml").write_text(
        f"name: meshy_cell\nrobots:\n  - name: m\n    robot: {robot}\n"
        "objects:\n  - {name: plinth, shape: box, size: [0.2, 0.2, 0.1], "
        "pose: {xyz: [0.5, 0, 0.05]}}\n")
    return {"robots": robots, "cells": cells, "robot": robot, "secret": secret}


@pytest.fixture
def mesh_client(tmp_path: Path, mesh_world):
    settings = make_settings(tmp_path / "state", robots_dirs=(mesh_world["robots"],),
                             cells_dir=mesh_world["cells"])
    with TestClient(create_app(settings), headers=AUTH) as c:
        yield c


def test_the_page_and_its_bundle_load_without_a_token(client):
    page = client.get("/", headers=NO_TOKEN)
    assert page.status_code == 200 and page.headers["content-type"].startswith("text/html")
    assert "viewer.js" in page.text
    bundle = client.get("/viewer/static/viewer.js", headers=NO_TOKEN)
    assert bundle.status_code == 200 and "javascript" in bundle.headers["content-type"]
    for bad in ("../__init__.py", "..%2f__init__.py", ".hidden", "describe.py"):
        assert client.get(f"/viewer/static/{bad}", headers=NO_TOKEN).status_code == 404


def test_the_views_data_needs_the_token(client):
    for path in ("/viewer/cells/servo_arm_pair", "/viewer/tasks", "/viewer/meshes/x/a.stl"):
        answer = client.get(path, headers=NO_TOKEN)
        assert answer.status_code == 401, path
    assert client.post("/viewer/tasks/tree", json={"task": "pick_place"},
                       headers=NO_TOKEN).status_code == 401


def test_the_cell_is_described_for_three_js(client):
    cell = client.get("/viewer/cells/servo_arm_pair").json()
    assert cell["urdf"].startswith("<robot") and "left_base_link" in cell["urdf"]
    assert "<collision" not in cell["urdf"]
    assert [r["prefix"] for r in cell["robots"]] == ["left_", "right_"]
    assert cell["robots"][1]["base"]["xyz"] == [0.25, 0.0, 0.75]
    groups = {g["name"]: g for g in cell["groups"]}
    assert groups["left_arm"]["poses"]["Candle"]["left_Revolute 1"] == pytest.approx(1.5708)
    joints = {j["name"]: j for j in cell["joints"]}
    assert joints["left_Revolute 1"]["velocity"] > 0
    assert [o["name"] for o in cell["objects"]] == ["table"]
    assert client.get("/viewer/cells/nope").status_code == 404


def test_a_task_compiles_to_a_tree_with_file_and_line(client):
    answer = client.post("/viewer/tasks/tree", json={"task": "pick_place"}).json()
    assert answer["cell"] == "servo_arm_table"
    tree = answer["tree"]
    assert tree["kind"] == "sequence" and tree["name"] == "pick_place"
    assert all(c["location"] and ":" in c["location"] for c in tree["children"])
    assert "pick_place" in client.get("/viewer/tasks").json()


def test_a_preview_plans_every_motion_and_moves_nothing(client):
    before = client.get("/cells/servo_arm_table/state?backend=mock").json()["joints"]
    answer = client.post("/viewer/tasks/preview", json={"task": "pick_place"}).json()
    assert answer["status"] == "succeeded"
    assert len(answer["motions"]) >= 8
    assert answer["final_scene"] is not None
    after = client.get("/cells/servo_arm_table/state?backend=mock").json()["joints"]
    assert after == before


def test_a_run_replay_holds_its_motions(client):
    run = client.post("/runs", json={"task": "pick_place", "backend": "mock"}).json()
    wait_until_done(client, run["run_id"], timeout=60)
    replay = client.get(f"/viewer/runs/{run['run_id']}/replay").json()
    assert replay["status"] == "succeeded" and len(replay["motions"]) >= 8
    assert all(m["executed"] is not None for m in replay["motions"])


def test_meshes_are_served_from_the_loaded_robots_folder_only(mesh_client, mesh_world):
    cell = mesh_client.get("/viewer/cells/meshy_cell").json()
    urls = [part.split('"')[0] for part in cell["urdf"].split('filename="')[1:]]
    assert len(urls) == 2 and all(u.startswith("meshes/") for u in urls)
    assert str(mesh_world["robot"]) not in cell["urdf"]  # no server path reaches the page
    root = urls[0].split("/")[1]
    ok = mesh_client.get(f"/viewer/{urls[0]}")
    assert ok.status_code == 200 and ok.content == _STL
    assert mesh_client.get(f"/viewer/{urls[0]}", headers=NO_TOKEN).status_code == 401
    for bad in (f"{root}/notes.txt",                # not a mesh
                f"{root}/escape.stl",               # a symlink out of the folder
                f"{root}/up/key.stl",               # through a symlinked folder
                f"{root}/%2e%2e/meshy.urdf",        # encoded ..
                f"{root}/%2e%2e/%2e%2e/secret/key.stl",
                f"{root}/..%2f..%2fsecret%2fkey.stl",
                f"{root}/%2fetc%2fpasswd",          # absolute
                f"{root}//etc/passwd",
                f"{root}/{mesh_world['secret']}/key.stl",
                f"{root}/missing.stl",
                "0000000000000000/base.stl"):       # not a root
        answer = mesh_client.get(f"/viewer/meshes/{bad}")
        assert answer.status_code == 404, bad
        assert b"SECRET" not in answer.content


def test_raw_dot_dot_paths_on_the_wire_get_nothing(tmp_path, mesh_world):
    """Paths sent as written (no client normalising ``..``) to a real server."""
    settings = make_settings(tmp_path / "state", robots_dirs=(mesh_world["robots"],),
                             cells_dir=mesh_world["cells"])
    with served(create_app(settings)) as port:
        def get(path: str) -> tuple[int, bytes]:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            conn.putrequest("GET", path, skip_accept_encoding=True)
            conn.putheader("Authorization", AUTH["Authorization"])
            conn.endheaders()
            answer = conn.getresponse()
            return answer.status, answer.read()

        status, body = get("/viewer/cells/meshy_cell")
        assert status == 200
        root = body.decode().split('meshes/')[1].split("/")[0]
        assert get(f"/viewer/meshes/{root}/base.stl")[0] == 200
        for bad in (f"/viewer/meshes/{root}/../meshy.urdf",
                    f"/viewer/meshes/{root}/../../../secret/key.stl",
                    f"/viewer/meshes/{root}/%2e%2e/%2e%2e/secret/key.stl",
                    f"/viewer/meshes/{root}/./../meshy.srdf",
                    "/viewer/static/../../api/app.py",
                    "/viewer/static/%2e%2e/describe.py"):
            status, body = get(bad)
            assert status == 404, bad
            assert b"SECRET" not in body and b"<robot" not in body


def test_a_copy_of_the_shipped_robot_serves_nothing_outside_its_folder(tmp_path):
    # the shipped servo arm draws primitives only: its cell names no mesh folder at all
    settings = make_settings(tmp_path / "state")
    with TestClient(create_app(settings), headers=AUTH) as c:
        cell = c.get("/viewer/cells/servo_arm_table").json()
        assert "meshes/" not in cell["urdf"]
