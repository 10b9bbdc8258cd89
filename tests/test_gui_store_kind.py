"""The GUI says which store happened after an upload over CANopen (issue 20 item 2): with
0x1010, kept by a valve that has no store command, or verified after a restart."""

from __future__ import annotations

import pytest
from support.gui_support import go_online

from prm9tool.catalogue.manual_od import KEPT_AS_WRITTEN, STORED_WITH_1010, VERIFIED_RESTART
from prm9tool.device.records import UploadResult


@pytest.mark.parametrize("store", [STORED_WITH_1010, KEPT_AS_WRITTEN, VERIFIED_RESTART, None])
def test_the_upload_message_names_the_store(qtbot, window, store):
    go_online(qtbot, window)
    messages: list[str] = []
    window.valve.message_posted.connect(messages.append)
    result = UploadResult(written=3, verified=True, stored=True, duration_s=0.1, store=store)
    window.valve.uploads.finished(result)
    (message,) = [m for m in messages if "verified and stored" in m]
    if store is None:  # USB: its own store command, nothing to add
        assert message.startswith("3 parameters written, verified and stored at ")
        assert "(" not in message
    else:
        hint = "; Valve → Verify by restart… checks that it keeps them"
        assert message.endswith(f" ({store})" + (hint if store == KEPT_AS_WRITTEN else ""))
