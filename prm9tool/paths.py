"""Where prm9tool keeps its own data: backups, emulated valves' memories, the user's spools.

One definition for every layer (the device layer's emulator stores there too). No Qt. The
platform's conventions come from ``platformdirs``:

========  ===============================================  =====================================
platform  data (backups, emulated valves, history, spools)  remembered settings (QSettings)
========  ===============================================  =====================================
Linux     ``$XDG_DATA_HOME/prm9tool`` (``~/.local/share``)  ``$XDG_CONFIG_HOME/prm9tool``
Windows   ``%LOCALAPPDATA%\\prm9tool``                      ``%APPDATA%\\prm9tool\\prm9tool.ini``
macOS     ``~/Library/Application Support/prm9tool``        ``~/Library/Preferences`` (Qt's own)
========  ===============================================  =====================================

Data is local (``%LOCALAPPDATA%``: it can be large and belongs to this PC), the settings roam
with the user's profile (``%APPDATA%``). Before platformdirs, macOS used the XDG folder
(``~/.local/share/prm9tool``): a data folder found there and not at the new place is moved over
once (read where it is when it cannot be moved), so no user's data vanishes.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from platformdirs.api import PlatformDirsABC
from platformdirs.macos import MacOS
from platformdirs.unix import Unix
from platformdirs.windows import Windows

APP = "prm9tool"


def user_data_dir() -> Path:
    """prm9tool's data folder (``PRM9TOOL_DATA_DIR`` overrides the platform default)."""
    override = os.environ.get("PRM9TOOL_DATA_DIR")
    if override:
        return Path(override)
    folder = Path(_dirs(roaming=False).user_data_dir)
    legacy = _legacy_data_dir()
    if legacy is None or legacy == folder or folder.exists() or not legacy.is_dir():
        return folder
    try:  # the folder of an earlier version on this platform: moved once
        folder.parent.mkdir(parents=True, exist_ok=True)
        legacy.rename(folder)
    except OSError:  # another file system, no rights: used where it is
        return legacy
    return folder


def settings_dir() -> Path:
    """The folder of the remembered settings (``%APPDATA%\\prm9tool`` on Windows,
    ``$XDG_CONFIG_HOME/prm9tool`` on Linux). Qt keeps its own place on macOS."""
    return Path(_dirs(roaming=True).user_config_dir)


def _dirs(*, roaming: bool) -> PlatformDirsABC:
    """platformdirs' conventions of the platform this runs on, chosen at each call (not at
    import, as ``platformdirs.user_data_dir`` does: the tests fake the platform). The modules
    are imported above, on the real platform: each reads ``sys.platform`` as it loads."""
    dirs: type[PlatformDirsABC] = Unix
    if sys.platform == "win32":
        dirs = Windows
    elif sys.platform == "darwin":
        dirs = MacOS
    return dirs(APP, appauthor=False, roaming=roaming)


def _legacy_data_dir() -> Path | None:
    """Where a version before platformdirs kept the data on this platform, if elsewhere."""
    if sys.platform == "darwin":
        base = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
        return Path(base) / APP
    return None  # Linux (XDG) and Windows (%LOCALAPPDATA%) kept their places
