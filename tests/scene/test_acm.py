"""The self-collision matrix generator, its SRDF output and its command line."""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.errors import InputError
from taskrunner.robot import RobotModel
from taskrunner.robot.srdf import parse_srdf, read_srdf
from taskrunner.scene.acm import (
    DisabledPair,
    MatrixOptions,
    format_disable_collisions,
    generate_collision_matrix,
    main,
    merge_disable_collisions,
)

SAMPLES = 300


@pytest.fixture(scope="module")
def panda_matrix(panda_model: RobotModel) -> list[DisabledPair]:
    return generate_collision_matrix(panda_model, samples=SAMPLES, seed=1)


def by_pair(entries: list[DisabledPair]) -> dict[frozenset[str], str]:
    return {e.pair: e.reason for e in entries}


def test_links_joined_by_a_joint_are_adjacent(
    panda_model: RobotModel, panda_matrix: list[DisabledPair]
) -> None:
    reasons = by_pair(panda_matrix)
    for pair in [("panda_link0", "panda_link1"), ("panda_link6", "panda_link7"),
                 ("panda_hand", "panda_leftfinger")]:
        assert reasons[frozenset(pair)] == "Adjacent"
    # panda_link8 has no geometry: link7 and the hand count as adjacent through it.
    assert reasons[frozenset(("panda_link7", "panda_hand"))] == "Adjacent"
    adjacent = {p for p, r in panda_model.disabled_collisions.items() if r == "Adjacent"}
    assert {p for p, r in reasons.items() if r == "Adjacent"} == adjacent


def test_pairs_touching_at_the_default_state_are_default(panda_matrix: list[DisabledPair]) -> None:
    reasons = by_pair(panda_matrix)
    assert reasons[frozenset(("panda_leftfinger", "panda_rightfinger"))] == "Default"
    assert reasons[frozenset(("panda_link5", "panda_link7"))] == "Default"


def test_distant_links_are_never_in_collision(panda_matrix: list[DisabledPair]) -> None:
    reasons = by_pair(panda_matrix)
    assert reasons[frozenset(("panda_link0", "panda_link2"))] == "Never"
    assert sum(r == "Never" for r in reasons.values()) >= 15
    # Pairs that do collide in some states must stay checked.
    assert frozenset(("panda_link1", "panda_hand")) not in reasons
    assert frozenset(("panda_link0", "panda_link6")) not in reasons


def test_shipped_panda_srdf_entries_are_all_found(
    panda_model: RobotModel, panda_matrix: list[DisabledPair]
) -> None:
    # Fewer samples can only add "Never" pairs to the Setup Assistant's 10000-sample result.
    reasons = by_pair(panda_matrix)
    for pair, reason in panda_model.disabled_collisions.items():
        assert reasons.get(pair) == reason, sorted(pair)


def test_entries_are_sorted_and_reproducible(
    panda_model: RobotModel, panda_matrix: list[DisabledPair]
) -> None:
    names = [(e.link1, e.link2) for e in panda_matrix]
    assert names == sorted(names)
    assert all(e.link1 < e.link2 for e in panda_matrix)
    assert generate_collision_matrix(panda_model, samples=SAMPLES, seed=1) == panda_matrix


def test_always_colliding_pairs_are_always(panda_model: RobotModel) -> None:
    # With a 1 % threshold, any pair seen in 1 of 100 states counts as "Always".
    entries = generate_collision_matrix(
        panda_model, samples=50, seed=0, options=MatrixOptions(always_fraction=0.01)
    )
    assert any(e.reason == "Always" for e in entries)


def test_invalid_options_are_refused() -> None:
    with pytest.raises(ValueError, match="'always_fraction' must be in"):
        MatrixOptions(always_fraction=0.0)
    with pytest.raises(ValueError, match="'always_batch' must be >= 1"):
        MatrixOptions(always_batch=0)


