"""What distinguishes one PRM9 from another for the electronics: configuration, coils, CANopen."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

from prm9tool.messages import QT_TRANSLATE_NOOP, Message


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
        """Short English label such as ``E04 coil A -CA`` (a view shows :func:`variant_label`)."""
        return str(variant_label(self))


def variant_label(variant: Variant) -> Message:
    """``variant.label`` (e.g. ``E04 coil A -CA``) as a translatable message."""
    coils = {
        Coils.AB: QT_TRANSLATE_NOOP("Problems", "{0} two coils{1}"),
        Coils.A: QT_TRANSLATE_NOOP("Problems", "{0} coil A{1}"),
        Coils.B: QT_TRANSLATE_NOOP("Problems", "{0} coil B{1}"),
    }[variant.coils]
    return coils(variant.config.value, " -CA" if variant.canopen else "")


ALL_VARIANTS: tuple[Variant, ...] = tuple(
    Variant(cfg, coils, ca) for cfg in Config for coils in Coils for ca in (False, True)
)
