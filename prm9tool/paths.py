"""Where prm9tool keeps its own data: backups, emulated valves' memories, the user's spools.

One definition for every layer (the device layer's emulator stores there too). No Qt.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path


def user_data_dir() -> Path:
    """prm9tool's data folder (``PRM9TOOL_DATA_DIR`` overrides the platform default)."""
    override = os.environ.get("PRM9TOOL_DATA_DIR")
    if override:
        return Path(override)
    if sys.platform.startswith("win"):
        base = os.environ.get("LOCALAPPDATA") or str(Path.home() / "AppData" / "Local")
        return Path(base) / "prm9tool"
    base = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
    return Path(base) / "prm9tool"
