"""taskrunner.yamlfile: line numbers, duplicate keys, non-scalar keys, errors with file:line."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from taskrunner.errors import YamlError
from taskrunner.yamlfile import LineDict, LineList, line_of, load_yaml, load_yaml_text


def write(tmp_path: Path, text: str, name: str = "file.yaml") -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def test_mappings_and_keys_know_their_lines():
    data = load_yaml_text(
        textwrap.dedent("""\
            # comment
            arm:
              timeout: 0.1

              attempts: 3
            hand: {a: 1}
            """)
    )
    assert isinstance(data, LineDict)
    assert data.line == 2
    assert data.line_of("arm") == 2
    assert data.line_of("hand") == 6
    assert data["arm"].line == 3
    assert data["arm"].line_of("timeout") == 3
    assert data["arm"].line_of("attempts") == 5
    # An absent key points at the mapping itself.
    assert data["arm"].line_of("missing") == 3
    assert line_of(data["arm"], "attempts") == 5
    assert line_of(data) == 2


def test_sequences_know_their_own_line_and_their_items():
    data = load_yaml_text("names:\n  - a\n  -\n    b\n  - {c: 1}\n")
    names = data["names"]
    assert isinstance(names, LineList)
    assert names == ["a", "b", {"c": 1}]
    assert names.line == 2
    assert names.item_lines == [2, 4, 5]
    assert line_of(names, 1) == 4
    assert line_of(names, 99) == 2  # out of range: the sequence's line
    assert names[2].line == 5


def test_line_of_plain_values_is_none():
    assert line_of({"a": 1}) is None
    assert line_of([1, 2], 0) is None
    assert line_of(3) is None


def test_values_keep_their_yaml_types():
    data = load_yaml_text("a: 1\nb: 1.5\nc: true\nd: null\ne: text\nf: '1'\n")
    assert data == {"a": 1, "b": 1.5, "c": True, "d": None, "e": "text", "f": "1"}
    assert type(data["a"]) is int and type(data["c"]) is bool


def test_duplicate_key_names_the_file_and_both_lines(tmp_path):
    path = write(tmp_path, """\
        arm:
          kinematics_solver_timeout: 0.1
          kinematics_solver_attempts: 3
          kinematics_solver_timeout: 0.2
        """)
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    error = info.value
    assert str(error) == (
        f"{path}:4: duplicate key 'kinematics_solver_timeout' (first defined on line 2)"
    )
    assert error.path == path and error.line == 4


def test_duplicate_top_level_key_in_flow_mapping_is_refused(tmp_path):
    path = write(tmp_path, "joint_limits: {j1: {max_velocity: 1}, j1: {max_velocity: 2}}\n")
    with pytest.raises(YamlError, match=r"file.yaml:1: duplicate key 'j1' \(first defined on line 1\)"):
        load_yaml(path)


def test_equal_keys_in_different_mappings_are_fine():
    data = load_yaml_text("a: {x: 1}\nb: {x: 2}\n")
    assert data["a"]["x"] == 1 and data["b"]["x"] == 2


@pytest.mark.parametrize(
    ("text", "line", "shown"),
    [
        ("ok: 1\n? [a, b]\n: 1\n", 2, "['a', 'b']"),
        ("ok: 1\n? {a: 1}\n: 1\n", 2, "{'a': 1}"),
        ("ok: 1\n[1, 2]: x\n", 2, "[1, 2]"),
    ],
    ids=["sequence", "mapping", "flow-sequence"],
)
def test_non_scalar_key_is_refused_with_its_line(tmp_path, text, line, shown):
    path = write(tmp_path, text)
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value) == f"{path}:{line}: mapping key must be a scalar (got {shown})"


def test_merge_keys_may_be_overridden_but_own_keys_may_not_repeat():
    text = textwrap.dedent("""\
        defaults: &defaults {has_velocity_limits: true, max_velocity: 1.0}
        fast: &fast {max_velocity: 3.0, max_acceleration: 9.0}
        j1:
          <<: *defaults
          max_velocity: 2.0
        j2:
          <<: [*fast, *defaults]
        """)
    data = load_yaml_text(text)
    assert data["j1"] == {"has_velocity_limits": True, "max_velocity": 2.0}
    assert data["j1"].line_of("max_velocity") == 5
    # Of several merged mappings the first listed wins (YAML merge-key semantics).
    assert data["j2"] == {"has_velocity_limits": True, "max_velocity": 3.0, "max_acceleration": 9.0}
    with pytest.raises(YamlError, match=r":6: duplicate key 'max_velocity' \(first defined on line 5\)"):
        load_yaml_text(text.replace("max_velocity: 2.0\n", "max_velocity: 2.0\n  max_velocity: 4.0\n"))


def test_syntax_error_names_the_file_and_line(tmp_path):
    path = write(tmp_path, "a: 1\nb: [1, 2\nc: 3\n")
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    message = str(info.value)
    assert message.startswith(f"{path}:")
    assert "invalid YAML" in message
    assert info.value.line is not None and info.value.line >= 2


def test_tab_indentation_error_names_the_line(tmp_path):
    path = write(tmp_path, "a:\n\tb: 1\n")
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value).startswith(f"{path}:2: invalid YAML")


def test_unknown_tag_is_a_yaml_error(tmp_path):
    path = write(tmp_path, "a: !!python/object:os.system 1\n")
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value).startswith(f"{path}:1: invalid YAML")


def test_two_documents_are_refused(tmp_path):
    path = write(tmp_path, "a: 1\n---\nb: 2\n")
    with pytest.raises(YamlError, match="invalid YAML"):
        load_yaml(path)


def test_missing_file_is_a_yaml_error(tmp_path):
    path = tmp_path / "nope.yaml"
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value) == f"{path}: file not found"


def test_file_that_is_not_utf8_is_a_yaml_error(tmp_path):
    path = tmp_path / "latin1.yaml"
    path.write_bytes("name: caf\xe9\n".encode("latin-1"))
    with pytest.raises(YamlError, match=r"latin1.yaml:1: file is not UTF-8 text \(invalid byte 0xe9\)"):
        load_yaml(path)


def test_empty_file_is_none(tmp_path):
    assert load_yaml(write(tmp_path, "# only a comment\n")) is None


def test_text_without_path_is_labelled_string():
    with pytest.raises(YamlError, match=r"^<string>:2: duplicate key 'a'"):
        load_yaml_text("a: 1\na: 2\n")


def test_a_control_character_is_a_yaml_error_with_its_line():
    from taskrunner.errors import YamlError
    from taskrunner.yamlfile import load_yaml_text

    with pytest.raises(YamlError, match=r"^task.yaml:2: invalid YAML: character #x001f"):
        load_yaml_text("a: 1\nb: \x1f\n", "task.yaml")
