"""Which of the main window's actions are enabled in which state of the document, the undo
stack, the access level and the connection."""

from __future__ import annotations

from prm9tool.catalogue import Access
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.connection import ValveConnection


def enabled_actions(
    doc: ParameterDocument,
    undo: DocumentUndo,
    access: AccessModel,
    connection: ValveConnection,
    uploaded: bool = False,
) -> dict[str, bool]:
    """Action name → enabled, for the actions whose state depends on the models;
    ``uploaded``: an upload was stored in this online session (Verify by restart…)."""
    online, busy = connection.is_online, connection.is_busy
    ready = online and not busy
    return {
        "save": doc.modified or doc.path is None,
        "undo": undo.stack.canUndo(),
        "redo": undo.stack.canRedo(),
        "online": not online and not busy,
        "hid_configuration": not online and not busy,  # the valve is chosen before
        "can_bus": online or not busy,  # online: the network view of the bus (issue 34)
        "export_dcf": doc.variant.canopen,
        "export_eds": doc.variant.canopen,  # the type's: online and offline alike
        "od_browser": ready,
        "offline": online or connection.is_reconnecting,  # also: stop looking for a lost valve
        "upload": ready,
        "download": ready,
        "store": ready,
        "compare_valve": ready,
        "restart": ready,
        "verify_restart": ready and uploaded,
        "restore_factory": not busy,
        "view_scope": online,
        "canopen": doc.variant.canopen,
        "change_password": access.level is Access.EXPERT,
        "valve_selection": not online,
        "new": not online,
        "open": not busy,
    }