# ------------------------------------------------------------------ SRDF text
SRDF = """<?xml version="1.0"?>
<!-- a hand-written comment -->
<robot name="bot">
  <group name="arm"><chain base_link="a" tip_link="c"/></group>
  <disable_collisions link1="a" link2="b" reason="Adjacent"/>
  <disable_collisions link1="x" link2="y" reason="User"></disable_collisions>
  <passive_joint name="j"/>
</robot>
"""


def test_merge_replaces_old_entries_and_keeps_the_rest_of_the_text() -> None:
    entries = [DisabledPair("c", "a", "Never"), DisabledPair("a", "b", "Adjacent")]
    text = merge_disable_collisions(SRDF, entries)
    assert "<!-- a hand-written comment -->" in text
    assert '<group name="arm"><chain base_link="a" tip_link="c"/></group>' in text
    assert 'link1="x"' not in text
    assert text.count("<disable_collisions") == 2
    assert '  <disable_collisions link1="a" link2="c" reason="Never"/>\n' in text
    parsed = parse_srdf(text)
    assert [(d.link1, d.link2, d.reason) for d in parsed.disabled_collisions] == [
        ("a", "b", "Adjacent"), ("a", "c", "Never")]
    assert parsed.passive_joints == ["j"]


def test_merge_can_keep_hand_written_entries() -> None:
    entries = [DisabledPair("a", "b", "Never")]
    text = merge_disable_collisions(SRDF, entries, keep_existing=True)
    parsed = parse_srdf(text)
    assert {(d.link1, d.link2, d.reason) for d in parsed.disabled_collisions} == {
        ("a", "b", "Never"), ("x", "y", "User")}


def test_merge_into_an_srdf_without_entries_goes_before_the_end() -> None:
    entries = [DisabledPair("a", "b", "Never")]
    text = merge_disable_collisions('<robot name="bot">\n</robot>\n', entries)
    line = '    <disable_collisions link1="a" link2="b" reason="Never"/>\n'
    assert text == f'<robot name="bot">\n{line}</robot>\n'


def test_merge_refuses_text_that_is_not_an_srdf() -> None:
    with pytest.raises(InputError, match="does not parse"):
        merge_disable_collisions("<robot", [])
    with pytest.raises(InputError, match="must be <robot>"):
        merge_disable_collisions("<launch/>", [])


def test_format_escapes_names() -> None:
    line = format_disable_collisions([DisabledPair("a&b", "c", "Never")], indent="")
    assert line == '<disable_collisions link1="a&amp;b" link2="c" reason="Never"/>\n'


# ------------------------------------------------------------------ command line
def test_cli_prints_entries_and_writes_a_new_srdf(
    robots_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "panda.srdf"
    args = [str(robots_dir / "panda"), "--samples", "50", "--seed", "2", "--write", str(target)]
    code = main(args)
    out, err = capsys.readouterr()
    assert code == 0
    assert '<disable_collisions link1="panda_hand" link2="panda_leftfinger" reason="Adjacent"/>' in out
    assert "Adjacent" in err and f"wrote {target}" in err
    written = read_srdf(target)
    assert written.robot_name == "panda"
    assert len(written.disabled_collisions) == out.count("<disable_collisions")


def test_cli_reports_errors_without_a_traceback(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main([str(tmp_path / "nothing")]) == 2  # invalid input, like other commands
    assert "error:" in capsys.readouterr().err


def test_cli_accepts_a_shipped_robot_name_and_package_paths(
    capsys: pytest.CaptureFixture[str]
) -> None:
    moveit = Path(__file__).resolve().parents[1] / "robot" / "fixtures" / "moveit"
    assert main(["servo_arm", "--samples", "20"]) == 0
    assert "pairs disabled" in capsys.readouterr().err
    assert main([str(moveit / "src" / "arm3_moveit_config"), "--samples", "20",
                 "--package-path", str(moveit / "src")]) == 0
    out = capsys.readouterr().out
    assert 'link1="a3_finger1" link2="a3_hand" reason="Adjacent"' in out
    assert main(["servo_arm", "--package-path", "/nonexistent/folder"]) == 2
