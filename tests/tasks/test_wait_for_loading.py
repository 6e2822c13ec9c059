"""``wait_for`` between a parallel's branches: what the loader accepts and refuses, at the
line of the ``wait_for``."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from taskrunner.errors import TaskSpecError
from taskrunner.tasks import load_task_text
from taskrunner.tasks.waits import wait_pairs

HEADER = "task: t\ncell: c.yaml\nsteps:\n"


def load(tmp_path: Path, steps: str):  # type: ignore[no-untyped-def]
    (tmp_path / "c.yaml").write_text("robots: []\n")
    return load_task_text(HEADER + textwrap.dedent(steps), tmp_path / "t.yaml")


def problems(tmp_path: Path, steps: str) -> list[tuple[int | None, str]]:
    with pytest.raises(TaskSpecError) as caught:
        load(tmp_path, steps)
    return [(p.line, p.message) for p in caught.value.problems]


STACK = """\
  - parallel:
      - sequence:
          - go: {group: left_arm, to: Up, name: base down}
          - go: {group: left_arm, to: Home}
      - sequence:
          - go: {group: right_arm, to: Up}
          - go: {group: right_arm, to: Home, wait_for: {step: base down}}
"""


def test_wait_for_in_another_branch_resolves_to_the_named_step(tmp_path: Path) -> None:
    spec = load(tmp_path, STACK)
    (pair,) = wait_pairs(spec.steps)
    assert pair.name == "base down"
    assert (pair.waiter_branch, pair.named_branch) == (1, 0)
    assert pair.waiter.loc is not None and pair.waiter.loc.line == 10
    assert pair.parallel is spec.steps[0]


def test_wait_for_an_unknown_name_is_refused_with_a_suggestion(tmp_path: Path) -> None:
    found = problems(tmp_path, STACK.replace("{step: base down}", "{step: base dwn}"))
    assert found == [(10, "'wait_for': no step is named 'base dwn'; did you mean 'base down'?")]


def test_wait_for_outside_a_parallel_is_refused(tmp_path: Path) -> None:
    found = problems(tmp_path, """\
      - go: {group: left_arm, to: Up, name: first}
      - go: {group: left_arm, to: Home,
             wait_for: {step: first}}
    """)
    assert len(found) == 1 and found[0][0] == 6
    assert "only a step in a branch of a 'parallel'" in found[0][1]


def test_wait_for_a_step_of_its_own_branch_is_refused(tmp_path: Path) -> None:
    found = problems(tmp_path, STACK.replace("name: base down", "name: up")
                     .replace("go: {group: right_arm, to: Up}",
                              "go: {group: right_arm, to: Up, name: base down}"))
    assert len(found) == 1 and found[0][0] == 10
    assert "not in another branch of a 'parallel'" in found[0][1]


def test_wait_for_an_ambiguous_name_names_both_lines(tmp_path: Path) -> None:
    found = problems(tmp_path, STACK.replace("to: Home}", "to: Home, name: base down}"))
    assert found == [(10, "'wait_for': 2 steps are named 'base down' (line 6, line 7): give "
                          "the one to wait for a name of its own")]


def test_waits_in_a_cycle_are_refused_naming_every_line(tmp_path: Path) -> None:
    # a waits for d; d comes after c, which waits for b, which comes after a.
    found = problems(tmp_path, """\
      - parallel:
          - sequence:
              - go: {group: left_arm, to: Up, name: a, wait_for: {step: d}}
              - go: {group: left_arm, to: Home, name: b}
          - sequence:
              - go: {group: right_arm, to: Up, name: c, wait_for: {step: b}}
              - go: {group: right_arm, to: Home, name: d}
    """)
    assert len(found) == 1
    line, message = found[0]
    assert line in (6, 9)
    assert "wait for each other, so none can start (a cycle)" in message
    assert "line 6 waits for 'd' (line 10)" in message
    assert "line 9 waits for 'b' (line 7)" in message


def test_waits_in_one_direction_across_branches_are_no_cycle(tmp_path: Path) -> None:
    spec = load(tmp_path, """\
      - parallel:
          - sequence:
              - go: {group: left_arm, to: Up, name: a}
              - go: {group: left_arm, to: Home, name: b, wait_for: {step: c}}
          - sequence:
              - go: {group: right_arm, to: Up, name: c, wait_for: {step: a}}
              - go: {group: right_arm, to: Home, name: d}
    """)
    assert [p.name for p in wait_pairs(spec.steps)] == ["c", "a"]


PLACED = """\
  - parallel:
      - sequence:
          - place: {arm: left_arm, object: base, at: {xyz: [0, 0, 0.77]}, name: base down}
          - go: {group: left_arm, to: Home}
      - sequence:
          - go: {group: right_arm, to: Up}
          - go: {group: right_arm, to: Home, wait_for: {step: base down, until: released}}
"""


def test_wait_for_a_moment_within_a_place_resolves_with_its_moment(tmp_path: Path) -> None:
    (pair,) = wait_pairs(load(tmp_path, PLACED).steps)
    assert (pair.name, pair.moment) == ("base down", "released")
    (plain,) = wait_pairs(load(tmp_path, STACK).steps)
    assert plain.moment == "finished"


def test_wait_for_an_unknown_moment_is_refused_at_its_line(tmp_path: Path) -> None:
    found = problems(tmp_path, PLACED.replace("until: released", "until: dropped"))
    assert len(found) == 1 and found[0][0] == 10
    assert found[0][1] == ("'go.wait_for.until' must be 'finished', 'set_down', 'released' or "
                           "'grasped' (got 'dropped')")


def test_wait_for_a_moment_the_named_step_has_not_is_refused_at_its_line(tmp_path: Path) -> None:
    found = problems(tmp_path, STACK.replace("{step: base down}",
                                             "{step: base down, until: released}"))
    assert found == [(10, "'wait_for': step 'base down' (line 6) is a 'go', which has no "
                          "moment 'released' (it has: 'finished')")]
