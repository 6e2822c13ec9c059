"""Which xacro expansions may be cached: one that includes by glob pattern, or by a name
an expression makes, depends on which files exist (read from the files it read, not from
inside xacro: taskrunner.robot.xacrofile._includes_by_pattern)."""

from __future__ import annotations

import pytest

from taskrunner.robot.xacrofile import _includes_by_pattern

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'


@pytest.mark.parametrize(("include", "pattern"), [
    ('<xacro:include filename="$(find parts)/link.xacro"/>', False),
    ('<xacro:include filename="parts.xacro" ns="p"/>', False),
    ('<xacro:include filename="$(find parts)/l*.xacro"/>', True),
    ("<x:include\n   filename='urdf/[ab].xacro'/>", True),
    ('<include filename="arm?.xacro"/>', True),
    ('<xacro:include filename="${prefix}.xacro"/>', True),
])
def test_an_include_by_pattern_or_expression_is_found(tmp_path, include, pattern):
    main = tmp_path / "r.urdf.xacro"
    main.write_text(f"{HEAD}\n  {include}\n</robot>\n", encoding="utf-8")
    plain = tmp_path / "plain.xacro"
    plain.write_text(f"{HEAD}<link name='a'/></robot>", encoding="utf-8")
    assert _includes_by_pattern([plain, main]) is pattern
    assert _includes_by_pattern([plain]) is False


def test_a_file_that_cannot_be_read_again_counts_as_a_pattern(tmp_path):
    assert _includes_by_pattern([tmp_path / "gone.xacro"]) is True
