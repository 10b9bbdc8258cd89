"""The comparison of two parameter sets (and optionally a third, the reference column).

A :class:`Comparison` lines up the *.prm parameter sets of its sides in catalogue order. Two
sides are compared (``sides[0]`` and ``sides[1]``, e.g. document and valve); an optional
reference (the factory defaults of the valve type) is shown beside them and never counts as a
difference. A side whose valve variant lacks a parameter shows no value there ("missing", a
difference: the type keys differ). A side whose valve type has the parameter but which holds
no value for it — a valve over CANopen without this project's object, a file marking it absent
— is "not on this valve": listed apart, never a difference (issue 20 item 4). Neither kind of
row can be chosen or applied. The user chooses per row which side's value to
take; :meth:`Comparison.to_apply` gives exactly the values that would change on a target side.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from prm9tool.catalogue import CATALOGUE, Access, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

Raw = int | str

_KEYS_DIFFER = QT_TRANSLATE_NOOP("Compare", "The type keys differ: {0} is {1}, {2} is {3}.")
_VARIANTS_DIFFER = QT_TRANSLATE_NOOP(
    "Compare",
    "The valve variants differ: only the parameters both have are compared; "
    "{0} parameters that one side lacks are left out.",
)


NOT_ON_VALVE = QT_TRANSLATE_NOOP("Compare", "not on this valve")
NOT_ON_SOURCE_VALVE = QT_TRANSLATE_NOOP("Compare", "not on the valve it was read from")


@dataclass(frozen=True)
class Side:
    """One column: a label for the user, the valve type and its raw values; ``absent`` says
    why a parameter of its valve type has no value (not on this valve)."""

    label: str
    type_key: TypeKey
    values: Mapping[str, Raw]
    absent: Message = field(default_factory=NOT_ON_VALVE)

    @classmethod
    def factory(cls, type_key: TypeKey, label: str = "factory defaults") -> Side:
        """The factory defaults of ``type_key`` (what ``--new`` writes)."""
        variant = type_key.variant
        params = CATALOGUE.file_parameters(variant)
        return cls(label, type_key, {p.mnemonic: p.default_for(variant) for p in params})

    def has(self, parameter: Parameter) -> bool:
        """True when this side's valve type has the parameter and a value for it."""
        return parameter.applies(self.type_key.variant) and parameter.mnemonic in self.values

    def value(self, parameter: Parameter) -> Raw | None:
        """The raw value, or None when the side lacks the parameter."""
        return self.values[parameter.mnemonic] if self.has(parameter) else None

    def lacks(self, parameter: Parameter) -> bool:
        """True when this side's valve type has the parameter but the side holds no value for
        it (not on this valve): not a difference."""
        return parameter.applies(self.type_key.variant) and parameter.mnemonic not in self.values


@dataclass(frozen=True)
class Row:
    """One parameter: its raw value on each side (None: missing) and on the reference."""

    parameter: Parameter
    values: tuple[Raw | None, ...]
    reference: Raw | None = None
    absent: tuple[bool, ...] = (False, False)  # per side: not on this valve

    @property
    def not_on_valve(self) -> bool:
        """True when a side's valve type has the parameter but the side holds no value."""
        return any(self.absent)

    @property
    def mnemonic(self) -> str:
        """The parameter's mnemonic."""
        return self.parameter.mnemonic

    @property
    def missing(self) -> bool:
        """True when one compared side's valve type has no such parameter."""
        return any(v is None and not a for v, a in zip(self.values, self.absent, strict=True))

    @property
    def comparable(self) -> bool:
        """True when both compared sides hold a value."""
        return all(value is not None for value in self.values)

    @property
    def changed(self) -> bool:
        """True when both compared sides have the parameter with different values."""
        return self.comparable and len(set(self.values)) > 1

    @property
    def differs(self) -> bool:
        """Changed or missing: a row the "differences only" filter keeps."""
        return self.missing or self.changed

    def display(self, column: int) -> str:
        """Side ``column``'s value in display units ("" when missing; -1: the reference)."""
        raw = self.reference if column < 0 else self.values[column]
        return "" if raw is None else self.parameter.format_display(raw)


