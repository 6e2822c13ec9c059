"""Fixtures of the task-language tests: the fixture folder, expected problems, cells."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import pytest

from taskrunner.robot.cell import Cell, load_cell

FIXTURES = Path(__file__).resolve().parent / "fixtures"
_EXPECT = re.compile(r"#\s*expect:\s*")


@pytest.fixture(scope="session")
def fixtures() -> Path:
    """``tests/tasks/fixtures``: small task files, valid and invalid."""
    return FIXTURES


@pytest.fixture(scope="session")
def expected_problems() -> Callable[[Path], list[tuple[int, str]]]:
    """``(line, message)`` of every ``# expect: <message>`` comment of a fixture file
    (several on one line allowed; ``{file}`` stands for the file's absolute path)."""

    def read(path: Path) -> list[tuple[int, str]]:
        found = []
        for number, text in enumerate(path.read_text().splitlines(), 1):
            for message in _EXPECT.split(text)[1:]:
                found.append((number, message.strip().replace("{file}", str(path))))
        return found

    return read


@pytest.fixture(scope="session")
def cells(robots_dir: Path) -> Callable[[str], Cell]:
    """``cells(name)``: a cell of ``robots/cells``, loaded once per session (read-only)."""
    loaded: dict[str, Cell] = {}

    def get(name: str) -> Cell:
        if name not in loaded:
            loaded[name] = load_cell(robots_dir / "cells" / f"{name}.yaml")
        return loaded[name]

    return get
