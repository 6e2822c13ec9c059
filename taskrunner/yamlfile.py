"""The one YAML reader for every user file: line numbers, no repeated keys, hard limits.

Every task, cell, robot manifest and MoveIt YAML file is read by :func:`load_yaml`. It
returns mappings and sequences that know their line numbers (:class:`LineDict`,
:class:`LineList`), so later checks can point back into the file, and raises a
:class:`~taskrunner.errors.YamlError` naming the file and line for:

- a repeated key (``duplicate key 'x' (first defined on line N)``): a safe loader would
  silently keep the last one and hide a real mistake;
- syntax errors, told in plain words (a tab, a line that does not line up, …);
- explicit tags other than the core ones (``!!str``, ``!!int``, ``!!float``, ``!!bool``,
  ``!!null``, ``!!map``, ``!!seq``) and values that do not fit theirs (``!!int "abc"``);
- hostile input (:class:`YamlLimits`): a file over the size limit, nesting deeper than the
  depth limit, more nodes than the node limit, aliases that would expand to more nodes
  than the alias limit (a "billion laughs" bomb is refused when its aliases are counted,
  before anything is expanded), an alias of a node that contains it.

The file is read by :func:`taskrunner.textfile.read_text_file` (regular UTF-8 files
only). Parsing is YAML 1.2 through ruamel.yaml's public event API: ``on``, ``yes`` and
``no`` are strings; ``true``/``false`` are booleans. Merge keys (``<<: *defaults``)
follow the merge-key spec: the mapping's own keys override merged ones, and of several
merged mappings the first listed wins. The tree is built from the event stream without
recursion, so no depth of nesting reaches Python's recursion limit.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ruamel.yaml import YAML
from ruamel.yaml import events as ev
from ruamel.yaml.error import MarkedYAMLError, YAMLError
from ruamel.yaml.nodes import ScalarNode

from taskrunner.errors import ArgumentError, YamlError
from taskrunner.textfile import DEFAULT_MAX_BYTES, read_text_file

__all__ = ["DEFAULT_LIMITS", "LineDict", "LineList", "YamlLimits", "line_of", "load_yaml",
           "load_yaml_text"]


@dataclass(frozen=True)
class YamlLimits:
    """Bounds on one YAML file, so that a hostile file is refused quickly.

    Attributes:
        max_bytes: file size (bytes, UTF-8).
        max_depth: nesting of mappings and sequences.
        max_nodes: nodes written in the file (scalars, mappings, sequences).
        max_alias_nodes: nodes produced by expanding aliases (``*name``), summed over
            every alias: each alias counts the nodes of what it names.
    """

    max_bytes: int = DEFAULT_MAX_BYTES
    max_depth: int = 64
    max_nodes: int = 200_000
    max_alias_nodes: int = 100_000

    def __post_init__(self) -> None:
        for name in ("max_bytes", "max_depth", "max_nodes", "max_alias_nodes"):
            value = getattr(self, name)
            if not isinstance(value, int) or value < 1:
                raise ArgumentError(f"{name!r} must be a positive integer (got {value!r})")


DEFAULT_LIMITS = YamlLimits()


class LineDict(dict):
    """A mapping from YAML that knows its own line and the line of each key (1-based)."""

    line: int | None = None
    key_lines: dict[Any, int]

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.key_lines = {}

    def line_of(self, key: Any) -> int | None:
        """Line of ``key`` in the file, or of the mapping itself if the key is absent."""
        return self.key_lines.get(key, self.line)


class LineList(list):
    """A sequence from YAML that knows its own line and the line of each item (1-based)."""

    line: int | None = None
    item_lines: list[int]

    def __init__(self, *args: Any) -> None:
        super().__init__(*args)
        self.item_lines = []


def line_of(node: Any, key: Any = None) -> int | None:
    """Line of ``node`` (or of ``node[key]``) if it came from :func:`load_yaml`, else None."""
    if isinstance(node, LineDict):
        return node.line_of(key) if key is not None else node.line
    if isinstance(node, LineList):
        if isinstance(key, int) and 0 <= key < len(node.item_lines):
            return node.item_lines[key]
        return node.line
    return None


def load_yaml(path: str | Path, limits: YamlLimits | None = None) -> Any:
    """Read and parse a YAML file.

    Args:
        path: the file.
        limits: bounds on size, depth and alias expansion (default :data:`DEFAULT_LIMITS`).

    Raises:
        YamlError: the file is missing, not a regular UTF-8 file, over a limit, does not
            parse, or repeats a key.
    """
    limits = limits or DEFAULT_LIMITS
    text = read_text_file(path, YamlError, limits.max_bytes)
    return load_yaml_text(text, path, limits)


def load_yaml_text(text: str, path: str | Path | None = None,
                   limits: YamlLimits | None = None) -> Any:
    """Parse YAML text; ``path`` only labels error messages.

    Raises:
        YamlError: the text is over a limit, does not parse, or a mapping repeats a key.
    """
    limits = limits or DEFAULT_LIMITS
    label = path if path is not None else "<string>"
    size = len(text.encode("utf-8", "surrogatepass"))
    if size > limits.max_bytes:
        raise YamlError(f"YAML text is too large ({size} bytes; the limit is "
                        f"{limits.max_bytes} bytes)", label)
    bad = _FORBIDDEN.search(text)
    if bad is not None:
        at = text.count("\n", 0, bad.start()) + 1
        raise YamlError(f"invalid YAML: character #x{ord(bad.group()):04x} is not allowed",
                        label, at)
    builder = _Builder(label, limits)
    try:
        for event in _YAML.parse(text):
            builder.feed(event)
    except YamlError:
        raise
    except MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark is not None else None
        raise YamlError(f"invalid YAML: {_plain_reason(exc)}", label, line) from None
    except YAMLError as exc:
        raise YamlError(f"invalid YAML: {' '.join(str(exc).split())}", label) from None
    return builder.result


# ------------------------------------------------------------------------------ parsing
_YAML = YAML(typ="safe")  # the parser (C if available) and the YAML 1.2 resolver
_RESOLVER = _YAML.resolver

# Characters YAML allows in a stream (YAML 1.2, 5.1): TAB, LF, CR, printable ASCII,
# NEL, and the printable Unicode ranges.
_FORBIDDEN = re.compile("[^\t\n\r\x20-\x7e\x85\xa0-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")

_TAG = "tag:yaml.org,2002:"
_CORE_SCALAR_TAGS = ("str", "int", "float", "bool", "null")
_INT = re.compile(r"[-+]?(0x[0-9a-fA-F_]+|0o[0-7_]+|0b[01_]+|[0-9][0-9_]*)")
_FLOAT_SPECIAL = {".inf": math.inf, "+.inf": math.inf, "-.inf": -math.inf, ".nan": math.nan}

# Parser problems in plain words (the parser's own text names its internal states).
_PLAIN_REASONS = (
    ("found character '\\t'", "a tab character: indent with spaces"),
    ("found character that cannot start any token",
     "a character that cannot start a value here (a tab? indent with spaces; "
     "quote values starting with '@' or '`')"),
    ("mapping values are not allowed",
     "a 'key: value' where none can start: check the indentation of this line, "
     "or quote a value that contains ': '"),
    ("could not find expected ':'",
     "expected 'key: value': a ':' is missing, or the line is indented wrongly"),
    ("did not find expected key",
     "this line does not line up with the keys above it (check its indentation)"),
    ("did not find expected '-' indicator",
     "this line does not line up with the list items above it (check its indentation)"),
    ("expected <block end>",
     "this line does not line up with the lines above it (check its indentation)"),
    ("did not find expected ',' or ']'", "a '[' list is not closed with ']'"),
    ("did not find expected ',' or '}'", "a '{' mapping is not closed with '}'"),
    ("found unexpected end of stream", "the file ends inside a quoted string"),
    ("found unknown escape character", "an unknown escape (\\…) in a double-quoted string"),
    ("found undefined alias", "an alias (*name) with no anchor (&name) before it"),
    ("expected a single document", "a file holds one YAML document (found a second '---')"),
)


def _plain_reason(exc: MarkedYAMLError) -> str:
    problem = str(exc.problem or "")
    for needle, reason in _PLAIN_REASONS:
        if needle in problem:
            return reason
    text = " ".join(part for part in (exc.context, exc.problem) if part)
    return " ".join(text.split()) or type(exc).__name__


_MERGE = object()
_NO_KEY = object()


@dataclass
class _Frame:
    """A mapping or sequence being built."""

    value: LineDict | LineList
    anchor: str | None
    line: int
    size: int = 1
    key: Any = _NO_KEY
    key_line: int = 0
    merges: list[tuple[LineDict, int]] = field(default_factory=list)


class _Builder:
    """Builds the LineDict / LineList tree from parser events, with the limits checked
    as the events arrive (nothing is expanded before it has been counted)."""

    def __init__(self, path: str | Path, limits: YamlLimits) -> None:
        self.path = path
        self.limits = limits
        self.stack: list[_Frame] = []
        self.anchors: dict[str, tuple[Any, int]] = {}
        self.open_anchors: set[str] = set()
        self.nodes = 0
        self.alias_nodes = 0
        self.documents = 0
        self.result: Any = None

    def error(self, message: str, line: int | None) -> YamlError:
        return YamlError(message, self.path, line)

    def feed(self, event: ev.Event) -> None:
        line = event.start_mark.line + 1 if event.start_mark is not None else None
        if isinstance(event, ev.ScalarEvent):
            self.count_node(line)
            key = _MERGE if (event.value == "<<" and event.tag is None
                             and event.implicit[0]) else None
            scalar = key if key is _MERGE else self.scalar(event, line)
            self.add(scalar, line or 0, 1, event.anchor)
        elif isinstance(event, (ev.MappingStartEvent, ev.SequenceStartEvent)):
            self.count_node(line)
            if len(self.stack) >= self.limits.max_depth:
                raise self.error(f"YAML nested deeper than {self.limits.max_depth} levels",
                                 line)
            self.check_collection_tag(event, line)
            node: LineDict | LineList = (LineDict() if isinstance(event, ev.MappingStartEvent)
                                         else LineList())
            node.line = line
            if event.anchor is not None:
                self.open_anchors.add(event.anchor)
            self.stack.append(_Frame(node, event.anchor, line or 0))
        elif isinstance(event, (ev.MappingEndEvent, ev.SequenceEndEvent)):
            frame = self.stack.pop()
            if frame.anchor is not None:
                self.open_anchors.discard(frame.anchor)
            done = self.merged(frame) if isinstance(frame.value, LineDict) else frame.value
            self.add(done, frame.line, frame.size, frame.anchor)
        elif isinstance(event, ev.AliasEvent):
            self.alias(event, line)
        elif isinstance(event, ev.DocumentStartEvent):
            self.documents += 1
            if self.documents > 1:
                raise self.error("invalid YAML: a file holds one YAML document "
                                 "(found a second '---')", line)

    def count_node(self, line: int | None) -> None:
        self.nodes += 1
        if self.nodes > self.limits.max_nodes:
            raise self.error(f"YAML has more than {self.limits.max_nodes} nodes", line)

    def alias(self, event: ev.AliasEvent, line: int | None) -> None:
        name = event.anchor
        if name in self.open_anchors:
            raise self.error(f"alias '*{name}' is inside the node it names "
                             "(a recursive structure)", line)
        if name not in self.anchors:
            raise self.error(f"invalid YAML: alias '*{name}' names no anchor "
                             f"('&{name}' before it)", line)
        value, size = self.anchors[name]
        self.alias_nodes += size
        if self.alias_nodes > self.limits.max_alias_nodes:
            raise self.error(f"aliases expand to more than {self.limits.max_alias_nodes} "
                             f"nodes (at '*{name}'; an alias bomb?)", line)
        if len(self.stack) + _depth(value) > self.limits.max_depth:
            raise self.error(f"YAML nested deeper than {self.limits.max_depth} levels "
                             f"(through '*{name}')", line)
        self.add(_copy(value), line or 0, size, None)

    def add(self, value: Any, line: int, size: int, anchor: str | None) -> None:
        """Put a finished node into its parent (or make it the document)."""
        frame = self.stack[-1] if self.stack else None
        if value is _MERGE and (frame is None or not isinstance(frame.value, LineDict)
                                or frame.key is not _NO_KEY):
            value = "<<"  # '<<' only merges as a key
        if anchor is not None:
            self.anchors[anchor] = (value, size)
        if frame is None:
            self.result = value
            return
        frame.size += size
        if isinstance(frame.value, LineList):
            frame.value.append(value)
            frame.value.item_lines.append(line)
            return
        if frame.key is _NO_KEY:
            if isinstance(value, (LineDict, LineList)):
                raise self.error(f"mapping key must be a scalar (got {value!r})", line)
            frame.key, frame.key_line = value, line
            return
        key, key_line = frame.key, frame.key_line
        frame.key = _NO_KEY
        if key is _MERGE:
            self.add_merge(frame, value, key_line)
            return
        mapping = frame.value
        if key in mapping:
            raise self.error(f"duplicate key {key!r} (first defined on line "
                             f"{mapping.key_lines[key]})", key_line)
        mapping[key] = value
        mapping.key_lines[key] = key_line

    def add_merge(self, frame: _Frame, value: Any, line: int) -> None:
        if frame.merges:
            raise self.error("duplicate key '<<' (merge them in one list: "
                             "'<<: [*a, *b]')", line)
        sources = value if isinstance(value, LineList) else [value]
        for source in sources:
            if not isinstance(source, LineDict):
                raise self.error("'<<' (merge key) must name a mapping or a list of "
                                 f"mappings (got {source!r})", line)
            frame.merges.append((source, line))
        if not frame.merges:
            raise self.error("'<<' (merge key) must name a mapping or a list of mappings "
                             "(got [])", line)

    def merged(self, frame: _Frame) -> LineDict:
        """The frame's mapping with its merge sources: own keys win, then the first
        source listed that has the key."""
        own = frame.value
        assert isinstance(own, LineDict)
        if frame.key is not _NO_KEY:  # cannot happen with a well-formed event stream
            raise self.error("mapping key without a value", frame.key_line)
        if not frame.merges:
            return own
        result = LineDict()
        result.line = own.line
        for source, _ in frame.merges:
            for key, value in source.items():
                if key not in own and key not in result:
                    result[key] = value
                    result.key_lines[key] = source.key_lines.get(key, frame.line)
        for key, value in own.items():
            result[key] = value
            result.key_lines[key] = own.key_lines[key]
        return result

    def check_collection_tag(self, event: ev.CollectionStartEvent, line: int | None) -> None:
        tag = _tag_text(event.tag)
        if tag is None:
            return
        expected = "map" if isinstance(event, ev.MappingStartEvent) else "seq"
        if tag != _TAG + expected:
            raise self.error(f"invalid YAML: tag {_short(tag)!r} is not supported here "
                             f"(only !!{expected})", line)

    def scalar(self, event: ev.ScalarEvent, line: int | None) -> Any:
        tag = _tag_text(event.tag)
        text = event.value
        if tag is None:
            if not event.implicit[0]:  # quoted: a string
                return text
            tag = str(_RESOLVER.resolve(ScalarNode, text, (True, False)))
            if tag[len(_TAG):] not in _CORE_SCALAR_TAGS:
                return text  # a timestamp, '=' …: kept as written
        kind = tag[len(_TAG):] if tag.startswith(_TAG) else None
        if kind not in _CORE_SCALAR_TAGS:
            raise self.error(f"invalid YAML: tag {_short(tag)!r} is not supported (only "
                             "!!str, !!int, !!float, !!bool, !!null)", line)
        try:
            return _convert(kind, text)
        except ValueError:
            shown = text if len(text) <= 40 else text[:40] + "…"
            raise self.error(f"invalid YAML: {shown!r} is not a valid !!{kind}", line) from None


def _tag_text(tag: Any) -> str | None:
    if tag is None:
        return None
    text = str(getattr(tag, "value", tag))
    return None if text in ("", "!") else text


def _short(tag: str) -> str:
    return "!!" + tag[len(_TAG):] if tag.startswith(_TAG) else tag


def _convert(kind: str | None, text: str) -> Any:
    """The value of scalar ``text`` of core type ``kind`` (ValueError if it is none)."""
    if kind == "str":
        return text
    if kind == "null":
        if text not in ("", "~", "null", "Null", "NULL"):
            raise ValueError(text)
        return None
    if kind == "bool":
        lowered = text.lower()
        if lowered not in ("true", "false"):
            raise ValueError(text)
        return lowered == "true"
    if kind == "int":
        if _INT.fullmatch(text) is None:
            raise ValueError(text)
        digits = text.replace("_", "")
        sign = -1 if digits.startswith("-") else 1
        digits = digits.lstrip("+-")
        base = {"0x": 16, "0o": 8, "0b": 2}.get(digits[:2].lower(), 10)
        # int() refuses more than 4300 digits (ValueError), which bounds the work.
        return sign * int(digits[2:] if base != 10 else digits, base)
    if kind == "float":
        special = _FLOAT_SPECIAL.get(text.lower())
        if special is not None:
            return special
        try:
            return float(text.replace("_", ""))
        except ValueError:
            raise ValueError(text) from None
    raise ValueError(text)


def _copy(value: Any) -> Any:
    """A deep copy of a built node, lines kept (an alias gets its own copy)."""
    if isinstance(value, LineDict):
        out = LineDict((k, _copy(v)) for k, v in value.items())
        out.line, out.key_lines = value.line, dict(value.key_lines)
        return out
    if isinstance(value, LineList):
        seq = LineList(_copy(v) for v in value)
        seq.line, seq.item_lines = value.line, list(value.item_lines)
        return seq
    return value


def _depth(value: Any) -> int:
    """Nesting depth of a built node (0 for a scalar)."""
    if isinstance(value, LineDict):
        return 1 + max((_depth(v) for v in value.values()), default=0)
    if isinstance(value, LineList):
        return 1 + max((_depth(v) for v in value), default=0)
    return 0
