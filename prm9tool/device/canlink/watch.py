"""The live network view's source: what every node on a bus tells without being asked.

:class:`BusWatch` keeps the bus open (the master shared with any session on it,
:func:`prm9tool.device.canlink.bus.acquire`) and gives, whenever asked, one
:class:`NodeHeard` per node heard since: its NMT state from the heartbeat (manual table 7-4),
the heartbeat's age and period, the last EMCY with its meaning (table 5-1), and whether it
booted (boot-up frame) or went silent. Nothing is sent: asking costs no bus time.

**Decision (silent).** A node counts as silent when its heartbeat is overdue by
:data:`SILENT_PERIODS` periods (and at least :data:`SILENT_MIN_S`): a heartbeat consumer's
usual margin. A node that sends only its boot-up (heartbeat 0x1017 = 0) is never called silent;
nothing on the bus could tell.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

from prm9tool.device.canlink import bus as canbus
from prm9tool.device.canlink.status import emcy_text
from prm9tool.device.records import NmtState

SILENT_PERIODS = 3.0
SILENT_MIN_S = 1.0


@dataclass(frozen=True)
class NodeHeard:
    """One node as the bus told about it (ages in seconds at the time of asking)."""

    node_id: int
    nmt_state: NmtState | None  # None: no heartbeat heard
    heartbeat_age_s: float | None
    period_s: float | None
    last_emcy: str  # "8100 communication error", "" none heard
    boot_up_age_s: float | None  # since its last boot-up frame (None: none heard)
    silent: bool

    @property
    def device_id(self) -> str:
        """``can:NODE``."""
        return f"can:{self.node_id}"


def heard(seen: canbus.NodeSeen, now: float) -> NodeHeard:
    """``seen`` as of ``now`` (time.monotonic())."""
    age = None if seen.heartbeat_at is None else now - seen.heartbeat_at
    silent = (
        age is not None
        and seen.period_s is not None
        and age > max(SILENT_PERIODS * seen.period_s, SILENT_MIN_S)
    )
    return NodeHeard(
        seen.node_id,
        seen.nmt_state,
        age,
        seen.period_s,
        emcy_shown(seen.emcy_code),
        None if seen.boot_up_at is None else now - seen.boot_up_at,
        silent,
    )


def emcy_shown(code: int | None) -> str:
    """An EMCY code with its meaning ("" for none heard; code 0 ends the errors)."""
    if code is None:
        return ""
    return f"{code:04X} {emcy_text(code) if code else 'errors cleared'}"


class BusWatch:
    """The bus ``options`` held open while a network view shows it (close it!)."""

    def __init__(self, options: canbus.CanOptions) -> None:
        """Opens the bus (CanAdapterError with what to check when it cannot be opened)."""
        self._shared = canbus.acquire(options)
        self._closed = False

    @property
    def options(self) -> canbus.CanOptions:
        """The bus watched."""
        return self._shared.options

    def nodes(self) -> list[NodeHeard]:
        """Every node heard so far (by node ID), as of now."""
        now = time.monotonic()
        with self._shared.lock:
            seen = [s for s in self._shared.seen.values() if s.heartbeat_at or s.emcy_at]
        return [heard(s, now) for s in sorted(seen, key=lambda s: s.node_id)]

    def close(self) -> None:
        """Let go of the bus (idempotent)."""
        if not self._closed:
            self._closed = True
            canbus.release(self._shared)
