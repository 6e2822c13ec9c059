"""Hostile task, cell and robot files through ``run-task check`` / ``run-task info``.

Each case runs ``taskrunner.cli.main`` in a forked child of the test process (the
libraries are imported once, so a case costs milliseconds, not an interpreter start),
with an address-space limit (``RLIMIT_AS``) as a safety net and a 5 s limit on the CPU time
it uses (its own and its children's: what the case costs, whatever else the machine runs),
with a wall-clock limit of a minute that only ends a case waiting on something (a FIFO).
Every case must end in time, under 500 MB of resident memory, without a traceback, and, when
the file is refused, with exit code 2 and a message naming the file.

The cases are the classes found by fuzzing (issue 16) written out, plus mutations of the
shipped files drawn by hypothesis (derandomized: the same examples every run).
"""

from __future__ import annotations

import os
import resource
import shutil
import signal
import sys
import tempfile
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from taskrunner import cli
from taskrunner.resources import DATA_ROOT

TIME_LIMIT_S = 5.0  # CPU time of a case (s)
WAIT_LIMIT_S = 60.0  # wall-clock time of a case (s): bounds a hang, not the work
MEMORY_LIMIT_MB = 500.0
# A fresh `run-task check pick_place` process peaks at ~200 MB (measured: 197 MB; `info`
# 105 MB). A forked child starts with the test process's pages (which grow over a whole
# suite run), so a case is charged its growth over what it inherited, plus this much for
# the libraries a fresh process would load.
FRESH_PROCESS_MB = 200.0
EXIT_INVALID = 2


@dataclass(frozen=True)
class Outcome:
    code: int | None
    output: str
    seconds: float  # wall-clock
    cpu_seconds: float
    max_rss_mb: float

    def describe(self) -> str:
        return (f"exit {self.code} after {self.seconds:.2f} s ({self.cpu_seconds:.2f} s of "
                f"CPU), {self.max_rss_mb:.0f} MB:\n{self.output[-3000:]}")


_CLOCK_TICKS = os.sysconf("SC_CLK_TCK")


def _cpu_seconds(pid: int) -> float:
    """CPU time (s) of process ``pid`` and of the children it has waited for, from /proc."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as stat:
            fields = stat.read().rsplit(b")", 1)[1].split()
    except OSError:
        return 0.0
    # After the command's closing parenthesis: utime, stime, cutime, cstime are 11-14.
    return sum(int(f) for f in fields[11:15]) / _CLOCK_TICKS


def _vm_size_bytes() -> int:
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    return 0


def run_cli(argv: list[str], cwd: Path) -> Outcome:
    """``run-task argv`` in a forked child, bounded in time and address space."""
    out = tempfile.TemporaryFile()
    # What the process has mapped already, plus the budget: a runaway case fails its
    # allocation instead of taking the machine down.
    address_space = _vm_size_bytes() + int(MEMORY_LIMIT_MB * 2**20)
    inherited_mb = _rss_mb()
    start = time.perf_counter()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # the child: never returns into pytest
        code = 99
        try:
            os.dup2(out.fileno(), 1)
            os.dup2(out.fileno(), 2)
            sys.stdout = os.fdopen(1, "w", closefd=False)
            sys.stderr = os.fdopen(2, "w", closefd=False)
            os.chdir(cwd)
            resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
            code = cli.main(argv)
        except BaseException:
            traceback.print_exc()
        finally:
            try:
                sys.stdout.flush()
                sys.stderr.flush()
            finally:
                os._exit(code if isinstance(code, int) else 98)
    code: int | None = None
    usage = None
    while True:
        done, status, usage = os.wait4(pid, os.WNOHANG)
        if done:
            code = os.waitstatus_to_exitcode(status)
            break
        if (_cpu_seconds(pid) > TIME_LIMIT_S
                or time.perf_counter() - start > WAIT_LIMIT_S):
            os.kill(pid, signal.SIGKILL)
            _, status, usage = os.wait4(pid, 0)
            break
        time.sleep(0.005)
    seconds = time.perf_counter() - start
    cpu_seconds = usage.ru_utime + usage.ru_stime if usage else 0.0
    out.seek(0)
    output = out.read().decode("utf-8", "replace")
    out.close()
    own_mb = max(0.0, usage.ru_maxrss / 1024 - inherited_mb) if usage else 0.0
    return Outcome(code, output, seconds, cpu_seconds, FRESH_PROCESS_MB + own_mb)


def _rss_mb() -> float:
    """This process's resident memory now (MB), from /proc."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return 0.0


