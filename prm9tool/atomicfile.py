"""Atomic file replacement with a backup of the previous content (no Qt).

Used for everything prm9tool saves: a crash, a full disk or a pulled USB stick during saving
leaves either the old file or the new one, never a mix.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import stat
from pathlib import Path
from typing import IO

BACKUP_SUFFIX = ".bak"


def atomic_write(
    path: Path, data: bytes, backup: bool = True, follow_symlinks: bool = True
) -> None:
    """Replace ``path`` with ``data`` so that it holds the old or the new bytes, never a mix.

    The data goes to a temporary file in the same directory, is flushed to disk, then renamed
    over ``path``. With ``backup``, the previous content is first saved as ``<name>.bak``
    (the same way). A symbolic link is followed, its target replaced (a *.prm file saved
    through a link); with ``follow_symlinks=False`` the link itself is replaced by the new
    file and whatever it pointed to is left alone (the ``--batch`` report).
    """
    target = path.resolve() if follow_symlinks else path.absolute()
    try:
        info = target.stat() if follow_symlinks else target.lstat()
        old_mode: int | None = None if stat.S_ISLNK(info.st_mode) else stat.S_IMODE(info.st_mode)
    except FileNotFoundError:
        old_mode = None
        info = None
    if info is not None and stat.S_ISLNK(info.st_mode):
        backup = False  # the link is replaced; what it pointed to is nobody's old content here
    if backup and old_mode is not None:
        _replace(target.with_name(target.name + BACKUP_SUFFIX), target.read_bytes(), old_mode)
    _replace(target, data, old_mode)


def _replace(target: Path, data: bytes, mode: int | None) -> None:
    temp = target.with_name(f".{target.name}.{secrets.token_hex(4)}.tmp")
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    fd = os.open(temp, flags, 0o666)  # the umask applies, as for any new file
    try:
        with os.fdopen(fd, "wb") as stream:
            _write_data(stream, data)
            stream.flush()
            os.fsync(stream.fileno())
        if mode is not None:
            os.chmod(temp, mode)
        os.replace(temp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise
    _sync_directory(target.parent)


def _write_data(stream: IO[bytes], data: bytes) -> None:
    stream.write(data)


def _sync_directory(directory: Path) -> None:
    """Make the rename durable (POSIX); not possible, and not needed, on Windows."""
    if os.name != "posix":
        return
    fd = os.open(directory, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)
