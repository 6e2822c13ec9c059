"""The live tree's layout: given a tree's state and a terminal size, which lines come out;
and the screen that draws frames in place."""

from __future__ import annotations

import io

import pytest

from taskrunner.runtime.display import (
    LiveTree,
    MotionProgress,
    NodeView,
    TerminalScreen,
    layout_frame,
    layout_tree,
    progress_bar,
)


def leaf(name: str, status: str = "INVALID", **kw) -> NodeView:  # type: ignore[no-untyped-def]
    return NodeView(name, status, **kw)


def seq(name: str, status: str, *children: NodeView) -> NodeView:
    return NodeView(name, status, tuple(children))


def pick_place(pick: str, motion: MotionProgress | None = None) -> NodeView:
    """pick_place as compiled: go, pick (8 steps), place (7 steps), go; the pick's
    ``pick`` step (by name) running, those before it done."""
    pick_steps = ["open", "to pre-grasp", "allow finger contact", "approach", "close",
                  "attach", "retreat", "lifted"]
    index = pick_steps.index(pick)
    steps = []
    for i, name in enumerate(pick_steps):
        status = "SUCCESS" if i < index else "RUNNING" if i == index else "INVALID"
        steps.append(leaf(f"pick cube: {name}", status,
                          motion=motion if status == "RUNNING" else None))
    place = [leaf(f"place cube: {n}") for n in
             ("to pre-place", "descend", "open", "detach", "retreat", "released", "check")]
    return seq("pick_place", "RUNNING", leaf("go arm", "SUCCESS"),
               seq("pick cube", "RUNNING", *steps), seq("place cube", "INVALID", *place),
               leaf("go arm"))


def test_tree_that_fits_shows_running_branch_and_collapses_the_rest():
    lines = layout_tree(pick_place("approach"), 80, 20)
    assert lines == [
        "▼ pick_place",
        "  ✔ go arm",
        "  ▼ pick cube",
        "    ✔ pick cube: open",
        "    ✔ pick cube: to pre-grasp",
        "    ✔ pick cube: allow finger contact",
        "    ▶ pick cube: approach",
        "    · pick cube: close",
        "    · pick cube: attach",
        "    · pick cube: retreat",
        "    · pick cube: lifted",
        "  · place cube  (7 steps)",
        "  · go arm",
    ]


def test_finished_subtree_collapses_to_one_line():
    tree = seq("t", "RUNNING", seq("pick cube", "SUCCESS", leaf("a", "SUCCESS"),
                                   leaf("b", "SUCCESS")), leaf("go", "RUNNING", seconds=0.42))
    assert layout_tree(tree, 80, 10) == ["▼ t", "  ✔ pick cube  (2 steps)", "  ▶ go  0.4 s"]


def test_running_motion_shows_progress_and_time_left():
    lines = layout_tree(pick_place("to pre-grasp", MotionProgress(12.3, 30.1)), 80, 20)
    running = [line for line in lines if "▶" in line]
    assert running == ["    ▶ pick cube: to pre-grasp  ▕████▏     ▏ 12.3 s of 30.1 s · 17.8 s left"]


def test_progress_bar_fills_in_eighths_of_a_cell():
    assert progress_bar(0.0) == "▕          ▏"
    assert progress_bar(0.425) == "▕████▎     ▏"
    assert progress_bar(1.0) == "▕██████████▏"
    assert progress_bar(1.7) == "▕██████████▏"  # clamped


def test_short_terminal_elides_far_rows_and_keeps_the_running_step():
    lines = layout_tree(pick_place("retreat", MotionProgress(1.0, 2.0)), 80, 8)
    assert len(lines) == 8
    assert lines[0] == "▼ pick_place"
    assert "  ▼ pick cube" in lines
    assert any(line.startswith("    ▶ pick cube: retreat  ▕") for line in lines)
    elided = [line for line in lines if "more" in line]
    assert elided and all(line.strip().startswith("… ") for line in elided)
    # Every row is shown or counted in an elision line.
    shown = len(lines) - len(elided)
    hidden = sum(int(line.split()[1]) for line in elided)
    assert shown + hidden == len(layout_tree(pick_place("retreat"), 80, 100))


