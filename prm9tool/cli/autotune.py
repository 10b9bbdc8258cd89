"""``prm9tool --autotune [LOOP]``: the Tuning window's autotune of one valve, headless.

The valve service's autotune (``service/autotune.py``, through the Python API's
``Valve.autotune``): steps with the present gains, a plant model, gains for the targets, the
proposal checked against the acceptance profile (``--profile``); the valve's own gains are
back afterwards. ``--apply`` then writes the proposed gains and stores them — only a proposal
that passes the profile and rests on a trustworthy model, as the window's Accept. Prints the
gains before → proposed and the verdict, or with ``--json [OUT.json]`` (or ``--report
OUT.json``) the run's record. Exit 0 when the proposal passes, 8 when it does not (docs/
tuning.md). The run moves the spool; a -CA valve as delivered waits for its master:
``--enable --hydraulics-safe`` as with ``--characterize``. Recorded in the history. No Qt.
"""

from __future__ import annotations

import argparse
import json
import sys

from prm9tool.api.valve import Valve
from prm9tool.characterize.frame import LimitExceededError
from prm9tool.characterize.rig import Stopped, ValveFaultError
from prm9tool.cli.batch_devices import BatchError
from prm9tool.cli.characterize import ENABLE_NEEDS_CONFIRMATION, stopped_text
from prm9tool.cli.enabling import commission
from prm9tool.cli.json_output import emit_json
from prm9tool.errors import CommunicationError, ExitCode, Prm9Error
from prm9tool.service.autotune import AutotuneOutcome

__all__ = ["run", "summary"]


def run(args: argparse.Namespace) -> int:
    """Entry point of ``--autotune``; returns the exit code."""
    from prm9tool.cli.values import _one_session

    if args.enable and not args.hydraulics_safe:
        print(f"prm9tool: {ENABLE_NEEDS_CONFIRMATION}", file=sys.stderr)
        return ExitCode.USAGE
    session = _one_session(args, "--autotune works")
    if isinstance(session, int):
        return session
    with Valve(session, history_db=args.history_db, command="--autotune") as valve:
        try:
            if args.enable:
                commission(valve.service)  # cli/enabling.py: its words and exit code
            outcome = valve.autotune(
                args.autotune, profile=args.profile or None, apply=args.apply,
                progress=lambda text: print(f"prm9tool: {text}", file=sys.stderr),
            )  # fmt: skip
        except BatchError as exc:
            print(f"prm9tool: {exc}", file=sys.stderr)
            return int(exc.code)
        except (OSError, ValueError) as exc:  # a profile that cannot be read, a bad setting
            print(f"prm9tool: --autotune: {exc}", file=sys.stderr)
            return ExitCode.USAGE
        except (Stopped, LimitExceededError, ValveFaultError) as exc:
            print(f"prm9tool: {stopped_text(exc)}", file=sys.stderr)
            return ExitCode.OUT_OF_LIMITS
        except CommunicationError as exc:
            print(f"prm9tool: {exc}", file=sys.stderr)
            return ExitCode.COMMUNICATION
        except Prm9Error as exc:  # refused (another motion runs), a test this link cannot take
            print(f"prm9tool: --autotune: {exc}", file=sys.stderr)
            return ExitCode.OUT_OF_LIMITS
    target = args.json if args.json is not None else args.report
    if target is not None:
        failed = emit_json(json.dumps(outcome.to_dict(), indent=2, ensure_ascii=False), target)
        if failed is not None:
            return failed
    if not isinstance(target, bool):
        print(summary(outcome))
    if args.apply and not outcome.applied:
        print("prm9tool: --apply: the proposal was not applied: it does not pass the acceptance "
              "profile or its model is not trustworthy", file=sys.stderr)  # fmt: skip
    return ExitCode.OK if outcome.passes else ExitCode.OUT_OF_LIMITS


def summary(outcome: AutotuneOutcome) -> str:
    """The gains before → proposed and the verdict, as ``--autotune`` prints them."""
    gains = ", ".join(f"{mn} {outcome.present.get(mn)} → {v}" for mn, v in outcome.proposed.items())
    state = "applied and stored" if outcome.applied else "not applied"
    return f"{outcome.loop} loop: {gains} (raw; {state})\n{outcome.verdict()}"
