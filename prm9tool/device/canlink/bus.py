"""Opening a python-can bus and sharing one CANopen master (``canopen.Network``) per bus.

python-can and canopen are imported when a bus is opened, never at import time (the GUI
starts without them). A bus that cannot be opened is a :class:`CanAdapterError` naming the
interface and what to install or check; no python-can traceback reaches the user.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from prm9tool.device.records import NmtState
from prm9tool.errors import CanAdapterError

if TYPE_CHECKING:
    import can
    import canopen

log = logging.getLogger(__name__)

# What to install or check per python-can interface (docs/can-link.md lists them all).
HINTS = {
    "socketcan": "is the network interface there and up? (ip link show CHANNEL; "
    "sudo ip link set CHANNEL up type can bitrate BITRATE)",
    "pcan": "install PEAK's PCAN-Basic driver (Linux: libpcanbasic; Windows: the PEAK "
    "driver package) and plug the PCAN-USB in; channel e.g. PCAN_USBBUS1",
    "kvaser": "install Kvaser CANlib (the Kvaser drivers) and plug the interface in; channel 0",
    "ixxat": "install the IXXAT VCI driver; channel 0",
    "vector": "install Vector's XL Driver Library and assign the channel to python-can in "
    "Vector Hardware Config",
    "slcan": "CHANNEL is the adapter's serial port (e.g. /dev/ttyACM0 or COM3): is it "
    "plugged in, and may you open it? (Linux: the group dialout)",
    "gs_usb": "install gs_usb and pyusb, and allow your user the USB device (a udev rule)",
    "udp_multicast": "needs the package msgpack and a multicast route (e.g. ip route add "
    "224.0.0.0/4 dev lo for one machine)",
    "virtual": "the in-process virtual bus always opens; check the channel name",
}
GENERIC_HINT = "check that the adapter is plugged in, its driver is installed and you may use it"

# The error class bits of an error frame's ID as SocketCAN reports them (linux/can/error.h;
# python-can keeps them in ``arbitration_id``): the controller went bus-off, and it was
# restarted (automatically with ``ip link set CHANNEL type can restart-ms 100``).
CAN_ERR_BUSOFF = 0x040
CAN_ERR_RESTARTED = 0x100
BUS_OFF_WORDS = ("bus-off", "busoff", "bus off")  # how adapters' own errors name it


@dataclass(frozen=True)
class CanOptions:
    """Which CAN bus: a python-can interface, channel and bit rate."""

    interface: str = "virtual"
    channel: str = "prm9tool"
    bitrate: int | None = None  # None: whatever the bus backend uses by default

    @classmethod
    def of(
        cls, interface: str | None = None, channel: str | None = None, bitrate: int | None = None
    ) -> CanOptions:
        """The options from loose settings; each one not given (None) is the default here.
        The one place the command line, the API and the GUI's remembered bus become options."""
        return cls(
            interface if interface is not None else cls.interface,
            channel if channel is not None else cls.channel,
            bitrate,
        )

    @classmethod
    def from_args(cls, args: Any) -> CanOptions:
        """The options of the CLI's ``--can-interface/--can-channel/--can-bitrate`` (None: the
        default here)."""
        return cls.of(args.can_interface, args.can_channel, args.can_bitrate)

    @classmethod
    def from_mapping(cls, bus: Mapping[str, object]) -> CanOptions:
        """The options of a bus the GUI remembers as a dict (``interface``, ``channel``,
        ``bitrate``: a number, its text, or empty for the default)."""
        rate = bus.get("bitrate")
        interface, channel = bus.get("interface"), bus.get("channel")
        return cls.of(
            None if interface is None else str(interface),
            None if channel is None else str(channel),
            int(str(rate)) if rate else None,
        )

    def __str__(self) -> str:
        rate = f", {self.bitrate} bit/s" if self.bitrate else ""
        return f"{self.interface} channel {self.channel}{rate}"


def open_bus(options: CanOptions, default_bitrate: int | None = None) -> can.BusABC:
    """A python-can bus for ``options``; CanAdapterError with what to check if it fails."""
    try:
        import can
    except ImportError as exc:  # pragma: no cover - python-can is a dependency
        raise CanAdapterError(f"python-can is not installed: {exc}") from exc
    kwargs: dict[str, Any] = {"interface": options.interface, "channel": options.channel}
    bitrate = options.bitrate if options.bitrate is not None else default_bitrate
    if bitrate:
        kwargs["bitrate"] = bitrate
    try:
        return can.Bus(**kwargs)
    except (can.CanError, OSError, ValueError, ImportError, NotImplementedError) as exc:
        raise CanAdapterError(adapter_problem(options, exc)) from exc


