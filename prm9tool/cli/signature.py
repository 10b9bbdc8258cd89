"""``prm9tool --signature``: the field signature of one valve against its birth certificate.

The short signature (≤ 20 s of motion, docs/twin.md "The birth certificate") on the one valve of
``--device``/``--emulator``, compared with its end-of-line test in the history; the drift in
words on standard output, the PDF (``--report OUT.pdf``) and the JSON (``--json`` prints it,
``--json OUT.json`` writes it), a ``signature`` history record. ``--enable --hydraulics-safe``
as with ``--characterize``. Exit 0: no figure drifted beyond its limit; 8: one did (or the
test was stopped); 7: no birth certificate in the history (nothing moved); 2 usage; 4/6 the
valve not found or not answering; 1 the valve refused an access before the test (SDO abort). Through :func:`prm9tool.characterize.drift.signature`, as the
window and ``Valve.signature()``.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from prm9tool.characterize.birth_certificate import NoReferenceError
from prm9tool.characterize.drift import DriftReport, signature
from prm9tool.characterize.frame import LimitExceededError
from prm9tool.characterize.rig import Stopped, ValveFaultError
from prm9tool.cli.batch_devices import BatchError
from prm9tool.cli.characterize import _profile, _rig, stopped_text
from prm9tool.errors import CommunicationError, ExitCode, HistoryError, Prm9Error
from prm9tool.files.atomicfile import atomic_write


def run(args: argparse.Namespace) -> int:
    """Entry point of ``--signature``; returns the exit code."""
    from prm9tool.cli.history import recorder_for
    from prm9tool.service.history import record_signature

    pdf = Path(args.report) if args.report else None
    js = Path(args.json) if isinstance(args.json, str) else None
    for option, path in (("--report", pdf), ("--json", js)):
        if path is not None and not path.parent.is_dir():
            print(f"prm9tool: {option} {path}: there is no folder {path.parent}", file=sys.stderr)
            return ExitCode.USAGE
    recorder = recorder_for(args)
    try:
        try:
            profile = _profile(args)
            rig, close = _rig(args, "--signature")
        except BatchError as exc:
            print(f"prm9tool: {exc}", file=sys.stderr)
            return int(exc.code)
        try:
            report = signature(rig, recorder.store().records, profile, _say)
        except NoReferenceError as exc:
            print(f"prm9tool: {exc}", file=sys.stderr)
            return ExitCode.HISTORY
        except HistoryError as exc:
            print(f"prm9tool: the birth certificate cannot be read: {exc}", file=sys.stderr)
            return ExitCode.HISTORY
        except (Stopped, LimitExceededError, ValveFaultError, ValueError) as exc:
            print(f"prm9tool: {stopped_text(exc)}", file=sys.stderr)
            return ExitCode.OUT_OF_LIMITS
        except CommunicationError as exc:
            print(f"prm9tool: {exc}", file=sys.stderr)
            return ExitCode.COMMUNICATION
        except Prm9Error as exc:
            print(f"prm9tool: test stopped: {exc}", file=sys.stderr)
            return ExitCode.OUT_OF_LIMITS
        finally:
            close()
        record_signature(recorder, report)
    finally:
        recorder.close()
    try:
        _write(report, pdf, js)
    except OSError as exc:
        print(f"prm9tool: cannot write the report: {exc}", file=sys.stderr)
        return ExitCode.USAGE
    if args.json is True:
        print(json.dumps(report.to_dict(), indent=2, ensure_ascii=False))
    else:
        for line in report.lines():
            print(line)
        print(report.summary())
    return ExitCode.OK if report.passed else ExitCode.OUT_OF_LIMITS


def _say(text: str) -> None:
    print(f"prm9tool: {text}", file=sys.stderr)


def _write(report: DriftReport, pdf: Path | None, js: Path | None) -> None:
    if pdf is not None:
        from prm9tool import i18n
        from prm9tool.views.tuning.report import ensure_app
        from prm9tool.views.tuning.signature_report import write_signature_pdf

        ensure_app()  # the PDF in the program language: the system's, as the GUI starts in
        i18n.set_language(i18n.system_language())
        write_signature_pdf(report, pdf)
    if js is not None:
        text = json.dumps(report.to_dict(), indent=2, ensure_ascii=False)
        atomic_write(js, (text + "\n").encode("utf-8"), backup=False)
