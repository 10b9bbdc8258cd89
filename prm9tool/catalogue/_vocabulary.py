"""Catalogue data's vocabulary: data types, scales, which valves a parameter applies to, the
choices several parameters share, and the nine-point linearization curves."""

from __future__ import annotations

from prm9tool.catalogue.scale import FULL_SCALE, PERCENT
from prm9tool.catalogue.schema import (
    EVERY_VARIANT,
    Access,
    Applies,
    DataType,
    ObjAccess,
    Parameter,
    Texts,
)
from prm9tool.catalogue.variant import Coils, Config

T = Texts
U8, U16, U32 = DataType.UNSIGNED8, DataType.UNSIGNED16, DataType.UNSIGNED32
S8, S16 = DataType.INTEGER8, DataType.INTEGER16
STR = DataType.VISIBLE_STRING
RO = ObjAccess.RO
# The firmware version the catalogue (and so the EDS) describes; the emulated valve runs it.
FIRMWARE_VERSION = "1.0.0"

TWO_COILS = Applies(coils=frozenset({Coils.AB}))
COIL_A = Applies(coils=frozenset({Coils.AB, Coils.A}))
COIL_B = Applies(coils=frozenset({Coils.AB, Coils.B}))
E04_ONLY = Applies(configs=frozenset({Config.E04}))
# The external sensor 0x2005-0x2008/0x2100: table 7-14 lists them among the objects of all
# valves, so every -CA valve answers them; they are parameters of the E04 only (the E02 has no
# external sensor input: §3.1, table 7-22, its diagram and list table 8-1/figure 8-18).
SENSOR_OBJECTS = Applies(configs=frozenset({Config.E04}), every_canopen=True)
CA_ONLY = Applies(canopen_only=True)

SIGNAL_TYPES: tuple[tuple[int, Texts], ...] = (
    (0, T("0…20 mA unipolar", "0…20 mA unipolar", "0…20 mA unipolární")),
    (1, T("0…20 mA bipolar", "0…20 mA bipolar", "0…20 mA bipolární")),
    (2, T("4…20 mA unipolar", "4…20 mA unipolar", "4…20 mA unipolární")),
    (3, T("4…20 mA bipolar", "4…20 mA bipolar", "4…20 mA bipolární")),
    (4, T("±10 mA unipolar", "±10 mA unipolar", "±10 mA unipolární")),
    (5, T("±10 mA bipolar", "±10 mA bipolar", "±10 mA bipolární")),
    (6, T("0…10 V unipolar", "0…10 V unipolar", "0…10 V unipolární")),
    (7, T("0…10 V bipolar", "0…10 V bipolar", "0…10 V bipolární")),
    (8, T("±10 V unipolar", "±10 V unipolar", "±10 V unipolární")),
    (9, T("±10 V bipolar", "±10 V bipolar", "±10 V bipolární")),
    (10, T("ratiometric unipolar", "ratiometrisch unipolar", "poměrový unipolární")),
    (11, T("ratiometric bipolar", "ratiometrisch bipolar", "poměrový bipolární")),
    (14, T("value over CANopen", "Wert über CANopen", "hodnota přes CANopen")),
)
OFF_ON = (
    (0, T("off", "aus", "vypnuto")),
    (1, T("on", "ein", "zapnuto")),
)
POLARITY = (
    (0, T("normal", "normal", "normální")),
    (1, T("inverted", "invertiert", "invertovaná")),
)


def linearization(
    prefix: str, index: int, axis: str, group: str, what: Texts, applies: Applies, source: str
) -> list[Parameter]:
    """The nine points A…I of one axis of a linearization curve (subindex 1…9 of ``index``)."""
    points = "ABCDEFGHI"
    result = []
    for n, letter in enumerate(points):
        default = -FULL_SCALE + n * 4096
        result.append(
            Parameter(
                f"{prefix}{axis}{letter}",
                index,
                n + 1,
                S16,
                -FULL_SCALE,
                FULL_SCALE,
                default,
                group=group,
                unit="%",
                scale=PERCENT,
                decimals=1,
                applies=applies,
                text=T(
                    f"{what.en}: point {axis}{letter}",
                    f"{what.de}: Punkt {axis}{letter}",
                    f"{what.cs}: bod {axis}{letter}",
                ),
                source=source,
            )
        )
    return result


def process_value(
    mnemonic: str,
    index: int,
    subindex: int,
    text: Texts,
    *,
    group: str,
    source: str,
    obj: ObjAccess = ObjAccess.RO,
    applies: Applies = EVERY_VARIANT,
) -> Parameter:
    """A process value of CiA 408 (S16, ±16384 = ±100 %), read-only and not in the file."""
    return Parameter(
        mnemonic,
        index,
        subindex,
        DataType.INTEGER16,
        -FULL_SCALE,
        FULL_SCALE,
        0,
        group=group,
        access=Access.READ_ONLY,
        obj_access=obj,
        in_file=False,
        unit="%",
        scale=PERCENT,
        decimals=1,
        applies=applies,
        text=text,
        source=source,
    )
