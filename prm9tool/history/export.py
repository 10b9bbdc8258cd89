"""A history record's parameter set as a *.prm file or a CSV table (display units). No Qt."""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.atomicfile import atomic_write
from prm9tool.files.prmfile import PrmContents, write_file

Raw = int | str


def parameters_of(record: Mapping[str, Any]) -> dict[str, Raw] | None:
    """The record's full parameter set (None: the operation left it unknown)."""
    text = record.get("parameters")
    return None if text is None else dict(json.loads(text))


def contents_of(record: Mapping[str, Any]) -> PrmContents:
    """The record as *.prm contents; ValueError when it holds no parameter set."""
    values = parameters_of(record)
    if values is None:
        raise ValueError(
            f"the record ({record['operation']}, {record['outcome']}) holds no parameter set"
        )
    key = TypeKey.parse(record["type_key"])
    return PrmContents(key, values, int(record["serial"]), record["firmware"] or None)


def export_record(record: Mapping[str, Any], path: str | Path) -> None:
    """Write the record's parameters to ``path``: CSV for ``*.csv``, else a *.prm file."""
    target = Path(path)
    contents = contents_of(record)
    if target.suffix.lower() == ".csv":
        atomic_write(target, csv_text(record, contents.values).encode("utf-8"), backup=True)
    else:
        write_file(contents, target)


def csv_text(record: Mapping[str, Any], values: Mapping[str, Raw]) -> str:
    """``mnemonic,value,unit,description`` in catalogue order, after a header of the record."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["# serial", record["serial"], "type key", record["type_key"],
                     "recorded (UTC)", record["recorded_at"], "operation", record["operation"]])  # fmt: skip
    writer.writerow(["mnemonic", "value", "unit", "description"])
    for param in CATALOGUE:
        if param.mnemonic in values:
            raw = values[param.mnemonic]
            writer.writerow([param.mnemonic, param.format_display(raw), param.unit, param.text.en])
    return out.getvalue()
