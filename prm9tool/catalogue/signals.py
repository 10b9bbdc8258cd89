"""Measuring points: the signals of the valve's signal chain that can be watched live.

These are the red dots of the signal-flow diagram (manual §8.7.2) and the channels of the
oscilloscope. The emulator computes every one of them each 200 µs cycle; the USB stream carries
them by ``code``. Values are raw integers (S16 process values ±16384 = ±100 %, currents in mA,
duty in 0.01 %, supply in mV, temperature in 0.1 °C); ``scale`` converts to ``unit``.
"""

from __future__ import annotations

from dataclasses import dataclass

from prm9tool.catalogue.scale import PERCENT
from prm9tool.catalogue.schema import EVERY_VARIANT, Applies, Parameter, Texts
from prm9tool.catalogue.variant import Coils, Config, Variant

T = Texts
_E04 = Applies(configs=frozenset({Config.E04}))
_COIL_A = Applies(coils=frozenset({Coils.AB, Coils.A}))
_COIL_B = Applies(coils=frozenset({Coils.AB, Coils.B}))


@dataclass(frozen=True)
class Signal:
    """One measuring point."""

    code: int  # stable number used on the USB stream
    key: str  # stable name used in code, CSV headers and the diagram
    text: Texts
    unit: str
    scale: float
    block: str  # diagram block the dot sits after
    applies: Applies = EVERY_VARIANT

    def to_display(self, raw: float) -> float:
        """Raw value to display units."""
        return raw * self.scale


SIGNALS: tuple[Signal, ...] = (
    Signal(
        1,
        "setpoint_raw",
        T("Setpoint input", "Sollwerteingang", "Vstup žádané hodnoty"),
        "%",
        PERCENT,
        "setpoint_input",
    ),
    Signal(
        2,
        "setpoint_threshold",
        T(
            "Setpoint after polarity and threshold",
            "Sollwert nach Polarität und Schwelle",
            "Žádaná hodnota za polaritou a prahem",
        ),
        "%",
        PERCENT,
        "threshold",
    ),
    Signal(
        3,
        "setpoint_gain",
        T(
            "Setpoint after gain and offset",
            "Sollwert nach Verstärkung und Offset",
            "Žádaná hodnota za zesílením a posunutím",
        ),
        "%",
        PERCENT,
        "gain_offset",
    ),
    Signal(
        4,
        "setpoint_linearized",
        T(
            "Setpoint after linearization",
            "Sollwert nach Linearisierung",
            "Žádaná hodnota za linearizací",
        ),
        "%",
        PERCENT,
        "setpoint_linearization",
    ),
    Signal(
        5,
        "demand",
        T(
            "Demand value after ramp (0x6310)",
            "Sollwert nach Rampe (0x6310)",
            "Hodnota požadavku za rampou (0x6310)",
        ),
        "%",
        PERCENT,
        "ramps",
    ),
    Signal(
        6,
        "process_setpoint",
        T("Process setpoint", "Prozesssollwert", "Žádaná procesní veličina"),
        "%",
        PERCENT,
        "ramps",
        _E04,
    ),
    Signal(
        7,
        "process_actual",
        T(
            "Process actual value (0x6381)",
            "Prozessistwert (0x6381)",
            "Skutečná procesní veličina (0x6381)",
        ),
        "%",
        PERCENT,
        "ext_sensor_linearization",
        _E04,
    ),
    Signal(
        8,
        "process_deviation",
        T(
            "Process deviation after gain and offset",
            "Prozessabweichung nach Verstärkung und Offset",
            "Regulační odchylka za zesílením a posunutím",
        ),
        "%",
        PERCENT,
        "gain_offset",
        _E04,
    ),
    Signal(
        9,
        "position_setpoint",
        T("Position setpoint", "Lagesollwert", "Žádaná poloha šoupátka"),
        "%",
        PERCENT,
        "process_controller",
    ),
    Signal(
        10,
        "position_actual",
        T(
            "Spool position actual (0x6301)",
            "Schieberlage Ist (0x6301)",
            "Skutečná poloha šoupátka (0x6301)",
        ),
        "%",
        PERCENT,
        "position_sensor",
    ),
    Signal(
        11,
        "position_deviation",
        T(
            "Position control deviation",  # = 0x6350 in position mode only (docs/emulator.md)
            "Lageregelabweichung",
            "Odchylka řízení polohy",
        ),
        "%",
        PERCENT,
        "position_controller",
    ),
    Signal(
        12,
        "controller_output",
        T("Position controller output", "Ausgang Lageregler", "Výstup regulátoru polohy"),
        "%",
        PERCENT,
        "position_controller",
    ),
    Signal(
        13,
        "current_setpoint_a",
        T("Current setpoint coil A", "Stromsollwert Spule A", "Žádaný proud cívky A"),
        "mA",
        1.0,
        "current_limit",
        _COIL_A,
    ),
    Signal(
        14,
        "current_setpoint_b",
        T("Current setpoint coil B", "Stromsollwert Spule B", "Žádaný proud cívky B"),
        "mA",
        1.0,
        "current_limit",
        _COIL_B,
    ),
    Signal(
        15,
        "current_a",
        T("Coil current A", "Spulenstrom A", "Proud cívky A"),
        "mA",
        1.0,
        "dither",
        _COIL_A,
    ),
    Signal(
        16,
        "current_b",
        T("Coil current B", "Spulenstrom B", "Proud cívky B"),
        "mA",
        1.0,
        "dither",
        _COIL_B,
    ),
    Signal(
        17,
        "pwm_a",
        T("PWM duty coil A", "PWM-Tastgrad Spule A", "Střída PWM cívky A"),
        "%",
        0.01,
        "dither",
        _COIL_A,
    ),
    Signal(
        18,
        "pwm_b",
        T("PWM duty coil B", "PWM-Tastgrad Spule B", "Střída PWM cívky B"),
        "%",
        0.01,
        "dither",
        _COIL_B,
    ),
    Signal(
        19,
        "supply_voltage",
        T("Supply voltage", "Versorgungsspannung", "Napájecí napětí"),
        "V",
        0.001,
        "supply",
    ),
    Signal(
        20,
        "temperature",
        T("Electronics temperature", "Elektroniktemperatur", "Teplota elektroniky"),
        "°C",
        0.1,
        "supply",
    ),
    Signal(
        21,
        "sensor_raw",
        T("External sensor input", "Eingang externer Sensor", "Vstup externího snímače"),
        "%",
        PERCENT,
        "ext_sensor",
        _E04,
    ),
)

