"""The README's emulator, driven from the GUI (issue 14 items 10 and 12): a delivered E02S02-CA
valve waits for a CANopen master, the program says so and enables it; the emulated valve's
faults, inputs and cable are in the Valve menu, and the LEDs and error list react."""

from __future__ import annotations

import pytest
from support.gui_support import E02_CA, emulated, go_online, main_window
from support.waiting import AUTOTUNE_ON_A_VALVE_WORK, work_timeout_s

from prm9tool.device.emulator import Fault
from prm9tool.scope import Waveform
from prm9tool.views import prompts

TIMEOUT = 10_000
SERIAL = 4301


@pytest.fixture
def window(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path, E02_CA) as win:
        go_online(qtbot, win, f"{E02_CA}:{SERIAL}")
        emulated(SERIAL).advance(2.0)  # booted: pre-operational, INIT
        yield win


def test_the_status_bar_and_the_status_window_say_the_valve_waits_for_a_master(qtbot, window):
    label = window.status.status_label
    qtbot.waitUntil(lambda: "waiting for a CANopen master" in label.text(), timeout=TIMEOUT)
    status_window = window.show_status_window()
    panel = status_window.commissioning
    assert panel is not None
    qtbot.waitUntil(lambda: "waits for a CANopen master" in panel.reason.text(), timeout=TIMEOUT)
    assert "NMT pre-operational, device state INIT" in panel.reason.text()
    assert "Press NMT start, then Enable" in panel.reason.text()  # not "under Valve → Valve status"
    assert "Valve status" not in panel.reason.text()
    panel.buttons["nmt_start"].click()
    panel.buttons["enable"].click()
    qtbot.waitUntil(lambda: "follows its setpoint" in panel.reason.text(), timeout=TIMEOUT)
    assert status_window.fields["nmt"].text() == "operational"
    assert label.text() == "Status: ok"
    panel.buttons["disable"].click()
    qtbot.waitUntil(lambda: str(emulated(SERIAL).device_state) == "INIT", timeout=TIMEOUT)


def test_starting_the_generator_offers_to_enable_and_the_spool_moves(qtbot, window, answers):
    window.open_scope("position_actual")
    scope = window.views["scope"]
    qtbot.waitUntil(lambda: "waits for a CANopen master" in scope.status.text(), timeout=TIMEOUT)
    answers.answers += [prompts.Button.Yes, prompts.Button.Yes]  # safe to move; enable it
    scope.generator_panel.waveform.setCurrentIndex(
        scope.generator_panel.waveform.findData(Waveform.STEP)
    )
    scope.generator_panel.period.setValue(0.1)
    scope.generator_panel.button.click()
    assert "Enable it now" in answers.asked[1]
    valve = emulated(SERIAL)
    qtbot.waitUntil(lambda: str(valve.device_state) == "DEVICE_MODE_ACTIVE", timeout=TIMEOUT)
    qtbot.waitUntil(lambda: valve.signal("position_actual") > 2000, timeout=TIMEOUT)  # 20 %
    qtbot.waitUntil(lambda: "does not follow" not in scope.status.text(), timeout=TIMEOUT)
    scope.stop()


def test_an_injected_fault_lights_the_leds_and_fills_the_error_list(qtbot, window):
    menu = window.emulated_menu
    qtbot.waitUntil(lambda: menu.isEnabled() and "COIL_A_OPEN" in menu.fault_actions,
                    timeout=TIMEOUT)  # fmt: skip
    assert menu.fault_actions["COIL_A_OPEN"].text() == "Coil A disconnected"
    status_window = window.show_status_window()
    menu.fault_actions["POSITION_SENSOR_BREAK"].trigger()
    qtbot.waitUntil(lambda: status_window.errors.count() and "0x7300" in status_window.errors.item(0).text(),
                    timeout=TIMEOUT)  # fmt: skip
    assert status_window.leds[0].colour == "red" and status_window.leds[0].pattern == "1Hz"
    assert "0x7300" in window.status.status_label.text()
    assert menu.fault_actions["POSITION_SENSOR_BREAK"].isChecked()
    menu.fault_actions["POSITION_SENSOR_BREAK"].trigger()  # repaired
    qtbot.waitUntil(lambda: not emulated(SERIAL).injected(), timeout=TIMEOUT)


