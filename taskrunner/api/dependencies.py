"""Getting the app's shared objects into endpoints (``Depends``).

The dependencies here and in :mod:`api.auth` are ``async``: they never block, and a
plain ``def`` dependency would cost every request a hop through the thread pool.
"""

from __future__ import annotations

from fastapi import Request

from taskrunner.api.admission import Admission, ControlExecutor
from taskrunner.api.cells import CellRegistry
from taskrunner.api.requestwork import RequestWork
from taskrunner.api.runs import RunManager
from taskrunner.api.settings import Settings
from taskrunner.api.store import RunStore
from taskrunner.api.streams import RunStreams

__all__ = ["get_cells", "get_checking", "get_control", "get_manager", "get_planning",
           "get_settings", "get_store", "get_work"]


async def get_settings(request: Request) -> Settings:
    return request.app.state.settings  # type: ignore[no-any-return]


async def get_manager(request: Request) -> RunManager:
    return request.app.state.manager  # type: ignore[no-any-return]


async def get_cells(request: Request) -> CellRegistry:
    return request.app.state.cells  # type: ignore[no-any-return]


async def get_store(request: Request) -> RunStore:
    return request.app.state.store  # type: ignore[no-any-return]


async def get_work(request: Request) -> RequestWork:
    return request.app.state.work  # type: ignore[no-any-return]


async def get_planning(request: Request) -> Admission:
    """The admission of plans and previews (``max_planners`` at once)."""
    return request.app.state.planning  # type: ignore[no-any-return]


async def get_checking(request: Request) -> Admission:
    """The admission of task loads and checks (``check_workers`` at once)."""
    return request.app.state.checking  # type: ignore[no-any-return]


async def get_streams(request: Request) -> RunStreams:
    """The runs' event feeds (one per run followed, shared by its streams)."""
    return request.app.state.streams  # type: ignore[no-any-return]


async def get_control(request: Request) -> ControlExecutor:
    """The control requests' own threads."""
    return request.app.state.control  # type: ignore[no-any-return]