def assert_clean(outcome: Outcome, *names: object, refused: bool = True) -> None:
    """The case ended in time, within memory, without a traceback; if ``refused`` (or
    whenever it exited 2) with exit 2 and a message naming one of ``names``."""
    assert outcome.code is not None, (
        f"killed after {TIME_LIMIT_S} s of CPU or {WAIT_LIMIT_S} s: {outcome.describe()}")
    assert outcome.cpu_seconds <= TIME_LIMIT_S, outcome.describe()
    assert outcome.max_rss_mb < MEMORY_LIMIT_MB, outcome.describe()
    assert "Traceback" not in outcome.output, outcome.describe()
    if refused:
        assert outcome.code == EXIT_INVALID, outcome.describe()
    else:
        assert outcome.code in (0, EXIT_INVALID), outcome.describe()
    if outcome.code == EXIT_INVALID:
        assert any(str(n) in outcome.output for n in names), (
            f"no mention of {[str(n) for n in names]}: {outcome.describe()}")


# ------------------------------------------------------------------------------ setup
@pytest.fixture(scope="module")
def data(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A private copy of the shipped robots, cells and tasks."""
    root = tmp_path_factory.mktemp("data")
    shutil.copytree(DATA_ROOT / "robots", root / "robots",
                    ignore=shutil.ignore_patterns("meshes"))
    # Meshes are large (the Sawyer's 15 MB) and no case edits one: every copy links them.
    for meshes in (DATA_ROOT / "robots").glob("*/meshes"):
        (root / "robots" / meshes.parent.name / "meshes").symlink_to(meshes)
    shutil.copytree(DATA_ROOT / "tasks", root / "tasks")
    # The commands import what they need on first use: do it once here, before the
    # forks, so that each case costs its own work only.
    assert cli.main(["check", str(root / "tasks" / "pick_place.yaml")]) == 0
    assert cli.main(["info", str(root / "robots" / "cells" / "servo_arm_pair.yaml")]) == 0
    return root


def fresh_copy(data: Path, where: Path) -> Path:
    """A copy of ``data`` at ``where`` for one case to change."""
    if where.exists():
        shutil.rmtree(where)
    shutil.copytree(data, where, symlinks=True)
    return where


def alias_bomb(levels: int = 9, width: int = 9) -> str:
    lines = [f"a0: &a0 [{', '.join(['lol'] * width)}]"]
    for i in range(1, levels):
        lines.append(f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * width)}]")
    return "\n".join(lines) + "\n"


def utf16(text: str) -> bytes:
    return text.encode("utf-16")


TASK = "tasks/pick_place.yaml"
CELL = "robots/cells/servo_arm_table.yaml"
URDF_LINK = """<robot name="r">
  <link name="base"/>
  <link name="tip">{element}</link>
  <joint name="j" type="revolute"><parent link="base"/><child link="tip"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def shipped(data: Path, name: str) -> str:
    return (data / name).read_text()


# A case: (name, what to run, how to make the hostile file). ``make(root)`` writes into
# a fresh copy of the data and returns the path to give run-task and the file the
# message must name.
Maker = Callable[[Path], tuple[list[str], Path]]


def task_case(text: str | bytes | Callable[[Path], str | bytes], name: str = "hostile.yaml",
              ) -> Maker:
    def make(root: Path) -> tuple[list[str], Path]:
        path = root / "tasks" / name
        body = text(root) if callable(text) else text
        if isinstance(body, bytes):
            path.write_bytes(body)
        else:
            path.write_text(body)
        return ["check", str(path)], path
    return make


def cell_case(text: str | bytes | Callable[[Path], str | bytes]) -> Maker:
    def make(root: Path) -> tuple[list[str], Path]:
        path = root / "robots" / "cells" / "hostile.yaml"
        body = text(root) if callable(text) else text
        if isinstance(body, bytes):
            path.write_bytes(body)
        else:
            path.write_text(body)
        return ["info", str(path)], path
    return make


def urdf_case(element: str) -> Maker:
    def make(root: Path) -> tuple[list[str], Path]:
        path = root / "robots" / "hostile.urdf"
        path.write_text(URDF_LINK.format(element=element))
        return ["info", str(path)], path
    return make


def xacro_case(body: str, extra: Callable[[Path], None] | None = None) -> Maker:
    def make(root: Path) -> tuple[list[str], Path]:
        folder = root / "robots" / "servo_arm" / "urdf"
        if extra is not None:
            extra(folder)
        path = folder / "hostile.urdf.xacro"
        path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                        f"{body}\n<link name=\"base\"/>\n</robot>\n")
        return ["info", str(path)], path
    return make


