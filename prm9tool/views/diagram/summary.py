"""The key values a diagram block shows, formatted through the catalogue (e.g. "Kp 8")."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.canopen_switches import CanSettings, effective, format_bitrate
from prm9tool.i18n import current_language, format_value
from prm9tool.model.document import ParameterDocument

NO_VALUE = "—"


translate = QCoreApplication.translate  # the name pyside6-lupdate looks for


def value_text(doc: ParameterDocument, mnemonic: str) -> str:
    """``raw`` of ``mnemonic`` in display units with its unit, or its choice label."""
    param = CATALOGUE[mnemonic]
    raw = doc.value(mnemonic)
    if param.choices and isinstance(raw, int):
        return param.choice_text(raw, current_language())
    unit = f" {param.unit}" if param.unit else ""
    return f"{format_value(param, raw)}{unit}"


def _bare(doc: ParameterDocument, mnemonic: str) -> str:
    return format_value(CATALOGUE[mnemonic], doc.value(mnemonic))


def _has(doc: ParameterDocument, mnemonic: str) -> bool:
    return CATALOGUE[mnemonic].applies(doc.variant)


def _setpoint_input(doc: ParameterDocument) -> list[str]:
    return [
        value_text(doc, "AINSETP"),
        translate("DiagramSummary", "Polarity: %1").replace("%1", value_text(doc, "INVERSEP")),
    ]


def _threshold(doc: ParameterDocument) -> list[str]:
    return [translate("DiagramSummary", "Threshold %1").replace("%1", value_text(doc, "THRESETP"))]


def _pair(doc: ParameterDocument, pos: str, neg: str, unit: str) -> str:
    if _has(doc, neg):
        return f"+{_bare(doc, pos)} / −{_bare(doc, neg)}{unit}"
    return f"{_bare(doc, pos)}{unit}"


def _gain_offset(doc: ParameterDocument) -> list[str]:
    return [
        translate("DiagramSummary", "Gain %1").replace(
            "%1", _pair(doc, "GAINSETPOS", "GAINSETNEG", "")
        ),
        translate("DiagramSummary", "Offset %1").replace(
            "%1", _pair(doc, "OFFSETPOS", "OFFSETNEG", " %")
        ),
    ]


def _linearization(switch: str, on_value: int) -> Callable[[ParameterDocument], list[str]]:
    def lines(doc: ParameterDocument) -> list[str]:
        on = doc.value(switch) == on_value
        return [
            translate("DiagramSummary", "9-point curve on")
            if on
            else translate("DiagramSummary", "off (1:1)")
        ]

    return lines


def _ramps(doc: ParameterDocument) -> list[str]:
    up, down = _bare(doc, "RAMPSETPOSUP"), _bare(doc, "RAMPSETPOSDOWN")
    if not _has(doc, "RAMPSETNEGUP"):
        return [f"↑ {up} ms  ↓ {down} ms"]
    neg_up, neg_down = _bare(doc, "RAMPSETNEGUP"), _bare(doc, "RAMPSETNEGDOWN")
    return [f"+ ↑ {up}  ↓ {down} ms", f"− ↑ {neg_up}  ↓ {neg_down} ms"]


def _pidt1(prefix: str) -> Callable[[ParameterDocument], list[str]]:
    def lines(doc: ParameterDocument) -> list[str]:
        kp, ki = _bare(doc, f"{prefix}KP"), _bare(doc, f"{prefix}KI")
        kd, t1 = _bare(doc, f"{prefix}KD"), _bare(doc, f"{prefix}T1")
        return [f"Kp {kp}   Ki {ki}", f"Kd {kd}   T1 {t1}"]

    return lines


def _current_limit(doc: ParameterDocument) -> list[str]:
    return [
        translate("DiagramSummary", "Coil %1: %2")
        .replace("%1", coil)
        .replace("%2", value_text(doc, f"LIMT{coil}"))
        for coil in "AB"
        if _has(doc, f"LIMT{coil}")
    ]


def _dither(doc: ParameterDocument) -> list[str]:
    return [
        translate("DiagramSummary", "Amplitude %1").replace("%1", value_text(doc, "DTAMP")),
        translate("DiagramSummary", "Frequency %1").replace("%1", value_text(doc, "DYNFREQ")),
    ]


def _valve(doc: ParameterDocument) -> list[str]:
    key = str(doc.type_key)
    head, _, tail = key.partition("-24")
    coils = {
        "AB": translate("DiagramSummary", "coils A and B"),
        "A": translate("DiagramSummary", "coil A only"),
        "B": translate("DiagramSummary", "coil B only"),
    }
    lines = [head, f"24{tail}"] if tail else [key]
    return [*lines, coils[doc.variant.coils.value]]


def _sensor_input(doc: ParameterDocument) -> list[str]:
    return [
        value_text(doc, "SENSTYPE"),
        translate("DiagramSummary", "Polarity: %1").replace("%1", value_text(doc, "SENSINV")),
    ]


def _sensor_scaling(doc: ParameterDocument) -> list[str]:
    return [
        translate("DiagramSummary", "Offset %1").replace("%1", value_text(doc, "SENSOFFS")),
        translate("DiagramSummary", "Gain %1").replace("%1", value_text(doc, "SENSGAIN")),
    ]


def _supply(doc: ParameterDocument) -> list[str]:
    return [
        translate("DiagramSummary", "Voltage, temperature"),
        translate("DiagramSummary", "(live values)"),
    ]


def _can_settings(doc: ParameterDocument) -> CanSettings:
    """What the valve runs with: its switches (as read from it, else the delivery state of
    table 7-22) and the document's settings."""
    values = [int(doc.value(mn)) for mn in ("SWBAUD", "SWNODE", "NODEID", "BITRATE", "CANTERM")]
    return effective(*values)


