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


# ------------------------------------------------------------------ YAML 1.2, tags, limits
def test_yaml_1_2_keeps_on_yes_and_no_as_strings():
    data = load_yaml_text("on: yes\noff: no\nflag: true\nwhen: 2024-01-01\nn: 1e3\n")
    assert data == {"on": "yes", "off": "no", "flag": True, "when": "2024-01-01", "n": 1000.0}


def test_merged_keys_keep_the_line_where_they_were_written():
    data = load_yaml_text("base: &b\n  x: 1\n  y: 2\nj:\n  <<: *b\n  y: 3\n")
    assert data["j"] == {"x": 1, "y": 3}
    assert data["j"].line_of("x") == 2 and data["j"].line_of("y") == 6


def test_merge_of_a_scalar_is_refused_with_its_line():
    with pytest.raises(YamlError, match=r"^<string>:2: '<<' \(merge key\) must name a mapping"):
        load_yaml_text("a: &a 1\nb: {<<: *a}\n")


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('a: !!int "abc"\n', "<string>:1: invalid YAML: 'abc' is not a valid !!int"),
        ("a: !!float x\n", "<string>:1: invalid YAML: 'x' is not a valid !!float"),
        ("a: !!bool yes\n", "<string>:1: invalid YAML: 'yes' is not a valid !!bool"),
        ("a: !!binary aGk=\n", "<string>:1: invalid YAML: tag '!!binary' is not supported "
                               "(only !!str, !!int, !!float, !!bool, !!null)"),
        ("a: !custom 1\n", "<string>:1: invalid YAML: tag '!custom' is not supported "
                           "(only !!str, !!int, !!float, !!bool, !!null)"),
        ("a: !!set {x}\n", "<string>:1: invalid YAML: tag '!!set' is not supported here "
                           "(only !!map)"),
        ("a: !!int " + "9" * 5000 + "\n", "<string>:1: invalid YAML: '" + "9" * 40
         + "…' is not a valid !!int"),
    ],
    ids=["int", "float", "bool", "binary", "local", "set", "5000 digits"],
)
def test_explicit_tags_are_checked(text, message):
    with pytest.raises(YamlError) as info:
        load_yaml_text(text)
    assert str(info.value) == message


def test_explicit_core_tags_convert():
    data = load_yaml_text('a: !!int "0x1f"\nb: !!float "1"\nc: !!str 12\nd: !!null ""\n')
    assert data == {"a": 31, "b": 1.0, "c": "12", "d": None}


def test_an_alias_bomb_is_refused_before_it_is_expanded():
    # 12 levels of 10: 10^12 nodes if expanded, which would never finish; the refusal
    # comes while reading line 5 (10^4 nodes counted), long before the last anchor.
    names = "abcdefghijkl"
    text = "a: &a [" + ",".join(["lol"] * 10) + "]\n" + "".join(
        f"{n}: &{n} [" + ",".join([f"*{p}"] * 10) + "]\n" for p, n in zip(names, names[1:]))
    assert len(text) < 500
    with pytest.raises(YamlError) as info:
        load_yaml_text(text, "bomb.yaml")
    assert str(info.value) == ("bomb.yaml:5: aliases expand to more than 100000 nodes "
                               "(at '*d'; an alias bomb?)")


def test_the_alias_limit_is_configurable_and_counts_every_alias():
    from taskrunner.yamlfile import YamlLimits

    text = "a: &a [1, 2, 3]\nb: [*a, *a]\n"  # each alias brings 4 nodes
    assert load_yaml_text(text, limits=YamlLimits(max_alias_nodes=8))["b"] == [[1, 2, 3]] * 2
    with pytest.raises(YamlError, match=r":2: aliases expand to more than 7 nodes"):
        load_yaml_text(text, limits=YamlLimits(max_alias_nodes=7))


def test_aliases_are_copies():
    data = load_yaml_text("a: &a {x: [1]}\nb: *a\n")
    assert data["a"] == data["b"] and data["a"] is not data["b"]
    assert data["b"].line == 1


def test_a_recursive_alias_is_refused():
    with pytest.raises(YamlError, match=r"^<string>:1: alias '\*a' is inside the node it names"):
        load_yaml_text("a: &a [1, *a]\n")


def test_an_undefined_alias_is_refused_with_its_line():
    with pytest.raises(YamlError, match=r"^<string>:2: invalid YAML: alias '\*nope' names no anchor"):
        load_yaml_text("a: 1\nb: *nope\n")


@pytest.mark.parametrize("depth", [65, 1000, 100_000])
def test_deep_nesting_is_refused_without_recursion(depth):
    with pytest.raises(YamlError) as info:
        load_yaml_text("a: " + "[" * depth + "]" * depth + "\n", "deep.yaml")
    assert str(info.value) == "deep.yaml:1: YAML nested deeper than 64 levels"


