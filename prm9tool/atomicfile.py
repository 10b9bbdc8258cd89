"""Atomic file replacement with a backup of the previous content (no Qt).

Used for everything prm9tool saves: a crash, a full disk or a pulled USB stick during saving
leaves either the old file or the new one, never a mix.

A save killed half-way (power loss, ``kill -9``) leaves its temporary file
``.<name>.<8 hex digits>.tmp`` beside the file. The writer holds an OS lock on its temporary
file while it writes (``flock`` on POSIX, ``msvcrt.locking`` on Windows: the system drops it
when the process dies), so the next save or open of that file
(:func:`remove_stale_temporaries`) removes the temporaries of its own name that no process
holds, and only those. They start with a dot (hidden on POSIX; on Windows marked hidden while
they exist) and do not end in ``.prm``, so File → Open does not list them.
"""

from __future__ import annotations

import contextlib
import os
import re
import secrets
import stat
import sys
from pathlib import Path
from typing import IO

BACKUP_SUFFIX = ".bak"
_TOKEN_HEX = 8  # secrets.token_hex(4)
_ATTEMPTS = 5  # fresh names tried when a cleaner raced the creation of a temporary file


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


def temporary_pattern(target: Path) -> re.Pattern[str]:
    """The names of ``target``'s temporary files (``.valve.prm.0123abcd.tmp``)."""
    return re.compile(rf"\.{re.escape(target.name)}\.[0-9a-f]{{{_TOKEN_HEX}}}\.tmp")


def remove_stale_temporaries(path: Path) -> list[Path]:
    """Remove the temporary files a killed save of ``path`` (or of its ``.bak``) left behind:
    only names of :func:`temporary_pattern`, only those no process holds locked (a save that
    is still running keeps its own). Returns what was removed; never raises."""
    target = path.absolute()
    patterns = [temporary_pattern(target), temporary_pattern(_backup_of(target))]
    try:
        names = [n for n in os.listdir(target.parent) if any(p.fullmatch(n) for p in patterns)]
    except OSError:
        return []
    return [target.parent / n for n in names if _remove_if_unheld(target.parent / n)]


def _backup_of(target: Path) -> Path:
    return target.with_name(target.name + BACKUP_SUFFIX)


def _remove_if_unheld(temp: Path) -> bool:
    try:
        fd = os.open(temp, os.O_RDWR | getattr(os, "O_BINARY", 0))
    except OSError:
        return False
    try:
        if not _try_lock(fd) or not _names(temp, fd):
            return False  # a save in progress holds it (or it is gone)
        if os.name == "nt":  # Windows deletes no open file; nobody writes this name again
            os.close(fd)
            fd = -1
        os.unlink(temp)
        return True
    except OSError:
        return False
    finally:
        if fd >= 0:
            os.close(fd)


def _try_lock(fd: int) -> bool:
    """Take an exclusive lock on the open file ``fd`` without waiting (False: held)."""
    try:
        if sys.platform == "win32":
            import msvcrt

            msvcrt.locking(fd, msvcrt.LK_NBLCK, 1)
        else:
            import fcntl

            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return False
    return True


def _names(path: Path, fd: int) -> bool:
    """True while ``path`` is the file open as ``fd`` (not removed or replaced meanwhile)."""
    try:
        return os.path.samestat(os.stat(path), os.fstat(fd))
    except OSError:
        return False


def _set_hidden(path: Path, hidden: bool) -> None:
    """Windows: the hidden attribute (a dot does not hide a file there); elsewhere nothing."""
    if sys.platform == "win32":
        import ctypes

        attribute = 0x2 if hidden else 0x80  # FILE_ATTRIBUTE_HIDDEN, FILE_ATTRIBUTE_NORMAL
        ctypes.windll.kernel32.SetFileAttributesW(str(path), attribute)


def _create_locked(target: Path) -> tuple[Path, int]:
    """A new temporary file beside ``target``, open and locked by this process."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    for _attempt in range(_ATTEMPTS):
        temp = target.with_name(f".{target.name}.{secrets.token_hex(_TOKEN_HEX // 2)}.tmp")
        fd = os.open(temp, flags, 0o666)  # the umask applies, as for any new file
        if _try_lock(fd) and _names(temp, fd):
            _set_hidden(temp, True)
            return temp, fd
        os.close(fd)  # a cleaner took it between creation and lock (and removes it)
    raise OSError(f"cannot create a temporary file beside {target}")


def _replace(target: Path, data: bytes, mode: int | None) -> None:
    remove_stale_temporaries(target)
    temp, fd = _create_locked(target)
    try:
        with os.fdopen(fd, "wb") as stream:
            _write_data(stream, data)
            stream.flush()
            os.fsync(stream.fileno())
            if mode is not None:
                os.chmod(temp, mode)
            _set_hidden(temp, False)  # os.replace carries the attributes to the target
            if os.name != "nt":
                os.replace(temp, target)  # still locked: no cleaner takes it meanwhile
        if os.name == "nt":
            os.replace(temp, target)  # Windows renames no open file
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
