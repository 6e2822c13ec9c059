"""Expanding xacro files, bounded in time and memory.

xacro evaluates Python expressions (``${10**10**8}``), expands macros without limit (a
macro calling another twice, 24 deep, is 2^24 elements) and opens whatever its includes
name (a FIFO blocks forever). A robot file must not be able to hang or exhaust the
process that loads it, so :func:`expand_xacro` runs xacro in a child process: a fork of
the current one (the xacro module and the package map are already there, so the child
costs a few milliseconds, not an interpreter start), with an address-space limit
(``RLIMIT_AS``) and a limit on the child's CPU time enforced by the parent, which kills
the child when it is used up. CPU time, not wall-clock time: a busy machine (other
processes taking the cores) slows an expansion down without making it any more hostile,
and a robot must not be refused for it; a generous wall-clock limit still ends a child
that waits without computing. In the child, every file xacro includes is first checked like any
other user file (:func:`taskrunner.textfile.read_text_file`: a regular UTF-8 file under
the size limit), so an include of a FIFO or ``/dev/zero`` is refused at once.

This bounds the damage of a hostile file; it is not a sandbox: xacro's expressions run
with the rights of the process. Load xacro only from folders the operator owns.

Expansions are cached (:mod:`taskrunner.robot.xacro_cache`) with every file, variable
and package they read, and reused only while all of these are unchanged.
"""

from __future__ import annotations

import io
import multiprocessing
import os
import re
import resource
import threading
import time
from collections.abc import Callable, Sequence
from contextlib import redirect_stderr, redirect_stdout
from dataclasses import dataclass
from multiprocessing.connection import Connection
from pathlib import Path
from typing import Any
from xml.parsers import expat

from taskrunner.errors import ArgumentError, RobotDescriptionError
from taskrunner.processes import cpu_seconds
from taskrunner.robot import xacro_cache
from taskrunner.robot.packages import PackageMap
from taskrunner.textfile import DEFAULT_MAX_BYTES, file_problem, read_text_file

__all__ = ["XacroOptions", "expand_xacro"]


@dataclass(frozen=True)
class XacroOptions:
    """Bounds on one xacro expansion.

    Attributes:
        time_limit_s: CPU time the whole expansion may use (s).
        wall_limit_s: wall-clock time after which a child still at work is stopped
            however little CPU it had (s): a bound on waiting, not on work.
        memory_limit_mb: address space the child may add to what it inherits (MiB).
        max_bytes: size limit of the xacro file and of each file it includes (bytes).
        in_process: expand in this process, unbounded (for debugging xacro itself).
    """

    time_limit_s: float = 3.0
    wall_limit_s: float = 120.0
    memory_limit_mb: int = 256
    max_bytes: int = DEFAULT_MAX_BYTES
    in_process: bool = False

    def __post_init__(self) -> None:
        if not self.time_limit_s > 0:
            raise ArgumentError(f"'time_limit_s' must be > 0 (got {self.time_limit_s!r})")
        if not self.wall_limit_s > 0:
            raise ArgumentError(f"'wall_limit_s' must be > 0 (got {self.wall_limit_s!r})")
        if self.memory_limit_mb < 16:
            raise ArgumentError(f"'memory_limit_mb' must be ≥ 16 (got {self.memory_limit_mb!r})")


_POLL_S = 0.02  # s between two reads of the child's CPU time (an answer wakes at once)

# xacro keeps its state in module globals: one in-process expansion at a time.
_XACRO_LOCK = threading.Lock()


def expand_xacro(path: str | Path, packages: PackageMap, mappings: dict[str, str] | None = None,
                 options: XacroOptions | None = None) -> str:
    """Expand a xacro file to URDF text, resolving ``$(find pkg)`` through ``packages``.

    Args:
        path: the ``.xacro`` file.
        packages: where ``$(find pkg)`` looks packages up.
        mappings: xacro arguments (``name:=value`` on the xacro command line).
        options: time and memory bounds (default :class:`XacroOptions`).

    Raises:
        RobotDescriptionError: xacro reports an error, an included file is refused, or
            the expansion runs out of time or memory (the message names the file).
    """
    options = options or XacroOptions()
    path = Path(path)
    problem = file_problem(path)
    if problem is not None:
        raise RobotDescriptionError(problem, path)
    cached = xacro_cache.lookup(path, mappings,
                                lambda package: str(packages.find(package, near=path.parent)))
    if cached is not None:
        return cached
    inputs = xacro_cache.XacroInputs()
    if options.in_process:
        text = _expand(path, packages, mappings, options.max_bytes, inputs)
    else:
        text = _expand_in_child(path, packages, mappings, options, inputs)
    xacro_cache.store(path, mappings, text, inputs)
    return text


