"""Writing files so that none is ever half-written: a temporary file, then a rename.

Contents:
    write_atomic(path, content)           one file: readers see the old one or the new one, never a part
    write_all_atomic(files, remove=...)   a set of files, all or none: each is written before any replaces its old one
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterable, Mapping
from pathlib import Path

from grader.interrupt import ctrl_c_deferred

__all__ = ["write_all_atomic", "write_atomic"]


def write_atomic(path: str | Path, content: str | bytes) -> Path:
    """Write ``content`` to ``path``: readers see the old file or the new one, never a part."""
    return write_all_atomic({path: content})[0]


def write_all_atomic(
    files: Mapping[str | Path, str | bytes] | Iterable[tuple[str | Path, str | bytes]],
    *,
    remove: Iterable[str | Path] = (),
) -> list[Path]:
    """Write every file in ``files`` (a mapping, or (path, content) pairs), or none; then delete ``remove``.

    Each file is first written in full to a temporary file beside it. Only when all are written
    are they renamed into place, so a failure while writing (a full disk, a folder that cannot be
    made, or an exception from the generator that makes the contents) leaves every old file as it
    was. The renames and deletions that follow need no space. Pairs are taken one at a time, so
    a generator keeps only one file's content in memory.
    """
    staged: dict[Path, Path] = {}
    try:
        for path, content in files.items() if isinstance(files, Mapping) else files:
            path = Path(path)
            if path in staged:  # given twice: the last content is the file's
                staged.pop(path).unlink()
            staged[path] = _temporary(path, content)
        with ctrl_c_deferred():  # a Ctrl-C among the renames would leave old and new files mixed
            for path, temporary in staged.items():
                os.replace(temporary, path)
            for path in remove:
                if Path(path) not in staged:
                    Path(path).unlink(missing_ok=True)
    finally:
        for temporary in staged.values():
            temporary.unlink(missing_ok=True)  # written but never renamed: the write failed
    return list(staged)


def _temporary(path: Path, content: str | bytes) -> Path:
    """``content`` written to disk in a temporary file beside ``path``."""
    path.parent.mkdir(parents=True, exist_ok=True)
    data = content.encode("utf-8") if isinstance(content, str) else content
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        # mkstemp makes the file readable by its owner alone; a report is read by TAs and web servers
        # as any file this user writes is: with the permissions the process's umask gives
        os.chmod(temporary, 0o666 & ~_umask())
        with os.fdopen(handle, "wb") as file:
            file.write(data)
            file.flush()
            os.fsync(file.fileno())
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return Path(temporary)


def _umask() -> int:
    """The process's umask (read by setting it, then setting it back)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask
