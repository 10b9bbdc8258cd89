"""Valve → Verify by restart…: after an upload, restart the valve (hydraulics confirmed off) and
read back whether it kept the values through the restart (issue 20 item 2; ``--batch
--verify-by-restart`` is the same check inside the upload).

Why an action of its own rather than an option of the upload: a restart drops the spool, so it
needs the hydraulics off, which is rarely the case at the moment of an upload in the field; the
engineer uploads, checks the valve, and verifies by restart when the hydraulics are off — any
time while the same valve stays online. It is offered on every link (USB: the restart command;
CANopen: NMT reset node) and says which store the upload made: "stored with 0x1010", "kept by
the valve as written (it has no store command)", and after the check "verified after a restart".

Nothing here touches the device: the connection runs prm9tool.service.restart_verify in its
worker thread and reports a ``RestartVerification`` (or ``lost``, when the valve does not come
back).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from PySide6.QtCore import QObject, QTime
from PySide6.QtWidgets import QDialog, QWidget

from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.online.connection import ValveConnection
from prm9tool.online.sync import ValveSync
from prm9tool.service.restart_verify import RestartVerification
from prm9tool.views import prompts
from prm9tool.views.online_dialogs import RestartDialog
from prm9tool.views.operation_progress import OperationProgress
from prm9tool.views.valve.upload import StoredUpload, ValveUpload

VERIFY_RESTART = "verify_restart"  # the connection's operation name


class RestartVerifier(QObject):
    """Asks, starts and reports the verification by restart of the last upload."""

    def __init__(
        self,
        window: QWidget,
        doc: ParameterDocument,
        connection: ValveConnection,
        sync: ValveSync,
        uploads: ValveUpload,
        progress: OperationProgress,
        post: Callable[[str], None],
        compare: Callable[[Mapping[str, Raw]], None],
    ) -> None:
        super().__init__(window)
        self._window, self._doc, self._connection = window, doc, connection
        self._sync, self._uploads, self._progress = sync, uploads, progress
        self._post, self._compare = post, compare
        self._running: StoredUpload | None = None  # the upload being verified

    @property
    def available(self) -> bool:
        """An upload was stored in this online session (the action is enabled)."""
        return self._uploads.last_stored is not None

    def start(self) -> bool:
        """Ask (the hydraulics confirmation) and start; False when nothing was restarted."""
        upload = self._uploads.last_stored
        title = self.tr("Verify by restart")
        if upload is None:
            prompts.inform(self._window, prompts.Icon.Information, title, self.tr(
                "Upload the parameters to the valve first: the verification restarts the "
                "valve and reads back whether it kept the last upload."))  # fmt: skip
            return False
        if self._sync.unstored:
            prompts.inform(self._window, prompts.Icon.Warning, title, self.tr(
                "The valve works with values changed online since the upload that it has not "
                "stored: a restart would lose them. Store them first (Valve → Store in valve), "
                "then verify. The valve was not restarted."))  # fmt: skip
            return False
        intro = self.tr(
            "The last upload wrote %n parameter(s): {0}. The valve is restarted, then its "
            "parameters are read back and compared with the document: this shows that it "
            "keeps them through a restart, as after a power loss.",
            "",
            upload.written,
        ).format(self._how(upload))
        dialog = RestartDialog(self._window, verify=intro)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            self._post(self.tr("Verification by restart cancelled: the valve was not restarted"))
            return False
        expected = {m: self._doc.values[m] for m in upload.mnemonics if m in self._doc.values}
        self._running = upload
        self._progress.start(
            VERIFY_RESTART, self.tr("Restarting the valve and reading its parameters back…"), False
        )
        self._connection.verify_by_restart(expected, upload.store)
        return True

    def _how(self, upload: StoredUpload) -> str:
        return self._uploads.store_text(upload.store) or self.tr("stored with its store command")

    def finished(self, result: object) -> None:
        """The connection finished the verification with ``result``."""
        upload, self._running = self._running, None
        if not isinstance(result, RestartVerification) or upload is None:
            return
        self._sync.stop()
        if not result.verified:
            self._report_not_kept(result)  # nothing more is sent: the user decides
            return
        if any(self._doc.values.get(m) != v for m, v in result.values.items()):
            self._compare(result.values)  # values the upload did not send differ: as online
        else:
            self._sync.start(result.values)
        at = QTime.currentTime().toString("HH:mm:ss")
        self._post(
            self.tr(
                "%n parameter(s) of the last upload read back unchanged at {0}: {1}",
                "",
                result.checked,
            ).format(at, self._uploads.store_text(result.store))
        )

    def _report_not_kept(self, result: RestartVerification) -> None:
        lines = [f"{m}: {want} → {got}" for m, (want, got) in result.mismatches.items()]
        shown = ", ".join(list(result.mismatches)[:8]) + (", …" if len(lines) > 8 else "")
        self._post(self.tr("Verification by restart failed: the valve did not keep {0}").format(
            shown))  # fmt: skip
        prompts.inform(
            self._window,
            prompts.Icon.Warning,
            self.tr("Verify by restart"),
            self.tr(
                "After the restart the valve reads back %n value(s) of the last upload "
                "otherwise: it did not keep them ({0}). It works with the values read back "
                "now (expected → read back below); the document still holds the uploaded "
                "values and the history records the differences. Edits no longer go to the "
                "valve: upload the document again, or download the valve's values.",
                "",
                len(lines),
            ).format(shown),
            "\n".join(lines),
        )

    def lost(self, message: str) -> bool:
        """The link broke while verifying (the valve did not come back after the restart):
        say what the valve holds as far as known. False when no verification was running."""
        upload, self._running = self._running, None
        if upload is None:
            return False
        self._post(self.tr("The valve did not come back after the restart"))
        then = self.tr(
            "Check the valve's supply and cable, then go online again: prm9tool compares the "
            "valve with the document."
        )
        if self._connection.is_reconnecting:
            then = self.tr(
                "prm9tool looks for the valve; when it is back, prm9tool compares it with the "
                "document and you decide what to do."
            )
        text = self.tr(
            "The valve did not come back after the restart; prm9tool is offline now.\n"
            "As far as known, the valve holds the values of the last upload ({0}): every "
            "one read back correctly before the restart, but whether it kept them through "
            "the restart could not be read.\n"
            "Nothing was lost on the PC side: the document still holds every value, the "
            "backup and the history are unchanged. {1}"
        ).format(self._how(upload), then)
        prompts.inform(
            self._window, prompts.Icon.Critical, self.tr("Verify by restart"), text, message
        )
        return True

    def failed(self) -> None:
        """Another error ended the verification (the connection's ``failed`` shows it)."""
        self._running = None
