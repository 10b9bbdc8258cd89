"""The tool's CAN adapter going bus-off, as the CAN link sees it (no GUI, no valve): SocketCAN's
error frames (linux/can/error.h) and an adapter's refusal naming it make SDO failures a
CanBusOffError; a restart or any frame heard again ends it."""

from __future__ import annotations

import can
import pytest

from prm9tool.device.canlink.bus import (
    CAN_ERR_BUSOFF,
    CAN_ERR_RESTARTED,
    CanNetwork,
    CanOptions,
)
from prm9tool.device.canlink.sdo import SdoChannel
from prm9tool.errors import CanBusOffError, DeviceDisconnectedError, DeviceTimeoutError

CAN_ERR_CRTL = 0x004  # controller problems (error passive, …): not a bus-off


def error_frame(error_class: int) -> can.Message:
    return can.Message(arbitration_id=error_class, is_error_frame=True, dlc=8, data=bytes(8))


def heartbeat(node: int) -> can.Message:
    return can.Message(arbitration_id=0x700 + node, data=[0x7F], is_extended_id=False)


@pytest.fixture
def shared():
    return CanNetwork(CanOptions(), network=None)  # type: ignore[arg-type]  # frames only


def test_socketcans_bus_off_frame_until_its_restart_frame(shared):
    shared.on_frame(error_frame(CAN_ERR_CRTL))
    assert not shared.is_bus_off() and shared.error_frames == 1
    shared.on_frame(error_frame(CAN_ERR_BUSOFF))
    assert shared.is_bus_off() and shared.error_frames == 2
    shared.on_frame(error_frame(CAN_ERR_RESTARTED))
    assert not shared.is_bus_off()


def test_a_frame_heard_again_ends_a_bus_off_without_a_restart_frame(shared):
    shared.on_frame(error_frame(CAN_ERR_BUSOFF))
    shared.on_frame(heartbeat(10))
    assert not shared.is_bus_off() and shared.node_seen(10).heartbeat_at is not None


def test_an_adapters_refusal_that_names_it_is_a_bus_off(shared):
    assert shared.is_bus_off(can.CanOperationError("PCAN: the CAN controller is in bus-off state"))
    assert not shared.is_bus_off(can.CanOperationError("Transmit buffer full"))


class _Port:
    """An SDO port whose sending fails with ``error`` or that never answers (None)."""

    def __init__(self, error: Exception | None) -> None:
        self.error = error

    def send(self, _data: bytes) -> None:
        if self.error is not None:
            raise self.error

    def receive(self, _timeout_s: float) -> bytes | None:
        return None

    def drain(self) -> int:
        return 0


class _Node:
    def __init__(self) -> None:
        self.id = 10


@pytest.mark.parametrize(
    ("error", "ordinary"),
    [
        (None, DeviceTimeoutError),
        (can.CanOperationError("Failed to transmit: [Errno 105] No buffer space available"),
         DeviceDisconnectedError),
    ],
    ids=["no-answer", "refused"],
)  # fmt: skip
def test_an_sdo_failure_during_a_bus_off_says_bus_off(shared, error, ordinary):
    sdo = SdoChannel(_Node(), 0.01, shared, _Port(error))  # type: ignore[arg-type]
    with pytest.raises(ordinary) as plain:
        sdo.upload(0x6041, 0)
    assert not isinstance(plain.value, CanBusOffError)
    shared.on_frame(error_frame(CAN_ERR_BUSOFF))
    with pytest.raises(CanBusOffError, match=r"node 10: the CAN adapter is bus-off \(") as off:
        sdo.upload(0x6041, 0)
    assert str(off.value.summary()).startswith("The CAN adapter went bus-off")
