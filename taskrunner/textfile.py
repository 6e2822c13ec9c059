"""Reading a user's text file without trusting it.

Every file a user names (task, cell, robot manifest, MoveIt YAML, URDF) is read through
:func:`read_text_file`, which refuses what would hang, exhaust memory or produce
garbage before any parser sees it:

- anything that is not a regular file: a FIFO (opened with ``O_NONBLOCK``, so opening it
  never blocks), a device (``/dev/zero``), a directory, a socket, or a pseudo-file of
  ``/proc`` or ``/sys`` (regular by ``stat`` but of unbounded, generated content);
- a symlink loop, a path that is too long or holds a NUL character or a lone surrogate
  (:func:`path_problem`, checked before any file system call);
- a file over the size limit (read up to the limit, never further);
- text that is not UTF-8: binary files (NUL bytes), UTF-16/32, invalid byte sequences.

Each refusal is an :class:`~taskrunner.errors.InputError` (the caller picks the subclass)
naming the file and the reason.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

from taskrunner.errors import InputError

__all__ = ["DEFAULT_MAX_BYTES", "MAX_NAME_BYTES", "MAX_PATH_BYTES", "file_problem",
           "path_problem", "read_text_file", "resolve_path"]

DEFAULT_MAX_BYTES = 4 * 1024 * 1024
"""Default size limit of a user's text file (bytes): far above any real task, cell or
robot file, far below what could exhaust memory once parsed."""

_PSEUDO_ROOTS = ("/proc", "/sys")

_KINDS = (
    (stat.S_ISDIR, "a directory"),
    (stat.S_ISFIFO, "a FIFO (named pipe)"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def _os_reason(exc: OSError) -> str:
    if exc.errno == errno.ENOENT or exc.errno == errno.ENOTDIR:
        return "file not found"
    if exc.errno == errno.ELOOP:
        return "symlink loop (too many levels of symbolic links)"
    if exc.errno == errno.ENAMETOOLONG:
        return "path too long"
    if exc.errno == errno.EACCES or exc.errno == errno.EPERM:
        return "permission denied"
    if exc.errno == errno.EISDIR:
        return "not a regular file (a directory)"
    return f"cannot read file: {exc.strerror or exc}"


MAX_NAME_BYTES = 255
"""Longest file or folder name (bytes, UTF-8): every Linux and macOS file system's."""
MAX_PATH_BYTES = 4095
"""Longest path (bytes, UTF-8): Linux's ``PATH_MAX`` less its terminating NUL."""


def path_problem(path: str | Path) -> str | None:
    """What makes ``path`` unusable as a file name before any file system call sees it
    (a NUL character, text that is no file name, a name over :data:`MAX_NAME_BYTES` or
    a path over :data:`MAX_PATH_BYTES`), as the end of a message; None if nothing does.
    Never touches the file system, never raises."""
    text = str(path)
    if "\0" in text:
        return "it holds a NUL character"
    try:
        encoded = os.fsencode(text)
    except UnicodeError:
        return "it holds a lone surrogate character (no file name can)"
    if len(encoded) > MAX_PATH_BYTES:
        return f"{len(encoded)} bytes long (paths end at {MAX_PATH_BYTES} bytes)"
    longest = max(len(part) for part in encoded.split(b"/"))
    if longest > MAX_NAME_BYTES:
        return (f"a name of {longest} bytes (file and folder names end at {MAX_NAME_BYTES} "
                "bytes)")
    return None


