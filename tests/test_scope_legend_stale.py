"""The legend's "at stop:" values after the held recording is no longer shown (File → Open of
a *.prm file, going online with another valve): they belonged to that recording and go with
it, instead of standing above an empty plot as if they were the new document's or valve's."""

from __future__ import annotations

import numpy as np
import pytest
from support.gui_support import E02, go_online, main_window

from prm9tool.views.files import dialogs as file_dialogs

TIMEOUT = 10_000
SERIAL = 4101


@pytest.fixture
def window(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path) as win:
        go_online(qtbot, win, f"{E02}:{SERIAL}")
        _settled(qtbot, win, SERIAL)
        yield win


def _settled(qtbot, window, serial: int) -> None:
    """The untouched document took the valve's set (the comparison after going online)."""
    qtbot.waitUntil(lambda: window.doc.source_serial == serial, timeout=TIMEOUT)
    qtbot.waitUntil(lambda: not window.connection.is_busy, timeout=TIMEOUT)


def _recorded_and_stopped(qtbot, window):
    """The scope recorded two measuring points of the emulated valve and was stopped."""
    window.open_scope("position_actual")
    scope = window.views["scope"]
    scope.preselect("demand")
    scope.start()
    qtbot.waitUntil(lambda: scope.capture is not None and scope.capture.buffer.total > 200,
                    timeout=TIMEOUT)  # fmt: skip
    scope.stop()
    legend = [entry.value.text() for entry in scope.plot.legend[:2]]
    assert all(text.startswith("at stop: ") for text in legend), legend
    assert min(_points(curve) for curve in scope.plot.curves[:2]) > 200  # its trace shown
    return scope


def _points(curve) -> int:
    return 0 if curve.yData is None else len(curve.yData)  # all set, not the clipped view


def _legend(scope) -> list[str]:
    return [entry.value.text() for entry in scope.plot.legend[:2]]


def _nothing_held(scope, folder) -> None:
    """No trace, no "at stop:" value, no data behind cursors or export of a recording gone."""
    assert scope.channels.selected() == ["position_actual", "demand"]  # the same points
    assert [_points(curve) for curve in scope.plot.curves[:2]] == [0, 0]
    assert _legend(scope) == ["—", "—"]  # no "at stop:" value of a trace gone
    assert scope.capture is None and not scope.display.frozen
    assert len(scope.display.data()[0]) == 0  # no cursor read-out of what is not shown
    with pytest.raises(ValueError, match="Nothing recorded"):
        scope.export_csv(folder / "gone.csv", whole=True)


def test_file_open_drops_the_held_recording_and_its_values_at_stop(
    qtbot, window, tmp_path, monkeypatch, answers
):
    scope = _recorded_and_stopped(qtbot, window)
    path = tmp_path / "other.prm"
    assert window.files.save_to(path)
    monkeypatch.setattr(file_dialogs, "open_file_name", lambda *_a, **_k: (str(path), ""))
    window.commands["open"].trigger()  # File → Open…
    assert window.doc.path == path and window.current_view() == "scope"
    _nothing_held(scope, tmp_path)
    scope.start()  # a new recording shows its own values at once, unmarked
    qtbot.waitUntil(lambda: scope.capture.buffer.total > 10, timeout=TIMEOUT)
    qtbot.waitUntil(lambda: "—" not in "".join(_legend(scope)), timeout=TIMEOUT)
    assert not any(":" in text for text in _legend(scope))
    scope.stop()
    assert all(text.startswith("at stop: ") for text in _legend(scope))


def test_another_valve_drops_the_held_recording_of_the_previous_one(
    qtbot, window, tmp_path, answers
):
    scope = _recorded_and_stopped(qtbot, window)
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        assert window.valve.go_offline()  # Communication → Offline
    assert _legend(scope)[0].startswith("at stop: ")  # offline the old trace is still its own
    go_online(qtbot, window, f"{E02}:{SERIAL + 1}")  # the untouched document takes its set
    _settled(qtbot, window, SERIAL + 1)
    window.open_scope()
    assert window.current_view() == "scope" and not answers.asked
    _nothing_held(scope, tmp_path)


def test_a_trace_still_shown_keeps_its_values_at_stop(qtbot, window):
    """Switching views does not drop the recording: its trace and values at Stop stay."""
    scope = _recorded_and_stopped(qtbot, window)
    before, data = _legend(scope), scope.display.data()[1].copy()
    window.show_view("parameters")
    window.open_scope()
    assert _legend(scope) == before
    assert np.array_equal(scope.display.data()[1], data, equal_nan=True)


def test_another_point_after_stop_drops_the_trace_and_its_values_at_stop(qtbot):
    """The channels set anew clear the plot: the held recording's values go with it."""
    from support.scope_fakes import FakeConnection

    from prm9tool.model.document import ParameterDocument
    from prm9tool.views.scope.widget import ScopeWidget

    conn = FakeConnection()
    scope = ScopeWidget(conn, ParameterDocument(E02))
    qtbot.addWidget(scope)
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.full((100, 1), 8192))
    scope._redraw()
    scope.stop()
    assert scope.plot.legend[0].value.text() == "at stop: 50 %"
    scope.preselect("position_actual")
    assert scope.channels.selected() == ["demand", "position_actual"]
    assert [entry.value.text() for entry in scope.plot.legend[:2]] == ["—", "—"]
    assert scope.capture is None and len(scope.display.data()[0]) == 0
