"""``--serve-emulator``: emulated -CA valves as headless nodes on a CAN bus (no GUI, no Qt).

Each valve runs its firmware in real time and answers on the bus of ``--can-interface`` /
``--can-channel`` until SIGINT or SIGTERM, so a PLC or a CANopen master under development (or
prm9tool in another process) talks to it as to a real valve. One line goes to stdout when a
valve is on the bus and one per NMT or device-state change, per LSS node-ID assignment and per
EMCY (named by the error that raised it), and one when a valve's simulation fell behind the
wall clock; the stored parameters persist in ``<user data dir>/emulator/<serial>.json`` as the
GUI's emulated valves' do. Lines on stdin inject and clear physical faults (:mod:`.serve_input`,
docs/plc-testing.md).
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from prm9tool.catalogue.canopen_switches import POSITIONS, node_position
from prm9tool.cli import serve_input
from prm9tool.device import emulated_valves, factory
from prm9tool.device.canlink.bus import CanOptions, open_bus
from prm9tool.device.emulator.canopen_watch import LATE_SYNC_MS
from prm9tool.device.emulator.paced_group import PacedGroup
from prm9tool.device.emulator.twinfile import TwinFileError
from prm9tool.device.records import DeviceState, NmtState
from prm9tool.errors import CanAdapterError, ExitCode, Prm9Error, TypeKeyError

if TYPE_CHECKING:
    import can

    from prm9tool.catalogue.error_kinds import ErrorKind
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.emulator.canopen_hub import SharedBus
    from prm9tool.device.emulator.canopen_slave import CanopenSlave

POLL_S = 0.02
LATENESS_REPORT_S = 1.0
# the receive thread answers a SYNC within this when a valve's loop holds the GIL (Python's
# default is 5 ms: a TPDO1 due within 1 ms of its SYNC would wait for it; docs/PERFORMANCE.md)
SWITCH_INTERVAL_S = 0.0002  # at most one line a second about a simulation that fell behind
LSS_POSITION = 1  # node-ID switch: LSS and automatic bit rate (table 7-17)


@dataclass
class _Served:
    valve: EmulatedValve
    slave: CanopenSlave
    close: Callable[[], None]
    emcy: list[str]  # EMCY lines the valve's error listener queued
    nmt: NmtState | None = None  # None: not reported yet
    state: DeviceState | None = None
    node: int = 0  # the node ID last reported (0: none yet, LSS)
    lateness_due: float = 0.0  # monotonic time of the next lateness report

    @property
    def label(self) -> str:
        """``serial 4711 node 10``, or ``serial 4711 (no node ID)`` before an LSS master."""
        node = self.slave.node_id
        return f"serial {self.valve.serial} " + (f"node {node}" if node else "(no node ID)")


def run(args: argparse.Namespace) -> int:
    """Serve until SIGINT/SIGTERM; returns the exit code (2 bad spec, 3 a twin file that
    cannot be used, 6 bus not opened)."""
    options = CanOptions.from_args(args)
    sys.setswitchinterval(SWITCH_INTERVAL_S)
    stop = threading.Event()
    served: list[_Served] = []
    shared = _SharedBus(options)
    try:
        for position, spec in enumerate(args.serve_emulator):
            node = args.node_id[position] if position < len(args.node_id) else None
            served.append(_serve(spec, position, node, shared))
    except TypeKeyError as exc:
        _close(served, shared)
        print(f"prm9tool: --serve-emulator: {exc}", file=sys.stderr)
        return ExitCode.USAGE
    except TwinFileError as exc:  # twin:FILE of a file that cannot be used
        _close(served, shared)
        print(f"prm9tool: --serve-emulator: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    except (CanAdapterError, Prm9Error) as exc:
        _close(served, shared)
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    previous = _on_signals(lambda *_: stop.set())
    # the bus's receive thread runs them all between frames: no paced thread to take its GIL
    pacing = PacedGroup([item.valve for item in served], driver=shared.hub)
    pacing.start()
    serve_input.listen(sys.stdin, [item.valve for item in served], _say)
    unanswered_due = [time.monotonic() + LATENESS_REPORT_S]
    try:
        while not stop.wait(POLL_S):
            for item in served:
                _report_changes(item, options)
                _report_lateness(item)
            _report_unanswered(served, unanswered_due)
    finally:
        _restore_signals(previous)
        pacing.stop()
        _close(served, shared)
    _say("stopped")
    return ExitCode.OK


class _SharedBus:
    """The one bus every served valve is on, opened with the first valve, and its one receive
    thread (:class:`~prm9tool.device.emulator.canopen_hub.SharedBus`): a bus per valve would
    decode every frame once per valve (docs/PERFORMANCE.md, "The PLC rig")."""

    def __init__(self, options: CanOptions) -> None:
        self.options = options
        self.bus: can.BusABC | None = None
        self.hub: SharedBus | None = None

    def join(self, valve: EmulatedValve) -> CanopenSlave:
        if self.bus is None:
            from prm9tool.device.emulator.canopen_hub import SharedBus

            self.bus = open_bus(self.options, valve.bitrate)
            self.hub = SharedBus(self.bus)
        assert self.hub is not None
        slave = valve.connect_can(self.bus, receive=False)
        self.hub.attach(slave)
        return slave

    def close(self) -> None:
        if self.hub is not None:
            self.hub.stop()
        if self.bus is not None:
            self.bus.shutdown()


def _serve(spec: str, position: int, node: int | str | None, shared: _SharedBus) -> _Served:
    type_key, serial = factory.parse_emulator_spec(spec, position + 1)
    valve = emulated_valves.emulated_valve(type_key, serial)
    if not valve.variant.canopen:
        raise TypeKeyError(f"{type_key} has no CANopen interface: serve a -CA valve")
    if node == "lss":
        _set_lss(valve)
    elif node is not None:
        _set_node(valve, int(node))
    options = shared.options
    slave = shared.join(valve)
    emcy: list[str] = []
    valve.add_error_cause_listener(
        lambda code, register, kind: emcy.append(_emcy_line(code, register, kind))
    )
    if valve.node_id:
        _say(f"serial {serial}: {type_key} starting as node {valve.node_id} on {options}")
    else:
        _say(
            f"serial {serial}: {type_key} without a node ID on {options}: waiting for an LSS master"
        )

    def close() -> None:
        valve.stop()
        slave.stop()

    return _Served(valve, slave, close, emcy, node=slave.node_id)


def _set_node(valve: EmulatedValve, node: int) -> None:
    """Node ``node``: by the node switch where a position gives it (2…F: 10, 15 … 75),
    else switch 0 and the stored NODEID (manual table 7-17). Read at power-up, so restart."""
    position = next((p for p in POSITIONS if node_position(p).node_id == node), None)
    if position is None:
        valve.write(0x2030, 1, node)
        valve.store()
        position = 0
    valve.set_input("switch_node", position)
    if valve.node_id != node:
        valve.restart()


def _set_lss(valve: EmulatedValve) -> None:
    """Node-ID switch at 1: the node ID an LSS master stored, none from the factory
    (manual table 7-17, CiA 305). Read at power-up, so restart."""
    valve.set_input("switch_node", LSS_POSITION)
    if not valve.lss_mode:
        valve.restart()


def _report_changes(item: _Served, options: CanOptions) -> None:
    status = item.valve.status()
    while item.emcy:
        _say(f"{item.label}: {item.emcy.pop(0)}")
    node = item.slave.node_id
    if node != item.node:
        was = f"node {item.node}" if item.node else "none"
        _say(f"serial {item.valve.serial}: LSS assigned node ID {node} (was {was})")
        item.node = node
    # the slave's own NMT state: a valve waiting for an LSS master is still initialising
    nmt = item.slave.state if node else NmtState.INITIALISING
    if nmt != item.nmt:
        if item.nmt in (None, NmtState.INITIALISING) and nmt is NmtState.PRE_OPERATIONAL:
            _say(f"{item.label}: on the bus {options}")
        item.nmt = nmt
        if node:
            _say(f"{item.label}: NMT {nmt}")
        else:
            _say(f"{item.label}: NMT {nmt}, waiting for an LSS master to assign a node ID")
    if status.device_state != item.state:
        item.state = status.device_state
        _say(f"{item.label}: state {status.device_state}")


def _report_lateness(item: _Served) -> None:
    """At most once a second: how often and how far the simulation fell behind real time."""
    now = time.monotonic()
    if now < item.lateness_due:
        return
    item.lateness_due = now + LATENESS_REPORT_S
    late = item.valve.pacer.take_lateness()
    if not late.episodes and not late.dropped_cycles:
        return
    dropped = f", {late.dropped_cycles} cycles dropped" if late.dropped_cycles else ""
    _say(
        f"{item.label}: simulation fell behind real time {late.episodes}x in the last "
        f"{LATENESS_REPORT_S:g} s, at most {late.worst_s * 1e3:.1f} ms{dropped} (a busy PC; "
        "SYNC and RPDO deadlines are judged at reception, so no fault from it)"
    )


def _report_unanswered(served: list[_Served], due: list[float]) -> None:
    """At most once a second, one line for every valve: the SYNCs it left without TPDO, as it
    got to them over LATE_SYNC_MS and two SYNC periods after they arrived (this PC fell
    behind the bus)."""
    now = time.monotonic()
    if now < due[0]:
        return
    due[0] = now + LATENESS_REPORT_S
    counts, worst = [], 0.0
    for item in served:
        count, late_ms = item.slave.take_unanswered_syncs()
        if count:
            counts.append(f"{item.label} {count}x")
            worst = max(worst, late_ms)
    if counts:
        _say(
            f"SYNCs answered with no TPDO in the last {LATENESS_REPORT_S:g} s, as this PC got "
            f"to them more than {LATE_SYNC_MS:g} ms and two SYNC periods after they arrived "
            f"(at most {worst:.0f} ms): {', '.join(counts)}. A TPDO that late would carry the "
            "state of a later moment; serve fewer valves per process or a slower SYNC "
            '(docs/plc-testing.md, "Limits")'
        )


def _emcy_line(code: int, register: int, kind: ErrorKind | None) -> str:
    if code == 0 or kind is None:
        return f"EMCY 0000 (errors cleared), error register 0x{register:02X}"
    return f"EMCY {code:04X} ({kind.text}), error register 0x{register:02X}"


def _say(line: str) -> None:
    print(f"prm9tool: {line}", flush=True)


def _on_signals(handler: Callable[..., Any]) -> dict[int, Any]:
    previous: dict[int, Any] = {}
    for number in (signal.SIGINT, signal.SIGTERM):
        previous[number] = signal.signal(number, handler)
    return previous


def _restore_signals(previous: dict[int, Any]) -> None:
    for number, handler in previous.items():
        signal.signal(number, handler)


def _close(served: list[_Served], shared: _SharedBus) -> None:
    for item in reversed(served):
        item.close()
    shared.close()
