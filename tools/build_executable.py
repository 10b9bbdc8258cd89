"""Build prm9tool as one executable file (``dist/prm9tool``, on Windows ``dist\\prm9tool.exe``)
or one folder (``dist/prm9tool-folder/``).

Run from a checkout with the build extra installed (``pip install -e '.[build]'``):

    python tools/build_executable.py                 # dist/prm9tool (one file)
    python tools/build_executable.py --mode onedir   # dist/prm9tool-folder/prm9tool
    python tools/build_executable.py --mode both

It stamps the git commit and the build date into the program (``prm9tool/_build_stamp.py``,
removed afterwards), renders the icon and runs PyInstaller on ``tools/prm9tool.spec`` (the one
folder). The one file is that folder packed (xz) behind a small launcher
(``tools/onefile_launcher.py``, built by PyInstaller as a one-file program of the Python runtime
only) that unpacks it once into the user's cache and checks it there at every start.
docs/executable.md says what to hand to whom and what differs on Windows and macOS.
"""

from __future__ import annotations

import argparse
import datetime
import hashlib
import json
import lzma
import os
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STAMP = ROOT / "prm9tool" / "_build_stamp.py"
SPEC = ROOT / "tools" / "prm9tool.spec"
LAUNCHER = ROOT / "tools" / "onefile_launcher.py"
sys.path.insert(0, str(ROOT / "tools"))
from onefile_launcher import MAGIC, TRAILER, file_digest  # noqa: E402

# xz preset of the one file's payload: 1 packs ~20 % smaller than PyInstaller's zlib and in
# about the time zlib takes; higher presets gain 4 % for three times the build time
XZ_PRESET = 1
# the launcher needs the Python runtime and these only (tarfile, lzma, hashlib's own BLAKE2b)
LAUNCHER_EXCLUDES = ("_hashlib", "_ssl", "ssl", "_bz2", "bz2", "_decimal", "decimal",
                     "unittest", "pydoc", "multiprocessing")  # fmt: skip


