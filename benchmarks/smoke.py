"""Run every benchmark in its smoke mode (``--quick``) and fail when one crashes.

Benchmarks rot when nothing runs them (issue 25 item 18): CI runs this after the tests.
Each benchmark gets a few seconds; the figures of a smoke run mean nothing, only that the
benchmark still runs through the program's public interfaces.

    QT_QPA_PLATFORM=offscreen .venv/bin/python benchmarks/smoke.py [bench_prm ...]
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

BENCHMARKS = Path(__file__).resolve().parent
TIMEOUT_S = 300  # a smoke run takes seconds; this only stops a hung one


def main(argv: list[str]) -> int:
    """Run the named benchmarks (default: all) with ``--quick``; exit 1 if any failed."""
    names = argv or sorted(p.stem for p in BENCHMARKS.glob("bench_*.py"))
    env = dict(os.environ, QT_QPA_PLATFORM=os.environ.get("QT_QPA_PLATFORM", "offscreen"))
    failed: list[str] = []
    for name in names:
        started = time.monotonic()
        try:
            run = subprocess.run(
                [sys.executable, str(BENCHMARKS / f"{name}.py"), "--quick"],
                capture_output=True,
                text=True,
                env=env,
                timeout=TIMEOUT_S,
                check=False,
            )
            code, output = run.returncode, run.stdout + run.stderr
        except subprocess.TimeoutExpired as exc:
            code, output = -1, f"did not end within {TIMEOUT_S} s: {exc}"
        took = time.monotonic() - started
        print(
            f"{name:<20} {'ok' if code == 0 else f'FAILED ({code})':<12} {took:6.1f} s", flush=True
        )
        if code != 0:
            failed.append(name)
            print(output[-4000:], file=sys.stderr)
    if failed:
        print(f"benchmarks that crashed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
