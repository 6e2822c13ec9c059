"""Generating a robot's self-collision matrix, as MoveIt's Setup Assistant does.

Link pairs (links with collision geometry only) are classified in four passes, each
looking only at the pairs the earlier ones left:

1. **Adjacent**: a link and its nearest ancestor with geometry (through links without
   geometry), from the kinematic tree.
2. **Default**: in collision at the default state (every joint at 0, clipped to its limits).
3. **Always**: in collision in at least ``always_fraction`` of a batch of random states;
   repeated with fresh batches until a batch finds none.
4. **Never**: not in collision in any random state sampled (the batches above included).

Every pair found is a candidate ``<disable_collisions link1= link2= reason=>`` SRDF entry.
Sampling is seeded, so a run is reproducible. Run it as a tool::

    python -m taskrunner.scene.acm robots/panda --samples 10000 --seed 0 [--write panda.srdf]
"""

from __future__ import annotations

import argparse
import re
import sys
import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np
import pinocchio as pin

from taskrunner.errors import ArgumentError, InputError, TaskrunnerError
from taskrunner.kinds import CollisionChoice
from taskrunner.resources import resolve_cell
from taskrunner.robot import PackageMap, Placement, RobotModel, build_model, load_description
from taskrunner.scene.geometry import LinkGeometry, robot_link_geometry
from taskrunner.scene.linkgeometry import COLLISION_CHOICES, check_collision_choice

__all__ = [
    "DisabledPair",
    "MatrixOptions",
    "format_disable_collisions",
    "generate_collision_matrix",
    "main",
    "merge_disable_collisions",
]

REASONS = ("Adjacent", "Default", "Always", "Never")


@dataclass(frozen=True)
class DisabledPair:
    """One ``disable_collisions`` entry; ``link1 < link2``."""

    link1: str
    link2: str
    reason: str

    def __post_init__(self) -> None:
        if self.link1 > self.link2:
            first, second = self.link2, self.link1
            object.__setattr__(self, "link1", first)
            object.__setattr__(self, "link2", second)

    @property
    def pair(self) -> frozenset[str]:
        return frozenset((self.link1, self.link2))


@dataclass(frozen=True)
class MatrixOptions:
    """Settings of :func:`generate_collision_matrix` besides the sample count and seed.

    Attributes:
        always_fraction: a pair colliding in at least this fraction of a batch is "Always".
        always_batch: states per batch of the "Always" pass (MoveIt uses 100).
        collision: the link geometry to check: ``exact``, ``convex`` or ``auto``; None:
            the robot's own choice, as :class:`~taskrunner.scene.Scene` checks it, so that
            the matrix matches what the scene checks.
        convex_meshes: the older spelling: True is ``convex``, False ``exact``.
    """

    always_fraction: float = 0.95
    always_batch: int = 100
    collision: str | None = None
    convex_meshes: bool | None = None

    @property
    def robot_collision(self) -> str | None:
        if self.collision is not None:
            return self.collision
        if self.convex_meshes is not None:
            return CollisionChoice.CONVEX if self.convex_meshes else CollisionChoice.EXACT
        return None

    def __post_init__(self) -> None:
        if self.collision is not None:
            check_collision_choice(self.collision)
        if not 0.0 < self.always_fraction <= 1.0:
            raise ArgumentError(f"'always_fraction' must be in (0, 1] (got {self.always_fraction})")
        if self.always_batch < 1:
            raise ArgumentError(f"'always_batch' must be >= 1 (got {self.always_batch})")


