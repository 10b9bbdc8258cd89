"""The single executable against the pip-installed program: size, and start-up to the main window.

Both start ``--emulator`` offscreen with ``PRM9TOOL_STARTUP_PROBE`` (the program prints when its
window is shown, then closes); each figure is the median of fresh processes with settings and
emulator data in a temporary folder. The one-file build unpacks itself into the user's cache on
its first start and checks that copy at every later start: its first start (empty cache) is
reported apart from the median of later starts. The one folder's first start is its first run
after the build.

Run (after ``python tools/build_executable.py --mode both``):
    QT_QPA_PLATFORM=offscreen python benchmarks/bench_executable.py [--runs N] [--quick]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ONEFILE = ROOT / "dist" / "prm9tool"
ONEDIR = ROOT / "dist" / "prm9tool-folder" / "prm9tool"


def start_once(command: list[str], cache: str) -> float:
    """Seconds from process start to the main window shown (the one file unpacked in ``cache``)."""
    with tempfile.TemporaryDirectory() as folder:
        env = dict(os.environ, QT_QPA_PLATFORM="offscreen", PRM9TOOL_STARTUP_PROBE="0")
        env.update(XDG_CONFIG_HOME=f"{folder}/config", PRM9TOOL_DATA_DIR=f"{folder}/data")
        env.update(XDG_CACHE_HOME=cache)
        env.pop("PRM9TOOL_EXE_CACHE", None)
        start = time.time()
        try:
            done = subprocess.run(
                [*command, "--emulator"], env=env, capture_output=True, text=True, timeout=120
            )
        except subprocess.TimeoutExpired as exc:  # say what it printed: why it did not end
            raise RuntimeError(
                f"{command[0]} did not end within 120 s after its window:\n"
                f"{_text(exc.stdout)}\n{_text(exc.stderr)}"
            ) from None
    for line in done.stdout.splitlines():
        if line.startswith("shown "):
            return float(line.split()[1]) - start
    raise RuntimeError(f"{command[0]} showed no window:\n{done.stdout}\n{done.stderr}")


def _text(output: bytes | str | None) -> str:
    return output.decode(errors="replace") if isinstance(output, bytes) else output or ""


def size_mb(path: Path) -> float:
    """Size of the one-file executable, or of the whole folder of a one-folder build, in MB
    (its symbolic links not counted twice)."""
    if path == ONEFILE:
        return path.stat().st_size / 1e6
    files = [p for p in path.parent.rglob("*") if p.is_file() and not p.is_symlink()]
    return sum(p.stat().st_size for p in files) / 1e6


def main() -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--quick", action="store_true", help="a smoke run: one start each")
    args = parser.parse_args()
    runs = 1 if args.quick else args.runs
    builds = [(label, path) for label, path in (("one file", ONEFILE), ("one folder", ONEDIR))
              if path.exists()]  # fmt: skip
    if not builds:
        print("no executable in dist/: build it with python tools/build_executable.py")
        return 0
    with tempfile.TemporaryDirectory() as cache:
        return measure(builds, runs, cache)


def measure(builds: list[tuple[str, Path]], runs: int, cache: str) -> int:
    """Print size and start-up of each build against the pip-installed program."""
    first = {label: start_once([str(path)], cache) for label, path in builds}
    # interleaved, so that a change in the machine's load hits every program alike
    times: dict[str, list[float]] = {label: [] for label, _ in [("pip", None), *builds]}
    for _ in range(runs):
        times["pip"].append(start_once([sys.executable, "-m", "prm9tool"], cache))
        for label, path in builds:
            times[label].append(start_once([str(path)], cache))
    reference = statistics.median(times["pip"])
    print(f"runs per figure: {runs} (median), Python {sys.version.split()[0]}")
    print(f"{'pip-installed prm9tool: window shown':44s} {reference * 1000:7.0f} ms   1.00 x")
    for label, path in builds:
        value = statistics.median(times[label])
        print(f"{label + ' (' + f'{size_mb(path):.1f} MB' + '): window shown':44s} "
              f"{value * 1000:7.0f} ms {value / reference:6.2f} x   "
              f"(first start {first[label] * 1000:.0f} ms, {first[label] / reference:.2f} x)")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
