"""The JSON Schema of task files: committed copy up to date, and it fits the language."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

from taskrunner.resources import DATA_ROOT
from taskrunner.tasks import STEP_TYPES
from taskrunner.tasks.schema import SCHEMA_PATH, main, schema_text, task_json_schema


def test_the_committed_schema_is_up_to_date(repo_root: Path):
    assert SCHEMA_PATH == DATA_ROOT / "tasks" / "task.schema.json"
    assert json.loads(SCHEMA_PATH.read_text(encoding="utf-8")) == json.loads(schema_text()), (
        "run: python -m taskrunner.tasks.schema --write")
    assert main(["--check"]) == 0


def test_write_puts_the_schema_where_asked(tmp_path: Path):
    assert main(["--write", str(tmp_path / "s.json")]) == 0
    assert json.loads((tmp_path / "s.json").read_text()) == task_json_schema()


def test_a_step_is_one_of_single_key_objects_one_per_verb():
    schema = task_json_schema()
    alternatives = schema["$defs"]["Step"]["oneOf"]
    assert [a["required"] for a in alternatives] == [[verb] for verb in STEP_TYPES]
    assert all(a["additionalProperties"] is False for a in alternatives)
    handoff = schema["$defs"]["HandoffStep"]
    assert {"from", "to", "at"} <= set(handoff["properties"])
    assert '"loc"' not in json.dumps(schema)


@pytest.fixture(scope="module")
def validator():
    jsonschema = pytest.importorskip("jsonschema")
    schema = task_json_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


@pytest.mark.parametrize("name", ["pick_place.yaml", "dual_arm.yaml", "pick_part.yaml",
                                  "include_twice.yaml", "bad_names_pair.yaml"])
def test_valid_task_files_satisfy_the_schema(validator, fixtures: Path, name: str):
    document = _yaml12_keys(yaml.safe_load((fixtures / name).read_text()))
    assert [e.message for e in validator.iter_errors(document)] == []


def _yaml12_keys(node: object) -> object:
    """PyYAML reads the key ``on:`` as True (YAML 1.1); editors read YAML 1.2 ("on")."""
    if isinstance(node, dict):
        return {("on" if k is True else k): _yaml12_keys(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_yaml12_keys(v) for v in node]
    return node


@pytest.mark.parametrize("step", [
    {"pik": {"arm": "arm", "object": "cube"}},
    {"pick": {"arm": "arm", "object": "cube", "aproach": 0.1}},
    {"wait": {"seconds": "soon"}},
    {"gripper": {"arm": "arm", "action": "opn"}},
    {"go": {"group": "arm", "to": "home"}, "name": "two keys"},
    {"parallel": [{"wait": {"seconds": 1}}]},
])
def test_the_schema_rejects_what_the_loader_rejects(validator, step: dict):
    document = {"task": "t", "cell": "c.yaml", "steps": [step]}
    assert list(validator.iter_errors(document))


def test_parameter_references_are_accepted_where_values_go(validator):
    document = {"task": "t", "steps": [
        {"wait": {"seconds": "${pause}"}},
        {"gripper": {"arm": "${arm}", "action": "${action}"}},
    ]}
    assert list(validator.iter_errors(document)) == []