def generate_collision_matrix(
    robot: RobotModel,
    samples: int = 10000,
    seed: int = 0,
    options: MatrixOptions | None = None,
) -> list[DisabledPair]:
    """Classify the robot's link pairs that need no collision check (see the module docstring).

    The robot's own SRDF entries are ignored: the matrix is computed from its geometry.

    Args:
        robot: the model (every robot in it, with their prefixed link names).
        samples: random states of the "Never" pass (MoveIt's default is 10000; fewer
            makes more pairs look "Never" that do collide in rare states).
        seed: seed of the random states.
        options: the other settings.

    Returns:
        The entries sorted by (link1, link2); pairs not listed must be checked.
    """
    options = options or MatrixOptions()
    if samples < 1:
        raise ArgumentError(f"'samples' must be >= 1 (got {samples})")
    links = robot_link_geometry(robot, options.robot_collision)
    reasons: dict[frozenset[str], str] = {
        pair: "Adjacent" for pair in adjacent_link_pairs(robot, {g.link for g in links})
    }
    sampler = _PairSampler(robot, links, reasons)
    for pair in sampler.colliding(robot.default_state()):
        reasons[pair] = "Default"
    sampler.drop(reasons)

    rng = np.random.default_rng(seed)
    seen: set[frozenset[str]] = set()
    threshold = options.always_fraction * options.always_batch
    while sampler.active:
        counts: Counter[frozenset[str]] = Counter()
        for _ in range(options.always_batch):
            counts.update(sampler.colliding(robot.random_state(rng)))
        seen.update(counts)
        always = {pair for pair, n in counts.items() if n >= threshold}
        if not always:
            break
        reasons.update(dict.fromkeys(always, "Always"))
        sampler.drop(always)

    sampler.drop(seen)
    for _ in range(samples):
        if not sampler.active:
            break
        sampler.drop(sampler.colliding(robot.random_state(rng)))
    reasons.update(dict.fromkeys(sampler.active, "Never"))
    entries = [DisabledPair(min(pair), max(pair), reason) for pair, reason in reasons.items()]
    return sorted(entries, key=lambda e: (e.link1, e.link2))


def adjacent_link_pairs(robot: RobotModel, with_geometry: Collection[str]) -> set[frozenset[str]]:
    """Each link of ``with_geometry`` with its nearest ancestor link in ``with_geometry``."""
    frames = robot.model.frames
    pairs = set()
    for link in with_geometry:
        frame = robot.frame_id(link)
        while frame != 0:
            frame = frames[frame].parentFrame
            if frames[frame].type == pin.BODY and frames[frame].name in with_geometry:
                pairs.add(frozenset((link, frames[frame].name)))
                break
    return pairs


class _PairSampler:
    """Which link pairs collide in a state, over the pairs still undecided."""

    def __init__(
        self, robot: RobotModel, links: Sequence[LinkGeometry], exclude: Collection[frozenset[str]]
    ) -> None:
        self._robot = robot
        self._geometry = pin.GeometryModel()
        for link in links:
            self._geometry.addGeometryObject(link.geometry)
        self._link_pairs: list[frozenset[str]] = []
        for i in range(len(links)):
            for j in range(i + 1, len(links)):
                pair = frozenset((links[i].link, links[j].link))
                if len(pair) == 2 and pair not in exclude:
                    self._geometry.addCollisionPair(pin.CollisionPair(i, j))
                    self._link_pairs.append(pair)
        self._data = robot.model.createData()
        self._geometry_data = self._geometry.createData()
        self._active = list(range(len(self._link_pairs)))

    @property
    def active(self) -> set[frozenset[str]]:
        """The link pairs still checked."""
        return {self._link_pairs[k] for k in self._active}

    def colliding(self, q: np.ndarray) -> set[frozenset[str]]:
        """The active link pairs in collision at state vector ``q``."""
        if not self._active or not pin.computeCollisions(
            self._robot.model, self._data, self._geometry, self._geometry_data,
            self._robot.to_pin(q), False,
        ):
            return set()
        results = self._geometry_data.collisionResults
        return {self._link_pairs[k] for k in self._active if results[k].isCollision()}

    def drop(self, pairs: Collection[frozenset[str]]) -> None:
        """Stop checking ``pairs``."""
        keep = []
        for k in self._active:
            if self._link_pairs[k] in pairs:
                self._geometry_data.deactivateCollisionPair(k)
            else:
                keep.append(k)
        self._active = keep


# --------------------------------------------------------------------------- SRDF text
_ENTRY = re.compile(
    r"^[ \t]*<disable_collisions\b[^>]*?(?:/>|>\s*</disable_collisions\s*>)[ \t]*\r?\n?",
    re.MULTILINE,
)


def format_disable_collisions(entries: Iterable[DisabledPair], indent: str = "    ") -> str:
    """SRDF lines ``<disable_collisions link1=… link2=… reason=…/>``, one per entry."""
    return "".join(
        f"{indent}<disable_collisions link1={quoteattr(e.link1)} link2={quoteattr(e.link2)} "
        f"reason={quoteattr(e.reason)}/>\n"
        for e in entries
    )


