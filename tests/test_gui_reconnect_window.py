"""The main window when the valve drops off and comes back: status bar, oscilloscope,
generator, unsaved online edits, an upload, a tuning test. Over USB (the emulated cable pulled
and plugged back in) and, where the state is the link's own business — the stream, the
generator, an upload, a tuning test —, also over CANopen: the valve leaves the bus and joins
again, and the tool's adapter goes bus-off and recovers (tests/support/reconnect_links.py). What the
status bar says of a bus-off: tests/test_can_reconnect.py."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from PySide6.QtWidgets import QDialog
from support.gui_support import E02, emulated, go_online, main_window
from support.reconnect_links import LINKS, online_window
from support.valve_sets import changed_set

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.canlink.rpdo_setpoint import DEADLINE_MS
from prm9tool.device.records import DeviceState
from prm9tool.scope import Waveform
from prm9tool.views import prompts
from prm9tool.views.online_dialogs import DiffChoice, OnlineDiffDialog

TIMEOUT = 10_000
SERIAL = 4301


@pytest.fixture
def window(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path) as win:
        win.connection.auto_reconnect = True  # as in the program (off in gui_support)
        go_online(qtbot, win, f"{E02}:{SERIAL}")
        qtbot.waitUntil(lambda: win.sync.active, timeout=TIMEOUT)
        yield win


@pytest.fixture(params=LINKS)
def link(request, qtbot, tmp_path, answers, data_dir, monkeypatch):
    """A window online with an emulated valve over each link (reconnect_links.Link)."""
    with online_window(qtbot, tmp_path, request.param, monkeypatch) as link:
        yield link


def pull_cable(qtbot, window):
    """Valve → Emulated valve → Pull the USB cable; returns once the window looks for it."""
    with qtbot.waitSignal(window.connection.reconnecting, timeout=TIMEOUT):
        window.emulated_menu.cable_action.trigger()
    assert not window.connection.is_online


def plug_back(qtbot, window):
    """Valve → Emulated valve → Plug the USB cable back in; returns once it is online."""
    assert window.emulated_menu.plug_action.isEnabled()
    with qtbot.waitSignal(window.connection.reconnected, timeout=TIMEOUT):
        window.emulated_menu.plug_action.trigger()


def valve_raw(mnemonic: str) -> int:
    return int(emulated(SERIAL).read(*CATALOGUE[mnemonic].key))


def test_idle_the_status_bar_counts_and_the_window_is_back_online(qtbot, window, answers, tmp_path):
    """The picture goes to ``$PRM9TOOL_SCREENSHOTS`` when set (README's is made with
    ``PRM9TOOL_SCREENSHOTS=docs/screenshots``, as tests/test_gui_smoke.py), else to tmp."""
    pull_cable(qtbot, window)
    mode = window.status.mode_label
    assert mode.text().startswith("Mode: RECONNECTING… ") and mode.text().endswith(" s")
    assert str(SERIAL) in mode.toolTip() and "nothing is written" in mode.toolTip()
    assert answers.informed == []  # no dialog in the way: the status bar says it
    assert "looking for it" in window.status.currentMessage()
    assert not window.emulated_menu.cable_action.isEnabled()
    status = window.status.status_label
    counted = []  # the seconds go on while it looks (the picture shows a few)
    window.connection.reconnecting.connect(counted.append)
    qtbot.waitUntil(lambda: bool(counted) and counted[-1] >= 2, timeout=TIMEOUT)
    assert mode.text().startswith(f"Mode: RECONNECTING… {int(counted[-1])} s")
    laid_out = lambda: mode.geometry().right() < status.geometry().left()  # noqa: E731
    qtbot.waitUntil(lambda: mode.width() >= mode.sizeHint().width() and laid_out(), timeout=TIMEOUT)
    folder = Path(os.environ.get("PRM9TOOL_SCREENSHOTS") or tmp_path)
    assert window.status.grab().save(str(folder / "status_bar_reconnecting.png"))
    plug_back(qtbot, window)
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert window.status.mode_label.text() == "Mode: ONLINE"
    assert window.status.currentMessage() == "Back online: document and valve agree"
    assert not window.emulated_menu.plug_action.isEnabled()


def test_the_oscilloscope_records_on_when_the_valve_is_back(qtbot, link):
    window = link.window
    window.open_scope("position_actual")
    scope = window.views["scope"]
    scope.start()
    qtbot.waitUntil(lambda: scope.capture is not None and scope.capture.buffer.total > 100,
                    timeout=TIMEOUT)  # fmt: skip
    link.pull()
    assert not scope.running and window.current_view() == "scope"  # the view stays
    link.plug()
    qtbot.waitUntil(lambda: scope.running, timeout=TIMEOUT)
    before = scope.capture.buffer.total
    qtbot.waitUntil(lambda: scope.capture.buffer.total > before + 100, timeout=TIMEOUT)


def test_a_recording_stopped_while_the_valve_is_away_stays_stopped(qtbot, window):
    window.open_scope("position_actual")
    scope = window.views["scope"]
    scope.start()
    qtbot.waitUntil(lambda: scope.capture is not None and scope.capture.buffer.total > 10,
                    timeout=TIMEOUT)  # fmt: skip
    pull_cable(qtbot, window)
    scope.stop()  # the user's Stop while it is looked for
    streams = []
    window.connection.stream_started.connect(streams.append)
    plug_back(qtbot, window)
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert not scope.running and streams == []


def test_live_values_flow_again(qtbot, link):
    link.pull()
    with qtbot.waitSignal(link.window.connection.live_values_changed, timeout=TIMEOUT):
        link.plug()


def generator_drives(link) -> bool:
    """The valve follows the generator: the override on (USB), or RPDO1 frames arriving under
    the reception deadline the generator armed (CANopen: a frame came since 0x1400/5 was set)."""
    if not link.canopen:
        return link.raw("SETPOVRON") == 1
    armed = [r.channel.deadline_ms for r in link.rig.slave._rpdo_logic]
    return link.raw("RPDO1TIMER") == DEADLINE_MS and any(d is not None for d in armed)


def test_the_generator_stops_with_the_link_and_is_not_restarted(qtbot, link, answers):
    """Over USB the valve drops the override 500 ms after the link; over CANopen the RPDO1
    deadline the generator armed ends the motion (fault 8100h), and once the valve is back the
    deadline is put back as it was. Nothing drives the setpoint then and the generator stays
    off: only the user starts it again."""
    window = link.window
    if link.canopen:  # RPDO1 drives the setpoint only of an operational, enabled valve
        window.control.nmt(NmtCommand.START)
        window.control.enable()
        qtbot.waitUntil(lambda: link.valve.status().device_state == DeviceState.DEVICE_MODE_ACTIVE,
                        timeout=TIMEOUT)  # fmt: skip
        qtbot.waitUntil(lambda: not window.connection.is_busy, timeout=TIMEOUT)
    window.open_scope("position_setpoint" if link.canopen else "setpoint_raw")
    scope = window.views["scope"]
    answers.answers.append(prompts.Button.Yes)
    panel = scope.generator_panel
    panel.waveform.setCurrentIndex(panel.waveform.findData(Waveform.STEP))
    panel.button.click()
    qtbot.waitUntil(lambda: generator_drives(link), timeout=TIMEOUT)
    link.pull()
    assert not scope.generator.running
    if link.canopen:  # away: the valve's deadline ends the motion
        qtbot.waitUntil(lambda: 0x8100 in link.valve.status().active_errors, timeout=TIMEOUT)
    said = []
    window.valve.message_posted.connect(said.append)
    link.plug()
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert not scope.generator.running  # it writes setpoints: only the user starts it again
    if not link.canopen:
        qtbot.waitUntil(lambda: link.raw("SETPOVRON") == 0, timeout=TIMEOUT)
    else:  # the deadline it armed is put back as it was, and the status bar says so
        assert link.raw("RPDO1TIMER") == 0
        assert any("is as before (RPDO1TIMER)" in text for text in said), said
        assert link.valve.status().device_state != DeviceState.DEVICE_MODE_ACTIVE


def test_unstored_online_edits_are_offered_not_sent(qtbot, window, monkeypatch):
    """The valve was power-cycled while away: it lost an edit that was not stored. The
    comparison shows it; the valve keeps its own value until the user decides."""
    before = valve_raw("THRESETP")
    window.doc.set_value("THRESETP", before + 100)
    qtbot.waitUntil(lambda: valve_raw("THRESETP") == before + 100, timeout=TIMEOUT)
    assert window.sync.unstored
    pull_cable(qtbot, window)
    emulated(SERIAL).restart()  # power cycle: the working values come from the EEPROM
    offered = []

    def decide(dialog):
        offered.append(valve_raw("THRESETP"))
        dialog.choice = DiffChoice.CANCEL
        return QDialog.DialogCode.Rejected

    monkeypatch.setattr(OnlineDiffDialog, "exec", decide)
    plug_back(qtbot, window)
    qtbot.waitUntil(lambda: bool(offered), timeout=TIMEOUT)
    assert offered == [before]  # nothing was sent before the user's answer
    qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)  # Cancel
    assert valve_raw("THRESETP") == before
    assert window.doc.value("THRESETP") == before + 100  # the edit is kept in the document


def test_an_upload_cut_off_reports_and_is_not_resumed(qtbot, link, answers, monkeypatch):
    window = link.window
    window.doc.set_value("DTAMP", 2000)
    qtbot.waitUntil(lambda: link.raw("DTAMP") == 2000, timeout=TIMEOUT)
    values = changed_set(window.doc.variant)  # every value differs: a long upload
    offered = []
    monkeypatch.setattr(
        OnlineDiffDialog,
        "exec",
        lambda d: (
            (offered.append(link.raw("LIMTA")), setattr(d, "choice", DiffChoice.CANCEL))
            and QDialog.DialogCode.Rejected
        ),
    )
    worker = window.connection._worker
    report_progress, cut = worker.progress, []

    def cut_in_the_middle(done, total, step):  # the worker thread, inside the upload
        if not cut and 0 < done < total and "write" in str(step):  # not the backup
            cut.append(done)
            link.pull_from_worker()
        report_progress(done, total, step)

    monkeypatch.setattr(worker, "progress", cut_in_the_middle)
    finished = []
    window.connection.operation_finished.connect(lambda name, _r: finished.append(name))
    window.valve.upload_values(values)
    qtbot.waitUntil(lambda: window.connection.is_reconnecting, timeout=TIMEOUT)
    link.plug()
    assert cut and "upload" not in finished
    report = answers.informed[-1]
    assert "Connection to the valve lost" in report and "upload failed while" in report
    assert "nothing is sent again by itself" in report
    assert "nothing was stored" in report  # what the valve holds: its stored set untouched
    qtbot.waitUntil(lambda: bool(offered) or window.sync.active, timeout=TIMEOUT)
    assert finished == ["compare"]  # the comparison; the upload did not run again by itself


def test_going_offline_stops_the_search(qtbot, window):
    pull_cable(qtbot, window)
    assert window.commands["offline"].isEnabled() and window.commands["online"].isEnabled()
    with qtbot.waitSignal(window.connection.reconnect_ended, timeout=TIMEOUT):
        window.commands["offline"].trigger()
    assert not window.connection.is_reconnecting
    assert window.status.mode_label.text() == "Mode: OFFLINE"
    assert not window.commands["offline"].isEnabled()


def test_a_tuning_test_cut_off_is_undone_once_the_valve_is_back(qtbot, link):
    """The test wrote a value, then the link went: the test stops with the link and, when the
    same valve is back, what it changed is written back (before the comparison) and the
    setpoint is the valve's own again."""
    from prm9tool.online.tuning_runner import ValveRunner

    before = link.raw("LIMTA")

    def procedure(rig):
        rig.write({"LIMTA": before - 100})
        assert link.raw("LIMTA") == before - 100
        link.pull_from_worker()
        rig.read(["LIMTA"])  # the link is gone: CommunicationError

    runner = ValveRunner(link.window.connection)
    with qtbot.waitSignal(runner.failed, timeout=TIMEOUT) as failed:
        runner.run("probe", procedure)
    assert failed.args[0] == "probe" and not runner.busy
    assert runner.to_restore == {"LIMTA": before}
    assert link.raw("LIMTA") == before - 100  # nothing could be written meanwhile
    qtbot.waitUntil(lambda: link.window.connection.is_reconnecting, timeout=TIMEOUT)
    with qtbot.waitSignal(runner.restored, timeout=TIMEOUT) as restored:
        link.plug()
    assert "restored (LIMTA)" in restored.args[0]
    assert link.raw("LIMTA") == before and runner.to_restore is None
    if not link.canopen:
        assert link.raw("SETPOVRON") == 0