def _expand_in_child(path: Path, packages: PackageMap, mappings: dict[str, str] | None,
                     options: XacroOptions, inputs: xacro_cache.XacroInputs) -> str:
    context = multiprocessing.get_context("fork")
    receiver, sender = context.Pipe(duplex=False)
    child = context.Process(target=_child_main, daemon=True,
                            args=(sender, path, packages, mappings, options))
    child.start()
    sender.close()
    try:
        _await_child(receiver, child.pid, options, path)
        try:
            kind, value = receiver.recv()
        except (EOFError, OSError):
            child.join(1.0)
            raise RobotDescriptionError(
                f"xacro expansion failed: its process ended (exit code {child.exitcode}); "
                f"out of memory (limit +{options.memory_limit_mb} MiB)?", path) from None
    finally:
        receiver.close()
        if child.is_alive():
            child.kill()
        child.join()
    if kind == "error":
        raise value
    text, found_warnings, read = value
    inputs.files, inputs.env, inputs.finds = read.files, read.env, read.finds
    inputs.cacheable = read.cacheable
    # A package found twice that the expansion used: the child's copy of the map warned.
    for warning in found_warnings:
        if warning not in packages.warnings:
            packages.warnings.append(warning)
    return str(text)


def _await_child(receiver: Connection, pid: int | None, options: XacroOptions,
                 path: Path) -> None:
    """Return once the child has sent its answer (or ended); raise when it has used its
    CPU time or the wall-clock limit."""
    started = time.monotonic()
    while not receiver.poll(_POLL_S):
        cpu = cpu_seconds(pid)
        waited = time.monotonic() - started
        if (cpu if cpu is not None else waited) > options.time_limit_s:
            raise RobotDescriptionError(
                f"xacro expansion took more than {options.time_limit_s:g} s of CPU time "
                "(a runaway expression or macro?)", path)
        if waited > options.wall_limit_s:
            raise RobotDescriptionError(
                f"xacro expansion did not end in {options.wall_limit_s:g} s (waiting on "
                "something it reads?)", path)


def _child_main(sender: Connection, path: Path, packages: PackageMap,
                mappings: dict[str, str] | None, options: XacroOptions) -> None:
    """The child: limit the address space, expand, send ("text", str) or ("error", exc)."""
    try:
        _limit_address_space(options.memory_limit_mb)
        known = len(packages.warnings)
        inputs = xacro_cache.XacroInputs()
        text = _expand(path, packages, mappings, options.max_bytes, inputs)
        result: tuple[str, Any] = ("text", (text, packages.warnings[known:], inputs))
    except RobotDescriptionError as exc:
        result = ("error", exc)
    except MemoryError:
        result = ("error", RobotDescriptionError(
            f"xacro expansion needs more memory than its limit "
            f"(+{options.memory_limit_mb} MiB): a runaway expression or macro?", path))
    except BaseException as exc:  # anything else is reported, never raised in the child
        result = ("error", RobotDescriptionError(
            f"xacro expansion failed: {type(exc).__name__}: {exc}", path))
    try:
        sender.send(result)
    except MemoryError:
        os._exit(3)
    finally:
        sender.close()


