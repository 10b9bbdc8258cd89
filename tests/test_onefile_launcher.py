"""The single executable's launcher (tools/onefile_launcher.py) on a small packed folder: it
unpacks once into a private cache, checks the copy at every start, unpacks again what changed,
and never uses a cache folder that others may write to. No PyInstaller needed: the packing is
tools/build_executable.py's own, behind a stand-in launcher file."""

from __future__ import annotations

import importlib
import os
import sys
import time
from pathlib import Path

import pytest

TOOLS = Path(__file__).resolve().parent.parent / "tools"
sys.path.insert(0, str(TOOLS))
launcher = importlib.import_module("onefile_launcher")
build = importlib.import_module("build_executable")

pytestmark = pytest.mark.skipif(os.name != "posix", reason="POSIX permissions")


@pytest.fixture
def packed(tmp_path: Path) -> Path:
    """A one file: a stand-in launcher carrying a folder with a program, a library, a link."""
    folder = tmp_path / "prm9tool-folder"
    (folder / "_internal").mkdir(parents=True)
    (folder / "prm9tool").write_text("#!/bin/sh\necho started\n")
    (folder / "prm9tool").chmod(0o755)
    (folder / "_internal" / "libx.so.1").write_bytes(os.urandom(5000))
    (folder / "_internal" / "libx.so").symlink_to("libx.so.1")
    stand_in = tmp_path / "launcher"
    stand_in.write_bytes(b"MZ not an ELF launcher\n")
    target = tmp_path / "dist" / "prm9tool"
    build._pack(stand_in, folder, target)
    return target


def _start(exe: Path, root: Path) -> Path | None:
    manifest, offset, size = launcher.read_manifest(exe)
    return launcher.cached_folder(exe, manifest, offset, size, root)


def test_unpacks_once_into_a_private_folder_and_reuses_it(packed: Path, tmp_path: Path) -> None:
    root = tmp_path / "cache"
    root.mkdir(mode=0o700)
    folder = _start(packed, root)
    assert folder is not None and folder.parent == root
    assert (folder / "prm9tool").read_text().endswith("echo started\n")
    assert os.readlink(folder / "_internal" / "libx.so") == "libx.so.1"
    assert not folder.stat().st_mode & 0o077
    stamp = (folder / "_internal" / "libx.so.1").stat().st_mtime_ns
    assert _start(packed, root) == folder  # second start: checked, not unpacked again
    assert (folder / "_internal" / "libx.so.1").stat().st_mtime_ns == stamp
    assert [p.name for p in root.iterdir()] == [folder.name]  # no staging folder left


@pytest.mark.parametrize("change", ["append", "remove", "add", "group-writable"])
def test_a_changed_copy_is_unpacked_again(packed: Path, tmp_path: Path, change: str) -> None:
    root = tmp_path / "cache"
    root.mkdir(mode=0o700)
    folder = _start(packed, root)
    assert folder is not None
    library = folder / "_internal" / "libx.so.1"
    original = library.read_bytes()
    manifest = launcher.read_manifest(packed)[0]
    if change == "append":
        with library.open("ab") as file:
            file.write(b"injected")
    elif change == "remove":
        library.unlink()
    elif change == "add":
        (folder / "_internal" / "sitecustomize.py").write_text("print('injected')")
    else:
        library.chmod(0o666)
    assert not launcher.verified(folder, manifest)
    assert _start(packed, root) == folder
    assert library.read_bytes() == original
    assert not (folder / "_internal" / "sitecustomize.py").exists()
    assert launcher.verified(folder, manifest)


def test_a_cache_others_may_write_to_is_not_used(
    packed: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    shared = tmp_path / "shared"
    shared.mkdir()
    shared.chmod(0o777)
    monkeypatch.setenv("PRM9TOOL_EXE_CACHE", str(shared))
    assert launcher.cache_root() is None
    private = tmp_path / "mine"
    monkeypatch.setenv("PRM9TOOL_EXE_CACHE", str(private))
    assert launcher.cache_root() == private
    assert not private.stat().st_mode & 0o077


def test_a_damaged_payload_is_refused_and_leaves_nothing(packed: Path, tmp_path: Path) -> None:
    _manifest, offset, _size = launcher.read_manifest(packed)
    data = bytearray(packed.read_bytes())
    data[offset + 2000] ^= 0xFF  # a flipped byte inside the xz stream
    packed.write_bytes(bytes(data))
    root = tmp_path / "cache"
    root.mkdir(mode=0o700)
    with pytest.raises(launcher.LaunchError, match="is damaged"):
        _start(packed, root)
    assert list(root.iterdir()) == []


def test_a_file_without_payload_says_so(tmp_path: Path) -> None:
    plain = tmp_path / "prm9tool"
    plain.write_bytes(b"\0" * 100)
    with pytest.raises(launcher.LaunchError, match="carries no program"):
        launcher.read_manifest(plain)


def test_other_builds_unused_for_30_days_are_removed(packed: Path, tmp_path: Path) -> None:
    root = tmp_path / "cache"
    root.mkdir(mode=0o700)
    folder = _start(packed, root)
    assert folder is not None
    old, recent = root / ("0" * 32), root / ("1" * 32)
    for other in (old, recent):
        other.mkdir()
        (other / launcher.VERIFIED).write_text("{}")
    month_ago = time.time() - 31 * 86400
    os.utime(old / launcher.VERIFIED, (month_ago, month_ago))
    launcher.prune(root, keep=folder.name)
    assert sorted(p.name for p in root.iterdir()) == sorted([folder.name, recent.name])


def test_a_group_writable_umask_does_not_make_every_start_unpack(
    packed: Path, tmp_path: Path
) -> None:
    root = tmp_path / "cache"
    root.mkdir(mode=0o700)
    previous = os.umask(0o002)
    try:
        folder = _start(packed, root)
        assert folder is not None
        assert launcher.verified(folder, launcher.read_manifest(packed)[0])
    finally:
        os.umask(previous)
    assert not (folder / "_internal").stat().st_mode & 0o022


def test_windows_modes_do_not_make_every_start_unpack(
    packed: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Windows reports every writable file as 0o666 and every folder as 0o777 (its access
    control is not in st_mode): judged by mode bits, no start would ever find its folder
    verified, each would unpack the program again and remove the folder another start runs
    from (two starts at once failed with FileNotFoundError under Wine)."""
    root = tmp_path / "cache"
    root.mkdir(mode=0o700)
    folder = _start(packed, root)
    assert folder is not None
    for path in [folder, *folder.rglob("*")]:
        if not path.is_symlink():
            path.chmod(0o777 if path.is_dir() else 0o666)  # what os.stat says on Windows
    manifest = launcher.read_manifest(packed)[0]
    assert not launcher.verified(folder, manifest)  # on POSIX: others may write: unpack again
    monkeypatch.setattr(launcher, "POSIX", False)
    assert launcher.verified(folder, manifest)
    stamp = (folder / "_internal" / "libx.so.1").stat().st_mtime_ns
    assert _start(packed, root) == folder  # reused, not unpacked again
    assert (folder / "_internal" / "libx.so.1").stat().st_mtime_ns == stamp
    (folder / "_internal" / "libx.so.1").write_bytes(b"changed")
    assert not launcher.verified(folder, manifest)  # a changed file still unpacks again