def resolve_path(path: str | Path, error: type[InputError] = InputError,
                 where: str | Path | None = None, line: int | None = None,
                 written: str | None = None) -> Path:
    """``path`` made absolute with symlinks followed, refusing what :func:`path_problem`
    refuses and symlink loops (``Path.resolve`` raises ``RuntimeError``, ``OSError`` or
    ``ValueError`` for those, depending on the Python version and the cause).

    The one gate between a name from a file or a request and the file system: every
    loader resolves the paths it is given here.

    Args:
        path: the path to resolve.
        error: the error class to raise.
        where: the file to name in the error (default: ``path`` itself).
        line: the line of ``where`` that names ``path``.
        written: ``path`` as the file or request wrote it: the message names it so
            (default: ``path``), never its resolution.
    """
    shown = written if written is not None else str(path)
    problem = path_problem(path)
    if problem is not None:
        if where is None:
            raise error(f"invalid path: {problem}", repr(shown)[1:-1], line)
        raise error(f"invalid path {shown!r}: {problem}", where, line)
    try:
        return Path(path).resolve()
    except ValueError:
        reason = "invalid path"
    except RuntimeError:  # Python 3.11 reports a symlink loop so
        reason = "symlink loop (too many levels of symbolic links)"
    except OSError as exc:
        reason = _os_reason(exc)
    raise error(f"{shown!r}: {reason}" if where is not None else reason,
                where if where is not None else shown, line)


def file_problem(path: str | Path) -> str | None:
    """Why ``path`` cannot be read as a regular file ("file not found", "not a regular
    file (a FIFO (named pipe))", "symlink loop …", "path too long"), or None if it can.
    Never opens the file, never raises."""
    problem = path_problem(path)
    if problem is not None:
        return f"invalid path: {problem}"
    try:
        info = os.stat(path)
    except ValueError:
        return "invalid path"
    except OSError as exc:
        return _os_reason(exc)
    if not stat.S_ISREG(info.st_mode):
        kind = next((name for test, name in _KINDS if test(info.st_mode)), "not a file")
        return f"not a regular file ({kind})"
    absolute = os.path.realpath(path)
    for root in _PSEUDO_ROOTS:
        if absolute == root or absolute.startswith(root + "/"):
            return f"not a regular file (a pseudo-file under {root})"
    return None


def read_text_file(path: str | Path, error: type[InputError] = InputError,
                   max_bytes: int = DEFAULT_MAX_BYTES) -> str:
    """The text of a regular UTF-8 file of at most ``max_bytes`` bytes.

    A leading byte order mark is dropped.

    Raises:
        InputError: (of class ``error``) the file is missing, not a regular file, a symlink
            loop, too large, binary or not UTF-8; the message says which.
    """
    path = Path(path)
    try:
        absolute = os.path.realpath(path)
    except (ValueError, OSError):
        absolute = str(path)
    problem = path_problem(path)
    if problem is not None:
        raise error(f"invalid path: {problem}", repr(str(path))[1:-1])
    for root in _PSEUDO_ROOTS:
        if absolute == root or absolute.startswith(root + "/"):
            raise error(f"not a regular file (a pseudo-file under {root})", path)
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as exc:
        raise error(_os_reason(exc), path) from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            kind = next((name for test, name in _KINDS if test(info.st_mode)), "not a file")
            raise error(f"not a regular file ({kind})", path)
        if info.st_size > max_bytes:
            raise error(_too_large(info.st_size, max_bytes), path)
        chunks: list[bytes] = []
        size = 0
        while size <= max_bytes:
            chunk = os.read(fd, min(1 << 20, max_bytes + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > max_bytes:  # grew while being read
            raise error(_too_large(size, max_bytes), path)
    except OSError as exc:
        raise error(_os_reason(exc), path) from None
    finally:
        os.close(fd)
    return decode_text(b"".join(chunks), path, error)


def decode_text(data: bytes, path: str | Path | None, error: type[InputError] = InputError) -> str:
    """``data`` as UTF-8 text (a leading BOM dropped), refusing binary, UTF-16/32 and
    invalid UTF-8 with the line of the first bad byte."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise error("file is not UTF-8 text (it is UTF-16 or UTF-32: save it as UTF-8)", path)
    nul = data.find(b"\0")
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise error("file is not UTF-8 text (a NUL byte: a binary file, or UTF-16)", path, line)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise error(f"file is not UTF-8 text (invalid byte 0x{data[exc.start]:02x})",
                    path, line) from None
    return text[1:] if text.startswith("\ufeff") else text


def _too_large(size: int, limit: int) -> str:
    return f"file is too large ({_mb(size)}; the limit is {_mb(limit)})"


def _mb(size: int) -> str:
    return f"{size / 1e6:.1f} MB" if size >= 100_000 else f"{size} bytes"
