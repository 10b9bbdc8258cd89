"""The composition root: command line → window, file, emulator; run() until the window closes."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, QTimer
from PySide6.QtWidgets import QApplication
from support.gui_support import record_prompts

from prm9tool import app, i18n
from prm9tool.app import start_plan
from prm9tool.catalogue.typekey import USER_SPOOLS_FILE, TypeKey, load_user_spools
from prm9tool.cli.main import build_parser, main
from prm9tool.device import emulated_valves, factory
from prm9tool.errors import TypeKeyError
from prm9tool.files import prmfile

E04_CA = "PRM9-10.3Z11/60-24E04S02-CA"
TIMEOUT = 15_000


@pytest.fixture
def answers(monkeypatch, tmp_path):
    QSettings.setPath(QSettings.Format.NativeFormat, QSettings.Scope.UserScope, str(tmp_path))
    yield record_prompts(monkeypatch)
    emulated_valves.forget_emulated_valves()
    i18n.set_language("en")


def _args(*argv):
    return build_parser().parse_args(list(argv))


def test_plan_fills_in_the_emulator_defaults():
    assert start_plan.plan_from(_args("--emulator")).emulators == [
        "PRM9-06.3Z11/30-24E02S02-CA:1001"
    ]
    plan = start_plan.plan_from(_args("valve.prm", "--emulator", f"{E04_CA}:7"))
    assert plan.emulators == [f"{E04_CA}:7"] and str(plan.file) == "valve.prm"
    assert (
        start_plan.plan_from(_args()).emulators == [] and start_plan.plan_from(_args()).file is None
    )


def test_an_emulator_of_another_type_does_not_take_the_serial_of_a_stored_valve():
    """README first line (E02-CA, serial 1001, stored), then ``--emulator`` of an E04-CA: it
    used to fail on 1001's image ("the image belongs to a …E02S02-CA valve")."""
    e02 = "PRM9-06.3Z11/30-24E02S02-CA"
    with factory.open_session(f"emulator:{e02}:1001", paced=False) as session:
        session.store()
    emulated_valves.forget_emulated_valves()  # the first program has ended
    assert start_plan.plan_from(_args("--emulator", E04_CA)).emulators == [f"{E04_CA}:1002"]
    assert start_plan.plan_from(_args("--emulator")).emulators == [
        f"{e02}:1001"
    ]  # its values again
    with factory.open_session(f"emulator:{E04_CA}:1002", paced=False) as session:
        assert session.read("PCODE") == E04_CA


def test_a_file_on_the_command_line_is_opened(qtbot, tmp_path, answers):
    path = tmp_path / "valve.prm"
    prmfile.write_file(prmfile.PrmContents.factory(TypeKey.parse(E04_CA)), path)
    app.create_application()
    window = app.create_window(_args(str(path)))
    qtbot.addWidget(window)
    start_plan.start(window, start_plan.plan_from(_args(str(path))))
    assert window.doc.path == path and str(window.doc.type_key) == E04_CA
    window.connection.shutdown()


def test_emulator_on_the_command_line_goes_online_and_is_remembered(qtbot, answers):
    app.create_application()
    args = _args("--emulator", "prm9-10.3z11/60-24e04s02-ca:4201")
    window = app.create_window(args)
    qtbot.addWidget(window)
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        start_plan.start(window, start_plan.plan_from(args))
    assert window.connection.device.serial == 4201
    assert f"{E04_CA}:4201" in window.settings.value("hid/emulators")
    assert window.settings.value("hid/selected") == f"emulator:{E04_CA}:4201"
    window.connection.shutdown()


