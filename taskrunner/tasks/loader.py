"""Loading task files: parse, bind parameters, expand includes, validate every step.

:func:`load_task` reads a task file (see ``ARCHITECTURE.md``, "Task language") into a
:class:`~taskrunner.tasks.spec.TaskSpec`. It reports every problem of the file and of the
files it includes at once: one :class:`~taskrunner.errors.TaskSpecError` whose message
lists each problem with its own ``file:line`` (and whose ``problems`` attribute holds
them as :class:`~taskrunner.tasks.problem.Problem`).

The order of work: parse the YAML (line numbers kept, repeated keys refused); declare the
parameters and bind the overrides; substitute ``${name}`` everywhere but in
``parameters``; validate the top level, the objects, the defaults; build each step by
its verb (composites recursively, ``include`` by loading the other file with its own
parameters); fill unset planner options from the defaults.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

from pydantic import BaseModel, ValidationError

from taskrunner.errors import InputError, TaskSpecError, YamlError
from taskrunner.folders import FileKind, FolderPolicy, PathNotAllowedError
from taskrunner.resources import is_bare_name, resolve_cell
from taskrunner.tasks.expect import Scenario, TaskExpectation
from taskrunner.tasks.nodes import Location, ObjectSpec, location_of
from taskrunner.tasks.parameters import Binding, bind_parameters, declare_parameters, substitute
from taskrunner.tasks.problem import (
    Problem,
    did_you_mean,
    problems_error,
    problems_from_validation,
)
from taskrunner.tasks.spec import Parameter, TaskFile, TaskSpec
from taskrunner.tasks.steps import (
    MOTION_OPTIONS,
    STEP_TYPES,
    AddObjectStep,
    IncludeBody,
    IncludeStep,
    MotionOptions,
    MotionStep,
    Step,
    StepNode,
    _DoComposite,
    _ListComposite,
)
from taskrunner.tasks.waits import wait_problems
from taskrunner.textfile import file_problem, resolve_path
from taskrunner.yamlfile import LineDict, LineList, line_of, load_yaml, load_yaml_text

__all__ = ["MAX_INCLUDE_DEPTH", "MAX_INCLUDES", "MAX_STEP_DEPTH", "load_task", "load_task_text"]

MAX_INCLUDE_DEPTH = 16
MAX_INCLUDES = 64
"""Included files loaded for one task, counting each ``include`` step that is reached:
a file included twice by each of a chain of files would otherwise expand 2^n times."""
MAX_STEP_DEPTH = 40
"""Nesting of steps (composites and includes together), far below Python's recursion
limit in every later stage (compiler, checker)."""


def load_task(path: str | Path, parameters: Mapping[str, object] | None = None,
              policy: FolderPolicy | None = None) -> TaskSpec:
    """Load a task file.

    Args:
        path: the task file.
        parameters: values for the task's parameters, overriding the defaults: strings
            (from a command line) are parsed to the parameter's type, other values
            (from an API) must already have it.
        policy: the folders the task, its includes, its cell and its meshes may come
            from (None: anything loads).

    Raises:
        TaskSpecError: the file (or an included one) is invalid; the message lists every
            problem with its file:line.
    """
    path = resolve_path(path, TaskSpecError)
    return _Loader(path, policy=policy).load_root(path, None, parameters or {})


def load_task_text(text: str, path: str | Path,
                   parameters: Mapping[str, object] | None = None,
                   policy: FolderPolicy | None = None) -> TaskSpec:
    """Load a task from YAML text; ``path`` is the file it stands for (need not exist):
    messages name it and relative paths (cell, includes, meshes) start from its folder.
    ``policy``: as for :func:`load_task`."""
    path = resolve_path(path, TaskSpecError)
    return _Loader(path, policy=policy).load_root(path, text, parameters or {})


@dataclass
class _FileResult:
    """What one task file contributes."""

    task: str
    description: str
    line: int | None
    cell: Path | None
    parameters: dict[str, Parameter]
    defaults: MotionOptions | None
    steps: tuple[Step, ...]
    expect: TaskExpectation | None = None
    scenarios: tuple[Scenario, ...] = ()

    @property
    def values(self) -> dict[str, Any]:
        return {p.name: p.value for p in self.parameters.values()}


@dataclass
class _Loader:
    root: Path
    problems: list[Problem] = field(default_factory=list)
    objects: list[ObjectSpec] = field(default_factory=list)
    root_cell: Path | None = None
    root_scene: Path | None = None
    policy: FolderPolicy | None = None
    includes: int = 0
    depth: int = 0

    def add(self, file: Path | None, line: int | None, message: str) -> None:
        self.problems.append(Problem(file, line, message))

    def validate(self, model: type[BaseModel], data: Any, node: Any, file: Path,
                 where: tuple[Any, ...], line: int | None = None) -> Any:
        """``model`` validated from ``data`` (``node``: the YAML it came from, ``line``:
        where it is when ``node`` has no line of its own), or None."""
        try:
            return model.model_validate(data, context={"file": file})
        except ValidationError as exc:
            self.report(problems_from_validation(exc, node, file, where, model, line))
            return None

    def report(self, problems: list[Problem]) -> None:
        """Add ``problems``, leaving out those about a value that is still a ``${…}``
        reference: its cause (an unknown or broken parameter) is reported already."""
        self.problems += [p for p in problems if "(got '${" not in p.message]

    def resolve_scene(self, tree: LineDict, path: Path, root: bool) -> None:
        """The root file's ``scene:`` (a MoveIt PlanningScene file), relative to it."""
        value, line = tree.get("scene"), line_of(tree, "scene")
        if not isinstance(value, str) or not value:
            return  # absent, or refused by the TaskFile model
        if not root:
            self.add(path, line, "an included file's 'scene' is not used: only the task run "
                                 "has one")
            return
        try:
            scene = resolve_path(path.parent / value, TaskSpecError, path, line, written=value)
        except TaskSpecError as exc:
            self.add(exc.path, exc.line, exc.reason)
            return
        if self.refused(scene, FileKind.TASK, value, path, line):
            return
        problem = file_problem(scene)
        if problem is not None:
            self.add(path, line, f"scene file not found: {_shown(scene, path)}"
                     if problem == "file not found" else f"scene {_shown(scene, path)}: {problem}")
            return
        self.root_scene = scene

    def refused(self, path: Path, kind: FileKind, written: str, file: Path,
                line: int | None) -> bool:
        """Whether the policy refuses ``path`` (then the problem is added)."""
        if self.policy is None:
            return False
        try:
            self.policy.check(path, kind, written)
        except PathNotAllowedError as exc:
            self.add(file, line, exc.reason)
            return True
        return False

    def refused_meshes(self, objects: Any, file: Path) -> bool:
        """Whether the policy refuses the mesh file of one of ``objects``."""
        refused = False
        for obj in objects:
            if self.policy is None or obj is None or getattr(obj, "file", None) is None:
                continue
            line = obj.loc.line_of("file") if obj.loc is not None else None
            if "://" in obj.file:  # package:// paths may climb out with '..'
                self.add(file, line, f"mesh {obj.file!r}: a task served over the API names "
                         "its meshes by path, not by URI")
                refused = True
            else:
                refused |= self.refused(Path(obj.file), FileKind.MESH, obj.file_as_written or "",
                                        file, line)
        return refused

    # ------------------------------------------------------------------------- files
    def load_root(self, path: Path, text: str | None, overrides: Mapping[str, object]) -> TaskSpec:
        if text is None and self.refused(path, FileKind.TASK, str(path), path, None):
            raise problems_error(self.problems)
        result = self.load_file(path, text, Binding(overrides, None, None), (path,), root=True)
        objects = tuple(self.unique_objects())
        spec = None
        if result is not None and not self.problems:
            self.problems += wait_problems(result.steps)
        if result is not None and result.cell is not None and not self.problems:
            spec = TaskSpec(
                name=result.task, description=result.description, path=path, cell=result.cell,
                parameters=result.parameters, objects=objects, scene=self.root_scene,
                defaults=result.defaults or MotionOptions(), steps=result.steps,
                expect=result.expect, scenarios=result.scenarios,
            ).located(Location(path, result.line))
        if self.problems or spec is None:
            files = list(dict.fromkeys(p.path for p in self.problems))
            ordered = sorted(self.problems, key=lambda p: (files.index(p.path), p.line or 0))
            raise problems_error(ordered)
        return spec  # type: ignore[return-value]

    def load_file(self, path: Path, text: str | None, binding: Binding,
                  stack: tuple[Path, ...], root: bool = False) -> _FileResult | None:
        """Load one file (``text``: its content, if not to be read); problems are
        collected; None when the file cannot be read as a mapping at all."""
        if text is None and self.policy is not None:
            text = self.policy.text_of(path)  # a file held in memory
        try:
            node = load_yaml(path) if text is None else load_yaml_text(text, path)
        except YamlError as exc:
            self.add(exc.path or path, exc.line, exc.reason)
            return None
        if not isinstance(node, LineDict):
            got = ("an empty file" if node is None else "a list" if isinstance(node, list)
                   else repr(node))
            self.add(path, line_of(node), "a task file must be a mapping with 'task', 'cell' "
                     f"and 'steps' (got {got})")
            return None
        name = str(node["task"]) if isinstance(node.get("task"), str) else path.stem
        declared, broken = declare_parameters(node.get("parameters"), node, path, self.problems)
        parameters = bind_parameters(declared, broken, binding, name, node, path, self.problems)
        values = {p.name: p.value for p in parameters.values() if p.value is not None}
        tree = substitute(node, values, set(declared) | broken, path, self.problems,
                          skip=("parameters",))
        top = self.validate(TaskFile, {k: v for k, v in tree.items() if k != "parameters"}
                            | {"parameters": {}}, tree, path, ())
        cell = self.resolve_cell(tree, path, root)
        self.resolve_scene(tree, path, root)
        if top is not None and not self.refused_meshes(top.objects, path):
            self.objects += top.objects
        defaults = top.defaults if top is not None else None
        steps_node = tree.get("steps")
        steps = []
        if isinstance(steps_node, LineList):
            for i in range(len(steps_node)):
                steps.append(self.build_step(steps_node, i, path, stack))
        built = tuple(s for s in steps if s is not None)
        if defaults is not None:
            built = tuple(apply_defaults(s, defaults) for s in built)
        description = top.description if top is not None else ""
        expect = top.expect if top is not None else None
        scenarios = tuple(top.scenarios) if top is not None else ()
        if not root:
            for key in ("expect", "scenarios"):
                if key in tree:
                    self.add(path, line_of(tree, key), f"an included file's {key!r} is not "
                             "used: only the task run has one (put checks in an 'expect' step)")
        return _FileResult(str(name), description, tree.line, cell, parameters, defaults, built,
                           expect, scenarios)

    def resolve_cell(self, tree: LineDict, path: Path, root: bool) -> Path | None:
        value = tree.get("cell")
        if not isinstance(value, str) or not value:
            if root and "cell" not in tree:
                self.add(path, tree.line, "a task file needs 'cell' (the cell file it runs in)")
            return None
        if is_bare_name(value):
            # A name (servo_arm_table): a file next to the task first, else a cell of the
            # cells folder by name (the server's: its policy's; else TASKRUNNER_CELLS_DIR,
            # then the shipped cells), as run-task info and load_workcell resolve it.
            folders = self.policy.folders(FileKind.CELL) if self.policy is not None else None
            try:
                target = resolve_cell(value, relative_to=path.parent, folders=folders,
                                      robots=False)
            except InputError as exc:
                self.add(path, line_of(tree, "cell"), f"cell {exc.reason}")
                return None
        else:
            target = path.parent / value
        try:
            cell = resolve_path(target, TaskSpecError, path, line_of(tree, "cell"), written=value)
        except TaskSpecError as exc:
            self.add(exc.path, exc.line, exc.reason)
            return None
        if self.refused(cell, FileKind.CELL, value, path, line_of(tree, "cell")):
            return None
        problem = file_problem(cell)
        if problem is not None:
            self.add(path, line_of(tree, "cell"), f"cell file not found: {_shown(cell, path)}"
                     if problem == "file not found" else f"cell {_shown(cell, path)}: {problem}")
        if root:
            self.root_cell = cell
        return cell

    def unique_objects(self) -> list[ObjectSpec]:
        """The task's objects, an object declared twice identically (a file included
        twice) kept once; two different objects of one name are a problem."""
        seen: dict[str, ObjectSpec] = {}
        for obj in self.objects:
            first = seen.get(obj.name)
            if first is None:
                seen[obj.name] = obj
            elif first != obj:
                loc = obj.loc
                self.add(loc.file if loc else None, loc.line_of("name") if loc else None,
                         f"object {obj.name!r} is declared twice (first at {first.loc})")
        return list(seen.values())

    # ------------------------------------------------------------------------- steps
    def build_step(self, container: LineList, index: int, file: Path,
                   stack: tuple[Path, ...]) -> Step | None:
        if self.depth >= MAX_STEP_DEPTH:
            if not any("steps nested deeper" in p.message for p in self.problems):
                self.add(file, line_of(container, index), f"steps nested deeper than "
                         f"{MAX_STEP_DEPTH} levels (composites and includes together)")
            return None
        self.depth += 1
        try:
            return self._build_step(container, index, file, stack)
        finally:
            self.depth -= 1

    def _build_step(self, container: LineList, index: int, file: Path,
                    stack: tuple[Path, ...]) -> Step | None:
        item, line = container[index], line_of(container, index)
        if not isinstance(item, LineDict) or len(item) != 1:
            self.add(file, line, _bad_step_message(item))
            return None
        verb = next(iter(item))
        verb_line, body = item.line_of(verb), item[verb]
        cls = STEP_TYPES.get(verb) if isinstance(verb, str) else None
        if cls is None:
            self.add(file, verb_line, f"{verb!r} is not a step verb"
                     f"{did_you_mean(str(verb), STEP_TYPES, 'verbs')}")
            return None
        if issubclass(cls, _ListComposite):
            step = self.build_list(cls, body, verb_line, file, stack)
        elif issubclass(cls, _DoComposite):
            step = self.build_do(cls, body, verb_line, file, stack)
        elif cls is IncludeStep:
            step = self.build_include(body, verb_line, file, stack)
        elif cls is AddObjectStep:
            obj = self.validate(ObjectSpec, body, body, file, (verb,), verb_line)
            step = AddObjectStep(object=obj) if obj is not None \
                and not self.refused_meshes([obj], file) else None
        else:
            step = self.validate(cls, body, body, file, (verb,), verb_line)
        if step is None:
            return None
        return cast(Step, step.located(location_of(body, file, verb_line)))

    def build_children(self, body: LineList, file: Path,
                       stack: tuple[Path, ...]) -> tuple[list[Step], bool]:
        """The steps of list ``body`` that could be built, and whether all could."""
        children = [self.build_step(body, j, file, stack) for j in range(len(body))]
        return [c for c in children if c is not None], None not in children

    def build_list(self, cls: type[_ListComposite], body: Any, line: int | None, file: Path,
                   stack: tuple[Path, ...]) -> StepNode | None:
        if not isinstance(body, LineList):
            self.add(file, line, f"'{cls.verb}' must be a list of steps (got {body!r})")
            return None
        children, complete = self.build_children(body, file, stack)
        least = cls.min_steps
        if len(body) < least:
            self.add(file, line, f"'{cls.verb}' needs at least {least} step"
                     f"{'s' * (least > 1)} (got {len(body)})")
            return None
        return cls(steps=tuple(children)) if complete else None

    def build_do(self, cls: type[_DoComposite], body: Any, line: int | None, file: Path,
                 stack: tuple[Path, ...]) -> StepNode | None:
        data, complete = body, True
        if isinstance(body, LineDict) and isinstance(body.get("do"), LineList):
            children, complete = self.build_children(body["do"], file, stack)
            data = {k: v for k, v in body.items() if k != "do"} | {"do": tuple(children)}
        elif isinstance(body, LineDict) and "do" in body:
            self.add(file, line_of(body, "do"),
                     f"'{cls.verb}.do' must be a list of steps (got {body['do']!r})")
            return None
        try:
            step = cls.model_validate(data, context={"file": file})
        except ValidationError as exc:
            problems = problems_from_validation(exc, body, file, (cls.verb,), cls, line)
            self.report([p for p in problems if complete or ".do" not in p.message])
            return None
        return step if complete else None

    def build_include(self, body: Any, line: int | None, file: Path,
                      stack: tuple[Path, ...]) -> StepNode | None:
        include = self.validate(IncludeBody, body, body, file, ("include",), line)
        if include is None:
            return None
        file_line = line_of(body, "file")
        try:
            target = resolve_path(file.parent / include.file, TaskSpecError, file, file_line,
                                  written=include.file)
        except TaskSpecError as exc:
            self.add(exc.path, exc.line, exc.reason)
            return None
        self.includes += 1
        if self.includes > MAX_INCLUDES:
            if self.includes == MAX_INCLUDES + 1:  # said once, not for each one after
                self.add(file, file_line, f"more than {MAX_INCLUDES} includes in one task "
                         "(a file included many times over?)")
            return None
        if target in stack:
            chain = stack[stack.index(target):] + (target,)
            shown = " → ".join(_shown(p, self.root) for p in chain)
            self.add(file, file_line, f"include cycle: {shown}")
            return None
        if len(stack) > MAX_INCLUDE_DEPTH:
            self.add(file, file_line, f"includes nested deeper than {MAX_INCLUDE_DEPTH}")
            return None
        if self.refused(target, FileKind.TASK, include.file, file, file_line):
            return None
        problem = file_problem(target)
        if problem is not None:
            self.add(file, file_line, f"included file not found: {_shown(target, file)}"
                     if problem == "file not found"
                     else f"included file {_shown(target, file)}: {problem}")
            return None
        binding = Binding(include.parameters, file, body.get("parameters") or body)
        result = self.load_file(target, None, binding, stack + (target,))
        if result is None:
            return None
        if result.cell is not None and self.root_cell is not None and result.cell != self.root_cell:
            self.add(file, file_line, f"{include.file!r} is a task for cell "
                     f"{_shown(result.cell, file)!r}, not this task's cell "
                     f"{_shown(self.root_cell, file)!r}")
            return None
        return IncludeStep(path=target, task=result.task,
                           parameters=result.values, steps=result.steps, name=include.name,
                           wait_for=include.wait_for)


