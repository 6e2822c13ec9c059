"""The live tree of a run in a terminal: one screen, redrawn in place.

A frame is a header line, the tree laid out to fit the terminal and, if the run said
something (a retry, a warning, a cancel), a last line with it. The tree fits the height:
finished and not-yet-started subtrees collapse to one line, the running branch (and a
failure) always shows, and when it still does not fit the rows farthest from the running
step are elided, each run of them replaced by one ``… N more`` line. The running motion
shows a progress bar and its time (``▕████▍    ▏ 12.3 s of 30.1 s · 17.8 s left``) from
the backend's execution handle. Lines are cut to the width.

Each frame overwrites the previous one (cursor up, erase to the end of the screen), so a
run leaves its final frame, not one copy per redraw, in the scrollback. The size is read
again for every frame: after a resize the frame is redrawn from the top of the screen.

:func:`layout_tree` is pure (a :class:`NodeView` and a size in, lines out);
:func:`view_tree` reads a py_trees tree; :class:`LiveTree` draws a :class:`Runner`.
"""

from __future__ import annotations

import os
import shutil
import time
import uuid
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, TextIO

import py_trees
from py_trees.common import Status

from taskrunner.backends.base import ExecutionHandle
from taskrunner.kinds import NodeStatus

if TYPE_CHECKING:
    from taskrunner.runtime.runner import Runner

__all__ = ["LiveTree", "MotionProgress", "NodeView", "TerminalScreen", "layout_frame",
           "layout_tree", "progress_bar", "view_tree"]

_MARKS: dict[str, str] = {NodeStatus.SUCCESS: "✔", NodeStatus.FAILURE: "✘",
                          NodeStatus.RUNNING: "▶", NodeStatus.INVALID: "·",
                          NodeStatus.CANCELLED: "■"}
_INDENT = "  "
_ELLIPSIS = "…"
_BAR_CELLS = 10
_PARTIAL = " ▏▎▍▌▋▊▉"  # 0/8 .. 7/8 of a cell


@dataclass(frozen=True)
class MotionProgress:
    """A motion under way.

    Attributes:
        elapsed: seconds of the trajectory executed (trajectory time, from its first sample).
        duration: seconds from the trajectory's first sample to its last.
    """

    elapsed: float
    duration: float


@dataclass(frozen=True)
class NodeView:
    """What the display needs of one tree node.

    Attributes:
        name: the node's name.
        status: a :class:`~taskrunner.kinds.NodeStatus` value (``INVALID``: not started,
            ``CANCELLED``: running when the run was stopped).
        children: the node's children, in order (none for a leaf).
        seconds: how long a running leaf has been at it (s), if known.
        motion: the motion a running leaf executes, if any.
    """

    name: str
    status: str
    children: tuple[NodeView, ...] = ()
    seconds: float | None = None
    motion: MotionProgress | None = None

    def leaves(self) -> int:
        """Leaves under this node (1 for a leaf)."""
        return sum(c.leaves() for c in self.children) if self.children else 1


def view_tree(root: py_trees.behaviour.Behaviour,
              clock: Callable[[], float] = time.monotonic,
              stopped: Mapping[uuid.UUID, tuple[str, str]] | None = None) -> NodeView:
    """A :class:`NodeView` of a py_trees tree as it is now (read from another thread:
    a status may be one tick old). A running leaf's motion progress comes from its
    execution handle (``handle``), its time from ``started_at`` (monotonic s).
    ``stopped``: once the run was stopped, each node's status as it was then (node id:
    (status, message), :attr:`Runner.stopped`), shown instead of the reset tree's."""
    if stopped is not None:
        status = stopped.get(root.id, (root.status.value, ""))[0]
        return NodeView(root.name, status,
                        tuple(view_tree(c, clock, stopped) for c in root.children))
    status = root.status.value
    if root.children:
        return NodeView(root.name, status, tuple(view_tree(c, clock) for c in root.children))
    if root.status != Status.RUNNING:
        return NodeView(root.name, status)
    started = getattr(root, "started_at", None)
    seconds = clock() - started if isinstance(started, (int, float)) and started else None
    handle = getattr(root, "handle", None)
    motion = None
    if isinstance(handle, ExecutionHandle):
        times = handle.trajectory.times
        motion = MotionProgress(float(handle.progress), float(times[-1] - times[0]))
    return NodeView(root.name, status, seconds=seconds, motion=motion)


def progress_bar(fraction: float, cells: int = _BAR_CELLS) -> str:
    """``▕████▍    ▏``: ``fraction`` (clamped to [0, 1]) of ``cells`` cells, in eighths."""
    eighths = round(min(max(fraction, 0.0), 1.0) * cells * 8)
    full, part = divmod(eighths, 8)
    bar = "█" * full + (_PARTIAL[part] if full < cells else "")
    return f"▕{bar.ljust(cells)}▏"


