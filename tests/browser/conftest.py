"""Fixtures of the browser tests: a real ``run-task serve`` and Debian's chromium driven
by playwright (WebGL through SwiftShader, headless).

Skipped, with the reason, when chromium or the playwright package is missing. The
screenshots go to ``$TASKRUNNER_SCREENSHOTS`` (default: a pytest temporary folder); the
folder is printed. Every page fails its test if the browser logs an error.
"""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

TOKEN = "browser-test-token-0123456789"
CHROMIUM_ARGS = ["--headless=new", "--no-sandbox", "--disable-gpu",
                 "--enable-unsafe-swiftshader", "--use-angle=swiftshader",
                 "--disable-background-networking", "--disable-component-update",
                 "--no-first-run", "--disable-sync"]


def chromium_path() -> str | None:
    for name in (os.environ.get("TASKRUNNER_CHROMIUM"), "chromium", "chromium-browser"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


@pytest.fixture(scope="session")
def chromium() -> Iterator[Any]:
    executable = chromium_path()
    if executable is None:
        pytest.skip("no chromium on this machine (apt-get install -y chromium)")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.skip("the playwright Python package is not installed (pip install playwright)")
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=executable, args=CHROMIUM_ARGS)
        yield browser
        browser.close()


@pytest.fixture(scope="session")
def screenshots(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = Path(os.environ.get("TASKRUNNER_SCREENSHOTS") or tmp_path_factory.mktemp("screenshots"))
    folder.mkdir(parents=True, exist_ok=True)
    print(f"\nbrowser screenshots: {folder}", file=sys.stderr)
    return folder


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Server:
    def __init__(self, url: str, process: subprocess.Popen[bytes]) -> None:
        self.url = url
        self.process = process

    def api(self, path: str) -> Any:
        import json

        request = urllib.request.Request(self.url + path,
                                         headers={"Authorization": f"Bearer {TOKEN}"})
        with urllib.request.urlopen(request, timeout=10) as answer:
            return json.loads(answer.read())


@pytest.fixture(scope="session")
def server(tmp_path_factory: pytest.TempPathFactory, chromium: Any) -> Iterator[Server]:
    """``run-task serve`` on a free port, with a token and its own data folder."""
    port = _free_port()
    data = tmp_path_factory.mktemp("state")
    # Planning workers at nice 0, as the test process and whatever else runs beside: at
    # the server's default nice 10, beside 4 spinning processes on 2 cores, a worker has a
    # few % of a core and did not load its cell in the 60 s it is given (the page's run
    # then failed); the tests are about the page, not that priority.
    env = {**os.environ, "TASKRUNNER_TOKEN": TOKEN, "TASKRUNNER_DATA_DIR": str(data),
           "TASKRUNNER_PLANNER_NICE": "0"}
    process = subprocess.Popen(
        [sys.executable, "-c", "import sys; from taskrunner.cli import main; sys.exit(main())",
         "serve", "--port", str(port), "--log-level", "warning"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 60
    while True:
        try:
            urllib.request.urlopen(url + "/health", timeout=1)
            break
        except OSError:
            if process.poll() is not None or time.monotonic() > deadline:
                process.kill()
                pytest.fail("run-task serve did not start")
            time.sleep(0.1)
    yield Server(url, process)
    process.terminate()
    try:
        process.wait(20)
    except subprocess.TimeoutExpired:
        process.kill()


# How long a run started from the page may take before the test calls it hung. Only a
# bound on a hang: a run's planning scales with the CPU share it gets, and beside 4
# spinning processes on 2 cores (load 9-16) a hand-over on sim took 70-95 s, and the
# server's first plans (kernels compiled) more.
HANG_MS = 600_000
# Every status a run ends in (taskrunner.kinds.RunStatus but "running").
RUN_ENDED = ("succeeded", "failed", "cancelled", "interrupted")


def wait_for_run_end(page: Any, run_id: str, hang_ms: float) -> dict[str, Any]:
    """Wait until the page shows the run ended, in whatever status, and return the run's
    record from the API. A run that fails is reported at once with its error; ``hang_ms``
    only bounds a hang (a busy machine makes a run slower, not different)."""
    ended = "[" + ", ".join(f"'{s}'" for s in RUN_ENDED) + "]"
    page.wait_for_function(f"{ended}.includes(window.__viewer.runStatus)", timeout=hang_ms)
    detail = page.server.api(f"/runs/{run_id}")
    assert detail["status"] == page.evaluate("window.__viewer.runStatus"), detail["status"]
    return dict(detail)


@pytest.fixture
def page(chromium: Any, server: Server) -> Iterator[Any]:
    """A fresh page (its own session storage); fails the test on a browser error, and
    checks that the token never travels in a URL."""
    context = chromium.new_context(viewport={"width": 1280, "height": 800})
    tab = context.new_page()
    errors: list[str] = []
    urls: list[str] = []
    tab.on("console", lambda m: errors.append(f"console: {m.text}") if m.type == "error" else None)
    tab.on("pageerror", lambda e: errors.append(f"page error: {e}"))
    tab.on("request", lambda r: urls.append(r.url))
    tab.server = server
    yield tab
    tab.wait_for_timeout(100)
    context.close()
    assert not errors, errors
    assert not [u for u in urls if TOKEN in u], "the token was sent in a URL"
