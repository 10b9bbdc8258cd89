"""Catalogue data: identity, live values and the setpoint chain (manual fig. 8-18, tables 7-14/7-16)."""

from __future__ import annotations

from prm9tool.catalogue.schema import Access, Applies, DataType, ObjAccess, Parameter, Texts
from prm9tool.catalogue.variant import Coils, Config

T = Texts
U8, U16, U32 = DataType.UNSIGNED8, DataType.UNSIGNED16, DataType.UNSIGNED32
S8, S16 = DataType.INTEGER8, DataType.INTEGER16
STR = DataType.VISIBLE_STRING
RO = ObjAccess.RO
# The firmware version the catalogue (and so the EDS) describes; the emulated valve runs it.
FIRMWARE_VERSION = "1.0.0"
PERCENT = 100.0 / 16384.0  # normalized internal scale: 16384 = 100 %
GAIN = 1.0 / 16384.0  # gain factors: 16384 = 1.0 (the manual's sensor-gain convention)

TWO_COILS = Applies(coils=frozenset({Coils.AB}))
COIL_A = Applies(coils=frozenset({Coils.AB, Coils.A}))
COIL_B = Applies(coils=frozenset({Coils.AB, Coils.B}))
E04_ONLY = Applies(configs=frozenset({Config.E04}))
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

IDENTITY: list[Parameter] = [
    Parameter(
        "PCODE",
        0x2041,
        0,
        STR,
        0,
        0,
        "",
        group="identity",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        text=T("Valve type key", "Typschlüssel des Ventils", "Objednací kód ventilu"),
        source="fig. 8-18 (object 0x2041: decision)",
    ),
    Parameter(
        "SNV",
        0x1018,
        4,
        U32,
        1,
        0xFFFFFFFF,
        1,
        group="identity",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        text=T("Valve serial number", "Seriennummer des Ventils", "Sériové číslo ventilu"),
        source="fig. 8-18, table 7-13",
    ),
    Parameter(
        "FWVER",
        0x100A,
        0,
        STR,
        0,
        0,
        FIRMWARE_VERSION,
        group="identity",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        text=T("Firmware version", "Firmware-Version", "Verze firmware"),
        source="table 7-13",
    ),
]

LIVE: list[Parameter] = [
    Parameter(
        "ERROR",
        0x2040,
        0,
        U16,
        0,
        0xFFFF,
        0,
        group="live",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        text=T(
            "Error message (CANopen error code)",
            "Fehlermeldung (CANopen-Fehlercode)",
            "Chybové hlášení (chybový kód CANopen)",
        ),
        source="fig. 8-18, table 5-1 (object 0x2040: decision)",
    ),
    Parameter(
        "PWR",
        0x2003,
        0,
        U16,
        0,
        65535,
        24000,
        group="live",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        unit="V",
        scale=0.001,
        decimals=2,
        text=T("Supply voltage", "Versorgungsspannung", "Napájecí napětí"),
        source="fig. 8-18, table 7-14",
    ),
    Parameter(
        "TEMP",
        0x2002,
        0,
        S8,
        -128,
        127,
        25,
        group="live",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        unit="°C",
        text=T("Electronics temperature", "Elektroniktemperatur", "Teplota elektroniky"),
        source="table 7-14",
    ),
    Parameter(
        "SWBAUD",
        0x2031,
        1,
        U8,
        0,
        15,
        6,
        group="canopen",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        applies=CA_ONLY,
        text=T(
            "Interface/bit-rate switch position",
            "Stellung Schalter Schnittstelle/Baudrate",
            "Poloha přepínače rozhraní/přenosová rychlost",
        ),
        source="table 7-17, 7-22 (object: decision)",
    ),
    Parameter(
        "SWNODE",
        0x2031,
        2,
        U8,
        0,
        15,
        2,
        group="canopen",
        access=Access.READ_ONLY,
        obj_access=RO,
        in_file=False,
        applies=CA_ONLY,
        text=T("Node-ID switch position", "Stellung Schalter Node-ID", "Poloha přepínače Node ID"),
        source="table 7-17, 7-22 (object: decision)",
    ),
]

