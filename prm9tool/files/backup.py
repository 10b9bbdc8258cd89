"""Backups of a valve's own parameters, taken before the first upload to that valve.

The manual (§8.7.1) recommends saving the valve's data to a *.prm file before the first
change; the program does it automatically: before uploading to a valve whose serial number
has no backup yet, it downloads the valve's parameters into
``<user data dir>/backups/<serial>/<type key>_<serial>_<date-time>.prm``. No Qt.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Mapping
from dataclasses import replace
from datetime import datetime
from pathlib import Path
from typing import Any

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import FileFormatError, FileProblem
from prm9tool.files.atomicfile import atomic_write
from prm9tool.files.prmfile import BANNER, PrmContents, check_bytes, text_for, write_file
from prm9tool.paths import user_data_dir

Progress = Callable[[int, int, str], None]


def backup_dir(serial: int) -> Path:
    """Folder of the backups of the valve with ``serial``."""
    return user_data_dir() / "backups" / str(serial)


def existing_backups(serial: int) -> list[Path]:
    """Backups of that valve, oldest first."""
    folder = backup_dir(serial)
    return sorted(folder.glob("*.prm")) if folder.is_dir() else []


def write_backup(
    type_key: str, serial: int, firmware: str, values: Mapping[str, int | str]
) -> Path:
    """Write a backup file of what the valve holds, valid or not (:func:`write_device_file`);
    raises FileFormatError (nothing written) if the file cannot be written."""
    key = TypeKey.parse(type_key)
    stamp = datetime.now().strftime("%Y%m%d-%H%M%S")
    path = backup_dir(serial) / f"{str(key).replace('/', '_')}_{serial}_{stamp}.prm"
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        problem = FileProblem(0, f"cannot create the backup folder: {exc.strerror or exc}")
        raise FileFormatError(str(path.parent), [problem]) from exc
    contents = PrmContents(key, dict(values), serial, firmware or None)
    write_device_file(contents, path, backup=False)
    return path


def write_device_file(
    contents: PrmContents, path: str | os.PathLike[str], backup: bool = True
) -> list[FileProblem]:
    """Write the values a valve holds, also when they are not a valid parameter set.

    A valid set is written as by :func:`write_file`. A set that breaks the file's rules (a real
    valve may hold a curve the catalogue rejects) is written all the same, its values exactly
    as the valve holds them, with a comment block at the top that marks it invalid and names
    every problem; reading such a file reports those problems, so it is never uploaded as it
    is. Returns the problems (empty for a valid set). FileFormatError only if writing fails.
    """
    text = text_for(contents, path)
    errors = check_bytes(text.encode("utf-8")).errors
    if not errors:
        write_file(contents, path, backup=backup)
        return []
    marked = replace(contents, comments=dict(contents.comments))
    marked.comments["format"] = [*BANNER, *_invalid_marking(errors)]
    data = marked.to_text().encode("utf-8")
    try:
        atomic_write(Path(path), data, backup=backup)
    except OSError as exc:
        problem = FileProblem(0, f"cannot save the file: {exc.strerror or exc}")
        raise FileFormatError(os.fspath(path), [problem]) from exc
    return errors


def _invalid_marking(errors: list[FileProblem]) -> list[str]:
    lines = [
        "#",
        "# NOT A VALID PARAMETER SET: these are the values the valve held, which break",
        "# the rules of a parameter file (correct them before uploading this file):",
    ]
    lines += [f"#   {problem.message}" for problem in errors]
    return [*lines, "#"]


def ensure_backup(
    session: Any, progress: Progress | None = None, cancel: threading.Event | None = None
) -> Path | None:
    """Back up the session's valve unless it has a backup already; returns the new file."""
    info = session.info
    if existing_backups(info.serial):
        return None
    values = session.download(progress, cancel)
    return write_backup(info.type_key, info.serial, info.firmware, values)
