"""A file full of unknown names: bounded spelling suggestions for ``--check``, and File → Open
reads off the GUI thread (issue 15, item 16)."""

from __future__ import annotations

import difflib
import threading

from PySide6.QtCore import QTimer
from support.gui_support import E02

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files import prmcheck, prmfile


def _with_unknown_names(count: int, name: str = "LIMTAX{0}") -> bytes:
    text = prmfile.PrmContents.factory(TypeKey.parse(E02)).to_text()
    body = [line for line in text.split("\n") if line and not line.startswith("checksum")]
    extra = [f"{name.format(n)} = 1" for n in range(count)]
    return ("\n".join([*body, *extra, "checksum = crc32:00000000"]) + "\n").encode()


def test_spelling_suggestions_are_made_for_the_first_unknown_names_only(monkeypatch):
    calls: list[str] = []
    original = difflib.get_close_matches

    def counted(word, *args, **kwargs):
        calls.append(word)
        return original(word, *args, **kwargs)

    monkeypatch.setattr(prmcheck.difflib, "get_close_matches", counted)
    result = prmfile.check_bytes(_with_unknown_names(500))
    assert result.contents is not None and len(result.contents.unknown) == 500
    unknown = [str(p.message) for p in result.problems if "unknown parameter" in str(p.message)]
    assert len(unknown) == 500  # every unknown name is still reported and kept
    assert len(calls) == 20
    assert (
        unknown[0]
        == "unknown parameter 'LIMTAX0': kept and written back unchanged (did you mean LIMTA?)"
    )
    assert unknown[-1] == "unknown parameter 'LIMTAX499': kept and written back unchanged"


def _read_slowly(monkeypatch) -> dict[str, object]:
    """``prmfile.read_file`` records its thread and waits for the GUI thread to run a timer:
    it finishes when the GUI thread ran meanwhile; on the GUI thread it never could."""
    real_read = prmfile.read_file
    gui_ran = threading.Event()
    seen: dict[str, object] = {}

    def slow_read(where):
        seen["thread"] = threading.current_thread()
        seen["gui_ran_meanwhile"] = gui_ran.wait(timeout=3)
        return real_read(where)

    monkeypatch.setattr(prmfile, "read_file", slow_read)
    QTimer.singleShot(20, gui_ran.set)
    return seen


def test_opening_a_file_reads_it_off_the_gui_thread_while_the_window_keeps_working(
    window, tmp_path, monkeypatch
):
    path = tmp_path / "slow.prm"
    path.write_bytes(_with_unknown_names(3))
    seen = _read_slowly(monkeypatch)
    assert window.files.open_path(path, ask=False)
    assert seen["thread"] is not threading.main_thread()
    assert seen["gui_ran_meanwhile"] is True
    assert window.doc.path == path and len(window.doc.unknown_entries) == 3


def test_a_file_read_with_an_error_on_the_worker_thread_is_reported(window, tmp_path, answers):
    path = tmp_path / "broken.prm"
    path.write_text("format = prm9tool 1\ntype_key = PRM9-06.3Z11/30-24E02S02\nLIMTA = lots\n")
    assert not window.files.open_path(path, ask=False)
    assert "broken.prm:3: LIMTA: 'lots' is not a number" in answers.asked[-1]
    assert window.doc.path is None


def test_the_warnings_of_a_file_with_thousands_of_unknown_names_are_listed_in_part(
    window, tmp_path, answers
):
    path = tmp_path / "many.prm"
    path.write_bytes(_with_unknown_names(1000))
    assert window.files.open_path(path, ask=False)
    shown = answers.informed[-1].splitlines()
    assert "1001 warnings were found" in shown[0]  # 1000 unknown names and the checksum
    assert shown[-1] == "… and 801 more problems."
    assert len(shown) == 1 + 200 + 1
    assert len(window.doc.unknown_entries) == 1000


def test_opening_another_file_while_one_is_being_read_is_refused(window, tmp_path, monkeypatch):
    first, second = tmp_path / "first.prm", tmp_path / "second.prm"
    first.write_bytes(_with_unknown_names(1))
    second.write_bytes(_with_unknown_names(2))
    real_read = prmfile.read_file
    inner: list[bool] = []
    messages: list[str] = []
    window.files.message_posted.connect(messages.append)

    tried = threading.Event()

    def read_and_meanwhile_open_another(where):
        if where == first:  # the user drops the second file while the first is read
            tried.wait(timeout=3)
        return real_read(where)

    def open_the_second():
        inner.append(window.files.open_path(second, ask=False))
        tried.set()

    QTimer.singleShot(20, open_the_second)
    monkeypatch.setattr(prmfile, "read_file", read_and_meanwhile_open_another)
    assert window.files.open_path(first, ask=False)
    assert inner == [False] and "Still reading first.prm" in messages
    assert window.doc.path == first


def test_compare_with_file_reads_off_the_gui_thread_too(window, tmp_path, monkeypatch, answers):
    path = tmp_path / "other.prm"
    path.write_text("format = prm9tool 1\ngarbage\n", encoding="utf-8")
    seen = _read_slowly(monkeypatch)
    window.compare.compare_with_file(path)
    assert seen["thread"] is not threading.main_thread() and seen["gui_ran_meanwhile"] is True
    assert "other.prm cannot be compared" in answers.informed[-1]
