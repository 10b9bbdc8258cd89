"""Finding the bit rate of a CAN bus by listening only (never transmitting at a guessed rate).

A CAN controller at the wrong bit rate sees bit errors on every frame; at the right one it
receives the frames the nodes send. So prm9tool opens the adapter in its **listen-only** mode
(it acknowledges nothing, sends no error frames: the bus does not notice it) at each rate a PRM9
supports (manual table 7-17: 1 M, 800 k, 500 k, 250 k, 125 k, 50 k, 20 k), listens for
:data:`LISTEN_S`, and takes the rate at which valid frames arrived without error frames.

Listen-only is an adapter feature python-can reaches per interface (:data:`LISTEN_ONLY`).
Where python-can has none (SocketCAN, where the system sets the controller's mode; IXXAT;
gs_usb; the virtual buses) the bit rate cannot be found passively, and :func:`find_bitrate`
says so and what to try instead: it does not fall back to transmitting, which at a wrong rate
would destroy the traffic of a running machine.

**Decision (window).** 1 s per rate: a CANopen node with a heartbeat (0x1017) sends at least
once per its period, usually 100 ms … 1 s; a silent bus shows as "nothing heard" with what to do
(power a valve up while listening: its boot-up frame is enough).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from prm9tool.catalogue.canopen_switches import BITRATE_CODES_KBIT
from prm9tool.device.canlink.bus import CanOptions, adapter_problem
from prm9tool.errors import CanAdapterError, CommunicationError
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    import can

RATES = tuple(kbit * 1000 for kbit in BITRATE_CODES_KBIT)  # fastest first
LISTEN_S = 1.0


# python-can's constructor arguments for listen-only, per interface ("PASSIVE": BusState.PASSIVE)
LISTEN_ONLY: dict[str, dict[str, object]] = {
    "pcan": {"state": "PASSIVE"},
    "systec": {"state": "PASSIVE"},
    "kvaser": {"driver_mode": False},  # python-can's kvaser DRIVER_MODE_SILENT
    "vector": {"listen_only": True},
    "slcan": {"listen_only": True},
    "nixnet": {"listen_only": True},
}


class NoListenOnlyError(CanAdapterError):
    """The adapter has no listen-only mode python-can can switch on."""

    summary = QT_TRANSLATE_NOOP(
        "Errors", "The bit rate cannot be found without transmitting on this adapter."
    )


class BitrateNotFoundError(CommunicationError):
    """No rate gave valid frames."""

    summary = QT_TRANSLATE_NOOP("Errors", "No bit rate gave valid frames.")


@dataclass
class RateHeard:
    """What listening at one rate gave."""

    bitrate: int
    frames: int = 0
    error_frames: int = 0
    nodes: set[int] = field(default_factory=set)

    def describe(self) -> str:
        """``500 kbit/s: 12 frames (nodes 10, 21), 0 error frames``."""
        nodes = ", ".join(str(n) for n in sorted(self.nodes))
        who = f" (node{'s' if len(self.nodes) > 1 else ''} {nodes})" if nodes else ""
        return f"{_kbit(self.bitrate)}: {self.frames} frames{who}, {self.error_frames} error frames"


Opener = Callable[[CanOptions, int], "can.BusABC"]


def open_listen_only(options: CanOptions, bitrate: int) -> can.BusABC:
    """The adapter of ``options`` at ``bitrate`` in listen-only mode; NoListenOnlyError where
    python-can has none for it, CanAdapterError when it does not open."""
    import can

    if options.interface not in LISTEN_ONLY:
        raise NoListenOnlyError(cannot_listen(options))
    extra: dict[str, Any] = {
        name: can.BusState.PASSIVE if value == "PASSIVE" else value
        for name, value in LISTEN_ONLY[options.interface].items()
    }
    try:
        return can.Bus(
            interface=options.interface, channel=options.channel, bitrate=bitrate, **extra
        )
    except (can.CanError, OSError, ValueError, ImportError, NotImplementedError) as exc:
        raise CanAdapterError(adapter_problem(options, exc)) from exc


def cannot_listen(options: CanOptions) -> str:
    """Why the rate cannot be found passively on ``options``, and what to try instead."""
    what = (
        f"the {options.interface} interface has no listen-only mode prm9tool can switch on"
        if options.interface not in ("virtual", "udp_multicast")
        else f"a {options.interface} bus has no bit rate"
    )
    hint = (
        f"set the controller to listen-only yourself and try each rate (sudo ip link set "
        f"{options.channel} down; sudo ip link set {options.channel} type can bitrate 500000 "
        f"listen-only on; sudo ip link set {options.channel} up; candump {options.channel}), "
        if options.interface == "socketcan"
        else "use an adapter with a listen-only mode (PEAK pcan, Kvaser, Vector, slcan), "
    )
    return (
        f"prm9tool cannot find the bit rate on {options.interface} channel {options.channel}: "
        f"{what}, and it never transmits at a guessed rate. Try: {hint}or read the rate off "
        "the valve: its interface switch sets it at node-ID switch 2…F (2 = 20 k … 8 = 1 M, "
        "manual table 7-17); the delivery state is 500 kbit/s"
    )


def find_bitrate(
    options: CanOptions,
    listen_s: float = LISTEN_S,
    opener: Opener = open_listen_only,
    progress: Callable[[RateHeard], None] | None = None,
) -> tuple[int, list[RateHeard]]:
    """The bus's bit rate and what each rate gave; BitrateNotFoundError when none fits."""
    heard: list[RateHeard] = []
    for rate in RATES:
        result = _listen(opener(options, rate), rate, listen_s)
        heard.append(result)
        if progress is not None:
            progress(result)
        if result.frames and not result.error_frames:
            return rate, heard
    best = max(heard, key=lambda h: h.frames - h.error_frames)
    if best.frames > best.error_frames:
        return best.bitrate, heard  # a noisy bus: the rate with the most valid frames
    raise BitrateNotFoundError(_nothing(options, heard, listen_s))


def _listen(bus: can.BusABC, rate: int, listen_s: float) -> RateHeard:
    result = RateHeard(rate)
    deadline = time.monotonic() + listen_s
    try:
        while (left := deadline - time.monotonic()) > 0:
            msg = bus.recv(timeout=left)
            if msg is None:
                break
            if msg.is_error_frame:
                result.error_frames += 1
            else:
                result.frames += 1
                if not msg.is_extended_id and msg.arbitration_id & 0x7F:
                    cob = msg.arbitration_id & 0x780
                    if cob in (0x080, 0x180, 0x280, 0x380, 0x480, 0x580, 0x700):
                        result.nodes.add(msg.arbitration_id & 0x7F)
    finally:
        bus.shutdown()
    return result


def _nothing(options: CanOptions, heard: list[RateHeard], listen_s: float) -> str:
    errors = sum(h.error_frames for h in heard)
    if not errors:
        return (
            f"nothing was heard on {options.interface} channel {options.channel} at any rate "
            f"({', '.join(_kbit(r) for r in RATES)}; {listen_s:g} s each): the "
            "bus is silent. Power a valve up while listening (its boot-up frame is enough), or "
            "let the machine's PLC run; a valve without a heartbeat (0x1017 = 0) sends nothing "
            "on its own"
        )
    return (
        f"no rate gave valid frames on {options.interface} channel {options.channel} "
        f"({errors} error frames in all): check the wiring and the terminators (120 Ω at both "
        "ends), then try again"
    )


def _kbit(rate: int) -> str:
    return "1 Mbit/s" if rate == 1_000_000 else f"{rate // 1000} kbit/s"
