"""The browser view of cells, tasks and runs.

``src/`` holds the page's JavaScript (three.js and urdf-loader, bundled with esbuild:
``npm install && npm run build`` in this folder); ``static/`` the built bundle and the
page, shipped as package data so that serving it needs no node and no network.
:mod:`taskrunner.viewer.describe` turns cells, trees and records into the JSON the page
reads; :mod:`taskrunner.api.routers.viewer` serves both.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["STATIC_DIR"]

STATIC_DIR = Path(__file__).resolve().parent / "static"
