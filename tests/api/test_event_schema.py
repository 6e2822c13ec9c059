"""The API's event body is the run record's event model, not a copy: same fields, same JSON."""

from __future__ import annotations

import json

from taskrunner.api.detail import _event_json
from taskrunner.api.schemas import EventOut
from taskrunner.runtime.events import RunEvent


def test_the_api_sends_the_records_event_model():
    assert EventOut is RunEvent


def test_an_event_body_is_the_records_json():
    events = [
        RunEvent(3, 1.23456789, "planned", node="go home", location="task.yaml:7",
                 status=None, message="planned in 0.1 s", data={"duration": 1.5, "waypoints": 4}),
        RunEvent(1, 0.0, "run_started"),
    ]
    for event in events:
        as_dict = event.as_dict()
        assert json.loads(_event_json(as_dict)) == as_dict
        assert list(json.loads(_event_json(as_dict))) == ["seq", "time", "kind", "node",
                                                          "location", "status", "message", "data"]
    assert json.loads(_event_json(events[0].as_dict()))["time"] == 1.234568


def test_the_openapi_document_describes_the_event_fields(tmp_path):
    from taskrunner.api import Settings, create_app

    schema = create_app(Settings(token="a-long-token", data_dir=tmp_path)).openapi()["components"]["schemas"]["RunEvent"]
    assert list(schema["properties"]) == ["seq", "time", "kind", "node", "location", "status",
                                          "message", "data"]
    assert schema["required"] == ["seq", "time", "kind"]
