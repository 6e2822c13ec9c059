"""The JSON Schema of task files, for editors (validation, completion, hover help).

A step is expressed as ``oneOf`` single-key objects, one per verb, so an editor offers
the verbs at a step and the fields of the verb inside it. Field descriptions come from
the models' attribute docstrings. Regenerate the committed copy with::

    python -m taskrunner.tasks.schema --write      # tasks/task.schema.json

and point an editor at it from a task file::

    # yaml-language-server: $schema=../tasks/task.schema.json
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from pydantic import BaseModel
from pydantic.json_schema import models_json_schema

from taskrunner.tasks.nodes import ObjectSpec
from taskrunner.tasks.spec import ParameterDecl, TaskFile
from taskrunner.tasks.steps import (
    STEP_TYPES,
    AddObjectStep,
    IncludeBody,
    IncludeStep,
    MotionOptions,
    _ListComposite,
)

__all__ = ["SCHEMA_PATH", "schema_text", "task_json_schema"]

SCHEMA_PATH = Path(__file__).resolve().parents[1] / "data" / "tasks" / "task.schema.json"


def _body_model(verb: str) -> type[BaseModel] | None:
    cls = STEP_TYPES[verb]
    if issubclass(cls, _ListComposite):
        return None
    special: dict[type[BaseModel], type[BaseModel]] = {AddObjectStep: ObjectSpec,
                                                       IncludeStep: IncludeBody}
    return special.get(cls, cls)


def task_json_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a task file."""
    models: list[type[BaseModel]] = [TaskFile, ParameterDecl, ObjectSpec, MotionOptions]
    models += [m for m in (_body_model(v) for v in STEP_TYPES) if m is not None and m not in models]
    _, top = models_json_schema([(m, "validation") for m in models],
                                ref_template="#/$defs/{model}")
    defs = dict(top["$defs"])
    root = defs.pop(TaskFile.__name__)
    alternatives = []
    for verb, cls in STEP_TYPES.items():
        body_model = _body_model(verb)
        if body_model is None:
            least = cls.min_steps  # type: ignore[attr-defined]
            body: dict[str, Any] = {"type": "array", "items": {"$ref": "#/$defs/Step"},
                                    "minItems": least}
        else:
            body = {"$ref": f"#/$defs/{body_model.__name__}"}
        body["description"] = (cls.__doc__ or "").strip().splitlines()[0]
        alternatives.append({"type": "object", "title": verb, "properties": {verb: body},
                             "required": [verb], "additionalProperties": False})
    defs["Step"] = {"description": "One step: a mapping with one key, the verb.",
                    "oneOf": alternatives}
    defs = {name: _allow_references(d) for name, d in defs.items()}
    defs["ParameterRef"] = {"type": "string", "pattern": _REFERENCE,
                            "description": "A parameter's value: ${name}."}
    schema = {"$schema": "https://json-schema.org/draft/2020-12/schema",
              **_allow_references(root), "title": "taskrunner task file"}
    used = _reachable(schema, defs)
    schema["$defs"] = {name: defs[name] for name in sorted(used)}
    return schema


_REFERENCE = r"^\$\{\s*[A-Za-z_][A-Za-z0-9_]*\s*\}$"
_TYPED = ("number", "integer", "boolean")


def _allow_references(schema: Any) -> Any:
    """``schema`` where every number, integer, boolean or enum also accepts ``${name}``
    (a parameter reference, substituted by the loader before validation)."""
    if isinstance(schema, list):
        return [_allow_references(s) for s in schema]
    if not isinstance(schema, dict):
        return schema
    out = {k: _allow_references(v) for k, v in schema.items()}
    if out.get("type") in _TYPED or "enum" in out or "const" in out:
        meta = {k: out.pop(k) for k in ("default", "description", "title") if k in out}
        return {"anyOf": [out, {"$ref": "#/$defs/ParameterRef"}], **meta}
    return out


def _reachable(schema: Any, defs: dict[str, Any]) -> set[str]:
    """Names of the definitions ``schema`` refers to, directly or through others."""
    seen: set[str] = set()
    stack = [schema]
    while stack:
        item = stack.pop()
        if isinstance(item, dict):
            ref = item.get("$ref")
            if isinstance(ref, str) and ref.startswith("#/$defs/"):
                name = ref.removeprefix("#/$defs/")
                if name not in seen:
                    seen.add(name)
                    stack.append(defs[name])
            stack.extend(item.values())
        elif isinstance(item, list):
            stack.extend(item)
    return seen


def schema_text() -> str:
    """The schema as the committed file holds it (2-space JSON, newline at the end)."""
    return json.dumps(task_json_schema(), indent=2, ensure_ascii=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m taskrunner.tasks.schema",
                                     description="Print or write the task file JSON Schema.")
    parser.add_argument("--write", nargs="?", const=str(SCHEMA_PATH), metavar="PATH",
                        help=f"write it to PATH (default {SCHEMA_PATH})")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 if the committed file is not up to date")
    args = parser.parse_args(argv)
    text = schema_text()
    if args.check:
        # Compared as JSON values: pydantic releases differ in how they print numbers (0 or
        # 0.0), not in what the schema says.
        try:
            current = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            current = None
        if current != json.loads(text):
            sys.stderr.write(f"{SCHEMA_PATH} is out of date: run "
                             "python -m taskrunner.tasks.schema --write\n")
            return 1
        return 0
    if args.write:
        path = Path(args.write)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        return 0
    sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
