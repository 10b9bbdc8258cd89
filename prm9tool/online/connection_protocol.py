"""What the views need of the valve connection, as typing protocols (online layer, QtCore only).

The views get the connection injected (``prm9tool.online.connection.ValveConnection`` in the program,
small fakes in the tests) and must not import the device layer. These protocols name exactly
the signals and methods each view uses, so mypy checks the views against them and checks that
``ValveConnection`` provides them (``online/conformance.py`` proves it to mypy). Signals are
declared as read-only ``SignalInstance`` properties: a ``Signal`` class attribute of a QObject
satisfies them.

The records the connection's signals carry (who the valve is, its status, an upload's outcome,
a listed valve) come from the device layer; the views read them through the record protocols
below, which the same block checks against the device layer's dataclasses.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Protocol, runtime_checkable

from PySide6.QtCore import SignalInstance

from prm9tool.history.identity import ValveIdentity

if TYPE_CHECKING:
    from prm9tool.scope import GeneratorSettings


class CanNodeListing(Protocol):
    """What a listed CAN node's English description says, as fields (``CanNodeFacts``): the
    CAN bus dialog words it in the program language."""

    @property
    def node_id(self) -> int:
        """The node ID, 1…127."""

    @property
    def interface(self) -> str:
        """The bus's python-can interface."""

    @property
    def channel(self) -> str:
        """The bus's channel."""

    @property
    def bitrate(self) -> int | None:
        """The bus's bit rate (None: the interface's default)."""

    @property
    def name(self) -> str:
        """A PRM9's device name (0x1008)."""

    @property
    def device_type(self) -> int | None:
        """Another node's device type 0x1000 (None: it did not answer)."""

    @property
    def vendor(self) -> int | None:
        """Another node's vendor ID 0x1018/1 (None: it has no identity object)."""

    @property
    def detail(self) -> str:
        """Why it did not answer or identify itself (English), else ""."""


class ValveListing(ValveIdentity, Protocol):
    """A valve that can be opened, as the HID configuration lists it (``DeviceEntry``)."""

    @property
    def kind(self) -> str:
        """``usb`` or ``emulator``."""

    @property
    def description(self) -> str:
        """A line about the valve in English (the device layer's words)."""

    @property
    def nmt_state(self) -> str | None:
        """CAN nodes: the NMT state their heartbeat told during the scan (None otherwise)."""

    @property
    def heartbeat_age_s(self) -> float | None:
        """CAN nodes: seconds since their last heartbeat (None: none heard, or not CAN)."""

    @property
    def last_emcy(self) -> str:
        """CAN nodes: the last EMCY heard ("" none)."""

    @property
    def can(self) -> CanNodeListing | None:
        """CAN nodes: what ``description`` says, as fields (None: not a CAN node)."""


ListedValves = list[ValveListing] | Exception  # what listing the valves delivers: them, or why not


class LedView(Protocol):
    """One of the valve's three LEDs as it looks (``LedState``)."""

    @property
    def color(self) -> str:
        """``white``, ``green``, ``orange``, ``red``, ``blue``, ``magenta`` or ``off``."""

    @property
    def pattern(self) -> str:
        """``on``, ``1Hz``, ``2Hz``, ``2.5Hz``, ``single_flash`` … or ``off``."""

    @property
    def lit(self) -> bool:
        """Whether the LED is lit at this moment of its pattern."""


class StatusView(Protocol):
    """A snapshot of what the valve shows outside (``ValveStatus``)."""

    @property
    def device_state(self) -> str:
        """The CiA 408 device state, e.g. ``ACTIVE``."""

    @property
    def nmt_state(self) -> str:
        """The CANopen NMT state (``NmtState``), or ``off`` without a CANopen interface."""

    @property
    def booting(self) -> bool:
        """The valve is starting up (the first ~2 s after power-up)."""

    @property
    def error_code(self) -> int:
        """The EMCY code of the most severe active error (0: none)."""

    @property
    def error_text(self) -> str:
        """That error's (or the warning's) description in English; "" without either."""

    @property
    def warning(self) -> bool:
        """The temperature warning is on."""

    @property
    def active_errors(self) -> Sequence[int]:
        """EMCY codes of every active error."""

    @property
    def temperature_c(self) -> float:
        """The electronics' temperature in °C."""

    @property
    def supply_v(self) -> float:
        """The supply voltage in V."""

    @property
    def leds(self) -> Sequence[LedView]:
        """The three LEDs: power, error, CAN."""


