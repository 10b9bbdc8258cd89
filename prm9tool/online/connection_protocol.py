"""What the views need of the valve connection, as typing protocols (model layer, QtCore only).

The views get the connection injected (``prm9tool.online.connection.ValveConnection`` in the program,
small fakes in the tests) and must not import the device layer. These protocols name exactly
the signals and methods each view uses, so mypy checks the views against them and checks that
``ValveConnection`` provides them (see the ``TYPE_CHECKING`` block at the end). Signals are
declared as read-only ``SignalInstance`` properties: a ``Signal`` class attribute of a QObject
satisfies them.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

from PySide6.QtCore import SignalInstance


class LinkState(Protocol):
    """Whether a valve is online, and the signal announcing a change."""

    @property
    def online_changed(self) -> SignalInstance:
        """Emitted with True/False when the valve goes online/offline."""

    @property
    def is_online(self) -> bool:
        """True while a valve is connected."""


class ParameterConnection(LinkState, Protocol):
    """Reading, writing and storing parameters (the CANopen window)."""

    @property
    def device(self) -> object | None:
        """The connected valve's DeviceInfo (``type_key``, ``serial``, …), None offline."""

    @property
    def operation_finished(self) -> SignalInstance:
        """Emitted with (operation name or tag, result) when an operation is done."""

    def write(self, mnemonic: str, raw: int | str) -> None:
        """Write one value to the valve (asynchronous)."""

    def store(self) -> None:
        """Copy the valve's working values into its non-volatile memory."""

    def read_many(self, mnemonics: Sequence[str], tag: str = "read") -> None:
        """Read values; the result arrives as ``operation_finished(tag, {mnemonic: raw})``."""


class DiagramConnection(ParameterConnection, Protocol):
    """The diagram: live values of the red measuring points, and the CANopen window it opens."""

    @property
    def signal_values_changed(self) -> SignalInstance:
        """Emitted (a few times a second) with ``{measuring-point key: raw}``."""

    def watch_signals(self, keys: Sequence[str]) -> None:
        """Choose the measuring points ``signal_values_changed`` carries."""


class ScopeConnection(LinkState, Protocol):
    """Streaming measuring points and writing the setpoint override (the oscilloscope)."""

    @property
    def lost(self) -> SignalInstance:
        """Emitted with a message when the link dropped (the connection is offline after)."""

    @property
    def failed(self) -> SignalInstance:
        """Emitted with a user-facing message when an operation failed."""

    @property
    def samples_received(self) -> SignalInstance:
        """Emitted with a raw ``(n, channels)`` numpy block of the running stream."""

    @property
    def stream_started(self) -> SignalInstance:
        """Emitted with the keys actually streaming once the valve started the stream."""

    @property
    def write_failed(self) -> SignalInstance:
        """Emitted with the mnemonics of a write the valve refused (after ``failed``)."""

    @property
    def status_changed(self) -> SignalInstance:
        """Emitted (≈ 2 Hz) with the valve's status (device state, NMT state, errors)."""

    def start_stream(self, keys: Sequence[str], rate_hz: int) -> None:
        """Start streaming ``keys`` at ``rate_hz`` (asynchronous)."""

    def stop_stream(self) -> None:
        """Stop the running stream."""

    def write(self, mnemonic: str, raw: int | str) -> None:
        """Write one value to the valve (asynchronous)."""


if TYPE_CHECKING:  # mypy proves that the real connection fits every protocol above
    from prm9tool.online.connection import ValveConnection

    def _conforms(connection: ValveConnection) -> None:
        diagram: DiagramConnection = connection
        parameters: ParameterConnection = connection
        scope: ScopeConnection = connection
        del diagram, parameters, scope
