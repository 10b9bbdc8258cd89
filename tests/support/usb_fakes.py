"""A fake ``hid`` module (hidapi's API) whose devices are emulated valves, with cable faults.

It sits exactly at the library boundary: prm9tool's HID backend talks to it as to hidapi
(report-ID byte on writes, lists of ints on reads, OSError when the device is gone).
"""

from __future__ import annotations

import time
from collections import deque
from dataclasses import dataclass, field
from types import SimpleNamespace

from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.usb_firmware import UsbFirmware


@dataclass
class FakeCable:
    """Faults on one fake device; numbers count that direction's reports from 1."""

    drop_out: set[int] = field(default_factory=set)
    drop_in: set[int] = field(default_factory=set)
    duplicate_in: set[int] = field(default_factory=set)
    late_in: dict[int, float] = field(default_factory=dict)  # answer number -> delay in s
    unplug_after_out: int | None = None
    corrupt_reads_after_out: int | None = None  # then flip a bit in every READ answer


class FakeValve:
    """One emulated valve presented as a HID device."""

    def __init__(
        self,
        valve: EmulatedValve,
        path: bytes,
        vendor_id: int = 0x1234,
        product_id: int = 0x5678,
        product: str = "PRM9 valve",
    ) -> None:
        self.valve, self.path = valve, path
        self.vendor_id, self.product_id, self.product = vendor_id, product_id, product
        self.firmware = UsbFirmware.of(valve)
        self.cable = FakeCable()
        self.plugged = True
        self.out_count = self.in_count = 0
        self.writes: list[bytes] = []  # every buffer handed to write(), report ID included
        self.inbox: deque[tuple[float, bytes]] = deque()

    def record(self) -> dict:
        return {
            "path": self.path,
            "vendor_id": self.vendor_id,
            "product_id": self.product_id,
            "serial_number": "",
            "manufacturer_string": "ARGO-HYTOS",
            "product_string": self.product,
            "interface_number": 0,
        }

    def receive(self, data: bytes) -> None:
        self.writes.append(bytes(data))
        self.out_count += 1
        cable = self.cable
        if cable.unplug_after_out is not None and self.out_count > cable.unplug_after_out:
            self.plugged = False
        if not self.plugged:
            raise OSError("write error: No such device")
        if self.out_count in cable.drop_out:
            return
        assert data[0] == 0 and len(data) == 65, "report ID 0 + 64 bytes"
        answer = self.firmware.handle(bytes(data[1:]))
        after = cable.corrupt_reads_after_out
        if after is not None and self.out_count > after and answer[0] == 0x82 and answer[3]:
            answer = answer[:5] + bytes([answer[5] ^ 0x01]) + answer[6:]
        self.in_count += 1
        number = self.in_count
        if number in cable.drop_in:
            return
        release = time.monotonic() + cable.late_in.get(number, 0.0)
        for _ in range(2 if number in cable.duplicate_in else 1):
            self.inbox.append((release, answer))

    def send(self, timeout_ms: int) -> list[int]:
        deadline = time.monotonic() + timeout_ms / 1000
        while True:
            while self.firmware.outbox:  # stream reports the firmware produced meanwhile
                self.inbox.append((0.0, self.firmware.outbox.popleft()[1]))
            if not self.plugged:
                raise OSError("read error")
            ready = [item for item in self.inbox if item[0] <= time.monotonic()]
            if ready:
                self.inbox.remove(ready[0])
                return list(ready[0][1])
            if time.monotonic() >= deadline:
                return []
            time.sleep(0.001)


class FakeHid:
    """Stands in for the ``hid`` module: ``enumerate`` and ``device``."""

    def __init__(self) -> None:
        self.valves: dict[bytes, FakeValve] = {}
        self.others: list[dict] = []  # non-valve HID devices (a keyboard …)
        self.opened: list[bytes] = []
        outer = self

        class Device:
            def __init__(self) -> None:
                self._valve: FakeValve | None = None
                self._nonblocking = False

            def set_nonblocking(self, value: int) -> int:
                self._nonblocking = bool(value)
                return 0

            def open_path(self, path: bytes) -> None:
                valve = outer.valves.get(path)
                if valve is None or not valve.plugged:
                    raise OSError("open failed")
                outer.opened.append(path)
                self._valve = valve

            def write(self, data: bytes) -> int:
                if self._valve is None:
                    raise ValueError("not open")
                self._valve.receive(bytes(data))
                return len(data)

            def read(self, max_length: int, timeout_ms: int = 0) -> list[int]:
                if self._valve is None:
                    raise ValueError("not open")
                assert timeout_ms > 0 or self._nonblocking, "hidapi's read(n, 0) blocks forever"
                return self._valve.send(timeout_ms)[:max_length]

            def close(self) -> None:
                self._valve = None

        self.device = Device

    def enumerate(self, vendor_id: int = 0, product_id: int = 0) -> list[dict]:
        records = [v.record() for v in self.valves.values() if v.plugged] + self.others
        return [
            r
            for r in records
            if (not vendor_id or r["vendor_id"] == vendor_id)
            and (not product_id or r["product_id"] == product_id)
        ]

    def add(self, valve: EmulatedValve, path: bytes, **kwargs) -> FakeValve:
        fake = self.valves[path] = FakeValve(valve, path, **kwargs)
        return fake

    def replug(self, old: bytes, new: bytes) -> None:
        """The device re-enumerates under another path (as after a restart)."""
        fake = self.valves.pop(old)
        fake.path = new
        self.valves[new] = fake

    def as_module(self) -> SimpleNamespace:
        return SimpleNamespace(enumerate=self.enumerate, device=self.device)
