"""What distinguishes one PRM9 from another for the electronics: configuration, coils, CANopen."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum


class Config(StrEnum):
    """Electronics configuration (manual §1.2)."""

    E02 = "E02"  # spool-position feedback: position loop over current loop
    E04 = "E04"  # plus external process sensor and an outer process loop


class Coils(StrEnum):
    """Coil layout (manual §8.7.2): two coils, or one coil on side A or B only."""

    AB = "AB"
    A = "A"
    B = "B"


@dataclass(frozen=True)
class Variant:
    """The electronics variant that decides which parameters, blocks and signals exist."""

    config: Config = Config.E02
    coils: Coils = Coils.AB
    canopen: bool = False

    @property
    def label(self) -> str:
        """Short label such as ``E04 coil A -CA``."""
        coils = {Coils.AB: "two coils", Coils.A: "coil A", Coils.B: "coil B"}[self.coils]
        return f"{self.config.value} {coils}{' -CA' if self.canopen else ''}"


ALL_VARIANTS: tuple[Variant, ...] = tuple(
    Variant(cfg, coils, ca) for cfg in Config for coils in Coils for ca in (False, True)
)