BY_KEY = {s.key: s for s in SIGNALS}
BY_CODE = {s.code: s for s in SIGNALS}
MAX_CHANNELS = 3  # the valve streams at most three measuring points at once (manual §8.7.2)

# Measuring points the valve also holds as an object of its dictionary (manual tables 7-13 and
# 7-14, CiA 408): readable at any time, also while the stream carries other points. Key ->
# (parameter mnemonic, factor from the object's raw value to the measuring point's raw units).
SIGNAL_OBJECTS: dict[str, tuple[str, float]] = {
    "position_actual": ("POSACT", 1.0),
    "process_actual": ("PRCACT", 1.0),
    "demand": ("DEMAND", 1.0),
    "position_deviation": ("CTRLDEV", 1.0),
    "supply_voltage": ("PWR", 1.0),
    "temperature": ("TEMP", 10.0),  # °C -> 0.1 °C
}

# Measuring points that are the setpoint a CANopen master writes (RPDO1 entry 2, manual table
# 7-13: 0x6300 in control mode 2, 0x6380 in mode 4): key -> the object's mnemonic. TPDO1 does
# not carry them back; over CANopen the scope shows the setpoint the tool itself sends.
SETPOINT_SIGNALS: dict[str, str] = {"position_setpoint": "POSSETP", "process_setpoint": "PRCSETP"}


def signal_object(key: str) -> tuple[Parameter, float] | None:
    """The catalogue parameter of the object that holds measuring point ``key`` (its address
    and data type: 0x6301/1, not the record's count at /0) and the factor from its raw value to
    the point's raw units; None when the point has no object (SIGNAL_OBJECTS)."""
    from prm9tool.catalogue import CATALOGUE

    found = SIGNAL_OBJECTS.get(key)
    return None if found is None else (CATALOGUE[found[0]], found[1])


def signal_at_index(index: int) -> str | None:
    """The measuring point the object ``index`` holds (0x6301 → ``position_actual``, the
    value a PDO mapping entry names by its index); None for any other object."""
    from prm9tool.catalogue import CATALOGUE

    for key, (mnemonic, _factor) in SIGNAL_OBJECTS.items():
        if CATALOGUE[mnemonic].index == index:
            return key
    return None


def signals_for(variant: Variant) -> list[Signal]:
    """The measuring points that exist on ``variant``."""
    return [s for s in SIGNALS if s.applies(variant)]


# One rule for every measured value shown (diagram, parameter list, valve status): decimals by
# unit. Stored parameters keep their own rule: the shortest text that reads back exactly.
MEASURED_DECIMALS = {"%": 1, "mA": 0, "V": 2, "°C": 1}
