"""prm9tool: parameterization tool for PRM9 proportional directional valves.

The public Python API (docs/api.md)::

    import prm9tool
    with prm9tool.connect("emulator:PRM9-06.3Z11/30-24E02S02-CA:4711") as valve:
        valve["LIMTA"] = 1800

Its names (:data:`prm9tool.api.EXPORTS`) load on first use (PEP 562): ``import prm9tool``
loads neither Qt nor the emulator, and the GUI's start-up pays nothing for them.
"""

from __future__ import annotations

import importlib
from typing import Any

from prm9tool._version import __version__

# the names' types: __init__.pyi (a TYPE_CHECKING import here would be an import of the API
# by every module that reads __version__, for import-linter)
_SUBPACKAGES = ("api", "history")  # reachable as attributes without importing them first
# the API's names, loaded from prm9tool.api on first use
__all__ = [
    "SIGNALS",
    "AccessDeniedError",
    "CommunicationError",
    "DeviceInfo",
    "DeviceState",
    "FileFormatError",
    "HistoryError",
    "LedState",
    "NmtCommand",
    "NmtState",
    "ParameterSet",
    "Prm9Error",
    "ReadBackError",
    "SdoAbortError",
    "SetpointGenerator",
    "TypeKeyError",
    "UploadResult",
    "ValueRangeError",
    "Valve",
    "ValveStatus",
    "__version__",
    "api",
    "connect",
    "diff",
    "find_bitrate",
    "history",
    "list_devices",
    "lss_assign",
    "lss_scan",
    "read_prm",
    "write_prm",
]


def __getattr__(name: str) -> Any:
    if name in _SUBPACKAGES:
        return importlib.import_module(f"{__name__}.{name}")
    if name.startswith("__") or name not in __all__:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module("prm9tool.api"), name)


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
