"""Build prm9tool as one executable file (``dist/prm9tool``) or one folder (``dist/prm9tool-folder/``).

Run from a checkout with the build extra installed (``pip install -e '.[build]'``):

    python tools/build_executable.py                 # dist/prm9tool (one file)
    python tools/build_executable.py --mode onedir   # dist/prm9tool-folder/prm9tool
    python tools/build_executable.py --mode both

It stamps the git commit and the build date into the program (``prm9tool/_build_stamp.py``,
removed afterwards), renders the icon and runs PyInstaller on ``tools/prm9tool.spec``.
docs/executable.md says what to hand to whom and what differs on Windows and macOS.
"""

from __future__ import annotations

import argparse
import datetime
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STAMP = ROOT / "prm9tool" / "_build_stamp.py"
SPEC = ROOT / "tools" / "prm9tool.spec"


def main(argv: list[str] | None = None) -> int:
    """Build the executable(s); returns PyInstaller's exit code."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mode", choices=("onefile", "onedir", "both"), default="onefile")
    parser.add_argument("--dist", type=Path, default=ROOT / "dist", help="output folder")
    args = parser.parse_args(argv)
    work = ROOT / "build" / "pyinstaller"
    icon = _render_icon(work)
    _write_stamp()
    try:
        for mode in ("onefile", "onedir") if args.mode == "both" else (args.mode,):
            env = dict(os.environ, PRM9TOOL_BUILD_MODE=mode, PRM9TOOL_BUILD_ICON=str(icon or ""))
            command = [
                sys.executable,
                "-m",
                "PyInstaller",
                "--noconfirm",
                "--clean",
                "--log-level",
                "WARN",
                "--distpath",
                str(args.dist),
                "--workpath",
                str(work / mode),
                str(SPEC),
            ]
            code = subprocess.call(command, cwd=ROOT, env=env)
            if code:
                return code
            target = args.dist / ("prm9tool" if mode == "onefile" else "prm9tool-folder")
            print(f"built {target} ({_size_mb(target):.1f} MB)")  # noqa: T201
    finally:
        STAMP.unlink(missing_ok=True)
    return 0


def _write_stamp() -> None:
    """The commit and the date the built program reports in ``--version`` and About."""
    from prm9tool.buildinfo import _git_commit

    built = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    STAMP.write_text(
        f'"""Written by tools/build_executable.py; not in git."""\n\n'
        f"COMMIT = {_git_commit(ROOT)!r}\nBUILT = {built!r}\n",
        encoding="utf-8",
    )


def _render_icon(work: Path) -> Path | None:
    """resources/icons/app.svg as a 256 px PNG (None when Qt cannot render it here)."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    try:
        from PySide6.QtCore import Qt
        from PySide6.QtGui import QGuiApplication, QImage, QPainter
        from PySide6.QtSvg import QSvgRenderer
    except ImportError:
        return None
    _app = QGuiApplication.instance() or QGuiApplication([])
    image = QImage(256, 256, QImage.Format.Format_ARGB32)
    image.fill(Qt.GlobalColor.transparent)
    painter = QPainter(image)
    QSvgRenderer(str(ROOT / "resources" / "icons" / "app.svg")).render(painter)
    painter.end()
    work.mkdir(parents=True, exist_ok=True)
    target = work / "prm9tool.png"
    return target if image.save(str(target)) else None


def _size_mb(path: Path) -> float:
    files = [path] if path.is_file() else [p for p in path.rglob("*") if p.is_file()]
    return sum(p.stat().st_size for p in files) / 1e6


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    sys.exit(main())
