"""Valve → Enable valve / Disable valve: asked first, then the session's commissioning runs in
the worker and the status bar says the state reached (here over the emulated USB link; the
CANopen link adds NMT start, tests/test_can_link.py)."""

from __future__ import annotations

from gui_support import E02_CA, emulated, go_online, main_window, record_prompts

from prm9tool.views import prompts


def test_enable_asks_first_and_enables_then_disable_returns_to_init(qtbot, tmp_path, monkeypatch):
    answers = record_prompts(monkeypatch)
    with main_window(qtbot, tmp_path, E02_CA) as window:
        go_online(qtbot, window, f"{E02_CA}:4301")
        qtbot.waitUntil(lambda: not window.connection.is_busy, timeout=10_000)
        emulated(4301).advance(3.0)  # past its power-up
        answers.answers.append(prompts.Button.No)
        window.commands["enable_valve"].trigger()
        assert "the spool then follows its setpoint" in answers.asked[-1]
        assert emulated(4301).device_state == "INIT"  # refused: nothing sent
        answers.answers.append(prompts.Button.Yes)
        with qtbot.waitSignal(window.connection.operation_finished, timeout=10_000):
            window.commands["enable_valve"].trigger()
        qtbot.waitUntil(
            lambda: "DEVICE_MODE_ACTIVE" in window.status.currentMessage(), timeout=5_000
        )
        assert emulated(4301).device_state == "DEVICE_MODE_ACTIVE"
        with qtbot.waitSignal(window.connection.operation_finished, timeout=10_000):
            window.commands["disable_valve"].trigger()
        assert emulated(4301).device_state == "INIT"