def test_a_twin_on_the_command_line_goes_online_as_its_valve(qtbot, answers, tmp_path):
    """``prm9tool --emulator twin:FILE`` (issue 31): the window goes online with the twin of
    the file's serial; a twin file that cannot be used is said in words, nothing online."""
    from dataclasses import replace

    from prm9tool.device.emulator.constants import PLANT
    from prm9tool.device.emulator.twinfile import write_twin
    from prm9tool.twin.identify import Fit

    path = tmp_path / "valve.toml"
    write_twin(path, Fit(replace(PLANT, force_n_per_a=25.0), (), 0.0, 0.0, 0.0, 0), 4301,
               E04_CA, "1.0.0", "steps", {"POSKP": 31})  # fmt: skip
    app.create_application()
    args = _args("--emulator", f"twin:{path}")
    window = app.create_window(args)
    qtbot.addWidget(window)
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        start_plan.start(window, start_plan.plan_from(args))
    assert window.connection.device.serial == 4301
    assert emulated_valves.EMULATED.valves[4301].plant.force_n_per_a == 25.0
    window.connection.shutdown()
    emulated_valves.forget_emulated_valves()
    bad = _args("--emulator", f"twin:{tmp_path / 'none.toml'}")
    window = app.create_window(bad)
    qtbot.addWidget(window)
    start_plan.start(window, start_plan.plan_from(bad))
    assert "cannot read the twin file" in answers.informed[-1]
    assert not window.connection.is_online


def test_the_emulated_ca_valve_joins_the_command_lines_can_bus_once_online(qtbot, answers):
    import can

    channel = "gui-app-join"
    listener = can.Bus(interface="virtual", channel=channel)
    try:
        app.create_application()
        args = _args("--emulator", f"{E04_CA}:4202", "--can-channel", channel)
        window = app.create_window(args)
        qtbot.addWidget(window)
        with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
            start_plan.start(window, start_plan.plan_from(args))
        node = emulated_valves.emulated_valve(E04_CA, 4202).node_id
        seen: list[int] = []

        def boot_up() -> bool:
            frame = listener.recv(0.05)
            if frame is not None:
                seen.append(frame.arbitration_id)
            return 0x700 + node in seen

        qtbot.waitUntil(boot_up, timeout=TIMEOUT)  # the valve's boot-up on the user's channel
        window.connection.shutdown()
    finally:
        listener.shutdown()


def test_a_bad_emulator_type_key_is_reported(qtbot, answers):
    app.create_application()
    args = _args("--emulator", "PRM9-07.3Z11/30-24E02S02")
    window = app.create_window(args)
    qtbot.addWidget(window)
    start_plan.start(window, start_plan.plan_from(args))
    assert "nominal size '07'" in answers.informed[-1]
    assert not window.connection.is_online


def test_run_shows_the_window_and_returns_when_it_closes(qapp, answers):
    # qapp: a timer set before the application exists never fires (the test alone hung)
    QTimer.singleShot(300, QApplication.closeAllWindows)
    assert app.run(_args()) == 0


def test_run_ends_when_a_late_result_shows_a_dialog_after_the_window_closed(qapp, answers):
    """Closed while the valve was still connecting: the result that arrives afterwards showed a
    dialog, which took Qt's quit back, and the program ran on with no window (the executable's
    start-up benchmark hung in CI). The window closed is the end of the program."""
    from PySide6.QtWidgets import QDialog

    from prm9tool.views.main_window import MainWindow

    def close_then_late_dialog() -> None:
        # run()'s window: the visible one (earlier tests' windows may linger, hidden or not)
        window = next(
            w for w in QApplication.topLevelWidgets() if isinstance(w, MainWindow) and w.isVisible()
        )
        QApplication.closeAllWindows()  # it, and any window an earlier test left open
        late = QDialog(window)  # what a result arriving now shows
        late.show()
        QTimer.singleShot(0, late.hide)

    QTimer.singleShot(0, close_then_late_dialog)
    guard = QTimer()  # a hang fails the test instead of the suite
    guard.setSingleShot(True)
    guard.timeout.connect(lambda: QApplication.exit(99))
    guard.start(TIMEOUT)
    try:
        assert app.run(_args()) == 0
    finally:
        guard.stop()


def _broken_spools_json() -> Path:
    path = Path(os.environ["PRM9TOOL_DATA_DIR"]) / USER_SPOOLS_FILE  # conftest: of this test
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text('[{"code": "4Z21", "coils": "C"}]', encoding="utf-8")
    return path