def adapter_problem(options: CanOptions, exc: BaseException) -> str:
    """The message for a bus that could not be opened: interface, reason, what to check."""
    hint = HINTS.get(options.interface, GENERIC_HINT)
    hint = hint.replace("CHANNEL", options.channel).replace(
        "BITRATE", str(options.bitrate or 500000)
    )
    reason = str(exc) or type(exc).__name__
    return f"cannot open the CAN interface {options.interface!r}, channel {options.channel!r}: {reason} — {hint}"


@dataclass
class NodeSeen:
    """What the bus told about one node without being asked: heartbeat and EMCY."""

    node_id: int
    nmt_state: NmtState | None = None  # None: no heartbeat heard yet
    heartbeat_at: float | None = None  # time.monotonic() of the last heartbeat/boot-up
    emcy_code: int | None = None
    emcy_register: int = 0
    emcy_at: float | None = None
    boot_ups: int = 0
    boot_up_at: float | None = None  # time.monotonic() of the last boot-up
    period_s: float | None = None  # the time between its last two heartbeats (not boot-ups)
    # two nodes at this ID (discovery.scan): heartbeats that go back to the state before the
    # last one (A, B, A: two heartbeat streams interleaved), boot-ups too close for one node
    alternations: int = 0
    twin_boot_ups: int = 0
    last_states: tuple[int, ...] = ()  # the state bytes of the last two heartbeats


TWIN_BOOT_S = 0.5  # no node boots twice within this (a PRM9's boot takes ~2 s, manual §7.6)
NMT_STATES = {  # the state byte of a heartbeat (CiA 301 §7.2.8.3.2.1)
    0x00: NmtState.INITIALISING,
    0x04: NmtState.STOPPED,
    0x05: NmtState.OPERATIONAL,
    0x7F: NmtState.PRE_OPERATIONAL,
}


@dataclass
class CanNetwork:
    """One opened bus with its CANopen master; shared by every session on that bus."""

    options: CanOptions
    network: canopen.Network
    users: int = 0
    seen: dict[int, NodeSeen] = field(default_factory=dict)
    lock: threading.RLock = field(default_factory=threading.RLock)
    error_frames: int = 0
    sync_owner: object | None = None  # the scope producing SYNC on this bus (one at a time)
    bus_off_at: float | None = None  # time.monotonic() the adapter reported bus-off
    taps: list[Any] = field(default_factory=list)  # listeners of every frame, sent ones too

    def add_listener(self, listener: Any) -> None:
        """One more python-can listener (a trace recorder): every frame the bus receives, from
        the one Notifier of the bus, and every frame this program sends on it (python-can
        does not receive its own frames), with its send time and ``is_rx`` False."""
        with self.lock:
            self.taps.append(listener)
            self.network.notifier.add_listener(listener)  # type: ignore[union-attr]

    def remove_listener(self, listener: Any) -> None:
        """Stop feeding ``listener``."""
        with self.lock:
            if listener in self.taps:
                self.taps.remove(listener)
            notifier = self.network.notifier
            if notifier is not None and listener in notifier.listeners:
                notifier.remove_listener(listener)

    def sent(self, msg: can.Message) -> None:
        """A frame this program sent: to the listeners of :meth:`add_listener`."""
        taps = self.taps
        if not taps:
            return
        import can

        copy = can.Message(
            timestamp=time.time(),
            arbitration_id=msg.arbitration_id,
            is_extended_id=msg.is_extended_id,
            is_remote_frame=msg.is_remote_frame,
            dlc=msg.dlc,
            data=msg.data,
            is_fd=msg.is_fd,
            is_rx=False,
            channel=msg.channel,
        )
        for listener in list(taps):
            listener.on_message_received(copy)

    def on_frame(self, msg: can.Message) -> None:
        """Every frame on the bus (a python-can listener): heartbeats, boot-ups, EMCY, and
        error frames (a bus-off of the adapter: until it restarts or a frame arrives)."""
        if msg.is_error_frame:
            self.error_frames += 1
            if msg.arbitration_id & CAN_ERR_RESTARTED:
                self.bus_off_at = None
            elif msg.arbitration_id & CAN_ERR_BUSOFF:
                self.bus_off_at = time.monotonic()
            return
        self.bus_off_at = None  # a frame arrived: the adapter is on the bus again
        if msg.is_extended_id or msg.is_remote_frame:
            return
        cob, node = msg.arbitration_id & 0x780, msg.arbitration_id & 0x7F
        if node == 0:
            return
        if cob == 0x700 and len(msg.data) >= 1:
            seen = self.seen.setdefault(node, NodeSeen(node))
            code, now = msg.data[0] & 0x7F, time.monotonic()
            seen.nmt_state = NMT_STATES.get(code, NmtState.UNKNOWN)
            if code == 0:
                seen.boot_ups += 1
                if seen.boot_up_at is not None and now - seen.boot_up_at < TWIN_BOOT_S:
                    seen.twin_boot_ups += 1
                seen.boot_up_at, seen.period_s = now, None  # a new life: its period anew
                seen.last_states = ()
            else:
                if seen.heartbeat_at is not None and seen.heartbeat_at != seen.boot_up_at:
                    seen.period_s = now - seen.heartbeat_at
                if (
                    len(seen.last_states) == 2
                    and seen.last_states[0] == code != seen.last_states[1]
                ):
                    seen.alternations += 1
                seen.last_states = (*seen.last_states[-1:], code)
            seen.heartbeat_at = now
        elif cob == 0x080 and len(msg.data) >= 3:
            seen = self.seen.setdefault(node, NodeSeen(node))
            seen.emcy_code = int.from_bytes(bytes(msg.data[:2]), "little")
            seen.emcy_register = msg.data[2]
            seen.emcy_at = time.monotonic()

    def is_bus_off(self, refusal: BaseException | None = None) -> bool:
        """Whether the adapter is off the bus: it reported bus-off in an error frame (as
        SocketCAN does), or ``refusal`` (its error on sending) names bus-off."""
        if self.bus_off_at is not None:
            return True
        text = str(refusal or "").lower()
        return any(word in text for word in BUS_OFF_WORDS)

    def node_seen(self, node_id: int) -> NodeSeen:
        """What the bus told about ``node_id`` so far."""
        return self.seen.setdefault(node_id, NodeSeen(node_id))


