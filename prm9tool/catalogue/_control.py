"""Catalogue data: controllers, current limiter, dither, CANopen settings,
monitoring, the service objects of the PC."""

from __future__ import annotations

from prm9tool.catalogue._vocabulary import (
    CA_ONLY,
    COIL_A,
    COIL_B,
    E04_ONLY,
    OFF_ON,
    PERCENT,
    RO,
    S8,
    S16,
    U8,
    U16,
    T,
)
from prm9tool.catalogue.scale import FULL_SCALE
from prm9tool.catalogue.schema import Access, Applies, Parameter, Texts
from prm9tool.catalogue.variant import Config

E02_ONLY = Applies(configs=frozenset({Config.E02}))


def _pidt1(
    prefix: str, index: int, what: Texts, applies: Applies, defaults: tuple[int, int, int, int]
) -> list[Parameter]:
    kp, ki, kd, t1 = defaults
    return [
        Parameter(
            f"{prefix}KP",
            index,
            1,
            U16,
            0,
            65535,
            kp,
            group=f"{prefix.lower()}_controller",
            scale=0.01,
            decimals=2,
            applies=applies,
            text=T(
                f"{what.en}: proportional gain Kp",
                f"{what.de}: P-Verstärkung Kp",
                f"{what.cs}: proporcionální člen Kp",
            ),
            source="§8.7.2 'Regulátor' (object and scaling: decision)",
        ),
        Parameter(
            f"{prefix}KI",
            index,
            2,
            U16,
            0,
            65535,
            ki,
            group=f"{prefix.lower()}_controller",
            unit="1/s",
            scale=0.1,
            decimals=1,
            applies=applies,
            text=T(
                f"{what.en}: integral gain Ki",
                f"{what.de}: I-Verstärkung Ki",
                f"{what.cs}: integrační člen Ki",
            ),
            source="§8.7.2 'Regulátor' (object and scaling: decision)",
        ),
        Parameter(
            f"{prefix}KD",
            index,
            3,
            U16,
            0,
            65535,
            kd,
            group=f"{prefix.lower()}_controller",
            unit="ms",
            scale=0.01,
            decimals=2,
            applies=applies,
            text=T(
                f"{what.en}: derivative time Kd",
                f"{what.de}: D-Anteil Kd",
                f"{what.cs}: derivační člen Kd",
            ),
            source="§8.7.2 'Regulátor' (object and scaling: decision)",
        ),
        Parameter(
            f"{prefix}T1",
            index,
            4,
            U16,
            0,
            65535,
            t1,
            group=f"{prefix.lower()}_controller",
            unit="ms",
            scale=0.01,
            decimals=2,
            applies=applies,
            text=T(
                f"{what.en}: lag time constant T1",
                f"{what.de}: Verzögerung T1",
                f"{what.cs}: dopravní zpoždění T1",
            ),
            source="§8.7.2 'Regulátor' (object and scaling: decision)",
        ),
    ]


CONTROLLERS: list[Parameter] = [
    *_pidt1(
        "POS",
        0x2020,
        T("Position controller", "Lageregler", "Regulátor polohy"),
        Applies(),
        (40, 1000, 40, 20),  # tuned on the emulator plant: docs/emulator.md (decision)
    ),
    *_pidt1(
        "PRC",
        0x2021,
        T("Process controller", "Prozessregler", "Regulátor procesní veličiny"),
        E04_ONLY,
        (200, 0, 0, 100),
    ),
]

CURRENT_AND_DITHER: list[Parameter] = [
    Parameter(
        "CURNORM",
        0x2004,
        1,
        U16,
        0,
        4000,
        2600,
        group="current_limit",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        unit="mA",
        text=T(
            "Nominal coil current CURNORM",
            "Nennstrom der Spule CURNORM",
            "Jmenovitý proud cívky CURNORM",
        ),
        source="table 7-14 (2600 mA: assumption)",
    ),
    Parameter(
        "LIMTA",
        0x2004,
        2,
        U16,
        0,
        4000,
        2400,
        group="current_limit",
        access=Access.BASIC,
        unit="mA",
        applies=COIL_A,
        text=T(
            "Solenoid A: maximum current",
            "Spule A: maximaler Strom",
            "Magnet A: maximální přípustná hodnota",
        ),
        source="fig. 8-18, table 7-14",
    ),
    Parameter(
        "LIMTB",
        0x2004,
        3,
        U16,
        0,
        4000,
        2400,
        group="current_limit",
        access=Access.BASIC,
        unit="mA",
        applies=COIL_B,
        text=T(
            "Solenoid B: maximum current",
            "Spule B: maximaler Strom",
            "Magnet B: maximální přípustná hodnota",
        ),
        source="fig. 8-18, table 7-14",
    ),
    Parameter(
        "DTAMP",
        0x6361,
        1,
        U16,
        0,
        FULL_SCALE,
        2458,
        group="dither",
        access=Access.BASIC,
        unit="%",
        scale=PERCENT,
        decimals=1,
        text=T("Dither: amplitude", "Dither: Amplitude", "Dynamické mazání: amplituda"),
        source="fig. 8-18 (15 %), table 7-16",
    ),
    Parameter(
        "DYNFREQ",
        0x6362,
        1,
        U16,
        0,
        65000,
        80,
        group="dither",
        access=Access.BASIC,
        unit="Hz",
        text=T("Dither: frequency", "Dither: Frequenz", "Dynamické mazání: frekvence"),
        source="fig. 8-18 (80 Hz), table 7-16",
    ),
]