def test_the_inputs_dialog_sets_the_supply_and_the_switches(qtbot, window):
    dialog = window.emulated_menu.show_dialog()
    qtbot.waitUntil(dialog.isEnabled, timeout=TIMEOUT)
    assert dialog.fields["supply_voltage"].value() == 24.0
    assert dialog.switches["switch_baud"].isVisible()  # a -CA valve has its switches
    dialog.fields["supply_voltage"].setValue(18.0)  # as the arrows or Enter do
    qtbot.waitUntil(lambda: emulated(SERIAL).inputs()["supply_voltage"] == 18.0, timeout=TIMEOUT)
    dialog.switches["switch_node"].setCurrentIndex(0)
    dialog.switches["switch_node"].activated.emit(0)
    qtbot.waitUntil(lambda: emulated(SERIAL).switches == (6, 0), timeout=TIMEOUT)
    qtbot.waitUntil(lambda: "0x3410" in window.status.status_label.text(), timeout=TIMEOUT)


def test_the_node_id_switch_at_1_is_lss_and_the_valve_then_waits_for_an_lss_master(qtbot, window):
    dialog = window.emulated_menu.show_dialog()
    qtbot.waitUntil(dialog.isEnabled, timeout=TIMEOUT)
    combo = dialog.switches["switch_node"]
    assert [combo.itemText(p) for p in (0, 1, 2, 15)] == [
        "0 — node ID and bit rate by software (NODEID, BITRATE)",
        "1 — LSS: node ID from an LSS master, automatic bit rate",
        "2 — node 10",
        "F — node 75",
    ]
    combo.setCurrentIndex(1)
    combo.activated.emit(1)
    valve = emulated(SERIAL)
    qtbot.waitUntil(lambda: valve.switches == (6, 1), timeout=TIMEOUT)
    valve.restart()  # switches are read at power-up
    assert valve.lss_mode and valve.node_id == 0  # no node ID until an LSS master gives one


def test_pulling_the_cable_takes_the_program_offline_with_a_message(qtbot, window, answers):
    with qtbot.waitSignal(window.connection.lost, timeout=TIMEOUT):
        window.emulated_menu.cable_action.trigger()
    assert not window.connection.is_online
    assert not window.emulated_menu.isEnabled()


def test_a_valve_without_canopen_enables_itself_and_offers_no_commissioning(qtbot, tmp_path):
    with main_window(qtbot, tmp_path) as window:  # an E02 without -CA: analog only
        go_online(qtbot, window, "PRM9-06.3Z11/30-24E02S02:4302")
        emulated(4302).advance(2.0)
        panel = window.show_status_window().commissioning
        qtbot.waitUntil(lambda: "follows its setpoint" in panel.reason.text(), timeout=TIMEOUT)
        assert not any(button.isEnabled() for button in panel.buttons.values())
        assert window.status.status_label.text() == "Status: ok"


def test_a_valve_without_canopen_has_its_nmt_state_in_the_program_language(qtbot, tmp_path):
    """The German Valve status read "CANopen-NMT-Zustand: off" for a USB valve."""
    from prm9tool import i18n

    with main_window(qtbot, tmp_path) as window:
        go_online(qtbot, window, "PRM9-06.3Z11/30-24E04S02:4303")
        emulated(4303).advance(2.0)
        i18n.set_language("de")
        try:
            field = window.show_status_window().fields["nmt"]
            qtbot.waitUntil(lambda: field.text() == "aus (kein CANopen)", timeout=TIMEOUT)
        finally:
            i18n.set_language("en")


def test_a_tuning_test_on_a_waiting_valve_offers_the_enabling_first(
    qtbot, window, answers, monkeypatch
):
    """Autotune used to stop with "the valve does not follow its setpoint … nothing was
    tested" (in English in every language), while the scope's generator offers the enabling."""
    from PySide6.QtWidgets import QMessageBox

    from prm9tool.catalogue.commissioning import Blocker
    from prm9tool.online.valve_control import status_blocker

    window.show_tuning_window("position")
    tuning = window.tuning_window
    waiting = Blocker.WAITING_FOR_MASTER
    qtbot.waitUntil(lambda: status_blocker(tuning._status) is waiting, timeout=TIMEOUT)
    monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
    answers.answers.append(prompts.Button.Yes)  # at Basic: run it, accept after switching
    answers.answers.append(prompts.Button.Yes)  # enable it
    wait_s = work_timeout_s(AUTOTUNE_ON_A_VALVE_WORK)  # a fixed 30 s timed out on a busy PC
    tuning.autotune.run_button.click()
    assert "cannot be accepted: POSKP can only be changed at Expert" in answers.asked[-2]
    assert "Enable it now" in answers.asked[-1]
    qtbot.waitUntil(lambda: not tuning.runner.busy, timeout=round(wait_s * 1000))
    assert "POSKP: 0.4 → " in tuning.autotune.result.text(), tuning.status.text()


def _position(widget):
    return widget.mapTo(widget.window(), widget.rect().topLeft())