_NETWORKS: dict[CanOptions, CanNetwork] = {}
_LOCK = threading.Lock()


def acquire(options: CanOptions) -> CanNetwork:
    """The shared master of the bus ``options`` (opened on first use); :func:`release` it."""
    with _LOCK:
        shared = _NETWORKS.get(options)
        if shared is None:
            shared = _connect(options)
            _NETWORKS[options] = shared
        shared.users += 1
        return shared


def release(shared: CanNetwork) -> None:
    """One user less; the last one closes the bus."""
    with _LOCK:
        shared.users -= 1
        if shared.users > 0:
            return
        _NETWORKS.pop(shared.options, None)
    try:
        shared.network.disconnect()
    except Exception as exc:
        log.warning("closing the CAN bus %s: %s", shared.options, exc)


def _connect(options: CanOptions) -> CanNetwork:
    import canopen

    bus = open_bus(options)
    network = canopen.Network(bus)
    network.NOTIFIER_CYCLE = 0.1
    shared = CanNetwork(options, network)
    network.listeners.append(_FrameListener(shared))  # type: ignore[arg-type]
    _tap_sends(bus, shared)
    try:
        network.connect()
    except Exception as exc:
        bus.shutdown()
        raise CanAdapterError(adapter_problem(options, exc)) from exc
    return shared


def _tap_sends(bus: can.BusABC, shared: CanNetwork) -> None:
    """Show every frame sent on ``bus`` to :meth:`CanNetwork.sent` (canopen sends everything,
    SDO, NMT, SYNC and PDOs, through ``bus.send``)."""
    send = bus.send

    def tapped(msg: can.Message, timeout: float | None = None) -> None:
        send(msg, timeout)
        shared.sent(msg)

    bus.send = tapped  # type: ignore[method-assign]


class _FrameListener:
    """A python-can listener feeding :meth:`CanNetwork.on_frame` (duck-typed: can.Listener
    would import python-can at module import)."""

    def __init__(self, shared: CanNetwork) -> None:
        self._shared = shared

    def on_message_received(self, msg: can.Message) -> None:
        self._shared.on_frame(msg)

    def on_error(self, exc: Exception) -> None:
        log.warning("CAN bus %s: %s", self._shared.options, exc)

    def stop(self) -> None:
        """Nothing to release."""

    def __call__(self, msg: can.Message) -> None:
        self.on_message_received(msg)