def _task_with(old: str, new: str) -> Callable[[Path], str]:
    def text(root: Path) -> str:
        original = shipped(root, TASK)
        assert old in original, old
        return original.replace(old, new, 1)
    return text


def _pose_task(pose: str) -> Callable[[Path], str]:
    return _task_with('pose: {xyz: ["${pick_x}", "${pick_y}", 0.7625]}', f"pose: {pose}")


def _cell_with(old: str, new: str) -> Callable[[Path], str]:
    def text(root: Path) -> str:
        original = shipped(root, CELL)
        assert old in original, old
        return original.replace(old, new)
    return text


def _fifo(path: Path) -> None:
    os.mkfifo(path)


def _include_of(target: str) -> Callable[[Path], str]:
    def text(root: Path) -> str:
        return (shipped(root, TASK).replace("steps:\n", f"steps:\n  - include: {{file: {target}}}\n"))
    return text


def _diamond(root: Path) -> str:
    for i in range(8):
        steps = ("  - {wait: {seconds: 0.1}}\n" if i == 7
                 else f"  - {{include: {{file: d{i + 1}.yaml}}}}\n" * 2)
        (root / "tasks" / f"d{i}.yaml").write_text(
            f"task: d{i}\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n{steps}")
    return "task: t\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n" + \
        "  - {include: {file: d0.yaml}}\n" * 8


def _symlink_loop(root: Path) -> None:
    loop = root / "tasks" / "loop.yaml"
    os.symlink(loop, loop)


def _with_loop(text: Callable[[Path], str]) -> Callable[[Path], str]:
    def make(root: Path) -> str:
        _symlink_loop(root)
        return text(root)
    return make


def _with_fifo(text: Callable[[Path], str]) -> Callable[[Path], str]:
    def make(root: Path) -> str:
        os.mkfifo(root / "tasks" / "fifo.yaml")
        return text(root)
    return make


def _fifo_task(root: Path) -> tuple[list[str], Path]:
    path = root / "tasks" / "fifo.yaml"
    os.mkfifo(path)
    return ["check", str(path)], path


def _loop_task(root: Path) -> tuple[list[str], Path]:
    path = root / "tasks" / "loop.yaml"
    os.symlink(path, path)
    return ["check", str(path)], path


def _path_task(target: str) -> Maker:
    return lambda root: (["check", target], Path(target))


def _mesh_object(file: str) -> Callable[[Path], str]:
    """The shipped task with a mesh object whose ``file:`` is ``file``."""
    return _task_with("objects:\n", "objects:\n  - {name: part, shape: mesh, file: "
                      f"{file}, pose: {{xyz: [0.1, 0.1, 0.8]}}}}\n")


def _mesh_loop(root: Path) -> str:
    """A mesh path through a loop of two symlinks in the tasks folder."""
    os.symlink(root / "tasks" / "la", root / "tasks" / "lb")
    os.symlink(root / "tasks" / "lb", root / "tasks" / "la")
    return _mesh_object("la/part.stl")(root)


def _srdf_case(old: str, new: str) -> Maker:
    def make(root: Path) -> tuple[list[str], Path]:
        srdf = root / "robots" / "servo_arm" / "config" / "servo_arm.srdf"
        text = srdf.read_text()
        assert old in text, old
        srdf.write_text(text.replace(old, new, 1))
        return ["check", str(root / TASK)], srdf
    return make


