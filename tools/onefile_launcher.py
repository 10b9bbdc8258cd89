"""The single executable's launcher: unpacks the program once into a private, verified cache.

``tools/build_executable.py`` builds this file with PyInstaller (a one-file program of the
Python runtime only, 14 MB) and adds the one-folder build of prm9tool to it as an xz tarball,
followed by a manifest (every file's path, size and BLAKE2b digest) and a trailer; on Linux all
of it sits in the ELF section ``prm9payload``. At start:

1. The cache folder is ``$PRM9TOOL_EXE_CACHE`` or the user's cache folder
   (``~/.cache/prm9tool/exe``, ``%LOCALAPPDATA%\\prm9tool\\exe``, ``~/Library/Caches/…``), one
   sub-folder per build, named by the manifest's hash, so a new build never runs old code.
2. It is used only when it belongs to the user and nobody else may write to it (mode 0700,
   no symbolic link); otherwise the program unpacks into a private temporary folder, deleted at
   exit — PyInstaller's own one-file behaviour.
3. The first start unpacks into a temporary folder beside it, checks every file against the
   manifest's digest, records each file's size and modification time, and renames the folder
   into place (atomic: a start running alongside sees the whole folder or none).
4. Every later start checks that the folder holds exactly the manifest's files with the
   recorded size and time and no write permission for others; any difference (a file changed,
   removed or added) and the folder is unpacked again.
5. The launcher then replaces itself with the cached program (``exec``; a child process on
   Windows), with the environment PyInstaller's launcher changed put back.

Folders of other builds unused for 30 days are removed. docs/executable.md says more.
"""

from __future__ import annotations

import hashlib
import json
import lzma
import os
import shutil
import stat
import struct
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

# payload, manifest and trailer follow each other: the trailer gives both sizes
TRAILER = struct.Struct("<8sQQ")  # magic, payload size, manifest size
MAGIC = b"PRM9PAY1"
SECTION = struct.Struct("<II16xQQ")  # ELF64 section header: name, type, offset, size
SECTION_NAME = b"prm9payload"
VERIFIED = ".verified.json"
PRUNE_AFTER_S = 30 * 86400
# POSIX: owner and mode bits say who may write; Windows reports every writable file as 0o666
# and every folder as 0o777 (its access control lists are not in st_mode), and the per-user
# %LOCALAPPDATA% is guarded by them
POSIX = os.name == "posix"


class LaunchError(Exception):
    """A reason the program cannot start, in words for the user."""


def main() -> int:
    """Start the program from the cache (or a temporary folder); returns its exit code."""
    exe = Path(sys.executable)
    try:
        manifest, offset, size = read_manifest(exe)
        root = cache_root()
        folder = cached_folder(exe, manifest, offset, size, root) if root else None
        if folder is None:
            return run_from_temporary(exe, manifest, offset, size)
        prune(root, keep=folder.name)
        return run(folder / manifest["program"])
    except LaunchError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)  # noqa: T201
        return 1


def read_manifest(exe: Path) -> tuple[dict, int, int]:
    """The manifest, and where in this file the payload starts and how long it is."""
    _start, end = payload_region(exe)
    with exe.open("rb") as file:
        file.seek(end - TRAILER.size)
        magic, size, manifest_size = TRAILER.unpack(file.read(TRAILER.size))
        if magic != MAGIC:
            raise LaunchError(f"{exe} carries no program (damaged or incomplete copy?)")
        file.seek(end - TRAILER.size - manifest_size)
        manifest = json.loads(file.read(manifest_size))
    return manifest, end - TRAILER.size - manifest_size - size, size


def payload_region(exe: Path) -> tuple[int, int]:
    """Where the payload, manifest and trailer are: the ELF section ``prm9payload`` (Linux), else
    the end of the file (appended).

    On Linux the build puts them into a section before PyInstaller's own ``pydata``: PyInstaller's
    launcher scans the file from its end for its archive, and 100 MB appended after it would
    cost that scan about a second at every start.
    """
    with exe.open("rb") as file:
        head = file.read(64)
        size = file.seek(0, os.SEEK_END)
        if head[:6] != b"\x7fELF\x02\x01":  # 64-bit little-endian ELF only
            return 0, size
        table, entry, count, names = struct.unpack_from("<Q10xHHH", head, 0x28)
        file.seek(table)
        sections = [SECTION.unpack_from(file.read(entry)) for _ in range(count)]
        file.seek(sections[names][2])
        strings = file.read(sections[names][3])
    for name, _kind, offset, length in sections:
        if strings[name : strings.index(b"\0", name)] == SECTION_NAME:
            return offset, offset + length
    return 0, size