@dataclass
class Comparison:
    """Two sides compared parameter by parameter, with an optional reference column."""

    sides: tuple[Side, Side]
    reference: Side | None = None
    rows: list[Row] = field(init=False)
    choices: dict[str, int] = field(init=False, default_factory=dict)

    def __post_init__(self) -> None:
        self.rows = [self._row(p) for p in self._parameters()]

    def _parameters(self) -> list[Parameter]:
        variants = {side.type_key.variant for side in self.sides}
        return [p for p in CATALOGUE if p.in_file and any(p.applies(v) for v in variants)]

    def _row(self, parameter: Parameter) -> Row:
        values = tuple(side.value(parameter) for side in self.sides)
        reference = self.reference.value(parameter) if self.reference else None
        return Row(parameter, values, reference, tuple(s.lacks(parameter) for s in self.sides))

    # --- what differs ---------------------------------------------------------------------
    @property
    def changed(self) -> list[Row]:
        """Rows both sides have with different values."""
        return [row for row in self.rows if row.changed]

    @property
    def missing(self) -> list[Row]:
        """Rows one side lacks (its valve variant has no such parameter)."""
        return [row for row in self.rows if row.missing]

    @property
    def not_on_valve(self) -> list[Row]:
        """Rows a side's valve type has but the side holds no value for: listed apart, not
        compared, never a difference."""
        return [row for row in self.rows if row.not_on_valve and not row.missing]

    @property
    def equal(self) -> bool:
        """True when nothing that both sides have differs and the type keys are the same
        (parameters not on a valve do not count)."""
        return not self.changed and not self.missing and not self.keys_differ

    @property
    def keys_differ(self) -> bool:
        """True when the two sides are for different type keys."""
        return self.sides[0].type_key != self.sides[1].type_key

    def warnings(self) -> list[Message]:
        """Type-key and variant mismatches, each a sentence for the user."""
        first, second = self.sides
        found: list[Message] = []
        if self.keys_differ:
            found.append(
                _KEYS_DIFFER(first.label, str(first.type_key), second.label, str(second.type_key))
            )
        if first.type_key.variant != second.type_key.variant:
            found.append(_VARIANTS_DIFFER(len(self.missing)))
        return found

    def filtered(
        self,
        differences_only: bool = False,
        mnemonics: Iterable[str] | None = None,
        access: Access | None = None,
    ) -> list[Row]:
        """Rows kept by the filters: only differences, only these parameters (a block of the
        diagram), only what the access level shows (Basic hides expert ones)."""
        wanted = set(mnemonics) if mnemonics is not None else None
        return [
            row
            for row in self.rows
            if (row.differs or not differences_only)
            and (wanted is None or row.mnemonic in wanted)
            and (access is not Access.BASIC or row.parameter.access is Access.BASIC)
        ]

    # --- choosing and applying ------------------------------------------------------------
    def choose(self, mnemonic: str, side: int | None) -> None:
        """Take side ``side``'s value for ``mnemonic`` (None: no choice). Missing rows refuse."""
        row = self.row(mnemonic)
        if side is None:
            self.choices.pop(mnemonic, None)
            return
        if not row.comparable:
            raise ValueError(f"{mnemonic}: one side lacks this parameter; it cannot be chosen")
        self.choices[mnemonic] = side

    def choose_all(self, side: int, rows: Iterable[Row] | None = None) -> None:
        """Take ``side``'s value for every changed row (of ``rows``, default all)."""
        for row in self.rows if rows is None else rows:
            if row.changed:
                self.choices[row.mnemonic] = side

    def row(self, mnemonic: str) -> Row:
        """The row of ``mnemonic``; KeyError if neither side has it."""
        for row in self.rows:
            if row.mnemonic == mnemonic:
                return row
        raise KeyError(mnemonic)

    def chosen(self) -> dict[str, Raw]:
        """The chosen value of every row with a choice, whichever side it comes from (what
        goes into a document or valve outside the comparison, e.g. from two history
        records)."""
        result: dict[str, Raw] = {}
        for mnemonic, side in self.choices.items():
            value = self.row(mnemonic).values[side]
            if value is not None:
                result[mnemonic] = value
        return result

    def to_apply(self, target: int) -> dict[str, Raw]:
        """The chosen values that differ from side ``target``'s: exactly what to write there."""
        result: dict[str, Raw] = {}
        for mnemonic, side in self.choices.items():
            row = self.row(mnemonic)
            value = row.values[side]
            if value is not None and value != row.values[target]:
                result[mnemonic] = value
        return result