def _manifest_case(urdf_maker: Callable[[Path], Path]) -> Maker:
    def make(root: Path) -> tuple[list[str], Path]:
        folder = root / "robots" / "servo_arm"
        urdf = urdf_maker(folder)
        manifest = folder / "robot.yaml"
        manifest.write_text(manifest.read_text().replace("urdf/servo_arm.urdf.xacro",
                                                         str(urdf.relative_to(folder))))
        return ["info", str(folder)], urdf
    return make


def _urdf_fifo(folder: Path) -> Path:
    path = folder / "urdf" / "fifo.urdf"
    os.mkfifo(path)
    return path


def _deep_xml(folder: Path) -> Path:
    path = folder / "urdf" / "deep.urdf"
    path.write_text('<robot name="r"><link name="a">' + "<visual>" * 100_000
                    + "</visual>" * 100_000 + "</link></robot>\n")
    return path


def _xml_bomb(folder: Path) -> Path:
    path = folder / "urdf" / "bomb.urdf"
    entities = ['<!ENTITY e0 "lol">'] + [
        f'<!ENTITY e{i} "{("&e" + str(i - 1) + ";") * 10}">' for i in range(1, 10)]
    path.write_text(f'<?xml version="1.0"?>\n<!DOCTYPE robot [{"".join(entities)}]>\n'
                    '<robot name="&e9;"><link name="a"/></robot>\n')
    return path


