"""The error contract (issue 24): every error taskrunner raises on purpose is a
:class:`~taskrunner.errors.TaskrunnerError` drawn in ``errors.py``'s tree.

Read from the source with :mod:`ast` (every module, including those no test imports):

- no ``raise ValueError/RuntimeError/LookupError/KeyError/TypeError(...)`` outside
  pydantic validators (pydantic turns a ``ValueError`` into its own validation error with
  the field's location, so there it is the contract) and the few argument-type checks
  listed below with their reasons;
- every exception class the package defines derives from ``TaskrunnerError``;
- every public class of ``errors.py`` is drawn in its docstring's tree.
"""

from __future__ import annotations

import ast
import builtins
import re
from functools import cache
from pathlib import Path

import taskrunner
from taskrunner import errors

PACKAGE = Path(taskrunner.__file__).resolve().parent

_BUILTIN = {"ValueError", "RuntimeError", "LookupError", "KeyError", "TypeError"}

# Decorators whose functions pydantic calls: a ValueError raised there becomes a
# ValidationError naming the field (and our loaders add the file:line).
_VALIDATORS = {"field_validator", "model_validator", "validator", "root_validator"}

# (module, enclosing function, exception) -> why a builtin exception is right there.
_ALLOWED: dict[tuple[str, str, str], str] = {
    ("backends/sim.py", "SimOptions.__post_init__", "TypeError"):
        "argument-type check: 'keep_history' must be a bool",
    ("planning/goal_states.py", "goal_states", "TypeError"):
        "argument-type check: a goal of a type the planner does not know",
    ("runtime/records.py", "_jsonable", "TypeError"):
        "json.dumps' 'default' hook: TypeError is its contract for a value it cannot encode",
    ("yamlfile.py", "_convert", "ValueError"):
        "a signal caught by its only caller, which reports the scalar with its file:line",
}


def _modules() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py") if "__pycache__" not in p.parts)


def _raised_name(node: ast.Raise) -> str | None:
    exc = node.exc
    if isinstance(exc, ast.Call):
        exc = exc.func
    if isinstance(exc, ast.Name):
        return exc.id
    if isinstance(exc, ast.Attribute) and isinstance(exc.value, ast.Name) \
            and exc.value.id == "builtins":
        return exc.attr
    return None


def _decorator_names(func: ast.FunctionDef | ast.AsyncFunctionDef) -> set[str]:
    names = set()
    for deco in func.decorator_list:
        target = deco.func if isinstance(deco, ast.Call) else deco
        if isinstance(target, ast.Attribute):
            names.add(target.attr)
        elif isinstance(target, ast.Name):
            names.add(target.id)
    return names


def _builtin_raises(path: Path) -> list[tuple[int, str, str]]:
    """``(line, enclosing function, exception)`` of each builtin raise of ``path`` that is
    not inside a pydantic validator."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found: list[tuple[int, str, str]] = []

    def visit(node: ast.AST, where: str, in_validator: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                visit(child, f"{where}.{child.name}" if where else child.name,
                      in_validator or bool(_decorator_names(child) & _VALIDATORS))
            elif isinstance(child, ast.ClassDef):
                visit(child, f"{where}.{child.name}" if where else child.name, in_validator)
            else:
                if isinstance(child, ast.Raise) and not in_validator:
                    name = _raised_name(child)
                    if name in _BUILTIN:
                        found.append((child.lineno, where or "<module>", name))
                visit(child, where, in_validator)

    visit(tree, "", False)
    return found


def test_the_package_raises_only_its_own_errors():
    offenders = []
    used = set()
    for path in _modules():
        rel = path.relative_to(PACKAGE).as_posix()
        for line, where, name in _builtin_raises(path):
            if (rel, where, name) in _ALLOWED:
                used.add((rel, where, name))
                continue
            offenders.append(f"taskrunner/{rel}:{line}: raise {name} in {where}")
    assert not offenders, (
        f"{len(offenders)} raise(s) of a builtin exception; raise a class of "
        "taskrunner/errors.py (or list an argument-type check in _ALLOWED with its reason):\n"
        + "\n".join(offenders))
    stale = set(_ALLOWED) - used
    assert not stale, f"allowed raises that are no longer there: {sorted(stale)}"


@cache
def _exception_classes() -> dict[str, tuple[str, list[str]]]:
    """Every class of the package: name -> (``module:line``, names of its bases)."""
    classes: dict[str, tuple[str, list[str]]] = {}
    for path in _modules():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef):
                bases = [b.id if isinstance(b, ast.Name) else b.attr
                         for b in node.bases if isinstance(b, (ast.Name, ast.Attribute))]
                rel = path.relative_to(PACKAGE).as_posix()
                classes[node.name] = (f"taskrunner/{rel}:{node.lineno}", bases)
    return classes


def _ancestry(classes: dict[str, tuple[str, list[str]]], name: str,
              seen: frozenset[str] = frozenset()) -> set[str]:
    if name not in classes or name in seen:
        return {name}
    out = {name}
    for base in classes[name][1]:
        out |= _ancestry(classes, base, seen | {name})
    return out


def test_every_exception_class_of_the_package_is_a_taskrunner_error():
    """Private classes (``_Unreachable``) are signals caught inside their module."""
    classes = _exception_classes()
    builtin_errors = {name for name, value in vars(builtins).items()
                      if isinstance(value, type) and issubclass(value, BaseException)}
    outside = []
    for name, (where, _bases) in sorted(classes.items()):
        names = _ancestry(classes, name)
        if names & builtin_errors and "TaskrunnerError" not in names \
                and not name.startswith("_"):
            outside.append(f"{where}: {name} derives from {sorted(names & builtin_errors)} "
                           "but not from TaskrunnerError")
    assert not outside, "\n".join(outside)


def test_every_error_class_is_drawn_in_the_tree():
    """The tree in ``errors.py``'s docstring names every public error class of the
    package, wherever it is defined, and nothing else."""
    drawn = set(re.findall(r"[├└]── (\w+)", errors.__doc__ or "")) | {"TaskrunnerError"}
    classes = _exception_classes()
    defined = {name for name in classes if not name.startswith("_")
               and "TaskrunnerError" in _ancestry(classes, name)}
    assert defined - drawn == set(), f"not drawn in errors.py's tree: {defined - drawn}"
    assert drawn - defined == set(), f"drawn but not defined: {drawn - defined}"
