"""The 128-bit LSS address of a device (CiA 305), below both the LSS master
(:mod:`.lss`) and its error answers in words (:mod:`.lss_errors`)."""

from __future__ import annotations

from dataclasses import dataclass

from prm9tool.device.canlink.sdo import ARGO_HYTOS_VENDOR


@dataclass(frozen=True)
class LssAddress:
    """The 128-bit LSS address of a device: its identity object 0x1018/1…4."""

    vendor: int
    product: int
    revision: int
    serial: int

    @property
    def is_prm9(self) -> bool:
        """Argo-Hytos' vendor ID 0xE6 (manual §7.6): a PRM9."""
        return self.vendor == ARGO_HYTOS_VENDOR

    def as_tuple(self) -> tuple[int, int, int, int]:
        """(vendor, product, revision, serial), the order of the selective switch."""
        return (self.vendor, self.product, self.revision, self.serial)

    def describe(self) -> str:
        """``PRM9 (vendor 0xE6), product 0x9, revision 0x10000, serial 4711``."""
        who = "PRM9" if self.is_prm9 else "not a PRM9"
        return (
            f"{who} (vendor 0x{self.vendor:X}), product 0x{self.product:X}, "
            f"revision 0x{self.revision:X}, serial {self.serial}"
        )