def _canopen(doc: ParameterDocument) -> list[str]:
    settings = _can_settings(doc)
    if not settings.can_enabled:
        return [
            translate("DiagramSummary", "CANopen off"),
            translate("DiagramSummary", "analog setpoint"),
        ]
    rate = (
        format_bitrate(settings.bitrate_kbit)
        if settings.bitrate_kbit
        else translate("DiagramSummary", "auto bit rate")
    )
    terminator = CATALOGUE["CANTERM"].choice_text(int(settings.terminator), current_language())
    return [
        translate("DiagramSummary", "Node ID %1 · %2")
        .replace("%1", str(settings.node_id))
        .replace("%2", rate),
        translate("DiagramSummary", "Terminator %1").replace("%1", terminator),
    ]


def _canopen_detail(doc: ParameterDocument) -> str:
    return (
        translate(
            "DiagramSummary",
            "Rotary switches: interface %1, node ID %2 (read by the valve at power-up; "
            "before a valve was read, the delivery state).",
        )
        .replace("%1", f"{int(doc.value('SWBAUD')):X}")
        .replace("%2", f"{int(doc.value('SWNODE')):X}")
    )


_SUMMARIES: dict[str, Callable[[ParameterDocument], list[str]]] = {
    "setpoint_input": _setpoint_input,
    "threshold": _threshold,
    "gain_offset": _gain_offset,
    "setpoint_linearization": _linearization("SETPLINON", -1),
    "ramps": _ramps,
    "process_controller": _pidt1("PRC"),
    "position_controller": _pidt1("POS"),
    "current_limit": _current_limit,
    "dither": _dither,
    "valve": _valve,
    "ext_sensor": _sensor_input,
    "ext_sensor_scaling": _sensor_scaling,
    "ext_sensor_linearization": _linearization("SENSLINON", 1),
    "supply": _supply,
    "canopen": _canopen,
}


def block_lines(doc: ParameterDocument, block_id: str) -> list[str]:
    """The value lines block ``block_id`` shows for ``doc`` (at most three)."""
    return _SUMMARIES[block_id](doc)[:3]


def block_detail(doc: ParameterDocument, block_id: str) -> str:
    """More about what block ``block_id`` shows, for its tooltip ('' if nothing)."""
    return _canopen_detail(doc) if block_id == "canopen" else ""
