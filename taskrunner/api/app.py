"""The FastAPI application: :func:`create_app` assembles the routers around one
:class:`~api.runs.RunManager`, built in the lifespan and closed with it."""

from __future__ import annotations

import asyncio
import contextlib
import gc
import logging
import secrets
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import FastAPI
from fastapi.openapi.docs import get_swagger_ui_html
from fastapi.responses import HTMLResponse

from taskrunner.api.admission import Admission, ControlExecutor
from taskrunner.api.auth import AuthGate
from taskrunner.api.cells import CellRegistry, settle_heap
from taskrunner.api.fastpath import RunDetailFastPath
from taskrunner.api.handlers import BodyLimit, add_error_handlers
from taskrunner.api.overload import RequestLimit
from taskrunner.api.requestwork import RequestWork
from taskrunner.api.routers import cells, health, plan, runs, tasks, viewer, viewer_goal
from taskrunner.api.runs import RunManager
from taskrunner.api.settings import Settings
from taskrunner.api.store import RunStore
from taskrunner.api.streams import RunStreams, StreamOptions

__all__ = ["create_app", "new_token"]

log = logging.getLogger("taskrunner.api")


def new_token() -> str:
    """A fresh random bearer token (URL-safe, 32 bytes of entropy)."""
    return secrets.token_urlsafe(32)


def create_app(settings: Settings | None = None) -> FastAPI:
    """The API app.

    With ``settings.auth`` on and no token set, a token is made here and kept in
    ``app.state.token`` (the CLI prints it); with ``auth`` off, no endpoint needs one.
    The run database is opened, and rows a previous server left running are marked
    interrupted, when the app starts; at shutdown every run in flight is cancelled and
    recorded as interrupted, the backends and planning workers are closed.
    """
    settings = settings or Settings.from_env()

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        store = RunStore(settings.db_path)
        marked = store.mark_interrupted()
        if marked:
            log.warning("%d run(s) left in flight by a previous server marked interrupted",
                        marked)
        registry = CellRegistry(settings.cells_dir,
                                {"sim": settings.sim_speed, "mock": settings.mock_speed},
                                settings.planner, store, settings.planner_nice,
                                policy=settings.folder_policy(),
                                servo_port=settings.servo_port, servo_url=settings.servo_url,
                                firmware_speedup=settings.firmware_speedup,
                                options=settings.load_options())
        feeds = None
        if settings.foxglove_port is not None:  # serve --foxglove: one feed per cell
            from taskrunner.export.cellfeeds import CellFeeds, CellFeedsOptions
            from taskrunner.resources import cell_files

            # The ports as serve printed them: every cell file of the folder, in order.
            feeds = CellFeeds(list(cell_files(settings.cells_dir)),
                              CellFeedsOptions(port=settings.foxglove_port))
            app.state.feeds = feeds
        manager = RunManager(registry, store, tick_hz=settings.tick_hz, feeds=feeds)
        work = RequestWork(settings.check_isolation, settings.check_timeout_s,
                           settings.check_memory_mb, settings.check_workers)
        work.start()
        app.state.cells, app.state.manager, app.state.store = registry, manager, store
        app.state.work = work
        app.state.control = ControlExecutor()
        reaper = asyncio.create_task(_reap_planners(registry, settings.planner_idle_s))
        settle_heap()
        try:
            yield
        finally:
            reaper.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await reaper
            app.state.control.close()
            work.close()
            manager.shutdown(settings.shutdown_timeout_s)
            if feeds is not None:
                feeds.close()
            registry.close()
            store.close()
            gc.unfreeze()  # what settle_heap froze can be collected again

    app = FastAPI(
        title="taskrunner",
        version="0.1.0",
        description="Run robot-cell tasks, follow them live, cancel them, check them, plan "
                    "motions. Every endpoint but /health and these docs needs the bearer "
                    "token (reads too, unless the server opens them: TASKRUNNER_OPEN_READS).",
        lifespan=lifespan,
        docs_url=None,  # served below with Swagger UI's files from the package, not a CDN
        redoc_url=None,
    )
    _add_docs_page(app)
    app.state.settings = settings
    app.state.token = (settings.token or new_token()) if settings.auth else None
    # Heavy work bounded (each kind: so many at once, so many more waiting, then 503);
    # control requests on threads of their own (see api.admission).
    app.state.planning = Admission("plans and previews", settings.max_planners,
                                   settings.work_queue, settings.plan_timeout_s,
                                   setting="max_planners")
    app.state.checking = Admission("task loads and checks", settings.check_workers,
                                   settings.work_queue, settings.check_timeout_s,
                                   setting="check_workers")
    # One feed per run followed, its streams bounded (see api.streams).
    app.state.streams = RunStreams(StreamOptions(
        max_lag=settings.stream_max_lag, send_timeout_s=settings.stream_send_timeout_s))
    routers = [module.router
               for module in (health, runs, tasks, cells, plan, viewer, viewer_goal)]
    for router in routers:
        app.include_router(router)
    add_error_handlers(app)
    app.add_middleware(BodyLimit, max_bytes=settings.max_body_bytes)
    # Before the body is read: a 401 costs no parsing.
    app.add_middleware(AuthGate, routes=[route for router in routers for route in router.routes])
    app.add_middleware(RunDetailFastPath)  # polls skip the rest
    # Outermost: past max_requests at once, 503 before any work (control requests exempt).
    app.add_middleware(RequestLimit, limit=settings.max_requests)
    return app


def _add_docs_page(app: FastAPI) -> None:
    """``/docs``: Swagger UI for ``/openapi.json``, its script, style sheet and icon served
    by the view's static route (copied there from swagger-ui-dist by the view's build), so
    the page works with no network; no validator badge (it would call swagger.io)."""
    static = "/viewer/static"

    @app.get("/docs", include_in_schema=False)
    async def docs_page() -> HTMLResponse:
        return get_swagger_ui_html(
            openapi_url=app.openapi_url or "/openapi.json", title=f"{app.title} - API",
            swagger_js_url=f"{static}/swagger-ui-bundle.js",
            swagger_css_url=f"{static}/swagger-ui.css",
            swagger_favicon_url=f"{static}/swagger-ui-favicon-32x32.png",
            swagger_ui_parameters={"validatorUrl": None})


async def _reap_planners(registry: CellRegistry, idle_s: float) -> None:
    """Close planning workers idle for ``idle_s`` (checked every ``idle_s / 4``, at
    least every 30 s): a burst of plans leaves no processes behind."""
    period = min(max(idle_s / 4, 0.05), 30.0)
    while True:
        await asyncio.sleep(period)
        closed = await asyncio.to_thread(registry.reap_planners, idle_s)
        if closed:
            log.info("closed %d idle planning worker(s)", closed)
