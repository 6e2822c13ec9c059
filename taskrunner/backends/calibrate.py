"""Calibrating the servo arm on the bench: find each joint's ``zero_rad`` and ``direction``.

For each joint with a servo of its own, the servo is driven to its 90° centre and the
builder says which angle the joint shows there, in the robot model's convention: that is
``zero_rad``. The servo then turns 20° further and the builder says whether the joint
turned toward positive or negative angles: that is ``direction``. The answers are written
into ``hardware.yaml`` in place: only those two values change, comments and layout stay.
"""

from __future__ import annotations

import math
import re
import shutil
from collections.abc import Callable, Sequence
from pathlib import Path

from taskrunner.backends.servo_backend import ServoBackend
from taskrunner.errors import InputError, YamlError
from taskrunner.yamlfile import LineDict, LineList, load_yaml

__all__ = ["calibrate_servos", "update_hardware_yaml"]

CENTRE_DEG = 90.0
PROBE_DEG = 20.0


def update_hardware_yaml(path: str | Path, updates: dict[str, dict[str, float]]) -> str:
    """Rewrite ``zero_rad`` / ``direction`` of the named joints in ``path``; returns the new
    text (also written). Every other line stays as it was.

    Raises:
        YamlError: the file has no such joint, or the joint entry lacks the key.
    """
    path = Path(path)
    node = load_yaml(path)
    joints = node.get("joints") if isinstance(node, LineDict) else None
    if not isinstance(joints, LineList):
        raise YamlError("'joints' must be a list", path, getattr(node, "line", None))
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    found = set()
    for entry in joints:
        if not isinstance(entry, LineDict) or entry.get("name") not in updates:
            continue
        name = entry["name"]
        found.add(name)
        for key, value in updates[name].items():
            line = entry.key_lines.get(key)
            if line is None:
                raise YamlError(f"joint {name!r} has no {key!r} to update", path, entry.line)
            pattern = re.compile(rf"^(\s*(?:-\s*)?{re.escape(key)}\s*:\s*)(\S+?)(\s*(#.*)?)$")
            text = lines[line - 1].rstrip("\n")
            match = pattern.match(text)
            if match is None:
                raise YamlError(f"cannot rewrite {key!r} of joint {name!r} in place", path, line)
            shown = f"{value:.6f}" if key == "zero_rad" else f"{int(value)}"
            lines[line - 1] = f"{match.group(1)}{shown}{match.group(3)}\n"
    missing = sorted(set(updates) - found)
    if missing:
        raise YamlError(f"no joint entries for {missing}", path, joints.line)
    text = "".join(lines)
    shutil.copyfile(path, path.with_suffix(path.suffix + ".bak"))
    path.write_text(text, encoding="utf-8")
    return text


def _yes(answer: str) -> bool | None:
    answer = answer.strip().lower()
    if answer in ("y", "yes", "+", "positive", "p"):
        return True
    if answer in ("n", "no", "-", "negative"):
        return False
    return None


def calibrate_servos(backend: ServoBackend, hardware_path: str | Path,
                     joints: Sequence[str] | None = None,
                     ask: Callable[[str], str] = input, say: Callable[[str], None] = print
                     ) -> dict[str, dict[str, float]]:
    """Walk the joints (default: every joint with its own servo), ask, and write the file.

    Raises:
        InputError: an answer that is not a number / yes-no after three tries, or a joint
            without a servo of its own.
    """
    calibration = backend.calibration
    names = list(joints or calibration.servo_joint_names)
    for name in names:
        if name not in calibration.servo_joint_names:
            raise InputError(f"joint {name!r} has no servo of its own "
                             f"(servos: {', '.join(calibration.servo_joint_names)})")
    degrees = list(backend.firmware_status().get("pos", [CENTRE_DEG] * len(calibration.channels)))
    updates: dict[str, dict[str, float]] = {}

    def move(servo: int, angle: float) -> None:
        degrees[servo] = angle
        backend.command("MOVE:" + ",".join(f"{d:.2f}" for d in degrees))

    def ask_until(question: str, parse: Callable[[str], object]) -> object:
        for _ in range(3):
            value = parse(ask(question))
            if value is not None:
                return value
            say("  (not understood)")
        raise InputError(f"no usable answer to: {question.strip()}")

    def number(text: str) -> float | None:
        try:
            value = float(text)
        except ValueError:
            return None
        return value if math.isfinite(value) else None

    for name in names:
        servo = calibration.servo_of(name)
        say(f"{name}: servo {servo} to {CENTRE_DEG:.0f}°")
        move(servo, CENTRE_DEG)
        shown = ask_until(f"  angle of {name} now, in degrees (robot model convention): ", number)
        move(servo, CENTRE_DEG + PROBE_DEG)
        positive = ask_until(f"  servo +{PROBE_DEG:.0f}°: did {name} turn toward positive "
                             "angles? [y/n] ", _yes)
        move(servo, CENTRE_DEG)
        updates[name] = {"zero_rad": math.radians(float(shown)),  # type: ignore[arg-type]
                         "direction": 1.0 if positive else -1.0}
        say(f"  zero_rad {updates[name]['zero_rad']:+.4f}, direction "
            f"{int(updates[name]['direction']):+d}")
    update_hardware_yaml(hardware_path, updates)
    say(f"wrote {hardware_path} (previous version kept as {Path(hardware_path).name}.bak)")
    return updates
