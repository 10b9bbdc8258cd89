"""``--fit-twin OUT.toml``: a valve's twin (docs/twin.md), fitted from a characterization's
report (``--from RUN.json``) or from a characterization it runs itself on one valve
(``--device ID`` with the CAN options, or ``--emulator KEY``; ``--profile`` as
``--characterize``), both through :mod:`prm9tool.twin.fitvalve`. The run and the twin are
recorded in the history for the valve's serial. Prints the fit report (``--json``: as JSON).

Exit codes: 0 fitted; 2 usage; 3 a report, CSV or output that cannot be read or written (or a
run with no position-loop step to fit); 4/6 the valve not found or not answering; 8 the
characterization stopped.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.errors import CommunicationError, ExitCode, Prm9Error

if TYPE_CHECKING:
    from prm9tool.characterize.run import Characterization
    from prm9tool.service.twin import ProvenTwin


def run(args: argparse.Namespace) -> int:
    """Fit, write the twin file, print the fit report (``--json``: as JSON)."""
    if args.fit_from is not None:
        code, proven = _from_report(args)
    else:
        code, proven = _from_valve(args)
    if proven is None:
        return code
    result, sides = proven.twin.fit, proven.sides
    if proven.proof_problem:
        print(f"prm9tool: the twin could not be characterized: {proven.proof_problem}",
              file=sys.stderr)  # fmt: skip
    if args.json:
        text = json.dumps(proven.report(), indent=2)
        if isinstance(args.json, str):  # --json OUT.json: the fit report into that file
            Path(args.json).write_text(text + "\n", encoding="utf-8")
        else:
            print(text)
        return ExitCode.OK
    print(f"twin {args.fit_twin}: residual {result.start_rms_pct:.3f} % → {result.rms_pct:.3f} %"
          f" rms ({'explained' if result.explained else 'NOT explained by the plant structure'})")  # fmt: skip
    for c in result.constants:
        state = "determined" if c.determined else "not determined, kept"
        print(f"  {c.name}: {c.start:g} → {c.value:.4g} ({state})")
    if sides:
        from prm9tool.twin.proof import table

        print(f"the twin characterized as the valve was ({proven.proof_link}):")
        print("\n".join(f"  {line}" for line in table(sides)))
    return ExitCode.OK


def _from_report(args: argparse.Namespace) -> tuple[int, ProvenTwin | None]:
    """The run of a ``--characterize --json`` report read back (its steps, sweep and static
    characteristic: :mod:`prm9tool.twin.report`), fitted and recorded as ``--device`` does
    (the twin only: the run was recorded when it was measured), and the side-by-side."""
    from prm9tool.twin.report import run_of_report

    try:
        run = run_of_report(args.fit_from)
    except Prm9Error as exc:
        print(f"prm9tool: --fit-twin: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE, None
    return _fit_run(args, run)


def _from_valve(args: argparse.Namespace) -> tuple[int, ProvenTwin | None]:
    """Characterize the one valve of ``--device``/``--emulator``, record the run, fit, and
    characterize the twin as the valve was (the side-by-side)."""
    from prm9tool.characterize.frame import LimitExceededError
    from prm9tool.characterize.rig import Stopped, ValveFaultError
    from prm9tool.characterize.run import characterize
    from prm9tool.cli.batch_devices import BatchError
    from prm9tool.cli.characterize import _profile, _rig, stopped_text
    from prm9tool.cli.history import recorder_for
    from prm9tool.service.history import record_characterization

    if not Path(args.fit_twin).parent.is_dir():
        print(f"prm9tool: --fit-twin {args.fit_twin}: there is no folder "
              f"{Path(args.fit_twin).parent}", file=sys.stderr)  # fmt: skip
        return ExitCode.USAGE, None
    try:
        profile = _profile(args)
        rig, close = _rig(args, "--fit-twin")
    except BatchError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return int(exc.code), None
    try:
        run = characterize(rig, profile, lambda text: print(f"prm9tool: {text}", file=sys.stderr))
    except (Stopped, LimitExceededError, ValveFaultError, ValueError) as exc:
        print(f"prm9tool: {stopped_text(exc)}", file=sys.stderr)
        return ExitCode.OUT_OF_LIMITS, None
    except CommunicationError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION, None
    except Prm9Error as exc:
        print(f"prm9tool: test stopped: {exc}", file=sys.stderr)
        return ExitCode.OUT_OF_LIMITS, None
    finally:
        close()
    recorder = recorder_for(args)
    try:
        record_characterization(recorder, run)
    finally:
        recorder.close()
    return _fit_run(args, run)


def _fit_run(args: argparse.Namespace, run: Characterization) -> tuple[int, ProvenTwin | None]:
    """Fit the twin of ``run``, write it, record it, characterize it as the valve was
    (:func:`prm9tool.service.twin.fit_proven`, as the Tuning window's Twin page)."""
    import logging

    from prm9tool.cli.history import recorder_for
    from prm9tool.service.history import HistoryHook
    from prm9tool.service.twin import fit_proven

    if not Path(args.fit_twin).parent.is_dir():
        print(f"prm9tool: --fit-twin {args.fit_twin}: there is no folder "
              f"{Path(args.fit_twin).parent}", file=sys.stderr)  # fmt: skip
        return ExitCode.USAGE, None
    log = logging.getLogger("prm9tool.history")
    recorder = recorder_for(args)
    try:
        hook = HistoryHook(recorder, lambda problem: log.error("history: %s", problem))
        proven = fit_proven(run, args.fit_twin, hook,
                            lambda text: print(f"prm9tool: {text}", file=sys.stderr))  # fmt: skip
    except OSError as exc:
        print(f"prm9tool: cannot write {args.fit_twin}: {exc.strerror or exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE, None
    except Prm9Error as exc:
        print(f"prm9tool: --fit-twin: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE, None
    finally:
        recorder.close()
    return ExitCode.OK, proven