def main(argv: list[str] | None = None) -> int:
    """Build the executable(s); returns PyInstaller's exit code."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mode", choices=("onefile", "onedir", "both"), default="onefile")
    parser.add_argument("--dist", type=Path, default=ROOT / "dist", help="output folder")
    args = parser.parse_args(argv)
    # one work folder per platform: the Windows stage builds under Wine beside the Linux build
    work = ROOT / "build" / ("pyinstaller-windows" if sys.platform == "win32" else "pyinstaller")
    icon = _render_icon(work)
    _write_stamp()
    try:
        folder_dist = args.dist if args.mode != "onefile" else work / "folder-dist"
        code = _pyinstaller(SPEC, folder_dist, work / "onedir", icon)
        if code:
            return code
        folder = folder_dist / "prm9tool-folder"
        if args.mode != "onefile":
            print(f"built {folder} ({_size_mb(folder):.1f} MB)")  # noqa: T201
        if args.mode != "onedir":
            code = _pyinstaller(LAUNCHER, work / "launcher-dist", work / "launcher", icon)
            if code:
                return code
            target = onefile_target(args.dist)
            _pack(work / "launcher-dist" / _program_name(), folder, target)
            print(f"built {target} ({_size_mb(target):.1f} MB)")  # noqa: T201
    finally:
        STAMP.unlink(missing_ok=True)
    return 0


def _pyinstaller(script: Path, dist: Path, work: Path, icon: Path | None) -> int:
    """Run PyInstaller on the spec (the one folder) or on the launcher script (one file)."""
    command = [sys.executable, "-m", "PyInstaller", "--noconfirm", "--clean", "--log-level",
               "WARN", "--distpath", str(dist), "--workpath", str(work)]  # fmt: skip
    if script.suffix == ".py":
        command += ["--onefile", "--console", "--name", "prm9tool", "--specpath", str(work)]
        command += [arg for name in LAUNCHER_EXCLUDES for arg in ("--exclude-module", name)]
        command += ["--icon", str(icon)] if icon else []
    env = dict(os.environ, PRM9TOOL_BUILD_ICON=str(icon or ""))
    return subprocess.call([*command, str(script)], cwd=ROOT, env=env)


def _pack(launcher: Path, folder: Path, target: Path) -> None:
    """``target`` = the launcher carrying the folder as an xz tarball, its manifest (every file's
    size and BLAKE2b digest) and a trailer saying where they are."""
    files: dict[str, list] = {}
    for path in sorted(folder.rglob("*")):
        name = path.relative_to(folder).as_posix()
        if path.is_symlink():
            files[name] = [len(os.fsencode(os.readlink(path))), os.readlink(path)]
        elif path.is_file():
            files[name] = [path.stat().st_size, file_digest(path)]
    identity = hashlib.sha256(json.dumps(files, sort_keys=True).encode()).hexdigest()[:32]
    manifest = json.dumps({"id": identity, "program": _program_name(), "files": files}).encode()
    target.parent.mkdir(parents=True, exist_ok=True)
    payload = target.with_name(target.name + ".payload")
    with (
        lzma.open(payload, "wb", preset=XZ_PRESET) as packed,
        tarfile.open(fileobj=packed, mode="w|", format=tarfile.PAX_FORMAT) as archive,
    ):
        for path in sorted(folder.iterdir()):
            archive.add(path, arcname=path.name, filter=_anonymous)
    # the payload, its manifest and the trailer with their sizes
    with payload.open("ab") as tail:
        size = tail.tell()
        tail.write(manifest)
        tail.write(TRAILER.pack(MAGIC, size, len(manifest)))
    # PyInstaller's launcher finds its archive by scanning the file from its end for this
    # pattern: appended after the archive (Windows, macOS), the payload must not contain it
    cookie = bytes([0x4D, 0x45, 0x49, 0x0C, 0x0B, 0x0A, 0x0B, 0x0E])
    if cookie in payload.read_bytes():
        raise SystemExit(f"{payload}: the payload happens to contain PyInstaller's cookie")
    if launcher.read_bytes()[:4] == b"\x7fELF":
        _elf_section(launcher, payload, target)
    else:  # Windows, macOS (untested): appended, found from the end of the file
        with target.open("wb") as out, launcher.open("rb") as head, payload.open("rb") as body:
            shutil.copyfileobj(head, out)
            shutil.copyfileobj(body, out)
    payload.unlink()
    target.chmod(0o755)


def _elf_section(launcher: Path, payload: Path, target: Path) -> None:
    """The payload as ELF section ``prm9payload`` placed before PyInstaller's ``pydata`` (its
    archive must stay last: PyInstaller's launcher looks for it from the end of the file)."""
    archive = payload.with_name("pydata.bin")
    stripped = payload.with_name("launcher-stripped")
    with_payload = payload.with_name("launcher-payload")
    for command in (
        ["objcopy", f"--dump-section=pydata={archive}", str(launcher), str(stripped)],
        ["objcopy", "--remove-section=pydata", str(stripped)],
        ["objcopy", f"--add-section=prm9payload={payload}", str(stripped), str(with_payload)],
        ["objcopy", f"--add-section=pydata={archive}", str(with_payload), str(target)],
    ):  # fmt: skip
        subprocess.run(command, check=True)
    for path in (archive, stripped, with_payload):
        path.unlink()


def _anonymous(member: tarfile.TarInfo) -> tarfile.TarInfo:
    """No builder's user or group in the payload: the files belong to whoever unpacks them."""
    member.uid = member.gid = 0
    member.uname = member.gname = ""
    return member


def _program_name() -> str:
    return "prm9tool.exe" if sys.platform == "win32" else "prm9tool"


def onefile_target(dist: Path) -> Path:
    """The one file: ``dist/prm9tool``, on Windows ``dist\\prm9tool.exe`` (Explorer starts
    only a file named so, and a .prm file can be opened with it)."""
    return dist / _program_name()


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
    files = [path] if path.is_file() else [p for p in path.rglob("*") if not p.is_symlink()]
    files = [p for p in files if p.is_file()]
    return sum(p.stat().st_size for p in files) / 1e6


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    sys.exit(main())
