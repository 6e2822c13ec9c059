"""Cached xacro expansions (taskrunner.robot.xacro_cache): reused while every file,
variable and package the expansion read is unchanged, expanded again otherwise."""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.robot import xacro_cache
from taskrunner.robot.packages import PackageMap
from taskrunner.robot.xacrofile import XacroOptions, expand_xacro

ROBOT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find parts)/link.xacro"/>
  <xacro:property name="size" value="${load_yaml('dims.yaml')['size']}"/>
  <xacro:part name="base" size="${size}"/>
  <link name="$(optenv TR_TEST_LINK tip)"/>
</robot>
"""
PART = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="part" params="name size">
    <link name="${name}"><visual><geometry><box size="${size} ${size} ${size}"/></geometry></visual></link>
  </xacro:macro>
</robot>
"""


@pytest.fixture
def robot(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.delenv("TR_TEST_LINK", raising=False)
    monkeypatch.delenv("TASKRUNNER_XACRO_CACHE", raising=False)
    xacro_cache.clear_memory()
    parts = tmp_path / "parts"
    parts.mkdir()
    (parts / "package.xml").write_text("<package><name>parts</name></package>")
    (parts / "link.xacro").write_text(PART)
    main = tmp_path / "robot" / "r.urdf.xacro"
    main.parent.mkdir()
    main.write_text(ROBOT)
    (main.parent / "dims.yaml").write_text("size: 0.1\n")
    yield main, PackageMap({"parts": parts}, environment=False)
    xacro_cache.clear_memory()


def _expansions(monkeypatch) -> list[Path]:
    """Count real expansions (the cache answers the others)."""
    import taskrunner.robot.xacrofile as xacrofile

    seen: list[Path] = []
    original = xacrofile._expand_in_child

    def counting(path, *args):  # type: ignore[no-untyped-def]
        seen.append(path)
        return original(path, *args)

    monkeypatch.setattr(xacrofile, "_expand_in_child", counting)
    return seen


def test_the_second_expansion_comes_from_the_cache_also_in_a_new_process(robot, monkeypatch):
    main, packages = robot
    seen = _expansions(monkeypatch)
    first = expand_xacro(main, packages)
    assert 'size="0.1 0.1 0.1"' in first and '<link name="tip"/>' in first
    assert expand_xacro(main, packages) == first
    xacro_cache.clear_memory()  # as a new process: from the disk
    assert expand_xacro(main, packages) == first
    assert len(seen) == 1
    assert len(list((main.parents[1] / "cache" / "taskrunner" / "xacro").glob("*.json"))) == 1


@pytest.mark.parametrize("change", ["include", "yaml", "main", "env", "package", "args"])
def test_any_change_to_what_it_read_expands_again(robot, monkeypatch, tmp_path, change):
    main, packages = robot
    seen = _expansions(monkeypatch)
    mappings = None
    expand_xacro(main, packages)
    if change == "include":
        (tmp_path / "parts" / "link.xacro").write_text(PART.replace("${size} ${size}", "${size} 1"))
    elif change == "yaml":
        (main.parent / "dims.yaml").write_text("size: 0.2\n")
    elif change == "main":
        main.write_text(ROBOT.replace("tip)", "end)"))
    elif change == "env":
        monkeypatch.setenv("TR_TEST_LINK", "flange")
    elif change == "package":
        other = tmp_path / "parts2"
        other.mkdir()
        (other / "link.xacro").write_text(PART.replace("${size} ${size}", "${size} 2"))
        packages = PackageMap({"parts": other}, environment=False)
    else:
        mappings = {"unused": "1"}
    text = expand_xacro(main, packages, mappings)
    assert len(seen) == 2
    expected = {"include": 'size="0.1 1 0.1"', "yaml": 'size="0.2 0.2 0.2"', "main": 'name="end"',
                "env": 'name="flange"', "package": 'size="0.1 2 0.1"', "args": 'name="tip"'}
    assert expected[change] in text
    assert expand_xacro(main, packages, mappings) == text and len(seen) == 2


def test_failed_expansions_are_not_kept_and_the_cache_can_be_switched_off(robot, monkeypatch):
    main, packages = robot
    (main.parent / "dims.yaml").unlink()
    with pytest.raises(Exception, match="dims.yaml"):
        expand_xacro(main, packages)
    assert not (main.parents[1] / "cache" / "taskrunner" / "xacro").exists()
    (main.parent / "dims.yaml").write_text("size: 0.3\n")
    monkeypatch.setenv("TASKRUNNER_XACRO_CACHE", "0")
    seen = _expansions(monkeypatch)
    expand_xacro(main, packages)
    expand_xacro(main, packages)
    assert len(seen) == 2


def test_in_process_expansions_are_cached_too(robot, monkeypatch):
    main, packages = robot
    text = expand_xacro(main, packages, options=XacroOptions(in_process=True))
    seen = _expansions(monkeypatch)
    assert expand_xacro(main, packages) == text and seen == []


def test_an_include_by_glob_pattern_is_not_cached(robot, monkeypatch, tmp_path):
    main, packages = robot
    main.write_text(ROBOT.replace("$(find parts)/link.xacro", "$(find parts)/l*.xacro"))
    seen = _expansions(monkeypatch)
    expand_xacro(main, packages)
    expand_xacro(main, packages)
    assert len(seen) == 2


def test_the_disk_cache_keeps_the_latest_expansions_only(robot, monkeypatch):
    main, packages = robot
    monkeypatch.setattr(xacro_cache, "MAX_FILES", 3)
    for k in range(5):
        expand_xacro(main, packages, {"variant": str(k)})
    folder = main.parents[1] / "cache" / "taskrunner" / "xacro"
    assert len(list(folder.glob("*.json"))) == 3
    xacro_cache.clear_memory()
    seen = _expansions(monkeypatch)
    expand_xacro(main, packages, {"variant": "4"})  # among the latest: from the disk
    assert seen == []