@dataclass(frozen=True)
class _Row:
    depth: int
    text: str  # mark and name: cut first when the line is too long
    suffixes: tuple[str, ...]  # what follows, longest first: the first that fits is used
    keep: bool  # on the running branch or a failure: elided last
    leaf: bool = False
    running: bool = False


def _rows(node: NodeView, depth: int, out: list[_Row]) -> None:
    mark = _MARKS.get(node.status, "?")
    running = node.status == NodeStatus.RUNNING
    keep = running or node.status in (NodeStatus.FAILURE, NodeStatus.CANCELLED)
    if not node.children:
        out.append(_Row(depth, f"{mark} {node.name}", _leaf_suffixes(node), keep,
                        leaf=True, running=running))
        return
    expanded = depth == 0 or keep
    if not expanded:
        count = node.leaves()
        out.append(_Row(depth, f"{mark} {node.name}",
                        (f"  ({count} step{'s' if count != 1 else ''})", ""), keep))
        return
    out.append(_Row(depth, f"{'▼' if running else mark} {node.name}", ("",), keep))
    for child in node.children:
        _rows(child, depth + 1, out)


def _leaf_suffixes(node: NodeView) -> tuple[str, ...]:
    if node.status != NodeStatus.RUNNING:
        return ("",)
    if node.motion is not None:
        m = node.motion
        done = f"{m.elapsed:.1f} s of {m.duration:.1f} s"
        bar = progress_bar(m.elapsed / m.duration if m.duration > 0 else 1.0)
        left = max(m.duration - m.elapsed, 0.0)
        return (f"  {bar} {done} · {left:.1f} s left", f"  {bar} {done}", f"  {done}", "")
    if node.seconds is not None:
        return (f"  {node.seconds:.1f} s", "")
    return ("",)


def _fit(text: str, width: int) -> str:
    """``text`` cut to ``width`` characters, an ellipsis marking the cut."""
    if len(text) <= width:
        return text
    return text[:width - 1] + _ELLIPSIS if width > 0 else ""


def _render(row: _Row, width: int) -> str:
    indent = _INDENT * row.depth
    for suffix in row.suffixes:
        room = width - len(indent) - len(suffix)
        # A suffix is worth showing only with enough of the name left to tell the step.
        if room >= min(len(row.text), 12) or suffix == row.suffixes[-1]:
            return _fit(indent + _fit(row.text, max(room, 0)) + suffix, width)
    return _fit(indent + row.text, width)  # pragma: no cover (the last suffix always fits)


def _cost(kept: set[int], total: int) -> int:
    """Lines shown for the rows ``kept`` out of ``total``: each row, plus one per gap."""
    gaps, previous = 0, -1
    for i in sorted(kept):
        gaps += i > previous + 1
        previous = i
    return len(kept) + gaps + (previous < total - 1)


def _select(rows: list[_Row], height: int) -> list[_Row | int]:
    """The rows to show in ``height`` lines; an int stands for that many elided rows."""
    if len(rows) <= height:
        return list(rows)
    # The step to show above all: the running leaf (the last one, in a parallel), else
    # the failed one, else the end.
    running = [i for i, r in enumerate(rows) if r.leaf and r.running]
    failed = [i for i, r in enumerate(rows) if r.leaf and r.keep]
    focus = (running or failed or [len(rows) - 1])[-1]

    def nearness(i: int) -> tuple[int, int, bool]:
        # The running branch first, then the closest rows, upcoming ones before finished.
        return (not rows[i].keep and i != 0, abs(i - focus), i < focus)

    kept: set[int] = set()
    for i in sorted(range(len(rows)), key=nearness):
        if _cost(kept | {i}, len(rows)) <= height:
            kept.add(i)
    if not kept:  # too small even for one row and its elision lines
        alone: list[_Row | int] = [rows[focus]]
        return alone[:height]
    shown: list[_Row | int] = []
    hidden = 0
    for i, row in enumerate(rows):
        if i in kept:
            if hidden:
                shown.append(hidden)
            shown.append(row)
            hidden = 0
        else:
            hidden += 1
    if hidden:
        shown.append(hidden)
    return shown


