"""Task parameters: declarations, typed overrides and ``${name}`` substitution.

A parameter is declared with a default (``cube_x: 0.2``: type inferred) or in full
(``place_y: {default: -0.08, type: float, min: -0.2, max: 0.2, description: …}``).
Overrides come from a command line (strings, parsed to the declared type), an API
(values of the type) or an ``include`` (YAML values). In any scalar string outside
``parameters``, ``${name}`` is replaced: a string that is exactly one reference takes
the value with its type (a float stays a float); a reference inside longer text is
interpolated as text; ``$${`` writes a literal ``${``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from taskrunner.errors import ArgumentError
from taskrunner.tasks.nodes import location_of
from taskrunner.tasks.problem import Problem, did_you_mean, problems_from_validation
from taskrunner.tasks.spec import Parameter, ParameterDecl
from taskrunner.yamlfile import LineDict, LineList, line_of

__all__ = ["Binding", "bind_parameters", "coerce_parameter", "declare_parameters", "substitute"]

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_REF = re.compile(r"\$(\$?)\{([^{}]*)\}")
_WHOLE = re.compile(r"\$\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\Z")
_TYPE_NAMES = {"float": "a float", "int": "an int", "bool": "a bool (true or false)",
               "str": "a string"}
_TRUE, _FALSE = {"true", "yes", "on", "1"}, {"false", "no", "off", "0"}


@dataclass(frozen=True)
class Binding:
    """Values given for a file's parameters, and where they were given.

    Attributes:
        values: parameter name → value.
        file: the file that gives them (an including task), or None for a caller's
            values (problems are then reported at the parameter's declaration).
        node: the YAML mapping of the values in ``file``, for line numbers.
    """

    values: Mapping[str, object]
    file: Path | None
    node: Any


def coerce_parameter(name: str, type_: str, value: object) -> Any:
    """``value`` as a value of ``type_``; strings are parsed (command-line values).

    Raises:
        ValueError: ``'<name>' must be a float (got 'abc')``.
    """
    error = ValueError(f"{name!r} must be {_TYPE_NAMES[type_]} (got {value!r})")
    if type_ == "str":
        if not isinstance(value, str):
            raise error
        return value
    if type_ == "bool":
        if isinstance(value, bool):
            return value
        if isinstance(value, str) and value.strip().lower() in _TRUE | _FALSE:
            return value.strip().lower() in _TRUE
        raise error
    if isinstance(value, bool):
        raise error
    if type_ == "int":
        if isinstance(value, int):
            return value
        if isinstance(value, float) and value.is_integer():
            return int(value)
        if isinstance(value, str):
            try:
                return int(value.strip())
            except ValueError:
                raise error from None
        raise error
    if isinstance(value, (int, float)):
        number = float(value)
    elif isinstance(value, str):
        try:
            number = float(value.strip())
        except ValueError:
            raise error from None
    else:
        raise error
    if not math.isfinite(number):
        raise error
    return number


def _infer_type(value: object) -> str | None:
    for python, name in ((bool, "bool"), (int, "int"), (float, "float"), (str, "str")):
        if isinstance(value, python):
            return name
    return None


def _check_bounds(param: Parameter, value: Any) -> None:
    if param.min is not None and value < param.min:
        raise ArgumentError(f"{param.name!r} must be >= {param.min:g} (got {value!r})")
    if param.max is not None and value > param.max:
        raise ArgumentError(f"{param.name!r} must be <= {param.max:g} (got {value!r})")


def declare_parameters(raw: Any, tree: Any, path: Path,
                       problems: list[Problem]) -> tuple[dict[str, Parameter], set[str]]:
    """The parameters declared by a file's ``parameters`` mapping (each with ``value``
    = its default), and the names of broken declarations (reported in ``problems``;
    references to them are not reported again)."""
    declared: dict[str, Parameter] = {}
    broken: set[str] = set()
    if raw is None:
        return declared, broken
    if not isinstance(raw, LineDict):
        problems.append(Problem(path, line_of(tree, "parameters"),
                                f"'parameters' must be a mapping name: default (got {raw!r})"))
        return declared, broken
    for name, spec in raw.items():
        line = line_of(raw, name)
        where = f"parameters.{name}"
        if not isinstance(name, str) or not _NAME.match(name):
            problems.append(Problem(path, line, f"parameter name {name!r} must be a letter or "
                                    "'_' followed by letters, digits or '_'"))
            continue
        broken.add(name)
        if isinstance(spec, LineDict):
            try:
                decl = ParameterDecl.model_validate(spec)
            except ValidationError as exc:
                problems += problems_from_validation(exc, spec, path, ("parameters", name),
                                                     ParameterDecl)
                continue
        elif isinstance(spec, (bool, int, float, str)):
            decl = ParameterDecl(default=spec)
        else:
            problems.append(Problem(path, line, f"{where!r} must be a default value or a "
                                    f"mapping {{default, type, min, max}} (got {spec!r})"))
            continue
        type_ = decl.type or _infer_type(decl.default)
        if type_ is None:
            got = "" if decl.default is None else f" (got default {decl.default!r})"
            problems.append(Problem(path, line, f"{where!r} needs a 'type' (float, int, bool or "
                                    f"str) or a 'default'{got}"))
            continue
        if (decl.min is not None or decl.max is not None) and type_ not in ("float", "int"):
            problems.append(Problem(path, line, f"{where!r} takes 'min'/'max' only for a float "
                                    f"or an int (it is {_TYPE_NAMES[type_]})"))
            continue
        if decl.min is not None and decl.max is not None and decl.min > decl.max:
            problems.append(Problem(path, line, f"{where!r} has min {decl.min:g} > max "
                                    f"{decl.max:g}"))
            continue
        param = Parameter(name=name, type=type_, min=decl.min, max=decl.max,  # type: ignore[arg-type]
                          description=decl.description)
        default = None
        if decl.default is not None:
            try:
                default = coerce_parameter(name, type_, decl.default)
                _check_bounds(param, default)
            except ValueError as exc:
                problems.append(Problem(path, line, f"default of {exc}"))
                default = None
        # A default reported above stands in as a valid value (see _stand_in).
        value = _stand_in(param) if default is None and decl.default is not None else default
        declared[name] = param.model_copy(update={"default": default, "value": value}).located(
            location_of(spec, path, line))
        if default is not None or decl.default is None:
            broken.discard(name)
    return declared, broken


def bind_parameters(declared: dict[str, Parameter], broken: set[str], binding: Binding,
                    task: str, tree: Any, path: Path,
                    problems: list[Problem]) -> dict[str, Parameter]:
    """``declared`` with the values of ``binding``; every parameter must end with one."""
    bound = dict(declared)
    for name, raw in binding.values.items():
        if binding.file is not None:
            where = (binding.file, line_of(binding.node, name))
        else:
            param = declared.get(name)
            where = (path, param.loc.line if param and param.loc else line_of(tree, "parameters"))
        if name in broken:
            continue
        if name not in declared:
            known = ", ".join(repr(n) for n in declared)
            listed = f"its parameters: {known}" if known else "it has no parameters"
            problems.append(Problem(*where, f"{name!r} is not a parameter of task {task!r} "
                                    f"({listed}){did_you_mean(name, declared)}"))
            continue
        param = declared[name]
        try:
            value = coerce_parameter(name, param.type, raw)
            _check_bounds(param, value)
        except ValueError as exc:
            problems.append(Problem(*where, str(exc)))
            bound[name] = param.model_copy(update={"value": _stand_in(param)})
            continue
        bound[name] = param.model_copy(update={"value": value})
    for name, param in list(bound.items()):
        if param.value is None and param.name not in broken:
            if binding.file is not None:  # the including file must give it
                problems.append(Problem(binding.file, line_of(binding.node),
                                        f"parameter {param.name!r} of task {task!r} has no "
                                        "default and is not given in the include"))
            else:
                problems.append(Problem(path, param.loc.line if param.loc else None,
                                        f"parameter {param.name!r} has no default and is not "
                                        "given (--param)"))
            bound[name] = param.model_copy(update={"value": _stand_in(param)})
    return bound


def _stand_in(param: Parameter) -> Any:
    """A valid value of ``param``'s type and range, put where a parameter whose value was
    reported as a problem is used: the steps are then checked for their own mistakes
    only, not for a ``${name}`` left in a number's place (one problem, not two). It
    never reaches a run: a task with problems does not load."""
    if param.min is not None:
        return math.ceil(param.min) if param.type == "int" else param.min
    if param.max is not None:
        return math.floor(param.max) if param.type == "int" else param.max
    return {"float": 1.0, "int": 1, "bool": False, "str": "stand-in"}[param.type]


def _text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value) if isinstance(value, float) else str(value)


def substitute(node: Any, values: Mapping[str, Any], declared: set[str], path: Path,
               problems: list[Problem], skip: tuple[str, ...] = (), line: int | None = None) -> Any:
    """A copy of YAML tree ``node`` with ``${name}`` references replaced (line numbers
    kept). References to declared parameters without a value are left as written.
    Boolean mapping keys become ``"on"`` / ``"off"`` (the YAML 1.1 reading of ``on:``)."""
    if isinstance(node, LineDict):
        out = LineDict()
        out.line = node.line
        for key, value in node.items():
            # YAML 1.1 reads the key ``on:`` (of ``place``) as True: give it back its name.
            name = {True: "on", False: "off"}.get(key, key) if isinstance(key, bool) else key
            if key in node.key_lines:
                out.key_lines[name] = node.key_lines[key]
            out[name] = value if key in skip else substitute(
                value, values, declared, path, problems, (), node.line_of(key))
        return out
    if isinstance(node, LineList):
        out_list = LineList(substitute(v, values, declared, path, problems, (), line_of(node, i))
                            for i, v in enumerate(node))
        out_list.line, out_list.item_lines = node.line, list(node.item_lines)
        return out_list
    if not isinstance(node, str) or "${" not in node:
        return node
    whole = _WHOLE.match(node)
    if whole and whole.group(1) in values:
        return values[whole.group(1)]

    def replace(match: re.Match[str]) -> str:
        if match.group(1):
            return "${" + match.group(2) + "}"
        name = match.group(2).strip()
        if name in values:
            return _text(values[name])
        if not _NAME.match(name):
            problems.append(Problem(path, line, f"{match.group(0)!r} is not a parameter "
                                    "reference (write ${name}; $${ for a literal ${)"))
        elif name not in declared:
            hint = did_you_mean(name, declared, "its parameters")
            problems.append(Problem(path, line, f"{match.group(0)!r}: {name!r} is not a "
                                    f"parameter of this task{hint or '; it declares none'}"))
        return match.group(0)

    return _REF.sub(replace, node)