def test_rows_next_to_the_running_step_are_kept_before_far_ones():
    lines = layout_tree(pick_place("attach"), 80, 9)
    at = next(i for i, line in enumerate(lines) if "▶" in line)
    assert "close" in lines[at - 1] and "retreat" in lines[at + 1]


@pytest.mark.parametrize("height", [1, 2, 3, 4, 5, 7, 12, 40])
@pytest.mark.parametrize("width", [1, 8, 20, 40, 80])
def test_layout_never_exceeds_the_size(width, height):
    lines = layout_tree(pick_place("close", MotionProgress(3.0, 7.5)), width, height)
    assert 0 < len(lines) <= height
    assert all(len(line) <= width for line in lines)


def test_narrow_terminal_cuts_the_name_before_the_progress():
    lines = layout_tree(pick_place("approach", MotionProgress(1.0, 4.0)), 50, 20)
    running = next(line for line in lines if "▶" in line)
    assert len(running) <= 50
    assert running.endswith("1.0 s of 4.0 s") and "…" in running


def test_failed_step_stays_visible_after_the_run():
    tree = seq("t", "FAILURE", seq("pick", "FAILURE", *(leaf(f"s{i}", "SUCCESS") for i in range(20)),
                                   leaf("approach", "FAILURE")), leaf("go"))
    lines = layout_tree(tree, 80, 6)
    assert lines[0] == "✘ t" and "  ✘ pick" in lines and "    ✘ approach" in lines
    assert len(lines) <= 6


def test_frame_has_header_tree_and_note_within_the_size():
    lines = layout_frame("pick_place  ·  3.2 s", pick_place("open"), "cancelled (Ctrl-C)", 40, 6)
    assert lines[0] == "pick_place  ·  3.2 s"
    assert lines[-1] == "cancelled (Ctrl-C)"
    assert len(lines) <= 6 and all(len(line) <= 40 for line in lines)


class FakeTerminal(io.StringIO):
    def __init__(self, size: tuple[int, int]) -> None:
        super().__init__()
        self.size = size


class SizedScreen(TerminalScreen):
    def __init__(self, out: FakeTerminal) -> None:
        super().__init__(out)
        self.terminal = out

    def size(self) -> tuple[int, int]:
        return self.terminal.size


def test_screen_redraws_in_place_and_erases_what_the_last_frame_left():
    out = FakeTerminal((80, 20))
    screen = SizedScreen(out)
    screen.show(["a", "b", "c"])
    first = out.getvalue()
    assert first == "\x1b[?25la\x1b[K\nb\x1b[K\nc\x1b[K\x1b[J"
    screen.show(["x"])
    assert out.getvalue()[len(first):] == "\r\x1b[2Ax\x1b[K\x1b[J"
    screen.close()
    screen.close()
    assert out.getvalue().endswith("x\x1b[K\x1b[J\n\x1b[?25h")


def test_screen_cuts_lines_short_of_the_width_and_to_the_height():
    out = FakeTerminal((10, 2))
    screen = SizedScreen(out)
    screen.show(["0123456789abc", "b", "c"])
    assert out.getvalue() == "\x1b[?25l01234567…\x1b[K\nb\x1b[K\x1b[J"


def test_screen_starts_from_the_top_after_a_resize():
    out = FakeTerminal((80, 20))
    screen = SizedScreen(out)
    screen.show(["a", "b"])
    mark = len(out.getvalue())
    out.size = (40, 10)
    screen.show(["c"])
    assert out.getvalue()[mark:] == "\x1b[Hc\x1b[K\x1b[J"


def test_live_tree_close_without_a_frame_writes_nothing():
    out = io.StringIO()
    LiveTree(out).close()
    assert out.getvalue() == ""
