"""The walk-through "Your first task" of docs/getting-started.md, followed as written: in
an empty folder, the task file of the page, ``run-task check``, ``run-task FILE``,
``run-task view`` (the runs of ./runs) and ``run-task view FILE`` (the task, plan only),
in chromium. Takes the page's pictures: with ``TASKRUNNER_DOCS_IMAGES=docs/images`` they
are written there (to refresh the docs), else to the screenshots folder."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "getting-started.md"
TOKEN = "first-task-token-0123456789"
_CLI = [sys.executable, "-c", "import sys; from taskrunner.cli import main; sys.exit(main())"]


def task_text() -> str:
    """The task file as the page gives it (the YAML block after its marker)."""
    text = PAGE.read_text()
    after = text.split("<!-- first-task:", 1)[1]
    found = re.search(r"```yaml\n(.*?)```", after, re.S)
    assert found, "getting-started.md lost its first task"
    return found.group(1)


def run_task(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if k != "TASKRUNNER_RUNS_DIR"}
    return subprocess.run([*_CLI, *args], cwd=folder, capture_output=True, text=True,
                          env=env, timeout=300)


@contextmanager
def view(folder: Path, *args: str) -> Iterator[str]:
    """``run-task view ARGS`` in ``folder``; yields the URL it prints."""
    env = {k: v for k, v in os.environ.items() if k != "TASKRUNNER_RUNS_DIR"}
    process = subprocess.Popen([*_CLI, "view", *args, "--token", TOKEN], cwd=folder, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        assert process.stdout is not None
        line = process.stdout.readline()
        assert line.startswith("taskrunner view at http://127.0.0.1:"), line
        url = line.split(" at ", 1)[1].strip()
        deadline = time.monotonic() + 60
        while True:  # the URL is printed before the server listens
            try:
                urllib.request.urlopen(url.split("/#", 1)[0] + "/health", timeout=2)
                break
            except OSError:
                assert time.monotonic() < deadline and process.poll() is None, "no server"
                time.sleep(0.1)
        yield url
    finally:
        process.terminate()
        try:
            process.wait(20)
        except subprocess.TimeoutExpired:
            process.kill()


@pytest.fixture
def images(screenshots: Path) -> Path:
    asked = os.environ.get("TASKRUNNER_DOCS_IMAGES")
    folder = Path(asked) if asked else screenshots
    folder.mkdir(parents=True, exist_ok=True)
    return folder


@contextmanager
def browser_page(chromium: Any) -> Iterator[Any]:
    context = chromium.new_context(viewport={"width": 1280, "height": 760})
    page = context.new_page()
    errors: list[str] = []
    # A failed request is judged by its URL (below), not by chromium's console line for it.
    page.on("console", lambda m: errors.append(m.text) if m.type == "error"
            and not m.text.startswith("Failed to load resource") else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    # The one expected 404: the compiled tree of a run the server did not start (a CLI
    # record); the page then draws the tree from the run's events.
    page.on("response", lambda r: errors.append(f"{r.status} {r.url}") if r.status >= 400
            and not re.search(r"/viewer/runs/[^/]+/tree$", r.url) else None)
    try:
        yield page
    finally:
        context.close()
    assert not errors, errors


def enter_token(page: Any) -> None:
    page.fill("#token", TOKEN)
    page.click("#token-form button[type=submit]")


def test_the_first_task_walk_through_runs_as_written(chromium, images, tmp_path):
    folder = tmp_path / "first-task"
    folder.mkdir()
    (folder / "my_first_task.yaml").write_text(task_text())
    # 2. check
    checked = run_task(folder, "check", "my_first_task.yaml")
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "my_first_task.yaml: ok (4 steps checked against cell 'servo_arm_table')" \
        in checked.stdout
    typo = folder / "typo.yaml"
    typo.write_text(task_text().replace("  - pick:", "  - pik:"))
    wrong = run_task(folder, "check", "typo.yaml")
    assert wrong.returncode == 2 and "'pik' is not a step verb; did you mean 'pick'?" \
        in wrong.stdout + wrong.stderr
    typo.unlink()
    # 3. run: the expectations hold, the record goes to ./runs
    ran = run_task(folder, "my_first_task.yaml", "--plain")
    assert ran.returncode == 0, ran.stdout + ran.stderr
    (record,) = (folder / "runs").glob("*.json")
    # 4. run-task view: the runs of ./runs, then the run replayed
    with browser_page(chromium) as page, view(folder) as url:
        assert url.endswith("/#/runs")
        page.goto(url)
        enter_token(page)
        page.wait_for_selector(f"table.runs a[href='#/run/{record.stem}']")
        assert "succeeded" in page.text_content("table.runs")
        page.screenshot(path=str(images / "first-task-runs.png"))
        page.click(f"table.runs a[href='#/run/{record.stem}']")
        page.wait_for_function("window.__viewer.runStatus === 'succeeded'", timeout=20_000)
        page.wait_for_function("window.__viewer.firstFrame !== null", timeout=20_000)
        assert "my_first_task on servo_arm_table (mock): succeeded" in page.text_content(".banner")
        leaves = page.eval_on_selector_all("#run-tree li[data-key]",
                                           "els => els.map(e => e.className)")
        assert leaves and all("st-SUCCESS" in c for c in leaves)
        # the moment the cube is carried: halfway through the place's transfer motion
        page.evaluate("window.__viewer.state.playing = false")
        page.fill("#scrub", "560")
        page.dispatch_event("#scrub", "input")
        page.wait_for_timeout(200)
        carried = page.evaluate("""(() => { const tl = window.__viewer.state.timeline;
            const s = tl.sceneAt(window.__viewer.state.time);
            return (s.objects.find(o => o.name === 'cube') || {}).attached_to || null; })()""")
        assert carried, "the replay's cube is not in the gripper at 56 %"
        page.screenshot(path=str(images / "first-task-replay.png"))
    # run-task view FILE: the task, checked, then plan only
    with browser_page(chromium) as page, view(folder, "my_first_task.yaml") as url:
        assert url.endswith("/#/task/my_first_task")
        page.goto(url)
        enter_token(page)
        page.wait_for_function("window.__viewer.check && window.__viewer.check.ok",
                               timeout=60_000)
        page.click("text=plan only (preview)")
        page.wait_for_function("window.__viewer.preview", timeout=120_000)
        preview = page.evaluate("window.__viewer.preview")
        assert preview["status"] == "succeeded" and len(preview["motions"]) >= 8
        page.evaluate("window.__viewer.state.playing = false")
        page.fill("#scrub", "300")  # the pick's approach
        page.dispatch_event("#scrub", "input")
        page.wait_for_timeout(200)
        page.screenshot(path=str(images / "first-task-preview.png"))
    for name in ("first-task-runs", "first-task-replay", "first-task-preview"):
        assert (images / f"{name}.png").stat().st_size > 10_000, name
