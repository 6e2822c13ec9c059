"""Every type in a public signature is public: exported by ``taskrunner``, or by one of
the subpackages whose ``__init__`` pins its names for scripts that go deeper (the robot
model, the scene, the task language, the MoveIt readers, the planners)."""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import sys
import typing
from collections.abc import Callable, Iterator

import pytest

import taskrunner

PUBLIC_PACKAGES = ("taskrunner.robot", "taskrunner.scene", "taskrunner.tasks",
                   "taskrunner.moveit", "taskrunner.planning")
# Made only by the API (start_task); their constructors take its internals.
MADE_BY_THE_API = {"TaskRun.__init__"}


def _public_namespace() -> dict[str, object]:
    names = {n: getattr(taskrunner, n) for n in taskrunner.__all__ if n != "__version__"}
    for package in PUBLIC_PACKAGES:
        module = importlib.import_module(package)
        names |= {n: getattr(module, n) for n in module.__all__ if n not in names}
    return names


def _leaf_types(hint: object) -> Iterator[type]:
    """The classes a type hint names (through unions, generics, Annotated; not Literal)."""
    origin = typing.get_origin(hint)
    if origin is typing.Literal:
        return
    if origin is typing.Annotated:
        yield from _leaf_types(typing.get_args(hint)[0])
        return
    if origin is not None:
        if isinstance(origin, type):
            yield origin
        for arg in typing.get_args(hint):
            for item in (arg if isinstance(arg, list) else [arg]):  # Callable's arguments
                if item is not Ellipsis:
                    yield from _leaf_types(item)
        return
    if isinstance(hint, type):
        yield hint


def _callables(name: str, obj: object) -> Iterator[tuple[str, Callable[..., object]]]:
    if inspect.isfunction(obj):
        yield name, obj
        return
    assert isinstance(obj, type), name
    for attr, value in vars(obj).items():
        if (attr.startswith("_") and attr != "__init__") or attr.startswith("model_"):
            continue
        if isinstance(value, property) and value.fget is not None:
            yield f"{name}.{attr}", value.fget
        elif isinstance(value, (classmethod, staticmethod)):
            yield f"{name}.{attr}", value.__func__
        elif inspect.isfunction(value):
            yield f"{name}.{attr}", value


def _public_hints() -> Iterator[tuple[str, str, object]]:
    """(where, argument, hint) for every annotated argument, return value and field."""
    namespace = _public_namespace()
    for name in taskrunner.__all__:
        if name == "__version__":
            continue
        obj = getattr(taskrunner, name)
        targets = list(_callables(name, obj))
        if dataclasses.is_dataclass(obj):
            targets.append((name, obj))  # its fields
        for where, target in targets:
            if where in MADE_BY_THE_API:
                continue
            module = sys.modules[target.__module__]
            hints = typing.get_type_hints(target, {**namespace, **vars(module)},
                                          include_extras=True)
            for argument, hint in hints.items():
                yield where, argument, hint


def test_public_signatures_name_only_public_types():
    public = {id(v) for v in _public_namespace().values()}
    leaks = sorted({f"{where}({argument}): {t.__module__}.{t.__qualname__}"
                    for where, argument, hint in _public_hints()
                    for t in _leaf_types(hint)
                    if t.__module__.split(".")[0] == "taskrunner" and id(t) not in public
                    or t.__name__.startswith("_")})
    assert leaks == []


def test_the_walk_sees_the_execution_handle_and_the_backend():
    # The check above cannot pass vacuously: it reads the handle and backend types.
    seen = {(where, argument): {t.__name__ for t in _leaf_types(hint)}
            for where, argument, hint in _public_hints()}
    assert "ExecutionHandle" in seen[("Workcell.execute", "return")]
    assert "Backend" in seen[("Workcell.connect", "return")]
    assert "BackendKind" in seen[("Workcell.connect", "kind")]
    assert {"Cell"} <= seen[("Workcell.cell", "return")]


@pytest.mark.parametrize("name", ["Backend", "ExecutionHandle", "BackendKind", "Expect",
                                  "RunRecord", "TaughtPose"])
def test_the_types_of_the_workcell_api_are_exported(name):
    assert getattr(taskrunner, name).__doc__
