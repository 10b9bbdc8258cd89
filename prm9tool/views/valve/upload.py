"""Valve → Upload: the checks before the document goes to the valve (valve variant, Expert
values at Basic level, the history), the upload itself and its outcome.

Nothing here touches the device: it drives the ValveConnection, which writes, verifies and
stores in its worker thread and reports an ``UploadOutcome``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from PySide6.QtCore import QObject, QTime
from PySide6.QtWidgets import QWidget

from prm9tool.catalogue import CATALOGUE, Access, variant_label
from prm9tool.catalogue.manual_od import KEPT_AS_WRITTEN, STORED_WITH_1010, VERIFIED_RESTART
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.online.connection import ValveConnection
from prm9tool.online.connection_protocol import UploadOutcome
from prm9tool.online.sync import ValveSync
from prm9tool.translate import translated
from prm9tool.views import prompts
from prm9tool.views.history.policy import may_upload
from prm9tool.views.operation_progress import OperationProgress


@dataclass(frozen=True)
class StoredUpload:
    """The last upload the valve stored: the parameters it sent, how the valve kept them
    (prm9tool.device.canlink.storing; None: the link's store command) and how many it wrote."""

    mnemonics: frozenset[str]
    store: str | None
    written: int


class ValveUpload(QObject):
    """Sends the document (or chosen values) to the valve and reports how it went."""

    def __init__(
        self,
        window: QWidget,
        doc: ParameterDocument,
        connection: ValveConnection,
        sync: ValveSync,
        progress: OperationProgress,
        post: Callable[[str], None],
        access: AccessModel | None = None,
    ) -> None:
        super().__init__(window)
        self._window = window
        self._doc = doc
        self._connection = connection
        self._sync = sync
        self._progress = progress
        self._post = post
        self._access = access
        self._repeats = False  # the running upload sends what the valve holds already
        self._pending: dict[str, Raw] = {}
        self._purpose = ""  # what the running upload is for, in the history
        self._uploading: dict[str, Raw] = {}  # the values of the running upload
        # the last upload stored while online: what it wrote and how (Verify by restart…)
        self.last_stored: StoredUpload | None = None
        connection.online_changed.connect(self._on_connection_online_changed)

    def upload(self, key: TypeKey, valve_values: Mapping[str, Raw] | None = None) -> bool:
        """Write the document into the valve of type ``key`` (backup first, then write →
        verify → store).

        ``valve_values``: what the valve holds, if just read (else what the online sync
        knows). False when nothing is sent (another variant, or the user declined).
        """
        if key.variant != self._doc.variant:
            self._refuse_other_variant(key)
            return False
        known = self._sync.valve_values if valve_values is None else valve_values
        if not self.basic_user_confirms_expert_values(known):
            self._post(self.tr("Nothing was sent to the valve"))
            return False
        # the valve holds the document already (edits went to it, nothing left unstored)
        self._repeats = self._sync.active and not self._sync.unstored
        self._repeats &= not self._sync.differences()
        self.upload_values(self._doc.values, "upload")
        return True

    def _refuse_other_variant(self, key: TypeKey) -> None:
        prompts.ask(
            self._window,
            prompts.Icon.Warning,
            self.tr("Upload to valve"),
            self.tr(
                "The document is for a {0} valve, the connected valve is a {1} valve. "
                "Choose the matching valve type or download the valve's parameters first."
            ).format(
                translated(variant_label(self._doc.variant)),
                translated(variant_label(key.variant)),
            ),
            prompts.Button.Ok,
        )

    def upload_values(self, values: Mapping[str, Raw], purpose: str = "") -> None:
        """Upload exactly ``values`` (write, read back, store), once the history can record
        it or the user said to go ahead without it (views/history/policy.py); ``purpose``
        goes into the history record (e.g. ``compare``)."""
        self._pending = dict(values)
        self._purpose = purpose
        if self._connection.history is None:
            self._start_upload()
            return
        self._progress.start("upload", self.tr("Uploading the parameters to the valve…"))
        self._connection.check_history(self._on_history_checked)

    def _on_history_checked(self, problem: object) -> None:
        self._progress.close()
        if may_upload(self._window, problem):
            self._start_upload()

    def _start_upload(self) -> None:
        values, self._pending = self._pending, {}
        self._uploading = values
        self._progress.start("upload", self.tr("Uploading the parameters to the valve…"))
        self._connection.upload(values, purpose=self._purpose)

    def expert_differences(
        self, valve_values: Mapping[str, Raw], values: Mapping[str, Raw] | None = None
    ) -> list[str]:
        """The Expert-level parameters whose value in ``values`` (default: the document's)
        differs from the valve's."""
        return [
            mnemonic
            for mnemonic, value in (self._doc.values if values is None else values).items()
            if CATALOGUE[mnemonic].access is Access.EXPERT
            and mnemonic in valve_values
            and valve_values[mnemonic] != value
        ]

    def basic_user_confirms_expert_values(
        self, valve_values: Mapping[str, Raw], values: Mapping[str, Raw] | None = None
    ) -> bool:
        """At Basic level, sending changes the Basic level cannot make needs a Yes (``values``:
        what is sent, default the document)."""
        if self._access is None or self._access.level is not Access.BASIC:
            return True
        changed = self.expert_differences(valve_values, values)
        if not changed:
            return True
        shown = ", ".join(changed[:8]) + (", …" if len(changed) > 8 else "")
        answer = prompts.ask(
            self._window,
            prompts.Icon.Warning,
            self.tr("Expert values at Basic level"),
            self.tr(
                "The document changes %n Expert-level value(s) of the valve ({0}), which the "
                "Basic access level cannot edit (controllers, linearizations, monitoring). "
                "Send them anyway?",
                "",
                len(changed),
            ).format(shown),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        return answer == prompts.Button.Yes

    def finished(self, result: object) -> None:
        """The connection finished the upload with ``result`` (an ``UploadOutcome``)."""
        outcome = result if isinstance(result, UploadOutcome) else None
        if outcome is not None and outcome.stored:
            self._on_stored(outcome)
        else:
            self._report_failure(outcome)

    def _on_connection_online_changed(self, online: bool) -> None:
        if not online:
            self.last_stored = None  # a restart verification is of this online session's upload

    def _on_stored(self, outcome: UploadOutcome) -> None:
        store = getattr(outcome, "store", None)
        self.last_stored = StoredUpload(frozenset(self._uploading), store, outcome.written)
        # values not from the document (a history record) become the document's too
        written = {m: v for m, v in self._uploading.items() if self._doc.values.get(m) != v}
        if written:
            with self._sync.suspended():
                self._doc.set_values(written, self.tr("Values written to the valve"), False)
        info = self._connection.device
        if info is not None:  # the document now belongs to the valve it was written to
            self._doc.set_source(info.serial, info.firmware)
        self._sync.start(self._doc.values)
        at = QTime.currentTime().toString("HH:mm:ss")  # each upload's message differs
        count = outcome.written
        message = self.tr("%n parameter(s) written, verified and stored at {0}", "", count)
        repeats, self._repeats = self._repeats, False
        if repeats:
            message = self.tr(
                "%n parameter(s) written, verified and stored again at {0}: the valve "
                "already held them",
                "",
                count,
            )
        how = self._store_texts().get(store or "")
        hint = ""
        if store == KEPT_AS_WRITTEN:  # no store command: a restart shows that it really keeps them
            hint = self.tr("; Valve → Verify by restart… checks that it keeps them")
        self._post(message.format(at) + (f" ({how})" if how else "") + hint)

    def store_text(self, store: str | None) -> str:
        """How the valve kept the set, in the program language ("" when not over CANopen)."""
        return self._store_texts().get(store or "", "")

    def _store_texts(self) -> dict[str, str]:
        """How the valve kept the set, as prm9tool.device.canlink.storing names it."""
        return {
            STORED_WITH_1010: self.tr("stored with 0x1010"),
            KEPT_AS_WRITTEN: self.tr("kept by the valve as written (it has no store command)"),
            VERIFIED_RESTART: self.tr("verified after a restart"),
        }

    def _report_failure(self, outcome: UploadOutcome | None) -> None:
        mismatches = outcome.mismatches if outcome is not None else {}
        lines = [f"{mn}: {want} → {got}" for mn, (want, got) in mismatches.items()]
        failure = outcome.failure if outcome is not None else None  # e.g. a refused store
        details = "\n".join([failure, *lines] if failure else lines)
        prompts.inform(
            self._window,
            prompts.Icon.Warning,
            self.tr("Upload failed"),
            self.tr(
                "The upload failed at step “{0}”. Nothing was stored: after a restart the valve "
                "holds its previous parameters."
            ).format("" if outcome is None else str(outcome.failed_step)),
            details,
        )