SETPOINT: list[Parameter] = [
    Parameter(
        "AINSETP",
        0x2010,
        1,
        U16,
        0,
        14,
        9,
        default_one_coil=6,
        group="setpoint_input",
        access=Access.BASIC,
        choices=SIGNAL_TYPES,
        text=T(
            "Setpoint signal: signal type",
            "Sollwertsignal: Signaltyp",
            "Řídicí signál: typ signálu",
        ),
        source="fig. 8-18, tables 7-15/7-22; one coil: 0…10 V per table 8-4 (decision); object: decision",
    ),
    Parameter(
        "INVERSEP",
        0x2010,
        2,
        U8,
        0,
        1,
        0,
        group="setpoint_input",
        access=Access.BASIC,
        choices=POLARITY,
        text=T("Setpoint signal: polarity", "Sollwertsignal: Polarität", "Řídicí signál: polarita"),
        source="fig. 8-18 (object 0x2010/2: decision)",
    ),
    Parameter(
        "THRESETP",
        0x6345,
        1,
        S16,
        0,
        16384,
        819,
        group="threshold",
        access=Access.BASIC,
        unit="%",
        scale=PERCENT,
        decimals=1,
        text=T(
            "Setpoint signal: threshold",
            "Sollwertsignal: Schwelle",
            "Řídicí signál: prahová hodnota",
        ),
        source="fig. 8-18 (5 %), table 7-16",
    ),
    Parameter(
        "RAMPSETPOSUP",
        0x6332,
        1,
        U16,
        0,
        40000,
        0,
        group="ramps",
        access=Access.BASIC,
        unit="ms",
        text=T(
            "Positive signal range: ramp up",
            "Positiver Signalbereich: Rampe auf",
            "Horní rozsah signálu: rampa nahoru",
        ),
        source="fig. 8-18, table 7-16 (acceleration time positive)",
    ),
    Parameter(
        "RAMPSETPOSDOWN",
        0x6335,
        1,
        U16,
        0,
        40000,
        0,
        group="ramps",
        access=Access.BASIC,
        unit="ms",
        text=T(
            "Positive signal range: ramp down",
            "Positiver Signalbereich: Rampe ab",
            "Horní rozsah signálu: rampa dolů",
        ),
        source="fig. 8-18, table 7-16 (deceleration time positive)",
    ),
    Parameter(
        "RAMPSETNEGUP",
        0x6333,
        1,
        U16,
        0,
        40000,
        0,
        group="ramps",
        access=Access.BASIC,
        unit="ms",
        applies=TWO_COILS,
        text=T(
            "Negative signal range: ramp up",
            "Negativer Signalbereich: Rampe auf",
            "Dolní rozsah signálu: rampa nahoru",
        ),
        source="fig. 8-18, table 7-16 (acceleration time negative)",
    ),
    Parameter(
        "RAMPSETNEGDOWN",
        0x6336,
        1,
        U16,
        0,
        40000,
        0,
        group="ramps",
        access=Access.BASIC,
        unit="ms",
        applies=TWO_COILS,
        text=T(
            "Negative signal range: ramp down",
            "Negativer Signalbereich: Rampe ab",
            "Dolní rozsah signálu: rampa dolů",
        ),
        source="fig. 8-18, table 7-16 (deceleration time negative)",
    ),
    Parameter(
        "GAINSETPOS",
        0x6341,
        0,
        U32,
        0,
        65535,
        16384,
        group="gain_offset",
        access=Access.BASIC,
        scale=GAIN,
        decimals=3,
        text=T(
            "Gain, positive (E02: setpoint; E04: control deviation)",
            "Verstärkung positiv (E02: Sollwert; E04: Regelabweichung)",
            "Zesílení kladné (E02: řídicí signál; E04: regulační odchylka)",
        ),
        source="fig. 8-18, table 7-16 (0x6341 holds the positive gain: decision)",
    ),
    Parameter(
        "GAINSETNEG",
        0x2011,
        0,
        U32,
        0,
        65535,
        16384,
        group="gain_offset",
        access=Access.BASIC,
        scale=GAIN,
        decimals=3,
        applies=TWO_COILS,
        text=T(
            "Gain, negative (E02: setpoint; E04: control deviation)",
            "Verstärkung negativ (E02: Sollwert; E04: Regelabweichung)",
            "Zesílení záporné (E02: řídicí signál; E04: regulační odchylka)",
        ),
        source="fig. 8-18 (object 0x2011: decision)",
    ),
    Parameter(
        "OFFSETPOS",
        0x6343,
        1,
        S16,
        0,
        16384,
        0,
        group="gain_offset",
        access=Access.BASIC,
        unit="%",
        scale=PERCENT,
        decimals=1,
        text=T(
            "Offset, positive (dead-band compensation jump)",
            "Offset positiv (Totbandkompensation)",
            "Posunutí nuly kladné (kompenzace pásma necitlivosti)",
        ),
        source="fig. 8-18, table 7-16",
    ),
    Parameter(
        "OFFSETNEG",
        0x6344,
        1,
        S16,
        0,
        16384,
        0,
        group="gain_offset",
        access=Access.BASIC,
        unit="%",
        scale=PERCENT,
        decimals=1,
        applies=TWO_COILS,
        text=T(
            "Offset, negative (dead-band compensation jump)",
            "Offset negativ (Totbandkompensation)",
            "Posunutí nuly záporné (kompenzace pásma necitlivosti)",
        ),
        source="fig. 8-18, table 7-16",
    ),
    Parameter(
        "SETPLINON",
        0x6346,
        0,
        S8,
        -1,
        0,
        0,
        group="setpoint_linearization",
        choices=(
            (0, T("off", "aus", "vypnuto")),
            (
                -1,
                T(
                    "on (9-point curve)",
                    "ein (9-Punkte-Kennlinie)",
                    "zapnuto (9bodová charakteristika)",
                ),
            ),
        ),
        text=T(
            "Setpoint linearization on/off",
            "Sollwertlinearisierung ein/aus",
            "Linearizace řídicího signálu zapnuto/vypnuto",
        ),
        source="table 7-16 (-1 = manufacturer 9-point curve: decision)",
    ),
]


def _linearization(
    prefix: str, index: int, axis: str, group: str, what: Texts, applies: Applies, source: str
) -> list[Parameter]:
    points = "ABCDEFGHI"
    result = []
    for n, letter in enumerate(points):
        default = -16384 + n * 4096
        result.append(
            Parameter(
                f"{prefix}{axis}{letter}",
                index,
                n + 1,
                S16,
                -16384,
                16384,
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


_SETP_LIN = T("Setpoint linearization", "Sollwertlinearisierung", "Linearizace řídicího signálu")
SETPOINT_LINEARIZATION: list[Parameter] = [
    *_linearization(
        "SETPLIN", 0x2000, "X", "setpoint_linearization", _SETP_LIN, Applies(), "table 7-14"
    ),
    *_linearization(
        "SETPLIN", 0x2001, "Y", "setpoint_linearization", _SETP_LIN, Applies(), "table 7-14"
    ),
]
