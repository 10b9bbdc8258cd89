"""What this prm9tool is: version, git commit, build date, Python and Qt — for ``--version`` and
Help → About.

A single executable carries a stamp written by ``tools/build_executable.py``
(``prm9tool/_build_stamp.py``, not in git); a checkout asks git for its commit. No Qt at import:
the Qt version is looked up only when asked for.
"""

from __future__ import annotations

import importlib
import platform
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from prm9tool._version import __version__


@dataclass(frozen=True, kw_only=True)
class BuildInfo:
    """Where this program came from. ``commit`` and ``built`` are "unknown" when nobody knows."""

    version: str
    commit: str
    built: str
    frozen: bool
    python: str

    def line(self, qt: str | None = None) -> str:
        """One line for ``--version``: ``prm9tool 0.1.0 (commit …, built …, Python …, Qt …)``."""
        parts = [f"commit {self.commit}", f"built {self.built}", f"Python {self.python}"]
        if qt:
            parts.append(f"Qt {qt}")
        kind = ", single executable" if self.frozen else ""
        return f"prm9tool {self.version} ({', '.join(parts)}{kind})"


def build_info() -> BuildInfo:
    """The stamp of a built executable, else the checkout's commit (git), else "unknown"."""
    frozen = bool(getattr(sys, "frozen", False))
    try:
        _build_stamp = importlib.import_module("prm9tool._build_stamp")
        commit, built = str(_build_stamp.COMMIT), str(_build_stamp.BUILT)
    except ImportError:
        commit, built = _git_commit(Path(__file__).resolve().parent.parent), "unknown"
    return BuildInfo(
        version=__version__,
        commit=commit,
        built=built,
        frozen=frozen,
        python=platform.python_version(),
    )


def qt_version() -> str | None:
    """The Qt version PySide6 runs on, or None without PySide6."""
    try:
        from PySide6.QtCore import qVersion
    except ImportError:
        return None
    return str(qVersion())


def _git_commit(root: Path) -> str:
    """The short commit of a git checkout at ``root`` (with "+dirty" for local changes)."""
    if not (root / ".git").exists():
        return "unknown"
    try:
        commit = subprocess.run(
            ["git", "-C", str(root), "describe", "--always", "--dirty=+dirty", "--abbrev=10"],
            capture_output=True,
            text=True,
            timeout=5,
            check=True,
        ).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return commit or "unknown"
