"""``--serve-emulator``: emulated -CA valves as headless nodes on a CAN bus (no GUI, no Qt).

Each valve runs its firmware in real time and answers on the bus of ``--can-interface`` /
``--can-channel`` until SIGINT or SIGTERM, so a PLC or a CANopen master under development (or
prm9tool in another process) talks to it as to a real valve. One line goes to stdout when a
valve is on the bus and one per NMT or device-state change and per EMCY; the stored parameters
persist in ``<user data dir>/emulator/<serial>.json`` as the GUI's emulated valves' do.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from prm9tool.catalogue.canopen_switches import POSITIONS, node_position
from prm9tool.device import factory
from prm9tool.device.canlink.bus import CanOptions, open_bus
from prm9tool.device.canlink.status import emcy_text
from prm9tool.device.records import DeviceState, NmtState
from prm9tool.errors import CanAdapterError, ExitCode, Prm9Error, TypeKeyError

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve

POLL_S = 0.02
LSS_POSITION = 1  # node-ID switch: LSS and automatic bit rate (table 7-17)


@dataclass
class _Served:
    valve: EmulatedValve
    close: Callable[[], None]
    emcy: list[str]  # EMCY lines the valve's error listener queued
    nmt: NmtState | None = None  # None: not reported yet
    state: DeviceState | None = None


def run(args: argparse.Namespace) -> int:
    """Serve until SIGINT/SIGTERM; returns the exit code (2 bad spec, 6 bus not opened)."""
    options = CanOptions.from_args(args)
    stop = threading.Event()
    served: list[_Served] = []
    try:
        for position, spec in enumerate(args.serve_emulator):
            node = args.node_id[position] if position < len(args.node_id) else None
            served.append(_serve(spec, position, node, options))
    except TypeKeyError as exc:
        _close(served)
        print(f"prm9tool: --serve-emulator: {exc}", file=sys.stderr)
        return ExitCode.USAGE
    except (CanAdapterError, Prm9Error) as exc:
        _close(served)
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    previous = _on_signals(lambda *_: stop.set())
    try:
        while not stop.wait(POLL_S):
            for item in served:
                _report_changes(item, options)
    finally:
        _restore_signals(previous)
        _close(served)
    _say("stopped")
    return ExitCode.OK


def _serve(spec: str, position: int, node: int | str | None, options: CanOptions) -> _Served:
    type_key, serial = factory.parse_emulator_spec(spec, position + 1)
    valve = factory.emulated_valve(type_key, serial)
    if not valve.variant.canopen:
        raise TypeKeyError(f"{type_key} has no CANopen interface: serve a -CA valve")
    if node == "lss":
        _set_lss(valve)
    elif node is not None:
        _set_node(valve, int(node))
    bus = open_bus(options, valve.bitrate)
    slave = valve.connect_can(bus)
    emcy: list[str] = []
    valve.add_error_listener(lambda code, register: emcy.append(_emcy_line(code, register)))
    valve.start()
    if valve.node_id:
        _say(f"serial {serial}: {type_key} starting as node {valve.node_id} on {options}")
    else:
        _say(
            f"serial {serial}: {type_key} without a node ID on {options}: waiting for an LSS master"
        )

    def close() -> None:
        valve.stop()
        slave.stop()
        bus.shutdown()

    return _Served(valve, close, emcy)


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
        _say(f"serial {item.valve.serial} node {item.valve.node_id}: {item.emcy.pop(0)}")
    if status.nmt_state != item.nmt:
        if (
            item.nmt in (None, NmtState.INITIALISING)
            and status.nmt_state is NmtState.PRE_OPERATIONAL
        ):
            _say(f"serial {item.valve.serial} node {item.valve.node_id}: on the bus {options}")
        item.nmt = status.nmt_state
        _say(f"serial {item.valve.serial} node {item.valve.node_id}: NMT {status.nmt_state}")
    if status.device_state != item.state:
        item.state = status.device_state
        _say(f"serial {item.valve.serial} node {item.valve.node_id}: state {status.device_state}")


def _emcy_line(code: int, register: int) -> str:
    if code == 0:
        return f"EMCY 0000 (errors cleared), error register 0x{register:02X}"
    return f"EMCY {code:04X} ({emcy_text(code)}), error register 0x{register:02X}"


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


def _close(served: list[_Served]) -> None:
    for item in reversed(served):
        item.close()
