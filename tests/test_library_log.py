"""The CAN libraries' log records reach the user as prm9tool's messages, never raw (issue 20
item 9)."""

from __future__ import annotations

import logging
import os
import subprocess
import sys
import threading
from pathlib import Path

from prm9tool.device.canlink.liblog import describe, route_library_logs

HERE = Path(__file__).parent
ABANDONED = (
    "prm9tool: CANopen: prm9tool abandoned an SDO transfer: SDO protocol timed out "
    "(abort code 0x05040000)"
)


def test_the_command_line_turns_a_real_sdo_abort_into_its_own_message():
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(HERE.parent), str(HERE)])}
    done = subprocess.run(
        [sys.executable, str(HERE / "support" / "can_liblog_driver.py")],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
        check=False,
    )
    assert done.returncode == 6, done.stderr
    assert "Transfer aborted by client" not in done.stderr  # the library's raw line
    lines = done.stderr.splitlines()
    assert ABANDONED in lines
    assert lines[-1] == "prm9tool: node 5 does not answer"  # the command's own report follows


def test_records_are_described_in_the_users_terms():
    def record(name: str, level: int, msg: str, *args: object) -> logging.LogRecord:
        return logging.getLogger(name).makeRecord(name, level, "x.py", 1, msg, args, None)

    aborted = record(
        "canopen.sdo.client",
        logging.ERROR,
        "Transfer aborted by client with code 0x%08X",
        0x06020000,
    )
    assert str(describe(aborted)) == (
        "CANopen: prm9tool abandoned an SDO transfer: object does not exist in the object "
        "dictionary (abort code 0x06020000)"
    )
    retry = record("canopen.sdo.client", logging.WARNING, "No SDO response received")
    assert "did not answer an SDO request in time" in str(describe(retry))
    other = record(
        "can.interfaces.socketcan",
        logging.ERROR,
        "Could not access SocketCAN device %s (%s)",
        "can0",
        "no such device",
    )
    assert str(describe(other)) == (
        "CAN interface (can.interfaces.socketcan): Could not access SocketCAN device can0 "
        "(no such device)"
    )


def test_routing_is_undone_and_debugging_is_not_shown():
    seen = []
    logger = logging.getLogger("canopen")
    before = (logger.propagate, logger.level, list(logger.handlers))
    undo = route_library_logs(seen.append)
    logging.getLogger("canopen.pdo").debug("a frame")
    logging.getLogger("can").warning("bus heavy")
    undo()
    assert [str(m) for m in seen] == ["CAN interface (can): bus heavy"]
    assert (logger.propagate, logger.level, list(logger.handlers)) == before


def test_the_gui_shows_library_messages_in_the_status_bar(window, qtbot):
    from prm9tool.app import show_library_messages

    library_log = show_library_messages(window)
    try:
        worker = threading.Thread(  # the bus's receive thread logs, not the GUI thread
            target=logging.getLogger("canopen.sdo.client").error,
            args=("Transfer aborted by client with code 0x%08X", 0x05040000),
        )
        with qtbot.waitSignal(library_log.message_posted):
            worker.start()
        worker.join()
        assert window.status.currentMessage() == ABANDONED.removeprefix("prm9tool: ")
    finally:
        library_log.close()
