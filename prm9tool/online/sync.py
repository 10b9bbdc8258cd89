"""Online editing: every document change is written to the valve while the connection is online.

The sync remembers what the valve holds (``valve_values``) and writes exactly the values in
which the document differs, whether they changed by a user edit, an undo/redo or a bulk
operation. While the document takes over values read *from* the valve, the sync is suspended.
QtCore only.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from contextlib import contextmanager

from PySide6.QtCore import QObject, Signal

from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.online.connection import ValveConnection


class ValveSync(QObject):
    """Mirrors document edits to the valve while online (offline: document only)."""

    active_changed = Signal(bool)  # edits go to the valve now (True) or no longer (False)

    def __init__(
        self, doc: ParameterDocument, connection: ValveConnection, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self._doc = doc
        self._connection = connection
        self._valve: dict[str, Raw] = {}
        self._suspended = 0
        self._active = False
        self.unstored = False  # values written online since the last store
        doc.value_changed.connect(self._on_document_value_changed)
        doc.values_reset.connect(self._on_document_values_reset)
        connection.online_changed.connect(self._on_connection_online_changed)

    @property
    def active(self) -> bool:
        """True when edits go to the valve (online and the document matches the valve)."""
        return self._active and self._connection.is_online

    @property
    def valve_values(self) -> Mapping[str, Raw]:
        """What the valve is known to hold."""
        return self._valve

    def start(self, valve_values: Mapping[str, Raw]) -> None:
        """Begin mirroring; ``valve_values`` is what the valve holds now."""
        self._valve = dict(valve_values)
        self._set_active(True)
        self.unstored = False
        self._write_differences()

    def stop(self) -> None:
        """Stop mirroring (offline, or the document was replaced by another valve type)."""
        self._set_active(False)

    def _set_active(self, active: bool) -> None:
        if active != self._active:
            self._active = active
            self.active_changed.emit(active)

    def differences(self) -> dict[str, tuple[Raw, Raw]]:
        """``{mnemonic: (document value, valve value)}`` for every value that differs."""
        return {
            mn: (value, self._valve[mn])
            for mn, value in self._doc.values.items()
            if mn in self._valve and self._valve[mn] != value
        }

    @contextmanager
    def suspended(self) -> Iterator[None]:
        """Apply values to the document without writing them (they came from the valve)."""
        self._suspended += 1
        try:
            yield
        finally:
            self._suspended -= 1

    def forget(self, mnemonics: list[str]) -> None:
        """A write of ``mnemonics`` failed: their valve value is unknown (rewritten on change)."""
        for mnemonic in mnemonics:
            self._valve.pop(mnemonic, None)

    def _on_connection_online_changed(self, online: bool) -> None:
        if not online:
            self._set_active(False)

    def _on_document_value_changed(self, mnemonic: str) -> None:
        if mnemonic in self._doc.values and self._ready():
            value = self._doc.values[mnemonic]
            if self._valve.get(mnemonic) != value:
                self._valve[mnemonic] = value
                self.unstored = True
                self._connection.write(mnemonic, value)

    def _on_document_values_reset(self) -> None:
        if self._ready():
            self._write_differences()

    def _ready(self) -> bool:
        return self.active and not self._suspended

    def _write_differences(self) -> None:
        changed = {mn: doc for mn, (doc, _valve) in self.differences().items()}
        if changed:
            self._valve.update(changed)
            self.unstored = True
            self._connection.write_many(changed)
