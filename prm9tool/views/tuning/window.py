"""The Tuning window: autotune, Bode, static characteristic and the test report.

Reached from the controller blocks of the diagram and from the oscilloscope. Online the tests
run on the valve (each asks first whether the hydraulics are safe for what it will do, and Stop
ends it at once with the valve put back as it was); offline they run on an emulated copy of
the document's valve. Proposals (gains, linearization) change the document only when accepted,
as one undo step. The procedures themselves: :mod:`prm9tool.characterize`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QMessageBox,
    QPushButton,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from prm9tool.analysis.profile import DEFAULT, Profile, load_profile
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import Blocker
from prm9tool.catalogue.variant import Config
from prm9tool.characterize.frame import LOOPS, gain_names
from prm9tool.i18n import unbroken_units
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.online.connection_protocol import StatusView
from prm9tool.online.tuning_runner import SimulationRunner, TuningRunner, ValveRunner
from prm9tool.online.valve_control import ValveControl, blocker_text, status_blocker
from prm9tool.translate import translated
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.help_dialog import add_context_help
from prm9tool.views.history.notes import record_online_change, record_tuning_run
from prm9tool.views.scope.start import offer_enable
from prm9tool.views.tuning.autotune import AutotunePage
from prm9tool.views.tuning.pages import BodePage, Page
from prm9tool.views.tuning.progress import TestProgress
from prm9tool.views.tuning.report_page import ReportPage
from prm9tool.views.tuning.signature_page import SignaturePage
from prm9tool.views.tuning.static import FlowPage, StaticPage
from prm9tool.views.tuning.twin_page import TwinPage


class TuningWindow(QDialog):
    """Autotune, frequency response, static characteristic and report for one valve."""

    def __init__(
        self,
        doc: ParameterDocument,
        connection: Any | None = None,
        parent: QWidget | None = None,
        control: ValveControl | None = None,
        access: AccessModel | None = None,
    ) -> None:
        super().__init__(parent)
        add_context_help(self, "tuning")  # F1
        self._access = access  # the level whose locked values Accept does not change
        self.setObjectName("tuning_window")
        self.doc, self.connection = doc, connection
        self._control = control  # NMT start and enabling, offered to a valve that would not move
        self._status: StatusView | None = None  # the valve's latest status
        self.runner: TuningRunner = self._make_runner()
        self.loop = QComboBox()
        self.loop.addItem("", "position")
        if doc.variant.config is Config.E04:
            self.loop.addItem("", "process")
        self.mode = QLabel()
        self.status = QLabel()
        self.status.setWordWrap(True)
        self._render: Callable[[], str] = lambda: self.tr("Ready.")  # the status line's text,
        self._failure = False  # in the program language when it changes; a failure shown
        self._shown = ""  # what it rendered last
        self.stop_button = QPushButton()
        self.stop_button.setEnabled(False)
        self.stop_button.clicked.connect(self.stop)
        self.tabs = QTabWidget()
        self.autotune = AutotunePage(self)
        self.bode = BodePage(self)
        self.static = StaticPage(self)
        self.flow = FlowPage(self) if doc.variant.config is Config.E04 else None
        self.report = ReportPage(self)
        self.signature = SignaturePage(self)  # Compare with birth certificate (issue 31)
        self.twin = TwinPage(self)  # Fit twin (issue 31)
        self.loop.currentIndexChanged.connect(self._on_loop_changed)
        if doc.variant.config is Config.E04 and doc.value("CTRLMODE") == 4:  # as delivered:
            self.loop.setCurrentIndex(self.loop.findData("process"))  # the loop its setpoint drives
        for page in self.pages():
            self.tabs.addTab(page, "")
        top = QFormLayout()
        self._loop_label = QLabel()
        top.addRow(self._loop_label, self.loop)
        bottom = QHBoxLayout()
        self.progress = TestProgress()
        bottom.addWidget(self.status, 1)
        bottom.addWidget(self.progress)
        bottom.addWidget(self.stop_button)
        layout = QVBoxLayout(self)
        layout.addWidget(self.mode)
        layout.addLayout(top)
        layout.addWidget(self.tabs, 1)
        layout.addLayout(bottom)
        if connection is not None:
            connection.online_changed.connect(self._on_online_changed)
            if hasattr(connection, "status_changed"):
                connection.status_changed.connect(self._on_status_changed)
        self.resize(1000, 720)  # fits 1024×768; the autotune page has plots and a table
        self.retranslate()

    # --- runner ----------------------------------------------------------------------------------
    def _make_runner(self) -> TuningRunner:
        if self.connection is not None and self.connection.is_online:
            runner: TuningRunner = ValveRunner(self.connection, self)
        else:
            from prm9tool.online.twins import twin_plant

            twin = twin_plant(self.doc.source_serial)  # its newest twin's plant, if it has one
            runner = SimulationRunner(str(self.doc.type_key), dict(self.doc.values), self, twin)
        runner.finished.connect(self._on_finished)
        runner.failed.connect(self._on_failed)
        runner.busy_changed.connect(self._on_busy_changed)
        if isinstance(runner, ValveRunner):
            runner.restored.connect(self._on_restored)
        return runner

    def _on_status_changed(self, status: StatusView) -> None:
        before, self._status = self._status, status
        recovered = status_blocker(before) is not None and status_blocker(status) is None
        if recovered and self._failure and not self.runner.busy:  # "FAULT_HOLD" after a
            self._say(lambda: self.tr("Ready."))  # restart or a fault reset: no longer so

    def _say(self, render: Callable[[], str], failure: bool = False) -> None:
        """Show ``render()`` in the status line; a language change renders it again."""
        self._render, self._failure = render, failure
        self._shown = render()
        self.status.setText(unbroken_units(self._shown))

    def _on_online_changed(self, online: bool) -> None:
        if self.runner.busy:
            self.runner.stop()
            return
        if online and isinstance(self.runner, ValveRunner):  # the valve is back: the same one
            self.retranslate()  # (it may still restore what a broken test changed)
            return
        self.runner.deleteLater()
        self.runner = self._make_runner()
        self.retranslate()

    def start(self, kind: str, what: str, procedure: Any, planned_s: float | None = None) -> bool:
        """Confirm (on a valve) what the test will do, then run ``procedure(rig)``.

        ``planned_s``: the valve seconds the test plays, for the progress bar (None: unknown,
        the bar only shows that it runs). A running setpoint generator is stopped by the test
        (the connection runs one thing on the valve's setpoint at a time): the confirmation and
        the status line say so. True when it started (False: refused, or not confirmed).
        """
        if self.runner.busy or not self._may_start(kind):
            return False
        generator = bool(getattr(self.connection, "generator_running", False))
        if isinstance(self.runner, SimulationRunner):
            self.runner.values = dict(self.doc.values)  # the document as it is now
            generator = False  # the test does not touch the valve
        elif not self._confirm(what, generator):
            return False
        else:
            offer_enable(self, self._control, self._status, self.tr("Tuning"))
        running = self.tr("Running: %1").replace("%1", what)
        if generator:  # stopped here, before the test, whether or not the scope is open
            self.connection.stop_generator()  # type: ignore[union-attr]
            running = self.tr("The oscilloscope's setpoint generator was stopped for the test.") + " " + running  # fmt: skip
        self._say(lambda: running)
        self.runner.run(kind, procedure)
        self.progress.start(self.runner, planned_s)
        return True

    def _may_start(self, kind: str) -> bool:
        """Before a long test, what would waste it: a valve that holds a fault (it would not
        move; refused with the reason) and an access level at which its result could not be
        accepted (asked: the result is kept, to accept after switching the level)."""
        if not isinstance(self.runner, SimulationRunner):  # on the valve
            reason = status_blocker(self._status)
            if reason in (Blocker.FAULT, Blocker.BOOTING):
                status, why = self._status, reason
                self._say(lambda: self.tr("Not started: the valve does not follow its setpoint: %1").replace("%1", blocker_text(why, status)), failure=True)  # fmt: skip
                return False
        locked = self._locked(self._accepts(kind))
        if not locked:
            return True
        answer = prompts.ask(
            self,
            prompts.Icon.Warning,
            self.tr("Tuning"),
            self.tr(
                "At the present access level the result of this test cannot be accepted: %1\n\n"
                "Switch to Expert first (View → Access level), or run the test now and switch "
                "before you accept: its result is kept. Start the test anyway?"
            ).replace("%1", locked),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        return answer == prompts.Button.Yes

    def _accepts(self, kind: str) -> list[str]:
        """The parameters a test of ``kind`` may propose (what its Accept would change)."""
        if kind == "autotune":
            return gain_names(LOOPS[self.current_loop()])
        if kind == "static":
            lin = [f"SETPLIN{a}{p}" for p in "ABCDEFGHI" for a in "XY"]
            return ["SETPLINON", *lin, "OFFSETPOS", "OFFSETNEG"]
        return ["OFFSETPOS", "OFFSETNEG"] if kind == "flow" else []

    def _locked(self, names: list[str]) -> str:
        """Why the first of ``names`` that this valve has is locked ("" when none is)."""
        if self._access is None:
            return ""
        for name in names:
            param = CATALOGUE.get(name)
            if param is None or name not in self.doc.values:
                continue
            if (reason := self._access.lock_reason(param)) is not None:
                return translated(reason)
        return ""

    def _confirm(self, what: str, generator: bool = False) -> bool:
        text = self.tr(
            "This test moves the spool (and on E04 the actuator): %1.\n\n"
            "Make sure the hydraulics are safe for it. Stop ends it at any time and puts the "
            "valve back as it was. Start the test?"
        ).replace("%1", what)
        if generator:
            text += "\n\n" + self.tr(
                "The oscilloscope's setpoint generator is running: the test stops it (start it "
                "again afterwards)."
            )
        answer = QMessageBox.question(self, self.tr("Tuning"), unbroken_units(text))
        return answer == QMessageBox.StandardButton.Yes

    def profile(self) -> Profile:
        """The acceptance profile chosen on the test report page (default when empty)."""
        path = self.report.profile_path.text().strip()
        return load_profile(path) if path else DEFAULT

    def stop(self) -> None:
        """Stop the running test."""
        self.runner.stop()
        self._say(lambda: self.tr("Stopping…"))

    def _on_busy_changed(self, busy: bool) -> None:
        self.stop_button.setEnabled(busy)
        if not busy:
            self.progress.finish()
        for page in self.pages():
            page.set_busy(busy)

    def pages(self) -> list[Page]:
        """The tabs' pages in order (the flow characteristic on E04 only)."""
        flow = [self.flow] if self.flow is not None else []
        return [self.autotune, self.bode, self.static, *flow, self.report, self.signature,
                self.twin]  # fmt: skip

    def _on_finished(self, kind: str, result: object) -> None:
        self._say(lambda: self.tr("Done."))
        pages: dict[str, Page] = {"autotune": self.autotune, "bode": self.bode}
        pages.update(static=self.static, flow=self.flow or self.report, signature=self.signature,
                     twin=self.twin)  # fmt: skip
        pages.get(kind, self.report).show_result(result)
        if isinstance(self.runner, ValveRunner):  # the valve moved: into its history
            record_tuning_run(self.connection, kind, result)

    def _on_restored(self, message: str) -> None:
        self._say(lambda: message)

    def _on_failed(self, kind: str, message: str) -> None:
        self._say(lambda: self.tr("Stopped: %1").replace("%1", message), failure=True)
        if kind == "signature":  # a refusal (no birth certificate) stays on its page
            self.signature.show_failure(message)
        elif kind == "twin":
            self.twin.show_failure(message)

    # --- document --------------------------------------------------------------------------------
    def accept_values(self, values: dict[str, int], text: str) -> bool:
        """Put ``values`` into the document as one undo step (online, on to the valve); False
        when the access level locks one (the status line says why and where to switch)."""
        wanted = {k: v for k, v in values.items() if k in self.doc.values}
        locked = [] if self._access is None else [
            reason for k in wanted if (reason := self._access.lock_reason(CATALOGUE[k]))
        ]  # fmt: skip
        if locked:  # at Basic level the controllers and linearizations are locked everywhere
            reason = locked[0]
            self._say(lambda: self.tr("Not accepted: %1").replace("%1", translated(reason) + " " + self.tr("(View → Access level)")))  # fmt: skip
            return False
        before = dict(self.doc.values)
        self.doc.set_values(wanted, text)
        record_online_change(self.connection, "tuning-accepted", before, self.doc.values,
                             what=text, loop=self.current_loop())  # fmt: skip
        self._say(lambda: self.tr("Accepted: %1").replace("%1", text))
        return True

    def _on_loop_changed(self) -> None:
        before = self.autotune.loop_shown
        self.autotune.set_loop(self.current_loop())
        self.bode.set_loop(self.current_loop(), before)

    def current_loop(self) -> str:
        """``position`` or ``process``."""
        return str(self.loop.currentData())

    def save_file(self, title: str, pattern: str, suggestion: str) -> Path | None:
        """Ask for a file name to write."""
        path, _ = file_dialogs.save_file_name(self, title, suggestion, pattern)
        return Path(path) if path else None

    # --- texts -----------------------------------------------------------------------------------
    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes (the main window keeps this window);
        a result in the status line stays until the next test."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate(keep_status=True)
        super().changeEvent(event)

    def retranslate(self, keep_status: bool = False) -> None:
        """Set every text in the program language (``keep_status``: the status line too only
        while it says "Ready.")."""
        self.setWindowTitle(self.tr("Tuning and characterization"))
        self.loop.setItemText(0, self.tr("Position controller (spool)"))
        if self.loop.count() > 1:
            self.loop.setItemText(1, self.tr("Process controller (E04)"))
        self._loop_label.setText(self.tr("Loop:"))
        self.stop_button.setText(self.tr("Stop"))
        if isinstance(self.runner, SimulationRunner) and self.runner.twin is not None:
            twin = self.runner.twin
            mode = self.tr(
                "Offline: the tests run on the twin of serial {0} (fitted {1}, {2}) with the "
                "document's values."
            ).format(twin.serial, twin.date[:10], twin.path)
        elif isinstance(self.runner, SimulationRunner):
            mode = (
                self.tr("Offline: the tests run on an emulated valve with the document's values.")
                + " "
                + self.tr("The emulator's plant: this serial has no twin in the history.")
            )
        else:
            mode = self.tr("Online: the tests move the connected valve.")
        self.mode.setText(mode)
        names = [self.tr("Autotune"), self.tr("Frequency response"),
                 self.tr("Static characteristic"), self.tr("Test report"),
                 self.tr("Birth certificate"), self.tr("Twin")]  # fmt: skip
        if self.flow is not None:
            names.insert(3, self.tr("Flow characteristic (E04)"))
        for k, name in enumerate(names):
            self.tabs.setTabText(k, name)
        for page in self.pages():
            page.retranslate()
        if keep_status:  # the same line in the new language (a text set from outside stays)
            if self.status.text() == self._shown:
                self._say(self._render, self._failure)
        else:
            self._say(lambda: self.tr("Ready."))

    def closeEvent(self, event: Any) -> None:
        if self.runner.busy:
            self.runner.stop()
        if isinstance(self.runner, SimulationRunner):
            self.runner.wait()
        self.twin.reports.wait()  # a report's fit writes its twin file first
        super().closeEvent(event)