def test_nesting_up_to_the_limit_is_fine():
    assert load_yaml_text("[" * 64 + "]" * 64) is not None


def test_nesting_through_an_alias_counts_too():
    from taskrunner.yamlfile import YamlLimits

    text = "a: &a [[[1]]]\nb: [[*a]]\n"
    assert load_yaml_text(text, limits=YamlLimits(max_depth=6))
    with pytest.raises(YamlError, match=r":2: YAML nested deeper than 5 levels \(through '\*a'\)"):
        load_yaml_text(text, limits=YamlLimits(max_depth=5))


def test_the_node_limit_bounds_a_flat_file():
    from taskrunner.yamlfile import YamlLimits

    with pytest.raises(YamlError, match=r"^<string>:1: YAML has more than 100 nodes"):
        load_yaml_text("[" + "1, " * 200 + "]", limits=YamlLimits(max_nodes=100))


def test_a_file_over_the_size_limit_is_refused_unread(tmp_path):
    from taskrunner.yamlfile import YamlLimits

    path = tmp_path / "big.yaml"
    path.write_text("description: '" + "x" * 20_000_000 + "'\n")
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value) == f"{path}: file is too large (20.0 MB; the limit is 4.2 MB)"
    with pytest.raises(YamlError, match=r"small.yaml: file is too large \(500 bytes; "
                                        r"the limit is 100 bytes\)"):
        load_yaml(write(tmp_path, "a: 1\n" * 100, "small.yaml"), YamlLimits(max_bytes=100))


@pytest.mark.parametrize(
    ("data", "message"),
    [
        ("a: 1\n".encode("utf-16"), "file is not UTF-8 text (it is UTF-16 or UTF-32: save it as UTF-8)"),
        ("a: 1\n".encode("utf-16-le"), "file is not UTF-8 text (a NUL byte: a binary file, or UTF-16)"),
        (b"a: 1\n\x7fELF\x00\x01", "file is not UTF-8 text (a NUL byte: a binary file, or UTF-16)"),
    ],
    ids=["utf-16 with BOM", "utf-16 without BOM", "binary"],
)
def test_binary_and_utf16_files_are_refused(tmp_path, data, message):
    path = tmp_path / "f.yaml"
    path.write_bytes(data)
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert info.value.reason == message and info.value.path == path


def test_a_utf8_byte_order_mark_is_fine(tmp_path):
    path = tmp_path / "bom.yaml"
    path.write_bytes(b"\xef\xbb\xbfa: 1\n")
    assert load_yaml(path) == {"a": 1}


def test_a_fifo_is_refused_without_blocking(tmp_path):
    import os

    path = tmp_path / "fifo.yaml"
    os.mkfifo(path)
    with pytest.raises(YamlError) as info:
        load_yaml(path)  # would block forever if opened for reading without O_NONBLOCK
    assert str(info.value) == f"{path}: not a regular file (a FIFO (named pipe))"


@pytest.mark.parametrize(
    ("path", "message"),
    [
        ("/dev/zero", "not a regular file (a character device)"),
        ("/proc/self/environ", "not a regular file (a pseudo-file under /proc)"),
        ("/", "not a regular file (a directory)"),
    ],
)
def test_devices_pseudo_files_and_folders_are_refused(path, message):
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value) == f"{path}: {message}"


def test_a_symlink_loop_is_refused(tmp_path):
    import os

    path = tmp_path / "loop.yaml"
    os.symlink(path, path)
    with pytest.raises(YamlError) as info:
        load_yaml(path)
    assert str(info.value) == f"{path}: symlink loop (too many levels of symbolic links)"


@pytest.mark.parametrize(
    ("text", "line", "reason"),
    [
        ("a:\n  b: 1\n c: 2\n", 3, "this line does not line up with the keys above it "
                                   "(check its indentation)"),
        ("a: 1\n  b: 2\n", 2, "a 'key: value' where none can start: check the indentation "
                              "of this line, or quote a value that contains ': '"),
        ("a: [1, 2\nb: 3\n", 2, "a '[' list is not closed with ']'"),
        ("- a\nb: 1\n", 2, "this line does not line up with the list items above it "
                           "(check its indentation)"),
    ],
    ids=["dedent", "indent", "unclosed list", "list then key"],
)
def test_indentation_errors_are_told_in_plain_words(text, line, reason):
    with pytest.raises(YamlError) as info:
        load_yaml_text(text, "f.yaml")
    assert str(info.value) == f"f.yaml:{line}: invalid YAML: {reason}"
    assert "while parsing" not in str(info.value)
