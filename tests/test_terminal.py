"""``run-task`` in a real terminal of 80 x 20, as a person sees it: the live tree fits the
screen, redraws in place, shows the motion's progress, and leaves no scrollback flood.

The program runs on a pseudo-terminal whose window size is set with ``TIOCSWINSZ``; what it
writes is replayed on :class:`Screen`, a small VT100 screen that counts the lines scrolled
off the top (into the scrollback) and the lines that wrapped. It knows what ``run-task``
writes (text, CR, LF, BS, TAB, cursor moves, erase in line and display; SGR and private
modes ignored). ``ED 2`` (erase the whole display) pushes the screen into the scrollback
first, as VTE-based terminals (GNOME Terminal, Tilix) do.
"""

from __future__ import annotations

import fcntl
import os
import pty
import re
import select
import signal
import struct
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

_CSI = re.compile(r"\x1b\[([0-9;?]*)([@-~])")
_OSC = re.compile(r"\x1b\][^\x07\x1b]*(\x07|\x1b\\)")


class Screen:
    """A ``columns`` x ``rows`` terminal screen with a scrollback."""

    def __init__(self, columns: int, rows: int) -> None:
        self.columns, self.rows = columns, rows
        self.grid = [[" "] * columns for _ in range(rows)]
        self.row = self.col = 0
        self.pending_wrap = False
        self.scrollback: list[str] = []
        self.wraps = 0  # lines that ran past the right margin

    def feed(self, text: str) -> None:
        i = 0
        while i < len(text):
            ch = text[i]
            if ch == "\x1b":
                match = _CSI.match(text, i) or _OSC.match(text, i)
                if match is None:  # a two-character escape (ESC 7, ESC =): skip it
                    i += 2
                    continue
                if match.re is _CSI:
                    self._csi(match.group(1), match.group(2))
                i = match.end()
                continue
            if ch == "\n":
                self._line_feed()
            elif ch == "\r":
                self.col, self.pending_wrap = 0, False
            elif ch == "\b":
                self.col, self.pending_wrap = max(self.col - 1, 0), False
            elif ch == "\t":
                self.col = min((self.col // 8 + 1) * 8, self.columns - 1)
            elif ch >= " ":
                self._put(ch)
            i += 1

    def lines(self) -> list[str]:
        """The screen's rows, trailing blanks cut."""
        return ["".join(row).rstrip() for row in self.grid]

    def _put(self, ch: str) -> None:
        if self.pending_wrap:
            self.wraps += 1
            self.col, self.pending_wrap = 0, False
            self._line_feed()
        self.grid[self.row][self.col] = ch
        if self.col == self.columns - 1:
            self.pending_wrap = True
        else:
            self.col += 1

    def _line_feed(self) -> None:
        self.pending_wrap = False
        if self.row == self.rows - 1:
            self.scrollback.append("".join(self.grid.pop(0)).rstrip())
            self.grid.append([" "] * self.columns)
        else:
            self.row += 1

    def _csi(self, params: str, final: str) -> None:
        if params.startswith("?"):
            return  # private modes (cursor visibility, ...)
        numbers = [int(p) if p else 0 for p in params.split(";")] if params else []
        n = max(numbers[0], 1) if numbers else 1
        if final != "m":
            self.pending_wrap = False
        if final == "A":
            self.row = max(self.row - n, 0)
        elif final == "B":
            self.row = min(self.row + n, self.rows - 1)
        elif final == "C":
            self.col = min(self.col + n, self.columns - 1)
        elif final == "D":
            self.col = max(self.col - n, 0)
        elif final in "Hf":
            row = numbers[0] if numbers else 1
            col = numbers[1] if len(numbers) > 1 else 1
            self.row = min(max(row, 1), self.rows) - 1
            self.col = min(max(col, 1), self.columns) - 1
        elif final == "K":
            mode = numbers[0] if numbers else 0
            start, end = {0: (self.col, self.columns), 1: (0, self.col + 1),
                          2: (0, self.columns)}.get(mode, (0, 0))
            for c in range(start, end):
                self.grid[self.row][c] = " "
        elif final == "J":
            mode = numbers[0] if numbers else 0
            if mode == 2:
                self.scrollback.extend(line for line in self.lines() if line)
                self.grid = [[" "] * self.columns for _ in range(self.rows)]
            elif mode == 0:
                for c in range(self.col, self.columns):
                    self.grid[self.row][c] = " "
                for r in range(self.row + 1, self.rows):
                    self.grid[r] = [" "] * self.columns


def run_in_terminal(argv: list[str], columns: int, rows: int, cwd: Path,
                    timeout: float = 180.0, resize_to: tuple[int, int] | None = None,
                    interrupt_on: re.Pattern[str] | None = None,
                    exit_code: int = 0) -> list[tuple[float, bytes]]:
    """Run ``argv`` on a pseudo-terminal of ``columns`` x ``rows``; what it wrote, in chunks
    with the time each was read. ``resize_to``: the size to change the window to (and
    SIGWINCH) once the live tree is up. ``interrupt_on``: press Ctrl-C (SIGINT to the
    process group, as the terminal does) once the output matches it."""
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", rows, columns, 0, 0))
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")}
    env.update(TERM="xterm-256color", PYTHONUNBUFFERED="1")
    process = subprocess.Popen(argv, stdin=slave, stdout=slave, stderr=slave, cwd=cwd,
                               env=env, start_new_session=True)
    os.close(slave)
    chunks: list[tuple[float, bytes]] = []
    started = time.monotonic()
    resized = resize_to is None
    interrupted = interrupt_on is None
    try:
        while time.monotonic() - started < timeout:
            ready, _, _ = select.select([master], [], [], 0.5)
            if not ready:
                if process.poll() is not None:
                    break
                continue
            try:
                data = os.read(master, 65536)
            except OSError:  # EIO: the program closed its terminal
                break
            if not data:
                break
            chunks.append((time.monotonic() - started, data))
            if not resized and b"\x1b[?25l" in b"".join(c for _, c in chunks):
                assert resize_to is not None
                fcntl.ioctl(master, termios.TIOCSWINSZ,
                            struct.pack("HHHH", resize_to[1], resize_to[0], 0, 0))
                os.killpg(process.pid, signal.SIGWINCH)
                resized = True
            if not interrupted and interrupt_on is not None and interrupt_on.search(
                    b"".join(c for _, c in chunks).decode(errors="replace")):
                os.killpg(process.pid, signal.SIGINT)
                interrupted = True
        code = process.wait(timeout=max(1.0, timeout - (time.monotonic() - started)))
        assert code == exit_code, \
            b"".join(c for _, c in chunks).decode(errors="replace")[-3000:]
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
        os.close(master)
    return chunks


def _run_task(*args: str) -> list[str]:
    return [sys.executable, "-m", "taskrunner.cli", *args]


PROGRESS = re.compile(r"▕[█▉▊▋▌▍▎▏ ]{10}▏ \d+\.\d s of \d+\.\d s")
SUMMARY = re.compile(r"pick_place: succeeded \(exit 0\) in [\d.]+ s wall\n  \d+ steps, .* s of motion")


@pytest.fixture(scope="module")
def sim_run(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Screen]:
    cwd = tmp_path_factory.mktemp("terminal")
    chunks = run_in_terminal(_run_task("pick_place", "--backend", "sim", "--speed", "20"),
                             80, 20, cwd)
    text = b"".join(c for _, c in chunks).decode()
    screen = Screen(80, 20)
    screen.feed(text)
    return text, screen


def test_live_tree_on_80x20_never_writes_a_line_wider_than_the_screen(sim_run):
    text, screen = sim_run
    assert screen.wraps == 0
    for line in re.split(r"[\r\n]|\x1b\[\d*[ABHJ]", _CSI.sub(
            lambda m: m.group(0) if m.group(2) in "ABHJ" else "", text)):
        assert len(line) <= 80, line


def test_live_tree_on_80x20_leaves_the_last_frame_and_summary_not_a_scrollback_flood(sim_run):
    text, screen = sim_run
    frames = text.count("\x1b[J")
    # it was redrawn all along (at least once a few steps: pick_place at --speed 20 plays
    # its 12.5 s of motion in about 0.6 s, so a frame count tied to wall time is small) ...
    assert frames > 5
    # ... in place: less than one screen went by into the scrollback (the check's line,
    # the top of the last frame pushed up by the summary).
    assert len(screen.scrollback) < 20, screen.scrollback
    everything = "\n".join(screen.scrollback + screen.lines()).rstrip("\n").splitlines()
    assert SUMMARY.search("\n".join(everything[-6:])), everything[-6:]
    assert "✔ pick_place" in everything  # the last frame


def test_live_tree_shows_the_motions_progress_while_it_runs(sim_run):
    text, _ = sim_run
    assert PROGRESS.search(text), "no progress bar was drawn during a motion"


def test_live_tree_follows_a_resize_and_a_narrow_terminal(tmp_path):
    chunks = run_in_terminal(_run_task("go_home", "--backend", "sim", "--speed", "20"),
                             80, 20, tmp_path, resize_to=(40, 12))
    text = b"".join(c for _, c in chunks).decode()
    screen = Screen(80, 20)
    screen.feed(text)
    # The frames drawn at the new size (the summary after them is plain text).
    after = text[text.index("\x1b[H"):text.index("\x1b[?25h")]
    for line in re.split(r"\r|\n|\x1b\[\d*[AHJ]", re.sub(r"\x1b\[(\?25[lh]|K)", "", after)):
        assert len(line) <= 40, line
    assert "go_home: succeeded" in text


def test_run_without_a_terminal_writes_plain_log_lines(tmp_path):
    result = subprocess.run(_run_task("go_home", "--backend", "sim", "--speed", "20"),
                            cwd=tmp_path, capture_output=True, text=True, timeout=180)
    assert result.returncode == 0, result.stderr
    assert "\x1b" not in result.stdout
    assert re.search(r"✔ go arm", result.stdout)


def test_ctrl_c_under_the_live_tree_shows_the_notice_and_ends_with_the_summary(tmp_path):
    chunks = run_in_terminal(_run_task("pick_place", "--backend", "sim"), 80, 20, tmp_path,
                             interrupt_on=PROGRESS, exit_code=130)
    text = b"".join(c for _, c in chunks).decode()
    assert "Traceback" not in text
    screen = Screen(80, 20)
    screen.feed(text)
    shown = "\n".join(screen.scrollback + screen.lines())
    assert "cancelled (Ctrl-C): stopping the motion where it is …" in shown
    assert "pick_place: cancelled (exit 130)" in shown
    assert screen.wraps == 0 and len(screen.scrollback) < 20
    assert text.rstrip().endswith(".json")  # the summary's record line is the last


def test_a_plain_run_in_a_terminal_ends_with_its_summary(tmp_path):
    """The expectations' check after the last motion loads the compiled kernels in
    run-task's own process; nothing (no terminal reset from numba's colour set-up) comes
    after the summary's record line."""
    chunks = run_in_terminal(_run_task("pick_place", "--plain", "--backend", "mock"), 80, 20,
                             tmp_path)
    text = b"".join(c for _, c in chunks).decode()
    assert "expectations met" in text
    assert "\x1b" not in text
    assert text.rstrip().endswith(".json")