HOSTILE: dict[str, Maker] = {
    # ---- task files (run-task check)
    "task: alias bomb 9^9": task_case(alias_bomb()),
    "task: alias bomb 10^12 in 600 bytes": task_case(alias_bomb(12, 10)),
    "task: recursive alias": task_case("a: &a [*a]\n"),
    "task: flow nesting 100000": task_case(
        lambda root: "steps: " + "[" * 100_000 + "]" * 100_000 + "\n"),
    "task: block nesting 5000": task_case("".join(" " * i + "a:\n" for i in range(5000))),
    "task: steps nested 200 deep": task_case(
        _task_with(
            "steps:\n", "steps:\n  - " + "{sequence: [" * 200 + "{wait: {seconds: 1}}"
            + "]}" * 200 + "\n")),
    "task: binary": task_case(bytes(range(256)) * 40),
    "task: UTF-16": task_case(lambda root: utf16(shipped(root, TASK))),
    "task: UTF-16 without BOM": task_case(
        lambda root: shipped(root, TASK).encode("utf-16-le")),
    "task: latin-1": task_case("task: caf\xe9\n".encode("latin-1")),
    "task: 20 MB string": task_case(
        lambda root: "task: t\ndescription: '" + "x" * 20_000_000 + "'\n"),
    "task: 5000-digit integer": task_case(
        _task_with("0.7625", "1" * 5000)),
    "task: inf in a pose": task_case(_pose_task("{xyz: [.inf, 0.04, 0.7625]}")),
    "task: 1e400 in a pose": task_case(_pose_task("{xyz: [1e400, 0.04, 0.7625]}")),
    "task: -1e308 in a pose": task_case(_pose_task("{xyz: [-1e308, 0.04, 0.7625]}")),
    "task: NaN in a pose": task_case(_pose_task("{xyz: [0.19, .nan, 0.7625]}")),
    "task: -1e308 in rpy": task_case(_pose_task("{xyz: [0.19, 0.04, 0.7625], rpy: [0, -1e308, 0]}")),
    "task: negative size": task_case(
        _task_with("size: [0.025, 0.025, 0.025]",
                                                 "size: [0.025, -0.025, 0.025]")),
    "task: NaN size": task_case(
        _task_with("size: [0.025, 0.025, 0.025]",
                                                 "size: [0.025, .nan, 0.025]")),
    "task: place at inf": task_case(
        _task_with('at: {xyz: ["${place_x}", "${place_y}", 0.7635]}',
                   'at: {xyz: [0.14, .inf, 0.7635]}')),
    "task: parameter default inf": task_case(
        _task_with("default: -0.12", "default: .inf")),
    "task: !!int abc": task_case(
        _task_with("approach: 0.04", 'approach: !!int "abc"')),
    "task: python tag": task_case("task: !!python/object/apply:os.system ['true']\n"),
    "task: tab indentation": task_case(
        _task_with("  - go: {group: arm, to: home}",
        "\t- go: {group: arm, to: home}")),
    "task: bad indentation": task_case(
        _task_with("  - go: {group: arm, to: home}",
        " - go: {group: arm, to: home}")),
    "task: include diamond": task_case(_diamond),
    "task: include of a symlink loop": task_case(_with_loop(_include_of("loop.yaml"))),
    "task: include of a FIFO": task_case(_with_fifo(_include_of("fifo.yaml"))),
    "task: include of /dev/zero": task_case(_include_of("/dev/zero")),
    "task: include of /proc/self/environ": task_case(_include_of("/proc/self/environ")),
    "task: include path of 300 characters": task_case(_include_of("x" * 300 + ".yaml")),
    "task: include path with NUL": task_case(_include_of('"a\\0b.yaml"')),
    "task: cell is a FIFO": task_case(_with_fifo(
        _task_with("../robots/cells/servo_arm_table.yaml",
                                                 "fifo.yaml"))),
    "task: cell is a symlink loop": task_case(_with_loop(
        _task_with("../robots/cells/servo_arm_table.yaml",
                                                 "loop.yaml"))),
    "task: cell is /dev/zero": task_case(
        _task_with("../robots/cells/servo_arm_table.yaml",
                                                 "/dev/zero")),
    "task: the task is a FIFO": _fifo_task,
    "task: the task is a symlink loop": _loop_task,
    "task: the task is /proc/self/environ": _path_task("/proc/self/environ"),
    "task: the task is /dev/zero": _path_task("/dev/zero"),
    # ---- names and numbers from a task file (issue 29)
    "task: mesh name of 300 bytes": task_case(_mesh_object("m" * 300 + ".stl")),
    "task: mesh path of 5000 bytes": task_case(_mesh_object("d/" * 2500 + "m.stl")),
    "task: mesh path is a symlink loop": task_case(_mesh_loop),
    "task: mesh path with NUL": task_case(_mesh_object('"a\\0b.stl"')),
    "task: mesh path with a lone surrogate": task_case(_mesh_object('"a\\udcffb.stl"')),
    "task: cell path with NUL": task_case(_task_with(
        "../robots/cells/servo_arm_table.yaml", '"../robots/cells/servo\\0arm_table.yaml"')),
    "task: cell name of 300 bytes": task_case(_task_with(
        "../robots/cells/servo_arm_table.yaml", "c" * 300 + ".yaml")),
    "task: boolean in a pose": task_case(_pose_task("{xyz: [0.19, 0.04, true]}")),
    "task: boolean size": task_case(_task_with("size: [0.025, 0.025, 0.025]",
                                               "size: [0.025, false, 0.025]")),
    "task: boolean joint value": task_case(_task_with(
        "  - go: {group: arm, to: home}", '  - go: {group: arm, joints: {"Revolute 1": true}}')),
    "task: NaN joint value": task_case(_task_with(
        "  - go: {group: arm, to: home}", '  - go: {group: arm, joints: {"Revolute 1": .nan}}')),
    "task: repeat 2**63 times": task_case(_task_with(
        "  - go: {group: arm, to: home}",
        "  - repeat: {times: 9223372036854775808, do: [{go: {group: arm, to: home}}]}")),
    "task: wait true seconds": task_case(_task_with(
        "  - go: {group: arm, to: home}", "  - wait: {seconds: true}")),
    "task: wait 1e300 seconds": task_case(_task_with(
        "  - go: {group: arm, to: home}", "  - wait: {seconds: 1e300}")),
    "task: velocity scaling true": task_case(_task_with(
        "  - go: {group: arm, to: home}", "  - go: {group: arm, to: home, velocity_scaling: true}")),
    "srdf: group_state of nan": _srdf_case('<joint name="Revolute 1" value="0.8"/>',
                                           '<joint name="Revolute 1" value="nan"/>'),
    "srdf: group_state of -inf": _srdf_case('<joint name="Revolute 1" value="0.8"/>',
                                            '<joint name="Revolute 1" value="-inf"/>'),
    # ---- cell files (run-task info)
    "cell: alias bomb": cell_case(alias_bomb()),
    "cell: UTF-16": cell_case(lambda root: utf16(shipped(root, CELL))),
    "cell: NaN base": cell_case(_cell_with("xyz: [0.0, 0.0, 0.75]", "xyz: [0, .nan, 0.75]")),
    "cell: inf base": cell_case(_cell_with("xyz: [0.0, 0.0, 0.75]", "xyz: [0, 0, -.inf]")),
    "cell: -1e308 base rpy": cell_case(_cell_with("xyz: [0.0, 0.0, 0.75]",
                                                  "xyz: [0, 0, 0.75], rpy: [0, -1e308, 0]")),
    "cell: negative box size": cell_case(_cell_with("size: [0.60, 0.40, 0.75]",
                                                    "size: [0.8, -0.6, 0.75]")),
    "cell: robot is a symlink loop": cell_case(
        lambda root: (os.symlink(root / "robots" / "cells" / "l", root / "robots" / "cells" / "l")
                      or _cell_with("robot: servo_arm", "robot: l")(root))),
    "cell: mesh name of 300 bytes": cell_case(_cell_with(
        "    shape: box\n    size: [0.10, 0.10, 0.01]",
        "    shape: mesh\n    file: " + "m" * 300 + ".stl")),
    "cell: boolean base": cell_case(_cell_with("xyz: [0.0, 0.0, 0.75]", "xyz: [0, true, 0.75]")),
    "cell: boolean named pose value": cell_case(_cell_with('"Revolute 1": 1.5708',
                                                           '"Revolute 1": true')),
    # ---- robot files (run-task info)
    "urdf: negative box size": urdf_case('<collision><geometry><box size="0.1 -0.1 0.1"/>'
                                         "</geometry></collision>"),
    "urdf: NaN sphere radius": urdf_case('<collision><geometry><sphere radius="nan"/>'
                                         "</geometry></collision>"),
    "urdf: zero cylinder length": urdf_case('<collision><geometry><cylinder radius="0.1" '
                                            'length="0"/></geometry></collision>'),
    "urdf: negative mass": urdf_case('<inertial><mass value="-1"/><inertia ixx="1" ixy="0" '
                                     'ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'),
    "urdf: inf inertia": urdf_case('<inertial><mass value="1"/><inertia ixx="inf" ixy="0" '
                                   'ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'),
    "urdf: negative inertia": urdf_case('<inertial><mass value="1"/><inertia ixx="-1" ixy="0" '
                                        'ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'),
    "urdf: inf origin": urdf_case('<visual><origin xyz="0 1e400 0"/><geometry>'
                                  '<sphere radius="0.1"/></geometry></visual>'),
    "urdf: the URDF is a FIFO": _manifest_case(_urdf_fifo),
    "urdf: XML nested 100000 deep": _manifest_case(_deep_xml),
    "urdf: XML entity bomb": _manifest_case(_xml_bomb),
    "robot.yaml: alias bomb": lambda root: (
        (root / "robots" / "servo_arm" / "robot.yaml").write_text(alias_bomb()),
        (["info", str(root / "robots" / "servo_arm")],
         root / "robots" / "servo_arm" / "robot.yaml"))[1],
    "xacro: 10**10**8": xacro_case('<xacro:property name="big" value="${10**10**8}"/>'
                                   '<link name="${big}"/>'),
    "xacro: macro fan-out 2^24": xacro_case(
        '<xacro:macro name="m0"><link name="x"/></xacro:macro>'
        + "".join(f'<xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>'
                  for i in range(1, 25)) + "<xacro:m24/>"),
    "xacro: 1 GB string": xacro_case(
        '<xacro:property name="s" value="${\'x\' * 10**9}"/><link name="${s}"/>'),
    "xacro: include of a FIFO": xacro_case('<xacro:include filename="fifo.xacro"/>',
                                           lambda folder: _fifo(folder / "fifo.xacro")),
}


