"""XML parsing that keeps the line of every element, for error messages.

The standard ElementTree parser drops source lines. We drive expat ourselves and keep a
side table from element to line, so an SRDF or URDF error can say ``robot.srdf:42``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from taskrunner.errors import RobotDescriptionError
from taskrunner.textfile import read_text_file

__all__ = ["MAX_XML_DEPTH", "XmlDocument", "parse_xml", "read_xml"]

MAX_XML_DEPTH = 64
"""Nesting of elements: a URDF or SRDF needs about 6; copying and walking a tree much
deeper would reach Python's recursion limit."""


class _TooDeep(Exception):
    pass


@dataclass
class XmlDocument:
    """A parsed XML document and the line of each of its elements."""

    root: ET.Element
    path: Path | None
    _lines: dict[int, tuple[ET.Element, int]] = field(default_factory=dict, repr=False)
    """By ``id()`` of the element: the element (kept, so that its id is never another's,
    even after it is removed from the tree) and its line."""

    def line(self, element: ET.Element) -> int | None:
        """1-based source line of ``element`` (None for elements added after parsing)."""
        kept = self._lines.get(id(element))
        return kept[1] if kept is not None and kept[0] is element else None

    def error(self, element: ET.Element | None, message: str) -> RobotDescriptionError:
        """An error located at ``element`` in this document."""
        line = self.line(element) if element is not None else None
        return RobotDescriptionError(message, self.path, line)


def parse_xml(text: str, path: str | Path | None = None) -> XmlDocument:
    """Parse XML text, keeping element lines; ``path`` labels error messages.

    Raises:
        RobotDescriptionError: the text is not well-formed XML.
    """
    builder = ET.TreeBuilder()
    parser = expat.ParserCreate()
    lines: dict[int, tuple[ET.Element, int]] = {}
    depth = 0

    def start(tag: str, attrs: dict[str, str]) -> None:
        nonlocal depth
        depth += 1
        if depth > MAX_XML_DEPTH:
            raise _TooDeep(parser.CurrentLineNumber)
        element = builder.start(tag, attrs)
        lines[id(element)] = (element, parser.CurrentLineNumber)

    def end(tag: str) -> None:
        nonlocal depth
        depth -= 1
        builder.end(tag)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = builder.data
    label = Path(path) if path is not None else None
    try:
        parser.Parse(text, True)
        root = builder.close()
    except expat.ExpatError as exc:
        raise RobotDescriptionError(
            f"invalid XML: {expat.ErrorString(exc.code)}", label, exc.lineno
        ) from None
    except _TooDeep as exc:
        raise RobotDescriptionError(f"XML nested deeper than {MAX_XML_DEPTH} elements",
                                    label, exc.args[0]) from None
    except AssertionError:
        raise RobotDescriptionError("invalid XML: no root element", label) from None
    return XmlDocument(root, label, lines)


def read_xml(path: str | Path) -> XmlDocument:
    """Read and parse an XML file.

    Raises:
        RobotDescriptionError: the file is missing, unreadable or not well-formed.
    """
    path = Path(path)
    return parse_xml(read_text_file(path, RobotDescriptionError), path)