def _limit_address_space(extra_mb: int) -> None:
    with open("/proc/self/status") as status:
        used = next((int(line.split()[1]) * 1024 for line in status
                     if line.startswith("VmSize:")), 0)
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = used + extra_mb * 2**20
    if hard != resource.RLIM_INFINITY:
        limit = min(limit, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def _guarded_includes(xacro: Any, max_bytes: int, inputs: xacro_cache.XacroInputs
                      ) -> tuple[Callable[..., Any], Callable[..., Any]]:
    """Wrap xacro's file readers so every file it opens is checked first (and recorded
    in ``inputs``); returns the originals to restore."""
    original_parse, original_load_yaml = xacro.parse, xacro.load_yaml

    def parse(inp: Any, filename: str | None = None) -> Any:
        if inp is None and filename is not None:
            full = os.path.join(xacro.root_dir or "", filename)
            if file_problem(full) == "file not found":  # xacro's own message names it
                return original_parse(inp, filename)
            try:
                inp = read_text_file(full, RobotDescriptionError, max_bytes)
                inputs.read_file(full, Path(full).read_bytes())
            except RobotDescriptionError as exc:
                raise xacro.XacroException(exc.reason) from None
            except OSError as exc:
                raise xacro.XacroException(f"{full}: {exc.strerror or exc}") from None
        return original_parse(inp, filename)

    def load_yaml(filename: str) -> Any:
        full = xacro.abs_filename_spec(filename)
        problem = file_problem(full)
        if problem is not None:
            raise xacro.XacroException(f"{filename}: {problem}")
        try:
            inputs.read_file(full, Path(full).read_bytes())
        except OSError as exc:
            raise xacro.XacroException(f"{filename}: {exc.strerror or exc}") from None
        return original_load_yaml(filename)

    xacro.parse, xacro.load_yaml = parse, load_yaml
    return original_parse, original_load_yaml


# An include's ``filename`` attribute, in any namespace prefix (``xacro:include``).
_INCLUDE = re.compile(r"""<\s*(?:[\w.-]+:)?include\b[^>]*?\bfilename\s*=\s*(["'])(.*?)\1""",
                      re.DOTALL)


def _includes_by_pattern(files: Sequence[str | Path]) -> bool:
    """Whether one of ``files`` (what an expansion read) includes by glob pattern, or by
    a name an expression makes (which may be a pattern): the expansion then depends on
    which files exist, which the cache does not track. Read from the files themselves
    (unreadable: assumed so), not from inside xacro."""
    for name in files:
        try:
            text = Path(name).read_text(encoding="utf-8", errors="replace")
        except OSError:
            return True
        for match in _INCLUDE.finditer(text):
            spec = match.group(2)
            if "${" in spec or any(c in spec for c in "*[?"):
                return True
    return False


# ``$(env NAME)``, ``$(optenv NAME default)``; ``env('NAME')``, ``optenv('NAME', …)`` in a
# ``$(eval …)`` expression; and any other call of those (a name not written out).
_ENV_ARG = re.compile(r"\$\(\s*(?:env|optenv)\s+([^\s)]+)")
_ENV_CALL = re.compile(r"""\b(?:env|optenv)\s*\(\s*(["'])([^"'$]*)\1""")
_ENV_ANY = re.compile(r"\b(?:env|optenv)\s*\(")


def _environment_read(files: Sequence[str | Path]) -> set[str] | None:
    """The environment variables an expansion of ``files`` (what it read) may read, from
    the files' own text; None when one is named by an expression or a substitution (not
    known before it runs) or a file cannot be read again. A name in a comment counts too
    (recorded, never wrong)."""
    names: set[str] = set()
    for name in files:
        try:
            text = Path(name).read_text(encoding="utf-8", errors="replace")
        except OSError:
            return None
        for match in _ENV_ARG.finditer(text):
            if "$" in match.group(1):
                return None
            names.add(match.group(1))
        literal = list(_ENV_CALL.finditer(text))
        if len(literal) != len(_ENV_ANY.findall(text)):
            return None
        names.update(m.group(2) for m in literal)
    return names


def _expand(path: Path, packages: PackageMap, mappings: dict[str, str] | None,
            max_bytes: int, inputs: xacro_cache.XacroInputs) -> str:
    """Expand in this process (unbounded; see :func:`expand_xacro`), recording what it
    reads in ``inputs``."""
    import xacro
    import xacro.substitution_args as substitution_args

    lookup_errors: list[RobotDescriptionError] = []

    def find(pkg: str) -> str:
        try:
            folder = str(packages.find(pkg, near=path.parent))
        except RobotDescriptionError as exc:
            lookup_errors.append(exc)
            raise
        inputs.finds[pkg] = folder
        return folder

    with _XACRO_LOCK:
        saved_find = substitution_args._eval_find
        saved_table = dict(substitution_args._eval_dict)
        substitution_args._eval_find = find
        substitution_args._eval_dict.update(find=find)
        saved_readers = _guarded_includes(xacro, max_bytes, inputs)
        known_includes = len(xacro.all_includes)
        chatter = io.StringIO()
        try:
            with redirect_stdout(chatter), redirect_stderr(chatter):
                document = xacro.process_file(str(path), mappings=dict(mappings or {}))
            # Every file xacro read, ``load_yaml`` from expressions included (xacro's
            # expression namespace holds its own reference to load_yaml, not the wrapper).
            included = list(xacro.all_includes[known_includes:])
            for name in included:
                try:
                    inputs.read_file(name, Path(name).read_bytes())
                except OSError:
                    inputs.cacheable = False
            if _includes_by_pattern([path, *included]):
                inputs.cacheable = False
            variables = _environment_read([path, *included])
            if variables is None:
                inputs.cacheable = False
            else:
                inputs.env.update({name: os.environ.get(name) for name in sorted(variables)})
            return str(document.toprettyxml(indent="  "))
        except MemoryError:
            raise
        except Exception as exc:  # xacro raises plain exceptions of many kinds
            # Report the file xacro was reading when it failed (maybe an included one).
            stack = [f for f in (xacro.filestack or []) if f]
            where = Path(stack[-1]) if stack else path
            if lookup_errors:
                raise RobotDescriptionError(
                    f"$(find …): {lookup_errors[0].reason}", where
                ) from None
            if isinstance(exc, expat.ExpatError):
                raise RobotDescriptionError(
                    f"invalid XML: {expat.ErrorString(exc.code)}", where, exc.lineno
                ) from None
            detail = " ".join(str(exc).split()) or type(exc).__name__
            chatter_text = " ".join(chatter.getvalue().split())
            if chatter_text:
                detail = f"{detail} ({chatter_text})"
            if where != path:
                detail = f"{detail} (included from {path})"
            raise RobotDescriptionError(f"xacro expansion failed: {detail}", where) from None
        finally:
            substitution_args._eval_find = saved_find
            substitution_args._eval_dict.clear()
            substitution_args._eval_dict.update(saved_table)
            xacro.parse, xacro.load_yaml = saved_readers
            xacro.init_stacks(None)