def merge_disable_collisions(
    srdf_text: str, entries: Sequence[DisabledPair], keep_existing: bool = False
) -> str:
    """Write ``entries`` into an SRDF document's text, leaving the rest of it as it was.

    Args:
        srdf_text: the SRDF file's content.
        entries: the new ``disable_collisions`` entries.
        keep_existing: keep the file's entries for pairs that ``entries`` does not name
            (hand-written ones); by default every old entry is replaced.

    Returns:
        The new text: the entries take the place of the first old one, or go before
        ``</robot>`` when there was none.

    Raises:
        InputError: the text is not an SRDF document (no ``<robot>`` root).
    """
    try:
        root = ET.fromstring(srdf_text)
    except ET.ParseError as exc:
        raise InputError(f"SRDF text does not parse: {exc}") from None
    if root.tag != "robot":
        raise InputError(f"SRDF root element must be <robot> (got <{root.tag}>)")
    new_pairs = {e.pair for e in entries}
    kept: list[DisabledPair] = []
    first = _ENTRY.search(srdf_text)
    indent = re.match(r"[ \t]*", first.group(0)).group(0) if first else "    "  # type: ignore[union-attr]
    for match in _ENTRY.finditer(srdf_text):
        element = ET.fromstring(match.group(0).strip())
        old = DisabledPair(element.get("link1", ""), element.get("link2", ""),
                           element.get("reason", ""))
        if keep_existing and old.pair not in new_pairs:
            kept.append(old)
    block = format_disable_collisions(
        sorted([*kept, *entries], key=lambda e: (e.link1, e.link2)), indent
    )
    if first is not None:
        start = first.start()
        stripped = _ENTRY.sub("", srdf_text[start:])
        return srdf_text[:start] + block + stripped
    close = srdf_text.rfind("</robot>")
    line_start = srdf_text.rfind("\n", 0, close) + 1
    if srdf_text[line_start:close].strip():
        line_start = close
    return srdf_text[:line_start] + block + srdf_text[line_start:]


# --------------------------------------------------------------------------- CLI
def main(argv: Sequence[str] | None = None) -> int:
    """``python -m taskrunner.scene.acm ROBOT [--samples N] [--seed S] [--write SRDF]``."""
    parser = argparse.ArgumentParser(
        prog="run-task collision-matrix",
        description="Generate a robot's self-collision matrix (SRDF disable_collisions).",
    )
    parser.add_argument("robot", help="robot.yaml, MoveIt config folder, URDF or xacro, or a "
                                      "shipped robot's name (servo_arm, panda, ur5)")
    parser.add_argument("--samples", type=int, default=10000, help="random states (10000)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (0)")
    parser.add_argument("--write", metavar="SRDF", type=Path,
                        help="write the entries into this SRDF file (created if missing)")
    parser.add_argument("--keep-existing", action="store_true",
                        help="with --write: keep old entries for pairs not generated")
    parser.add_argument("--collision", choices=COLLISION_CHOICES, default=None,
                        help="link geometry: exact meshes, convex hulls, or auto (hulls where "
                             "tight); default: the robot's own choice, as planning checks it")
    parser.add_argument("--meshes", action="store_true", help="the same as --collision exact")
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        type=Path, help="also look for ROS packages under DIR (repeatable)")
    args = parser.parse_args(argv)
    try:
        packages = PackageMap()
        for folder in args.package_path:
            if not folder.is_dir():
                raise InputError(f"'--package-path' must be a folder (got {folder})")
            packages.discover(folder)
        robot_path = resolve_cell(args.robot)
        packages.discover_around(robot_path)
        # The matrix is what fixes a pose in self-collision: no such warning here.
        robot = build_model([Placement(load_description(robot_path, packages))],
                            check_self_collision=False)
        entries = generate_collision_matrix(
            robot, args.samples, args.seed,
            MatrixOptions(collision=CollisionChoice.EXACT if args.meshes else args.collision))
        sys.stdout.write(format_disable_collisions(entries, indent=""))
        counts = Counter(e.reason for e in entries)
        summary = ", ".join(f"{counts[r]} {r}" for r in REASONS)
        sys.stderr.write(f"{len(entries)} pairs disabled: {summary}\n")
        if args.write is not None:
            path: Path = args.write
            text = (path.read_text(encoding="utf-8") if path.exists()
                    else f'<?xml version="1.0"?>\n<robot name={quoteattr(robot.name)}>\n</robot>\n')
            path.write_text(merge_disable_collisions(text, entries, args.keep_existing),
                            encoding="utf-8")
            sys.stderr.write(f"wrote {path}\n")
    except (TaskrunnerError, ValueError, OSError) as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 2  # invalid input, as for every run-task command
    return 0


if __name__ == "__main__":
    sys.exit(main())
