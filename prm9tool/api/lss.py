"""LSS commissioning from a script: the valve service's LSS (``prm9tool.service.lss``), the
same operations and words as ``--lss-scan``/``--lss-assign``/``--find-bitrate`` and the CAN
bus window (docs/api.md, "LSS commissioning"). No Qt.

A valve whose node-ID switch is at position 1 has no node ID until the bus gives it one (manual
table 7-17, CiA 305)::

    found = prm9tool.lss_scan(can_interface="pcan", can_channel="PCAN_USBBUS1")
    prm9tool.lss_assign({found[0].serial: 21}, can_interface="pcan", ...)  # stored
    with prm9tool.connect("can:21", can_interface="pcan", ...) as valve: ...
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from prm9tool.device.canlink.bus import CanOptions
from prm9tool.errors import ValueRangeError
from prm9tool.service import lss
from prm9tool.service.lss import Assigned, FoundRate, LssDevice, LssFailedError

__all__ = ["Assigned", "FoundRate", "LssDevice", "LssFailedError", "find_bitrate", "lss_assign",
           "lss_scan"]  # fmt: skip


def lss_scan(
    *, can_interface: str | None = None, can_channel: str | None = None,
    can_bitrate: int | None = None,
) -> list[LssDevice]:  # fmt: skip
    """The devices without a node ID on the bus (LSS Fastscan), each with its identity (vendor,
    product, revision, serial; ``is_prm9``). Empty when none answers. CanAdapterError when
    the bus cannot be opened, LssFailedError (a CommunicationError) when the scan fails."""
    return lss.scan(CanOptions.of(can_interface, can_channel, can_bitrate))


def lss_assign(
    plan: Mapping[int, int] | Sequence[tuple[int, int]],
    *, can_interface: str | None = None, can_channel: str | None = None,
    can_bitrate: int | None = None,
) -> list[Assigned]:  # fmt: skip
    """Give each device without a node ID its node ID (``{serial: node_id}``) and store it;
    returns once each answers there (``Assigned.device_id`` is what :func:`connect` opens).

    ValueRangeError for a node ID outside 1…127 or one given twice (nothing sent);
    LssFailedError (``kind``) when a node ID is taken (``taken``, nothing changed), no device
    has a serial (``none``), a device refuses (``refused``) or is not heard after (``lost``)."""
    items = plan.items() if isinstance(plan, Mapping) else plan
    pairs: list[tuple[int, int]] = [(int(serial), int(node)) for serial, node in items]
    problem = lss.plan_problem(pairs)
    if problem is not None:
        raise ValueRangeError(problem.removeprefix("--lss-assign").lstrip(": "))
    return lss.assign(CanOptions.of(can_interface, can_channel, can_bitrate), list(pairs))


def find_bitrate(*, can_interface: str | None = None, can_channel: str | None = None) -> FoundRate:
    """The bus's bit rate, found by listening at each rate a PRM9 supports (listen-only: the
    adapter never transmits), and the nodes heard at it. BitrateNotFoundError when no rate
    fits, NoListenOnlyError when the adapter cannot listen only."""
    return lss.find_bitrate(CanOptions.of(can_interface, can_channel))