@pytest.mark.parametrize("case", list(HOSTILE), ids=list(HOSTILE))
def test_hostile_file_is_refused_cleanly(data, tmp_path, case):
    root = fresh_copy(data, tmp_path / "data")
    argv, named = HOSTILE[case](root)
    outcome = run_cli(argv, root)
    assert_clean(outcome, named, named.name)


# The same names through `run-task run`, whose early worker reads the task's cell before
# the loader does (runtime/prestart.py): refused as `check` refuses them, nothing moves.
RUN_CASES = ("task: cell path with NUL", "task: cell is a symlink loop",
             "task: cell name of 300 bytes", "task: mesh name of 300 bytes",
             "task: mesh path is a symlink loop", "task: boolean in a pose",
             "task: repeat 2**63 times", "srdf: group_state of nan")


@pytest.mark.parametrize("case", RUN_CASES, ids=RUN_CASES)
def test_hostile_file_is_refused_cleanly_by_run(data, tmp_path, case):
    root = fresh_copy(data, tmp_path / "data")
    argv, named = HOSTILE[case](root)
    task = argv[1]
    outcome = run_cli(["run", task, "--backend", "mock"], root)
    assert_clean(outcome, named, named.name)
    assert "nothing moved" in outcome.output, outcome.describe()


# ------------------------------------------------------------------------- mutations
HOSTILE_NUMBERS = ("nan", ".nan", ".inf", "-.inf", "1e400", "-1e308", "-0.5", "0", "1e30",
                   "-1", '"abc"', "[]", "{}", "null", "true")

