"""Validating YAML nodes with pydantic while keeping file:line in every message.

pydantic reports a location as a tuple of keys (``("robots", 0, "base", "xyz")``); the
node tree from :func:`taskrunner.yamlfile.load_yaml` knows the line of each of those
keys. :func:`validate_node` joins the two, so a typo in a cell or task file is reported
as ``cell.yaml:12: robots[0].base.xyz: …``, every problem at once.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Annotated, Any, TypeVar

from pydantic import AfterValidator, BaseModel, Field, Strict, ValidationError

from taskrunner.errors import ArgumentError, YamlError
from taskrunner.yamlfile import line_of

__all__ = ["MAX_METRES", "MAX_RADIANS", "NUMBER", "Integer", "Metres", "NonNegativeMetres",
           "Number", "PositiveMetres", "Radians", "Scale", "check_number", "locate",
           "validate_node", "without_cascades"]

M = TypeVar("M", bound=BaseModel)

MAX_METRES = 1000.0
"""Largest coordinate, size or distance a file may give (m): a cell is not a kilometre
wide, and a bound keeps later arithmetic (path lengths, step counts) finite."""
MAX_RADIANS = 100.0
"""Largest angle a file may give (rad, about 16 turns)."""


def check_number(value: float, low: float, high: float, unit: str = "",
                 low_open: bool = False) -> str | None:
    """What is wrong with ``value`` as a finite number in [low, high] (``(low, high]``
    when ``low_open``), as the end of an attrs-style message, or None if nothing is.

    >>> check_number(float("nan"), 0, 1000, "m", low_open=True)
    'must be a finite number > 0 and ≤ 1000 m (got nan)'
    """
    unit = f" {unit}" if unit else ""
    if low == -high:
        expected = f"a finite number within ±{high:g}{unit}"
    else:
        expected = f"a finite number {'>' if low_open else '≥'} {low:g} and ≤ {high:g}{unit}"
    ok = math.isfinite(value) and (value > low if low_open else value >= low) and value <= high
    return None if ok else f"must be {expected} (got {value!r})"


def _bounded(low: float, high: float, unit: str, low_open: bool = False) -> Callable[[float], float]:
    def check(value: float) -> float:
        problem = check_number(value, low, high, unit, low_open)
        if problem is not None:
            raise ArgumentError(problem)
        return value
    return check


NUMBER = Strict()
"""Numbers as numbers: pydantic's lax mode reads ``true`` as 1 and ``"0.5"`` as 0.5; a
strict float takes an int or a float only (never a boolean or text), a strict int an
int only. Put it first in ``Annotated``; bounds (``Field(gt=…)``) still apply."""
Number = Annotated[float, NUMBER, Field(allow_inf_nan=False)]
"""A finite number; not a boolean, not text."""
Integer = Annotated[int, NUMBER]
"""An integer; not a boolean, a float or text."""

# The JSON-schema bounds tell editors; the validators give the messages.
Metres = Annotated[float, NUMBER, AfterValidator(_bounded(-MAX_METRES, MAX_METRES, "m")),
                   Field(json_schema_extra={"minimum": -MAX_METRES, "maximum": MAX_METRES})]
"""A coordinate (m): finite, within ±:data:`MAX_METRES`."""
Radians = Annotated[float, NUMBER, AfterValidator(_bounded(-MAX_RADIANS, MAX_RADIANS, "rad")),
                    Field(json_schema_extra={"minimum": -MAX_RADIANS, "maximum": MAX_RADIANS})]
"""An angle (rad): finite, within ±:data:`MAX_RADIANS`."""
PositiveMetres = Annotated[float, NUMBER, AfterValidator(_bounded(0.0, MAX_METRES, "m", low_open=True)),
                           Field(json_schema_extra={"exclusiveMinimum": 0,
                                                    "maximum": MAX_METRES})]
"""A size, radius or length (m): finite, > 0, at most :data:`MAX_METRES`."""
NonNegativeMetres = Annotated[float, NUMBER, AfterValidator(_bounded(0.0, MAX_METRES, "m")),
                              Field(json_schema_extra={"minimum": 0, "maximum": MAX_METRES})]
"""A distance (m): finite, ≥ 0, at most :data:`MAX_METRES`."""
Scale = Annotated[float, NUMBER, AfterValidator(_bounded(0.0, 1e6, "", low_open=True)),
                  Field(json_schema_extra={"exclusiveMinimum": 0, "maximum": 1e6})]
"""A mesh scale factor: finite, > 0."""


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


def without_cascades(errors: Sequence[Any]) -> list[Any]:
    """Pydantic's errors without the echoes of another: a tuple with a bad item is also
    reported as too short (the bad item left out), and the item's own error says it all.
    Used for cell files, task files and REST requests alike."""
    items_failed = {tuple(e["loc"][:-1]) for e in errors
                    if e["loc"] and isinstance(e["loc"][-1], int)}
    return [e for e in errors
            if not (e["type"] == "too_short" and tuple(e["loc"]) in items_failed)]


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
        for error in without_cascades(exc.errors(include_url=False)):
            loc = tuple(k for k in error["loc"] if not (isinstance(k, str) and k.startswith("function-")))
            # Discriminated unions add the tag name to the location: drop it.
            loc = tuple(k for k in loc if not (isinstance(k, str) and k[:1].isupper()))
            line = locate(node, loc)
            message = error["msg"]
            if error["type"] == "value_error" and loc:
                # Our own checks say what they expect and what they got (attrs style).
                reason = str((error.get("ctx") or {}).get("error", message))
                problems.append((line, f"'{_dotted(loc)}' {reason}" if reason.startswith(
                    "must be") else f"{_dotted(loc)}: {reason}"))
                continue
            if error["type"] == "finite_number":
                problems.append((line, f"'{_dotted(loc)}' must be a finite number "
                                       f"(got {error.get('input')!r})"))
                continue
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
