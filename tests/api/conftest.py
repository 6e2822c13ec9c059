"""Fixtures of the API tests: an app on a temporary database, planning in-process."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from apitest import AUTH, make_settings
from fastapi.testclient import TestClient

from taskrunner.api import Settings, create_app


@pytest.fixture
def settings(tmp_path: Path) -> Settings:
    return make_settings(tmp_path / "state")


@pytest.fixture
def client(settings: Settings) -> Iterator[TestClient]:
    # Every endpoint but /health needs the token: the client sends it (tests of the
    # answers without it send their own headers).
    with TestClient(create_app(settings), headers=AUTH) as c:
        yield c
