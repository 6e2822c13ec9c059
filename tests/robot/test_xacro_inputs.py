"""What a xacro expansion depends on besides its files, read from the files it read (not
from inside xacro): an include by glob pattern, or by a name an expression makes, depends
on which files exist (not cached: ``_includes_by_pattern``); ``$(env)``/``$(optenv)``
name the environment variables whose values it depends on (``_environment_read``)."""

from __future__ import annotations

import pytest

from taskrunner.robot.xacrofile import _environment_read, _includes_by_pattern

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


@pytest.mark.parametrize(("text", "names"), [
    ('<link name="$(optenv TR_LINK tip)"/>', {"TR_LINK"}),
    ('<link name="$(env ROBOT_NAME)"/><x v="$(optenv  A_B default words)"/>', {"ROBOT_NAME", "A_B"}),
    ("<x v=\"$(eval env('HOME') + optenv(\"SUFFIX\", 'x'))\"/>", {"HOME", "SUFFIX"}),
    ('<link name="base"/>', set()),
    ('<x v="$(optenv $(arg prefix)_NAME x)"/>', None),
    ("<x v=\"$(eval env(prefix + 'NAME'))\"/>", None),
])
def test_the_environment_an_expansion_reads_is_found(tmp_path, text, names):
    main = tmp_path / "r.urdf.xacro"
    main.write_text(f"{HEAD}\n  {text}\n</robot>\n", encoding="utf-8")
    assert _environment_read([main]) == names
    assert _environment_read([tmp_path / "gone.xacro"]) is None
