"""``--restart``, ``--restore-factory``, ``--enable`` and ``--disable`` of one valve: the
window's Valve → Restart valve, Valve → Restore factory values and the status window's Enable
and Disable, through the same operations of the valve service (``prm9tool.service.valve``).

Each moves the spool, so each needs ``--hydraulics-safe``, the answer to the window's question:
a restart (also the one that makes the factory values effective) returns the spool to its
spring-centred position and ignores the setpoint for a few seconds — over CAN a -CA valve then
comes back in pre-operational, waiting for its master (``--enable``); ``--enable`` makes the
valve follow its setpoint (NMT start when it waits, then the control word 08h → 09h → 0Bh →
0Fh, as ``--characterize --enable``), ``--disable`` takes it back to INIT (0Fh → 0Bh → 09h →
08h). The restart and the factory reset are recorded in the history as the window records
them (``restart`` and ``restore-factory``, with the set read back after); ``--json [OUT.json]``
for what happened. Exit codes as ``--batch`` (docs/batch.md); a failed ``--enable`` or
``--disable`` as ``cli/enabling.py`` rules for every ``--enable``. No Qt.
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from prm9tool.api.params import display
from prm9tool.api.valve import Valve
from prm9tool.cli.batch_devices import BatchError
from prm9tool.cli.enabling import commission, exit_code_of, takes_control_word
from prm9tool.cli.json_output import emit_json
from prm9tool.cli.values import _one_session
from prm9tool.device.records import Value, ValveStatus
from prm9tool.errors import ExitCode, Prm9Error

# the options, in the order usage_problem names them, and the attribute each sets
COMMANDS = {"--restart": "restart", "--restore-factory": "restore_factory",
            "--enable": "enable", "--disable": "disable"}  # fmt: skip

RESTART_WARNING = (
    "restarting the valve electronics is only allowed with the hydraulic circuit "
    "disconnected: during the restart the spool returns to its spring-centred position and "
    "the setpoint is ignored for a few seconds"
)
FACTORY_WARNING = (
    "the valve's stored parameters are reset to the factory values, which take effect after "
    "a restart of the valve (after its backup file, if it has none yet); " + RESTART_WARNING
)
ENABLE_WARNING = (
    "enabled, the valve follows its setpoint and the spool moves (on E04 the actuator too): "
    "make sure the hydraulics are safe for it"
)
DISABLE_WARNING = (
    "disabled, the valve stops following its setpoint and the spool returns to its rest "
    "position: make sure the hydraulics are safe for it"
)
WARNINGS = {"restart": RESTART_WARNING, "restore_factory": FACTORY_WARNING,
            "enable": ENABLE_WARNING, "disable": DISABLE_WARNING}  # fmt: skip

# What is being done, once --hydraulics-safe confirmed the warning (the warning itself, shown
# after the confirmation, read like a refusal)
DOING = {
    "restart": "restarting the valve (hydraulics confirmed safe): the spool returns to its "
    "spring-centred position and the setpoint is ignored for a few seconds",
    "restore_factory": "restoring the factory values (hydraulics confirmed safe), then "
    "restarting the valve: the spool returns to its spring-centred position and the setpoint "
    "is ignored for a few seconds",
    "enable": "enabling the valve (hydraulics confirmed safe): it follows its setpoint",
    "disable": "disabling the valve (hydraulics confirmed safe): the spool returns to its rest "
    "position",
}


def command_of(args: argparse.Namespace) -> str | None:
    """The valve command ``args`` name alone (``--enable`` beside a test is that test's)."""
    for flag, dest in COMMANDS.items():
        if getattr(args, dest, False):
            return flag
    return None


def confirmation_problem(flag: str) -> str:
    """The refusal of ``flag`` without ``--hydraulics-safe``: the window's warning."""
    return f"{flag}: {WARNINGS[COMMANDS[flag]]}; add --hydraulics-safe"


def run(args: argparse.Namespace) -> int:
    """Entry point of the four valve commands; returns the exit code."""
    flag = command_of(args)
    assert flag is not None  # cli.main dispatches here only then
    if not args.hydraulics_safe:  # usage_problem says so first; a direct caller too
        print(f"prm9tool: {confirmation_problem(flag)}", file=sys.stderr)
        return ExitCode.USAGE
    session = _one_session(args, f"{flag} works")
    if isinstance(session, int):
        return session
    with Valve(session, history_db=args.history_db, command=flag) as valve:
        try:
            report, lines = _run(flag, valve)
        except BatchError as exc:  # --enable: cli/enabling.py's words and exit code
            print(f"prm9tool: {exc}", file=sys.stderr)
            return int(exc.code)
        except Prm9Error as exc:  # the same rule: 2 CANopen off, 6 the link, 1 the valve refused
            print(f"prm9tool: {flag}: {exc}", file=sys.stderr)
            return exit_code_of(exc)
        if args.json:
            text = json.dumps({"device": valve.info.to_dict(), **report}, indent=2)
            return emit_json(text, args.json) or ExitCode.OK
    for text in lines:
        print(text)
    return ExitCode.OK


def _run(flag: str, valve: Valve) -> tuple[dict[str, Any], list[str]]:
    """Run ``flag`` through the valve service: the JSON report and the lines to print."""
    service = valve.service
    if flag in ("--enable", "--disable"):
        takes_control_word(service)  # CANopen off: refused, nothing sent (exit 2)
    print(f"prm9tool: {flag}: {DOING[COMMANDS[flag]]} …", file=sys.stderr)
    if flag == "--restart":
        values = service.restart_and_read()  # the window's Restart valve (recorded)
        said = [f"the valve restarted; it runs with its stored parameters ({len(values)} read)"]
        said += _after_restart(service.commissioning.wait_booted())
        return {"operation": "restart", "values": _shown(valve, values)}, said
    if flag == "--restore-factory":
        factory, backup = service.restore_factory()  # the window's, online (recorded)
        kept = (
            f"the valve's previous parameters are in {backup}"
            if backup is not None
            else "the valve's backup from before is kept"
        )
        said = [
            f"factory values restored; {kept}",
            *_after_restart(service.commissioning.wait_booted()),
        ]
        report = {"operation": "restore-factory", "backup": None if backup is None else str(backup),
                  "values": _shown(valve, factory or {})}  # fmt: skip
        return report, said
    if flag == "--enable":
        status = commission(service, say=False)  # NMT start when it waits, then 08h … 0Fh
        return {"operation": "enable", "status": status.to_dict()}, [_state(status)]
    status = service.commissioning.disable()  # NotDisabledError: still active (exit 1)
    return {"operation": "disable", "status": status.to_dict()}, [_state(status)]


def _shown(valve: Valve, values: dict[str, Value]) -> dict[str, Any]:
    """The values in display units (as ``--get --json`` prints them)."""
    shown: dict[str, Any] = {}
    for mnemonic, value in values.items():
        try:
            shown[mnemonic] = display(valve.parameter(mnemonic), value)
        except KeyError:  # not in this variant's catalogue: as the valve gave it
            shown[mnemonic] = value
    return shown


def _state(status: ValveStatus) -> str:
    if str(status.nmt_state) == "unknown":  # over CAN, before its first heartbeat (0x1017)
        return (
            f"device state {status.device_state}, NMT state not heard yet (it answers SDO: "
            "pre-operational or operational; its heartbeat had not come)"
        )
    return f"device state {status.device_state}, NMT {status.nmt_state}"


def _after_restart(status: ValveStatus) -> list[str]:
    """What a -CA valve waiting for its master after the restart means (manual §7.2)."""
    if str(status.nmt_state) in ("pre-operational", "stopped"):
        return [
            f"{_state(status)}: it waits for its CANopen master and does not follow its "
            "setpoint (--enable --hydraulics-safe enables it)"
        ]
    return [_state(status)]


__all__ = ["COMMANDS", "command_of", "confirmation_problem", "run"]