@runtime_checkable
class UploadOutcome(Protocol):
    """How an upload ended (``UploadResult``): ``operation_finished("upload", outcome)``."""

    @property
    def written(self) -> int:
        """Values written."""

    @property
    def stored(self) -> bool:
        """The valve stored them (the upload succeeded)."""

    @property
    def mismatches(self) -> Mapping[str, tuple[object, object]]:
        """``{mnemonic: (written, read back)}`` of the values the verify step found wrong."""

    @property
    def failed_step(self) -> str | None:
        """``write``, ``verify``, ``store`` or None."""

    @property
    def failure(self) -> str | None:
        """Why the step failed when ``mismatches`` do not say it (e.g. a refused store)."""

    @property
    def store(self) -> str | None:
        """How the valve keeps the set over CANopen (prm9tool.device.canlink.storing)."""


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
    def device(self) -> ValveIdentity | None:
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


class StatusConnection(LinkState, Protocol):
    """Who the valve is and its live status (the valve-status window)."""

    @property
    def device_changed(self) -> SignalInstance:
        """Emitted with the :class:`ValveIdentity` of a valve come online, None when offline."""

    @property
    def status_changed(self) -> SignalInstance:
        """Emitted (about once a second online) with a :class:`StatusView`."""

    @property
    def device(self) -> ValveIdentity | None:
        """The connected valve, or None."""


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
    def reconnect_ended(self) -> SignalInstance:
        """Emitted when a lost valve is no longer looked for (back online, or not)."""

    @property
    def is_reconnecting(self) -> bool:
        """True while a lost valve is looked for (service/reconnect.py)."""

    @property
    def stream_started(self) -> SignalInstance:
        """Emitted with the keys actually streaming once the valve started the stream."""

    @property
    def write_failed(self) -> SignalInstance:
        """Emitted with the mnemonics of a write the valve refused (after ``failed``)."""

    @property
    def stream_stopped(self) -> SignalInstance:
        """Emitted when the stream has stopped (whoever stopped it)."""

    @property
    def stream_silent(self) -> SignalInstance:
        """Emitted with why, when a stream that sent nothing for its silence bound was stopped
        (``failed`` with the same words and ``stream_stopped`` follow)."""

    @property
    def status_changed(self) -> SignalInstance:
        """Emitted (≈ 2 Hz) with the valve's status (device state, NMT state, errors)."""

    @property
    def busy_changed(self) -> SignalInstance:
        """Emitted with True when a long operation (upload, restart, a tuning test…) starts."""

    @property
    def is_busy(self) -> bool:
        """True while a long operation runs."""

    def start_stream(self, keys: Sequence[str], rate_hz: int) -> None:
        """Start streaming ``keys`` at ``rate_hz`` (asynchronous)."""

    def stop_stream(self) -> None:
        """Stop the running stream."""

    @property
    def samples_lost(self) -> int:
        """Samples the running stream lost on the link since it started."""

    def write(self, mnemonic: str, raw: int | str) -> None:
        """Write one value to the valve (asynchronous)."""

    def start_generator(self, settings: GeneratorSettings) -> None:
        """Run a setpoint waveform on the valve's override, on the valve's time base."""

    def stop_generator(self) -> None:
        """End the waveform and switch the override off."""


class StepSimulation(Protocol):
    """The controller dialogs' step-response simulator (``prm9tool.online.tuning.StepSimulator``)."""

    @property
    def response_ready(self) -> SignalInstance:
        """Emitted with the ``StepResponse`` of the newest request."""

    @property
    def failed(self) -> SignalInstance:
        """Emitted with a message when a simulation failed."""

    def request(self, controller_values: Mapping[str, int]) -> None:
        """Simulate with ``controller_values`` (asynchronous; the newest request wins)."""

    def stop(self) -> None:
        """Drop pending requests and wait for a running simulation to end."""
