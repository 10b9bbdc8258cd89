"""A save killed half-way leaves its temporary file; the next save or open of that file
removes its own stale temporaries — only names of its own pattern, only those no process
holds (issue 34 item 21)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from prm9tool import atomicfile
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.prmfile import PrmContents, read_file, write_file

E02 = TypeKey.parse("PRM9-06.3Z11/30-24E02S02")
ROOT = Path(__file__).resolve().parents[1]
# a save that writes half its data, says so and then hangs (until it is killed)
_HANGING_SAVE = """
import sys, time
from pathlib import Path
from prm9tool import atomicfile
def half(stream, data):
    stream.write(data[: len(data) // 2]); stream.flush()
    print("writing", flush=True)
    time.sleep(600)
atomicfile._write_data = half
atomicfile.atomic_write(Path(sys.argv[1]), b"x" * 4000, backup=False)
"""


def _hanging_save(path: Path) -> subprocess.Popen[str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    process = subprocess.Popen(
        [sys.executable, "-c", _HANGING_SAVE, str(path)], stdout=subprocess.PIPE, text=True, env=env
    )
    assert process.stdout is not None and process.stdout.readline() == "writing\n"
    return process


def _kill(process: subprocess.Popen[str]) -> None:
    process.send_signal(signal.SIGKILL if os.name != "nt" else signal.SIGTERM)
    process.wait()
    assert process.stdout is not None
    process.stdout.close()


def _temporaries(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".tmp"))


@pytest.fixture
def saved(tmp_path) -> Path:
    path = tmp_path / "valve.prm"
    write_file(PrmContents.factory(E02), path)
    return path


@pytest.mark.parametrize("next_use", ["save", "open"])
def test_the_next_save_or_open_removes_what_a_killed_save_left(saved, next_use):
    before = saved.read_bytes()
    _kill(_hanging_save(saved))
    left = _temporaries(saved.parent)
    assert len(left) == 1 and atomicfile.temporary_pattern(saved).fullmatch(left[0])
    assert saved.read_bytes() == before  # the file itself is the old one
    if next_use == "save":
        write_file(PrmContents.factory(E02), saved)
    else:
        read_file(saved)
    assert _temporaries(saved.parent) == []


def test_a_temporary_another_process_is_writing_is_left_alone(saved):
    writer = _hanging_save(saved)
    try:
        held = _temporaries(saved.parent)
        read_file(saved)
        write_file(PrmContents.factory(E02), saved)  # a save beside it goes through
        assert _temporaries(saved.parent) == held
    finally:
        _kill(writer)
    assert atomicfile.remove_stale_temporaries(saved) == [saved.parent / held[0]]


def test_only_the_files_own_temporaries_are_removed(saved):
    _kill(_hanging_save(saved))
    other = saved.with_name("other.prm")
    write_file(PrmContents.factory(E02), other)
    _kill(_hanging_save(other))
    foreign = [".valve.prm.notmine.tmp", ".valve.prm.0123abcd.tmp.keep", "valve.prm.tmp", "x.tmp"]
    for name in foreign:
        (saved.parent / name).write_text("someone else's", encoding="utf-8")
    backup_leftover = saved.parent / ".valve.prm.bak.89abcdef.tmp"
    backup_leftover.write_text("a killed backup", encoding="utf-8")
    others = [n for n in _temporaries(saved.parent) if n.startswith(".other.prm.")]
    read_file(saved)
    assert len(others) == 1  # another file's: not this open's business
    assert _temporaries(saved.parent) == sorted(
        [*others, *(n for n in foreign if n[-4:] == ".tmp")]
    )
    assert (saved.parent / ".valve.prm.0123abcd.tmp.keep").exists()


def test_file_open_does_not_list_temporaries(qapp, saved):
    from PySide6.QtCore import QDir

    _kill(_hanging_save(saved))
    assert _temporaries(saved.parent)  # left until the next save or open of valve.prm
    listed = QDir(str(saved.parent)).entryList(["*.prm"], QDir.Filter.Files)
    assert listed == ["valve.prm"]
    everything = QDir(str(saved.parent)).entryList(["*"], QDir.Filter.Files)
    assert everything == ["valve.prm"]  # "All files (*)" shows no hidden file either
