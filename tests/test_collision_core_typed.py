"""The compiled collision core stays typed: no ``type: ignore`` in it, every function
annotated (so mypy checks the kernels' bodies and the calls between them; numba's
dispatchers are typed as the functions they compile: ``taskrunner.collision.frames.jit``)."""

from __future__ import annotations

import ast
import io
import tokenize
from pathlib import Path

import taskrunner

PACKAGE = Path(taskrunner.__file__).parent
# The collision core: taskrunner/collision and the kernel modules of taskrunner/scene.
SCENE_KERNELS = ("advancement", "coalpath", "distance_bounds", "geometry_records",
                 "path_verifier", "screen")
# Ignores still present, per file, at most (the two-arm schedule's module, worked on
# elsewhere): the count may only fall.
KNOWN = {"collision/spacetime.py": 2}


def core_files() -> list[Path]:
    files = sorted((PACKAGE / "collision").glob("*.py"))
    files += [PACKAGE / "scene" / f"{name}.py" for name in SCENE_KERNELS]
    return files


def ignores(source: str) -> int:
    """The ``type: ignore`` comments in ``source`` (comments only, not strings)."""
    tokens = tokenize.generate_tokens(io.StringIO(source).readline)
    return sum(1 for t in tokens if t.type == tokenize.COMMENT
               and t.string.lstrip("#").strip().startswith("type: ignore"))


def unannotated(source: str) -> list[str]:
    """The functions of ``source`` with an argument or the result not annotated."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            args = node.args.posonlyargs + node.args.args + node.args.kwonlyargs
            args += [a for a in (node.args.vararg, node.args.kwarg) if a is not None]
            missing = [a.arg for a in args if a.annotation is None and a.arg not in ("self", "cls")]
            if missing or node.returns is None:
                found.append(f"{node.name} (line {node.lineno}): "
                             + (f"arguments {missing}" if missing else "result"))
    return found


def test_the_core_files_are_found() -> None:
    files = core_files()
    assert all(f.is_file() for f in files), [f for f in files if not f.is_file()]
    names = {f.name for f in files}
    assert {"frames.py", "tree.py", "geometry.py", "advancement.py", "screen.py"} <= names


def test_no_type_ignore_in_the_collision_core() -> None:
    over = {}
    for path in core_files():
        key = path.relative_to(PACKAGE).as_posix()
        count = ignores(path.read_text())
        if count > KNOWN.get(key, 0):
            over[key] = count
    assert not over, f"'type: ignore' in the collision core (type it instead): {over}"


def test_every_kernel_function_is_annotated() -> None:
    missing = {}
    for path in core_files():
        if path.relative_to(PACKAGE).as_posix() in KNOWN:
            continue
        found = unannotated(path.read_text())
        if found:
            missing[path.name] = found
    assert not missing, f"functions mypy would not check: {missing}"


def test_the_checks_find_what_they_look_for() -> None:
    source = ("def f(a, b: int):  # type: ignore[no-untyped-def]\n"
              "    s = '# type: ignore'\n"
              "    return a\n"
              "x = 1  #type: ignore\n")
    assert ignores(source) == 2
    assert unannotated(source) == ["f (line 1): arguments ['a']"]
    assert unannotated("def g(a: int):\n    return a\n") == ["g (line 1): result"]
    assert unannotated("def h(a: int) -> int:\n    return a\n") == []