MUTABLE = {
    "tasks/pick_place.yaml": "check",
    "tasks/handoff.yaml": "check",
    "tasks/fallback_place.yaml": "check",
    "robots/cells/servo_arm_table.yaml": "info",
    "robots/cells/servo_arm_pair.yaml": "info",
    "robots/servo_arm/robot.yaml": "info",
    "robots/servo_arm/config/joint_limits.yaml": "info",
    "robots/servo_arm/config/kinematics.yaml": "info",
    "robots/servo_arm/config/servo_arm.srdf": "info",
    "robots/servo_arm/urdf/servo_arm_macros.xacro": "info",
}


def _target(relative: str, root: Path) -> str:
    """What run-task is given for a change of ``relative``."""
    if relative.startswith("tasks/") or relative.startswith("robots/cells/"):
        return str(root / relative)
    return str(root / "robots" / "servo_arm")


@st.composite
def mutations(draw: st.DrawFn) -> tuple[str, str]:
    relative = draw(st.sampled_from(sorted(MUTABLE)))
    text = (DATA_ROOT / relative).read_text()
    for _ in range(draw(st.integers(1, 3))):
        lines = text.splitlines(keepends=True) or [""]
        kind = draw(st.sampled_from(("number", "number", "delete", "duplicate", "indent",
                                     "truncate", "insert", "swap")))
        at = draw(st.integers(0, len(lines) - 1))
        if kind == "number":
            import re

            numbers = list(re.finditer(r"-?\d+\.?\d*(e-?\d+)?", text))
            if numbers:
                match = numbers[draw(st.integers(0, len(numbers) - 1))]
                text = text[:match.start()] + draw(st.sampled_from(HOSTILE_NUMBERS)) + \
                    text[match.end():]
            continue
        if kind == "delete":
            del lines[at]
        elif kind == "duplicate":
            lines.insert(at, lines[at])
        elif kind == "indent":
            lines[at] = draw(st.sampled_from(("\t", " ", "   "))) + lines[at]
        elif kind == "truncate":
            text = text[:draw(st.integers(0, len(text)))]
            continue
        elif kind == "insert":
            lines.insert(at, draw(st.text(min_size=1, max_size=20)) + "\n")
        elif kind == "swap":
            other = draw(st.integers(0, len(lines) - 1))
            lines[at], lines[other] = lines[other], lines[at]
        text = "".join(lines)
    return relative, text


@settings(max_examples=150, derandomize=True, deadline=None, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(mutation=mutations())
def test_mutated_shipped_files_end_cleanly(data, tmp_path, mutation):
    relative, text = mutation
    root = fresh_copy(data, tmp_path / "mutated")
    path = root / relative
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    outcome = run_cli([MUTABLE[relative], _target(relative, root)], root)
    assert_clean(outcome, path, path.name, _target(relative, root), refused=False)
