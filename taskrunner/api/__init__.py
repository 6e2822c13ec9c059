"""The taskrunner REST API: runs, live events, cancel, checking, cells, planning.

    from taskrunner.api import Settings, create_app
    app = create_app(Settings(token="..."))      # serve with uvicorn, or run-task serve
"""

from __future__ import annotations

from taskrunner.api.app import create_app, new_token
from taskrunner.api.settings import Settings

__all__ = ["Settings", "create_app", "new_token"]
