"""The oscilloscope in the main window, online with an emulated valve (real session path)."""

from __future__ import annotations

import pytest
from gui_support import E02, emulated, go_online, main_window, record_prompts

from prm9tool.catalogue import CATALOGUE
from prm9tool.scope import GeneratorSettings, Waveform
from prm9tool.views import prompts

TIMEOUT = 10_000
SERIAL = 4101


@pytest.fixture
def answers(monkeypatch):
    return record_prompts(monkeypatch)


@pytest.fixture
def window(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path) as win:
        go_online(qtbot, win, f"{E02}:{SERIAL}")
        yield win


def _override_on(valve) -> int:
    return int(valve.read(*CATALOGUE["SETPOVRON"].key))


def test_red_dot_opens_the_scope_with_that_signal_and_samples_flow(qtbot, window):
    window.open_scope("position_actual")
    scope = window.views["scope"]
    assert window.current_view() == "scope"
    assert scope.channels.selected() == ["position_actual"]
    scope.start()
    qtbot.waitUntil(lambda: scope.capture is not None and scope.capture.buffer.total > 100,
                    timeout=TIMEOUT)  # fmt: skip
    assert scope.capture.keys == ["position_actual"]


def test_generator_drives_the_override_and_closing_the_window_switches_it_off(
    qtbot, window, answers
):
    window.open_scope("setpoint_raw")
    scope = window.views["scope"]
    answers.answers.append(prompts.Button.Yes)
    scope.generator_panel.waveform.setCurrentIndex(
        scope.generator_panel.waveform.findData(Waveform.STEP)
    )
    scope.generator_panel.button.click()
    assert "valve will move" in answers.asked[-1]
    valve = emulated(SERIAL)
    qtbot.waitUntil(lambda: _override_on(valve) == 1, timeout=TIMEOUT)
    window.close()
    assert not scope.generator.running
    assert _override_on(valve) == 0


def test_going_offline_stops_the_generator(qtbot, window):
    scope = window.views["scope"]
    scope.generator.start(GeneratorSettings(Waveform.SQUARE, 20.0, 0.0, 0.5))
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.connection.go_offline()
    assert not scope.generator.running
    assert not scope.generator_panel.isEnabled()
