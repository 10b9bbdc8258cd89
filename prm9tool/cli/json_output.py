"""``--json [OUT.json]``, the same for every command that reports JSON: ``--json`` alone prints
it on standard output, ``--json OUT.json`` writes it to that file (atomically, UTF-8), as
``--characterize --json OUT.json`` writes its report. No Qt."""

from __future__ import annotations

import sys
from pathlib import Path

from prm9tool.errors import ExitCode


def emit_json(text: str, target: bool | str | None) -> int | None:
    """Print ``text`` or write it to ``target``; the exit code of a file that cannot be
    written (said on standard error), None when it went where it should."""
    if not isinstance(target, str):
        print(text)
        return None
    from prm9tool.atomicfile import atomic_write

    try:
        atomic_write(Path(target), (text + "\n").encode("utf-8"), backup=False)
    except OSError as exc:
        print(f"prm9tool: --json {target}: cannot write it: {exc}", file=sys.stderr)
        return ExitCode.USAGE
    return None
