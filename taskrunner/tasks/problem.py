"""Problems found in a task file, and readable messages for pydantic's errors.

A :class:`Problem` is one thing wrong at one ``file:line``. The loader collects every
problem of a file (and of the files it includes) before raising one
:class:`~taskrunner.errors.TaskSpecError` listing them all; the name checks return
them without raising.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, get_args

from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo

from taskrunner.errors import TaskSpecError, did_you_mean
from taskrunner.validation import locate, without_cascades

__all__ = ["Problem", "did_you_mean", "problems_error", "problems_from_validation",
           "raise_for_problems"]


@dataclass(frozen=True)
class Problem:
    """One problem of a task file.

    Attributes:
        path: the file (None when the problem has no file, e.g. a bad API parameter).
        line: 1-based line in that file, if known.
        message: what is wrong, without the location.
    """

    path: Path | None
    line: int | None
    message: str

    def __str__(self) -> str:
        if self.path is None:
            return self.message
        where = f"{self.path}:{self.line}" if self.line is not None else str(self.path)
        return f"{where}: {self.message}"


def problems_error(problems: Sequence[Problem]) -> TaskSpecError:
    """One :class:`TaskSpecError` for ``problems`` (located at the first; all listed).

    The problems are also kept as the error's ``problems`` attribute.
    """
    first = problems[0]
    if len(problems) == 1:
        error = TaskSpecError(first.message, first.path, first.line)
    else:
        listed = "\n".join(f"  {p}" for p in problems)
        error = TaskSpecError(f"{len(problems)} problems:\n{listed}", first.path, first.line)
    error.problems = tuple(problems)  # type: ignore[attr-defined]
    return error


def raise_for_problems(problems: Sequence[Problem]) -> None:
    """Raise :func:`problems_error` if there are any problems."""
    if problems:
        raise problems_error(problems)


# ------------------------------------------------------------- pydantic errors → messages
_EXPECTED = {
    "float_type": "a number", "float_parsing": "a number", "finite_number": "a finite number",
    "int_type": "an integer", "int_parsing": "an integer", "int_from_float": "an integer",
    "bool_type": "true or false", "bool_parsing": "true or false",
    "string_type": "a string", "dict_type": "a mapping", "model_type": "a mapping",
    "model_attributes_type": "a mapping", "list_type": "a list", "tuple_type": "a list",
    "path_type": "a path",
}
_BOUNDS = {"greater_than": ">", "greater_than_equal": ">=", "less_than": "<",
           "less_than_equal": "<="}


def _dotted(parts: Sequence[Any]) -> str:
    out = ""
    for key in parts:
        if isinstance(key, int):
            out += f"[{key}]"
        elif isinstance(key, str) and key.isidentifier():
            out += ("." if out else "") + key
        else:
            out += f"[{key!r}]"
    return out


def _shown(value: Any) -> str:
    text = repr(dict(value) if isinstance(value, dict) else list(value) if isinstance(value, list)
                else value)
    return text if len(text) <= 60 else text[:57] + "..."


def _model_classes(annotation: Any) -> list[type[BaseModel]]:
    """The pydantic models an annotation can hold (through Optional, Annotated, tuple…)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    found: list[type[BaseModel]] = []
    for arg in get_args(annotation):
        found += _model_classes(arg)
    return found


def _length_bounds(info: FieldInfo) -> tuple[int | None, int | None]:
    """The min_length / max_length constraints of a field, wherever they are declared."""
    low = high = None
    stack: list[Any] = [info.annotation, *info.metadata]
    while stack:
        item = stack.pop()
        if isinstance(item, FieldInfo):
            stack.extend(item.metadata)
            continue
        if isinstance(getattr(item, "min_length", None), int):
            low = item.min_length
        if isinstance(getattr(item, "max_length", None), int):
            high = item.max_length
        stack.extend(get_args(item))
    return low, high


def _field_names(model: type[BaseModel]) -> dict[str, Any]:
    """YAML key → field info, for ``model`` (every accepted spelling of each field)."""
    names = {}
    for name, info in model.model_fields.items():
        names[info.alias or name] = info
        choices = getattr(info.validation_alias, "choices", ())
        names.update({c: info for c in choices if isinstance(c, str)})
    return names


def _model_at(model: type[BaseModel] | None, path: Sequence[Any]) -> type[BaseModel] | None:
    for key in path:
        if model is None:
            return None
        if isinstance(key, int):
            continue  # an item of a list field: same model as the field's items
        info = _field_names(model).get(key)
        if info is None:
            return None
        candidates = _model_classes(info.annotation)
        model = candidates[0] if candidates else None
    return model


def problems_from_validation(error: ValidationError, node: Any, file: Path | None,
                             where: Sequence[Any] = (),
                             model: type[BaseModel] | None = None,
                             line: int | None = None) -> list[Problem]:
    """Readable problems for ``error``, raised validating ``node`` (a YAML tree).

    Args:
        where: the path of what was validated, named in the messages: ``("pick",)`` for
            a step's body, ``("objects", 0)``, or ``()`` for the top level of a file.
        model: the model validated, to suggest field names for unknown keys.
        line: the line to report when ``node`` has none (a scalar where a mapping
            belongs).
    """
    problems = []
    for err in without_cascades(error.errors(include_url=False)):
        loc = tuple(k for k in err["loc"] if not (isinstance(k, str) and k.startswith("<")))
        found = locate(node, loc)
        problems.append(Problem(file, found if found is not None else line,
                                _message(err, loc, where, model)))
    return problems


def _message(err: Any, loc: tuple[Any, ...], where: Sequence[Any],
             model: type[BaseModel] | None) -> str:
    kind, ctx, value = err["type"], err.get("ctx") or {}, err.get("input")
    prefix = list(where)
    owner = _dotted(prefix + list(loc[:-1]))
    subject = _dotted(prefix + list(loc)) or "the task file"
    if kind == "extra_forbidden":
        parent = _model_at(model, loc[:-1])
        known = list(_field_names(parent)) if parent else []
        of = f"'{owner}'" if owner else "a task file"
        return f"{loc[-1]!r} is not a field of {of}{did_you_mean(loc[-1], known, 'fields')}"
    if kind == "missing":
        of = f"'{owner}'" if owner else "a task file"
        return f"{of} needs {loc[-1]!r}"
    text = f"'{subject}'" if subject != "the task file" else subject
    if kind == "value_error":
        reason = str(ctx.get("error", err["msg"]))
        return f"{text} {reason}"
    if kind in ("float_type", "int_type") and isinstance(value, bool):
        return f"{text} must be {_EXPECTED[kind]}, not a boolean (got {str(value).lower()})"
    if kind in _EXPECTED:
        return f"{text} must be {_EXPECTED[kind]} (got {_shown(value)})"
    if kind in _BOUNDS:
        limit = next(v for k, v in ctx.items() if k in ("gt", "ge", "lt", "le"))
        shown = f"{limit:g}" if isinstance(limit, (int, float)) else limit
        return f"{text} must be {_BOUNDS[kind]} {shown} (got {_shown(value)})"
    if kind == "literal_error":
        options = re.findall(r"'([^']*)'", str(ctx.get("expected", "")))
        hint = did_you_mean(value, options) if isinstance(value, str) else ""
        return f"{text} must be {ctx.get('expected')} (got {_shown(value)}){hint}"
    if kind in ("too_short", "too_long"):
        low, high = ctx.get("min_length"), ctx.get("max_length")
        parent = _model_at(model, loc[:-1]) if loc else None
        info = _field_names(parent).get(loc[-1]) if parent else None
        if info is not None:
            declared = _length_bounds(info)
            low, high = declared[0] if declared[0] is not None else low, declared[1] or high
        count = ctx.get("actual_length", len(value) if hasattr(value, "__len__") else "?")
        if low is not None and low == high:
            return f"{text} must have {low} values (got {count})"
        if kind == "too_short":
            return f"{text} must have at least {low} item{'s' * (low != 1)} (got {count})"
        return f"{text} must have at most {high} items (got {count})"
    return f"{text}: {err['msg']}"
