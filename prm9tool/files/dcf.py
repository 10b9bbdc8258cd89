"""CiA 306 DCF: the EDS of a valve with its configured values (``ParameterValue``) and the
commissioning section, e.g. for a PLC's CANopen configurator.

The DCF is the EDS prm9tool exports (prm9tool.files.eds) with, in every object section whose
value is known, ``ParameterValue=`` after ``DefaultValue=``, and a ``[DeviceComissioning]``
section (CiA 306 spells it so) with node ID, bit rate and node name.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from datetime import datetime

from prm9tool.catalogue import CATALOGUE, DataType, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.eds import export_eds

_SECTION = re.compile(r"^\[([0-9A-F]{4})(?:sub([0-9A-F]+))?\]$")


def export_dcf(
    type_key: str | TypeKey,
    values: Mapping[str, int | str],
    node_id: int,
    bitrate_kbit: int,
    node_name: str = "",
    created: datetime | None = None,
) -> str:
    """A DCF for the valve ``type_key`` with the raw ``values`` (by mnemonic) it is configured
    with, at ``node_id`` and ``bitrate_kbit``. TypeKeyError for a key without -CA."""
    key = type_key if isinstance(type_key, TypeKey) else TypeKey.parse(type_key)
    by_address = {p.key: p for p in CATALOGUE.for_variant(key.variant)}
    lines = export_eds(key, created).splitlines()
    out: list[str] = []
    param: Parameter | None = None
    for line in lines:
        match = _SECTION.match(line)
        if match:
            index, sub = int(match.group(1), 16), int(match.group(2) or "0", 16)
            param = by_address.get((index, sub))
        out.append(line)
        if line.startswith("DefaultValue=") and param is not None and param.mnemonic in values:
            out.append(f"ParameterValue={_text(param, values[param.mnemonic])}")
        if line.startswith("FileName="):
            out[-1] = line.rsplit(".", 1)[0] + ".dcf"
    out += [
        "[DeviceComissioning]",
        f"NodeID={node_id}",
        f"NodeName={node_name or key}",
        f"Baudrate={bitrate_kbit}",
        "NetNumber=1",
        "NetworkName=",
        "CANopenManager=0",
        "LSS_SerialNumber=0",
        "",
    ]
    return "\n".join(out) + "\n"


def _text(param: Parameter, value: int | str) -> str:
    if isinstance(value, str):
        return value.encode("ascii", errors="replace").decode("ascii")
    if param.dtype is DataType.UNSIGNED32:
        return f"0x{value:X}"
    return str(value)