_BITRATES = (
    (0, T("1 Mbit/s", "1 Mbit/s", "1 Mbit/s")),
    (1, T("800 kbit/s", "800 kbit/s", "800 kbit/s")),
    (2, T("500 kbit/s", "500 kbit/s", "500 kbit/s")),
    (3, T("250 kbit/s", "250 kbit/s", "250 kbit/s")),
    (4, T("125 kbit/s", "125 kbit/s", "125 kbit/s")),
    (5, T("50 kbit/s", "50 kbit/s", "50 kbit/s")),
    (6, T("20 kbit/s", "20 kbit/s", "20 kbit/s")),
)
CANOPEN_SETTINGS: list[Parameter] = [
    Parameter(
        "NODEID",
        0x2030,
        1,
        U8,
        1,
        127,
        10,
        group="canopen",
        applies=CA_ONLY,
        text=T(
            "CANopen node ID (node switch at 0)",
            "CANopen-Node-ID (Schalter auf 0)",
            "CANopen Node ID (přepínač v poloze 0)",
        ),
        source="§7.3.1, §8.7 (object 0x2030: decision)",
    ),
    Parameter(
        "BITRATE",
        0x2030,
        2,
        U8,
        0,
        6,
        2,
        group="canopen",
        applies=CA_ONLY,
        choices=_BITRATES,
        text=T(
            "CANopen bit rate (node switch at 0)",
            "CANopen-Bitrate (Schalter auf 0)",
            "Přenosová rychlost CANopen (přepínač v poloze 0)",
        ),
        source="table 7-1 (object 0x2030/2: decision)",
    ),
    Parameter(
        "CANTERM",
        0x2030,
        3,
        U8,
        0,
        1,
        0,
        group="canopen",
        applies=CA_ONLY,
        choices=OFF_ON,
        text=T("CAN terminator 120 Ω", "CAN-Abschlusswiderstand 120 Ω", "Terminátor CAN 120 Ω"),
        source="§7.3.1, §8.7 (object 0x2030/3: decision)",
    ),
]

MONITORING: list[Parameter] = [
    Parameter(
        "MONTYPE",
        0x6351,
        0,
        S8,
        2,
        2,
        2,
        group="monitoring",
        in_file=False,
        text=T("Control monitoring type", "Typ der Regelüberwachung", "Typ řídicího monitoringu"),
        source="table 7-16",
    ),
    Parameter(
        "MONDELAY",
        0x6352,
        1,
        U16,
        0,
        5000,
        1000,
        group="monitoring",
        unit="ms",
        text=T(
            "Control monitoring delay",
            "Verzögerung der Regelüberwachung",
            "Dopravní zpoždění řídicího monitoringu",
        ),
        source="table 7-16",
    ),
    Parameter(
        "MONTHRES",
        0x6353,
        1,
        S16,
        0,
        FULL_SCALE,
        1600,
        group="monitoring",
        unit="%",
        scale=PERCENT,
        decimals=1,
        text=T(
            "Control monitoring threshold",
            "Schwelle der Regelüberwachung",
            "Práh řídicího monitoringu",
        ),
        source="table 7-16",
    ),
]


__all__ = [
    "CANOPEN_SETTINGS",
    "CONTROLLERS",
    "CURRENT_AND_DITHER",
    "E02_ONLY",
    "MONITORING",
    "U8",
]

# Service objects for tuning from the PC (decision, not in the manual): while SETPOVRON = 1
# the firmware uses SETPOVR instead of the analog setpoint. The firmware switches the override
# off by itself on restart and when no USB report (or SDO request) arrived for 500 ms (a
# dropped cable never leaves a generator running).
SERVICE: list[Parameter] = [
    Parameter(
        "SETPOVRON",
        0x2050,
        1,
        U8,
        0,
        1,
        0,
        group="service",
        in_file=False,
        choices=OFF_ON,
        text=T(
            "Setpoint override from the PC on/off",
            "Sollwertvorgabe vom PC ein/aus",
            "Žádaná hodnota z PC zapnuto/vypnuto",
        ),
        source="decision (tuning generator)",
    ),
    Parameter(
        "SETPOVR",
        0x2050,
        2,
        S16,
        -FULL_SCALE,
        FULL_SCALE,
        0,
        group="service",
        in_file=False,
        unit="%",
        scale=PERCENT,
        decimals=1,
        text=T("Setpoint override value", "Sollwertvorgabe vom PC", "Žádaná hodnota z PC"),
        source="decision (tuning generator)",
    ),
]