def cache_root() -> Path | None:
    """The user's own cache folder for unpacked builds, or None when it is not safe to use."""
    override = os.environ.get("PRM9TOOL_EXE_CACHE")
    if override:
        root = Path(override)
    elif sys.platform == "win32":
        root = Path(os.environ.get("LOCALAPPDATA") or Path.home() / "AppData" / "Local")
        root = root / "prm9tool" / "exe"
    elif sys.platform == "darwin":
        root = Path.home() / "Library" / "Caches" / "prm9tool" / "exe"
    else:
        base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        root = Path(base) / "prm9tool" / "exe"
    try:
        root.mkdir(mode=0o700, parents=True, exist_ok=True)
    except OSError:
        return None
    return root if private(root) else None


def private(path: Path) -> bool:
    """True when ``path`` is a real folder of this user that no other user may write to."""
    try:
        info = os.lstat(path)
    except OSError:
        return False
    if not stat.S_ISDIR(info.st_mode):
        return False
    if not POSIX:
        return True  # per-user %LOCALAPPDATA%: Windows' own access control
    return info.st_uid == os.geteuid() and not info.st_mode & 0o022


def cached_folder(exe: Path, manifest: dict, offset: int, size: int, root: Path) -> Path | None:
    """The verified folder of this build in ``root``, unpacked first if needed (None: cannot)."""
    folder = root / manifest["id"]
    if verified(folder, manifest):
        return folder
    if folder.exists() or folder.is_symlink():
        _remove(folder)
    try:
        staging = Path(tempfile.mkdtemp(prefix=".unpack-", dir=root))
    except OSError:
        return None
    try:
        unpack(exe, offset, size, staging, manifest)
        try:
            os.rename(staging, folder)
        except OSError:
            _remove(staging)  # another start put the same build in place first
        return folder if verified(folder, manifest) else None
    except BaseException:
        _remove(staging)
        raise


def unpack(exe: Path, offset: int, size: int, target: Path, manifest: dict) -> None:
    """Unpack the payload into ``target``, check it against the manifest, record what it is."""
    try:
        with exe.open("rb") as file:
            file.seek(offset)
            with tarfile.open(fileobj=_Slice(file, size), mode="r|xz") as archive:
                archive.extractall(target, filter="data")
        # tar's data filter leaves folders to the umask: a 002 umask made them group-writable
        for name, info in entries(target).items():
            if name.endswith("/") and info.st_mode & 0o022:
                os.chmod(target / name, 0o755)
    except (tarfile.TarError, lzma.LZMAError, EOFError) as exc:
        raise LaunchError(f"the program in {exe} is damaged (copy it again): {exc}") from exc
    except OSError as exc:
        raise LaunchError(f"cannot unpack the program into {target}: {exc}") from exc
    files = manifest["files"]
    if {name for name in entries(target) if not name.endswith("/")} != set(files):
        raise LaunchError(f"the program in {exe} is incomplete (damaged copy?)")
    record = {}
    for name, (length, digest) in files.items():
        path = target / name
        info = os.lstat(path)
        if stat.S_ISLNK(info.st_mode):
            if os.readlink(path) != digest:
                raise LaunchError(f"{name} in {exe} is damaged")
        elif info.st_size != length or file_digest(path) != digest:
            raise LaunchError(f"{name} in {exe} is damaged (copy it again)")
        record[name] = [info.st_size, info.st_mtime_ns]
    (target / VERIFIED).write_text(json.dumps({"id": manifest["id"], "files": record}))


