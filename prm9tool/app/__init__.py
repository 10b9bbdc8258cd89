"""The composition root of the GUI: application, settings, translations, models, main window;
what the command line asks the window to do once it is shown is the start plan, :mod:`.start_plan`.

``prm9tool`` opens the window; ``prm9tool FILE.prm`` opens a file; ``prm9tool --emulator
[TYPEKEY]`` starts online with an emulated valve. Heavy modules (the device layer, pyqtgraph,
the views) are imported here, lazily, so the command-line tools never load them.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from types import TracebackType
from typing import TYPE_CHECKING

from prm9tool.app.start_plan import plan_from, start
from prm9tool.errors import ExitCode

if TYPE_CHECKING:
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication, QWidget

    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.device.session import ValveSession
    from prm9tool.errors import Prm9Error
    from prm9tool.online.connection_protocol import ValveListing
    from prm9tool.online.library_log import LibraryLog
    from prm9tool.views.main_window import MainWindow


def create_application(argv: list[str] | None = None) -> QApplication:
    """The QApplication (reused if one exists), with names for QSettings."""
    from PySide6.QtCore import QCoreApplication
    from PySide6.QtWidgets import QApplication

    QCoreApplication.setOrganizationName("prm9tool")
    QCoreApplication.setApplicationName("prm9tool")
    folder = settings_folder()
    if folder is not None:
        from PySide6.QtCore import QSettings

        ini = QSettings.Format.IniFormat
        QSettings.setDefaultFormat(ini)
        QSettings.setPath(ini, QSettings.Scope.UserScope, str(folder))
    from prm9tool._version import __version__

    QCoreApplication.setApplicationVersion(__version__)
    app = QApplication.instance() or QApplication(argv or sys.argv[:1])
    assert isinstance(app, QApplication)
    collect_garbage_on_the_gui_thread(app)
    return app


def settings_folder() -> Path | None:
    """Where QSettings keeps the remembered settings when not in Qt's native place: on Windows
    the file ``%APPDATA%\\prm9tool\\prm9tool.ini`` (this folder, then organization and
    application name), roaming with the user's profile and visible, instead of the registry.
    None elsewhere: Qt's native places are the platform's (Linux ``$XDG_CONFIG_HOME``, macOS
    ``~/Library/Preferences``); paths.py says where the data goes."""
    if sys.platform != "win32":
        return None
    from prm9tool.paths import settings_dir

    return settings_dir().parent


GC_INTERVAL_MS = 1000
FULL_COLLECTION_EVERY = 60  # timer ticks between full collections (the rest: young generations)


def collect_garbage_on_the_gui_thread(app: QApplication) -> None:
    """Run Python's cycle collector only on the GUI thread, from a timer.

    Left automatic, the collector runs in whichever thread happens to allocate: when that is a
    worker (the valve's thread), the Qt widgets in the collected cycles are handed to the GUI
    thread for deletion while the worker may hold a Qt connection lock and wait for the GIL —
    the two threads then wait for each other and the window freezes (seen once in the test
    suite: the GUI thread in ``QObject::~QObject`` under a ``sizeHint`` call, the worker in a
    queued signal). pyqtgraph's ``GarbageCollector`` does the same; it is not used here so that
    the window comes up without importing pyqtgraph.

    Each tick collects the young generations (well under a millisecond); a full collection,
    which walks every object holding the GIL, only every :data:`FULL_COLLECTION_EVERY` ticks:
    one a second stopped the connection's worker 0.14 s (idle PC) to 0.8 s (loaded PC), longer
    than the valve keeps its setpoint override without a report (0.5 s), and the GUI's
    end-of-line test lost the override. :func:`freeze_start_up_objects` keeps the start-up's
    objects out of the full collections.
    """
    import gc

    from PySide6.QtCore import QTimer

    gc.disable()
    if app.property("prm9tool_gc_timer"):
        return  # the application has its timer already
    timer = QTimer(app)
    timer.setInterval(GC_INTERVAL_MS)
    ticks = [0]

    def collect() -> None:
        ticks[0] += 1
        gc.collect(2 if ticks[0] % FULL_COLLECTION_EVERY == 0 else 1)

    timer.timeout.connect(collect)
    timer.start()
    app.setProperty("prm9tool_gc_timer", True)


def freeze_start_up_objects() -> None:
    """Move every object alive once the window is up (modules, classes, the catalogue, the
    widgets) to the collector's permanent generation (``gc.freeze``): a full collection then
    walks only what the session made since, a fraction of a millisecond instead of 0.14 s for
    the ~150 000 objects of the start-up. Garbage is collected first, so none is kept."""
    import gc

    gc.collect()
    gc.freeze()


def create_window(args: argparse.Namespace) -> MainWindow:
    """Build models and the main window for ``args`` (the application must exist)."""
    from PySide6.QtCore import QSettings

    from prm9tool import i18n
    from prm9tool.model.access import AccessModel
    from prm9tool.model.document import ParameterDocument
    from prm9tool.model.undo import DocumentUndo
    from prm9tool.online.connection import ValveConnection
    from prm9tool.views.main_window import MainWindow
    from prm9tool.views.valve.selection import DEFAULT_TYPE_KEY

    settings = QSettings()
    _remember_command_line_bus(args, settings)
    language = str(settings.value("language", i18n.system_language()))
    i18n.set_language(language if language in i18n.LANGUAGES else i18n.DEFAULT_LANGUAGE)
    doc = ParameterDocument(DEFAULT_TYPE_KEY)
    undo = DocumentUndo(doc)
    connection = ValveConnection(opener=_opener(args), lister=_lister, after_open=_joiner(args))
    from prm9tool.history.recorder import Recorder  # opens its database on first use

    connection.set_recorder(Recorder(getattr(args, "history_db", None)))
    return MainWindow(doc, undo, AccessModel(), connection, settings)


def _remember_command_line_bus(args: argparse.Namespace, settings: QSettings) -> None:
    """A CAN bus named on the command line becomes the CAN bus dialog's: the dialog offered the
    bus remembered from before (socketcan can0) while the program talked on this one."""
    names = ("can_interface", "can_channel", "can_bitrate")
    given = [getattr(args, name, None) for name in names]
    if all(value is None for value in given):
        return  # (the dialog's module is not loaded at every start)
    from prm9tool.views.canbus.bus_dialog import BITRATE_KEY, CHANNEL_KEY, INTERFACE_KEY

    for key, value in zip((INTERFACE_KEY, CHANNEL_KEY, BITRATE_KEY), given, strict=True):
        if value is not None:
            settings.setValue(key, value)


def _opener(args: argparse.Namespace) -> Callable[[object], ValveSession]:
    """Open sessions through the one device factory (the CAN bus joins later: _joiner)."""

    def open_session(entry: object) -> ValveSession:
        from prm9tool.device import factory

        assert isinstance(entry, factory.DeviceEntry | str)  # a listed valve or its device id
        label_key = getattr(args, "type_key", None)  # --type-key: a valve without 0x2041
        device_id = entry.device_id if isinstance(entry, factory.DeviceEntry) else entry
        # the bus only for a CAN node: reading the dialog's choice imports the CAN views
        can_link = _can_link(args) if device_id.startswith(f"{factory.CAN}:") else None
        return factory.open_session(entry, paced=True, can_link=can_link, label_key=label_key)

    return open_session


def _can_link(args: argparse.Namespace) -> CanOptions:
    """The bus of ``can:NODE`` valves: the command line's CAN options, else the CAN bus dialog's
    remembered choice (QSettings)."""
    from prm9tool.device import factory

    given = [getattr(args, n, None) for n in ("can_interface", "can_channel", "can_bitrate")]
    if any(v is not None for v in given):
        return factory.CanOptions.from_args(args)
    from PySide6.QtCore import QSettings

    from prm9tool.service.valve_listing import can_options
    from prm9tool.views.canbus.bus_dialog import saved_bus

    return can_options(saved_bus(QSettings()))


def _joiner(args: argparse.Namespace) -> Callable[[ValveSession], object] | None:
    """Put an emulated -CA valve on the command line's CAN bus once its session is open.

    Not part of opening: python-can's import would delay "online" by ~0.2 s, and a bus that
    cannot be opened is reported (the connection's ``failed``) while the valve stays online
    over USB.
    """
    if not hasattr(args, "can_interface"):
        return None

    def join(session: ValveSession) -> object:
        from prm9tool.device import factory

        return factory.join_can(session, factory.CanOptions.from_args(args))

    return join


def _lister(emulators: Sequence[str], can: dict[str, object] | None = None) -> list[ValveListing]:
    """The connection's listing, with the remembered emulated valves that cannot be made
    listed as such (the valve selection says why and offers to remove them)."""
    from prm9tool.device import factory
    from prm9tool.service.valve_listing import default_lister

    usable, unusable = factory.usable_emulators(emulators)
    return [*default_lister(usable, can), *unusable]


def show_internal_error(
    window: QWidget, kind: type[BaseException], error: BaseException, trace: TracebackType | None
) -> None:
    """Say that the program failed (a bug) instead of leaving it on standard error only.

    Installed as ``sys.excepthook`` while the GUI runs: an exception in a Qt slot otherwise goes
    unnoticed and the user goes on with a window that did not do what it showed.
    """
    import traceback

    from PySide6.QtCore import QCoreApplication

    from prm9tool.views import prompts

    details = "".join(traceback.format_exception(kind, error, trace))
    sys.stderr.write(details)
    title = QCoreApplication.translate("App", "Internal error")
    text = QCoreApplication.translate(
        "App",
        "prm9tool failed: {0}\n\nThe last action may not have been completed. Save your work "
        "under a new name and please report this error with the details below.",
    )
    prompts.inform(window, prompts.Icon.Critical, title, text.format(error), details)


def show_library_messages(window: MainWindow) -> LibraryLog:
    """The CAN libraries' warnings, as prm9tool's messages, in the window's status bar (the
    command line prints them on standard error too)."""
    from prm9tool.online.library_log import LibraryLog

    library_log = LibraryLog(window)
    library_log.message_posted.connect(lambda text: window.status.showMessage(text, 8000))
    return library_log


def run(args: argparse.Namespace, spools_problem: Prm9Error | None = None) -> int:
    """Start the GUI (``spools_problem``: why spools.json was left out); returns the exit code."""
    from PySide6.QtCore import Qt

    from prm9tool.app.outside_close import watch_outside_close
    from prm9tool.display import missing_x11_message, missing_x11_packages

    missing = missing_x11_packages()
    if missing:  # Qt would abort, naming another library than the missing one
        sys.stderr.write(missing_x11_message(missing))
        return ExitCode.USAGE
    app = create_application()
    # a window destroyed from outside (XDestroyWindow) tells Qt nothing: closed as by its
    # button; watched from before the window shows (the start may run events of its own)
    outside = watch_outside_close(app)
    window = create_window(args)
    sys.excepthook = lambda *exc: show_internal_error(window, *exc)
    library_log = show_library_messages(window)
    window.show()
    start(window, plan_from(args, spools_problem))
    freeze_start_up_objects()
    _probe_start_up(window)
    # the window closed is the end of the program: a result that arrives afterwards and shows
    # a dialog (a valve still connecting when the window was closed) would otherwise take back
    # Qt's own quit, and the program run on with no window (issue 34)
    app.lastWindowClosed.connect(app.quit, Qt.ConnectionType.QueuedConnection)
    try:
        code = app.exec()
    finally:
        if outside is not None:
            app.removeNativeEventFilter(outside)
        app.lastWindowClosed.disconnect(app.quit)
        library_log.close()
    return ExitCode.OK if code == 0 else int(code)


def _probe_start_up(window: MainWindow) -> None:
    """``PRM9TOOL_STARTUP_PROBE=SECONDS``: print when the window is shown (``shown <epoch>``),
    then close it after SECONDS — how the single executable's start-up is measured and its GUI
    smoke-tested (tools/smoke_executable.py, benchmarks/bench_startup.py --executable)."""
    seconds = os.environ.get("PRM9TOOL_STARTUP_PROBE")
    if not seconds:
        return
    from PySide6.QtCore import QTimer

    def shown() -> None:
        sys.stdout.write(f"shown {time.time()}\n")
        sys.stdout.flush()
        QTimer.singleShot(int(float(seconds) * 1000), window.close)

    QTimer.singleShot(0, shown)