def apply_defaults(step: Step, defaults: MotionOptions) -> Step:
    """``step`` with the planner options it leaves unset taken from ``defaults``."""
    update: dict[str, Any] = {}
    if isinstance(step, MotionStep):
        update = {name: getattr(defaults, name) for name in MOTION_OPTIONS
                  if getattr(step, name) is None and getattr(defaults, name) is not None}
    elif isinstance(step, (_ListComposite, IncludeStep)):
        update = {"steps": tuple(apply_defaults(s, defaults) for s in step.steps)}
    elif isinstance(step, _DoComposite):
        update = {"do": tuple(apply_defaults(s, defaults) for s in step.do)}
    return step.model_copy(update=update) if update else step


def _shown(path: Path, seen_from: Path) -> str:
    """``path`` relative to the folder of file ``seen_from`` (as one would write it there)."""
    try:
        return os.path.relpath(path, seen_from.parent)
    except ValueError:  # another drive
        return str(path)


def _bad_step_message(item: Any) -> str:
    if isinstance(item, dict) and item:
        verbs = [k for k in item if k in STEP_TYPES]
        others = ", ".join(repr(k) for k in item if k not in verbs)
        if len(verbs) == 1:
            return (f"a step is one 'verb: body' mapping: indent {others} under "
                    f"'{verbs[0]}:'")
        if verbs:
            return f"a step has one verb (got {' and '.join(repr(v) for v in verbs)})"
    if isinstance(item, str) and item in STEP_TYPES:
        return f"step '{item}' needs a body: write '{item}: {{…}}'"
    shown = repr(dict(item)) if isinstance(item, dict) else repr(item)
    return (f"a step must be a mapping 'verb: body', e.g. 'go: {{group: arm, to: home}}' "
            f"(got {shown})")

