"""taskrunner.robot.packages: package names → folders, without ROS."""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot import PackageMap
from taskrunner.robot.packages import default_package_map


def make_package(folder: Path, name: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "package.xml").write_text(
        f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n</package>\n'
    )
    return folder.resolve()


def test_package_is_found_by_its_package_xml_name_not_its_folder_name(robots_dir):
    packages = PackageMap(search_roots=[robots_dir])
    assert packages.find("servo_arm_description") == (robots_dir / "servo_arm").resolve()
    assert "servo_arm" not in packages.names


def test_discovery_descends_into_nested_folders_but_skips_build_trees(tmp_path):
    nested = make_package(tmp_path / "ws" / "src" / "group" / "deep_pkg", "deep")
    make_package(tmp_path / "ws" / "build" / "deep_copy", "built")
    packages = PackageMap(search_roots=[tmp_path / "ws"])
    assert packages.find("deep") == nested
    assert "built" not in packages.names


def test_explicit_entries_win_over_discovered_packages(tmp_path):
    make_package(tmp_path / "found", "robot_description")
    explicit = (tmp_path / "elsewhere").resolve()
    packages = PackageMap({"robot_description": explicit}, search_roots=[tmp_path])
    assert packages.find("robot_description") == explicit
    packages.add("robot_description", tmp_path / "third")
    assert packages.find("robot_description") == (tmp_path / "third").resolve()


def test_unknown_package_error_names_it_the_folders_searched_and_the_known_ones(
        tmp_path, monkeypatch):
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    (tmp_path / "roots" / "a").mkdir(parents=True)
    packages = PackageMap({"mine": tmp_path}, search_roots=[tmp_path / "roots"])
    with pytest.raises(RobotDescriptionError) as info:
        packages.find("their_description")
    message = str(info.value)
    assert message.startswith(
        f"package 'their_description' not found (searched: {tmp_path / 'roots'}; "
        "ROS_PACKAGE_PATH and AMENT_PREFIX_PATH not set; known packages: ")
    assert "mine" in message
    assert "add its folder with --package-path or TASKRUNNER_PACKAGE_PATH" in message


def test_example_robot_data_is_known_under_both_of_its_names(example_robot_data):
    packages = PackageMap()
    assert packages.find("example-robot-data") == example_robot_data
    assert packages.find("example_robot_descriptions") == example_robot_data


def test_package_xml_without_name_is_an_error_naming_the_file(tmp_path):
    folder = tmp_path / "broken"
    folder.mkdir()
    (folder / "package.xml").write_text('<package format="3">\n  <version>1</version>\n</package>\n')
    packages = PackageMap(search_roots=[tmp_path])
    [warning] = packages.warnings
    assert str(warning) == f"{folder / 'package.xml'}:1: package.xml has no <name>; package skipped"
    with pytest.raises(RobotDescriptionError) as info:
        packages.find("broken")
    assert f"skipped broken manifests: {folder / 'package.xml'}:1: package.xml has no <name>" \
        in str(info.value)


def test_malformed_package_xml_names_file_and_line(tmp_path):
    folder = tmp_path / "broken"
    folder.mkdir()
    (folder / "package.xml").write_text("<package>\n  <name>x</nam>\n</package>\n")
    good = tmp_path / "good"
    good.mkdir()
    (good / "package.xml").write_text("<package>\n  <name>good</name>\n</package>\n")
    packages = PackageMap(search_roots=[tmp_path])  # a broken sibling is no reason to fail
    assert packages.find("good") == good.resolve()
    [warning] = packages.warnings
    assert str(warning) == (f"{folder / 'package.xml'}:2: invalid XML: mismatched tag; "
                            "package skipped")


def test_missing_search_root_is_ignored(tmp_path):
    assert "x" not in PackageMap(search_roots=[tmp_path / "nope"]).names


@pytest.mark.parametrize(
    ("uri", "expected"),
    [
        ("package://pkg/meshes/a%20b.stl", "PKG/meshes/a b.stl"),
        ("file:///abs/mesh.stl", "/abs/mesh.stl"),
        ("/abs/mesh.stl", "/abs/mesh.stl"),
        ("../meshes/m.dae", "BASE/../meshes/m.dae"),
    ],
    ids=["package", "file-uri", "absolute", "relative"],
)
def test_mesh_references_resolve_to_paths(tmp_path, uri, expected):
    packages = PackageMap({"pkg": tmp_path / "pkg"})
    resolved = packages.resolve(uri, tmp_path / "base")
    replaced = expected.replace("PKG", str((tmp_path / "pkg").resolve()))
    assert resolved == Path(replaced.replace("BASE", str(tmp_path / "base")))


def test_unsupported_uri_scheme_is_refused(tmp_path):
    with pytest.raises(RobotDescriptionError, match=r"unsupported URI scheme in 'http://x/m.stl'"):
        PackageMap().resolve("http://x/m.stl", tmp_path)


def test_package_uri_with_unknown_package_names_it(tmp_path):
    with pytest.raises(RobotDescriptionError, match=r"package 'nope' not found"):
        PackageMap().resolve("package://nope/m.stl", tmp_path)


def test_the_folder_above_a_robot_is_searched_only_four_folders_deep(tmp_path):
    """A robot file in a crowded folder (``/tmp``, a home folder's subfolder) does not
    pick up a same-named package from deep inside an unrelated tree beside it."""
    robot = tmp_path / "mine" / "arm.urdf"
    robot.parent.mkdir()
    robot.write_text("<robot name='arm'/>")
    near = tmp_path / "ws" / "src" / "near_pkg"
    far = tmp_path / "other" / "checkout" / "tests" / "fixtures" / "src" / "far_pkg"
    for folder, name in ((near, "near_pkg"), (far, "far_pkg")):
        folder.mkdir(parents=True)
        (folder / "package.xml").write_text(f"<package><name>{name}</name></package>")
    packages = default_package_map(robot)
    assert packages.find("near_pkg") == near
    assert not packages.has("far_pkg")
    assert f"{tmp_path} (4 folders deep)" in packages.searched_folders()


def test_a_robot_in_a_crowded_folder_uses_its_own_package_not_a_copy_beside_it(tmp_path):
    """A copy of the robot elsewhere under the folder above (another checkout, a test's
    temporary folder) found first must not stand in for the robot's own package."""
    copies = [make_package(tmp_path / name / "arm", "arm_description")
              for name in ("a_old_checkout", "b_tests")]
    mine = make_package(tmp_path / "mine" / "arm", "arm_description")
    urdf = mine / "urdf" / "arm.urdf"
    urdf.parent.mkdir()
    urdf.write_text("<robot name='arm'/>")
    packages = default_package_map(tmp_path / "mine" / "cell.yaml")  # the cell beside it
    packages.discover_around(urdf)
    assert packages.resolve("package://arm_description/meshes/a.stl", urdf.parent) \
        == mine / "meshes" / "a.stl"
    assert packages.warnings == []  # the file is inside the package it names: no doubt
    # A file outside every copy gets the nearest, with the warning naming them all.
    elsewhere = tmp_path / "b_tests" / "cells"
    elsewhere.mkdir()
    assert packages.find("arm_description", near=elsewhere) == copies[1]
    assert len(packages.warnings) == 1 and "nearest to" in str(packages.warnings[0])
    assert all(str(c) in str(packages.warnings[0]) for c in (mine, copies[0]))
