"""Validating YAML nodes with pydantic while keeping file:line in every message.

pydantic reports a location as a tuple of keys (``("robots", 0, "base", "xyz")``); the
node tree from :func:`taskrunner.yamlfile.load_yaml` knows the line of each of those
keys. :func:`validate_node` joins the two, so a typo in a cell or task file is reported
as ``cell.yaml:12: robots[0].base.xyz: …``, every problem at once.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from taskrunner.errors import YamlError
from taskrunner.yamlfile import line_of

__all__ = ["locate", "validate_node"]

M = TypeVar("M", bound=BaseModel)


def locate(node: Any, loc: tuple[Any, ...]) -> int | None:
    """Line of the deepest element of ``loc`` that can be found in ``node``."""
    line = line_of(node)
    for key in loc:
        if isinstance(node, dict) and key in node:
            line = line_of(node, key) or line
            node = node[key]
        elif isinstance(node, list) and isinstance(key, int) and 0 <= key < len(node):
            line = line_of(node, key) or line
            node = node[key]
        else:
            break
    return line


def _dotted(loc: tuple[Any, ...]) -> str:
    out = ""
    for key in loc:
        if isinstance(key, int):
            out += f"[{key}]"
        else:
            out += ("." if out else "") + str(key)
    return out or "(top level)"


def validate_node(model: type[M], node: Any, path: str | Path | None) -> M:
    """Validate ``node`` against pydantic ``model``.

    Raises:
        YamlError: located at the first problem; its message lists every problem, each
            with its own line.
    """
    try:
        return model.model_validate(node)
    except ValidationError as exc:
        problems = []
        for error in exc.errors(include_url=False):
            loc = tuple(k for k in error["loc"] if not (isinstance(k, str) and k.startswith("function-")))
            # Discriminated unions add the tag name to the location: drop it.
            loc = tuple(k for k in loc if not (isinstance(k, str) and k[:1].isupper()))
            line = locate(node, loc)
            message = error["msg"]
            if error["type"] == "extra_forbidden":
                message = "unknown field"
            elif error["type"] == "missing":
                message = "field required"
            value = error.get("input")
            shown = "" if error["type"] in ("missing", "extra_forbidden") or isinstance(
                value, dict
            ) else f" (got {value!r})"
            problems.append((line, f"{_dotted(loc)}: {message}{shown}"))
        first_line = problems[0][0]
        if len(problems) == 1:
            raise YamlError(problems[0][1], path, first_line) from None
        listed = "\n".join(
            f"  {path}:{line}: {text}" if line is not None else f"  {path}: {text}"
            for line, text in problems
        )
        raise YamlError(f"{len(problems)} problems:\n{listed}", path, first_line) from None
