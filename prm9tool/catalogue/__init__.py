"""The parameter catalogue: the single source of truth for every valve parameter.

The table, the diagram, the *.prm format, the emulator's object dictionary and the EDS export
all derive from :data:`CATALOGUE`. Nothing about a parameter is written down anywhere else.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass

from prm9tool.catalogue._comm import (
    COMMUNICATION,
    ERROR_HISTORY_DEPTH,
    LOAD_SIGNATURE,
    SAVE_SIGNATURE,
)
from prm9tool.catalogue._control import (
    CANOPEN_SETTINGS,
    CONTROLLERS,
    CURRENT_AND_DITHER,
    MONITORING,
    SERVICE,
)
from prm9tool.catalogue._identity import IDENTITY, LIVE
from prm9tool.catalogue._profile import DEVICE_PROFILE
from prm9tool.catalogue._sensor import EXTERNAL_SENSOR, EXTERNAL_SENSOR_DATA
from prm9tool.catalogue._setpoint import SETPOINT, SETPOINT_LINEARIZATION
from prm9tool.catalogue._vocabulary import SIGNAL_TYPES
from prm9tool.catalogue.schema import (
    Access,
    Applies,
    DataType,
    ObjAccess,
    Parameter,
    Texts,
)
from prm9tool.catalogue.variant import Coils, Variant, variant_label
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

__all__ = [
    "CAPPED_BY",
    "CATALOGUE",
    "ERROR_HISTORY_DEPTH",
    "LOAD_SIGNATURE",
    "SAVE_SIGNATURE",
    "SIGNAL_TYPES",
    "Access",
    "Applies",
    "Catalogue",
    "DataType",
    "ObjAccess",
    "Parameter",
    "Problem",
    "Texts",
    "variant_label",
]

# Upper limits a parameter has beyond its own range: the current limits LIMTA/LIMTB are at most
# the nominal coil current CURNORM (manual table 7-14: "0..CURNORM"). The rule, the edit dialog's
# "allowed range" and the EDS limits all read this table.
CAPPED_BY: Mapping[str, str] = {"LIMTA": "CURNORM", "LIMTB": "CURNORM"}

# Recommended setpoint signal types per coil layout (manual table 8-4).
RECOMMENDED_SETPOINT_TYPES: Mapping[Coils, frozenset[int]] = {
    Coils.AB: frozenset({9, 5, 3}),  # ±10 V, ±10 mA, 12±8 mA (= 4…20 mA bipolar)
    Coils.A: frozenset({6, 0, 2}),  # 0…10 V, 0…20 mA, 4…20 mA
    Coils.B: frozenset({6, 0, 2}),
}


@dataclass(frozen=True)
class Problem:
    """A rule violation in a parameter set; ``severity`` is ``error`` or ``warning``.

    ``text`` is translatable (``prm9tool.translate.translated``); ``message`` is English.
    """

    mnemonics: tuple[str, ...]
    text: Message
    severity: str = "error"

    @property
    def message(self) -> str:
        """The problem in English (files, the command line)."""
        return str(self.text)


class Catalogue:
    """All parameters, with lookups by mnemonic and by object-dictionary address."""

    def __init__(self, parameters: Iterable[Parameter]) -> None:
        self._parameters = tuple(parameters)
        self._by_mnemonic = {p.mnemonic: p for p in self._parameters}
        self._by_key = {p.key: p for p in self._parameters}

    def __iter__(self) -> Iterator[Parameter]:
        return iter(self._parameters)

    def __len__(self) -> int:
        return len(self._parameters)

    def __contains__(self, mnemonic: object) -> bool:
        return mnemonic in self._by_mnemonic

    def __getitem__(self, mnemonic: str) -> Parameter:
        return self._by_mnemonic[mnemonic]

    def get(self, mnemonic: str) -> Parameter | None:
        """The parameter with that mnemonic, or None."""
        return self._by_mnemonic.get(mnemonic)

    def by_address(self, index: int, subindex: int) -> Parameter | None:
        """The parameter at ``index``/``subindex``, or None."""
        return self._by_key.get((index, subindex))

    def indices(self) -> set[int]:
        """All object indices that exist in the catalogue."""
        return {p.index for p in self._parameters}

    def for_variant(self, variant: Variant) -> list[Parameter]:
        """Every object that exists on ``variant`` (its object dictionary), in catalogue order.

        Includes objects that are not part of the variant's parameter set (``Applies``): the
        external sensor objects of an E02 -CA."""
        return [p for p in self._parameters if p.on_device(variant)]

    def parameter_set(self, variant: Variant) -> list[Parameter]:
        """The parameters of ``variant``: the list, the diagram, files, uploads, comparisons."""
        return [p for p in self._parameters if p.applies(variant)]

    def file_parameters(self, variant: Variant) -> list[Parameter]:
        """The parameter set a *.prm file and an upload carry for ``variant``."""
        return [p for p in self.parameter_set(variant) if p.in_file]

    def visible(self, variant: Variant, access: Access) -> list[Parameter]:
        """Parameters shown in the parameter list at ``access`` (Basic hides expert ones)."""
        result = []
        for p in self.parameter_set(variant):
            if p.group in ("canopen_comm", "profile_types", "service"):
                continue
            if access is Access.BASIC and p.access is Access.EXPERT:
                continue
            if p.group == "process_values" and access is Access.BASIC:
                continue
            result.append(p)
        return result

    def defaults(self, variant: Variant, node_id: int = 0) -> dict[str, int | str]:
        """Factory defaults (raw) of every parameter on ``variant``."""
        return {p.mnemonic: p.default_for(variant, node_id) for p in self.for_variant(variant)}

    def check_rules(self, variant: Variant, values: Mapping[str, int | str]) -> list[Problem]:
        """Cross-parameter rules (current limits, curves that go one way, recommended types)."""
        problems = _check_current_limits(values, self["CURNORM"].default)
        for prefix in ("SETPLIN", "SENSLIN"):
            problems.extend(_check_curve(prefix, values))
        problems.extend(self._check_setpoint_type(variant, values.get("AINSETP")))
        if not variant.canopen:
            for mn in ("AINSETP", "SENSTYPE"):
                if values.get(mn) == 14:
                    text = QT_TRANSLATE_NOOP(
                        "Problems", "{0}: 'value over CANopen' needs a -CA valve"
                    )(mn)
                    problems.append(Problem((mn,), text))
        return problems

    def _check_setpoint_type(self, variant: Variant, setp_type: int | str | None) -> list[Problem]:
        """Warn about a setpoint type manual table 8-4 does not recommend for the coil layout."""
        if not isinstance(setp_type, int) or setp_type == 14:
            return []
        if setp_type in RECOMMENDED_SETPOINT_TYPES[variant.coils]:
            return []
        label = dict(self["AINSETP"].choices).get(setp_type, str(setp_type))
        text = QT_TRANSLATE_NOOP(
            "Problems",
            "AINSETP: {0} is not a recommended setpoint type for {1} valves (manual table 8-4)",
        )(label, variant_label(variant))
        return [Problem(("AINSETP",), text, "warning")]


def _check_current_limits(values: Mapping[str, int | str], default: int | str) -> list[Problem]:
    curnorm = values.get("CURNORM", default)
    problems = []
    for mn in (mn for mn, cap in CAPPED_BY.items() if cap == "CURNORM"):
        value = values.get(mn)
        if isinstance(value, int) and isinstance(curnorm, int) and value > curnorm:
            text = QT_TRANSLATE_NOOP(
                "Problems", "{0} = {1} mA is above the nominal coil current CURNORM = {2} mA"
            )(mn, value, curnorm)
            problems.append(Problem((mn, "CURNORM"), text))
    return problems


def _check_curve(prefix: str, values: Mapping[str, int | str]) -> list[Problem]:
    """X points must increase strictly, Y points must not decrease (equal neighbours allowed)."""
    problems = []
    for axis in ("X", "Y"):
        names = [f"{prefix}{axis}{letter}" for letter in "ABCDEFGHI"]
        points = [values.get(n) for n in names]
        if not all(isinstance(v, int) for v in points):
            continue
        for left, right, a, b in zip(names, names[1:], points, points[1:], strict=False):
            assert isinstance(a, int) and isinstance(b, int)
            if b < a or (axis == "X" and b == a):
                problems.append(
                    Problem((left, right), _curve_text(prefix, axis, left, right, a, b))
                )
                break
    return problems


def _curve_text(prefix: str, axis: str, left: str, right: str, a: int, b: int) -> Message:
    if b == a:
        return QT_TRANSLATE_NOOP("Problems", "{0}: {1} equals {2}; X points must differ")(
            prefix, right, left
        )
    if axis == "X":
        template = QT_TRANSLATE_NOOP(
            "Problems", "{0} linearization points must increase strictly: {1} < {2}"
        )
    else:
        template = QT_TRANSLATE_NOOP(
            "Problems", "{0} linearization outputs must not decrease: {1} < {2}"
        )
    return template(prefix, right, left)


CATALOGUE = Catalogue(
    [
        *IDENTITY,
        *LIVE,
        *SETPOINT,
        *SETPOINT_LINEARIZATION,
        *CONTROLLERS,
        *CURRENT_AND_DITHER,
        *MONITORING,
        *EXTERNAL_SENSOR,
        *EXTERNAL_SENSOR_DATA,
        *CANOPEN_SETTINGS,
        *DEVICE_PROFILE,
        *SERVICE,
        *COMMUNICATION,
    ]
)
