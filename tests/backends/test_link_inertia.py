"""Links without <inertial> weigh what their collision geometry would at the documented
density, with one warning per robot naming them."""

from __future__ import annotations

import logging
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from taskrunner.robot.cell import load_cell_or_robot

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import physics_cell  # noqa: E402
from taskrunner.backends.physics.inertia import (  # noqa: E402
    DEFAULT_LINK_DENSITY,
    shape_inertia,
)
from taskrunner.backends.physics.mjcf import MjcfOptions, cell_mjcf, compiled_model  # noqa: E402
from taskrunner.shapes import Mesh  # noqa: E402

ARM3 = Path(__file__).parents[1] / "robot" / "fixtures" / "moveit" / "src" / "arm3_moveit_config"
TETRA = Path(__file__).parents[1] / "fixtures" / "moveit_scenes" / "tetra.stl"


def body_id(model, name: str) -> int:
    """The body of link ``name`` (the cell prefixes the robot's links)."""
    found = [b for b in range(model.nbody) if model.body(b).name.endswith(name)]
    assert len(found) == 1, name
    return found[0]


def body_mass(model, name: str) -> float:
    return float(model.body_mass[body_id(model, name)])


def test_links_without_inertial_weigh_their_geometry_and_warn_once(tmp_path, caplog):
    cell = load_cell_or_robot(ARM3)
    with caplog.at_level(logging.WARNING, logger="taskrunner.backends.physics.mjcf"):
        described = physics_cell(cell)
        model, _ = compiled_model(cell_mjcf(described, MjcfOptions(), tmp_path), tmp_path)
        cell_mjcf(described.with_objects(()), MjcfOptions(), tmp_path)  # a rebuild
    warnings = [r.getMessage() for r in caplog.records if "without <inertial>" in r.getMessage()]
    assert len(warnings) == 1
    for link in ("link1", "link2", "link3", "hand", "finger1", "finger2"):
        assert f"{link} " in warnings[0]
    assert "base_link" not in warnings[0]  # fixed to the world: its mass never matters
    assert "flange" not in warnings[0]  # no geometry, fixed to link3: no mass needed
    rho = DEFAULT_LINK_DENSITY
    expected = {"link1": np.pi * 0.04**2 * 0.2, "link2": 0.05 * 0.05 * 0.3,
                "link3": np.pi * 0.02**2 * 0.2, "finger1": 0.01 * 0.01 * 0.04}
    for link, volume in expected.items():
        assert body_mass(model, link) == pytest.approx(rho * volume, rel=1e-6)
    # Proportional to volume: link2's box holds 2.98 times link1's cylinder.
    assert body_mass(model, "link2") / body_mass(model, "link1") == pytest.approx(
        expected["link2"] / expected["link1"], rel=1e-6)
    # The inertia about the link's own frame follows the collision origin (z 0.15 m).
    link2 = body_id(model, "link2")
    assert model.body_ipos[link2] == pytest.approx([0.0, 0.0, 0.15], abs=1e-9)
    m = rho * expected["link2"]
    assert sorted(model.body_inertia[link2]) == pytest.approx(
        sorted([m * (0.05**2 + 0.3**2) / 12] * 2 + [m * (0.05**2 + 0.05**2) / 12]), rel=1e-6)


def test_a_link_that_gives_its_inertial_keeps_it(tmp_path):
    cell = load_cell_or_robot(ARM3)
    root = ET.fromstring(cell.model.urdf_xml)
    link = next(lk for lk in root.findall("link") if lk.get("name", "").endswith("link2"))
    link.append(ET.fromstring('<inertial><mass value="2.5"/>'
                              '<inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" '
                              'iyz="0"/></inertial>'))
    cell.model.urdf_xml = ET.tostring(root, encoding="unicode")
    described = physics_cell(cell)
    assert link.get("name") not in described.link_inertias
    model, _ = compiled_model(cell_mjcf(described, MjcfOptions(), tmp_path), tmp_path)
    assert body_mass(model, "link2") == pytest.approx(2.5)


def test_a_closed_mesh_weighs_its_volume():
    volume, centre, inertia, hull = shape_inertia(Mesh(TETRA, (2.0, 2.0, 2.0)))
    assert not hull
    assert volume == pytest.approx(8.0 / 6.0)  # the unit tetrahedron scaled by 2
    assert centre == pytest.approx([0.5, 0.5, 0.5])
    assert np.allclose(inertia, inertia.T) and np.all(np.linalg.eigvalsh(inertia) > 0)