def test_after_nmt_start_valve_status_asks_only_for_enable_and_enter_enables_nothing(qtbot, window):
    """Issue 25 item 14: "Press NMT start, then Enable" stayed after NMT start, and Enable
    was the default button (Enter moved the valve)."""
    panel = window.show_status_window().commissioning
    qtbot.waitUntil(lambda: "Press NMT start, then Enable" in panel.reason.text(), timeout=TIMEOUT)
    assert not any(b.isDefault() or b.autoDefault() for b in panel.buttons.values())
    buttons = {name: _position(button) for name, button in panel.buttons.items()}
    panel.buttons["nmt_start"].click()
    qtbot.waitUntil(lambda: "operational on CANopen" in panel.reason.text(), timeout=TIMEOUT)
    assert "Press Enable" in panel.reason.text() and "NMT start" not in panel.reason.text()
    panel.buttons["enable"].click()
    qtbot.waitUntil(lambda: "follows its setpoint" in panel.reason.text(), timeout=TIMEOUT)
    assert {name: _position(button) for name, button in panel.buttons.items()} == buttons


def test_the_oscilloscopes_buttons_stay_where_they_are_whatever_the_message(qtbot, window):
    """Issue 25 item 14: the buttons under the plot moved when the status line changed its
    number of lines (clicks missed)."""
    window.open_scope("position_actual")
    scope = window.views["scope"]
    window.resize(1024, 700)
    qtbot.waitUntil(lambda: "waits for a CANopen master" in scope.status.text(), timeout=TIMEOUT)
    watched = [scope.generator_panel.button, scope.tuning_button, *scope.controls.findChildren(
        type(scope.tuning_button))]  # fmt: skip
    before = [_position(button) for button in watched]
    for text in ("", "Short.", " ".join(["A long message that wraps."] * 30)):
        scope._say(text)
        qtbot.wait(10)  # the layout settles in the event loop
        assert [_position(button) for button in watched] == before
    assert scope.status.toolTip()  # the cut message is whole in the tip
    # nor a long message of the main window's status bar (it wraps: the bar keeps two lines)
    window.statusBar().showMessage(" ".join(["The valve said something long."] * 12))
    qtbot.wait(10)
    assert [_position(button) for button in watched] == before


def test_a_fault_whose_error_display_ended_is_listed_and_enable_resets_it(qtbot, window):
    """Issue 30: after a fault the list said "No error." in FAULT_HOLD and Enable did nothing
    (08h was no edge of R: R was already 1 in DEVICE_MODE_ACTIVE)."""
    valve = emulated(SERIAL)
    status_window = window.show_status_window()
    panel = status_window.commissioning
    qtbot.waitUntil(lambda: "Press NMT start, then Enable" in panel.reason.text(), timeout=TIMEOUT)
    panel.buttons["nmt_start"].click()
    panel.buttons["enable"].click()
    qtbot.waitUntil(lambda: str(valve.device_state) == "DEVICE_MODE_ACTIVE", timeout=TIMEOUT)
    valve.inject(Fault.COIL_A_OPEN)
    valve.advance(0.2)
    with qtbot.waitSignal(window.connection.failed, timeout=TIMEOUT) as refused:
        panel.buttons["enable"].click()  # the cause is still there: the window says so
    assert "error 0x5411 (Solenoid A disconnected) is still present" in refused.args[0]
    valve.clear(Fault.COIL_A_OPEN)
    valve.advance(11.0)  # the error's display hold (manual §5.5) is over: no error active
    assert str(valve.device_state) == "FAULT_HOLD" and not valve.status().active_errors
    qtbot.waitUntil(lambda: "still holds the fault" in status_window.errors.item(0).text(),
                    timeout=TIMEOUT)  # fmt: skip
    assert "No error." not in status_window.errors.item(0).text()
    panel.buttons["enable"].click()
    qtbot.waitUntil(lambda: str(valve.device_state) == "DEVICE_MODE_ACTIVE", timeout=TIMEOUT)


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_the_valve_status_window_shows_its_bottom_edge(qtbot, window, language):
    """Issue 34 (a new user): the window opened lower than its wrapped texts need, so the
    LEDs' box lost its bottom edge; its least height now counts the wrapped lines."""
    from prm9tool import i18n

    i18n.set_language(language)
    try:
        status_window = window.show_status_window()
        layout = status_window.layout()
        qtbot.waitUntil(lambda: "CANopen" in status_window.commissioning.reason.text(),
                        timeout=TIMEOUT)  # fmt: skip
        leds = status_window._groups["leds"]

        def whole() -> bool:
            return (
                status_window.height() >= layout.totalHeightForWidth(status_window.width())
                and leds.height() >= leds.layout().totalHeightForWidth(leds.width())
                and leds.geometry().bottom() < status_window.height()
            )

        qtbot.waitUntil(whole, timeout=TIMEOUT)  # the layout follows the texts in the event loop
    finally:
        i18n.set_language("en")
