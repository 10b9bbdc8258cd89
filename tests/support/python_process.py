"""Run a fresh Python process for a test: the command line, a start without a display, a
program whose environment (scale factor, missing libraries) must be set before it starts."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Mapping
from pathlib import Path


def run_python(
    *args: str, env: Mapping[str, str], cwd: Path | None = None, timeout: float = 120
) -> subprocess.CompletedProcess[str]:
    """``python ARGS`` (e.g. ``-m prm9tool …`` or ``-c CODE``); its output as text, never raises."""
    return subprocess.run(
        [sys.executable, *args],
        cwd=cwd,
        env=dict(env),
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )
