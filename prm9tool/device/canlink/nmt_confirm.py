"""The master's own NMT command, confirmed: the session knows the state it asked for at once.

An NMT command has no answer (CiA 301). Waiting for the node's next heartbeat to learn that
the command took effect costs up to a heartbeat period (1 s by default, table 7-10), during
which the tool would refuse its own next step ("node 10 is NMT pre-operational") right after
its own NMT start. So :func:`send_and_confirm` sends the command and confirms it within
:data:`CONFIRM_S` by what the node shows on the bus anyway:

* a heartbeat after the command telling the state asked for (one telling another state is
  taken only at the end of the bound: it may have left the node before the command came);
* for start: the first TPDO of the node (0x180/0x280 + node ID; CiA 301 sends event-driven
  TPDOs on entering OPERATIONAL);
* failing both within the bound, for start and pre-operational one SDO read of 0x1000: a node
  that answers is not stopped and so took the command (a node that does not answer is gone:
  the read's DeviceTimeoutError says so). A stopped node answers no SDO; stop is confirmed by
  a heartbeat or taken as asked.

Then the shared view of the node (:class:`~prm9tool.device.canlink.bus.NodeSeen`) holds that
state until the next heartbeat says otherwise. No node guarding: the manual's valve has none.
"""

from __future__ import annotations

import threading
import time

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.canlink import bus as canbus
from prm9tool.device.canlink.sdo import SdoChannel
from prm9tool.device.records import NmtState

CONFIRM_S = 0.3  # the bound: an NMT command takes effect at once on a valve (table 7-4)
EXPECTED = {
    NmtCommand.START: NmtState.OPERATIONAL,
    NmtCommand.STOP: NmtState.STOPPED,
    NmtCommand.PRE_OPERATIONAL: NmtState.PRE_OPERATIONAL,
}


def send_and_confirm(
    shared: canbus.CanNetwork, sdo: SdoChannel, node_id: int, command: int
) -> NmtState | None:
    """Send ``command`` to ``node_id`` (behind ``sdo``) and return the NMT state it is now in
    (None for the reset commands: their boot-up tells, as before)."""
    expected = EXPECTED.get(command)  # type: ignore[call-overload]  # an IntEnum key
    seen = shared.node_seen(node_id)
    if expected is None:
        sdo.node.nmt.send_command(command)
        return None
    shown = threading.Event()
    tpdos = (0x180 + node_id, 0x280 + node_id) if expected is NmtState.OPERATIONAL else ()

    def on_tpdo(_can_id: int, _data: bytearray, _timestamp: float) -> None:
        shown.set()

    for cob_id in tpdos:
        shared.network.subscribe(cob_id, on_tpdo)
    heard_before = seen.heartbeat_at
    try:
        sdo.node.nmt.send_command(command)
        state = _wait(seen, heard_before, shown, expected)
    finally:
        for cob_id in tpdos:
            shared.network.unsubscribe(cob_id, on_tpdo)
    if state is None:
        if expected is not NmtState.STOPPED:
            sdo.read_u32(0x1000, 0)  # it answers: not stopped, so it took the command
        state = expected
    with shared.lock:
        seen.nmt_state = state
    return state


def _wait(
    seen: canbus.NodeSeen, heard_before: float | None, shown: threading.Event, expected: NmtState
) -> NmtState | None:
    """``expected`` once a heartbeat after the command says so (or, for start, a TPDO showed
    it); at the end of CONFIRM_S the state a later heartbeat told instead (one in flight as
    the command went out may still tell the old state: it does not end the wait), or None."""
    deadline = time.monotonic() + CONFIRM_S
    while True:
        heard = seen.heartbeat_at is not None and seen.heartbeat_at != heard_before
        if heard and seen.nmt_state is expected:
            return expected
        if shown.is_set():
            return NmtState.OPERATIONAL
        left = deadline - time.monotonic()
        if left <= 0:
            return seen.nmt_state if heard else None
        shown.wait(min(left, 0.005))
