"""The public Python API of prm9tool: scripts, test benches, notebooks (docs/api.md).

Everything here is also reachable as ``prm9tool.<name>``; names load on first use (PEP 562),
so ``import prm9tool`` costs nothing and loads neither Qt nor the emulator. No Qt.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from prm9tool.api.compare import diff as diff
    from prm9tool.api.devices import connect as connect
    from prm9tool.api.devices import list_devices as list_devices
    from prm9tool.api.lss import find_bitrate as find_bitrate
    from prm9tool.api.lss import lss_assign as lss_assign
    from prm9tool.api.lss import lss_scan as lss_scan
    from prm9tool.api.measure import SetpointGenerator as SetpointGenerator
    from prm9tool.api.params import ParameterSet as ParameterSet
    from prm9tool.api.params import read_prm as read_prm
    from prm9tool.api.params import write_prm as write_prm
    from prm9tool.api.valve import ReadBackError as ReadBackError
    from prm9tool.api.valve import Valve as Valve
    from prm9tool.catalogue.commissioning import NmtCommand as NmtCommand
    from prm9tool.catalogue.signals import SIGNALS as SIGNALS
    from prm9tool.device.records import DeviceInfo as DeviceInfo
    from prm9tool.device.records import DeviceState as DeviceState
    from prm9tool.device.records import LedState as LedState
    from prm9tool.device.records import NmtState as NmtState
    from prm9tool.device.records import UploadResult as UploadResult
    from prm9tool.device.records import ValveStatus as ValveStatus
    from prm9tool.errors import AccessDeniedError as AccessDeniedError
    from prm9tool.errors import CommunicationError as CommunicationError
    from prm9tool.errors import FileFormatError as FileFormatError
    from prm9tool.errors import HistoryError as HistoryError
    from prm9tool.errors import Prm9Error as Prm9Error
    from prm9tool.errors import SdoAbortError as SdoAbortError
    from prm9tool.errors import TypeKeyError as TypeKeyError
    from prm9tool.errors import ValueRangeError as ValueRangeError

# name -> the module that defines it
EXPORTS = {
    "connect": "prm9tool.api.devices",
    "list_devices": "prm9tool.api.devices",
    "Valve": "prm9tool.api.valve",
    "ReadBackError": "prm9tool.api.valve",
    "ParameterSet": "prm9tool.api.params",
    "read_prm": "prm9tool.api.params",
    "write_prm": "prm9tool.api.params",
    "diff": "prm9tool.api.compare",
    "SetpointGenerator": "prm9tool.api.measure",
    "lss_scan": "prm9tool.api.lss",
    "lss_assign": "prm9tool.api.lss",
    "find_bitrate": "prm9tool.api.lss",
    "SIGNALS": "prm9tool.catalogue.signals",
    "NmtCommand": "prm9tool.catalogue.commissioning",
    "DeviceInfo": "prm9tool.device.records",
    "DeviceState": "prm9tool.device.records",
    "LedState": "prm9tool.device.records",
    "NmtState": "prm9tool.device.records",
    "UploadResult": "prm9tool.device.records",
    "ValveStatus": "prm9tool.device.records",
    "Prm9Error": "prm9tool.errors",
    "AccessDeniedError": "prm9tool.errors",
    "CommunicationError": "prm9tool.errors",
    "FileFormatError": "prm9tool.errors",
    "HistoryError": "prm9tool.errors",
    "SdoAbortError": "prm9tool.errors",
    "TypeKeyError": "prm9tool.errors",
    "ValueRangeError": "prm9tool.errors",
}
__all__ = sorted(EXPORTS)


def __getattr__(name: str) -> Any:
    module = EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # the next access is a plain lookup
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(EXPORTS))
