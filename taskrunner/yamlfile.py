"""YAML loading that remembers where every node came from and refuses repeated keys.

PyYAML's ``safe_load`` silently keeps the last of two equal keys, which hides real
mistakes in hand-written MoveIt configs and task files. :func:`load_yaml` raises a
:class:`~taskrunner.errors.YamlError` naming the file and both lines instead, and returns
mappings and sequences that know their line numbers, so later checks can point back
into the file too.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from taskrunner.errors import YamlError

__all__ = ["LineDict", "LineList", "load_yaml", "load_yaml_text", "line_of"]


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


class _Loader(yaml.SafeLoader):
    """SafeLoader that builds LineDict / LineList and rejects duplicate keys."""


def _construct_mapping(loader: _Loader, node: yaml.MappingNode) -> LineDict:
    # flatten_mapping puts the pairs of ``<<: *anchor`` merges before the mapping's own
    # pairs, ordered so that the later pair wins (YAML merge semantics): merged keys may
    # be overridden, only the mapping's own keys must not repeat.
    own_pairs = sum(1 for key_node, _ in node.value if key_node.tag != "tag:yaml.org,2002:merge")
    loader.flatten_mapping(node)
    merged_pairs = len(node.value) - own_pairs
    result = LineDict()
    result.line = node.start_mark.line + 1
    own_keys: set[Any] = set()
    for index, (key_node, value_node) in enumerate(node.value):
        key = loader.construct_object(key_node, deep=True)
        try:
            hash(key)
        except TypeError:
            raise YamlError(
                f"mapping key must be a scalar (got {key!r})",
                loader.name,
                key_node.start_mark.line + 1,
            ) from None
        if index >= merged_pairs:
            if key in own_keys:
                first = result.key_lines[key]
                raise YamlError(
                    f"duplicate key {key!r} (first defined on line {first})",
                    loader.name,
                    key_node.start_mark.line + 1,
                )
            own_keys.add(key)
        result[key] = loader.construct_object(value_node, deep=True)
        result.key_lines[key] = key_node.start_mark.line + 1
    return result


def _construct_sequence(loader: _Loader, node: yaml.SequenceNode) -> LineList:
    result = LineList(loader.construct_object(child, deep=True) for child in node.value)
    result.line = node.start_mark.line + 1
    result.item_lines = [child.start_mark.line + 1 for child in node.value]
    return result


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)
_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_SEQUENCE_TAG, _construct_sequence)


def load_yaml_text(text: str, path: str | Path | None = None) -> Any:
    """Parse YAML text; ``path`` only labels error messages.

    Raises:
        YamlError: the text does not parse, or a mapping repeats a key.
    """
    try:
        # The reader checks the characters when it is made: keep it inside the try.
        loader = _Loader(text)
    except yaml.reader.ReaderError as exc:
        at = text.count("\n", 0, exc.position) + 1
        raise YamlError(f"invalid YAML: character #x{exc.character:04x} is not allowed",
                        path, at) from None
    loader.name = str(path) if path is not None else "<string>"
    try:
        return loader.get_single_data()
    except YamlError:
        raise
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark is not None else None
        reason = " ".join(part for part in (exc.context, exc.problem) if part)
        raise YamlError(f"invalid YAML: {reason}", path, line) from None
    except yaml.YAMLError as exc:
        raise YamlError(f"invalid YAML: {exc}", path) from None
    finally:
        loader.dispose()


def load_yaml(path: str | Path) -> Any:
    """Read and parse a YAML file.

    Raises:
        YamlError: the file is missing or unreadable, does not parse, or repeats a key.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise YamlError("file not found", path) from None
    except OSError as exc:
        raise YamlError(f"cannot read file: {exc.strerror}", path) from None
    except UnicodeDecodeError as exc:
        raise YamlError(f"file is not UTF-8 text ({exc.reason})", path) from None
    return load_yaml_text(text, path)