def test_the_gui_is_told_why_spools_json_was_left_out(monkeypatch, capsys, spools):
    path = _broken_spools_json()
    started = []
    monkeypatch.setattr(app, "run", lambda args, problem=None: started.append(problem) or 0)
    assert main([]) == 0
    (problem,) = started
    assert str(problem) == f"spool catalogue {path}: entry 1: coils 'C' must be AB, A or B"
    assert "prm9tool: warning: spool catalogue" in capsys.readouterr().err
    assert "4Z21" not in spools


def test_a_broken_spools_json_is_shown_once_at_start_in_the_program_language(
    qtbot, answers, spools
):
    path = _broken_spools_json()
    with pytest.raises(TypeKeyError) as caught:
        load_user_spools(path.parent)
    app.create_application()
    window = app.create_window(_args())
    qtbot.addWidget(window)
    window.set_language("de")
    start_plan.start(window, start_plan.plan_from(_args(), caught.value))
    assert answers.informed == [
        f"Schieberkatalog: Schieberkatalog {path}: Eintrag 1: coils 'C' muss AB, A oder B sein"
        "\n\nBis die Datei korrigiert ist, kennt prm9tool nur die mitgelieferten Schieber."
    ]
    window.connection.shutdown()


def test_the_window_comes_up_without_the_heavy_modules(tmp_path):
    """numpy, pyqtgraph and the device layer load when first needed (the connection's worker,
    the oscilloscope, a controller dialog), not on the way to the window (docs/PERFORMANCE.md)."""
    from support.python_process import run_python

    code = (
        "import sys\n"
        "from prm9tool import app\n"
        "from prm9tool.cli.main import build_parser\n"
        "qapp = app.create_application()\n"
        "window = app.create_window(build_parser().parse_args([]))\n"
        "window.show()\n"
        "qapp.processEvents()\n"
        "heavy = ('numpy', 'pyqtgraph', 'can', 'prm9tool.device', 'prm9tool.online.tuning')\n"
        "print(sorted(m for m in heavy if m in sys.modules))\n"
    )
    env = dict(os.environ, PRM9TOOL_DATA_DIR=str(tmp_path / "data"), QT_QPA_PLATFORM="offscreen")
    env["XDG_CONFIG_HOME"] = str(tmp_path / "config")
    result = run_python("-c", code, env=env)
    assert result.stdout.strip() == "[]", result.stderr


def test_cycles_are_collected_on_the_gui_thread_by_the_program_itself(qtbot):
    """Automatic collection is off (it may run in the valve's thread and deadlock Qt); the
    program's timer collects on the GUI thread instead."""
    import gc
    import threading
    import weakref

    app.create_application()
    gc.enable()  # as a program starts: the collector is automatic until the application exists
    app.create_application()
    assert not gc.isenabled()

    class Node:
        pass

    cycle = Node()
    cycle.me = cycle  # only the cycle collector frees it
    where: list[str] = []
    weakref.finalize(cycle, lambda: where.append(threading.current_thread().name))
    del cycle
    qtbot.waitUntil(lambda: where != [], timeout=5000)
    assert where == [threading.main_thread().name]


def test_the_can_bus_dialog_shows_the_bus_named_on_the_command_line(qtbot, answers):
    """``--device can:10 --can-interface udp_multicast --can-channel 239.74.163.2`` went online
    on that bus, but Communication → CAN bus… offered socketcan can0 (the remembered bus), so
    "Search the bus" searched another one."""
    from prm9tool.views.canbus.bus_dialog import CanBusDialog

    app.create_application()
    args = _args("--device", "can:10", "--can-interface", "udp_multicast",
                 "--can-channel", "239.74.163.2", "--can-bitrate", "250000")  # fmt: skip
    window = app.create_window(args)
    qtbot.addWidget(window)
    dialog = CanBusDialog(lambda _bus, _deliver: None, window.settings, window)
    qtbot.addWidget(dialog)
    assert dialog.bus() == {"interface": "udp_multicast", "channel": "239.74.163.2",
                            "bitrate": 250000}  # fmt: skip
    window.connection.shutdown()
    window = app.create_window(_args())  # without CAN options: the bus last used
    qtbot.addWidget(window)
    assert CanBusDialog(lambda _b, _d: None, window.settings, window).bus()["channel"] == (
        "239.74.163.2"
    )
    window.connection.shutdown()