def layout_tree(tree: NodeView, width: int, height: int) -> list[str]:
    """The tree as at most ``height`` lines of at most ``width`` characters.

    The root and every running or failed composite are expanded; other composites
    collapse to one line (``✔ pick cube  (8 steps)``). A running leaf with a motion shows
    its progress. When the rows still do not fit, those farthest from the running step
    are elided, each run of them shown as ``… N more``.
    """
    if width <= 0 or height <= 0:
        return []
    rows: list[_Row] = []
    _rows(tree, 0, rows)
    lines: list[str] = []
    for index, item in enumerate(shown := _select(rows, height)):
        if isinstance(item, int):
            after = shown[index + 1] if index + 1 < len(shown) else None
            depth = after.depth if isinstance(after, _Row) else 1
            lines.append(_fit(f"{_INDENT * depth}{_ELLIPSIS} {item} more", width))
        else:
            lines.append(_render(item, width))
    return lines


def layout_frame(header: str, tree: NodeView, note: str | None, width: int,
                 height: int) -> list[str]:
    """A whole frame: ``header``, the tree in what is left, and ``note`` (if any) last."""
    if height <= 0 or width <= 0:
        return []
    lines = [_fit(header, width)]
    footer = [_fit(note, width)] if note and height >= 3 else []
    lines += layout_tree(tree, width, height - len(lines) - len(footer))
    return lines[:height - len(footer)] + footer


class TerminalScreen:
    """Frames drawn in place on a terminal (ANSI/VT100 cursor control).

    Each frame replaces the previous one: the cursor goes back to the frame's first line,
    every line is rewritten and erased to its end, and the rest of the screen is erased.
    Lines are cut one short of the width (a full-width line leaves the cursor pending a
    wrap, where erasing to the end of the line eats its last character).
    """

    def __init__(self, out: TextIO) -> None:
        self.out = out
        self._lines = 0  # lines of the frame on screen (the cursor is on its last one)
        self._size: tuple[int, int] | None = None
        self._closed = False

    def size(self) -> tuple[int, int]:
        """(columns, rows) of the terminal now."""
        try:
            columns, rows = os.get_terminal_size(self.out.fileno())
        except (AttributeError, ValueError, OSError):
            columns, rows = shutil.get_terminal_size()
        return max(columns, 1), max(rows, 1)

    def show(self, lines: list[str]) -> None:
        """Replace the frame on screen with ``lines`` (cut to the width)."""
        size = self.size()
        width = max(size[0] - 1, 1)
        parts = []
        if self._size is None:
            parts.append("\x1b[?25l")  # hide the cursor while frames are drawn
        if self._size is not None and size != self._size:
            # Lines drawn at the old size may have been rewrapped: start again at the top.
            parts.append("\x1b[H")
        elif self._lines:
            parts.append("\r" + (f"\x1b[{self._lines - 1}A" if self._lines > 1 else ""))
        body = [_fit(line, width) + "\x1b[K" for line in lines[:size[1]]]
        parts.append("\n".join(body))
        parts.append("\x1b[J")
        self.out.write("".join(parts))
        self.out.flush()
        self._lines = len(body)
        self._size = size

    def close(self) -> None:
        """Leave the last frame on screen, the cursor below it and visible (idempotent)."""
        if self._closed:
            return
        self._closed = True
        if self._size is not None:
            self.out.write("\n\x1b[?25h" if self._lines else "\x1b[?25h")
            self.out.flush()


class LiveTree:
    """The live display of one run: :meth:`update` a few times a second, then
    :meth:`close`. :attr:`note` (a cancel notice) shows on the last line."""

    def __init__(self, out: TextIO, clock: Callable[[], float] = time.monotonic) -> None:
        self.screen = TerminalScreen(out)
        self.note: str | None = None
        self._clock = clock
        self._started = clock()

    def update(self, runner: Runner) -> None:
        """Draw the run as it is now."""
        columns, rows = self.screen.size()
        tree = view_tree(runner.tree, self._clock, runner.stopped)
        done = _finished_leaves(tree)
        header = (f"{runner.spec.name}  ·  {self._clock() - self._started:.1f} s  ·  "
                  f"{done} of {tree.leaves()} steps")
        leaf = runner.current_leaf()
        if leaf is not None and leaf.location:
            header += f"  ·  {os.path.basename(leaf.location)}"
        # A cancel too late to stop anything says so, not "stopping the motion".
        note = runner.late_cancel or self.note or _last_message(runner)
        self.screen.show(layout_frame(header, tree, note, columns - 1, rows))

    def close(self) -> None:
        """Stop drawing; the last frame stays (idempotent)."""
        self.screen.close()


def _finished_leaves(node: NodeView) -> int:
    if node.children:
        return sum(_finished_leaves(c) for c in node.children)
    return int(node.status in (NodeStatus.SUCCESS, NodeStatus.FAILURE))


def _last_message(runner: Runner) -> str | None:
    for event in reversed(runner.events.events()):
        if event.kind == "message":
            return event.message
    return None
