"""prm9tool's command line meeting a real SDO timeout in the ``canopen`` package (a child process).

``main()`` runs with a command (in place of the one its arguments name) that asks a node on an
empty python-can ``virtual`` bus for an object: the ``canopen`` package retries, gives up,
sends the abort 0x05040000 and logs "Transfer aborted by client …" on its logger. The process
prints what a user would see; tests/test_library_log.py reads its standard error.
"""

from __future__ import annotations

import argparse
import sys

from prm9tool.cli import main as cli
from prm9tool.errors import ExitCode


def ask_a_silent_node(_args: argparse.Namespace) -> int:
    """One SDO upload to node 5 of an empty bus, reported as a command would."""
    import can
    import canopen

    network = canopen.Network()
    network.connect(interface="virtual", channel=f"liblog-{id(network)}")
    node = network.add_node(5, canopen.ObjectDictionary())
    node.sdo.RESPONSE_TIMEOUT = 0.05
    try:
        node.sdo.upload(0x1000, 0)
    except (canopen.SdoCommunicationError, can.CanError):
        print("prm9tool: node 5 does not answer", file=sys.stderr)
        return ExitCode.COMMUNICATION
    finally:
        network.disconnect()
    return ExitCode.OK


if __name__ == "__main__":
    cli._headless_command = lambda _args: ("__main__", "ask_a_silent_node")  # type: ignore[assignment]
    sys.exit(cli.main(["--list-devices"]))
