"""Types of the lazily loaded names of prm9tool (prm9tool/__init__.py loads them on first use)."""

from prm9tool import api as api
from prm9tool import history as history
from prm9tool.api import (
    SIGNALS as SIGNALS,
)
from prm9tool.api import (
    AccessDeniedError as AccessDeniedError,
)
from prm9tool.api import (
    CommunicationError as CommunicationError,
)
from prm9tool.api import (
    DeviceInfo as DeviceInfo,
)
from prm9tool.api import (
    DeviceState as DeviceState,
)
from prm9tool.api import (
    FileFormatError as FileFormatError,
)
from prm9tool.api import (
    HistoryError as HistoryError,
)
from prm9tool.api import (
    LedState as LedState,
)
from prm9tool.api import (
    NmtCommand as NmtCommand,
)
from prm9tool.api import (
    NmtState as NmtState,
)
from prm9tool.api import (
    ParameterSet as ParameterSet,
)
from prm9tool.api import (
    Prm9Error as Prm9Error,
)
from prm9tool.api import (
    ReadBackError as ReadBackError,
)
from prm9tool.api import (
    SdoAbortError as SdoAbortError,
)
from prm9tool.api import (
    SetpointGenerator as SetpointGenerator,
)
from prm9tool.api import (
    TypeKeyError as TypeKeyError,
)
from prm9tool.api import (
    UploadResult as UploadResult,
)
from prm9tool.api import (
    ValueRangeError as ValueRangeError,
)
from prm9tool.api import (
    Valve as Valve,
)
from prm9tool.api import (
    ValveStatus as ValveStatus,
)
from prm9tool.api import (
    connect as connect,
)
from prm9tool.api import (
    diff as diff,
)
from prm9tool.api import (
    find_bitrate as find_bitrate,
)
from prm9tool.api import (
    list_devices as list_devices,
)
from prm9tool.api import (
    lss_assign as lss_assign,
)
from prm9tool.api import (
    lss_scan as lss_scan,
)
from prm9tool.api import (
    read_prm as read_prm,
)
from prm9tool.api import (
    write_prm as write_prm,
)

__version__: str
__all__: list[str]
