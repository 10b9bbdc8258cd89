"""The oscilloscope in the main window, online with an emulated valve (real session path)."""

from __future__ import annotations

import pytest
from support.gui_support import E02, emulated, go_online, main_window, session_of

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import AccessDeniedError
from prm9tool.model.access import Access
from prm9tool.scope import GeneratorSettings, Waveform
from prm9tool.views import prompts

TIMEOUT = 10_000
SERIAL = 4101


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


def _generator_driving(qtbot, window):
    """The scope's generator running a square wave; the emulated valve's override is on."""
    scope = window.views["scope"]
    valve = emulated(SERIAL)
    scope.generator.start(GeneratorSettings(Waveform.SQUARE, 20.0, 0.0, 0.5))
    qtbot.waitUntil(lambda: _override_on(valve) == 1, timeout=TIMEOUT)
    return scope, valve


def test_going_offline_switches_the_override_off_before_disconnecting(qtbot, window):
    scope, valve = _generator_driving(qtbot, window)
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        assert window.valve.go_offline()  # Communication → Offline
    assert not scope.generator.running
    assert not scope.generator_panel.isEnabled()
    assert _override_on(valve) == 0


def test_an_override_left_on_by_a_lost_link_is_switched_off_at_the_next_connection(qtbot, window):
    scope, valve = _generator_driving(qtbot, window)
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.connection.go_offline()  # the link goes without the generator writing
    assert not scope.generator.running
    assert _override_on(valve) == 1  # the emulated valve stands still while offline
    go_online(qtbot, window, f"{E02}:{SERIAL}")
    qtbot.waitUntil(lambda: _override_on(valve) == 0, timeout=TIMEOUT)
    assert not scope.generator.running


def test_a_refused_generator_write_stops_the_generator_and_says_why(
    qtbot, window, answers, monkeypatch
):
    scope = window.views["scope"]
    session = session_of(window)
    write_many = session.write_many

    def refuse_the_setpoint(values):
        if "SETPOVR" in values:
            raise AccessDeniedError("SETPOVR: write access denied")
        write_many(values)

    monkeypatch.setattr(session, "write_many", refuse_the_setpoint)
    scope.generator.start(GeneratorSettings(Waveform.SQUARE, 20.0, 0.0, 0.5))
    qtbot.waitUntil(lambda: not scope.generator.running, timeout=TIMEOUT)
    assert "generator has stopped" in scope.status.text()
    assert "write access denied" in scope.status.text()
    assert not scope.generator_panel.button.isChecked()
    qtbot.waitUntil(lambda: _override_on(emulated(SERIAL)) == 0, timeout=TIMEOUT)


def test_a_tuning_test_stops_the_generator_first_and_measures_a_real_step(
    qtbot, window, monkeypatch, tmp_path
):
    """Autotune started while the generator drove the setpoint used to fit the generator's
    waveform (a model with a negative gain) and propose Kp 0.01, Ki 0."""
    from PySide6.QtWidgets import QMessageBox

    scope, valve = _generator_driving(qtbot, window)
    scope.preselect("position_actual")
    scope.start()
    qtbot.waitUntil(lambda: scope.receiving, timeout=TIMEOUT)
    monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
    window.access.set_level(Access.EXPERT)  # the result may be accepted: nothing to ask
    window.show_tuning_window("position")
    tuning = window.tuning_window
    profile = tmp_path / "short.toml"  # the acceptance check in real time: keep it short
    profile.write_text("[test]\nstep_amplitudes_pct = [25]\nstatic_period_s = 0.5\n")
    tuning.report.profile_path.setText(str(profile))
    tuning.autotune.run_button.click()
    assert not scope.generator.running
    assert "another operation" in scope.status.text()
    qtbot.waitUntil(lambda: not tuning.runner.busy, timeout=120_000)
    assert "— before: overshoot" in tuning.autotune.result.text(), tuning.autotune.result.text()
    assert _override_on(valve) == 0
    assert not scope.running and "recording stopped" in scope.status.text()


def test_closing_the_window_during_a_test_stops_it_and_puts_the_valve_back(
    qtbot, window, monkeypatch, tmp_path
):
    """Closing the main window while the Tuning window's end-of-line test ran left the test
    running in the worker thread past the window's end: the valve kept the test's transparent
    chain (threshold 0) and the override, and the thread died with "Signal source has been
    deleted"."""
    import threading

    from PySide6.QtWidgets import QMessageBox

    valve = emulated(SERIAL)
    threshold = int(valve.read(*CATALOGUE["THRESETP"].key))
    assert threshold != 0
    died: list[BaseException] = []
    monkeypatch.setattr(threading, "excepthook", lambda args: died.append(args.exc_value))
    monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
    window.show_tuning_window("position")
    tuning = window.tuning_window
    tuning.report.run_button.click()
    qtbot.waitUntil(lambda: _override_on(valve) == 1, timeout=TIMEOUT)  # the test drives it
    assert int(valve.read(*CATALOGUE["THRESETP"].key)) == 0  # the chain made transparent
    window.close()
    assert not tuning.runner.busy or tuning.runner.stop_requested.is_set()
    assert window.connection._worker._thread is None  # the worker ended within its time
    assert int(valve.read(*CATALOGUE["THRESETP"].key)) == threshold  # put back
    assert _override_on(valve) == 0 and died == []