def verified(folder: Path, manifest: dict) -> bool:
    """True when ``folder`` holds exactly what was unpacked and checked, unchanged since."""
    if not private(folder):
        return False
    try:
        record = json.loads((folder / VERIFIED).read_text())
    except (OSError, ValueError):
        return False
    if record.get("id") != manifest["id"] or set(record["files"]) != set(manifest["files"]):
        return False
    uid = os.geteuid() if POSIX else None
    files = record["files"]
    found = entries(folder)
    found.pop(VERIFIED, None)
    if {name for name in found if not name.endswith("/")} != set(files):
        return False
    for name, info in found.items():
        if stat.S_ISLNK(info.st_mode):
            ok = [info.st_size, info.st_mtime_ns] == files[name]
        else:
            # the mode bits only where they say something (see POSIX): on Windows they would
            # call every file writable by others and unpack the program again at every start
            ok = uid is None or (not info.st_mode & 0o022 and info.st_uid == uid)
            ok = ok and (name.endswith("/") or [info.st_size, info.st_mtime_ns] == files[name])
        if not ok:
            return False
    return True


def prune(root: Path, keep: str) -> None:
    """Remove other builds' folders not checked for 30 days (an old copy re-unpacks if used)."""
    now = time.time()
    try:
        os.utime(root / keep / VERIFIED)
        for entry in root.iterdir():
            if entry.name == keep or entry.is_symlink():
                continue
            try:
                age = now - (entry / VERIFIED).stat().st_mtime
            except OSError:
                age = now - entry.lstat().st_mtime  # an unpacking that never finished
            if age > PRUNE_AFTER_S:
                _remove(entry)
    except OSError:
        pass  # tidying up is not worth failing the start for


def run(program: Path) -> int:
    """Replace this process with ``program`` (Windows: run it and return its exit code)."""
    argv = [str(program), *sys.argv[1:]]
    try:
        if os.name == "posix":
            os.execve(program, argv, program_environment())
        return subprocess.call(argv, env=program_environment())
    except OSError as exc:  # e.g. a cache on a file system mounted noexec
        raise LaunchError(
            f"cannot start {program}: {exc} (PRM9TOOL_EXE_CACHE=<folder> unpacks it elsewhere)"
        ) from exc


def run_from_temporary(exe: Path, manifest: dict, offset: int, size: int) -> int:
    """No usable cache: unpack into a private temporary folder, run, delete it afterwards."""
    folder = Path(tempfile.mkdtemp(prefix="prm9tool-"))
    try:
        unpack(exe, offset, size, folder, manifest)
        program = folder / manifest["program"]
        return subprocess.call([str(program), *sys.argv[1:]], env=program_environment())
    finally:
        _remove(folder)


def program_environment() -> dict[str, str]:
    """This environment without what PyInstaller's launcher changed for the launcher itself."""
    env = dict(os.environ)
    for name in ("LD_LIBRARY_PATH", "DYLD_LIBRARY_PATH", "LIBPATH"):
        original = env.pop(name + "_ORIG", None)
        env.pop(name, None)
        if original is not None:
            env[name] = original
    # the program is a PyInstaller build too: it must set itself up afresh
    env["PYINSTALLER_RESET_ENVIRONMENT"] = "1"
    return env


def entries(folder: Path) -> dict[str, os.stat_result]:
    """Every file and symbolic link under ``folder`` (relative POSIX path → lstat), and folders
    under the key ``name/``; symbolic links are not followed."""
    found: dict[str, os.stat_result] = {}
    for directory, subfolders, names in os.walk(folder):
        for name in subfolders + names:
            path = os.path.join(directory, name)
            info = os.lstat(path)
            relative = os.path.relpath(path, folder).replace(os.sep, "/")
            found[relative + ("/" if stat.S_ISDIR(info.st_mode) else "")] = info
    return found


def file_digest(path: Path) -> str:
    """BLAKE2b-256 of a file: Python's own, fast without OpenSSL (the launcher carries none)."""
    digest = hashlib.blake2b(digest_size=32)
    with path.open("rb") as file:
        while chunk := file.read(1 << 20):
            digest.update(chunk)
    return digest.hexdigest()


def _remove(path: Path) -> None:
    if path.is_symlink() or path.is_file():
        path.unlink(missing_ok=True)
    else:
        shutil.rmtree(path, ignore_errors=True)


class _Slice:
    """A read-only window of ``size`` bytes of an open file, from its current position."""

    def __init__(self, file, size: int) -> None:
        self._file = file
        self._left = size

    def read(self, count: int = -1) -> bytes:
        if count < 0 or count > self._left:
            count = self._left
        data = self._file.read(count)
        self._left -= len(data)
        return data


if __name__ == "__main__":
    sys.exit(main())
