"""taskrunner.robot.xmldoc: element lines and located XML errors."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot.xmldoc import parse_xml, read_xml

TEXT = """\
<?xml version="1.0"?>
<!-- a comment
     over two lines -->
<robot name="r">
  <link name="a"/>

  <joint name="j"
         type="fixed">
    <parent link="a"/>
    <child
      link="b"/>
  </joint>
  <link name="b"></link>
</robot>
"""


def test_every_element_knows_the_line_its_start_tag_begins_on():
    doc = parse_xml(TEXT, "robot.urdf")
    root = doc.root
    assert doc.line(root) == 4
    assert doc.line(root.find("link")) == 5
    joint = root.find("joint")
    assert doc.line(joint) == 7  # a start tag over two lines: its first line
    assert doc.line(joint.find("parent")) == 9
    assert doc.line(joint.find("child")) == 10
    assert doc.line(root.findall("link")[1]) == 13


def test_attributes_and_text_are_kept():
    doc = parse_xml('<robot name="r"><name> pkg </name><x a="1" b="two"/></robot>')
    assert doc.root.get("name") == "r"
    assert doc.root.find("name").text == " pkg "
    assert doc.root.find("x").attrib == {"a": "1", "b": "two"}


def test_element_added_after_parsing_has_no_line():
    doc = parse_xml(TEXT)
    assert doc.line(ET.SubElement(doc.root, "link", name="c")) is None


def test_error_at_an_element_names_file_and_line(tmp_path):
    doc = parse_xml(TEXT, tmp_path / "robot.urdf")
    error = doc.error(doc.root.find("joint"), "joint 'j': something is wrong")
    assert isinstance(error, RobotDescriptionError)
    assert str(error) == f"{tmp_path / 'robot.urdf'}:7: joint 'j': something is wrong"
    assert str(doc.error(None, "whole file")) == f"{tmp_path / 'robot.urdf'}: whole file"


@pytest.mark.parametrize(
    ("text", "line", "reason"),
    [
        ('<robot>\n  <link name="a">\n</robot>\n', 3, "mismatched tag"),
        ('<robot>\n  <link name="a"/>\n  <link name=b/>\n</robot>\n', 3, "not well-formed (invalid token)"),
        ("<robot>\n</robot>\n<robot/>\n", 3, "junk after document element"),
        ('<robot>\n  <link name="a"/>\n', 3, "no element found"),
        ("", 1, "no element found"),
    ],
    ids=["mismatched", "unquoted-attribute", "two-roots", "truncated", "empty"],
)
def test_malformed_xml_is_a_robot_description_error_at_file_line(tmp_path, text, line, reason):
    path = tmp_path / "bad.srdf"
    path.write_text(text)
    with pytest.raises(RobotDescriptionError) as info:
        read_xml(path)
    assert str(info.value) == f"{path}:{line}: invalid XML: {reason}"


def test_missing_file_is_a_robot_description_error(tmp_path):
    with pytest.raises(RobotDescriptionError) as info:
        read_xml(tmp_path / "nope.urdf")
    assert str(info.value) == f"{tmp_path / 'nope.urdf'}: file not found"


def test_file_that_is_not_utf8_is_a_robot_description_error(tmp_path):
    path = tmp_path / "latin1.urdf"
    path.write_bytes('<robot name="caf\xe9"/>'.encode("latin-1"))
    with pytest.raises(RobotDescriptionError,
                       match=r"latin1.urdf:1: file is not UTF-8 text \(invalid byte 0xe9\)"):
        read_xml(path)


def test_an_element_made_where_a_removed_one_was_has_no_line():
    # Lines are kept by the element's id(): an element removed from the tree and freed
    # must not lend its line to a new element that the allocator puts at its address.
    import gc
    import xml.etree.ElementTree as ET

    doc = parse_xml("<robot>\n  <link name='a'/>\n  <link name='b'/>\n</robot>")
    gone = doc.root[0]
    assert doc.line(gone) == 2
    address = id(gone)
    doc.root.remove(gone)
    del gone
    gc.collect()
    made = []
    for _ in range(100_000):
        made.append(ET.Element("link"))
        if id(made[-1]) == address:
            break
    assert doc.line(doc.root[0]) == 3
    assert all(doc.line(element) is None for element in made)
